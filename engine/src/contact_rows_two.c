// SPDX-License-Identifier: MIT
/* The sequential solvers' (NGS's, Baumgarte's) warm start and velocity
 * passes over the contacts, two at a time where they can be
 * (rb_contact_solver_warm_start, rb_contact_solver_solve_velocities).
 *
 * The constraints are laid out colour by colour, and no two constraints
 * of a colour move the same body (constraint_colouring.h): what one of
 * them does to its bodies' velocities cannot change what another of its
 * colour finds, so within a colour they may be solved in any order, or
 * two at once, and give the same numbers. The substep's preparation
 * (contact_solver_wide.c) pairs the two-point contacts of each colour
 * into rows (rb_contact_row, contact_solver.h): every value a pass reads
 * of the two contacts side by side, lane 0 the first contact's and lane 1
 * the second's, 16-byte aligned, in the order the pass reads them, so
 * that one SSE2 load (part of every x86-64 processor) takes a value of
 * both and the rows stream through the cache. A pass then visits the
 * colours in order (or in reverse), and in each colour solves its rows
 * two contacts at a time and its other constraints (one point, a circle,
 * restitution, a pair of which one does not use the 2x2 block, the odd
 * one out) one at a time by the reference,
 * rb_contact_solver_solve_velocities_range. The overflow colour, whose
 * constraints may share a body, has no rows: it goes to the reference in
 * its order. The rows hold their contacts' impulses while the passes run
 * and from one substep to the next (contact_solver_wide.c), and give them
 * back to the constraints when the step stores them
 * (rb_contact_rows_store_impulses).
 *
 * Same bits. Each lane does the reference's sums and products in the
 * reference's order (contact_solver.c: row_velocity, apply_row_impulse,
 * solve_point_friction, solve_normal_block), and an SSE2 operation
 * rounds each lane as the scalar one would; the build contracts no
 * product into a fused multiply-add (-ffp-contract=off, CMakeLists.txt).
 * Where the reference branches, both lanes compute what each branch would
 * and a mask picks each lane's, so a lane's values are the ones the
 * reference finds:
 * - friction, skipped where a point has no impulse at all: the skipped
 *   lane keeps its velocities and impulse (applying a zero impulse could
 *   turn a -0 into +0);
 * - the 2x2 block's four cases, tried in the reference's order: the
 *   first case that holds in a lane gives its impulses, and where none
 *   holds (round-off), the lane keeps its impulses and velocities.
 * When both lanes take the common branch (friction active, both points
 * pushing), the masks are skipped. Two contacts of a colour may share a
 * body that cannot move (static, kinematic or asleep): both lanes write
 * its velocities back unchanged, as the reference does.
 * tests/test_contact_rows.c compares both ways byte for byte. */
#include "allocator.h"
#include "contact_solver.h"

void rb_contact_rows_free(rb_contact_rows *rows)
{
    rb_free_array((void **)&rows->rows, &rows->row_capacity, sizeof *rows->rows);
    rb_free_array((void **)&rows->runs, &rows->run_capacity, sizeof *rows->runs);
    rows->row_count = 0;
    rows->run_count = 0;
    rows->live = false;
}

size_t rb_contact_rows_bytes(const rb_contact_rows *rows)
{
    return (size_t)rows->row_capacity * sizeof *rows->rows + (size_t)rows->run_capacity * sizeof *rows->runs;
}

void rb_contact_rows_store_impulses(rb_world *world)
{
    rb_contact_rows_store_range(world, 0, world->contact_rows.row_count);
    world->contact_rows.live = false;
}

void rb_contact_rows_store_range(rb_world *world, int begin, int end)
{
    const rb_contact_rows *laid = &world->contact_rows;
    for (int k = begin; k < end; ++k) {
        const rb_contact_row *row = &laid->rows[k];
        for (int lane = 0; lane < 2; ++lane) {
            rb_contact_constraint *c = &world->constraints[row->constraints[lane]];
            for (int j = 0; j < 2; ++j) {
                c->points[j].normal_impulse = row->points[j].normal_impulse.v[lane];
                c->points[j].tangent_impulse = row->points[j].tangent_impulse.v[lane];
            }
        }
    }
}

#if defined(__SSE2__)
#include "contact_lanes_two.h"

/* The two bodies' velocities of both contacts, read once before a row is
 * solved and written back once after (as body_velocities in
 * contact_solver.c). */
typedef struct velocity_lanes {
    lanes vax, vay, wa; /* body A: m/s, m/s, rad/s */
    lanes vbx, vby, wb; /* body B */
} velocity_lanes;

