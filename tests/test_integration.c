/* SPDX-License-Identifier: MIT */
/* Time integration of free bodies: free fall and projectiles against the
 * closed form of semi-implicit Euler, gravity scale, substeps, damping,
 * kinematic, static and fixed-rotation bodies.
 *
 * Semi-implicit Euler with step h, v_{k+1} = v_k + h·g then
 * x_{k+1} = x_k + h·v_{k+1}, gives after n steps (t = n·h)
 *     v_n = v0 + g·t,   x_n = x0 + v0·t + h·g·(1 + 2 + ... + n)·h
 *                           = x0 + v0·t + ½·g·t·(t + h),
 * which is ahead of the exact x0 + v0·t + ½·g·t² by exactly ½·g·h·t.
 *
 * Tolerance: the engine reaches x_n by n additions, each rounding to
 * 1.1e-16 of the running value; for n <= 240 the error stays below 1e-13
 * of the size of the terms (|x0| + |v0|·t + ½·|g|·t·(t + h)), so
 * REL = 1e-12 of that size is a wide margin, while a wrong scheme (explicit
 * Euler, a substep missed) is off by ½·g·h·t, about 1e-2 of it.
 */
#include <math.h>

#include "test_support.h"

#define REL 1e-12

/* The models' gravity, -9.8 m/s², plus a sideways part so that both axes
 * are checked. */
static const rb_vec2 gravity = {0.5, -9.8};

typedef struct launch {
    rb_vec2 position, velocity; /* of the centre of mass */
    double angle, omega;
    double gravity_scale;
    int substeps;
} launch;

/* Checks one axis after n steps (t = n·dt, substep h) against the closed
 * form: x and v to REL of the size of their terms, and x within ½·|g|·h·t
 * of the continuous motion. */
static void check_axis(int n, const char *axis, double x, double v, double x0, double v0, double g, double t, double h)
{
    const double scale = fabs(x0) + fabs(v0) * t + 0.5 * fabs(g) * t * (t + h);
    const double euler = x0 + v0 * t + 0.5 * g * t * (t + h);
    cr_expect(fabs(x - euler) <= REL * scale, "step %d, %s: x = %.17g, semi-implicit Euler gives %.17g", n, axis, x,
              euler);
    const double v_expected = v0 + g * t;
    cr_expect(fabs(v - v_expected) <= REL * (fabs(v0) + fabs(g) * t),
              "step %d, %s: v = %.17g, expected v0 + g·t = %.17g", n, axis, v, v_expected);
    const double exact = x0 + v0 * t + 0.5 * g * t * t;
    cr_expect(fabs(x - exact) <= 0.5 * fabs(g) * h * t + REL * scale,
              "step %d, %s: x = %.17g is %g from the exact %.17g, more than ½·g·h·t = %g", n, axis, x, fabs(x - exact),
              exact, 0.5 * fabs(g) * h * t);
}

/* Flies a circle for one second of 60 Hz steps and checks its pose and
 * velocities after every step. */
static void fly(launch l)
{
    rb_world *world = make_world(gravity);
    set_substeps(world, l.substeps);
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = l.position;
    def.angle = l.angle;
    def.linear_velocity = l.velocity;
    def.angular_velocity = l.omega;
    def.gravity_scale = l.gravity_scale;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_circle(world, body, rb_v2(0.0, 0.0), 0.1, 1.0);

    const double h = TEST_DT / l.substeps;
    const rb_vec2 g = rb_scale(l.gravity_scale, gravity);
    for (int n = 1; n <= 60; ++n) {
        step_world(world, TEST_DT, 1);
        const double t = n * TEST_DT;
        const rb_vec2 x = rb_body_position(world, body);
        const rb_vec2 v = rb_body_linear_velocity(world, body);
        check_axis(n, "x", x.x, v.x, l.position.x, l.velocity.x, g.x, t, h);
        check_axis(n, "y", x.y, v.y, l.position.y, l.velocity.y, g.y, t, h);
        /* No torque: ω stays, and the angle grows as θ0 + ω·t. */
        cr_expect_eq(rb_body_angular_velocity(world, body), l.omega, "step %d: ω changed", n);
        expect_near(rb_body_angle(world, body), l.angle + l.omega * t, REL * (fabs(l.angle) + fabs(l.omega) * t),
                    "angle θ0 + ω·t");
    }
    destroy_world_and_expect_no_leak(world);
}

Test(integration, free_fall_from_rest) { fly((launch){.position = {0.5, 10.0}, .gravity_scale = 1.0, .substeps = 1}); }

