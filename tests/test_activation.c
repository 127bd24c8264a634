/* SPDX-License-Identifier: MIT */
/* Activation dynamics (Millard et al. 2013): the derivative function
 * against the hand formula, GSL's rk8pd and the equation's closed form
 * against each other, and the muscle's exponential midpoint step against
 * GSL for a step of excitation up and down, with its order of accuracy,
 * its stability at any step and the muscle using it.
 *
 * The closed form. With u held, da/dt = (u - a)/τ(a) separates.
 * Activating, τ = τ_a·(0.5 + 1.5a):
 *   (0.5 + 1.5a)/(u - a) = -1.5 + (0.5 + 1.5u)/(u - a), so
 *   t(a) = τ_a·(-1.5·(a - a0) + (0.5 + 1.5u)·ln((u - a0)/(u - a))).
 * Deactivating, τ = τ_d/(0.5 + 1.5a):
 *   1/((u - a)(0.5 + 1.5a)) = (1/(u - a) + 1.5/(0.5 + 1.5a))/(0.5 + 1.5u), so
 *   t(a) = τ_d/(0.5 + 1.5u)·ln((0.5 + 1.5a)(a0 - u)/((0.5 + 1.5a0)(a - u))).
 */
#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mu/activation.h"
#include "mu/muscle.h"
#include "test_support.h"

#define TAU_A 0.010
#define TAU_D 0.040

static mu_activation_params params_for(double excitation)
{
    mu_activation_params p = mu_default_activation_params();
    p.excitation = excitation;
    return p;
}

/* t(a) of the closed forms above, from a0 under excitation u. */
static double closed_form_time(double a0, double a, double u)
{
    if (u > a0) {
        return TAU_A * (-1.5 * (a - a0) + (0.5 + 1.5 * u) * log((u - a0) / (u - a)));
    }
    return TAU_D / (0.5 + 1.5 * u) * log((0.5 + 1.5 * a) * (a0 - u) / ((0.5 + 1.5 * a0) * (a - u)));
}

Test(activation, defaults_are_millards)
{
    const mu_activation_params p = mu_default_activation_params();
    cr_expect_eq(p.activation_time, 0.010);
    cr_expect_eq(p.deactivation_time, 0.040);
    cr_expect_eq(p.excitation, 0.0);
}

Test(activation, derivative_is_the_hand_formula)
{
    const double activations[] = {0.0, 0.2, 0.5, 0.9, 1.0};
    const double excitations[] = {0.0, 0.3, 1.0};
    for (size_t i = 0; i < sizeof activations / sizeof *activations; ++i) {
        for (size_t j = 0; j < sizeof excitations / sizeof *excitations; ++j) {
            const double a = activations[i], u = excitations[j];
            mu_activation_params p = params_for(u);
            const double tau = u > a ? TAU_A * (0.5 + 1.5 * a) : TAU_D / (0.5 + 1.5 * a);
            double y[1] = {a}, dydt[1] = {NAN};
            cr_assert_eq(mu_activation_derivative(0.0, y, dydt, &p), GSL_SUCCESS);
            expect_near(dydt[0], (u - a) / tau, 1e-12, "da/dt");
            expect_near(mu_activation_time_constant(a, &p), tau, 1e-15, "τ");
        }
    }
    /* The ends: activating from rest τ_a/2, deactivating from full τ_d/2. */
    mu_activation_params up = params_for(1.0), down = params_for(0.0);
    expect_near(mu_activation_time_constant(0.0, &up), 0.005, 1e-15, "τ activating from 0");
    expect_near(mu_activation_time_constant(1.0, &up), 0.020, 1e-15, "u = a = 1 is not activating: τ_d/2");
    expect_near(mu_activation_time_constant(1.0, &down), 0.020, 1e-15, "τ deactivating from 1");
    expect_near(mu_activation_time_constant(0.0, &down), 0.080, 1e-15, "τ deactivating near 0");
}

