/* SPDX-License-Identifier: MIT */
/* Mouse joint: pulls a point of one body towards a target with a
 * spring-damper of the given frequency and damping (on the body's mass),
 * its force capped at max_force: what a viewer uses to drag a body. The
 * spring acts through the point's 2x2 mass matrix K (as the pin's, with
 * no body A), softened by gamma:
 *   P = -(K + gamma·I)^-1 (Cdot + bias_rate·C + gamma·P_acc),
 * and the accumulated impulse is scaled back to max_force·h. */
#include <float.h>

#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"

rb_mouse_joint_def rb_default_mouse_joint_def(void)
{
    return (rb_mouse_joint_def){
        .max_force = 1000.0, .hertz = 5.0, .damping_ratio = 0.7, .internal_value = RB_DEF_COOKIE};
}

rb_status rb_mouse_joint_create(rb_world *world, const rb_mouse_joint_def *def, rb_joint_id *out)
{
    const char *f = "rb_mouse_joint_create";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "out", out));
    *out = (rb_joint_id){0};
    RB_TRY(rb_check_pointer(f, "def", def));
    RB_TRY(rb_check_def_cookie(f, "rb_default_mouse_joint_def", def->internal_value));
    int body;
    RB_TRY(rb_world_find_body(world, def->body, f, &body));
    if (world->bodies[body].type != RB_BODY_DYNAMIC) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: the body is not dynamic and cannot be dragged", f);
    }
    RB_TRY(rb_check_point(f, "local_anchor", def->local_anchor));
    RB_TRY(rb_check_point(f, "target", def->target));
    RB_TRY(rb_check_range(f, "max_force", def->max_force, 0.0, RB_MAX_FORCE));
    RB_TRY(rb_check_hertz(f, "hertz", def->hertz, false));
    RB_TRY(rb_check_range(f, "damping_ratio", def->damping_ratio, 0.0, RB_MAX_DAMPING_RATIO));
    rb_joint joint = {
        .type = RB_JOINT_MOUSE,
        .body_a = -1,
        .body_b = body,
        .local_anchor_b = def->local_anchor,
        .user_data = def->user_data,
        .as.mouse =
            {
                .target = def->target,
                .max_force = def->max_force,
                .hertz = def->hertz,
                .damping_ratio = def->damping_ratio,
            },
    };
    return rb_joint_create(world, &joint, out, f);
}

rb_status rb_mouse_joint_set_target(rb_world *world, rb_joint_id id, rb_vec2 target)
{
    const char *f = "rb_mouse_joint_set_target";
    rb_status status;
    rb_joint *joint = rb_joint_find_for_change(world, id, RB_JOINT_MOUSE, f, &status);
    RB_TRY(status);
    RB_TRY(rb_check_point(f, "target", target));
    joint->as.mouse.target = target;
    return RB_OK;
}

void rb_mouse_warm_start(rb_world *world, rb_joint *joint)
{
    rb_joint_apply_linear(joint, NULL, rb_joint_state_b(world, joint), joint->as.mouse.impulse);
}

void rb_mouse_solve(rb_world *world, rb_joint *joint, double h)
{
    rb_mouse_data *m = &joint->as.mouse;
    const rb_joint_frame *f = &joint->frame;
    rb_body_state *b = rb_joint_state_b(world, joint);
    if (f->inv_mass_b <= 0.0) {
        return;
    }
    rb_softness soft = rb_make_softness(m->hertz, m->damping_ratio, 1.0 / f->inv_mass_b, h);
    rb_vec2 r = f->rb;
    double ib = f->inv_inertia_b;
    double k11 = f->inv_mass_b + ib * r.y * r.y + soft.gamma;
    double k12 = -ib * r.x * r.y;
    double k22 = f->inv_mass_b + ib * r.x * r.x + soft.gamma;
    double det = k11 * k22 - k12 * k12;
    rb_vec2 gap = rb_sub(rb_add(b->center, r), m->target);
    rb_vec2 cdot = rb_joint_relative_velocity(joint, NULL, b);
    rb_vec2 rhs = rb_add(rb_add(cdot, rb_scale(soft.bias_rate, gap)), rb_scale(soft.gamma, m->impulse));
    rb_vec2 impulse = rb_v2(-(k22 * rhs.x - k12 * rhs.y) / det, -(k11 * rhs.y - k12 * rhs.x) / det);
    rb_vec2 old = m->impulse;
    m->impulse = rb_add(m->impulse, impulse);
    double limit = m->max_force * h;
    double magnitude = rb_length(m->impulse);
    if (magnitude > limit) {
        m->impulse = rb_scale(limit / magnitude, m->impulse);
    }
    rb_joint_apply_linear(joint, NULL, b, rb_sub(m->impulse, old));
}