Test(integration, projectile_with_spin)
{
    fly((launch){.position = {1.0, 2.0},
                 .velocity = {3.0, 6.0},
                 .angle = 0.25,
                 .omega = 2.0,
                 .gravity_scale = 1.0,
                 .substeps = 1});
}

Test(integration, projectile_with_gravity_scale)
{
    fly((launch){.position = {1.0, 2.0}, .velocity = {3.0, 6.0}, .gravity_scale = 0.5, .substeps = 1});
    fly((launch){.position = {-2.0, 1.0}, .velocity = {-1.0, 0.5}, .gravity_scale = -1.5, .substeps = 1});
}

Test(integration, projectile_with_substeps)
{
    fly((launch){.position = {1.0, 2.0},
                 .velocity = {3.0, 6.0},
                 .angle = -1.0,
                 .omega = -3.0,
                 .gravity_scale = 1.0,
                 .substeps = 4});
    fly((launch){.position = {1.0, 2.0}, .velocity = {3.0, 6.0}, .gravity_scale = 0.5, .substeps = 3});
}

Test(integration, gravity_scale_setter)
{
    rb_world *world = make_world(gravity);
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    add_circle(world, body, rb_v2(0.0, 0.0), 0.1, 1.0);
    cr_assert_eq(rb_body_set_gravity_scale(world, body, 2.0), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_body_gravity_scale(world, body), 2.0, "gravity scale getter");
    step_world(world, TEST_DT, 1);
    expect_vec_near(rb_body_linear_velocity(world, body), rb_scale(2.0 * TEST_DT, gravity), REL * 20.0 * TEST_DT,
                    "one step at twice the gravity");
    /* Scale 0: the body keeps its velocity exactly. */
    cr_assert_eq(rb_body_set_gravity_scale(world, body, 0.0), RB_OK, "%s", rb_last_error());
    const rb_vec2 v = rb_body_linear_velocity(world, body);
    step_world(world, TEST_DT, 5);
    const rb_vec2 after = rb_body_linear_velocity(world, body);
    cr_expect(after.x == v.x && after.y == v.y, "with gravity scale 0 the velocity changed");
    destroy_world_and_expect_no_leak(world);
}

Test(integration, force_acts_during_every_substep)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    const int substeps = 4;
    set_substeps(world, substeps);
    const rb_vec2 x0 = rb_v2(1.0, -1.0);
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, x0, 0.0);
    add_circle(world, body, rb_v2(0.0, 0.0), 0.5, 2.0);
    const double mass = 2.0 * RB_PI * 0.25;
    const rb_vec2 force = rb_v2(3.0, 1.0);
    cr_assert_eq(rb_body_apply_force_to_center(world, body, force), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 1);
    /* The force acts on all four substeps: after the step v = dt·F/m and,
     * by the closed form above with t = dt, x = x0 + ½·a·dt·(dt + h). */
    const double h = TEST_DT / substeps;
    const rb_vec2 a = rb_scale(1.0 / mass, force);
    expect_vec_near(rb_body_linear_velocity(world, body), rb_scale(TEST_DT, a), REL * rb_length(a) * TEST_DT,
                    "velocity after a step of 4 substeps");
    expect_vec_near(rb_body_position(world, body), rb_mul_add(x0, 0.5 * TEST_DT * (TEST_DT + h), a), REL * 2.0,
                    "position after a step of 4 substeps");
    destroy_world_and_expect_no_leak(world);
}

/* body.h: every (sub)step of length h divides the velocities by (1 + h·c),
 * so after N substeps v = v0/(1 + h·c)^N. N divisions round N times, at
 * most 240·1.1e-16 = 3e-14 relative here: REL is wide. */
