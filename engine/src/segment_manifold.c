/* SPDX-License-Identifier: MIT */
/* Narrow phase for segments and chain segments against circles and
 * polygons. Everything is computed in the segment's frame and moved to
 * the world at the end; the segment is always shape A, so the normal
 * points from the segment to the other shape.
 *
 * Chains: a polygon sliding along a chain of segments reaches each
 * joint with its leading corner a hair above the next segment (it sinks
 * by about the linear slop). Plain SAT then finds the polygon's leading
 * side face the axis of least penetration and pushes the polygon back
 * along it: the polygon catches on a joint of a flat floor (the "ghost
 * collision" problem). The ghost vertices, the chain's neighbouring
 * points, say which normals the joint can really have: only the
 * segment's own normal at a flat or concave joint, the fan between the
 * two segments' normals at a convex joint. Other axes are refused and
 * the segment's face is used instead. Same idea as Box2D's chain shapes
 * (Catto, "Ghost Collisions", box2d.org blog, 2020); our own code. */
#include "manifold_internal.h"

/* The point on the segment midway between the circle's surface and the
 * segment point `closest`, with the normal from the segment to the centre. */
static rb_manifold circle_point(rb_vec2 closest, rb_vec2 normal, double distance, rb_vec2 center, double radius,
                                double speculative_distance)
{
    rb_manifold m = {0};
    double separation = distance - radius;
    if (separation > speculative_distance) {
        return m;
    }
    m.normal = normal;
    rb_vec2 surface_b = rb_mul_sub(center, radius, normal);
    rb_manifold_add_point(&m, rb_lerp(closest, surface_b, 0.5), separation, 0);
    return m;
}

/* The circle's centre in the segment's frame. */
static rb_vec2 local_center(rb_transform xfa, const rb_circle *b, rb_transform xfb)
{
    return rb_inv_transform_point(xfa, rb_transform_point(xfb, b->center));
}

/* A vertex point: from the segment's end `vertex` to the centre. A
 * centre on the vertex takes `fallback` as its normal. */
static rb_manifold vertex_point(rb_vec2 vertex, rb_vec2 c, rb_vec2 fallback, double radius, double speculative_distance)
{
    double distance = rb_distance(vertex, c);
    rb_vec2 normal = distance > 0.0 ? rb_scale(1.0 / distance, rb_sub(c, vertex)) : fallback;
    return circle_point(vertex, normal, distance, c, radius, speculative_distance);
}

rb_manifold rb_collide_segment_and_circle(const rb_segment *a, rb_transform xfa, const rb_circle *b, rb_transform xfb,
                                          double speculative_distance)
{
    rb_vec2 c = local_center(xfa, b, xfb);
    rb_vec2 p1 = a->point1;
    rb_vec2 p2 = a->point2;
    rb_vec2 e = rb_sub(p2, p1);
    rb_vec2 left = rb_normalize(rb_left_perp(e));
    double u = rb_dot(rb_sub(c, p1), e) / rb_dot(e, e);
    rb_manifold m;
    if (u <= 0.0) {
        m = vertex_point(p1, c, left, b->radius, speculative_distance);
    } else if (u >= 1.0) {
        m = vertex_point(p2, c, left, b->radius, speculative_distance);
    } else {
        /* Face region: the normal is the face's, on the centre's side. */
        double offset = rb_dot(left, rb_sub(c, p1));
        rb_vec2 normal = offset >= 0.0 ? left : rb_neg(left);
        m = circle_point(rb_mul_sub(c, fabs(offset), normal), normal, fabs(offset), c, b->radius, speculative_distance);
    }
    rb_manifold_to_world(&m, xfa);
    return m;
}

/* The segment as a two-vertex outline in its own frame. */
static rb_placed_polygon place_segment(const rb_segment *segment)
{
    rb_vec2 tangent = rb_normalize(rb_sub(segment->point2, segment->point1));
    rb_placed_polygon placed = {.count = 2};
    placed.vertices[0] = segment->point1;
    placed.vertices[1] = segment->point2;
    placed.normals[0] = rb_right_perp(tangent);
    placed.normals[1] = rb_left_perp(tangent);
    return placed;
}

rb_manifold rb_collide_segment_and_polygon(const rb_segment *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                           double speculative_distance)
{
    rb_placed_polygon pa = place_segment(a);
    rb_placed_polygon pb;
    rb_place_polygon(b, rb_inv_mul_transforms(xfa, xfb), &pb);
    rb_manifold m = {0};
    rb_collide_placed_polygons(&pa, &pb, speculative_distance, &m);
    rb_manifold_to_world(&m, xfa);
    return m;
}

/* ---- chain segments -------------------------------------------------------- */

/* The chain segment's frame of reference: its ends, unit direction and
 * front (left) normal. */
typedef struct chain_frame {
    rb_vec2 p1, p2, tangent, normal;
} chain_frame;

static chain_frame make_chain_frame(const rb_chain_segment *a)
{
    chain_frame f;
    f.p1 = a->segment.point1;
    f.p2 = a->segment.point2;
    f.tangent = rb_normalize(rb_sub(f.p2, f.p1));
    f.normal = rb_left_perp(f.tangent);
    return f;
}

