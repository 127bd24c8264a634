/* SPDX-License-Identifier: MIT */
/** @file
 * Moment arms: how much a muscle's pull turns a hinge.
 *
 * A hinge's angle θ is angle(bone B) - angle(bone A) (model.h). Turn the
 * bodies on B's side of the hinge (joint_sides: everything joined to B
 * by other joints, up to the ground) by dθ about the hinge's pivot, the
 * rest held still; a muscle's path length L changes by dL. Its moment
 * arm about the hinge is
 *
 *   r = -dL/dθ   (m)
 *
 * (the tendon-excursion definition: An, Ueba, Chao, Cooney and
 * Linscheid, "Tendon excursion and moment arm of index finger muscles",
 * 1983): positive when the muscle, by
 * shortening, turns B counter-clockwise relative to A, i.e. raises θ (the
 * arm's elbow flexors). A muscle that pulls with tension F then applies
 * the torque τ = F·r about the hinge to B's side, by the principle of
 * virtual work (F·dL + τ·dθ = 0).
 *
 * It is computed analytically, not by a difference: the path is straight
 * segments between its points (via points included), and a point X on
 * B's side moves by dX = dθ·k×(X - c) (c the pivot, k the unit normal to
 * the plane), so a segment from P to Q with unit direction u = (Q-P)/|Q-P|
 * changes length by u·(dQ - dP):
 *
 *   dL/dθ = Σ over segments  u·(s_Q·k×(Q - c) - s_P·k×(P - c)),
 *
 * s_X = 1 for a point on B's side, 0 otherwise. Segments with both ends on
 * one side contribute nothing (a rigid segment keeps its length), so r is
 * the sum, over the segments that cross the hinge, of the perpendicular
 * distance from the pivot to the segment's line, signed. Exact up to
 * rounding; tests/test_moment_arms.c checks it against a central
 * difference of the path length (error O(Δθ²)) and against closed forms.
 *
 * A muscle crosses a hinge when its path has points on both sides; the
 * test is of the model's topology (which bodies the points are on), not
 * of the pose, so a crossing muscle can have r = 0 at some pose. The
 * pivot is the hinge's anchor on body B.
 *
 * Indices: `muscle` is a built muscle's (0 .. mu_model_muscle_count - 1),
 * `hinge` a hinge's (0 .. mu_model_hinge_count - 1). A bad index or a
 * NULL model is refused as model.h says (NaN, false, or the status); a
 * hinge the variant does not build gives NaN without an error.
 */
#ifndef MU_MOMENT_ARMS_H
#define MU_MOMENT_ARMS_H

#include <stdbool.h>

#include "mu/export.h"
#include "mu/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Whether the muscle's path has points on both sides of the hinge. */
MU_API bool mu_model_muscle_crosses(const mu_model *model, int muscle, int hinge);

/** r = -dL/dθ at the present pose, m; 0 for a muscle that does not cross. */
MU_API double mu_model_moment_arm(const mu_model *model, int muscle, int hinge);

/** Every built muscle's moment arm about the hinge at once (one search of
 * the hinge's sides): arms[m] in m for m in 0 .. mu_model_muscle_count - 1,
 * arms must hold that many (NULL only when there are none). */
MU_API rb_status mu_model_moment_arms(const mu_model *model, int hinge, double *arms);

/** The torque the muscle applies about the hinge to B's side, N·m: its
 * present tension (mu_muscle_readout.total_force) times its moment arm. */
MU_API double mu_model_muscle_torque(const mu_model *model, int muscle, int hinge);

/** Σ over the built muscles of their torques about the hinge, N·m. */
MU_API double mu_model_hinge_muscle_torque(const mu_model *model, int hinge);

/** Puts the hinge at `degrees` (within its limits, when it has them) by
 * turning one side of it about its pivot, the rest of the model held
 * still: B's side, or A's when B's side is fixed to the ground. The
 * turned bodies keep their velocities; the muscles' readouts are not
 * refreshed (read forces with mu_muscle_isometric_forces). For analyses
 * that pose the model without simulating it (`sinew moment-arms`).
 * Refused, with a message naming the hinge, when it is not built, when
 * both its sides are fixed to the ground or it closes a loop of joints,
 * and for an angle outside its limits. */
MU_API rb_status mu_model_pose_hinge(mu_model *model, int hinge, double degrees);

#ifdef __cplusplus
}
#endif

#endif
