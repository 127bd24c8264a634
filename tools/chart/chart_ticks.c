/* SPDX-License-Identifier: MIT */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "chart/chart_ticks.h"

/* The smallest and largest steps: 1-2-5 numbers whose powers of ten are
 * normal doubles. The tick indices stay far within a long: a range is
 * widened to at least 1e-12 of its magnitude, so |min|/step < 1e15, and
 * below MIN_STEP the values are less than a step. */
#define MIN_STEP 1e-307
#define MAX_STEP 1e308

/* The 1-2-5 number nearest `raw` (> 0) on a log scale: the cut-offs
 * sqrt(2), sqrt(10) and sqrt(50) are the geometric means between 1, 2, 5
 * and 10. */
static double nice_step(double raw)
{
    double magnitude = pow(10.0, floor(log10(raw)));
    double mantissa = raw / magnitude;
    double nice = mantissa < sqrt(2.0) ? 1.0 : mantissa < sqrt(10.0) ? 2.0 : mantissa < sqrt(50.0) ? 5.0 : 10.0;
    return nice * magnitude;
}

bool chart_nice_ticks(double min, double max, int intervals, chart_ticks *ticks, char *error, size_t error_size)
{
    if (ticks == NULL) {
        if (error != NULL) {
            snprintf(error, error_size, "chart_nice_ticks: ticks is NULL");
        }
        return false;
    }
    if (!isfinite(min) || !isfinite(max) || min > max) {
        if (error != NULL) {
            snprintf(error, error_size, "chart_nice_ticks: the range [%g, %g] must be finite with min <= max", min,
                     max);
        }
        return false;
    }
    if (intervals < 1 || intervals > CHART_MAX_TICK_INTERVALS) {
        if (error != NULL) {
            snprintf(error, error_size, "chart_nice_ticks: intervals %d, expected 1 .. %d", intervals,
                     CHART_MAX_TICK_INTERVALS);
        }
        return false;
    }
    /* Halves, so that the width of any finite range is finite
     * (DBL_MAX - -DBL_MAX is not). */
    double half_span = max / 2.0 - min / 2.0;
    double magnitude = fmax(fabs(min), fabs(max));
    if (half_span <= 0.5e-12 * magnitude || half_span == 0.0) {
        double half = magnitude > 0.0 ? 0.05 * magnitude : 1.0;
        min = fmax(min - half, -DBL_MAX);
        max = fmin(max + half, DBL_MAX);
        half_span = max / 2.0 - min / 2.0;
    }
    /* A step below MIN_STEP would be denormal (too few bits for its ticks
     * to be 1-2-5 multiples, and 10^k underflows): values that close to 0
     * share the ticks 0 and MIN_STEP. Above MAX_STEP no multiple but 0
     * and ±1 is finite. */
    double step = nice_step(fmin(fmax(half_span / intervals * 2.0, MIN_STEP), MAX_STEP));
    /* min/step is rounded (0.3/0.1 is 2.9999999999999996): an end within
     * 1e-9 of a step of a tick counts as on it, so that 0.3 gets the tick
     * 0.3 rather than a spare one at 0.2. */
    double first = floor(min / step + 1e-9);
    double last = ceil(max / step - 1e-9);
    /* A tick beyond ±DBL_MAX is not drawn: the outermost finite one is the
     * end tick (the range's end lies past it). */
    if (!isfinite(first * step)) {
        first += 1.0;
    }
    if (!isfinite(last * step)) {
        last -= 1.0;
    }
    if (last <= first) {
        if (isfinite((first + 1.0) * step)) {
            last = first + 1.0;
        } else {
            first = last - 1.0;
        }
    }
    *ticks = (chart_ticks){.first_index = (long)first, .step = step, .count = (int)(last - first) + 1};
    return true;
}

double chart_tick_value(const chart_ticks *ticks, int i) { return (double)(ticks->first_index + i) * ticks->step; }

void chart_tick_label(const chart_ticks *ticks, int i, char *text, size_t text_size)
{
    double value = chart_tick_value(ticks, i);
    if (ticks->first_index + i == 0) {
        snprintf(text, text_size, "0");
        return;
    }
    double largest = fmax(fabs(chart_tick_value(ticks, 0)), fabs(chart_tick_value(ticks, ticks->count - 1)));
    int step_exponent = (int)floor(log10(ticks->step) + 1e-9);
    if (largest >= 1e6 || ticks->step < 1e-4) {
        /* Significant digits from the largest tick down to the step's. */
        int digits = (int)floor(log10(largest) + 1e-9) - step_exponent + 1;
        snprintf(text, text_size, "%.*g", digits < 1 ? 1 : digits, value);
        return;
    }
    int decimals = step_exponent < 0 ? -step_exponent : 0;
    snprintf(text, text_size, "%.*f", decimals, value);
}
