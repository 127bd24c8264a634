/* SPDX-License-Identifier: MIT */
/* The soft step's joints in colour order.
 *
 * A Gauss-Seidel pass that visits the joints in the order they were made
 * carries each pass's correction along that order: far in the sweep's
 * direction, one joint against it. A net built column by column, like
 * the 100 x 100 joint grid hung from the middle of its top row, is then
 * solved unevenly: the half whose load must travel against the sweep to
 * reach the supports converges more slowly and stretches further. At Box2D
 * v3's budget (4 substeps of one solve and one relax pass) the grid
 * stretched to 0.634 m swept from the last joint made to the first, and
 * to 0.861 m from the first to the last.
 *
 * Coloured (constraint_colouring.c), a pass solves one colour after
 * another, each a set of joints that share no moving body and so give
 * the same result in any order: the pass no longer depends on the order
 * the joints were made in, and corrections spread alike in every
 * direction, a few joints per pass. The joints that hold a body to one
 * that cannot move (a support, the world, a sleeping body) take the
 * highest colours and are solved last in each pass, so that the supports
 * have the last word on the velocities they leave; solved first instead,
 * the grid stretches to 0.620 m, and coloured with the lowest colours
 * like any other joint, to 0.622 m. Coloured so, the grid stretches to
 * 0.613 m, Box2D v3's own order, which reaches 0.620 m in single
 * precision (docs/benchmarks.md).
 *
 * The colours are found again in every step, in the order of the pass
 * list, so a step depends only on the joints and bodies there are: a
 * few microseconds for the grid's 19,800 joints. */
#include "constraint_colouring.h"
#include "joint_solver.h"

/* A body the joints' impulses move: dynamic and awake (a joint is solved
 * while one of its bodies is). */
static bool moves(const rb_world *world, int body)
{
    return body >= 0 && world->bodies[body].type == RB_BODY_DYNAMIC && world->bodies[body].awake;
}

void rb_joints_order_by_colour(rb_world *world)
{
    int count = 0;
    const int *joints = rb_joint_pass_list(world, &count);
    rb_colouring *colouring = &world->joint_colouring;
    /* The space was made by rb_joints_collect_active: this allocates nothing. */
    (void)rb_colouring_begin(colouring, world->body_slots);
    for (int k = 0; k < count; ++k) {
        const rb_joint *joint = &world->joints[joints[k]];
        int a = moves(world, joint->body_a) ? joint->body_a : -1;
        int b = moves(world, joint->body_b) ? joint->body_b : -1;
        world->joint_colours[k] = rb_colouring_assign(colouring, a, b);
    }
    int offsets[RB_COLOUR_COUNT + 1];
    (void)rb_colouring_offsets(colouring, offsets);
    for (int k = 0; k < count; ++k) { /* in pass order within each colour */
        world->coloured_joints[offsets[world->joint_colours[k]]++] = joints[k];
    }
    world->coloured_joint_count = count;
    world->joints_coloured = true;
}
