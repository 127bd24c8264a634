/* SPDX-License-Identifier: MIT */
/* The Hill muscle's curves f_L, f_P and f_V, in
 * two kinds:
 *
 * - tabulated: the tables of Castanyer ("Implementació d'un model
 *   computacional de sistemes musculoesquelètics", 2023-24), digitised
 *   from Ross et al. 2018 (PLOS Comput Biol), interpolated by
 *   straight lines as Castanyer's (evaluated here) or by GSL's
 *   Steffen monotone cubic (Steffen 1990, Astron. Astrophys. 239:443),
 *   which is smooth yet never overshoots its knots; outside the table f_P
 *   and f_V keep their end values and f_L is 0;
 * - analytic: the Gaussian force-length of the MATLAB worksheet "1D
 *   Muscle Model based on the Hill 2-Element Model" (anonymous), exponential passive curve
 *   and Hill's (1938) hyperbola for shortening, joined at ṽ = 0 to an
 *   eccentric branch for lengthening (derived at analytic_velocity).
 *
 * The curves are read-only once made, so one set may serve many muscles
 * (and threads): GSL is called without an accelerator, whose cached
 * interval would be state written on every evaluation.
 */
#include <errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curve_table.h"
#include "data_file.h"
#include "mu/curves.h"

struct mu_curves {
    bool tabulated;
    bool linear; /* tabulated, straight lines between the knots */
    /* Tabulated: the knots and GSL's interpolants over them. */
    mu_curve_table tables[MU_CURVE_KIND_COUNT];
    gsl_interp *interpolants[MU_CURVE_KIND_COUNT];
    /* Analytic: the parameters, and the hyperbola's slope at ṽ = 0, where
     * the eccentric branch starts. */
    mu_analytic_curves analytic;
    double isometric_slope;
};

mu_analytic_curves mu_default_analytic_curves(void)
{
    /* The MATLAB worksheet's constants: SK = 0.25; a/F0 = 0.25 N / 5 N;
     * c = 0.01, d = 10. The plateau is ours (the worksheet has no
     * lengthening branch); 1.5 lies in the physiological 1.4-1.8. */
    return (mu_analytic_curves){
        .width = 0.25,
        .curvature = 0.05,
        .eccentric_plateau = 1.5,
        .passive_scale = 0.01,
        .passive_rate = 10.0,
    };
}

/* The tabulated curves of the table read from `file`, named `path` in
 * messages. */
/* `f` is the API function called, for its messages. */
static rb_status create_tabulated(const char *f, const char *path, FILE *file, mu_interpolation interpolation,
                                  mu_curves **out)
{
    const gsl_interp_type *type = NULL;
    const char *type_name = NULL;
    switch (interpolation) {
    case MU_INTERPOLATION_LINEAR:
        type = gsl_interp_linear;
        type_name = "linear";
        break;
    case MU_INTERPOLATION_STEFFEN:
        type = gsl_interp_steffen;
        type_name = "Steffen";
        break;
    default:
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: interpolation is %d, expected MU_INTERPOLATION_LINEAR or MU_INTERPOLATION_STEFFEN",
                               f, (int)interpolation);
    }
    mu_curves *curves = calloc(1, sizeof *curves);
    if (curves == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    }
    curves->tabulated = true;
    curves->linear = interpolation == MU_INTERPOLATION_LINEAR;
    /* The reader asks for GSL's own minimum (2 knots for lines, 3 for
     * Steffen) and strictly increasing x, the two things gsl_interp_alloc
     * and gsl_interp_init reject, so neither can fail below but for memory
     * (on which GSL's default error handler aborts before returning NULL;
     * a program that turned the handler off gets our error). */
    rb_status status = mu_curve_tables_read(path, file, gsl_interp_type_min_size(type), type_name, curves->tables);
    for (size_t kind = 0; kind < MU_CURVE_KIND_COUNT && status == RB_OK; kind++) {
        const mu_curve_table *table = &curves->tables[kind];
        curves->interpolants[kind] = gsl_interp_alloc(type, table->count);
        if (curves->interpolants[kind] == NULL) {
            status = rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory for the interpolants of %s", f, path);
        } else {
            gsl_interp_init(curves->interpolants[kind], table->x, table->y, table->count);
        }
    }
    if (status != RB_OK) {
        mu_curves_destroy(curves);
        return status;
    }
    *out = curves;
    return RB_OK;
}

