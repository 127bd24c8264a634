/* SPDX-License-Identifier: MIT */
/* The chart library (tools/chart) and the CSV tables it draws
 * (tools/io/csv_table): nice ticks against the 1-2-5 rule and the range
 * they must cover; PNG files of the asked size with the series' colour
 * in them, read back through Cairo; SVG files; degenerate data drawn
 * without failing; bad arguments refused with a message; a failed write
 * leaves nothing; CSV reading with quotes, CRLF and errors by line;
 * axis labels from column names. Logarithmic axes: decade and 1-2-5
 * ticks covering the range, points placed by their logarithm, values at
 * or below 0 refused by name; a table's rows split into series by a key
 * column, sorted by x or split into their front, against sets worked out
 * by hand; a column's cells as text with their lines.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <cairo.h>
#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "chart/chart.h"
#include "chart/chart_log_ticks.h"
#include "chart/chart_ticks.h"
#include "chart/column_label.h"
#include "chart/series_groups.h"
#include "io/csv_cells.h"
#include "io/csv_table.h"

/* ------------------------------------------------------------------ ticks */

/* Whether `step` is 1, 2 or 5 times a power of ten. */
static bool is_nice(double step)
{
    double mantissa = step / pow(10.0, floor(log10(step)));
    return fabs(mantissa - 1.0) < 1e-9 || fabs(mantissa - 2.0) < 1e-9 || fabs(mantissa - 5.0) < 1e-9 ||
           fabs(mantissa - 10.0) < 1e-9;
}

static void expect_covering_nice_ticks(double min, double max, int intervals)
{
    chart_ticks ticks;
    char error[256];
    cr_assert(chart_nice_ticks(min, max, intervals, &ticks, error, sizeof error), "[%g, %g]: %s", min, max, error);
    double first = chart_tick_value(&ticks, 0);
    double last = chart_tick_value(&ticks, ticks.count - 1);
    cr_expect(is_nice(ticks.step), "[%g, %g]: step %g is not 1, 2 or 5 x 10^k", min, max, ticks.step);
    double slack = 1e-9 * ticks.step; /* a tick's rounding (chart_ticks.h) */
    cr_expect(first <= min + slack && last >= max - slack, "[%g, %g]: ticks %g .. %g do not cover it", min, max, first,
              last);
    if (min < max) {
        /* No tick to spare at either end. */
        cr_expect(first + ticks.step > min && last - ticks.step < max, "[%g, %g]: ticks %g .. %g (step %g) too wide",
                  min, max, first, last, ticks.step);
        /* The nearest 1-2-5 step on a log scale is within a factor
         * sqrt(10)/2 ≈ 1.6 of the asked one, ±1 interval for the ends. */
        int count = ticks.count - 1;
        cr_expect(count >= intervals / 1.6 - 1.0 && count <= intervals * 1.6 + 2.0, "[%g, %g]: %d intervals for %d",
                  min, max, count, intervals);
    }
}

Test(chart_ticks, are_nice_and_cover_the_range)
{
    const double ranges[][2] = {
        {0.0, 1.0},       {0.0, 0.3},    {-1.0, 1.0},       {0.3, 0.7},    {-0.1395, 0.0255},
        {2.75, 5.5},      {0.0, 4400.0}, {1e-7, 3e-7},      {-5e6, 2.5e7}, {123.4, 125.7},
        {0.2942, 0.2962}, {-2.0, -1.0},  {1e-3, 1.0001e-3},
    };
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; ++k) {
        for (int intervals = 2; intervals <= 10; intervals += 4) {
            expect_covering_nice_ticks(ranges[k][0], ranges[k][1], intervals);
        }
    }
    /* Pseudo-random ranges over 18 decades of width (from 1e-9 of the
     * centre's magnitude up: narrower ones count as equal ends). */
    unsigned long state = 12345;
    for (int k = 0; k < 2000; ++k) {
        state = state * 6364136223846793005UL + 1442695040888963407UL;
        double centre = ((double)(state >> 11) / 9007199254740992.0 - 0.5) * 2e3;
        state = state * 6364136223846793005UL + 1442695040888963407UL;
        double width = pow(10.0, ((double)(state >> 11) / 9007199254740992.0) * 18.0 - 6.0);
        expect_covering_nice_ticks(centre, centre + width, 2 + k % 9);
    }
}

Test(chart_ticks, equal_ends_get_a_range_around_the_value)
{
    chart_ticks ticks;
    cr_assert(chart_nice_ticks(3.0, 3.0, 5, &ticks, NULL, 0));
    cr_expect(chart_tick_value(&ticks, 0) <= 2.85 && chart_tick_value(&ticks, ticks.count - 1) >= 3.15);
    cr_assert(chart_nice_ticks(0.0, 0.0, 5, &ticks, NULL, 0));
    cr_expect(chart_tick_value(&ticks, 0) <= -1.0 && chart_tick_value(&ticks, ticks.count - 1) >= 1.0);
}

Test(chart_ticks, refuse_non_finite_or_reversed_ranges)
{
    chart_ticks ticks;
    char error[256] = "";
    cr_expect_not(chart_nice_ticks(NAN, 1.0, 5, &ticks, error, sizeof error));
    cr_expect(strstr(error, "chart_nice_ticks") != NULL, "message: %s", error);
    cr_expect_not(chart_nice_ticks(0.0, INFINITY, 5, &ticks, NULL, 0));
    cr_expect_not(chart_nice_ticks(2.0, 1.0, 5, &ticks, NULL, 0));
    cr_expect_not(chart_nice_ticks(0.0, 1.0, 0, &ticks, NULL, 0));
    cr_expect_not(chart_nice_ticks(0.0, 1.0, 5, NULL, NULL, 0));
}

/* Ranges at the ends of what a double holds: denormal values, a width
 * that overflows, constants, one sign only. Each must get finite,
 * increasing ticks of a 1-2-5 step whose labels read back as their values;
 * they cover the range but where the next tick out would not be finite
 * (no multiple of a 1-2-5 step reaches -DBL_MAX). */
