/* SPDX-License-Identifier: MIT */
/* Pins solved together, exactly, over the trees they form (joint_tree.h
 * says why and how; Baraff, "Linear-time dynamics using Lagrange
 * multipliers", 1996).
 *
 * The nodes are stored breadth first from each root, so a parent comes
 * before its children: elimination runs through them backwards (children
 * first), back substitution forwards. Each node keeps its block of the
 * matrix towards its parent, H(i, p), and after factoring its pivot's
 * inverse D⁻¹ and X = D⁻¹·H(i, p). Then
 *
 *     D(p) = H(p, p) - Σ over children c of H(c, p)ᵀ·X(c)
 *     solve H·x = b:  y(p) = b(p) - Σ X(c)ᵀ·y(c);  z = D⁻¹·y;
 *                     x(c) = z(c) - X(c)·x(p)
 *
 * which is the L·D·Lᵀ factorisation with L(p, c) = X(c)ᵀ.
 */
#include <math.h>
#include <string.h>

#include "allocator.h"
#include "joint_chain.h"
#include "joint_solver.h"
#include "joint_tree.h"

/* ---- which pins -------------------------------------------------------- */

static bool moves_freely(double inv_mass, double inv_inertia) { return inv_mass > 0.0 && inv_inertia > 0.0; }
static bool is_fixed(double inv_mass, double inv_inertia) { return inv_mass == 0.0 && inv_inertia == 0.0; }

static bool is_candidate(const rb_joint *joint)
{
    if (joint->type != RB_JOINT_REVOLUTE || joint->body_a < 0 || joint->in_block) {
        return false;
    }
    const rb_revolute_data *r = &joint->as.revolute;
    const rb_joint_frame *f = &joint->frame;
    bool a_moves = moves_freely(f->inv_mass_a, f->inv_inertia_a);
    bool b_moves = moves_freely(f->inv_mass_b, f->inv_inertia_b);
    return !r->enable_lower && !r->enable_upper && (a_moves || is_fixed(f->inv_mass_a, f->inv_inertia_a)) &&
           (b_moves || is_fixed(f->inv_mass_b, f->inv_inertia_b)) && (a_moves || b_moves);
}

static int find_root(int *parent, int i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]]; /* path halving */
        i = parent[i];
    }
    return i;
}

/* The mass ratio from which a tree is solved together, by solver. */
static double uneven_ratio(const rb_world *world)
{
    return world->settings.type == RB_SOLVER_SOFT_STEP ? RB_SOFT_STEP_TREE_MASS_RATIO : RB_TREE_MASS_RATIO;
}

/* Clears every active joint's in_tree, and says whether the candidate
 * pins' moving bodies differ in mass by uneven_ratio or more: when
 * not, no tree of them can be uneven. One pass, comparing inverse masses
 * (the heaviest has the smallest), so the common case of like masses
 * costs a load and a comparison or two a joint. */
static bool clear_and_find_uneven(rb_world *world)
{
    double smallest = INFINITY, largest = 0.0; /* inverse masses, 1/kg */
    for (int k = 0; k < world->active_joint_count; ++k) {
        rb_joint *joint = &world->joints[world->active_joints[k]];
        joint->in_tree = false;
        if (!is_candidate(joint)) {
            continue;
        }
        const rb_joint_frame *f = &joint->frame;
        if (moves_freely(f->inv_mass_a, f->inv_inertia_a)) {
            smallest = rb_min(smallest, f->inv_mass_a);
            largest = rb_max(largest, f->inv_mass_a);
        }
        if (moves_freely(f->inv_mass_b, f->inv_inertia_b)) {
            smallest = rb_min(smallest, f->inv_mass_b);
            largest = rb_max(largest, f->inv_mass_b);
        }
    }
    return largest >= uneven_ratio(world) * smallest;
}

/* Leaves in the trees only the pins of trees whose heaviest body is at
 * least uneven_ratio times their lightest (joint_tree.h says why),
 * and returns how many are left. */
static int keep_uneven_trees(rb_world *world, int pins)
{
    rb_joint_tree *tree = &world->joint_tree;
    double *range = tree->mass_range;
    for (int k = 0; k < world->active_joint_count; ++k) {
        const rb_joint *joint = &world->joints[world->active_joints[k]];
        if (!joint->in_tree) {
            continue;
        }
        const int bodies[2] = {joint->body_a, joint->body_b};
        for (int i = 0; i < 2; ++i) {
            const rb_body *body = &world->bodies[bodies[i]];
            if (!moves_freely(body->inv_mass, body->inv_inertia)) {
                continue;
            }
            int root = find_root(tree->union_parent, bodies[i]);
            double mass = 1.0 / body->inv_mass;
            range[2 * root] = rb_min(range[2 * root], mass);
            range[2 * root + 1] = rb_max(range[2 * root + 1], mass);
        }
    }
    for (int k = 0; k < world->active_joint_count; ++k) {
        rb_joint *joint = &world->joints[world->active_joints[k]];
        if (!joint->in_tree) {
            continue;
        }
        const rb_joint_frame *f = &joint->frame;
        int root = find_root(tree->union_parent,
                             moves_freely(f->inv_mass_a, f->inv_inertia_a) ? joint->body_a : joint->body_b);
        if (range[2 * root + 1] < uneven_ratio(world) * range[2 * root]) {
            joint->in_tree = false;
            --pins;
        }
    }
    return pins;
}

