/* SPDX-License-Identifier: MIT */
/* The controls of a run: activations, tension targets and one-frame
 * pulses, each for a muscle or a group, scheduled over time.
 *
 * Every event is checked when it is added (the name is a muscle or a group
 * of the model with a muscle in the chosen variant; the value is in
 * range), so a run never stops half-way on a bad control.
 *
 * An event at time t acts from the first frame that starts at or after t
 * (within 1e-6 of a frame), before that frame is stepped; events of one
 * frame act in the order they were added. Each muscle keeps a command: the
 * last activation or tension target given to it (activation 0 at the
 * start). A pulse sets the activation for one frame only; before the next
 * frame each pulsed muscle returns to its command, unless an activation or
 * tension event of the pulse's own frame, added after it, replaced it.
 */
#ifndef SINEW_CONTROLS_H
#define SINEW_CONTROLS_H

#include <stdbool.h>
#include <stddef.h>

#include "mu/model.h"

typedef enum control_kind {
    CONTROL_ACTIVATION, /* value: activation, 0 .. 1 */
    CONTROL_TENSION,    /* value: target tension, N, 0 .. CONTROL_MAX_TENSION */
    CONTROL_PULSE,      /* value: activation for one frame, 0 .. 1 */
} control_kind;

/* Largest tension target accepted, N: far beyond any muscle of the
 * built-in models (the biceps reaches about 350 N), only to catch typing
 * mistakes and to keep the value finite. */
#define CONTROL_MAX_TENSION 1e9

/* Longest time accepted, s (as `sinew run --duration`). */
#define CONTROL_MAX_TIME 1e6

typedef struct control_event {
    double time; /* s, as given */
    long frame;  /* acts before this frame is stepped (frame 0 starts at t = 0) */
    control_kind kind;
    mu_model_ref target; /* a muscle or a group */
    double value;
} control_event;

typedef struct controls {
    const mu_model_desc *desc;
    int variant;
    control_event *events; /* in the order they act */
    int event_count, event_capacity;
    int next;              /* events before this one have acted */
    bool *pulsed;          /* by description muscle: pulsed in the last frame */
    control_kind *command; /* by description muscle: CONTROL_ACTIVATION or CONTROL_TENSION */
    double *command_value;
} controls;

/* Prepares an empty schedule for the description's variant `variant`.
 * Returns false when out of memory. */
bool controls_init(controls *schedule, const mu_model_desc *desc, int variant);
void controls_free(controls *schedule);

/* The name of a control kind as written: "activation", "tension", "pulse". */
const char *control_kind_name(control_kind kind);

/* Adds an event at `time` s (0 .. CONTROL_MAX_TIME; not before the last
 * event added) for the muscle or group `name`. On failure writes what is
 * wrong to `error` (without the program's name or the event's origin) and
 * returns false. */
bool controls_add(controls *schedule, double time, control_kind kind, const char *name, double value, char *error,
                  size_t error_size);

/* Returns the muscles pulsed in the last frame to their command, then
 * applies the events that act before frame `frame`. Call it once before
 * each frame, with frames 0, 1, 2, ... */
rb_status controls_apply(controls *schedule, mu_model *model, long frame);

/* Events that have not acted yet (after the end of a run). */
int controls_pending(const controls *schedule);

#endif
