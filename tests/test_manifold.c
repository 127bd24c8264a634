/* SPDX-License-Identifier: MIT */
/* Narrow phase: contact manifolds of rb/collision.h against hand-derived
 * geometry, and the stability of feature ids from frame to frame.
 *
 * Conventions checked (rb/collision.h): the normal is a unit vector from
 * shape A to shape B; each point lies midway between the two surfaces,
 * that is halfway along the normal between the incident feature and the
 * reference surface; the separation is the signed gap along the normal.
 *
 * Many configurations are built in a local frame where the contact face
 * is horizontal, then placed in the world by a rigid "frame" transform G:
 * contact geometry is invariant under rigid motions, so the expected
 * world normal is G's rotation of the local one, the expected points are
 * G applied to the local ones, and separations do not change.
 *
 * Tolerance: the values are of order 1..3 and the engine reaches them in
 * a few dozen floating-point operations (transforms, dot products, one
 * clip), so the rounding error stays below 1e-14; TOLERANCE = 1e-12 is far
 * below any geometric mistake tested here (the overlaps are 0.01 or more).
 */
#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"
#include "test_support.h"

#define TOLERANCE 1e-12

static rb_transform pose(double x, double y, double angle) { return (rb_transform){{x, y}, rb_rot_from_angle(angle)}; }

static rb_polygon make_box(double hx, double hy)
{
    rb_polygon box;
    cr_assert_eq(rb_make_box(hx, hy, &box), RB_OK, "rb_make_box(%g, %g) failed: %s", hx, hy, rb_last_error());
    return box;
}

/* Index of the manifold point closest to `target`, or -1 when there is none. */
static int nearest_point(const rb_manifold *manifold, rb_vec2 target)
{
    int best = -1;
    for (int i = 0; i < manifold->point_count; ++i) {
        if (best < 0 ||
            rb_distance(manifold->points[i].point, target) < rb_distance(manifold->points[best].point, target)) {
            best = i;
        }
    }
    return best;
}

/* The manifold has a point at `expected_point` with `expected_separation`.
 * When a test expects two points they are far apart (>= 0.7 m), so each
 * expectation can only be met by its own point. */
static void expect_point(const rb_manifold *manifold, rb_vec2 expected_point, double expected_separation,
                         const char *what)
{
    int i = nearest_point(manifold, expected_point);
    cr_assert(i >= 0, "%s: the manifold has no points", what);
    expect_vec_near(manifold->points[i].point, expected_point, TOLERANCE, what);
    expect_near(manifold->points[i].separation, expected_separation, TOLERANCE, what);
}

static void expect_point_count(const rb_manifold *manifold, int expected)
{
    cr_expect_eq(manifold->point_count, expected, "manifold has %d points, expected %d", manifold->point_count,
                 expected);
}

/* Swapping A and B negates the normal and keeps every point and
 * separation (the midway point is symmetric in the two surfaces). */
static void expect_swap_symmetric(const rb_manifold *ab, const rb_manifold *ba)
{
    cr_assert(ab->point_count > 0, "the unswapped manifold should have points");
    cr_expect_eq(ba->point_count, ab->point_count, "swapped manifold has %d points, unswapped %d", ba->point_count,
                 ab->point_count);
    expect_vec_near(ba->normal, rb_neg(ab->normal), TOLERANCE, "swapped normal");
    for (int i = 0; i < ab->point_count; ++i) {
        expect_point(ba, ab->points[i].point, ab->points[i].separation, "swapped point");
    }
}

/* ---- Box against box ---- */

/* Box A, half-extents (2, 0.5), at the frame's origin: its top face is
 * y = 0.5 for x in [-2, 2]. Box B, half-extents (0.5, 0.5), centred at
 * (1.8, 1 - d): its bottom face is y = 0.5 - d for x in [1.3, 2.3].
 * The least-overlap axis is y (overlap d; along x the overlap is
 * 2 - 1.3 = 0.7), so the normal is +y. Clipping either bottom/top face
 * against the other's side planes keeps x in [1.3, 2.0], and each point is
 * halfway between y = 0.5 and y = 0.5 - d. */
