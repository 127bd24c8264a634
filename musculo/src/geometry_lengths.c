/* SPDX-License-Identifier: MIT */
/* Lengths from the anchor geometry (derived in geometry_lengths.h). */
#include <math.h>

#include "mu/geometry_lengths.h"
#include "mu/pennation.h"

rb_status mu_lengths_from_geometry(double path_length, double tendon_fraction, double start_normalized_length,
                                   double pennation_angle, mu_derived_lengths *out)
{
    const char *f = "mu_lengths_from_geometry";
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: out is NULL", f);
    }
    if (!(path_length > 0.0 && isfinite(path_length))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: path_length is %g m, expected > 0", f, path_length);
    }
    if (!(tendon_fraction >= 0.0 && tendon_fraction < 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: tendon_fraction is %g, expected 0 to below 1", f,
                               tendon_fraction);
    }
    if (!(pennation_angle >= 0.0 && pennation_angle < MU_MAX_PENNATION_ANGLE)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: pennation_angle is %g rad, expected 0 to below %g", f,
                               pennation_angle, MU_MAX_PENNATION_ANGLE);
    }
    const double sine = sin(pennation_angle);
    if (!(isfinite(start_normalized_length) && start_normalized_length * sin(MU_MAX_PENNATION_ANGLE) > sine)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: start_normalized_length is %g, expected above %g (the shortest fibre of the "
                               "pennation angle %g rad)",
                               f, start_normalized_length, sine / sin(MU_MAX_PENNATION_ANGLE), pennation_angle);
    }
    const double belly = (1.0 - tendon_fraction) * path_length;
    out->tendon_length = tendon_fraction * path_length;
    out->rest_length = belly / sqrt(start_normalized_length * start_normalized_length - sine * sine);
    return RB_OK;
}
