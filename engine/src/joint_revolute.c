/* SPDX-License-Identifier: MIT */
/* Revolute joint: a pin (the point constraint) plus, about the pin, an
 * optional spring, motor and lower and upper limits on the joint angle
 * θ = angle(B) - angle(A) - reference. Every angular part acts on the
 * relative angular velocity ωB - ωA with the axial mass 1/(1/IA + 1/IB).
 *
 * Each substep solves, in order: spring, motor (its accumulated impulse
 * clamped to ±max_torque·h), lower limit, upper limit, then the pin: the
 * parts that may give way first, the rigid pin last (Catto, Box2D 2.x). A
 * limit that is not yet reached is speculative: the joint may approach
 * it at |C|/h, enough to arrive at the limit in this substep and no
 * further, so a fast swing stops at the limit instead of passing it. */

#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"

rb_revolute_joint_def rb_default_revolute_joint_def(void)
{
    return (rb_revolute_joint_def){.internal_value = RB_DEF_COOKIE};
}

rb_status rb_revolute_joint_def_at(rb_revolute_joint_def *def, const rb_world *world, rb_body_id body_a,
                                   rb_body_id body_b, rb_vec2 world_anchor)
{
    const char *f = "rb_revolute_joint_def_at";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "def", def));
    rb_revolute_joint_def filled = rb_default_revolute_joint_def();
    RB_TRY(rb_joint_anchor_at(world, body_a, body_b, world_anchor, f, &filled.local_anchor_a, &filled.local_anchor_b,
                              &filled.reference_angle));
    filled.body_a = body_a;
    filled.body_b = body_b;
    *def = filled;
    return RB_OK;
}

rb_status rb_revolute_joint_create(rb_world *world, const rb_revolute_joint_def *def, rb_joint_id *out)
{
    const char *f = "rb_revolute_joint_create";
    rb_clear_error();
    int a;
    int b;
    RB_TRY(rb_joint_check_common(world, def, RB_JOINT_COMMON(def), out, f, "rb_default_revolute_joint_def", &a, &b));
    RB_TRY(rb_check_bound(f, "reference_angle", def->reference_angle, RB_MAX_ANGLE, "rad"));
    RB_TRY(rb_joint_check_limits(f, "lower_angle", "upper_angle", "rad", RB_MAX_ANGLE, def->enable_lower_limit,
                                 def->lower_angle, def->enable_upper_limit, def->upper_angle));
    RB_TRY(rb_joint_check_motor(f, "max_motor_torque", def->motor_speed, def->max_motor_torque));
    RB_TRY(rb_joint_check_spring(f, def->spring_hertz, def->spring_damping_ratio));
    rb_joint joint = {
        .type = RB_JOINT_REVOLUTE,
        .body_a = a,
        .body_b = b,
        .local_anchor_a = def->local_anchor_a,
        .local_anchor_b = def->local_anchor_b,
        .collide_connected = def->collide_connected,
        .user_data = def->user_data,
        .as.revolute =
            {
                .reference_angle = def->reference_angle,
                .enable_lower = def->enable_lower_limit,
                .enable_upper = def->enable_upper_limit,
                .lower = def->lower_angle,
                .upper = def->upper_angle,
                .enable_motor = def->enable_motor,
                .motor_speed = def->motor_speed,
                .max_motor_torque = def->max_motor_torque,
                .enable_spring = def->enable_spring,
                .spring_hertz = def->spring_hertz,
                .spring_damping_ratio = def->spring_damping_ratio,
            },
    };
    return rb_joint_create(world, &joint, out, f);
}

/* ---- getters and setters ----------------------------------------------------- */

static const rb_revolute_data *find_revolute(const rb_world *world, rb_joint_id id, const char *f, int *index)
{
    rb_clear_error();
    if (rb_joint_find_typed(world, id, RB_JOINT_REVOLUTE, f, index) != RB_OK) {
        return NULL;
    }
    return &world->joints[*index].as.revolute;
}

double rb_revolute_joint_angle(const rb_world *world, rb_joint_id id)
{
    int index;
    const rb_revolute_data *r = find_revolute(world, id, "rb_revolute_joint_angle", &index);
    return r != NULL ? rb_joint_relative_angle(world, &world->joints[index], r->reference_angle) : 0.0;
}

double rb_revolute_joint_speed(const rb_world *world, rb_joint_id id)
{
    int index;
    if (find_revolute(world, id, "rb_revolute_joint_speed", &index) == NULL) {
        return 0.0;
    }
    const rb_joint *joint = &world->joints[index];
    return world->states[joint->body_b].angular_velocity - world->states[joint->body_a].angular_velocity;
}

