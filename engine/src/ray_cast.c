/* SPDX-License-Identifier: MIT */
/* Ray casts and point tests against single shapes: pure functions of
 * the shape, its transform and the ray.
 *
 * Every cast works in the shape's local frame (the ray is moved there,
 * the answer moved back), where the geometry is as stored. */
#include "rb/geometry.h"

static rb_ray_cast_output no_hit(void) { return (rb_ray_cast_output){0}; }

static rb_ray_cast_output make_hit(rb_transform xf, rb_vec2 origin, rb_vec2 translation, double fraction,
                                   rb_vec2 local_normal)
{
    return (rb_ray_cast_output){
        .hit = true,
        .fraction = fraction,
        .point = rb_mul_add(origin, fraction, translation),
        .normal = rb_rotate(xf.q, local_normal),
    };
}

/* The ray p(t) = s + t·d meets the circle |p - c| = r where
 *   (d·d) t² + 2 (s·d) t + (s·s - r²) = 0,  s = origin - centre.
 * The entry is the smaller root, t = (-(s·d) - √Δ)/(d·d) with
 * Δ = (s·d)² - (d·d)(s·s - r²). An origin inside (s·s < r²) never
 * enters. */
rb_ray_cast_output rb_ray_cast_circle(const rb_circle *circle, rb_transform xf, rb_vec2 origin, rb_vec2 translation)
{
    rb_vec2 center = rb_transform_point(xf, circle->center);
    rb_vec2 s = rb_sub(origin, center);
    double a = rb_dot(translation, translation);
    double b = rb_dot(s, translation);
    double c = rb_dot(s, s) - circle->radius * circle->radius;
    double discriminant = b * b - a * c;
    if (a <= 0.0 || c < 0.0 || discriminant < 0.0) {
        return no_hit();
    }
    double t = (-b - sqrt(discriminant)) / a;
    if (!(t >= 0.0 && t <= 1.0)) {
        return no_hit();
    }
    rb_vec2 point = rb_mul_add(origin, t, translation);
    return (rb_ray_cast_output){
        .hit = true,
        .fraction = t,
        .point = point,
        .normal = rb_normalize(rb_sub(point, center)),
    };
}

/* Cyrus-Beck clipping (Cyrus and Beck, "Generalized two- and
 * three-dimensional clipping", Computers & Graphics 3, 1978): the
 * polygon is the intersection of the half-planes n_i·(p - v_i) <= 0.
 * Along the ray each half-plane bounds t from below where the ray enters
 * it (n_i·d < 0) and from above where it leaves (n_i·d > 0); the ray
 * crosses the polygon over [lower, upper] when that interval is not
 * empty, and enters it through the edge that set `lower`. */
rb_ray_cast_output rb_ray_cast_polygon(const rb_polygon *polygon, rb_transform xf, rb_vec2 origin, rb_vec2 translation)
{
    rb_vec2 s = rb_inv_transform_point(xf, origin);
    rb_vec2 d = rb_inv_rotate(xf.q, translation);
    double lower = 0.0;
    double upper = 1.0;
    int entry_edge = -1;
    for (int i = 0; i < polygon->count; ++i) {
        /* n·(s + t d - v) <= 0  <=>  t (n·d) <= n·(v - s) */
        double numerator = rb_dot(polygon->normals[i], rb_sub(polygon->vertices[i], s));
        double denominator = rb_dot(polygon->normals[i], d);
        if (denominator == 0.0) {
            if (numerator < 0.0) {
                return no_hit(); /* parallel to the edge and outside it */
            }
        } else if (denominator < 0.0 && numerator < lower * denominator) {
            lower = numerator / denominator;
            entry_edge = i;
        } else if (denominator > 0.0 && numerator < upper * denominator) {
            upper = numerator / denominator;
        }
        if (upper < lower) {
            return no_hit();
        }
    }
    if (entry_edge < 0) {
        return no_hit(); /* the origin is inside: the ray never enters */
    }
    return make_hit(xf, origin, translation, lower, polygon->normals[entry_edge]);
}

/* The ray s + t·d meets the segment p1 + u·e where
 *   t = ((p1 - s) × e)/(d × e),  u = ((p1 - s) × d)/(d × e),
 * with both in [0, 1]; d × e = 0 means parallel (no single point).
 * Returns the fraction and the segment's left normal, or false. */
static bool cross_segment(const rb_segment *segment, rb_vec2 s, rb_vec2 d, double *fraction, rb_vec2 *left_normal)
{
    rb_vec2 e = rb_sub(segment->point2, segment->point1);
    double denominator = rb_cross(d, e);
    if (denominator == 0.0) {
        return false;
    }
    rb_vec2 w = rb_sub(segment->point1, s);
    double t = rb_cross(w, e) / denominator;
    double u = rb_cross(w, d) / denominator;
    if (!(t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0)) {
        return false;
    }
    *fraction = t;
    *left_normal = rb_normalize(rb_left_perp(e));
    return true;
}

rb_ray_cast_output rb_ray_cast_segment(const rb_segment *segment, rb_transform xf, rb_vec2 origin, rb_vec2 translation)
{
    rb_vec2 d = rb_inv_rotate(xf.q, translation);
    double fraction;
    rb_vec2 normal;
    if (!cross_segment(segment, rb_inv_transform_point(xf, origin), d, &fraction, &normal)) {
        return no_hit();
    }
    /* Either side: the normal faces where the ray comes from. */
    if (rb_dot(normal, d) > 0.0) {
        normal = rb_neg(normal);
    }
    return make_hit(xf, origin, translation, fraction, normal);
}

rb_ray_cast_output rb_ray_cast_chain_segment(const rb_chain_segment *segment, rb_transform xf, rb_vec2 origin,
                                             rb_vec2 translation)
{
    rb_vec2 d = rb_inv_rotate(xf.q, translation);
    double fraction;
    rb_vec2 normal;
    if (!cross_segment(&segment->segment, rb_inv_transform_point(xf, origin), d, &fraction, &normal) ||
        rb_dot(normal, d) >= 0.0) {
        return no_hit(); /* missed, or came from behind */
    }
    return make_hit(xf, origin, translation, fraction, normal);
}

bool rb_circle_contains(const rb_circle *circle, rb_transform xf, rb_vec2 point)
{
    rb_vec2 center = rb_transform_point(xf, circle->center);
    return rb_length_squared(rb_sub(point, center)) <= circle->radius * circle->radius;
}

bool rb_polygon_contains(const rb_polygon *polygon, rb_transform xf, rb_vec2 point)
{
    rb_vec2 p = rb_inv_transform_point(xf, point);
    for (int i = 0; i < polygon->count; ++i) {
        if (rb_dot(polygon->normals[i], rb_sub(p, polygon->vertices[i])) > 0.0) {
            return false;
        }
    }
    return true;
}
