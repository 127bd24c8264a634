/* SPDX-License-Identifier: MIT */
/** @file
 * Inverse dynamics: the net torque about each hinge that makes the model's
 * bones move as prescribed.
 *
 * Given every hinge's angle θ (degrees, as mu_model_hinge_angle), its rate
 * θ' (rad/s) and its acceleration θ'' (rad/s²), the bones' poses,
 * velocities and accelerations follow from the tree of joints, outwards
 * from the ground (the forward pass of the recursive Newton–Euler method:
 * Featherstone, "Rigid Body Dynamics Algorithms", 2008, chapter 5, here
 * in the plane). For each hinge j, cut the model there: B's side is a set
 * S of rigid bodies whose external loads are gravity, the bones' damping,
 * the hinge's reaction force (through the pivot p, so without a moment
 * about it) and the net torque τ that everything crossing the hinge
 * (muscles, limits, springs) applies to B. The moment equation about p,
 * valid for a moving point as well, gives
 *
 *   τ = Σ over bodies k in S of  I_k·α_k + (c_k − p) × m_k·(a_k − g_k + d_k·v_k) + D_k·I_k·ω_k
 *
 * with m_k, I_k (about the centre c_k) the body's mass and inertia
 * (rb_body_mass_data: glued bones are one merged body, the weight
 * included), a_k, v_k its centre's acceleration and velocity, α_k, ω_k
 * its angular ones, g_k the world's gravity times its gravity scale, and
 * d_k, D_k its linear and angular damping (1/s): the engine damps a
 * velocity once per substep h, after the solve, as v' = (v + h·a)/(1 + h·c),
 * that is (v' − v)/h = a − c·v', a drag of c times the velocity reached.
 * This is the backward pass of Newton–Euler summed in one step.
 * When the side that leaves the ground is A's, the same sum over A's side
 * is −τ.
 *
 * Conventions are those of joint_loads.h: θ = angle(B) − angle(A), the
 * torque on B counter-clockwise positive, body A receiving −τ. The
 * model's present pose only fixes the shape of each joint (where its
 * anchors sit on its bodies); the state is not changed.
 *
 * Refused (RB_ERR_INVALID_ARGUMENT with a message naming the joint or the
 * body): a joint that closes a loop (the leg's chain between its two
 * nails: a closed chain's torques are not determined by its motion
 * alone), a moving body not joined to the ground (a floating base such as
 * the worm), a non-finite input. A hinge between two static bodies moves
 * nothing and gets a NaN torque.
 */
#ifndef MU_INVERSE_DYNAMICS_H
#define MU_INVERSE_DYNAMICS_H

#include "mu/export.h"
#include "mu/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Whether inverse dynamics can be done on the model (a tree of joints
 * held by the ground); RB_OK or the refusal above, with its message. */
MU_API rb_status mu_model_check_tree(const mu_model *model);

/** The net torques: each array has mu_model_hinge_count entries, indexed
 * by hinge; angles in degrees, rates in rad/s, accelerations in rad/s²,
 * torques in N·m on body B. A hinge the variant does not build is
 * ignored (its inputs are not read) and gets a NaN torque. */
MU_API rb_status mu_model_inverse_dynamics(const mu_model *model, const double *angles_deg, const double *rates,
                                           const double *accelerations, double *torques);

#ifdef __cplusplus
}
#endif

#endif
