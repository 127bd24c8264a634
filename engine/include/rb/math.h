/* SPDX-License-Identifier: MIT */
/** @file
 * Vectors, rotations and rigid transforms in the plane.
 *
 * Conventions: the y axis points up; angles are in radians, counter-
 * clockwise positive; the 2D cross product of two vectors is the scalar
 * a.x*b.y - a.y*b.x (the z component of the 3D cross product). All
 * functions are pure and inline.
 */
#ifndef RB_MATH_H
#define RB_MATH_H

#include <math.h>
#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RB_PI 3.14159265358979323846

typedef struct rb_vec2 {
    double x, y;
} rb_vec2;

/** A rotation stored as its cosine and sine (c*c + s*s = 1). */
typedef struct rb_rot {
    double c, s;
} rb_rot;

/** A rigid transform: rotate by q, then translate by p. */
typedef struct rb_transform {
    rb_vec2 p;
    rb_rot q;
} rb_transform;

/** An axis-aligned box. */
typedef struct rb_aabb {
    rb_vec2 lower, upper;
} rb_aabb;

/** The vector (x, y). The other functions build their results with it, not
 * with compound literals, so that the header also compiles as C++. */
static inline rb_vec2 rb_v2(double x, double y)
{
    rb_vec2 v = {x, y};
    return v;
}
static inline rb_vec2 rb_add(rb_vec2 a, rb_vec2 b) { return rb_v2(a.x + b.x, a.y + b.y); }
static inline rb_vec2 rb_sub(rb_vec2 a, rb_vec2 b) { return rb_v2(a.x - b.x, a.y - b.y); }
static inline rb_vec2 rb_neg(rb_vec2 a) { return rb_v2(-a.x, -a.y); }
static inline rb_vec2 rb_scale(double s, rb_vec2 a) { return rb_v2(s * a.x, s * a.y); }
/** a + s*b */
static inline rb_vec2 rb_mul_add(rb_vec2 a, double s, rb_vec2 b) { return rb_v2(a.x + s * b.x, a.y + s * b.y); }
/** a - s*b */
static inline rb_vec2 rb_mul_sub(rb_vec2 a, double s, rb_vec2 b) { return rb_v2(a.x - s * b.x, a.y - s * b.y); }
static inline double rb_dot(rb_vec2 a, rb_vec2 b) { return a.x * b.x + a.y * b.y; }
static inline double rb_cross(rb_vec2 a, rb_vec2 b) { return a.x * b.y - a.y * b.x; }
/** s × a for a scalar s (an angular velocity) and a vector a: (-s*a.y, s*a.x). */
static inline rb_vec2 rb_cross_sv(double s, rb_vec2 a) { return rb_v2(-s * a.y, s * a.x); }
/** a × s: (s*a.y, -s*a.x). */
static inline rb_vec2 rb_cross_vs(rb_vec2 a, double s) { return rb_v2(s * a.y, -s * a.x); }
/** The vector turned a quarter turn counter-clockwise. */
static inline rb_vec2 rb_left_perp(rb_vec2 a) { return rb_v2(-a.y, a.x); }
/** The vector turned a quarter turn clockwise. */
static inline rb_vec2 rb_right_perp(rb_vec2 a) { return rb_v2(a.y, -a.x); }
static inline double rb_length_squared(rb_vec2 a) { return a.x * a.x + a.y * a.y; }
static inline double rb_length(rb_vec2 a) { return sqrt(a.x * a.x + a.y * a.y); }
static inline double rb_distance(rb_vec2 a, rb_vec2 b) { return rb_length(rb_sub(b, a)); }
static inline rb_vec2 rb_lerp(rb_vec2 a, rb_vec2 b, double t)
{
    return rb_v2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
}
/** The larger and the smaller of two numbers, for finite arguments (the
 * solvers' inner loops): one instruction each, where fmax and fmin are
 * library calls that also order NaNs. */
static inline double rb_max(double a, double b) { return a > b ? a : b; }
static inline double rb_min(double a, double b) { return a < b ? a : b; }
/** x limited to [lower, upper], lower <= upper. */
static inline double rb_clamp(double x, double lower, double upper) { return rb_min(rb_max(x, lower), upper); }
static inline rb_vec2 rb_vmin(rb_vec2 a, rb_vec2 b) { return rb_v2(fmin(a.x, b.x), fmin(a.y, b.y)); }
static inline rb_vec2 rb_vmax(rb_vec2 a, rb_vec2 b) { return rb_v2(fmax(a.x, b.x), fmax(a.y, b.y)); }

/** The unit vector along a, or (0, 0) when a is shorter than 1e-300. */
static inline rb_vec2 rb_normalize(rb_vec2 a)
{
    double length = rb_length(a);
    if (length < 1e-300) {
        return rb_v2(0.0, 0.0);
    }
    return rb_scale(1.0 / length, a);
}

static inline bool rb_is_finite(double x) { return isfinite(x); }
static inline bool rb_vec2_is_finite(rb_vec2 a) { return isfinite(a.x) && isfinite(a.y); }

static inline rb_rot rb_rot_identity(void)
{
    rb_rot q = {1.0, 0.0};
    return q;
}
static inline rb_rot rb_rot_from_angle(double angle)
{
    rb_rot q = {cos(angle), sin(angle)};
    return q;
}
/** The angle of q in (-pi, pi]. */
static inline double rb_rot_angle(rb_rot q) { return atan2(q.s, q.c); }
/** q applied to v. */
static inline rb_vec2 rb_rotate(rb_rot q, rb_vec2 v) { return rb_v2(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y); }
/** The inverse of q applied to v. */
static inline rb_vec2 rb_inv_rotate(rb_rot q, rb_vec2 v)
{
    return rb_v2(q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y);
}
/** q then r: the rotation r*q. */
static inline rb_rot rb_mul_rot(rb_rot r, rb_rot q)
{
    rb_rot rq = {r.c * q.c - r.s * q.s, r.s * q.c + r.c * q.s};
    return rq;
}
/** The rotation from q to r: inverse(q)*r. */
static inline rb_rot rb_inv_mul_rot(rb_rot q, rb_rot r)
{
    rb_rot qr = {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c};
    return qr;
}

static inline rb_transform rb_transform_identity(void)
{
    rb_transform t = {{0.0, 0.0}, {1.0, 0.0}};
    return t;
}
/** The world point of a point given in the transform's local frame. */
static inline rb_vec2 rb_transform_point(rb_transform t, rb_vec2 v) { return rb_add(rb_rotate(t.q, v), t.p); }
/** The local point of a world point. */
static inline rb_vec2 rb_inv_transform_point(rb_transform t, rb_vec2 v) { return rb_inv_rotate(t.q, rb_sub(v, t.p)); }
/** a then b expressed in a's frame: inverse(a)*b, the pose of b seen from a. */
static inline rb_transform rb_inv_mul_transforms(rb_transform a, rb_transform b)
{
    rb_transform t = {rb_inv_rotate(a.q, rb_sub(b.p, a.p)), rb_inv_mul_rot(a.q, b.q)};
    return t;
}
/** a*b: b's pose, given in a's frame, expressed in the world. */
static inline rb_transform rb_mul_transforms(rb_transform a, rb_transform b)
{
    rb_transform t = {rb_transform_point(a, b.p), rb_mul_rot(a.q, b.q)};
    return t;
}

static inline bool rb_aabb_overlaps(rb_aabb a, rb_aabb b)
{
    return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

#ifdef __cplusplus
}
#endif

#endif
