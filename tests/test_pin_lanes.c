// SPDX-License-Identifier: MIT
/* The plain pins' passes two rows at a time (pin_rows_two.c:
 * rb_pins_warm_start, rb_pins_solve_rigid, rb_pins_solve,
 * rb_pins_correct_positions) against the one-at-a-time reference they
 * stand for (rb_pin_warm_start, rb_pin_solve_rigid, rb_pin_solve,
 * rb_pin_correct, one row after the other in the pass's order): from the
 * same rows, poses and velocities, both ways must leave the same rows
 * and body states, byte for byte, in either direction. The stated
 * tolerance is none: two rows are solved together only when their four
 * bodies are distinct, which makes solving them together solving them
 * one after the other, and each lane does the reference's arithmetic in
 * the reference's order.
 *
 * The rows are those of a 12 × 12 joint grid hung from a ceiling by its
 * whole top row (so that consecutive top pins share the fixed ceiling and
 * go one at a time), with one body that cannot turn, swung for half a
 * second, in the engine's order and reordered so that rows sharing a
 * moving body follow each other; the states are then disturbed so that
 * the branches the pairs leave to the reference are met, and the test
 * counts that they were: a drift capped (bodies spinning fast), a turn
 * beyond the Taylor series' 1/32 rad (poses pulled apart), a body that
 * cannot turn, a pin whose bodies cannot move (one row's masses set to
 * zero), and rows alone. The velocity passes run under the rigid
 * response and under a soft one (a bias on the gap, a softened
 * impulse). */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "joint_solver.h"
#include "rb/rb.h"
#include "test_support.h"
#include "world_internal.h"

enum { SIDE = 12 };

/* A deterministic value in [-1, 1) (a linear congruential generator,
 * Knuth's MMIX constants). */
static double next_unit(uint64_t *state)
{
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (double)(*state >> 11) / (double)(UINT64_C(1) << 52) - 1.0;
}

/* The grid, swung for 30 steps: its rows are then the last substep's. */
static rb_world *make_swung_grid(void)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_world_enable_sleep(world, false);
    rb_body_id ceiling = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.5), 0.0);
    rb_body_id bodies[SIDE][SIDE];
    for (int row = 0; row < SIDE; ++row) {
        for (int column = 0; column < SIDE; ++column) {
            rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2((double)column, -(double)row), 0.0);
            add_circle(world, body, rb_v2(0.0, 0.0), 0.4, 1.0 + 0.1 * column);
            bodies[row][column] = body;
            rb_body_id above = row > 0 ? bodies[row - 1][column] : ceiling;
            make_pin(world, above, body, rb_v2((double)column, 0.5 - (double)row));
            if (column > 0) {
                make_pin(world, bodies[row][column - 1], body, rb_v2((double)column - 0.5, -(double)row));
            }
        }
    }
    cr_assert_eq(rb_body_set_fixed_rotation(world, bodies[SIDE / 2][SIDE / 2], true), RB_OK, "%s", rb_last_error());
    rb_body_apply_linear_impulse(world, bodies[SIDE - 1][SIDE - 1], rb_v2(40.0, 0.0),
                                 rb_body_position(world, bodies[SIDE - 1][SIDE - 1]));
    step_world(world, TEST_DT, 30);
    cr_assert_eq(world->pin_row_count, SIDE * SIDE + SIDE * (SIDE - 1), "every pin in its row");
    return world;
}

/* What a pass reads and writes: the rows, the body states, and the
 * angular velocities the drift is made from. */
typedef struct snapshot {
    rb_pin_row *rows;
    rb_pin_anchors *anchors;
    rb_body_state *states;
    double *omega;
} snapshot;

static snapshot take(const rb_world *world)
{
    snapshot s = {
        .rows = malloc((size_t)world->pin_row_count * sizeof *s.rows),
        .anchors = malloc((size_t)world->pin_row_count * sizeof *s.anchors),
        .states = malloc((size_t)world->body_slots * sizeof *s.states),
        .omega = malloc((size_t)world->body_slots * sizeof *s.omega),
    };
    cr_assert(s.rows != NULL && s.anchors != NULL && s.states != NULL && s.omega != NULL);
    memcpy(s.rows, world->pin_rows, (size_t)world->pin_row_count * sizeof *s.rows);
    memcpy(s.anchors, world->pin_anchors, (size_t)world->pin_row_count * sizeof *s.anchors);
    memcpy(s.states, world->states, (size_t)world->body_slots * sizeof *s.states);
    memcpy(s.omega, world->substep_omega, (size_t)world->body_slots * sizeof *s.omega);
    return s;
}

