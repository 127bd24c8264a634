/* SPDX-License-Identifier: MIT */
/* Pulley joint: the Atwood machine and its geared form against their
 * analytic accelerations, balanced loads at rest, the rope going slack
 * when a body is lifted, a body stopping at its pulley, the world's
 * statistics, and the API's checks.
 *
 * The machine: pulleys at gA = (-1, 3) and gB = (1, 3) m, balls of radius
 * 0.1 m hanging 3 m below them, each rope side attached at the ball's
 * centre, in gravity -g·ŷ. With y the balls' heights, l_a = 3 - y_a and
 * l_b = 3 - y_b.
 *
 * Geared Atwood machine (the analytic truth). The rope keeps
 * C = constant - l_a - r·l_b >= 0; taut, l_a + r·l_b is constant, so
 * ÿ_a = -r·ÿ_b. The constraint force is the tension T times ∂C/∂y:
 * T on A and r·T on B, both upwards (virtual work). Newton:
 *   m_a·ÿ_a = T - m_a·g,   m_b·ÿ_b = r·T - m_b·g.
 * Substituting T = m_a·(g + ÿ_a) = m_a·(g - r·ÿ_b) in the second,
 *   ÿ_b = g·(r·m_a - m_b)/(m_b + r²·m_a),   ÿ_a = -r·ÿ_b.
 * For r = 1 this is the Atwood machine, ÿ_a = g·(m_b - m_a)/(m_a + m_b),
 * and the loads balance (rest) when m_b = r·m_a.
 */
#include <math.h>
#include <string.h>

#include "test_support.h"

#define G 9.8 /* m/s² */

typedef struct machine {
    rb_world *world;
    rb_body_id a, b;
    rb_joint_id rope;
    double m_a, m_b; /* kg */
} machine;

static const rb_vec2 ground_a = {-1.0, 3.0};
static const rb_vec2 ground_b = {1.0, 3.0};

static rb_body_id make_ball(rb_world *world, rb_vec2 position, double density)
{
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, position, 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.1, density);
    return ball;
}

/* The machine with balls of the given densities and the rope just taut. */
static machine make_machine(double density_a, double density_b, double ratio, double min_length)
{
    machine m = {.world = make_world(rb_v2(0.0, -G))};
    m.a = make_ball(m.world, rb_v2(-1.0, 0.0), density_a);
    m.b = make_ball(m.world, rb_v2(1.0, 0.0), density_b);
    m.m_a = rb_body_mass(m.world, m.a);
    m.m_b = rb_body_mass(m.world, m.b);
    rb_pulley_joint_def def = rb_default_pulley_joint_def();
    cr_assert_eq(
        rb_pulley_joint_def_between(&def, m.world, m.a, m.b, ground_a, ground_b, rb_v2(-1.0, 0.0), rb_v2(1.0, 0.0)),
        RB_OK, "%s", rb_last_error());
    def.ratio = ratio;
    def.min_length = min_length;
    cr_assert_eq(rb_pulley_joint_create(m.world, &def, &m.rope), RB_OK, "%s", rb_last_error());
    return m;
}

static double height(const machine *m, rb_body_id body) { return rb_body_world_center(m->world, body).y; }

/* The machine runs for 1 s from rest; the accelerations are constant,
 * so semi-implicit Euler moves each ball exactly ½·a·t·(t + h)
 * (test_support.h), to rounding (1e-9 m); ½·a·t² differs from it by the
 * method's first-order term ½·a·t·h. The rope's length l_a + r·l_b stays
 * at its constant (1e-9 m), the length getters follow the balls (1e-12),
 * and the joint's force on B is r·T upwards, T = m_a·(g + ÿ_a) (1e-9
 * relative). */