/* Marks in_tree the candidate pins that keep every tree a tree: none
 * closing a loop among moving bodies, and at most one pin to a fixed body
 * per tree (two would close a loop through the ground). Returns how many. */
static int choose_pins(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    for (int i = 0; i < world->body_slots; ++i) {
        tree->union_parent[i] = i;
        tree->grounded[i] = 0;
        tree->body_node[i] = -1;
        tree->mass_range[2 * i] = INFINITY;
        tree->mass_range[2 * i + 1] = 0.0;
    }
    int pins = 0;
    for (int k = 0; k < world->active_joint_count; ++k) {
        rb_joint *joint = &world->joints[world->active_joints[k]];
        if (!is_candidate(joint)) {
            continue;
        }
        const rb_joint_frame *f = &joint->frame;
        bool a_moves = moves_freely(f->inv_mass_a, f->inv_inertia_a);
        bool b_moves = moves_freely(f->inv_mass_b, f->inv_inertia_b);
        if (a_moves && b_moves) {
            int ra = find_root(tree->union_parent, joint->body_a);
            int rb = find_root(tree->union_parent, joint->body_b);
            if (ra == rb || (tree->grounded[ra] && tree->grounded[rb])) {
                continue;
            }
            tree->union_parent[ra] = rb;
            tree->grounded[rb] = (unsigned char)(tree->grounded[rb] | tree->grounded[ra]);
        } else {
            int r = find_root(tree->union_parent, a_moves ? joint->body_a : joint->body_b);
            if (tree->grounded[r]) {
                continue;
            }
            tree->grounded[r] = 1;
        }
        joint->in_tree = true;
        ++pins;
    }
    return keep_uneven_trees(world, pins);
}

/* ---- the nodes ---------------------------------------------------------- */

static int add_node(rb_world *world, int body, int joint, int parent)
{
    rb_joint_tree *tree = &world->joint_tree;
    int index = tree->node_count++;
    rb_tree_node *node = &tree->nodes[index];
    node->body = body;
    node->joint = joint;
    node->parent = parent;
    node->dim = body >= 0 ? 3 : 2;
    if (parent >= 0) { /* the edge's pin and body: one is the node, the other its parent */
        const rb_tree_node *up = &tree->nodes[parent];
        node->edge_on_b = (body >= 0 ? body : up->body) == world->joints[joint >= 0 ? joint : up->joint].body_b;
    }
    if (body >= 0) {
        tree->body_node[body] = index;
        node->inv_mass = world->bodies[body].inv_mass;
        node->inv_inertia = world->bodies[body].inv_inertia;
        node->mass = 1.0 / node->inv_mass; /* finite: the body moves freely */
        node->inertia = 1.0 / node->inv_inertia;
    }
    return index;
}

/* Adds, breadth first from node `root` (already added), every node of its
 * tree. */
static void grow_tree(rb_world *world, int root)
{
    rb_joint_tree *tree = &world->joint_tree;
    for (int n = root; n < tree->node_count; ++n) {
        const rb_tree_node node = tree->nodes[n];
        if (node.joint >= 0) {
            /* A pin: its moving bodies other than its parent. */
            const rb_joint *joint = &world->joints[node.joint];
            const rb_joint_frame *f = &joint->frame;
            int parent_body = node.parent >= 0 ? tree->nodes[node.parent].body : -1;
            if (moves_freely(f->inv_mass_a, f->inv_inertia_a) && joint->body_a != parent_body) {
                add_node(world, joint->body_a, -1, n);
            }
            if (moves_freely(f->inv_mass_b, f->inv_inertia_b) && joint->body_b != parent_body) {
                add_node(world, joint->body_b, -1, n);
            }
            continue;
        }
        /* A body: its pins in the tree other than its parent. */
        int parent_joint = node.parent >= 0 ? tree->nodes[node.parent].joint : -1;
        for (int j = world->bodies[node.body].first_joint; j >= 0;) {
            const rb_joint *joint = &world->joints[j];
            if (joint->in_tree && j != parent_joint) {
                add_node(world, -1, j, n);
            }
            j = joint->body_a == node.body ? joint->next_on_a : joint->next_on_b;
        }
    }
}

static bool in_a_tree(const rb_joint_tree *tree, int body) { return body >= 0 && tree->body_node[body] >= 0; }

/* Whether no row but the trees' own pins acts on a body in a tree this
 * step: no other joint, no motor or spring of a pin in a tree, no cable,
 * no contact with a manifold point. A velocity pass then solves the trees
 * exactly, and the substep's further passes would find only rounding
 * left to correct. */
static bool trees_alone(const rb_world *world)
{
    const rb_joint_tree *tree = &world->joint_tree;
    for (int k = 0; k < world->active_joint_count; ++k) {
        const rb_joint *joint = &world->joints[world->active_joints[k]];
        bool its_pin_only = joint->in_tree && joint->plain_pin;
        if (!its_pin_only && (in_a_tree(tree, joint->body_a) || in_a_tree(tree, joint->body_b))) {
            return false;
        }
    }
    for (int i = 0; i < world->cable_slots; ++i) {
        const rb_cable *cable = &world->cables[i];
        for (int p = 0; cable->in_use && p < cable->point_count; ++p) {
            if (in_a_tree(tree, cable->bodies[p])) {
                return false;
            }
        }
    }
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *contact = &world->contacts[i];
        if (contact->manifold.point_count > 0 &&
            (in_a_tree(tree, contact->body_a) || in_a_tree(tree, contact->body_b))) {
            return false;
        }
    }
    return true;
}