static void check_face_to_face(rb_transform frame, double d, double speculative_distance)
{
    rb_polygon a = make_box(2.0, 0.5);
    rb_polygon b = make_box(0.5, 0.5);
    rb_transform xfa = frame;
    rb_transform xfb = rb_mul_transforms(frame, pose(1.8, 1.0 - d, 0.0));
    rb_manifold m = rb_collide_polygons(&a, xfa, &b, xfb, speculative_distance);

    expect_point_count(&m, 2);
    expect_vec_near(m.normal, rb_rotate(frame.q, rb_v2(0.0, 1.0)), TOLERANCE, "face-to-face normal");
    expect_point(&m, rb_transform_point(frame, rb_v2(1.3, 0.5 - d / 2.0)), -d, "face-to-face point at x = 1.3");
    expect_point(&m, rb_transform_point(frame, rb_v2(2.0, 0.5 - d / 2.0)), -d, "face-to-face point at x = 2.0");
}

Test(manifold, box_face_to_face) { check_face_to_face(rb_transform_identity(), 0.01, 0.0); }

Test(manifold, box_face_to_face_in_rotated_frame) { check_face_to_face(pose(-3.0, 2.0, 2.2), 0.01, 0.0); }

Test(manifold, box_exactly_touching)
{
    /* d = 0: the faces meet, both points have separation 0 (reported,
     * since 0 <= the speculative distance 0). */
    check_face_to_face(rb_transform_identity(), 0.0, 0.0);
}

Test(manifold, box_deep_overlap)
{
    /* Box B (half 0.5) centred at (0.3, 0.3), inside the top of box A
     * (half (2, 0.5)): B's bottom y = -0.2 is 0.7 below A's top y = 0.5.
     * Candidate axes: A's top face / B's bottom face: -0.7; A's bottom
     * face: B's top (0.8) is 1.3 above y = -0.5, so -1.3; the x faces:
     * -2.2 or less. So the normal is +y, separation -0.7, the points at
     * B's x extents -0.2 and 0.8, halfway between y = 0.5 and y = -0.2,
     * at y = 0.15. */
    rb_polygon a = make_box(2.0, 0.5);
    rb_polygon b = make_box(0.5, 0.5);
    rb_manifold m = rb_collide_polygons(&a, rb_transform_identity(), &b, pose(0.3, 0.3, 0.0), 0.0);

    expect_point_count(&m, 2);
    expect_vec_near(m.normal, rb_v2(0.0, 1.0), TOLERANCE, "deep overlap normal");
    expect_point(&m, rb_v2(-0.2, 0.15), -0.7, "deep overlap point at x = -0.2");
    expect_point(&m, rb_v2(0.8, 0.15), -0.7, "deep overlap point at x = 0.8");
}

Test(manifold, box_separated_beyond_speculative_distance)
{
    /* The face-to-face pair with a gap of 0.02 m (d = -0.02): a speculative
     * distance of 0.01 m reports nothing. */
    rb_polygon a = make_box(2.0, 0.5);
    rb_polygon b = make_box(0.5, 0.5);
    rb_manifold m = rb_collide_polygons(&a, rb_transform_identity(), &b, pose(1.8, 1.02, 0.0), 0.01);
    expect_point_count(&m, 0);
}

Test(manifold, box_separated_within_speculative_distance)
{
    /* The same gap of 0.02 m with a speculative distance of 0.05 m: both
     * points, separation +0.02, halfway up the gap at y = 0.51. */
    check_face_to_face(rb_transform_identity(), -0.02, 0.05);
}

Test(manifold, box_corner_on_face)
{
    /* Box B (half 0.5) turned by 45°: its lowest corner, local (-0.5, -0.5),
     * is √2/2 below its centre and straight under it. With the centre at
     * (0.3, 0.5 + √2/2 - d) the corner is at (0.3, 0.5 - d), d = 0.01 into
     * A's top face (A: half (2, 0.5)). B's faces give overlaps over 1 m, so
     * the normal is +y, and the only point within reach is the corner: its
     * neighbours are √2/2 higher. The point is halfway between the corner
     * and the face: (0.3, 0.5 - d/2), separation -d. */
    double d = 0.01;
    rb_polygon a = make_box(2.0, 0.5);
    rb_polygon b = make_box(0.5, 0.5);
    rb_manifold m =
        rb_collide_polygons(&a, rb_transform_identity(), &b, pose(0.3, 0.5 + sqrt(0.5) - d, RB_PI / 4.0), 0.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_v2(0.0, 1.0), TOLERANCE, "corner-on-face normal");
    expect_point(&m, rb_v2(0.3, 0.5 - d / 2.0), -d, "corner-on-face point");
}