static void check_geared_atwood(double density_a, double density_b, double ratio)
{
    machine m = make_machine(density_a, density_b, ratio, 0.05);
    const double acc_b = G * (ratio * m.m_a - m.m_b) / (m.m_b + ratio * ratio * m.m_a);
    const double acc_a = -ratio * acc_b;
    const double tension = m.m_a * (G + acc_a);
    const double h = substep_of(m.world, TEST_DT);
    const double constant = 3.0 + ratio * 3.0;
    for (int n = 1; n <= 60; ++n) {
        step_world(m.world, TEST_DT, 1);
        const double t = n * TEST_DT;
        expect_near(height(&m, m.a), step_displacement(acc_a, t, h), 1e-9, "ball A against ½·a·t·(t + h)");
        expect_near(height(&m, m.b), step_displacement(acc_b, t, h), 1e-9, "ball B against ½·a·t·(t + h)");
        expect_near(height(&m, m.a), 0.5 * acc_a * t * t, 0.5 * fabs(acc_a) * t * h + 1e-9, "ball A against ½·a·t²");
        const double length_a = rb_pulley_joint_length_a(m.world, m.rope);
        const double length_b = rb_pulley_joint_length_b(m.world, m.rope);
        expect_near(length_a, 3.0 - height(&m, m.a), 1e-12, "rb_pulley_joint_length_a");
        expect_near(length_b, 3.0 - height(&m, m.b), 1e-12, "rb_pulley_joint_length_b");
        expect_near(length_a + ratio * length_b, constant, 1e-9, "l_a + r·l_b");
    }
    expect_vec_near(rb_joint_reaction_force(m.world, m.rope), rb_v2(0.0, ratio * tension), 1e-9 * ratio * tension,
                    "the rope's pull on B");
    expect_near(rb_joint_reaction_torque(m.world, m.rope), 0.0, 0.0, "a rope's torque");
    cr_expect(rb_world_statistics(m.world).max_joint_gap <= 1e-9, "max_joint_gap %g m",
              rb_world_statistics(m.world).max_joint_gap);
    destroy_world_and_expect_no_leak(m.world);
}

/* m_b = 3·m_a, ratio 1: ÿ_a = g/2 upwards, B down as fast. */
Test(pulley, atwood_machine_accelerates_at_g_times_mass_difference_over_sum) { check_geared_atwood(10.0, 30.0, 1.0); }

/* Equal masses, ratio 2: ÿ_b = g·(2 - 1)/(1 + 4) = g/5 upwards and
 * ÿ_a = -2·g/5: B, pulled twice as hard, rises. */
Test(pulley, geared_atwood_machine_conserves_l_a_plus_ratio_times_l_b) { check_geared_atwood(20.0, 20.0, 2.0); }

/* Balanced loads: equal masses on ratio 1, and m_b = 2·m_a on ratio 2,
 * stay at rest (1e-12 m over 2 s), the rope carrying each weight: the
 * force on B is (0, m_b·g) (1e-9 relative). */
Test(pulley, balanced_loads_stay_at_rest)
{
    const double ratios[2] = {1.0, 2.0};
    for (int k = 0; k < 2; ++k) {
        machine m = make_machine(10.0, 10.0 * ratios[k], ratios[k], 0.05);
        step_world(m.world, TEST_DT, 120);
        expect_near(height(&m, m.a), 0.0, 1e-12, "ball A at rest");
        expect_near(height(&m, m.b), 0.0, 1e-12, "ball B at rest");
        const double weight = m.m_b * G;
        expect_vec_near(rb_joint_reaction_force(m.world, m.rope), rb_v2(0.0, weight), 1e-9 * weight,
                        "the rope carries B");
        destroy_world_and_expect_no_leak(m.world);
    }
}

/* Balanced equal masses, then A is thrown up at 3 m/s. The rope cannot
 * push: while l_a + l_b < constant both balls fly freely, A at 3 - g·t
 * and B falling from rest at -g·t (1e-12), with no force on B. The rope
 * is taut again when A's rise 3·t - ½·g·t² equals B's fall ½·g·t², at
 * t = 3/g = 0.306 s; the first 15 steps (0.25 s) are slack. Then the
 * rope catches them and stays within the slop of its length. */
Test(pulley, rope_goes_slack_when_a_body_is_lifted)
{
    machine m = make_machine(10.0, 10.0, 1.0, 0.05);
    step_world(m.world, TEST_DT, 30);
    cr_assert_eq(rb_body_set_linear_velocity(m.world, m.a, rb_v2(0.0, 3.0)), RB_OK, "%s", rb_last_error());
    for (int n = 1; n <= 15; ++n) {
        step_world(m.world, TEST_DT, 1);
        const double t = n * TEST_DT;
        expect_vec_near(rb_body_linear_velocity(m.world, m.a), rb_v2(0.0, 3.0 - G * t), 1e-12, "A flies freely");
        expect_vec_near(rb_body_linear_velocity(m.world, m.b), rb_v2(0.0, -G * t), 1e-12, "B falls freely");
        expect_vec_near(rb_joint_reaction_force(m.world, m.rope), rb_v2(0.0, 0.0), 1e-12, "a slack rope's force");
        cr_expect(rb_pulley_joint_length_a(m.world, m.rope) + rb_pulley_joint_length_b(m.world, m.rope) < 6.0,
                  "the rope is not slack at step %d", n);
    }
    const double slop = rb_world_solver_settings(m.world).linear_slop;
    double worst = 0.0;
    for (int n = 0; n < 60; ++n) {
        step_world(m.world, TEST_DT, 1);
        worst = fmax(worst, rb_world_statistics(m.world).max_joint_gap);
    }
    cr_expect(worst <= slop, "the rope stretched by %g m once caught", worst);
    expect_near(rb_pulley_joint_length_a(m.world, m.rope) + rb_pulley_joint_length_b(m.world, m.rope), 6.0, slop,
                "the rope is taut again");
    destroy_world_and_expect_no_leak(m.world);
}

