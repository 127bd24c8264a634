/* SPDX-License-Identifier: MIT */
/* Activation dynamics (Millard et al. 2013, eq. 1-2): the state-dependent
 * time constant, the derivative function for GSL-shaped integrators, and
 * the stable step the muscle takes each substep.
 *
 * Why the exponential midpoint step: with τ frozen the equation
 * da/dt = (u - a)/τ is linear with the exact solution
 * a(t) = u + (a0 - u)·exp(-t/τ) (the exponential integrator of Hochbruck
 * and Ostermann 2010, Acta Numerica 19, §2). Freezing τ at the start
 * state is first order; evaluating it at the midpoint a(h/2) makes the
 * exponent ∫ dt/τ(a(t)) a midpoint-rule quadrature, so the step is second
 * order, and each stage stays between a and u whatever h is (explicit
 * Euler overshoots u once h > τ, that is h > 5 ms when activating from
 * rest with τ_act = 10 ms). u > a keeps its truth over the step, since a
 * never crosses u.
 */
#include <math.h>

#include "mu/activation.h"

mu_activation_params mu_default_activation_params(void)
{
    return (mu_activation_params){.excitation = 0.0, .activation_time = 0.010, .deactivation_time = 0.040};
}

static rb_status check_params(const mu_activation_params *params, const char *function)
{
    if (params == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: params is NULL", function);
    }
    if (!(params->excitation >= 0.0 && params->excitation <= 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: excitation is %g, expected 0 to 1", function,
                               params->excitation);
    }
    if (!(params->activation_time > 0.0 && isfinite(params->activation_time) && params->deactivation_time > 0.0 &&
          isfinite(params->deactivation_time))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: activation_time %g s and deactivation_time %g s, expected both finite and > 0",
                               function, params->activation_time, params->deactivation_time);
    }
    return RB_OK;
}

/* τ for checked params; a is clamped to [0, 1]. */
static double time_constant(double a, const mu_activation_params *p)
{
    const double clamped = fmin(fmax(a, 0.0), 1.0);
    if (p->excitation > clamped) {
        return p->activation_time * (0.5 + 1.5 * clamped);
    }
    return p->deactivation_time / (0.5 + 1.5 * clamped);
}

double mu_activation_time_constant(double activation, const mu_activation_params *params)
{
    if (check_params(params, "mu_activation_time_constant") != RB_OK) {
        return NAN;
    }
    if (!isfinite(activation)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_activation_time_constant: activation is %g, expected a finite number", activation);
        return NAN;
    }
    return time_constant(activation, params);
}

int mu_activation_derivative(double t, const double y[], double dydt[], void *params)
{
    (void)t;
    const mu_activation_params *p = params;
    rb_status status = check_params(p, "mu_activation_derivative");
    if (status != RB_OK) {
        return (int)status;
    }
    if (y == NULL || dydt == NULL) {
        return (int)rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_activation_derivative: y and dydt must not be NULL");
    }
    if (!isfinite(y[0])) {
        return (int)rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                    "mu_activation_derivative: y[0] is %g, expected a finite activation", y[0]);
    }
    dydt[0] = (p->excitation - y[0]) / time_constant(y[0], p);
    return RB_OK;
}

double mu_activation_step(double activation, double h, const mu_activation_params *params)
{
    const char *f = "mu_activation_step";
    if (check_params(params, f) != RB_OK) {
        return NAN;
    }
    if (!(activation >= 0.0 && activation <= 1.0) || !(h >= 0.0 && isfinite(h))) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: activation %g and h %g s, expected 0 to 1 and a finite h >= 0", f,
                        activation, h);
        return NAN;
    }
    const double u = params->excitation;
    const double midpoint = u + (activation - u) * exp(-0.5 * h / time_constant(activation, params));
    return u + (activation - u) * exp(-h / time_constant(midpoint, params));
}