/* Finds the trees (sets in_tree and the nodes); returns false when out
 * of memory, which leaves every pin to Gauss-Seidel. */
static bool find_trees(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    tree->node_count = 0;
    if (!clear_and_find_uneven(world) || !tree->enabled) {
        return true;
    }
    int slots = world->body_slots;
    if (rb_grow_array((void **)&tree->body_node, &tree->body_node_capacity, slots, sizeof(int)) != 0 ||
        rb_grow_array((void **)&tree->union_parent, &tree->union_capacity, slots, sizeof(int)) != 0 ||
        rb_grow_array((void **)&tree->grounded, &tree->grounded_capacity, slots, 1) != 0 ||
        rb_grow_array((void **)&tree->mass_range, &tree->mass_range_capacity, 2 * slots, sizeof(double)) != 0) {
        return false;
    }
    int pins = choose_pins(world);
    /* A forest of `pins` edges has at most 2·pins bodies. */
    if (pins == 0 || rb_grow_array((void **)&tree->nodes, &tree->node_capacity, 3 * pins, sizeof(rb_tree_node)) != 0 ||
        rb_grow_array((void **)&tree->gauss_seidel_joints, &tree->gauss_seidel_capacity, world->active_joint_count,
                      sizeof(int)) != 0) {
        for (int k = 0; k < world->active_joint_count; ++k) {
            world->joints[world->active_joints[k]].in_tree = false;
        }
        return pins == 0;
    }
    /* Trees with a pin to a fixed body are rooted at that pin, so that no
     * pin is a leaf (its pivot would be zero); the others at a body. */
    for (int k = 0; k < world->active_joint_count; ++k) {
        const int j = world->active_joints[k];
        const rb_joint *joint = &world->joints[j];
        const rb_joint_frame *f = &joint->frame;
        bool grounded_pin =
            !moves_freely(f->inv_mass_a, f->inv_inertia_a) || !moves_freely(f->inv_mass_b, f->inv_inertia_b);
        if (joint->in_tree && grounded_pin) {
            grow_tree(world, add_node(world, -1, j, -1));
        }
    }
    for (int k = 0; k < world->active_joint_count; ++k) {
        const rb_joint *joint = &world->joints[world->active_joints[k]];
        const rb_joint_frame *f = &joint->frame;
        bool both_move = moves_freely(f->inv_mass_a, f->inv_inertia_a) && moves_freely(f->inv_mass_b, f->inv_inertia_b);
        if (joint->in_tree && both_move && tree->body_node[joint->body_a] < 0) {
            grow_tree(world, add_node(world, joint->body_a, -1, -1));
        }
    }
    tree->chains = rb_joint_chain_all_chains(tree);
    tree->gauss_seidel_count = 0;
    for (int k = 0; k < world->active_joint_count; ++k) {
        const rb_joint *joint = &world->joints[world->active_joints[k]];
        if (!(joint->in_tree && joint->plain_pin)) {
            tree->gauss_seidel_joints[tree->gauss_seidel_count++] = world->active_joints[k];
        }
    }
    return true;
}

/* ---- kept from step to step ---------------------------------------------- */

/* What finding the trees reads of an active joint. */
static rb_tree_key key_of(const rb_world *world, int slot)
{
    const rb_joint *joint = &world->joints[slot];
    const rb_joint_frame *f = &joint->frame;
    bool revolute = joint->type == RB_JOINT_REVOLUTE;
    return (rb_tree_key){
        .joint = slot,
        .generation = joint->generation,
        .body_a = joint->body_a,
        .body_b = joint->body_b,
        .type = joint->type,
        .in_block = joint->in_block,
        .plain_pin = joint->plain_pin,
        .enable_lower = revolute && joint->as.revolute.enable_lower,
        .enable_upper = revolute && joint->as.revolute.enable_upper,
        .inv_mass_a = f->inv_mass_a,
        .inv_inertia_a = f->inv_inertia_a,
        .inv_mass_b = f->inv_mass_b,
        .inv_inertia_b = f->inv_inertia_b,
    };
}

/* Whether the joint in `slot` reads as `key` says: key_of's fields,
 * compared straight from the joint (building its key first took a tenth
 * more instructions on the joint grid). */
static bool same_as_key(const rb_world *world, int slot, const rb_tree_key *key)
{
    const rb_joint *joint = &world->joints[slot];
    const rb_joint_frame *f = &joint->frame;
    bool revolute = joint->type == RB_JOINT_REVOLUTE;
    return key->joint == slot && key->generation == joint->generation && key->body_a == joint->body_a &&
           key->body_b == joint->body_b && key->type == joint->type && key->in_block == joint->in_block &&
           key->plain_pin == joint->plain_pin && key->enable_lower == (revolute && joint->as.revolute.enable_lower) &&
           key->enable_upper == (revolute && joint->as.revolute.enable_upper) && key->inv_mass_a == f->inv_mass_a &&
           key->inv_inertia_a == f->inv_inertia_a && key->inv_mass_b == f->inv_mass_b &&
           key->inv_inertia_b == f->inv_inertia_b;
}

