/* SPDX-License-Identifier: MIT */
/* Shape geometry: polygon construction (convex hull, validation) and the
 * mass properties of circles and polygons. */
#include <float.h>

#include "error.h"
#include "rb/geometry.h"

/* ---- polygon construction ---------------------------------------------- */

/* Twice the signed area of triangle (a, b, c): positive when counter-clockwise. */
static double orientation(rb_vec2 a, rb_vec2 b, rb_vec2 c) { return rb_cross(rb_sub(b, a), rb_sub(c, a)); }

static int compare_points(rb_vec2 a, rb_vec2 b)
{
    if (a.x != b.x) {
        return a.x < b.x ? -1 : 1;
    }
    if (a.y != b.y) {
        return a.y < b.y ? -1 : 1;
    }
    return 0;
}

static rb_status check_points(const char *function, const rb_vec2 *points, int count)
{
    RB_TRY(rb_check_pointer(function, "points", points));
    if (count < 3 || count > RB_MAX_POLYGON_VERTICES) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: count is %d, expected 3 to %d points", function, count,
                               RB_MAX_POLYGON_VERTICES);
    }
    for (int i = 0; i < count; ++i) {
        if (!(fabs(points[i].x) <= RB_MAX_LENGTH && fabs(points[i].y) <= RB_MAX_LENGTH)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "%s: point %d is (%g, %g) m, expected coordinates in [%g, %g] m", function, i,
                                   points[i].x, points[i].y, -RB_MAX_LENGTH, RB_MAX_LENGTH);
        }
    }
    return RB_OK;
}

/* Drops every point within RB_POLYGON_WELD_DISTANCE of an earlier one;
 * returns how many remain in `welded`. */
static int weld_points(const rb_vec2 *points, int count, rb_vec2 *welded)
{
    const double weld_squared = RB_POLYGON_WELD_DISTANCE * RB_POLYGON_WELD_DISTANCE;
    int kept = 0;
    for (int i = 0; i < count; ++i) {
        bool duplicate = false;
        for (int j = 0; j < kept && !duplicate; ++j) {
            duplicate = rb_length_squared(rb_sub(points[i], welded[j])) < weld_squared;
        }
        if (!duplicate) {
            welded[kept++] = points[i];
        }
    }
    return kept;
}

/* Andrew's monotone chain (Andrew 1979): sort the points by x then y,
 * build the lower and the upper chain, keeping only left turns. Returns
 * the hull's vertex count; the hull is counter-clockwise, starting at the
 * lowest-x point, without collinear vertices. */
static int monotone_chain_hull(const rb_vec2 *points, int count, rb_vec2 *hull)
{
    rb_vec2 sorted[RB_MAX_POLYGON_VERTICES];
    for (int i = 0; i < count; ++i) {
        int j = i;
        while (j > 0 && compare_points(sorted[j - 1], points[i]) > 0) {
            sorted[j] = sorted[j - 1];
            --j;
        }
        sorted[j] = points[i];
    }
    rb_vec2 chain[2 * RB_MAX_POLYGON_VERTICES];
    int size = 0;
    for (int i = 0; i < count; ++i) {
        while (size >= 2 && orientation(chain[size - 2], chain[size - 1], sorted[i]) <= 0.0) {
            --size;
        }
        chain[size++] = sorted[i];
    }
    for (int i = count - 2, lower_size = size + 1; i >= 0; --i) {
        while (size >= lower_size && orientation(chain[size - 2], chain[size - 1], sorted[i]) <= 0.0) {
            --size;
        }
        chain[size++] = sorted[i];
    }
    int hull_count = size - 1; /* the last point repeats the first */
    for (int i = 0; i < hull_count; ++i) {
        hull[i] = chain[i];
    }
    return hull_count;
}

/* Removes vertices closer than the weld distance to the line through
 * their neighbours: exact orientation tests keep nearly collinear points
 * that would make sliver edges with ill-defined normals. */
static int remove_collinear(rb_vec2 *hull, int count)
{
    bool removed = true;
    while (removed && count >= 3) {
        removed = false;
        for (int i = 0; i < count; ++i) {
            rb_vec2 prev = hull[(i + count - 1) % count];
            rb_vec2 next = hull[(i + 1) % count];
            double base = rb_distance(prev, next);
            double height = base > 0.0 ? orientation(prev, hull[i], next) / base : 0.0;
            if (height < RB_POLYGON_WELD_DISTANCE) {
                for (int j = i; j + 1 < count; ++j) {
                    hull[j] = hull[j + 1];
                }
                --count;
                removed = true;
                break;
            }
        }
    }
    return count;
}