rb_manifold rb_collide_chain_segment_and_circle(const rb_chain_segment *a, rb_transform xfa, const rb_circle *b,
                                                rb_transform xfb, double speculative_distance)
{
    chain_frame f = make_chain_frame(a);
    rb_vec2 c = local_center(xfa, b, xfb);
    rb_manifold m = {0};
    double offset = rb_dot(f.normal, rb_sub(c, f.p1));
    if (offset < 0.0) {
        return m; /* behind a one-sided segment */
    }
    double along = rb_dot(rb_sub(c, f.p1), f.tangent);
    double length = rb_distance(f.p1, f.p2);
    /* The face owns its ends (a centre right above a joint gets the face
     * point from both segments, never from neither). */
    if (along < 0.0) {
        /* Before point1: the previous segment's face owns the centres that
         * project onto it; what remains is the wedge of a convex joint (or
         * everything, at a free end). */
        if (a->has_ghost1 && rb_dot(rb_sub(c, f.p1), rb_sub(f.p1, a->ghost1)) <= 0.0) {
            return m;
        }
        m = vertex_point(f.p1, c, f.normal, b->radius, speculative_distance);
    } else if (along > length) {
        /* Beyond point2: the next segment owns the joint. */
        if (a->has_ghost2) {
            return m;
        }
        m = vertex_point(f.p2, c, f.normal, b->radius, speculative_distance);
    } else {
        m = circle_point(rb_mul_sub(c, offset, f.normal), f.normal, offset, c, b->radius, speculative_distance);
    }
    rb_manifold_to_world(&m, xfa);
    return m;
}

/* Whether `n` (unit, from the segment to the other shape) is a normal
 * the chain can have at one of the segment's ends: in the fan between
 * the two segments' normals at a convex joint, in the quarter turn from
 * the normal to the outward tangent at a free end. Flat and concave
 * joints allow only the segment's own normal, which is not asked here. */
static bool admits_normal(const rb_chain_segment *a, const chain_frame *f, rb_vec2 n)
{
    if (!a->has_ghost1) {
        if (rb_dot(n, f->tangent) <= 0.0 && rb_dot(n, f->normal) >= 0.0) {
            return true;
        }
    } else {
        rb_vec2 previous = rb_normalize(rb_sub(f->p1, a->ghost1));
        /* Convex (turning right, away from the front): the normals turn
         * clockwise from the previous segment's to this one's. */
        if (rb_cross(previous, f->tangent) < 0.0 && rb_cross(rb_left_perp(previous), n) <= 0.0 &&
            rb_cross(n, f->normal) <= 0.0) {
            return true;
        }
    }
    if (!a->has_ghost2) {
        return rb_dot(n, f->tangent) >= 0.0 && rb_dot(n, f->normal) >= 0.0;
    }
    rb_vec2 next = rb_normalize(rb_sub(a->ghost2, f->p2));
    return rb_cross(f->tangent, next) < 0.0 && rb_cross(f->normal, n) <= 0.0 && rb_cross(n, rb_left_perp(next)) <= 0.0;
}

rb_manifold rb_collide_chain_segment_and_polygon(const rb_chain_segment *a, rb_transform xfa, const rb_polygon *b,
                                                 rb_transform xfb, double speculative_distance)
{
    chain_frame f = make_chain_frame(a);
    rb_transform relative = rb_inv_mul_transforms(xfa, xfb);
    rb_placed_polygon pb;
    rb_place_polygon(b, relative, &pb);
    rb_manifold m = {0};
    if (rb_dot(f.normal, rb_sub(rb_transform_point(relative, b->centroid), f.p1)) < 0.0) {
        return m; /* behind a one-sided segment */
    }

    /* The segment's front face: how far the polygon reaches below it. */
    double segment_separation = INFINITY;
    for (int j = 0; j < pb.count; ++j) {
        segment_separation = fmin(segment_separation, rb_dot(f.normal, rb_sub(pb.vertices[j], f.p1)));
    }
    if (segment_separation > speculative_distance) {
        return m;
    }
    /* The polygon's faces: how far the segment's ends reach below each. */
    int polygon_edge = 0;
    double polygon_separation = -INFINITY;
    for (int i = 0; i < pb.count; ++i) {
        double s = fmin(rb_dot(pb.normals[i], rb_sub(f.p1, pb.vertices[i])),
                        rb_dot(pb.normals[i], rb_sub(f.p2, pb.vertices[i])));
        if (s > polygon_separation) {
            polygon_separation = s;
            polygon_edge = i;
        }
    }
    if (polygon_separation > speculative_distance) {
        return m;
    }

    /* The front face is edge 1 of the two-vertex outline: point2 -> point1. */
    const rb_edge front = {f.p2, f.p1, 1, 0};
    const rb_outline polygon = rb_placed_outline(&pb);
    if (polygon_separation > segment_separation + RB_REFERENCE_FACE_TOLERANCE &&
        admits_normal(a, &f, rb_neg(pb.normals[polygon_edge]))) {
        rb_edge face = rb_polygon_edge(&polygon, polygon_edge);
        rb_clip_incident_edge(&face, pb.normals[polygon_edge], &front, true, speculative_distance, &m);
    } else {
        /* The incident edge: the polygon's edge most opposed to the front. */
        int incident_edge = 0;
        double most_opposed = INFINITY;
        for (int i = 0; i < pb.count; ++i) {
            double d = rb_dot(f.normal, pb.normals[i]);
            if (d < most_opposed) {
                most_opposed = d;
                incident_edge = i;
            }
        }
        rb_edge incident = rb_polygon_edge(&polygon, incident_edge);
        rb_clip_incident_edge(&front, f.normal, &incident, false, speculative_distance, &m);
    }
    rb_manifold_to_world(&m, xfa);
    return m;
}