/* Whether the trees found last would be found again: the same active
 * joints in the same slots, order and generations, with the same bodies,
 * types, limits, motors and springs, and bodies of the same masses that
 * move or not as before (a body asleep, static or of infinite mass does
 * not move: the frames say so), under the same solver settings. The
 * search reads nothing else: the bodies' lists of joints change only when
 * a joint is made or destroyed. One comparison of a few fields a joint,
 * where finding the trees again took some 500 instructions a joint. */
static bool found_from_the_same(const rb_world *world)
{
    const rb_joint_tree *tree = &world->joint_tree;
    if (!tree->found || tree->key_count != world->active_joint_count || tree->found_body_slots != world->body_slots ||
        tree->found_ratio != uneven_ratio(world) || tree->found_enabled != tree->enabled) {
        return false;
    }
    for (int k = 0; k < world->active_joint_count; ++k) {
        if (!same_as_key(world, world->active_joints[k], &tree->keys[k])) {
            return false;
        }
    }
    return true;
}

/* Records what the trees were found from; on running out of memory
 * nothing, and they are found again next step. */
static void record_keys(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    tree->found =
        rb_grow_array((void **)&tree->keys, &tree->key_capacity, world->active_joint_count, sizeof(rb_tree_key)) == 0;
    if (!tree->found) {
        return;
    }
    for (int k = 0; k < world->active_joint_count; ++k) {
        tree->keys[k] = key_of(world, world->active_joints[k]);
    }
    tree->key_count = world->active_joint_count;
    tree->found_body_slots = world->body_slots;
    tree->found_ratio = uneven_ratio(world);
    tree->found_enabled = tree->enabled;
}

void rb_joint_tree_build(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    tree->pose_factors = false;
    if (!found_from_the_same(world)) {
        ++tree->finds;
        if (find_trees(world)) {
            record_keys(world);
        } else {
            tree->found = false;
        }
    }
    /* Contacts and cables come and go from step to step. */
    tree->alone = tree->node_count > 0 && trees_alone(world);
}

/* ---- factor and solve ----------------------------------------------------- */

/* Every block between a pin and one of its bodies has one shape: the pin's
 * Jacobian on the body is s·G with s = +1 on body B, -1 on body A, and
 *
 *     G = | 1  0  -r.y |     (r the anchor's offset from the body's centre)
 *         | 0  1   r.x |
 *
 * so H(pin, body) = -s·G and H(body, pin) = -s·Gᵀ. The products the
 * factorisation needs are then those of the point constraint's mass
 * matrix (joint_point.c): G·E·Gᵀ for a body's 3×3 block E, and Gᵀ·F·G for
 * a pin's 2×2 block F. Symmetric blocks keep their upper triangle alone
 * (invert), each product written out for its shape. */

/* s and r of the edge between node `n` and its parent, r the pin's
 * offset (measured before factoring) on the edge's body. */
static void edge(const rb_tree_node *node, const rb_tree_node *parent, double *s, rb_vec2 *r)
{
    const rb_tree_node *pin = node->joint >= 0 ? node : parent;
    *s = node->edge_on_b ? 1.0 : -1.0;
    *r = node->edge_on_b ? pin->rb : pin->ra;
}

/* A pin's anchor offsets at the bodies' poses now. */
static void measure_offsets(const rb_world *world, rb_tree_node *pin)
{
    const rb_joint *joint = &world->joints[pin->joint];
    pin->ra = rb_rotate(world->states[joint->body_a].rotation, joint->frame.local_a);
    pin->rb = rb_rotate(world->states[joint->body_b].rotation, joint->frame.local_b);
}

/* The inverse of a symmetric 2×2 or 3×3 block, each kept as its upper
 * triangle row by row (a 2×2 as 11 12 22, a 3×3 as 11 12 13 22 23 33);
 * false when singular. */
static bool invert(const double *a, double *inverse, int n)
{
    if (n == 2) {
        const double a11 = a[0], a12 = a[1], a22 = a[2];
        double det = a11 * a22 - a12 * a12;
        if (!(det != 0.0 && isfinite(det))) {
            return false;
        }
        double s = 1.0 / det;
        inverse[0] = s * a22;
        inverse[1] = -s * a12;
        inverse[2] = s * a11;
        return true;
    }
    const double a11 = a[0], a12 = a[1], a13 = a[2], a22 = a[3], a23 = a[4], a33 = a[5];
    double c11 = a22 * a33 - a23 * a23; /* cofactors */
    double c12 = a23 * a13 - a12 * a33;
    double c13 = a12 * a23 - a22 * a13;
    double det = a11 * c11 + a12 * c12 + a13 * c13;
    if (!(det != 0.0 && isfinite(det))) {
        return false;
    }
    double s = 1.0 / det;
    inverse[0] = s * c11;
    inverse[1] = s * c12;
    inverse[2] = s * c13;
    inverse[3] = s * (a11 * a33 - a13 * a13);
    inverse[4] = s * (a13 * a12 - a11 * a23);
    inverse[5] = s * (a11 * a22 - a12 * a12);
    return true;
}

/* Eliminates body node `node` into its parent pin: X = D⁻¹·H = -s·E·Gᵀ
 * (3×2) and the pin's pivot loses H·ᵀX = G·E·Gᵀ. */