/* m_b = 3·m_a: B pulls A up to its pulley, where A stops min_length =
 * 0.5 m below it (reached after ½·(g/2)·t² = 2.5 m, t = 1.01 s, at
 * 5 m/s). It never comes nearer than the slop, and after 3 s both balls
 * rest: A at the stop, B at l_b = 6 - 0.5 m, the joint carrying B's
 * weight (force on B (0, m_b·g), 1e-6 relative). */
Test(pulley, a_body_stops_at_its_pulley)
{
    machine m = make_machine(10.0, 30.0, 1.0, 0.5);
    const double slop = rb_world_solver_settings(m.world).linear_slop;
    double nearest = INFINITY, worst_gap = 0.0;
    for (int n = 0; n < 180; ++n) {
        step_world(m.world, TEST_DT, 1);
        nearest = fmin(nearest, rb_pulley_joint_length_a(m.world, m.rope));
        worst_gap = fmax(worst_gap, rb_world_statistics(m.world).max_joint_gap);
    }
    cr_expect(nearest >= 0.5 - slop, "A came %g m near its pulley, min_length 0.5 m", nearest);
    cr_expect(worst_gap <= slop, "max_joint_gap reached %g m", worst_gap);
    expect_near(rb_pulley_joint_length_a(m.world, m.rope), 0.5, slop, "A at its stop");
    expect_near(rb_pulley_joint_length_b(m.world, m.rope), 5.5, slop, "B where the rope holds it");
    expect_vec_near(rb_body_linear_velocity(m.world, m.a), rb_v2(0.0, 0.0), 1e-6, "A at rest");
    expect_vec_near(rb_body_linear_velocity(m.world, m.b), rb_v2(0.0, 0.0), 1e-6, "B at rest");
    const double weight = m.m_b * G;
    expect_vec_near(rb_joint_reaction_force(m.world, m.rope), rb_v2(0.0, weight), 1e-6 * weight, "the joint carries B");
    destroy_world_and_expect_no_leak(m.world);
}

/* The statistics report a rope made too long as it is, without position
 * passes: the rope def says 2 + 2 m while the balls hang 3 m below their
 * pulleys, so in zero gravity (nothing moves) the gap is 6 - 4 = 2 m
 * (1e-12). With the default NGS pass, or with Baumgarte, the rope is
 * then pulled in within 2 s, to the slop. */