/* Box A, half-extents (1, 0.5), at the frame's origin; box B, half 0.5,
 * turned by 30° (c = cos 30°, s = sin 30°). B's corners relative to its
 * centre are R(30°)(±0.5, ±0.5); the lowest is R(30°)(-0.5, -0.5) =
 * (-(c - s)/2, -(c + s)/2), the next lowest R(30°)(0.5, -0.5) =
 * ((c + s)/2, (s - c)/2), s = 0.5 m higher. B's centre is placed at
 * (0.2, 0.5 + (c + s)/2 - d) so that the lowest corner is at
 * (0.2 - (c - s)/2, 0.5 - d), d = 0.02 into A's top face. B's own faces
 * give overlaps of 0.5 m and more (e.g. A's corner (-1, 0.5) is 0.508 m
 * behind B's lower-left face), so the normal is A's +y, one point halfway
 * between the corner and the face, separation -d. Placed by `frame`. */
static rb_manifold collide_general_position(rb_transform frame, bool swap)
{
    double d = 0.02;
    double c = cos(RB_PI / 6.0);
    double s = sin(RB_PI / 6.0);
    rb_polygon a = make_box(1.0, 0.5);
    rb_polygon b = make_box(0.5, 0.5);
    rb_transform xfa = frame;
    rb_transform xfb = rb_mul_transforms(frame, pose(0.2, 0.5 + (c + s) / 2.0 - d, RB_PI / 6.0));
    return swap ? rb_collide_polygons(&b, xfb, &a, xfa, 0.0) : rb_collide_polygons(&a, xfa, &b, xfb, 0.0);
}

/* An arbitrary placement for the configuration above. */
static rb_transform general_frame(void) { return pose(0.7, -1.3, -0.9); }

Test(manifold, rotated_boxes_general_position)
{
    rb_transform frame = general_frame();
    rb_manifold m = collide_general_position(frame, false);
    double d = 0.02;
    double c = cos(RB_PI / 6.0);
    double s = sin(RB_PI / 6.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_rotate(frame.q, rb_v2(0.0, 1.0)), TOLERANCE, "general position normal");
    expect_point(&m, rb_transform_point(frame, rb_v2(0.2 - (c - s) / 2.0, 0.5 - d / 2.0)), -d,
                 "general position point");
}

Test(manifold, swapping_boxes_negates_normal)
{
    rb_manifold ab = collide_general_position(general_frame(), false);
    rb_manifold ba = collide_general_position(general_frame(), true);
    expect_swap_symmetric(&ab, &ba);

    /* The two-point face contact too. */
    rb_polygon a = make_box(2.0, 0.5);
    rb_polygon b = make_box(0.5, 0.5);
    rb_transform xfb = pose(1.8, 0.99, 0.0);
    rb_manifold face_ab = rb_collide_polygons(&a, rb_transform_identity(), &b, xfb, 0.0);
    rb_manifold face_ba = rb_collide_polygons(&b, xfb, &a, rb_transform_identity(), 0.0);
    expect_swap_symmetric(&face_ab, &face_ba);
}

/* ---- Polygons: a triangle and a hexagon ---- */

/* Regular hexagon of circumradius 1 with a flat bottom: vertices at
 * k·60°, its bottom edge from (-0.5, -√3/2) to (0.5, -√3/2). */
static rb_polygon make_hexagon(void)
{
    double h = sqrt(3.0) / 2.0;
    const rb_vec2 points[6] = {{1.0, 0.0}, {0.5, h}, {-0.5, h}, {-1.0, 0.0}, {-0.5, -h}, {0.5, -h}};
    rb_polygon hexagon;
    cr_assert_eq(rb_make_polygon(points, 6, &hexagon), RB_OK, "hexagon: %s", rb_last_error());
    return hexagon;
}

