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
 * the end.
 */
#include "manifold_internal.h"

/* Below this centre distance two circles have no defined normal (m). */
#define COINCIDENT_DISTANCE 1e-12

rb_manifold rb_manifold_to_world(rb_manifold local, rb_transform xf)
{
    rb_manifold m = local;
    m.normal = rb_rotate(xf.q, local.normal);
    for (int i = 0; i < m.point_count; ++i) {
        m.points[i].point = rb_transform_point(xf, local.points[i].point);
    }
    return m;
}

void rb_manifold_add_point(rb_manifold *m, rb_vec2 point, double separation, uint32_t id)
{
    rb_manifold_point *p = &m->points[m->point_count++];
    *p = (rb_manifold_point){0};
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
    return rb_manifold_to_world(m, xfa);
}

/* The polygon in its own frame: a copy, which no rotation can round. */
static rb_placed_polygon polygon_in_own_frame(const rb_polygon *polygon)
{
    rb_placed_polygon placed;
    placed.count = polygon->count;
    for (int i = 0; i < polygon->count; ++i) {
        placed.vertices[i] = polygon->vertices[i];
        placed.normals[i] = polygon->normals[i];
    }
    return placed;
}

rb_placed_polygon rb_place_polygon(const rb_polygon *polygon, rb_transform xf)
{
    rb_placed_polygon placed;
    placed.count = polygon->count;
    for (int i = 0; i < polygon->count; ++i) {
        placed.vertices[i] = rb_transform_point(xf, polygon->vertices[i]);
        placed.normals[i] = rb_rotate(xf.q, polygon->normals[i]);
    }
    return placed;
}

/* The edge of `p` along whose normal `q` reaches least far below it:
 * the separation of the two polygons on that axis. */
static double max_edge_separation(const rb_placed_polygon *p, const rb_placed_polygon *q, int *edge)
{
    double best = -INFINITY;
    *edge = 0;
    for (int i = 0; i < p->count; ++i) {
        double deepest = INFINITY;
        for (int j = 0; j < q->count; ++j) {
            double s = rb_dot(p->normals[i], rb_sub(q->vertices[j], p->vertices[i]));
            deepest = s < deepest ? s : deepest;
        }
        if (deepest > best) {
            best = deepest;
            *edge = i;
        }
    }
    return best;
}

/* Keeps the part of segment `in` where dot(normal, p) <= offset, in the
 * segment's order. Returns the number of points kept (2 unless the
 * segment lies wholly outside). */
static int clip_segment(const rb_vec2 in[2], rb_vec2 out[2], rb_vec2 normal, double offset)
{
    double d0 = rb_dot(normal, in[0]) - offset;
    double d1 = rb_dot(normal, in[1]) - offset;
    if (d0 > 0.0 && d1 > 0.0) {
        return 0;
    }
    out[0] = in[0];
    out[1] = in[1];
    if (d0 > 0.0) {
        out[0] = rb_lerp(in[0], in[1], d0 / (d0 - d1));
    } else if (d1 > 0.0) {
        out[1] = rb_lerp(in[0], in[1], d0 / (d0 - d1));
    }
    return 2;
}

rb_edge rb_polygon_edge(const rb_placed_polygon *polygon, int i)
{
    int next = i + 1 < polygon->count ? i + 1 : 0;
    return (rb_edge){polygon->vertices[i], polygon->vertices[next], i, next};
}

rb_manifold rb_clip_incident_edge(rb_edge reference, rb_vec2 reference_normal, rb_edge incident, bool flip,
                                  double speculative_distance)
{
    rb_manifold m = {0};
    rb_vec2 tangent = rb_normalize(rb_sub(reference.v2, reference.v1));
    rb_vec2 ends[2] = {incident.v1, incident.v2};
    rb_vec2 clipped_once[2];
    rb_vec2 clipped[2];
    if (clip_segment(ends, clipped_once, rb_neg(tangent), -rb_dot(tangent, reference.v1)) < 2 ||
        clip_segment(clipped_once, clipped, tangent, rb_dot(tangent, reference.v2)) < 2) {
        return m;
    }

    /* The manifold normal points from A to B. */
    m.normal = flip ? rb_neg(reference_normal) : reference_normal;
    m.reference_on_b = flip;
    /* The incident edge runs against the reference face: its first end
     * lies towards the face's second vertex, its second end towards the
     * first. */
    const int incident_vertex[2] = {incident.index1, incident.index2};
    const int reference_vertex[2] = {reference.index2, reference.index1};
    for (int i = 0; i < 2; ++i) {
        double separation = rb_dot(reference_normal, rb_sub(clipped[i], reference.v1));
        if (separation <= speculative_distance) {
            /* The clipped point lies on the incident surface; the
             * reference surface is `separation` behind it along the
             * reference normal: report the midpoint. */
            rb_vec2 midpoint = rb_mul_sub(clipped[i], 0.5 * separation, reference_normal);
            uint32_t id = flip ? rb_feature_id(incident_vertex[i], reference_vertex[i])
                               : rb_feature_id(reference_vertex[i], incident_vertex[i]);
            rb_manifold_add_point(&m, midpoint, separation, id);
        }
    }
    return m;
}

rb_manifold rb_collide_placed_polygons(const rb_placed_polygon *pa, const rb_placed_polygon *pb,
                                       double speculative_distance)
{
    rb_manifold m = {0};
    int edge_a;
    double separation_a = max_edge_separation(pa, pb, &edge_a);
    if (separation_a > speculative_distance) {
        return m;
    }
    int edge_b;
    double separation_b = max_edge_separation(pb, pa, &edge_b);
    if (separation_b > speculative_distance) {
        return m;
    }

    bool flip = separation_b > separation_a + RB_REFERENCE_FACE_TOLERANCE;
    const rb_placed_polygon *reference = flip ? pb : pa;
    const rb_placed_polygon *incident = flip ? pa : pb;
    int reference_edge = flip ? edge_b : edge_a;
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
    return rb_clip_incident_edge(rb_polygon_edge(reference, reference_edge), reference_normal,
                                 rb_polygon_edge(incident, incident_edge), flip, speculative_distance);
}

rb_manifold rb_collide_polygons(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                double speculative_distance)
{
    rb_placed_polygon pa = polygon_in_own_frame(a);
    rb_placed_polygon pb = rb_place_polygon(b, rb_inv_mul_transforms(xfa, xfb));
    return rb_manifold_to_world(rb_collide_placed_polygons(&pa, &pb, speculative_distance), xfa);
}
