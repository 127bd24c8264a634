/* SPDX-License-Identifier: MIT */
/* Small limbs solved as one dense system (joint_block.h says why and
 * how): the search for them once a step, the rows and factors once a
 * substep, the solve in every velocity pass. */
#include <math.h>

#include "contact_solver.h"
#include "joint_block.h"
#include "joint_solver.h"

/* ---- which joints ------------------------------------------------------- */

static bool moves_freely(const rb_body *body)
{
    return body->type == RB_BODY_DYNAMIC && body->awake && body->inv_mass > 0.0 && body->inv_inertia > 0.0;
}
/* A static body: the block gives fixed bodies no velocity (a kinematic
 * one has its own). */
static bool is_fixed(const rb_body *body) { return body->type == RB_BODY_STATIC; }

static bool has_limit(const rb_joint *joint)
{
    return joint->type == RB_JOINT_REVOLUTE && (joint->as.revolute.enable_lower || joint->as.revolute.enable_upper);
}

/* A revolute joint between bodies that each move freely or not at all. */
static bool fits_a_block(const rb_world *world, const rb_joint *joint)
{
    if (joint->type != RB_JOINT_REVOLUTE || joint->body_a < 0) {
        return false;
    }
    const rb_body *a = &world->bodies[joint->body_a];
    const rb_body *b = &world->bodies[joint->body_b];
    return (moves_freely(a) || is_fixed(a)) && (moves_freely(b) || is_fixed(b));
}

static int find(const int *list, int count, int value)
{
    for (int i = 0; i < count; ++i) {
        if (list[i] == value) {
            return i;
        }
    }
    return -1;
}

/* Gathers, breadth first from `seed`, the bodies and joints linked to it
 * into `block`; false when the group is too large or has a joint that
 * does not fit. */
static bool gather(const rb_world *world, int seed, rb_joint_block *block)
{
    block->body_count = 0;
    block->joint_count = 0;
    const rb_joint *first = &world->joints[seed];
    const int ends[2] = {first->body_a, first->body_b};
    for (int e = 0; e < 2; ++e) {
        if (moves_freely(&world->bodies[ends[e]]) && find(block->bodies, block->body_count, ends[e]) < 0) {
            block->bodies[block->body_count++] = ends[e];
        }
    }
    for (int n = 0; n < block->body_count; ++n) {
        int body = block->bodies[n];
        for (int j = world->bodies[body].first_joint; j >= 0;) {
            const rb_joint *joint = &world->joints[j];
            if (!fits_a_block(world, joint)) {
                return false;
            }
            if (find(block->joints, block->joint_count, j) < 0) {
                if (block->joint_count == RB_BLOCK_MAX_JOINTS) {
                    return false;
                }
                block->joints[block->joint_count++] = j;
                int other = joint->body_a == body ? joint->body_b : joint->body_a;
                if (moves_freely(&world->bodies[other]) && find(block->bodies, block->body_count, other) < 0) {
                    if (block->body_count == RB_BLOCK_MAX_BODIES) {
                        return false;
                    }
                    block->bodies[block->body_count++] = other;
                }
            }
            j = joint->body_a == body ? joint->next_on_a : joint->next_on_b;
        }
    }
    return true;
}

/* The lightest and heaviest of some bodies' masses (kg), and whether
 * they are uneven enough to defeat Gauss-Seidel. */
typedef struct mass_range {
    double lightest, heaviest;
} mass_range;

static void widen(mass_range *range, const rb_body *body)
{
    double mass = 1.0 / body->inv_mass;
    range->lightest = rb_min(range->lightest, mass);
    range->heaviest = rb_max(range->heaviest, mass);
}

static bool uneven(mass_range range) { return range.heaviest >= RB_BLOCK_MASS_RATIO * range.lightest; }

/* Whether a gathered group is a block: every joint limited (the trees
 * take unlimited pins) and masses uneven. */
static bool needs_a_block(const rb_world *world, const rb_joint_block *block)
{
    for (int j = 0; j < block->joint_count; ++j) {
        if (!has_limit(&world->joints[block->joints[j]])) {
            return false;
        }
    }
    mass_range range = {INFINITY, 0.0};
    for (int b = 0; b < block->body_count; ++b) {
        widen(&range, &world->bodies[block->bodies[b]]);
    }
    return uneven(range);
}