/* Triangle A, apex down: (0, -1), (0.5, 0), (-0.5, 0), its top edge y = 0
 * for x in [-0.5, 0.5]. The hexagon B centred at (0.25, √3/2 - d): its
 * bottom edge is y = -d for x in [-0.25, 0.75]. Overlap d along y; the
 * slanted faces of both overlap by more than 0.3 m. Clipping leaves x in
 * [-0.25, 0.5]; the points are halfway, at y = -d/2. */
static rb_manifold collide_triangle_and_hexagon_faces(bool swap)
{
    double d = 0.01;
    const rb_vec2 points[3] = {{0.0, -1.0}, {0.5, 0.0}, {-0.5, 0.0}};
    rb_polygon triangle;
    cr_assert_eq(rb_make_polygon(points, 3, &triangle), RB_OK, "triangle: %s", rb_last_error());
    rb_polygon hexagon = make_hexagon();
    rb_transform xfa = rb_transform_identity();
    rb_transform xfb = pose(0.25, sqrt(3.0) / 2.0 - d, 0.0);
    return swap ? rb_collide_polygons(&hexagon, xfb, &triangle, xfa, 0.0)
                : rb_collide_polygons(&triangle, xfa, &hexagon, xfb, 0.0);
}

Test(manifold, triangle_and_hexagon_face_to_face)
{
    double d = 0.01;
    rb_manifold m = collide_triangle_and_hexagon_faces(false);

    expect_point_count(&m, 2);
    expect_vec_near(m.normal, rb_v2(0.0, 1.0), TOLERANCE, "triangle-hexagon normal");
    expect_point(&m, rb_v2(-0.25, -d / 2.0), -d, "triangle-hexagon point at x = -0.25");
    expect_point(&m, rb_v2(0.5, -d / 2.0), -d, "triangle-hexagon point at x = 0.5");

    rb_manifold swapped = collide_triangle_and_hexagon_faces(true);
    expect_swap_symmetric(&m, &swapped);
}

Test(manifold, triangle_apex_into_hexagon_face)
{
    /* Triangle A, apex up at (0, 0): (-0.5, -1), (0.5, -1), (0, 0). The
     * hexagon B centred at (0.1, √3/2 - d): bottom edge y = -d for x in
     * [-0.4, 0.6]. The hexagon's bottom face gives overlap d; the
     * triangle's slanted faces and the hexagon's lower slanted faces all
     * give more than 0.3 m. The triangle's base corners are 1 - d below
     * the face, out of reach, so one point: halfway between the apex and
     * the face, (0, -d/2), separation -d, normal +y (from A to B). */
    double d = 0.01;
    const rb_vec2 points[3] = {{-0.5, -1.0}, {0.5, -1.0}, {0.0, 0.0}};
    rb_polygon triangle;
    cr_assert_eq(rb_make_polygon(points, 3, &triangle), RB_OK, "triangle: %s", rb_last_error());
    rb_polygon hexagon = make_hexagon();
    rb_manifold m =
        rb_collide_polygons(&triangle, rb_transform_identity(), &hexagon, pose(0.1, sqrt(3.0) / 2.0 - d, 0.0), 0.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_v2(0.0, 1.0), TOLERANCE, "apex normal");
    expect_point(&m, rb_v2(0.0, -d / 2.0), -d, "apex point");
}

/* ---- Circle against polygon ---- */

Test(manifold, circle_on_box_face)
{
    /* In a frame G (turned 0.4 rad, at (1, -2)): box A, half (1, 0.5), at
     * the origin; circle B of radius 0.25 centred at (0.1, 0) in its body,
     * whose body is turned a quarter turn at (0.3, 0.65 - d), so the centre
     * is at (0.3, 0.75 - d): its lowest point is d = 0.01 below the top
     * face y = 0.5, well inside x in [-1, 1]. Normal +y, separation -d,
     * point halfway: (0.3, 0.5 - d/2). */
    double d = 0.01;
    rb_transform frame = pose(1.0, -2.0, 0.4);
    rb_polygon a = make_box(1.0, 0.5);
    rb_circle b = {.center = {0.1, 0.0}, .radius = 0.25};
    rb_transform xfb = rb_mul_transforms(frame, pose(0.3, 0.65 - d, RB_PI / 2.0));
    rb_manifold m = rb_collide_polygon_and_circle(&a, frame, &b, xfb, 0.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_rotate(frame.q, rb_v2(0.0, 1.0)), TOLERANCE, "circle-on-face normal");
    expect_point(&m, rb_transform_point(frame, rb_v2(0.3, 0.5 - d / 2.0)), -d, "circle-on-face point");
}

