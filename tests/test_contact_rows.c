// SPDX-License-Identifier: MIT
/* The sequential solvers' (NGS's, Baumgarte's) contact passes over rows
 * of two contacts (contact_rows_two.c: rb_contact_solver_warm_start and
 * rb_contact_solver_solve_velocities after rb_contact_solver_prepare_points
 * laid the rows out, contact_solver_wide.c) against the reference that
 * prepares and solves one contact at a time over the constraints in order
 * (rb_contact_solver_prepare_points_range,
 * rb_contact_solver_warm_start_range,
 * rb_contact_solver_solve_velocities_range): from the same contacts, poses
 * and velocities, both ways must leave the same velocities and impulses,
 * and the rows must hold what the reference prepares, byte for byte. The
 * stated tolerance is none: within a colour no two contacts move the same
 * body, so solving two at once is solving them one after the other, and
 * each lane does the reference's arithmetic in the reference's order.
 *
 * The contacts are those of a settled base-20 pyramid (590 contacts of two
 * points) with balls beside it (contacts of one point, which stay out of
 * the rows) and every seventh box given restitution (its contacts too stay
 * out). The piles are run as they are and pushed: every box's velocity
 * and pose disturbed, so that points push or let go, one point of a
 * contact pushes while the other lets go (the 2x2 block's cases 2 and 3),
 * both let go (case 4), and friction slides at the cone. The test counts
 * that each of these happened in the reference's results, so that a wrong
 * choice in any of them could not go unseen. Two choices cannot be forced
 * from real contacts: friction's skip of a point with no impulse at all
 * (a lane that did not skip would apply a zero impulse, which can only
 * change the sign of a zero), and the block keeping its impulses where
 * round-off defeats all four cases. */
#include <string.h>

#include "contact_solver.h"
#include "pile_support.h"

#define SUBSTEPS 6
#define PASSES 4

/* A deterministic value in [-1, 1) (a linear congruential generator,
 * Knuth's MMIX constants). */
static double next_unit(uint64_t *state)
{
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (double)(*state >> 11) / (double)(UINT64_C(1) << 52) - 1.0;
}

/* What the reference's impulses show of the cases the passes met. */
typedef struct cases_met {
    int both_push;     /* two-point contacts with both normal impulses > 0 */
    int one_pushes;    /* exactly one > 0 */
    int neither;       /* both 0 */
    int sliding;       /* points whose friction reached the cone in a pass, |λt| = μ·λn > 0 */
    int rows, singles; /* contacts solved in rows, and one at a time */
} cases_met;

/* The points whose friction reached the cone in the pass just done:
 * a contact's friction is solved before its normal rows, and no other
 * contact changes its impulses, so its cone was μ times the normal
 * impulse it had before the pass (`before`, two a constraint). */
static int count_sliding(const rb_world *world, const double *before)
{
    int sliding = 0;
    for (int i = 0; i < world->constraint_count; ++i) {
        const rb_contact_constraint *c = &world->constraints[i];
        for (int j = 0; j < c->point_count; ++j) {
            double limit = c->friction * before[2 * i + j];
            sliding += limit > 0.0 && fabs(c->points[j].tangent_impulse) == limit;
        }
    }
    return sliding;
}

static void record_normal_impulses(const rb_world *world, double *before)
{
    for (int i = 0; i < world->constraint_count; ++i) {
        for (int j = 0; j < world->constraints[i].point_count; ++j) {
            before[2 * i + j] = world->constraints[i].points[j].normal_impulse;
        }
    }
}

/* The normal impulses' cases at the end of the passes. */
static cases_met count_cases(const rb_world *world)
{
    cases_met met = {0};
    for (int i = 0; i < world->constraint_count; ++i) {
        const rb_contact_constraint *c = &world->constraints[i];
        if (c->point_count == 2) {
            int pushing = (c->points[0].normal_impulse > 0.0) + (c->points[1].normal_impulse > 0.0);
            met.both_push += pushing == 2;
            met.one_pushes += pushing == 1;
            met.neither += pushing == 0;
        }
    }
    return met;
}

