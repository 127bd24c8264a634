/* Broad phase: which shape pairs are close enough to need the narrow phase. */
#ifndef RB_BROAD_PHASE_H
#define RB_BROAD_PHASE_H

#include "world_internal.h"

/* Refreshes every shape's box for a step of dt seconds and fills
 * world->pairs, sorted by (body_key, shape_key). */
rb_status rb_broad_phase_update_pairs(rb_world *world, double dt);

/* Whether two shapes may ever touch: different bodies, at least one of
 * them dynamic, not two sensors, and their filters agree. */
bool rb_should_collide(const rb_world *world, int shape_a, int shape_b);

#endif
