/* SPDX-License-Identifier: MIT */
/* Narrow phase for boxes: the general path's manifolds (manifold.c), bit
 * for bit, for a fraction of its work.
 *
 * A box here is a polygon whose four vertices lie on an axis-aligned
 * rectangle of its own frame (rb_polygon_is_box): every box that
 * rb_make_box makes. Everything is computed in box A's frame, as on the
 * general path, with box B's vertices and normals placed there by the
 * same arithmetic.
 *
 * Why one corner per axis gives the same number. On the general path the
 * separation on a face (through vertex v, outward normal n) is the least
 * of dot(n, w - v) over the other outline's vertices w. Rounding to
 * nearest never reverses an order, so each rounded step of
 * n.x (w.x - v.x) + n.y (w.y - v.y) is monotone in w.x (rising when
 * n.x > 0, falling when n.x < 0) and likewise in w.y: over the corners of
 * an axis-aligned rectangle the least value is the one at the corner
 * lowest along n, chosen by the signs of n's components (the "support"
 * corner; Ericson, "Real-Time Collision Detection", 2005, ch. 5). So:
 *
 *  - on B's faces, A's four vertices are such a rectangle: one dot product
 *    per face where the general path takes four;
 *  - on A's faces, whose normals have one zero component, that component
 *    contributes a zero whatever B's vertices are, and the other
 *    coordinate's least value among B's four vertices is read from their
 *    bounds: again one dot product per face.
 *
 * The separations are the general path's to the last bit (up to the sign
 * of a zero, which no comparison sees), so the same faces win, and the
 * rest (reference face, incident edge, clipping) is the general path's
 * own code, rb_manifold_from_axes, on the same numbers. tests/
 * test_manifold.c compares the two paths on many thousands of poses.
 */
#include "manifold_internal.h"

bool rb_polygon_is_box(const rb_polygon *polygon)
{
    const rb_vec2 *v = polygon->vertices;
    const rb_vec2 *n = polygon->normals;
    /* One branch: the comparisons are combined with & rather than &&. */
    return (polygon->count == 4) & (v[0].y == v[1].y) & (v[1].x == v[2].x) & (v[2].y == v[3].y) & (v[3].x == v[0].x) &
           (v[0].x < v[1].x) & (v[1].y < v[2].y) & (n[0].x == 0.0) & (n[1].y == 0.0) & (n[2].x == 0.0) &
           (n[3].y == 0.0);
}

/* The separation from the face through `v` with outward normal `n` of
 * the rectangle with corners `lower` and `upper` (or of any points with
 * those bounds, when n has a zero component): dot(n, c - v) at the corner
 * c lowest along n, whose two terms are each the lesser of their values
 * at the two corners. */
static double support_separation(rb_vec2 n, rb_vec2 v, rb_vec2 lower, rb_vec2 upper)
{
    return rb_min(n.x * (lower.x - v.x), n.x * (upper.x - v.x)) + rb_min(n.y * (lower.y - v.y), n.y * (upper.y - v.y));
}

/* An outline's best axis against the rectangle (lower, upper): the face
 * on which the rectangle reaches least far below, the first of equals,
 * as the general path's search picks it. */
static rb_axis best_axis_against_rectangle(rb_outline outline, rb_vec2 lower, rb_vec2 upper)
{
    rb_axis best = {0, -INFINITY};
    for (int i = 0; i < outline.count; ++i) {
        double s = support_separation(outline.normals[i], outline.vertices[i], lower, upper);
        if (s > best.separation) {
            best = (rb_axis){i, s};
        }
    }
    return best;
}

rb_manifold rb_collide_box_and_polygon(const rb_polygon *a, rb_transform xfa, const rb_polygon *b, rb_transform xfb,
                                       double speculative_distance)
{
    /* B placed in A's frame as rb_place_polygon places it, and the bounds
     * of its vertices there. */
    rb_placed_polygon pb = rb_place_polygon(b, rb_inv_mul_transforms(xfa, xfb));
    rb_vec2 lower_b = pb.vertices[0];
    rb_vec2 upper_b = pb.vertices[0];
    for (int i = 1; i < pb.count; ++i) {
        lower_b = rb_v2(rb_min(lower_b.x, pb.vertices[i].x), rb_min(lower_b.y, pb.vertices[i].y));
        upper_b = rb_v2(rb_max(upper_b.x, pb.vertices[i].x), rb_max(upper_b.y, pb.vertices[i].y));
    }

    rb_manifold m = {0};
    rb_outline box = rb_polygon_outline(a);
    rb_axis axis_a = best_axis_against_rectangle(box, lower_b, upper_b);
    if (axis_a.separation > speculative_distance) {
        return m;
    }
    /* A's lower left and upper right corners are its vertices 0 and 2. */
    rb_axis axis_b = best_axis_against_rectangle(rb_placed_outline(&pb), a->vertices[0], a->vertices[2]);
    if (axis_b.separation > speculative_distance) {
        return m;
    }
    rb_manifold_from_axes(box, rb_placed_outline(&pb), axis_a, axis_b, speculative_distance, &m);
    rb_manifold_to_world(&m, xfa);
    return m;
}

rb_manifold rb_collide_box_and_circle(const rb_polygon *a, rb_transform xfa, const rb_circle *b, rb_transform xfb,
                                      double speculative_distance)
{
    return rb_collide_convex_polygon_and_circle(a, xfa, b, xfb, speculative_distance);
}
