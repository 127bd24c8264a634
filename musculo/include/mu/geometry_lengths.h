/* SPDX-License-Identifier: MIT */
/** @file
 * Muscle and tendon lengths derived from the anchor geometry (the third
 * improvement proposed by Castanyer, "Implementació d'un model
 * computacional de sistemes musculoesquelètics", 2023-24): instead of a
 * measured belly length, the muscle-tendon path's length L at the model's
 * start pose and the fraction of it that is tendon.
 *
 *   tendon length  l_T = f·L
 *   belly extent   x   = (1 - f)·L   along the line of action
 *
 * The belly starts with its fibres at s times their optimal (rest)
 * length l_opt, s the start normalized length. With pennation α_opt at
 * l_opt the fixed-width model (pennation.h) gives x = √(l_f² - w²),
 * l_f = s·l_opt, w = l_opt·sin α_opt, so
 *
 *   l_opt = x/√(s² - sin² α_opt),
 *
 * which is x/s without pennation. The start fibre must lie above the
 * pennation model's shortest fibre: s·sin(84.26°) > sin α_opt.
 */
#ifndef MU_GEOMETRY_LENGTHS_H
#define MU_GEOMETRY_LENGTHS_H

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_derived_lengths {
    double rest_length;   /**< m, > 0: the fibres' optimal length l_opt */
    double tendon_length; /**< m, >= 0: f·L (a rigid tendon's length, a compliant one's slack length) */
} mu_derived_lengths;

/** path_length: m, > 0; tendon_fraction in [0, 1); start_normalized_length
 * > 0; pennation_angle: rad, in [0, MU_MAX_PENNATION_ANGLE), with
 * start_normalized_length·sin(MU_MAX_PENNATION_ANGLE) > sin(pennation_angle).
 * Fails with RB_ERR_INVALID_ARGUMENT naming the argument otherwise. */
MU_API rb_status mu_lengths_from_geometry(double path_length, double tendon_fraction, double start_normalized_length,
                                          double pennation_angle, mu_derived_lengths *out);

#ifdef __cplusplus
}
#endif

#endif
