/* SPDX-License-Identifier: MIT */
/* The fibre and its compliant tendon in series (private to the muscle
 * layer): the damped equilibrium of Millard et al. 2013 (J Biomech Eng
 * 135:021005, §2.5 "damped equilibrium model").
 *
 * The path's length L is the tendon's plus the belly's extent along the
 * line of action, L = l_T + X(l_f), X(l_f) = √(l_f² - w²) (pennation.h).
 * The fibre's force, projected on the tendon, balances the tendon's:
 *
 *   G(l_f, v) = Fmax·(a·f_L(l̃)·f_V(ṽ) + f_P(l̃) + β·ṽ)·cos α = Fmax·f_T(ε),
 *   ε = (L - X(l_f) - l_s)/l_s,  l̃ = l_f/l_opt,  ṽ = v/Vmax.
 *
 * Without the damper β·ṽ this equation for the fibre velocity v has no
 * solution when a·f_L = 0 (nothing to invert; Thelen 2003 divides by a)
 * and many where f_V is flat; with β > 0 its left side rises strictly
 * with v, from -∞ to +∞, so exactly one v solves it, for any activation
 * and at the ends of every curve (Millard 2013 uses β = 0.1).
 *
 * Each substep takes the backward-Euler step of the fibre: v solves the
 * balance at the substep's end, with l_f + h·v and the predicted path
 * length. Backward Euler is stable for the stiff fibre-tendon pair (with
 * only β to damp a passive fibre against a stiff tendon its time constant
 * β·l_s·ε0/(1.72·Vmax) is about 1 ms for the original's Vmax of 0.25 m/s, below
 * the 1.7 ms substep, where an explicit step would diverge).
 */
#ifndef MU_FIBRE_TENDON_H
#define MU_FIBRE_TENDON_H

#include "mu/curves.h"

typedef struct mu_fibre_tendon {
    const mu_curves *curves;
    double max_force;           /* N, > 0 */
    double optimal_length;      /* l_opt, m, > 0 */
    double max_velocity;        /* Vmax, m/s, > 0 */
    double width;               /* w, m, >= 0 */
    double min_fibre_length;    /* m, > 0: the fibre never gets shorter */
    double slack_length;        /* l_s, m, > 0 */
    double strain_at_max_force; /* ε0, in (0, 1] */
    double damping;             /* β, > 0: per unit normalized velocity */
} mu_fibre_tendon;

/* The forces of a fibre of length l_f moving at v under activation a,
 * each projected on the tendon (times cos α), N. */
typedef struct mu_fibre_forces {
    double active;  /* Fmax·a·f_L·f_V·cos α */
    double passive; /* Fmax·f_P·cos α */
    double damping; /* Fmax·β·ṽ·cos α */
    double cos_angle;
} mu_fibre_forces;

mu_fibre_forces mu_fibre_forces_at(const mu_fibre_tendon *unit, double fibre_length, double velocity,
                                   double activation);

/* The tendon's force (N) when the path has length `path_length` and the
 * fibre `fibre_length`. */
double mu_fibre_tendon_tension(const mu_fibre_tendon *unit, double path_length, double fibre_length);

/* The static equilibrium (v = 0): the fibre length in
 * [min_fibre_length, ∞) at which the fibre's projected force equals the
 * tendon's for this path length and activation. When fibre and tendon
 * are both slack over a range of lengths the tendon is left at its slack
 * length; when even the shortest fibre leaves the tendon slack the
 * shortest fibre is returned. */
double mu_fibre_tendon_static_length(const mu_fibre_tendon *unit, double path_length, double activation);

/* One backward-Euler step of the fibre over h s from `fibre_length`, with
 * the path at `path_length` at the substep's end. */
typedef struct mu_fibre_tendon_step {
    double velocity; /* v, m/s: the fibre's lengthening velocity over the step */
    double tension;  /* N: the balanced force at the step's end */
    /* dv/dT, m/(s·N) > 0: how the fibre velocity answers a change of
     * tension, 1/(∂G/∂v). */
    double velocity_per_tension;
    /* dT/dL', N·s/m >= 0: the tension's answer to the path's speed over
     * the step, the series combination of the tendon's k_T·h and the
     * fibre's ∂G/∂v/X'; the cable takes it as its damping. */
    double path_damping;
} mu_fibre_tendon_step;

mu_fibre_tendon_step mu_fibre_tendon_solve(const mu_fibre_tendon *unit, double fibre_length, double activation,
                                           double path_length, double h, double velocity_guess);

#endif
