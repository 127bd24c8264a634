/* SPDX-License-Identifier: MIT */
/** @file
 * Narrow phase: contact manifolds between two shapes.
 *
 * Pure functions of two shapes and their body transforms. The manifold
 * normal points from shape A to shape B; each point lies midway between
 * the two surfaces, its separation is the signed gap along the normal
 * (negative when the shapes overlap), and its feature id names the pair
 * of geometric features that made it, so a solver can carry impulses
 * from frame to frame. Points are reported while the separation is at
 * most `speculative_distance` (m, >= 0): a solver can then stop bodies
 * that would meet during the next step (speculative contact).
 */
#ifndef RB_COLLISION_H
#define RB_COLLISION_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/export.h"
#include "rb/geometry.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RB_MAX_MANIFOLD_POINTS 2

typedef struct rb_manifold_point {
    rb_vec2 point;          /**< m, world, midway between the two surfaces */
    double separation;      /**< m, negative when overlapping */
    uint32_t id;            /**< feature id, see rb_feature_id */
    double normal_impulse;  /**< N·s, impulse the solver applied along the normal in the last step */
    double tangent_impulse; /**< N·s, friction impulse of the last step */
} rb_manifold_point;

typedef struct rb_manifold {
    rb_vec2 normal; /**< unit, world, from shape A to shape B */
    rb_manifold_point points[RB_MAX_MANIFOLD_POINTS];
    int point_count; /**< 0 .. 2 */
    /** Between outlines (polygons, segments): the normal is the outward
     * normal of shape B's reference face, reversed, rather than of shape
     * A's. Always false when a circle is involved. */
    bool reference_on_b;
} rb_manifold;

/** A feature id names the two vertices, one on each shape, that made a
 * point between outlines: the incident vertex the point comes from, and
 * the end of the reference face on that vertex's side (its side plane
 * cuts the incident edge there when the vertex lies beyond it). The pair
 * is written in shape order, A's vertex first, so an id says nothing
 * about which shape holds the reference face: when two faces are nearly
 * parallel, as in any stack, the reference face changes sides with tiny
 * tilts, and the same corner must keep its id, or the point loses the
 * impulse that warm-starts it. Nor does the id say whether a side plane
 * cut the point: for equal boxes stacked exactly, round-off decides it.
 * Circle points have id 0. */
static inline uint32_t rb_feature_id(int vertex_a, int vertex_b)
{
    return ((uint32_t)vertex_a << 8) | (uint32_t)vertex_b;
}

RB_API rb_manifold rb_collide_circles(const rb_circle *a, rb_transform xfa, const rb_circle *b, rb_transform xfb,
                                      double speculative_distance);

RB_API rb_manifold rb_collide_polygon_and_circle(const rb_polygon *a, rb_transform xfa, const rb_circle *b,
                                                 rb_transform xfb, double speculative_distance);

RB_API rb_manifold rb_collide_polygons(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                       double speculative_distance);

/** Segments against circles and polygons, the segment always shape A.
 * Against a polygon the segment is a two-vertex outline whose edge 0
 * runs from point1 to point2 (right normal) and edge 1 back (left
 * normal), so feature ids and reference faces follow the polygon rules
 * above. A circle point has id 0. Segments do not collide with segments. */
RB_API rb_manifold rb_collide_segment_and_circle(const rb_segment *a, rb_transform xfa, const rb_circle *b,
                                                 rb_transform xfb, double speculative_distance);
RB_API rb_manifold rb_collide_segment_and_polygon(const rb_segment *a, rb_transform xfa, const rb_polygon *b,
                                                  rb_transform xfb, double speculative_distance);

/** Chain segments: one-sided (only shapes in front of the left normal
 * collide; a circle whose centre, or a polygon whose centroid, is behind
 * the line gets no points) and smoothed by the ghost vertices. A circle
 * beyond a joint belongs to the neighbour: the segment reports a point
 * at point1 only in the wedge of a convex joint, and never at point2
 * when it has a neighbour there. Against a polygon, the polygon's face
 * becomes the reference only when its normal lies in the fan of
 * normals a convex joint or a free end allows; otherwise the segment's
 * front (edge 1) is the reference, so a box sliding over a flat joint
 * is pushed along the chain's normal only. */
RB_API rb_manifold rb_collide_chain_segment_and_circle(const rb_chain_segment *a, rb_transform xfa, const rb_circle *b,
                                                       rb_transform xfb, double speculative_distance);
RB_API rb_manifold rb_collide_chain_segment_and_polygon(const rb_chain_segment *a, rb_transform xfa,
                                                        const rb_polygon *b, rb_transform xfb,
                                                        double speculative_distance);

#ifdef __cplusplus
}
#endif

#endif