/* A body's place in the block, RB_BLOCK_MAX_BODIES (no velocity, no
 * inverse mass) for a fixed one. */
static int slot_of(const rb_joint_block *block, int body)
{
    int slot = find(block->bodies, block->body_count, body);
    return slot >= 0 ? slot : RB_BLOCK_MAX_BODIES;
}

/* Whether the moving bodies at the ends of the limited joints that fit a
 * block differ in mass enough for any group of them to be a block: a
 * group's mass ratio is at most theirs, so a world whose limbs are all
 * even (the arm) needs no search, step after step. */
static bool uneven_enough(const rb_world *world)
{
    mass_range range = {INFINITY, 0.0};
    for (int k = 0; k < world->active_joint_count; ++k) {
        const rb_joint *joint = &world->joints[world->active_joints[k]];
        if (!has_limit(joint) || !fits_a_block(world, joint)) {
            continue;
        }
        const int ends[2] = {joint->body_a, joint->body_b};
        for (int e = 0; e < 2; ++e) {
            if (moves_freely(&world->bodies[ends[e]])) {
                widen(&range, &world->bodies[ends[e]]);
            }
        }
    }
    return uneven(range);
}

/* Whether a contact this step acts on one of the block's bodies. */
static bool touched_by_contacts(const rb_world *world, const rb_joint_block *block)
{
    for (int c = 0; c < world->constraint_count; ++c) {
        const int ends[2] = {world->constraints[c].body_a, world->constraints[c].body_b};
        for (int e = 0; e < 2; ++e) {
            if (find(block->bodies, block->body_count, ends[e]) >= 0) {
                return true;
            }
        }
    }
    return false;
}

void rb_joint_blocks_build(rb_world *world)
{
    rb_joint_blocks *blocks = &world->joint_blocks;
    const int last_count = blocks->count;
    blocks->count = 0;
    world->velocity_joints_fresh = false; /* the velocity passes' list follows the blocks (joint.c) */
    for (int k = 0; k < world->active_joint_count; ++k) {
        world->joints[world->active_joints[k]].in_block = false;
    }
    if (world->settings.type != RB_SOLVER_NGS || !world->settings.tree_pins || !uneven_enough(world)) {
        return;
    }
    /* Each group is seeded by its first limited joint; a joint already
     * in a block seeds nothing more. */
    for (int k = 0; k < world->active_joint_count && blocks->count < RB_MAX_JOINT_BLOCKS; ++k) {
        int seed = world->active_joints[k];
        if (world->joints[seed].in_block || !has_limit(&world->joints[seed]) ||
            !fits_a_block(world, &world->joints[seed])) {
            continue;
        }
        rb_joint_block *block = &blocks->blocks[blocks->count];
        if (!gather(world, seed, block) || block->body_count == 0 || !needs_a_block(world, block)) {
            continue;
        }
        for (int b = 0; b <= RB_BLOCK_MAX_BODIES; ++b) {
            const rb_body *body = b < block->body_count ? &world->bodies[block->bodies[b]] : NULL;
            block->inv_mass[b] = body != NULL ? body->inv_mass : 0.0;
            block->inv_inertia[b] = body != NULL ? body->inv_inertia : 0.0;
        }
        for (int j = 0; j < block->joint_count; ++j) {
            const rb_joint *joint = &world->joints[block->joints[j]];
            block->ends[j][0] = slot_of(block, joint->body_a);
            block->ends[j][1] = slot_of(block, joint->body_b);
        }
        for (int j = 0; j < block->joint_count; ++j) {
            world->joints[block->joints[j]].in_block = true;
        }
        block->touched = touched_by_contacts(world, block);
        /* The factors last step's block in this place kept may serve, if
         * made for the same rows (rb_joint_blocks_factor); the residual's
         * check answers for everything else, masses included. */
        block->keep_factors = block->keep_factors && blocks->count < last_count;
        block->missed = false;
        ++blocks->count;
    }
}

/* ---- the rows ---------------------------------------------------------- */

/* Appends the row J·v + bias = 0 of a joint between the bodies in
 * places slot_a and slot_b, J = (ja on A, jb on B); its weights M⁻¹·Jᵀ
 * are made with K (fill_k). */
