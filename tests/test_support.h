/* SPDX-License-Identifier: MIT */
/* Helpers shared by the test executables (each tests/test_*.c is its own
 * Criterion program; this header only holds static inline helpers).
 *
 * Failure messages carry a `what` string naming the quantity checked, so a
 * failure in a helper still says which check of which test failed.
 */
#ifndef TESTS_TEST_SUPPORT_H
#define TESTS_TEST_SUPPORT_H

#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"

/* Destroys `world` and checks that the engine then holds no memory. Each
 * Criterion test runs in its own process, so after the last world of a test
 * is destroyed rb_bytes_in_use() must be exactly 0. */
static inline void destroy_world_and_expect_no_leak(rb_world *world)
{
    rb_world_destroy(world);
    size_t bytes = rb_bytes_in_use();
    cr_expect_eq(bytes, 0, "rb_bytes_in_use() is %zu after destroying the world, expected 0", bytes);
}

/* |actual - expected| <= tolerance, and actual is a number. */
static inline void expect_near(double actual, double expected, double tolerance, const char *what)
{
    cr_expect(fabs(actual - expected) <= tolerance, "%s: got %.17g, expected %.17g (tolerance %g, error %g)", what,
              actual, expected, tolerance, fabs(actual - expected));
}

/* Both components within `tolerance`. */
static inline void expect_vec_near(rb_vec2 actual, rb_vec2 expected, double tolerance, const char *what)
{
    cr_expect(fabs(actual.x - expected.x) <= tolerance && fabs(actual.y - expected.y) <= tolerance,
              "%s: got (%.17g, %.17g), expected (%.17g, %.17g) (tolerance %g)", what, actual.x, actual.y, expected.x,
              expected.y, tolerance);
}

/* The step of the models and the benchmarks: 60 Hz. */
#define TEST_DT (1.0 / 60.0)

/* A world with the default solver settings and the given gravity; the test
 * stops if the engine refuses it. */
static inline rb_world *make_world(rb_vec2 gravity)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = gravity;
    rb_world *world = NULL;
    rb_status status = rb_world_create(&def, &world);
    cr_assert_eq(status, RB_OK, "rb_world_create: %s", rb_last_error());
    return world;
}

/* The length (s) of one substep of a step of dt in this world: the h of
 * semi-implicit Euler's closed forms, and the time over which a reported
 * contact or joint impulse acted. */
static inline double substep_of(const rb_world *world, double dt)
{
    return dt / rb_world_solver_settings(world).substeps;
}

/* How far semi-implicit Euler moves in one step of dt, split into
 * substeps of h, under a constant acceleration a and from rest: substep k
 * moves h·(k·h·a), which sums to ½·a·dt·(dt + h). */
static inline double step_displacement(double a, double dt, double h) { return 0.5 * a * dt * (dt + h); }

/* Replaces the world's number of substeps, keeping its other settings. */
static inline void set_substeps(rb_world *world, int substeps)
{
    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.substeps = substeps;
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
}

/* `steps` steps of `dt`; the test stops at the first error. */
static inline void step_world(rb_world *world, double dt, int steps)
{
    for (int i = 0; i < steps; ++i) {
        rb_status status = rb_world_step(world, dt);
        cr_assert_eq(status, RB_OK, "rb_world_step failed at step %d: %s", i, rb_last_error());
    }
}

/* A body of the given type at rest at `position`, turned by `angle`. */
static inline rb_body_id make_body(rb_world *world, rb_body_type type, rb_vec2 position, double angle)
{
    rb_body_def def = rb_default_body_def();
    def.type = type;
    def.position = position;
    def.angle = angle;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "rb_body_create: %s", rb_last_error());
    return body;
}

/* A circle of the default material but the given density on `body`. */
static inline rb_shape_id add_circle(rb_world *world, rb_body_id body, rb_vec2 center, double radius, double density)
{
    rb_shape_def def = rb_default_shape_def();
    def.density = density;
    const rb_circle circle = {.center = center, .radius = radius};
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_circle(world, body, &def, &circle, &shape), RB_OK, "rb_shape_create_circle: %s",
                 rb_last_error());
    return shape;
}

/* A box of half-extents hx × hy centred on the body origin, default
 * material but the given density, on `body`. */
static inline rb_shape_id add_box(rb_world *world, rb_body_id body, double hx, double hy, double density)
{
    rb_polygon box;
    cr_assert_eq(rb_make_box(hx, hy, &box), RB_OK, "rb_make_box: %s", rb_last_error());
    rb_shape_def def = rb_default_shape_def();
    def.density = density;
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_polygon(world, body, &def, &box, &shape), RB_OK, "rb_shape_create_polygon: %s",
                 rb_last_error());
    return shape;
}

/* A revolute joint with the default settings pinning `a` and `b` together
 * at the world point `anchor` in their current poses. */
static inline rb_joint_id make_pin(rb_world *world, rb_body_id a, rb_body_id b, rb_vec2 anchor)
{
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    cr_assert_eq(rb_revolute_joint_def_at(&def, world, a, b, anchor), RB_OK, "rb_revolute_joint_def_at: %s",
                 rb_last_error());
    rb_joint_id joint;
    cr_assert_eq(rb_revolute_joint_create(world, &def, &joint), RB_OK, "rb_revolute_joint_create: %s", rb_last_error());
    return joint;
}

#endif
