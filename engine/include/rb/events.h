/* SPDX-License-Identifier: MIT */
/** @file
 * Contact and sensor events, and the pre-solve filter.
 *
 * Events are read after a step, never delivered by callback: the step
 * records them, and rb_world_contact_events / rb_world_sensor_events
 * return arrays that stay valid and unchanged until the next
 * rb_world_step (or rb_world_destroy). So a caller may change the world
 * while it walks them.
 *
 * A contact begins touching when some manifold point reaches separation
 * <= 0 and ends when none does, or when its shapes part, stop passing the
 * filter, or one of them is destroyed: each begin is followed by exactly
 * one end. Destroying a shape between steps ends its touching contacts;
 * those end events come with the next step's events, and their ids are
 * then stale (compare them, do not look them up). A sensor's events
 * follow its overlaps at the end of each step, as
 * rb_shape_sensor_overlaps reports them. Events are in the world's
 * deterministic contact order.
 */
#ifndef RB_EVENTS_H
#define RB_EVENTS_H

#include <stdbool.h>

#include "rb/collision.h"
#include "rb/export.h"
#include "rb/id.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rb_contact_begin_event {
    rb_shape_id shape_a, shape_b;
    /** As the narrow phase found it before this step's solve (impulses
     * are last step's, zero for a new contact); normal from A to B. */
    rb_manifold manifold;
} rb_contact_begin_event;

typedef struct rb_contact_end_event {
    rb_shape_id shape_a, shape_b;
} rb_contact_end_event;

typedef struct rb_contact_events {
    const rb_contact_begin_event *begin_events;
    int begin_count;
    const rb_contact_end_event *end_events;
    int end_count;
} rb_contact_events;

/** A non-sensor shape (the visitor) began or stopped overlapping a sensor. */
typedef struct rb_sensor_event {
    rb_shape_id sensor_shape;
    rb_shape_id visitor_shape;
} rb_sensor_event;

typedef struct rb_sensor_events {
    const rb_sensor_event *begin_events;
    int begin_count;
    const rb_sensor_event *end_events;
    int end_count;
} rb_sensor_events;

/** The events of the last step (all empty before the first). A NULL world
 * gives empty arrays and an error. */
RB_API rb_contact_events rb_world_contact_events(const rb_world *world);
RB_API rb_sensor_events rb_world_sensor_events(const rb_world *world);

/** Called during the step for every non-sensor contact that has manifold
 * points (speculative ones too: they push as well), after the narrow
 * phase and before the solver. Return false to disable the contact for
 * this step: its points are dropped, so it pushes nothing, carries no
 * impulse to the next step, and rb_world_contacts shows it without
 * points; its touching state and events are unchanged. The world is
 * locked: the function may read it, not change it. */
typedef bool rb_pre_solve_fn(rb_shape_id shape_a, rb_shape_id shape_b, const rb_manifold *manifold, void *context);

/** Registers the pre-solve filter (NULL removes it); `context` is passed
 * back to it. */
RB_API rb_status rb_world_set_pre_solve(rb_world *world, rb_pre_solve_fn *fn, void *context);

#ifdef __cplusplus
}
#endif

#endif
