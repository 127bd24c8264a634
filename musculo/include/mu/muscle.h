/* SPDX-License-Identifier: MIT */
/** @file
 * The Hill muscle of Castanyer, "Implementació d'un model computacional de
 * sistemes musculoesquelètics" (2023-24), pulling along a path of
 * body points through an engine cable.
 *
 * Sign convention: velocities are lengthening velocities, negative while
 * the muscle shortens; ṽ = v/Vmax.
 *
 * That original muscle is the default: activation set directly, a rigid
 * tendon (its length fixed at creation, so the belly's velocity is the
 * path's) and fibres along the line of action. Three options, each per
 * muscle, go beyond it:
 * - activation dynamics: the controls set the excitation, and the
 *   activation follows it with a first-order delay (activation.h) or
 *   through a calcium stage and a force-generating stage
 *   (calcium_force.h);
 * - pennation (pennation.h): fibres at an angle that rises as they
 *   shorten, their force projected on the tendon;
 * - a compliant tendon (tendon.h): a series spring, the fibre length a
 *   state balancing fibre and tendon forces (the damped equilibrium of
 *   Millard et al. 2013, solved each substep by backward Euler).
 * rest_length is the fibres' optimal length throughout.
 *
 * Each substep: mu_muscle_prepare, before the substep, sets the cable's
 * tension law from the muscle's state; mu_muscle_measure, after it, reads
 * the force the implicit solve produced, advances the fibre and fills the
 * readout. h is the substep's duration, and the law holds for one engine
 * substep of h, which a compliant tendon needs: its law holds the
 * tendon's stiffness over h. Called from the engine's substep callback
 * (the models), both happen at the start of each substep
 * (mu_muscle_advance), and the last substep is measured after the step.
 *
 * A NULL muscle or world, or a non-finite number, is refused with
 * RB_ERR_INVALID_ARGUMENT and a message (rb_last_error()) naming the
 * function and the argument; a getter then returns NaN (a readout of NaN
 * fields, the null cable id) and records the same error.
 */
#ifndef MU_MUSCLE_H
#define MU_MUSCLE_H

#include <stdbool.h>

#include "mu/activation.h"
#include "mu/calcium_force.h"
#include "mu/curves.h"
#include "mu/export.h"
#include "mu/pennation.h"
#include "mu/tendon.h"
#include "rb/rb.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_muscle mu_muscle;

typedef struct mu_muscle_def {
    int point_count;                           /**< 2 .. RB_MAX_CABLE_POINTS: origin, via points, insertion */
    rb_body_id bodies[RB_MAX_CABLE_POINTS];    /**< the body of each path point */
    rb_vec2 local_points[RB_MAX_CABLE_POINTS]; /**< m, each point in its body's frame */
    double rest_length;                        /**< m, > 0: belly length of maximal active force */
    /** Maximal isometric force: max_force if > 0, else the belly's circular
     * cross-section π·rest_width²/4 times specific_tension. */
    double max_force;        /**< N, >= 0 */
    double rest_width;       /**< m, > 0 when max_force is 0 */
    double specific_tension; /**< N/m², > 0 when max_force is 0; the original code uses 1.5e6 */
    double max_velocity;     /**< m/s, > 0: shortening speed at which the force vanishes (the original: 0.25) */
    /** The tendon: tendon_length if >= 0, else path length minus
     * rest_length·start_normalized_length, never below 0. */
    double tendon_length;           /**< m, or -1 */
    double start_normalized_length; /**< > 0, default 1 */
    double tension_gain;            /**< per substep, > 0: the tension controller's gain (the original: 0.08) */
    const mu_curves *curves;        /**< not owned; must outlive the muscle */
    /** Pennation angle at the optimal fibre length: rad, in
     * [0, MU_MAX_PENNATION_ANGLE); default 0 (fibres along the path). With
     * a rigid tendon the tendon_length above is then path length minus the
     * belly's extent √(l² - w²) at the start fibre length l. */
    double pennation_angle;
    /** Activation dynamics: off by default (the activation is what the
     * controls set). On, the controls set the excitation. */
    bool activation_dynamics;
    double activation_time;   /**< τ_act, s, > 0; default 0.010 */
    double deactivation_time; /**< τ_deact, s, > 0; default 0.040 */
    /** Which dynamics; the two time constants above belong to the first
     * order's, calcium_force to the two stages'. */
    mu_activation_model activation_model;
    mu_calcium_force_times calcium_force; /**< each s, > 0; default the fast set */
    /** A compliant tendon: off by default (rigid). On, tendon_length (or the
     * length derived from start_normalized_length) is the tendon's slack
     * length, which must be > 0, and the fibre starts in static
     * equilibrium at activation 0. */
    bool compliant_tendon;
    double tendon_strain_at_max_force; /**< ε0, in (0, 1]; default 0.049 */
    double fibre_damping;              /**< β, > 0: damping per unit ṽ over Fmax; default 0.1 (Millard 2013) */
} mu_muscle_def;

MU_API mu_muscle_def mu_default_muscle_def(void);

/** Everything the muscle reports after a substep. Without pennation the
 * fibre is the belly; with a rigid tendon the tendon's length is fixed. */
