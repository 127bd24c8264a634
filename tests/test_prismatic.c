/* SPDX-License-Identifier: MIT */
/* Prismatic joint: a slide on an inclined axis against the analytic
 * constant acceleration, limits, motor, spring, the locked rotation, a
 * bead on a spinning rod (the axis turning with body A), momentum and
 * angular momentum of two free bodies, the world's statistics and
 * position correction, and the API's checks.
 *
 * Unless a test says otherwise, body A is static at the origin and body B
 * a box of half-extents 0.2 × 0.1 m and density 5 (0.4 kg), its anchor
 * off its centre so the lever arms enter every row.
 */
#include <math.h>
#include <string.h>

#include "test_support.h"

#define G 9.8 /* m/s² */

static double radians(double degrees) { return degrees * RB_PI / 180.0; }

typedef struct slide {
    rb_world *world;
    rb_body_id ground, box;
    rb_joint_id joint;
    rb_vec2 axis; /* unit, world */
} slide;

/* Anchor B, in the box's frame. */
static const rb_vec2 box_anchor = {0.15, -0.05};

/* The box with its anchor on the world origin, sliding along `axis`
 * (unit) with the settings of `def` (bodies, anchors, axis and reference
 * are filled in here). */
static slide make_slide(rb_vec2 gravity, rb_vec2 axis, rb_prismatic_joint_def def)
{
    slide s = {.world = make_world(gravity), .axis = axis};
    s.ground = make_body(s.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    s.box = make_body(s.world, RB_BODY_DYNAMIC, rb_neg(box_anchor), 0.0);
    add_box(s.world, s.box, 0.2, 0.1, 5.0);
    /* The helper returns a complete definition, settings at their
     * defaults: its geometry goes into `def`. */
    rb_prismatic_joint_def at;
    cr_assert_eq(rb_prismatic_joint_def_at(&at, s.world, s.ground, s.box, rb_v2(0.0, 0.0), axis), RB_OK, "%s",
                 rb_last_error());
    def.body_a = at.body_a;
    def.body_b = at.body_b;
    def.local_anchor_a = at.local_anchor_a;
    def.local_anchor_b = at.local_anchor_b;
    def.local_axis_a = at.local_axis_a;
    def.reference_angle = at.reference_angle;
    cr_assert_eq(rb_prismatic_joint_create(s.world, &def, &s.joint), RB_OK, "%s", rb_last_error());
    return s;
}

/* Anchor B's offset from the axis (m), measured from the box's pose. */
static double off_axis(const slide *s)
{
    rb_vec2 anchor = rb_body_world_point(s->world, s->box, box_anchor);
    return rb_cross(s->axis, anchor);
}

static double along_axis(const slide *s) { return rb_dot(s->axis, rb_body_world_point(s->world, s->box, box_anchor)); }

static void set_correction(rb_world *world, rb_solver_type correction)
{
    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.type = correction;
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
}

/* ---- Free slide ---------------------------------------------------------------------- */

/* An axis 30° below +x, gravity -g·ŷ: along the axis the box feels
 * a = g·(u·(-ŷ)) = g·sin 30° = 4.9 m/s², across it nothing moves, and
 * the joint's force on the box is what cancels gravity's component
 * across the axis, m·(a·u - g). From rest s(t) = ½·a·t²; semi-implicit
 * Euler over substeps of h gives exactly ½·a·t·(t + h) (test_support.h),
 * which differs from ½·a·t² only by its first-order term ½·a·t·h, so
 * both are checked: the first to rounding (1e-9 m), the second within
 * that term. The joint rows on one box against the ground are solved
 * exactly, so anchor B stays on the axis and the box does not turn (to
 * 1e-12), with either position correction. */
Test(prismatic, inclined_slide_accelerates_at_g_along_the_axis)
{
    const rb_solver_type corrections[2] = {RB_SOLVER_NGS, RB_SOLVER_BAUMGARTE};
    for (int c = 0; c < 2; ++c) {
        const rb_vec2 axis = rb_v2(cos(radians(-30.0)), sin(radians(-30.0)));
        slide s = make_slide(rb_v2(0.0, -G), axis, rb_default_prismatic_joint_def());
        set_correction(s.world, corrections[c]);
        const double a = G * rb_dot(axis, rb_v2(0.0, -1.0));
        const double h = substep_of(s.world, TEST_DT);
        const double m = rb_body_mass(s.world, s.box);
        double worst_off = 0.0, worst_angle = 0.0, worst_gap = 0.0;
        for (int n = 1; n <= 60; ++n) {
            step_world(s.world, TEST_DT, 1);
            const double t = n * TEST_DT;
            expect_near(along_axis(&s), 0.5 * a * t * (t + h), 1e-9, "translation against ½·a·t·(t + h)");
            expect_near(along_axis(&s), 0.5 * a * t * t, 0.5 * a * t * h + 1e-9, "translation against ½·a·t²");
            expect_near(rb_prismatic_joint_translation(s.world, s.joint), along_axis(&s), 1e-12,
                        "rb_prismatic_joint_translation");
            expect_near(rb_prismatic_joint_speed(s.world, s.joint), a * t, 1e-9, "rb_prismatic_joint_speed");
            worst_off = fmax(worst_off, fabs(off_axis(&s)));
            worst_angle = fmax(worst_angle, fabs(rb_body_angle(s.world, s.box)));
            worst_gap = fmax(worst_gap, rb_world_statistics(s.world).max_joint_gap);
        }
        cr_expect(worst_off <= 1e-12, "anchor B left the axis by %g m (correction %d)", worst_off, c);
        cr_expect(worst_angle <= 1e-12, "the box turned by %g rad (correction %d)", worst_angle, c);
        cr_expect(worst_gap <= 1e-12, "max_joint_gap reached %g m (correction %d)", worst_gap, c);
        const rb_vec2 expected = rb_scale(m, rb_sub(rb_scale(a, axis), rb_v2(0.0, -G)));
        expect_vec_near(rb_joint_reaction_force(s.world, s.joint), expected, 1e-9 * m * G, "normal force on the box");
        destroy_world_and_expect_no_leak(s.world);
    }
}

/* ---- Limits ---------------------------------------------------------------------------- */

/* The box is launched at 20 m/s along the axis (30° above +x) towards a
 * limit 0.5 m away, gravity helping or not: the speculative limit lets it
 * arrive and no further, at every step within the linear slop. After 2 s
 * it rests on the limit within the slop, and the joint carries its whole
 * weight: the force on the box is (0, m·g) (1e-6 relative). With only one
 * side enabled the other is free: launched the other way the box passes
 * -0.5 m and beyond, decelerating at exactly g·sin 30° (1e-9). */
static void check_limit(bool lower)
{
    const rb_vec2 axis = rb_v2(cos(radians(30.0)), sin(radians(30.0)));
    rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
    def.enable_lower_limit = lower;
    def.enable_upper_limit = !lower;
    def.lower_translation = -0.5;
    def.upper_translation = 0.5;
    /* Gravity pulls towards the limit: down the slope for the lower one,
     * and for the upper one the world is turned upside down. */
    slide s = make_slide(rb_v2(0.0, lower ? -G : G), axis, def);
    const double sign = lower ? -1.0 : 1.0;
    cr_assert_eq(rb_body_set_linear_velocity(s.world, s.box, rb_scale(20.0 * sign, axis)), RB_OK, "%s",
                 rb_last_error());
    const double slop = rb_world_solver_settings(s.world).linear_slop;
    double worst = 0.0;
    for (int n = 0; n < 120; ++n) {
        step_world(s.world, TEST_DT, 1);
        worst = fmax(worst, sign * along_axis(&s) - 0.5);
    }
    cr_expect(worst <= slop, "the box passed the %s limit by %g m", lower ? "lower" : "upper", worst);
    expect_near(along_axis(&s), 0.5 * sign, slop, "resting on the limit");
    expect_near(rb_prismatic_joint_speed(s.world, s.joint), 0.0, 1e-6, "speed at rest");
    const double weight = rb_body_mass(s.world, s.box) * G;
    expect_vec_near(rb_joint_reaction_force(s.world, s.joint), rb_v2(0.0, -sign * weight), 1e-6 * weight,
                    "the joint carries the weight");
    cr_expect(rb_world_statistics(s.world).max_joint_gap <= slop, "max_joint_gap %g m at rest on the limit",
              rb_world_statistics(s.world).max_joint_gap);

    /* Launched away from the limit: nothing holds it on the other side. */
    cr_assert_eq(rb_body_set_linear_velocity(s.world, s.box, rb_scale(-10.0 * sign, axis)), RB_OK, "%s",
                 rb_last_error());
    step_world(s.world, TEST_DT, 1);
    double speed = rb_prismatic_joint_speed(s.world, s.joint);
    for (int n = 0; n < 30; ++n) {
        step_world(s.world, TEST_DT, 1);
        const double next = rb_prismatic_joint_speed(s.world, s.joint);
        expect_near((next - speed) / TEST_DT, G * sin(radians(30.0)) * sign, 1e-9, "free deceleration");
        speed = next;
    }
    cr_expect(sign * along_axis(&s) < -0.5, "the box did not pass the disabled side (at %g m)", along_axis(&s));
    destroy_world_and_expect_no_leak(s.world);
}

Test(prismatic, lower_limit_alone_stops_the_slide) { check_limit(true); }

Test(prismatic, upper_limit_alone_stops_the_slide) { check_limit(false); }

/* ---- Motor ------------------------------------------------------------------------------- */

/* Zero gravity, axis +x. With ample force (100 N) the motor drives the
 * box to 2 m/s within a step (an axial row on one box is solved exactly)
 * and then, unloaded, gives no force (1e-9 relative). */
Test(prismatic, motor_reaches_its_speed_when_its_force_suffices)
{
    rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
    def.enable_motor = true;
    def.motor_speed = 2.0;
    def.max_motor_force = 100.0;
    slide s = make_slide(rb_v2(0.0, 0.0), rb_v2(1.0, 0.0), def);
    step_world(s.world, TEST_DT, 60);
    expect_near(rb_prismatic_joint_speed(s.world, s.joint), 2.0, 2e-9, "slide speed");
    expect_vec_near(rb_body_linear_velocity(s.world, s.box), rb_v2(2.0, 0.0), 2e-9, "box velocity");
    expect_near(rb_prismatic_joint_motor_force(s.world, s.joint), 0.0, 1e-9 * 100.0, "unloaded motor force");
    destroy_world_and_expect_no_leak(s.world);
}

/* Target 100 m/s with 0.5 N on the 0.4 kg box: the motor saturates and
 * the box accelerates at a = F/m = 1.25 m/s², measured from the velocity
 * of consecutive steps (1e-9 relative), while rb_prismatic_joint_motor_force
 * reports F. With the world's gravity along the axis (-g·x̂) too, the
 * motor's bound still holds: a = F/m - g. */
Test(prismatic, motor_force_bounds_the_acceleration)
{
    const double force = 0.5;
    const double gravities[2] = {0.0, G};
    for (int k = 0; k < 2; ++k) {
        rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
        def.enable_motor = true;
        def.motor_speed = 100.0;
        def.max_motor_force = force;
        slide s = make_slide(rb_v2(-gravities[k], 0.0), rb_v2(1.0, 0.0), def);
        const double m = rb_body_mass(s.world, s.box);
        const double a = force / m - gravities[k];
        step_world(s.world, TEST_DT, 10);
        double v = rb_body_linear_velocity(s.world, s.box).x;
        for (int n = 0; n < 3; ++n) {
            step_world(s.world, TEST_DT, 1);
            const double next = rb_body_linear_velocity(s.world, s.box).x;
            expect_near((next - v) / TEST_DT, a, 1e-9 * fmax(fabs(a), 1.0), "acceleration F/m - g");
            expect_near(rb_prismatic_joint_motor_force(s.world, s.joint), force, 1e-9 * force, "motor force");
            v = next;
        }
        cr_assert_eq(rb_prismatic_joint_set_motor(s.world, s.joint, false, 0.0, 0.0), RB_OK, "%s", rb_last_error());
        step_world(s.world, TEST_DT, 1);
        expect_near(rb_prismatic_joint_motor_force(s.world, s.joint), 0.0, 0.0, "motor force once disabled");
        destroy_world_and_expect_no_leak(s.world);
    }
}

/* ---- Spring ------------------------------------------------------------------------------- */

/* Zero gravity, axis +x, the box released at translation 0.2 m with a
 * 2 Hz undamped spring. The spring acts on the axial effective mass,
 * here the box's mass (the axial row's lever arm about B's centre is
 * rB × u, and with A static the angular row takes the rest), so the box
 * oscillates at 2 Hz: timed over 5 periods between zero crossings,
 * within 1 % (the implicit spring's frequency error at h = 1/360 s is of
 * order (ω·h)², 0.1 %). */
Test(prismatic, spring_oscillates_at_its_frequency)
{
    rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
    slide s = make_slide(rb_v2(0.0, 0.0), rb_v2(1.0, 0.0), def);
    cr_assert_eq(rb_prismatic_joint_set_spring(s.world, s.joint, true, 2.0, 0.0), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_transform(s.world, s.box, rb_add(rb_neg(box_anchor), rb_v2(0.2, 0.0)), 0.0), RB_OK, "%s",
                 rb_last_error());
    double previous = 0.2, first = 0.0, last = 0.0;
    int crossings = 0;
    for (int n = 1; n <= 4 * 60 && crossings < 11; ++n) {
        step_world(s.world, TEST_DT, 1);
        const double x = along_axis(&s);
        if ((previous > 0.0) != (x > 0.0)) {
            last = (n - 1) * TEST_DT + TEST_DT * previous / (previous - x);
            first = crossings == 0 ? last : first;
            ++crossings;
        }
        previous = x;
    }
    cr_assert_eq(crossings, 11, "the translation crossed zero %d times in 4 s, expected 11", crossings);
    expect_near(5.0 / (last - first), 2.0, 0.01 * 2.0, "spring frequency (Hz)");
    destroy_world_and_expect_no_leak(s.world);
}

/* ---- Rotation locked ----------------------------------------------------------------------- */

/* Zero gravity, axis +x, the box sliding at 1 m/s while a torque of
 * 3 N·m acts on it every step: the joint's angular row holds the angle
 * (1e-12 rad) and returns exactly the torque (the force at anchor B is 0,
 * so the reaction torque is -3 N·m, 1e-9 relative), and the slide goes
 * on at 1 m/s untouched (1e-12). */
Test(prismatic, rotation_stays_locked_under_a_torque)
{
    slide s = make_slide(rb_v2(0.0, 0.0), rb_v2(1.0, 0.0), rb_default_prismatic_joint_def());
    cr_assert_eq(rb_body_set_linear_velocity(s.world, s.box, rb_v2(1.0, 0.0)), RB_OK, "%s", rb_last_error());
    const double torque = 3.0;
    double worst_angle = 0.0;
    for (int n = 0; n < 60; ++n) {
        cr_assert_eq(rb_body_apply_torque(s.world, s.box, torque), RB_OK, "%s", rb_last_error());
        step_world(s.world, TEST_DT, 1);
        worst_angle = fmax(worst_angle, fabs(rb_body_angle(s.world, s.box)));
        worst_angle = fmax(worst_angle, rb_world_statistics(s.world).max_joint_angle_error);
    }
    cr_expect(worst_angle <= 1e-12, "the box turned by %g rad", worst_angle);
    expect_near(rb_joint_reaction_torque(s.world, s.joint), -torque, 1e-9 * torque, "reaction torque");
    expect_vec_near(rb_joint_reaction_force(s.world, s.joint), rb_v2(0.0, 0.0), 1e-9 * torque, "reaction force");
    expect_vec_near(rb_body_linear_velocity(s.world, s.box), rb_v2(1.0, 0.0), 1e-12, "slide velocity");
    expect_near(rb_prismatic_joint_speed(s.world, s.joint), 1.0, 1e-12, "rb_prismatic_joint_speed");
    destroy_world_and_expect_no_leak(s.world);
}

/* ---- The axis turns with body A ---------------------------------------------------------- */

/* A bead on a spinning rod: body A kinematic, turning at ω = 2 rad/s
 * about its origin, body B a ball on the axis through that origin,
 * released 0.1 m out, moving with the rod (radial speed 0). Free along
 * the rod, the bead's distance obeys r'' = ω²·r (the centrifugal term of
 * the radial equation), so r(t) = r0·cosh(ω·t), while across the rod the
 * joint supplies the Coriolis force m·2·ω·ṙ and keeps the bead turning
 * with it (Goldstein, Classical Mechanics, §3.1). Over 1 s (r grows 3.8
 * fold) at 60 Hz, r stays within 1 % of r0·cosh(ω·t) (the integrator's
 * first-order error; it halves with twice the substeps), and likewise
 * its speed ṙ = r0·ω·sinh(ω·t) (the getter, which includes ωA × u), the bead within
 * the slop of the axis, and its angle that of the rod. */
Test(prismatic, bead_on_a_spinning_rod_moves_out_as_cosh)
{
    const double omega = 2.0, r0 = 0.1;
    double errors[2];
    for (int k = 0; k < 2; ++k) {
        rb_world *world = make_world(rb_v2(0.0, 0.0));
        set_substeps(world, 6 * (k + 1));
        rb_body_def rod_def = rb_default_body_def();
        rod_def.type = RB_BODY_KINEMATIC;
        rod_def.angular_velocity = omega;
        rb_body_id rod;
        cr_assert_eq(rb_body_create(world, &rod_def, &rod), RB_OK, "%s", rb_last_error());
        rb_body_id bead = make_body(world, RB_BODY_DYNAMIC, rb_v2(r0, 0.0), 0.0);
        add_circle(world, bead, rb_v2(0.0, 0.0), 0.02, 1.0);
        cr_assert_eq(rb_body_set_linear_velocity(world, bead, rb_v2(0.0, omega * r0)), RB_OK, "%s", rb_last_error());
        cr_assert_eq(rb_body_set_angular_velocity(world, bead, omega), RB_OK, "%s", rb_last_error());
        rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
        def.body_a = rod;
        def.body_b = bead;
        def.local_anchor_b = rb_v2(0.0, 0.0);
        def.local_anchor_a = rb_v2(0.0, 0.0);
        def.local_axis_a = rb_v2(3.0, 0.0);
        rb_joint_id joint;
        cr_assert_eq(rb_prismatic_joint_create(world, &def, &joint), RB_OK, "%s", rb_last_error());
        const double slop = rb_world_solver_settings(world).linear_slop;
        double worst = 0.0;
        for (int n = 1; n <= 60; ++n) {
            step_world(world, TEST_DT, 1);
            const double t = n * TEST_DT;
            const double r = rb_prismatic_joint_translation(world, joint);
            worst = fmax(worst, fabs(r / (r0 * cosh(omega * t)) - 1.0));
            worst = fmax(worst, fabs(rb_prismatic_joint_speed(world, joint) / (r0 * omega * sinh(omega * t)) - 1.0));
            cr_expect(rb_world_statistics(world).max_joint_gap <= slop, "bead off the rod by %g m at t = %g s",
                      rb_world_statistics(world).max_joint_gap, t);
        }
        expect_near(rb_body_angle(world, bead), rb_body_angle(world, rod), RB_PI / 360.0, "bead turns with the rod");
        errors[k] = worst;
        destroy_world_and_expect_no_leak(world);
    }
    cr_expect(errors[0] <= 0.01, "r or ṙ is off by %.3g (relative)", errors[0]);
    cr_expect(errors[1] <= 0.6 * errors[0], "the error does not shrink with the substep: %.3g, then %.3g", errors[0],
              errors[1]);
}

/* ---- Two free bodies ------------------------------------------------------------------------ */

/* L = Σ m·(c × v) + I·ω about the origin (kg·m²/s), and the momentum. */
static double angular_momentum(const rb_world *world, const rb_body_id *bodies, int count)
{
    double total = 0.0;
    for (int i = 0; i < count; ++i) {
        total += rb_body_mass(world, bodies[i]) *
                     rb_cross(rb_body_world_center(world, bodies[i]), rb_body_linear_velocity(world, bodies[i])) +
                 rb_body_rotational_inertia(world, bodies[i]) * rb_body_angular_velocity(world, bodies[i]);
    }
    return total;
}

static rb_vec2 momentum(const rb_world *world, const rb_body_id *bodies, int count)
{
    rb_vec2 total = rb_v2(0.0, 0.0);
    for (int i = 0; i < count; ++i) {
        total = rb_mul_add(total, rb_body_mass(world, bodies[i]), rb_body_linear_velocity(world, bodies[i]));
    }
    return total;
}

/* Two dynamic boxes in zero gravity, B sliding on A's axis with a 3 Hz
 * spring, a motor and both limits, the pair tumbling (A at 2 rad/s, B
 * thrown along and across). The joint's impulses are internal: +P at
 * anchor B on B and -P on A acting at the same world point (A's lever arm
 * is d + rA, which ends at anchor B), and ±L, so momentum and angular
 * momentum about any point are conserved to rounding (1e-9 relative over
 * 2 s); with A's arm taken as rA instead, the joint's force would exert a
 * net torque d × P on the pair. The drift is removed by Baumgarte's
 * velocity bias, itself such an internal impulse; NGS would move the
 * bodies without their velocities, changing L by m·Δc × v. Meanwhile
 * anchor B stays on the axis and the pair's angle locked, within the
 * slops. */
Test(prismatic, two_free_bodies_conserve_momentum_and_angular_momentum)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    set_correction(world, RB_SOLVER_BAUMGARTE);
    rb_body_id a = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.3);
    add_box(world, a, 0.5, 0.1, 2.0);
    rb_body_id b = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.4, 0.2), 0.3);
    add_box(world, b, 0.2, 0.1, 5.0);
    rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
    cr_assert_eq(rb_prismatic_joint_def_at(&def, world, a, b, rb_v2(0.3, 0.1), rb_v2(1.0, 0.5)), RB_OK, "%s",
                 rb_last_error());
    def.enable_spring = true;
    def.spring_hertz = 3.0;
    def.spring_damping_ratio = 0.1;
    def.enable_motor = true;
    def.motor_speed = 0.5;
    def.max_motor_force = 0.2;
    def.enable_lower_limit = def.enable_upper_limit = true;
    def.lower_translation = -0.3;
    def.upper_translation = 0.3;
    rb_joint_id joint;
    cr_assert_eq(rb_prismatic_joint_create(world, &def, &joint), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_angular_velocity(world, a, 2.0), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_linear_velocity(world, b, rb_v2(3.0, -1.0)), RB_OK, "%s", rb_last_error());
    const rb_body_id bodies[2] = {a, b};
    step_world(world, TEST_DT, 1);
    const double l0 = angular_momentum(world, bodies, 2);
    const rb_vec2 p0 = momentum(world, bodies, 2);
    const rb_solver_settings settings = rb_world_solver_settings(world);
    double worst_gap = 0.0, worst_angle = 0.0;
    for (int n = 0; n < 120; ++n) {
        step_world(world, TEST_DT, 1);
        expect_near(angular_momentum(world, bodies, 2), l0, 1e-9 * fabs(l0), "angular momentum");
        expect_vec_near(momentum(world, bodies, 2), p0, 1e-9 * rb_length(p0), "momentum");
        worst_gap = fmax(worst_gap, rb_world_statistics(world).max_joint_gap);
        worst_angle = fmax(worst_angle, rb_world_statistics(world).max_joint_angle_error);
    }
    cr_expect(worst_gap <= settings.linear_slop, "anchor B off the axis or past a limit by %g m", worst_gap);
    cr_expect(worst_angle <= RB_PI / 360.0, "the pair's angle drifted by %g rad", worst_angle);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Statistics and position correction ---------------------------------------------------- */