Test(chart_ticks, any_finite_range_gets_finite_ordered_ticks)
{
    const double ranges[][2] = {
        {0.0, 5e-324},      {5e-324, 5e-324},     {-5e-324, 0.0},  {1e-320, 1e308},    {-DBL_MAX, DBL_MAX},
        {DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX}, {-1e308, 1e308}, {-3e-310, -1e-320}, {1e-310, 2e-310},
        {-5.0, -5.0},       {-DBL_MAX, -1e300},   {0.0, DBL_MIN},  {-DBL_MIN, 0.0},    {1e300, 1e308},
        {-1e-300, 1e-300},  {1e-300, 1e-300},     {0.0, 1e-305},   {1e307, DBL_MAX},   {-2e-308, 2e-308},
    };
    const int interval_counts[] = {1, 2, 5, 9, CHART_MAX_TICK_INTERVALS};
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; ++k) {
        for (size_t n = 0; n < sizeof interval_counts / sizeof interval_counts[0]; ++n) {
            const double min = ranges[k][0], max = ranges[k][1];
            const int intervals = interval_counts[n];
            chart_ticks ticks;
            char error[256] = "";
            cr_assert(chart_nice_ticks(min, max, intervals, &ticks, error, sizeof error), "[%g, %g] / %d: %s", min, max,
                      intervals, error);
            cr_assert(isfinite(ticks.step) && ticks.step > 0.0 && is_nice(ticks.step), "[%g, %g] / %d: step %g", min,
                      max, intervals, ticks.step);
            cr_assert(ticks.count >= 2 && ticks.count <= 2 * CHART_MAX_TICK_INTERVALS + 3, "[%g, %g] / %d: %d ticks",
                      min, max, intervals, ticks.count);
            double previous = -INFINITY;
            char label[64], previous_label[64] = "";
            for (int i = 0; i < ticks.count; ++i) {
                const double value = chart_tick_value(&ticks, i);
                cr_assert(isfinite(value) && value > previous, "[%g, %g] / %d: tick %d is %g after %g", min, max,
                          intervals, i, value, previous);
                chart_tick_label(&ticks, i, label, sizeof label);
                char *end = NULL;
                const double read = strtod(label, &end);
                cr_expect(end != label && *end == '\0' && fabs(read - value) <= 0.5 * ticks.step,
                          "[%g, %g] / %d: tick %d (%g) is labelled \"%s\"", min, max, intervals, i, value, label);
                cr_expect(strcmp(label, previous_label) != 0, "[%g, %g] / %d: two ticks read \"%s\"", min, max,
                          intervals, label);
                snprintf(previous_label, sizeof previous_label, "%s", label);
                previous = value;
            }
            const double first = chart_tick_value(&ticks, 0), last = chart_tick_value(&ticks, ticks.count - 1);
            const double below = (double)(ticks.first_index - 1) * ticks.step;
            const double above = (double)(ticks.first_index + ticks.count) * ticks.step;
            const double slack = 1e-9 * ticks.step; /* a tick's rounding (chart_ticks.h) */
            cr_expect(first <= min + slack || !isfinite(below), "[%g, %g] / %d: the first tick %g is above the minimum",
                      min, max, intervals, first);
            cr_expect(last >= max - slack || !isfinite(above), "[%g, %g] / %d: the last tick %g is below the maximum",
                      min, max, intervals, last);
        }
    }
}

Test(chart_ticks, labels_have_the_decimals_of_the_step)
{
    chart_ticks ticks;
    char label[64];
    cr_assert(chart_nice_ticks(0.0, 0.9, 9, &ticks, NULL, 0));
    cr_assert_float_eq(ticks.step, 0.1, 1e-15);
    chart_tick_label(&ticks, 3, label, sizeof label);
    cr_expect_str_eq(label, "0.3"); /* 3 × 0.1 is 0.30000000000000004 */
    cr_assert(chart_nice_ticks(-0.2, 0.2, 4, &ticks, NULL, 0));
    for (int i = 0; i < ticks.count; ++i) {
        chart_tick_label(&ticks, i, label, sizeof label);
        cr_expect(strcmp(label, "-0") != 0 && strcmp(label, "-0.0") != 0, "tick %d reads %s", i, label);
    }
    cr_assert(chart_nice_ticks(0.0, 4000.0, 4, &ticks, NULL, 0));
    chart_tick_label(&ticks, 1, label, sizeof label);
    cr_expect_str_eq(label, "1000");
    cr_assert(chart_nice_ticks(0.0, 3e7, 3, &ticks, NULL, 0));
    chart_tick_label(&ticks, 1, label, sizeof label);
    cr_expect_str_eq(label, "1e+07");
}

/* ------------------------------------------------------------ log ticks */

/* Whether v is 1, 2 or 5 times a power of ten (decades only: 1). */
static bool is_decade_tick(double v, bool decades_only)
{
    double mantissa = v / pow(10.0, floor(log10(v) + 1e-12));
    bool one = fabs(mantissa - 1.0) < 1e-9 || fabs(mantissa - 10.0) < 1e-9;
    return decades_only ? one : one || fabs(mantissa - 2.0) < 1e-9 || fabs(mantissa - 5.0) < 1e-9;
}

