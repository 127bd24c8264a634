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
         * the rest (rb_pin_prepare). */
        const rb_joint_frame *f = &joint->frame;
        world->pin_rows[count] = (rb_pin_row){
            .body_a = joint->body_a,
            .body_b = joint->body_b,
            .inv_mass_a = f->inv_mass_a,
            .inv_inertia_a = f->inv_inertia_a,
            .inv_mass_b = f->inv_mass_b,
            .inv_inertia_b = f->inv_inertia_b,
            .impulse = joint->as.revolute.point_impulse,
        };
        world->pin_anchors[count] = (rb_pin_anchors){f->local_a, f->local_b};
        world->pin_row_of[slot] = count++;
    }
    world->pin_row_count = count;
    world->pin_rows_live = true;
}

void rb_pin_warm_start(rb_world *world, int row, double h)
{
    rb_pin_row *r = &world->pin_rows[row];
    rb_pin_prepare(world, r, &world->pin_anchors[row], h);
    rb_apply_at_anchors(&world->states[r->body_a], &world->states[r->body_b], r->inv_mass_a, r->inv_inertia_a,
                        r->inv_mass_b, r->inv_inertia_b, r->ra, r->rb, r->impulse);
}

bool rb_pin_correct(rb_world *world, int row)
{
    return rb_pin_correct_point(world, &world->pin_rows[row], &world->pin_anchors[row]) <= world->settings.linear_slop;
}

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