static void eliminate_body(rb_tree_node *node, rb_tree_node *pin, double s, rb_vec2 r)
{
    const double *e = node->dinv;
    const double e11 = e[0], e12 = e[1], e13 = e[2], e22 = e[3], e23 = e[4], e33 = e[5];
    double *x = node->x;
    x[0] = -s * (e11 - r.y * e13);
    x[1] = -s * (e12 + r.x * e13);
    x[2] = -s * (e12 - r.y * e23);
    x[3] = -s * (e22 + r.x * e23);
    x[4] = -s * (e13 - r.y * e33);
    x[5] = -s * (e23 + r.x * e33);
    double k11 = e11 - 2.0 * r.y * e13 + r.y * r.y * e33;
    double k12 = e12 + r.x * e13 - r.y * e23 - r.x * r.y * e33;
    double k22 = e22 + 2.0 * r.x * e23 + r.x * r.x * e33;
    double *p = pin->pivot;
    p[0] -= k11;
    p[1] -= k12;
    p[2] -= k22;
}

/* Eliminates pin node `node` into its parent body: X = D⁻¹·H = -s·F·G
 * (2×3) and the body's pivot loses Gᵀ·F·G. */
static void eliminate_pin(rb_tree_node *node, rb_tree_node *body, double s, rb_vec2 r)
{
    const double f11 = node->dinv[0], f12 = node->dinv[1], f22 = node->dinv[2];
    const double f13 = -r.y * f11 + r.x * f12; /* (F·G) third column */
    const double f23 = -r.y * f12 + r.x * f22;
    double *x = node->x;
    x[0] = -s * f11;
    x[1] = -s * f12;
    x[2] = -s * f13;
    x[3] = -s * f12;
    x[4] = -s * f22;
    x[5] = -s * f23;
    const double g33 = -r.y * f13 + r.x * f23;
    double *p = body->pivot;
    p[0] -= f11;
    p[1] -= f12;
    p[2] -= f13;
    p[3] -= f22;
    p[4] -= f23;
    p[5] -= g33;
}

/* Starts a node's pivot at its own block of H, before its children are
 * eliminated into it: a body's mass and inertia, a pin's zero. Chains
 * keep no such pivots (joint_chain.c). */
static void start_pivot(const rb_joint_tree *tree, rb_tree_node *node)
{
    if (tree->chains) {
        return;
    }
    double *p = node->pivot;
    if (node->body >= 0) {
        p[0] = p[3] = node->mass;
        p[5] = node->inertia;
        p[1] = p[2] = p[4] = 0.0;
    } else {
        p[0] = p[1] = p[2] = 0.0;
    }
}

/* The forward substitution at a node whose children are done: its
 * parent's right-hand side loses X(n)ᵀ·y(n), and y(n) becomes D⁻¹·y(n).
 * A body's X is 3 × 2 (its parent a pin), a pin's 2 × 3 (its parent a
 * body); written out for each, as this runs in every pass. */
static void substitute_forward(rb_tree_node *node, rb_tree_node *parent)
{
    double *y = node->value;
    const double *d = node->dinv;
    const double *x = node->x;
    if (node->dim == 3) {
        if (parent != NULL) {
            double *yp = parent->value;
            yp[0] -= x[0] * y[0] + x[2] * y[1] + x[4] * y[2];
            yp[1] -= x[1] * y[0] + x[3] * y[1] + x[5] * y[2];
        }
        const double y0 = y[0], y1 = y[1], y2 = y[2];
        y[0] = d[0] * y0 + d[1] * y1 + d[2] * y2;
        y[1] = d[1] * y0 + d[3] * y1 + d[4] * y2;
        y[2] = d[2] * y0 + d[4] * y1 + d[5] * y2;
    } else {
        if (parent != NULL) {
            double *yp = parent->value;
            yp[0] -= x[0] * y[0] + x[3] * y[1];
            yp[1] -= x[1] * y[0] + x[4] * y[1];
            yp[2] -= x[2] * y[0] + x[5] * y[1];
        }
        const double y0 = y[0], y1 = y[1];
        y[0] = d[0] * y0 + d[1] * y1;
        y[1] = d[1] * y0 + d[2] * y1;
    }
}

/* The back substitution, down from the roots: x(n) -= X(n)·x(p). */
static void substitute_back(rb_joint_tree *tree)
{
    for (int n = 0; n < tree->node_count; ++n) {
        rb_tree_node *node = &tree->nodes[n];
        if (node->parent < 0) {
            continue;
        }
        const double *xp = tree->nodes[node->parent].value;
        const double *x = node->x;
        double *y = node->value;
        if (node->dim == 3) {
            y[0] -= x[0] * xp[0] + x[1] * xp[1];
            y[1] -= x[2] * xp[0] + x[3] * xp[1];
            y[2] -= x[4] * xp[0] + x[5] * xp[1];
        } else {
            y[0] -= x[0] * xp[0] + x[1] * xp[1] + x[2] * xp[2];
            y[1] -= x[3] * xp[0] + x[4] * xp[1] + x[5] * xp[2];
        }
    }
}

static rb_tree_node *parent_of(rb_joint_tree *tree, const rb_tree_node *node)
{
    return node->parent >= 0 ? &tree->nodes[node->parent] : NULL;
}

/* Solves H·x = b in place over node->value with the factors the nodes
 * hold: L·D·Lᵀ from the leaves up, then down from the roots. */
static void solve(rb_joint_tree *tree)
{
    if (tree->chains) {
        rb_joint_chain_solve(tree);
        return;
    }
    for (int n = tree->node_count - 1; n >= 0; --n) {
        rb_tree_node *node = &tree->nodes[n];
        substitute_forward(node, parent_of(tree, node));
    }
    substitute_back(tree);
}

