/* SPDX-License-Identifier: MIT */
/* Moment arms from the path's geometry (mu/moment_arms.h). */
#include <math.h>
#include <stdlib.h>

#include "arguments.h"
#include "joint_sides.h"
#include "mu/moment_arms.h"

#define DEGREES (180.0 / RB_PI)

/* Whether `hinge` is refused (a NULL model, a bad index), and whether it
 * is built: *joint is its joint, null when not built. */
static bool refuse_hinge(const mu_model *model, int hinge, const char *function, rb_joint_id *joint)
{
    if (mu_refuse_null(function, "model", model) ||
        mu_refuse_index(function, "hinge", hinge, mu_model_hinge_count(model))) {
        return true;
    }
    *joint = mu_model_hinge_joint(model, hinge);
    return false;
}

static bool refuse_muscle(const mu_model *model, int muscle, const char *function)
{
    return mu_refuse_index(function, "muscle", muscle, mu_model_muscle_count(model));
}

static rb_vec2 pivot_of(const mu_model *model, rb_joint_id joint)
{
    return rb_joint_world_anchor_b(mu_model_world_to_read(model), joint);
}

bool mu_model_muscle_crosses(const mu_model *model, int muscle, int hinge)
{
    const char *f = "mu_model_muscle_crosses";
    rb_joint_id joint;
    if (refuse_hinge(model, hinge, f, &joint) || refuse_muscle(model, muscle, f) || rb_joint_id_is_null(joint)) {
        return false;
    }
    mu_joint_sides sides;
    if (mu_joint_sides_find(model, joint, false, &sides) != RB_OK) {
        return false;
    }
    bool turns[RB_MAX_CABLE_POINTS];
    const bool result = mu_joint_sides_crosses_path(turns, mu_joint_sides_of_path(model, muscle, &sides, turns));
    mu_joint_sides_free(&sides);
    return result;
}

