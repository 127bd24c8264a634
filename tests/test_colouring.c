/* SPDX-License-Identifier: MIT */
/* Graph colouring of the contact constraints (constraint_colouring.c):
 * the rules on small graphs worked by hand, the layout a world's step
 * leaves, and what it is for: the peers' base-100 pyramid holds, no box
 * moving more than 0.25 m sideways in 6 s, with the default solver and
 * with the soft step, at the default passes and at Box2D v3's budget (4
 * substeps of one solve and one relax pass), where Box2D v3 holds it too
 * (before colouring, 49 boxes moved there; before the feature ids
 * survived a change of reference face, 3,878). */
#include "constraint_colouring.h"
#include "contact_solver.h"
#include "scenes/scenes.h"
#include "test_support.h"

#define FIXED -1

Test(colouring, a_chain_alternates_and_the_ground_takes_the_top_colour)
{
    /* Bodies 0-1-2-3 in a chain, then each of 0 and 1 against the ground. */
    rb_colouring colouring = {0};
    cr_assert_eq(rb_colouring_begin(&colouring, 4), 0);
    cr_expect_eq(rb_colouring_assign(&colouring, 0, 1), 0);
    cr_expect_eq(rb_colouring_assign(&colouring, 1, 2), 1, "body 1 is in colour 0 already");
    cr_expect_eq(rb_colouring_assign(&colouring, 2, 3), 0, "neither 2 nor 3 is in colour 0");
    cr_expect_eq(rb_colouring_assign(&colouring, FIXED, 0), RB_COLOUR_COUNT - 1);
    cr_expect_eq(rb_colouring_assign(&colouring, 1, FIXED), RB_COLOUR_COUNT - 1, "the ground may be in a colour twice");
    cr_expect_eq(rb_colouring_assign(&colouring, FIXED, 0), RB_COLOUR_COUNT - 2);

    int offsets[RB_COLOUR_COUNT + 1];
    cr_expect_eq(rb_colouring_offsets(&colouring, offsets), 4, "colours 0, 1, 62 and 63 are used");
    cr_expect_eq(offsets[0], 0);
    cr_expect_eq(offsets[1], 2, "colour 0 holds two constraints");
    cr_expect_eq(offsets[2], 3);
    cr_expect_eq(offsets[RB_COLOUR_COUNT - 2], 3);
    cr_expect_eq(offsets[RB_COLOUR_COUNT - 1], 4);
    cr_expect_eq(offsets[RB_OVERFLOW_COLOUR], 6);
    rb_colouring_free(&colouring);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

Test(colouring, a_body_in_every_colour_overflows)
{
    /* Body 0 against bodies 1 .. 65: one colour each until all 64 are
     * taken, then the overflow colour. */
    rb_colouring colouring = {0};
    cr_assert_eq(rb_colouring_begin(&colouring, RB_COLOUR_COUNT + 2), 0);
    for (int k = 0; k < RB_COLOUR_COUNT; ++k) {
        cr_expect_eq(rb_colouring_assign(&colouring, 0, k + 1), k);
    }
    cr_expect_eq(rb_colouring_assign(&colouring, 0, RB_COLOUR_COUNT + 1), RB_OVERFLOW_COLOUR);
    cr_expect_eq(rb_colouring_assign(&colouring, FIXED, 0), RB_OVERFLOW_COLOUR);
    /* A new colouring starts empty. */
    cr_assert_eq(rb_colouring_begin(&colouring, RB_COLOUR_COUNT + 2), 0);
    cr_expect_eq(rb_colouring_assign(&colouring, 0, 1), 0);
    rb_colouring_free(&colouring);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

/* After a step of the base-20 pyramid, the constraints run colour by
 * colour, and within a colour (but overflow) no moving body appears twice. */
Test(colouring, a_step_lays_the_pyramid_out_by_colour)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 20, &pyramid), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 10);

    cr_assert_gt(world->constraint_count, 400, "the pyramid has %d constraints", world->constraint_count);
    static int seen_in_colour[RB_OVERFLOW_COLOUR + 1][512];
    int previous = 0;
    int colours = 0;
    for (int i = 0; i < world->constraint_count; ++i) {
        const rb_contact_constraint *c = &world->constraints[i];
        int colour = world->contacts[c->contact].colour;
        cr_assert_geq(colour, previous, "constraint %d has colour %d after colour %d", i, colour, previous);
        colours += i == 0 || colour != previous ? 1 : 0;
        previous = colour;
        const int bodies[2] = {c->body_a, c->body_b};
        const double inverse_masses[2] = {c->inv_mass_a, c->inv_mass_b};
        for (int side = 0; side < 2; ++side) {
            if (inverse_masses[side] == 0.0 || colour == RB_OVERFLOW_COLOUR) {
                continue;
            }
            cr_assert_lt(bodies[side], 512);
            cr_expect_eq(seen_in_colour[colour][bodies[side]]++, 0, "body %d twice in colour %d", bodies[side], colour);
        }
    }
    rb_statistics statistics = rb_world_statistics(world);
    cr_expect_eq(statistics.contact_colours, colours);
    /* A box touches at most 6 others (two below, two above, two beside)
     * and the ground: a handful of colours, not one per contact. */
    cr_expect_leq(colours, 12, "%d colours", colours);
    destroy_world_and_expect_no_leak(world);
}

