/* SPDX-License-Identifier: MIT */
/* Distance joint: along the axis u from anchor A to anchor B, with
 * current length L, the joint is
 *   - a rigid bar, C = L - length = 0, without the spring;
 *   - a spring-damper towards `length` with it (0 Hz: no pull at all);
 *   - and, with the limit, min_length <= L <= max_length whatever the
 *     spring does: a rope is a 0 Hz spring with a max_length (the "rigid
 *     bar" and "maximum distance" constraints of Box2D).
 * An impulse λ along u changes the length rate by λ/m_u, with
 *   1/m_u = 1/mA + 1/mB + (rA × u)²/IA + (rB × u)²/IB. */
#include <float.h>

#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"

/* Below this length the axis is undefined (m). */
#define MIN_AXIS_LENGTH 1e-9

rb_distance_joint_def rb_default_distance_joint_def(void)
{
    return (rb_distance_joint_def){
        .length = 1.0, .min_length = 0.0, .max_length = DBL_MAX, .internal_value = RB_DEF_COOKIE};
}

rb_status rb_distance_joint_def_between(rb_distance_joint_def *def, const rb_world *world, rb_body_id body_a,
                                        rb_body_id body_b, rb_vec2 world_anchor_a, rb_vec2 world_anchor_b)
{
    const char *f = "rb_distance_joint_def_between";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "def", def));
    RB_TRY(rb_check_point(f, "world_anchor_a", world_anchor_a));
    RB_TRY(rb_check_point(f, "world_anchor_b", world_anchor_b));
    int a;
    int b;
    RB_TRY(rb_joint_check_bodies(world, body_a, body_b, f, &a, &b));
    *def = rb_default_distance_joint_def();
    def->body_a = body_a;
    def->body_b = body_b;
    def->local_anchor_a = rb_inv_transform_point(rb_body_origin_transform(world, a), world_anchor_a);
    def->local_anchor_b = rb_inv_transform_point(rb_body_origin_transform(world, b), world_anchor_b);
    def->length = rb_distance(world_anchor_a, world_anchor_b);
    def->min_length = def->length;
    def->max_length = def->length;
    return RB_OK;
}

rb_status rb_distance_joint_create(rb_world *world, const rb_distance_joint_def *def, rb_joint_id *out)
{
    const char *f = "rb_distance_joint_create";
    rb_clear_error();
    int a;
    int b;
    RB_TRY(rb_joint_check_common(world, def, RB_JOINT_COMMON(def), out, f, "rb_default_distance_joint_def", &a, &b));
    RB_TRY(rb_check_range(f, "length", def->length, MIN_AXIS_LENGTH, RB_MAX_LENGTH));
    RB_TRY(rb_check_hertz(f, "spring_hertz", def->spring_hertz, true));
    RB_TRY(rb_check_range(f, "spring_damping_ratio", def->spring_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO));
    if (def->enable_limit) {
        RB_TRY(rb_check_range(f, "min_length", def->min_length, 0.0, RB_MAX_LENGTH));
        RB_TRY(rb_check_range(f, "max_length", def->max_length, 0.0, DBL_MAX));
        if (def->min_length > def->max_length) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: min_length %g m is above max_length %g m", f,
                                   def->min_length, def->max_length);
        }
    }
    rb_joint joint = {
        .type = RB_JOINT_DISTANCE,
        .body_a = a,
        .body_b = b,
        .local_anchor_a = def->local_anchor_a,
        .local_anchor_b = def->local_anchor_b,
        .collide_connected = def->collide_connected,
        .user_data = def->user_data,
        .as.distance =
            {
                .length = def->length,
                .enable_spring = def->enable_spring,
                .spring_hertz = def->spring_hertz,
                .spring_damping_ratio = def->spring_damping_ratio,
                .enable_limit = def->enable_limit,
                .min_length = def->min_length,
                .max_length = def->max_length,
                .axis = {1.0, 0.0},
            },
    };
    return rb_joint_create(world, &joint, out, f);
}

double rb_distance_joint_current_length(const rb_world *world, rb_joint_id id)
{
    rb_clear_error();
    int index;
    if (rb_joint_find_typed(world, id, RB_JOINT_DISTANCE, "rb_distance_joint_current_length", &index) != RB_OK) {
        return 0.0;
    }
    const rb_joint *joint = &world->joints[index];
    return rb_distance(rb_joint_anchor_a(world, joint), rb_joint_anchor_b(world, joint));
}

/* ---- solver ---------------------------------------------------------------------- */

/* Axis and length between the anchors at the poses now. */
static rb_vec2 separation(const rb_world *world, const rb_joint *joint, rb_vec2 ra, rb_vec2 rb)
{
    const rb_body_state *a = &world->states[joint->body_a];
    const rb_body_state *b = &world->states[joint->body_b];
    return rb_sub(rb_add(b->center, rb), rb_add(a->center, ra));
}

static double axial_mass(const rb_joint_frame *f, rb_vec2 ra, rb_vec2 rb, rb_vec2 axis)
{
    double cra = rb_cross(ra, axis);
    double crb = rb_cross(rb, axis);
    double k = f->inv_mass_a + f->inv_mass_b + f->inv_inertia_a * cra * cra + f->inv_inertia_b * crb * crb;
    return k > 0.0 ? 1.0 / k : 0.0;
}