rb_status mu_model_moment_arms(const mu_model *model, int hinge, double *arms)
{
    const char *f = "mu_model_moment_arms";
    rb_joint_id joint;
    if (refuse_hinge(model, hinge, f, &joint)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const int muscles = mu_model_muscle_count(model);
    if (muscles > 0 && mu_refuse_null(f, "arms", arms)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    if (rb_joint_id_is_null(joint)) {
        for (int m = 0; m < muscles; ++m) {
            arms[m] = NAN;
        }
        return RB_OK;
    }
    mu_joint_sides sides;
    rb_status status = mu_joint_sides_find(model, joint, false, &sides);
    if (status != RB_OK) {
        return status;
    }
    const rb_vec2 pivot = pivot_of(model, joint);
    for (int m = 0; m < muscles; ++m) {
        arms[m] = mu_joint_sides_moment_arm(model, m, &sides, pivot);
    }
    mu_joint_sides_free(&sides);
    return RB_OK;
}

/* The moment arm, the arguments checked in the name of `function`. */
static double checked_arm(const mu_model *model, int muscle, int hinge, const char *function)
{
    rb_joint_id joint;
    if (refuse_hinge(model, hinge, function, &joint) || refuse_muscle(model, muscle, function)) {
        return NAN;
    }
    if (rb_joint_id_is_null(joint)) {
        return NAN;
    }
    mu_joint_sides sides;
    if (mu_joint_sides_find(model, joint, false, &sides) != RB_OK) {
        return NAN;
    }
    const double arm = mu_joint_sides_moment_arm(model, muscle, &sides, pivot_of(model, joint));
    mu_joint_sides_free(&sides);
    return arm;
}

double mu_model_moment_arm(const mu_model *model, int muscle, int hinge)
{
    return checked_arm(model, muscle, hinge, "mu_model_moment_arm");
}

double mu_model_muscle_torque(const mu_model *model, int muscle, int hinge)
{
    const double arm = checked_arm(model, muscle, hinge, "mu_model_muscle_torque");
    return isnan(arm) ? NAN : mu_model_muscle_readout(model, muscle).total_force * arm;
}

double mu_model_hinge_muscle_torque(const mu_model *model, int hinge)
{
    const char *f = "mu_model_hinge_muscle_torque";
    rb_joint_id joint;
    if (refuse_hinge(model, hinge, f, &joint)) {
        return NAN;
    }
    const int muscles = mu_model_muscle_count(model);
    double *arms = malloc(((size_t)muscles + 1) * sizeof *arms);
    if (arms == NULL) {
        rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
        return NAN;
    }
    double torque = NAN;
    if (mu_model_moment_arms(model, hinge, arms) == RB_OK) {
        torque = 0.0;
        for (int m = 0; m < muscles; ++m) {
            torque += mu_model_muscle_readout(model, m).total_force * arms[m];
        }
    }
    free(arms);
    return torque;
}

/* ---- posing ----------------------------------------------------------------------- */

/* Turns every body marked in `turns` by `angle` rad about `pivot`. */
static rb_status turn_bodies(mu_model *model, const bool *turns, rb_vec2 pivot, double angle)
{
    rb_world *world = mu_model_world(model);
    const rb_rot q = rb_rot_from_angle(angle);
    for (int b = 0; b < mu_model_body_count(model); ++b) {
        if (!turns[b]) {
            continue;
        }
        const rb_body_id body = mu_model_body(model, b);
        const rb_transform pose = rb_body_transform(world, body);
        const rb_vec2 position = rb_add(pivot, rb_rotate(q, rb_sub(pose.p, pivot)));
        rb_status status = rb_body_set_transform(world, body, position, rb_rot_angle(pose.q) + angle);
        if (status != RB_OK) {
            return status;
        }
    }
    return RB_OK;
}

rb_status mu_model_pose_hinge(mu_model *model, int hinge, double degrees)
{
    const char *f = "mu_model_pose_hinge";
    rb_joint_id joint;
    if (refuse_hinge(model, hinge, f, &joint) || mu_refuse_non_finite(f, "degrees", degrees)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const mu_model_hinge *h = &mu_model_description(model)->hinges[hinge];
    if (rb_joint_id_is_null(joint)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: hinge \"%s\" is not built in this variant", f, h->name);
    }
    if ((h->has_lower && degrees < h->lower) || (h->has_upper && degrees > h->upper)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %g degrees is outside hinge \"%s\"'s limits %g .. %g", f,
                               degrees, h->name, h->has_lower ? h->lower : -INFINITY,
                               h->has_upper ? h->upper : INFINITY);
    }
    /* B's side turns by +Δ about the pivot; when it holds to the ground,
     * A's side turns by -Δ instead, which changes θ = angle(B) - angle(A)
     * alike. */
    const double change = (degrees - mu_model_hinge_angle(model, hinge)) / DEGREES;
    mu_joint_sides sides;
    rb_status status = mu_joint_sides_find(model, joint, false, &sides);
    if (status == RB_OK && !sides.closes_loop && sides.grounded) {
        mu_joint_sides_free(&sides);
        status = mu_joint_sides_find(model, joint, true, &sides);
        if (status == RB_OK && !sides.grounded && !sides.closes_loop) {
            status =
                turn_bodies(model, sides.turns, rb_joint_world_anchor_a(mu_model_world_to_read(model), joint), -change);
            mu_joint_sides_free(&sides);
            return status;
        }
    } else if (status == RB_OK && !sides.closes_loop) {
        status = turn_bodies(model, sides.turns, pivot_of(model, joint), change);
        mu_joint_sides_free(&sides);
        return status;
    }
    if (status == RB_OK) {
        status = rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                 "%s: hinge \"%s\" cannot turn with the rest of the model held: it closes a loop of "
                                 "joints, or both its sides are fixed to the ground",
                                 f, h->name);
    }
    mu_joint_sides_free(&sides);
    return status;
}