static void put_back(rb_world *world, const snapshot *s)
{
    memcpy(world->pin_rows, s->rows, (size_t)world->pin_row_count * sizeof *s->rows);
    memcpy(world->pin_anchors, s->anchors, (size_t)world->pin_row_count * sizeof *s->anchors);
    memcpy(world->states, s->states, (size_t)world->body_slots * sizeof *s->states);
    memcpy(world->substep_omega, s->omega, (size_t)world->body_slots * sizeof *s->omega);
}

static void release(snapshot *s)
{
    free(s->rows);
    free(s->anchors);
    free(s->states);
    free(s->omega);
}

/* The rows (and their anchors) reordered so that rows sharing a moving
 * body follow each other: each row in turn, then the first row not yet placed
 * whose end `second` (0 for A, 1 for B) is its end `first`. A pass must
 * not pair such rows; with all four choices of ends, every one of the
 * four comparisons that keep a pair apart is needed. */
static int end_of(const rb_pin_row *row, int end) { return end == 0 ? row->body_a : row->body_b; }

static void order_sharing(rb_world *world, int first, int second)
{
    const int count = world->pin_row_count;
    rb_pin_row *rows = malloc((size_t)count * sizeof *rows);
    rb_pin_anchors *anchors = malloc((size_t)count * sizeof *anchors);
    bool *taken = calloc((size_t)count, sizeof *taken);
    cr_assert(rows != NULL && anchors != NULL && taken != NULL);
    int out = 0;
    for (int i = 0; i < count; ++i) {
        if (taken[i]) {
            continue;
        }
        taken[i] = true;
        rows[out] = world->pin_rows[i];
        anchors[out++] = world->pin_anchors[i];
        int shared = end_of(&world->pin_rows[i], first);
        if (world->bodies[shared].type != RB_BODY_DYNAMIC) {
            continue;
        }
        for (int j = 0; j < count; ++j) {
            if (!taken[j] && end_of(&world->pin_rows[j], second) == shared) {
                taken[j] = true;
                rows[out] = world->pin_rows[j];
                anchors[out++] = world->pin_anchors[j];
                break;
            }
        }
    }
    memcpy(world->pin_rows, rows, (size_t)count * sizeof *rows);
    memcpy(world->pin_anchors, anchors, (size_t)count * sizeof *anchors);
    free(rows);
    free(anchors);
    free(taken);
}

/* Every moving body's velocity and pose disturbed (the centres by up to
 * `reach` m, the angles by up to 50 reach rad; at reach 0, one body pulled
 * 5 cm off its pins instead), a few of them spun fast for the drift, and
 * the rows' impulses scaled. */
static void disturb(rb_world *world, uint64_t seed, double reach)
{
    uint64_t random = seed;
    for (int i = 0; i < world->body_slots; ++i) {
        if (world->bodies[i].type != RB_BODY_DYNAMIC) {
            continue;
        }
        rb_body_state *s = &world->states[i];
        s->linear_velocity = rb_add(s->linear_velocity, rb_v2(2.0 * next_unit(&random), 2.0 * next_unit(&random)));
        s->angular_velocity += 5.0 * next_unit(&random);
        s->center = rb_add(s->center, rb_v2(reach * next_unit(&random), reach * next_unit(&random)));
        /* A body that cannot turn keeps its angle; at -0, a turn by +0
         * would make it +0 where the reference leaves it. */
        s->angle = world->bodies[i].inv_inertia > 0.0 ? s->angle + 50.0 * reach * next_unit(&random) : -0.0;
        s->rotation = rb_rot_from_angle(s->angle);
        world->substep_omega[i] = i % 7 == 0 ? 120.0 * next_unit(&random) : s->angular_velocity;
    }
    if (reach == 0.0) {
        /* One body alone pulled off its pins: the pass is within the slop
         * everywhere but at its rows. */
        world->states[world->body_slots / 2].center.x += 0.05;
    }
    for (int k = 0; k < world->pin_row_count; ++k) {
        world->pin_rows[k].impulse = rb_scale(1.0 + 0.5 * next_unit(&random), world->pin_rows[k].impulse);
    }
}

/* The branches met in the reference's rows that the pass pairs. */
typedef struct met {
    int pairs, alone; /* consecutive rows of the pass with four distinct bodies, and rows left alone */
    int capped;       /* drifts at their cap */
    int wide_turns;   /* bodies turned beyond 1/32 rad by one row */
    int cannot_turn;  /* rows with a body of zero inverse inertia that moves */
    int cannot_move;  /* rows whose bodies cannot move */
} met;

typedef enum pass_kind { WARM_START, SOLVE_RIGID, SOLVE_SOFT, CORRECT } pass_kind;

