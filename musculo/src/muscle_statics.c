/* SPDX-License-Identifier: MIT */
/* The static formulas of Castanyer's report ("Implementació d'un model
 * computacional de sistemes musculoesquelètics", 2023-24), argument
 * checks included.
 *
 * PCSA = ACSA/cos β is the report's relation as it states it: behind one
 * anatomical section of a pennate muscle lie more fibres, packed
 * obliquely, than the section cuts square, so the fibres' own total
 * cross-section exceeds it by 1/cos β. */
#include <math.h>
#include <stdbool.h>

#include "mu/muscle_statics.h"
#include "rb/math.h"

static bool non_negative(double value) { return value >= 0.0 && isfinite(value); }
static bool positive(double value) { return value > 0.0 && isfinite(value); }

double mu_max_force_from_pcsa(double pcsa, double specific_tension)
{
    if (!non_negative(pcsa) || !positive(specific_tension)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_max_force_from_pcsa: pcsa %g m² and specific_tension %g N/m², expected >= 0 and > 0", pcsa,
                        specific_tension);
        return NAN;
    }
    return pcsa * specific_tension;
}

double mu_pcsa_from_volume(double volume, double fibre_length)
{
    if (!non_negative(volume) || !positive(fibre_length)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_pcsa_from_volume: volume %g m³ and fibre_length %g m, expected >= 0 and > 0", volume,
                        fibre_length);
        return NAN;
    }
    return volume / fibre_length;
}

double mu_pcsa_from_anatomical(double anatomical_cross_section, double pennation_angle)
{
    if (!non_negative(anatomical_cross_section) || !(pennation_angle >= 0.0 && pennation_angle < 0.5 * RB_PI)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_pcsa_from_anatomical: anatomical_cross_section %g m² and pennation_angle %g rad, "
                        "expected >= 0 and 0 to below π/2",
                        anatomical_cross_section, pennation_angle);
        return NAN;
    }
    return anatomical_cross_section / cos(pennation_angle);
}

double mu_fibre_length_from_sarcomeres(double sarcomeres)
{
    if (!positive(sarcomeres)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_fibre_length_from_sarcomeres: sarcomeres is %g, expected > 0",
                        sarcomeres);
        return NAN;
    }
    return sarcomeres * MU_OPTIMAL_SARCOMERE_LENGTH;
}

double mu_fibre_length_normalized(double measured_fibre_length, double measured_sarcomere_length)
{
    if (!positive(measured_fibre_length) || !positive(measured_sarcomere_length)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_fibre_length_normalized: measured_fibre_length %g m and measured_sarcomere_length %g m, "
                        "expected both > 0",
                        measured_fibre_length, measured_sarcomere_length);
        return NAN;
    }
    return measured_fibre_length * MU_OPTIMAL_SARCOMERE_LENGTH / measured_sarcomere_length;
}
