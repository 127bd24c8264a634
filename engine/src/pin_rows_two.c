// SPDX-License-Identifier: MIT
/* The plain pins' warm start, velocity passes and NGS position pass, two
 * rows at a time where they can be (joint_pin.c gives the rows and the
 * one-row reference: rb_pin_warm_start, rb_pin_correct; joint_solver.h
 * rb_pin_solve_rigid and rb_pin_solve).
 *
 * A pass visits the rows in order (or in reverse), each row reading the
 * poses or velocities the rows before it wrote. Two consecutive rows
 * whose four bodies are distinct cannot see each other's work: what one
 * writes, the other never reads. Solved side by side, each in a lane of
 * an SSE2 register (lanes_two.h), they give what one after the other
 * gives, to the bit, as long as each lane does the reference's sums and
 * products in the reference's order. The order the pins are visited in
 * (joint_order.c: depth by depth, colour by colour, no two pins of a
 * colour sharing a body) makes almost every consecutive pair such a pair:
 * the 100 × 100 joint grid's 19,794 rows make 9,894 pairs and leave 6
 * alone. A row that shares a body with the next, even a fixed one, goes
 * through the reference on its own.
 *
 * Where the reference branches, the pair takes the common branch in both
 * lanes or hands the branch to the reference:
 * - a pin between two bodies that cannot move (K singular): its inverse
 *   is 0 in the warm start, as the reference makes it, and the position
 *   pass leaves both rows to the reference before either has written
 *   anything;
 * - a drift beyond its cap (rb_point_drift) is made again by the
 *   reference, for both rows;
 * - a body turns by its Taylor series while |Δθ| <= 1/32 rad
 *   (rb_body_state_turn): where a lane's turn is larger, or its body
 *   cannot turn (inverse inertia 0, where the reference does not touch
 *   its angle), each lane's body turns, or not, through the reference.
 * Without SSE2 every row goes through the reference.
 * tests/test_pin_lanes.c compares both ways byte for byte. */
#include "joint_solver.h"

/* The k-th row of a pass, counted from the end when sweeping backwards. */
static int row_at(int count, int k, bool backwards) { return backwards ? count - 1 - k : k; }

#if defined(__SSE2__)
#include "lanes_two.h"

/* Whether two rows move four distinct bodies (a row's two are distinct). */
static inline bool apart(const rb_pin_row *first, const rb_pin_row *second)
{
    return first->body_a != second->body_a && first->body_a != second->body_b && first->body_b != second->body_a &&
           first->body_b != second->body_b;
}

/* The rows the pass visits at its k-th place: *first, and *second too
 * when the two move four distinct bodies (returns 2), else 1. */
static inline int rows_at(const rb_world *world, int count, int k, bool backwards, int *first, int *second)
{
    *first = row_at(count, k, backwards);
    if (k + 1 < count) {
        *second = row_at(count, k + 1, backwards);
        if (apart(&world->pin_rows[*first], &world->pin_rows[*second])) {
            return 2;
        }
    }
    return 1;
}

/* A pair of bodies' states, lane by lane. */
typedef struct state_pair {
    rb_body_state *s[2];
} state_pair;

/* rb_apply_at_anchors on both lanes' bodies: -P at rA to A, +P at rB to B. */
static inline void apply_two(state_pair a, state_pair b, lanes inv_mass_a, lanes inv_inertia_a, lanes inv_mass_b,
                             lanes inv_inertia_b, lanes rax, lanes ray, lanes rbx, lanes rby, lanes px, lanes py)
{
    store_pair(&a.s[0]->linear_velocity.x, &a.s[1]->linear_velocity.x,
               sub(pair(a.s[0]->linear_velocity.x, a.s[1]->linear_velocity.x), mul(inv_mass_a, px)));
    store_pair(&a.s[0]->linear_velocity.y, &a.s[1]->linear_velocity.y,
               sub(pair(a.s[0]->linear_velocity.y, a.s[1]->linear_velocity.y), mul(inv_mass_a, py)));
    store_pair(&a.s[0]->angular_velocity, &a.s[1]->angular_velocity,
               sub(pair(a.s[0]->angular_velocity, a.s[1]->angular_velocity),
                   mul(inv_inertia_a, sub(mul(rax, py), mul(ray, px)))));
    store_pair(&b.s[0]->linear_velocity.x, &b.s[1]->linear_velocity.x,
               add(pair(b.s[0]->linear_velocity.x, b.s[1]->linear_velocity.x), mul(inv_mass_b, px)));
    store_pair(&b.s[0]->linear_velocity.y, &b.s[1]->linear_velocity.y,
               add(pair(b.s[0]->linear_velocity.y, b.s[1]->linear_velocity.y), mul(inv_mass_b, py)));
    store_pair(&b.s[0]->angular_velocity, &b.s[1]->angular_velocity,
               add(pair(b.s[0]->angular_velocity, b.s[1]->angular_velocity),
                   mul(inv_inertia_b, sub(mul(rbx, py), mul(rby, px)))));
}

