/* SPDX-License-Identifier: MIT */
/* The plain pins' rows (joint_pin.c): within a step a plain revolute
 * joint is solved from a dense row, not from the joint, and its impulse
 * goes back to the joint at the end of the step. What the user reads
 * must not tell the difference: the reaction of a pin holding a bob at
 * rest is its weight, m·g, whether read after a step or inside the
 * substep callback (where the row, not the joint, holds the impulse);
 * a mesh of pins moves to the same bits whether the rows stand alone
 * (every joint a plain pin) or are found through the joints' look-up
 * (another joint beside them); and a chain of them to the same bits as
 * the same chain solved through the joints' general passes. */
#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"
#include "test_support.h"

#define G 9.8

typedef struct reaction_log {
    rb_joint_id pin;
    int calls;
    double worst_error; /* N, |reaction - m·g| over the callbacks after each step's first substep */
    double weight;      /* N */
} reaction_log;

/* From the second substep on, the reaction is the last substep's impulse
 * over its length, and a bob at rest under its pivot hangs its weight. */
static void read_reaction(rb_world *world, int substep, double h, void *context)
{
    (void)h;
    reaction_log *log = context;
    log->calls++;
    if (substep == 0) {
        return; /* at the first step's first substep nothing has acted yet */
    }
    rb_vec2 force = rb_joint_reaction_force(world, log->pin);
    double error = hypot(force.x, force.y - log->weight);
    log->worst_error = fmax(log->worst_error, error);
}

Test(pin_rows, reaction_inside_a_substep_and_after_the_step_is_the_weight)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id pivot = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -1.0), 0.0);
    add_circle(world, bob, rb_v2(0.0, 0.0), 0.1, 1.0);
    reaction_log log = {.pin = make_pin(world, pivot, bob, rb_v2(0.0, 0.0))};
    log.weight = rb_body_mass(world, bob) * G;
    rb_vec2 before = rb_joint_reaction_force(world, log.pin);
    cr_expect(before.x == 0.0 && before.y == 0.0, "no reaction before the first step: (%g, %g) N", before.x, before.y);
    cr_assert_eq(rb_world_set_substep_callback(world, read_reaction, &log), RB_OK, "%s", rb_last_error());

    for (int step = 0; step < 3; ++step) {
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
        rb_vec2 after = rb_joint_reaction_force(world, log.pin);
        cr_expect(hypot(after.x, after.y - log.weight) <= 1e-9 * log.weight,
                  "step %d: reaction (%.15g, %.15g) N after the step, weight %.15g N", step, after.x, after.y,
                  log.weight);
    }
    int substeps = rb_world_solver_settings(world).substeps;
    cr_assert_eq(log.calls, 3 * substeps);
    cr_expect(log.worst_error <= 1e-9 * log.weight,
              "inside the substeps the reaction is off the weight %.15g N by %g N", log.weight, log.worst_error);
    destroy_world_and_expect_no_leak(world);
}

enum { SIDE = 6 };

enum { PINS = 2 * SIDE * (SIDE - 1) };

/* The peers' joint grid (docs/benchmarks.md) at SIDE × SIDE: circles 1 m
 * apart, each pinned to the one above and the one to its left, hung by
 * its top left corner alone, so that it swings down as a whole; the pins'
 * ids go to pins[PINS]. */
static void make_grid(rb_world *world, rb_body_id bodies[SIDE][SIDE], rb_joint_id pins[PINS])
{
    int pin_count = 0;
    for (int row = 0; row < SIDE; ++row) {
        for (int column = 0; column < SIDE; ++column) {
            bool fixed = row == 0 && column == 0;
            rb_body_id body =
                make_body(world, fixed ? RB_BODY_STATIC : RB_BODY_DYNAMIC, rb_v2((double)column, -(double)row), 0.0);
            add_circle(world, body, rb_v2(0.0, 0.0), 0.4, 1.0);
            bodies[row][column] = body;
            if (row > 0) {
                pins[pin_count++] =
                    make_pin(world, bodies[row - 1][column], body, rb_v2((double)column, 0.5 - (double)row));
            }
            if (column > 0) {
                pins[pin_count++] =
                    make_pin(world, bodies[row][column - 1], body, rb_v2((double)column - 0.5, -(double)row));
            }
        }
    }
}

