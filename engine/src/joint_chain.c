/* SPDX-License-Identifier: MIT */
/* Trees that are chains, solved through their pins alone (joint_chain.h
 * says why and how).
 *
 * Pin k's Jacobian on a body is s·G(r), s = +1 on its body B and -1 on
 * its body A, r its anchor's offset on that body and
 *
 *     G(r) = | 1  0  -r.y |
 *            | 0  1   r.x |
 *
 * so with E = diag(1/m, 1/m, 1/I) a body's blocks of K = J·M⁻¹·Jᵀ are
 *
 *     G(a)·E·G(b)ᵀ = I/m + (1/I)·| a.y·b.y   -a.y·b.x |
 *                                | -a.x·b.y   a.x·b.x |
 *
 * K(k, k) sums it with a = b = the pin's offset over the pin's moving
 * bodies; K(k, k+1), between a pin and the next one down the chain, is
 * s·s'·G(a)·E·G(b)ᵀ on the body they share, a and b their two offsets on
 * it. Down the chain from the fixed end, with F = D⁻¹:
 *
 *     D(0) = K(0, 0),   D(k+1) = K(k+1, k+1) - K(k, k+1)ᵀ·W(k),
 *     W(k) = F(k)·K(k, k+1)                                     (factor)
 *     z(0) = -b(0),     z(k+1) = -b(k+1) - W(k)ᵀ·z(k)           (forward)
 *     λ(last) = F·z,    λ(k) = F(k)·z(k) - W(k)·λ(k+1)          (back)
 *
 * solves K·λ = -b, and each body's change is E·Σ s·G(r)ᵀ·λ over its two
 * pins. A pin node keeps F in dinv (11 12 22) and W in x (row-major).
 */
#include <math.h>
#include <stddef.h>

#include "joint_chain.h"

bool rb_joint_chain_all_chains(const rb_joint_tree *tree)
{
    for (int n = 0; n < tree->node_count; ++n) {
        const rb_tree_node *node = &tree->nodes[n];
        if (node->parent < 0 ? node->joint < 0 : node->parent != n - 1) {
            return false;
        }
    }
    return true;
}

/* One side of a pin: the body, the sign of the pin's Jacobian on it and
 * the pin's anchor offset on it. */
typedef struct pin_side {
    const rb_tree_node *body;
    double s;
    rb_vec2 r; /* m */
} pin_side;

/* Pin node `pin` seen from the body at node `body`, one of its two
 * neighbours in the chain; `edge` is the node of the two whose parent is
 * the other (its edge_on_b says whether the body is the pin's body B). */
static pin_side side(const rb_tree_node *pin, const rb_tree_node *body, const rb_tree_node *edge)
{
    return (pin_side){.body = body, .s = edge->edge_on_b ? 1.0 : -1.0, .r = edge->edge_on_b ? pin->rb : pin->ra};
}

/* Adds G(r)·E·G(r)ᵀ, a pin's own block on a body (s² = 1), to k: 11 12 22. */
static void add_own_block(const rb_tree_node *body, rb_vec2 r, double k[3])
{
    const double m = body->inv_mass, i = body->inv_inertia;
    k[0] += m + i * r.y * r.y;
    k[1] -= i * r.x * r.y;
    k[2] += m + i * r.x * r.x;
}

/* s·s'·G(a)·E·G(b)ᵀ on the body two pins share, row-major. */
static void shared_block(const rb_tree_node *body, pin_side a, pin_side b, double k[4])
{
    const double m = body->inv_mass, i = body->inv_inertia, ss = a.s * b.s;
    k[0] = ss * (m + i * a.r.y * b.r.y);
    k[1] = ss * (-i * a.r.y * b.r.x);
    k[2] = ss * (-i * a.r.x * b.r.y);
    k[3] = ss * (m + i * a.r.x * b.r.x);
}

/* Whether the pin at node n has a next pin down its chain. */
static bool has_next(const rb_joint_tree *tree, int n)
{
    return n + 2 < tree->node_count && tree->nodes[n + 2].parent == n + 1;
}

/* The sweep down every chain: with `factoring`, the pivots and W first;
 * then the forward substitution, over the pins' values. False when a
 * pivot is singular. */
