/* SPDX-License-Identifier: MIT */
/* Smoothing and differentiating a sampled angle, for inverse dynamics.
 *
 * The filter is a zero-phase fourth-order Butterworth low-pass: a
 * second-order Butterworth section run forwards and then backwards over
 * the samples, as Winter recommends for movement data (D. A. Winter,
 * "Biomechanics and Motor Control of Human Movement", 4th ed., 2009,
 * section 2.2.4.4). The backward pass cancels the forward pass's phase
 * lag; the two passes square the gain, so the section's cut-off is raised
 * by 1/0.802 to put the −3 dB point of the pair at the cut-off asked for
 * (Winter's correction for a twice-run second-order filter). Before
 * filtering, each end is extended by the signal turned about its end
 * point (x(−k) = 2·x(0) − x(k)), which keeps the start-up transient small
 * for a signal that does not start at rest at zero.
 *
 * Derivatives are finite differences of second order on the uniform
 * samples: central ones inside, three- and four-point one-sided ones at
 * the ends.
 */
#ifndef MOTION_FILTER_H
#define MOTION_FILTER_H

#include <stdbool.h>
#include <stddef.h>

/* The default cut-off, Hz: 6 Hz, where Winter's residual analysis puts the
 * cut-off of most limb-segment markers in walking (Winter 2009, 3.4.4.3). */
#define MOTION_FILTER_DEFAULT_CUTOFF 6.0

/* Winter's correction of the cut-off for a second-order section run twice. */
#define MOTION_FILTER_TWO_PASS_CORRECTION 0.802

/* Whether a cut-off of `cutoff_hz` can be applied at `sample_rate_hz`:
 * the corrected section cut-off below the Nyquist frequency. */
bool motion_filter_cutoff_valid(double cutoff_hz, double sample_rate_hz);

/* Filters x[0 .. n-1] (n >= 2) in place; false when out of memory. */
bool motion_filter_low_pass(double *x, size_t n, double cutoff_hz, double sample_rate_hz);

/* rate[i] = dx/dt and acceleration[i] = d²x/dt² at sample i, for samples
 * h apart (n >= 4). */
void motion_filter_differentiate(const double *x, size_t n, double h, double *rate, double *acceleration);

#endif
