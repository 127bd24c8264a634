/* SPDX-License-Identifier: MIT */
/* Contact and sensor events, and the pre-solve filter. */
#include <assert.h>
#include <string.h>

#include "allocator.h"
#include "contact_events.h"
#include "error.h"

static rb_status reserve(void **array, int *capacity, int needed, size_t size)
{
    if (rb_grow_array(array, capacity, needed, size) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for contact events");
    }
    return RB_OK;
}

static rb_contact_end_event end_event(const rb_world *world, const rb_contact *contact)
{
    return (rb_contact_end_event){rb_make_shape_id(world, contact->pair.shape_a),
                                  rb_make_shape_id(world, contact->pair.shape_b)};
}

/* The sensor first, the visitor second, whichever is shape A. */
static rb_sensor_event sensor_event(const rb_world *world, const rb_contact *contact)
{
    int a = contact->pair.shape_a;
    int b = contact->pair.shape_b;
    bool a_is_sensor = world->shapes[a].sensor;
    return (rb_sensor_event){rb_make_shape_id(world, a_is_sensor ? a : b),
                             rb_make_shape_id(world, a_is_sensor ? b : a)};
}

rb_status rb_contact_events_start_step(rb_world *world)
{
    rb_event_arrays *e = &world->events;
    RB_TRY(reserve((void **)&e->ends, &e->end_capacity, e->pending_end_count + world->contact_count, sizeof *e->ends));
    RB_TRY(reserve((void **)&e->sensor_ends, &e->sensor_end_capacity,
                   e->pending_sensor_end_count + world->contact_count, sizeof *e->sensor_ends));
    e->begin_count = 0;
    e->sensor_begin_count = 0;
    e->end_count = e->pending_end_count;
    if (e->end_count > 0) {
        memcpy(e->ends, e->pending_ends, (size_t)e->end_count * sizeof *e->ends);
    }
    e->sensor_end_count = e->pending_sensor_end_count;
    if (e->sensor_end_count > 0) {
        memcpy(e->sensor_ends, e->pending_sensor_ends, (size_t)e->sensor_end_count * sizeof *e->sensor_ends);
    }
    e->pending_end_count = 0;
    e->pending_sensor_end_count = 0;
    return RB_OK;
}

rb_status rb_contact_events_reserve_begins(rb_world *world)
{
    rb_event_arrays *e = &world->events;
    RB_TRY(reserve((void **)&e->begins, &e->begin_capacity, world->contact_count, sizeof *e->begins));
    RB_TRY(
        reserve((void **)&e->sensor_begins, &e->sensor_begin_capacity, world->contact_count, sizeof *e->sensor_begins));
    return RB_OK;
}

void rb_contact_events_update(rb_world *world, rb_contact *contact)
{
    rb_event_arrays *e = &world->events;
    if (contact->touching == contact->reported_touching) {
        return;
    }
    if (contact->touching) {
        assert(e->begin_count < e->begin_capacity);
        e->begins[e->begin_count++] = (rb_contact_begin_event){
            .shape_a = rb_make_shape_id(world, contact->pair.shape_a),
            .shape_b = rb_make_shape_id(world, contact->pair.shape_b),
            .manifold = contact->manifold,
        };
    } else {
        assert(e->end_count < e->end_capacity);
        e->ends[e->end_count++] = end_event(world, contact);
    }
    contact->reported_touching = contact->touching;
}

void rb_contact_events_update_sensor(rb_world *world, rb_contact *contact)
{
    rb_event_arrays *e = &world->events;
    if (contact->touching == contact->reported_touching) {
        return;
    }
    if (contact->touching) {
        assert(e->sensor_begin_count < e->sensor_begin_capacity);
        e->sensor_begins[e->sensor_begin_count++] = sensor_event(world, contact);
    } else {
        assert(e->sensor_end_count < e->sensor_end_capacity);
        e->sensor_ends[e->sensor_end_count++] = sensor_event(world, contact);
    }
    contact->reported_touching = contact->touching;
}

void rb_contact_events_drop(rb_world *world, const rb_contact *contact)
{
    rb_event_arrays *e = &world->events;
    if (!contact->reported_touching) {
        return;
    }
    if (contact->sensor) {
        assert(e->sensor_end_count < e->sensor_end_capacity);
        e->sensor_ends[e->sensor_end_count++] = sensor_event(world, contact);
    } else {
        assert(e->end_count < e->end_capacity);
        e->ends[e->end_count++] = end_event(world, contact);
    }
}

