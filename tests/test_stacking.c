/* SPDX-License-Identifier: MIT */
/* Stacking: the 10-box stack and the base-20 pyramid of the benchmarks stand
 * for 10 s at 60 Hz with the default solver settings.
 *
 * Limits: "standing" is the required figure, the top box less than 1 cm
 * sideways from where it started (a stack that starts to topple leaves it
 * within a second, a fallen one by metres). No pyramid box may move more than
 * 0.25 m, the peers' threshold (docs/benchmarks.md), half a box. The
 * deepest overlap after any step must stay under 3 linear slops: position
 * correction leaves at most one slop at rest, and one step of gravity adds
 * g·dt² = 2.7 mm before the solver pushes back; a solver that lets boxes sink
 * goes past it within seconds.
 */
#include <math.h>

#include "scenes/scenes.h"
#include "test_support.h"

#define STAND_STEPS 600 /* 10 s at 60 Hz */
#define TOP_SIDEWAYS_LIMIT 0.01
#define BOX_MOVE_LIMIT 0.25
#define PENETRATION_SLOPS 3.0

/* Steps the world for 10 s and returns the deepest penetration seen after
 * any step. */
static double stand(rb_world *world)
{
    double deepest = 0.0;
    for (int n = 0; n < STAND_STEPS; ++n) {
        step_world(world, TEST_DT, 1);
        deepest = fmax(deepest, rb_world_statistics(world).max_penetration);
    }
    return deepest;
}

static void expect_shallow(const rb_world *world, double deepest)
{
    const double limit = PENETRATION_SLOPS * rb_world_solver_settings(world).linear_slop;
    cr_expect(deepest < limit, "deepest penetration %g m, limit %g m (%g linear slops)", deepest, limit,
              PENETRATION_SLOPS);
}

Test(stacking, ten_box_stack_stands_for_ten_seconds)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    scene_stack stack;
    cr_assert_eq(scene_stack_create(world, 10, &stack), RB_OK, "%s", rb_last_error());
    const rb_vec2 top0 = rb_body_position(world, stack.top);
    /* scenes.h: box i starts at (0, 0.5 + i); the top is box 9. */
    cr_assert(top0.x == 0.0 && top0.y == 9.5, "the stack's top box starts at (%g, %g)", top0.x, top0.y);

    const double deepest = stand(world);

    const rb_vec2 top = rb_body_position(world, stack.top);
    cr_expect(fabs(top.x - top0.x) < TOP_SIDEWAYS_LIMIT, "the top box moved %g m sideways (limit 1 cm)",
              fabs(top.x - top0.x));
    /* Still on top of nine boxes: each of the ten contacts below it may
     * close by a slop or two, 10·2·5 mm = 0.1 m in all; a box that fell off
     * the stack is at least 0.5 m lower. */
    cr_expect(top.y > top0.y - 0.1, "the top box sank from %g to %g m", top0.y, top.y);
    expect_shallow(world, deepest);
    destroy_world_and_expect_no_leak(world);
}

Test(stacking, base_twenty_pyramid_stands_for_ten_seconds)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 20, &pyramid), RB_OK, "%s", rb_last_error());
    cr_assert_eq(pyramid.box_count, 20 * 21 / 2, "a base-20 pyramid has 210 boxes");
    rb_vec2 start[20 * 21 / 2];
    for (int k = 0; k < pyramid.box_count; ++k) {
        const rb_body_id box = scene_body_at(pyramid.first_box, k);
        cr_assert(rb_body_is_valid(world, box), "box %d of the pyramid is not a valid body", k);
        start[k] = rb_body_position(world, box);
    }
    const rb_vec2 top0 = rb_body_position(world, pyramid.top);
    /* The single box of row 19 sits at x = 20·0.5 + 0 - 0.5·20 = 0, y = 39·0.5. */
    expect_vec_near(top0, rb_v2(0.0, 19.5), 1e-12, "the pyramid's top box starts at (0, 19.5)");

    const double deepest = stand(world);

    const rb_vec2 top = rb_body_position(world, pyramid.top);
    cr_expect(fabs(top.x - top0.x) < TOP_SIDEWAYS_LIMIT, "the top box moved %g m sideways (limit 1 cm)",
              fabs(top.x - top0.x));
    int moved = 0;
    double farthest = 0.0;
    for (int k = 0; k < pyramid.box_count; ++k) {
        const double d = rb_distance(start[k], rb_body_position(world, scene_body_at(pyramid.first_box, k)));
        farthest = fmax(farthest, d);
        moved += d > BOX_MOVE_LIMIT;
    }
    cr_expect_eq(moved, 0, "%d boxes moved more than %g m (farthest %g m)", moved, BOX_MOVE_LIMIT, farthest);
    expect_shallow(world, deepest);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Memory in the steady state ---------------------------------------------
 *
 * Once a scene has run for a while, its arrays (contacts, constraints,
 * pairs, islands) have reached their size: a step must then take no heap
 * memory at all, so that a long run never pays for the allocator or
 * fragments it. rb_allocation_count() counts every allocation the engine
 * makes. */

