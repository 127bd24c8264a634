/* SPDX-License-Identifier: MIT */
/* Shape geometry: polygon construction and validation, mass properties and
 * bounding boxes, against closed-form values derived in the comments.
 *
 * Tolerance: unless a test says otherwise, expected values are exact
 * rationals or a few trigonometric terms of order 1..100, and the engine
 * reaches them in a few dozen floating-point operations; with a unit
 * roundoff of 1.1e-16 the accumulated error stays below 1e-13, so
 * TOLERANCE = 1e-12 (relative to values of order 1) cannot hide a wrong
 * formula, whose errors here are of order 0.01 or more.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "rb/rb.h"
#include "test_support.h"

#define TOLERANCE 1e-12

/* A call failed with `expected`, rb_last_status() agrees, and
 * rb_last_error() is a message naming the function that failed. */
static void expect_failure(rb_status status, rb_status expected, const char *function)
{
    cr_expect_eq(status, expected, "%s returned %s, expected %s", function, rb_status_name(status),
                 rb_status_name(expected));
    cr_expect_eq(rb_last_status(), expected, "rb_last_status() is %s after %s failed, expected %s",
                 rb_status_name(rb_last_status()), function, rb_status_name(expected));
    const char *message = rb_last_error();
    cr_expect(message != NULL && strstr(message, function) != NULL,
              "rb_last_error() after a failed %s should name it, got \"%s\"", function, message ? message : "(null)");
}

/* How many vertices of `polygon` lie within `tolerance` of `point`. */
static int count_vertices_near(const rb_polygon *polygon, rb_vec2 point, double tolerance)
{
    int matches = 0;
    for (int i = 0; i < polygon->count; ++i) {
        if (rb_distance(polygon->vertices[i], point) <= tolerance) {
            ++matches;
        }
    }
    return matches;
}

/* The polygon is counter-clockwise and convex (every turn strictly left)
 * and each normals[i] is the unit outward normal of edge i -> i+1, which
 * for a counter-clockwise polygon is the edge direction turned clockwise. */
static void expect_ccw_with_outward_normals(const rb_polygon *polygon)
{
    int n = polygon->count;
    for (int i = 0; i < n; ++i) {
        rb_vec2 v0 = polygon->vertices[i];
        rb_vec2 v1 = polygon->vertices[(i + 1) % n];
        rb_vec2 v2 = polygon->vertices[(i + 2) % n];
        double turn = rb_cross(rb_sub(v1, v0), rb_sub(v2, v1));
        cr_expect(turn > 0.0, "turn at vertex %d is %g, expected a left (counter-clockwise) turn", (i + 1) % n, turn);

        rb_vec2 expected_normal = rb_normalize(rb_right_perp(rb_sub(v1, v0)));
        expect_vec_near(polygon->normals[i], expected_normal, TOLERANCE, "edge normal");
        expect_near(rb_length(polygon->normals[i]), 1.0, TOLERANCE, "edge normal length");
        for (int j = 0; j < n; ++j) {
            /* Every vertex lies on or behind each edge's outward normal. */
            double height = rb_dot(polygon->normals[i], rb_sub(polygon->vertices[j], v0));
            cr_expect(height <= TOLERANCE, "vertex %d is %g in front of edge %d", j, height, i);
        }
    }
}

/* ---- Mass properties ---- */

Test(geometry, circle_mass_with_offset)
{
    /* Area π r² = π/4; mass ρ·area = 2·π/4 = π/2; centre of mass at the
     * circle's centre; a uniform disc about its centre has m r²/2. */
    rb_circle circle = {.center = {0.3, -0.2}, .radius = 0.5};
    double density = 2.0;
    rb_mass_data mass = rb_circle_mass(&circle, density);

    expect_near(rb_circle_area(&circle), RB_PI / 4.0, TOLERANCE, "circle area");
    expect_near(mass.mass, RB_PI / 2.0, TOLERANCE, "circle mass");
    expect_vec_near(mass.center, rb_v2(0.3, -0.2), TOLERANCE, "circle centre of mass");
    expect_near(mass.rotational_inertia, (RB_PI / 2.0) * 0.25 / 2.0, TOLERANCE, "circle inertia about its centre");
}