/* The joint made with the box 0.3 m off the axis, turned by 0.2 rad and
 * 0.4 m below a lower limit at -0.1 m, in zero gravity. Without position
 * passes (NGS with 0 iterations) the velocity rows only keep the errors
 * from growing, and the statistics report them as they are: the gap is
 * the larger of the offset and the limit violation, max(0.3, 0.4) m, the
 * angle error 0.2 rad (1e-12). With the default NGS pass, or with
 * Baumgarte, the errors are then removed within 1 s: the gap within the
 * slop, the angle within half a degree. */
Test(prismatic, statistics_report_and_correction_removes_the_errors)
{
    const rb_solver_type corrections[2] = {RB_SOLVER_NGS, RB_SOLVER_BAUMGARTE};
    for (int c = 0; c < 2; ++c) {
        rb_world *world = make_world(rb_v2(0.0, 0.0));
        rb_solver_settings settings = rb_world_solver_settings(world);
        settings.position_iterations = 0;
        settings.type = RB_SOLVER_NGS;
        cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
        rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
        rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(-0.5, 0.3), 0.2);
        add_box(world, box, 0.2, 0.1, 5.0);
        rb_prismatic_joint_def def = rb_default_prismatic_joint_def();
        def.body_a = ground;
        def.body_b = box;
        def.enable_lower_limit = true;
        def.lower_translation = -0.1;
        rb_joint_id joint;
        cr_assert_eq(rb_prismatic_joint_create(world, &def, &joint), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
        expect_near(rb_world_statistics(world).max_joint_gap, 0.4, 1e-12, "max_joint_gap before correction");
        expect_near(rb_world_statistics(world).max_joint_angle_error, 0.2, 1e-12, "angle error before correction");

        settings = rb_default_solver_settings();
        settings.type = corrections[c];
        cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 60);
        const rb_statistics stats = rb_world_statistics(world);
        cr_expect(stats.max_joint_gap <= settings.linear_slop, "gap %g m after 1 s (correction %d)",
                  stats.max_joint_gap, c);
        cr_expect(stats.max_joint_angle_error <= RB_PI / 360.0, "angle error %g rad after 1 s (correction %d)",
                  stats.max_joint_angle_error, c);
        cr_expect(rb_prismatic_joint_translation(world, joint) >= -0.1 - settings.linear_slop,
                  "translation %g m, below the lower limit", rb_prismatic_joint_translation(world, joint));
        destroy_world_and_expect_no_leak(world);
    }
}

