/* SPDX-License-Identifier: MIT */
/* The plain pins' rows: a revolute joint with no limit, motor or spring
 * is the point constraint alone (joint_point.c), and in a large mesh of
 * them, the 100 x 100 joint grid, the solver's time goes to memory rather
 * than arithmetic: each phase of each substep streams every pin through
 * the caches. A joint holds much a pass does not read (its type's
 * settings, the pool's links, the limits' impulses), so the step gathers
 * what a plain pin's velocity passes read, its bodies, the frame's
 * masses, anchors, inverse mass matrix and drift, and its impulse, into a
 * dense array once (rb_pin_row), with the anchors in the body frames
 * beside it, lets the phases read and write those alone, and writes the
 * impulses back into the joints once at the end (Box2D v3
 * keeps its joints' solver data apart from their definitions likewise:
 * Catto, "Solver2D", 2024).
 *
 * The rows run the same arithmetic as the joints they stand for, in the
 * same order (the pass list's, which every phase keeps), so a step
 * gives the same bits either way. */
#include <string.h>

#include "joint_solver.h"

void rb_pins_gather(rb_world *world)
{
    if (world->joint_slots > 0) {
        memset(world->pin_row_of, 0xff, (size_t)world->joint_slots * sizeof *world->pin_row_of); /* all -1 */
    }
    int count = 0;
    int listed = 0;
    const int *joints = rb_joint_pass_list(world, &listed);
    for (int k = 0; k < listed; ++k) {
        int slot = joints[k];
        const rb_joint *joint = &world->joints[slot];
        if (joint->type != RB_JOINT_REVOLUTE || !joint->plain_pin || joint->in_tree) {
            continue;
        }
        /* The masses and the anchors in the body frames, this step's
         * (rb_joints_collect_active); each substep's warm start prepares
         * the rest (warm_start_row). */
        const rb_joint_frame *f = &joint->frame;
        /* Field by field: a whole row written as one compound literal
         * zeroes its 128 bytes first (a `rep stos` of 16 words a pin), for
         * fields the warm start writes before any pass reads them. */
        rb_pin_row *row = &world->pin_rows[count];
        row->body_a = joint->body_a;
        row->body_b = joint->body_b;
        row->inv_mass_a = f->inv_mass_a;
        row->inv_inertia_a = f->inv_inertia_a;
        row->inv_mass_b = f->inv_mass_b;
        row->inv_inertia_b = f->inv_inertia_b;
        row->impulse = joint->as.revolute.point_impulse;
        world->pin_anchors[count] = (rb_pin_anchors){f->local_a, f->local_b};
        world->pin_row_of[slot] = count++;
    }
    world->pin_row_count = count;
    world->pin_rows_live = true;
}

/* The row's substep: its anchors turned into the world at the poses now,
 * the inverse of its 2 × 2 mass matrix K (rb_pin_correct gives K) and the
 * drift its velocity passes ask for (rb_point_drift), as
 * rb_point_constraint_prepare prepares a joint's (joint_point.c), to the
 * same bits; then the warm start with its impulse. Inlined by force into
 * the whole pass, which would otherwise make a call a pin. */
static inline __attribute__((always_inline)) void warm_start_row(rb_world *world, int row, double h, double drift_cap)
{
    rb_pin_row *r = &world->pin_rows[row];
    const rb_pin_anchors *anchors = &world->pin_anchors[row];
    r->rb = rb_rotate(world->states[r->body_b].rotation, anchors->local_b);
    r->ra = rb_rotate(world->states[r->body_a].rotation, anchors->local_a);
    const rb_vec2 ra = r->ra;
    const rb_vec2 rb = r->rb;
    const double m = r->inv_mass_a + r->inv_mass_b;
    const double k11 = m + r->inv_inertia_a * ra.y * ra.y + r->inv_inertia_b * rb.y * rb.y;
    const double k12 = -r->inv_inertia_a * ra.x * ra.y - r->inv_inertia_b * rb.x * rb.y;
    const double k22 = m + r->inv_inertia_a * ra.x * ra.x + r->inv_inertia_b * rb.x * rb.x;
    const double det = k11 * k22 - k12 * k12;
    const double inverse_det = det > 0.0 ? 1.0 / det : 0.0; /* all 0 when K is singular */
    r->point_inverse11 = inverse_det * k22;
    r->point_inverse12 = -inverse_det * k12;
    r->point_inverse22 = inverse_det * k11;
    r->point_drift = rb_point_drift(world, r->body_a, r->body_b, ra, rb, h, drift_cap);
    rb_apply_at_anchors(&world->states[r->body_a], &world->states[r->body_b], r->inv_mass_a, r->inv_inertia_a,
                        r->inv_mass_b, r->inv_inertia_b, r->ra, r->rb, r->impulse);
}