static inline void add_row(rb_joint_block *block, int slot_a, int slot_b, const double ja[3], const double jb[3],
                           double bias, double *accumulated, bool one_sided)
{
    rb_block_row *row = &block->rows[block->row_count++];
    row->slot_a = slot_a;
    row->slot_b = slot_b;
    for (int k = 0; k < 3; ++k) {
        row->ja[k] = ja[k];
        row->jb[k] = jb[k];
    }
    row->bias = bias;
    row->compliance = 0.0;
    row->accumulated = accumulated;
    row->one_sided = one_sided;
}

/* The two rows of the block's joint j, a pin: Cdot = vB + ωB × rB - vA -
 * ωA × rA less the drift; x: (1, 0, -rB.y) on B, (-1, 0, rA.y) on A;
 * y: (0, 1, rB.x), (0, -1, -rA.x). */
static void add_pin(rb_joint_block *block, int j, rb_joint *joint)
{
    const rb_joint_frame *f = &joint->frame;
    rb_revolute_data *r = &joint->as.revolute;
    int a = block->ends[j][0];
    int b = block->ends[j][1];
    add_row(block, a, b, (const double[3]){-1.0, 0.0, f->ra.y}, (const double[3]){1.0, 0.0, -f->rb.y},
            -f->point_drift.x, &r->point_impulse.x, false);
    add_row(block, a, b, (const double[3]){0.0, -1.0, -f->ra.x}, (const double[3]){0.0, 1.0, f->rb.x},
            -f->point_drift.y, &r->point_impulse.y, false);
}

/* The place in the block of a cable share's body, or -1 when the body
 * is not one of the block's. */
static int share_slot(const rb_world *world, const rb_joint_block *block, const rb_cable_share *share)
{
    return find(block->bodies, block->body_count, (int)(share->state - world->states));
}

/* The row of each damped cable that pulls on the block's bodies and on
 * nothing else that moves, at most two of them. Its law P = h·(T0 + c·L')
 * at the substep's end (cable.c), with J·v = -L' the rate of its row,
 * becomes
 *
 *     J·v + P/(h·c) - T0/c = 0,
 *
 * a row whose compliance 1/(h·c) adds to K's diagonal: a soft constraint
 * (Catto, "Soft Constraints", GDC 2011; Servin, Lacoursière and Melin,
 * "Interactive simulation of elastic deformable materials", 2006), one
 * sided because a cable only pulls. An undamped cable (c = 0) is a
 * tension the passes apply whatever the velocities, and stays theirs, as
 * does one so lightly damped that 1/(h·c) or T0/c overflows. */
static void add_cables(rb_world *world, rb_joint_block *block, double h)
{
    block->cable_rows = 0;
    for (int c = 0; c < world->cable_slots && block->cable_rows < RB_BLOCK_MAX_CABLES; ++c) {
        rb_cable *cable = &world->cables[c];
        if (!cable->in_use || !(cable->damping > 0.0) || cable->share_count == 0 || cable->share_count > 2) {
            continue;
        }
        const double compliance = 1.0 / (h * cable->damping);
        const double bias = -cable->base_tension / cable->damping;
        if (!isfinite(compliance) || !isfinite(bias)) {
            continue;
        }
        int slots[2] = {RB_BLOCK_MAX_BODIES, RB_BLOCK_MAX_BODIES};
        double j[2][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        bool inside = true;
        for (int m = 0; m < cable->share_count && inside; ++m) {
            const rb_cable_share *share = &cable->shares[m];
            slots[m] = share_slot(world, block, share);
            inside = slots[m] >= 0;
            j[m][0] = share->linear.x;
            j[m][1] = share->linear.y;
            j[m][2] = share->angular;
        }
        if (!inside) {
            continue;
        }
        add_row(block, slots[0], slots[1], j[0], j[1], bias, &cable->impulse, true);
        block->rows[block->row_count - 1].compliance = compliance;
        block->cables[block->cable_rows++] = cable;
    }
}

/* Gives the block's cables back to their own passes: their rows go, and
 * the limits' follow the pins'. Their impulses so far stay theirs. */
static void drop_cables(rb_joint_block *block)
{
    const int limits_start = block->pin_rows + block->cable_rows;
    for (int i = limits_start; i < block->row_count; ++i) {
        block->rows[i - block->cable_rows] = block->rows[i];
    }
    block->row_count -= block->cable_rows;
    block->cable_rows = 0;
}

/* Whether a damped cable that is not the block's pulls on one of its
 * bodies: its passes would then change their velocities after the
 * block's. */
static bool pulled_from_outside(const rb_world *world, const rb_joint_block *block)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        const rb_cable *cable = &world->cables[c];
        if (!cable->in_use || cable->in_block || !(cable->damping > 0.0)) {
            continue;
        }
        for (int m = 0; m < cable->share_count; ++m) {
            if (share_slot(world, block, &cable->shares[m]) >= 0) {
                return true;
            }
        }
    }
    return false;
}