/* ---- API --------------------------------------------------------------------------------------- */

static void expect_status(rb_status status, rb_status expected, const char *what)
{
    cr_expect_eq(status, expected, "%s: returned %s, expected %s", what, rb_status_name(status),
                 rb_status_name(expected));
    cr_expect_eq(rb_last_status(), expected, "%s: rb_last_status() is %s", what, rb_status_name(rb_last_status()));
    cr_expect(rb_last_error()[0] != '\0', "%s: no error message", what);
}

/* Every bad definition and setter value is refused, the message naming
 * the function and the argument; getters of a joint of another type or of
 * a destroyed joint return 0 with an error; the defaults are as the
 * header says; the type, bodies, anchors and normalised axis are kept. */
Test(prismatic, invalid_arguments_are_refused)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(1.0, 0.0), 0.0);
    add_box(world, box, 0.2, 0.1, 5.0);
    rb_joint_id joint;

    const rb_prismatic_joint_def defaults = rb_default_prismatic_joint_def();
    cr_expect(defaults.local_axis_a.x == 1.0 && defaults.local_axis_a.y == 0.0, "default axis (1, 0)");
    cr_expect(!defaults.enable_lower_limit && !defaults.enable_upper_limit && !defaults.enable_motor &&
                  !defaults.enable_spring && !defaults.collide_connected,
              "defaults enable nothing");

    rb_prismatic_joint_def good = defaults;
    good.body_a = ground;
    good.body_b = box;
    rb_prismatic_joint_def d = good;
    expect_status(rb_prismatic_joint_create(world, NULL, &joint), RB_ERR_INVALID_ARGUMENT, "NULL def");
    expect_status(rb_prismatic_joint_create(world, &d, NULL), RB_ERR_INVALID_ARGUMENT, "NULL out");
    expect_status(rb_prismatic_joint_create(NULL, &d, &joint), RB_ERR_INVALID_ARGUMENT, "NULL world");
    d.body_b = ground;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "same body twice");
    d = good;
    d.local_axis_a = rb_v2(0.0, 0.0);
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "zero axis");
    cr_expect(strstr(rb_last_error(), "rb_prismatic_joint_create") && strstr(rb_last_error(), "local_axis_a"),
              "message names the function and the argument: %s", rb_last_error());
    d.local_axis_a = rb_v2(NAN, 1.0);
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "NaN axis");
    d = good;
    d.reference_angle = INFINITY;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "infinite reference");
    d = good;
    d.enable_lower_limit = d.enable_upper_limit = true;
    d.lower_translation = 0.5;
    d.upper_translation = -0.5;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "lower > upper");
    cr_expect(strstr(rb_last_error(), "lower_translation") != NULL, "message: %s", rb_last_error());
    d = good;
    d.max_motor_force = -1.0;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "force < 0");
    d = good;
    d.motor_speed = NAN;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "speed NaN");
    d = good;
    d.spring_hertz = -1.0;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "hertz < 0");
    d = good;
    d.spring_damping_ratio = NAN;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "damping NaN");
    d = good;
    d.local_anchor_b.y = INFINITY;
    expect_status(rb_prismatic_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "anchor infinite");
    expect_status(rb_prismatic_joint_def_at(&d, world, ground, box, rb_v2(0.0, 0.0), rb_v2(0.0, 0.0)),
                  RB_ERR_INVALID_ARGUMENT, "rb_prismatic_joint_def_at, zero axis");
    expect_status(rb_prismatic_joint_def_at(NULL, world, ground, box, rb_v2(0.0, 0.0), rb_v2(1.0, 0.0)),
                  RB_ERR_INVALID_ARGUMENT, "rb_prismatic_joint_def_at, NULL def");
    cr_expect_eq(rb_world_statistics(world).joint_count, 0, "a refused joint was created");

    /* A body turned by 0.5 rad: the world axis (0, 2) becomes a unit
     * axis in its frame; the anchor lies where given. */
    cr_assert_eq(rb_body_set_transform(world, box, rb_v2(1.0, 0.0), 0.5), RB_OK, "%s", rb_last_error());
    d = good;
    d.body_a = box;
    d.body_b = ground;
    cr_assert_eq(rb_prismatic_joint_def_at(&d, world, box, ground, rb_v2(1.0, 1.0), rb_v2(0.0, 2.0)), RB_OK, "%s",
                 rb_last_error());
    expect_vec_near(d.local_axis_a, rb_v2(sin(0.5), cos(0.5)), 1e-15, "local axis of the turned body");
    expect_near(d.reference_angle, -0.5, 1e-15, "reference angle");
    cr_assert_eq(rb_prismatic_joint_create(world, &d, &joint), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_joint_type_of(world, joint), RB_JOINT_PRISMATIC, "type");
    expect_vec_near(rb_joint_world_anchor_a(world, joint), rb_v2(1.0, 1.0), 1e-15, "world anchor A");
    expect_vec_near(rb_joint_world_anchor_b(world, joint), rb_v2(1.0, 1.0), 1e-15, "world anchor B");
    expect_near(rb_prismatic_joint_translation(world, joint), 0.0, 1e-15, "translation 0 where made");

    expect_status(rb_prismatic_joint_set_limits(world, joint, true, 1.0, true, 0.0), RB_ERR_INVALID_ARGUMENT,
                  "set_limits, lower > upper");
    expect_status(rb_prismatic_joint_set_limits(world, joint, true, NAN, false, 0.0), RB_ERR_INVALID_ARGUMENT,
                  "set_limits, NaN");
    expect_status(rb_prismatic_joint_set_motor(world, joint, true, 1.0, -2.0), RB_ERR_INVALID_ARGUMENT,
                  "set_motor, force < 0");
    expect_status(rb_prismatic_joint_set_spring(world, joint, true, INFINITY, 0.0), RB_ERR_INVALID_ARGUMENT,
                  "set_spring, hertz infinite");
    cr_expect_eq(rb_prismatic_joint_set_limits(world, joint, true, 1.0, false, 0.0), RB_OK,
                 "one side's limit may lie above the unused other: %s", rb_last_error());

    /* Another type's joint. */
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(5.0, 0.0), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.1, 1.0);
    rb_joint_id pin = make_pin(world, ground, ball, rb_v2(5.0, 1.0));
    expect_status(rb_prismatic_joint_set_motor(world, pin, true, 1.0, 1.0), RB_ERR_INVALID_ARGUMENT,
                  "set_motor on a revolute joint");
    expect_near(rb_prismatic_joint_translation(world, pin), 0.0, 0.0, "translation of a revolute joint");
    cr_expect_eq(rb_last_status(), RB_ERR_INVALID_ARGUMENT, "translation of a revolute joint: %s",
                 rb_status_name(rb_last_status()));

    /* Destroyed. */
    step_world(world, TEST_DT, 2);
    cr_assert_eq(rb_joint_destroy(world, joint), RB_OK, "%s", rb_last_error());
    cr_expect(!rb_joint_is_valid(world, joint), "destroyed joint still valid");
    expect_status(rb_joint_destroy(world, joint), RB_ERR_STALE_ID, "destroying twice");
    expect_near(rb_prismatic_joint_speed(world, joint), 0.0, 0.0, "speed of a destroyed joint");
    cr_expect_eq(rb_last_status(), RB_ERR_STALE_ID, "speed of a destroyed joint: %s", rb_status_name(rb_last_status()));
    expect_near(rb_prismatic_joint_motor_force(world, joint), 0.0, 0.0, "motor force of a destroyed joint");
    expect_status(rb_prismatic_joint_set_spring(world, joint, true, 1.0, 0.0), RB_ERR_STALE_ID,
                  "set_spring on a destroyed joint");
    step_world(world, TEST_DT, 1);
    cr_expect_eq(rb_world_statistics(world).joint_count, 1, "joints left: %d, expected 1",
                 rb_world_statistics(world).joint_count);
    destroy_world_and_expect_no_leak(world);
}
