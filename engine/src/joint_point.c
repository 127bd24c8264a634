/* SPDX-License-Identifier: MIT */
/* The point constraint shared by revolute and weld joints: anchor A and
 * anchor B coincide, C = (cB + rB) - (cA + rA) = 0, optionally solved
 * together with one angular row on ωB - ωA (a rigid weld's angle, or a
 * revolute limit that is reached).
 *
 * An impulse P at the anchors and an angular impulse L (+L on B, -L on A)
 * change the point's Cdot = vB + ωB × rB - vA - ωA × rA and the relative
 * angular velocity ωB - ωA by K·(P, L) with the symmetric matrix
 *   k11 = 1/mA + 1/mB + rA.y²/IA + rB.y²/IB,   k12 = -rA.x·rA.y/IA - rB.x·rB.y/IB,
 *   k22 = 1/mA + 1/mB + rA.x²/IA + rB.x²/IB,
 *   k13 = -rA.y/IA - rB.y/IB,   k23 = rA.x/IA + rB.x/IB,   k33 = 1/IA + 1/IB
 * (expand ω × r for the angular effect (r × P)/I of an impulse; Catto,
 * Box2D-Lite, Joint.cpp). Solving the angular row with the pin matters:
 * alone it would use only the bodies' own inertias, and the pin would
 * then undo most of it (a small bob on a 1 m arm keeps 1/800 of each
 * limit correction). */
#include "joint_solver.h"

static inline rb_block_matrix make_mass_matrix(double inv_mass_a, double inv_inertia_a, double inv_mass_b,
                                               double inv_inertia_b, rb_vec2 ra, rb_vec2 rb)
{
    double m = inv_mass_a + inv_mass_b;
    double ia = inv_inertia_a;
    double ib = inv_inertia_b;
    return (rb_block_matrix){
        .k11 = m + ia * ra.y * ra.y + ib * rb.y * rb.y,
        .k12 = -ia * ra.x * ra.y - ib * rb.x * rb.y,
        .k22 = m + ia * ra.x * ra.x + ib * rb.x * rb.x,
        .k13 = -ia * ra.y - ib * rb.y,
        .k23 = ia * ra.x + ib * rb.x,
        .k33 = ia + ib,
    };
}

static void apply(const rb_joint *joint, rb_body_state *a, rb_body_state *b, rb_vec2 impulse, double angular)
{
    rb_joint_apply_linear(joint, a, b, impulse);
    rb_joint_apply_angular(joint, a, b, angular);
}

/* K's inverse with its angular row, once a substep: K is fixed within
 * it, and every pass then solves K·(x, z) = (v, w) with three dot
 * products (where rb_block_solve3 takes K's cofactors and divides by its
 * determinant in every pass). The inverse is the cofactors over the
 * determinant, Cramer's rule; a determinant that is 0 to the last
 * digits leaves the pin to be solved alone. */
#define SINGULAR_DET 1e-300 /* |det| at or below it: K is singular, and the pin is solved alone */

static void make_inverse(rb_point_block *p)
{
    const rb_block_matrix *k = &p->mass;
    const double c11 = k->k22 * k->k33 - k->k23 * k->k23;
    const double c12 = k->k13 * k->k23 - k->k12 * k->k33;
    const double c13 = k->k12 * k->k23 - k->k13 * k->k22;
    p->det = k->k11 * c11 + k->k12 * c12 + k->k13 * c13;
    p->c33 = k->k11 * k->k22 - k->k12 * k->k12;
    const double inverse_det = fabs(p->det) > SINGULAR_DET ? 1.0 / p->det : 0.0;
    p->inverse11 = inverse_det * c11;
    p->inverse12 = inverse_det * c12;
    p->inverse13 = inverse_det * c13;
    p->inverse22 = inverse_det * (k->k11 * k->k33 - k->k13 * k->k13);
    p->inverse23 = inverse_det * (k->k13 * k->k12 - k->k11 * k->k23);
    p->inverse33 = inverse_det * p->c33;
}