static void check_damping(int substeps)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    set_substeps(world, substeps);
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.linear_velocity = rb_v2(3.0, -1.5);
    def.angular_velocity = 4.0;
    def.linear_damping = 2.0;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_circle(world, body, rb_v2(0.0, 0.0), 0.5, 1.0);
    /* The angular damping through the setter, the linear through the def. */
    const double angular_damping = 0.5;
    cr_assert_eq(rb_body_set_angular_damping(world, body, angular_damping), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_body_linear_damping(world, body), def.linear_damping, "linear damping getter");
    cr_expect_eq(rb_body_angular_damping(world, body), angular_damping, "angular damping getter");

    const double h = TEST_DT / substeps;
    for (int n = 1; n <= 60; ++n) {
        step_world(world, TEST_DT, 1);
        const double linear = pow(1.0 + h * def.linear_damping, -(double)(n * substeps));
        const double angular = pow(1.0 + h * angular_damping, -(double)(n * substeps));
        const rb_vec2 v = rb_body_linear_velocity(world, body);
        cr_expect(fabs(v.x - def.linear_velocity.x * linear) <= REL * fabs(def.linear_velocity.x * linear) &&
                      fabs(v.y - def.linear_velocity.y * linear) <= REL * fabs(def.linear_velocity.y * linear),
                  "substeps %d, step %d: v = (%.17g, %.17g), expected v0/(1 + h·c)^%d = (%.17g, %.17g)", substeps, n,
                  v.x, v.y, n * substeps, def.linear_velocity.x * linear, def.linear_velocity.y * linear);
        const double omega = rb_body_angular_velocity(world, body);
        const double omega_expected = def.angular_velocity * angular;
        cr_expect(fabs(omega - omega_expected) <= REL * omega_expected,
                  "substeps %d, step %d: ω = %.17g, expected ω0/(1 + h·c)^%d = %.17g", substeps, n, omega, n * substeps,
                  omega_expected);
    }
    destroy_world_and_expect_no_leak(world);
}

Test(integration, damping_divides_by_one_plus_h_c_each_step) { check_damping(1); }

Test(integration, damping_divides_by_one_plus_h_c_each_substep) { check_damping(4); }

Test(integration, kinematic_body_moves_at_constant_velocity_and_ignores_gravity)
{
    rb_world *world = make_world(gravity);
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_KINEMATIC;
    def.position = rb_v2(-1.0, 3.0);
    def.angle = 0.1;
    def.linear_velocity = rb_v2(1.5, -0.5);
    def.angular_velocity = 0.8;
    /* Damping is a drag on dynamic bodies: a kinematic body given some
     * keeps its velocity all the same. */
    def.linear_damping = 2.0;
    def.angular_damping = 3.0;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_box(world, body, 0.5, 0.5, 1.0);
    for (int n = 1; n <= 60; ++n) {
        step_world(world, TEST_DT, 1);
        const double t = n * TEST_DT;
        const rb_vec2 x = rb_body_position(world, body);
        const rb_vec2 v = rb_body_linear_velocity(world, body);
        cr_expect(v.x == def.linear_velocity.x && v.y == def.linear_velocity.y &&
                      rb_body_angular_velocity(world, body) == def.angular_velocity,
                  "step %d: a kinematic body's velocity changed", n);
        /* The closed form with g = 0: x0 + v·t, and no lag behind it. */
        check_axis(n, "x", x.x, v.x, def.position.x, def.linear_velocity.x, 0.0, t, TEST_DT);
        check_axis(n, "y", x.y, v.y, def.position.y, def.linear_velocity.y, 0.0, t, TEST_DT);
        expect_near(rb_body_angle(world, body), def.angle + def.angular_velocity * t,
                    REL * (def.angle + def.angular_velocity * t), "angle θ0 + ω·t");
    }
    destroy_world_and_expect_no_leak(world);
}

Test(integration, kinematic_body_pushes_a_dynamic_body_without_slowing)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_KINEMATIC;
    def.position = rb_v2(-2.0, 0.0);
    def.linear_velocity = rb_v2(2.0, 0.0);
    rb_body_id pusher;
    cr_assert_eq(rb_body_create(world, &def, &pusher), RB_OK, "%s", rb_last_error());
    add_box(world, pusher, 0.5, 0.5, 1.0);
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.25, 1.0);
    /* The box's face reaches the ball (gap 2 - 0.5 - 0.25 = 1.25 m at
     * 2 m/s) after 0.625 s; one second is 22 steps later. */
    step_world(world, TEST_DT, 60);
    const rb_vec2 v = rb_body_linear_velocity(world, pusher);
    cr_expect(v.x == 2.0 && v.y == 0.0, "the kinematic body's velocity changed to (%.17g, %.17g)", v.x, v.y);
    expect_near(rb_body_position(world, pusher).x, -2.0 + 2.0 * 1.0, REL * 4.0, "kinematic x0 + v·t");
    /* An infinite mass pushing with restitution 0 leaves the ball moving at
     * its own speed along the normal: 2 m/s, up to the 1 % an iterative
     * solver may leave. */
    expect_near(rb_body_linear_velocity(world, ball).x, 2.0, 0.02, "ball pushed at the kinematic body's speed");
    destroy_world_and_expect_no_leak(world);
}