static void expect_covering_log_ticks(double min, double max, int intervals)
{
    chart_log_ticks ticks;
    char error[256];
    cr_assert(chart_log_ticks_make(min, max, intervals, &ticks, error, sizeof error), "[%g, %g]: %s", min, max, error);
    cr_assert(ticks.count >= 2 && ticks.count <= CHART_MAX_LOG_TICKS, "[%g, %g]: %d ticks", min, max, ticks.count);
    cr_expect(ticks.values[0] <= min * (1.0 + 1e-12) && ticks.values[ticks.count - 1] >= max * (1.0 - 1e-12),
              "[%g, %g]: ticks %g .. %g do not cover it", min, max, ticks.values[0], ticks.values[ticks.count - 1]);
    /* No tick to spare: the second is above min, the last but one below max. */
    cr_expect(ticks.values[1] > min && ticks.values[ticks.count - 2] < max, "[%g, %g]: ticks %g .. %g too wide", min,
              max, ticks.values[0], ticks.values[ticks.count - 1]);
    bool decades_only = true;
    for (int i = 0; i < ticks.count; ++i) {
        cr_expect(is_decade_tick(ticks.values[i], false), "[%g, %g]: tick %d is %g", min, max, i, ticks.values[i]);
        decades_only = decades_only && is_decade_tick(ticks.values[i], true);
        if (i > 0) {
            cr_expect_gt(ticks.values[i], ticks.values[i - 1], "[%g, %g]: ticks not increasing at %d", min, max, i);
        }
    }
    if (decades_only) {
        /* Evenly spaced decades, at most `intervals` + 1 intervals. */
        double ratio = ticks.values[1] / ticks.values[0];
        for (int i = 2; i < ticks.count; ++i) {
            cr_expect_float_eq(ticks.values[i] / ticks.values[i - 1], ratio, 1e-9 * ratio, "[%g, %g]: uneven at %d",
                               min, max, i);
        }
        cr_expect_leq(ticks.count, intervals + 2, "[%g, %g]: %d ticks for %d intervals", min, max, ticks.count,
                      intervals);
    } else {
        cr_expect_leq(ticks.count, intervals + 1, "[%g, %g]: %d ticks for %d intervals", min, max, ticks.count,
                      intervals);
    }
}

Test(chart_log_ticks, are_decades_or_1_2_5_and_cover_the_range)
{
    expect_covering_log_ticks(0.003, 0.05, 5);    /* 0.002 0.005 0.01 0.02 0.05 */
    expect_covering_log_ticks(2.0, 3.0, 5);       /* 2 5 */
    expect_covering_log_ticks(1.0, 100.0, 5);     /* 1 10 100: 1 2 5 .. 100 would be 6 intervals */
    expect_covering_log_ticks(6.4, 130.0, 10);    /* 5 10 20 50 100 200 */
    expect_covering_log_ticks(1e-5, 20.0, 10);    /* decades 1e-5 .. 100 */
    expect_covering_log_ticks(3.3e-5, 0.5, 10);   /* decades 1e-5 .. 1 */
    expect_covering_log_ticks(1e-300, 1e300, 10); /* every 60 decades */
    expect_covering_log_ticks(1e-12, 1e12, 4);    /* every 6 decades */
    expect_covering_log_ticks(0.9, 1e308, 10);
    chart_log_ticks ticks;
    cr_assert(chart_log_ticks_make(0.003, 0.05, 5, &ticks, NULL, 0));
    const double expected[] = {0.002, 0.005, 0.01, 0.02, 0.05};
    cr_assert_eq(ticks.count, 5);
    for (int i = 0; i < 5; ++i) {
        cr_expect_float_eq(ticks.values[i], expected[i], 1e-15, "tick %d: %g", i, ticks.values[i]);
    }
    cr_assert(chart_log_ticks_make(6.4, 130.0, 10, &ticks, NULL, 0));
    const double few_decades[] = {5.0, 10.0, 20.0, 50.0, 100.0, 200.0};
    cr_assert_eq(ticks.count, 6);
    for (int i = 0; i < 6; ++i) {
        cr_expect_float_eq(ticks.values[i], few_decades[i], 1e-12, "tick %d: %g", i, ticks.values[i]);
    }
    cr_assert(chart_log_ticks_make(1.0, 100.0, 5, &ticks, NULL, 0));
    cr_expect(ticks.count == 3 && ticks.values[1] == 10.0, "[1, 100] in 5 intervals: %d ticks", ticks.count);
    /* Equal ends get the ticks around them. */
    cr_assert(chart_log_ticks_make(7.0, 7.0, 5, &ticks, NULL, 0));
    cr_expect(ticks.count == 2 && ticks.values[0] == 5.0 && ticks.values[1] == 10.0, "[7, 7]: %d ticks, %g ..",
              ticks.count, ticks.values[0]);
    cr_assert(chart_log_ticks_make(100.0, 100.0, 5, &ticks, NULL, 0));
    cr_expect(ticks.count == 3 && ticks.values[0] == 50.0 && ticks.values[1] == 100.0 && ticks.values[2] == 200.0,
              "[100, 100]: %d ticks, %g ..", ticks.count, ticks.values[0]);
    /* A denormal minimum: the least decade a double has, short of it. */
    cr_assert(chart_log_ticks_make(5e-324, 1.0, 10, &ticks, NULL, 0));
    cr_expect(ticks.values[0] > 0.0 && isfinite(ticks.values[ticks.count - 1]));
}

Test(chart_log_ticks, refuse_ends_at_or_below_zero)
{
    chart_log_ticks ticks;
    char error[256] = "";
    const double bad[][2] = {{0.0, 1.0}, {-1.0, 10.0}, {2.0, 1.0}, {NAN, 1.0}, {1.0, INFINITY}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        cr_expect_not(chart_log_ticks_make(bad[k][0], bad[k][1], 5, &ticks, error, sizeof error), "[%g, %g]", bad[k][0],
                      bad[k][1]);
        cr_expect(strstr(error, "above 0") != NULL, "[%g, %g]: %s", bad[k][0], bad[k][1], error);
    }
    cr_expect_not(chart_log_ticks_make(1.0, 10.0, 0, &ticks, error, sizeof error));
    cr_expect(strstr(error, "intervals") != NULL, "%s", error);
}