/* Each row's lanes against the constraints as the reference prepared
 * them: the same bytes. */
static void expect_rows_hold_the_reference(const rb_world *world, const rb_contact_constraint *reference)
{
    const rb_contact_rows *laid = &world->contact_rows;
    for (int k = 0; k < laid->row_count; ++k) {
        const rb_contact_row *row = &laid->rows[k];
        for (int lane = 0; lane < 2; ++lane) {
            const rb_contact_constraint *c = &reference[row->constraints[lane]];
            cr_assert(c->use_block, "constraint %d is in a row but the reference does not use its block",
                      row->constraints[lane]);
            double row_values[2 + 6 + 2 * 6];
            double reference_values[2 + 6 + 2 * 6];
            double *x = row_values;
            double *y = reference_values;
            *x++ = row->normal_x.v[lane], *y++ = c->normal.x;
            *x++ = row->normal_y.v[lane], *y++ = c->normal.y;
            *x++ = row->k11.v[lane], *y++ = c->k11;
            *x++ = row->k12.v[lane], *y++ = c->k12;
            *x++ = row->k22.v[lane], *y++ = c->k22;
            *x++ = row->inv_k11.v[lane], *y++ = c->inv_k11;
            *x++ = row->inv_k12.v[lane], *y++ = c->inv_k12;
            *x++ = row->inv_k22.v[lane], *y++ = c->inv_k22;
            for (int j = 0; j < 2; ++j) {
                const rb_row_point *q = &row->points[j];
                const rb_constraint_point *p = &c->points[j];
                *x++ = q->normal_arm_a.v[lane], *y++ = p->normal_arm_a;
                *x++ = q->normal_arm_b.v[lane], *y++ = p->normal_arm_b;
                *x++ = q->tangent_arm_a.v[lane], *y++ = p->tangent_arm_a;
                *x++ = q->tangent_arm_b.v[lane], *y++ = p->tangent_arm_b;
                *x++ = q->tangent_mass.v[lane], *y++ = p->tangent_mass;
                *x++ = q->min_normal_velocity.v[lane], *y++ = p->min_normal_velocity;
            }
            cr_expect(memcmp(row_values, reference_values, sizeof row_values) == 0,
                      "constraint %d prepared differently in lane %d of row %d: normal (%.17g, %.17g) and "
                      "(%.17g, %.17g), k11 %.17g and %.17g",
                      row->constraints[lane], lane, k, row_values[0], row_values[1], reference_values[0],
                      reference_values[1], row_values[2], reference_values[2]);
        }
    }
}

/* Disturbs every dynamic body's velocity by up to `push` (m/s, and rad/s
 * per m of its size, 1 m here) and its pose by up to `shift` m (and
 * shift/2 rad), as a substep's start might find them. */
static void disturb(rb_world *world, double push, double shift, uint64_t seed)
{
    for (int i = 0; i < world->body_slots; ++i) {
        if (!world->bodies[i].in_use || world->bodies[i].type != RB_BODY_DYNAMIC) {
            continue;
        }
        rb_body_state *s = &world->states[i];
        s->linear_velocity = rb_add(s->linear_velocity, rb_v2(push * next_unit(&seed), push * next_unit(&seed)));
        s->angular_velocity += push * next_unit(&seed);
        s->center = rb_add(s->center, rb_v2(shift * next_unit(&seed), shift * next_unit(&seed)));
        s->angle += 0.5 * shift * next_unit(&seed);
        s->rotation = rb_rot_from_angle(s->angle);
    }
}

/* From the contacts of the poses now, disturbed, one substep's
 * preparation, warm start and velocity passes both ways (alternating in
 * direction for NGS, forwards only for Baumgarte, as the solvers run
 * them); expects the same results and returns the cases the reference
 * met. */
/* The states and constraints the passes start from, to run them again,
 * and as the reference left them. */
typedef struct copies {
    size_t state_bytes, constraint_bytes;
    rb_body_state *start_states, *reference_states;
    rb_contact_constraint *start_constraints, *reference;
} copies;

