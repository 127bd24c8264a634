/* SPDX-License-Identifier: MIT */
/* Every solver variant (rb_solver_type: Baumgarte, NGS, soft step) at the
 * engine's default iterations and substeps, on the stacking, pyramid and pendulum tests' scenes:
 * a 10-box stack and the base-20 pyramid stand, a pendulum keeps the
 * period of the elliptic integral, and two runs of a scene end in the
 * same bits.
 *
 * Limits: standing as in test_stacking.c (the top box within 1 cm
 * sideways, no pyramid box moved 0.25 m). The pendulum: a 1 m simple
 * pendulum released at 30°, its period over five periods at 60 Hz against
 * T = 4·√(I_pivot/(m·g·L))·K(sin(θ₀/2)) with GSL's complete elliptic
 * integral. Measured: 2e-6 relative for Baumgarte and NGS, 7e-6 for the
 * soft step, whose pin is a 60 Hz spring (it stretches by g/ω², 0.07 mm,
 * under the bob's weight). The bar, 5e-5, is seven times the worst of
 * them: a pin that stretched 0.1 mm more would lengthen the period by
 * δ/2L = 5e-5 and fail.
 */
#include <gsl/gsl_sf_ellint.h>
#include <math.h>

#include "scenes/scenes.h"
#include "test_support.h"

#define STAND_STEPS 600 /* 10 s at 60 Hz */
#define TOP_SIDEWAYS_LIMIT 0.01
#define BOX_MOVE_LIMIT 0.25
#define PERIOD_TOLERANCE 5e-5
#define G 9.8

static rb_world *make_world_with(rb_solver_type type, rb_vec2 gravity)
{
    rb_world *world = make_world(gravity);
    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.type = type;
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
    return world;
}

static void check_stack_stands(rb_solver_type type)
{
    const char *name = rb_solver_type_name(type);
    rb_world *world = make_world_with(type, rb_default_world_def().gravity);
    scene_stack stack;
    cr_assert_eq(scene_stack_create(world, 10, &stack), RB_OK, "%s", rb_last_error());
    const rb_vec2 top0 = rb_body_position(world, stack.top);
    step_world(world, TEST_DT, STAND_STEPS);
    const rb_vec2 top = rb_body_position(world, stack.top);
    cr_expect(fabs(top.x - top0.x) < TOP_SIDEWAYS_LIMIT, "%s: the stack's top box moved %g m sideways", name,
              fabs(top.x - top0.x));
    cr_expect(top.y > top0.y - 0.1, "%s: the stack's top box sank from %g to %g m", name, top0.y, top.y);
    destroy_world_and_expect_no_leak(world);
}

static void check_pyramid_stands(rb_solver_type type)
{
    const char *name = rb_solver_type_name(type);
    rb_world *world = make_world_with(type, rb_default_world_def().gravity);
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 20, &pyramid), RB_OK, "%s", rb_last_error());
    rb_vec2 start[20 * 21 / 2];
    for (int k = 0; k < pyramid.box_count; ++k) {
        start[k] = rb_body_position(world, scene_body_at(pyramid.first_box, k));
    }
    step_world(world, TEST_DT, STAND_STEPS);
    int moved = 0;
    for (int k = 0; k < pyramid.box_count; ++k) {
        moved += rb_distance(start[k], rb_body_position(world, scene_body_at(pyramid.first_box, k))) > BOX_MOVE_LIMIT;
    }
    cr_expect_eq(moved, 0, "%s: %d boxes of the pyramid moved more than %g m", name, moved, BOX_MOVE_LIMIT);
    destroy_world_and_expect_no_leak(world);
}

/* θ: the bob's angle from the downward vertical through the pivot. */
static double swing_angle(const rb_world *world, rb_body_id bob)
{
    const rb_vec2 c = rb_body_world_center(world, bob);
    return atan2(c.x, -c.y);
}

