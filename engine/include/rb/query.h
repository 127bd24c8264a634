/* SPDX-License-Identifier: MIT */
/** @file
 * World queries: which shapes overlap a box, contain a point, or lie
 * along a ray. Enough for a viewer to pick the body under the mouse.
 *
 * Every query sees the shapes at the bodies' current poses (after the
 * last step, or wherever they were placed since), takes a filter, and a
 * flag to include sensor shapes (the models' bones are sensors, so a
 * picker passes true). Results come in a deterministic order: by shape
 * index for overlaps, by fraction along the ray (then shape index) for
 * ray casts. Queries only read the world: they may run between steps
 * and from inside a pre-solve callback.
 */
#ifndef RB_QUERY_H
#define RB_QUERY_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/export.h"
#include "rb/id.h"
#include "rb/math.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The query acts as a shape with these bits would collide: a shape is
 * reported when its category is in mask_bits and category_bits is in
 * its mask. Group indices play no part. */
typedef struct rb_query_filter {
    uint32_t category_bits; /**< default 1, the default shape category */
    uint32_t mask_bits;     /**< default all bits */
} rb_query_filter;

RB_API rb_query_filter rb_default_query_filter(void);

/** Called once per shape found; return false to stop the query. */
typedef bool rb_query_fn(rb_shape_id shape, void *context);

/** The shapes whose bounding box (tight, at the current pose) overlaps
 * `box` (finite, lower <= upper): each passed to fn, or copied to out. */
RB_API rb_status rb_world_query_aabb(const rb_world *world, rb_aabb box, rb_query_filter filter, bool include_sensors,
                                     rb_query_fn *fn, void *context);
/** Copies the first min(capacity, found) shapes to out and stores the
 * number found in *count (which may exceed capacity: call again with a
 * larger array). out may be NULL when capacity is 0. */
RB_API rb_status rb_world_overlap_aabb(const rb_world *world, rb_aabb box, rb_query_filter filter, bool include_sensors,
                                       rb_shape_id *out, int capacity, int *count);

/** The shapes that contain a world point (boundary included). Segments
 * have no area and never contain a point. */
RB_API rb_status rb_world_query_point(const rb_world *world, rb_vec2 point, rb_query_filter filter,
                                      bool include_sensors, rb_query_fn *fn, void *context);
RB_API rb_status rb_world_overlap_point(const rb_world *world, rb_vec2 point, rb_query_filter filter,
                                        bool include_sensors, rb_shape_id *out, int capacity, int *count);

/** Where a ray from `origin` to origin + translation (m, world) enters a
 * shape; see rb_ray_cast_circle for what counts as a hit (a ray that
 * starts inside a shape does not hit it). */
typedef struct rb_ray_hit {
    rb_shape_id shape;
    rb_body_id body;
    rb_vec2 point;   /**< m, world */
    rb_vec2 normal;  /**< unit, world, the shape's outward normal at the point */
    double fraction; /**< 0 .. 1 of the translation */
} rb_ray_hit;

/** The nearest hit: *found says whether there is one, *hit is it (zeroed
 * when none). Equal fractions go to the lower shape index. */
RB_API rb_status rb_world_ray_cast_closest(const rb_world *world, rb_vec2 origin, rb_vec2 translation,
                                           rb_query_filter filter, bool include_sensors, rb_ray_hit *hit, bool *found);

/** Every hit, nearest first: the first min(capacity, hits) go to out, and
 * *count is the number of hits. */
RB_API rb_status rb_world_ray_cast_all(const rb_world *world, rb_vec2 origin, rb_vec2 translation,
                                       rb_query_filter filter, bool include_sensors, rb_ray_hit *out, int capacity,
                                       int *count);

#ifdef __cplusplus
}
#endif

#endif