Test(pulley, statistics_report_and_correction_shortens_the_rope)
{
    const rb_solver_type corrections[2] = {RB_SOLVER_NGS, RB_SOLVER_BAUMGARTE};
    for (int c = 0; c < 2; ++c) {
        rb_world *world = make_world(rb_v2(0.0, 0.0));
        rb_solver_settings settings = rb_world_solver_settings(world);
        settings.position_iterations = 0;
        cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
        rb_body_id a = make_ball(world, rb_v2(-1.0, 0.0), 10.0);
        rb_body_id b = make_ball(world, rb_v2(1.0, 0.0), 10.0);
        rb_pulley_joint_def def = rb_default_pulley_joint_def();
        def.body_a = a;
        def.body_b = b;
        def.ground_anchor_a = ground_a;
        def.ground_anchor_b = ground_b;
        def.length_a = def.length_b = 2.0;
        rb_joint_id rope;
        cr_assert_eq(rb_pulley_joint_create(world, &def, &rope), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
        expect_near(rb_world_statistics(world).max_joint_gap, 2.0, 1e-12, "gap of a rope 2 m too long");
        expect_near(rb_world_statistics(world).max_joint_angle_error, 0.0, 0.0, "a rope has no angle error");

        settings = rb_default_solver_settings();
        settings.type = corrections[c];
        cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 120);
        cr_expect(rb_world_statistics(world).max_joint_gap <= settings.linear_slop,
                  "gap %g m after 2 s (correction %d)", rb_world_statistics(world).max_joint_gap, c);
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

/* Every bad definition is refused, the message naming the function and
 * the argument; the length getters of another type's joint or of a
 * destroyed joint return 0 with an error; destroying the joint frees the
 * balls (they then fall freely). */
Test(pulley, invalid_arguments_are_refused)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id a = make_ball(world, rb_v2(-1.0, 0.0), 10.0);
    rb_body_id b = make_ball(world, rb_v2(1.0, 0.0), 10.0);
    rb_joint_id joint;

    const rb_pulley_joint_def defaults = rb_default_pulley_joint_def();
    cr_expect(defaults.ratio == 1.0 && defaults.min_length == 0.05, "defaults ratio 1, min_length 0.05 m");
    rb_pulley_joint_def good = defaults;
    good.body_a = a;
    good.body_b = b;
    good.ground_anchor_a = ground_a;
    good.ground_anchor_b = ground_b;
    good.length_a = good.length_b = 3.0;
    rb_pulley_joint_def d = good;
    expect_status(rb_pulley_joint_create(world, NULL, &joint), RB_ERR_INVALID_ARGUMENT, "NULL def");
    expect_status(rb_pulley_joint_create(world, &d, NULL), RB_ERR_INVALID_ARGUMENT, "NULL out");
    d.body_b = a;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "same body twice");
    const double bad_ratios[3] = {0.0, -1.0, NAN};
    for (int i = 0; i < 3; ++i) {
        d = good;
        d.ratio = bad_ratios[i];
        expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "ratio <= 0 or NaN");
        cr_expect(strstr(rb_last_error(), "rb_pulley_joint_create") && strstr(rb_last_error(), "ratio"),
                  "message names the function and the argument: %s", rb_last_error());
    }
    d = good;
    d.min_length = 0.0;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "min_length 0");
    d = good;
    d.length_a = 0.01;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "length_a < min_length");
    cr_expect(strstr(rb_last_error(), "length_a") != NULL, "message: %s", rb_last_error());
    d = good;
    d.length_b = INFINITY;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "length_b infinite");
    d = good;
    d.ratio = 1e308;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "constant overflows");
    d = good;
    d.ground_anchor_b.x = NAN;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "ground anchor NaN");
    d = good;
    d.local_anchor_a.y = INFINITY;
    expect_status(rb_pulley_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "local anchor infinite");
    expect_status(
        rb_pulley_joint_def_between(&d, world, a, b, rb_v2(NAN, 0.0), ground_b, rb_v2(0.0, 0.0), rb_v2(0.0, 0.0)),
        RB_ERR_INVALID_ARGUMENT, "rb_pulley_joint_def_between, ground anchor NaN");
    expect_status(rb_pulley_joint_def_between(NULL, world, a, b, ground_a, ground_b, rb_v2(0.0, 0.0), rb_v2(0.0, 0.0)),
                  RB_ERR_INVALID_ARGUMENT, "rb_pulley_joint_def_between, NULL def");
    cr_expect_eq(rb_world_statistics(world).joint_count, 0, "a refused joint was created");

    cr_assert_eq(rb_pulley_joint_create(world, &good, &joint), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_joint_type_of(world, joint), RB_JOINT_PULLEY, "type");
    expect_vec_near(rb_joint_world_anchor_a(world, joint), rb_v2(-1.0, 0.0), 1e-15, "anchor A");
    expect_vec_near(rb_joint_world_anchor_b(world, joint), rb_v2(1.0, 0.0), 1e-15, "anchor B");

    rb_body_id other = make_ball(world, rb_v2(5.0, 0.0), 1.0);
    rb_joint_id pin = make_pin(world, b, other, rb_v2(3.0, 0.0));
    expect_near(rb_pulley_joint_length_a(world, pin), 0.0, 0.0, "length of a revolute joint");
    cr_expect_eq(rb_last_status(), RB_ERR_INVALID_ARGUMENT, "length of a revolute joint: %s",
                 rb_status_name(rb_last_status()));
    cr_assert_eq(rb_joint_destroy(world, pin), RB_OK, "%s", rb_last_error());

    step_world(world, TEST_DT, 10);
    cr_assert_eq(rb_joint_destroy(world, joint), RB_OK, "%s", rb_last_error());
    expect_status(rb_joint_destroy(world, joint), RB_ERR_STALE_ID, "destroying twice");
    expect_near(rb_pulley_joint_length_b(world, joint), 0.0, 0.0, "length of a destroyed joint");
    cr_expect_eq(rb_last_status(), RB_ERR_STALE_ID, "length of a destroyed joint: %s",
                 rb_status_name(rb_last_status()));
    const rb_vec2 v = rb_body_linear_velocity(world, a);
    step_world(world, TEST_DT, 1);
    expect_vec_near(rb_body_linear_velocity(world, a), rb_add(v, rb_v2(0.0, -G * TEST_DT)), 1e-12,
                    "the freed ball falls");
    destroy_world_and_expect_no_leak(world);
}