/* GSL's rk8pd with tight tolerances from a0 under u: a at the times. */
static void integrate_with_gsl(double a0, double u, const double *times, double *out, int count)
{
    mu_activation_params p = params_for(u);
    gsl_odeiv2_system system = {.function = mu_activation_derivative, .jacobian = NULL, .dimension = 1, .params = &p};
    gsl_odeiv2_driver *driver = gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-6, 1e-13, 1e-13);
    cr_assert_not_null(driver);
    double y[1] = {a0};
    double t = 0.0;
    for (int i = 0; i < count; ++i) {
        cr_assert_eq(gsl_odeiv2_driver_apply(driver, &t, times[i], y), GSL_SUCCESS);
        out[i] = y[0];
    }
    gsl_odeiv2_driver_free(driver);
}

Test(activation, gsl_follows_the_closed_form)
{
    /* The closed form gives t(a); GSL integrating our derivative function
     * must reach a at that t. */
    const double cases[][3] = {{0.0, 1.0, 0.9}, {0.1, 0.6, 0.55}, {1.0, 0.0, 0.02}, {0.8, 0.3, 0.35}};
    for (size_t c = 0; c < sizeof cases / sizeof *cases; ++c) {
        const double a0 = cases[c][0], u = cases[c][1];
        double times[5], expected[5], got[5];
        for (int i = 0; i < 5; ++i) {
            expected[i] = a0 + (cases[c][2] - a0) * (i + 1) / 5.0;
            times[i] = closed_form_time(a0, expected[i], u);
        }
        integrate_with_gsl(a0, u, times, got, 5);
        for (int i = 0; i < 5; ++i) {
            expect_near(got[i], expected[i], 1e-10, "GSL against the closed form");
        }
    }
}

/* The largest |a - a_GSL| of the exponential midpoint step over an
 * excitation step to u from a0, for `duration` s in steps of h. */
static double step_error(double a0, double u, double h, double duration)
{
    const int count = (int)lround(duration / h);
    double *times = calloc((size_t)count, sizeof *times);
    double *reference = calloc((size_t)count, sizeof *reference);
    cr_assert(times != NULL && reference != NULL);
    for (int i = 0; i < count; ++i) {
        times[i] = (i + 1) * h;
    }
    integrate_with_gsl(a0, u, times, reference, count);
    const mu_activation_params p = params_for(u);
    double a = a0;
    double worst = 0.0;
    for (int i = 0; i < count; ++i) {
        a = mu_activation_step(a, h, &p);
        worst = fmax(worst, fabs(a - reference[i]));
    }
    free(times);
    free(reference);
    return worst;
}

Test(activation, midpoint_step_matches_gsl_for_a_step_up_and_down)
{
    /* At the models' substep (1/600 s) the step is within 0.02 of GSL
     * (measured: 0.016 in the first substep activating from rest, where τ
     * starts at 5 ms, h/τ = 0.33, and grows by half within the substep;
     * less than 0.002 otherwise); halving h divides the error by about 4
     * (second order). */
    const double h = 1.0 / 600.0;
    const double cases[][2] = {{0.0, 1.0}, {1.0, 0.0}, {0.2, 0.7}, {0.7, 0.2}};
    for (size_t c = 0; c < sizeof cases / sizeof *cases; ++c) {
        const double e1 = step_error(cases[c][0], cases[c][1], h, 0.2);
        const double e2 = step_error(cases[c][0], cases[c][1], h / 2.0, 0.2);
        const double e4 = step_error(cases[c][0], cases[c][1], h / 4.0, 0.2);
        cr_expect(e1 < (cases[c][0] == 0.0 ? 0.02 : 2e-3), "from %g to %g: error %g at h = 1/600 s", cases[c][0],
                  cases[c][1], e1);
        cr_expect(e1 / e2 > 3.0 && e1 / e2 < 5.0 && e2 / e4 > 3.0 && e2 / e4 < 5.0,
                  "from %g to %g: errors %g, %g, %g do not fall as h²", cases[c][0], cases[c][1], e1, e2, e4);
    }
}

