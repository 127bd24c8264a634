/* SPDX-License-Identifier: MIT */
/* The order in which the passes visit the joints.
 *
 * One Gauss-Seidel pass of joints carries a correction far along the
 * order it visits them and one joint against it: a joint solved after
 * its neighbours sees what they did in this pass, one solved before sees
 * what they did in the last. Where the load goes matters. A hanging
 * structure's joints carry the weight of everything beyond them, from
 * the free ends towards the supports, and the pass that visits them in
 * that order hands each joint the loads already corrected below it in
 * the same pass, and leaves the last word to the joints at the supports,
 * which hold everything. The passes therefore visit the joints by their
 * depth, the number of joints between them and a body that cannot move
 * (a support, the world, a sleeping body), the deepest first; a joint's
 * depth is its deeper body's, found by a breadth-first search from the
 * bodies pinned to the supports.
 *
 * Joints of one depth (the rungs of a ladder, the rows of a net) are
 * taken colour by colour (constraint_colouring.c): a colour is a set of
 * joints that share no moving body, whose order within the colour
 * changes nothing, so that the pass does not depend on the order the
 * joints were made in. Joints that reach no support (a mechanism in free
 * flight) have no depth: they come first, by colour alone.
 *
 * Measured at Box2D v3's budget (4 substeps of one solve and one relax
 * pass, bench_engine --scene joint_grid --grid N): the joint grid hung
 * from the middle of its top row, built column by column, stretched to
 * 0.634 m at N = 100 swept in the order the joints were made, backwards
 * (0.861 m forwards): the load of one half of it travelled to the
 * supports with the sweep, the other half's against it, one joint a
 * pass. Colour by colour alone, as Box2D v3 solves its
 * joints, it reaches 0.613 m, as Box2D v3's 0.620 m (and the 30 and 60
 * grids Box2D v3's gaps to 5 digits); by depth alone 0.689 m; by depth
 * and colour 0.589 m. On a chain the order is a sweep from the free end
 * to the pin.
 *
 * NGS and Baumgarte visit the plain pins (revolute joints with no limit,
 * motor or spring: nets, grids, chains the trees leave) in the same
 * order, after the other joints, which keep the order they were made in.
 * For the grid at the defaults (NGS, 6 substeps of 2 + 1 passes) this
 * order gives 0.411 m of worst stretch, against 0.499 m swept in the
 * order made, and a shorter step for nearly the same instructions: in
 * the order made, each pin shares a body with the one before it and
 * waits for its stores, while the pins of one colour share none and the
 * processor overlaps them (10 % on the 100 grid, 24 to 29 % on the 60
 * and 30 grids). The other joints keep their order because the built-in
 * muscle models (limited pins, welds, distance joints) were validated
 * in it, and ordering them changes the arm's and the leg's results. */
#include <string.h>

#include "joint_solver.h"

/* Whether a body the joints' impulses move (dynamic and awake: a joint
 * is solved while one of its bodies is), once find_depths has marked
 * them: -1 or a depth for those, 0 for the others and the world (-1). */
static bool marked_moving(const rb_world *world, int body) { return body >= 0 && world->body_depth[body] != 0; }

/* Marks the bodies that move and links each to its active joints' other
 * bodies (compressed rows: body i's in body_edges[body_edge_start[i] ..
 * body_edge_start[i + 1]]), with each active joint's bodies in
 * joint_ends: the passes below read these small arrays rather than the
 * joints and bodies. */
static void link_bodies(rb_world *world)
{
    int *depth = world->body_depth;
    for (int i = 0; i < world->body_slots; ++i) {
        const rb_body *body = &world->bodies[i];
        depth[i] = body->type == RB_BODY_DYNAMIC && body->awake ? -1 : 0;
    }
    int *start = world->body_edge_start;
    memset(start, 0, (size_t)(world->body_slots + 1) * sizeof *start);
    for (int k = 0; k < world->active_joint_count; ++k) {
        int slot = world->active_joints[k];
        int a = world->joints[slot].body_a;
        int b = world->joints[slot].body_b;
        world->joint_ends[2 * slot] = a;
        world->joint_ends[2 * slot + 1] = b;
        start[a + 1] += marked_moving(world, a) ? 1 : 0; /* counts, one place on */
        start[b + 1] += marked_moving(world, b) ? 1 : 0;
    }
    for (int i = 0; i < world->body_slots; ++i) {
        start[i + 1] += start[i];
    }
    /* Filled through start[i], which then ends at the next body's start:
     * moved back one place after. */
    for (int k = 0; k < world->active_joint_count; ++k) {
        const int *ends = &world->joint_ends[2 * world->active_joints[k]];
        if (marked_moving(world, ends[0])) {
            world->body_edges[start[ends[0]]++] = ends[1];
        }
        if (marked_moving(world, ends[1])) {
            world->body_edges[start[ends[1]]++] = ends[0];
        }
    }
    for (int i = world->body_slots; i > 0; --i) {
        start[i] = start[i - 1];
    }
    start[0] = 0;
}

/* Every moving body's depth in world->body_depth: 1 for one pinned to a
 * body that cannot move, one more for each joint beyond, -1 for one that
 * reaches no support. Returns the deepest. */