Test(chart_log_ticks, labels_are_plain_or_powers_of_ten)
{
    const struct {
        double value;
        const char *label;
    } cases[] = {{0.001, "0.001"}, {0.002, "0.002"}, {0.5, "0.5"}, {1.0, "1"},         {20.0, "20"},    {1e4, "10000"},
                 {1e-4, "1e-4"},   {5e-5, "5e-5"},   {2e6, "2e6"}, {1e-300, "1e-300"}, {1e300, "1e300"}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char label[64];
        chart_log_tick_label(cases[k].value, label, sizeof label);
        cr_expect_str_eq(label, cases[k].label, "%g", cases[k].value);
    }
}

/* ------------------------------------------------------------------ files */

static char dir[] = "/tmp/sinew-chart-XXXXXX";

static void make_dir(void) { cr_assert_not_null(mkdtemp(dir)); }

static void path_in_dir(char *path, size_t size, const char *name) { snprintf(path, size, "%s/%s", dir, name); }

/* Pixels of a PNG whose colour is within 0.1 of rgb in each channel. */
static long pixels_of_colour(cairo_surface_t *image, const double rgb[3])
{
    cairo_surface_flush(image);
    const unsigned char *data = cairo_image_surface_get_data(image);
    int stride = cairo_image_surface_get_stride(image);
    long found = 0;
    for (int y = 0; y < cairo_image_surface_get_height(image); ++y) {
        const uint32_t *row = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);
        for (int x = 0; x < cairo_image_surface_get_width(image); ++x) {
            double r = ((row[x] >> 16) & 0xFF) / 255.0, g = ((row[x] >> 8) & 0xFF) / 255.0, b = (row[x] & 0xFF) / 255.0;
            found += fabs(r - rgb[0]) < 0.1 && fabs(g - rgb[1]) < 0.1 && fabs(b - rgb[2]) < 0.1;
        }
    }
    return found;
}

Test(chart_file, a_png_has_the_asked_size_and_draws_each_series_in_its_colour)
{
    make_dir();
    enum { N = 200 };
    double x[N], y[N], z[N];
    for (int i = 0; i < N; ++i) {
        x[i] = 0.01 * i;
        y[i] = sin(6.0 * x[i]);
        z[i] = 0.5 * cos(3.0 * x[i]);
    }
    chart_series series[2] = {{.label = "sin", .x = x, .y = y, .count = N},
                              {.label = "cos", .x = x, .y = z, .count = N}};
    chart plot = {.title = "test", .x_label = "time (s)", .y_label = "value (m)", .series = series, .series_count = 2};
    chart_figure figure = {.charts = &plot, .chart_count = 1, .columns = 1, .width = 640, .height = 400};
    char path[512], error[CHART_ERROR_SIZE];
    path_in_dir(path, sizeof path, "plot.png");
    cr_assert(chart_write_png(&figure, path, error, sizeof error), "%s", error);

    cairo_surface_t *image = cairo_image_surface_create_from_png(path);
    cr_assert_eq(cairo_surface_status(image), CAIRO_STATUS_SUCCESS, "not a PNG: %s", path);
    cr_expect_eq(cairo_image_surface_get_width(image), 640);
    cr_expect_eq(cairo_image_surface_get_height(image), 400);
    const double white[3] = {1.0, 1.0, 1.0};
    long pixels = 640L * 400L;
    long background = pixels_of_colour(image, white);
    cr_expect(background < pixels && background > pixels / 2, "%ld of %ld pixels white: blank or not a chart",
              background, pixels);
    for (int s = 0; s < 2; ++s) {
        double rgb[3];
        chart_series_colour(s, rgb);
        /* A 1.5 px line across ~500 px of plot shows in hundreds of pixels. */
        long drawn = pixels_of_colour(image, rgb);
        cr_expect(drawn > 300, "series %d: %ld pixels of its colour", s, drawn);
    }
    cairo_surface_destroy(image);
    remove(path);
    rmdir(dir);
}

Test(chart_file, an_svg_is_written_with_its_size)
{
    make_dir();
    double x[3] = {0.0, 1.0, 2.0}, y[3] = {1.0, 3.0, 2.0};
    chart_series series = {.label = "s", .x = x, .y = y, .count = 3};
    chart plot = {.series = &series, .series_count = 1};
    chart_figure figure = {.charts = &plot, .chart_count = 1, .columns = 1, .width = 500, .height = 300};
    char path[512], error[CHART_ERROR_SIZE];
    path_in_dir(path, sizeof path, "plot.SVG");
    cr_assert(chart_write_file(&figure, path, error, sizeof error), "%s", error);
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f);
    static char text[1 << 16];
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    cr_expect(strstr(text, "<svg") != NULL, "no <svg element");
    cr_expect(strstr(text, "width=\"500") != NULL && strstr(text, "height=\"300") != NULL, "size not 500 x 300");
    cr_expect(strstr(text, "</svg>") != NULL, "the SVG is not finished");
    remove(path);
    rmdir(dir);
}

Test(chart_file, a_failed_write_leaves_no_file)
{
    make_dir();
    chart plot = {.series_count = 0};
    chart_figure figure = {.charts = &plot, .chart_count = 1, .columns = 1, .width = 100, .height = 100};
    char path[512], error[CHART_ERROR_SIZE] = "";
    snprintf(path, sizeof path, "%s/missing/plot.png", dir);
    cr_expect_not(chart_write_png(&figure, path, error, sizeof error));
    cr_expect(strstr(error, "missing/plot.png") != NULL, "message: %s", error);
    path_in_dir(path, sizeof path, "plot.jpg");
    cr_expect_not(chart_write_file(&figure, path, error, sizeof error));
    cr_expect(strstr(error, ".png or .svg") != NULL, "message: %s", error);
    cr_expect_neq(access(path, F_OK), 0);
    /* A chart that cannot be drawn: nothing written. */
    plot.series_count = -1;
    path_in_dir(path, sizeof path, "plot.png");
    cr_expect_not(chart_write_png(&figure, path, error, sizeof error));
    cr_expect_neq(access(path, F_OK), 0, "a failed write left %s", path);
    rmdir(dir);
}

/* --------------------------------------------------------- degenerate data */