static void check_pendulum_period(rb_solver_type type)
{
    const char *name = rb_solver_type_name(type);
    const double L = 1.0, r = 0.05, rho = 100.0, theta0 = 30.0 * RB_PI / 180.0;
    rb_world *world = make_world_with(type, rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(L * sin(theta0), -L * cos(theta0)), theta0);
    add_circle(world, bob, rb_v2(0.0, 0.0), r, rho);
    make_pin(world, ground, bob, rb_v2(0.0, 0.0));
    const double m = rho * RB_PI * r * r;
    const double pivot_inertia = 0.5 * m * r * r + m * L * L;
    const double exact =
        4.0 * sqrt(pivot_inertia / (m * G * L)) * gsl_sf_ellint_Kcomp(sin(0.5 * theta0), GSL_PREC_DOUBLE);

    /* Ten zero crossings of θ, each placed by linear interpolation. */
    const int half_periods = 10;
    double previous = swing_angle(world, bob);
    double first = 0.0, last = 0.0;
    int crossings = 0;
    const int max_steps = (int)ceil(2.0 * (half_periods + 1) * exact / TEST_DT);
    for (int n = 1; n <= max_steps && crossings <= half_periods; ++n) {
        step_world(world, TEST_DT, 1);
        const double theta = swing_angle(world, bob);
        if ((previous > 0.0) != (theta > 0.0)) {
            const double t = (n - 1) * TEST_DT + TEST_DT * previous / (previous - theta);
            first = crossings == 0 ? t : first;
            last = t;
            ++crossings;
        }
        previous = theta;
    }
    cr_assert_eq(crossings, half_periods + 1, "%s: θ crossed zero %d times", name, crossings);
    const double period = 2.0 * (last - first) / half_periods;
    cr_expect(fabs(period - exact) <= PERIOD_TOLERANCE * exact, "%s: period %.6f s, exact %.6f s (relative %.2g)", name,
              period, exact, (period - exact) / exact);
    destroy_world_and_expect_no_leak(world);
}

/* Two runs of a pyramid and a joint grid from the same start. */
static uint64_t run_scene_hash(rb_solver_type type, bool grid)
{
    rb_world *world = make_world_with(type, rb_v2(0.0, -10.0));
    if (grid) {
        scene_joint_grid joint_grid;
        cr_assert_eq(scene_joint_grid_create(world, 10, &joint_grid), RB_OK, "%s", rb_last_error());
    } else {
        scene_pyramid pyramid;
        cr_assert_eq(scene_pyramid_create(world, 10, &pyramid), RB_OK, "%s", rb_last_error());
    }
    step_world(world, TEST_DT, 120);
    const uint64_t hash = rb_world_state_hash(world);
    destroy_world_and_expect_no_leak(world);
    return hash;
}

static void check_determinism(rb_solver_type type)
{
    for (int grid = 0; grid < 2; ++grid) {
        cr_expect_eq(run_scene_hash(type, grid), run_scene_hash(type, grid), "%s: two runs of the %s differ",
                     rb_solver_type_name(type), grid ? "joint grid" : "pyramid");
    }
}

Test(solver_variants, baumgarte_stacks) { check_stack_stands(RB_SOLVER_BAUMGARTE); }
Test(solver_variants, ngs_stacks) { check_stack_stands(RB_SOLVER_NGS); }
Test(solver_variants, soft_step_stacks) { check_stack_stands(RB_SOLVER_SOFT_STEP); }
Test(solver_variants, baumgarte_pyramid_stands) { check_pyramid_stands(RB_SOLVER_BAUMGARTE); }
Test(solver_variants, ngs_pyramid_stands) { check_pyramid_stands(RB_SOLVER_NGS); }
Test(solver_variants, soft_step_pyramid_stands) { check_pyramid_stands(RB_SOLVER_SOFT_STEP); }
Test(solver_variants, baumgarte_pendulum_period) { check_pendulum_period(RB_SOLVER_BAUMGARTE); }
Test(solver_variants, ngs_pendulum_period) { check_pendulum_period(RB_SOLVER_NGS); }
Test(solver_variants, soft_step_pendulum_period) { check_pendulum_period(RB_SOLVER_SOFT_STEP); }
Test(solver_variants, baumgarte_is_deterministic) { check_determinism(RB_SOLVER_BAUMGARTE); }
Test(solver_variants, ngs_is_deterministic) { check_determinism(RB_SOLVER_NGS); }
Test(solver_variants, soft_step_is_deterministic) { check_determinism(RB_SOLVER_SOFT_STEP); }
