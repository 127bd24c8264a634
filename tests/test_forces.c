/* SPDX-License-Identifier: MIT */
/* Forces, torques and impulses on one body, its point kinematics and frame
 * conversions, and its mass properties, against Newton's laws and the
 * closed-form mass of circles and rectangles.
 *
 * Tolerance: every expected value here is a handful of floating-point
 * operations on numbers of order 0.1 .. 10, each correct to 1.1e-16
 * relative, and the engine's mass and inertia come from a few more (area
 * and second-moment sums over at most 8 vertices). REL = 1e-12, relative
 * to the size of the expected value, is thousands of roundoffs wide, while
 * any wrong formula (a missing factor, the inertia about the wrong point,
 * a step counted twice) is off by 1 % or more.
 */
#include <math.h>

#include "test_support.h"

#define REL 1e-12

/* The test box: half-extents 1 × 0.5 m and density 2 kg/m², so its mass is
 * density · (2·hx)·(2·hy) = 4 kg and its inertia about its centre
 * m·(w² + h²)/12 = 4·(2² + 1²)/12 = 5/3 kg·m². */
#define BOX_HX 1.0
#define BOX_HY 0.5
#define BOX_DENSITY 2.0
#define BOX_MASS (BOX_DENSITY * 4.0 * BOX_HX * BOX_HY)
#define BOX_INERTIA (BOX_MASS * (4.0 * BOX_HX * BOX_HX + 4.0 * BOX_HY * BOX_HY) / 12.0)

/* A dynamic test box at rest at `position` (its centre), turned by `angle`. */
static rb_body_id make_test_box(rb_world *world, rb_vec2 position, double angle)
{
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, position, angle);
    add_box(world, body, BOX_HX, BOX_HY, BOX_DENSITY);
    return body;
}

/* The world point `local` of a body at `position` turned by `angle`,
 * written out with cos and sin rather than through the engine's rotation. */
static rb_vec2 place(rb_vec2 position, double angle, rb_vec2 local)
{
    const double c = cos(angle), s = sin(angle);
    return rb_v2(position.x + c * local.x - s * local.y, position.y + s * local.x + c * local.y);
}

static void expect_ok(rb_status status, const char *call)
{
    cr_expect_eq(status, RB_OK, "%s returned %s: %s", call, rb_status_name(status), rb_last_error());
}