static bool draw_to_image(const chart *plot, char *error, size_t error_size)
{
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 300, 200);
    cairo_t *cr = cairo_create(surface);
    bool ok = chart_draw(plot, cr, 0.0, 0.0, 300.0, 200.0, error, error_size);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    return ok;
}

Test(chart_draw, degenerate_data_is_drawn)
{
    double one_x[1] = {2.0}, one_y[1] = {5.0};
    double flat_x[4] = {0.0, 1.0, 2.0, 3.0}, flat_y[4] = {7.0, 7.0, 7.0, 7.0};
    double holes_x[6] = {0.0, 1.0, NAN, 3.0, INFINITY, 5.0}, holes_y[6] = {1.0, NAN, 2.0, 3.0, 4.0, -INFINITY};
    double nan_y[3] = {NAN, NAN, NAN};
    double same_x[3] = {1.0, 1.0, 1.0}, huge_y[3] = {1e300, -1e300, 0.0};
    double denormal_y[2] = {0.0, 5e-324};
    double extreme_x[3] = {1e-320, 1.0, 1e308}, extreme_y[3] = {-DBL_MAX, 0.0, DBL_MAX};
    const chart_series cases[][2] = {
        {{.label = "empty", .count = 0}, {.label = NULL, .count = 0}},
        {{.label = "one point", .x = one_x, .y = one_y, .count = 1}, {.count = 0}},
        {{.label = "constant", .x = flat_x, .y = flat_y, .count = 4}, {.count = 0}},
        {{.label = "holes", .x = holes_x, .y = holes_y, .count = 6, .marker_radius = 2.0}, {.count = 0}},
        {{.label = "all NaN", .x = flat_x, .y = nan_y, .count = 3}, {.label = "", .x = one_x, .y = one_y, .count = 1}},
        {{.label = "vertical", .x = same_x, .y = flat_y, .count = 3}, {.count = 0}},
        {{.label = "too wide", .x = flat_x, .y = huge_y, .count = 3}, {.count = 0}},
        {{.label = "denormal", .x = flat_x, .y = denormal_y, .count = 2}, {.count = 0}},
        {{.label = "widest", .x = extreme_x, .y = extreme_y, .count = 3}, {.count = 0}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        chart plot = {
            .title = cases[k][0].label, .x_label = "x", .y_label = "y", .series = cases[k], .series_count = 2};
        char error[CHART_ERROR_SIZE] = "";
        cr_expect(draw_to_image(&plot, error, sizeof error), "case %zu (%s): %s", k, cases[k][0].label, error);
    }
    chart nothing = {.series_count = 0};
    cr_expect(draw_to_image(&nothing, NULL, 0));
    /* A fixed range with the data outside it. */
    chart fixed = {.series = cases[2], .series_count = 1, .y_range = {.fixed = true, .min = -1.0, .max = 1.0}};
    cr_expect(draw_to_image(&fixed, NULL, 0));
}

/* Names come from files: a CSV header in Latin-1 or cut inside a character
 * is not UTF-8, which Cairo refuses, putting the whole cairo_t in error.
 * Such text is drawn with U+FFFD for the bytes that start no character
 * (found by fuzz/fuzz_csv_chart). */
Test(chart_draw, text_that_is_not_utf8_is_drawn)
{
    double x[2] = {0.0, 1.0}, y[2] = {1.0, 2.0};
    const char *texts[] = {
        "temperature \xB0"
        "C",                                /* Latin-1 degree sign */
        "\xC3",                             /* a lead byte at the end */
        "over\xC0\xAFlong",                 /* an overlong '/' */
        "surrogate \xED\xA0\x80",           /* U+D800 */
        "beyond \xF4\x90\x80\x80",          /* U+110000 */
        "noncharacter \xEF\xBF\xBE",        /* U+FFFE, which Cairo refuses too */
        "\xFF\xFE\x80 and \xE2\x82\xAC ok", /* stray bytes, then a valid euro sign */
        "\xFF\xBB\xBF \xF8\x80\x80",        /* no lead byte past 0xF7, whatever follows */
    };
    for (size_t k = 0; k < sizeof texts / sizeof texts[0]; ++k) {
        chart_series series = {.label = texts[k], .x = x, .y = y, .count = 2};
        chart plot = {
            .title = texts[k], .x_label = texts[k], .y_label = texts[k], .series = &series, .series_count = 1};
        char error[CHART_ERROR_SIZE] = "";
        cr_expect(draw_to_image(&plot, error, sizeof error), "text %zu: %s", k, error);
    }
}

Test(chart_draw, bad_arguments_are_refused_with_a_message)
{
    char error[CHART_ERROR_SIZE] = "";
    cr_expect_not(draw_to_image(NULL, error, sizeof error));
    cr_expect(strstr(error, "chart_draw") != NULL && strstr(error, "chart") != NULL, "message: %s", error);
    chart plot = {.series_count = CHART_MAX_SERIES + 1};
    cr_expect_not(draw_to_image(&plot, error, sizeof error));
    cr_expect(strstr(error, "series_count") != NULL, "message: %s", error);
    chart_series no_data = {.label = "x", .count = 3};
    plot = (chart){.series = &no_data, .series_count = 1};
    cr_expect_not(draw_to_image(&plot, error, sizeof error));
    cr_expect(strstr(error, "series[0]") != NULL, "message: %s", error);
    plot = (chart){.series_count = 0, .x_range = {.fixed = true, .min = 1.0, .max = 1.0}};
    cr_expect_not(draw_to_image(&plot, error, sizeof error));
    cr_expect(strstr(error, "x_range") != NULL, "message: %s", error);

    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 10, 10);
    cairo_t *cr = cairo_create(surface);
    chart empty = {.series_count = 0};
    cr_expect_not(chart_draw(&empty, cr, 0.0, 0.0, 0.0, 10.0, error, sizeof error));
    cr_expect(strstr(error, "rectangle") != NULL, "message: %s", error);
    cr_expect_not(chart_draw(&empty, cr, 0.0, NAN, 10.0, 10.0, NULL, 0));
    cr_expect_not(chart_draw(&empty, NULL, 0.0, 0.0, 10.0, 10.0, NULL, 0));
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    chart_figure figure = {.charts = &empty, .chart_count = 1, .columns = 0, .width = 10, .height = 10};
    surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 10, 10);
    cr = cairo_create(surface);
    cr_expect_not(chart_figure_draw(&figure, cr, error, sizeof error));
    cr_expect(strstr(error, "columns") != NULL, "message: %s", error);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
}