Test(integration, static_body_never_moves)
{
    rb_world *world = make_world(gravity);
    const rb_vec2 p0 = rb_v2(1.0, 2.0);
    const double angle0 = 0.2;
    rb_body_id ground = make_body(world, RB_BODY_STATIC, p0, angle0);
    add_box(world, ground, 2.0, 0.5, 1.0);
    /* A heavy box lands on it and stays (the slope, tan 0.2 = 0.2, is
     * below the friction 0.6), so it is pushed as well as pulled by
     * gravity. */
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(1.0, 3.5), angle0);
    add_box(world, box, 0.25, 0.25, 5.0);
    step_world(world, TEST_DT, 120);
    const rb_vec2 p = rb_body_position(world, ground);
    cr_expect(p.x == p0.x && p.y == p0.y && rb_body_angle(world, ground) == angle0,
              "the static body moved to (%.17g, %.17g, %.17g)", p.x, p.y, rb_body_angle(world, ground));
    const rb_vec2 v = rb_body_linear_velocity(world, ground);
    cr_expect(v.x == 0.0 && v.y == 0.0 && rb_body_angular_velocity(world, ground) == 0.0,
              "the static body has a velocity");
    /* Resting on the top face, whose middle is 0.5/cos 0.2 = 0.51 m above
     * the centre: the box's centre is about 0.76 m above it. */
    cr_expect(rb_body_position(world, box).y > p0.y + 0.5, "the box must rest on the static body, not fall through");
    destroy_world_and_expect_no_leak(world);
}

Test(integration, fixed_rotation_keeps_omega_zero)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.angle = 0.3;
    def.fixed_rotation = true;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_box(world, body, 1.0, 0.5, 2.0);
    cr_expect(rb_body_is_fixed_rotation(world, body), "fixed rotation getter");
    const double mass = 2.0 * 2.0 * 1.0;
    const rb_vec2 force = rb_v2(0.0, 4.0);
    for (int n = 1; n <= 10; ++n) {
        /* At the box's right end, 1 m from the centre: 4 N·m of torque. */
        cr_assert_eq(rb_body_apply_force(world, body, force, rb_body_world_point(world, body, rb_v2(1.0, 0.0))), RB_OK,
                     "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
        cr_expect_eq(rb_body_angular_velocity(world, body), 0.0, "step %d: a fixed-rotation body turns", n);
        cr_expect_eq(rb_body_angle(world, body), def.angle, "step %d: a fixed-rotation body's angle changed", n);
        /* It still translates as a free body: v = n·h·F/m. */
        expect_near(rb_body_linear_velocity(world, body).y, n * TEST_DT * force.y / mass, REL, "v = n·h·F/m");
    }
    cr_assert_eq(
        rb_body_apply_linear_impulse(world, body, rb_v2(1.0, 0.0), rb_body_world_point(world, body, rb_v2(0.0, 0.5))),
        RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_body_angular_velocity(world, body), 0.0, "an off-centre impulse turns a fixed-rotation body");
    destroy_world_and_expect_no_leak(world);
}

/* ---- Turning a pose ----------------------------------------------------------
 *
 * The solvers turn a body by composing its rotation with the rotation by a
 * small angle whose cosine and sine come from a Taylor series
 * (rb_body_state_turn, world_internal.h). Against the library's cos and sin
 * of the new angle, over 100 turns (more than a step makes: 6 substeps of
 * a few passes each): within 5e-14 for the small angles the series covers
 * (the roundings of 100 products; measured up to 5e-15), and exact for a
 * larger turn (the library's own values). The world resets every rotation
 * from its angle after each step. */
#include "world_internal.h"

Test(integration, small_turns_compose_to_the_rotation_of_the_angle)
{
    static const double deltas[] = {0.0, 1e-9, -3e-6, 1e-3, -0.01, 0.03125, -0.03125};
    for (size_t k = 0; k < sizeof deltas / sizeof deltas[0]; ++k) {
        rb_body_state state = {.angle = 0.7, .rotation = rb_rot_from_angle(0.7)};
        double worst = 0.0;
        for (int n = 0; n < 100; ++n) {
            rb_body_state_turn(&state, deltas[k]);
            rb_rot exact = rb_rot_from_angle(state.angle);
            worst = fmax(worst, fmax(fabs(state.rotation.c - exact.c), fabs(state.rotation.s - exact.s)));
        }
        cr_expect(worst < 5e-14, "turns of %g rad: rotation off cos/sin of the angle by %g after 100", deltas[k],
                  worst);
    }
    rb_body_state state = {.angle = 0.7, .rotation = rb_rot_from_angle(0.7)};
    rb_body_state_turn(&state, 0.5);
    rb_rot exact = rb_rot_from_angle(1.2);
    cr_expect(state.rotation.c == exact.c && state.rotation.s == exact.s,
              "a large turn takes cos and sin of the angle");
}