Test(forces, force_at_the_centre_accelerates_without_turning)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const rb_vec2 p0 = rb_v2(0.5, -0.3);
    const double angle0 = 0.4;
    rb_body_id body = make_test_box(world, p0, angle0);
    const rb_vec2 force = rb_v2(3.0, -2.0);
    expect_ok(rb_body_apply_force_to_center(world, body, force), "rb_body_apply_force_to_center");
    cr_expect_eq(rb_body_torque(world, body), 0.0, "a force at the centre has no moment");

    step_world(world, TEST_DT, 1);

    /* One semi-implicit Euler step from rest: v = dt·F/m, and the position
     * moves by ½·(F/m)·dt·(dt + h) over the substeps of length h. */
    const double h = substep_of(world, TEST_DT);
    const rb_vec2 v = rb_v2(TEST_DT * force.x / BOX_MASS, TEST_DT * force.y / BOX_MASS);
    expect_vec_near(rb_body_linear_velocity(world, body), v, REL * rb_length(v), "velocity after one step");
    const rb_vec2 moved =
        rb_v2(step_displacement(force.x / BOX_MASS, TEST_DT, h), step_displacement(force.y / BOX_MASS, TEST_DT, h));
    expect_vec_near(rb_body_position(world, body), rb_add(p0, moved), REL, "position");
    cr_expect_eq(rb_body_angular_velocity(world, body), 0.0, "a force at the centre must not turn the body");
    expect_near(rb_body_angle(world, body), angle0, REL, "angle");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, force_at_an_offset_also_gives_a_torque)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const rb_vec2 p0 = rb_v2(0.5, -0.3);
    const double angle0 = 0.4;
    rb_body_id body = make_test_box(world, p0, angle0);
    /* r × F = 0.7·2 - (-0.2)·0.5 = 1.5 N·m. */
    const rb_vec2 r = rb_v2(0.7, -0.2);
    const rb_vec2 force = rb_v2(0.5, 2.0);
    const double torque = r.x * force.y - r.y * force.x;
    expect_ok(rb_body_apply_force(world, body, force, rb_add(p0, r)), "rb_body_apply_force");
    expect_vec_near(rb_body_force(world, body), force, REL, "accumulated force");
    expect_near(rb_body_torque(world, body), torque, REL * fabs(torque), "accumulated torque r × F");

    step_world(world, TEST_DT, 1);

    const double h = substep_of(world, TEST_DT);
    const rb_vec2 v = rb_v2(TEST_DT * force.x / BOX_MASS, TEST_DT * force.y / BOX_MASS);
    const double omega = TEST_DT * torque / BOX_INERTIA;
    expect_vec_near(rb_body_linear_velocity(world, body), v, REL * rb_length(v), "Δv = dt·F/m");
    expect_near(rb_body_angular_velocity(world, body), omega, REL * omega, "Δω = dt·(r × F)/I");
    expect_near(rb_body_angle(world, body), angle0 + step_displacement(torque / BOX_INERTIA, TEST_DT, h), REL,
                "angle = angle0 + ½·α·dt·(dt + h)");
    /* The step consumed the force: none is left for the next one. */
    cr_expect(rb_body_force(world, body).x == 0.0 && rb_body_force(world, body).y == 0.0,
              "the force must be cleared by the step");
    cr_expect_eq(rb_body_torque(world, body), 0.0, "the torque must be cleared by the step");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, forces_and_torques_add_up_and_last_one_step)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const rb_vec2 p0 = rb_v2(-1.0, 2.0);
    rb_body_id body = make_test_box(world, p0, 0.0);
    const rb_vec2 f1 = rb_v2(1.0, 0.5), r1 = rb_v2(0.0, 0.5);
    const rb_vec2 f2 = rb_v2(-3.0, 1.5);
    const double applied_torque = 0.8;
    expect_ok(rb_body_apply_force(world, body, f1, rb_add(p0, r1)), "rb_body_apply_force");
    expect_ok(rb_body_apply_force_to_center(world, body, f2), "rb_body_apply_force_to_center");
    expect_ok(rb_body_apply_torque(world, body, applied_torque), "rb_body_apply_torque");

    /* Total force f1 + f2 = (-2, 2) N; total torque r1 × f1 + T =
     * (0·0.5 - 0.5·1) + 0.8 = 0.3 N·m. */
    const rb_vec2 force = rb_add(f1, f2);
    const double torque = (r1.x * f1.y - r1.y * f1.x) + applied_torque;
    expect_vec_near(rb_body_force(world, body), force, REL, "sum of the forces");
    expect_near(rb_body_torque(world, body), torque, REL, "sum of the torques");

    step_world(world, TEST_DT, 1);
    const rb_vec2 v = rb_v2(TEST_DT * force.x / BOX_MASS, TEST_DT * force.y / BOX_MASS);
    const double omega = TEST_DT * torque / BOX_INERTIA;
    expect_vec_near(rb_body_linear_velocity(world, body), v, REL * rb_length(v), "velocity after the forced step");
    expect_near(rb_body_angular_velocity(world, body), omega, REL * omega, "ω after the forced step");

    /* Without gravity and with the forces cleared, a second step changes
     * no velocity. */
    step_world(world, TEST_DT, 1);
    expect_vec_near(rb_body_linear_velocity(world, body), v, REL * rb_length(v), "velocity after a free step");
    expect_near(rb_body_angular_velocity(world, body), omega, REL * omega, "ω after a free step");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, torque_turns_without_moving)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_test_box(world, rb_v2(0.0, 0.0), 0.0);
    const double torque = -2.5;
    expect_ok(rb_body_apply_torque(world, body, torque), "rb_body_apply_torque");
    step_world(world, TEST_DT, 1);
    const double omega = TEST_DT * torque / BOX_INERTIA;
    expect_near(rb_body_angular_velocity(world, body), omega, REL * fabs(omega), "Δω = h·τ/I");
    cr_expect(rb_body_linear_velocity(world, body).x == 0.0 && rb_body_linear_velocity(world, body).y == 0.0,
              "a pure torque must not move the centre");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, linear_impulse_at_a_point_changes_both_velocities_at_once)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = rb_v2(2.0, 1.0);
    def.angle = -0.6;
    def.linear_velocity = rb_v2(1.0, -0.5);
    def.angular_velocity = 0.3;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_box(world, body, BOX_HX, BOX_HY, BOX_DENSITY);

    /* r × J = (-0.4)·(-0.8) - 0.6·0.3 = 0.14 N·m·s. */
    const rb_vec2 impulse = rb_v2(0.3, -0.8), r = rb_v2(-0.4, 0.6);
    expect_ok(rb_body_apply_linear_impulse(world, body, impulse, rb_add(def.position, r)),
              "rb_body_apply_linear_impulse");

    const rb_vec2 v = rb_v2(def.linear_velocity.x + impulse.x / BOX_MASS, def.linear_velocity.y + impulse.y / BOX_MASS);
    const double omega = def.angular_velocity + (r.x * impulse.y - r.y * impulse.x) / BOX_INERTIA;
    expect_vec_near(rb_body_linear_velocity(world, body), v, REL, "v0 + J/m, before any step");
    expect_near(rb_body_angular_velocity(world, body), omega, REL, "ω0 + (r × J)/I, before any step");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, linear_impulse_at_the_centre_does_not_turn)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_test_box(world, rb_v2(0.0, 0.0), 1.0);
    const rb_vec2 impulse = rb_v2(-2.0, 6.0);
    expect_ok(rb_body_apply_linear_impulse_to_center(world, body, impulse), "rb_body_apply_linear_impulse_to_center");
    expect_vec_near(rb_body_linear_velocity(world, body), rb_v2(impulse.x / BOX_MASS, impulse.y / BOX_MASS), REL,
                    "J/m");
    cr_expect_eq(rb_body_angular_velocity(world, body), 0.0, "an impulse at the centre must not turn the body");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, angular_impulse_turns_without_moving)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_test_box(world, rb_v2(0.0, 0.0), 0.0);
    const double impulse = 0.9;
    expect_ok(rb_body_apply_angular_impulse(world, body, impulse), "rb_body_apply_angular_impulse");
    expect_near(rb_body_angular_velocity(world, body), impulse / BOX_INERTIA, REL, "Δω = L/I");
    cr_expect(rb_body_linear_velocity(world, body).x == 0.0 && rb_body_linear_velocity(world, body).y == 0.0,
              "an angular impulse must not move the centre");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, point_velocity_is_v_plus_omega_cross_r)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    /* A body whose only shape is a circle centred at (0.5, 0) in its own
     * frame, so that its centre of mass is not its origin. */
    const rb_vec2 origin = rb_v2(1.0, 2.0);
    const double angle = 0.3;
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, origin, angle);
    const rb_vec2 local_center = rb_v2(0.5, 0.0);
    add_circle(world, body, local_center, 0.2, 1.0);
    const rb_vec2 v = rb_v2(2.0, -1.0);
    const double omega = 3.0;
    expect_ok(rb_body_set_linear_velocity(world, body, v), "rb_body_set_linear_velocity");
    expect_ok(rb_body_set_angular_velocity(world, body, omega), "rb_body_set_angular_velocity");

    const rb_vec2 center = place(origin, angle, local_center);
    expect_vec_near(rb_body_world_center(world, body), center, REL, "world centre of mass");
    const rb_vec2 points[] = {{1.7, 2.9}, {-3.0, 0.5}, {center.x, center.y}};
    for (size_t i = 0; i < sizeof points / sizeof points[0]; ++i) {
        const rb_vec2 r = rb_sub(points[i], center);
        /* ω × r = (-ω·r.y, ω·r.x) */
        const rb_vec2 expected = rb_v2(v.x - omega * r.y, v.y + omega * r.x);
        expect_vec_near(rb_body_point_velocity(world, body, points[i]), expected, REL, "v + ω × r");
    }
    destroy_world_and_expect_no_leak(world);
}