/* ------------------------------------------------------------- CSV tables */

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fputs(text, f);
    fclose(f);
}

Test(csv_table, reads_quoted_names_crlf_blank_lines_and_text_columns)
{
    make_dir();
    char path[512], error[1024];
    path_in_dir(path, sizeof path, "t.csv");
    write_text(path, "time_s,\"a, \"\"quoted\"\" name [N]\",label,gap\r\n"
                     "0,1.5,x,\r\n"
                     "\r\n"
                     "0.5, -2e3 ,y,nan\r\n");
    csv_table table;
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    cr_expect_eq(table.column_count, 4);
    cr_expect_eq(table.row_count, 2);
    cr_expect_eq(csv_table_find(&table, "a, \"quoted\" name [N]"), 1);
    cr_expect_float_eq(table.columns[1].values[1], -2000.0, 1e-12);
    cr_expect(table.columns[0].numeric && table.columns[1].numeric && table.columns[3].numeric);
    cr_expect(isnan(table.columns[3].values[0]) && isnan(table.columns[3].values[1]));
    cr_expect_not(table.columns[2].numeric);
    cr_expect_eq(table.columns[2].bad_line, 2);
    cr_expect_str_eq(table.columns[2].bad_cell, "x");
    csv_table_free(&table);

    /* Written back and read again: the same numbers. */
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    char copy[512];
    path_in_dir(copy, sizeof copy, "copy.csv");
    cr_assert(csv_table_write(&table, copy, error, sizeof error), "%s", error);
    csv_table again;
    cr_assert(csv_table_read(copy, &again, error, sizeof error), "%s", error);
    cr_expect_eq(csv_table_find(&again, "a, \"quoted\" name [N]"), 1);
    cr_expect_float_eq(again.columns[1].values[0], 1.5, 1e-12);
    csv_table_free(&table);
    csv_table_free(&again);
    remove(copy);
    remove(path);
    rmdir(dir);
}

Test(csv_table, errors_name_the_file_and_the_line)
{
    make_dir();
    char path[512], error[1024] = "";
    path_in_dir(path, sizeof path, "bad.csv");
    const struct {
        const char *text;
        const char *expected;
    } cases[] = {
        {"", "empty file"},
        {"a,b\n1,2\n3\n", "bad.csv:3: 1 fields, the header has 2"},
        {"a,b\n1,2,3\n", "bad.csv:2: 3 fields, the header has 2"},
        {"a,\"b\n1,2\n", "bad.csv:1: field 2: a quoted field is not closed on its line"},
        {"a,,c\n", "column 2 has no name"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        write_text(path, cases[k].text);
        csv_table table;
        cr_expect_not(csv_table_read(path, &table, error, sizeof error), "case %zu was read", k);
        cr_expect(strstr(error, cases[k].expected) != NULL, "case %zu: %s", k, error);
        cr_expect_eq(table.column_count, 0);
    }
    remove(path);
    csv_table table;
    cr_expect_not(csv_table_read(path, &table, error, sizeof error));
    cr_expect(strstr(error, "No such file") != NULL, "%s", error);
    rmdir(dir);
}

Test(column_label, units_from_sinew_column_names)
{
    const char *cases[][2] = {
        {"time_s", "time (s)"},
        {"Biceps Long.velocity_m_s", "Biceps Long.velocity (m/s)"},
        {"Biceps Long.total_force_N", "Biceps Long.total force (N)"},
        {"Elbow.angle_deg", "Elbow.angle (deg)"},
        {"force [N]", "force (N)"},
        {"normalized_length", "normalized_length"},
    };
    char label[128];
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        column_label(cases[k][0], label, sizeof label);
        cr_expect_str_eq(label, cases[k][1]);
    }
}

/* -------------------------------------------------------- logarithmic axes */

/* The rows holding a pixel of `rgb`, averaged: where a horizontal line
 * of that colour was drawn. */
static double mean_row_of_colour(cairo_surface_t *image, const double rgb[3])
{
    cairo_surface_flush(image);
    const unsigned char *data = cairo_image_surface_get_data(image);
    int stride = cairo_image_surface_get_stride(image);
    double sum = 0.0;
    long found = 0;
    for (int y = 0; y < cairo_image_surface_get_height(image); ++y) {
        const uint32_t *row = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);
        for (int x = 0; x < cairo_image_surface_get_width(image); ++x) {
            double r = ((row[x] >> 16) & 0xFF) / 255.0, g = ((row[x] >> 8) & 0xFF) / 255.0, b = (row[x] & 0xFF) / 255.0;
            if (fabs(r - rgb[0]) < 0.15 && fabs(g - rgb[1]) < 0.15 && fabs(b - rgb[2]) < 0.15) {
                sum += y;
                ++found;
            }
        }
    }
    return found > 0 ? sum / (double)found : NAN;
}

/* On a log axis each decade has the same length: lines at 2, 20 and 200
 * are evenly spaced (log10 20 - log10 2 = log10 200 - log10 20 = 1), where
 * a linear axis would put the first two 9 times closer than the last two. */