/* The joint's point block, kept by the world beside the joints. */
static rb_point_block *point_block(const rb_world *world, const rb_joint *joint)
{
    return &world->point_blocks[joint - world->joints];
}

/* Whether the pin is solved with an angular row in its passes: a
 * revolute joint's nearer limit, a rigid weld's angle. */
static bool solves_with_a_row(const rb_joint *joint)
{
    if (joint->type == RB_JOINT_REVOLUTE) {
        return joint->as.revolute.enable_lower || joint->as.revolute.enable_upper;
    }
    return joint->type == RB_JOINT_WELD && joint->as.weld.linear_hertz == 0.0 && joint->as.weld.angular_hertz == 0.0;
}

/* The inverse of K's upper-left 2x2, the pin alone, or all 0 when that
 * is singular: (inverse11, inverse12, inverse22); returns 1/det (0 when
 * singular). */
static double point_inverse(const rb_block_matrix *k, double *inverse11, double *inverse12, double *inverse22)
{
    double det = k->k11 * k->k22 - k->k12 * k->k12;
    double inverse_det = det > 0.0 ? 1.0 / det : 0.0;
    *inverse11 = inverse_det * k->k22;
    *inverse12 = -inverse_det * k->k12;
    *inverse22 = inverse_det * k->k11;
    return inverse_det;
}

void rb_point_constraint_prepare_matrices(const rb_world *world, rb_joint *joint)
{
    rb_joint_frame *f = &joint->frame;
    rb_point_block *p = point_block(world, joint);
    p->mass = make_mass_matrix(f->inv_mass_a, f->inv_inertia_a, f->inv_mass_b, f->inv_inertia_b, f->ra, f->rb);
    const double inverse_det = point_inverse(&p->mass, &f->point_inverse11, &f->point_inverse12, &f->point_inverse22);
    if (solves_with_a_row(joint)) {
        make_inverse(p);
        p->inverse_c33 = inverse_det; /* c33 is that 2x2's determinant, made by the same expression */
    }
}

void rb_point_constraint_prepare(const rb_world *world, rb_joint *joint, double h)
{
    if (!joint->in_block) {
        rb_point_constraint_prepare_matrices(world, joint);
    }
    rb_point_constraint_prepare_drift(world, joint, h);
}

void rb_point_constraint_prepare_drift(const rb_world *world, rb_joint *joint, double h)
{
    rb_joint_frame *f = &joint->frame;
    f->point_drift = rb_point_drift(world, joint->body_a, joint->body_b, f->ra, f->rb, h, rb_point_drift_cap(world, h));
}

/* Solves K_s·(x, z) = (v, w) with K_s = K whose coupling terms k13, k23
 * take the row's sign s = ±1. Flipping them flips K⁻¹'s entries 13 and
 * 23 and leaves the others as they are (each cofactor keeps its terms'
 * products of two flipped factors, and so does the determinant), so K's
 * inverse serves both signs. The row's z comes first, by itself: whether
 * a limit holds depends on z alone, and a limit that lets go discards x
 * (solve_point). */
static double row_part(const rb_point_block *p, double sign, rb_vec2 v, double w)
{
    return sign * p->inverse13 * v.x + sign * p->inverse23 * v.y + p->inverse33 * w;
}

static rb_vec2 point_part(const rb_point_block *p, double sign, rb_vec2 v, double w)
{
    const double i13 = sign * p->inverse13;
    const double i23 = sign * p->inverse23;
    return rb_v2(p->inverse11 * v.x + p->inverse12 * v.y + i13 * w, p->inverse12 * v.x + p->inverse22 * v.y + i23 * w);
}

/* The pin alone, K2·x = v, with K2's determinant c33 and its inverse
 * made once a substep: rb_block_solve2's arithmetic without its division. */
static bool solve_pin_alone(const rb_point_block *p, rb_vec2 v, rb_vec2 *x)
{
    if (!(p->c33 > 0.0)) {
        return false;
    }
    const rb_block_matrix *k = &p->mass;
    *x = rb_v2((k->k22 * v.x - k->k12 * v.y) * p->inverse_c33, (k->k11 * v.y - k->k12 * v.x) * p->inverse_c33);
    return true;
}