static int find_depths(rb_world *world)
{
    link_bodies(world);
    int *depth = world->body_depth;
    int *queue = world->body_queue;
    int tail = 0;
    for (int k = 0; k < world->active_joint_count; ++k) {
        const int *ends = &world->joint_ends[2 * world->active_joints[k]];
        bool a_moves = marked_moving(world, ends[0]);
        bool b_moves = marked_moving(world, ends[1]);
        int pinned = a_moves && !b_moves ? ends[0] : (b_moves && !a_moves ? ends[1] : -1);
        if (pinned >= 0 && depth[pinned] < 0) {
            depth[pinned] = 1;
            queue[tail++] = pinned;
        }
    }
    int deepest = 0;
    for (int head = 0; head < tail; ++head) {
        int body = queue[head];
        deepest = depth[body];
        for (int e = world->body_edge_start[body]; e < world->body_edge_start[body + 1]; ++e) {
            int other = world->body_edges[e];
            if (other >= 0 && depth[other] < 0) {
                depth[other] = depth[body] + 1;
                queue[tail++] = other;
            }
        }
    }
    return deepest;
}

/* The list's joints colour by colour into world->joint_order_scratch, in
 * the list's order within each colour. */
static void sort_by_colour(rb_world *world, const int *joints, int count)
{
    rb_colouring *colouring = &world->joint_colouring;
    (void)rb_colouring_begin(colouring, world->body_slots); /* the space is there: no allocation */
    for (int k = 0; k < count; ++k) {
        const int *ends = &world->joint_ends[2 * joints[k]];
        int a = marked_moving(world, ends[0]) ? ends[0] : -1;
        int b = marked_moving(world, ends[1]) ? ends[1] : -1;
        world->joint_keys[k] = rb_colouring_assign(colouring, a, b);
    }
    int offsets[RB_COLOUR_COUNT + 1];
    (void)rb_colouring_offsets(colouring, offsets);
    for (int k = 0; k < count; ++k) {
        world->joint_order_scratch[offsets[world->joint_keys[k]]++] = joints[k];
    }
}

/* Where a joint goes: 0 for one that reaches no support, then from the
 * deepest (1) to depth 1 (deepest). */
static int depth_bucket(const rb_world *world, int slot, int deepest)
{
    const int *ends = &world->joint_ends[2 * slot];
    int depth_a = ends[0] >= 0 ? world->body_depth[ends[0]] : 0;
    int depth_b = world->body_depth[ends[1]];
    if (depth_a < 0 || depth_b < 0) {
        return 0;
    }
    return deepest + 1 - (depth_a > depth_b ? depth_a : depth_b);
}

/* Whether a listed joint is a plain pin, which NGS and Baumgarte order
 * (the list holds no pin of a tree). */
static bool is_plain_pin(const rb_world *world, int slot)
{
    const rb_joint *joint = &world->joints[slot];
    return joint->type == RB_JOINT_REVOLUTE && joint->plain_pin;
}

/* Finds the order into world->ordered_joints: with `scope` the plain
 * pins, the other joints first as listed, then the pins; every joint
 * otherwise. */
static void find_order(rb_world *world, rb_joint_order_scope scope)
{
    int listed = 0;
    const int *joints = rb_joint_pass_list(world, &listed);
    world->ordered_joint_count = listed;
    if (listed == 0) {
        return; /* and the list may not even be allocated (NULL + 0 is undefined) */
    }
    int first = 0; /* where the ordered joints start */
    int count = listed;
    if (scope == RB_ORDER_PLAIN_PINS) {
        /* The others to the front; the pins, as listed, after them until
         * sort_by_colour has read them. */
        int pins = 0;
        for (int k = 0; k < listed; ++k) {
            first += is_plain_pin(world, joints[k]) ? 0 : 1;
        }
        int others = 0;
        for (int k = 0; k < listed; ++k) {
            int slot = joints[k];
            world->ordered_joints[is_plain_pin(world, slot) ? first + pins++ : others++] = slot;
        }
        joints = world->ordered_joints + first;
        count = pins;
        if (count == 0) {
            return; /* no pin to order (the muscle models' limbs): the others as they were made */
        }
    }
    int deepest = find_depths(world);
    sort_by_colour(world, joints, count);

    /* A stable counting sort of the coloured list by depth, the deepest
     * first; the queue, done with, holds the buckets' starts. */
    int *start = world->body_queue;
    memset(start, 0, (size_t)(deepest + 1) * sizeof *start);
    for (int k = 0; k < count; ++k) {
        world->joint_keys[k] = depth_bucket(world, world->joint_order_scratch[k], deepest);
        ++start[world->joint_keys[k]];
    }
    int offset = first;
    for (int bucket = 0; bucket <= deepest; ++bucket) {
        int size = start[bucket];
        start[bucket] = offset;
        offset += size;
    }
    for (int k = 0; k < count; ++k) {
        world->ordered_joints[start[world->joint_keys[k]]++] = world->joint_order_scratch[k];
    }
}

void rb_joints_order(rb_world *world, rb_joint_order_scope scope)
{
    /* The order depends on what the trees are found from (the active
     * joints, their bodies and whether those move: joint_tree.c), and is
     * kept while they are: found again in each step, it took some 4 M
     * instructions a step of the joint grid's 55 M. */
    const rb_joint_tree *tree = &world->joint_tree;
    if (!(tree->found && world->joint_order_kept && world->joint_order_finds == tree->finds &&
          world->joint_order_scope == scope)) {
        find_order(world, scope);
        world->joint_order_kept = tree->found;
        world->joint_order_finds = tree->finds;
        world->joint_order_scope = scope;
    }
    world->joints_ordered = true;
}
