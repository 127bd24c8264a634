/* SPDX-License-Identifier: MIT */
/* Narrow phase when shape A is a box: the general path's manifolds
 * (manifold.c), bit for bit, for a fraction of its work.
 *
 * A box here is a polygon whose four vertices lie on an axis-aligned
 * rectangle of its own frame (rb_polygon_is_box): every box rb_make_box
 * makes. Shape B may be any convex polygon. As on the general path,
 * everything is computed in A's frame, B's vertices and normals placed
 * there by the same arithmetic (rb_place_polygon).
 *
 * SAT asks, for each face of either shape (through vertex v, outward
 * normal n), for the least of dot(n, w - v) over the other shape's
 * vertices w, and the general path computes every such dot product:
 * 2 x 4 x 4 for two boxes. Rounding to nearest never reverses an order,
 * so each rounded term of n.x (w.x - v.x) + n.y (w.y - v.y) is monotone
 * in its coordinate of w, and the rounded sum in each term: over points
 * whose coordinates range over [lower, upper] the least value has each
 * term at the lesser of its values at the two bounds (the "support"
 * point, lowest along n; Ericson, "Real-Time Collision Detection", 2005,
 * ch. 5). So:
 *
 *  - on B's faces the other shape is A, whose four vertices are exactly
 *    the corners of its bounds: one evaluation per face instead of four;
 *  - on A's faces the normal has a zero component, whose term only adds
 *    a zero: the least value is the other term's, at the lower or the
 *    upper bound of B's vertices in that coordinate, however B is turned.
 *
 * The separations are the general path's to the last bit (up to the sign
 * of a zero, which no comparison tells apart), so the same faces win,
 * and the rest (reference face, incident edge, clipping) is the general
 * path's own code, rb_manifold_from_axes, on the same numbers.
 * tests/test_box_manifold.c compares the two paths on tens of thousands
 * of poses.
 */
#include "manifold_internal.h"

/* The separation from the face through `v` with outward normal `n` of
 * the rectangle with opposite corners `lower` and `upper`: dot(n, c - v)
 * at the corner c lowest along n, whose two terms are each the lesser of
 * their values at the two corners (in either order). */
static double support_separation(rb_vec2 n, rb_vec2 v, rb_vec2 lower, rb_vec2 upper)
{
    return rb_min(n.x * (lower.x - v.x), n.x * (upper.x - v.x)) + rb_min(n.y * (lower.y - v.y), n.y * (upper.y - v.y));
}

/* The box's best axis against points with the bounds (lower, upper). A
 * box's normals have a zero component, whose term of the dot product only
 * adds a zero: each separation is the other term's least value, at the
 * lower or the upper bound. */
static rb_axis best_box_face(const rb_polygon *box, rb_vec2 lower, rb_vec2 upper)
{
    const rb_vec2 *n = box->normals;
    const rb_vec2 *v = box->vertices;
    const double separations[4] = {
        rb_min(n[0].y * (lower.y - v[0].y), n[0].y * (upper.y - v[0].y)),
        rb_min(n[1].x * (lower.x - v[1].x), n[1].x * (upper.x - v[1].x)),
        rb_min(n[2].y * (lower.y - v[2].y), n[2].y * (upper.y - v[2].y)),
        rb_min(n[3].x * (lower.x - v[3].x), n[3].x * (upper.x - v[3].x)),
    };
    /* The first of the largest, as the general path's search picks it. */
    rb_axis best = {0, separations[0]};
    for (int i = 1; i < 4; ++i) {
        if (separations[i] > best.separation) {
            best = (rb_axis){i, separations[i]};
        }
    }
    return best;
}

/* An outline's best axis against the box: on each face, the box's corner
 * lowest along the face's normal. */
static rb_axis best_face_against_box(const rb_placed_polygon *outline, const rb_polygon *box)
{
    rb_axis best = {0, -INFINITY};
    for (int i = 0; i < outline->count; ++i) {
        double s = support_separation(outline->normals[i], outline->vertices[i], box->vertices[0], box->vertices[2]);
        if (s > best.separation) {
            best = (rb_axis){i, s};
        }
    }
    return best;
}

rb_manifold rb_collide_box_and_polygon(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                       double speculative_distance)
{
    /* B placed in A's frame as the general path places it, and the bounds
     * of its vertices there. */
    rb_placed_polygon pb;
    rb_place_polygon(b, rb_inv_mul_transforms(xfa, xfb), &pb);
    rb_vec2 lower_b = {INFINITY, INFINITY};
    rb_vec2 upper_b = {-INFINITY, -INFINITY};
    for (int i = 0; i < pb.count; ++i) {
        lower_b = rb_v2(rb_min(lower_b.x, pb.vertices[i].x), rb_min(lower_b.y, pb.vertices[i].y));
        upper_b = rb_v2(rb_max(upper_b.x, pb.vertices[i].x), rb_max(upper_b.y, pb.vertices[i].y));
    }

    rb_manifold m = {0};
    rb_axis axis_a = best_box_face(a, lower_b, upper_b);
    if (axis_a.separation > speculative_distance) {
        return m;
    }
    rb_axis axis_b = best_face_against_box(&pb, a);
    if (axis_b.separation > speculative_distance) {
        return m;
    }
    rb_outline outline_a = rb_polygon_outline(a);
    rb_outline outline_b = rb_placed_outline(&pb);
    rb_manifold_from_axes(&outline_a, &outline_b, axis_a, axis_b, speculative_distance, &m);
    rb_manifold_to_world(&m, xfa);
    return m;
}