static copies copy_start(const rb_world *world, int count)
{
    copies c = {.state_bytes = (size_t)world->body_slots * sizeof *world->states,
                .constraint_bytes = (size_t)count * sizeof *world->constraints};
    c.start_states = malloc(c.state_bytes);
    c.reference_states = malloc(c.state_bytes);
    c.start_constraints = malloc(c.constraint_bytes);
    c.reference = malloc(c.constraint_bytes);
    cr_assert(c.start_states && c.reference_states && c.start_constraints && c.reference);
    memcpy(c.start_states, world->states, c.state_bytes);
    memcpy(c.start_constraints, world->constraints, c.constraint_bytes);
    return c;
}

/* The world as it was when the copies were made. */
static void restart(rb_world *world, const copies *c)
{
    memcpy(world->states, c->start_states, c->state_bytes);
    memcpy(world->constraints, c->start_constraints, c->constraint_bytes);
}

static void free_copies(copies *c)
{
    free(c->start_states);
    free(c->reference_states);
    free(c->start_constraints);
    free(c->reference);
}

static cases_met expect_passes_agree(rb_world *world, rb_substep_rows rows, double push, double shift, uint64_t seed)
{
    cr_assert_geq(rb_contact_solver_prepare(world), 0, "out of memory");
    int count = world->constraint_count;
    cr_assert_gt(count, 590, "the pyramid's contacts and the balls' (%d)", count);
    disturb(world, push, shift, seed);
    double h = TEST_DT / SUBSTEPS;
    bool alternate = !rows.baumgarte_bias;

    copies c = copy_start(world, count);

    /* the reference: one contact at a time, in order */
    rb_contact_solver_prepare_points_range(world, h, rows, 0, count);
    memcpy(c.reference, world->constraints, c.constraint_bytes);
    rb_contact_solver_warm_start_range(world, 0, count);
    double *normal_before = malloc((size_t)count * 2 * sizeof *normal_before);
    cr_assert(normal_before);
    int sliding = 0;
    for (int pass = 0; pass < PASSES; ++pass) {
        record_normal_impulses(world, normal_before);
        rb_contact_solver_solve_velocities_range(world, alternate && pass % 2 == 1, 0, count);
        sliding += count_sliding(world, normal_before);
    }
    free(normal_before);
    cases_met met = count_cases(world);
    met.sliding = sliding;
    memcpy(c.reference_states, world->states, c.state_bytes);
    for (int i = 0; i < count; ++i) {
        memcpy(c.reference[i].points, world->constraints[i].points, sizeof c.reference[i].points);
    }

    /* the rows */
    restart(world, &c);
    rb_contact_solver_prepare_points(world, h, rows);
    cr_assert(world->contact_rows.live, "the preparation laid out rows");
    expect_rows_hold_the_reference(world, c.reference);
    met.rows = 2 * world->contact_rows.row_count;
    met.singles = count - met.rows;
    rb_contact_solver_warm_start(world);
    for (int pass = 0; pass < PASSES; ++pass) {
        rb_contact_solver_solve_velocities(world, alternate && pass % 2 == 1);
    }
    rb_contact_rows_store_impulses(world);

    for (int i = 0; i < world->body_slots; ++i) {
        const rb_body_state *r = &c.reference_states[i];
        const rb_body_state *w = &world->states[i];
        cr_expect(memcmp(r, w, sizeof *r) == 0,
                  "body %d: velocity (%.17g, %.17g, %.17g) one at a time, (%.17g, %.17g, %.17g) in rows (push %g, "
                  "seed %llu)",
                  i, r->linear_velocity.x, r->linear_velocity.y, r->angular_velocity, w->linear_velocity.x,
                  w->linear_velocity.y, w->angular_velocity, push, (unsigned long long)seed);
    }
    for (int i = 0; i < count; ++i) {
        const rb_contact_constraint *r = &c.reference[i];
        const rb_contact_constraint *w = &world->constraints[i];
        for (int j = 0; j < r->point_count; ++j) {
            double expected[2] = {r->points[j].normal_impulse, r->points[j].tangent_impulse};
            double found[2] = {w->points[j].normal_impulse, w->points[j].tangent_impulse};
            cr_expect(memcmp(expected, found, sizeof expected) == 0,
                      "constraint %d point %d: impulses (%.17g, %.17g) one at a time, (%.17g, %.17g) in rows (push "
                      "%g, seed %llu)",
                      i, j, expected[0], expected[1], found[0], found[1], push, (unsigned long long)seed);
        }
    }
    free_copies(&c);
    return met;
}

