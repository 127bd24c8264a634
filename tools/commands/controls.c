/* SPDX-License-Identifier: MIT */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "controls.h"

bool controls_init(controls *schedule, const mu_model_desc *desc, int variant)
{
    *schedule = (controls){.desc = desc, .variant = variant};
    size_t count = (size_t)desc->muscle_count + 1; /* + 1: calloc(0) may return NULL */
    schedule->pulsed = calloc(count, sizeof *schedule->pulsed);
    schedule->command = calloc(count, sizeof *schedule->command);
    schedule->command_value = calloc(count, sizeof *schedule->command_value);
    if (schedule->pulsed == NULL || schedule->command == NULL || schedule->command_value == NULL) {
        controls_free(schedule);
        return false;
    }
    /* calloc's zeros are each muscle's state at creation: activation 0. */
    return true;
}

void controls_free(controls *schedule)
{
    free(schedule->events);
    free(schedule->pulsed);
    free(schedule->command);
    free(schedule->command_value);
    *schedule = (controls){.desc = NULL};
}

const char *control_kind_name(control_kind kind)
{
    switch (kind) {
    case CONTROL_ACTIVATION:
        return "activation";
    case CONTROL_TENSION:
        return "tension";
    case CONTROL_PULSE:
        break;
    }
    return "pulse";
}

/* Muscle i (description index) of a target, and how many it has: a
 * muscle is its own group of one. */
static int target_muscle(const mu_model_desc *desc, mu_model_ref target, int i)
{
    return target.kind == MU_MODEL_MUSCLE ? target.index : desc->groups[target.index].muscles[i];
}

static int target_muscle_count(const mu_model_desc *desc, mu_model_ref target)
{
    return target.kind == MU_MODEL_MUSCLE ? 1 : desc->groups[target.index].muscle_count;
}

/* Appends to the message in `error`, *used bytes long; snprintf keeps
 * it a string, truncated once full, and *used then passes error_size. */
static void append(char *error, size_t error_size, size_t *used, const char *format, const char *text)
{
    if (*used >= error_size) {
        return;
    }
    int written = snprintf(error + *used, error_size - *used, format, text);
    if (written > 0) {
        *used += (size_t)written;
    }
}

/* An error for a name that is no muscle or group: lists the names there
 * are, since model files give them with spaces and capitals. */
static void report_unknown_name(const mu_model_desc *desc, const char *name, char *error, size_t error_size)
{
    size_t used = 0;
    append(error, error_size, &used, "no muscle or group named \"%s\" (muscles:", name);
    for (int m = 0; m < desc->muscle_count; ++m) {
        append(error, error_size, &used, m == 0 ? " \"%s\"" : ", \"%s\"", desc->muscles[m].name);
    }
    append(error, error_size, &used, "%s", desc->group_count > 0 ? "; groups:" : "");
    for (int g = 0; g < desc->group_count; ++g) {
        append(error, error_size, &used, g == 0 ? " \"%s\"" : ", \"%s\"", desc->groups[g].name);
    }
    append(error, error_size, &used, "%s", ")");
}

/* Finds the muscle or group `name` with a muscle in the schedule's
 * variant; a control that could move nothing is a mistake in the name or
 * the variant. */
static bool resolve_target(const controls *schedule, const char *name, mu_model_ref *target, char *error,
                           size_t error_size)
{
    const mu_model_desc *desc = schedule->desc;
    if (!mu_model_desc_find(desc, name, target) ||
        (target->kind != MU_MODEL_MUSCLE && target->kind != MU_MODEL_GROUP)) {
        report_unknown_name(desc, name, error, error_size);
        return false;
    }
    const mu_model_variant *variant = &desc->variants[schedule->variant];
    for (int i = 0; i < target_muscle_count(desc, *target); ++i) {
        if (mu_model_variant_has_muscle(variant, target_muscle(desc, *target, i))) {
            return true;
        }
    }
    snprintf(error, error_size,
             target->kind == MU_MODEL_MUSCLE ? "muscle \"%s\" is not in variant \"%s\""
                                             : "group \"%s\" has no muscle in variant \"%s\"",
             name, variant->name);
    return false;
}