Test(forces, local_and_world_points_and_vectors_round_trip)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    /* Two poses, the second turned past π/2 so that every sign of cos and
     * sin is exercised. */
    const rb_vec2 origins[] = {{1.0, 2.0}, {-4.0, 0.5}};
    const double angles[] = {0.7, -2.5};
    const rb_vec2 local = rb_v2(0.3, -0.4);
    for (int k = 0; k < 2; ++k) {
        rb_body_id body = make_body(world, RB_BODY_DYNAMIC, origins[k], angles[k]);
        const rb_vec2 world_point = place(origins[k], angles[k], local);
        const rb_vec2 world_vector = place(rb_v2(0.0, 0.0), angles[k], local);
        expect_vec_near(rb_body_world_point(world, body, local), world_point, REL, "world point");
        expect_vec_near(rb_body_local_point(world, body, world_point), local, REL, "local point of the world point");
        expect_vec_near(rb_body_world_vector(world, body, local), world_vector, REL, "world vector");
        expect_vec_near(rb_body_local_vector(world, body, world_vector), local, REL,
                        "local vector of the world vector");
        const rb_transform xf = rb_body_transform(world, body);
        expect_vec_near(xf.p, origins[k], REL, "transform position");
        expect_near(xf.q.c, cos(angles[k]), REL, "transform cosine");
        expect_near(xf.q.s, sin(angles[k]), REL, "transform sine");
    }
    destroy_world_and_expect_no_leak(world);
}