void rb_point_constraint_solve(const rb_world *world, const rb_joint *joint, rb_body_state *a, rb_body_state *b,
                               rb_vec2 *accumulated, const rb_angular_row *row)
{
    const rb_rigid_response *response = &world->joint_response;
    rb_vec2 cdot = rb_point_frame_velocity_error(world, &joint->frame, a, b);

    const rb_point_block *p = NULL;
    if (row != NULL && fabs((p = point_block(world, joint))->det) > SINGULAR_DET) {
        /* The row is s·(ωB - ωA) + bias = 0 with s = ±1; in K its coupling
         * terms take the sign s. A singular K (a body that cannot turn
         * makes the row redundant) leaves the pin alone. */
        const double wdot = row->sign * (b->angular_velocity - a->angular_velocity) + row->bias;
        const rb_vec2 v = rb_neg(cdot);
        double angular =
            response->mass_scale * row_part(p, row->sign, v, -wdot) - response->impulse_scale * *row->accumulated;
        rb_vec2 impulse;
        if (row->one_sided && *row->accumulated + angular < 0.0) {
            /* The limit would pull: release it and hold the pin alone,
             * net of the release's effect on the point. */
            angular = -*row->accumulated;
            const rb_block_matrix *k = &p->mass;
            rb_vec2 rhs = rb_neg(rb_add(cdot, rb_scale(angular, rb_v2(row->sign * k->k13, row->sign * k->k23))));
            impulse = solve_pin_alone(p, rhs, &impulse) ? rb_soften(response, impulse, *accumulated) : rb_v2(0.0, 0.0);
        } else {
            impulse = rb_soften(response, point_part(p, row->sign, v, -wdot), *accumulated);
        }
        *row->accumulated += angular;
        *accumulated = rb_add(*accumulated, impulse);
        apply(joint, a, b, impulse, row->sign * angular);
        return;
    }
    rb_point_alone_solve(world, &joint->frame, a, b, cdot, accumulated);
}

/* One NGS pass on bodies a and b, of the given inverse masses, whose
 * anchors are local_a and local_b in their frames (from the centres).
 * (A plain pin's rows have their own, the point alone: joint_pin.c.) */
static double correct_point(rb_body_state *a, rb_body_state *b, double inv_mass_a, double inv_inertia_a,
                            double inv_mass_b, double inv_inertia_b, rb_vec2 local_a, rb_vec2 local_b,
                            const double *angle_error)
{
    rb_vec2 ra = rb_rotate(a->rotation, local_a);
    rb_vec2 rb = rb_rotate(b->rotation, local_b);
    rb_vec2 gap = rb_sub(rb_add(b->center, rb), rb_add(a->center, ra));
    double error = rb_length(gap);
    rb_block_matrix k = make_mass_matrix(inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b, ra, rb);
    rb_vec2 impulse = rb_v2(0.0, 0.0);
    double angular = 0.0;
    bool solved = angle_error != NULL && rb_block_solve3(&k, rb_neg(gap), -*angle_error, &impulse, &angular);
    if (!solved && !rb_block_solve2(&k, rb_neg(gap), &impulse)) {
        return error;
    }
    a->center = rb_mul_sub(a->center, inv_mass_a, impulse);
    b->center = rb_mul_add(b->center, inv_mass_b, impulse);
    if (inv_inertia_a > 0.0) {
        rb_body_state_turn(a, -(inv_inertia_a * (rb_cross(ra, impulse) + angular)));
    }
    if (inv_inertia_b > 0.0) {
        rb_body_state_turn(b, inv_inertia_b * (rb_cross(rb, impulse) + angular));
    }
    return error;
}

double rb_point_constraint_correct(rb_world *world, rb_joint *joint, const double *angle_error)
{
    const rb_joint_frame *f = &joint->frame;
    return correct_point(rb_joint_state_a(world, joint), rb_joint_state_b(world, joint), f->inv_mass_a,
                         f->inv_inertia_a, f->inv_mass_b, f->inv_inertia_b, f->local_a, f->local_b, angle_error);
}
