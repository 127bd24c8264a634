/* SPDX-License-Identifier: MIT */
/* The pieces of the narrow phase that the polygon and the segment
 * manifolds share: placing a polygon in another frame, SAT between two
 * placed convex outlines, and clipping an incident edge against a
 * reference face. */
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

rb_placed_polygon rb_place_polygon(const rb_polygon *polygon, rb_transform xf);

/* The manifold of two outlines given in the same frame (shape A's), in
 * that frame: the reference face on the axis of least penetration,
 * shape A's unless B's is deeper by RB_REFERENCE_FACE_TOLERANCE. */
rb_manifold rb_collide_placed_polygons(const rb_placed_polygon *pa, const rb_placed_polygon *pb,
                                       double speculative_distance);

/* An edge of an outline: its two vertices in the outline's order, and
 * their indices in it, which name the vertices in feature ids. */
typedef struct rb_edge {
    rb_vec2 v1, v2;
    int index1, index2;
} rb_edge;

/* Edge `i` of a polygon: from vertex i to the next. */
rb_edge rb_polygon_edge(const rb_placed_polygon *polygon, int i);

/* Clips the incident edge to the side planes of the reference face
 * (outward normal `reference_normal`) and keeps the points within the
 * speculative distance of the face. `flip` says the reference face is
 * shape B's; the normal is then reversed, so it still points from A to
 * B. Empty when the incident edge misses the face. */
rb_manifold rb_clip_incident_edge(rb_edge reference, rb_vec2 reference_normal, rb_edge incident, bool flip,
                                  double speculative_distance);

void rb_manifold_add_point(rb_manifold *m, rb_vec2 point, double separation, uint32_t id);

/* Moves a manifold computed in xf's local frame to the world. */
rb_manifold rb_manifold_to_world(rb_manifold local, rb_transform xf);

#endif
