/* SPDX-License-Identifier: MIT */
/* A zero-phase Butterworth low-pass and finite differences (motion_filter.h). */
#include <math.h>
#include <stdlib.h>

#include "motion_filter.h"
#include "rb/math.h"

bool motion_filter_cutoff_valid(double cutoff_hz, double sample_rate_hz)
{
    return cutoff_hz > 0.0 && cutoff_hz / MOTION_FILTER_TWO_PASS_CORRECTION < 0.5 * sample_rate_hz;
}

/* A second-order Butterworth low-pass section by the bilinear transform
 * with the cut-off prewarped (ω = tan(π·fc/fs)):
 *   y[n] = b0·x[n] + b1·x[n−1] + b2·x[n−2] − a1·y[n−1] − a2·y[n−2],
 * b0 = ω²/(1 + √2·ω + ω²), b1 = 2·b0, b2 = b0,
 * a1 = 2·(ω² − 1)/(1 + √2·ω + ω²), a2 = (1 − √2·ω + ω²)/(1 + √2·ω + ω²).
 * Its gain at 0 Hz is 1. It runs over y[0 .. n-1] in place, starting as
 * if the signal had always been y[0]. */
typedef struct section {
    double b0, b1, b2, a1, a2;
} section;

static section butterworth(double cutoff_hz, double sample_rate_hz)
{
    const double w = tan(RB_PI * cutoff_hz / sample_rate_hz);
    const double norm = 1.0 + sqrt(2.0) * w + w * w;
    const double b0 = w * w / norm;
    return (section){b0, 2.0 * b0, b0, 2.0 * (w * w - 1.0) / norm, (1.0 - sqrt(2.0) * w + w * w) / norm};
}

static void run_section(const section *s, double *y, size_t n, ptrdiff_t stride)
{
    double *at = stride > 0 ? y : y + (n - 1);
    double x1 = at[0], x2 = at[0], y1 = at[0], y2 = at[0];
    for (size_t i = 0; i < n; ++i, at += stride) {
        const double x0 = *at;
        const double y0 = s->b0 * x0 + s->b1 * x1 + s->b2 * x2 - s->a1 * y1 - s->a2 * y2;
        x2 = x1;
        x1 = x0;
        y2 = y1;
        y1 = y0;
        *at = y0;
    }
}

bool motion_filter_low_pass(double *x, size_t n, double cutoff_hz, double sample_rate_hz)
{
    /* The extension at each end: about three periods of the cut-off, at
     * most the signal's own length less one. */
    size_t pad = (size_t)ceil(3.0 * sample_rate_hz / cutoff_hz);
    pad = pad < n - 1 ? pad : n - 1;
    const size_t total = n + 2 * pad;
    double *y = malloc(total * sizeof *y);
    if (y == NULL) {
        return false;
    }
    for (size_t k = 0; k < pad; ++k) {
        y[pad - 1 - k] = 2.0 * x[0] - x[k + 1];
        y[pad + n + k] = 2.0 * x[n - 1] - x[n - 2 - k];
    }
    for (size_t i = 0; i < n; ++i) {
        y[pad + i] = x[i];
    }
    const section s = butterworth(cutoff_hz / MOTION_FILTER_TWO_PASS_CORRECTION, sample_rate_hz);
    run_section(&s, y, total, 1);
    run_section(&s, y, total, -1);
    for (size_t i = 0; i < n; ++i) {
        x[i] = y[pad + i];
    }
    free(y);
    return true;
}

/* Second-order differences: inside, (x[i+1] − x[i−1])/2h and
 * (x[i+1] − 2x[i] + x[i−1])/h²; at the first sample (−3x0 + 4x1 − x2)/2h
 * and (2x0 − 5x1 + 4x2 − x3)/h², mirrored at the last (Taylor expansions
 * of the samples about the end point, error O(h²)). */
void motion_filter_differentiate(const double *x, size_t n, double h, double *rate, double *acceleration)
{
    for (size_t i = 1; i + 1 < n; ++i) {
        rate[i] = (x[i + 1] - x[i - 1]) / (2.0 * h);
        acceleration[i] = (x[i + 1] - 2.0 * x[i] + x[i - 1]) / (h * h);
    }
    const size_t e = n - 1;
    rate[0] = (-3.0 * x[0] + 4.0 * x[1] - x[2]) / (2.0 * h);
    rate[e] = (3.0 * x[e] - 4.0 * x[e - 1] + x[e - 2]) / (2.0 * h);
    acceleration[0] = (2.0 * x[0] - 5.0 * x[1] + 4.0 * x[2] - x[3]) / (h * h);
    acceleration[e] = (2.0 * x[e] - 5.0 * x[e - 1] + 4.0 * x[e - 2] - x[e - 3]) / (h * h);
}