/* Releases a limit's accumulated impulse (sign +1 lower, -1 upper). */
static void release(rb_world *world, rb_joint *joint, double sign, double *accumulated)
{
    rb_joint_apply_angular(joint, rb_joint_state_a(world, joint), rb_joint_state_b(world, joint), -sign * *accumulated);
    *accumulated = 0.0;
}

/* The nearer enabled limit's row of the block's joint j, when the joint
 * could reach it within the substep or held it; the farther limit, a
 * swing away, is released. Returns the row's margin (rad), or INFINITY
 * for no row. */
static double add_limit(rb_world *world, rb_joint_block *block, int j, rb_joint *joint, double h)
{
    rb_revolute_data *r = &joint->as.revolute;
    if (!r->enable_lower && !r->enable_upper) {
        return INFINITY;
    }
    double angle = rb_joint_relative_angle(world, joint, r->reference_angle);
    bool lower = r->enable_lower && (!r->enable_upper || angle - r->lower <= r->upper - angle);
    if (lower && r->upper_impulse != 0.0) {
        release(world, joint, -1.0, &r->upper_impulse);
    } else if (!lower && r->lower_impulse != 0.0) {
        release(world, joint, 1.0, &r->lower_impulse);
    }
    double sign = lower ? 1.0 : -1.0;
    double margin = lower ? angle - r->lower : r->upper - angle;
    double *accumulated = lower ? &r->lower_impulse : &r->upper_impulse;
    const rb_body_state *a = rb_joint_state_a(world, joint);
    const rb_body_state *b = rb_joint_state_b(world, joint);
    double reach = 2.0 * fabs(b->angular_velocity - a->angular_velocity) * h + RB_ANGULAR_SLOP;
    if (margin > reach && *accumulated == 0.0) {
        return INFINITY;
    }
    add_row(block, block->ends[j][0], block->ends[j][1], (const double[3]){0.0, 0.0, -sign},
            (const double[3]){0.0, 0.0, sign}, rb_one_sided_bias(world, margin, h), accumulated, true);
    return margin;
}

/* ---- the factors --------------------------------------------------------- */

/* The row's M⁻¹·Jᵀ on each body (0 on a fixed one). */
static void weigh(const rb_joint_block *block, rb_block_row *row)
{
    row->wa[0] = block->inv_mass[row->slot_a] * row->ja[0];
    row->wa[1] = block->inv_mass[row->slot_a] * row->ja[1];
    row->wa[2] = block->inv_inertia[row->slot_a] * row->ja[2];
    row->wb[0] = block->inv_mass[row->slot_b] * row->jb[0];
    row->wb[1] = block->inv_mass[row->slot_b] * row->jb[1];
    row->wb[2] = block->inv_inertia[row->slot_b] * row->jb[2];
}

static double dot3(const double *x, const double *y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }

/* L·D·Lᵀ of the n × n symmetric `a` (row-major, RB_BLOCK_MAX_ROWS to a
 * row; its lower triangle is read) into `f`: L below the diagonal, 1/D
 * on it, so that a solve only multiplies. Row by row: with u_j = L_ij·D_j,
 *
 *     u_j = a_ij - Σ_{k<j} u_k·L_jk,   L_ij = u_j / D_j,
 *     D_i = a_ii - Σ_{j<i} u_j·L_ij.
 *
 * Row i of `a` is 0 before column first[i] (its envelope), and so is row
 * i of L: each u_j with j < first[i] sums only zeros in turn (George and
 * Liu, "Computer Solution of Large Sparse Positive Definite Systems",
 * 1981, §4.2). The sums therefore start at the envelope, and L's entries
 * before it are neither made nor read: the leg's block, its pins a chain
 * through the limb, leaves a quarter of L empty. All rows dense
 * (first[i] = 0) is the plain factorisation. False when a pivot is not
 * positive beyond rounding (dependent rows). */