void rb_distance_prepare_step(rb_joint *joint)
{
    rb_distance_data *d = &joint->as.distance;
    if (!d->enable_limit) {
        d->lower_impulse = 0.0;
        d->upper_impulse = 0.0;
    }
}

void rb_distance_prepare(const rb_world *world, rb_joint *joint)
{
    rb_distance_data *d = &joint->as.distance;
    rb_vec2 delta = separation(world, joint, joint->frame.ra, joint->frame.rb);
    d->current_length = rb_length(delta);
    if (d->current_length > MIN_AXIS_LENGTH) {
        d->axis = rb_scale(1.0 / d->current_length, delta);
    }
    d->axial_mass = axial_mass(&joint->frame, joint->frame.ra, joint->frame.rb, d->axis);
}

void rb_distance_warm_start(rb_world *world, rb_joint *joint)
{
    const rb_distance_data *d = &joint->as.distance;
    rb_vec2 impulse = rb_scale(d->impulse + d->lower_impulse - d->upper_impulse, d->axis);
    rb_joint_apply_linear(joint, rb_joint_state_a(world, joint), rb_joint_state_b(world, joint), impulse);
}

static bool is_rigid(const rb_distance_data *d) { return !d->enable_spring; }

void rb_distance_solve(rb_world *world, rb_joint *joint, double h)
{
    rb_distance_data *d = &joint->as.distance;
    if (d->axial_mass <= 0.0) {
        return;
    }
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);

    if (is_rigid(d) || d->spring_hertz > 0.0) {
        double c = d->current_length - d->length;
        double cdot = rb_dot(d->axis, rb_joint_relative_velocity(joint, a, b));
        double impulse;
        if (is_rigid(d)) {
            impulse = rb_rigid_row_impulse(world, d->axial_mass, cdot, c, d->impulse);
        } else {
            rb_softness soft = rb_make_softness(d->spring_hertz, d->spring_damping_ratio, d->axial_mass, h);
            impulse = -(cdot + soft.bias_rate * c + soft.gamma * d->impulse) / (1.0 / d->axial_mass + soft.gamma);
        }
        d->impulse += impulse;
        rb_joint_apply_linear(joint, a, b, rb_scale(impulse, d->axis));
    }
    if (d->enable_limit) {
        /* Lower: L - min >= 0; upper: max - L >= 0. Speculative while
         * open, as the revolute limits. */
        double margins[2] = {d->current_length - d->min_length, d->max_length - d->current_length};
        double *accumulated[2] = {&d->lower_impulse, &d->upper_impulse};
        for (int side = 0; side < 2; ++side) {
            double sign = side == 0 ? 1.0 : -1.0;
            double cdot = sign * rb_dot(d->axis, rb_joint_relative_velocity(joint, a, b));
            double total = rb_one_sided_row_total(world, d->axial_mass, cdot, margins[side], h, *accumulated[side]);
            double impulse = total - *accumulated[side];
            *accumulated[side] = total;
            rb_joint_apply_linear(joint, a, b, rb_scale(sign * impulse, d->axis));
        }
    }
}

/* How far the length lies outside what the joint allows (m, >= 0). */
static double length_error(const rb_distance_data *d, double length)
{
    double error = is_rigid(d) ? fabs(length - d->length) : 0.0;
    if (d->enable_limit) {
        error = fmax(error, fmax(d->min_length - length, length - d->max_length));
    }
    return error;
}

double rb_distance_error(const rb_world *world, const rb_joint *joint)
{
    return length_error(&joint->as.distance,
                        rb_distance(rb_joint_anchor_a(world, joint), rb_joint_anchor_b(world, joint)));
}

bool rb_distance_correct(rb_world *world, rb_joint *joint)
{
    rb_distance_data *d = &joint->as.distance;
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    const rb_joint_frame *f = &joint->frame;
    rb_vec2 ra = rb_rotate(a->rotation, f->local_a);
    rb_vec2 rb = rb_rotate(b->rotation, f->local_b);
    rb_vec2 delta = separation(world, joint, ra, rb);
    double length = rb_length(delta);
    if (length <= MIN_AXIS_LENGTH) {
        return true;
    }
    rb_vec2 axis = rb_scale(1.0 / length, delta);
    /* The signed correction: the length should become length - c. */
    double c = 0.0;
    if (is_rigid(d)) {
        c = length - d->length;
    }
    if (d->enable_limit) {
        c = length < d->min_length ? length - d->min_length : (length > d->max_length ? length - d->max_length : c);
    }
    double error = length_error(d, length);
    c = fmin(fmax(c, -world->settings.max_linear_correction), world->settings.max_linear_correction);
    double mass = axial_mass(f, ra, rb, axis);
    if (c != 0.0 && mass > 0.0) {
        rb_vec2 impulse = rb_scale(-mass * c, axis);
        a->center = rb_mul_sub(a->center, f->inv_mass_a, impulse);
        b->center = rb_mul_add(b->center, f->inv_mass_b, impulse);
        rb_body_state_turn(a, -(f->inv_inertia_a * rb_cross(ra, impulse)));
        rb_body_state_turn(b, f->inv_inertia_b * rb_cross(rb, impulse));
    }
    return error <= world->settings.linear_slop;
}
