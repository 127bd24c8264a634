/* SPDX-License-Identifier: MIT */
/* The scale and clipping of the joint-load arrows (load_arrows.h). */
#include <math.h>

#include "load_arrows.h"

/* The largest 1, 2 or 5 × 10^k at most `value` (> 0). */
static double step_at_most(double value)
{
    const double decade = pow(10.0, floor(log10(value)));
    const double mantissa = value / decade;
    /* A hair of tolerance keeps 2 from reading as 1.999… */
    return decade * (mantissa >= 5.0 - 1e-9 ? 5.0 : mantissa >= 2.0 - 1e-9 ? 2.0 : 1.0);
}

double load_arrow_scale(double largest_force)
{
    if (!(largest_force > 0.0) || !isfinite(largest_force)) {
        return 0.0;
    }
    return step_at_most(LOAD_ARROW_MAX_PX / largest_force);
}

rb_vec2 load_arrow_clip(rb_vec2 base, rb_vec2 tip, double width, double height, bool *cut)
{
    const double low_x = LOAD_ARROW_MARGIN_PX, high_x = width - LOAD_ARROW_MARGIN_PX;
    const double low_y = LOAD_ARROW_MARGIN_PX, high_y = height - LOAD_ARROW_MARGIN_PX;
    /* The largest t in [0, 1] with base + t·(tip - base) inside, axis by axis. */
    double t = 1.0;
    const rb_vec2 d = rb_sub(tip, base);
    if (tip.x > high_x && d.x > 0.0) {
        t = fmin(t, (high_x - base.x) / d.x);
    }
    if (tip.x < low_x && d.x < 0.0) {
        t = fmin(t, (low_x - base.x) / d.x);
    }
    if (tip.y > high_y && d.y > 0.0) {
        t = fmin(t, (high_y - base.y) / d.y);
    }
    if (tip.y < low_y && d.y < 0.0) {
        t = fmin(t, (low_y - base.y) / d.y);
    }
    t = fmax(t, 0.0);
    *cut = t < 1.0;
    return rb_mul_add(base, t, d);
}

double load_arrow_legend_force(double scale, double *length_px)
{
    const double force = step_at_most(100.0 / scale);
    *length_px = force * scale;
    return force;
}