static bool factor(const double *restrict a, int n, const int *restrict first, double *restrict f)
{
    for (int i = 0; i < n; ++i) {
        const double *a_i = a + i * RB_BLOCK_MAX_ROWS;
        double *l_i = f + i * RB_BLOCK_MAX_ROWS;
        double u[RB_BLOCK_MAX_ROWS];
        double pivot = a_i[i];
        for (int j = first[i]; j < i; ++j) {
            const double *l_j = f + j * RB_BLOCK_MAX_ROWS;
            double sum = a_i[j];
            for (int k = first[i] > first[j] ? first[i] : first[j]; k < j; ++k) {
                sum -= u[k] * l_j[k];
            }
            u[j] = sum;
            l_i[j] = sum * l_j[j]; /* L_ij = u_j / D_j: f keeps 1/D_j */
            pivot -= sum * l_i[j];
        }
        if (!(pivot > 1e-12 * a_i[i])) {
            return false;
        }
        l_i[i] = 1.0 / pivot;
    }
    return true;
}

/* Solves L·D·Lᵀ·x = x in place, L's rows from their envelopes. */
static void solve_factored(const double *restrict f, int n, const int *restrict first, double *restrict x)
{
    for (int i = 1; i < n; ++i) {
        const double *row = f + i * RB_BLOCK_MAX_ROWS;
        double sum = x[i];
        for (int k = first[i]; k < i; ++k) {
            sum -= row[k] * x[k];
        }
        x[i] = sum;
    }
    for (int i = 0; i < n; ++i) {
        x[i] *= f[i * RB_BLOCK_MAX_ROWS + i];
    }
    for (int i = n - 1; i > 0; --i) {
        const double *row = f + i * RB_BLOCK_MAX_ROWS;
        double xi = x[i];
        for (int k = first[i]; k < i; ++k) {
            x[k] -= row[k] * xi;
        }
    }
}

/* Each row's envelope and K's lower triangle within it, body by body:
 * K_ij = Σ_b J_ib·M_b⁻¹·J_jbᵀ over the moving bodies b that rows i and j
 * both act on, and a cable's compliance on its diagonal. A row acts on
 * at most two bodies, so each body's rows are listed once and each pair
 * of them adds one product; K is symmetric and 0 outside the envelopes,
 * so neither the zeros nor the upper triangle are written (k_entry reads
 * them). Row i's envelope begins at the first row that acts on one of
 * its moving bodies. */
static void fill_k(rb_joint_block *block)
{
    const int n = block->row_count;
    const int moving = block->body_count;
    int count[RB_BLOCK_MAX_BODIES] = {0};
    int rows_of[RB_BLOCK_MAX_BODIES][RB_BLOCK_MAX_ROWS];           /* each moving body's rows, in order */
    const double *parts[RB_BLOCK_MAX_BODIES][RB_BLOCK_MAX_ROWS];   /* their J on that body */
    const double *weights[RB_BLOCK_MAX_BODIES][RB_BLOCK_MAX_ROWS]; /* and M⁻¹·Jᵀ */
    for (int i = 0; i < n; ++i) {
        rb_block_row *row = &block->rows[i];
        weigh(block, row);
        int first = i;
        const int slots[2] = {row->slot_a, row->slot_b};
        for (int p = 0; p < 2; ++p) {
            const int b = slots[p];
            if (b < moving) {
                first = count[b] > 0 && rows_of[b][0] < first ? rows_of[b][0] : first;
                rows_of[b][count[b]] = i;
                parts[b][count[b]] = p == 0 ? row->ja : row->jb;
                weights[b][count[b]++] = p == 0 ? row->wa : row->wb;
            }
        }
        block->first[i] = first;
        double *k_i = block->k + i * RB_BLOCK_MAX_ROWS;
        for (int j = first; j < i; ++j) {
            k_i[j] = 0.0;
        }
        k_i[i] = row->compliance;
    }
    for (int b = 0; b < moving; ++b) {
        for (int p = 0; p < count[b]; ++p) {
            double *k_p = block->k + rows_of[b][p] * RB_BLOCK_MAX_ROWS;
            const double *j_p = parts[b][p];
            for (int q = 0; q <= p; ++q) {
                k_p[rows_of[b][q]] += dot3(j_p, weights[b][q]);
            }
        }
    }
}

