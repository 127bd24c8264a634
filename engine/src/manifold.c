/* SPDX-License-Identifier: MIT */
/* Narrow phase: contact manifolds by the separating axis theorem.
 *
 * Polygons: the axis of least penetration among both polygons' edge
 * normals names a reference face; the incident face is the other
 * polygon's edge most opposed to it; the incident edge is clipped to the
 * reference face's side planes and every clipped point within the
 * speculative distance becomes a manifold point (Gottschalk 1996 for
 * SAT; face clipping as in Catto, "Contact Manifolds", GDC 2007).
 * Everything is computed in shape A's frame and moved to the world at
 * the end. This search over every edge and vertex is the general path
 * and the reference; when shape A is a box, box_manifold.c finds the
 * same axes with less work and hands them to rb_manifold_from_axes.
 */
#include "manifold_internal.h"

/* Below this centre distance two circles have no defined normal (m). */
#define COINCIDENT_DISTANCE 1e-12

void rb_manifold_add_point(rb_manifold *m, rb_vec2 point, double separation, uint32_t id)
{
    rb_manifold_point *p = &m->points[m->point_count++];
    p->point = point;
    p->separation = separation;
    p->id = id;
}

rb_manifold rb_collide_circles(const rb_circle *a, rb_transform xfa, const rb_circle *b, rb_transform xfb,
                               double speculative_distance)
{
    rb_vec2 ca = rb_transform_point(xfa, a->center);
    rb_vec2 cb = rb_transform_point(xfb, b->center);
    rb_vec2 d = rb_sub(cb, ca);
    double distance = rb_length(d);
    double separation = distance - a->radius - b->radius;
    rb_manifold m = (rb_manifold){0};
    if (separation > speculative_distance) {
        return m;
    }
    /* Coincident centres: any direction separates them equally; take +y. */
    m.normal = distance > COINCIDENT_DISTANCE ? rb_scale(1.0 / distance, d) : rb_v2(0.0, 1.0);
    rb_vec2 surface_a = rb_mul_add(ca, a->radius, m.normal);
    rb_vec2 surface_b = rb_mul_sub(cb, b->radius, m.normal);
    rb_manifold_add_point(&m, rb_lerp(surface_a, surface_b, 0.5), separation, 0);
    return m;
}

rb_manifold rb_collide_polygon_and_circle(const rb_polygon *a, rb_transform xfa, const rb_circle *b, rb_transform xfb,
                                          double speculative_distance)
{
    rb_vec2 c = rb_inv_transform_point(xfa, rb_transform_point(xfb, b->center));
    double radius = b->radius;

    /* The face whose plane the centre is farthest outside of. */
    int face = 0;
    double face_separation = -INFINITY;
    for (int i = 0; i < a->count; ++i) {
        double s = rb_dot(a->normals[i], rb_sub(c, a->vertices[i]));
        if (s > face_separation) {
            face_separation = s;
            face = i;
        }
    }
    rb_manifold m = (rb_manifold){0};
    if (face_separation - radius > speculative_distance) {
        return m;
    }

    rb_vec2 v1 = a->vertices[face];
    rb_vec2 v2 = a->vertices[face + 1 < a->count ? face + 1 : 0];
    rb_vec2 normal = a->normals[face];
    rb_vec2 surface_a;
    double distance;
    /* Outside the face's plane, the centre is in a vertex region when it
     * projects beyond an end of the face; otherwise (and always when the
     * centre is inside the polygon) the face normal separates. */
    if (face_separation > 0.0 && rb_dot(rb_sub(c, v1), rb_sub(v2, v1)) <= 0.0) {
        distance = rb_distance(v1, c);
        normal = rb_normalize(rb_sub(c, v1));
        surface_a = v1;
    } else if (face_separation > 0.0 && rb_dot(rb_sub(c, v2), rb_sub(v1, v2)) <= 0.0) {
        distance = rb_distance(v2, c);
        normal = rb_normalize(rb_sub(c, v2));
        surface_a = v2;
    } else {
        distance = face_separation;
        surface_a = rb_mul_sub(c, face_separation, normal);
    }
    double separation = distance - radius;
    if (separation > speculative_distance) {
        return m;
    }
    m.normal = normal;
    rb_vec2 surface_b = rb_mul_sub(c, radius, normal);
    rb_manifold_add_point(&m, rb_lerp(surface_a, surface_b, 0.5), separation, 0);
    rb_manifold_to_world(&m, xfa);
    return m;
}

/* The edge of `p` along whose normal `q` reaches least far below it,
 * and the separation of the two outlines on that axis: the largest over
 * p's edges of the smallest over q's vertices. */
static rb_axis max_edge_separation(const rb_outline *p, const rb_outline *q)
{
    rb_axis best = {0, -INFINITY};
    for (int i = 0; i < p->count; ++i) {
        double deepest = INFINITY;
        for (int j = 0; j < q->count; ++j) {
            double s = rb_dot(p->normals[i], rb_sub(q->vertices[j], p->vertices[i]));
            deepest = s < deepest ? s : deepest;
        }
        if (deepest > best.separation) {
            best = (rb_axis){i, deepest};
        }
    }
    return best;
}

/* Keeps the part of the segment `ends` where dot(normal, p) <= offset,
 * in the segment's order. False when the segment lies wholly outside. */
