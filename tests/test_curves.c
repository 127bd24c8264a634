/* SPDX-License-Identifier: MIT */
/* The Hill curves: the original report's tables (Ross et al. 2018) read,
 * interpolated (linear as the original, or Steffen 1990) and clamped; the
 * MATLAB Hill worksheet's analytic
 * curves and their eccentric branch; the slope the muscle uses as its
 * damping; and the reader's and the parameters' errors.
 *
 * The tables' knots are read here by a reader of the test's own, so the
 * library is checked against the file rather than against itself.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <criterion/criterion.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/curves.h"
#include "test_support.h"

#define SEED_TABLES SINEW_SOURCE_DIR "/models/data/hill-curves.csv"
#define MAX_KNOTS 128

typedef struct knots {
    double x[MAX_KNOTS];
    double y[MAX_KNOTS];
    size_t count;
} knots;

typedef double (*curve_function)(const mu_curves *, double);

/* The three curves in the file's names, with the function evaluating each. */
static const struct {
    const char *name;
    curve_function evaluate;
} curve_kinds[3] = {
    {"active_force_length", mu_curve_active_length},
    {"passive_force_length", mu_curve_passive_length},
    {"force_velocity", mu_curve_velocity},
};

static const mu_interpolation interpolations[2] = {MU_INTERPOLATION_LINEAR, MU_INTERPOLATION_STEFFEN};

/* The knots of curve `name` in the tables' file, in file order. */
static knots read_seed_knots(const char *name)
{
    FILE *file = fopen(SEED_TABLES, "r");
    cr_assert_not_null(file, "cannot open %s", SEED_TABLES);
    knots k = {.count = 0};
    char line[256];
    cr_assert_not_null(fgets(line, sizeof line, file), "%s has no header", SEED_TABLES);
    while (fgets(line, sizeof line, file) != NULL) {
        char *x_text = strchr(line, ',');
        cr_assert_not_null(x_text, "bad row in %s: %s", SEED_TABLES, line);
        *x_text++ = '\0';
        if (strcmp(line, name) != 0) {
            continue;
        }
        char *y_text = NULL;
        double x = strtod(x_text, &y_text);
        cr_assert_eq(*y_text, ',', "bad row in %s: %s", SEED_TABLES, x_text);
        cr_assert_lt(k.count, MAX_KNOTS, "more than %d knots of %s", MAX_KNOTS, name);
        k.x[k.count] = x;
        k.y[k.count] = strtod(y_text + 1, NULL);
        k.count++;
    }
    fclose(file);
    cr_assert_geq(k.count, 3, "%s has %zu knots of %s", SEED_TABLES, k.count, name);
    return k;
}

static mu_curves *seed_tables(mu_interpolation interpolation)
{
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(interpolation, &curves), RB_OK, "%s", rb_last_error());
    cr_assert_not_null(curves);
    return curves;
}

static mu_curves *analytic(const mu_analytic_curves *parameters)
{
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_analytic(parameters, &curves), RB_OK, "%s", rb_last_error());
    cr_assert_not_null(curves);
    return curves;
}

Test(curves, tables_are_exact_at_their_knots)
{
    for (size_t i = 0; i < 2; i++) {
        mu_curves *curves = seed_tables(interpolations[i]);
        for (size_t c = 0; c < 3; c++) {
            const knots k = read_seed_knots(curve_kinds[c].name);
            for (size_t j = 0; j < k.count; j++) {
                /* The f_V knot at -1.0025 lies beyond Vmax, where f_V is 0 (next tests). */
                const double expected = c == 2 && k.x[j] <= -1.0 ? 0.0 : k.y[j];
                const double value = curve_kinds[c].evaluate(curves, k.x[j]);
                cr_expect_eq(value, expected, "%s (interpolation %zu) at knot x = %g: got %.17g, expected %.17g",
                             curve_kinds[c].name, i, k.x[j], value, expected);
            }
        }
        mu_curves_destroy(curves);
    }
}

Test(curves, linear_tables_are_straight_between_knots)
{
    mu_curves *curves = seed_tables(MU_INTERPOLATION_LINEAR);
    for (size_t c = 0; c < 3; c++) {
        const knots k = read_seed_knots(curve_kinds[c].name);
        for (size_t j = 0; j + 1 < k.count; j++) {
            const double middle = 0.5 * (k.x[j] + k.x[j + 1]);
            const double quarter = 0.75 * k.x[j] + 0.25 * k.x[j + 1];
            const double slope = (k.y[j + 1] - k.y[j]) / (k.x[j + 1] - k.x[j]);
            expect_near(curve_kinds[c].evaluate(curves, middle), 0.5 * (k.y[j] + k.y[j + 1]), 1e-12,
                        "linear table at a midpoint: the knots' average");
            expect_near(curve_kinds[c].evaluate(curves, quarter), k.y[j] + slope * (quarter - k.x[j]), 1e-12,
                        "linear table a quarter into an interval");
        }
    }
    mu_curves_destroy(curves);
}

/* Outside its table, f_P keeps its end values and f_V its eccentric
 * plateau; f_L is 0, and f_V is 0 from ṽ = -1 down (the next test). */