/* Both bodies turned by their lane of delta, as rb_body_state_turn turns
 * one, where they can turn (inverse inertia > 0); qc, qs their rotations
 * before the turn. */
static inline void turn_two(state_pair bodies, lanes delta, lanes inv_inertia, lanes qc, lanes qs)
{
    const lanes zero = _mm_setzero_pd();
    const int turns = _mm_movemask_pd(_mm_cmpgt_pd(inv_inertia, zero));
    const int small = _mm_movemask_pd(_mm_cmple_pd(_mm_andnot_pd(both(-0.0), delta), both(0.03125)));
    if (turns != 3 || small != 3) {
        /* Only where a lane's body turns, through the reference. */
        const double deltas[2] = {first_of(delta), second_of(delta)};
        for (int lane = 0; lane < 2; ++lane) {
            if (turns & (1 << lane)) {
                rb_body_state_turn(bodies.s[lane], deltas[lane]);
            }
        }
        return;
    }
    store_pair(&bodies.s[0]->angle, &bodies.s[1]->angle, add(pair(bodies.s[0]->angle, bodies.s[1]->angle), delta));
    const lanes one = both(1.0);
    const lanes d2 = mul(delta, delta);
    const lanes sine =
        mul(delta, sub(one, mul(mul(d2, both(1.0 / 6.0)),
                                sub(one, mul(mul(d2, both(1.0 / 20.0)), sub(one, mul(d2, both(1.0 / 42.0))))))));
    const lanes cosine =
        sub(one, mul(mul(d2, both(0.5)),
                     sub(one, mul(mul(d2, both(1.0 / 12.0)),
                                  sub(one, mul(mul(d2, both(1.0 / 30.0)), sub(one, mul(d2, both(1.0 / 56.0)))))))));
    /* rb_mul_rot(rotation, (cosine, sine)) */
    store_pair(&bodies.s[0]->rotation.c, &bodies.s[1]->rotation.c, sub(mul(qc, cosine), mul(qs, sine)));
    store_pair(&bodies.s[0]->rotation.s, &bodies.s[1]->rotation.s, add(mul(qs, cosine), mul(qc, sine)));
}

/* A pair's rotations and its anchors turned into the world at the poses
 * now: rA = R(θA)·localA, rB likewise, as rb_rotate turns them. */
typedef struct arm_lanes {
    lanes qac, qas, qbc, qbs; /* cosines and sines of A's and B's angles */
    lanes rax, ray, rbx, rby; /* m */
} arm_lanes;

static inline arm_lanes arms_now(const rb_world *world, int i0, int i1, state_pair a, state_pair b)
{
    const rb_pin_anchors *n0 = &world->pin_anchors[i0];
    const rb_pin_anchors *n1 = &world->pin_anchors[i1];
    arm_lanes arms = {
        .qac = pair(a.s[0]->rotation.c, a.s[1]->rotation.c),
        .qas = pair(a.s[0]->rotation.s, a.s[1]->rotation.s),
        .qbc = pair(b.s[0]->rotation.c, b.s[1]->rotation.c),
        .qbs = pair(b.s[0]->rotation.s, b.s[1]->rotation.s),
    };
    const lanes lax = pair(n0->local_a.x, n1->local_a.x);
    const lanes lay = pair(n0->local_a.y, n1->local_a.y);
    const lanes lbx = pair(n0->local_b.x, n1->local_b.x);
    const lanes lby = pair(n0->local_b.y, n1->local_b.y);
    arms.rax = sub(mul(arms.qac, lax), mul(arms.qas, lay));
    arms.ray = add(mul(arms.qas, lax), mul(arms.qac, lay));
    arms.rbx = sub(mul(arms.qbc, lbx), mul(arms.qbs, lby));
    arms.rby = add(mul(arms.qbs, lbx), mul(arms.qbc, lby));
    return arms;
}