Test(activation, step_never_overshoots)
{
    /* Even a step of 1 s (100 τ_act) lands between a and u; explicit Euler
     * would land at a + h·(u - a)/τ, far beyond. */
    const double hs[] = {1e-4, 0.01, 0.1, 1.0};
    for (size_t i = 0; i < sizeof hs / sizeof *hs; ++i) {
        const mu_activation_params up = params_for(1.0), down = params_for(0.0);
        const double rising = mu_activation_step(0.3, hs[i], &up);
        const double falling = mu_activation_step(0.3, hs[i], &down);
        cr_expect(rising > 0.3 && rising <= 1.0, "h %g: rising to %g", hs[i], rising);
        cr_expect(falling < 0.3 && falling >= 0.0, "h %g: falling to %g", hs[i], falling);
    }
    const mu_activation_params held = params_for(0.4);
    cr_expect_eq(mu_activation_step(0.4, 0.01, &held), 0.4, "a = u stays");
}

Test(activation, bad_arguments_are_errors)
{
    mu_activation_params p = params_for(0.5);
    double y[1] = {0.2}, dydt[1];
    cr_expect_neq(mu_activation_derivative(0.0, y, dydt, NULL), GSL_SUCCESS);
    cr_expect(strstr(rb_last_error(), "mu_activation_derivative") != NULL, "%s", rb_last_error());
    cr_expect_neq(mu_activation_derivative(0.0, NULL, dydt, &p), GSL_SUCCESS);
    p.activation_time = 0.0;
    cr_expect_neq(mu_activation_derivative(0.0, y, dydt, &p), GSL_SUCCESS);
    cr_expect(strstr(rb_last_error(), "activation_time") != NULL, "%s", rb_last_error());
    p = params_for(1.5);
    cr_expect(isnan(mu_activation_step(0.2, 0.01, &p)), "excitation above 1");
    p = params_for(0.5);
    cr_expect(isnan(mu_activation_step(NAN, 0.01, &p)), "NaN activation");
    cr_expect(isnan(mu_activation_step(0.2, -0.01, &p)), "negative h");
    cr_expect(isnan(mu_activation_time_constant(0.2, NULL)), "NULL params");
}

/* A muscle between two static bodies at rest length, Fmax 1000 N, with
 * or without activation dynamics. */
static mu_muscle *static_muscle(rb_world *world, const mu_curves *curves, bool dynamics)
{
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(0.25, 0.0), 0.0);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = origin;
    def.bodies[1] = insertion;
    def.rest_length = 0.2;
    def.max_force = 1000.0;
    def.tendon_length = 0.05;
    def.curves = curves;
    def.activation_dynamics = dynamics;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    return muscle;
}

Test(activation, muscle_activation_follows_its_excitation)
{
    /* With dynamics on, mu_muscle_set_activation sets the excitation and
     * the activation follows it substep by substep exactly as the
     * midpoint step does; with dynamics off it is set at once (the original). */
    const double h = 1.0 / 600.0;
    const mu_analytic_curves parameters = mu_default_analytic_curves();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_analytic(&parameters, &curves), RB_OK);
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    mu_muscle *lagging = static_muscle(world, curves, true);
    mu_muscle *direct = static_muscle(world, curves, false);
    cr_assert_eq(mu_muscle_set_activation(lagging, 1.0), RB_OK);
    cr_assert_eq(mu_muscle_set_activation(direct, 1.0), RB_OK);
    const mu_activation_params up = params_for(1.0);
    double expected = 0.0;
    for (int i = 0; i < 30; ++i) {
        cr_assert_eq(mu_muscle_prepare(lagging, world, h), RB_OK);
        cr_assert_eq(mu_muscle_prepare(direct, world, h), RB_OK);
        step_world(world, h, 1);
        cr_assert_eq(mu_muscle_measure(lagging, world), RB_OK);
        cr_assert_eq(mu_muscle_measure(direct, world), RB_OK);
        expected = mu_activation_step(expected, h, &up);
        const mu_muscle_readout r = mu_muscle_read(lagging);
        expect_near(r.activation, expected, 1e-15, "activation under dynamics");
        cr_expect_eq(r.excitation, 1.0);
        /* Isometric at rest length with the analytic set: F = a·Fmax. */
        expect_near(r.total_force, 1000.0 * expected, 1e-9, "force follows the activation");
        cr_expect_eq(mu_muscle_read(direct).activation, 1.0);
    }
    mu_muscle_destroy(lagging, world);
    mu_muscle_destroy(direct, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}