Test(curves, tables_keep_their_end_values_outside_but_active_length_is_zero)
{
    for (size_t i = 0; i < 2; i++) {
        mu_curves *curves = seed_tables(interpolations[i]);
        for (size_t c = 0; c < 3; c++) {
            const knots k = read_seed_knots(curve_kinds[c].name);
            const double first = k.x[0];
            const double last = k.x[k.count - 1];
            const double below[] = {first - 1e-9, first - 0.1, -10.0};
            const double above[] = {last + 1e-9, last + 0.1, 10.0};
            const bool active = c == 0, velocity = c == 2;
            for (size_t j = 0; j < 3; j++) {
                cr_expect_eq(curve_kinds[c].evaluate(curves, below[j]), active || velocity ? 0.0 : k.y[0],
                             "%s below its table at %g", curve_kinds[c].name, below[j]);
                cr_expect_eq(curve_kinds[c].evaluate(curves, above[j]), active ? 0.0 : k.y[k.count - 1],
                             "%s above its table at %g", curve_kinds[c].name, above[j]);
            }
        }
        const knots v = read_seed_knots("force_velocity");
        cr_expect_eq(mu_curve_velocity_slope(curves, v.x[0] - 0.01), 0.0, "f_V slope below the table");
        cr_expect_eq(mu_curve_velocity_slope(curves, v.x[v.count - 1] + 0.01), 0.0, "f_V slope above the table");
        cr_expect_eq(mu_curve_velocity_slope(curves, -5.0), 0.0, "f_V slope far below the table");
        mu_curves_destroy(curves);
    }
}

/* A muscle shortening at Vmax or faster exerts no active force, in every
 * set: f_V and its slope are 0 for ṽ <= -1 (the tables' first knot,
 * (-1.0025, 0.0055), is digitisation, not a force beyond Vmax). */
Test(curves, no_set_has_active_force_at_or_beyond_vmax)
{
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *sets[3] = {seed_tables(MU_INTERPOLATION_LINEAR), seed_tables(MU_INTERPOLATION_STEFFEN), analytic(&p)};
    const double beyond[] = {-1.0, -1.0 - 1e-12, -1.001, -1.0025, -1.01, -2.0, -1e6, -1e300};
    for (size_t s = 0; s < 3; s++) {
        for (size_t j = 0; j < sizeof beyond / sizeof beyond[0]; j++) {
            cr_expect_eq(mu_curve_velocity(sets[s], beyond[j]), 0.0, "set %zu: f_V(%g)", s, beyond[j]);
            cr_expect_eq(mu_curve_velocity_slope(sets[s], beyond[j]), 0.0, "set %zu: f_V'(%g)", s, beyond[j]);
        }
        cr_expect_gt(mu_curve_velocity(sets[s], -0.99), 0.0, "set %zu: f_V just short of Vmax", s);
        mu_curves_destroy(sets[s]);
    }
}

/* The analytic f_P is the worksheet's exponential up to l̃ = 2, then the
 * straight line that continues it with its slope: a finite force for any
 * finite stretch (exp(10·(l̃ - 1)) overflows from l̃ = 72), C¹ at 2. */
Test(curves, analytic_passive_force_is_finite_for_any_stretch)
{
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *curves = analytic(&p);
    const double at_two = p.passive_scale * expm1(p.passive_rate);
    const double slope = p.passive_scale * p.passive_rate * exp(p.passive_rate);
    expect_near(mu_curve_passive_length(curves, 1.9), p.passive_scale * expm1(0.9 * p.passive_rate), 1e-12,
                "the exponential below 2");
    expect_near(mu_curve_passive_length(curves, 2.0), at_two, 1e-9, "f_P(2)");
    const double far[] = {3.0, 72.0, 1e3, 1e6, 1e300};
    for (size_t j = 0; j < sizeof far / sizeof far[0]; j++) {
        const double value = mu_curve_passive_length(curves, far[j]);
        cr_expect(isfinite(value), "f_P(%g) = %g", far[j], value);
        expect_near(value, at_two + slope * (far[j] - 2.0), 1e-12 * (at_two + slope * far[j]), "the line past 2");
    }
    const double h = 1e-6;
    expect_near((mu_curve_passive_length(curves, 2.0) - mu_curve_passive_length(curves, 2.0 - h)) / h, slope,
                1e-4 * slope, "slope just below 2");
    expect_near((mu_curve_passive_length(curves, 2.0 + h) - mu_curve_passive_length(curves, 2.0)) / h, slope,
                1e-4 * slope, "slope just above 2");
    mu_curves_destroy(curves);
}

