/* SPDX-License-Identifier: MIT */
/* What each joint carries (mu/joint_loads.h). */
#include <math.h>

#include "arguments.h"
#include "joint_sides.h"
#include "mu/joint_loads.h"

#define DEGREES (180.0 / RB_PI)

static mu_joint_load nan_load(void) { return (mu_joint_load){{NAN, NAN}, NAN, NAN, NAN, NAN}; }

static int part_of(const mu_model_desc *desc, mu_model_ref ref)
{
    return ref.kind == MU_MODEL_NAIL ? ref.index : desc->nail_count + ref.index;
}

/* The proximal part's axis in the world (mu/joint_loads.h): its box's
 * long side, pointed towards `anchor` (in the part's own frame). */
static rb_vec2 bone_axis(const mu_model *model, int part, rb_vec2 anchor)
{
    const mu_model_desc *desc = mu_model_description(model);
    rb_vec2 local = rb_v2(1.0, 0.0);
    if (part >= desc->nail_count) {
        const rb_vec2 size = desc->bones[part - desc->nail_count].size;
        local = size.x >= size.y ? rb_v2(1.0, 0.0) : rb_v2(0.0, 1.0);
        local = rb_dot(local, anchor) < 0.0 ? rb_neg(local) : local;
    }
    return rb_rotate(rb_rot_from_angle(mu_model_part_angle(model, part) / DEGREES), local);
}

/* The Σ tension × moment arm of every muscle about `joint` on B's side. */
static double muscle_torque(const mu_model *model, rb_joint_id joint)
{
    mu_joint_sides sides;
    if (mu_joint_sides_find(model, joint, false, &sides) != RB_OK) {
        return NAN;
    }
    const rb_vec2 pivot = rb_joint_world_anchor_b(mu_model_world_to_read(model), joint);
    double torque = 0.0;
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        torque += mu_model_muscle_readout(model, m).total_force * mu_joint_sides_moment_arm(model, m, &sides, pivot);
    }
    mu_joint_sides_free(&sides);
    return torque;
}

static mu_joint_load load_of(const mu_model *model, rb_joint_id joint, rb_vec2 axis)
{
    const rb_world *world = mu_model_world_to_read(model);
    const rb_vec2 force = rb_joint_reaction_force(world, joint);
    return (mu_joint_load){
        .force = force,
        .along = rb_dot(force, axis),
        .across = rb_cross(axis, force), /* force · (axis turned +90°) */
        .torque = rb_joint_reaction_torque(world, joint),
        .muscle_torque = muscle_torque(model, joint),
    };
}

/* The hinge's proximal bone axis, the arguments checked in the name of `f`. */
static rb_vec2 checked_axis(const mu_model *model, int hinge, const char *f)
{
    if (mu_refuse_null(f, "model", model) || mu_refuse_index(f, "hinge", hinge, mu_model_hinge_count(model)) ||
        rb_joint_id_is_null(mu_model_hinge_joint(model, hinge))) {
        return rb_v2(NAN, NAN);
    }
    const mu_model_desc *desc = mu_model_description(model);
    const mu_model_hinge *h = &desc->hinges[hinge];
    return bone_axis(model, part_of(desc, h->body_a), h->anchor_a);
}

rb_vec2 mu_model_hinge_bone_axis(const mu_model *model, int hinge)
{
    return checked_axis(model, hinge, "mu_model_hinge_bone_axis");
}

mu_joint_load mu_model_hinge_load(const mu_model *model, int hinge)
{
    const rb_vec2 axis = checked_axis(model, hinge, "mu_model_hinge_load");
    return isnan(axis.x) ? nan_load() : load_of(model, mu_model_hinge_joint(model, hinge), axis);
}

mu_joint_load mu_model_glue_load(const mu_model *model, int glue)
{
    const char *f = "mu_model_glue_load";
    if (mu_refuse_null(f, "model", model) || mu_refuse_index(f, "glue", glue, mu_model_glue_count(model))) {
        return nan_load();
    }
    const rb_joint_id joint = mu_model_glue_joint(model, glue);
    if (rb_joint_id_is_null(joint)) {
        return nan_load();
    }
    const mu_model_desc *desc = mu_model_description(model);
    const int a = part_of(desc, desc->glues[glue].body_a);
    const int b = part_of(desc, desc->glues[glue].body_b);
    /* The weld's anchor, part B's centre, in part A's frame. */
    const rb_transform pose_a = {mu_model_part_centre(model, a),
                                 rb_rot_from_angle(mu_model_part_angle(model, a) / DEGREES)};
    const rb_vec2 anchor = rb_inv_transform_point(pose_a, mu_model_part_centre(model, b));
    return load_of(model, joint, bone_axis(model, a, anchor));
}