rb_status mu_curves_create_tabulated(const char *path, mu_interpolation interpolation, mu_curves **out)
{
    const char *f = "mu_curves_create_tabulated";
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: out is NULL", f);
    }
    *out = NULL;
    if (path == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: path is NULL", f);
    }
    FILE *file = fopen(path, "r");
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: cannot open the file: %s", f, path, strerror(errno));
    }
    rb_status status = create_tabulated(f, path, file, interpolation, out);
    fclose(file);
    return status;
}

rb_status mu_curves_create_seed_tables(mu_interpolation interpolation, mu_curves **out)
{
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_curves_create_seed_tables: out is NULL");
    }
    *out = NULL;
    mu_data_file data;
    rb_status status = mu_data_file_open(MU_CURVE_TABLE_FILE, "mu_curves_create_seed_tables", &data);
    if (status != RB_OK) {
        return status;
    }
    status = create_tabulated("mu_curves_create_seed_tables", data.label, data.stream, interpolation, out);
    mu_data_file_close(&data);
    return status;
}

/* `value` is finite and above `minimum` (NaN fails too). */
static bool in_range(double value, double minimum) { return isfinite(value) && value > minimum; }

rb_status mu_curves_create_analytic(const mu_analytic_curves *parameters, mu_curves **out)
{
    const char *f = "mu_curves_create_analytic";
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: out is NULL", f);
    }
    *out = NULL;
    if (parameters == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: parameters is NULL", f);
    }
    const mu_analytic_curves p = *parameters;
    if (!in_range(p.width, 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: width is %g, expected a finite SK > 0 (the Hill worksheet's: 0.25)", f, p.width);
    }
    if (!in_range(p.curvature, 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: curvature is %g, expected a finite a/F0 > 0 (the Hill worksheet's: 0.05)", f,
                               p.curvature);
    }
    if (!in_range(p.eccentric_plateau, 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: eccentric_plateau is %g, expected a finite f_V limit > 1 (default 1.5)", f,
                               p.eccentric_plateau);
    }
    if (!in_range(p.passive_scale, 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: passive_scale is %g, expected a finite c > 0 (the Hill worksheet's: 0.01)", f,
                               p.passive_scale);
    }
    if (!in_range(p.passive_rate, 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: passive_rate is %g, expected a finite d > 0 (the Hill worksheet's: 10)", f,
                               p.passive_rate);
    }
    mu_curves *curves = calloc(1, sizeof *curves);
    if (curves == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    }
    curves->analytic = p;
    /* d f_V/d ṽ of the hyperbola at ṽ = 0: (1 + k)/k, see analytic_velocity. */
    curves->isometric_slope = (1.0 + p.curvature) / p.curvature;
    *out = curves;
    return RB_OK;
}

void mu_curves_destroy(mu_curves *curves)
{
    if (curves == NULL) {
        return;
    }
    for (size_t kind = 0; kind < MU_CURVE_KIND_COUNT; kind++) {
        gsl_interp_free(curves->interpolants[kind]);
    }
    mu_curve_tables_free(curves->tables);
    free(curves);
}

_Static_assert(sizeof(((mu_curve_hint *)0)->interval) / sizeof(size_t) == MU_CURVE_KIND_COUNT,
               "a hint holds one interval per table");

/* GSL's accelerator for a look-up: the hint's interval for this table
 * (the search then starts there), or none. A hint made for a longer
 * table falls back to the first interval. */
static gsl_interp_accel *start_lookup(const mu_curves *curves, mu_curve_kind kind, const mu_curve_hint *hint,
                                      gsl_interp_accel *accel)
{
    if (hint == NULL) {
        return NULL;
    }
    size_t interval = hint->interval[kind];
    *accel = (gsl_interp_accel){.cache = interval + 1 < curves->tables[kind].count ? interval : 0};
    return accel;
}

static void end_lookup(mu_curve_kind kind, mu_curve_hint *hint, const gsl_interp_accel *accel)
{
    if (hint != NULL) {
        hint->interval[kind] = accel->cache;
    }
}

/* The interval [x_i, x_i+1) that holds x, for x_0 <= x < x_last, by
 * bisection on the side of the hint's interval `start` where x lies,
 * keeping x_lo <= x < x_hi. The knots rise strictly, so the interval is
 * unique: it is the one GSL's accelerated search finds, and a hint serves
 * both. */
static size_t search_interval(const mu_curve_table *table, size_t start, double x)
{
    size_t lo = 0;
    size_t hi = table->count - 1;
    if (start + 1 < table->count) {
        if (x < table->x[start]) {
            hi = start;
        } else {
            lo = start;
        }
    }
    while (hi > lo + 1) {
        const size_t middle = lo + (hi - lo) / 2;
        if (table->x[middle] > x) {
            hi = middle;
        } else {
            lo = middle;
        }
    }
    return lo;
}

/* The interval that holds x (x_0 <= x < x_last): the hint's interval
 * `start` when x is still in it, as it mostly is (a muscle moves little
 * between two look-ups), at the cost of two comparisons; else the
 * search. */
static inline size_t find_interval(const mu_curve_table *table, size_t start, double x)
{
    if (start + 1 < table->count && x >= table->x[start] && x < table->x[start + 1]) {
        return start;
    }
    return search_interval(table, start, x);
}

/* The straight line between the knots around x (x_0 <= x < x_last), and
 * its slope, in the hint's interval, which it updates. The value is
 * y_i + (x - x_i)/(x_i+1 - x_i)·(y_i+1 - y_i), evaluated in that order,
 * as GSL's linear interpolant does, so both give the same bits. */
static size_t linear_interval(const mu_curves *curves, mu_curve_kind kind, mu_curve_hint *hint, double x)
{
    const size_t interval = find_interval(&curves->tables[kind], hint != NULL ? hint->interval[kind] : 0, x);
    if (hint != NULL) {
        hint->interval[kind] = interval;
    }
    return interval;
}

static double linear_value(const mu_curves *curves, mu_curve_kind kind, mu_curve_hint *hint, double x)
{
    const mu_curve_table *table = &curves->tables[kind];
    const size_t i = linear_interval(curves, kind, hint, x);
    return table->y[i] + (x - table->x[i]) / (table->x[i + 1] - table->x[i]) * (table->y[i + 1] - table->y[i]);
}

static double linear_slope(const mu_curves *curves, mu_curve_kind kind, mu_curve_hint *hint, double x)
{
    const mu_curve_table *table = &curves->tables[kind];
    const size_t i = linear_interval(curves, kind, hint, x);
    return (table->y[i + 1] - table->y[i]) / (table->x[i + 1] - table->x[i]);
}

/* The interpolant at x, and never below 0: a muscle only pulls, and a
 * hand-edited table may dip below (the original report's annex prints
 * -0.001 for the first passive knots). Outside the table f_P and f_V keep
 * their end values, but f_L is 0: the seed table ends at 0.3422 and
 * 1.7033 with 0.0031 and 0.0020, the digitisation's floor rather than a
 * force, and fibres stretched or shortened beyond where the measured curve
 * ends no longer develop active force (Gordon, Huxley and Julian, "The
 * variation in isometric tension with sarcomere length in vertebrate
 * muscle fibres", 1966). */
static double tabulated_value(const mu_curves *curves, mu_curve_kind kind, mu_curve_hint *hint, double x)
{
    const mu_curve_table *table = &curves->tables[kind];
    const size_t last = table->count - 1;
    double y = 0.0;
    if (kind == MU_CURVE_ACTIVE_LENGTH && (x < table->x[0] || x > table->x[last])) {
        y = 0.0;
    } else if (x <= table->x[0]) {
        y = table->y[0];
    } else if (x >= table->x[last]) {
        y = table->y[last];
    } else if (curves->linear) {
        y = linear_value(curves, kind, hint, x);
    } else {
        gsl_interp_accel accel;
        y = gsl_interp_eval(curves->interpolants[kind], table->x, table->y, x,
                            start_lookup(curves, kind, hint, &accel));
        end_lookup(kind, hint, &accel);
    }
    return y < 0.0 ? 0.0 : y;
}

/* The interpolant's derivative at x; 0 outside the table, where the curve
 * is clamped flat. Negative slopes are raised to 0: the muscle uses the
 * slope as a damping coefficient, and a negative one would feed energy in
 * (the f_V table's last knots fall by 0.0014, digitisation noise). At a
 * knot of the linear table this is one side's slope. */
static double tabulated_slope(const mu_curves *curves, mu_curve_kind kind, mu_curve_hint *hint, double x)
{
    const mu_curve_table *table = &curves->tables[kind];
    if (!(x > table->x[0] && x < table->x[table->count - 1])) {
        return 0.0;
    }
    double slope = 0.0;
    if (curves->linear) {
        slope = linear_slope(curves, kind, hint, x);
    } else {
        gsl_interp_accel accel;
        slope = gsl_interp_eval_deriv(curves->interpolants[kind], table->x, table->y, x,
                                      start_lookup(curves, kind, hint, &accel));
        end_lookup(kind, hint, &accel);
    }
    return slope < 0.0 ? 0.0 : slope;
}

/* Analytic f_V, with k = a/F0 (curvature) and P the eccentric plateau.
 *
 * Shortening (ṽ <= 0), the MATLAB worksheet's hyperbola (Hill 1938) in the shortening
 * speed s = -ṽ:
 *   f_V = (1 - s)/(1 + s/k) = k(1 - s)/(k + s)   for 0 <= s < 1 (0 from s = 1
 *   on: velocity()).
 * Its slope: d f_V/ds = k·(-(k + s) - (1 - s))/(k + s)² = -k(1 + k)/(k + s)²,
 * so d f_V/dṽ = k(1 + k)/(k - ṽ)², which is s0 = (1 + k)/k at ṽ = 0 (21 for
 * k = 0.05).
 *
 * Lengthening (ṽ > 0): the hyperbola cannot be continued (it is singular
 * at ṽ = k), so we join it to
 *   f_V = P - (P - 1)·exp(-s0·ṽ/(P - 1)).
 * It gives f_V(0) = 1 and d f_V/dṽ = s0·exp(-s0·ṽ/(P - 1)), which is s0 at
 * 0 (so f_V is C¹ there), positive (monotone), and tends to P from below
 * (bounded). It needs no parameter beyond the plateau; its rise length
 * (P - 1)/s0 = 0.024 for the defaults matches the tabulated curve, which is
 * at 1.316 at ṽ = 0.027 where this branch gives 1.341. It is evaluated as
 * 1 - (P - 1)·expm1(-s0·ṽ/(P - 1)), the same value without cancellation
 * near ṽ = 0. */
static double analytic_velocity(const mu_curves *curves, double v)
{
    const double k = curves->analytic.curvature;
    if (v <= 0.0) {
        const double s = -v;
        return (1.0 - s) / (1.0 + s / k);
    }
    const double rise = curves->analytic.eccentric_plateau - 1.0;
    return 1.0 - rise * expm1(-curves->isometric_slope * v / rise);
}

/* d f_V/dṽ of analytic_velocity (derived there). */
static double analytic_velocity_slope(const mu_curves *curves, double v)
{
    const double k = curves->analytic.curvature;
    if (v <= 0.0) {
        return k * (1.0 + k) / ((k - v) * (k - v));
    }
    const double rise = curves->analytic.eccentric_plateau - 1.0;
    return curves->isometric_slope * exp(-curves->isometric_slope * v / rise);
}

/* NULL curves or a NaN input gives NaN (visible, rather than a plausible
 * force), with the error recorded in the name of the function called. */
static bool refuse_lookup(const char *function, const mu_curves *curves, const char *name, double x)
{
    if (curves == NULL) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: curves is NULL", function);
        return true;
    }
    if (isnan(x)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is NaN, expected a number", function, name);
        return true;
    }
    return false;
}

static double active_length(const mu_curves *curves, mu_curve_hint *hint, double normalized_length)
{
    if (curves->tabulated) {
        return tabulated_value(curves, MU_CURVE_ACTIVE_LENGTH, hint, normalized_length);
    }
    /* The MATLAB worksheet's (Challis 1994 after Hatze 1981): a Gaussian
     * of width SK. */
    const double z = (normalized_length - 1.0) / curves->analytic.width;
    return exp(-z * z);
}

static double passive_length(const mu_curves *curves, mu_curve_hint *hint, double normalized_length)
{
    if (curves->tabulated) {
        return tabulated_value(curves, MU_CURVE_PASSIVE_LENGTH, hint, normalized_length);
    }
    /* The MATLAB worksheet's: c·(exp(d·(l̃ - 1)) - 1), counted only where positive, that
     * is for l̃ > 1; expm1 keeps its digits just above l̃ = 1. Past l̃ = 2
     * (220 Fmax for the defaults, twice any fibre's working length) it
     * goes on as the straight line with the exponential's slope there, so
     * that a model that has come apart pulls with a large but finite force
     * rather than exp's overflow to infinity from l̃ = 72. A steep d moves
     * the join closer, to where d·(l̃ - 1) = 100. */
    const double c = curves->analytic.passive_scale, d = curves->analytic.passive_rate;
    if (normalized_length <= 1.0) {
        return 0.0;
    }
    const double join = 1.0 + fmin(1.0, 100.0 / d);
    if (normalized_length <= join) {
        return c * expm1(d * (normalized_length - 1.0));
    }
    return c * expm1(d * (join - 1.0)) + c * d * exp(d * (join - 1.0)) * (normalized_length - join);
}

/* A muscle shortening at Vmax or faster exerts no active force, in every
 * set: the hyperbola reaches 0 at ṽ = -1 and would turn negative, and the
 * seed table's first knot, (-1.0025, 0.0055), is the digitisation's floor.
 * So the tabulated f_V steps down by 0.0055 at ṽ = -1. */
#define VMAX_SHORTENING (-1.0)

static double velocity(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity)
{
    if (normalized_velocity <= VMAX_SHORTENING) {
        return 0.0;
    }
    if (curves->tabulated) {
        return tabulated_value(curves, MU_CURVE_VELOCITY, hint, normalized_velocity);
    }
    return analytic_velocity(curves, normalized_velocity);
}

static double velocity_slope(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity)
{
    if (normalized_velocity <= VMAX_SHORTENING) {
        return 0.0;
    }
    if (curves->tabulated) {
        return tabulated_slope(curves, MU_CURVE_VELOCITY, hint, normalized_velocity);
    }
    return analytic_velocity_slope(curves, normalized_velocity);
}

/* The line of interval i at x and its slope, each clamped at 0. */
static inline double line_and_slope(const mu_curve_table *table, size_t i, double x, double *slope)
{
    const double rise = table->y[i + 1] - table->y[i];
    const double run = table->x[i + 1] - table->x[i];
    const double line_slope = rise / run;
    const double value = table->y[i] + (x - table->x[i]) / run * rise; /* linear_value's order */
    *slope = line_slope < 0.0 ? 0.0 : line_slope;
    return value < 0.0 ? 0.0 : value;
}

/* f_V and its slope at one ṽ, as velocity() and velocity_slope() give
 * them. A straight-line table finds the interval once: the slope inside
 * the table is the line's between the knots the value used, and outside
 * it (or at its ends) 0, while the value is clamped to the end's. */
static double velocity_and_slope(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity,
                                 double *slope)
{
    const mu_curve_table *table = &curves->tables[MU_CURVE_VELOCITY];
    const double x = normalized_velocity;
    if (x <= VMAX_SHORTENING || !curves->tabulated || !curves->linear ||
        !(x > table->x[0] && x < table->x[table->count - 1])) {
        const double value = velocity(curves, hint, x);
        *slope = velocity_slope(curves, hint, x);
        return value;
    }
    return line_and_slope(table, linear_interval(curves, MU_CURVE_VELOCITY, hint, x), x, slope);
}

/* The hinted look-up's common case: a straight-line table and x strictly
 * inside the hint's interval, x_i < x < x_i+1, where a muscle's next
 * look-up mostly falls. Then x_0 < x < x_last, so no end of the table
 * (nor f_L's zero outside it) applies, and the value is the line's,
 * clamped at 0, as tabulated_value gives it; the tests of the ends, and
 * the check for NaN (which fails x_i < x), are skipped. Any other x, a
 * knot itself included, takes the full look-up. */
static inline bool within_hint(const mu_curves *curves, mu_curve_kind kind, const mu_curve_hint *hint, double x)
{
    if (curves == NULL || hint == NULL || !curves->linear) {
        return false;
    }
    const mu_curve_table *table = &curves->tables[kind];
    const size_t i = hint->interval[kind];
    return i + 1 < table->count && x > table->x[i] && x < table->x[i + 1];
}

/* The line of the hint's interval at x (within_hint holds), clamped at 0. */
static inline double hinted_line(const mu_curves *curves, mu_curve_kind kind, const mu_curve_hint *hint, double x)
{
    const mu_curve_table *table = &curves->tables[kind];
    const size_t i = hint->interval[kind];
    const double y =
        table->y[i] + (x - table->x[i]) / (table->x[i + 1] - table->x[i]) * (table->y[i + 1] - table->y[i]);
    return y < 0.0 ? 0.0 : y;
}

double mu_curve_active_length_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_length)
{
    if (within_hint(curves, MU_CURVE_ACTIVE_LENGTH, hint, normalized_length)) {
        return hinted_line(curves, MU_CURVE_ACTIVE_LENGTH, hint, normalized_length);
    }
    return refuse_lookup("mu_curve_active_length_hinted", curves, "normalized_length", normalized_length)
               ? NAN
               : active_length(curves, hint, normalized_length);
}

double mu_curve_active_length(const mu_curves *curves, double normalized_length)
{
    return refuse_lookup("mu_curve_active_length", curves, "normalized_length", normalized_length)
               ? NAN
               : active_length(curves, NULL, normalized_length);
}

double mu_curve_passive_length_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_length)
{
    if (within_hint(curves, MU_CURVE_PASSIVE_LENGTH, hint, normalized_length)) {
        return hinted_line(curves, MU_CURVE_PASSIVE_LENGTH, hint, normalized_length);
    }
    return refuse_lookup("mu_curve_passive_length_hinted", curves, "normalized_length", normalized_length)
               ? NAN
               : passive_length(curves, hint, normalized_length);
}

double mu_curve_passive_length(const mu_curves *curves, double normalized_length)
{
    return refuse_lookup("mu_curve_passive_length", curves, "normalized_length", normalized_length)
               ? NAN
               : passive_length(curves, NULL, normalized_length);
}

double mu_curve_velocity_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity)
{
    return refuse_lookup("mu_curve_velocity_hinted", curves, "normalized_velocity", normalized_velocity)
               ? NAN
               : velocity(curves, hint, normalized_velocity);
}