/* The pin's 2 × 2 mass matrix K at those anchors (joint_point.c gives
 * it), and its determinant. */
typedef struct mass_lanes {
    lanes k11, k12, k22, det;
} mass_lanes;

static inline mass_lanes mass_of(lanes inv_mass_a, lanes inv_inertia_a, lanes inv_mass_b, lanes inv_inertia_b,
                                 const arm_lanes *r)
{
    const lanes m = add(inv_mass_a, inv_mass_b);
    mass_lanes k = {
        .k11 = add(add(m, mul(mul(inv_inertia_a, r->ray), r->ray)), mul(mul(inv_inertia_b, r->rby), r->rby)),
        .k12 = sub(mul(mul(negate(inv_inertia_a), r->rax), r->ray), mul(mul(inv_inertia_b, r->rbx), r->rby)),
        .k22 = add(add(m, mul(mul(inv_inertia_a, r->rax), r->rax)), mul(mul(inv_inertia_b, r->rbx), r->rbx)),
    };
    k.det = sub(mul(k.k11, k.k22), mul(k.k12, k.k12));
    return k;
}

/* rb_pin_warm_start (joint_pin.c) on rows i0 and i1 at once: each row's
 * anchors at the poses now, the inverse of its K, its drift, and its
 * impulse applied. */
static void warm_start_two(rb_world *world, int i0, int i1, double h, double drift_cap)
{
    rb_pin_row *r0 = &world->pin_rows[i0];
    rb_pin_row *r1 = &world->pin_rows[i1];
    const state_pair a = {{&world->states[r0->body_a], &world->states[r1->body_a]}};
    const state_pair b = {{&world->states[r0->body_b], &world->states[r1->body_b]}};
    const arm_lanes arms = arms_now(world, i0, i1, a, b);
    const lanes rax = arms.rax, ray = arms.ray, rbx = arms.rbx, rby = arms.rby;
    store_pair(&r0->ra.x, &r1->ra.x, rax);
    store_pair(&r0->ra.y, &r1->ra.y, ray);
    store_pair(&r0->rb.x, &r1->rb.x, rbx);
    store_pair(&r0->rb.y, &r1->rb.y, rby);

    /* K's inverse, all 0 where K is singular. */
    const lanes ima = pair(r0->inv_mass_a, r1->inv_mass_a);
    const lanes iia = pair(r0->inv_inertia_a, r1->inv_inertia_a);
    const lanes imb = pair(r0->inv_mass_b, r1->inv_mass_b);
    const lanes iib = pair(r0->inv_inertia_b, r1->inv_inertia_b);
    const mass_lanes k = mass_of(ima, iia, imb, iib, &arms);
    const lanes inverse_det =
        _mm_and_pd(_mm_cmpgt_pd(k.det, _mm_setzero_pd()), divide(both(1.0), k.det)); /* 1/det where det > 0, else +0 */
    store_pair(&r0->point_inverse11, &r1->point_inverse11, mul(inverse_det, k.k22));
    store_pair(&r0->point_inverse12, &r1->point_inverse12, mul(negate(inverse_det), k.k12));
    store_pair(&r0->point_inverse22, &r1->point_inverse22, mul(inverse_det, k.k11));

    /* The drift (rb_point_drift), capped through the reference's
     * arithmetic in the rare lane that needs it. */
    const lanes wa0 = pair(world->substep_omega[r0->body_a], world->substep_omega[r1->body_a]);
    const lanes wb0 = pair(world->substep_omega[r0->body_b], world->substep_omega[r1->body_b]);
    const lanes wa2 = mul(wa0, wa0);
    const lanes wb2 = mul(wb0, wb0);
    const lanes half_h = both(0.5 * h);
    const lanes dx = mul(half_h, sub(mul(wb2, rbx), mul(wa2, rax)));
    const lanes dy = mul(half_h, sub(mul(wb2, rby), mul(wa2, ray)));
    store_pair(&r0->point_drift.x, &r1->point_drift.x, dx);
    store_pair(&r0->point_drift.y, &r1->point_drift.y, dy);
    if (_mm_movemask_pd(_mm_cmpgt_pd(add(mul(dx, dx), mul(dy, dy)), both(drift_cap * drift_cap))) != 0) {
        r0->point_drift = rb_point_drift(world, r0->body_a, r0->body_b, r0->ra, r0->rb, h, drift_cap);
        r1->point_drift = rb_point_drift(world, r1->body_a, r1->body_b, r1->ra, r1->rb, h, drift_cap);
    }

    /* The warm start: the accumulated impulse at the anchors. */
    const lanes px = pair(r0->impulse.x, r1->impulse.x);
    const lanes py = pair(r0->impulse.y, r1->impulse.y);
    apply_two(a, b, ima, iia, imb, iib, rax, ray, rbx, rby, px, py);
}

