/* SPDX-License-Identifier: MIT */
/* The order in which the soft step visits the joints, and NGS and
 * Baumgarte the plain pins (engine/src/joint_order.c): from the free ends
 * to the supports, colour by colour within a depth.
 *
 * Three truths. A body cut free falls freely, whatever order the passes
 * kept from the steps before. The physics of a chain does not depend on
 * the order its joints were made in: made from the pin outwards or from the free end
 * inwards, the same chain must move the same, to the bit, since the
 * passes visit its joints by their distance from the pin either way
 * (swept in the order the joints were made, the two differed). And Box2D
 * v3 (erincatto/box2d at commit 617d32a, SSE2, the peers' harness
 * box2d3_bench joint_grid --grid 30, 60 + 300 steps) stretches the 30 x 30
 * joint grid to 0.0607861 m at its own budget: the soft step at that
 * budget holds it within that (0.0607 m; 0.0615 m swept in the order the
 * joints were made, from the last to the first).
 */
#include <criterion/criterion.h>
#include <math.h>

#include "scenes/scenes.h"
#include "test_support.h"

#define V3_SUBSTEPS 4 /* Box2D v3's budget: 4 substeps of one solve and one relax pass */
#define PEER_GRAVITY (-10.0)

static rb_world *make_v3_budget_world(void)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, PEER_GRAVITY);
    def.enable_sleep = false; /* as the peers' harness runs */
    def.solver.type = RB_SOLVER_SOFT_STEP;
    def.solver.substeps = V3_SUBSTEPS;
    def.solver.velocity_iterations = 1;
    def.solver.position_iterations = 1;
    def.solver.relax_iterations = 1;
    rb_world *world = NULL;
    cr_assert_eq(rb_world_create(&def, &world), RB_OK, "rb_world_create: %s", rb_last_error());
    return world;
}

/* The defaults' world (NGS), with the pins left to the passes: the trees
 * (joint_tree.h) would solve a chain of plain pins whole, in no order. */
static rb_world *make_ngs_world_without_trees(void)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, PEER_GRAVITY);
    def.enable_sleep = false;
    def.solver.tree_pins = false;
    rb_world *world = NULL;
    cr_assert_eq(rb_world_create(&def, &world), RB_OK, "rb_world_create: %s", rb_last_error());
    cr_assert_eq(def.solver.type, RB_SOLVER_NGS, "the defaults' solver is NGS");
    return world;
}

typedef rb_world *(*world_maker)(void);

#define CHAIN_LINKS 20
#define LINK_HALF_LENGTH 0.25 /* m */

/* A chain of CHAIN_LINKS boxes swinging from a pin at the origin, released
 * horizontal, its last link `heavy` times as dense as the others; its
 * joints made from the pin outwards, or (inwards) from the free end, joint
 * i holding link i to the one before (or the pin). */
static void make_chain(rb_world *world, double heavy, bool inwards, rb_body_id links[CHAIN_LINKS],
                       rb_joint_id joints[CHAIN_LINKS])
{
    rb_body_def pin_def = rb_default_body_def();
    rb_body_id pin;
    cr_assert_eq(rb_body_create(world, &pin_def, &pin), RB_OK, "%s", rb_last_error()); /* static */
    for (int i = 0; i < CHAIN_LINKS; ++i) {
        rb_body_def def = rb_default_body_def();
        def.type = RB_BODY_DYNAMIC;
        def.position = rb_v2(LINK_HALF_LENGTH * (2 * i + 1), 0.0);
        cr_assert_eq(rb_body_create(world, &def, &links[i]), RB_OK, "%s", rb_last_error());
        rb_shape_def shape = rb_default_shape_def();
        shape.density = i == CHAIN_LINKS - 1 ? heavy : 1.0;
        shape.filter.group_index = -1; /* the links do not collide */
        rb_polygon box;
        cr_assert_eq(rb_make_offset_box(LINK_HALF_LENGTH, 0.05, rb_v2(0.0, 0.0), 0.0, &box), RB_OK, "%s",
                     rb_last_error());
        rb_shape_id id;
        cr_assert_eq(rb_shape_create_polygon(world, links[i], &shape, &box, &id), RB_OK, "%s", rb_last_error());
    }
    for (int k = 0; k < CHAIN_LINKS; ++k) {
        int i = inwards ? CHAIN_LINKS - 1 - k : k;
        rb_revolute_joint_def def = rb_default_revolute_joint_def();
        def.body_a = i == 0 ? pin : links[i - 1];
        def.body_b = links[i];
        def.local_anchor_a = i == 0 ? rb_v2(0.0, 0.0) : rb_v2(LINK_HALF_LENGTH, 0.0);
        def.local_anchor_b = rb_v2(-LINK_HALF_LENGTH, 0.0);
        cr_assert_eq(rb_revolute_joint_create(world, &def, &joints[i]), RB_OK, "%s", rb_last_error());
    }
}

/* The order is kept from step to step while the joints are the same
 * (joint_order.c): cut between two steps, the chain must come apart as if
 * the order were found anew. Its lower half is then free, and its centre
 * of mass (the links are alike) falls as semi-implicit Euler moves a body
 * under gravity alone over N substeps of h: by v0·N·h - g·h²·N(N + 1)/2,
 * whatever its links do to one another. Held by the cut joint, it would
 * swing from the pin instead, metres away. */
