/* SPDX-License-Identifier: MIT */
/** @file
 * Static optimization: the muscle activations that produce a motion's
 * joint torques, frame by frame.
 *
 * At one frame the hinges' angles θ_j, rates θ'_j and accelerations θ''_j
 * give, by inverse dynamics (inverse_dynamics.h), the net torque τ_j
 * about each hinge. The pose and the rates fix what each muscle i can
 * pull: its path length L_i and lengthening speed L'_i = −Σ_j r_ij·θ'_j
 * (the moment arms r_ij of moment_arms.h are −∂L_i/∂θ_j), hence, with a
 * rigid tendon, its active force per unit activation
 * C_i = Fmax·f_L(l̃)·f_V(ṽ)·cos α and its passive force P_i = Fmax·f_P(l̃)·cos α
 * (mu_muscle_forces_at_speed). A torque muscle k (torque_actuator.h) adds
 * e_k·T_k·s_kj, its exertion e_k times its peak torque, s_kj = +1, −1 or
 * 0 as its body and its reaction body lie on the hinge's two sides.
 * The activations solve
 *
 *   minimize    Σ_i a_i^p + Σ_k e_k^p + Σ_j (ρ_j/R)²
 *   subject to  Σ_i r_ij·(a_i·C_i + P_i) + Σ_k e_k·T_k·s_kj + ρ_j = τ_j   for every hinge j,
 *               0 <= a_i <= 1,  0 <= e_k <= 1,
 *
 * the criterion of Crowninshield and Brand ("A physiologically based
 * criterion of muscle force prediction in locomotion", J Biomech
 * 14:793–801, 1981) for p = 3, the sum of squared activations for p = 2.
 * ρ_j is a reserve actuator: a torque on hinge j that costs (ρ_j/R)², so
 * that every frame has a solution; with R far below what the muscles
 * give per unit activation (the arm's give tens of N·m) it carries a
 * torque only where the muscles cannot, and it is always reported.
 * Where the muscles can, the Lagrange conditions of the problem give
 * ρ_j = λ_j·R²/2 with λ_j the marginal cost of torque at hinge j, so the
 * reserve left is of order R²/(r·C)² of the torque, more where the
 * activations are high: 1e-5 to 6e-4 N·m on the arm for R = 0.1 N·m.
 *
 * The problem is solved with NLopt's SLSQP (sequential least-squares
 * quadratic programming, D. Kraft, "A software package for sequential
 * quadratic programming", DFVLR-FB 88-28, 1988), given the exact
 * gradients of the cost and of the linear constraints, each frame
 * starting from the previous frame's activations (and, when that run does
 * not end at a solution, again from where it stopped, then from zero).
 *
 * The model is posed at each frame (mu_model_pose_hinge for every built
 * hinge), so its bodies are moved; its muscles' states are not changed.
 * The model must be a tree of joints held by the ground (as inverse
 * dynamics needs), have at least one muscle or torque muscle, and its
 * muscles rigid tendons.
 */
#ifndef MU_STATIC_OPTIMIZATION_H
#define MU_STATIC_OPTIMIZATION_H

#include <stdbool.h>

#include "mu/export.h"
#include "mu/joint_loads.h"
#include "mu/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The default exponent p of the cost. */
#define MU_STATIC_OPTIMIZATION_DEFAULT_EXPONENT 2.0
/** The default reserve scale R, N·m. */
#define MU_STATIC_OPTIMIZATION_DEFAULT_RESERVE_SCALE 0.1

typedef struct mu_static_optimization_settings {
    double exponent;      /**< p, finite, >= 1; default 2 */
    double reserve_scale; /**< R, N·m, finite, > 0; default 0.1 */
    /** SLSQP stops when a step changes every variable by less than this,
     * relative (> 0, < 1); default 1e-12. */
    double tolerance;
    int max_evaluations; /**< >= 1: the evaluations SLSQP may take per frame; default 1000 */
} mu_static_optimization_settings;

MU_API mu_static_optimization_settings mu_default_static_optimization_settings(void);

typedef struct mu_static_optimizer mu_static_optimizer;

/** An optimizer for the model, which must outlive it. Refused
 * (RB_ERR_INVALID_ARGUMENT and a message): NULL, a setting out of its
 * range, a model that is not a tree of joints held by the ground
 * (mu_model_check_tree), without a built muscle or torque muscle, or with
 * a muscle with a compliant tendon. */
MU_API rb_status mu_static_optimizer_create(mu_model *model, const mu_static_optimization_settings *settings,
                                            mu_static_optimizer **out);
/** Accepts NULL. */
MU_API void mu_static_optimizer_destroy(mu_static_optimizer *optimizer);

/** The actuators: the built muscles (mu_model_muscle_count, in their
 * order), then the built torque muscles; -1 (and an error) for NULL. */
MU_API int mu_static_optimizer_actuator_count(const mu_static_optimizer *optimizer);

/** One frame's solution, into the caller's arrays: each is NULL when not
 * wanted, else holds the count given. */
typedef struct mu_static_frame {
    double *activations; /**< actuators: a muscle's activation, a torque muscle's exertion, 0 .. 1 */
    double *forces;      /**< actuators: a muscle's tension a·C + P (N), a torque muscle's torque e·T (N·m) */
    double *net_torques; /**< hinges: τ by inverse dynamics, N·m on body B */
    /** hinges: the actuators' torque on body B, N·m (τ minus the reserve,
     * up to the solver's tolerance) */
    double *actuator_torques;
    double *reserves;     /**< hinges: the reserve torque ρ, N·m on body B */
    mu_joint_load *loads; /**< hinges: the joint's reaction under those forces (joint_loads.h); torque 0 */
    /** NLopt's nlopt_result of SLSQP's last run on the frame: > 0 it
     * stopped as asked, < 0 it failed (NLOPT_ROUNDOFF_LIMITED, −4, often
     * comes with a point that is a solution all the same). */
    int solver_result;
    /** The point found is a solution: the constraints hold within
     * 1e-7·(1 + |τ_j|) N·m and the first-order (Karush–Kuhn–Tucker)
     * conditions within 1e-5 (of activation), checked here, not taken
     * from SLSQP's word. */
    bool solved;
} mu_static_frame;

/** Solves one frame: angles in degrees, rates in rad/s and accelerations
 * in rad/s², each indexed by hinge (mu_model_hinge_count entries; a
 * hinge the variant does not build is not read, and its outputs are
 * NaN). A failure of SLSQP is not an error: the frame is filled from
 * its last point with `solved` false and the code in solver_result.
 * Refused (RB_ERR_INVALID_ARGUMENT and a message naming the hinge): NULL,
 * a non-finite input, an angle outside the hinge's limits (where the
 * limit, not an actuator, would carry torque). */
MU_API rb_status mu_static_optimizer_solve(mu_static_optimizer *optimizer, const double *angles_deg,
                                           const double *rates, const double *accelerations, mu_static_frame *frame);

/** The name NLopt gives a result code ("SUCCESS", "ROUNDOFF_LIMITED",
 * ...), for reports; NULL (and an error) for a code NLopt does not have. */
MU_API const char *mu_static_optimizer_result_name(int solver_result);

#ifdef __cplusplus
}
#endif

#endif