Test(geometry, box_mass_and_vertices)
{
    /* Half-extents (1.5, 0.5): a 3 × 1 rectangle, area 3, mass 3ρ = 9;
     * I = m (w² + h²)/12 = 9 (9 + 1)/12 = 7.5 about the centre. */
    rb_polygon box;
    cr_assert_eq(rb_make_box(1.5, 0.5, &box), RB_OK, "rb_make_box failed: %s", rb_last_error());
    rb_mass_data mass = rb_polygon_mass(&box, 3.0);

    cr_expect_eq(box.count, 4, "a box has 4 vertices, got %d", box.count);
    const rb_vec2 corners[4] = {{-1.5, -0.5}, {1.5, -0.5}, {1.5, 0.5}, {-1.5, 0.5}};
    for (int i = 0; i < 4; ++i) {
        cr_expect_eq(count_vertices_near(&box, corners[i], TOLERANCE), 1, "corner (%g, %g) should appear once",
                     corners[i].x, corners[i].y);
    }
    expect_ccw_with_outward_normals(&box);
    expect_vec_near(box.centroid, rb_v2(0.0, 0.0), TOLERANCE, "box centroid");
    expect_near(rb_polygon_area(&box), 3.0, TOLERANCE, "box area");
    expect_near(mass.mass, 9.0, TOLERANCE, "box mass");
    expect_vec_near(mass.center, rb_v2(0.0, 0.0), TOLERANCE, "box centre of mass");
    expect_near(mass.rotational_inertia, 7.5, TOLERANCE, "box inertia");
}

Test(geometry, offset_rotated_box_mass_and_vertices)
{
    /* A 1 × 0.5 box centred at (1, -2), turned by 0.7 rad. Mass and
     * inertia about the centroid do not depend on placement:
     * m = 3 · 0.5 = 1.5, I = 1.5 (1² + 0.5²)/12 = 0.15625. Its corners are
     * c + R(0.7)(±0.5, ±0.25). */
    double angle = 0.7;
    rb_vec2 center = {1.0, -2.0};
    rb_polygon box;
    cr_assert_eq(rb_make_offset_box(0.5, 0.25, center, angle, &box), RB_OK, "rb_make_offset_box failed: %s",
                 rb_last_error());
    rb_mass_data mass = rb_polygon_mass(&box, 3.0);

    cr_expect_eq(box.count, 4, "a box has 4 vertices, got %d", box.count);
    rb_rot q = rb_rot_from_angle(angle);
    const rb_vec2 local_corners[4] = {{-0.5, -0.25}, {0.5, -0.25}, {0.5, 0.25}, {-0.5, 0.25}};
    for (int i = 0; i < 4; ++i) {
        rb_vec2 corner = rb_add(center, rb_rotate(q, local_corners[i]));
        cr_expect_eq(count_vertices_near(&box, corner, TOLERANCE), 1, "corner (%g, %g) should appear once", corner.x,
                     corner.y);
    }
    expect_ccw_with_outward_normals(&box);
    expect_vec_near(box.centroid, center, TOLERANCE, "offset box centroid");
    expect_near(rb_polygon_area(&box), 0.5, TOLERANCE, "offset box area");
    expect_near(mass.mass, 1.5, TOLERANCE, "offset box mass");
    expect_vec_near(mass.center, center, TOLERANCE, "offset box centre of mass");
    expect_near(mass.rotational_inertia, 0.15625, TOLERANCE, "offset box inertia about its centre");
}