static int row_at(int count, int k, bool backwards) { return backwards ? count - 1 - k : k; }

static bool apart(const rb_pin_row *first, const rb_pin_row *second)
{
    return first->body_a != second->body_a && first->body_a != second->body_b && first->body_b != second->body_a &&
           first->body_b != second->body_b;
}

/* The reference: each row in the pass's order, one at a time. */
static bool reference_pass(rb_world *world, pass_kind kind, bool backwards, met *m)
{
    const int count = world->pin_row_count;
    const double h = TEST_DT / rb_world_solver_settings(world).substeps;
    const double cap = rb_point_drift_cap(world, h);
    bool *paired = calloc((size_t)count, sizeof *paired);
    cr_assert(paired != NULL);
    for (int k = 0; k < count;) {
        bool two = k + 1 < count && apart(&world->pin_rows[row_at(count, k, backwards)],
                                          &world->pin_rows[row_at(count, k + 1, backwards)]);
        m->pairs += two;
        m->alone += !two;
        paired[k] = two;
        paired[k + two] = two;
        k += two ? 2 : 1;
    }
    bool all_within = true;
    for (int k = 0; k < count; ++k) {
        int index = row_at(count, k, backwards);
        rb_pin_row *row = &world->pin_rows[index];
        double angle_a = world->states[row->body_a].angle;
        double angle_b = world->states[row->body_b].angle;
        switch (kind) {
        case WARM_START:
            rb_pin_warm_start(world, index, h);
            m->capped += paired[k] && fabs(rb_length(row->point_drift) - cap) <= 1e-12 * cap;
            break;
        case SOLVE_RIGID:
            rb_pin_solve_rigid(world->states, row);
            break;
        case SOLVE_SOFT:
            rb_pin_solve(world, row);
            break;
        case CORRECT:
            all_within = rb_pin_correct(world, index) && all_within;
            m->wide_turns += paired[k] && fabs(world->states[row->body_a].angle - angle_a) > 0.03125;
            m->wide_turns += paired[k] && fabs(world->states[row->body_b].angle - angle_b) > 0.03125;
            break;
        }
        m->cannot_turn += paired[k] && ((row->inv_inertia_a == 0.0 && row->inv_mass_a > 0.0) ||
                                        (row->inv_inertia_b == 0.0 && row->inv_mass_b > 0.0));
        m->cannot_move += paired[k] && row->inv_mass_a == 0.0 && row->inv_mass_b == 0.0;
    }
    free(paired);
    return all_within;
}

static bool lanes_pass(rb_world *world, pass_kind kind, bool backwards)
{
    const double h = TEST_DT / rb_world_solver_settings(world).substeps;
    switch (kind) {
    case WARM_START:
        rb_pins_warm_start(world, h, backwards);
        return true;
    case SOLVE_RIGID:
        rb_pins_solve_rigid(world, backwards);
        return true;
    case SOLVE_SOFT:
        rb_pins_solve(world, backwards);
        return true;
    case CORRECT:
        return rb_pins_correct_positions(world, backwards);
    }
    return false;
}

/* Runs the pass both ways from the same disturbed start and expects the
 * same bytes; returns the branches met. */
static met compare(rb_world *world, pass_kind kind, bool backwards, int order, uint64_t seed, double reach)
{
    snapshot swung = take(world);
    if (order > 0) {
        order_sharing(world, (order - 1) / 2, (order - 1) % 2);
    }
    disturb(world, seed, reach);
    /* One row's bodies made immovable: K is singular there. */
    rb_pin_row *frozen = &world->pin_rows[world->pin_row_count / 2];
    frozen->inv_mass_a = frozen->inv_inertia_a = frozen->inv_mass_b = frozen->inv_inertia_b = 0.0;
    snapshot start = take(world);

    bool lanes_within = lanes_pass(world, kind, backwards);
    snapshot by_lanes = take(world);
    put_back(world, &start);
    met m = {0};
    bool reference_within = reference_pass(world, kind, backwards, &m);

    const int rows = world->pin_row_count;
    int rows_differ = 0;
    for (int k = 0; k < rows; ++k) {
        rows_differ += memcmp(&by_lanes.rows[k], &world->pin_rows[k], sizeof(rb_pin_row)) != 0;
    }
    int states_differ = 0;
    for (int i = 0; i < world->body_slots; ++i) {
        states_differ += memcmp(&by_lanes.states[i], &world->states[i], sizeof(rb_body_state)) != 0;
    }
    cr_expect_eq(rows_differ, 0, "pass %d, backwards %d, order %d: %d of %d rows differ from the reference", kind,
                 backwards, order, rows_differ, rows);
    cr_expect_eq(states_differ, 0, "pass %d, backwards %d, order %d: %d of %d body states differ from the reference",
                 kind, backwards, order, states_differ, world->body_slots);
    cr_expect_eq(lanes_within, reference_within, "pass %d, backwards %d: within the slop %d, reference %d", kind,
                 backwards, lanes_within, reference_within);
    int moved = 0;
    for (int i = 0; i < world->body_slots; ++i) {
        moved += memcmp(&start.states[i], &world->states[i], sizeof(rb_body_state)) != 0;
    }
    cr_expect_gt(moved, SIDE * SIDE / 2, "pass %d moved only %d bodies: it proves nothing", kind, moved);

    put_back(world, &swung);
    release(&swung);
    release(&start);
    release(&by_lanes);
    return m;
}