static bool sweep_down(rb_joint_tree *tree, bool factoring)
{
    double schur[3] = {0.0, 0.0, 0.0}; /* K(k, k+1)ᵀ·W(k) from the pin above: 11 12 22 */
    const double *above_w = NULL;      /* W and z of the pin above, none at a chain's top */
    const double *above_z = NULL;
    for (int n = 0; n < tree->node_count; n += 2) {
        rb_tree_node *pin = &tree->nodes[n];
        if (pin->parent < 0) {
            above_w = above_z = NULL;
            schur[0] = schur[1] = schur[2] = 0.0;
        }
        const rb_tree_node *below = &tree->nodes[n + 1];
        if (factoring) {
            double d[3] = {0.0, 0.0, 0.0};
            add_own_block(below, side(pin, below, below).r, d);
            if (pin->parent >= 0) {
                add_own_block(&tree->nodes[n - 1], side(pin, &tree->nodes[n - 1], pin).r, d);
            }
            const double d11 = d[0] - schur[0], d12 = d[1] - schur[1], d22 = d[2] - schur[2];
            const double det = d11 * d22 - d12 * d12;
            if (!(det != 0.0 && isfinite(det))) {
                return false;
            }
            /* F = adj(D)/det. W and the next Schur complement are taken
             * as adj(D)·C and Cᵀ·adj(D)·C scaled by 1/det, so that they
             * are formed while the division runs: the sweep waits on one
             * division and one product a pin, not on F, W and the
             * complement in turn. */
            const double inverse_det = 1.0 / det;
            double *f = pin->dinv;
            f[0] = inverse_det * d22;
            f[1] = -inverse_det * d12;
            f[2] = inverse_det * d11;
            if (has_next(tree, n)) {
                const rb_tree_node *next = &tree->nodes[n + 2];
                double c[4]; /* K(k, k+1) */
                shared_block(below, side(pin, below, below), side(next, below, next), c);
                const double a0 = d22 * c[0] - d12 * c[2], a1 = d22 * c[1] - d12 * c[3]; /* adj(D)·C */
                const double a2 = d11 * c[2] - d12 * c[0], a3 = d11 * c[3] - d12 * c[1];
                double *w = pin->x;
                w[0] = inverse_det * a0;
                w[1] = inverse_det * a1;
                w[2] = inverse_det * a2;
                w[3] = inverse_det * a3;
                schur[0] = inverse_det * (c[0] * a0 + c[2] * a2);
                schur[1] = inverse_det * (c[0] * a1 + c[2] * a3);
                schur[2] = inverse_det * (c[1] * a1 + c[3] * a3);
            }
        }
        double *z = pin->value;
        z[0] = -z[0];
        z[1] = -z[1];
        if (above_w != NULL) {
            z[0] -= above_w[0] * above_z[0] + above_w[2] * above_z[1];
            z[1] -= above_w[1] * above_z[0] + above_w[3] * above_z[1];
        }
        above_w = pin->x;
        above_z = pin->value;
    }
    return true;
}

/* The back substitution up every chain, and each body's change from its
 * pins' impulses. */
static void sweep_up(rb_joint_tree *tree)
{
    for (int n = tree->node_count - 2; n >= 0; n -= 2) {
        rb_tree_node *pin = &tree->nodes[n];
        rb_tree_node *below = &tree->nodes[n + 1];
        const double *f = pin->dinv;
        double *lambda = pin->value;
        const double z0 = lambda[0], z1 = lambda[1];
        lambda[0] = f[0] * z0 + f[1] * z1;
        lambda[1] = f[1] * z0 + f[2] * z1;
        rb_vec2 force = rb_v2(0.0, 0.0); /* Σ s·λ and Σ s·r × λ of the pins on the body below */
        double torque = 0.0;
        if (has_next(tree, n)) {
            const rb_tree_node *next = &tree->nodes[n + 2];
            const double *w = pin->x;
            const rb_vec2 after = rb_v2(next->value[0], next->value[1]);
            lambda[0] -= w[0] * after.x + w[1] * after.y;
            lambda[1] -= w[2] * after.x + w[3] * after.y;
            const pin_side next_side = side(next, below, next);
            force = rb_scale(next_side.s, after);
            torque = next_side.s * rb_cross(next_side.r, after);
        }
        const pin_side own = side(pin, below, below);
        const rb_vec2 impulse = rb_v2(lambda[0], lambda[1]);
        force = rb_mul_add(force, own.s, impulse);
        torque += own.s * rb_cross(own.r, impulse);
        below->value[0] = below->inv_mass * force.x;
        below->value[1] = below->inv_mass * force.y;
        below->value[2] = below->inv_inertia * torque;
    }
}

bool rb_joint_chain_factor_and_solve(rb_joint_tree *tree)
{
    if (!sweep_down(tree, true)) {
        return false;
    }
    sweep_up(tree);
    return true;
}

void rb_joint_chain_solve(rb_joint_tree *tree)
{
    sweep_down(tree, false);
    sweep_up(tree);
}