Test(chart_draw, a_log_axis_places_values_by_their_logarithm)
{
    double x[2] = {0.0, 1.0}, low[2] = {2.0, 2.0}, middle[2] = {20.0, 20.0}, high[2] = {200.0, 200.0};
    /* No labels, so no legend whose samples share the lines' colours. */
    chart_series series[3] = {
        {.x = x, .y = low, .count = 2}, {.x = x, .y = middle, .count = 2}, {.x = x, .y = high, .count = 2}};
    chart plot = {.series = series,
                  .series_count = 3,
                  .y_scale = CHART_LOG,
                  .y_range = {.fixed = true, .min = 1.0, .max = 1000.0}};
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 400);
    cairo_t *cr = cairo_create(surface);
    char error[CHART_ERROR_SIZE];
    cr_assert(chart_draw(&plot, cr, 0.0, 0.0, 400.0, 400.0, error, sizeof error), "%s", error);
    cairo_destroy(cr);
    double rows[3];
    for (int s = 0; s < 3; ++s) {
        double rgb[3];
        chart_series_colour(s, rgb);
        rows[s] = mean_row_of_colour(surface, rgb);
        cr_assert(!isnan(rows[s]), "series %d not drawn", s);
    }
    cairo_surface_destroy(surface);
    cr_expect(rows[0] > rows[1] && rows[1] > rows[2], "2, 20, 200 upwards: rows %g %g %g", rows[0], rows[1], rows[2]);
    cr_expect_float_eq(rows[0] - rows[1], rows[1] - rows[2], 1.0, "decades of %g and %g px", rows[0] - rows[1],
                       rows[1] - rows[2]);
    /* And both log axes with data alone: drawn. */
    plot = (chart){.series = series, .series_count = 3, .y_scale = CHART_LOG};
    double positive_x[2] = {1e-3, 1e3};
    series[0].x = series[1].x = series[2].x = positive_x;
    plot.x_scale = CHART_LOG;
    cr_expect(draw_to_image(&plot, error, sizeof error), "%s", error);
}

Test(chart_draw, a_log_axis_refuses_values_at_or_below_zero_by_name)
{
    double x[3] = {1.0, 2.0, 3.0}, y[3] = {1.0, 0.0, 4.0}, holes[3] = {1.0, NAN, 4.0};
    chart_series series[2] = {{.label = "fine", .x = x, .y = holes, .count = 3},
                              {.label = "ngs", .x = x, .y = y, .count = 3}};
    chart plot = {.series = series, .series_count = 2, .y_scale = CHART_LOG};
    char error[CHART_ERROR_SIZE] = "";
    cr_expect_not(draw_to_image(&plot, error, sizeof error));
    cr_expect(strstr(error, "series[1]") != NULL && strstr(error, "\"ngs\"") != NULL &&
                  strstr(error, "point 1 has y = 0") != NULL && strstr(error, "above 0") != NULL,
              "message: %s", error);
    /* The same values on a linear axis, or the NaN alone on a log one: drawn. */
    plot.y_scale = CHART_LINEAR;
    cr_expect(draw_to_image(&plot, error, sizeof error), "%s", error);
    plot = (chart){.series = series, .series_count = 1, .y_scale = CHART_LOG};
    cr_expect(draw_to_image(&plot, error, sizeof error), "%s", error);
    /* x too, and the marks. */
    double negative_x[3] = {-1.0, 2.0, 3.0};
    chart_series marked = {
        .label = "m", .x = x, .y = holes, .count = 3, .mark_x = negative_x, .mark_y = x, .mark_count = 3};
    plot = (chart){.series = &marked, .series_count = 1, .x_scale = CHART_LOG};
    cr_expect_not(draw_to_image(&plot, error, sizeof error));
    cr_expect(strstr(error, "mark 0 has x = -1") != NULL, "message: %s", error);
    /* A fixed range from 0 on a log axis. */
    plot = (chart){.series_count = 0, .y_scale = CHART_LOG, .y_range = {.fixed = true, .min = 0.0, .max = 1.0}};
    cr_expect_not(draw_to_image(&plot, error, sizeof error));
    cr_expect(strstr(error, "y_range") != NULL && strstr(error, "logarithmic") != NULL, "message: %s", error);
}

/* ----------------------------------------------------------- series groups */

static void expect_points(const series_groups *groups, int k, const char *key, const double *x, const double *y,
                          size_t count)
{
    cr_assert_lt(k, groups->count, "no series %d (%s)", k, key);
    cr_expect_str_eq(groups->keys[k], key);
    cr_assert_eq(groups->points[k], count, "series %s: %zu points, expected %zu", key, groups->points[k], count);
    for (size_t i = 0; i < count; ++i) {
        cr_expect(groups->x[k][i] == x[i] || (isnan(groups->x[k][i]) && isnan(x[i])), "%s point %zu: x %g, not %g", key,
                  i, groups->x[k][i], x[i]);
        cr_expect(groups->y[k][i] == y[i] || (isnan(groups->y[k][i]) && isnan(y[i])), "%s point %zu: y %g, not %g", key,
                  i, groups->y[k][i], y[i]);
    }
}

/* A solver benchmark in miniature: three solvers' rows interleaved, one
 * row left out. */
static const char *const solver_keys[] = {"ngs", "soft", "ngs", "baum", "soft", "ngs", "ngs", "baum"};
static const double solver_x[] = {3.0, 1.0, 1.0, 2.0, 2.0, 2.0, 4.0, 1.0};
static const double solver_y[] = {0.5, 9.0, 4.0, 7.0, 3.0, 5.0, 0.1, 8.0};
static const bool solver_keep[] = {true, true, true, true, true, true, true, false};