static bool clip_segment(rb_vec2 ends[2], rb_vec2 normal, double offset)
{
    double d0 = rb_dot(normal, ends[0]) - offset;
    double d1 = rb_dot(normal, ends[1]) - offset;
    if (d0 > 0.0 && d1 > 0.0) {
        return false;
    }
    if (d0 > 0.0) {
        ends[0] = rb_lerp(ends[0], ends[1], d0 / (d0 - d1));
    } else if (d1 > 0.0) {
        ends[1] = rb_lerp(ends[0], ends[1], d0 / (d0 - d1));
    }
    return true;
}

rb_edge rb_polygon_edge(const rb_outline *outline, int i)
{
    int next = i + 1 < outline->count ? i + 1 : 0;
    return (rb_edge){outline->vertices[i], outline->vertices[next], i, next};
}

void rb_clip_incident_edge(const rb_edge *reference, rb_vec2 reference_normal, const rb_edge *incident, bool flip,
                           double speculative_distance, rb_manifold *m)
{
    rb_vec2 tangent = rb_normalize(rb_sub(reference->v2, reference->v1));
    rb_vec2 clipped[2] = {incident->v1, incident->v2};
    /* The side planes: beyond the first vertex against the tangent,
     * beyond the second along it. */
    const rb_vec2 side_normals[2] = {rb_neg(tangent), tangent};
    const double side_offsets[2] = {-rb_dot(tangent, reference->v1), rb_dot(tangent, reference->v2)};
    for (int k = 0; k < 2; ++k) {
        if (!clip_segment(clipped, side_normals[k], side_offsets[k])) {
            return;
        }
    }

    /* The manifold normal points from A to B. */
    m->normal = flip ? rb_neg(reference_normal) : reference_normal;
    m->reference_on_b = flip;
    /* The incident edge runs against the reference face: its first end
     * lies towards the face's second vertex, its second end towards the
     * first. */
    const int incident_vertex[2] = {incident->index1, incident->index2};
    const int reference_vertex[2] = {reference->index2, reference->index1};
    for (int i = 0; i < 2; ++i) {
        double separation = rb_dot(reference_normal, rb_sub(clipped[i], reference->v1));
        if (separation <= speculative_distance) {
            /* The clipped point lies on the incident surface; the
             * reference surface is `separation` behind it along the
             * reference normal: report the midpoint. */
            rb_vec2 midpoint = rb_mul_sub(clipped[i], 0.5 * separation, reference_normal);
            uint32_t id = flip ? rb_feature_id(incident_vertex[i], reference_vertex[i])
                               : rb_feature_id(reference_vertex[i], incident_vertex[i]);
            rb_manifold_add_point(m, midpoint, separation, id);
        }
    }
}

void rb_manifold_from_axes(const rb_outline *a, const rb_outline *b, rb_axis axis_a, rb_axis axis_b,
                           double speculative_distance, rb_manifold *m)
{
    bool flip = axis_b.separation > axis_a.separation + RB_REFERENCE_FACE_TOLERANCE;
    const rb_outline *reference = flip ? b : a;
    const rb_outline *incident = flip ? a : b;
    int reference_edge = flip ? axis_b.edge : axis_a.edge;
    rb_vec2 reference_normal = reference->normals[reference_edge];

    /* The incident edge: the one whose normal opposes the reference normal most. */
    int incident_edge = 0;
    double most_opposed = INFINITY;
    for (int i = 0; i < incident->count; ++i) {
        double d = rb_dot(reference_normal, incident->normals[i]);
        if (d < most_opposed) {
            most_opposed = d;
            incident_edge = i;
        }
    }
    rb_edge reference_face = rb_polygon_edge(reference, reference_edge);
    rb_edge incident_face = rb_polygon_edge(incident, incident_edge);
    rb_clip_incident_edge(&reference_face, reference_normal, &incident_face, flip, speculative_distance, m);
}

/* SAT over every edge of both outlines, stopping at the first outline
 * whose best axis separates them. */
static void collide_outlines(const rb_outline *a, const rb_outline *b, double speculative_distance, rb_manifold *m)
{
    rb_axis axis_a = max_edge_separation(a, b);
    if (axis_a.separation > speculative_distance) {
        return;
    }
    rb_axis axis_b = max_edge_separation(b, a);
    if (axis_b.separation > speculative_distance) {
        return;
    }
    rb_manifold_from_axes(a, b, axis_a, axis_b, speculative_distance, m);
}

void rb_collide_placed_polygons(const rb_placed_polygon *pa, const rb_placed_polygon *pb, double speculative_distance,
                                rb_manifold *m)
{
    rb_outline a = rb_placed_outline(pa);
    rb_outline b = rb_placed_outline(pb);
    collide_outlines(&a, &b, speculative_distance, m);
}

rb_manifold rb_collide_polygons(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                double speculative_distance)
{
    if (rb_polygon_is_box(a)) {
        return rb_collide_box_and_polygon(a, xfa, b, xfb, speculative_distance);
    }
    return rb_collide_convex_polygons(a, xfa, b, xfb, speculative_distance);
}

/* Shape A is read in its own frame as it is; B is placed in it. */
rb_manifold rb_collide_convex_polygons(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                       double speculative_distance)
{
    rb_placed_polygon pb;
    rb_place_polygon(b, rb_inv_mul_transforms(xfa, xfb), &pb);
    rb_manifold m = {0};
    rb_outline outline_a = rb_polygon_outline(a);
    rb_outline outline_b = rb_placed_outline(&pb);
    collide_outlines(&outline_a, &outline_b, speculative_distance, &m);
    rb_manifold_to_world(&m, xfa);
    return m;
}