Test(curves, steffen_is_monotone_between_monotone_knots)
{
    /* Sampled densely in every interval: the worst overshoot beyond the
     * interval's knot values and the worst step against their direction
     * (one check per curve: Criterion reports every check it makes). */
    mu_curves *curves = seed_tables(MU_INTERPOLATION_STEFFEN);
    for (size_t c = 0; c < 3; c++) {
        const knots k = read_seed_knots(curve_kinds[c].name);
        double overshoot = 0.0;
        double reversal = 0.0;
        double worst_x = 0.0;
        /* f_V's first interval straddles ṽ = -1, below which f_V is 0 by decision, not by interpolation. */
        for (size_t j = c == 2 ? 1 : 0; j + 1 < k.count; j++) {
            const double low = fmin(k.y[j], k.y[j + 1]);
            const double high = fmax(k.y[j], k.y[j + 1]);
            const double direction = k.y[j + 1] >= k.y[j] ? 1.0 : -1.0;
            double previous = k.y[j];
            for (int s = 1; s <= 64; s++) {
                const double x = k.x[j] + (k.x[j + 1] - k.x[j]) * s / 64.0;
                const double value = curve_kinds[c].evaluate(curves, x);
                const double beyond = fmax(low - value, value - high);
                const double back = direction * (previous - value);
                if (beyond > overshoot || back > reversal) {
                    worst_x = x;
                }
                overshoot = fmax(overshoot, beyond);
                reversal = fmax(reversal, back);
                previous = value;
            }
        }
        cr_expect_leq(overshoot, 1e-14, "%s, Steffen: overshoots its knots by %g (worst near x = %.9g)",
                      curve_kinds[c].name, overshoot, worst_x);
        cr_expect_leq(reversal, 1e-14, "%s, Steffen: steps back by %g between monotone knots (worst near x = %.9g)",
                      curve_kinds[c].name, reversal, worst_x);
    }
    mu_curves_destroy(curves);
}

Test(curves, seed_tables_values_at_rest)
{
    /* The linear tables at l̃ = 1 and ṽ = 0: f_V(0)
     * is not exactly 1, since no knot sits at 0. */
    mu_curves *curves = seed_tables(MU_INTERPOLATION_LINEAR);
    const knots v = read_seed_knots("force_velocity");
    const knots l = read_seed_knots("active_force_length");
    size_t j = 0;
    while (v.x[j + 1] <= 0.0) {
        j++;
    }
    const double fv0 = v.y[j] + (0.0 - v.x[j]) * (v.y[j + 1] - v.y[j]) / (v.x[j + 1] - v.x[j]);
    size_t i = 0;
    while (l.x[i + 1] <= 1.0) {
        i++;
    }
    const double fl1 = l.y[i] + (1.0 - l.x[i]) * (l.y[i + 1] - l.y[i]) / (l.x[i + 1] - l.x[i]);
    expect_near(mu_curve_velocity(curves, 0.0), fv0, 1e-12, "tabulated f_V(0) against its two knots");
    expect_near(mu_curve_active_length(curves, 1.0), fl1, 1e-12, "tabulated f_L(1) against its two knots");
    expect_near(mu_curve_velocity(curves, 0.0), 1.0116, 5e-5, "tabulated f_V(0)");
    expect_near(mu_curve_active_length(curves, 1.0), 0.998, 5e-4, "tabulated f_L(1)");
    mu_curves_destroy(curves);
}

/* The formulas of the MATLAB worksheet "1D Muscle Model based on the Hill
 * 2-Element Model", written as the worksheet writes them. */
static double seed_active_length(double width, double l) { return exp(-pow((l - 1.0) / width, 2.0)); }

static double seed_passive_length(double c, double d, double l) { return fmax(c * (exp(d * (l - 1.0)) - 1.0), 0.0); }

/* f_V = a(Vmax - V)/(F_MAX·(b + V)), b = a·Vmax/F_MAX, V the shortening speed. */
static double seed_velocity(double a, double max_force, double max_velocity, double shortening_speed)
{
    const double b = a * max_velocity / max_force;
    return a * (max_velocity - shortening_speed) / (max_force * (b + shortening_speed));
}

Test(curves, analytic_set_follows_seed_003)
{
    /* The worksheet's constants (a = 0.25 N, F_MAX = 5 N, Vmax = 1.5 mm/s), and
     * a second set with every parameter changed. */
    const double seed_a[2] = {0.25, 1.0};
    const double seed_max_force[2] = {5.0, 4.0};
    const double seed_max_velocity[2] = {1.5, 2.0};
    mu_analytic_curves sets[2] = {mu_default_analytic_curves(), mu_default_analytic_curves()};
    sets[1] = (mu_analytic_curves){
        .width = 0.4, .curvature = 0.25, .eccentric_plateau = 1.8, .passive_scale = 0.02, .passive_rate = 5.0};
    for (size_t s = 0; s < 2; s++) {
        const mu_analytic_curves p = sets[s];
        expect_near(p.curvature, seed_a[s] / seed_max_force[s], 1e-15, "curvature is a/F_MAX");
        mu_curves *curves = analytic(&p);
        for (int i = 0; i <= 150; i++) {
            /* l̃ over [0, 1.5], the worksheet's L_TOT = 0 : 1.5·L_rest. */
            const double l = i / 100.0;
            expect_near(mu_curve_active_length(curves, l), seed_active_length(p.width, l), 1e-14, "analytic f_L");
            const double passive = seed_passive_length(p.passive_scale, p.passive_rate, l);
            expect_near(mu_curve_passive_length(curves, l), passive, 1e-14 + 1e-12 * passive, "analytic f_P");
        }
        for (int i = 0; i <= 10; i++) {
            /* The worksheet's family of shortening speeds V = (i/10)·Vmax. */
            const double speed = i / 10.0 * seed_max_velocity[s];
            const double expected = seed_velocity(seed_a[s], seed_max_force[s], seed_max_velocity[s], speed);
            expect_near(mu_curve_velocity(curves, -speed / seed_max_velocity[s]), expected, 1e-14,
                        "analytic f_V while shortening");
        }
        mu_curves_destroy(curves);
    }
}