/* Boxes of the peers' base-100 pyramid (gravity 10 m/s², sleeping off)
 * moved more than 0.25 m sideways after 6 s, with the given solver. */
static int boxes_moved_in_pyramid_100(rb_solver_type type, int substeps, int velocity_iterations, int position_passes)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, -10.0);
    def.enable_sleep = false;
    def.solver.type = type;
    def.solver.substeps = substeps;
    def.solver.velocity_iterations = velocity_iterations;
    def.solver.position_iterations = position_passes;
    def.solver.relax_iterations = position_passes;
    rb_world *world = NULL;
    cr_assert_eq(rb_world_create(&def, &world), RB_OK, "%s", rb_last_error());
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 100, &pyramid), RB_OK, "%s", rb_last_error());
    static double start_x[5050];
    cr_assert_eq(pyramid.box_count, 5050);
    for (int k = 0; k < pyramid.box_count; ++k) {
        start_x[k] = rb_body_position(world, scene_body_at(pyramid.first_box, k)).x;
    }
    step_world(world, 1.0 / 60.0, 360);
    int moved = 0;
    for (int k = 0; k < pyramid.box_count; ++k) {
        moved += fabs(rb_body_position(world, scene_body_at(pyramid.first_box, k)).x - start_x[k]) > 0.25 ? 1 : 0;
    }
    destroy_world_and_expect_no_leak(world);
    return moved;
}

Test(colouring, the_soft_step_holds_the_base_100_pyramid_at_box2d_v3s_budget, .timeout = 600)
{
    int moved = boxes_moved_in_pyramid_100(RB_SOLVER_SOFT_STEP, 4, 1, 1);
    cr_expect_eq(moved, 0, "at 4 substeps of 1 solve and 1 relax pass, %d boxes moved more than 0.25 m", moved);
}

/* Swept back and forth, the soft step's contacts blew this pyramid apart
 * at 6 substeps of 2 passes (1,470 boxes moved, one 99 m). */
Test(colouring, the_soft_step_holds_the_base_100_pyramid_at_the_default_passes, .timeout = 600)
{
    rb_solver_settings defaults = rb_default_solver_settings();
    int moved = boxes_moved_in_pyramid_100(RB_SOLVER_SOFT_STEP, defaults.substeps, defaults.velocity_iterations,
                                           defaults.relax_iterations);
    cr_expect_eq(moved, 0, "at the default passes, %d boxes moved more than 0.25 m", moved);
}

/* The default solver: swept forward only, NGS spread it (928 boxes). */
Test(colouring, the_default_solver_holds_the_base_100_pyramid, .timeout = 600)
{
    rb_solver_settings defaults = rb_default_solver_settings();
    int moved = boxes_moved_in_pyramid_100(defaults.type, defaults.substeps, defaults.velocity_iterations,
                                           defaults.position_iterations);
    cr_expect_eq(moved, 0, "%d boxes moved more than 0.25 m", moved);
}
