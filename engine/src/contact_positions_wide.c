// SPDX-License-Identifier: MIT
/* The non-linear Gauss-Seidel position pass's test for contacts that need
 * no correction, two at a time (rb_contact_solver_correct_positions).
 *
 * In a settled pile the position pass measures every point and finds
 * nothing to correct: each point's overlap is within the slop, so its
 * correction C = min(max(beta·(s + slop), -max_correction), 0) is exactly
 * 0 and the bodies do not move. Measuring s is most of the pass's work:
 * the normal turned with its face's body, and each surface point carried
 * by its body, s = n·(pB - pA). Here the four separations of two
 * neighbouring two-point contacts are measured at once, each contact in
 * one lane of SSE2's 2 × double registers (part of every x86-64
 * processor), with the reference's sums and products in the reference's
 * order, so each lane's s and C are those the one-at-a-time pass would
 * find, to the bit. A contact all of whose corrections are 0 is passed
 * over; the first one that has a correction to make is left to the
 * reference, which measures it again and moves its bodies, so the contacts
 * after it are measured at the poses that correction leaves: the pass's
 * results are those of the reference, whatever the mix
 * (tests/test_contact_positions.c). Without SSE2 every contact goes to
 * the reference. */
#include "contact_solver.h"

#if defined(__SSE2__)
#include "contact_lanes_two.h"

/* Whether a constraint can be measured in a lane: two points (so two
 * polygons, radii 0) and a normal that turns with one body. */
static inline bool fits_a_lane(const rb_contact_constraint *c)
{
    return c->point_count == 2 && c->normal_follows != RB_NORMAL_FROM_CENTERS;
}

/* The correction that contact_solver.c's pass finds from the separation
 * s, in each lane: min(max(beta·(s + slop), -max_correction), 0), with
 * min and max as rb_min and rb_max (a < b ? a : b, a > b ? a : b). */
static inline lanes correction(lanes s, const rb_solver_settings *settings)
{
    lanes scaled = mul(both(settings->baumgarte), add(s, both(settings->linear_slop)));
    return _mm_min_pd(_mm_max_pd(scaled, both(-settings->max_linear_correction)), _mm_setzero_pd());
}

/* Point j's separation in both contacts along the normal (nx, ny): each
 * surface point carried by its body, then moved out along the normal by
 * its circle's radius (0 here, but added as the reference adds it, for
 * the sign of a zero), as surface_points_now in contact_solver.c. */
static inline lanes separation(const rb_contact_constraint *c0, const rb_contact_constraint *c1, int j,
                               const pose_lanes *a, const pose_lanes *b, lanes nx, lanes ny)
{
    const rb_constraint_point *p0 = &c0->points[j];
    const rb_constraint_point *p1 = &c1->points[j];
    lanes lax = pair(p0->local_surface_a.x, p1->local_surface_a.x);
    lanes lay = pair(p0->local_surface_a.y, p1->local_surface_a.y);
    lanes lbx = pair(p0->local_surface_b.x, p1->local_surface_b.x);
    lanes lby = pair(p0->local_surface_b.y, p1->local_surface_b.y);
    lanes radius_a = pair(c0->radius_a, c1->radius_a);
    lanes radius_b = pair(c0->radius_b, c1->radius_b);
    lanes pax = add(add(a->cx, sub(mul(a->qc, lax), mul(a->qs, lay))), mul(radius_a, nx));
    lanes pay = add(add(a->cy, add(mul(a->qs, lax), mul(a->qc, lay))), mul(radius_a, ny));
    lanes pbx = sub(add(b->cx, sub(mul(b->qc, lbx), mul(b->qs, lby))), mul(radius_b, nx));
    lanes pby = sub(add(b->cy, add(mul(b->qs, lbx), mul(b->qc, lby))), mul(radius_b, ny));
    return add(mul(nx, sub(pbx, pax)), mul(ny, sub(pby, pay)));
}

/* How many of the two contacts, from the first, need no correction: 0, 1
 * or 2. Their separations lower *deepest, in the reference's order, as
 * far as they are passed over. */
static int resting_of_two(const rb_contact_constraint *c0, const rb_contact_constraint *c1, const rb_body_state *states,
                          const rb_solver_settings *settings, double *deepest)
{
    const rb_body_state *a0 = &states[c0->body_a];
    const rb_body_state *b0 = &states[c0->body_b];
    const rb_body_state *a1 = &states[c1->body_a];
    const rb_body_state *b1 = &states[c1->body_b];
    lanes nx, ny;
    turned_normals_of_two(c0, c1, a0, b0, a1, b1, &nx, &ny);
    pose_lanes a = poses(a0, a1);
    pose_lanes b = poses(b0, b1);
    lanes s1 = separation(c0, c1, 0, &a, &b, nx, ny);
    lanes s2 = separation(c0, c1, 1, &a, &b, nx, ny);
    /* all ones in a lane whose two corrections are both exactly 0 */
    lanes zero = _mm_setzero_pd();
    lanes resting =
        _mm_and_pd(_mm_cmpeq_pd(correction(s1, settings), zero), _mm_cmpeq_pd(correction(s2, settings), zero));
    int mask = _mm_movemask_pd(resting);
    if (!(mask & 1)) {
        return 0;
    }
    *deepest = rb_min(rb_min(*deepest, first_of(s1)), first_of(s2));
    if (!(mask & 2)) {
        return 1;
    }
    *deepest = rb_min(rb_min(*deepest, second_of(s1)), second_of(s2));
    return 2;
}

int rb_contact_solver_skip_resting(const rb_world *world, int begin, double *deepest)
{
    const rb_contact_constraint *constraints = world->constraints;
    int count = world->constraint_count;
    int i = begin;
    while (i + 1 < count && fits_a_lane(&constraints[i]) && fits_a_lane(&constraints[i + 1])) {
        int resting = resting_of_two(&constraints[i], &constraints[i + 1], world->states, &world->settings, deepest);
        i += resting;
        if (resting < 2) {
            break;
        }
    }
    return i;
}

#else

int rb_contact_solver_skip_resting(const rb_world *world, int begin, double *deepest)
{
    (void)world;
    (void)deepest;
    return begin;
}

#endif