double rb_revolute_joint_motor_torque(const rb_world *world, rb_joint_id id)
{
    int index;
    const rb_revolute_data *r = find_revolute(world, id, "rb_revolute_joint_motor_torque", &index);
    return r != NULL ? r->motor_impulse / world->last_substep : 0.0;
}

static rb_revolute_data *find_for_change(rb_world *world, rb_joint_id id, const char *f, rb_status *status)
{
    rb_joint *joint = rb_joint_find_for_change(world, id, RB_JOINT_REVOLUTE, f, status);
    return joint != NULL ? &joint->as.revolute : NULL;
}

rb_status rb_revolute_joint_set_motor(rb_world *world, rb_joint_id id, bool enable, double speed, double max_torque)
{
    const char *f = "rb_revolute_joint_set_motor";
    rb_status status;
    rb_revolute_data *r = find_for_change(world, id, f, &status);
    RB_TRY(status);
    RB_TRY(rb_joint_check_motor(f, "max_motor_torque", speed, max_torque));
    r->enable_motor = enable;
    r->motor_speed = speed;
    r->max_motor_torque = max_torque;
    return RB_OK;
}

rb_status rb_revolute_joint_set_limits(rb_world *world, rb_joint_id id, bool enable_lower, double lower,
                                       bool enable_upper, double upper)
{
    const char *f = "rb_revolute_joint_set_limits";
    rb_status status;
    rb_revolute_data *r = find_for_change(world, id, f, &status);
    RB_TRY(status);
    RB_TRY(rb_joint_check_limits(f, "lower_angle", "upper_angle", "rad", RB_MAX_ANGLE, enable_lower, lower,
                                 enable_upper, upper));
    r->enable_lower = enable_lower;
    r->enable_upper = enable_upper;
    r->lower = lower;
    r->upper = upper;
    return RB_OK;
}

rb_status rb_revolute_joint_set_spring(rb_world *world, rb_joint_id id, bool enable, double hertz, double damping_ratio)
{
    const char *f = "rb_revolute_joint_set_spring";
    rb_status status;
    rb_revolute_data *r = find_for_change(world, id, f, &status);
    RB_TRY(status);
    RB_TRY(rb_joint_check_spring(f, hertz, damping_ratio));
    r->enable_spring = enable;
    r->spring_hertz = hertz;
    r->spring_damping_ratio = damping_ratio;
    return RB_OK;
}

/* ---- solver ---------------------------------------------------------------------- */

void rb_revolute_prepare_step(rb_joint *joint)
{
    double inverse_axial = joint->frame.inv_inertia_a + joint->frame.inv_inertia_b;
    rb_revolute_data *r = &joint->as.revolute;
    r->axial_mass = inverse_axial > 0.0 ? 1.0 / inverse_axial : 0.0;
    if (!r->enable_motor) {
        r->motor_impulse = 0.0;
    }
    if (!r->enable_spring) {
        r->spring_impulse = 0.0;
    }
    if (!r->enable_lower) {
        r->lower_impulse = 0.0;
    }
    if (!r->enable_upper) {
        r->upper_impulse = 0.0;
    }
    joint->plain_pin = !r->enable_lower && !r->enable_upper && !r->enable_motor && !r->enable_spring;
}

void rb_revolute_warm_start(rb_world *world, rb_joint *joint, double h)
{
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    const rb_revolute_data *r = &joint->as.revolute;
    rb_point_constraint_prepare(world, joint, h);
    rb_joint_apply_linear(joint, a, b, r->point_impulse);
    rb_joint_apply_angular(joint, a, b, r->motor_impulse + r->spring_impulse + r->lower_impulse - r->upper_impulse);
}

/* A limit's row on the relative angular velocity: sign +1 for the lower
 * limit (the angle may not fall below it), -1 for the upper one. */
static rb_angular_row limit_row(const rb_world *world, rb_revolute_data *r, bool lower, double angle, double h)
{
    double margin = lower ? angle - r->lower : r->upper - angle;
    return (rb_angular_row){
        .sign = lower ? 1.0 : -1.0,
        .bias = rb_one_sided_bias(world, margin, h),
        .accumulated = lower ? &r->lower_impulse : &r->upper_impulse,
        .one_sided = true,
    };
}

/* The nearer enabled limit is solved with the pin as one block; the
 * other one, a swing away, alone (it only releases what it held). */
