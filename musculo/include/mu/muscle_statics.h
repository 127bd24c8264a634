/* SPDX-License-Identifier: MIT */
/** @file
 * Static muscle formulas, as Castanyer's "Implementació d'un model
 * computacional de sistemes musculoesquelètics" (2023-24) states them: how big
 * a muscle's force is from its anatomy, before any dynamics.
 *
 *   Fmax = PCSA·σ                   σ the specific tension, 0.2-0.4 MPa in
 *                                   mammals
 *   PCSA = V/l_f                    volume over the resting fibre length
 *   PCSA = ACSA/cos β               anatomical cross-section and pennation
 *   l_f  = n·2 µm                   n sarcomeres in series of optimal 2 µm
 *   l_f  = l_measured·2 µm/s        normalized to the optimal sarcomere
 *                                   length, s the measured one
 *
 * Each returns NaN and records an error (rb_last_error) for an argument
 * out of its range.
 */
#ifndef MU_MUSCLE_STATICS_H
#define MU_MUSCLE_STATICS_H

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The optimal sarcomere length fibre lengths are normalized to, m. */
#define MU_OPTIMAL_SARCOMERE_LENGTH 2e-6

/** N, from the physiological cross-section (m², >= 0) and the specific
 * tension (N/m², > 0). */
MU_API double mu_max_force_from_pcsa(double pcsa, double specific_tension);

/** m², from the muscle's volume (m³, >= 0) and its resting fibre length
 * (m, > 0). */
MU_API double mu_pcsa_from_volume(double volume, double fibre_length);

/** m², from the anatomical cross-section (m², >= 0) and the pennation
 * angle (rad, in [0, π/2)). */
MU_API double mu_pcsa_from_anatomical(double anatomical_cross_section, double pennation_angle);

/** m: the resting fibre length of `sarcomeres` (> 0) optimal sarcomeres. */
MU_API double mu_fibre_length_from_sarcomeres(double sarcomeres);

/** m: a fibre length measured (m, > 0) with sarcomeres of the measured
 * length (m, > 0), scaled to optimal sarcomeres. */
MU_API double mu_fibre_length_normalized(double measured_fibre_length, double measured_sarcomere_length);

#ifdef __cplusplus
}
#endif

#endif
