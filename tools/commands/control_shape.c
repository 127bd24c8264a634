/* SPDX-License-Identifier: MIT */
#include <math.h>

#include "control_shape.h"
#include "rb/math.h"

const char *control_shape_name(control_shape_kind kind)
{
    switch (kind) {
    case CONTROL_STEP:
        return "step";
    case CONTROL_RAMP:
        return "ramp";
    case CONTROL_SINE:
        return "sine";
    case CONTROL_PULSES:
        break;
    }
    return "pulses";
}

long control_first_substep_at(double time, double substep)
{
    double substeps = time / substep;
    double nearest = nearbyint(substeps);
    return (long)(fabs(substeps - nearest) < 1e-6 ? nearest : ceil(substeps));
}

long control_shape_pulse_substeps(const control_shape *shape, double substep) { return lround(shape->width / substep); }

/* Whether the substep starting at `time` lies in a pulse of the train.
 * Pulse n starts at substep k_n, the first at or after start + n/f; the
 * substep k is in it when k_n <= k < k_n + width. The pulse that may hold
 * k is the last that starts at or before it: n = floor((t − start)·f),
 * give or take one for the rounding of start + n/f to a substep. */
static bool in_pulse(const control_shape *shape, double time, double substep)
{
    const long k = lround(time / substep);
    const long width = control_shape_pulse_substeps(shape, substep);
    /* Pulses start while start + n/f < start + duration: n < duration·f. */
    const double last = ceil(shape->duration * shape->frequency - 1e-9) - 1.0;
    const double guess = floor((time - shape->start) * shape->frequency + 1e-9);
    for (double n = fmax(guess - 1.0, 0.0); n <= fmin(guess + 1.0, last); n += 1.0) {
        long first = control_first_substep_at(shape->start + n / shape->frequency, substep);
        if (first <= k && k < first + width) {
            return true;
        }
    }
    return false;
}

double control_shape_value(const control_shape *shape, double time, double substep)
{
    const double elapsed = fmax(time - shape->start, 0.0);
    switch (shape->kind) {
    case CONTROL_STEP:
        break;
    case CONTROL_RAMP:
        if (elapsed >= shape->duration) {
            return shape->second;
        }
        /* FROM + (TO − FROM)·s with s = elapsed/duration in [0, 1). */
        return shape->first + (shape->second - shape->first) * (elapsed / shape->duration);
    case CONTROL_SINE:
        if (elapsed >= shape->duration) {
            return shape->first;
        }
        return shape->first + shape->second * sin(2.0 * RB_PI * shape->frequency * elapsed);
    case CONTROL_PULSES:
        return in_pulse(shape, time, substep) ? shape->first : 0.0;
    }
    return shape->first;
}

void control_shape_range(const control_shape *shape, double *low, double *high)
{
    switch (shape->kind) {
    case CONTROL_STEP:
        break;
    case CONTROL_RAMP:
        *low = fmin(shape->first, shape->second);
        *high = fmax(shape->first, shape->second);
        return;
    case CONTROL_SINE:
        *low = shape->first - shape->second;
        *high = shape->first + shape->second;
        return;
    case CONTROL_PULSES:
        *low = fmin(shape->first, 0.0);
        *high = fmax(shape->first, 0.0);
        return;
    }
    *low = shape->first;
    *high = shape->first;
}
