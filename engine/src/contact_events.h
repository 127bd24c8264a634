/* SPDX-License-Identifier: MIT */
/* Contact and sensor events: recorded by the contact phases of the step
 * (contact.c), published as arrays that stay put until the next step.
 *
 * Every array is reserved before the phases that fill it, in
 * rb_contacts_update (which can report running out of memory), so
 * recording an event never allocates and never fails. Each holds one
 * event per contact, whatever the contacts do: the arrays grow only
 * when the contacts' own arrays do, so a step whose contact count stays
 * within what it has had allocates nothing (bench_engine counts). */
#ifndef RB_CONTACT_EVENTS_H
#define RB_CONTACT_EVENTS_H

#include "world_internal.h"

/* Starts a step's events: drops the last step's, brings in the end
 * events of shapes destroyed since, and reserves room for an end event
 * per contact (what the step can end). */
rb_status rb_contact_events_start_step(rb_world *world);

/* Reserves room for a begin event per contact (what the step can
 * begin), once the contacts are updated. */
rb_status rb_contact_events_reserve_begins(rb_world *world);

/* Records a begin or an end when a non-sensor contact's touching state
 * differs from the one last reported. */
void rb_contact_events_update(rb_world *world, rb_contact *contact);

/* The same for a sensor contact. */
void rb_contact_events_update_sensor(rb_world *world, rb_contact *contact);

/* Records the end of a touching contact whose pair is gone. */
void rb_contact_events_drop(rb_world *world, const rb_contact *contact);

/* Ends the touching contacts of a shape about to be destroyed; the
 * events wait for the next step. */
rb_status rb_contact_events_remove_shape(rb_world *world, int shape);

/* The registered pre-solve filter's verdict on a contact (true without one). */
bool rb_contact_events_pre_solve(const rb_world *world, const rb_contact *contact);

void rb_contact_events_free(rb_world *world);
size_t rb_contact_events_bytes(const rb_world *world);

#endif
