/* SPDX-License-Identifier: MIT */
/* Weld joint: the point constraint and the angular constraint
 * θ = angle(B) - angle(A) - reference = 0 freeze the bodies' relative
 * pose (a model file's glue). Each part is rigid, or soft when given a
 * frequency: a spring-damper towards the frozen pose. Each substep solves
 * the angle, then the point. */
#include <float.h>

#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"

rb_weld_joint_def rb_default_weld_joint_def(void) { return (rb_weld_joint_def){.internal_value = RB_DEF_COOKIE}; }

rb_status rb_weld_joint_def_at(rb_weld_joint_def *def, const rb_world *world, rb_body_id body_a, rb_body_id body_b,
                               rb_vec2 world_anchor)
{
    const char *f = "rb_weld_joint_def_at";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "def", def));
    rb_weld_joint_def filled = rb_default_weld_joint_def();
    RB_TRY(rb_joint_anchor_at(world, body_a, body_b, world_anchor, f, &filled.local_anchor_a, &filled.local_anchor_b,
                              &filled.reference_angle));
    filled.body_a = body_a;
    filled.body_b = body_b;
    *def = filled;
    return RB_OK;
}

rb_status rb_weld_joint_create(rb_world *world, const rb_weld_joint_def *def, rb_joint_id *out)
{
    const char *f = "rb_weld_joint_create";
    rb_clear_error();
    int a;
    int b;
    RB_TRY(rb_joint_check_common(world, def, RB_JOINT_COMMON(def), out, f, "rb_default_weld_joint_def", &a, &b));
    RB_TRY(rb_check_bound(f, "reference_angle", def->reference_angle, RB_MAX_ANGLE, "rad"));
    RB_TRY(rb_check_hertz(f, "linear_hertz", def->linear_hertz, true));
    RB_TRY(rb_check_range(f, "linear_damping_ratio", def->linear_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO));
    RB_TRY(rb_check_hertz(f, "angular_hertz", def->angular_hertz, true));
    RB_TRY(rb_check_range(f, "angular_damping_ratio", def->angular_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO));
    rb_joint joint = {
        .type = RB_JOINT_WELD,
        .body_a = a,
        .body_b = b,
        .local_anchor_a = def->local_anchor_a,
        .local_anchor_b = def->local_anchor_b,
        .collide_connected = def->collide_connected,
        .user_data = def->user_data,
        .as.weld =
            {
                .reference_angle = def->reference_angle,
                .linear_hertz = def->linear_hertz,
                .linear_damping_ratio = def->linear_damping_ratio,
                .angular_hertz = def->angular_hertz,
                .angular_damping_ratio = def->angular_damping_ratio,
            },
    };
    return rb_joint_create(world, &joint, out, f);
}

void rb_weld_prepare_step(rb_joint *joint)
{
    double inverse_axial = joint->frame.inv_inertia_a + joint->frame.inv_inertia_b;
    joint->as.weld.axial_mass = inverse_axial > 0.0 ? 1.0 / inverse_axial : 0.0;
}

void rb_weld_warm_start(rb_world *world, rb_joint *joint)
{
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    rb_joint_apply_linear(joint, a, b, joint->as.weld.point_impulse);
    rb_joint_apply_angular(joint, a, b, joint->as.weld.angular_impulse);
}

static void solve_angle(rb_world *world, rb_joint *joint, rb_body_state *a, rb_body_state *b, double h)
{
    rb_weld_data *w = &joint->as.weld;
    if (w->axial_mass <= 0.0) {
        return;
    }
    double c = rb_joint_relative_angle(world, joint, w->reference_angle);
    double cdot = b->angular_velocity - a->angular_velocity;
    double impulse;
    if (w->angular_hertz > 0.0) {
        rb_softness soft = rb_make_softness(w->angular_hertz, w->angular_damping_ratio, w->axial_mass, h);
        impulse = -(cdot + soft.bias_rate * c + soft.gamma * w->angular_impulse) / (1.0 / w->axial_mass + soft.gamma);
    } else {
        impulse = rb_rigid_row_impulse(world, w->axial_mass, cdot, c, w->angular_impulse);
    }
    w->angular_impulse += impulse;
    rb_joint_apply_angular(joint, a, b, impulse);
}