/* Factors every tree with the offsets its pins hold (node ra, rb) and
 * solves H·x = b as solve() does, in one sweep from the leaves: a node's
 * forward substitution needs only its own factors and its children's.
 * The pivots must be started (start_pivot) and the right-hand side set.
 * Returns false when a pivot is singular, which leaves the trees unusable
 * until they are factored again. */
static bool factor_and_solve(rb_joint_tree *tree)
{
    if (tree->chains) {
        return rb_joint_chain_factor_and_solve(tree);
    }
    for (int n = tree->node_count - 1; n >= 0; --n) {
        rb_tree_node *node = &tree->nodes[n];
        if (!invert(node->pivot, node->dinv, node->dim)) {
            return false;
        }
        rb_tree_node *parent = parent_of(tree, node);
        if (parent != NULL) {
            double s;
            rb_vec2 r;
            edge(node, parent, &s, &r);
            if (node->body >= 0) {
                eliminate_body(node, parent, s, r);
            } else {
                eliminate_pin(node, parent, s, r);
            }
        }
        substitute_forward(node, parent);
    }
    substitute_back(tree);
    return true;
}

/* Whether this substep's pins start cold: a tree that no other row
 * touches, under a solver whose first velocity pass solves it exactly
 * (NGS, rb_joint_tree_solve_velocities). Its bodies' velocities after
 * that pass are then those of the exact solution whatever impulse the
 * pins were warm started with: applying the held impulses first and
 * adding the pass's correction to them, or solving from the velocities
 * as they are for the whole impulse, differ only in rounding. So its
 * pins are not warm started; their velocity errors are read in the same
 * sweep that prepares their frames, and the pass's impulses replace
 * those they hold. (The soft step's passes soften each impulse by the
 * one the pin holds, rb_soften, and need the warm start.) */
static bool starts_cold(const rb_world *world)
{
    return world->joint_tree.alone && world->settings.type != RB_SOLVER_SOFT_STEP;
}

/* A plain pin's anchors turned into the world at the poses now (its
 * frame's ra, rb) and its centripetal drift for the substep. */
static void prepare_pin(rb_world *world, rb_joint *joint, double h)
{
    rb_joint_frame *f = &joint->frame;
    f->rb = rb_rotate(world->states[joint->body_b].rotation, f->local_b);
    f->ra = rb_rotate(world->states[joint->body_a].rotation, f->local_a);
    rb_point_constraint_prepare_drift(world, joint, h);
}

/* Applies each plain pin's held impulse at its anchors. */
static void apply_held_impulses(rb_world *world, bool backwards)
{
    const rb_joint_tree *tree = &world->joint_tree;
    for (int k = 0; k < tree->node_count; ++k) {
        const int j = tree->nodes[backwards ? tree->node_count - 1 - k : k].joint;
        if (j >= 0 && world->joints[j].plain_pin) {
            const rb_joint *joint = &world->joints[j];
            rb_joint_apply_linear(joint, &world->states[joint->body_a], &world->states[joint->body_b],
                                  joint->as.revolute.point_impulse);
        }
    }
}

/* The cold start's sweep: each pin prepared as rb_joint_tree_warm_start
 * does, then its velocity error as the substep's first pass reads it
 * (rb_joint_tree_solve_velocities), at the anchors it factors at. */
static void prepare_cold(rb_world *world, double h)
{
    rb_joint_tree *tree = &world->joint_tree;
    tree->cold = true;
    for (int n = 0; n < tree->node_count; ++n) {
        rb_tree_node *node = &tree->nodes[n];
        if (node->joint < 0) {
            memset(node->value, 0, sizeof node->value);
            continue;
        }
        rb_joint *joint = &world->joints[node->joint];
        prepare_pin(world, joint, h); /* a tree alone has no pin with a motor or spring */
        node->ra = joint->frame.ra;
        node->rb = joint->frame.rb;
        const rb_vec2 cdot =
            rb_point_velocity_error(world, joint, &world->states[joint->body_a], &world->states[joint->body_b]);
        node->value[0] = cdot.x;
        node->value[1] = cdot.y;
    }
}

void rb_joint_tree_warm_start(rb_world *world, double h, bool backwards)
{
    rb_joint_tree *tree = &world->joint_tree;
    if (starts_cold(world)) {
        prepare_cold(world, h);
        return;
    }
    tree->cold = false;
    for (int k = 0; k < tree->node_count; ++k) {
        const int j = tree->nodes[backwards ? tree->node_count - 1 - k : k].joint;
        if (j >= 0 && world->joints[j].plain_pin) { /* not a body, nor a pin with a motor or spring */
            prepare_pin(world, &world->joints[j], h);
        }
    }
    apply_held_impulses(world, backwards);
}

void rb_joint_tree_start_substep(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    tree->pose_factors = false;
    tree->velocity_factors = false;
    tree->solved = false;
}

/* Sets each node's right-hand side for a velocity pass: a pin's velocity
 * error, a body's zero; when factoring, also each pin's offsets (the
 * substep's anchors, which the pins' frames hold). */
