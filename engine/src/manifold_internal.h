/* SPDX-License-Identifier: MIT */
/* The pieces of the narrow phase that the polygon, box and segment
 * manifolds share: placing a polygon in another frame, SAT between two
 * placed convex outlines, the manifold from their best axes, and
 * clipping an incident edge against a reference face. */
#ifndef RB_MANIFOLD_INTERNAL_H
#define RB_MANIFOLD_INTERNAL_H

#include "rb/collision.h"

/* How much deeper shape B's best axis must be than shape A's before B
 * holds the reference face (m). Without this margin two nearly equal
 * axes would swap from frame to frame, and with them the feature ids
 * that carry impulses. */
#define RB_REFERENCE_FACE_TOLERANCE 0.5e-3

/* A convex outline's vertices and outward edge normals in some frame:
 * a polygon, or a segment as a two-vertex outline (edge 0 from point1 to
 * point2 with the right normal, edge 1 back with the left normal). */
typedef struct rb_placed_polygon {
    rb_vec2 vertices[RB_MAX_POLYGON_VERTICES];
    rb_vec2 normals[RB_MAX_POLYGON_VERTICES];
    int count;
} rb_placed_polygon;

/* The polygon placed by xf, written into `placed` (a copy of the
 * whole struct would cost a fifth of a box's manifold). */
static inline void rb_place_polygon(const rb_polygon *polygon, rb_transform xf, rb_placed_polygon *placed)
{
    placed->count = polygon->count;
    for (int i = 0; i < polygon->count; ++i) {
        placed->vertices[i] = rb_transform_point(xf, polygon->vertices[i]);
        placed->normals[i] = rb_rotate(xf.q, polygon->normals[i]);
    }
}

/* An outline read where it lies, without a copy: a polygon in its own
 * frame, or a placed polygon. */
typedef struct rb_outline {
    const rb_vec2 *vertices;
    const rb_vec2 *normals;
    int count;
} rb_outline;

static inline rb_outline rb_polygon_outline(const rb_polygon *polygon)
{
    return (rb_outline){polygon->vertices, polygon->normals, polygon->count};
}

static inline rb_outline rb_placed_outline(const rb_placed_polygon *placed)
{
    return (rb_outline){placed->vertices, placed->normals, placed->count};
}

/* An outline's best separating axis: the edge along whose normal the
 * other outline reaches least far below it, and that separation (m). */
typedef struct rb_axis {
    int edge;
    double separation;
} rb_axis;

/* The functions below that take `rb_manifold *m` write a manifold into
 * one that starts zeroed (no points, no impulses), in the frame their
 * arguments are given in. */

/* The manifold of two outlines given in the same frame (shape A's), from
 * each one's best axis (neither separating by more than the speculative
 * distance): the reference face is on the axis of least penetration,
 * shape A's unless B's is deeper by RB_REFERENCE_FACE_TOLERANCE; the
 * incident edge is the other outline's edge most opposed to it, clipped
 * to the face. */
void rb_manifold_from_axes(const rb_outline *a, const rb_outline *b, rb_axis axis_a, rb_axis axis_b,
                           double speculative_distance, rb_manifold *m);

/* The manifold of two outlines given in the same frame (shape A's): both
 * outlines' best axes by a search over every edge and vertex, then
 * rb_manifold_from_axes. */
void rb_collide_placed_polygons(const rb_placed_polygon *pa, const rb_placed_polygon *pb, double speculative_distance,
                                rb_manifold *m);

/* rb_collide_polygons for any two convex polygons: the reference that
 * the box path (box_manifold.c) must reproduce. */
rb_manifold rb_collide_convex_polygons(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                       double speculative_distance);

/* An edge of an outline: its two vertices in the outline's order, and
 * their indices in it, which name the vertices in feature ids. */
typedef struct rb_edge {
    rb_vec2 v1, v2;
    int index1, index2;
} rb_edge;

/* Edge `i` of an outline: from vertex i to the next. */
rb_edge rb_polygon_edge(const rb_outline *outline, int i);

/* Clips the incident edge to the side planes of the reference face
 * (outward normal `reference_normal`) and keeps the points within the
 * speculative distance of the face. `flip` says the reference face is
 * shape B's; the normal is then reversed, so it still points from A to
 * B. No points when the incident edge misses the face. */
void rb_clip_incident_edge(const rb_edge *reference, rb_vec2 reference_normal, const rb_edge *incident, bool flip,
                           double speculative_distance, rb_manifold *m);

/* Adds a point to a manifold, its impulses left zero. */
void rb_manifold_add_point(rb_manifold *m, rb_vec2 point, double separation, uint32_t id);

/* Moves a manifold computed in xf's local frame to the world. */
static inline void rb_manifold_to_world(rb_manifold *m, rb_transform xf)
{
    m->normal = rb_rotate(xf.q, m->normal);
    for (int i = 0; i < m->point_count; ++i) {
        m->points[i].point = rb_transform_point(xf, m->points[i].point);
    }
}

/* ---- boxes (box_manifold.c) ---- */

/* Whether a polygon is a box the box path takes: four vertices in turn
 * round an axis-aligned rectangle of its own frame, starting on a
 * horizontal edge, with normals whose other component is exactly zero,
 * as rb_make_box and rb_make_offset_box at angle 0 make them (a box
 * turned in its body frame takes the general path). Past the count, the
 * comparisons are combined with & rather than &&: one branch, not eight. */
static inline bool rb_polygon_is_box(const rb_polygon *polygon)
{
    const rb_vec2 *v = polygon->vertices;
    const rb_vec2 *n = polygon->normals;
    return polygon->count == 4 && (v[0].y == v[1].y) & (v[1].x == v[2].x) & (v[2].y == v[3].y) & (v[3].x == v[0].x) &
                                      (n[0].x == 0.0) & (n[1].y == 0.0) & (n[2].x == 0.0) & (n[3].y == 0.0);
}

/* rb_collide_polygons when shape A is a box (rb_polygon_is_box; B any
 * convex polygon): the general path's manifold, bit for bit, for less
 * work. */
rb_manifold rb_collide_box_and_polygon(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                       double speculative_distance);

#endif
