/* SPDX-License-Identifier: MIT */
/** @file
 * The Hill muscle's curves, as pure functions of normalized inputs.
 *
 * Normalized length l̃ = belly length / rest (optimal) length. Normalized
 * velocity ṽ = lengthening velocity / Vmax: negative while the muscle
 * shortens (one sign convention for the whole project).
 *   f_L(l̃)  active force-length, in [0, 1] (never negative: a muscle never
 *           pushes); a table's f_L is 0 outside the table
 *   f_P(l̃)  passive force-length, >= 0 and finite for any finite l̃
 *   f_V(ṽ)  force-velocity: 0 for ṽ <= -1 in every set (a muscle
 *           shortening at Vmax or faster exerts no active force), 1 at
 *           ṽ = 0, rising to an eccentric plateau while lengthening, never
 *           negative
 * Errors use the engine's channel: an rb_status, and rb_last_error().
 */
#ifndef MU_CURVES_H
#define MU_CURVES_H

#include <stddef.h>

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_curves mu_curves;

typedef enum mu_interpolation {
    MU_INTERPOLATION_LINEAR,  /**< as the original: straight lines between the knots */
    MU_INTERPOLATION_STEFFEN, /**< monotone cubic (Steffen 1990): smooth, no overshoot */
} mu_interpolation;

/** The analytic curves of the MATLAB worksheet "1D Muscle Model based on
 * the Hill 2-Element Model" (anonymous) and the eccentric branch joined to
 * them. */
typedef struct mu_analytic_curves {
    double width;             /**< SK of the Gaussian f_L = exp(-((l̃ - 1)/SK)²), > 0, default 0.25 */
    double curvature;         /**< a/F0 of the Hill hyperbola for shortening, > 0, default 0.05 */
    double eccentric_plateau; /**< f_V's limit for fast lengthening, > 1, default 1.5 */
    /** c of f_P = c·(exp(d·(l̃ - 1)) - 1) where positive, > 0, default 0.01;
     * past l̃ = 1 + min(1, 100/d) f_P goes on as the straight line with
     * the exponential's slope there, so that it stays finite. */
    double passive_scale;
    double passive_rate; /**< d, > 0, default 10 */
} mu_analytic_curves;

MU_API mu_analytic_curves mu_default_analytic_curves(void);

/** Tables of the curves (such as Ross et al. 2018's, digitised), read from the CSV file
 * `path` (columns curve,x,y; curves active_force_length,
 * passive_force_length, force_velocity; x strictly increasing within a
 * curve), interpolated as asked. Outside its table f_P and f_V keep
 * their end values and f_L is 0 (its end values are the digitisation's
 * floor); f_V is 0 for ṽ <= -1 whatever the table says there.
 * A bad file fails with a message naming the file, the line and what was
 * expected. */
MU_API rb_status mu_curves_create_tabulated(const char *path, mu_interpolation interpolation, mu_curves **out);

/** The tables of Castanyer's model (Ross et al. 2018, "A modelling
 * approach for exploring muscle dynamics during cyclic contractions",
 * digitised; models/data/hill-curves.csv), compiled into the
 * library; when the environment variable SINEW_DATA_DIR names a folder,
 * read from hill-curves.csv in that folder instead. */
MU_API rb_status mu_curves_create_seed_tables(mu_interpolation interpolation, mu_curves **out);

MU_API rb_status mu_curves_create_analytic(const mu_analytic_curves *parameters, mu_curves **out);

/** Accepts NULL. */
MU_API void mu_curves_destroy(mu_curves *curves);

/** The curves at a normalized length or velocity. Read-only: one set may
 * serve many muscles and threads. A NaN input, or NULL curves, gives NaN
 * (visible, rather than a plausible force) and records the error. */
MU_API double mu_curve_active_length(const mu_curves *curves, double normalized_length);
MU_API double mu_curve_passive_length(const mu_curves *curves, double normalized_length);
MU_API double mu_curve_velocity(const mu_curves *curves, double normalized_velocity);
/** d f_V / d ṽ at ṽ (>= 0): the muscle's damping, for the implicit solve.
 * A table's slope is 0 outside it and one side's slope at a linear knot;
 * every set's is 0 for ṽ <= -1. */
MU_API double mu_curve_velocity_slope(const mu_curves *curves, double normalized_velocity);

/** Where the last look-ups fell in each table (GSL's gsl_interp_accel):
 * the next ones, a little away, skip the binary search. Zero-initialise
 * one per muscle and keep it with the muscle; it is not shared between
 * threads. A hinted look-up returns exactly what the plain one does. */
typedef struct mu_curve_hint {
    size_t interval[3]; /**< per table: the knot that starts the last interval found */
} mu_curve_hint;

MU_API double mu_curve_active_length_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_length);
MU_API double mu_curve_passive_length_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_length);
MU_API double mu_curve_velocity_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity);
MU_API double mu_curve_velocity_slope_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity);
/** mu_curve_velocity_hinted and mu_curve_velocity_slope_hinted at one
 * ṽ, to the bit, in one look-up: returns f_V and sets *slope (NaN for
 * both on a NaN input or NULL curves; NULL slope is refused with NaN). */
MU_API double mu_curve_velocity_and_slope_hinted(const mu_curves *curves, mu_curve_hint *hint,
                                                 double normalized_velocity, double *slope);

#ifdef __cplusplus
}
#endif

#endif