static void finish_polygon(const rb_vec2 *hull, int count, rb_polygon *out)
{
    out->count = count;
    for (int i = 0; i < count; ++i) {
        out->vertices[i] = hull[i];
    }
    for (int i = 0; i < count; ++i) {
        rb_vec2 edge = rb_sub(hull[(i + 1) % count], hull[i]);
        out->normals[i] = rb_normalize(rb_right_perp(edge));
    }
    out->centroid = rb_polygon_mass(out, 1.0).center;
}

/* Builds the hull; on failure reports for `function`. */
static rb_status build_hull(const char *function, const rb_vec2 *points, int count, rb_vec2 *hull, int *hull_count,
                            int *welded_count)
{
    RB_TRY(check_points(function, points, count));
    rb_vec2 welded[RB_MAX_POLYGON_VERTICES];
    *welded_count = weld_points(points, count, welded);
    if (*welded_count < 3) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE,
                               "%s: only %d distinct points (points closer than %g m are one), expected at least 3",
                               function, *welded_count, RB_POLYGON_WELD_DISTANCE);
    }
    *hull_count = remove_collinear(hull, monotone_chain_hull(welded, *welded_count, hull));
    if (*hull_count < 3) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE, "%s: the points are collinear and enclose no area", function);
    }
    return RB_OK;
}

rb_status rb_make_polygon_hull(const rb_vec2 *points, int count, rb_polygon *out)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_make_polygon_hull", "out", out));
    rb_vec2 hull[RB_MAX_POLYGON_VERTICES];
    int hull_count = 0;
    int welded_count = 0;
    RB_TRY(build_hull("rb_make_polygon_hull", points, count, hull, &hull_count, &welded_count));
    finish_polygon(hull, hull_count, out);
    return RB_OK;
}

rb_status rb_make_polygon(const rb_vec2 *points, int count, rb_polygon *out)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_make_polygon", "out", out));
    rb_vec2 hull[RB_MAX_POLYGON_VERTICES];
    int hull_count = 0;
    int welded_count = 0;
    RB_TRY(build_hull("rb_make_polygon", points, count, hull, &hull_count, &welded_count));
    if (welded_count < count) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE, "rb_make_polygon: %d of the %d points coincide with another",
                               count - welded_count, count);
    }
    if (hull_count < count) {
        for (int i = 0; i < count; ++i) {
            bool on_hull = false;
            for (int j = 0; j < hull_count && !on_hull; ++j) {
                on_hull = points[i].x == hull[j].x && points[i].y == hull[j].y;
            }
            if (!on_hull) {
                return rb_report_error(RB_ERR_NOT_CONVEX,
                                       "rb_make_polygon: point %d (%g, %g) lies inside the convex hull of the others "
                                       "or on one of its edges: the polygon is not strictly convex",
                                       i, points[i].x, points[i].y);
            }
        }
    }
    finish_polygon(hull, hull_count, out);
    return RB_OK;
}

static rb_status check_box(const char *function, double hx, double hy, rb_polygon *out)
{
    RB_TRY(rb_check_pointer(function, "out", out));
    RB_TRY(rb_check_bound(function, "hx", hx, RB_MAX_LENGTH, "m"));
    RB_TRY(rb_check_bound(function, "hy", hy, RB_MAX_LENGTH, "m"));
    if (hx < RB_POLYGON_WELD_DISTANCE || hy < RB_POLYGON_WELD_DISTANCE) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE,
                               "%s: hx and hy are (%g, %g) m, expected both >= %g m (smaller boxes have no "
                               "well-defined faces)",
                               function, hx, hy, RB_POLYGON_WELD_DISTANCE);
    }
    return RB_OK;
}

static void fill_box(double hx, double hy, rb_transform xf, rb_polygon *out)
{
    const rb_vec2 corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    const rb_vec2 normals[4] = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
    out->count = 4;
    for (int i = 0; i < 4; ++i) {
        out->vertices[i] = rb_transform_point(xf, corners[i]);
        out->normals[i] = rb_rotate(xf.q, normals[i]);
    }
    out->centroid = xf.p;
}

rb_status rb_make_offset_box(double hx, double hy, rb_vec2 center, double angle, rb_polygon *out)
{
    rb_clear_error();
    RB_TRY(check_box("rb_make_offset_box", hx, hy, out));
    RB_TRY(rb_check_point("rb_make_offset_box", "center", center));
    RB_TRY(rb_check_bound("rb_make_offset_box", "angle", angle, RB_MAX_ANGLE, "rad"));
    fill_box(hx, hy, (rb_transform){center, rb_rot_from_angle(angle)}, out);
    return RB_OK;
}

rb_status rb_make_box(double hx, double hy, rb_polygon *out)
{
    rb_clear_error();
    RB_TRY(check_box("rb_make_box", hx, hy, out));
    fill_box(hx, hy, rb_transform_identity(), out);
    return RB_OK;
}

