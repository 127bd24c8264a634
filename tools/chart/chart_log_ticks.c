/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>

#include "chart/chart_log_ticks.h"
#include "chart/chart_ticks.h"

/* m·10^k for a whole m and k in the decades a double reaches, from its
 * decimal text, so that 5e-5 is the double nearest 5·10^-5, as a reader
 * of the label expects (5 * pow(10, -5) may be off by an ulp, enough to
 * miss a range's end that is exactly that value). */
static double decimal(int m, int k)
{
    char text[24];
    snprintf(text, sizeof text, "%de%d", m, k);
    double value;
    sscanf(text, "%lf", &value);
    return value;
}

static double power_of_ten(int k) { return decimal(1, k); }

static int clamp_decade(double d)
{
    return d < CHART_LOG_MIN_DECADE ? CHART_LOG_MIN_DECADE : d > CHART_LOG_MAX_DECADE ? CHART_LOG_MAX_DECADE : (int)d;
}

/* The 1-2-5 ticks from the largest at or below min to the smallest at or
 * above max, which is at most 10^high_decade; at most
 * CHART_MAX_LOG_TICKS of them (more would be refused by the caller's
 * interval count anyway). */
static void one_two_five(double min, double max, int low_decade, int high_decade, chart_log_ticks *ticks)
{
    static const int mantissas[3] = {1, 2, 5};
    ticks->count = 0;
    for (int k = low_decade; k <= high_decade && ticks->count < CHART_MAX_LOG_TICKS; ++k) {
        for (int m = 0; m < 3 && ticks->count < CHART_MAX_LOG_TICKS; ++m) {
            double value = decimal(mantissas[m], k);
            double next = m < 2 ? decimal(mantissas[m + 1], k) : power_of_ten(k + 1);
            /* Skip ticks wholly below min (the next one is still at or
             * below it); stop after the first at or above max. */
            if (next <= min && ticks->count == 0) {
                continue;
            }
            if (!isfinite(value)) {
                return;
            }
            ticks->values[ticks->count++] = value;
            if (value >= max) {
                return;
            }
        }
    }
}

bool chart_log_ticks_make(double min, double max, int intervals, chart_log_ticks *ticks, char *error, size_t error_size)
{
    if (ticks == NULL) {
        if (error != NULL) {
            snprintf(error, error_size, "chart_log_ticks_make: ticks is NULL");
        }
        return false;
    }
    if (!(isfinite(min) && isfinite(max) && min > 0.0 && min <= max)) {
        if (error != NULL) {
            snprintf(error, error_size,
                     "chart_log_ticks_make: the range [%g, %g] must be finite with 0 < min <= max (a logarithmic "
                     "axis shows only values above 0)",
                     min, max);
        }
        return false;
    }
    if (intervals < 1 || intervals > CHART_MAX_TICK_INTERVALS) {
        if (error != NULL) {
            snprintf(error, error_size, "chart_log_ticks_make: intervals %d, expected 1 .. %d", intervals,
                     CHART_MAX_TICK_INTERVALS);
        }
        return false;
    }
    /* Equal ends: a range around their value, a quarter of it either
     * way on the log scale's terms (÷ and × 1.25), so that a constant
     * shows off the axis's ends. */
    if (max <= min * (1.0 + 1e-12) && min / 1.25 > 0.0 && isfinite(max * 1.25)) {
        min /= 1.25;
        max *= 1.25;
    }
    /* The decades around the range; log10 of an exact power of ten is
     * exact in glibc, and 1e-9 absorbs the rounding of any other. */
    int low = clamp_decade(floor(log10(min) + 1e-9));
    int high = clamp_decade(ceil(log10(max) - 1e-9));
    if (high <= low) {
        high = low + 1 <= CHART_LOG_MAX_DECADE ? low + 1 : low;
        low = high - 1;
    }
    /* 1, 2 and 5 times the powers of ten, when they make no more than
     * `intervals` intervals (three a decade: a range of up to about
     * intervals / 3 decades); else decades alone. */
    if (3 * (high - low) <= intervals + 3) {
        one_two_five(min, max, low, high, ticks);
        if (ticks->count >= 2 && ticks->count - 1 <= intervals) {
            return true;
        }
    }
    /* Every `step` decades, the ends rounded outwards to multiples of the
     * step so that the labels are regular (1e-6, 1e-3, 1, 1e3); where
     * that passes the decades a double reaches, `step`s counted from the
     * range's own end decade instead. */
    int step = (high - low + intervals - 1) / intervals;
    int first = (int)floor((double)low / step) * step;
    int last = (int)ceil((double)high / step) * step;
    if (first < CHART_LOG_MIN_DECADE || last > CHART_LOG_MAX_DECADE) {
        int steps = (high - low + step - 1) / step;
        first = low;
        last = low + steps * step;
        if (last > CHART_LOG_MAX_DECADE) {
            last = high;
            first = high - steps * step;
        }
    }
    ticks->count = 0;
    for (int k = first; k <= last && ticks->count < CHART_MAX_LOG_TICKS; k += step) {
        ticks->values[ticks->count++] = power_of_ten(k);
    }
    return true;
}

void chart_log_tick_label(double value, char *text, size_t text_size)
{
    if (value >= 1e-3 && value <= 1e4) {
        snprintf(text, text_size, "%g", value);
        return;
    }
    /* A tick is m·10^k with m = 1, 2 or 5: one significant digit, the
     * exponent without its sign's "+" and leading zeros. */
    int exponent = (int)floor(log10(value) + 1e-9);
    double mantissa = value / power_of_ten(exponent);
    if (exponent <= CHART_LOG_MIN_DECADE || !isfinite(mantissa)) {
        snprintf(text, text_size, "%.0e", value);
        return;
    }
    snprintf(text, text_size, "%.0fe%d", mantissa, exponent);
}