typedef struct mu_muscle_readout {
    double activation;             /**< 0 .. 1 */
    double target_tension;         /**< N; negative when under activation control */
    double length;                 /**< m, belly length along the path (path minus tendon) */
    double normalized_length;      /**< fibre_length / rest_length: the argument of f_L and f_P */
    double velocity;               /**< m/s, the fibre's lengthening velocity */
    double normalized_velocity;    /**< velocity / max_velocity: the argument of f_V */
    double contraction;            /**< m, rest_length - fibre_length */
    double normalized_contraction; /**< contraction / rest_length */
    double active_force;           /**< N, >= 0: the contractile element's force, projected on the tendon */
    double passive_force;          /**< N, >= 0: the parallel elastic element's force, projected on the tendon */
    double total_force;            /**< N, the tension the path carried */
    double excitation;             /**< 0 .. 1: the neural drive; the activation itself without activation dynamics */
    double fibre_length;           /**< m */
    double tendon_length;          /**< m */
    double pennation_angle;        /**< rad, 0 .. MU_MAX_PENNATION_ANGLE */
    /** 0 .. 1: the calcium stage of the two-stage dynamics; the activation
     * itself under the others, whose one state lumps both stages. */
    double calcium;
} mu_muscle_readout;

MU_API rb_status mu_muscle_create(rb_world *world, const mu_muscle_def *def, mu_muscle **out);
/** Removes the muscle's cable from the world (if the world still holds
 * it) and frees the muscle. Accepts NULL. */
MU_API void mu_muscle_destroy(mu_muscle *muscle, rb_world *world);

/** Sets the activation (clamped to [0, 1]) and switches tension control
 * off; with activation dynamics it sets the excitation, which the
 * activation follows from the next substep. */
MU_API rb_status mu_muscle_set_activation(mu_muscle *muscle, double activation);
/** Switches tension control on: each substep the activation (with
 * activation dynamics, the excitation) moves by gain·(target - active
 * force)/max force, clamped to [0, 1]; a target of 0 drives it to 0. */
MU_API rb_status mu_muscle_set_target_tension(mu_muscle *muscle, double target);

/** With a compliant tendon, puts the fibre at its static equilibrium (fibre
 * force·cos α = tendon force, at rest) for the present path and
 * activation, and refreshes the readout (its total force is then the
 * tendon's). With a rigid tendon the fibre has no state of its own: only
 * the readout is refreshed, at zero velocity. */
MU_API rb_status mu_muscle_solve_equilibrium(mu_muscle *muscle, const rb_world *world);

/** The forces along the path (N, >= 0) the muscle would carry held still
 * at the path's present length with `activation` (0 .. 1), its state
 * left as it is: the active part Fmax·a·f_L·f_V(0)·cos α and the passive
 * part Fmax·f_P·cos α, with a compliant tendon at the fibre length that
 * balances the tendon (as mu_muscle_solve_equilibrium). For analyses that
 * move the bones without simulating (moment_arms.h). */
MU_API rb_status mu_muscle_isometric_forces(const mu_muscle *muscle, const rb_world *world, double activation,
                                            double *active, double *passive);

/** The forces along the path (N, >= 0) of a muscle with a rigid tendon
 * whose path has its present length and lengthens at `path_speed` (m/s,
 * finite, negative while it shortens), its state left as it is: per unit
 * activation the active part Fmax·f_L(l̃)·f_V(ṽ)·cos α (the active force
 * at activation a is a times it), and the passive part Fmax·f_P(l̃)·cos α,
 * with ṽ = L'·cos α/Vmax the fibre's normalized speed. For static
 * optimization (static_optimization.h), where the pose and its rates fix
 * the force a muscle can give. A compliant tendon's fibre length is a
 * state of its own, not fixed by the pose: refused with
 * RB_ERR_INVALID_ARGUMENT and a message. */
MU_API rb_status mu_muscle_forces_at_speed(const mu_muscle *muscle, const rb_world *world, double path_speed,
                                           double *active_per_activation, double *passive);

MU_API double mu_muscle_max_force(const mu_muscle *muscle); /**< N */
/** m: the rigid tendon's length, or the compliant tendon's slack length. */
MU_API double mu_muscle_tendon_length(const mu_muscle *muscle);
MU_API rb_cable_id mu_muscle_cable(const mu_muscle *muscle);

MU_API rb_status mu_muscle_prepare(mu_muscle *muscle, rb_world *world, double h);
MU_API rb_status mu_muscle_measure(mu_muscle *muscle, const rb_world *world);
/** mu_muscle_measure then mu_muscle_prepare, reading the path once: for
 * the start of every substep but the first, when the state the last
 * substep left is the one the next starts from. */
MU_API rb_status mu_muscle_advance(mu_muscle *muscle, rb_world *world, double h);
MU_API mu_muscle_readout mu_muscle_read(const mu_muscle *muscle);
/** m/s: the path's lengthening speed when the muscle was last measured
 * (mu_muscle_measure or mu_muscle_advance), < 0 while shortening; with
 * the readout's total force it gives the power the muscle then put into
 * the bodies, −T·L', without reading the path again. 0 before the first
 * measure. */
MU_API double mu_muscle_path_speed(const mu_muscle *muscle);
/** N: the tension the path carried in the substep last measured, the
 * readout's total_force, without making the whole readout. */
MU_API double mu_muscle_tension(const mu_muscle *muscle);

#ifdef __cplusplus
}
#endif

#endif