Test(manifold, circle_on_box_corner)
{
    /* Box A, half (1, 0.5): corner (1, 0.5). Circle B of radius 0.25
     * centred at corner + 0.2·(0.6, 0.8) = (1.12, 0.66), beyond both faces
     * that meet there (x > 1, y > 0.5), so the closest box point is the
     * corner. Normal (0.6, 0.8), separation 0.2 - 0.25 = -0.05, point
     * halfway between the corner and the circle's surface point
     * corner + (0.2 - 0.25)·n: corner - 0.025·n = (0.985, 0.48). */
    rb_polygon a = make_box(1.0, 0.5);
    rb_circle b = {.center = {0.0, 0.0}, .radius = 0.25};
    rb_manifold m = rb_collide_polygon_and_circle(&a, rb_transform_identity(), &b, pose(1.12, 0.66, 0.0), 0.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_v2(0.6, 0.8), TOLERANCE, "circle-on-corner normal");
    expect_point(&m, rb_v2(0.985, 0.48), -0.05, "circle-on-corner point");
}

Test(manifold, circle_centre_inside_box)
{
    /* Box A, half (1, 0.5); circle B of radius 0.25 centred at (0.7, 0.1),
     * inside the box. Distances from the centre to the faces: right 0.3,
     * top 0.4, bottom 0.6, left 1.7: the right face is nearest, so the
     * normal is +x. The circle reaches from the face at x = 1 back to
     * 0.7 - 0.25 = 0.45: separation -(0.3 + 0.25) = -0.55, point halfway
     * between x = 1 and x = 0.45: (0.725, 0.1). */
    rb_polygon a = make_box(1.0, 0.5);
    rb_circle b = {.center = {0.0, 0.0}, .radius = 0.25};
    rb_manifold m = rb_collide_polygon_and_circle(&a, rb_transform_identity(), &b, pose(0.7, 0.1, 0.0), 0.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_v2(1.0, 0.0), TOLERANCE, "circle-inside normal");
    expect_point(&m, rb_v2(0.725, 0.1), -0.55, "circle-inside point");
}

/* ---- Circle against circle ---- */

Test(manifold, circles_overlapping)
{
    /* Circle A of radius 0.5 centred at (0.5, 0) in a body turned a
     * quarter turn at (1, 2): world centre (1, 2.5). Circle B of radius
     * 0.3 centred 0.7 m away along n = (0.6, 0.8): (1.42, 3.06).
     * Separation 0.7 - 0.8 = -0.1; A's surface point (1, 2.5) + 0.5 n =
     * (1.3, 2.9), B's (1.42, 3.06) - 0.3 n = (1.24, 2.82); midpoint
     * (1.27, 2.86). */
    rb_circle a = {.center = {0.5, 0.0}, .radius = 0.5};
    rb_circle b = {.center = {0.0, 0.0}, .radius = 0.3};
    rb_manifold m = rb_collide_circles(&a, pose(1.0, 2.0, RB_PI / 2.0), &b, pose(1.42, 3.06, 0.0), 0.0);

    expect_point_count(&m, 1);
    expect_vec_near(m.normal, rb_v2(0.6, 0.8), TOLERANCE, "circles normal");
    expect_point(&m, rb_v2(1.27, 2.86), -0.1, "circles point");
}

Test(manifold, circles_coincident_centres)
{
    /* Both centres at (0.4, -0.3): no direction is preferred, but the
     * normal must still be a unit vector (no NaN), the separation is
     * -(0.2 + 0.3) = -0.5, and the point is halfway between A's surface
     * c + 0.2 n and B's c - 0.3 n, at c - 0.05 n for whatever n. */
    rb_circle a = {.center = {0.0, 0.0}, .radius = 0.2};
    rb_circle b = {.center = {0.0, 0.0}, .radius = 0.3};
    rb_vec2 c = {0.4, -0.3};
    rb_manifold m = rb_collide_circles(&a, pose(c.x, c.y, 0.0), &b, pose(c.x, c.y, 0.0), 0.0);

    expect_point_count(&m, 1);
    cr_expect(rb_vec2_is_finite(m.normal), "normal (%g, %g) is not finite", m.normal.x, m.normal.y);
    expect_near(rb_length(m.normal), 1.0, TOLERANCE, "coincident circles normal length");
    expect_point(&m, rb_mul_sub(c, 0.05, m.normal), -0.5, "coincident circles point");
}

