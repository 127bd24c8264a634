// SPDX-License-Identifier: MIT
/* Two contacts side by side in SSE2's 2 × double registers (part of every
 * x86-64 processor): lane 0 holds the first contact's value, lane 1 the
 * second's. Each operation is one instruction on both lanes and rounds
 * each lane exactly as the scalar operation would, so code written with
 * these in the one-at-a-time reference's order of sums and products gives
 * that reference's doubles, lane by lane. Used by the contact points'
 * preparation (contact_solver_wide.c) and the position pass's test for
 * resting contacts (contact_positions_wide.c), and the sequential solvers'
 * warm start and velocity passes over rows of two contacts
 * (contact_rows_two.c). Include only where
 * __SSE2__ is defined. */
#ifndef SINEW_CONTACT_LANES_TWO_H
#define SINEW_CONTACT_LANES_TWO_H

#include "contact_solver.h"
#include "lanes_two.h"

/* Both values of a row's field (contact_solver.h) in one load, and back. */
static inline lanes load(const rb_lanes2 *field) { return _mm_load_pd(field->v); }
static inline void store(rb_lanes2 *field, lanes a) { _mm_store_pd(field->v, a); }

/* The bodies' poses a point is carried by, lane by lane. */
typedef struct pose_lanes {
    lanes cx, cy; /* m, centre of mass */
    lanes qc, qs; /* cosine and sine of the angle */
} pose_lanes;

static inline pose_lanes poses(const rb_body_state *first, const rb_body_state *second)
{
    return (pose_lanes){pair(first->center.x, second->center.x), pair(first->center.y, second->center.y),
                        pair(first->rotation.c, second->rotation.c), pair(first->rotation.s, second->rotation.s)};
}

/* Both contacts' normals as their faces' bodies now turn them (the
 * reference's turned_normal): n = q·n_local, q the rotation of the body
 * whose face the normal is, of a0 or b0 for the first contact and of a1
 * or b1 for the second. Neither contact's normal may come from the
 * centres. */
static inline void turned_normals_of_two(const rb_contact_constraint *c0, const rb_contact_constraint *c1,
                                         const rb_body_state *a0, const rb_body_state *b0, const rb_body_state *a1,
                                         const rb_body_state *b1, lanes *nx, lanes *ny)
{
    const rb_body_state *turns0 = c0->normal_follows == RB_NORMAL_TURNS_WITH_A ? a0 : b0;
    const rb_body_state *turns1 = c1->normal_follows == RB_NORMAL_TURNS_WITH_A ? a1 : b1;
    lanes qc = pair(turns0->rotation.c, turns1->rotation.c);
    lanes qs = pair(turns0->rotation.s, turns1->rotation.s);
    lanes lx = pair(c0->local_normal.x, c1->local_normal.x);
    lanes ly = pair(c0->local_normal.y, c1->local_normal.y);
    *nx = sub(mul(qc, lx), mul(qs, ly));
    *ny = add(mul(qs, lx), mul(qc, ly));
}

#endif
