/* SPDX-License-Identifier: MIT */
/** @file
 * Pennation with a constant-thickness (fixed-width) muscle: fibres at an
 * angle α to the tendon's line of action, in a belly whose thickness
 * perpendicular to that line stays constant as the fibres shorten
 * (Zajac 1989, Crit Rev Biomed Eng 17:359, fig. 3; Millard et al. 2013,
 * §2.3). With the fibre length l_f and the width
 *
 *   w = l_opt·sin α_opt   (α_opt the angle at the optimal length l_opt),
 *
 * sin α = w/l_f: the angle rises as the fibre shortens. The belly's
 * extent along the line of action is x = l_f·cos α = √(l_f² - w²), so a
 * fibre shortening at v_f moves the tendon at x' = v_f/cos α, and a fibre
 * force F projects on the tendon as F·cos α.
 *
 * The cap: as α → 90° the projected force vanishes and x' = v_f/cos α
 * diverges (a singular velocity ratio). The angle is capped at
 * acos(0.1) = 84.26°, as OpenSim's MuscleFixedWidthPennationModel and
 * Millard 2013 do: the fibre is never shorter than w/sin(84.26°), where
 * cos α = 0.1 still passes a tenth of its force.
 */
#ifndef MU_PENNATION_H
#define MU_PENNATION_H

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** acos(0.1), rad (84.26°): the largest pennation angle. */
#define MU_MAX_PENNATION_ANGLE 1.4706289056333368

/** w = l_opt·sin α_opt, m, for l_opt > 0 (m) and α_opt in
 * [0, MU_MAX_PENNATION_ANGLE) rad. NaN (and an error) out of range. */
MU_API double mu_pennation_width(double optimal_fibre_length, double optimal_angle);

/** The shortest fibre, m: w/sin(MU_MAX_PENNATION_ANGLE) for a width w >= 0
 * (0 for an unpennated muscle). NaN (and an error) for a bad width. */
MU_API double mu_pennation_min_fibre_length(double width);

/** α = asin(w/l_f), rad, in [0, MU_MAX_PENNATION_ANGLE]: the fibre length
 * (m) is raised to the shortest one first; 0 for w = 0 at any fibre
 * length. NaN (and an error) for a NaN length or a bad width. */
MU_API double mu_pennation_angle(double fibre_length, double width);

/** The fibre length (m) whose belly spans `belly_length` (m) along the line
 * of action: √(x² + w²), never below the shortest fibre; for w = 0 the
 * belly length itself (any sign: the original rigid-tendon muscle's behaviour). NaN
 * (and an error) for a NaN length or a bad width. */
MU_API double mu_pennation_fibre_length(double belly_length, double width);

#ifdef __cplusplus
}
#endif

#endif