/* rb_pin_correct (joint_pin.c) on rows i0 and i1 at once, lane 0 and lane
 * 1; true when both gaps were within the slop. */
static bool correct_two(rb_world *world, int i0, int i1, lanes slop_squared)
{
    const rb_pin_row *r0 = &world->pin_rows[i0];
    const rb_pin_row *r1 = &world->pin_rows[i1];
    const state_pair a = {{&world->states[r0->body_a], &world->states[r1->body_a]}};
    const state_pair b = {{&world->states[r0->body_b], &world->states[r1->body_b]}};
    const lanes inv_mass_a = pair(r0->inv_mass_a, r1->inv_mass_a);
    const lanes inv_inertia_a = pair(r0->inv_inertia_a, r1->inv_inertia_a);
    const lanes inv_mass_b = pair(r0->inv_mass_b, r1->inv_mass_b);
    const lanes inv_inertia_b = pair(r0->inv_inertia_b, r1->inv_inertia_b);

    /* The gap C = (cB + rB) - (cA + rA), and K, at the poses now. */
    const arm_lanes arms = arms_now(world, i0, i1, a, b);
    const lanes rax = arms.rax, ray = arms.ray, rbx = arms.rbx, rby = arms.rby;
    lanes acx = pair(a.s[0]->center.x, a.s[1]->center.x);
    lanes acy = pair(a.s[0]->center.y, a.s[1]->center.y);
    lanes bcx = pair(b.s[0]->center.x, b.s[1]->center.x);
    lanes bcy = pair(b.s[0]->center.y, b.s[1]->center.y);
    const lanes gx = sub(add(bcx, rbx), add(acx, rax));
    const lanes gy = sub(add(bcy, rby), add(acy, ray));
    const bool within = _mm_movemask_pd(_mm_cmple_pd(add(mul(gx, gx), mul(gy, gy)), slop_squared)) == 3;
    const mass_lanes k = mass_of(inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b, &arms);
    if (_mm_movemask_pd(_mm_cmpgt_pd(k.det, _mm_setzero_pd())) != 3) {
        /* A pin that cannot move its bodies: both rows through the
         * reference, which skips it (nothing has been written yet). */
        bool first = rb_pin_correct(world, i0);
        return rb_pin_correct(world, i1) && first;
    }

    /* P = -K⁻¹·C by Cramer's rule; the centres move by ∓P/m. */
    const lanes inverse_det = divide(both(1.0), k.det);
    const lanes vx = negate(gx);
    const lanes vy = negate(gy);
    const lanes px = mul(sub(mul(k.k22, vx), mul(k.k12, vy)), inverse_det);
    const lanes py = mul(sub(mul(k.k11, vy), mul(k.k12, vx)), inverse_det);
    acx = sub(acx, mul(inv_mass_a, px));
    acy = sub(acy, mul(inv_mass_a, py));
    bcx = add(bcx, mul(inv_mass_b, px));
    bcy = add(bcy, mul(inv_mass_b, py));
    store_pair(&a.s[0]->center.x, &a.s[1]->center.x, acx);
    store_pair(&a.s[0]->center.y, &a.s[1]->center.y, acy);
    store_pair(&b.s[0]->center.x, &b.s[1]->center.x, bcx);
    store_pair(&b.s[0]->center.y, &b.s[1]->center.y, bcy);

    /* The turns, ∓(r × P)/I. */
    turn_two(a, negate(mul(inv_inertia_a, sub(mul(rax, py), mul(ray, px)))), inv_inertia_a, arms.qac, arms.qas);
    turn_two(b, mul(inv_inertia_b, sub(mul(rbx, py), mul(rby, px))), inv_inertia_b, arms.qbc, arms.qbs);
    return within;
}

