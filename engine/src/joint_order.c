/* SPDX-License-Identifier: MIT */
/* The order in which the soft step's passes visit the joints.
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
 * (0.861 m forwards): the half whose load travelled against the sweep
 * converged more slowly. Colour by colour alone, as Box2D v3 solves its
 * joints, it reaches 0.613 m, as Box2D v3's 0.620 m (and the 30 and 60
 * grids Box2D v3's gaps to 5 digits); by depth alone 0.689 m; by depth
 * and colour 0.589 m. On a chain the order is the backward sweep the
 * soft step used before: from the free end to the pin. */
#include <string.h>

#include "joint_solver.h"

/* A body the joints' impulses move: dynamic and awake (a joint is solved
 * while one of its bodies is). */
static bool moves(const rb_world *world, int body)
{
    return body >= 0 && world->bodies[body].type == RB_BODY_DYNAMIC && world->bodies[body].awake;
}

/* The list's joints colour by colour into world->joint_order_scratch, in
 * the list's order within each colour. */
static void sort_by_colour(rb_world *world, const int *joints, int count)
{
    rb_colouring *colouring = &world->joint_colouring;
    (void)rb_colouring_begin(colouring, world->body_slots); /* the space is there: no allocation */
    for (int k = 0; k < count; ++k) {
        const rb_joint *joint = &world->joints[joints[k]];
        int a = moves(world, joint->body_a) ? joint->body_a : -1;
        int b = moves(world, joint->body_b) ? joint->body_b : -1;
        world->joint_keys[k] = rb_colouring_assign(colouring, a, b);
    }
    int offsets[RB_COLOUR_COUNT + 1];
    (void)rb_colouring_offsets(colouring, offsets);
    for (int k = 0; k < count; ++k) {
        world->joint_order_scratch[offsets[world->joint_keys[k]]++] = joints[k];
    }
}

/* Every moving body's depth in world->body_depth: 1 for one pinned to a
 * body that cannot move, one more for each joint beyond, -1 for one that
 * reaches no support. Returns the deepest. */
static int find_depths(rb_world *world, const int *joints, int count)
{
    int *depth = world->body_depth;
    int *queue = world->body_queue;
    memset(depth, 0xff, (size_t)world->body_slots * sizeof *depth); /* all -1 */
    int tail = 0;
    for (int k = 0; k < count; ++k) {
        const rb_joint *joint = &world->joints[joints[k]];
        bool a_moves = moves(world, joint->body_a);
        bool b_moves = moves(world, joint->body_b);
        int pinned = a_moves && !b_moves ? joint->body_a : (b_moves && !a_moves ? joint->body_b : -1);
        if (pinned >= 0 && depth[pinned] < 0) {
            depth[pinned] = 1;
            queue[tail++] = pinned;
        }
    }
    int deepest = 0;
    for (int head = 0; head < tail; ++head) {
        int body = queue[head];
        deepest = depth[body];
        for (int j = world->bodies[body].first_joint; j >= 0;) {
            const rb_joint *joint = &world->joints[j];
            int other = joint->body_a == body ? joint->body_b : joint->body_a;
            if (moves(world, other) && depth[other] < 0) {
                depth[other] = depth[body] + 1;
                queue[tail++] = other;
            }
            j = joint->body_a == body ? joint->next_on_a : joint->next_on_b;
        }
    }
    return deepest;
}

/* Where a joint goes: 0 for one that reaches no support, then from the
 * deepest (1) to depth 1 (deepest). */
static int depth_bucket(const rb_world *world, const rb_joint *joint, int deepest)
{
    int depth_a = moves(world, joint->body_a) ? world->body_depth[joint->body_a] : 0;
    int depth_b = moves(world, joint->body_b) ? world->body_depth[joint->body_b] : 0;
    if (depth_a < 0 || depth_b < 0) {
        return 0;
    }
    return deepest + 1 - (depth_a > depth_b ? depth_a : depth_b);
}

void rb_joints_order_for_soft_step(rb_world *world)
{
    int count = 0;
    const int *joints = rb_joint_pass_list(world, &count);
    sort_by_colour(world, joints, count);
    int deepest = find_depths(world, joints, count);

    /* A stable counting sort of the coloured list by depth, the deepest
     * first; the queue, done with, holds the buckets' starts. */
    int *start = world->body_queue;
    memset(start, 0, (size_t)(deepest + 1) * sizeof *start);
    for (int k = 0; k < count; ++k) {
        world->joint_keys[k] = depth_bucket(world, &world->joints[world->joint_order_scratch[k]], deepest);
        ++start[world->joint_keys[k]];
    }
    int offset = 0;
    for (int bucket = 0; bucket <= deepest; ++bucket) {
        int size = start[bucket];
        start[bucket] = offset;
        offset += size;
    }
    for (int k = 0; k < count; ++k) {
        world->ordered_joints[start[world->joint_keys[k]]++] = world->joint_order_scratch[k];
    }
    world->ordered_joint_count = count;
    world->joints_ordered = true;
}