Test(curves, analytic_velocity_is_one_at_rest_zero_at_max_and_c1_at_zero)
{
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *curves = analytic(&p);
    cr_expect_eq(mu_curve_velocity(curves, 0.0), 1.0, "f_V(0)");
    cr_expect_eq(mu_curve_velocity(curves, -1.0), 0.0, "f_V(-1)");
    cr_expect_eq(mu_curve_velocity(curves, -1.5), 0.0, "f_V beyond -1");
    /* The slope at 0 from either side: d/dṽ of (1 + ṽ)/(1 - ṽ/k) at 0 is
     * (1 + k)/k. */
    const double s0 = (1.0 + p.curvature) / p.curvature;
    expect_near(mu_curve_velocity_slope(curves, 0.0), s0, 1e-12, "f_V' at 0");
    expect_near(mu_curve_velocity_slope(curves, -1e-12), s0, 1e-8, "f_V' just below 0");
    expect_near(mu_curve_velocity_slope(curves, 1e-12), s0, 1e-8, "f_V' just above 0");
    const double h = 1e-7;
    expect_near((mu_curve_velocity(curves, h) - 1.0) / h, s0, 1e-3 * s0, "one-sided difference while lengthening");
    expect_near((1.0 - mu_curve_velocity(curves, -h)) / h, s0, 1e-3 * s0, "one-sided difference while shortening");
    /* The eccentric branch rises to its plateau and stays below it (in
     * doubles it reaches the plateau's neighbourhood and goes flat by
     * ṽ ≈ 0.8, so "rising" is strict only before that). */
    double previous = 1.0;
    int fall_count = 0;
    int flat_count = 0;
    int above_count = 0;
    for (int i = 1; i <= 400; i++) {
        const double value = mu_curve_velocity(curves, i / 100.0);
        fall_count += value < previous;
        flat_count += i <= 50 && value <= previous;
        above_count += value > p.eccentric_plateau;
        previous = value;
    }
    cr_expect_eq(fall_count, 0, "f_V falls %d times while lengthening", fall_count);
    cr_expect_eq(flat_count, 0, "f_V does not rise %d times over (0, 0.5]", flat_count);
    cr_expect_eq(above_count, 0, "f_V exceeds its plateau %d times", above_count);
    expect_near(mu_curve_velocity(curves, 1.0), p.eccentric_plateau, 1e-9, "f_V at fast lengthening");
    mu_curves_destroy(curves);
}

/* The smallest of f over [from, to] in steps of `step`, and where. */
static double minimum_over(curve_function f, const mu_curves *curves, double from, double to, double step,
                           double *where)
{
    double minimum = INFINITY;
    const int count = (int)lround((to - from) / step);
    for (int i = 0; i <= count; i++) {
        const double x = from + i * step;
        const double value = f(curves, x);
        if (!(value >= minimum)) {
            minimum = value;
            *where = x;
        }
    }
    return minimum;
}

Test(curves, no_curve_is_ever_negative)
{
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *sets[3] = {analytic(&p), seed_tables(MU_INTERPOLATION_LINEAR), seed_tables(MU_INTERPOLATION_STEFFEN)};
    const char *set_names[3] = {"analytic", "linear tables", "Steffen tables"};
    const struct {
        const char *name;
        curve_function f;
        double from, to;
    } sweeps[4] = {
        {"f_L", mu_curve_active_length, 0.0, 2.5},
        {"f_P", mu_curve_passive_length, 0.0, 2.5},
        {"f_V", mu_curve_velocity, -2.0, 2.0},
        {"f_V'", mu_curve_velocity_slope, -2.0, 2.0},
    };
    for (size_t s = 0; s < 3; s++) {
        for (size_t w = 0; w < 4; w++) {
            double where = 0.0;
            const double minimum = minimum_over(sweeps[w].f, sets[s], sweeps[w].from, sweeps[w].to, 1e-4, &where);
            cr_expect_geq(minimum, 0.0, "%s: %s is %g at %g", set_names[s], sweeps[w].name, minimum, where);
        }
        mu_curves_destroy(sets[s]);
    }
}

/* Central difference of f_V at v with step h. */
static double velocity_difference(const mu_curves *curves, double v, double h)
{
    return (mu_curve_velocity(curves, v + h) - mu_curve_velocity(curves, v - h)) / (2.0 * h);
}

Test(curves, slope_matches_a_central_difference)
{
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *curves = analytic(&p);
    const double points[] = {-0.99, -0.8, -0.5, -0.2, -0.05, -0.01, 0.01, 0.02, 0.05, 0.1, 0.3};
    for (size_t i = 0; i < sizeof points / sizeof points[0]; i++) {
        const double slope = mu_curve_velocity_slope(curves, points[i]);
        expect_near(slope, velocity_difference(curves, points[i], 1e-6), 1e-6 * (1.0 + slope),
                    "analytic f_V' against a central difference");
    }
    mu_curves_destroy(curves);

    /* Tables: inside each interval, clear of its knots, where both
     * interpolants are smooth. The slope is the difference raised to 0 (the
     * table's last knots fall a little). */
    const knots v = read_seed_knots("force_velocity");
    for (size_t i = 0; i < 2; i++) {
        curves = seed_tables(interpolations[i]);
        for (size_t j = 0; j + 1 < v.count; j++) {
            const double width = v.x[j + 1] - v.x[j];
            const double fractions[] = {0.3, 0.5, 0.7};
            for (size_t f = 0; f < 3; f++) {
                const double x = v.x[j] + fractions[f] * width;
                const double slope = mu_curve_velocity_slope(curves, x);
                const double difference = fmax(velocity_difference(curves, x, 1e-4 * width), 0.0);
                expect_near(slope, difference, 1e-6 * (1.0 + slope), "tabulated f_V' against a central difference");
            }
        }
        mu_curves_destroy(curves);
    }
}