/* A world under gravity G whose bodies never sleep, solved by `solver`. */
static rb_world *make_awake_world(rb_solver_type solver)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_world_enable_sleep(world, false);
    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.type = solver;
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
    return world;
}

/* Whether two worlds' grids end in the same bits: positions, velocities
 * and angles; the number of bodies that differ. */
static int count_different(rb_world *worlds[2], rb_body_id grids[2][SIDE][SIDE])
{
    int different = 0;
    for (int row = 0; row < SIDE; ++row) {
        for (int column = 0; column < SIDE; ++column) {
            rb_vec2 p0 = rb_body_position(worlds[0], grids[0][row][column]);
            rb_vec2 p1 = rb_body_position(worlds[1], grids[1][row][column]);
            rb_vec2 v0 = rb_body_linear_velocity(worlds[0], grids[0][row][column]);
            rb_vec2 v1 = rb_body_linear_velocity(worlds[1], grids[1][row][column]);
            double a0 = rb_body_angle(worlds[0], grids[0][row][column]);
            double a1 = rb_body_angle(worlds[1], grids[1][row][column]);
            if (p0.x != p1.x || p0.y != p1.y || v0.x != v1.x || v0.y != v1.y || a0 != a1) {
                ++different;
            }
        }
    }
    return different;
}

/* Expects the two worlds' grids in the same bits, and moved (a test of
 * bodies at rest would prove nothing); then destroys both worlds. */
static void expect_same_moved_grids_and_destroy(rb_world *worlds[2], rb_body_id grids[2][SIDE][SIDE],
                                                rb_solver_type solver, const char *what)
{
    int different = count_different(worlds, grids);
    cr_expect_eq(different, 0, "solver %d: %d of the grid's %d bodies differ %s", solver, different, SIDE * SIDE, what);
    rb_vec2 corner = rb_body_position(worlds[0], grids[0][SIDE - 1][SIDE - 1]);
    cr_expect(hypot(corner.x - (SIDE - 1.0), corner.y + (SIDE - 1.0)) > 1.0, "the grid's corner stayed at (%g, %g)",
              corner.x, corner.y);
    rb_world_destroy(worlds[1]);
    destroy_world_and_expect_no_leak(worlds[0]);
}

/* The grid alone, and the grid after a distance joint between two bodies
 * far away (created first, so that no pin's row is its joint's place in
 * the active list), under `solver`: the grid's bodies end in the same
 * bits. */
static void expect_same_grid(rb_solver_type solver)
{
    rb_world *worlds[2];
    rb_body_id grids[2][SIDE][SIDE];
    for (int w = 0; w < 2; ++w) {
        worlds[w] = make_awake_world(solver);
        if (w == 1) {
            rb_body_id a = make_body(worlds[w], RB_BODY_DYNAMIC, rb_v2(-1000.0, 0.0), 0.0);
            rb_body_id b = make_body(worlds[w], RB_BODY_DYNAMIC, rb_v2(-1001.0, 0.0), 0.0);
            add_circle(worlds[w], a, rb_v2(0.0, 0.0), 0.2, 1.0);
            add_circle(worlds[w], b, rb_v2(0.0, 0.0), 0.2, 1.0);
            rb_distance_joint_def def = rb_default_distance_joint_def();
            cr_assert_eq(rb_distance_joint_def_between(&def, worlds[w], a, b, rb_v2(-1000.0, 0.0), rb_v2(-1001.0, 0.0)),
                         RB_OK, "%s", rb_last_error());
            rb_joint_id bar;
            cr_assert_eq(rb_distance_joint_create(worlds[w], &def, &bar), RB_OK, "%s", rb_last_error());
        }
        rb_joint_id pins[PINS];
        make_grid(worlds[w], grids[w], pins);
        step_world(worlds[w], TEST_DT, 90);
    }
    expect_same_moved_grids_and_destroy(worlds, grids, solver, "with a joint beside the pins");
}

Test(pin_rows, same_bits_with_and_without_another_joint_under_ngs) { expect_same_grid(RB_SOLVER_NGS); }