void rb_pins_warm_start(rb_world *world, double h, bool backwards)
{
    const int count = world->pin_row_count;
    const double drift_cap = rb_point_drift_cap(world, h);
    for (int k = 0, i0, i1; k < count;) {
        if (rows_at(world, count, k, backwards, &i0, &i1) == 2) {
            warm_start_two(world, i0, i1, h, drift_cap);
            k += 2;
        } else {
            rb_pin_warm_start(world, i0, h);
            k += 1;
        }
    }
}

bool rb_pins_correct_positions(rb_world *world, bool backwards)
{
    const int count = world->pin_row_count;
    const double slop = world->settings.linear_slop;
    const lanes slop_squared = both(slop * slop);
    bool all_within = true;
    for (int k = 0, i0, i1; k < count;) {
        if (rows_at(world, count, k, backwards, &i0, &i1) == 2) {
            all_within = correct_two(world, i0, i1, slop_squared) && all_within;
            k += 2;
        } else {
            all_within = rb_pin_correct(world, i0) && all_within;
            k += 1;
        }
    }
    return all_within;
}

/* A velocity pass of rows r0 and r1 at once: rb_pin_solve_rigid
 * (joint_solver.h) where `soft` is NULL, else rb_pin_solve under that
 * response (its bias on the gap, and the softening
 * P·mass_scale - accumulated·impulse_scale). */