Test(geometry, triangle_mass)
{
    /* Triangle (0,0), (4,0), (1,3): area = |cross((4,0), (1,3))|/2 = 12/2 = 6;
     * centroid = mean of the vertices = (5/3, 1). A uniform triangle of
     * mass m has polar moment m (a² + b² + c²)/36 about its centroid
     * (equilateral check: side s gives m s²/12, the known value). Squared
     * sides: 16, (3² + 3²) = 18, (1² + 3²) = 10; sum 44. With ρ = 0.5:
     * m = 3, I = 3 · 44/36 = 11/3. */
    const rb_vec2 points[3] = {{0.0, 0.0}, {4.0, 0.0}, {1.0, 3.0}};
    rb_polygon triangle;
    cr_assert_eq(rb_make_polygon(points, 3, &triangle), RB_OK, "rb_make_polygon failed: %s", rb_last_error());
    rb_mass_data mass = rb_polygon_mass(&triangle, 0.5);

    expect_near(rb_polygon_area(&triangle), 6.0, TOLERANCE, "triangle area");
    expect_vec_near(triangle.centroid, rb_v2(5.0 / 3.0, 1.0), TOLERANCE, "triangle centroid");
    expect_near(mass.mass, 3.0, TOLERANCE, "triangle mass");
    expect_vec_near(mass.center, rb_v2(5.0 / 3.0, 1.0), TOLERANCE, "triangle centre of mass");
    expect_near(mass.rotational_inertia, 11.0 / 3.0, TOLERANCE, "triangle inertia about its centroid");
}

Test(geometry, irregular_pentagon_mass)
{
    /* Pentagon P0..P4 = (0,0), (3,0), (4,2), (2,4), (-1,2), counter-clockwise
     * (turns 6, 6, 10, 8, 6 are all positive). With k_i = x_i y_{i+1} -
     * x_{i+1} y_i = 0, 6, 12, 8, 0 (shoelace):
     *   area A = Σk/2 = 13;
     *   centroid x = Σ(x_i + x_{i+1}) k_i / (6A) = (42 + 72 + 8)/78 = 61/39,
     *            y = Σ(y_i + y_{i+1}) k_i / (6A) = (12 + 72 + 48)/78 = 22/13;
     *   polar moment about the origin per unit density
     *     J_O = Σ k_i (x_i² + x_i x_{i+1} + x_{i+1}² + y_i² + y_i y_{i+1} + y_{i+1}²)/12
     *         = (6·41 + 12·56 + 8·31)/12 = 1166/12 = 583/6;
     *   parallel axis: J_C = J_O - A |c|² = 583/6 - 13 (3721 + 4356)/1521
     *         = 583/6 - 8077/117 = 6583/234.
     * With ρ = 2.5: m = 32.5, I = 2.5 · 6583/234. The points are given
     * starting from P2 to check that the start vertex does not matter. */
    const rb_vec2 points[5] = {{4.0, 2.0}, {2.0, 4.0}, {-1.0, 2.0}, {0.0, 0.0}, {3.0, 0.0}};
    rb_polygon pentagon;
    cr_assert_eq(rb_make_polygon(points, 5, &pentagon), RB_OK, "rb_make_polygon failed: %s", rb_last_error());
    double density = 2.5;
    rb_mass_data mass = rb_polygon_mass(&pentagon, density);
    rb_vec2 centroid = {61.0 / 39.0, 22.0 / 13.0};

    cr_expect_eq(pentagon.count, 5, "pentagon keeps its 5 vertices, got %d", pentagon.count);
    expect_near(rb_polygon_area(&pentagon), 13.0, TOLERANCE, "pentagon area");
    expect_vec_near(pentagon.centroid, centroid, TOLERANCE, "pentagon centroid");
    expect_near(mass.mass, density * 13.0, TOLERANCE, "pentagon mass");
    expect_vec_near(mass.center, centroid, TOLERANCE, "pentagon centre of mass");
    /* Values of order 100: 1e-12 relative. */
    expect_near(mass.rotational_inertia, density * 6583.0 / 234.0, 100.0 * TOLERANCE,
                "pentagon inertia about its centroid");
}