void rb_pin_warm_start(rb_world *world, int row, double h)
{
    warm_start_row(world, row, h, rb_point_drift_cap(world, h));
}

/* The position pass of a pin row: the point constraint's NGS pass
 * (rb_point_constraint_correct, joint_point.c) with the arithmetic a pin
 * alone needs and no more, to the same bits. With the anchors turned into
 * the world at the poses now, rA = R(θA)·localA and rB likewise, the gap
 * C = (cB + rB) - (cA + rA) is closed to first order by the impulse
 * P = -K⁻¹·C, K being the pin's 2 × 2 mass matrix at the poses now
 * (joint_point.c gives it):
 *   k11 = 1/mA + 1/mB + rA.y²/IA + rB.y²/IB,
 *   k12 = -rA.x·rA.y/IA - rB.x·rB.y/IB,
 *   k22 = 1/mA + 1/mB + rA.x²/IA + rB.x²/IB,
 * solved by its adjugate over its determinant (Cramer's rule for 2 × 2);
 * P moves the centres by ∓P/m and turns the bodies by ∓(r × P)/I. The
 * pass is within the slop when |C| is, compared squared: no square root.
 * (Catto, Box2D 2.4, b2RevoluteJoint::SolvePositionConstraints.) */
static inline __attribute__((always_inline)) bool correct_row(rb_world *world, int row_index, double slop_squared)
{
    const rb_pin_row *row = &world->pin_rows[row_index];
    const rb_pin_anchors *anchors = &world->pin_anchors[row_index];
    rb_body_state *a = &world->states[row->body_a];
    rb_body_state *b = &world->states[row->body_b];
    const double inv_mass_a = row->inv_mass_a;
    const double inv_inertia_a = row->inv_inertia_a;
    const double inv_mass_b = row->inv_mass_b;
    const double inv_inertia_b = row->inv_inertia_b;

    const rb_vec2 ra = rb_rotate(a->rotation, anchors->local_a);
    const rb_vec2 rb = rb_rotate(b->rotation, anchors->local_b);
    const rb_vec2 gap = rb_sub(rb_add(b->center, rb), rb_add(a->center, ra));
    const bool within = rb_length_squared(gap) <= slop_squared;

    const double m = inv_mass_a + inv_mass_b;
    const double k11 = m + inv_inertia_a * ra.y * ra.y + inv_inertia_b * rb.y * rb.y;
    const double k12 = -inv_inertia_a * ra.x * ra.y - inv_inertia_b * rb.x * rb.y;
    const double k22 = m + inv_inertia_a * ra.x * ra.x + inv_inertia_b * rb.x * rb.x;
    const double det = k11 * k22 - k12 * k12;
    if (!(det > 0.0)) {
        return within; /* two bodies that cannot move */
    }
    const double inverse_det = 1.0 / det;
    const rb_vec2 v = rb_neg(gap);
    const rb_vec2 impulse = rb_v2((k22 * v.x - k12 * v.y) * inverse_det, (k11 * v.y - k12 * v.x) * inverse_det);

    a->center = rb_mul_sub(a->center, inv_mass_a, impulse);
    b->center = rb_mul_add(b->center, inv_mass_b, impulse);
    if (inv_inertia_a > 0.0) {
        rb_body_state_turn(a, -(inv_inertia_a * rb_cross(ra, impulse)));
    }
    if (inv_inertia_b > 0.0) {
        rb_body_state_turn(b, inv_inertia_b * rb_cross(rb, impulse));
    }
    return within;
}

static double slop_squared(const rb_world *world) { return world->settings.linear_slop * world->settings.linear_slop; }

bool rb_pin_correct(rb_world *world, int row) { return correct_row(world, row, slop_squared(world)); }

void rb_pins_scatter(rb_world *world)
{
    if (!world->pin_rows_live) {
        return;
    }
    for (int k = 0; k < world->active_joint_count; ++k) {
        int slot = world->active_joints[k];
        int row = world->pin_row_of[slot];
        if (row >= 0) {
            world->joints[slot].as.revolute.point_impulse = world->pin_rows[row].impulse;
        }
    }
    world->pin_rows_live = false;
}

rb_vec2 rb_pin_impulse(const rb_world *world, const rb_joint *joint)
{
    if (world->pin_rows_live) {
        int row = world->pin_row_of[joint - world->joints];
        if (row >= 0) {
            return world->pin_rows[row].impulse;
        }
    }
    return joint->as.revolute.point_impulse;
}