Test(forces, static_body_ignores_forces_and_impulses)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    const rb_vec2 p0 = rb_v2(1.0, 2.0);
    const double angle0 = 0.5;
    rb_body_id body = make_body(world, RB_BODY_STATIC, p0, angle0);
    add_box(world, body, BOX_HX, BOX_HY, BOX_DENSITY);
    expect_ok(rb_body_apply_force(world, body, rb_v2(10.0, 3.0), rb_v2(1.5, 2.0)), "rb_body_apply_force");
    expect_ok(rb_body_apply_force_to_center(world, body, rb_v2(-4.0, 1.0)), "rb_body_apply_force_to_center");
    expect_ok(rb_body_apply_torque(world, body, 7.0), "rb_body_apply_torque");
    expect_ok(rb_body_apply_linear_impulse(world, body, rb_v2(1.0, 1.0), rb_v2(0.0, 0.0)),
              "rb_body_apply_linear_impulse");
    expect_ok(rb_body_apply_angular_impulse(world, body, 2.0), "rb_body_apply_angular_impulse");
    cr_expect(rb_body_force(world, body).x == 0.0 && rb_body_force(world, body).y == 0.0,
              "a static body accumulates no force");
    cr_expect_eq(rb_body_torque(world, body), 0.0, "a static body accumulates no torque");

    step_world(world, TEST_DT, 10);
    const rb_vec2 p = rb_body_position(world, body);
    cr_expect(p.x == p0.x && p.y == p0.y, "a static body moved to (%.17g, %.17g)", p.x, p.y);
    cr_expect_eq(rb_body_angle(world, body), angle0, "a static body turned");
    const rb_vec2 v = rb_body_linear_velocity(world, body);
    cr_expect(v.x == 0.0 && v.y == 0.0, "a static body has velocity (%g, %g)", v.x, v.y);
    cr_expect_eq(rb_body_angular_velocity(world, body), 0.0, "a static body has angular velocity");
    destroy_world_and_expect_no_leak(world);
}

