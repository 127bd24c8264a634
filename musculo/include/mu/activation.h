/* SPDX-License-Identifier: MIT */
/** @file
 * Activation dynamics: the first-order delay between a muscle's neural
 * excitation u and its activation a (the calcium-driven state of the
 * contractile element), as in Millard et al. 2013 (J Biomech Eng 135,
 * "Flexing computational muscle", eq. 1-2) and OpenSim's
 * FirstOrderMuscleActivationDynamics after Thelen 2003:
 *
 *   da/dt = (u - a)/τ(a, u),
 *   τ = τ_act·(0.5 + 1.5·a)    while u > a (activating),
 *   τ = τ_deact/(0.5 + 1.5·a)  otherwise (deactivating).
 *
 * Activating is fast from rest (τ = τ_act/2 at a = 0) and slows as a
 * nears 1 (2·τ_act); deactivating is slow from full activation
 * (τ_deact/2 at a = 1 ... 2·τ_deact at a = 0). Defaults τ_act = 10 ms,
 * τ_deact = 40 ms (Millard et al. 2013, Thelen 2003; Zajac 1989,
 * Thelen 2003 and Millard et al. 2013 use 10-15 ms and 40-60 ms).
 */
#ifndef MU_ACTIVATION_H
#define MU_ACTIVATION_H

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The activation dynamics a muscle follows when they are on. */
typedef enum mu_activation_model {
    MU_ACTIVATION_FIRST_ORDER,   /**< activation.h: one first-order lag (the default) */
    MU_ACTIVATION_CALCIUM_FORCE, /**< calcium_force.h: a calcium stage, then the force-generating state */
} mu_activation_model;

typedef struct mu_activation_params {
    double excitation;        /**< u, in [0, 1]: held constant over a step */
    double activation_time;   /**< τ_act, s, > 0; default 0.010 */
    double deactivation_time; /**< τ_deact, s, > 0; default 0.040 */
} mu_activation_params;

/** Excitation 0 and the default time constants. */
MU_API mu_activation_params mu_default_activation_params(void);

/** τ(a, u) in s for activation a in [0, 1] (a finite value is clamped to
 * it) under the params' excitation. NaN (and an error) for a non-finite
 * activation, NULL or invalid params. */
MU_API double mu_activation_time_constant(double activation, const mu_activation_params *params);

/** The derivative function, in the shape of GSL's gsl_odeiv2_system
 * function so that GSL's integrators can run it directly: state y[0] = a,
 * dydt[0] = (u - a)/τ(a, u); params is a const mu_activation_params *.
 * t is unused (the system is autonomous while u is held). Returns 0
 * (GSL_SUCCESS), or a non-zero status (RB_ERR_INVALID_ARGUMENT, which GSL
 * reports as a failed step) for NULL pointers, a non-finite y[0] or invalid
 * params. */
MU_API int mu_activation_derivative(double t, const double y[], double dydt[], void *params);

/** One step of h s from activation a (in [0, 1]) under the params'
 * excitation, by the exponential midpoint rule: τ is evaluated at the
 * midpoint state a* = u + (a - u)·exp(-h/(2·τ(a, u))), then
 *   a_next = u + (a - u)·exp(-h/τ(a*, u)).
 * Each stage is the exact solution of the linear equation with τ frozen,
 * so the step is stable for any h and never overshoots: a_next lies
 * between a and u (and in [0, 1]). Second order in h (the midpoint τ).
 * NaN (and an error) for invalid arguments. */
MU_API double mu_activation_step(double activation, double h, const mu_activation_params *params);

#ifdef __cplusplus
}
#endif

#endif