static inline velocity_lanes load_velocities(const rb_contact_row *row)
{
    const rb_body_state *a0 = row->body_a[0];
    const rb_body_state *a1 = row->body_a[1];
    const rb_body_state *b0 = row->body_b[0];
    const rb_body_state *b1 = row->body_b[1];
    return (velocity_lanes){
        pair(a0->linear_velocity.x, a1->linear_velocity.x), pair(a0->linear_velocity.y, a1->linear_velocity.y),
        pair(a0->angular_velocity, a1->angular_velocity),   pair(b0->linear_velocity.x, b1->linear_velocity.x),
        pair(b0->linear_velocity.y, b1->linear_velocity.y), pair(b0->angular_velocity, b1->angular_velocity),
    };
}

static inline void store_velocities(const velocity_lanes *v, const rb_contact_row *row)
{
    rb_body_state *a0 = row->body_a[0];
    rb_body_state *a1 = row->body_a[1];
    rb_body_state *b0 = row->body_b[0];
    rb_body_state *b1 = row->body_b[1];
    store_pair(&a0->linear_velocity.x, &a1->linear_velocity.x, v->vax);
    store_pair(&a0->linear_velocity.y, &a1->linear_velocity.y, v->vay);
    store_pair(&a0->angular_velocity, &a1->angular_velocity, v->wa);
    store_pair(&b0->linear_velocity.x, &b1->linear_velocity.x, v->vbx);
    store_pair(&b0->linear_velocity.y, &b1->linear_velocity.y, v->vby);
    store_pair(&b0->angular_velocity, &b1->angular_velocity, v->wb);
}

/* In each lane, the velocities `yes` where the mask is all ones, else
 * `no`. */
static inline velocity_lanes select_velocities(lanes mask, const velocity_lanes *yes, const velocity_lanes *no)
{
    return (velocity_lanes){
        select(mask, yes->vax, no->vax), select(mask, yes->vay, no->vay), select(mask, yes->wa, no->wa),
        select(mask, yes->vbx, no->vbx), select(mask, yes->vby, no->vby), select(mask, yes->wb, no->wb),
    };
}

/* A row's values are read where they are used, not copied out first:
 * SSE2's operations take one operand straight from an aligned address,
 * and the sixteen registers are held by the velocities and the values
 * being worked out (copied out, the row's constants were stored to the
 * stack and read back). The normal is (normal_x, normal_y) and the
 * tangent (normal_y, tangent_y). */

/* row_velocity: d·(vB - vA) + ωB·arm_b - ωA·arm_a along the direction
 * (dx, dy). */
static inline lanes row_velocity(const rb_lanes2 *dx, const rb_lanes2 *dy, const rb_lanes2 *arm_a,
                                 const rb_lanes2 *arm_b, const velocity_lanes *v)
{
    lanes dot = add(mul(load(dx), sub(v->vbx, v->vax)), mul(load(dy), sub(v->vby, v->vay)));
    return sub(add(dot, mul(v->wb, load(arm_b))), mul(v->wa, load(arm_a)));
}

/* apply_row_impulse: -λ·d to A, +λ·d to B, at lever arms arm_a, arm_b. */
static inline void apply_row_impulse(const rb_contact_row *row, const rb_lanes2 *dx, const rb_lanes2 *dy,
                                     const rb_lanes2 *arm_a, const rb_lanes2 *arm_b, lanes lambda, velocity_lanes *v)
{
    lanes ix = mul(lambda, load(dx));
    lanes iy = mul(lambda, load(dy));
    v->vax = sub(v->vax, mul(load(&row->inv_mass_a), ix));
    v->vay = sub(v->vay, mul(load(&row->inv_mass_a), iy));
    v->wa = sub(v->wa, mul(mul(load(&row->inv_inertia_a), lambda), load(arm_a)));
    v->vbx = add(v->vbx, mul(load(&row->inv_mass_b), ix));
    v->vby = add(v->vby, mul(load(&row->inv_mass_b), iy));
    v->wb = add(v->wb, mul(mul(load(&row->inv_inertia_b), lambda), load(arm_b)));
}

/* warm_start_point: the normal's impulse, then the tangent's. */
static inline void warm_start_point(const rb_contact_row *row, const rb_row_point *q, velocity_lanes *v)
{
    apply_row_impulse(row, &row->normal_x, &row->normal_y, &q->normal_arm_a, &q->normal_arm_b, load(&q->normal_impulse),
                      v);
    apply_row_impulse(row, &row->normal_y, &row->tangent_y, &q->tangent_arm_a, &q->tangent_arm_b,
                      load(&q->tangent_impulse), v);
}