rb_status rb_contact_events_remove_shape(rb_world *world, int shape)
{
    rb_event_arrays *e = &world->events;
    int ends = 0;
    int sensor_ends = 0;
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *c = &world->contacts[i];
        if (c->reported_touching && (c->pair.shape_a == shape || c->pair.shape_b == shape)) {
            ends += c->sensor ? 0 : 1;
            sensor_ends += c->sensor ? 1 : 0;
        }
    }
    if (rb_grow_array((void **)&e->pending_ends, &e->pending_end_capacity, e->pending_end_count + ends,
                      sizeof *e->pending_ends) != 0 ||
        rb_grow_array((void **)&e->pending_sensor_ends, &e->pending_sensor_end_capacity,
                      e->pending_sensor_end_count + sensor_ends, sizeof *e->pending_sensor_ends) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_shape_destroy: out of memory for its contacts' end events");
    }
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *c = &world->contacts[i];
        if (!c->reported_touching || (c->pair.shape_a != shape && c->pair.shape_b != shape)) {
            continue;
        }
        if (c->sensor) {
            e->pending_sensor_ends[e->pending_sensor_end_count++] = sensor_event(world, c);
        } else {
            e->pending_ends[e->pending_end_count++] = end_event(world, c);
        }
    }
    return RB_OK;
}

bool rb_contact_events_pre_solve(const rb_world *world, const rb_contact *contact)
{
    if (world->pre_solve == NULL) {
        return true;
    }
    return world->pre_solve(rb_make_shape_id(world, contact->pair.shape_a),
                            rb_make_shape_id(world, contact->pair.shape_b), &contact->manifold,
                            world->pre_solve_context);
}

void rb_contact_events_free(rb_world *world)
{
    rb_event_arrays *e = &world->events;
    rb_free_array((void **)&e->begins, &e->begin_capacity, sizeof *e->begins);
    rb_free_array((void **)&e->ends, &e->end_capacity, sizeof *e->ends);
    rb_free_array((void **)&e->sensor_begins, &e->sensor_begin_capacity, sizeof *e->sensor_begins);
    rb_free_array((void **)&e->sensor_ends, &e->sensor_end_capacity, sizeof *e->sensor_ends);
    rb_free_array((void **)&e->pending_ends, &e->pending_end_capacity, sizeof *e->pending_ends);
    rb_free_array((void **)&e->pending_sensor_ends, &e->pending_sensor_end_capacity, sizeof *e->pending_sensor_ends);
}

size_t rb_contact_events_bytes(const rb_world *world)
{
    const rb_event_arrays *e = &world->events;
    return (size_t)e->begin_capacity * sizeof *e->begins + (size_t)e->end_capacity * sizeof *e->ends +
           (size_t)e->sensor_begin_capacity * sizeof *e->sensor_begins +
           (size_t)e->sensor_end_capacity * sizeof *e->sensor_ends +
           (size_t)e->pending_end_capacity * sizeof *e->pending_ends +
           (size_t)e->pending_sensor_end_capacity * sizeof *e->pending_sensor_ends;
}

/* ---- public -------------------------------------------------------------- */

rb_contact_events rb_world_contact_events(const rb_world *world)
{
    rb_clear_error();
    if (world == NULL) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_world_contact_events: world is NULL");
        return (rb_contact_events){0};
    }
    const rb_event_arrays *e = &world->events;
    return (rb_contact_events){e->begins, e->begin_count, e->ends, e->end_count};
}

rb_sensor_events rb_world_sensor_events(const rb_world *world)
{
    rb_clear_error();
    if (world == NULL) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_world_sensor_events: world is NULL");
        return (rb_sensor_events){0};
    }
    const rb_event_arrays *e = &world->events;
    return (rb_sensor_events){e->sensor_begins, e->sensor_begin_count, e->sensor_ends, e->sensor_end_count};
}

rb_status rb_world_set_pre_solve(rb_world *world, rb_pre_solve_fn *fn, void *context)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_set_pre_solve", "world", world));
    RB_TRY(rb_world_check_unlocked(world, "rb_world_set_pre_solve"));
    world->pre_solve = fn;
    world->pre_solve_context = context;
    return RB_OK;
}