/* K_ij from the lower triangle's envelopes. */
static double k_entry(const rb_joint_block *block, int i, int j)
{
    int row = i > j ? i : j;
    int column = i > j ? j : i;
    return column >= block->first[row] ? block->k[row * RB_BLOCK_MAX_ROWS + column] : 0.0;
}

/* Takes a limit's accumulated impulse, warm started, back from its
 * bodies: a limit left out of the substep must not go on pushing. */
static void release_row(rb_world *world, const rb_joint_block *block, const rb_block_row *row)
{
    const int slots[2] = {row->slot_a, row->slot_b};
    const double *weights[2] = {row->wa, row->wb};
    for (int p = 0; p < 2; ++p) {
        if (slots[p] < block->body_count) {
            rb_body_state *s = &world->states[block->bodies[slots[p]]];
            s->linear_velocity = rb_mul_sub(s->linear_velocity, *row->accumulated, rb_v2(weights[p][0], weights[p][1]));
            s->angular_velocity -= *row->accumulated * weights[p][2];
        }
    }
    *row->accumulated = 0.0;
}

/* Factors K made now, giving up rows it cannot factor with: cables damped
 * almost as stiffly as pins, more of them than the pins leave freedoms,
 * make K singular too, and the block keeps its joints and gives the
 * cables back; then the farthest limits go. Records the rows the factors
 * are for. */
static void factor_rows(rb_world *world, rb_joint_block *block)
{
    fill_k(block);
    block->factored = factor(block->k, block->row_count, block->first, block->factor);
    if (!block->factored && block->cable_rows > 0) {
        drop_cables(block);
        fill_k(block);
        block->factored = factor(block->k, block->row_count, block->first, block->factor);
    }
    while (!block->factored && block->row_count > block->pin_rows) {
        release_row(world, block, &block->rows[--block->row_count]);
        block->factored = factor(block->k, block->row_count, block->first, block->factor);
    }
    block->keep_factors = block->factored && !block->missed;
    block->factored_row_count = block->row_count;
    for (int i = 0; i < block->row_count; ++i) {
        block->factored_rows[i] = (uintptr_t)block->rows[i].accumulated;
    }
}

/* Whether the factors were made for the rows of this substep: the same
 * pins, cables and limits, in the same order. */
static bool same_rows(const rb_joint_block *block)
{
    if (block->row_count != block->factored_row_count) {
        return false;
    }
    for (int i = 0; i < block->row_count; ++i) {
        if ((uintptr_t)block->rows[i].accumulated != block->factored_rows[i]) {
            return false;
        }
    }
    return true;
}

void rb_joint_blocks_factor(rb_world *world, double h)
{
    rb_joint_blocks *blocks = &world->joint_blocks;
    for (int n = 0; n < blocks->count; ++n) {
        rb_joint_block *block = &blocks->blocks[n];
        block->row_count = 0;
        for (int j = 0; j < block->joint_count; ++j) {
            add_pin(block, j, &world->joints[block->joints[j]]);
        }
        block->pin_rows = block->row_count;
        add_cables(world, block, h);
        block->settled = false;
        const int pins = block->row_count; /* the pins' and the cables' rows */
        /* The limits after them, nearest first: a singular K drops the
         * last. */
        double margins[RB_BLOCK_MAX_JOINTS];
        for (int j = 0; j < block->joint_count; ++j) {
            double margin = add_limit(world, block, j, &world->joints[block->joints[j]], h);
            if (margin == INFINITY) {
                continue;
            }
            int i = block->row_count - 1 - pins;
            rb_block_row row = block->rows[block->row_count - 1];
            for (; i > 0 && margins[i - 1] > margin; --i) {
                margins[i] = margins[i - 1];
                block->rows[pins + i] = block->rows[pins + i - 1];
            }
            margins[i] = margin;
            block->rows[pins + i] = row;
        }
        block->kept = block->keep_factors && same_rows(block);
        if (block->kept) {
            for (int i = 0; i < block->row_count; ++i) {
                weigh(block, &block->rows[i]);
            }
        } else {
            factor_rows(world, block);
        }
        for (int c = 0; c < block->cable_rows; ++c) {
            block->cables[c]->in_block = block->factored; /* or its own passes solve it */
        }
        block->closed = !block->touched && !pulled_from_outside(world, block);
        for (int j = 0; j < block->joint_count; ++j) {
            rb_joint *joint = &world->joints[block->joints[j]];
            if (joint->in_block && !block->factored) {
                rb_point_constraint_prepare_matrices(world, joint); /* which its warm start left to the block */
            }
            if (joint->in_block != block->factored) {
                world->velocity_joints_fresh = false; /* the velocity passes take the joint back, or leave it */
            }
            joint->in_block = block->factored;
        }
    }
}