Test(curves, nan_in_nan_out)
{
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *sets[2] = {analytic(&p), seed_tables(MU_INTERPOLATION_LINEAR)};
    for (size_t s = 0; s < 2; s++) {
        cr_expect(isnan(mu_curve_active_length(sets[s], NAN)), "set %zu: f_L(NaN)", s);
        cr_expect(isnan(mu_curve_passive_length(sets[s], NAN)), "set %zu: f_P(NaN)", s);
        cr_expect(isnan(mu_curve_velocity(sets[s], NAN)), "set %zu: f_V(NaN)", s);
        cr_expect(isnan(mu_curve_velocity_slope(sets[s], NAN)), "set %zu: f_V'(NaN)", s);
        mu_curves_destroy(sets[s]);
    }
    cr_expect(isnan(mu_curve_velocity(NULL, 0.0)), "f_V of NULL curves");
}

Test(curves, hinted_look_ups_equal_plain_ones)
{
    /* A hint only changes where GSL's search starts: the values must be
     * bit-identical however far the inputs jump, back and forth across
     * each table, and with a hint left by a longer table (out of range
     * indices). The inputs follow a deterministic irregular walk. */
    for (size_t i = 0; i < 2; i++) {
        mu_curves *curves = seed_tables(interpolations[i]);
        mu_curve_hint hint = {0};
        double x = 0.0;
        for (int n = 0; n < 2000; n++) {
            x = fmod(x + 0.137 + 0.5 * sin(n), 4.0);
            const double l = x - 0.5;     /* -0.5 .. 3.5: the length tables and beyond */
            const double v = 0.8 * x - 2; /* -2 .. 1.2: the velocity table and beyond */
            cr_expect_eq(mu_curve_active_length_hinted(curves, &hint, l), mu_curve_active_length(curves, l));
            cr_expect_eq(mu_curve_passive_length_hinted(curves, &hint, l), mu_curve_passive_length(curves, l));
            cr_expect_eq(mu_curve_velocity_hinted(curves, &hint, v), mu_curve_velocity(curves, v));
            cr_expect_eq(mu_curve_velocity_slope_hinted(curves, &hint, v), mu_curve_velocity_slope(curves, v));
            if (n == 1000) {
                hint = (mu_curve_hint){{1000, 1000, 1000}};
            }
        }
        mu_curves_destroy(curves);
    }
}

/* The same double to the bit (-0 and +0 differ). */
static bool same_bits(double a, double b)
{
    uint64_t x = 0;
    uint64_t y = 0;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &b, sizeof y);
    return x == y;
}

Test(curves, velocity_and_slope_in_one_look_up_equal_the_two_look_ups_bit_for_bit)
{
    /* The muscle's law reads f_V and its slope at one ṽ with one look-up;
     * both must be the bits of the separate plain look-ups (which the
     * test above holds to GSL's interpolants) for every set, along a walk
     * that jumps back and forth across the table and beyond it, at the
     * velocity table's knots (read from the seed file), at Vmax and at the
     * ends. */
    const mu_analytic_curves p = mu_default_analytic_curves();
    mu_curves *sets[3] = {seed_tables(MU_INTERPOLATION_LINEAR), seed_tables(MU_INTERPOLATION_STEFFEN), analytic(&p)};
    double points[2200];
    size_t count = 0;
    double x = 0.0;
    for (int n = 0; n < 2000; n++) {
        x = fmod(x + 0.137 + 0.5 * sin(n), 4.0);
        points[count++] = 0.8 * x - 2.0; /* -2 .. 1.2: the velocity table and beyond */
    }
    const double special[] = {-1.0, -1.0025, nextafter(-1.0, 0.0), 0.0, -0.0, 1e-12, -1e-12, 1.0, 2.0, -3.0};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++) {
        points[count++] = special[i];
    }
    for (size_t s = 0; s < 3; s++) {
        mu_curve_hint hint = {0};
        for (size_t i = 0; i < count; i++) {
            double slope = -1.0;
            const double value = mu_curve_velocity_and_slope_hinted(sets[s], &hint, points[i], &slope);
            cr_expect(same_bits(value, mu_curve_velocity(sets[s], points[i])), "set %zu: f_V(%.17g) = %.17g", s,
                      points[i], value);
            cr_expect(same_bits(slope, mu_curve_velocity_slope(sets[s], points[i])), "set %zu: f_V'(%.17g) = %.17g", s,
                      points[i], slope);
        }
        mu_curves_destroy(sets[s]);
    }
}

