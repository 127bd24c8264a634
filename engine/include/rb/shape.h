/* SPDX-License-Identifier: MIT */
/** @file
 * Shapes: the geometry, material and collision filter attached to a body.
 *
 * Mixing rules when two shapes touch: friction is the geometric mean
 * sqrt(f_a·f_b) (so a frictionless shape slides on anything), restitution
 * the larger of the two (so one bouncy ball bounces on any floor).
 */
#ifndef RB_SHAPE_H
#define RB_SHAPE_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/export.h"
#include "rb/geometry.h"
#include "rb/id.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Which shapes may touch. Two shapes collide when they share a non-zero
 * group index that is positive (always) — a negative shared group never
 * collides — and otherwise when each one's category is in the other's
 * mask. */
typedef struct rb_filter {
    uint32_t category_bits; /**< default 1 */
    uint32_t mask_bits;     /**< default all bits */
    int32_t group_index;    /**< default 0 */
} rb_filter;

typedef struct rb_shape_def {
    double friction;    /**< Coulomb coefficient, 0 .. RB_MAX_FRICTION, default 0.6 */
    double restitution; /**< 0 .. 1, default 0 */
    /** kg/m², 0 .. RB_MAX_DENSITY, default 1. The shape's mass, density
     * times area, is at most RB_MAX_MASS; on a dynamic body without a
     * mass override the density must be > 0 and the mass at least
     * RB_MIN_MASS. */
    double density;
    bool is_sensor; /**< reports overlaps with non-sensor shapes, never pushes */
    rb_filter filter;
    void *user_data;
    /** Set by rb_default_shape_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_shape_def() and change fields. */
    int32_t internal_value;
} rb_shape_def;

RB_API rb_filter rb_default_filter(void);
RB_API rb_shape_def rb_default_shape_def(void);

RB_API rb_status rb_shape_create_circle(rb_world *world, rb_body_id body, const rb_shape_def *def,
                                        const rb_circle *circle, rb_shape_id *out);
RB_API rb_status rb_shape_create_polygon(rb_world *world, rb_body_id body, const rb_shape_def *def,
                                         const rb_polygon *polygon, rb_shape_id *out);
/** A two-sided segment (see rb_segment). Segments have no mass: on a
 * dynamic body without a mass override this fails with RB_ERR_NO_MASS;
 * the density is kept but adds nothing. */
RB_API rb_status rb_shape_create_segment(rb_world *world, rb_body_id body, const rb_shape_def *def,
                                         const rb_segment *segment, rb_shape_id *out);

/** A chain: one chain-segment shape (rb_chain_segment, one-sided, facing
 * left of the point order) per pair of consecutive points, each knowing
 * its neighbours as ghost vertices, so shapes slide and roll across the
 * joints. `count` points (at least 2, or 3 for a loop; consecutive
 * points at least RB_POLYGON_WELD_DISTANCE apart) make count - 1
 * segments, or `count` when `loop` closes the chain from the last point
 * back to the first. Their ids go to `out` in order when it is not NULL
 * (capacity at least the segment count). Same mass rule as segments.
 * On failure no segment is left on the body. */
RB_API rb_status rb_shape_create_chain(rb_world *world, rb_body_id body, const rb_shape_def *def, const rb_vec2 *points,
                                       int count, bool loop, rb_shape_id *out, int capacity);

RB_API rb_status rb_shape_destroy(rb_world *world, rb_shape_id shape);
RB_API bool rb_shape_is_valid(const rb_world *world, rb_shape_id shape);

RB_API rb_shape_type rb_shape_type_of(const rb_world *world, rb_shape_id shape);
RB_API rb_body_id rb_shape_body(const rb_world *world, rb_shape_id shape);
RB_API rb_circle rb_shape_circle(const rb_world *world, rb_shape_id shape);
RB_API rb_polygon rb_shape_polygon(const rb_world *world, rb_shape_id shape);
/** A segment's or chain segment's points (zero for other shapes). */
RB_API rb_segment rb_shape_segment(const rb_world *world, rb_shape_id shape);
/** A chain segment with its ghosts (zero for other shapes). */
RB_API rb_chain_segment rb_shape_chain_segment(const rb_world *world, rb_shape_id shape);
/** The smallest axis-aligned box around the shape at its body's current pose. */
RB_API rb_aabb rb_shape_aabb(const rb_world *world, rb_shape_id shape);

RB_API rb_status rb_shape_set_friction(rb_world *world, rb_shape_id shape, double friction);
RB_API double rb_shape_friction(const rb_world *world, rb_shape_id shape);
RB_API rb_status rb_shape_set_restitution(rb_world *world, rb_shape_id shape, double restitution);
RB_API double rb_shape_restitution(const rb_world *world, rb_shape_id shape);
/** Changes the density and recomputes the body's mass. */
RB_API rb_status rb_shape_set_density(rb_world *world, rb_shape_id shape, double density);
RB_API double rb_shape_density(const rb_world *world, rb_shape_id shape);
RB_API bool rb_shape_is_sensor(const rb_world *world, rb_shape_id shape);
RB_API rb_status rb_shape_set_filter(rb_world *world, rb_shape_id shape, rb_filter filter);
RB_API rb_filter rb_shape_filter(const rb_world *world, rb_shape_id shape);
RB_API rb_status rb_shape_set_user_data(rb_world *world, rb_shape_id shape, void *user_data);
RB_API void *rb_shape_user_data(const rb_world *world, rb_shape_id shape);

/** For a sensor: the non-sensor shapes overlapping it after the last step,
 * in deterministic order. Returns how many it copied (at most capacity),
 * or -1 with an error when `sensor` is not a valid sensor shape. */
RB_API int rb_shape_sensor_overlaps(const rb_world *world, rb_shape_id sensor, rb_shape_id *out, int capacity);

#ifdef __cplusplus
}
#endif

#endif
