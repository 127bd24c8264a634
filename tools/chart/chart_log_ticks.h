/* SPDX-License-Identifier: MIT */
/* Ticks of a logarithmic axis: 1, 2 and 5 times the powers of ten when
 * they make no more intervals than the axis has room for (a range of a
 * few decades), else powers of ten alone (every decade, or every few
 * decades when the range spans more of them than the axis has room
 * for). The first tick is at or below the range's minimum and the last
 * at or above its maximum; on a log scale the ticks 1, 2, 5, 10 are
 * nearly evenly spaced (log10 2 = 0.30, log10 5 = 0.70), the reason for
 * the 1-2-5 series (Cleveland, "The Elements of Graphing Data", 1985, on
 * logarithmic scales).
 */
#ifndef CHART_CHART_LOG_TICKS_H
#define CHART_CHART_LOG_TICKS_H

#include <stdbool.h>
#include <stddef.h>

/* Most ticks of a log axis: (intervals <= CHART_MAX_TICK_INTERVALS) + 1. */
#define CHART_MAX_LOG_TICKS 101

/* The decades a double reaches: 10^-323 is its least power of ten above
 * 0 (a denormal), 10^308 its largest. */
#define CHART_LOG_MIN_DECADE (-323)
#define CHART_LOG_MAX_DECADE 308

typedef struct chart_log_ticks {
    int count; /* >= 2 */
    double values[CHART_MAX_LOG_TICKS];
} chart_log_ticks;

/* Ticks covering [min, max] (0 < min <= max, finite) with at most
 * `intervals` (1 .. CHART_MAX_TICK_INTERVALS) intervals between them, or
 * one more where decade ends rounded outwards to a multiple of their step
 * add one. Equal ends get a range around their value (÷ and × 1.25). Near
 * the ends of what a double holds (below 10^-323, above 10^308) the end
 * tick may fall short of the range's end. Fails, with `error` saying why, on an end that is not a
 * finite number above 0, or min > max. */
bool chart_log_ticks_make(double min, double max, int intervals, chart_log_ticks *ticks, char *error,
                          size_t error_size);

/* A tick's label: plain decimals from 0.001 to 10000 ("0.002", "500"),
 * else a power of ten ("1e-05" reads "1e-5", "2e+06" reads "2e6"). */
void chart_log_tick_label(double value, char *text, size_t text_size);

#endif
