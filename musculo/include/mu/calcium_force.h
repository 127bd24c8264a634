/* SPDX-License-Identifier: MIT */
/** @file
 * Excitation-contraction coupling in two stages: the neural excitation u
 * drives a calcium stage c (the activator calcium bound to troponin, the
 * "active state"), and c drives the force-generating state a (the
 * fraction of cross-bridges attached and pulling), which is the muscle's
 * activation:
 *
 *   dc/dt = (u - c)/τ_c,   τ_c = calcium_rise_time  while u > c,
 *                                calcium_decay_time otherwise;
 *   da/dt = (c - a)/τ_a,   τ_a = force_rise_time    while c > a,
 *                                force_decay_time   otherwise.
 *
 * The single first-order lag of activation.h (Zajac 1989, "Muscle and
 * tendon: properties, models, scaling, and application to biomechanics
 * and motor control", Crit Rev Biomed Eng 17) lumps both stages together,
 * so an isometric twitch peaks the moment a brief excitation stops. Two
 * stages in series, as in Winters and Stark, "Analysis of fundamental
 * human movement patterns through the use of in-depth antagonistic muscle
 * models" (IEEE Trans Biomed Eng 32, 1985), who put a neural stage before
 * Zajac's, give a twitch that keeps rising after the stimulus while the
 * calcium, released within a few ms, binds and the cross-bridges attach:
 * for an impulse the force is the difference of two exponentials, which
 * peaks at t* = ln(τ_a/τ_c)·τ_a·τ_c/(τ_a - τ_c) (t* = τ when the two are
 * equal) and relaxes more slowly than it rose. The calcium stage's fast
 * rise and slow decay make a train of brief pulses hold c near 1 (each
 * pulse refills it), so the tetanus reaches full activation while a single
 * twitch reaches about a quarter of it.
 *
 * Both stages are linear while their branches hold, so a step has a
 * closed form (mu_calcium_force_step); the branches are chosen at the
 * start of each step.
 */
#ifndef MU_CALCIUM_FORCE_H
#define MU_CALCIUM_FORCE_H

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The four time constants, each in s, finite and > 0. */
typedef struct mu_calcium_force_times {
    double calcium_rise_time;  /**< τ of the calcium stage while the excitation is above it */
    double calcium_decay_time; /**< τ of the calcium stage otherwise (re-uptake) */
    double force_rise_time;    /**< τ of the force-generating state while the calcium is above it */
    double force_decay_time;   /**< τ of the force-generating state otherwise (detachment) */
} mu_calcium_force_times;

/** The two parameter sets (see docs/muscle.md for their sources). Both
 * rise with τ 2 ms, the order of the rise of the calcium transient after
 * an action potential (Baylor and Hollingworth, "Sarcoplasmic reticulum
 * calcium release compared in slow-twitch and fast-twitch fibres of mouse
 * muscle", J Physiol 551, 2003, whose slow-twitch fibres' transients also
 * decay more slowly). The three slower constants are chosen, not
 * measured: slow three times fast, as the contraction times of slow and
 * fast muscles differ (Close, "Dynamic properties of mammalian skeletal
 * muscles", Physiol Rev 52, 1972), and such that an isometric twitch to a
 * 2 ms pulse falls within the published ranges (docs/muscle.md): */
typedef enum mu_fibre_type {
    /** calcium 2 ms / 16 ms, force 20 ms / 25 ms: P1's twitch peaks after
     * 18.7 ms (fast muscle: 10-50 ms), fuses at 80 Hz, tetanus 3.8 ×. */
    MU_FIBRE_FAST,
    /** calcium 2 ms / 50 ms, force 60 ms / 80 ms: 55.5 ms to peak (slow
     * muscle: 40-160 ms), fuses at 30 Hz, tetanus 4.4 ×. */
    MU_FIBRE_SLOW,
} mu_fibre_type;

/** The time constants of a fibre type; NaN times (and an error) for any
 * other value. */
MU_API mu_calcium_force_times mu_calcium_force_times_of(mu_fibre_type type);

typedef struct mu_calcium_force_params {
    double excitation; /**< u, in [0, 1]: held constant over a step */
    mu_calcium_force_times times;
} mu_calcium_force_params;

/** The state: both in [0, 1]. */
typedef struct mu_calcium_force_state {
    double calcium;    /**< c */
    double activation; /**< a, the force-generating state */
} mu_calcium_force_state;

/** The derivative function, in the shape of GSL's gsl_odeiv2_system
 * function: y[0] = c, y[1] = a, params a const mu_calcium_force_params *;
 * t is unused. Returns 0, or RB_ERR_INVALID_ARGUMENT (with a message) for
 * NULL pointers, a non-finite state or invalid params. */
MU_API int mu_calcium_force_derivative(double t, const double y[], double dydt[], void *params);

/** Advances the state by h s (finite, >= 0) under the params' excitation,
 * exactly for the branches chosen at the start of the step (the force
 * stage's by the calcium halfway through it, so that from c = a the
 * calcium's coming rise or fall decides): with τ_c and τ_a so chosen and
 * x = h·(1/τ_a - 1/τ_c),
 *   c(h) = u + (c - u)·e^(-h/τ_c),
 *   a(h) = u + (a - u)·e^(-h/τ_a) + (c - u)·(h/τ_a)·e^(-h/τ_a)·(e^x - 1)/x,
 * the convolution of the calcium's exponential with the force stage's
 * (the last factor is 1 at x = 0, when τ_a = τ_c). c never crosses u, so
 * its branch holds over the step; the force stage's may turn within it
 * (c falling through a), an error of the order of h·|a - c| that the
 * next step corrects. Both stay in [0, 1]. The state is left unchanged
 * on invalid arguments (NULL, a state out of [0, 1], invalid params),
 * which return RB_ERR_INVALID_ARGUMENT with a message. */
MU_API rb_status mu_calcium_force_step(mu_calcium_force_state *state, double h, const mu_calcium_force_params *params);

#ifdef __cplusplus
}
#endif

#endif