/* ---- the passes ---------------------------------------------------------- */

/* J·v + bias of a row, v the block's velocities (vx, vy, ω a body, the
 * fixed bodies' 0 last). */
static double row_rate(const rb_block_row *row, const double *v)
{
    return row->bias + dot3(row->ja, v + 3 * row->slot_a) + dot3(row->jb, v + 3 * row->slot_b);
}

/* The same for a cable's row, whose rate grows with its impulse so far. */
static double cable_rate(const rb_block_row *row, const double *v)
{
    return row_rate(row, v) + row->compliance * *row->accumulated;
}

/* v += M⁻¹·Jᵀ·x: the velocities the rows' impulses x give. */
static void push(const rb_joint_block *block, const double *x, double *v)
{
    for (int i = 0; i < block->row_count; ++i) {
        const rb_block_row *row = &block->rows[i];
        /* A and B are two places (a fixed body's wa, wb are 0). */
        double *restrict va = v + 3 * row->slot_a;
        double *restrict vb = v + 3 * row->slot_b;
        va[0] += row->wa[0] * x[i];
        va[1] += row->wa[1] * x[i];
        va[2] += row->wa[2] * x[i];
        vb[0] += row->wb[0] * x[i];
        vb[1] += row->wb[1] * x[i];
        vb[2] += row->wb[2] * x[i];
    }
}

/* Whether x solves K·x = rhs, K made with this substep's rows, to a
 * relative residual of RB_BLOCK_KEPT_RESIDUAL: K·x is J·dv + C·x, dv =
 * M⁻¹·Jᵀ·x the velocities the impulses give (left in dv), read back
 * through the rows. */
static bool kept_solve_holds(const rb_joint_block *block, const double *rhs, const double *x, double *dv)
{
    for (int m = 0; m < 3 * (RB_BLOCK_MAX_BODIES + 1); ++m) {
        dv[m] = 0.0;
    }
    push(block, x, dv);
    double residual = 0.0;
    double scale = 0.0;
    for (int i = 0; i < block->row_count; ++i) {
        const rb_block_row *row = &block->rows[i];
        const double kx =
            dot3(row->ja, dv + 3 * row->slot_a) + dot3(row->jb, dv + 3 * row->slot_b) + row->compliance * x[i];
        residual += (rhs[i] - kx) * (rhs[i] - kx);
        scale += rhs[i] * rhs[i];
    }
    return residual <= RB_BLOCK_KEPT_RESIDUAL * RB_BLOCK_KEPT_RESIDUAL * scale;
}

/* Whether every one-sided row keeps pulling (or pushing, a limit) with
 * the impulses x added: then no row lets go in this pass. */
static bool pulls_only(const rb_joint_block *block, const double *x)
{
    for (int i = block->pin_rows; i < block->row_count; ++i) {
        if (block->rows[i].one_sided && *block->rows[i].accumulated + x[i] < 0.0) {
            return false;
        }
    }
    return true;
}

/* Solves K_SS·x_S = rhs_S - K_SF·x_F for the rows in S (free[i]), the
 * others' x fixed, with a factorisation of K_SS made here: only a pass
 * that releases a limit needs it. */
static void solve_subset(const rb_joint_block *block, const bool *free, const double *rhs, double *x)
{
    int n = block->row_count;
    int index[RB_BLOCK_MAX_ROWS];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (free[i]) {
            index[m++] = i;
        }
    }
    double sub[RB_BLOCK_MAX_ROWS * RB_BLOCK_MAX_ROWS] = {0}, f[RB_BLOCK_MAX_ROWS * RB_BLOCK_MAX_ROWS],
                                   y[RB_BLOCK_MAX_ROWS];
    for (int p = 0; p < m; ++p) {
        y[p] = rhs[index[p]];
        for (int j = 0; j < n; ++j) {
            if (!free[j]) {
                y[p] -= k_entry(block, index[p], j) * x[j];
            }
        }
        for (int q = 0; q < m; ++q) {
            sub[p * RB_BLOCK_MAX_ROWS + q] = k_entry(block, index[p], index[q]);
        }
    }
    /* A principal submatrix of a positive definite K is positive definite. */
    static const int dense[RB_BLOCK_MAX_ROWS] = {0};
    (void)factor(sub, m, dense, f);
    solve_factored(f, m, dense, y);
    for (int p = 0; p < m; ++p) {
        x[index[p]] = y[p];
    }
}