Test(curves, velocity_and_slope_at_the_knots_equal_the_two_look_ups)
{
    /* At every knot of the f_V table (read from the seed file), the
     * doubles on either side of it and the midpoints, where a straight
     * line's interval changes, for both interpolations. */
    const knots k = read_seed_knots("force_velocity");
    const mu_interpolation interpolations[2] = {MU_INTERPOLATION_LINEAR, MU_INTERPOLATION_STEFFEN};
    for (size_t s = 0; s < 2; s++) {
        mu_curves *curves = seed_tables(interpolations[s]);
        mu_curve_hint hint = {0};
        for (size_t i = 0; i < k.count; i++) {
            const double mid = i + 1 < k.count ? 0.5 * (k.x[i] + k.x[i + 1]) : k.x[i] + 1.0;
            const double at[4] = {k.x[i], nextafter(k.x[i], -INFINITY), nextafter(k.x[i], INFINITY), mid};
            for (int j = 0; j < 4; j++) {
                double slope = 0.0;
                const double value = mu_curve_velocity_and_slope_hinted(curves, &hint, at[j], &slope);
                cr_expect(same_bits(value, mu_curve_velocity(curves, at[j])), "set %zu: f_V(%.17g)", s, at[j]);
                cr_expect(same_bits(slope, mu_curve_velocity_slope(curves, at[j])), "set %zu: f_V'(%.17g)", s, at[j]);
            }
        }
        mu_curves_destroy(curves);
    }
}

Test(curves, hinted_length_look_ups_at_the_knots_equal_the_plain_ones)
{
    /* Walked upwards with one hint, each midpoint and the doubles beside a
     * knot fall inside the interval the previous look-up left in the hint
     * (the hinted look-up's shortcut), the knots themselves on its edge
     * (the full look-up): every one must give the plain look-up's bits. */
    const char *rows[2] = {"active_force_length", "passive_force_length"};
    for (size_t t = 0; t < 2; t++) {
        const knots k = read_seed_knots(rows[t]);
        mu_curves *curves = seed_tables(MU_INTERPOLATION_LINEAR);
        mu_curve_hint hint = {0};
        for (size_t i = 0; i < k.count; i++) {
            const double mid = i + 1 < k.count ? 0.5 * (k.x[i] + k.x[i + 1]) : k.x[i] + 1.0;
            const double at[4] = {nextafter(k.x[i], -INFINITY), k.x[i], nextafter(k.x[i], INFINITY), mid};
            for (int j = 0; j < 4; j++) {
                const double hinted = t == 0 ? mu_curve_active_length_hinted(curves, &hint, at[j])
                                             : mu_curve_passive_length_hinted(curves, &hint, at[j]);
                const double plain =
                    t == 0 ? mu_curve_active_length(curves, at[j]) : mu_curve_passive_length(curves, at[j]);
                cr_expect(same_bits(hinted, plain), "%s(%.17g): %.17g hinted, %.17g plain", rows[t], at[j], hinted,
                          plain);
            }
        }
        mu_curves_destroy(curves);
    }
}

Test(curves, velocity_and_slope_refuse_nan_null_curves_and_null_slope)
{
    mu_curves *curves = seed_tables(MU_INTERPOLATION_LINEAR);
    mu_curve_hint hint = {0};
    double slope = 0.0;
    cr_expect(isnan(mu_curve_velocity_and_slope_hinted(curves, &hint, NAN, &slope)));
    cr_expect(isnan(slope), "the slope of NaN is NaN");
    cr_expect(strstr(rb_last_error(), "normalized_velocity is NaN") != NULL, "%s", rb_last_error());
    slope = 0.0;
    cr_expect(isnan(mu_curve_velocity_and_slope_hinted(NULL, &hint, 0.0, &slope)));
    cr_expect(isnan(slope), "NULL curves give a NaN slope");
    cr_expect(strstr(rb_last_error(), "curves is NULL") != NULL, "%s", rb_last_error());
    cr_expect(isnan(mu_curve_velocity_and_slope_hinted(curves, &hint, 0.0, NULL)));
    cr_expect(strstr(rb_last_error(), "slope is NULL") != NULL, "%s", rb_last_error());
    mu_curves_destroy(curves);
}