static inline __attribute__((always_inline)) void solve_two(rb_body_state *states, rb_pin_row *r0, rb_pin_row *r1,
                                                            const rb_rigid_response *soft)
{
    const state_pair a = {{&states[r0->body_a], &states[r1->body_a]}};
    const state_pair b = {{&states[r0->body_b], &states[r1->body_b]}};
    const lanes rax = pair(r0->ra.x, r1->ra.x);
    const lanes ray = pair(r0->ra.y, r1->ra.y);
    const lanes rbx = pair(r0->rb.x, r1->rb.x);
    const lanes rby = pair(r0->rb.y, r1->rb.y);
    const lanes vax = pair(a.s[0]->linear_velocity.x, a.s[1]->linear_velocity.x);
    const lanes vay = pair(a.s[0]->linear_velocity.y, a.s[1]->linear_velocity.y);
    const lanes wa = pair(a.s[0]->angular_velocity, a.s[1]->angular_velocity);
    const lanes vbx = pair(b.s[0]->linear_velocity.x, b.s[1]->linear_velocity.x);
    const lanes vby = pair(b.s[0]->linear_velocity.y, b.s[1]->linear_velocity.y);
    const lanes wb = pair(b.s[0]->angular_velocity, b.s[1]->angular_velocity);

    /* Cdot = (vB + ωB × rB) - (vA + ωA × rA) - drift; ω × r = (-ω·r.y, ω·r.x). */
    lanes cx = sub(sub(add(vbx, mul(negate(wb), rby)), add(vax, mul(negate(wa), ray))),
                   pair(r0->point_drift.x, r1->point_drift.x));
    lanes cy = sub(sub(add(vby, mul(wb, rbx)), add(vay, mul(wa, rax))), pair(r0->point_drift.y, r1->point_drift.y));
    if (soft != NULL && soft->bias_rate > 0.0) {
        /* Cdot + bias·C, the gap C = (cB + rB) - (cA + rA). */
        const lanes bias = both(soft->bias_rate);
        cx = add(cx, mul(bias, sub(add(pair(b.s[0]->center.x, b.s[1]->center.x), rbx),
                                   add(pair(a.s[0]->center.x, a.s[1]->center.x), rax))));
        cy = add(cy, mul(bias, sub(add(pair(b.s[0]->center.y, b.s[1]->center.y), rby),
                                   add(pair(a.s[0]->center.y, a.s[1]->center.y), ray))));
    }
    const lanes i11 = pair(r0->point_inverse11, r1->point_inverse11);
    const lanes i12 = pair(r0->point_inverse12, r1->point_inverse12);
    const lanes i22 = pair(r0->point_inverse22, r1->point_inverse22);
    lanes px = negate(add(mul(i11, cx), mul(i12, cy)));
    lanes py = negate(add(mul(i12, cx), mul(i22, cy)));
    const lanes accumulated_x = pair(r0->impulse.x, r1->impulse.x);
    const lanes accumulated_y = pair(r0->impulse.y, r1->impulse.y);
    if (soft != NULL) {
        const lanes mass_scale = both(soft->mass_scale);
        const lanes impulse_scale = both(soft->impulse_scale);
        px = sub(mul(mass_scale, px), mul(impulse_scale, accumulated_x));
        py = sub(mul(mass_scale, py), mul(impulse_scale, accumulated_y));
    }
    store_pair(&r0->impulse.x, &r1->impulse.x, add(accumulated_x, px));
    store_pair(&r0->impulse.y, &r1->impulse.y, add(accumulated_y, py));

    apply_two(a, b, pair(r0->inv_mass_a, r1->inv_mass_a), pair(r0->inv_inertia_a, r1->inv_inertia_a),
              pair(r0->inv_mass_b, r1->inv_mass_b), pair(r0->inv_inertia_b, r1->inv_inertia_b), rax, ray, rbx, rby, px,
              py);
}

void rb_pins_solve_rigid(rb_world *world, bool backwards)
{
    const int count = world->pin_row_count;
    rb_pin_row *rows = world->pin_rows;
    for (int k = 0, i0, i1; k < count;) {
        if (rows_at(world, count, k, backwards, &i0, &i1) == 2) {
            solve_two(world->states, &rows[i0], &rows[i1], NULL);
            k += 2;
        } else {
            rb_pin_solve_rigid(world->states, &rows[i0]);
            k += 1;
        }
    }
}

void rb_pins_solve(rb_world *world, bool backwards)
{
    const int count = world->pin_row_count;
    rb_pin_row *rows = world->pin_rows;
    const rb_rigid_response *response = &world->joint_response;
    for (int k = 0, i0, i1; k < count;) {
        if (rows_at(world, count, k, backwards, &i0, &i1) == 2) {
            solve_two(world->states, &rows[i0], &rows[i1], response);
            k += 2;
        } else {
            rb_pin_solve(world, &rows[i0]);
            k += 1;
        }
    }
}

#else

void rb_pins_warm_start(rb_world *world, double h, bool backwards)
{
    const int count = world->pin_row_count;
    for (int k = 0; k < count; ++k) {
        rb_pin_warm_start(world, row_at(count, k, backwards), h);
    }
}

bool rb_pins_correct_positions(rb_world *world, bool backwards)
{
    const int count = world->pin_row_count;
    bool all_within = true;
    for (int k = 0; k < count; ++k) {
        all_within = rb_pin_correct(world, row_at(count, k, backwards)) && all_within;
    }
    return all_within;
}

void rb_pins_solve_rigid(rb_world *world, bool backwards)
{
    const int count = world->pin_row_count;
    for (int k = 0; k < count; ++k) {
        rb_pin_solve_rigid(world->states, &world->pin_rows[row_at(count, k, backwards)]);
    }
}

void rb_pins_solve(rb_world *world, bool backwards)
{
    const int count = world->pin_row_count;
    for (int k = 0; k < count; ++k) {
        rb_pin_solve(world, &world->pin_rows[row_at(count, k, backwards)]);
    }
}

#endif