Test(series_groups, split_rows_by_key_in_order_of_first_appearance)
{
    series_groups groups;
    char error[256];
    cr_assert(series_groups_build(solver_keys, solver_keep, solver_x, solver_y, 8, SERIES_AS_READ, &groups, error,
                                  sizeof error),
              "%s", error);
    cr_assert_eq(groups.count, 3);
    expect_points(&groups, 0, "ngs", (double[]){3.0, 1.0, 2.0, 4.0}, (double[]){0.5, 4.0, 5.0, 0.1}, 4);
    expect_points(&groups, 1, "soft", (double[]){1.0, 2.0}, (double[]){9.0, 3.0}, 2);
    expect_points(&groups, 2, "baum", (double[]){2.0}, (double[]){7.0}, 1); /* the other baum row is left out */
    cr_expect_eq(groups.front[0], 4, "no front: every point is on the line");
    series_groups_free(&groups);
    cr_expect_eq(groups.count, 0);

    /* Sorted by x. */
    cr_assert(series_groups_build(solver_keys, NULL, solver_x, solver_y, 8, SERIES_BY_X, &groups, error, sizeof error));
    expect_points(&groups, 0, "ngs", (double[]){1.0, 2.0, 3.0, 4.0}, (double[]){4.0, 5.0, 0.5, 0.1}, 4);
    expect_points(&groups, 2, "baum", (double[]){1.0, 2.0}, (double[]){8.0, 7.0}, 2);
    series_groups_free(&groups);

    /* No keys: one series of every row. */
    cr_assert(series_groups_build(NULL, NULL, solver_x, solver_y, 8, SERIES_AS_READ, &groups, error, sizeof error));
    cr_assert_eq(groups.count, 1);
    cr_expect_eq(groups.points[0], 8);
    series_groups_free(&groups);
}

/* The front worked out by hand: ngs at x 1, 2, 3, 4 has y 4, 5, 0.5, 0.1;
 * (2, 5) is beaten by (1, 4), cheaper and more accurate, so the front is
 * (1, 4), (3, 0.5), (4, 0.1) and (2, 5) is off it. A NaN y is never on it;
 * a tie in x goes to the lower y. */
Test(series_groups, a_front_keeps_the_points_no_cheaper_one_beats)
{
    series_groups groups;
    char error[256];
    cr_assert(
        series_groups_build(solver_keys, NULL, solver_x, solver_y, 8, SERIES_FRONT, &groups, error, sizeof error));
    expect_points(&groups, 0, "ngs", (double[]){1.0, 3.0, 4.0, 2.0}, (double[]){4.0, 0.5, 0.1, 5.0}, 4);
    cr_expect_eq(groups.front[0], 3);
    expect_points(&groups, 1, "soft", (double[]){1.0, 2.0}, (double[]){9.0, 3.0}, 2);
    cr_expect_eq(groups.front[1], 2);
    expect_points(&groups, 2, "baum", (double[]){1.0, 2.0}, (double[]){8.0, 7.0}, 2);
    cr_expect_eq(groups.front[2], 2);
    series_groups_free(&groups);

    const double x[] = {1.0, 1.0, 2.0, NAN, 3.0, 5.0};
    const double y[] = {3.0, 2.0, NAN, 0.0, 2.0, 1.0};
    cr_assert(series_groups_build(NULL, NULL, x, y, 6, SERIES_FRONT, &groups, error, sizeof error));
    expect_points(&groups, 0, "", (double[]){1.0, 5.0, 1.0, 2.0, 3.0, NAN}, (double[]){2.0, 1.0, 3.0, NAN, 2.0, 0.0},
                  6);
    cr_expect_eq(groups.front[0], 2);
    series_groups_free(&groups);
}

Test(series_groups, more_keys_than_a_chart_draws_are_refused)
{
    enum { ROWS = CHART_MAX_SERIES + 1 };
    char texts[ROWS][16];
    const char *keys[ROWS];
    double values[ROWS];
    for (int r = 0; r < ROWS; ++r) {
        snprintf(texts[r], sizeof texts[r], "k%d", r);
        keys[r] = texts[r];
        values[r] = r;
    }
    series_groups groups;
    char error[256] = "";
    cr_expect_not(series_groups_build(keys, NULL, values, values, ROWS, SERIES_AS_READ, &groups, error, sizeof error));
    cr_expect(strstr(error, "more than 64 distinct values") != NULL && strstr(error, "\"k64\"") != NULL, "%s", error);
    cr_expect_eq(groups.count, 0);
    /* One fewer fits. */
    cr_expect(series_groups_build(keys, NULL, values, values, ROWS - 1, SERIES_AS_READ, &groups, error, sizeof error));
    cr_expect_eq(groups.count, CHART_MAX_SERIES);
    series_groups_free(&groups);
}

/* ---------------------------------------------------------------- CSV cells */

Test(csv_cells, a_column_as_text_with_each_row_s_line)
{
    make_dir();
    char path[512], error[1024];
    path_in_dir(path, sizeof path, "cells.csv");
    write_text(path, "scene,\"solver, name\",ms\n"
                     "chain,ngs,0.5\n"
                     "\n"
                     "chain,\"soft, step\",0.25\r\n"
                     "grid,,12\n");
    csv_cells cells;
    cr_assert(csv_cells_read(path, "solver, name", &cells, error, sizeof error), "%s", error);
    cr_assert_eq(cells.count, 3);
    cr_expect_str_eq(cells.text[0], "ngs");
    cr_expect_str_eq(cells.text[1], "soft, step");
    cr_expect_str_eq(cells.text[2], "");
    cr_expect(cells.line[0] == 2 && cells.line[1] == 4 && cells.line[2] == 5, "lines %ld %ld %ld", cells.line[0],
              cells.line[1], cells.line[2]);
    csv_cells_free(&cells);
    /* The same rows as the table's. */
    csv_table table;
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    cr_expect_eq(table.row_count, 3);
    cr_expect_float_eq(table.columns[2].values[1], 0.25, 1e-15);
    csv_table_free(&table);

    cr_expect_not(csv_cells_read(path, "solver", &cells, error, sizeof error));
    cr_expect(strstr(error, "cells.csv") != NULL && strstr(error, "no column \"solver\"") != NULL, "%s", error);
    write_text(path, "a,b\n1,2\n3\n");
    cr_expect_not(csv_cells_read(path, "b", &cells, error, sizeof error));
    cr_expect(strstr(error, "cells.csv:3: 1 fields") != NULL, "%s", error);
    cr_expect_eq(cells.count, 0);
    remove(path);
    rmdir(dir);
}
