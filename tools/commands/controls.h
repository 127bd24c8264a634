/* SPDX-License-Identifier: MIT */
/* The controls of a run: activations, tension targets and one-frame
 * pulses of muscles and groups, and the recruitment of torque muscles,
 * each a shape over time (control_shape.h: a step, a ramp, a sine, a
 * pulse train), scheduled from a time on.
 *
 * Every event is checked when it is added (the name is a muscle or a group
 * of the model with a muscle in the chosen variant, or for recruitment a
 * torque muscle built in it; every value the shape takes is in range), so
 * a run never stops half-way on a bad control.
 *
 * Times are resolved to the model's substeps (1/(frame rate · substeps) s,
 * 1/600 s for the built-in models): an event at time t acts from the
 * first substep that starts at or after t, before that substep is
 * stepped; events of one substep act in the order they were added. Each
 * muscle keeps a command: the last activation or tension event given to
 * it, a shape sampled at the start of every substep (activation 0 at the
 * start), and each torque muscle the last recruit event (until then, the
 * recruitment the model starts with). A later event replaces the command
 * from its time on, whatever the earlier one's shape and duration (a
 * group's event replaces that of each of its muscles). A pulse sets the
 * activation for the substeps of one frame, after which the muscle
 * returns to its command; an activation or tension event after the pulse
 * ends it.
 */
#ifndef SINEW_CONTROLS_H
#define SINEW_CONTROLS_H

#include <stdbool.h>
#include <stddef.h>

#include "control_shape.h"
#include "mu/model.h"

typedef enum control_kind {
    CONTROL_ACTIVATION, /* value: activation, 0 .. 1 */
    CONTROL_TENSION,    /* value: target tension, N, 0 .. CONTROL_MAX_TENSION */
    CONTROL_PULSE,      /* value: activation for one frame, 0 .. 1; a step only */
    CONTROL_RECRUIT,    /* value: neurons a torque muscle recruits, 0 .. its pool's size */
} control_kind;

/* Largest tension target accepted, N: far beyond any muscle of the
 * built-in models (the biceps reaches about 350 N), only to catch typing
 * mistakes and to keep the value finite. */
#define CONTROL_MAX_TENSION 1e9

/* Longest time and duration accepted, s (as `sinew run --duration`). */
#define CONTROL_MAX_TIME 1e6

typedef struct control_event {
    long substep; /* acts before this substep is stepped (substep 0 starts at t = 0) */
    control_kind kind;
    mu_model_ref target; /* a muscle or a group; a torque muscle for CONTROL_RECRUIT */
    control_shape shape; /* shape.start: the time as given, s */
} control_event;

/* What drives one muscle or torque muscle. */
/* A channel's pulse_end when no pulse has acted: below every substep, so
 * that a channel no line drives is never driven (a torque muscle keeps
 * the recruitment `--recruit` gave it, a muscle its activation). */
#define CONTROLS_NO_PULSE (-1L)

typedef struct control_channel {
    control_kind kind;   /* CONTROL_ACTIVATION or CONTROL_TENSION; CONTROL_RECRUIT for a torque muscle */
    control_shape shape; /* the command */
    long pulse_end;      /* a pulse holds the activation before this substep (CONTROLS_NO_PULSE: none) */
    double pulse_value;
    bool due;     /* to be driven at the substep being applied */
    double value; /* the value last driven (activation, N or neurons) */
} control_channel;

typedef struct controls {
    const mu_model_desc *desc;
    int variant;
    double substep;        /* s, one substep of the model */
    control_event *events; /* in the order they act */
    int event_count, event_capacity;
    int next;                  /* events before this one have acted */
    control_channel *channels; /* the description's muscles, then its torque muscles */
} controls;

/* Prepares an empty schedule for the description's variant `variant`.
 * Returns false when out of memory. */
bool controls_init(controls *schedule, const mu_model_desc *desc, int variant);
void controls_free(controls *schedule);

/* The name of a control kind as written: "activation", "tension",
 * "pulse", "recruit". */
const char *control_kind_name(control_kind kind);

/* Adds an event of shape `shape` from shape->start s (0 ..
 * CONTROL_MAX_TIME; not before the last event added) for the muscle or
 * group `name`, or for CONTROL_RECRUIT the torque muscle `name`. On
 * failure writes what is wrong to `error` (without the program's name or
 * the event's origin) and returns false. */
bool controls_add_shape(controls *schedule, control_kind kind, const char *name, const control_shape *shape,
                        char *error, size_t error_size);

/* The same for a step to `value` at `time` s. */
bool controls_add(controls *schedule, double time, control_kind kind, const char *name, double value, char *error,
                  size_t error_size);

/* Applies the events that act before substep `substep` and drives every
 * muscle and torque muscle whose command changes there. Call it before
 * each substep, with substeps 0, 1, 2, ... (controls_step_frame does). */
rb_status controls_apply(controls *schedule, mu_model *model, long substep);

/* Steps frame `frame` (0, 1, 2, ...), applying the controls before each
 * of its substeps: as one step of the whole frame (mu_model_step) when
 * nothing the schedule drives changes within it, else substep by substep
 * (mu_model_substep). */
rb_status controls_step_frame(controls *schedule, mu_model *model, long frame);

/* The command of muscle `muscle` (an index into the description's
 * muscles) at the last substep applied: its value, and in *kind whether
 * it is an activation or a tension target (a pulse's activation counts as
 * an activation). */
double controls_muscle_value(const controls *schedule, int muscle, control_kind *kind);

/* Events that have not acted yet (after the end of a run). */
int controls_pending(const controls *schedule);

#endif