/* One velocity pass over a factored block. Out of line: its frame (some
 * 3 kB of rows and right-hand sides) is then set up only for a block, not
 * in every pass of a world that has none. */
static __attribute__((noinline)) void solve_block_velocities(rb_world *world, rb_joint_block *block)
{
    double v[3 * (RB_BLOCK_MAX_BODIES + 1)];
    double *fixed = v + 3 * RB_BLOCK_MAX_BODIES; /* every fixed body's place: no velocity */
    fixed[0] = fixed[1] = fixed[2] = 0.0;
    for (int b = 0; b < block->body_count; ++b) {
        const rb_body_state *s = &world->states[block->bodies[b]];
        v[3 * b] = s->linear_velocity.x;
        v[3 * b + 1] = s->linear_velocity.y;
        v[3 * b + 2] = s->angular_velocity;
    }
    int rows = block->row_count;
    double rhs[RB_BLOCK_MAX_ROWS], x[RB_BLOCK_MAX_ROWS];
    bool free[RB_BLOCK_MAX_ROWS];
    const int cables_end = block->pin_rows + block->cable_rows;
    for (int i = 0; i < rows; ++i) {
        const rb_block_row *row = &block->rows[i];
        rhs[i] = -(i >= block->pin_rows && i < cables_end ? cable_rate(row, v) : row_rate(row, v));
        x[i] = rhs[i];
        free[i] = true;
    }
    solve_factored(block->factor, rows, block->first, x);
    double dv[3 * (RB_BLOCK_MAX_BODIES + 1)];
    if (block->kept && !(kept_solve_holds(block, rhs, x, dv) && pulls_only(block, x))) {
        /* The earlier factors miss here, or a row lets go, for which the
         * subsets need K: K made now is factored, and serves the rest of
         * the step. Should it not factor (the same rows did earlier in the
         * step), this pass's solve stands, the substep's later passes
         * leave the block, and the next substep factors as usual. */
        block->kept = false;
        block->keep_factors = false;
        block->missed = true;
        fill_k(block);
        block->factored = factor(block->k, rows, block->first, block->factor);
        if (block->factored) {
            for (int i = 0; i < rows; ++i) {
                x[i] = rhs[i];
            }
            solve_factored(block->factor, rows, block->first, x);
        }
    }
    /* Release the limit or cable that would pull hardest, then solve the
     * rest again, until none pulls (their rows follow the pins'). */
    block->settled = true;
    for (;;) {
        int worst = -1;
        double most = 0.0;
        for (int i = block->pin_rows; i < rows; ++i) {
            const rb_block_row *row = &block->rows[i];
            double total = *row->accumulated + x[i];
            if (row->one_sided && free[i] && total < most) {
                most = total;
                worst = i;
            }
        }
        if (worst < 0) {
            break;
        }
        free[worst] = false;
        block->settled = false; /* the rows left may now need what was released */
        x[worst] = -*block->rows[worst].accumulated;
        solve_subset(block, free, rhs, x);
    }
    for (int i = 0; i < rows; ++i) {
        *block->rows[i].accumulated += x[i];
    }
    if (block->kept) { /* the check made the velocities' change */
        for (int m = 0; m < 3 * block->body_count; ++m) {
            v[m] += dv[m];
        }
    } else {
        push(block, x, v);
    }
    for (int b = 0; b < block->body_count; ++b) {
        rb_body_state *s = &world->states[block->bodies[b]];
        s->linear_velocity = rb_v2(v[3 * b], v[3 * b + 1]);
        s->angular_velocity = v[3 * b + 2];
    }
}

void rb_joint_blocks_solve_velocities(rb_world *world)
{
    rb_joint_blocks *blocks = &world->joint_blocks;
    for (int n = 0; n < blocks->count; ++n) {
        rb_joint_block *block = &blocks->blocks[n];
        if (block->factored && !(block->closed && block->settled)) {
            solve_block_velocities(world, block);
        }
    }
}
