/* SPDX-License-Identifier: MIT */
/* A heavy end on a rope: 30 links (boxes 0.5 m × 0.1 m, 0.05 kg, revolute
 * joints, no self-collision) pinned at one end, with a box of up to 1,000
 * times a link's mass at the other, at the engine's default settings.
 *
 * Solved one joint at a time, the links pass the box's pull on one joint
 * per pass, and at 700:1 and more the box's momentum tore the rope apart
 * for good (worst gap 24.7 m at 1,000:1, the box 427 m from the pin). The
 * pins of a tree are solved together (engine/src/joint_tree.h), and the
 * rope stays a rope: its length is the truth here, 30 links and the box's
 * half side, 15.25 m from the pin to the box's centre. Swinging at
 * 1,000:1 the whole rope stretches by at most 5 % at the bottom of the
 * swing (its joints' gaps add up) and closes again.
 */
#include <criterion/criterion.h>
#include <math.h>

#include "scenes/scenes.h"
#include "test_support.h"

#define LINK_MASS 0.05   /* kg: 0.5 m × 0.1 m at 1 kg/m² */
#define BOX_AREA 0.25    /* m²: the box is 0.5 m square */
#define ROPE_REACH 15.25 /* m: pin to the box's centre, pulled straight */
#define LINKS 30

typedef struct rope_run {
    double worst_gap; /* m, over every step */
    double final_gap; /* m, after the last step */
    double farthest;  /* m, the box's largest distance from the pin */
    double final_reach;
} rope_run;

static rope_run run_rope(double ratio, scene_chain_layout layout, double seconds, bool tree_pins)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.tree_pins = tree_pins;
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
    scene_chain rope;
    cr_assert_eq(scene_chain_create(world, LINKS, ratio * LINK_MASS / BOX_AREA, layout, &rope), RB_OK, "%s",
                 rb_last_error());
    rope_run run = {0};
    int steps = (int)lround(seconds * 60.0);
    for (int i = 0; i < steps; ++i) {
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
        rb_statistics stats = rb_world_statistics(world);
        run.worst_gap = fmax(run.worst_gap, stats.max_joint_gap);
        run.final_gap = stats.max_joint_gap;
        run.final_reach = rb_length(rb_body_position(world, rope.heavy));
        run.farthest = fmax(run.farthest, run.final_reach);
    }
    destroy_world_and_expect_no_leak(world);
    return run;
}

Test(rope, a_heavy_end_released_horizontal_stays_a_rope_up_to_1000_to_1)
{
    const double ratios[] = {100.0, 300.0, 600.0, 700.0, 1000.0};
    for (size_t k = 0; k < sizeof ratios / sizeof ratios[0]; ++k) {
        rope_run run = run_rope(ratios[k], SCENE_CHAIN_SWING, 10.0, true);
        cr_expect_lt(run.worst_gap, 0.2, "%g:1: worst joint gap %.3f m", ratios[k], run.worst_gap);
        cr_expect_lt(run.farthest, ROPE_REACH + 1.0, "%g:1: the box went %.2f m from the pin (the rope reaches %g m)",
                     ratios[k], run.farthest, ROPE_REACH);
        cr_expect_lt(run.final_gap, 0.02, "%g:1: gap %.4f m after 10 s", ratios[k], run.final_gap);
    }
}

Test(rope, a_heavy_end_hanging_at_rest_settles)
{
    rope_run run = run_rope(1000.0, SCENE_CHAIN_HANG, 5.0, true);
    cr_expect_lt(run.worst_gap, 0.01, "worst joint gap %.4f m", run.worst_gap);
    cr_expect_lt(run.final_gap, 1e-4, "gap %.2e m after 5 s", run.final_gap);
    expect_near(run.final_reach, ROPE_REACH, 1e-3, "the box's distance from the pin after 5 s (m)");
}

Test(rope, with_tree_pins_off_gauss_seidel_alone_lets_it_tear)
{
    /* What rb_solver_settings.tree_pins = false is for: the joints solved
     * one at a time, as before, which 1,000:1 defeats. */
    rope_run run = run_rope(1000.0, SCENE_CHAIN_SWING, 10.0, false);
    cr_expect_gt(run.worst_gap, 1.0, "worst joint gap %.3f m", run.worst_gap);
}
