/* SPDX-License-Identifier: MIT */
/* Contacts: their life from broad-phase pairs, and the narrow phase that
 * gives each its manifold. */
#ifndef RB_CONTACT_H
#define RB_CONTACT_H

#include "world_internal.h"

/* Makes world->contacts follow the broad phase's pairs: keeps contacts
 * whose pair remains (with their impulses), adds the pairs that began,
 * drops those that ended (broad_phase.h). */
rb_status rb_contacts_update(rb_world *world);

/* Mixes again the friction and restitution of every contact of `shape`
 * (an index in world->shapes), after its material changed. */
void rb_contacts_mix_materials(rb_world *world, int shape);

/* Whether the contact's two shapes' swept boxes overlap in this step (or
 * did in the last one, between steps): if not, they cannot meet within
 * the step, and the contact has no point. */
static inline bool rb_contact_may_meet_in_step(const rb_world *world, const rb_contact *contact)
{
    return rb_aabb_overlaps(world->shapes[contact->pair.shape_a].aabb, world->shapes[contact->pair.shape_b].aabb);
}

/* Computes the manifold of every contact whose shapes' swept boxes
 * overlap (the others get none) for a step of dt seconds, carries the
 * last step's impulses to points with the same feature id, and wakes a
 * sleeping body touched by a moving one. */
void rb_contacts_collide(rb_world *world, double dt);

/* m, >= 0: the deepest overlap of the contact's two shapes at the bodies'
 * poses now, by the narrow phase (exact, where the solver's contact
 * points, carried with the bodies since the step's narrow phase, are
 * first-order). */
double rb_contact_deepest_overlap_now(const rb_world *world, const rb_contact *contact);

/* Sets `touching` on every sensor contact from the bodies' poses at the
 * end of the step, so a sensor reports what overlaps it now. */
void rb_contacts_update_sensors(rb_world *world);

#endif