Test(geometry, area_density_from_volume)
{
    /* A bone plate of ρ = 1900 kg/m³ and depth 0.03 m: area density
     * ρ·depth = 57 kg/m². A 0.1 m × 0.4 m plate of it weighs
     * ρ · area · depth = 1900 · 0.04 · 0.03 = 2.28 kg. */
    double area_density = 0.0;
    cr_assert_eq(rb_area_density_from_volume(1900.0, 0.03, &area_density), RB_OK,
                 "rb_area_density_from_volume failed: %s", rb_last_error());
    expect_near(area_density, 57.0, 100.0 * TOLERANCE, "area density");

    rb_polygon plate;
    cr_assert_eq(rb_make_box(0.05, 0.2, &plate), RB_OK, "rb_make_box failed: %s", rb_last_error());
    expect_near(rb_polygon_mass(&plate, area_density).mass, 2.28, TOLERANCE, "plate mass");
}

Test(geometry, area_density_rejects_bad_arguments)
{
    /* Both the density and the depth must be finite and > 0. */
    const double bad[4] = {0.0, -1.0, NAN, INFINITY};
    double area_density = 0.0;
    for (int i = 0; i < 4; ++i) {
        expect_failure(rb_area_density_from_volume(bad[i], 0.03, &area_density), RB_ERR_INVALID_ARGUMENT,
                       "rb_area_density_from_volume");
        expect_failure(rb_area_density_from_volume(1000.0, bad[i], &area_density), RB_ERR_INVALID_ARGUMENT,
                       "rb_area_density_from_volume");
    }
    expect_failure(rb_area_density_from_volume(1000.0, 0.03, NULL), RB_ERR_INVALID_ARGUMENT,
                   "rb_area_density_from_volume");
}

/* ---- Polygon validation ---- */

Test(geometry, make_polygon_rejects_non_convex)
{
    /* (1, 0.5) lies inside the square (0,0)-(2,2): a dented outline. */
    const rb_vec2 dented[5] = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {1.0, 0.5}, {0.0, 2.0}};
    rb_polygon polygon;
    expect_failure(rb_make_polygon(dented, 5, &polygon), RB_ERR_NOT_CONVEX, "rb_make_polygon");

    /* (1, 0) lies on the edge (0,0)-(2,0) of the hull of the others. */
    const rb_vec2 on_edge[5] = {{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {0.0, 2.0}};
    expect_failure(rb_make_polygon(on_edge, 5, &polygon), RB_ERR_NOT_CONVEX, "rb_make_polygon");
}