Test(curves, straight_lines_equal_gsl_linear_interpolant_bit_for_bit)
{
    /* The linear tables are evaluated by the library's own search and
     * line, with GSL's rounding: the value and the slope must equal GSL's
     * linear interpolant (over the file's knots, read by this test) to the
     * last bit, at every knot, between knots and along a walk that jumps
     * back and forth (hinted and plain). Inside the table only: the ends
     * are clamped. */
    mu_curves *curves = seed_tables(MU_INTERPOLATION_LINEAR);
    for (size_t c = 0; c < 3; c++) {
        const knots k = read_seed_knots(curve_kinds[c].name);
        gsl_interp *line = gsl_interp_alloc(gsl_interp_linear, k.count);
        cr_assert_not_null(line);
        gsl_interp_init(line, k.x, k.y, k.count);
        mu_curve_hint hint = {0};
        double walk = 0.0;
        for (int n = 0; n < 3000; n++) {
            double x = 0.0;
            if (n < 2 * (int)k.count - 2) { /* the knots but the last, and the midpoints */
                const size_t i = (size_t)n / 2;
                x = n % 2 == 0 ? k.x[i] : 0.5 * (k.x[i] + k.x[i + 1]);
            } else {
                walk = fmod(walk + 0.37 + 0.6 * sin(n), 1.0);
                x = k.x[0] + walk * (k.x[k.count - 1] - k.x[0]);
            }
            /* f_V is 0 from the maximum shortening speed on, ṽ <= -1, where the table starts just below -1. */
            if (!(x > k.x[0] && x < k.x[k.count - 1]) || (c == 2 && x <= -1.0)) {
                continue;
            }
            const double expected = fmax(gsl_interp_eval(line, k.x, k.y, x, NULL), 0.0);
            cr_expect_eq(curve_kinds[c].evaluate(curves, x), expected, "%s(%.17g)", curve_kinds[c].name, x);
            if (c == 2) {
                const double slope = fmax(gsl_interp_eval_deriv(line, k.x, k.y, x, NULL), 0.0);
                cr_expect_eq(mu_curve_velocity_slope(curves, x), slope, "f_V'(%.17g)", x);
                cr_expect_eq(mu_curve_velocity_slope_hinted(curves, &hint, x), slope, "f_V'(%.17g), hinted", x);
                cr_expect_eq(mu_curve_velocity_hinted(curves, &hint, x), expected, "f_V(%.17g), hinted", x);
            }
        }
        gsl_interp_free(line);
    }
    mu_curves_destroy(curves);
}

/* A scratch directory for one test's files, removed by remove_scratch. */
typedef struct scratch {
    char directory[64];
    char path[128];
} scratch;

static void make_scratch(scratch *s)
{
    snprintf(s->directory, sizeof s->directory, "/tmp/sinew-test-curves-XXXXXX");
    cr_assert_not_null(mkdtemp(s->directory), "mkdtemp failed");
    snprintf(s->path, sizeof s->path, "%s/curves.csv", s->directory);
}

static void remove_scratch(scratch *s)
{
    unlink(s->path);
    cr_expect_eq(rmdir(s->directory), 0, "cannot remove %s", s->directory);
}

static void write_text(const char *path, const char *text)
{
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file, "cannot write %s", path);
    fputs(text, file);
    fclose(file);
}

/* Two knots of f_L and f_P and three of f_V: enough for lines, too few
 * for Steffen in f_L and f_P. Lines 2-8. */
#define HEADER_ROW "curve,x,y\n"
#define GOOD_ROWS                                                                                                      \
    "active_force_length,0.5,0\n"                                                                                      \
    "active_force_length,1.5,1\n"                                                                                      \
    "passive_force_length,1,0\n"                                                                                       \
    "passive_force_length,2,1\n"                                                                                       \
    "force_velocity,-1,0\n"                                                                                            \
    "force_velocity,0,1\n"                                                                                             \
    "force_velocity,1,1.5\n"

/* Creating curves from `text` fails, with a message naming the file and,
 * if `line` > 0, ":line:". */
static void expect_bad_file(const char *text, mu_interpolation interpolation, int line, const char *what)
{
    scratch s;
    make_scratch(&s);
    write_text(s.path, text);
    mu_curves *curves = (mu_curves *)&s; /* any non-NULL value: a failure must reset it */
    const rb_status status = mu_curves_create_tabulated(s.path, interpolation, &curves);
    const char *message = rb_last_error();
    cr_expect_eq(status, RB_ERR_INVALID_ARGUMENT, "%s: status %s", what, rb_status_name(status));
    cr_expect_null(curves, "%s: out is not NULL after a failure", what);
    cr_expect_not_null(strstr(message, s.path), "%s: message '%s' does not name the file", what, message);
    if (line > 0) {
        char where[160];
        snprintf(where, sizeof where, "%s:%d:", s.path, line);
        cr_expect_not_null(strstr(message, where), "%s: message '%s' does not name line %d", what, message, line);
    }
    if (status == RB_OK) {
        mu_curves_destroy(curves);
    }
    remove_scratch(&s);
}

Test(curves, a_good_small_file_is_read)
{
    /* Windows line endings, a blank line, and curves interleaved. */
    scratch s;
    make_scratch(&s);
    write_text(s.path, "curve,x,y\r\n"
                       "force_velocity,-1,0\r\n"
                       "active_force_length,0.5,0\r\n"
                       "\r\n"
                       "force_velocity,0,1\r\n"
                       "passive_force_length,1,0\r\n"
                       "active_force_length,1.5,1\r\n"
                       "passive_force_length,2,-0.25\r\n"
                       "force_velocity,1,1.5\r\n");
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_tabulated(s.path, MU_INTERPOLATION_LINEAR, &curves), RB_OK, "%s", rb_last_error());
    expect_near(mu_curve_active_length(curves, 1.0), 0.5, 1e-15, "f_L of the small file");
    expect_near(mu_curve_velocity(curves, -0.5), 0.5, 1e-15, "f_V of the small file");
    expect_near(mu_curve_velocity(curves, 0.5), 1.25, 1e-15, "f_V of the small file");
    expect_near(mu_curve_velocity_slope(curves, 0.5), 0.5, 1e-15, "f_V' of the small file");
    /* A knot below 0 is kept, but the curve is clamped at 0. */
    cr_expect_eq(mu_curve_passive_length(curves, 1.9), 0.0, "f_P raised to 0");
    mu_curves_destroy(curves);
    remove_scratch(&s);
}