/* ---- mass properties ----------------------------------------------------- */

double rb_circle_area(const rb_circle *circle) { return RB_PI * circle->radius * circle->radius; }

rb_mass_data rb_circle_mass(const rb_circle *circle, double density)
{
    double mass = density * rb_circle_area(circle);
    /* A uniform disc: I = m r² / 2 about its centre. */
    return (rb_mass_data){mass, circle->center, 0.5 * mass * circle->radius * circle->radius};
}

double rb_polygon_area(const rb_polygon *polygon) { return rb_polygon_mass(polygon, 1.0).mass; }

/* The polygon is a fan of triangles (o, v_i, v_i+1) from o = vertex 0,
 * which keeps the numbers small for a polygon far from the body origin.
 * For a triangle with edge vectors e1, e2 from o, with D = e1 × e2:
 *   area = D/2, centroid = o + (e1 + e2)/3,
 *   polar second moment about o = (D/12)·(e1·e1 + e1·e2 + e2·e2)
 * (integrate |r|² over the triangle; e.g. Eberly, "Polygonal mass
 * properties", 2002). Summing, then moving the moment from o to the
 * centroid with the parallel-axis theorem, gives the inertia about the
 * centre of mass. */
rb_mass_data rb_polygon_mass(const rb_polygon *polygon, double density)
{
    rb_vec2 origin = polygon->vertices[0];
    double area = 0.0;
    rb_vec2 first_moment = {0.0, 0.0};
    double second_moment = 0.0;
    for (int i = 1; i + 1 < polygon->count; ++i) {
        rb_vec2 e1 = rb_sub(polygon->vertices[i], origin);
        rb_vec2 e2 = rb_sub(polygon->vertices[i + 1], origin);
        double d = rb_cross(e1, e2);
        double triangle_area = 0.5 * d;
        area += triangle_area;
        first_moment = rb_mul_add(first_moment, triangle_area / 3.0, rb_add(e1, e2));
        second_moment += (d / 12.0) * (rb_dot(e1, e1) + rb_dot(e1, e2) + rb_dot(e2, e2));
    }
    rb_vec2 offset = rb_scale(1.0 / area, first_moment); /* centroid relative to origin */
    double mass = density * area;
    double inertia = density * second_moment - mass * rb_dot(offset, offset);
    return (rb_mass_data){mass, rb_add(origin, offset), inertia};
}

rb_status rb_area_density_from_volume(double volume_density, double depth, double *area_density)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_area_density_from_volume", "area_density", area_density));
    RB_TRY(rb_check_range("rb_area_density_from_volume", "volume_density", volume_density, DBL_MIN, DBL_MAX));
    RB_TRY(rb_check_range("rb_area_density_from_volume", "depth", depth, DBL_MIN, DBL_MAX));
    *area_density = volume_density * depth;
    return RB_OK;
}

/* ---- bounding boxes ------------------------------------------------------ */

/* The corner-wise least and greatest of two finite points. rb_vmin and
 * rb_vmax call the C library's fmin and fmax, which must treat NaN and
 * the sign of zero, and which the compiler cannot inline: the broad phase
 * computes every shape's box each step, and those calls were a third of
 * its cost. */
static rb_vec2 lower_corner(rb_vec2 a, rb_vec2 b) { return rb_v2(rb_min(a.x, b.x), rb_min(a.y, b.y)); }
static rb_vec2 upper_corner(rb_vec2 a, rb_vec2 b) { return rb_v2(rb_max(a.x, b.x), rb_max(a.y, b.y)); }

rb_aabb rb_circle_aabb(const rb_circle *circle, rb_transform xf)
{
    rb_vec2 c = rb_transform_point(xf, circle->center);
    rb_vec2 r = {circle->radius, circle->radius};
    return (rb_aabb){rb_sub(c, r), rb_add(c, r)};
}

rb_aabb rb_polygon_aabb(const rb_polygon *polygon, rb_transform xf)
{
    rb_vec2 lower = rb_transform_point(xf, polygon->vertices[0]);
    rb_vec2 upper = lower;
    for (int i = 1; i < polygon->count; ++i) {
        rb_vec2 v = rb_transform_point(xf, polygon->vertices[i]);
        lower = lower_corner(lower, v);
        upper = upper_corner(upper, v);
    }
    return (rb_aabb){lower, upper};
}

rb_aabb rb_segment_aabb(const rb_segment *segment, rb_transform xf)
{
    rb_vec2 p1 = rb_transform_point(xf, segment->point1);
    rb_vec2 p2 = rb_transform_point(xf, segment->point2);
    return (rb_aabb){lower_corner(p1, p2), upper_corner(p1, p2)};
}
