/* SPDX-License-Identifier: MIT */
/* The shape of a control over time: what value a control line gives a
 * muscle's activation or tension, or a torque muscle's recruitment, at
 * each instant from its start (docs/cli.md, "Control files").
 *
 *   step    VALUE                         VALUE from the start on
 *   ramp    FROM TO DURATION              linear from FROM to TO, then TO
 *   sine    MEAN AMPLITUDE FREQUENCY DURATION
 *                                         MEAN + AMPLITUDE·sin(2π·f·(t − start)),
 *                                         then MEAN
 *   pulses  LEVEL FREQUENCY WIDTH DURATION
 *                                         LEVEL during each pulse, 0 between
 *                                         pulses and after the last
 *
 * A run samples a shape at the start of every substep (the built-in
 * models: 600 per second) and holds that value over the substep. Ramps
 * and sines are sampled at the substep's time; a pulse train is counted
 * in whole substeps, so that every pulse of it has the same width: pulse
 * n starts at the first substep that starts at or after start + n/f, for
 * every n with start + n/f < start + DURATION, and lasts WIDTH rounded to
 * the nearest whole number of substeps (a pulse of 2 ms at 600 substeps
 * per second lasts one substep, 1.667 ms).
 */
#ifndef SINEW_CONTROL_SHAPE_H
#define SINEW_CONTROL_SHAPE_H

#include <stdbool.h>

typedef enum control_shape_kind {
    CONTROL_STEP,
    CONTROL_RAMP,
    CONTROL_SINE,
    CONTROL_PULSES,
} control_shape_kind;

typedef struct control_shape {
    control_shape_kind kind;
    double start;     /* s, the control's time */
    double duration;  /* s, > 0 (not used by a step) */
    double first;     /* step: the value; ramp: FROM; sine: MEAN; pulses: LEVEL */
    double second;    /* ramp: TO; sine: AMPLITUDE (>= 0) */
    double frequency; /* Hz, > 0: sine, pulses */
    double width;     /* s, > 0: pulses */
} control_shape;

/* The shape's name as written in a control file: "step", "ramp", ... */
const char *control_shape_name(control_shape_kind kind);

/* The shape's value at `time` s, for a run whose substeps last `substep` s
 * and start at whole multiples of it (time is the start of one of them);
 * a time before the start gives the value at the start. */
double control_shape_value(const control_shape *shape, double time, double substep);

/* The least and greatest value the shape takes, for range checks. */
void control_shape_range(const control_shape *shape, double *low, double *high);

/* Substeps in one pulse of a train: WIDTH rounded to whole substeps. */
long control_shape_pulse_substeps(const control_shape *shape, double substep);

/* The first substep (of `substep` s each) that starts at or after `time`
 * s; a time within a millionth of a substep of one's start is that
 * substep's (2.5 s at 600 Hz is rarely 1500 substeps exactly in binary). */
long control_first_substep_at(double time, double substep);

#endif
