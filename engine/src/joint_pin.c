/* SPDX-License-Identifier: MIT */
/* The plain pins' rows: a revolute joint with no limit, motor or spring
 * is the point constraint alone (joint_point.c), and in a large mesh of
 * them, the 100 x 100 joint grid, the solver's time goes to memory rather
 * than arithmetic: each phase of each substep streams every pin through
 * the caches. A joint holds much a pass does not read (its type's
 * settings, the pool's links, the limits' impulses), so the step gathers
 * what a plain pin's phases read, its bodies, frame and impulse, into a
 * dense array once, lets the phases read and write that alone, and
 * writes the impulses back into the joints once at the end (Box2D v3
 * keeps its joints' solver data apart from their definitions likewise:
 * Catto, "Solver2D", 2024).
 *
 * The rows run the same arithmetic as the joints they stand for, in the
 * same order (the active joints', which every phase keeps), so a step
 * gives the same bits either way. */
#include <string.h>

#include "joint_solver.h"

void rb_pins_gather(rb_world *world)
{
    if (world->joint_slots > 0) {
        memset(world->pin_row_of, 0xff, (size_t)world->joint_slots * sizeof *world->pin_row_of); /* all -1 */
    }
    int count = 0;
    for (int k = 0; k < world->active_joint_count; ++k) {
        int slot = world->active_joints[k];
        const rb_joint *joint = &world->joints[slot];
        if (joint->type != RB_JOINT_REVOLUTE || !joint->plain_pin || joint->in_tree) {
            continue;
        }
        world->pin_rows[count] = (rb_pin_row){
            .body_a = joint->body_a,
            .body_b = joint->body_b,
            .impulse = joint->as.revolute.point_impulse,
            .frame = joint->frame, /* the masses and local anchors this step (rb_joints_collect_active) */
        };
        world->pin_row_of[slot] = count++;
    }
    world->pin_row_count = count;
    world->pin_rows_live = true;
}

void rb_pin_warm_start(rb_world *world, rb_pin_row *row, double h)
{
    rb_joint_frame *f = &row->frame;
    rb_body_state *a = &world->states[row->body_a];
    rb_body_state *b = &world->states[row->body_b];
    f->rb = rb_rotate(b->rotation, f->local_b);
    f->ra = rb_rotate(a->rotation, f->local_a);
    rb_point_alone_prepare(world, f, row->body_a, row->body_b, h);
    rb_frame_apply_linear(f, a, b, row->impulse);
}

void rb_pin_solve(rb_world *world, rb_pin_row *row)
{
    rb_body_state *a = &world->states[row->body_a];
    rb_body_state *b = &world->states[row->body_b];
    rb_point_alone_solve(world, &row->frame, a, b, rb_point_frame_velocity_error(world, &row->frame, a, b),
                         &row->impulse);
}

bool rb_pin_correct(rb_world *world, rb_pin_row *row)
{
    rb_body_state *a = &world->states[row->body_a];
    rb_body_state *b = &world->states[row->body_b];
    return rb_point_frame_correct(&row->frame, a, b, NULL) <= world->settings.linear_slop;
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
