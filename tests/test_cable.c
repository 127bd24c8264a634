/* SPDX-License-Identifier: MIT */
/* Cables: the path's length and lengthening speed, where its tension
 * pulls, and the implicit tension law, against hand-derived values.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "rb/rb.h"
#include "test_support.h"

/* A dynamic unit-mass body without rotation (mass data override), at p. */
static rb_body_id unit_point_mass(rb_world *world, rb_vec2 p)
{
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, p, 0.0);
    const rb_mass_data mass = {1.0, {0.0, 0.0}, 0.0};
    cr_assert_eq(rb_body_set_mass_data(world, body, &mass), RB_OK, "%s", rb_last_error());
    return body;
}

static rb_cable_id make_cable(rb_world *world, int count, const rb_body_id *bodies, const rb_vec2 *points)
{
    rb_cable_def def = rb_default_cable_def();
    def.point_count = count;
    for (int i = 0; i < count; ++i) {
        def.bodies[i] = bodies[i];
        def.local_points[i] = points[i];
    }
    rb_cable_id cable;
    cr_assert_eq(rb_cable_create(world, &def, &cable), RB_OK, "%s", rb_last_error());
    return cable;
}

static void set_law(rb_world *world, rb_cable_id cable, double tension, double damping)
{
    cr_assert_eq(rb_cable_set_tension_law(world, cable, tension, damping), RB_OK, "%s", rb_last_error());
}

