/* SPDX-License-Identifier: MIT */
/* Broad phase: which shape pairs are close enough to need the narrow phase. */
#ifndef RB_BROAD_PHASE_H
#define RB_BROAD_PHASE_H

#include "world_internal.h"

/* Refreshes every shape's swept box for a step of dt seconds and tells
 * how the pairs (shapes that may collide, fat boxes overlapping) change:
 * after a full search, world->pairs holds them all (pairs_rebuilt);
 * otherwise world->new_pairs and world->ended_pairs list those that begin
 * and end, both empty when no shape left its fat box. Every list is
 * sorted by (body_key, shape_key). */
rb_status rb_broad_phase_update_pairs(rb_world *world, double dt);

/* Called for each shape found; return false to stop. */
typedef bool rb_broad_phase_visit_fn(const rb_world *world, int shape, void *context);

/* Visits every live shape whose tight box at the bodies' current poses
 * overlaps `box`, in increasing shape index, until `visit` returns false.
 * The world queries (query.c) find their candidates through this one
 * function, so another broad phase only has to provide it. */
void rb_broad_phase_query(const rb_world *world, rb_aabb box, rb_broad_phase_visit_fn *visit, void *context);

/* Whether two shapes may ever touch: different bodies, at least one of
 * them dynamic, not two sensors, and their filters agree. */
bool rb_should_collide(const rb_world *world, int shape_a, int shape_b);

#endif