static void read_velocity_errors(rb_world *world, bool factoring)
{
    rb_joint_tree *tree = &world->joint_tree;
    for (int n = 0; n < tree->node_count; ++n) {
        rb_tree_node *node = &tree->nodes[n];
        if (node->joint < 0) {
            memset(node->value, 0, sizeof node->value);
        } else {
            const rb_joint *joint = &world->joints[node->joint];
            if (factoring) {
                node->ra = joint->frame.ra;
                node->rb = joint->frame.rb;
            }
            rb_vec2 cdot =
                rb_point_velocity_error(world, joint, rb_joint_state_a(world, joint), rb_joint_state_b(world, joint));
            node->value[0] = cdot.x;
            node->value[1] = cdot.y;
        }
    }
}

/* The substep's first pass factors the trees at the substep's anchors as
 * it solves, its right-hand side read by the warm start's sweep when the
 * pins start cold; the further passes reuse the factors. */
void rb_joint_tree_solve_velocities(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    const bool factoring = !tree->solved;
    if (tree->node_count == 0 || (!factoring && (tree->alone || !tree->velocity_factors))) {
        return;
    }
    tree->solved = true;
    const bool cold = tree->cold; /* the warm start's sweep read the velocity errors */
    tree->cold = false;
    if (!cold) {
        read_velocity_errors(world, factoring);
    }
    if (factoring) {
        for (int n = 0; !tree->chains && n < tree->node_count; ++n) {
            start_pivot(tree, &tree->nodes[n]);
        }
        tree->velocity_factors = factor_and_solve(tree);
        if (!tree->velocity_factors) {
            if (cold) {
                apply_held_impulses(world, false); /* the warm start they would have had */
            }
            return;
        }
    } else {
        solve(tree);
    }
    for (int n = 0; n < tree->node_count; ++n) {
        const rb_tree_node *node = &tree->nodes[n];
        if (node->body >= 0) {
            rb_body_state *state = &world->states[node->body];
            state->linear_velocity = rb_add(state->linear_velocity, rb_v2(node->value[0], node->value[1]));
            state->angular_velocity += node->value[2];
        } else {
            rb_revolute_data *r = &world->joints[node->joint].as.revolute;
            const rb_vec2 impulse = rb_v2(node->value[0], node->value[1]);
            r->point_impulse = cold ? impulse : rb_add(r->point_impulse, impulse);
        }
    }
}

/* A pin's bodies and the offsets it holds. */
typedef struct pin_offsets {
    rb_body_state *a, *b;
    rb_vec2 ra, rb; /* m, from each body's centre to its anchor */
} pin_offsets;

static pin_offsets offsets_of(rb_world *world, const rb_tree_node *pin)
{
    const rb_joint *joint = &world->joints[pin->joint];
    return (pin_offsets){
        .a = &world->states[joint->body_a], .b = &world->states[joint->body_b], .ra = pin->ra, .rb = pin->rb};
}

/* m: anchor B less anchor A. */
static rb_vec2 pin_gap(const pin_offsets *p)
{
    return rb_sub(rb_add(p->b->center, p->rb), rb_add(p->a->center, p->ra));
}

/* The soft step's pass. Its relax pass comes after the positions have
 * moved, so the pins are taken where they are now: the trees factored at
 * the current poses, the rows' velocities at the current anchors (Box2D
 * v3 also solves its joints at anchors turned with the bodies). Asked to
 * close the gap at the spring's bias rate, the tree's impulses are then
 * softened as a single row's are (rb_soften): the spring's softness is
 * proportional to the rows' mass, gamma = K/a2 (rb_make_rigid_softness),
 * so the soft solution of K·λ = -(Cdot + bias) - gamma·λ_accumulated is
 * (K + K/a2)⁻¹ applied to it, mass_scale times the rigid solution less
 * impulse_scale times the impulse each pin holds. The bodies take the
 * softened impulses at the pins' anchors. The factors serve every pass
 * until the bodies move: the relax pass's serve the next substep's solve
 * pass, the integration of velocities between them moving no body. */
void rb_joint_tree_solve_soft(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    if (tree->node_count == 0) {
        return;
    }
    const bool factoring = !tree->pose_factors;
    const rb_rigid_response *response = &world->joint_response;
    for (int n = 0; n < tree->node_count; ++n) {
        rb_tree_node *node = &tree->nodes[n];
        if (factoring) {
            start_pivot(tree, node);
        }
        if (node->joint < 0) {
            memset(node->value, 0, sizeof node->value);
            continue;
        }
        if (factoring) {
            measure_offsets(world, node);
        }
        const pin_offsets p = offsets_of(world, node);
        rb_vec2 va = rb_add(p.a->linear_velocity, rb_cross_sv(p.a->angular_velocity, p.ra));
        rb_vec2 vb = rb_add(p.b->linear_velocity, rb_cross_sv(p.b->angular_velocity, p.rb));
        rb_vec2 cdot = rb_sub(vb, va);
        if (response->bias_rate > 0.0) {
            cdot = rb_mul_add(cdot, response->bias_rate, pin_gap(&p));
        }
        node->value[0] = cdot.x;
        node->value[1] = cdot.y;
    }
    if (factoring) {
        tree->pose_factors = factor_and_solve(tree);
        if (!tree->pose_factors) {
            return;
        }
    } else {
        solve(tree);
    }
    for (int n = 0; n < tree->node_count; ++n) {
        const rb_tree_node *node = &tree->nodes[n];
        if (node->body >= 0) {
            continue;
        }
        rb_joint *joint = &world->joints[node->joint];
        const rb_joint_frame *f = &joint->frame;
        rb_revolute_data *r = &joint->as.revolute;
        rb_vec2 impulse = rb_soften(response, rb_v2(node->value[0], node->value[1]), r->point_impulse);
        r->point_impulse = rb_add(r->point_impulse, impulse);
        const pin_offsets p = offsets_of(world, node);
        p.a->linear_velocity = rb_mul_sub(p.a->linear_velocity, f->inv_mass_a, impulse);
        p.a->angular_velocity -= f->inv_inertia_a * rb_cross(p.ra, impulse);
        p.b->linear_velocity = rb_mul_add(p.b->linear_velocity, f->inv_mass_b, impulse);
        p.b->angular_velocity += f->inv_inertia_b * rb_cross(p.rb, impulse);
    }
}

