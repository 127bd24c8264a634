/* SPDX-License-Identifier: MIT */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "controls.h"

bool controls_init(controls *schedule, const mu_model_desc *desc, int variant)
{
    *schedule = (controls){
        .desc = desc,
        .variant = variant,
        /* As mu_model_substep_duration computes it, so that a shape is
         * sampled at the very times an experiment driving the model
         * substep by substep computes. */
        .substep = 1.0 / (desc->frame_rate * desc->substeps),
    };
    size_t count = (size_t)desc->muscle_count + (size_t)desc->torque_muscle_count + 1; /* + 1: calloc(0) may be NULL */
    schedule->channels = calloc(count, sizeof *schedule->channels);
    if (schedule->channels == NULL) {
        controls_free(schedule);
        return false;
    }
    /* Each muscle's state at creation: activation 0. A torque muscle keeps
     * the recruitment it was built with until a recruit event. */
    for (int c = 0; c < desc->muscle_count + desc->torque_muscle_count; ++c) {
        schedule->channels[c] = (control_channel){
            .kind = c < desc->muscle_count ? CONTROL_ACTIVATION : CONTROL_RECRUIT,
            .shape = {.kind = CONTROL_STEP},
            .pulse_end = CONTROLS_NO_PULSE,
        };
    }
    return true;
}

void controls_free(controls *schedule)
{
    free(schedule->events);
    free(schedule->channels);
    *schedule = (controls){.desc = NULL};
}

const char *control_kind_name(control_kind kind)
{
    switch (kind) {
    case CONTROL_ACTIVATION:
        return "activation";
    case CONTROL_TENSION:
        return "tension";
    case CONTROL_RECRUIT:
        return "recruit";
    case CONTROL_PULSE:
        break;
    }
    return "pulse";
}

/* ------------------------------------------------------------- targets */

/* Channel i of a target, and how many it has: a muscle is its own group
 * of one; a torque muscle's channel follows the muscles'. */
static int target_channel(const mu_model_desc *desc, mu_model_ref target, int i)
{
    switch (target.kind) {
    case MU_MODEL_GROUP:
        return desc->groups[target.index].muscles[i];
    case MU_MODEL_TORQUE_MUSCLE:
        return desc->muscle_count + target.index;
    default:
        return target.index;
    }
}

static int target_channel_count(const mu_model_desc *desc, mu_model_ref target)
{
    return target.kind == MU_MODEL_GROUP ? desc->groups[target.index].muscle_count : 1;
}

/* Whether channel `c` exists in the variant (a torque muscle does when its
 * bones do, as the model builds it). */