Test(pin_rows, same_bits_with_and_without_another_joint_under_the_soft_step) { expect_same_grid(RB_SOLVER_SOFT_STEP); }

Test(pin_rows, same_bits_with_and_without_another_joint_under_baumgarte) { expect_same_grid(RB_SOLVER_BAUMGARTE); }

/* The rows' passes (joint_pin.c) have their own arithmetic, written for a
 * pin alone: the mass matrix, its inverse and the position pass, and
 * under NGS a velocity pass without the softening. The joints' general
 * passes (joint_point.c) are the independent reference: a pin with an
 * idle motor (enabled, no torque) is no plain pin, so it is solved as a
 * joint, through them, and its motor adds nothing.
 *
 * NGS and Baumgarte visit plain pins by depth and colour but other
 * joints in the order they were made (joint_order.c), so the two worlds
 * must meet the same order either way: a chain held out sideways from a
 * pivot, its pins made from the free end to the pivot, the deepest
 * first, one to a depth, with no trees (which would take a chain of
 * plain pins whole). Released, it falls and folds, which turns every
 * anchor and fills every term of each pin's mass matrix. The two chains
 * end in the same bits. */
enum { LINKS = 8 };

static void make_chain(rb_world *world, rb_body_id links[LINKS], bool idle_motors)
{
    rb_body_id pivot = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    for (int k = 0; k < LINKS; ++k) {
        links[k] = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.5 + (double)k, 0.0), 0.0);
        add_circle(world, links[k], rb_v2(0.0, 0.0), 0.3, 1.0);
    }
    for (int k = LINKS - 1; k >= 0; --k) {
        rb_body_id inner = k == 0 ? pivot : links[k - 1];
        rb_joint_id pin = make_pin(world, inner, links[k], rb_v2((double)k, 0.0));
        if (idle_motors) {
            cr_assert_eq(rb_revolute_joint_set_motor(world, pin, true, 0.0, 0.0), RB_OK, "%s", rb_last_error());
        }
    }
}

static void expect_rows_as_joints(rb_solver_type solver)
{
    rb_world *worlds[2];
    rb_body_id links[2][LINKS];
    for (int w = 0; w < 2; ++w) {
        worlds[w] = make_awake_world(solver);
        rb_solver_settings settings = rb_world_solver_settings(worlds[w]);
        settings.tree_pins = false;
        cr_assert_eq(rb_world_set_solver_settings(worlds[w], &settings), RB_OK, "%s", rb_last_error());
        make_chain(worlds[w], links[w], w == 1);
        step_world(worlds[w], TEST_DT, 90);
    }
    int different = 0;
    for (int k = 0; k < LINKS; ++k) {
        rb_vec2 p0 = rb_body_position(worlds[0], links[0][k]);
        rb_vec2 p1 = rb_body_position(worlds[1], links[1][k]);
        rb_vec2 v0 = rb_body_linear_velocity(worlds[0], links[0][k]);
        rb_vec2 v1 = rb_body_linear_velocity(worlds[1], links[1][k]);
        bool same = p0.x == p1.x && p0.y == p1.y && v0.x == v1.x && v0.y == v1.y &&
                    rb_body_angle(worlds[0], links[0][k]) == rb_body_angle(worlds[1], links[1][k]);
        different += same ? 0 : 1;
    }
    cr_expect_eq(different, 0, "solver %d: %d of the chain's %d links differ between rows and joints", solver,
                 different, LINKS);
    rb_vec2 end = rb_body_position(worlds[0], links[0][LINKS - 1]);
    cr_expect(end.y < -2.0, "the chain's end has not fallen: (%g, %g)", end.x, end.y);
    rb_world_destroy(worlds[1]);
    destroy_world_and_expect_no_leak(worlds[0]);
}

Test(pin_rows, same_bits_as_the_joints_general_passes_under_ngs) { expect_rows_as_joints(RB_SOLVER_NGS); }

Test(pin_rows, same_bits_as_the_joints_general_passes_under_baumgarte) { expect_rows_as_joints(RB_SOLVER_BAUMGARTE); }