#define CUT_ABOVE 10 /* the joint that holds link 10 to link 9 */

static rb_vec2 lower_centre(const rb_world *world, const rb_body_id links[CHAIN_LINKS], bool velocity)
{
    rb_vec2 sum = rb_v2(0.0, 0.0);
    for (int i = CUT_ABOVE; i < CHAIN_LINKS; ++i) {
        sum = rb_add(sum, velocity ? rb_body_linear_velocity(world, links[i]) : rb_body_position(world, links[i]));
    }
    return rb_scale(1.0 / (CHAIN_LINKS - CUT_ABOVE), sum);
}

static void expect_a_cut_chain_to_come_apart(world_maker make)
{
    rb_world *world = make();
    rb_body_id links[CHAIN_LINKS];
    rb_joint_id joints[CHAIN_LINKS];
    make_chain(world, 1.0, false, links, joints);
    for (int step = 0; step < 30; ++step) { /* the order is found, then kept */
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
    }
    cr_assert_eq(rb_joint_destroy(world, joints[CUT_ABOVE]), RB_OK, "%s", rb_last_error());
    const rb_vec2 start = lower_centre(world, links, false);
    const rb_vec2 start_velocity = lower_centre(world, links, true);
    const int steps = 60;
    for (int step = 0; step < steps; ++step) {
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
    }
    const int substeps = rb_world_solver_settings(world).substeps;
    const double h = TEST_DT / substeps;
    const double n = (double)steps * substeps;
    const double expected_y = start.y + start_velocity.y * n * h + PEER_GRAVITY * h * h * n * (n + 1.0) / 2.0;
    const double expected_x = start.x + start_velocity.x * n * h;
    const rb_vec2 end = lower_centre(world, links, false);
    cr_expect(fabs(end.y - expected_y) < 1e-6 && fabs(end.x - expected_x) < 1e-6,
              "the cut half's centre at (%.9f, %.9f) m, free fall puts it at (%.9f, %.9f) m", end.x, end.y, expected_x,
              expected_y);
    destroy_world_and_expect_no_leak(world);
}

Test(joint_order, a_chain_cut_between_steps_comes_apart) { expect_a_cut_chain_to_come_apart(make_v3_budget_world); }

Test(joint_order, a_chain_of_plain_pins_cut_between_steps_comes_apart_under_ngs)
{
    expect_a_cut_chain_to_come_apart(make_ngs_world_without_trees);
}

static void expect_a_chain_to_move_the_same_whichever_way_made(world_maker make)
{
    const double heavies[] = {1.0, 50.0}; /* the last link as dense as the others, and 50 times */
    for (size_t h = 0; h < sizeof heavies / sizeof heavies[0]; ++h) {
        rb_world *worlds[2];
        rb_body_id links[2][CHAIN_LINKS];
        rb_joint_id joints[2][CHAIN_LINKS];
        for (int w = 0; w < 2; ++w) {
            worlds[w] = make();
            make_chain(worlds[w], heavies[h], w == 1, links[w], joints[w]);
        }
        for (int step = 0; step < 120; ++step) {
            for (int w = 0; w < 2; ++w) {
                cr_assert_eq(rb_world_step(worlds[w], TEST_DT), RB_OK, "%s", rb_last_error());
            }
        }
        for (int i = 0; i < CHAIN_LINKS; ++i) {
            rb_vec2 out = rb_body_position(worlds[0], links[0][i]);
            rb_vec2 in = rb_body_position(worlds[1], links[1][i]);
            cr_expect(out.x == in.x && out.y == in.y,
                      "last link %g times as dense: link %d at (%.17g, %.17g) made outwards, (%.17g, %.17g) "
                      "inwards",
                      heavies[h], i, out.x, out.y, in.x, in.y);
        }
        rb_world_destroy(worlds[0]);
        destroy_world_and_expect_no_leak(worlds[1]); /* the last world: nothing left */
    }
}

Test(joint_order, a_chain_moves_the_same_whichever_way_its_joints_were_made)
{
    expect_a_chain_to_move_the_same_whichever_way_made(make_v3_budget_world);
}

Test(joint_order, a_chain_of_plain_pins_moves_the_same_whichever_way_made_under_ngs)
{
    expect_a_chain_to_move_the_same_whichever_way_made(make_ngs_world_without_trees);
}

#define GRID 30
#define GRID_STEPS 360              /* the harness's 60 warm-up steps and 300 timed */
#define BOX2D_V3_GRID_GAP 0.0607861 /* m, the worst over every step (peak_sep_all_steps) */

Test(joint_order, the_30_grid_stretches_no_further_than_box2d_v3s_at_its_budget)
{
    rb_world *world = make_v3_budget_world();
    scene_joint_grid grid;
    cr_assert_eq(scene_joint_grid_create(world, GRID, &grid), RB_OK, "%s", rb_last_error());
    double worst = 0.0;
    for (int step = 0; step < GRID_STEPS; ++step) {
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
        worst = fmax(worst, rb_world_statistics(world).max_joint_gap);
    }
    cr_expect_leq(worst, BOX2D_V3_GRID_GAP, "worst joint gap %.7f m (Box2D v3: %.7f m)", worst, BOX2D_V3_GRID_GAP);
    destroy_world_and_expect_no_leak(world);
}