static bool channel_in_variant(const controls *schedule, int c)
{
    const mu_model_desc *desc = schedule->desc;
    const mu_model_variant *variant = &desc->variants[schedule->variant];
    if (c < desc->muscle_count) {
        return mu_model_variant_has_muscle(variant, c);
    }
    const mu_model_torque_muscle *torque = &desc->torque_muscles[c - desc->muscle_count];
    return mu_model_variant_has_bone(variant, torque->body.index) &&
           (!torque->has_reaction_body || torque->reaction_body.kind == MU_MODEL_NAIL ||
            mu_model_variant_has_bone(variant, torque->reaction_body.index));
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

/* Lists the names a control may address, since model files give them
 * with spaces and capitals: "muscles: ...; groups: ...; torque muscles: ...". */
static void append_names(const mu_model_desc *desc, char *error, size_t error_size, size_t *used)
{
    append(error, error_size, used, "%s", "muscles:");
    for (int m = 0; m < desc->muscle_count; ++m) {
        append(error, error_size, used, m == 0 ? " \"%s\"" : ", \"%s\"", desc->muscles[m].name);
    }
    append(error, error_size, used, "%s", desc->muscle_count == 0 ? " none" : "");
    append(error, error_size, used, "%s", desc->group_count > 0 ? "; groups:" : "");
    for (int g = 0; g < desc->group_count; ++g) {
        append(error, error_size, used, g == 0 ? " \"%s\"" : ", \"%s\"", desc->groups[g].name);
    }
    append(error, error_size, used, "%s", "; torque muscles (recruit):");
    for (int t = 0; t < desc->torque_muscle_count; ++t) {
        append(error, error_size, used, t == 0 ? " \"%s\"" : ", \"%s\"", desc->torque_muscles[t].name);
    }
    append(error, error_size, used, "%s", desc->torque_muscle_count == 0 ? " none" : "");
}

/* Finds what `name` drives for an event of `kind`: a muscle or a group
 * with a muscle in the schedule's variant, or for recruitment a torque
 * muscle built in it; a control that could move nothing is a mistake in
 * the name or the variant. */
static bool resolve_target(const controls *schedule, control_kind kind, const char *name, mu_model_ref *target,
                           char *error, size_t error_size)
{
    const mu_model_desc *desc = schedule->desc;
    bool found = mu_model_desc_find(desc, name, target);
    bool torque = found && target->kind == MU_MODEL_TORQUE_MUSCLE;
    bool muscle = found && (target->kind == MU_MODEL_MUSCLE || target->kind == MU_MODEL_GROUP);
    size_t used = 0;
    if (kind == CONTROL_RECRUIT && !torque) {
        append(error, error_size, &used,
               muscle ? "recruit drives a torque muscle, and \"%s\" is a muscle or group ("
                      : "no torque muscle named \"%s\" (",
               name);
        append_names(desc, error, error_size, &used);
        append(error, error_size, &used, "%s", ")");
        return false;
    }
    if (kind != CONTROL_RECRUIT && !muscle) {
        if (torque) {
            used = (size_t)snprintf(error, error_size,
                                    "\"%s\" is a torque muscle, driven by recruitment (a recruit line, or --recruit "
                                    "NAME=NEURONS), not %s (",
                                    name, control_kind_name(kind));
        } else {
            append(error, error_size, &used, "no muscle or group named \"%s\" (", name);
        }
        append_names(desc, error, error_size, &used);
        append(error, error_size, &used, "%s", ")");
        return false;
    }
    for (int i = 0; i < target_channel_count(desc, *target); ++i) {
        if (channel_in_variant(schedule, target_channel(desc, *target, i))) {
            return true;
        }
    }
    const char *variant = desc->variants[schedule->variant].name;
    const char *format = target->kind == MU_MODEL_MUSCLE  ? "muscle \"%s\" is not in variant \"%s\""
                         : target->kind == MU_MODEL_GROUP ? "group \"%s\" has no muscle in variant \"%s\""
                                                          : "torque muscle \"%s\" is not built in variant \"%s\"";
    snprintf(error, error_size, format, name, variant);
    return false;
}

/* ---------------------------------------------------------- the values */

/* The largest value of a kind for the target (a torque muscle's pool). */
static double kind_max(const controls *schedule, control_kind kind, mu_model_ref target)
{
    switch (kind) {
    case CONTROL_TENSION:
        return CONTROL_MAX_TENSION;
    case CONTROL_RECRUIT:
        return schedule->desc->torque_muscles[target.index].neurons;
    default:
        return 1.0;
    }
}

/* What a value of the kind is, for messages. */
static const char *kind_quantity(control_kind kind)
{
    switch (kind) {
    case CONTROL_TENSION:
        return "a tension";
    case CONTROL_RECRUIT:
        return "a whole number of neurons";
    default:
        return "an activation";
    }
}

/* Checks one value the line gives (`label`: "the value", "FROM", ...):
 * in 0 .. max, and whole for a count of neurons (`whole`). */
static bool check_value(const controls *schedule, control_kind kind, mu_model_ref target, const char *label,
                        double value, bool whole, char *error, size_t error_size)
{
    double max = kind_max(schedule, kind, target);
    if (value >= 0.0 && value <= max && (!whole || kind != CONTROL_RECRUIT || value == floor(value))) {
        return true;
    }
    snprintf(error, error_size, "%s must be %s from 0 to %g%s, got %g", label, kind_quantity(kind), max,
             kind == CONTROL_TENSION   ? " N"
             : kind == CONTROL_RECRUIT ? " (the size of its motor pool)"
                                       : "",
             value);
    return false;
}

/* Checks the shape's durations and frequencies against the model's
 * substeps, which sample it. */
static bool check_timing(const controls *schedule, const control_shape *shape, char *error, size_t error_size)
{
    const char *name = shape->kind == CONTROL_PULSES ? "pulses'" : shape->kind == CONTROL_SINE ? "sine's" : "ramp's";
    const double rate = 1.0 / schedule->substep; /* substeps per second */
    if (!(shape->duration > 0.0 && shape->duration <= CONTROL_MAX_TIME)) {
        snprintf(error, error_size, "the %s DURATION must be more than 0 s (at most %g s), got %g", name,
                 CONTROL_MAX_TIME, shape->duration);
        return false;
    }
    if (shape->kind == CONTROL_RAMP) {
        return true;
    }
    if (!(shape->frequency > 0.0 && shape->frequency <= rate)) {
        snprintf(error, error_size, "the %s FREQUENCY must be more than 0 Hz (at most %g Hz), got %g", name, rate,
                 shape->frequency);
        return false;
    }
    if (shape->kind == CONTROL_SINE) {
        if (shape->frequency > rate / 2.0) {
            snprintf(error, error_size,
                     "the sine's FREQUENCY %g Hz is above %g Hz, half the model's %g substeps per second: sampled "
                     "once a substep it would alias",
                     shape->frequency, rate / 2.0, rate);
            return false;
        }
        return true;
    }
    const double period = 1.0 / shape->frequency;
    if (!(shape->width > 0.0 && shape->width < period)) {
        snprintf(error, error_size,
                 "the pulses' WIDTH must be more than 0 s and less than the period 1/%g Hz = %g s, got %g",
                 shape->frequency, period, shape->width);
        return false;
    }
    const long width = control_shape_pulse_substeps(shape, schedule->substep);
    if (width < 1) {
        snprintf(error, error_size,
                 "the pulses' WIDTH %g s is less than half a substep of the model (%g s): a pulse is at least "
                 "one substep",
                 shape->width, schedule->substep);
        return false;
    }
    if (floor(period / schedule->substep + 1e-6) < (double)(width + 1)) {
        snprintf(error, error_size,
                 "the pulses of %ld substep%s (WIDTH %g s, in substeps of %g s) at %g Hz leave no substep between "
                 "two pulses",
                 width, width == 1 ? "" : "s", shape->width, schedule->substep, shape->frequency);
        return false;
    }
    return true;
}

/* Checks every value the shape takes. */
static bool check_shape(const controls *schedule, control_kind kind, mu_model_ref target, const control_shape *shape,
                        char *error, size_t error_size)
{
    switch (shape->kind) {
    case CONTROL_STEP:
        return check_value(schedule, kind, target, kind == CONTROL_RECRUIT ? "the neurons recruited" : "the value",
                           shape->first, true, error, error_size);
    case CONTROL_RAMP:
        return check_timing(schedule, shape, error, error_size) &&
               check_value(schedule, kind, target, "the ramp's FROM", shape->first, true, error, error_size) &&
               check_value(schedule, kind, target, "the ramp's TO", shape->second, true, error, error_size);
    case CONTROL_SINE:
        if (!(shape->second >= 0.0)) {
            snprintf(error, error_size, "the sine's AMPLITUDE must be 0 or more, got %g", shape->second);
            return false;
        }
        return check_timing(schedule, shape, error, error_size) &&
               check_value(schedule, kind, target, "the sine's MEAN - AMPLITUDE", shape->first - shape->second, false,
                           error, error_size) &&
               check_value(schedule, kind, target, "the sine's MEAN + AMPLITUDE", shape->first + shape->second, false,
                           error, error_size);
    case CONTROL_PULSES:
        return check_timing(schedule, shape, error, error_size) &&
               check_value(schedule, kind, target, "the pulses' LEVEL", shape->first, true, error, error_size);
    }
    return true;
}

/* ---------------------------------------------------------- the events */

bool controls_add_shape(controls *schedule, control_kind kind, const char *name, const control_shape *shape,
                        char *error, size_t error_size)
{
    const double time = shape->start;
    if (!(time >= 0.0 && time <= CONTROL_MAX_TIME)) {
        snprintf(error, error_size, "the time must be from 0 to %g s, got %g", CONTROL_MAX_TIME, time);
        return false;
    }
    if (schedule->event_count > 0 && time < schedule->events[schedule->event_count - 1].shape.start) {
        snprintf(error, error_size, "the time %g s is before the previous control's %g s: times must not decrease",
                 time, schedule->events[schedule->event_count - 1].shape.start);
        return false;
    }
    mu_model_ref target;
    if (!resolve_target(schedule, kind, name, &target, error, error_size) ||
        !check_shape(schedule, kind, target, shape, error, error_size)) {
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
        .substep = control_first_substep_at(time, schedule->substep),
        .kind = kind,
        .target = target,
        .shape = *shape,
    };
    return true;
}

bool controls_add(controls *schedule, double time, control_kind kind, const char *name, double value, char *error,
                  size_t error_size)
{
    control_shape step = {.kind = CONTROL_STEP, .start = time, .first = value};
    return controls_add_shape(schedule, kind, name, &step, error, error_size);
}

/* ---------------------------------------------------- driving the model */

/* The value channel `c` has at `substep`: its pulse's while one lasts,
 * else its command's, a whole number of neurons for a torque muscle
 * (rounded to the nearest, halves up, as a ramp or sine of recruitment asks). */
static double channel_value(const controls *schedule, const control_channel *channel, long substep)
{
    if (substep < channel->pulse_end) {
        return channel->pulse_value;
    }
    double value = control_shape_value(&channel->shape, (double)substep * schedule->substep, schedule->substep);
    return channel->kind == CONTROL_RECRUIT ? round(value) : value;
}

/* Gives channel `c` its value at `substep`. */
static rb_status drive(controls *schedule, mu_model *model, int c, long substep)
{
    const mu_model_desc *desc = schedule->desc;
    control_channel *channel = &schedule->channels[c];
    channel->value = channel_value(schedule, channel, substep);
    if (channel->kind == CONTROL_RECRUIT) {
        const char *name = desc->torque_muscles[c - desc->muscle_count].name;
        /* Built at level 3 and above only. */
        for (int t = 0; t < mu_model_torque_muscle_count(model); ++t) {
            if (strcmp(mu_model_torque_muscle_name(model, t), name) == 0) {
                return mu_model_recruit_at(model, t, (int)channel->value);
            }
        }
        return RB_OK;
    }
    const char *name = desc->muscles[c].name;
    bool tension = channel->kind == CONTROL_TENSION && substep >= channel->pulse_end;
    return tension ? mu_model_set_tension(model, name, channel->value)
                   : mu_model_set_activation(model, name, channel->value);
}

/* Acts event `event` on each of its channels in the variant, at `substep`. */
static void act(controls *schedule, const control_event *event, long substep)
{
    const mu_model_desc *desc = schedule->desc;
    for (int i = 0; i < target_channel_count(desc, event->target); ++i) {
        int c = target_channel(desc, event->target, i);
        if (!channel_in_variant(schedule, c)) {
            continue;
        }
        control_channel *channel = &schedule->channels[c];
        if (event->kind == CONTROL_PULSE) {
            channel->pulse_end = substep + desc->substeps;
            channel->pulse_value = event->shape.first;
        } else {
            channel->kind = event->kind;
            channel->shape = event->shape;
            channel->pulse_end = CONTROLS_NO_PULSE;
        }
        channel->due = true;
    }
}

static int channel_count(const controls *schedule)
{
    return schedule->desc->muscle_count + schedule->desc->torque_muscle_count;
}

rb_status controls_apply(controls *schedule, mu_model *model, long substep)
{
    for (; schedule->next < schedule->event_count && schedule->events[schedule->next].substep <= substep;
         ++schedule->next) {
        act(schedule, &schedule->events[schedule->next], substep);
    }
    for (int c = 0; c < channel_count(schedule); ++c) {
        control_channel *channel = &schedule->channels[c];
        /* A step's command changes only when an event comes or a pulse
         * ends; another shape is sampled at every substep. */
        if (channel->due || substep == channel->pulse_end || channel->shape.kind != CONTROL_STEP) {
            channel->due = false;
            rb_status status = drive(schedule, model, c, substep);
            if (status != RB_OK) {
                return status;
            }
        }
    }
    return RB_OK;
}

/* Whether, once substep `first` is applied, nothing the schedule drives
 * changes before substep first + count: no event acts and no pulse ends
 * in between, and every shape keeps its value there. */
static bool steady(const controls *schedule, long first, int count)
{
    const long end = first + count;
    if (schedule->next < schedule->event_count && schedule->events[schedule->next].substep < end) {
        return false;
    }
    for (int c = 0; c < channel_count(schedule); ++c) {
        const control_channel *channel = &schedule->channels[c];
        if (channel->pulse_end > first && channel->pulse_end < end) {
            return false;
        }
        if (channel->shape.kind == CONTROL_STEP || !channel_in_variant(schedule, c)) {
            continue;
        }
        double value = channel_value(schedule, channel, first);
        for (long k = first + 1; k < end; ++k) {
            if (channel_value(schedule, channel, k) != value) {
                return false;
            }
        }
    }
    return true;
}

rb_status controls_step_frame(controls *schedule, mu_model *model, long frame)
{
    const int substeps = schedule->desc->substeps;
    const long first = frame * substeps;
    rb_status status = controls_apply(schedule, model, first);
    if (status != RB_OK) {
        return status;
    }
    if (steady(schedule, first, substeps)) {
        return mu_model_step(model);
    }
    status = mu_model_substep(model);
    for (long k = first + 1; k < first + substeps && status == RB_OK; ++k) {
        status = controls_apply(schedule, model, k);
        if (status == RB_OK) {
            status = mu_model_substep(model);
        }
    }
    return status;
}

double controls_muscle_value(const controls *schedule, int muscle, control_kind *kind)
{
    const control_channel *channel = &schedule->channels[muscle];
    *kind = channel->kind;
    return channel->value;
}

int controls_pending(const controls *schedule) { return schedule->event_count - schedule->next; }
