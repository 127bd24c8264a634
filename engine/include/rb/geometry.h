/* SPDX-License-Identifier: MIT */
/** @file
 * Shape geometry, its mass properties, bounding boxes and ray casts.
 *
 * Geometry is given in the body's local frame (metres). Boxes are
 * polygons. A polygon is convex, counter-clockwise, with 3 to
 * RB_MAX_POLYGON_VERTICES vertices and outward unit edge normals.
 * Segments are lines of no thickness and no mass, for ground outlines.
 */
#ifndef RB_GEOMETRY_H
#define RB_GEOMETRY_H

#include "rb/base.h"
#include "rb/export.h"
#include "rb/math.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RB_MAX_POLYGON_VERTICES 8

/** Points closer than this are one point to the hull and polygon
 * builders, and a hull vertex closer than this to the line through its
 * neighbours is dropped as collinear (m). */
#define RB_POLYGON_WELD_DISTANCE 0.5e-3

typedef enum rb_shape_type {
    RB_SHAPE_CIRCLE,
    RB_SHAPE_POLYGON,
    RB_SHAPE_SEGMENT,       /**< two-sided line segment */
    RB_SHAPE_CHAIN_SEGMENT, /**< one-sided segment of a chain, smoothed by its neighbours */
} rb_shape_type;

typedef struct rb_circle {
    rb_vec2 center; /**< m, offset from the body origin, coordinates within ±RB_MAX_LENGTH */
    double radius;  /**< m, RB_POLYGON_WELD_DISTANCE .. RB_MAX_LENGTH */
} rb_circle;

typedef struct rb_polygon {
    rb_vec2 vertices[RB_MAX_POLYGON_VERTICES]; /**< m, counter-clockwise */
    rb_vec2 normals[RB_MAX_POLYGON_VERTICES];  /**< unit, normals[i] is outward normal of edge i -> i+1 */
    rb_vec2 centroid;                          /**< m, area centroid */
    int count;                                 /**< 3 .. RB_MAX_POLYGON_VERTICES */
} rb_polygon;

/** A line segment from point1 to point2 (m, at least
 * RB_POLYGON_WELD_DISTANCE apart, coordinates within ±RB_MAX_LENGTH). It has no thickness and no area: its
 * mass is zero, so it belongs on a static or kinematic body, or on a
 * dynamic body with a mass override. It collides with circles and
 * polygons on both sides, not with other segments. */
typedef struct rb_segment {
    rb_vec2 point1, point2;
} rb_segment;

/** One segment of a chain (rb_shape_create_chain), with its neighbours'
 * far points as ghost vertices. It is one-sided: it collides only with
 * shapes on its left, seen from point1 towards point2 (a ground outline
 * given from left to right faces up; a loop given clockwise faces out,
 * counter-clockwise in). The ghosts smooth the joints: a shape sliding
 * along the chain meets each joint as the neighbour's surface, never as
 * a corner, so it does not catch on flat or concave joints. */
typedef struct rb_chain_segment {
    rb_segment segment;
    rb_vec2 ghost1;  /**< m, the previous chain point, when has_ghost1 */
    rb_vec2 ghost2;  /**< m, the next chain point, when has_ghost2 */
    bool has_ghost1; /**< false at the start of an open chain: point1 is a free end */
    bool has_ghost2; /**< false at the end of an open chain: point2 is a free end */
} rb_chain_segment;

/** Mass properties of a shape or a body. */
typedef struct rb_mass_data {
    double mass;               /**< kg, >= 0 */
    rb_vec2 center;            /**< m, centre of mass in the body frame */
    double rotational_inertia; /**< kg·m², about the centre of mass, >= 0 */
} rb_mass_data;

/** A box of half-extents hx, hy (m, from RB_POLYGON_WELD_DISTANCE to
 * RB_MAX_LENGTH) centred on the body origin. */
RB_API rb_status rb_make_box(double hx, double hy, rb_polygon *out);

/** A box of half-extents hx, hy centred at `center` (m, within
 * ±RB_MAX_LENGTH) and turned by `angle` (rad, within ±RB_MAX_ANGLE) in the
 * body frame. */