double mu_curve_velocity(const mu_curves *curves, double normalized_velocity)
{
    return refuse_lookup("mu_curve_velocity", curves, "normalized_velocity", normalized_velocity)
               ? NAN
               : velocity(curves, NULL, normalized_velocity);
}

double mu_curve_velocity_slope_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity)
{
    return refuse_lookup("mu_curve_velocity_slope_hinted", curves, "normalized_velocity", normalized_velocity)
               ? NAN
               : velocity_slope(curves, hint, normalized_velocity);
}

double mu_curve_velocity_slope(const mu_curves *curves, double normalized_velocity)
{
    return refuse_lookup("mu_curve_velocity_slope", curves, "normalized_velocity", normalized_velocity)
               ? NAN
               : velocity_slope(curves, NULL, normalized_velocity);
}

double mu_curve_velocity_and_slope_hinted(const mu_curves *curves, mu_curve_hint *hint, double normalized_velocity,
                                          double *slope)
{
    if (slope != NULL && normalized_velocity > VMAX_SHORTENING &&
        within_hint(curves, MU_CURVE_VELOCITY, hint, normalized_velocity)) {
        return line_and_slope(&curves->tables[MU_CURVE_VELOCITY], hint->interval[MU_CURVE_VELOCITY],
                              normalized_velocity, slope);
    }
    if (slope == NULL) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_curve_velocity_and_slope_hinted: slope is NULL");
        return NAN;
    }
    if (refuse_lookup("mu_curve_velocity_and_slope_hinted", curves, "normalized_velocity", normalized_velocity)) {
        *slope = NAN;
        return NAN;
    }
    return velocity_and_slope(curves, hint, normalized_velocity, slope);
}