Test(forces, kinematic_body_ignores_forces_and_impulses)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_KINEMATIC;
    def.linear_velocity = rb_v2(1.0, 0.5);
    def.angular_velocity = 0.2;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_box(world, body, BOX_HX, BOX_HY, BOX_DENSITY);
    expect_ok(rb_body_apply_force(world, body, rb_v2(10.0, 3.0), rb_v2(0.5, 0.0)), "rb_body_apply_force");
    expect_ok(rb_body_apply_torque(world, body, 7.0), "rb_body_apply_torque");
    expect_ok(rb_body_apply_linear_impulse(world, body, rb_v2(1.0, 1.0), rb_v2(0.0, 0.3)),
              "rb_body_apply_linear_impulse");
    expect_ok(rb_body_apply_angular_impulse(world, body, 2.0), "rb_body_apply_angular_impulse");
    step_world(world, TEST_DT, 1);
    const rb_vec2 v = rb_body_linear_velocity(world, body);
    cr_expect(v.x == def.linear_velocity.x && v.y == def.linear_velocity.y,
              "a kinematic body's velocity changed to (%.17g, %.17g)", v.x, v.y);
    cr_expect_eq(rb_body_angular_velocity(world, body), def.angular_velocity,
                 "a kinematic body's angular velocity changed");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, circle_matches_closed_form)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(3.0, -1.0), 0.2);
    const double radius = 0.3, density = 2.0;
    add_circle(world, body, rb_v2(0.0, 0.0), radius, density);
    /* m = ρ·π·r², I = m·r²/2 about the centre. */
    const double mass = density * RB_PI * radius * radius;
    const double inertia = 0.5 * mass * radius * radius;
    expect_near(rb_body_mass(world, body), mass, REL * mass, "circle mass");
    expect_near(rb_body_rotational_inertia(world, body), inertia, REL * inertia, "circle inertia");
    const rb_mass_data data = rb_body_mass_data(world, body);
    expect_near(data.mass, mass, REL * mass, "mass data: mass");
    expect_near(data.rotational_inertia, inertia, REL * inertia, "mass data: inertia");
    expect_vec_near(data.center, rb_v2(0.0, 0.0), REL, "mass data: centre");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, box_matches_closed_form)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_test_box(world, rb_v2(0.0, 0.0), 0.0);
    expect_near(rb_body_mass(world, body), BOX_MASS, REL * BOX_MASS, "box mass");
    expect_near(rb_body_rotational_inertia(world, body), BOX_INERTIA, REL * BOX_INERTIA, "box inertia");
    expect_vec_near(rb_body_local_center(world, body), rb_v2(0.0, 0.0), REL, "box centre");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, offset_shape_inertia_is_about_its_own_centre_of_mass)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const rb_vec2 origin = rb_v2(-1.0, 0.5);
    const double body_angle = 0.3;
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, origin, body_angle);
    /* A 1 × 0.5 m box centred at (1, 2) in the body frame, turned by 0.4
     * rad: m = 3·0.5 = 1.5 kg, and its inertia about its own centre,
     * m·(1² + 0.5²)/12, does not depend on the turn. The body's centre of
     * mass is the box's centre, so the inertia about it has no
     * parallel-axis term; about the body origin it would be larger by
     * m·|(1, 2)|² = 7.5 kg·m². */
    const double hx = 0.5, hy = 0.25, density = 3.0;
    const rb_vec2 local_center = rb_v2(1.0, 2.0);
    rb_polygon box;
    cr_assert_eq(rb_make_offset_box(hx, hy, local_center, 0.4, &box), RB_OK, "%s", rb_last_error());
    rb_shape_def def = rb_default_shape_def();
    def.density = density;
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_polygon(world, body, &def, &box, &shape), RB_OK, "%s", rb_last_error());

    const double mass = density * 4.0 * hx * hy;
    const double inertia = mass * (4.0 * hx * hx + 4.0 * hy * hy) / 12.0;
    expect_near(rb_body_mass(world, body), mass, REL * mass, "mass");
    expect_near(rb_body_rotational_inertia(world, body), inertia, REL * inertia, "inertia about the centre of mass");
    expect_vec_near(rb_body_local_center(world, body), local_center, REL, "local centre of mass");
    expect_vec_near(rb_body_world_center(world, body), place(origin, body_angle, local_center), REL,
                    "world centre of mass");
    destroy_world_and_expect_no_leak(world);
}