/* Moves every dynamic body by its velocity over h, as a substep's end
 * does (without damping). */
static void move_bodies(rb_world *world, double h)
{
    for (int i = 0; i < world->body_slots; ++i) {
        if (world->bodies[i].in_use && world->bodies[i].type == RB_BODY_DYNAMIC) {
            rb_body_state *s = &world->states[i];
            s->center = rb_mul_add(s->center, h, s->linear_velocity);
            s->angle += h * s->angular_velocity;
            s->rotation = rb_rot_from_angle(s->angle);
        }
    }
}

/* Every ninth two-point constraint given restitution, so that it leaves
 * the rows in the next substep's preparation. */
static void bounce_some(rb_world *world)
{
    for (int i = 0; i < world->constraint_count; i += 9) {
        world->constraints[i].restitution = 0.5;
    }
}

/* Three substeps' preparations, warm starts and velocity passes both
 * ways, the bodies moved between them, and before the third some
 * contacts leaving the rows: the second substep's rows pair the same
 * contacts as the first's and keep their impulses; the third's differ
 * from the first contact that left on, and the rows before it keep
 * theirs while the others give them back and take them anew. */
static void expect_substeps_agree(rb_world *world, rb_substep_rows rows, double push, uint64_t seed)
{
    cr_assert_geq(rb_contact_solver_prepare(world), 0, "out of memory");
    int count = world->constraint_count;
    disturb(world, push, 0.0, seed);
    double h = TEST_DT / SUBSTEPS;
    copies c = copy_start(world, count);
    for (int substep = 0; substep < 3; ++substep) {
        if (substep == 2) {
            bounce_some(world);
        }
        rb_contact_solver_prepare_points_range(world, h, rows, 0, count);
        rb_contact_solver_warm_start_range(world, 0, count);
        for (int pass = 0; pass < PASSES; ++pass) {
            rb_contact_solver_solve_velocities_range(world, pass % 2 == 1, 0, count);
        }
        move_bodies(world, h);
    }
    memcpy(c.reference_states, world->states, c.state_bytes);
    memcpy(c.reference, world->constraints, c.constraint_bytes);

    restart(world, &c);
    int row_counts[3];
    for (int substep = 0; substep < 3; ++substep) {
        if (substep == 2) {
            bounce_some(world);
        }
        rb_contact_solver_prepare_points(world, h, rows);
        row_counts[substep] = world->contact_rows.row_count;
        rb_contact_solver_warm_start(world);
        for (int pass = 0; pass < PASSES; ++pass) {
            rb_contact_solver_solve_velocities(world, pass % 2 == 1);
        }
        move_bodies(world, h);
    }
    rb_contact_rows_store_impulses(world);
    cr_expect(row_counts[0] == row_counts[1] && row_counts[2] < row_counts[1],
              "the rows stay while no contact leaves them, and fewer after some leave (%d, %d, %d)", row_counts[0],
              row_counts[1], row_counts[2]);

    for (int i = 0; i < world->body_slots; ++i) {
        cr_expect(memcmp(&c.reference_states[i], &world->states[i], sizeof *world->states) == 0,
                  "body %d: state after three substeps differs one at a time and in rows", i);
    }
    for (int i = 0; i < count; ++i) {
        for (int j = 0; j < c.reference[i].point_count; ++j) {
            const rb_constraint_point *r = &c.reference[i].points[j];
            const rb_constraint_point *w = &world->constraints[i].points[j];
            cr_expect(r->normal_impulse == w->normal_impulse && r->tangent_impulse == w->tangent_impulse,
                      "constraint %d point %d: impulses (%.17g, %.17g) one at a time, (%.17g, %.17g) in rows after "
                      "three substeps",
                      i, j, r->normal_impulse, r->tangent_impulse, w->normal_impulse, w->tangent_impulse);
        }
    }
    free_copies(&c);
}