/* Runs a pass in both directions, in the engine's order and in the four
 * orders that put rows sharing a body side by side; returns the branches
 * met in the engine's order, and expects the others to have left many
 * rows alone. */
static met compare_every_way(rb_world *world, pass_kind kind, uint64_t seed)
{
    /* Poses pulled far apart (turns beyond the series), nearly together
     * (turns within it, in both lanes), and as they were but one body. */
    static const double reaches[] = {0.3, 0.002, 0.0};
    met in_order = {0};
    for (int r = 0; r < 3; ++r) {
        for (int backwards = 0; backwards < 2; ++backwards) {
            uint64_t way = seed + 4u * (uint64_t)r + 2u * (uint64_t)backwards;
            met m = compare(world, kind, backwards, 0, way, reaches[r]);
            in_order.pairs += m.pairs;
            in_order.alone += m.alone;
            in_order.capped += m.capped;
            in_order.wide_turns += m.wide_turns;
            in_order.cannot_turn += m.cannot_turn;
            in_order.cannot_move += m.cannot_move;
            for (int order = 1; order <= 4; ++order) {
                met shared = compare(world, kind, backwards, order, way + 1u, reaches[r]);
                cr_expect_gt(shared.alone, 5, "pass %d, rows sharing a body in order %d: %d rows alone", kind, order,
                             shared.alone);
            }
        }
    }
    cr_expect_gt(in_order.pairs, world->pin_row_count, "pass %d: pairs %d", kind, in_order.pairs);
    cr_expect_gt(in_order.alone, 0, "pass %d: rows alone %d", kind, in_order.alone);
    return in_order;
}

/* The rows of a body that cannot turn and of bodies that cannot move
 * met in pairs. */
static void expect_fixed_bodies_paired(met m)
{
    cr_expect_gt(m.cannot_turn, 0, "paired rows with a body that cannot turn: %d", m.cannot_turn);
    cr_expect_gt(m.cannot_move, 0, "paired rows whose bodies cannot move: %d", m.cannot_move);
}

/* compare_every_way on a fresh swung grid whose joints answer with
 * `response`. */
static met compare_on_a_grid(pass_kind kind, rb_rigid_response response, uint64_t seed)
{
    rb_world *world = make_swung_grid();
    world->joint_response = response;
    met m = compare_every_way(world, kind, seed);
    destroy_world_and_expect_no_leak(world);
    return m;
}

/* The rigid response, NGS's and the soft step's relax. */
static const rb_rigid_response rigid = {.mass_scale = 1.0};

Test(pin_lanes, the_warm_start_two_rows_at_a_time_is_the_reference)
{
    met m = compare_on_a_grid(WARM_START, rigid, 11u);
    cr_expect_gt(m.capped, 0, "capped drifts in pairs: %d", m.capped);
    expect_fixed_bodies_paired(m);
}

Test(pin_lanes, the_rigid_velocity_pass_two_rows_at_a_time_is_the_reference)
{
    compare_on_a_grid(SOLVE_RIGID, rigid, 23u);
}

Test(pin_lanes, the_soft_velocity_pass_two_rows_at_a_time_is_the_reference)
{
    /* A soft response, as the soft step's biased passes have: a bias on
     * the gap and a softened impulse. */
    compare_on_a_grid(SOLVE_SOFT, (rb_rigid_response){.bias_rate = 30.0, .mass_scale = 0.8, .impulse_scale = 0.15},
                      29u);
}

Test(pin_lanes, the_position_pass_two_rows_at_a_time_is_the_reference)
{
    met m = compare_on_a_grid(CORRECT, rigid, 37u);
    cr_expect_gt(m.wide_turns, 10, "turns beyond 1/32 rad in pairs: %d", m.wide_turns);
    expect_fixed_bodies_paired(m);
}