Test(geometry, make_polygon_rejects_collinear_points)
{
    /* All on the line y = x, or all on y = 0 (in scrambled order): no area. */
    const rb_vec2 diagonal[3] = {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}};
    const rb_vec2 horizontal[4] = {{0.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}, {2.0, 0.0}};
    rb_polygon polygon;
    expect_failure(rb_make_polygon(diagonal, 3, &polygon), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon");
    expect_failure(rb_make_polygon(horizontal, 4, &polygon), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon");
}

Test(geometry, make_polygon_rejects_coincident_points)
{
    rb_polygon polygon;
    const rb_vec2 repeated[4] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
    expect_failure(rb_make_polygon(repeated, 4, &polygon), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon");

    const rb_vec2 one_point[3] = {{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}};
    expect_failure(rb_make_polygon(one_point, 3, &polygon), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon");

    /* (1, 0) and (1.0001, 0.0001) are 1.4e-4 m apart, closer than
     * RB_POLYGON_WELD_DISTANCE (5e-4 m), so they are one point; both are
     * corners of the hull, so this is a coincidence, not a concavity. */
    const rb_vec2 near_repeated[4] = {{0.0, 0.0}, {1.0, 0.0}, {1.0001, 0.0001}, {0.0, 1.0}};
    expect_failure(rb_make_polygon(near_repeated, 4, &polygon), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon");
}

Test(geometry, make_polygon_rejects_bad_counts)
{
    /* Nine points of a regular nonagon: convex, but more than
     * RB_MAX_POLYGON_VERTICES (8). */
    rb_vec2 nonagon[9];
    for (int i = 0; i < 9; ++i) {
        nonagon[i] = rb_v2(cos(2.0 * RB_PI * i / 9.0), sin(2.0 * RB_PI * i / 9.0));
    }
    rb_polygon polygon;
    expect_failure(rb_make_polygon(nonagon, 9, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
    expect_failure(rb_make_polygon(nonagon, 2, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
    expect_failure(rb_make_polygon(nonagon, 0, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
    expect_failure(rb_make_polygon(nonagon, -3, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
}

Test(geometry, make_polygon_rejects_non_finite_and_null)
{
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    rb_polygon polygon;
    for (int i = 0; i < 3; ++i) {
        const rb_vec2 bad_x[3] = {{0.0, 0.0}, {bad[i], 0.0}, {0.0, 1.0}};
        const rb_vec2 bad_y[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, bad[i]}};
        expect_failure(rb_make_polygon(bad_x, 3, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
        expect_failure(rb_make_polygon(bad_y, 3, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
    }
    const rb_vec2 triangle[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
    expect_failure(rb_make_polygon(NULL, 3, &polygon), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
    expect_failure(rb_make_polygon(triangle, 3, NULL), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon");
}

Test(geometry, make_polygon_accepts_clockwise_input)
{
    /* The pentagon of irregular_pentagon_mass listed clockwise. The result
     * holds the same five points, counter-clockwise, with unit outward
     * normals, and the same area 13. */
    const rb_vec2 clockwise[5] = {{0.0, 0.0}, {-1.0, 2.0}, {2.0, 4.0}, {4.0, 2.0}, {3.0, 0.0}};
    rb_polygon polygon;
    cr_assert_eq(rb_make_polygon(clockwise, 5, &polygon), RB_OK, "rb_make_polygon failed: %s", rb_last_error());

    cr_expect_eq(polygon.count, 5, "count %d, expected 5", polygon.count);
    for (int i = 0; i < 5; ++i) {
        cr_expect_eq(count_vertices_near(&polygon, clockwise[i], TOLERANCE), 1, "point (%g, %g) should appear once",
                     clockwise[i].x, clockwise[i].y);
    }
    expect_ccw_with_outward_normals(&polygon);
    expect_near(rb_polygon_area(&polygon), 13.0, TOLERANCE, "area");
}

Test(geometry, make_polygon_accepts_any_order)
{
    /* The same pentagon, its points shuffled so that the given order is
     * not an outline at all. */
    const rb_vec2 shuffled[5] = {{2.0, 4.0}, {0.0, 0.0}, {4.0, 2.0}, {-1.0, 2.0}, {3.0, 0.0}};
    rb_polygon polygon;
    cr_assert_eq(rb_make_polygon(shuffled, 5, &polygon), RB_OK, "rb_make_polygon failed: %s", rb_last_error());

    cr_expect_eq(polygon.count, 5, "count %d, expected 5", polygon.count);
    for (int i = 0; i < 5; ++i) {
        cr_expect_eq(count_vertices_near(&polygon, shuffled[i], TOLERANCE), 1, "point (%g, %g) should appear once",
                     shuffled[i].x, shuffled[i].y);
    }
    expect_ccw_with_outward_normals(&polygon);
    expect_near(rb_polygon_area(&polygon), 13.0, TOLERANCE, "area");
}

Test(geometry, success_clears_last_error)
{
    const rb_vec2 collinear[3] = {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}};
    const rb_vec2 triangle[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
    rb_polygon polygon;
    expect_failure(rb_make_polygon(collinear, 3, &polygon), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon");
    cr_assert_eq(rb_make_polygon(triangle, 3, &polygon), RB_OK, "rb_make_polygon failed: %s", rb_last_error());
    cr_expect_eq(rb_last_status(), RB_OK, "rb_last_status() is %s after a success", rb_status_name(rb_last_status()));
    cr_expect_str_empty(rb_last_error(), "rb_last_error() should be \"\" after a success, got \"%s\"", rb_last_error());
}

/* ---- Convex hull ---- */

Test(geometry, hull_drops_interior_collinear_and_welds)
{
    /* The rectangle (0,0)-(2,1) plus: an interior point (1, 0.5); the
     * midpoint (1, 0) of the bottom edge; (1.5, 1.0001), 1e-4 m outside
     * the top edge, closer than the weld distance (5e-4 m) to the line
     * through its hull neighbours (2,1) and (0,1), so dropped as
     * collinear; and (2.0001, 0.0001), 1.4e-4 m from the corner (2, 0),
     * welded to it. The hull is the rectangle: 4 vertices, each within
     * 1.5e-4 m of a corner (either copy of the welded corner may stay), and
     * area 2 up to the 1e-4 m perturbations times the 2 m sides. */
    const rb_vec2 cloud[8] = {{1.0, 0.5},       {0.0, 0.0}, {1.0, 0.0},    {2.0, 0.0},
                              {2.0001, 0.0001}, {2.0, 1.0}, {1.5, 1.0001}, {0.0, 1.0}};
    rb_polygon hull;
    cr_assert_eq(rb_make_polygon_hull(cloud, 8, &hull), RB_OK, "rb_make_polygon_hull failed: %s", rb_last_error());

    cr_expect_eq(hull.count, 4, "hull has %d vertices, expected the rectangle's 4", hull.count);
    const rb_vec2 corners[4] = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {0.0, 1.0}};
    for (int i = 0; i < 4; ++i) {
        cr_expect_eq(count_vertices_near(&hull, corners[i], 1.5e-4), 1, "corner (%g, %g) should appear once",
                     corners[i].x, corners[i].y);
    }
    expect_ccw_with_outward_normals(&hull);
    expect_near(rb_polygon_area(&hull), 2.0, 4e-4, "hull area");
}

Test(geometry, hull_rejects_degenerate_and_invalid_input)
{
    rb_polygon hull;
    /* Collinear: no area. */
    const rb_vec2 collinear[4] = {{0.0, 0.0}, {2.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}};
    expect_failure(rb_make_polygon_hull(collinear, 4, &hull), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon_hull");

    /* (1, 0) and (1, 2e-4) weld into one point, leaving two. */
    const rb_vec2 sliver[3] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 2e-4}};
    expect_failure(rb_make_polygon_hull(sliver, 3, &hull), RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon_hull");

    const rb_vec2 not_finite[3] = {{0.0, 0.0}, {1.0, NAN}, {0.0, 1.0}};
    expect_failure(rb_make_polygon_hull(not_finite, 3, &hull), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon_hull");
    expect_failure(rb_make_polygon_hull(NULL, 3, &hull), RB_ERR_INVALID_ARGUMENT, "rb_make_polygon_hull");
}

/* ---- Boxes ---- */

Test(geometry, make_box_rejects_bad_sizes)
{
    rb_polygon box;
    /* Zero size: a box without area. */
    expect_failure(rb_make_box(0.0, 1.0, &box), RB_ERR_DEGENERATE_SHAPE, "rb_make_box");
    expect_failure(rb_make_box(1.0, 0.0, &box), RB_ERR_DEGENERATE_SHAPE, "rb_make_box");
    /* Non-finite: not a number at all. */
    expect_failure(rb_make_box(NAN, 1.0, &box), RB_ERR_INVALID_ARGUMENT, "rb_make_box");
    expect_failure(rb_make_box(1.0, INFINITY, &box), RB_ERR_INVALID_ARGUMENT, "rb_make_box");
    expect_failure(rb_make_box(1.0, 1.0, NULL), RB_ERR_INVALID_ARGUMENT, "rb_make_box");
    expect_failure(rb_make_offset_box(1.0, 1.0, rb_v2(NAN, 0.0), 0.0, &box), RB_ERR_INVALID_ARGUMENT,
                   "rb_make_offset_box");
    expect_failure(rb_make_offset_box(1.0, 1.0, rb_v2(0.0, 0.0), INFINITY, &box), RB_ERR_INVALID_ARGUMENT,
                   "rb_make_offset_box");

    /* Negative size: rb/base.h files it under both "out of range"
     * (INVALID_ARGUMENT) and "zero size" (DEGENERATE_SHAPE) readings, so
     * either status is right; success is not. */
    const double negative[2][2] = {{-1.0, 1.0}, {1.0, -0.5}};
    for (int i = 0; i < 2; ++i) {
        rb_status status = rb_make_box(negative[i][0], negative[i][1], &box);
        cr_expect(status == RB_ERR_INVALID_ARGUMENT || status == RB_ERR_DEGENERATE_SHAPE,
                  "rb_make_box(%g, %g) returned %s, expected a failure", negative[i][0], negative[i][1],
                  rb_status_name(status));
        cr_expect(strstr(rb_last_error(), "rb_make_box") != NULL, "rb_last_error() should name rb_make_box, got \"%s\"",
                  rb_last_error());
    }
}

/* ---- Bounding boxes ---- */

Test(geometry, rotated_box_aabb)
{
    /* Half-extents (1, 0.5) turned by 30° and moved to (2, -1). The
     * bounding half-widths of a rectangle turned by θ are
     *   ex = hx |cos θ| + hy |sin θ| = √3/2 + 1/4,
     *   ey = hx |sin θ| + hy |cos θ| = 1/2 + √3/4. */
    rb_polygon box;
    cr_assert_eq(rb_make_box(1.0, 0.5, &box), RB_OK, "rb_make_box failed: %s", rb_last_error());
    rb_transform xf = {{2.0, -1.0}, rb_rot_from_angle(RB_PI / 6.0)};
    rb_aabb aabb = rb_polygon_aabb(&box, xf);

    double ex = sqrt(3.0) / 2.0 + 0.25;
    double ey = 0.5 + sqrt(3.0) / 4.0;
    expect_vec_near(aabb.lower, rb_v2(2.0 - ex, -1.0 - ey), TOLERANCE, "rotated box aabb lower");
    expect_vec_near(aabb.upper, rb_v2(2.0 + ex, -1.0 + ey), TOLERANCE, "rotated box aabb upper");
}

Test(geometry, offset_box_aabb_under_quarter_turn)
{
    /* A box of half-extents (1, 0.5) centred at (0.5, 0) in the body frame;
     * the body turned a quarter turn at (3, 0). The quarter turn maps the
     * centre to (0, 0.5) and swaps the extents, so the world box is centred
     * at (3, 0.5) with half-extents (0.5, 1): (2.5, -0.5) .. (3.5, 1.5). */
    rb_polygon box;
    cr_assert_eq(rb_make_offset_box(1.0, 0.5, rb_v2(0.5, 0.0), 0.0, &box), RB_OK, "rb_make_offset_box failed: %s",
                 rb_last_error());
    rb_transform xf = {{3.0, 0.0}, rb_rot_from_angle(RB_PI / 2.0)};
    rb_aabb aabb = rb_polygon_aabb(&box, xf);

    expect_vec_near(aabb.lower, rb_v2(2.5, -0.5), TOLERANCE, "offset box aabb lower");
    expect_vec_near(aabb.upper, rb_v2(3.5, 1.5), TOLERANCE, "offset box aabb upper");
}

Test(geometry, offset_circle_aabb)
{
    /* A circle of radius 0.2 centred at (0.3, 0) in the body frame; the body
     * turned a quarter turn at (1, 1). The centre goes to (1, 1.3), so the
     * box is (0.8, 1.1) .. (1.2, 1.5). */
    rb_circle circle = {.center = {0.3, 0.0}, .radius = 0.2};
    rb_transform xf = {{1.0, 1.0}, rb_rot_from_angle(RB_PI / 2.0)};
    rb_aabb aabb = rb_circle_aabb(&circle, xf);

    expect_vec_near(aabb.lower, rb_v2(0.8, 1.1), TOLERANCE, "circle aabb lower");
    expect_vec_near(aabb.upper, rb_v2(1.2, 1.5), TOLERANCE, "circle aabb upper");
}
