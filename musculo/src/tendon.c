/* SPDX-License-Identifier: MIT */
/* Thelen's (2003) tendon curve with its joint made exact.
 *
 * The toe's slope at ε_toe is A/ε_toe with
 *   A = F_toe·k_toe·exp(k_toe)/(exp(k_toe) - 1) = 1.051343,
 * and the line through (ε_toe, F_toe) reaching 1 at ε0 has slope
 * (1 - F_toe)/(ε0 - ε_toe). Equal slopes give
 *   ε_toe = A·ε0/(A + 1 - F_toe) = 0.611835·ε0,
 *   k_lin = (1 - F_toe)/(ε0 - ε_toe) = (A + 1 - F_toe)/ε0 = 1.718343/ε0,
 * against Thelen's rounded 0.609·ε0 and 1.712/ε0 (which reach 1.002 at ε0
 * with a 0.8 % kink in slope).
 */
#include <math.h>
#include <stdbool.h>

#include "mu/tendon.h"

#define TOE_FORCE 0.333 /* F_toe, Thelen 2003 */
#define TOE_SHAPE 3.0   /* k_toe, Thelen 2003 */

/* A of the header comment: the toe's slope at ε_toe times ε_toe. */
static double toe_end_slope_factor(void) { return TOE_FORCE * TOE_SHAPE * exp(TOE_SHAPE) / expm1(TOE_SHAPE); }

static double toe_strain(double strain_at_max_force)
{
    const double a = toe_end_slope_factor();
    return a * strain_at_max_force / (a + 1.0 - TOE_FORCE);
}

static double linear_stiffness(double strain_at_max_force)
{
    return (toe_end_slope_factor() + 1.0 - TOE_FORCE) / strain_at_max_force;
}

static bool valid(double strain, double strain_at_max_force, const char *function)
{
    if (isnan(strain) || !(strain_at_max_force > 0.0 && strain_at_max_force <= 1.0)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "%s: strain %g and strain_at_max_force %g, expected a number and (0, 1]", function, strain,
                        strain_at_max_force);
        return false;
    }
    return true;
}

double mu_tendon_force(double strain, double strain_at_max_force)
{
    if (!valid(strain, strain_at_max_force, "mu_tendon_force")) {
        return NAN;
    }
    if (strain <= 0.0) {
        return 0.0;
    }
    const double toe = toe_strain(strain_at_max_force);
    if (strain <= toe) {
        return TOE_FORCE * expm1(TOE_SHAPE * strain / toe) / expm1(TOE_SHAPE);
    }
    return TOE_FORCE + linear_stiffness(strain_at_max_force) * (strain - toe);
}

double mu_tendon_stiffness(double strain, double strain_at_max_force)
{
    if (!valid(strain, strain_at_max_force, "mu_tendon_stiffness")) {
        return NAN;
    }
    if (strain <= 0.0) {
        return 0.0;
    }
    const double toe = toe_strain(strain_at_max_force);
    if (strain <= toe) {
        return TOE_FORCE * TOE_SHAPE / toe * exp(TOE_SHAPE * strain / toe) / expm1(TOE_SHAPE);
    }
    return linear_stiffness(strain_at_max_force);
}