/* The frame an event at `time` acts before: the first that starts at or
 * after it. A time written as a multiple of the frame (2.5 s at 60 Hz)
 * is rarely one exactly in binary, hence the tolerance. */
static long first_frame_at(double time, double frame_rate)
{
    double frames = time * frame_rate;
    double nearest = nearbyint(frames);
    return (long)(fabs(frames - nearest) < 1e-6 ? nearest : ceil(frames));
}

bool controls_add(controls *schedule, double time, control_kind kind, const char *name, double value, char *error,
                  size_t error_size)
{
    if (!(time >= 0.0 && time <= CONTROL_MAX_TIME)) {
        snprintf(error, error_size, "the time must be from 0 to %g s, got %g", CONTROL_MAX_TIME, time);
        return false;
    }
    if (schedule->event_count > 0 && time < schedule->events[schedule->event_count - 1].time) {
        snprintf(error, error_size, "the time %g s is before the previous control's %g s: times must not decrease",
                 time, schedule->events[schedule->event_count - 1].time);
        return false;
    }
    double max = kind == CONTROL_TENSION ? CONTROL_MAX_TENSION : 1.0;
    if (!(value >= 0.0 && value <= max)) {
        snprintf(error, error_size, "the %s must be from 0 to %g%s, got %g", control_kind_name(kind), max,
                 kind == CONTROL_TENSION ? " N" : "", value);
        return false;
    }
    mu_model_ref target;
    if (!resolve_target(schedule, name, &target, error, error_size)) {
        return false;
    }
    if (schedule->event_count == schedule->event_capacity) {
        if (schedule->event_capacity > INT_MAX / 2) {
            snprintf(error, error_size, "more than %d controls", schedule->event_capacity);
            return false;
        }
        int capacity = schedule->event_capacity > 0 ? 2 * schedule->event_capacity : 16;
        control_event *events = realloc(schedule->events, (size_t)capacity * sizeof *events);
        if (events == NULL) {
            snprintf(error, error_size, "out of memory");
            return false;
        }
        schedule->events = events;
        schedule->event_capacity = capacity;
    }
    schedule->events[schedule->event_count++] = (control_event){
        .time = time,
        .frame = first_frame_at(time, schedule->desc->frame_rate),
        .kind = kind,
        .target = target,
        .value = value,
    };
    return true;
}

/* Gives muscle `m` its command, or a pulse's activation. */
static rb_status drive(mu_model *model, const mu_model_desc *desc, int m, control_kind kind, double value)
{
    const char *name = desc->muscles[m].name;
    return kind == CONTROL_TENSION ? mu_model_set_tension(model, name, value)
                                   : mu_model_set_activation(model, name, value);
}

rb_status controls_apply(controls *schedule, mu_model *model, long frame)
{
    const mu_model_desc *desc = schedule->desc;
    for (int m = 0; m < desc->muscle_count; ++m) {
        if (schedule->pulsed[m]) {
            schedule->pulsed[m] = false;
            rb_status status = drive(model, desc, m, schedule->command[m], schedule->command_value[m]);
            if (status != RB_OK) {
                return status;
            }
        }
    }
    const mu_model_variant *variant = &desc->variants[schedule->variant];
    for (; schedule->next < schedule->event_count && schedule->events[schedule->next].frame <= frame;
         ++schedule->next) {
        const control_event *event = &schedule->events[schedule->next];
        for (int i = 0; i < target_muscle_count(desc, event->target); ++i) {
            int m = target_muscle(desc, event->target, i);
            if (!mu_model_variant_has_muscle(variant, m)) {
                continue;
            }
            if (event->kind == CONTROL_PULSE) {
                schedule->pulsed[m] = true;
            } else {
                schedule->pulsed[m] = false;
                schedule->command[m] = event->kind;
                schedule->command_value[m] = event->value;
            }
            rb_status status = drive(model, desc, m, event->kind, event->value);
            if (status != RB_OK) {
                return status;
            }
        }
    }
    return RB_OK;
}

int controls_pending(const controls *schedule) { return schedule->event_count - schedule->next; }