Test(manifold, circles_speculative)
{
    /* Radii 0.5 and 0.3 with centres 1 m apart along x: gap 0.2 m. A
     * speculative distance of 0.1 reports nothing; 0.3 reports the point
     * (0.5 + 0.2/2, 0) = (0.6, 0) with separation +0.2 and normal +x. */
    rb_circle a = {.center = {0.0, 0.0}, .radius = 0.5};
    rb_circle b = {.center = {0.0, 0.0}, .radius = 0.3};
    rb_manifold beyond = rb_collide_circles(&a, rb_transform_identity(), &b, pose(1.0, 0.0, 0.0), 0.1);
    expect_point_count(&beyond, 0);

    rb_manifold within = rb_collide_circles(&a, rb_transform_identity(), &b, pose(1.0, 0.0, 0.0), 0.3);
    expect_point_count(&within, 1);
    expect_vec_near(within.normal, rb_v2(1.0, 0.0), TOLERANCE, "speculative circles normal");
    expect_point(&within, rb_v2(0.6, 0.0), 0.2, "speculative circles point");
}

/* ---- Feature ids ---- */

/* Each point of `after` has the id of the point of `before` nearest to it
 * (the bodies moved far less than the 1 m between the two points). */
static void expect_same_ids(const rb_manifold *before, const rb_manifold *after)
{
    cr_assert_eq(before->point_count, 2, "first frame has %d points, expected 2", before->point_count);
    cr_assert_eq(after->point_count, 2, "second frame has %d points, expected 2", after->point_count);
    cr_expect_neq(before->points[0].id, before->points[1].id, "the two points share id %#x", before->points[0].id);
    for (int i = 0; i < 2; ++i) {
        int j = nearest_point(before, after->points[i].point);
        cr_expect_eq(after->points[i].id, before->points[j].id,
                     "point near (%g, %g) changed id from %#x to %#x between frames", after->points[i].point.x,
                     after->points[i].point.y, before->points[j].id, after->points[i].id);
    }
}

Test(manifold, feature_ids_stable_when_box_moves_slightly)
{
    /* A unit box resting 1 mm deep on a ground box (half (2, 0.5)), then
     * moved by 1e-4 m right and 1e-4 m down: the same corners meet the
     * same face, so the ids are unchanged. */
    rb_polygon ground = make_box(2.0, 0.5);
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold first = rb_collide_polygons(&ground, rb_transform_identity(), &box, pose(0.3, 0.999, 0.0), 0.0);
    rb_manifold second =
        rb_collide_polygons(&ground, rb_transform_identity(), &box, pose(0.3 + 1e-4, 0.999 - 1e-4, 0.0), 0.0);
    expect_same_ids(&first, &second);
}

Test(manifold, feature_ids_stable_when_box_rocks_slightly)
{
    /* The box is now shape A and the ground shape B. Level, the box's bottom
     * face and the ground's top face overlap equally (1 mm), a tie. Tilted
     * by θ the box's lowest corner sinks 0.5|θ| deeper, while the ground's
     * far corners (x = ±2) fall up to 2.3|θ| behind the box's bottom face:
     * the ground's face is better by about 1.8|θ|, here 2e-5 m. Such a
     * tiny preference must not swap the reference face, or the ids of
     * the same two corners on the same face would change as the box
     * rocks by 1e-5 rad. */
    rb_polygon ground = make_box(2.0, 0.5);
    rb_polygon box = make_box(0.5, 0.5);
    const double angles[3] = {0.0, 1e-5, -1e-5};
    rb_manifold frames[3];
    for (int i = 0; i < 3; ++i) {
        frames[i] = rb_collide_polygons(&box, pose(0.3, 0.999, angles[i]), &ground, rb_transform_identity(), 0.0);
        expect_vec_near(frames[i].normal, rb_v2(0.0, -1.0), 1e-4, "rocking box normal (within the 1e-5 rad tilt)");
    }
    expect_same_ids(&frames[0], &frames[1]);
    expect_same_ids(&frames[1], &frames[2]);
}