static void expect_no_allocation_in_steady_steps(rb_world *world, const char *what)
{
    cr_assert_eq(rb_world_enable_sleep(world, false), RB_OK, "every body stays simulated");
    step_world(world, TEST_DT, 60);
    const uint64_t before = rb_allocation_count();
    step_world(world, TEST_DT, 60);
    cr_expect_eq(rb_allocation_count(), before, "%s: %llu allocations in 60 steady steps", what,
                 (unsigned long long)(rb_allocation_count() - before));
}

Test(stacking, steady_steps_allocate_nothing)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 20, &pyramid), RB_OK, "%s", rb_last_error());
    expect_no_allocation_in_steady_steps(world, "pyramid 20");
    destroy_world_and_expect_no_leak(world);

    world = make_world(rb_v2(0.0, -10.0));
    scene_joint_grid grid;
    cr_assert_eq(scene_joint_grid_create(world, 20, &grid), RB_OK, "%s", rb_last_error());
    expect_no_allocation_in_steady_steps(world, "joint grid 20");
    destroy_world_and_expect_no_leak(world);
}

/* ---- Many pyramids (the benchmark's scale scene) ----------------------------
 *
 * scenes.h: pyramid k of `base` is centred at x = k·(base + 1), its top box
 * at height (2·base - 1)·0.5; the boxes form one run of ids, pyramid by
 * pyramid; out-of-range counts are refused with a message. The three
 * pyramids stand for 5 s with no box moved more than 0.25 m. */
Test(stacking, many_pyramids_are_laid_out_and_stand)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    scene_pyramid pyramids;
    cr_assert_eq(scene_many_pyramids_create(world, 3, 4, &pyramids), RB_OK, "%s", rb_last_error());
    cr_assert_eq(pyramids.box_count, 3 * 4 * 5 / 2, "three pyramids of base 4 have 30 boxes");
    rb_vec2 start[30];
    for (int k = 0; k < pyramids.box_count; ++k) {
        start[k] = rb_body_position(world, scene_body_at(pyramids.first_box, k));
    }
    /* Box 9 is the first pyramid's top, box 29 the last one's. */
    expect_vec_near(start[9], rb_v2(0.0, 3.5), 1e-12, "the first pyramid's top box");
    expect_vec_near(start[29], rb_v2(10.0, 3.5), 1e-12, "the last pyramid's top box");
    expect_vec_near(rb_body_position(world, pyramids.top), start[29], 0.0, "out->top is the last pyramid's top");

    step_world(world, TEST_DT, 300);
    int moved = 0;
    for (int k = 0; k < pyramids.box_count; ++k) {
        moved += rb_distance(start[k], rb_body_position(world, scene_body_at(pyramids.first_box, k))) > BOX_MOVE_LIMIT;
    }
    cr_expect_eq(moved, 0, "%d boxes of the three pyramids moved more than %g m", moved, BOX_MOVE_LIMIT);

    scene_pyramid unused;
    cr_expect_eq(scene_many_pyramids_create(world, 0, 4, &unused), RB_ERR_INVALID_ARGUMENT, "a count of 0");
    cr_expect_eq(scene_many_pyramids_create(world, 3, 101, &unused), RB_ERR_INVALID_ARGUMENT, "a base of 101");
    cr_expect_eq(scene_many_pyramids_create(NULL, 3, 4, &unused), RB_ERR_INVALID_ARGUMENT, "no world");
    destroy_world_and_expect_no_leak(world);
}