/* Whether every pin's gap is within the linear slop at the poses now:
 * the position pass's check, which is all it does while the trees hold
 * (at the defaults, every pass of the 100:1 chains), reading only the
 * poses and the anchors in the body frames. */
static bool gaps_within_slop(const rb_world *world)
{
    const rb_joint_tree *tree = &world->joint_tree;
    const double slop = world->settings.linear_slop;
    for (int n = 0; n < tree->node_count; ++n) {
        const int j = tree->nodes[n].joint;
        if (j < 0) {
            continue;
        }
        const rb_joint *joint = &world->joints[j];
        const rb_body_state *a = &world->states[joint->body_a];
        const rb_body_state *b = &world->states[joint->body_b];
        const rb_vec2 anchor_a = rb_add(a->center, rb_rotate(a->rotation, joint->frame.local_a));
        const rb_vec2 anchor_b = rb_add(b->center, rb_rotate(b->rotation, joint->frame.local_b));
        if (rb_length_squared(rb_sub(anchor_b, anchor_a)) > slop * slop) {
            return false;
        }
    }
    return true;
}

bool rb_joint_tree_correct_positions(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    if (tree->node_count == 0) {
        return true;
    }
    /* The factors at the current poses replace the substep's, and are
     * out of date once the bodies move. */
    tree->velocity_factors = false;
    tree->pose_factors = false;
    if (gaps_within_slop(world)) {
        return true;
    }
    double cap = world->settings.max_linear_correction;
    for (int n = 0; n < tree->node_count; ++n) {
        rb_tree_node *node = &tree->nodes[n];
        if (node->joint < 0) {
            continue;
        }
        measure_offsets(world, node);
        const pin_offsets p = offsets_of(world, node);
        rb_vec2 gap = pin_gap(&p);
        double error_squared = rb_length_squared(gap);
        if (error_squared > cap * cap) {
            gap = rb_scale(cap / sqrt(error_squared), gap);
        }
        node->value[0] = gap.x;
        node->value[1] = gap.y;
    }
    for (int n = 0; n < tree->node_count; ++n) {
        rb_tree_node *node = &tree->nodes[n];
        start_pivot(tree, node);
        if (node->joint < 0) {
            memset(node->value, 0, sizeof node->value);
        }
    }
    if (!factor_and_solve(tree)) {
        return false;
    }
    /* The step is the linearised system's, exact for small gaps. Where a
     * gap is large or a light body spins, it can ask for turns far beyond
     * the linearisation's reach, and the next pass overshoots back: scaled
     * as a whole so that no body moves more than max_linear_correction or
     * turns more than RB_MAX_ANGULAR_CORRECTION, the step keeps its
     * direction and the trees converge over the passes and substeps. */
    double scale = 1.0;
    for (int n = 0; n < tree->node_count; ++n) {
        const rb_tree_node *node = &tree->nodes[n];
        if (node->body >= 0) {
            double move = sqrt(node->value[0] * node->value[0] + node->value[1] * node->value[1]);
            if (move * scale > cap) {
                scale = cap / move;
            }
            if (fabs(node->value[2]) * scale > RB_MAX_ANGULAR_CORRECTION) {
                scale = RB_MAX_ANGULAR_CORRECTION / fabs(node->value[2]);
            }
        }
    }
    for (int n = 0; n < tree->node_count; ++n) {
        const rb_tree_node *node = &tree->nodes[n];
        if (node->body >= 0) {
            rb_body_state *state = &world->states[node->body];
            state->center = rb_add(state->center, rb_v2(scale * node->value[0], scale * node->value[1]));
            rb_body_state_turn(state, scale * node->value[2]);
        }
    }
    return false;
}

void rb_joint_tree_poses_moved(rb_world *world) { world->joint_tree.pose_factors = false; }

void rb_joint_tree_free(rb_world *world)
{
    rb_joint_tree *tree = &world->joint_tree;
    rb_free_array((void **)&tree->nodes, &tree->node_capacity, sizeof(rb_tree_node));
    rb_free_array((void **)&tree->body_node, &tree->body_node_capacity, sizeof(int));
    rb_free_array((void **)&tree->union_parent, &tree->union_capacity, sizeof(int));
    rb_free_array((void **)&tree->grounded, &tree->grounded_capacity, 1);
    rb_free_array((void **)&tree->mass_range, &tree->mass_range_capacity, sizeof(double));
    rb_free_array((void **)&tree->gauss_seidel_joints, &tree->gauss_seidel_capacity, sizeof(int));
    rb_free_array((void **)&tree->keys, &tree->key_capacity, sizeof(rb_tree_key));
    tree->node_count = 0;
    tree->found = false;
}