static void solve_limits(rb_world *world, rb_joint *joint, rb_body_state *a, rb_body_state *b, double angle, double h)
{
    rb_revolute_data *r = &joint->as.revolute;
    bool lower_nearer = r->enable_lower && (!r->enable_upper || angle - r->lower <= r->upper - angle);
    bool upper_nearer = r->enable_upper && !lower_nearer;
    if (r->enable_lower && !lower_nearer) {
        double cdot = b->angular_velocity - a->angular_velocity;
        double total = rb_one_sided_row_total(world, r->axial_mass, cdot, angle - r->lower, h, r->lower_impulse);
        rb_joint_apply_angular(joint, a, b, total - r->lower_impulse);
        r->lower_impulse = total;
    }
    if (r->enable_upper && !upper_nearer) {
        double cdot = a->angular_velocity - b->angular_velocity;
        double total = rb_one_sided_row_total(world, r->axial_mass, cdot, r->upper - angle, h, r->upper_impulse);
        rb_joint_apply_angular(joint, a, b, -(total - r->upper_impulse));
        r->upper_impulse = total;
    }
    if (lower_nearer || upper_nearer) {
        rb_angular_row row = limit_row(world, r, lower_nearer, angle, h);
        rb_point_constraint_solve(world, joint, a, b, &r->point_impulse, &row);
    } else {
        rb_point_constraint_solve(world, joint, a, b, &r->point_impulse, NULL);
    }
}

void rb_revolute_solve(rb_world *world, rb_joint *joint, double h)
{
    /* A plain pin is solved in its row (joint_pin.c) or with its tree, a
     * pin with limits alone in a block with its block (joint_block.h): the
     * velocity passes do not visit them (rb_joints_solve_velocities). */
    rb_revolute_data *r = &joint->as.revolute;
    /* A revolute joint always links two bodies (rb_joint_state_a's NULL is
     * a mouse joint's), and its angle is theirs less the reference, as
     * rb_joint_relative_angle gives it. */
    rb_body_state *a = &world->states[joint->body_a];
    rb_body_state *b = &world->states[joint->body_b];
    if (r->axial_mass > 0.0) {
        double angle = b->angle - a->angle - r->reference_angle;
        if (r->enable_spring && r->spring_hertz > 0.0) {
            rb_softness soft = rb_make_softness(r->spring_hertz, r->spring_damping_ratio, r->axial_mass, h);
            double cdot = b->angular_velocity - a->angular_velocity;
            double impulse =
                -(cdot + soft.bias_rate * angle + soft.gamma * r->spring_impulse) / (1.0 / r->axial_mass + soft.gamma);
            r->spring_impulse += impulse;
            rb_joint_apply_angular(joint, a, b, impulse);
        }
        if (r->enable_motor) {
            double cdot = b->angular_velocity - a->angular_velocity - r->motor_speed;
            double limit = r->max_motor_torque * h;
            double accumulated = fmin(fmax(r->motor_impulse - r->axial_mass * cdot, -limit), limit);
            double impulse = accumulated - r->motor_impulse;
            r->motor_impulse = accumulated;
            rb_joint_apply_angular(joint, a, b, impulse);
        }
        if (!joint->in_tree && !joint->in_block) { /* solved together (joint_tree.h, joint_block.h) */
            solve_limits(world, joint, a, b, angle, h);
        }
        return;
    }
    rb_point_constraint_solve(world, joint, a, b, &r->point_impulse, NULL);
}

/* How far the joint angle lies beyond an enabled limit (rad, >= 0). */
double rb_revolute_angle_error(const rb_world *world, const rb_joint *joint)
{
    const rb_revolute_data *r = &joint->as.revolute;
    double angle = rb_joint_relative_angle(world, joint, r->reference_angle);
    double error = 0.0;
    if (r->enable_lower) {
        error = fmax(error, r->lower - angle);
    }
    if (r->enable_upper) {
        error = fmax(error, angle - r->upper);
    }
    return error;
}

bool rb_revolute_correct(rb_world *world, rb_joint *joint)
{
    if (joint->in_tree) { /* corrected with its tree (joint_tree.h); a plain pin otherwise in its row */
        return true;
    }
    rb_revolute_data *r = &joint->as.revolute;
    double angle = rb_joint_relative_angle(world, joint, r->reference_angle);
    /* Negative below the lower limit, positive above the upper one. */
    double violation = 0.0;
    if (r->axial_mass > 0.0 && r->enable_lower && angle < r->lower) {
        violation = angle - r->lower;
    } else if (r->axial_mass > 0.0 && r->enable_upper && angle > r->upper) {
        violation = angle - r->upper;
    }
    double correction = fmin(fmax(violation, -RB_MAX_ANGULAR_CORRECTION), RB_MAX_ANGULAR_CORRECTION);
    double gap = rb_point_constraint_correct(world, joint, violation != 0.0 ? &correction : NULL);
    return gap <= world->settings.linear_slop && fabs(violation) <= RB_ANGULAR_SLOP;
}