Test(curves, bad_files_name_the_file_and_the_line)
{
    const mu_interpolation linear = MU_INTERPOLATION_LINEAR;
    expect_bad_file("", linear, 1, "empty file");
    expect_bad_file(GOOD_ROWS, linear, 1, "missing header");
    expect_bad_file("curve,x,z\n" GOOD_ROWS, linear, 1, "wrong column name");
    expect_bad_file("curve,x\n" GOOD_ROWS, linear, 1, "missing column");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,2\n", linear, 9, "a row with two fields");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,2,1.5,3\n", linear, 9, "a row with four fields");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,two,1.5\n", linear, 9, "non-numeric x");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,2,1.5x\n", linear, 9, "trailing characters after y");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,2,\n", linear, 9, "empty y");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,2,nan\n", linear, 9, "NaN y");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,inf,1.5\n", linear, 9, "infinite x");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,1,1.6\n", linear, 9, "repeated x");
    expect_bad_file(HEADER_ROW GOOD_ROWS "force_velocity,0.5,1.6\n", linear, 9, "decreasing x");
    expect_bad_file(HEADER_ROW GOOD_ROWS "tendon_force_length,1,1\n", linear, 9, "unknown curve");
    expect_bad_file(HEADER_ROW "active_force_length,0.5,0\n"
                               "passive_force_length,1,0\n"
                               "passive_force_length,2,1\n"
                               "force_velocity,-1,0\n"
                               "force_velocity,0,1\n",
                    linear, 2, "one knot of f_L for lines");
    expect_bad_file(HEADER_ROW GOOD_ROWS, MU_INTERPOLATION_STEFFEN, 3, "two knots of f_L for Steffen");
    expect_bad_file(HEADER_ROW "active_force_length,0.5,0\n"
                               "active_force_length,1.5,1\n"
                               "passive_force_length,1,0\n"
                               "passive_force_length,2,1\n",
                    linear, 5, "no f_V at all");
    char long_row[400];
    memset(long_row, '1', sizeof long_row);
    memcpy(long_row, "force_velocity,2,", 17);
    long_row[sizeof long_row - 2] = '\n';
    long_row[sizeof long_row - 1] = '\0';
    char long_file[600];
    snprintf(long_file, sizeof long_file, "%s%s%s", HEADER_ROW, GOOD_ROWS, long_row);
    expect_bad_file(long_file, linear, 9, "a line too long");
}

Test(curves, a_missing_file_is_named)
{
    scratch s;
    make_scratch(&s);
    mu_curves *curves = NULL;
    cr_expect_eq(mu_curves_create_tabulated(s.path, MU_INTERPOLATION_LINEAR, &curves), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(curves);
    cr_expect_not_null(strstr(rb_last_error(), s.path), "message '%s' does not name the file", rb_last_error());
    cr_expect_eq(rmdir(s.directory), 0, "cannot remove %s", s.directory);
}

Test(curves, bad_arguments_fail)
{
    mu_curves *curves = NULL;
    cr_expect_eq(mu_curves_create_tabulated(NULL, MU_INTERPOLATION_LINEAR, &curves), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_curves_create_tabulated(SEED_TABLES, MU_INTERPOLATION_LINEAR, NULL), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_curves_create_tabulated(SEED_TABLES, (mu_interpolation)7, &curves), RB_ERR_INVALID_ARGUMENT);
    cr_expect_not_null(strstr(rb_last_error(), "interpolation"), "%s", rb_last_error());
    cr_expect_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, NULL), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_curves_create_analytic(NULL, &curves), RB_ERR_INVALID_ARGUMENT);
    const mu_analytic_curves good = mu_default_analytic_curves();
    cr_expect_eq(mu_curves_create_analytic(&good, NULL), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(curves);
}

Test(curves, bad_analytic_parameters_fail)
{
    const double bad_values[] = {0.0, -1.0, NAN, INFINITY};
    const char *names[] = {"width", "curvature", "eccentric_plateau", "passive_scale", "passive_rate"};
    for (size_t field = 0; field < 5; field++) {
        /* A plateau of 1 is also bad: f_V must rise while lengthening. */
        const size_t bad_count = field == 2 ? 5 : 4;
        for (size_t b = 0; b < bad_count; b++) {
            mu_analytic_curves p = mu_default_analytic_curves();
            const double value = b < 4 ? bad_values[b] : 1.0;
            double *fields[] = {&p.width, &p.curvature, &p.eccentric_plateau, &p.passive_scale, &p.passive_rate};
            *fields[field] = value;
            mu_curves *curves = NULL;
            const rb_status status = mu_curves_create_analytic(&p, &curves);
            cr_expect_eq(status, RB_ERR_INVALID_ARGUMENT, "%s = %g accepted", names[field], value);
            cr_expect_null(curves, "%s = %g: out is not NULL", names[field], value);
            cr_expect_not_null(strstr(rb_last_error(), names[field]), "%s = %g: message '%s' does not name it",
                               names[field], value, rb_last_error());
            mu_curves_destroy(curves);
        }
    }
}

Test(curves, destroy_accepts_null) { mu_curves_destroy(NULL); }