/* A soft point: each axis a spring-damper on the linear effective mass
 * 1/(1/mA + 1/mB); the anchors' lever arms only shift where it acts. */
static void solve_soft_point(rb_joint *joint, rb_body_state *a, rb_body_state *b, double h)
{
    rb_weld_data *w = &joint->as.weld;
    const rb_joint_frame *f = &joint->frame;
    double inverse_mass = f->inv_mass_a + f->inv_mass_b;
    if (inverse_mass <= 0.0) {
        return;
    }
    rb_softness soft = rb_make_softness(w->linear_hertz, w->linear_damping_ratio, 1.0 / inverse_mass, h);
    rb_vec2 gap = rb_sub(rb_add(b->center, f->rb), rb_add(a->center, f->ra));
    rb_vec2 cdot = rb_joint_relative_velocity(joint, a, b);
    rb_vec2 target = rb_add(rb_add(cdot, rb_scale(soft.bias_rate, gap)), rb_scale(soft.gamma, w->point_impulse));
    rb_vec2 impulse = rb_scale(-1.0 / (inverse_mass + soft.gamma), target);
    w->point_impulse = rb_add(w->point_impulse, impulse);
    rb_joint_apply_linear(joint, a, b, impulse);
}

void rb_weld_solve(rb_world *world, rb_joint *joint, double h)
{
    rb_weld_data *w = &joint->as.weld;
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    if (w->linear_hertz == 0.0 && w->angular_hertz == 0.0) {
        /* Rigid: the angle and the pin as one 3x3 block. */
        double c = rb_joint_relative_angle(world, joint, w->reference_angle);
        rb_angular_row row = {
            .sign = 1.0,
            .bias = world->joint_response.bias_rate * c,
            .accumulated = &w->angular_impulse,
            .one_sided = false,
        };
        rb_point_constraint_solve(world, joint, a, b, &w->point_impulse, &row);
        return;
    }
    solve_angle(world, joint, a, b, h);
    if (w->linear_hertz > 0.0) {
        solve_soft_point(joint, a, b, h);
    } else {
        rb_point_constraint_solve(world, joint, a, b, &w->point_impulse, NULL);
    }
}

double rb_weld_angle_error(const rb_world *world, const rb_joint *joint)
{
    if (joint->as.weld.angular_hertz > 0.0) {
        return 0.0;
    }
    return fabs(rb_joint_relative_angle(world, joint, joint->as.weld.reference_angle));
}

bool rb_weld_correct(rb_world *world, rb_joint *joint)
{
    rb_weld_data *w = &joint->as.weld;
    bool rigid_angle = w->angular_hertz == 0.0 && w->axial_mass > 0.0;
    double angle_error = rigid_angle ? rb_joint_relative_angle(world, joint, w->reference_angle) : 0.0;
    double correction = fmin(fmax(angle_error, -RB_MAX_ANGULAR_CORRECTION), RB_MAX_ANGULAR_CORRECTION);
    double gap = 0.0;
    if (w->linear_hertz == 0.0) {
        gap = rb_point_constraint_correct(world, joint, rigid_angle ? &correction : NULL);
    } else if (rigid_angle) {
        rb_body_state *a = rb_joint_state_a(world, joint);
        rb_body_state *b = rb_joint_state_b(world, joint);
        double impulse = -w->axial_mass * correction;
        rb_body_state_turn(a, -(joint->frame.inv_inertia_a * impulse));
        rb_body_state_turn(b, joint->frame.inv_inertia_b * impulse);
    }
    return gap <= world->settings.linear_slop && fabs(angle_error) <= RB_ANGULAR_SLOP;
}