static void warm_start_row(const rb_contact_row *row)
{
    velocity_lanes v = load_velocities(row);
    warm_start_point(row, &row->points[0], &v);
    warm_start_point(row, &row->points[1], &v);
    store_velocities(&v, row);
}

/* solve_point_friction, in both lanes: a lane whose point has neither a
 * normal nor a tangent impulse is left as it is. */
static inline __attribute__((always_inline)) void solve_point_friction(const rb_contact_row *row, rb_row_point *q,
                                                                       velocity_lanes *v)
{
    lanes normal_impulse = load(&q->normal_impulse);
    lanes tangent_impulse = load(&q->tangent_impulse);
    lanes zero = _mm_setzero_pd();
    lanes active = _mm_or_pd(_mm_cmpneq_pd(normal_impulse, zero), _mm_cmpneq_pd(tangent_impulse, zero));
    int lanes_active = _mm_movemask_pd(active);
    if (lanes_active == 0) {
        return;
    }
    lanes vt = row_velocity(&row->normal_y, &row->tangent_y, &q->tangent_arm_a, &q->tangent_arm_b, v);
    lanes limit = mul(load(&row->friction), normal_impulse);
    lanes accumulated =
        min(max(sub(tangent_impulse, mul(load(&q->tangent_mass), vt)), negate(limit)), limit); /* rb_clamp */
    lanes delta = sub(accumulated, tangent_impulse);
    if (lanes_active == 3) {
        store(&q->tangent_impulse, accumulated);
        apply_row_impulse(row, &row->normal_y, &row->tangent_y, &q->tangent_arm_a, &q->tangent_arm_b, delta, v);
        return;
    }
    velocity_lanes before = *v;
    apply_row_impulse(row, &row->normal_y, &row->tangent_y, &q->tangent_arm_a, &q->tangent_arm_b, delta, v);
    *v = select_velocities(active, v, &before);
    store(&q->tangent_impulse, select(active, accumulated, tangent_impulse));
}

/* The changes of both points' normal impulses, applied in the
 * reference's order: the first point's, then the second's. */
static inline void apply_normal_changes(const rb_contact_row *row, lanes change1, lanes change2, velocity_lanes *v)
{
    apply_row_impulse(row, &row->normal_x, &row->normal_y, &row->points[0].normal_arm_a, &row->points[0].normal_arm_b,
                      change1, v);
    apply_row_impulse(row, &row->normal_x, &row->normal_y, &row->points[1].normal_arm_a, &row->points[1].normal_arm_b,
                      change2, v);
}

/* solve_normal_block, in both lanes: the 2x2 complementarity problem's
 * four cases in the reference's order, each lane taking the first that
 * holds in it, or keeping its impulses and velocities where none does. */
