/* SPDX-License-Identifier: MIT */
/** @file
 * The tendon's force-strain curve: the series elastic element of a Hill
 * muscle-tendon unit.
 *
 * Strain ε = (l_T - l_s)/l_s over the tendon's slack length l_s; the force
 * is normalized by the muscle's maximal isometric force. The curve is
 * Thelen's (2003, J Biomech Eng 125:70, eq. 4): an exponential toe region
 * for small strains joined to a straight line,
 *
 *   f_T = F_toe·(exp(k_toe·ε/ε_toe) - 1)/(exp(k_toe) - 1)   0 < ε <= ε_toe
 *   f_T = F_toe + k_lin·(ε - ε_toe)                          ε > ε_toe
 *   f_T = 0                                                  ε <= 0 (a slack tendon does not push)
 *
 * with F_toe = 0.333 and k_toe = 3 as Thelen's. Thelen rounds ε_toe and
 * k_lin (0.609·ε0 and 1.712/ε0, ε0 the strain at f_T = 1); we take the
 * exact values that make f_T(ε0) = 1 and the slope continuous at ε_toe
 * (derived in tendon.c): ε_toe = 0.61184·ε0, k_lin = 1.71834/ε0. The
 * default ε0 = 0.049 is Millard et al.'s (2013) and OpenSim's.
 */
#ifndef MU_TENDON_H
#define MU_TENDON_H

#include "mu/export.h"
#include "rb/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The default strain at the maximal isometric force. */
#define MU_DEFAULT_TENDON_STRAIN_AT_MAX_FORCE 0.049

/** f_T(ε) >= 0 for a curve reaching 1 at strain_at_max_force (ε0, in
 * (0, 1]). NaN (and an error) for a NaN strain or an ε0 out of range. */
MU_API double mu_tendon_force(double strain, double strain_at_max_force);

/** d f_T/dε >= 0 (per unit strain), 0 while slack. NaN (and an error) as
 * mu_tendon_force. */
MU_API double mu_tendon_stiffness(double strain, double strain_at_max_force);

#ifdef __cplusplus
}
#endif

#endif
