/* SPDX-License-Identifier: MIT */
/* "Nice" axis ticks: steps of 1, 2 or 5 times a power of ten, the first
 * tick at or below the data's minimum and the last at or above its
 * maximum, to within 1e-9 of a step, the rounding of a tick's value
 * (Heckbert, "Nice numbers for graph labels", Graphics Gems,
 * 1990, with the 1-2-5 series and covering ends).
 */
#ifndef CHART_CHART_TICKS_H
#define CHART_CHART_TICKS_H

#include <stdbool.h>
#include <stddef.h>

/* Most intervals chart_nice_ticks accepts as a target. */
#define CHART_MAX_TICK_INTERVALS 100

typedef struct chart_ticks {
    long first_index; /* the first tick is first_index·step */
    double step;      /* 1, 2 or 5 × 10^k */
    int count;        /* ticks, >= 2; the last is (first_index + count - 1)·step */
} chart_ticks;

/* Ticks covering [min, max] (finite, min <= max) with about `intervals`
 * intervals (1 .. CHART_MAX_TICK_INTERVALS; the step is the nice number
 * nearest (max - min)/intervals, so there may be up to about twice as
 * many or half as many). Ends equal to within 1e-12 of their magnitude
 * get a range around their value: ±5 %
 * of it, or ±1 about 0. Every finite range gets finite ticks: the step is
 * at least 1e-307 (denormal values share the ticks 0 and 1e-307) and at
 * most 1e308, and near ±DBL_MAX, where the next multiple of the step
 * would overflow, the end tick is the last finite one, short of the end.
 * Fails, with `error` saying why, on a NaN or an infinite end, or
 * min > max. */
bool chart_nice_ticks(double min, double max, int intervals, chart_ticks *ticks, char *error, size_t error_size);

/* The value of tick i (0 .. count - 1), computed from its index so that
 * ticks do not accumulate rounding (0.1 + 0.1 + 0.1 is not 0.3). */
double chart_tick_value(const chart_ticks *ticks, int i);

/* The label of tick i: as many decimals as the step needs ("0.25",
 * "1500", never "0.30000000000000004" or "-0"); exponent notation for
 * very large or small values ("2e+06", "5e-06"). */
void chart_tick_label(const chart_ticks *ticks, int i, char *text, size_t text_size);

#endif