/* A settled base-20 pyramid with nine balls beside it, every seventh box
 * bouncing, in a world of the given solver. */
static rb_world *settled_pile(rb_solver_type type)
{
    scene_pyramid pyramid;
    rb_world *world = make_pile(type, &pyramid);
    for (int k = 0; k < pyramid.box_count; k += 7) {
        rb_shape_id shape;
        cr_assert_eq(rb_body_shapes(world, scene_body_at(pyramid.first_box, k), &shape, 1), 1);
        cr_assert_eq(rb_shape_set_restitution(world, shape, 0.5), RB_OK, "%s", rb_last_error());
    }
    step_world(world, TEST_DT, 60);
    return world;
}

Test(contact_rows, ngs_rows_give_the_reference_velocities_and_impulses)
{
    rb_world *world = settled_pile(RB_SOLVER_NGS);
    size_t bytes = (size_t)world->body_slots * sizeof *world->states;
    rb_body_state *settled = malloc(bytes);
    cr_assert(settled);
    memcpy(settled, world->states, bytes);
    double slop = world->settings.linear_slop;
    rb_substep_rows rows = {.block_normals = true};

    cases_met rest = expect_passes_agree(world, rows, 0.0, 0.0, 1u);
    cr_expect_gt(rest.rows, 400, "most of the pyramid's contacts are solved in rows (%d)", rest.rows);
    cr_expect_gt(rest.singles, 60, "the balls' and the bouncing boxes' contacts are not (%d)", rest.singles);
    cr_expect_gt(rest.both_push, 400, "a settled pile: most contacts push at both points (%d)", rest.both_push);

    cases_met total = rest;
    static const double pushes[] = {0.5, 2.0, 5.0};
    for (int k = 0; k < 3; ++k) {
        memcpy(world->states, settled, bytes);
        cases_met met = expect_passes_agree(world, rows, pushes[k], 2.0 * slop, 100u + (uint64_t)k);
        total.one_pushes += met.one_pushes;
        total.neither += met.neither;
        total.sliding += met.sliding;
    }
    cr_expect_gt(total.one_pushes, 100, "pushed: one point of a contact pushes, the other lets go (%d)",
                 total.one_pushes);
    cr_expect_gt(total.neither, 100, "pushed: contacts let go at both points (%d)", total.neither);
    cr_expect_gt(total.sliding, 100, "pushed: points slide at the friction cone (%d)", total.sliding);
    free(settled);
    destroy_world_and_expect_no_leak(world);
}

/* Baumgarte's passes: a push-out bias in the bounds, forwards only. */
Test(contact_rows, baumgarte_rows_give_the_reference_velocities_and_impulses)
{
    rb_world *world = settled_pile(RB_SOLVER_BAUMGARTE);
    double slop = world->settings.linear_slop;
    rb_substep_rows rows = {.baumgarte_bias = true, .block_normals = true};
    cases_met met = expect_passes_agree(world, rows, 1.0, 4.0 * slop, 7u);
    cr_expect_gt(met.rows, 400, "most of the pyramid's contacts are solved in rows (%d)", met.rows);
    destroy_world_and_expect_no_leak(world);
}

/* The rows kept from one substep to the next, and laid out anew when
 * contacts leave them. */
Test(contact_rows, rows_carry_their_impulses_from_substep_to_substep)
{
    rb_world *world = settled_pile(RB_SOLVER_NGS);
    expect_substeps_agree(world, (rb_substep_rows){.block_normals = true}, 1.0, 21u);
    destroy_world_and_expect_no_leak(world);
}