RB_API rb_status rb_make_offset_box(double hx, double hy, rb_vec2 center, double angle, rb_polygon *out);

/** A convex polygon whose vertices are exactly `points` (any order, any
 * winding). Fails with RB_ERR_NOT_CONVEX when a point lies inside the
 * hull of the others or on one of its edges, RB_ERR_DEGENERATE_SHAPE when
 * the points are collinear, coincident or enclose no area, and
 * RB_ERR_INVALID_ARGUMENT for a count outside 3..8 or a point whose
 * coordinates are not within ±RB_MAX_LENGTH m. */
RB_API rb_status rb_make_polygon(const rb_vec2 *points, int count, rb_polygon *out);

/** The convex hull of a point cloud as a polygon: interior and collinear
 * points are dropped, coincident points welded. Fails only when the hull
 * is degenerate (fewer than 3 vertices) or the input invalid. */
RB_API rb_status rb_make_polygon_hull(const rb_vec2 *points, int count, rb_polygon *out);

/** Mass properties for an area density (kg/m², > 0). */
RB_API rb_mass_data rb_circle_mass(const rb_circle *circle, double density);
RB_API rb_mass_data rb_polygon_mass(const rb_polygon *polygon, double density);

/** Area (m²) of a shape. */
RB_API double rb_circle_area(const rb_circle *circle);
RB_API double rb_polygon_area(const rb_polygon *polygon);

/** The area density (kg/m²) of a plate of thickness `depth` (m, > 0) made
 * of a material of volume density `volume_density` (kg/m³, > 0), so that
 * mass = volume_density · area · depth, as musculoskeletal models' bones and weights. */
RB_API rb_status rb_area_density_from_volume(double volume_density, double depth, double *area_density);

/** Bounding boxes of a shape placed by a transform. */
RB_API rb_aabb rb_circle_aabb(const rb_circle *circle, rb_transform xf);
RB_API rb_aabb rb_polygon_aabb(const rb_polygon *polygon, rb_transform xf);
RB_API rb_aabb rb_segment_aabb(const rb_segment *segment, rb_transform xf);

/** Ray casts against one shape placed by xf: the ray runs from `origin`
 * to origin + translation (m, world). A hit reports where the ray enters
 * the shape: fraction in [0, 1] of the translation, the world point and
 * the shape's outward unit normal there. A ray that starts inside a
 * circle or polygon does not hit it (it never enters), a ray parallel to
 * a segment never hits it, and a zero translation hits nothing. A
 * segment is hit from either side, its normal facing the ray; a chain
 * segment only from its front (left) side. */
typedef struct rb_ray_cast_output {
    bool hit;
    double fraction; /**< 0 .. 1, of the translation */
    rb_vec2 point;   /**< m, world */
    rb_vec2 normal;  /**< unit, world, pointing out of the shape towards the ray's origin side */
} rb_ray_cast_output;

RB_API rb_ray_cast_output rb_ray_cast_circle(const rb_circle *circle, rb_transform xf, rb_vec2 origin,
                                             rb_vec2 translation);
RB_API rb_ray_cast_output rb_ray_cast_polygon(const rb_polygon *polygon, rb_transform xf, rb_vec2 origin,
                                              rb_vec2 translation);
RB_API rb_ray_cast_output rb_ray_cast_segment(const rb_segment *segment, rb_transform xf, rb_vec2 origin,
                                              rb_vec2 translation);
RB_API rb_ray_cast_output rb_ray_cast_chain_segment(const rb_chain_segment *segment, rb_transform xf, rb_vec2 origin,
                                                    rb_vec2 translation);

/** Whether a world point lies inside (or on) the shape placed by xf. */
RB_API bool rb_circle_contains(const rb_circle *circle, rb_transform xf, rb_vec2 point);
RB_API bool rb_polygon_contains(const rb_polygon *polygon, rb_transform xf, rb_vec2 point);

#ifdef __cplusplus
}
#endif

#endif