/* The body of two shapes: a circle of radius 0.5 at (-1, 0), density 1, and
 * a unit square at (2, 1), density 4. */
#define PAIR_CIRCLE_RADIUS 0.5
#define PAIR_SQUARE_DENSITY 4.0
static const rb_vec2 pair_circle_center = {-1.0, 0.0};
static const rb_vec2 pair_square_center = {2.0, 1.0};

static void add_pair_shapes(rb_world *world, rb_body_id body)
{
    add_circle(world, body, pair_circle_center, PAIR_CIRCLE_RADIUS, 1.0);
    rb_polygon square;
    cr_assert_eq(rb_make_offset_box(0.5, 0.5, pair_square_center, 0.0, &square), RB_OK, "%s", rb_last_error());
    rb_shape_def def = rb_default_shape_def();
    def.density = PAIR_SQUARE_DENSITY;
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_polygon(world, body, &def, &square, &shape), RB_OK, "%s", rb_last_error());
}

/* The mass data of add_pair_shapes: total mass, the mass-weighted centre,
 * and by the parallel-axis theorem I = Σ (I_i + m_i·|c_i - C|²). */
static rb_mass_data pair_mass_data(void)
{
    const double m1 = RB_PI * PAIR_CIRCLE_RADIUS * PAIR_CIRCLE_RADIUS;
    const double i1 = 0.5 * m1 * PAIR_CIRCLE_RADIUS * PAIR_CIRCLE_RADIUS;
    const double m2 = PAIR_SQUARE_DENSITY * 1.0;
    const double i2 = m2 * (1.0 + 1.0) / 12.0;
    const double m = m1 + m2;
    const rb_vec2 c = rb_v2((m1 * pair_circle_center.x + m2 * pair_square_center.x) / m,
                            (m1 * pair_circle_center.y + m2 * pair_square_center.y) / m);
    const rb_vec2 d1 = rb_sub(pair_circle_center, c), d2 = rb_sub(pair_square_center, c);
    const double inertia = i1 + m1 * (d1.x * d1.x + d1.y * d1.y) + i2 + m2 * (d2.x * d2.x + d2.y * d2.y);
    return (rb_mass_data){.mass = m, .center = c, .rotational_inertia = inertia};
}

static void expect_mass_data(rb_world *world, rb_body_id body, rb_mass_data expected, const char *what)
{
    const rb_mass_data data = rb_body_mass_data(world, body);
    cr_expect(fabs(data.mass - expected.mass) <= REL * expected.mass, "%s: mass %.17g, expected %.17g", what, data.mass,
              expected.mass);
    cr_expect(fabs(data.rotational_inertia - expected.rotational_inertia) <= REL * expected.rotational_inertia,
              "%s: inertia %.17g, expected %.17g", what, data.rotational_inertia, expected.rotational_inertia);
    expect_vec_near(data.center, expected.center, REL, what);
    expect_near(rb_body_mass(world, body), expected.mass, REL * expected.mass, what);
    expect_near(rb_body_rotational_inertia(world, body), expected.rotational_inertia, REL * expected.rotational_inertia,
                what);
    expect_vec_near(rb_body_local_center(world, body), expected.center, REL, what);
}