Test(cable, length_and_lengthening_speed)
{
    /* Anchor at the origin, a via point on a static body at (3, 0), and a
     * body at (3, 4) moving at (1, 2): length 3 + 4 = 7 m; only the last
     * segment changes, along (0, 1): L' = 2 m/s. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id mover = unit_point_mass(world, rb_v2(3.0, 4.0));
    cr_assert_eq(rb_body_set_linear_velocity(world, mover, rb_v2(1.0, 2.0)), RB_OK);
    const rb_body_id bodies[3] = {ground, ground, mover};
    const rb_vec2 points[3] = {{0.0, 0.0}, {3.0, 0.0}, {0.0, 0.0}};
    rb_cable_id cable = make_cable(world, 3, bodies, points);
    expect_near(rb_cable_length(world, cable), 7.0, 1e-12, "length");
    expect_near(rb_cable_lengthening_speed(world, cable), 2.0, 1e-12, "lengthening speed");
    rb_vec2 out[3];
    cr_expect_eq(rb_cable_points(world, cable, out, 3), 3);
    expect_vec_near(out[2], rb_v2(3.0, 4.0), 1e-12, "third point");
    destroy_world_and_expect_no_leak(world);
}

Test(cable, a_via_point_gets_the_sum_of_both_pulls)
{
    /* A unit mass at (0, 0) between static points at (-3, 4) and (4, 3),
     * tension 10 N, no damping: it is pulled by 10·(u1 + u2) with
     * u1 = (-3, 4)/5 and u2 = (4, 3)/5, so a = 10·(1/5, 7/5) m/s². Over a
     * step of 1e-6 s the directions do not change (to 1e-12), so
     * v = a·dt. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id via = unit_point_mass(world, rb_v2(0.0, 0.0));
    const rb_body_id bodies[3] = {ground, via, ground};
    const rb_vec2 points[3] = {{-3.0, 4.0}, {0.0, 0.0}, {4.0, 3.0}};
    rb_cable_id cable = make_cable(world, 3, bodies, points);
    set_law(world, cable, 10.0, 0.0);
    const double dt = 1e-6;
    step_world(world, dt, 1);
    expect_vec_near(rb_body_linear_velocity(world, via), rb_v2(10.0 * 0.2 * dt, 10.0 * 1.4 * dt), 1e-15,
                    "velocity of the via point");
    expect_near(rb_cable_tension(world, cable), 10.0, 1e-9, "tension reported");
    destroy_world_and_expect_no_leak(world);
}

Test(cable, ends_on_one_body_exert_no_net_force_or_torque)
{
    /* A box in zero gravity with a cable between two of its own points
     * and 100 N of tension: the two pulls are equal, opposite and on one
     * line, so the box keeps its (zero) velocities. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(1.0, 2.0), 0.3);
    add_box(world, box, 1.0, 0.5, 1.0);
    const rb_body_id bodies[2] = {box, box};
    const rb_vec2 points[2] = {{-0.8, 0.3}, {0.7, -0.4}};
    rb_cable_id cable = make_cable(world, 2, bodies, points);
    set_law(world, cable, 100.0, 5.0);
    step_world(world, TEST_DT, 10);
    expect_vec_near(rb_body_linear_velocity(world, box), rb_v2(0.0, 0.0), 1e-12, "linear velocity");
    expect_near(rb_body_angular_velocity(world, box), 0.0, 1e-12, "angular velocity");
    destroy_world_and_expect_no_leak(world);
}

Test(cable, damping_is_implicit_and_stable_at_any_stiffness)
{
    /* A unit mass moving straight away from the cable's anchor in zero
     * gravity, tension law T = c·L' (no base tension): m·v' = -c·v. Each
     * substep of h is a backward-Euler step, v ← v/(1 + h·c/m), exactly;
     * with h·c/m = 1000 an explicit step would multiply v by -999 each
     * substep, while this one decays monotonically. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id anchor = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id mass = unit_point_mass(world, rb_v2(1.0, 0.0));
    cr_assert_eq(rb_body_set_linear_velocity(world, mass, rb_v2(2.0, 0.0)), RB_OK);
    const rb_body_id bodies[2] = {anchor, mass};
    const rb_vec2 points[2] = {{0.0, 0.0}, {0.0, 0.0}};
    rb_cable_id cable = make_cable(world, 2, bodies, points);
    const double h = substep_of(world, TEST_DT);
    const double damping = 1000.0 / h;
    set_law(world, cable, 0.0, damping);
    double expected = 2.0;
    const int substeps = rb_world_solver_settings(world).substeps;
    for (int n = 1; n <= 5; ++n) {
        step_world(world, TEST_DT, 1);
        for (int k = 0; k < substeps; ++k) {
            expected /= 1.0 + h * damping;
        }
        const rb_vec2 v = rb_body_linear_velocity(world, mass);
        expect_near(v.x, expected, 1e-12 * 2.0, "v after backward-Euler substeps");
        cr_expect(v.x >= 0.0, "step %d: the velocity changed sign (%g): the damper overshot", n, v.x);
    }
    destroy_world_and_expect_no_leak(world);
}

Test(cable, a_cable_never_pushes)
{
    /* A unit mass moving towards the anchor (the cable shortens) with a
     * law of 0 N + 50 N·s/m: the law asks for a negative tension, which a
     * cable cannot give, so it stays slack and the mass moves freely. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id anchor = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id mass = unit_point_mass(world, rb_v2(2.0, 0.0));
    cr_assert_eq(rb_body_set_linear_velocity(world, mass, rb_v2(-1.0, 0.0)), RB_OK);
    const rb_body_id bodies[2] = {anchor, mass};
    const rb_vec2 points[2] = {{0.0, 0.0}, {0.0, 0.0}};
    rb_cable_id cable = make_cable(world, 2, bodies, points);
    set_law(world, cable, 0.0, 50.0);
    step_world(world, TEST_DT, 3);
    expect_vec_near(rb_body_linear_velocity(world, mass), rb_v2(-1.0, 0.0), 1e-15, "free motion");
    cr_expect_eq(rb_cable_tension(world, cable), 0.0, "a shortening cable under this law is slack");
    destroy_world_and_expect_no_leak(world);
}

Test(cable, bad_input_is_refused_and_bodies_take_their_cables_with_them)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id a = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id b = unit_point_mass(world, rb_v2(1.0, 0.0));
    rb_cable_def def = rb_default_cable_def();
    rb_cable_id cable;
    def.point_count = 1;
    def.bodies[0] = a;
    cr_expect_eq(rb_cable_create(world, &def, &cable), RB_ERR_INVALID_ARGUMENT, "one point");
    cr_expect(rb_cable_id_is_null(cable), "a failed create must give the null id");
    def.point_count = RB_MAX_CABLE_POINTS + 1;
    cr_expect_eq(rb_cable_create(world, &def, &cable), RB_ERR_INVALID_ARGUMENT, "too many points");
    def.point_count = 2;
    def.bodies[1] = b;
    def.local_points[1] = rb_v2(NAN, 0.0);
    cr_expect_eq(rb_cable_create(world, &def, &cable), RB_ERR_INVALID_ARGUMENT, "NaN point");
    def.bodies[1] = a;
    def.local_points[1] = rb_v2(0.0, 0.0);
    cr_expect_eq(rb_cable_create(world, &def, &cable), RB_ERR_DEGENERATE_SHAPE, "coincident points");
    cr_expect(strstr(rb_last_error(), "coincide") != NULL, "message: %s", rb_last_error());
    def.bodies[1] = (rb_body_id){0};
    cr_expect_eq(rb_cable_create(world, &def, &cable), RB_ERR_FOREIGN_ID, "null body id");
    cr_expect_eq(rb_cable_create(world, NULL, &cable), RB_ERR_INVALID_ARGUMENT, "NULL def");

    def.bodies[1] = b;
    cr_assert_eq(rb_cable_create(world, &def, &cable), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_cable_set_tension_law(world, cable, NAN, 0.0), RB_ERR_INVALID_ARGUMENT, "NaN tension");
    cr_expect_eq(rb_cable_set_tension_law(world, cable, 1.0, -1.0), RB_ERR_INVALID_ARGUMENT, "negative damping");
    cr_expect_eq(rb_body_destroy(world, b), RB_OK);
    cr_expect(!rb_cable_is_valid(world, cable), "destroying a body destroys its cables");
    cr_expect_eq(rb_cable_length(world, cable), 0.0);
    cr_expect_eq(rb_last_status(), RB_ERR_STALE_ID, "reading a destroyed cable reports a stale id");
    step_world(world, TEST_DT, 1);
    destroy_world_and_expect_no_leak(world);
}

/* What the substep callback of the next test compares. */
typedef struct read_check {
    rb_cable_id cable;
    int readings;   /* callbacks that compared */
    int mismatches; /* readings that differed from rb_cable_state and rb_cable_tension */
    int misplaced;  /* readings whose length differed from the path's points as the bodies place them now */
    double tension; /* the law's base tension, N */
} read_check;

/* The path's length from its points as rb_cable_points places them from
 * the bodies now, summed in the path's order as the engine sums it. */
static double length_from_points(const rb_world *world, rb_cable_id cable)
{
    rb_vec2 points[8];
    int count = rb_cable_points(world, cable, points, 8);
    double length = 0.0;
    for (int i = 0; i + 1 < count; ++i) {
        length += rb_length(rb_sub(points[i + 1], points[i]));
    }
    return length;
}

static bool same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* In the substep callback, where the cable reads the points the solver
 * located: rb_cable_read against the separate calls, then the next law. */
static void compare_readings(rb_world *world, int substep, double h, void *context)
{
    (void)substep;
    (void)h;
    read_check *check = context;
    rb_cable_reading reading;
    double length = 0.0, speed = 0.0;
    bool ok = rb_cable_read(world, check->cable, &reading) == RB_OK &&
              rb_cable_state(world, check->cable, &length, &speed) == RB_OK;
    double tension = rb_cable_tension(world, check->cable);
    if (!ok || !same_bits(reading.length, length) || !same_bits(reading.lengthening_speed, speed) ||
        !same_bits(reading.tension, tension)) {
        check->mismatches += 1;
    }
    check->misplaced += same_bits(reading.length, length_from_points(world, check->cable)) ? 0 : 1;
    check->readings += 1;
    (void)rb_cable_set_tension_law(world, check->cable, check->tension, 50.0);
}

Test(cable, one_read_gives_the_length_speed_and_tension_of_the_separate_calls)
{
    /* A path from a fixed point over two via points on one swinging disc
     * to a second disc: 4 points on 3 bodies, one of them static. Before
     * any step, the geometry gives the length by hand: (0, 0) -> (1, 0)
     * -> (1, -1) -> (2, -1), 3 m. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id disc = make_body(world, RB_BODY_DYNAMIC, rb_v2(1.0, -0.5), 0.0);
    rb_body_id weight = make_body(world, RB_BODY_DYNAMIC, rb_v2(2.0, -1.0), 0.0);
    add_circle(world, disc, rb_v2(0.0, 0.0), 0.3, 1000.0);
    add_circle(world, weight, rb_v2(0.0, 0.0), 0.1, 1000.0);
    cr_assert_eq(rb_body_set_angular_velocity(world, disc, 2.0), RB_OK);
    const rb_body_id bodies[4] = {ground, disc, disc, weight};
    const rb_vec2 points[4] = {{0.0, 0.0}, {0.0, 0.5}, {0.0, -0.5}, {0.0, 0.0}};
    read_check check = {.cable = make_cable(world, 4, bodies, points), .tension = 100.0};
    rb_cable_reading reading;
    cr_assert_eq(rb_cable_read(world, check.cable, &reading), RB_OK, "%s", rb_last_error());
    expect_near(reading.length, 3.0, 1e-15, "length before any step");
    /* The disc turns at 2 rad/s: its via points move at 1 m/s, the upper
     * one along -x (shortening the first segment by 1 m/s), the lower
     * along +x (shortening the last by 1 m/s); the middle segment turns
     * without changing length. */
    expect_near(reading.lengthening_speed, -2.0, 1e-15, "lengthening speed before any step");
    cr_assert_eq(rb_world_set_substep_callback(world, compare_readings, &check), RB_OK);
    step_world(world, TEST_DT, 30);
    /* A second circle moves the disc's centre of mass between two steps:
     * the points the solver locates must follow it. */
    add_circle(world, disc, rb_v2(0.2, 0.1), 0.1, 1000.0);
    step_world(world, TEST_DT, 30);
    cr_expect_eq(check.readings, 60 * rb_world_solver_settings(world).substeps, "a reading every substep");
    cr_expect_eq(check.mismatches, 0, "rb_cable_read differs from rb_cable_state and rb_cable_tension");
    cr_expect_eq(check.misplaced, 0, "%d readings measured the path elsewhere than rb_cable_points places it",
                 check.misplaced);
    /* After the step, outside the callback, the path is measured from the bodies. */
    double length = 0.0, speed = 0.0;
    cr_assert_eq(rb_cable_read(world, check.cable, &reading), RB_OK);
    cr_assert_eq(rb_cable_state(world, check.cable, &length, &speed), RB_OK);
    cr_expect(same_bits(reading.length, length) && same_bits(reading.lengthening_speed, speed));
    cr_expect(same_bits(reading.tension, rb_cable_tension(world, check.cable)));
    cr_expect_gt(reading.tension, 0.0, "the cable pulls");
    destroy_world_and_expect_no_leak(world);
}

Test(cable, a_read_of_a_bad_cable_or_into_nowhere_is_refused)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id a = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id b = unit_point_mass(world, rb_v2(1.0, 0.0));
    const rb_body_id bodies[2] = {a, b};
    const rb_vec2 points[2] = {{0.0, 0.0}, {0.0, 0.0}};
    rb_cable_id cable = make_cable(world, 2, bodies, points);
    cr_expect_eq(rb_cable_read(world, cable, NULL), RB_ERR_INVALID_ARGUMENT, "NULL out");
    cr_expect(strstr(rb_last_error(), "rb_cable_read") != NULL, "message: %s", rb_last_error());
    rb_cable_reading reading = {1.0, 1.0, 1.0};
    cr_expect_eq(rb_cable_read(NULL, cable, &reading), RB_ERR_INVALID_ARGUMENT, "NULL world");
    cr_expect(reading.length == 0.0 && reading.lengthening_speed == 0.0 && reading.tension == 0.0,
              "a refused read leaves zeros");
    cr_expect_eq(rb_cable_read(world, (rb_cable_id){0}, &reading), RB_ERR_FOREIGN_ID, "null id");
    cr_assert_eq(rb_cable_destroy(world, cable), RB_OK);
    cr_expect_eq(rb_cable_read(world, cable, &reading), RB_ERR_STALE_ID, "destroyed cable");
    cr_expect(strstr(rb_last_error(), "destroyed") != NULL, "message: %s", rb_last_error());
    destroy_world_and_expect_no_leak(world);
}
