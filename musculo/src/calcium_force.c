/* SPDX-License-Identifier: MIT */
/* Two-stage excitation-contraction coupling (mu/calcium_force.h): the
 * parameter sets, the derivative for GSL-shaped integrators and the exact
 * step the muscle takes each substep.
 *
 * The step. With u held and both branches frozen the system is linear:
 * c - u decays as e^(-t/τ_c), and d = a - u obeys d' = ((c - u) - d)/τ_a,
 * whose solution from d(0) = a - u is
 *   d(t) = d(0)·e^(-t/τ_a) + (c - u)·τ_c/(τ_c - τ_a)·(e^(-t/τ_c) - e^(-t/τ_a)).
 * Written as (c - u)·(t/τ_a)·e^(-t/τ_a)·(e^x - 1)/x with x = t·(1/τ_a - 1/τ_c),
 * the last term has no cancellation when τ_c is close to τ_a (expm1 keeps
 * its precision, and the factor tends to 1); for |x| above 1/2 the
 * difference of exponentials is well conditioned and is taken as it is
 * (e^x itself could overflow when τ_a is tiny and h long).
 */
#include <math.h>
#include <stdbool.h>

#include "mu/calcium_force.h"

mu_calcium_force_times mu_calcium_force_times_of(mu_fibre_type type)
{
    if (type != MU_FIBRE_FAST && type != MU_FIBRE_SLOW) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_calcium_force_times_of: type is %d, expected MU_FIBRE_FAST (%d) "
                        "or MU_FIBRE_SLOW (%d)",
                        (int)type, (int)MU_FIBRE_FAST, (int)MU_FIBRE_SLOW);
        return (mu_calcium_force_times){NAN, NAN, NAN, NAN};
    }
    if (type == MU_FIBRE_SLOW) {
        return (mu_calcium_force_times){.calcium_rise_time = 0.002,
                                        .calcium_decay_time = 0.050,
                                        .force_rise_time = 0.060,
                                        .force_decay_time = 0.080};
    }
    return (mu_calcium_force_times){
        .calcium_rise_time = 0.002, .calcium_decay_time = 0.016, .force_rise_time = 0.020, .force_decay_time = 0.025};
}

static bool valid_time(double tau) { return tau > 0.0 && isfinite(tau); }

static rb_status check_params(const mu_calcium_force_params *p, const char *function)
{
    if (p == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: params is NULL", function);
    }
    if (!(p->excitation >= 0.0 && p->excitation <= 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: excitation is %g, expected 0 to 1", function,
                               p->excitation);
    }
    const mu_calcium_force_times *t = &p->times;
    if (!(valid_time(t->calcium_rise_time) && valid_time(t->calcium_decay_time) && valid_time(t->force_rise_time) &&
          valid_time(t->force_decay_time))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: times: calcium_rise_time %g s, calcium_decay_time %g s, force_rise_time %g s, "
                               "force_decay_time %g s, expected each finite and > 0",
                               function, t->calcium_rise_time, t->calcium_decay_time, t->force_rise_time,
                               t->force_decay_time);
    }
    return RB_OK;
}

/* The branches' time constants at state (c, a) under excitation u. */
static double calcium_time(double u, double c, const mu_calcium_force_times *t)
{
    return u > c ? t->calcium_rise_time : t->calcium_decay_time;
}
static double force_time(double c, double a, const mu_calcium_force_times *t)
{
    return c > a ? t->force_rise_time : t->force_decay_time;
}

int mu_calcium_force_derivative(double t, const double y[], double dydt[], void *params)
{
    (void)t;
    const mu_calcium_force_params *p = params;
    const char *f = "mu_calcium_force_derivative";
    rb_status status = check_params(p, f);
    if (status != RB_OK) {
        return (int)status;
    }
    if (y == NULL || dydt == NULL) {
        return (int)rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: y and dydt must not be NULL", f);
    }
    if (!isfinite(y[0]) || !isfinite(y[1])) {
        return (int)rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: y is (%g, %g), expected a finite state", f, y[0],
                                    y[1]);
    }
    dydt[0] = (p->excitation - y[0]) / calcium_time(p->excitation, y[0], &p->times);
    dydt[1] = (y[0] - y[1]) / force_time(y[0], y[1], &p->times);
    return RB_OK;
}

/* (e^(-h/τc) - e^(-h/τa))·τc/(τc - τa), the force stage's response to a
 * unit calcium excess over h (see the top of this file). */
static double convolution(double h, double tau_c, double tau_a)
{
    const double x = h * (1.0 / tau_a - 1.0 / tau_c);
    if (fabs(x) <= 0.5) {
        const double factor = x == 0.0 ? 1.0 : expm1(x) / x;
        return h / tau_a * exp(-h / tau_a) * factor;
    }
    return tau_c / (tau_c - tau_a) * (exp(-h / tau_c) - exp(-h / tau_a));
}

rb_status mu_calcium_force_step(mu_calcium_force_state *state, double h, const mu_calcium_force_params *params)
{
    const char *f = "mu_calcium_force_step";
    rb_status status = check_params(params, f);
    if (status != RB_OK) {
        return status;
    }
    if (state == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: state is NULL", f);
    }
    const double c = state->calcium, a = state->activation, u = params->excitation;
    if (!(c >= 0.0 && c <= 1.0 && a >= 0.0 && a <= 1.0) || !(h >= 0.0 && isfinite(h))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: calcium %g, activation %g and h %g s, expected 0 to 1, 0 to 1 and a finite h >= 0",
                               f, c, a, h);
    }
    const double tau_c = calcium_time(u, c, &params->times);
    /* The force stage's branch by the calcium halfway through the step:
     * from c = a at rest the calcium is about to rise above a. */
    const double tau_a = force_time(u + (c - u) * exp(-0.5 * h / tau_c), a, &params->times);
    const double next_c = u + (c - u) * exp(-h / tau_c);
    const double next_a = u + (a - u) * exp(-h / tau_a) + (c - u) * convolution(h, tau_c, tau_a);
    /* Both are convex combinations of values in [0, 1]; the clamp removes
     * rounding only. */
    state->calcium = fmin(fmax(next_c, 0.0), 1.0);
    state->activation = fmin(fmax(next_a, 0.0), 1.0);
    return RB_OK;
}
