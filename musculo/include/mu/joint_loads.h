/* SPDX-License-Identifier: MIT */
/** @file
 * What each joint carries: the reaction the joint applies to its distal
 * body, and the net torque the muscles apply about it.
 *
 * Frames and signs. A joint's body A is the proximal one and body B the
 * distal one, as the model file names them (body_a, body_b).
 * - force: the force (N) the joint applied to body B over the last
 *   substep, in the world frame (x right, y up); body A received the
 *   opposite. The engine reports it as the last substep's impulse divided
 *   by the substep h (rb_joint_reaction_force), so at rest it is the
 *   static reaction exactly, and in motion the joint's share of B's
 *   momentum change over that substep.
 * - along, across: the same force in the frame of the proximal bone.
 *   The bone's axis is its box's long side (x in the bone's own frame
 *   when size.x >= size.y, else y), pointed from the bone's centre
 *   towards the joint (the sign that gives the joint's anchor on the bone
 *   a coordinate >= 0 along it); across is the axis turned 90°
 *   counter-clockwise. along > 0: the joint pushes the distal body away
 *   from the proximal bone (compression of the joint); along < 0: it
 *   holds the distal body against being pulled off. A nail (no bone) has
 *   the world's axes.
 * - torque: the torque (N·m, counter-clockwise) the joint applied to
 *   body B: a hinge's limits (a free hinge carries none), a weld's
 *   bending moment.
 * - muscle_torque: Σ over the muscles of tension × moment arm about the
 *   joint (moment_arms.h), the torque (N·m, counter-clockwise, positive
 *   raising the hinge's angle) the muscles apply to B's side about the
 *   pivot, equal to the moment of their cable forces on that side's
 *   points about the pivot.
 *
 * For every hinge (mu_model_hinge_load) and every glue kept as a weld
 * joint (weld_glues; mu_model_glue_load, anchored at the glue's part B
 * centre). A hinge or glue that is not built as a joint (left out by the
 * variant, or merged) gives every field NaN, without an error; a bad
 * index or a NULL model gives NaN fields and the error (model.h).
 */
#ifndef MU_JOINT_LOADS_H
#define MU_JOINT_LOADS_H

#include "mu/export.h"
#include "mu/model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_joint_load {
    rb_vec2 force;        /**< N, world frame, on body B */
    double along;         /**< N, along the proximal bone, > 0 compressing the joint */
    double across;        /**< N, across the proximal bone (its axis turned +90°) */
    double torque;        /**< N·m, counter-clockwise, on body B */
    double muscle_torque; /**< N·m, counter-clockwise, the muscles' about the pivot on B's side */
} mu_joint_load;

MU_API mu_joint_load mu_model_hinge_load(const mu_model *model, int hinge);
MU_API mu_joint_load mu_model_glue_load(const mu_model *model, int glue);

/** The proximal bone's axis of the hinge (as above), a world unit vector;
 * (NaN, NaN) when the hinge is not built or the index is bad. */
MU_API rb_vec2 mu_model_hinge_bone_axis(const mu_model *model, int hinge);

#ifdef __cplusplus
}
#endif

#endif