/* Ground box A (half (2, 0.5)) and unit box B centred at (0.3, 0.999),
 * 1 mm deep, first level, then turned by `angle` = ±0.01 rad. Turned, one
 * bottom corner rises by 0.5 sin|θ| ≈ 5 mm, out of reach (separation
 * +4 mm > 0), and the other sinks: only it stays, and it must keep the id
 * it had when the box was level, as it is the same corner on the same
 * face. The sinking corner is R(θ)(∓0.5, -0.5) from the centre (left
 * for θ > 0): at (0.3 ∓ 0.5 cos θ + 0.5 sin|θ|, 0.999 - 0.5 (cos θ + sin|θ|)),
 * separation its height above y = 0.5, the point halfway down to it. */
static void check_surviving_corner_keeps_id(double angle)
{
    rb_polygon ground = make_box(2.0, 0.5);
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold level = rb_collide_polygons(&ground, rb_transform_identity(), &box, pose(0.3, 0.999, 0.0), 0.0);
    rb_manifold turned = rb_collide_polygons(&ground, rb_transform_identity(), &box, pose(0.3, 0.999, angle), 0.0);

    double c = cos(angle);
    double s = fabs(sin(angle));
    double side = angle > 0.0 ? -1.0 : 1.0;
    rb_vec2 corner = {0.3 + side * 0.5 * c + -side * 0.5 * s, 0.999 - 0.5 * (c + s)};
    double separation = corner.y - 0.5;

    cr_assert_eq(level.point_count, 2, "level box: %d points, expected 2", level.point_count);
    cr_assert_eq(turned.point_count, 1, "turned box: %d points, expected 1", turned.point_count);
    expect_vec_near(turned.normal, rb_v2(0.0, 1.0), TOLERANCE, "turned box normal");
    expect_point(&turned, rb_v2(corner.x, 0.5 + separation / 2.0), separation, "turned box corner point");

    int j = nearest_point(&level, turned.points[0].point);
    cr_expect_eq(turned.points[0].id, level.points[j].id, "the corner at x = %g had id %#x level, %#x turned", corner.x,
                 level.points[j].id, turned.points[0].id);
}

Test(manifold, feature_id_follows_surviving_corner)
{
    /* Both directions, so that the survivor is once the first and once the
     * second point of the level manifold. */
    check_surviving_corner_keeps_id(0.01);
    check_surviving_corner_keeps_id(-0.01);
}

Test(manifold, feature_ids_survive_a_change_of_reference_face)
{
    /* Two unit boxes as in a pyramid: the upper one (B) centred over the
     * lower one's right edge, 1 cm deep. Its bottom face and the lower
     * box's top face are nearly parallel, so a tilt of -1 mrad leaves the
     * reference face on A and -2 mrad moves it to B. The same two corners
     * meet in both frames (the lower box's top right, the upper box's
     * bottom left cut by the other's side plane), and they must keep their
     * ids: with the side of the reference face in the id, every point of
     * a leaning stack lost its warm start whenever a box rocked past the
     * tie, and a soft-step pyramid of base 100 spread by metres. */
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold on_a = rb_collide_polygons(&box, rb_transform_identity(), &box, pose(0.5, 0.99, -1e-3), 0.0);
    rb_manifold on_b = rb_collide_polygons(&box, rb_transform_identity(), &box, pose(0.5, 0.99, -2e-3), 0.0);
    cr_assert(!on_a.reference_on_b, "at -1 mrad the reference face should be the lower box's");
    cr_assert(on_b.reference_on_b, "at -2 mrad the reference face should be the upper box's");
    expect_same_ids(&on_a, &on_b);
}