Test(mass, two_shapes_combine_by_the_parallel_axis_theorem)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    add_pair_shapes(world, body);
    expect_mass_data(world, body, pair_mass_data(), "two shapes");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, override_holds_until_reset)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const rb_vec2 origin = rb_v2(0.5, 0.5);
    const double angle = 0.25;
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, origin, angle);
    add_circle(world, body, pair_circle_center, PAIR_CIRCLE_RADIUS, 1.0);

    const rb_mass_data override = {.mass = 5.0, .center = {0.2, -0.1}, .rotational_inertia = 1.5};
    cr_assert_eq(rb_body_set_mass_data(world, body, &override), RB_OK, "%s", rb_last_error());
    expect_mass_data(world, body, override, "override");
    expect_vec_near(rb_body_world_center(world, body), place(origin, angle, override.center), REL,
                    "world centre of the override");
    /* The override is what the dynamics use. */
    const rb_vec2 impulse = rb_v2(2.0, -1.0);
    expect_ok(rb_body_apply_linear_impulse_to_center(world, body, impulse), "rb_body_apply_linear_impulse_to_center");
    expect_ok(rb_body_apply_angular_impulse(world, body, 0.6), "rb_body_apply_angular_impulse");
    expect_vec_near(rb_body_linear_velocity(world, body), rb_v2(impulse.x / 5.0, impulse.y / 5.0), REL, "J/m");
    expect_near(rb_body_angular_velocity(world, body), 0.6 / 1.5, REL, "L/I");

    /* A shape added later does not end the override... */
    rb_polygon square;
    cr_assert_eq(rb_make_offset_box(0.5, 0.5, pair_square_center, 0.0, &square), RB_OK, "%s", rb_last_error());
    rb_shape_def def = rb_default_shape_def();
    def.density = PAIR_SQUARE_DENSITY;
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_polygon(world, body, &def, &square, &shape), RB_OK, "%s", rb_last_error());
    expect_mass_data(world, body, override, "override after adding a shape");

    /* ...and a reset goes back to the mass of all the shapes. */
    cr_assert_eq(rb_body_reset_mass_data(world, body), RB_OK, "%s", rb_last_error());
    expect_mass_data(world, body, pair_mass_data(), "after reset");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, density_change_recomputes_the_mass)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    const double radius = 0.4;
    rb_shape_id shape = add_circle(world, body, rb_v2(0.0, 0.0), radius, 2.0);
    cr_assert_eq(rb_shape_set_density(world, shape, 3.0), RB_OK, "%s", rb_last_error());
    const double mass = 3.0 * RB_PI * radius * radius;
    expect_near(rb_body_mass(world, body), mass, REL * mass, "mass after rb_shape_set_density");
    expect_near(rb_body_rotational_inertia(world, body), 0.5 * mass * radius * radius, REL * mass,
                "inertia after rb_shape_set_density");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, dynamic_body_without_shapes_weighs_one_kilogram_and_does_not_turn)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    cr_expect_eq(rb_body_mass(world, body), 1.0, "body.h: a dynamic body without shapes has mass 1 kg");
    cr_expect_eq(rb_body_rotational_inertia(world, body), 0.0, "and no rotational inertia");
    const rb_vec2 force = rb_v2(0.0, 3.0);
    expect_ok(rb_body_apply_force(world, body, force, rb_v2(1.0, 0.0)), "rb_body_apply_force");
    expect_ok(rb_body_apply_torque(world, body, 2.0), "rb_body_apply_torque");
    step_world(world, TEST_DT, 1);
    expect_vec_near(rb_body_linear_velocity(world, body), rb_v2(0.0, TEST_DT * force.y), REL, "h·F/(1 kg)");
    cr_expect_eq(rb_body_angular_velocity(world, body), 0.0, "a body without inertia must not turn");
    destroy_world_and_expect_no_leak(world);
}

Test(mass, static_and_kinematic_bodies_have_zero_mass)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const rb_body_type types[] = {RB_BODY_STATIC, RB_BODY_KINEMATIC};
    for (int k = 0; k < 2; ++k) {
        rb_body_id body = make_body(world, types[k], rb_v2(0.0, 0.0), 0.0);
        add_box(world, body, BOX_HX, BOX_HY, BOX_DENSITY);
        cr_expect_eq(rb_body_mass(world, body), 0.0, "body type %d: mass %g, expected 0", (int)types[k],
                     rb_body_mass(world, body));
    }
    destroy_world_and_expect_no_leak(world);
}
