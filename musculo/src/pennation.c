/* SPDX-License-Identifier: MIT */
/* The fixed-width pennation model (pennation.h). sin(acos 0.1) = √0.99,
 * so the shortest fibre is w/√0.99 and its belly extent √(l² - w²) is
 * 0.1·l = w·0.1/√0.99. */
#include <math.h>
#include <stdbool.h>

#include "mu/pennation.h"

/* The shortest fibre of a belly of width w: at the capped angle. */
static double shortest_fibre(double width) { return width / sqrt(0.99); }

static bool valid_width(double width, const char *function)
{
    if (!(width >= 0.0 && isfinite(width))) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: width is %g m, expected finite and >= 0", function, width);
        return false;
    }
    return true;
}

double mu_pennation_width(double optimal_fibre_length, double optimal_angle)
{
    if (!(optimal_fibre_length > 0.0 && isfinite(optimal_fibre_length)) ||
        !(optimal_angle >= 0.0 && optimal_angle < MU_MAX_PENNATION_ANGLE)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_pennation_width: optimal_fibre_length %g m and optimal_angle %g rad, expected > 0 and "
                        "0 to below %g rad",
                        optimal_fibre_length, optimal_angle, MU_MAX_PENNATION_ANGLE);
        return NAN;
    }
    return optimal_fibre_length * sin(optimal_angle);
}

double mu_pennation_min_fibre_length(double width)
{
    if (!valid_width(width, "mu_pennation_min_fibre_length")) {
        return NAN;
    }
    return shortest_fibre(width);
}

double mu_pennation_angle(double fibre_length, double width)
{
    if (!valid_width(width, "mu_pennation_angle")) {
        return NAN;
    }
    if (isnan(fibre_length)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_pennation_angle: fibre_length is NaN");
        return NAN;
    }
    if (width == 0.0) {
        return 0.0;
    }
    return asin(width / fmax(fibre_length, shortest_fibre(width)));
}

double mu_pennation_fibre_length(double belly_length, double width)
{
    if (!valid_width(width, "mu_pennation_fibre_length")) {
        return NAN;
    }
    if (isnan(belly_length)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_pennation_fibre_length: belly_length is NaN");
        return NAN;
    }
    if (width == 0.0) {
        return belly_length;
    }
    return fmax(sqrt(belly_length * belly_length + width * width), shortest_fibre(width));
}