Test(manifold, feature_ids_ignore_roundoff_at_side_planes)
{
    /* Two equal unit boxes stacked exactly: the upper box's bottom corners
     * lie on the side planes of the lower box's top face, so whether a
     * side plane cuts them is decided by round-off. Shifting the upper box
     * by +1e-12 m and then -1e-12 m puts one corner just outside a side
     * plane in each frame (cut there) and just inside in the other (kept
     * as a vertex). The ids must not change: a changed id would throw
     * away the warm-start impulse of every contact in a column of equal
     * boxes, every frame. */
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold right_shift = rb_collide_polygons(&box, rb_transform_identity(), &box, pose(1e-12, 0.999, 0.0), 0.0);
    rb_manifold left_shift = rb_collide_polygons(&box, rb_transform_identity(), &box, pose(-1e-12, 0.999, 0.0), 0.0);
    cr_assert_eq(right_shift.point_count, 2, "right shift: %d points, expected 2", right_shift.point_count);
    cr_assert_eq(left_shift.point_count, 2, "left shift: %d points, expected 2", left_shift.point_count);
    for (int side = 0; side < 2; ++side) {
        rb_vec2 corner = rb_v2(side == 0 ? -0.5 : 0.5, 0.4995);
        uint32_t before = right_shift.points[nearest_point(&right_shift, corner)].id;
        uint32_t after = left_shift.points[nearest_point(&left_shift, corner)].id;
        cr_expect_eq(after, before, "corner %d: id %#x became %#x under a 2e-12 m shift", side, before, after);
    }
}

Test(manifold, feature_ids_change_with_features)
{
    /* Ids are equal exactly when the same features meet. A unit box 1 mm
     * deep on a ground box (half (2, 0.5)) uses the ground's top edge as
     * reference and its own bottom edge as incident edge. Turned by a
     * quarter turn, the box meets the ground with a different edge of its
     * own (its right edge comes to the bottom), so both ids change; the
     * two points of one frame also differ from each other. */
    rb_polygon ground = make_box(2.0, 0.5);
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold flat = rb_collide_polygons(&ground, rb_transform_identity(), &box, pose(0.0, 0.999, 0.0), 0.0);
    rb_manifold turned =
        rb_collide_polygons(&ground, rb_transform_identity(), &box, pose(0.0, 0.999, 0.5 * RB_PI), 0.0);
    cr_assert_eq(flat.point_count, 2, "flat: %d points, expected 2", flat.point_count);
    cr_assert_eq(turned.point_count, 2, "turned: %d points, expected 2", turned.point_count);
    cr_expect_neq(flat.points[0].id, flat.points[1].id, "the two points of one manifold share id %#x",
                  flat.points[0].id);
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
            cr_expect_neq(flat.points[i].id, turned.points[j].id,
                          "id %#x kept though the box meets the ground with another edge", flat.points[i].id);
        }
    }
}

Test(manifold, feature_ids_stable_in_world)
{
    /* A dynamic unit box (half 0.5) starting exactly on a static ground box
     * whose top face is y = 0. After each of two steps of 1/60 s the world
     * holds one contact with two points whose ids must not change. The box
     * settles by at most millimetres in two steps and gets no sideways
     * push, so the points stay near x = ±0.5 and the normal near ±y; 1e-3
     * only checks that this is the face contact, not solver accuracy. */
    rb_world *world = make_world(rb_default_world_def().gravity);
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, -0.5), 0.0);
    add_box(world, ground, 5.0, 0.5, 1.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.5), 0.0);
    add_box(world, box, 0.5, 0.5, 1.0);

    rb_manifold frames[2];
    for (int step = 0; step < 2; ++step) {
        step_world(world, TEST_DT, 1);
        rb_contact_data contacts[4];
        int count = rb_world_contacts(world, contacts, 4);
        cr_assert_eq(count, 1, "step %d: %d contacts, expected 1", step, count);
        frames[step] = contacts[0].manifold;

        rb_vec2 up = rb_body_id_equals(contacts[0].body_a, ground) ? rb_v2(0.0, 1.0) : rb_v2(0.0, -1.0);
        expect_vec_near(frames[step].normal, up, 1e-3, "world contact normal");
        cr_assert_eq(frames[step].point_count, 2, "step %d: %d points, expected 2", step, frames[step].point_count);
        expect_vec_near(frames[step].points[nearest_point(&frames[step], rb_v2(-0.5, 0.0))].point, rb_v2(-0.5, 0.0),
                        1e-3, "world contact left point");
        expect_vec_near(frames[step].points[nearest_point(&frames[step], rb_v2(0.5, 0.0))].point, rb_v2(0.5, 0.0), 1e-3,
                        "world contact right point");
    }
    expect_same_ids(&frames[0], &frames[1]);

    destroy_world_and_expect_no_leak(world);
}
