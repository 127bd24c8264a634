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