static inline __attribute__((always_inline)) void solve_normal_block(rb_contact_row *row, velocity_lanes *v)
{
    rb_row_point *q1 = &row->points[0];
    rb_row_point *q2 = &row->points[1];
    lanes zero = _mm_setzero_pd();
    lanes x1_old = load(&q1->normal_impulse);
    lanes x2_old = load(&q2->normal_impulse);
    lanes w1 = sub(row_velocity(&row->normal_x, &row->normal_y, &q1->normal_arm_a, &q1->normal_arm_b, v),
                   load(&q1->min_normal_velocity));
    lanes w2 = sub(row_velocity(&row->normal_x, &row->normal_y, &q2->normal_arm_a, &q2->normal_arm_b, v),
                   load(&q2->min_normal_velocity));
    lanes b1 = sub(w1, add(mul(load(&row->k11), x1_old), mul(load(&row->k12), x2_old)));
    lanes b2 = sub(w2, add(mul(load(&row->k12), x1_old), mul(load(&row->k22), x2_old)));

    /* Case 1: both push, w = 0. */
    lanes x1 = negate(add(mul(load(&row->inv_k11), b1), mul(load(&row->inv_k12), b2)));
    lanes x2 = negate(add(mul(load(&row->inv_k12), b1), mul(load(&row->inv_k22), b2)));
    lanes both_push = _mm_and_pd(_mm_cmpge_pd(x1, zero), _mm_cmpge_pd(x2, zero));
    if (_mm_movemask_pd(both_push) == 3) {
        store(&q1->normal_impulse, x1);
        store(&q2->normal_impulse, x2);
        apply_normal_changes(row, sub(x1, x1_old), sub(x2, x2_old), v);
        return;
    }
    /* Case 2: only the first pushes. */
    lanes k12 = load(&row->k12);
    lanes first_x1 = divide(negate(b1), load(&row->k11));
    lanes first_only = _mm_and_pd(_mm_cmpge_pd(first_x1, zero), _mm_cmpge_pd(add(mul(k12, first_x1), b2), zero));
    /* Case 3: only the second pushes. */
    lanes second_x2 = divide(negate(b2), load(&row->k22));
    lanes second_only = _mm_and_pd(_mm_cmpge_pd(second_x2, zero), _mm_cmpge_pd(add(mul(k12, second_x2), b1), zero));
    /* Case 4: neither pushes; valid when both separate. */
    lanes neither = _mm_and_pd(_mm_cmpge_pd(b1, zero), _mm_cmpge_pd(b2, zero));
    /* Each lane's first case that holds: 1, else 2, else 3, else 4 (both
     * impulses 0). */
    x1 = select(both_push, x1, select(first_only, first_x1, zero));
    x2 = select(both_push, x2, select(first_only, zero, select(second_only, second_x2, zero)));
    lanes solved = _mm_or_pd(_mm_or_pd(both_push, first_only), _mm_or_pd(second_only, neither));
    if (_mm_movemask_pd(solved) == 3) {
        store(&q1->normal_impulse, x1);
        store(&q2->normal_impulse, x2);
        apply_normal_changes(row, sub(x1, x1_old), sub(x2, x2_old), v);
        return;
    }
    velocity_lanes before = *v;
    apply_normal_changes(row, sub(x1, x1_old), sub(x2, x2_old), v);
    *v = select_velocities(solved, v, &before);
    store(&q1->normal_impulse, select(solved, x1, x1_old));
    store(&q2->normal_impulse, select(solved, x2, x2_old));
}

/* The reference's work on one constraint (friction, then the block), on
 * both contacts of a row. */
static void solve_row(rb_contact_row *row)
{
    velocity_lanes v = load_velocities(row);
    solve_point_friction(row, &row->points[0], &v);
    solve_point_friction(row, &row->points[1], &v);
    solve_normal_block(row, &v);
    store_velocities(&v, row);
}

void rb_contact_solver_warm_start(rb_world *world)
{
    const rb_contact_rows *laid = &world->contact_rows;
    if (!laid->live || laid->row_count == 0) {
        if (world->constraint_count > 0) { /* a world of joints and muscles has none, in every pass */
            rb_contact_solver_warm_start_range(world, 0, world->constraint_count);
        }
        return;
    }
    for (int colour = 0; colour < laid->colour_count; ++colour) {
        for (int k = laid->row_start[colour]; k < laid->row_start[colour + 1]; ++k) {
            warm_start_row(&laid->rows[k]);
        }
        for (int k = laid->run_start[colour]; k < laid->run_start[colour + 1]; ++k) {
            rb_contact_solver_warm_start_range(world, laid->runs[k].begin, laid->runs[k].end);
        }
    }
}

/* Colour by colour, forwards or backwards; within a colour the rows, then
 * the others one at a time (in reverse when backwards, which matters only
 * in the overflow colour). Without rows, that is the reference's sweep
 * over all the constraints. */
void rb_contact_solver_solve_velocities(rb_world *world, bool backwards)
{
    const rb_contact_rows *laid = &world->contact_rows;
    if (!laid->live || laid->row_count == 0) {
        if (world->constraint_count > 0) {
            rb_contact_solver_solve_velocities_range(world, backwards, 0, world->constraint_count);
        }
        return;
    }
    for (int n = 0; n < laid->colour_count; ++n) {
        int colour = backwards ? laid->colour_count - 1 - n : n;
        for (int k = laid->row_start[colour]; k < laid->row_start[colour + 1]; ++k) {
            solve_row(&laid->rows[k]);
        }
        int first = laid->run_start[colour];
        int last = laid->run_start[colour + 1] - 1;
        for (int k = first; k <= last; ++k) {
            const rb_constraint_run *run = &laid->runs[backwards ? first + last - k : k];
            rb_contact_solver_solve_velocities_range(world, backwards, run->begin, run->end);
        }
    }
}

#else

void rb_contact_solver_warm_start(rb_world *world)
{
    rb_contact_solver_warm_start_range(world, 0, world->constraint_count);
}

void rb_contact_solver_solve_velocities(rb_world *world, bool backwards)
{
    rb_contact_solver_solve_velocities_range(world, backwards, 0, world->constraint_count);
}

#endif
