/* SPDX-License-Identifier: MIT */
/* Bad input to the world, body and shape API: every kind returns its status
 * with a message naming the function or the argument, changes nothing, and
 * leaves the world usable. (The geometry builders' own errors, rb_make_box
 * and rb_make_polygon, are tested in test_geometry.c.)
 *
 * "Usable" is checked with a probe: a dynamic circle far from everything
 * that, after the bad calls, must still fall exactly as semi-implicit Euler
 * says, v1 = v0 + g·dt and x1 = x0 + dt·v1. Those are two operations on
 * values of order 100, so 1e-12 of 100 is a wide tolerance; a NaN or a
 * stray force left behind by a failed call would be far outside it.
 */
#include <math.h>
#include <string.h>

#include "test_support.h"

/* The last call failed with `expected`, and rb_last_error() is a message
 * that names the function or the argument. */
static void expect_last_failure(rb_status expected, const char *function, const char *argument)
{
    cr_expect_eq(rb_last_status(), expected, "%s (%s): rb_last_status() is %s, expected %s", function, argument,
                 rb_status_name(rb_last_status()), rb_status_name(expected));
    const char *message = rb_last_error();
    cr_expect(message != NULL && message[0] != '\0' &&
                  (strstr(message, function) != NULL || strstr(message, argument) != NULL),
              "%s (%s): rb_last_error() should name the function or the argument, got \"%s\"", function, argument,
              message != NULL ? message : "(null)");
}

static void expect_failure(rb_status status, rb_status expected, const char *function, const char *argument)
{
    cr_expect_eq(status, expected, "%s (%s): returned %s, expected %s", function, argument, rb_status_name(status),
                 rb_status_name(expected));
    expect_last_failure(expected, function, argument);
}

typedef struct fixture {
    rb_world *world;
    rb_body_id probe;
} fixture;

#define PROBE_POSITION                                                                                                 \
    {                                                                                                                  \
        100.0, 100.0                                                                                                   \
    }

static fixture make_fixture(void)
{
    fixture f = {.world = make_world(rb_default_world_def().gravity)};
    f.probe = make_body(f.world, RB_BODY_DYNAMIC, (rb_vec2)PROBE_POSITION, 0.0);
    add_circle(f.world, f.probe, rb_v2(0.0, 0.0), 0.5, 1.0);
    return f;
}

/* The probe's pose and velocities are exactly what they were. */
typedef struct probe_state {
    rb_vec2 position, velocity, force;
    double angle, omega, torque;
} probe_state;

static probe_state probe_state_of(const fixture *f)
{
    return (probe_state){.position = rb_body_position(f->world, f->probe),
                         .velocity = rb_body_linear_velocity(f->world, f->probe),
                         .force = rb_body_force(f->world, f->probe),
                         .angle = rb_body_angle(f->world, f->probe),
                         .omega = rb_body_angular_velocity(f->world, f->probe),
                         .torque = rb_body_torque(f->world, f->probe)};
}

static void expect_probe_unchanged(const fixture *f, probe_state before, const char *call)
{
    const probe_state now = probe_state_of(f);
    cr_expect(now.position.x == before.position.x && now.position.y == before.position.y &&
                  now.velocity.x == before.velocity.x && now.velocity.y == before.velocity.y &&
                  now.force.x == before.force.x && now.force.y == before.force.y && now.angle == before.angle &&
                  now.omega == before.omega && now.torque == before.torque,
              "the failed %s changed the probe", call);
}

/* One step: the probe falls exactly, and the world holds only the bodies
 * it should. */
static void expect_usable(const fixture *f, int body_count)
{
    const rb_vec2 x0 = rb_body_position(f->world, f->probe);
    const rb_vec2 v0 = rb_body_linear_velocity(f->world, f->probe);
    const rb_vec2 g = rb_world_gravity(f->world);
    step_world(f->world, TEST_DT, 1);
    const double h = substep_of(f->world, TEST_DT);
    const rb_vec2 v1 = rb_mul_add(v0, TEST_DT, g);
    const rb_vec2 x1 = rb_add(rb_mul_add(x0, TEST_DT, v0),
                              rb_v2(step_displacement(g.x, TEST_DT, h), step_displacement(g.y, TEST_DT, h)));
    expect_vec_near(rb_body_linear_velocity(f->world, f->probe), v1, 1e-12 * 100.0, "probe velocity after a step");
    expect_vec_near(rb_body_position(f->world, f->probe), x1, 1e-12 * 100.0, "probe position after a step");
    cr_expect_eq(rb_world_statistics(f->world).body_count, body_count, "the world has %d bodies, expected %d",
                 rb_world_statistics(f->world).body_count, body_count);
}

/* ---- World ----------------------------------------------------------------- */

static void expect_world_create_fails(const rb_world_def *def, const char *argument)
{
    /* Any non-NULL value: world.h says a failure sets *out to NULL. */
    rb_world *world = (rb_world *)&world;
    expect_failure(rb_world_create(def, &world), RB_ERR_INVALID_ARGUMENT, "rb_world_create", argument);
    cr_expect_null(world, "rb_world_create (%s): *out is not NULL after a failure", argument);
}

Test(api_errors, world_create_rejects_bad_definitions)
{
    const rb_world_def good = rb_default_world_def();
    rb_world_def def = good;
    def.gravity.x = NAN;
    expect_world_create_fails(&def, "gravity");
    def = good;
    def.gravity.y = -INFINITY;
    expect_world_create_fails(&def, "gravity");
    def = good;
    def.solver.velocity_iterations = 0;
    expect_world_create_fails(&def, "velocity_iterations");
    def = good;
    def.solver.linear_slop = -0.001;
    expect_world_create_fails(&def, "linear_slop");
    def = good;
    def.solver.baumgarte = NAN;
    expect_world_create_fails(&def, "baumgarte");
    expect_world_create_fails(NULL, "def");
    expect_failure(rb_world_create(&good, NULL), RB_ERR_INVALID_ARGUMENT, "rb_world_create", "out");
    cr_expect_eq(rb_bytes_in_use(), 0, "failed world creations hold %zu bytes", rb_bytes_in_use());

    fixture f = make_fixture();
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, step_rejects_bad_dt)
{
    fixture f = make_fixture();
    const probe_state before = probe_state_of(&f);
    /* world.h: dt is finite, > 0 and <= 10. */
    const double bad[] = {NAN, INFINITY, -INFINITY, 0.0, -0.0, -TEST_DT, 10.5};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        expect_failure(rb_world_step(f.world, bad[i]), RB_ERR_INVALID_ARGUMENT, "rb_world_step", "dt");
        expect_probe_unchanged(&f, before, "rb_world_step");
    }
    expect_failure(rb_world_step(NULL, TEST_DT), RB_ERR_INVALID_ARGUMENT, "rb_world_step", "world");
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, gravity_must_be_finite)
{
    fixture f = make_fixture();
    const rb_vec2 gravity = rb_world_gravity(f.world);
    expect_failure(rb_world_set_gravity(f.world, rb_v2(NAN, 0.0)), RB_ERR_INVALID_ARGUMENT, "rb_world_set_gravity",
                   "gravity");
    expect_failure(rb_world_set_gravity(f.world, rb_v2(0.0, INFINITY)), RB_ERR_INVALID_ARGUMENT, "rb_world_set_gravity",
                   "gravity");
    expect_failure(rb_world_set_gravity(NULL, rb_v2(0.0, -1.0)), RB_ERR_INVALID_ARGUMENT, "rb_world_set_gravity",
                   "world");
    const rb_vec2 now = rb_world_gravity(f.world);
    cr_expect(now.x == gravity.x && now.y == gravity.y, "a failed rb_world_set_gravity changed the gravity");
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

static bool settings_equal(rb_solver_settings a, rb_solver_settings b)
{
    return a.velocity_iterations == b.velocity_iterations && a.position_iterations == b.position_iterations &&
           a.substeps == b.substeps && a.warm_starting == b.warm_starting && a.block_solver == b.block_solver &&
           a.type == b.type && a.baumgarte == b.baumgarte && a.linear_slop == b.linear_slop &&
           a.max_linear_correction == b.max_linear_correction && a.restitution_threshold == b.restitution_threshold;
}

static void expect_settings_rejected(const fixture *f, rb_solver_settings settings, const char *field)
{
    const rb_solver_settings before = rb_world_solver_settings(f->world);
    expect_failure(rb_world_set_solver_settings(f->world, &settings), RB_ERR_INVALID_ARGUMENT,
                   "rb_world_set_solver_settings", field);
    cr_expect(settings_equal(before, rb_world_solver_settings(f->world)), "a rejected %s changed the world's settings",
              field);
}

Test(api_errors, solver_settings_out_of_range)
{
    fixture f = make_fixture();
    const rb_solver_settings good = rb_default_solver_settings();
    rb_solver_settings s = good;
    s.velocity_iterations = 0;
    expect_settings_rejected(&f, s, "velocity_iterations");
    s = good;
    s.velocity_iterations = 1001;
    expect_settings_rejected(&f, s, "velocity_iterations");
    s = good;
    s.position_iterations = -1;
    expect_settings_rejected(&f, s, "position_iterations");
    s = good;
    s.substeps = 0;
    expect_settings_rejected(&f, s, "substeps");
    s = good;
    s.type = (rb_solver_type)7;
    expect_settings_rejected(&f, s, "type");
    const double bad_baumgarte[] = {NAN, -0.1, 1.5};
    for (int i = 0; i < 3; ++i) {
        s = good;
        s.baumgarte = bad_baumgarte[i];
        expect_settings_rejected(&f, s, "baumgarte");
    }
    const double bad_slop[] = {NAN, -0.001, 0.2};
    for (int i = 0; i < 3; ++i) {
        s = good;
        s.linear_slop = bad_slop[i];
        expect_settings_rejected(&f, s, "linear_slop");
    }
    s = good;
    s.max_linear_correction = 0.0;
    expect_settings_rejected(&f, s, "max_linear_correction");
    s = good;
    s.max_linear_correction = INFINITY;
    expect_settings_rejected(&f, s, "max_linear_correction");
    s = good;
    s.restitution_threshold = -1.0;
    expect_settings_rejected(&f, s, "restitution_threshold");
    s = good;
    s.restitution_threshold = NAN;
    expect_settings_rejected(&f, s, "restitution_threshold");
    expect_failure(rb_world_set_solver_settings(f.world, NULL), RB_ERR_INVALID_ARGUMENT, "rb_world_set_solver_settings",
                   "settings");
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

/* ---- Bodies ---------------------------------------------------------------- */

static void expect_body_def_rejected(const fixture *f, rb_body_def def, const char *field)
{
    rb_body_id body;
    expect_failure(rb_body_create(f->world, &def, &body), RB_ERR_INVALID_ARGUMENT, "rb_body_create", field);
}

Test(api_errors, body_create_rejects_bad_definitions)
{
    fixture f = make_fixture();
    rb_body_def good = rb_default_body_def();
    good.type = RB_BODY_DYNAMIC;
    good.position = rb_v2(-100.0, 0.0);
    rb_body_def d = good;
    d.position.x = NAN;
    expect_body_def_rejected(&f, d, "position");
    d = good;
    d.position.y = INFINITY;
    expect_body_def_rejected(&f, d, "position");
    d = good;
    d.angle = NAN;
    expect_body_def_rejected(&f, d, "angle");
    d = good;
    d.angle = -INFINITY;
    expect_body_def_rejected(&f, d, "angle");
    d = good;
    d.linear_velocity.x = NAN;
    expect_body_def_rejected(&f, d, "linear_velocity");
    d = good;
    d.linear_velocity.y = -INFINITY;
    expect_body_def_rejected(&f, d, "linear_velocity");
    d = good;
    d.angular_velocity = NAN;
    expect_body_def_rejected(&f, d, "angular_velocity");
    const double bad_damping[] = {-1.0, NAN, INFINITY};
    for (int i = 0; i < 3; ++i) {
        d = good;
        d.linear_damping = bad_damping[i];
        expect_body_def_rejected(&f, d, "linear_damping");
        d = good;
        d.angular_damping = bad_damping[i];
        expect_body_def_rejected(&f, d, "angular_damping");
    }
    d = good;
    d.gravity_scale = NAN;
    expect_body_def_rejected(&f, d, "gravity_scale");
    d = good;
    d.gravity_scale = INFINITY;
    expect_body_def_rejected(&f, d, "gravity_scale");
    d = good;
    d.type = (rb_body_type)7;
    expect_body_def_rejected(&f, d, "type");

    rb_body_id body;
    expect_failure(rb_body_create(f.world, NULL, &body), RB_ERR_INVALID_ARGUMENT, "rb_body_create", "def");
    expect_failure(rb_body_create(f.world, &good, NULL), RB_ERR_INVALID_ARGUMENT, "rb_body_create", "out");
    expect_failure(rb_body_create(NULL, &good, &body), RB_ERR_INVALID_ARGUMENT, "rb_body_create", "world");
    /* None of the failed calls left a body behind: only the probe. */
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, body_setters_reject_bad_values)
{
    fixture f = make_fixture();
    const rb_world *w = f.world;
    const rb_body_id p = f.probe;
    const probe_state before = probe_state_of(&f);
    const rb_vec2 nan2 = rb_v2(NAN, 0.0), inf2 = rb_v2(0.0, INFINITY), at = (rb_vec2)PROBE_POSITION;

    expect_failure(rb_body_set_transform(f.world, p, nan2, 0.0), RB_ERR_INVALID_ARGUMENT, "rb_body_set_transform",
                   "position");
    expect_failure(rb_body_set_transform(f.world, p, at, INFINITY), RB_ERR_INVALID_ARGUMENT, "rb_body_set_transform",
                   "angle");
    expect_failure(rb_body_set_linear_velocity(f.world, p, nan2), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_set_linear_velocity", "velocity");
    expect_failure(rb_body_set_angular_velocity(f.world, p, INFINITY), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_set_angular_velocity", "omega");
    expect_failure(rb_body_apply_force(f.world, p, nan2, at), RB_ERR_INVALID_ARGUMENT, "rb_body_apply_force", "force");
    expect_failure(rb_body_apply_force(f.world, p, rb_v2(1.0, 0.0), inf2), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_force", "point");
    expect_failure(rb_body_apply_force_to_center(f.world, p, inf2), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_force_to_center", "force");
    expect_failure(rb_body_apply_torque(f.world, p, NAN), RB_ERR_INVALID_ARGUMENT, "rb_body_apply_torque", "torque");
    expect_failure(rb_body_apply_linear_impulse(f.world, p, nan2, at), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_linear_impulse", "impulse");
    expect_failure(rb_body_apply_linear_impulse(f.world, p, rb_v2(1.0, 0.0), nan2), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_linear_impulse", "point");
    expect_failure(rb_body_apply_linear_impulse_to_center(f.world, p, inf2), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_linear_impulse_to_center", "impulse");
    expect_failure(rb_body_apply_angular_impulse(f.world, p, NAN), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_angular_impulse", "impulse");
    expect_probe_unchanged(&f, before, "body setters");

    expect_failure(rb_body_set_linear_damping(f.world, p, -1.0), RB_ERR_INVALID_ARGUMENT, "rb_body_set_linear_damping",
                   "damping");
    expect_failure(rb_body_set_linear_damping(f.world, p, NAN), RB_ERR_INVALID_ARGUMENT, "rb_body_set_linear_damping",
                   "damping");
    expect_failure(rb_body_set_angular_damping(f.world, p, -0.5), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_set_angular_damping", "damping");
    expect_failure(rb_body_set_gravity_scale(f.world, p, NAN), RB_ERR_INVALID_ARGUMENT, "rb_body_set_gravity_scale",
                   "scale");
    expect_failure(rb_body_set_type(f.world, p, (rb_body_type)9), RB_ERR_INVALID_ARGUMENT, "rb_body_set_type", "type");
    cr_expect(rb_body_linear_damping(w, p) == 0.0 && rb_body_angular_damping(w, p) == 0.0,
              "a rejected damping was stored");
    cr_expect_eq(rb_body_gravity_scale(w, p), 1.0, "a rejected gravity scale was stored");
    cr_expect_eq(rb_body_type_of(w, p), RB_BODY_DYNAMIC, "a rejected type was stored");
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

/* ---- Shapes ---------------------------------------------------------------- */

Test(api_errors, shape_creation_rejects_bad_geometry)
{
    fixture f = make_fixture();
    const rb_body_id body = make_body(f.world, RB_BODY_DYNAMIC, rb_v2(-100.0, 0.0), 0.0);
    const rb_shape_def def = rb_default_shape_def();
    rb_shape_id shape;

    const rb_circle zero = {.center = {0.0, 0.0}, .radius = 0.0};
    expect_failure(rb_shape_create_circle(f.world, body, &def, &zero, &shape), RB_ERR_DEGENERATE_SHAPE,
                   "rb_shape_create_circle", "radius");
    const rb_circle nan_radius = {.center = {0.0, 0.0}, .radius = NAN};
    expect_failure(rb_shape_create_circle(f.world, body, &def, &nan_radius, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "radius");
    const rb_circle far = {.center = {INFINITY, 0.0}, .radius = 1.0};
    expect_failure(rb_shape_create_circle(f.world, body, &def, &far, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "center");

    /* Polygons filled by hand rather than by rb_make_polygon. */
    rb_polygon square;
    cr_assert_eq(rb_make_box(0.5, 0.5, &square), RB_OK, "%s", rb_last_error());
    rb_polygon p = square;
    p.count = 2;
    expect_failure(rb_shape_create_polygon(f.world, body, &def, &p, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_polygon", "count");
    p.count = RB_MAX_POLYGON_VERTICES + 1;
    expect_failure(rb_shape_create_polygon(f.world, body, &def, &p, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_polygon", "count");
    p = square;
    p.vertices[2].x = NAN;
    expect_failure(rb_shape_create_polygon(f.world, body, &def, &p, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_polygon", "vertices");
    /* A dart: the fourth vertex, (0, -0.2), lies inside the triangle of
     * the other three, a reflex corner. */
    p = square;
    p.vertices[3] = rb_v2(0.0, -0.2);
    expect_failure(rb_shape_create_polygon(f.world, body, &def, &p, &shape), RB_ERR_NOT_CONVEX,
                   "rb_shape_create_polygon", "polygon");
    /* Three points on one line: no area. */
    p.count = 3;
    p.vertices[0] = rb_v2(0.0, 0.0);
    p.vertices[1] = rb_v2(1.0, 1.0);
    p.vertices[2] = rb_v2(2.0, 2.0);
    expect_failure(rb_shape_create_polygon(f.world, body, &def, &p, &shape), RB_ERR_DEGENERATE_SHAPE,
                   "rb_shape_create_polygon", "polygon");

    expect_failure(rb_shape_create_circle(f.world, body, NULL, &far, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "def");
    expect_failure(rb_shape_create_circle(f.world, body, &def, NULL, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "circle");
    expect_failure(rb_shape_create_polygon(f.world, body, &def, NULL, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_polygon", "polygon");
    cr_expect_eq(rb_body_shape_count(f.world, body), 0, "failed creations attached %d shapes",
                 rb_body_shape_count(f.world, body));
    expect_usable(&f, 2);
    cr_expect_eq(rb_world_statistics(f.world).shape_count, 1, "only the probe's shape exists");
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, shape_material_out_of_range)
{
    fixture f = make_fixture();
    const rb_body_id body = make_body(f.world, RB_BODY_STATIC, rb_v2(-100.0, 0.0), 0.0);
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.5};
    const rb_shape_def good = rb_default_shape_def();
    rb_shape_id shape;
    const double bad_friction[] = {-0.1, NAN, INFINITY};
    const double bad_restitution[] = {-0.1, 1.5, NAN};
    for (int i = 0; i < 3; ++i) {
        rb_shape_def d = good;
        d.friction = bad_friction[i];
        expect_failure(rb_shape_create_circle(f.world, body, &d, &circle, &shape), RB_ERR_INVALID_ARGUMENT,
                       "rb_shape_create_circle", "friction");
        d = good;
        d.restitution = bad_restitution[i];
        expect_failure(rb_shape_create_circle(f.world, body, &d, &circle, &shape), RB_ERR_INVALID_ARGUMENT,
                       "rb_shape_create_circle", "restitution");
    }
    /* A negative or non-finite density is out of range on any body. */
    rb_shape_def d = good;
    d.density = -1.0;
    expect_failure(rb_shape_create_circle(f.world, body, &d, &circle, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "density");
    d.density = NAN;
    expect_failure(rb_shape_create_circle(f.world, body, &d, &circle, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "density");
    cr_expect_eq(rb_body_shape_count(f.world, body), 0, "failed creations attached shapes");

    /* The setters check the same ranges and keep the old value. */
    cr_assert_eq(rb_shape_create_circle(f.world, body, &good, &circle, &shape), RB_OK, "%s", rb_last_error());
    expect_failure(rb_shape_set_friction(f.world, shape, -1.0), RB_ERR_INVALID_ARGUMENT, "rb_shape_set_friction",
                   "friction");
    expect_failure(rb_shape_set_restitution(f.world, shape, 2.0), RB_ERR_INVALID_ARGUMENT, "rb_shape_set_restitution",
                   "restitution");
    expect_failure(rb_shape_set_density(f.world, shape, NAN), RB_ERR_INVALID_ARGUMENT, "rb_shape_set_density",
                   "density");
    cr_expect(rb_shape_friction(f.world, shape) == good.friction &&
                  rb_shape_restitution(f.world, shape) == good.restitution &&
                  rb_shape_density(f.world, shape) == good.density,
              "a rejected material value was stored");
    expect_usable(&f, 2);
    destroy_world_and_expect_no_leak(f.world);
}

/* shape.h: density must be > 0 on a dynamic body without a mass override;
 * base.h: RB_ERR_NO_MASS when a dynamic body would get zero mass. A
 * negative density is out of range anywhere: RB_ERR_INVALID_ARGUMENT. */
Test(api_errors, zero_density_on_a_dynamic_body_has_no_mass)
{
    fixture f = make_fixture();
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.5};
    rb_shape_def def = rb_default_shape_def();
    rb_shape_id shape;

    const rb_body_id body = make_body(f.world, RB_BODY_DYNAMIC, rb_v2(-100.0, 0.0), 0.0);
    def.density = 0.0;
    expect_failure(rb_shape_create_circle(f.world, body, &def, &circle, &shape), RB_ERR_NO_MASS,
                   "rb_shape_create_circle", "density");
    def.density = -2.0;
    expect_failure(rb_shape_create_circle(f.world, body, &def, &circle, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "density");
    cr_expect_eq(rb_body_shape_count(f.world, body), 0, "failed creations attached shapes");
    cr_expect_eq(rb_body_mass(f.world, body), 1.0, "the shapeless body keeps its 1 kg");

    /* With a positive density, setting it to zero would leave no mass. */
    def.density = 1.0;
    cr_assert_eq(rb_shape_create_circle(f.world, body, &def, &circle, &shape), RB_OK, "%s", rb_last_error());
    const double mass = rb_body_mass(f.world, body);
    expect_failure(rb_shape_set_density(f.world, shape, 0.0), RB_ERR_NO_MASS, "rb_shape_set_density", "density");
    cr_expect_eq(rb_shape_density(f.world, shape), 1.0, "the rejected density was stored");
    cr_expect_eq(rb_body_mass(f.world, body), mass, "the rejected density changed the mass");

    /* Zero density is fine on a static body and under a mass override. */
    const rb_body_id ground = make_body(f.world, RB_BODY_STATIC, rb_v2(-100.0, -10.0), 0.0);
    def.density = 0.0;
    cr_expect_eq(rb_shape_create_circle(f.world, ground, &def, &circle, &shape), RB_OK, "static body: %s",
                 rb_last_error());
    const rb_body_id weighed = make_body(f.world, RB_BODY_DYNAMIC, rb_v2(-100.0, 10.0), 0.0);
    const rb_mass_data override = {.mass = 2.0, .center = {0.0, 0.0}, .rotational_inertia = 0.5};
    cr_assert_eq(rb_body_set_mass_data(f.world, weighed, &override), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_shape_create_circle(f.world, weighed, &def, &circle, &shape), RB_OK, "overridden body: %s",
                 rb_last_error());
    cr_expect_eq(rb_body_mass(f.world, weighed), 2.0, "the override holds");
    expect_usable(&f, 4);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, mass_data_out_of_range)
{
    fixture f = make_fixture();
    const rb_mass_data before = rb_body_mass_data(f.world, f.probe);
    /* body.h asks mass > 0; a zero or negative one is out of range
     * (RB_ERR_INVALID_ARGUMENT) or no mass (RB_ERR_NO_MASS): base.h allows
     * either reading, so either is accepted. */
    const double no_mass[] = {0.0, -1.0};
    for (int i = 0; i < 2; ++i) {
        const rb_mass_data m = {.mass = no_mass[i], .rotational_inertia = 1.0};
        const rb_status status = rb_body_set_mass_data(f.world, f.probe, &m);
        cr_expect(status == RB_ERR_INVALID_ARGUMENT || status == RB_ERR_NO_MASS,
                  "rb_body_set_mass_data with mass %g returned %s", no_mass[i], rb_status_name(status));
        expect_last_failure(status, "rb_body_set_mass_data", "mass");
    }
    const rb_mass_data bad[] = {
        {.mass = NAN, .rotational_inertia = 1.0},
        {.mass = INFINITY, .rotational_inertia = 1.0},
        {.mass = 1.0, .rotational_inertia = -1.0},
        {.mass = 1.0, .rotational_inertia = NAN},
        {.mass = 1.0, .center = {NAN, 0.0}, .rotational_inertia = 1.0},
    };
    const char *field[] = {"mass", "mass", "inertia", "inertia", "center"};
    for (int i = 0; i < 5; ++i) {
        expect_failure(rb_body_set_mass_data(f.world, f.probe, &bad[i]), RB_ERR_INVALID_ARGUMENT,
                       "rb_body_set_mass_data", field[i]);
    }
    expect_failure(rb_body_set_mass_data(f.world, f.probe, NULL), RB_ERR_INVALID_ARGUMENT, "rb_body_set_mass_data",
                   "mass_data");
    const rb_mass_data after = rb_body_mass_data(f.world, f.probe);
    cr_expect(after.mass == before.mass && after.rotational_inertia == before.rotational_inertia &&
                  after.center.x == before.center.x && after.center.y == before.center.y,
              "a rejected mass override was stored");
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

/* ---- Stale and foreign ids ------------------------------------------------- */

Test(api_errors, destroyed_body_ids_are_stale)
{
    fixture f = make_fixture();
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = rb_v2(-100.0, 3.0);
    def.linear_velocity = rb_v2(1.0, 2.0);
    def.angle = 0.5;
    rb_body_id body;
    cr_assert_eq(rb_body_create(f.world, &def, &body), RB_OK, "%s", rb_last_error());
    const rb_shape_id shape = add_circle(f.world, body, rb_v2(0.0, 0.0), 0.5, 1.0);
    cr_assert_eq(rb_body_destroy(f.world, body), RB_OK, "%s", rb_last_error());

    cr_expect_not(rb_body_is_valid(f.world, body), "a destroyed body is still valid");
    /* Getters return zeros and say why. */
    const rb_vec2 x = rb_body_position(f.world, body);
    cr_expect(x.x == 0.0 && x.y == 0.0, "position of a destroyed body: (%g, %g)", x.x, x.y);
    expect_last_failure(RB_ERR_STALE_ID, "rb_body_position", "body");
    const rb_vec2 v = rb_body_linear_velocity(f.world, body);
    cr_expect(v.x == 0.0 && v.y == 0.0, "velocity of a destroyed body: (%g, %g)", v.x, v.y);
    expect_last_failure(RB_ERR_STALE_ID, "rb_body_linear_velocity", "body");
    cr_expect_eq(rb_body_angle(f.world, body), 0.0, "angle of a destroyed body");
    expect_last_failure(RB_ERR_STALE_ID, "rb_body_angle", "body");
    cr_expect_eq(rb_body_mass(f.world, body), 0.0, "mass of a destroyed body");
    expect_last_failure(RB_ERR_STALE_ID, "rb_body_mass", "body");
    /* Setters and destroy fail. */
    expect_failure(rb_body_set_linear_velocity(f.world, body, rb_v2(1.0, 0.0)), RB_ERR_STALE_ID,
                   "rb_body_set_linear_velocity", "body");
    expect_failure(rb_body_enable_sleep(f.world, body, false), RB_ERR_STALE_ID, "rb_body_enable_sleep", "body");
    cr_expect_not(rb_body_is_sleep_enabled(f.world, body), "sleep flag of a destroyed body");
    expect_failure(rb_body_apply_force_to_center(f.world, body, rb_v2(1.0, 0.0)), RB_ERR_STALE_ID,
                   "rb_body_apply_force_to_center", "body");
    expect_failure(rb_body_destroy(f.world, body), RB_ERR_STALE_ID, "rb_body_destroy", "body");
    rb_shape_id other;
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.5};
    const rb_shape_def shape_def = rb_default_shape_def();
    expect_failure(rb_shape_create_circle(f.world, body, &shape_def, &circle, &other), RB_ERR_STALE_ID,
                   "rb_shape_create_circle", "body");
    /* Its shape went with it. */
    cr_expect_not(rb_shape_is_valid(f.world, shape), "the destroyed body's shape is still valid");
    cr_expect_eq(rb_shape_friction(f.world, shape), 0.0, "friction of a destroyed shape");
    expect_last_failure(RB_ERR_STALE_ID, "rb_shape_friction", "shape");
    expect_failure(rb_shape_destroy(f.world, shape), RB_ERR_STALE_ID, "rb_shape_destroy", "shape");
    expect_usable(&f, 1);
    cr_expect_eq(rb_world_statistics(f.world).shape_count, 1, "only the probe's shape is left");
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, destroyed_shape_ids_are_stale)
{
    fixture f = make_fixture();
    const rb_body_id body = make_body(f.world, RB_BODY_DYNAMIC, rb_v2(-100.0, 0.0), 0.0);
    const rb_shape_id doomed = add_circle(f.world, body, rb_v2(0.0, 0.0), 0.5, 1.0);
    add_circle(f.world, body, rb_v2(0.0, 0.0), 0.25, 2.0);
    cr_assert_eq(rb_shape_destroy(f.world, doomed), RB_OK, "%s", rb_last_error());

    cr_expect_not(rb_shape_is_valid(f.world, doomed), "a destroyed shape is still valid");
    cr_expect_eq(rb_shape_density(f.world, doomed), 0.0, "density of a destroyed shape");
    expect_last_failure(RB_ERR_STALE_ID, "rb_shape_density", "shape");
    cr_expect(rb_body_id_is_null(rb_shape_body(f.world, doomed)), "the body of a destroyed shape is not the null id");
    expect_last_failure(RB_ERR_STALE_ID, "rb_shape_body", "shape");
    expect_failure(rb_shape_set_friction(f.world, doomed, 0.5), RB_ERR_STALE_ID, "rb_shape_set_friction", "shape");
    expect_failure(rb_shape_destroy(f.world, doomed), RB_ERR_STALE_ID, "rb_shape_destroy", "shape");
    /* The body keeps the other shape, and its mass: 2·π·0.25². */
    cr_expect_eq(rb_body_shape_count(f.world, body), 1, "the body should have one shape left");
    const double mass = 2.0 * RB_PI * 0.25 * 0.25;
    expect_near(rb_body_mass(f.world, body), mass, 1e-12 * mass, "mass of the remaining shape");
    expect_usable(&f, 2);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, reused_slot_does_not_alias_the_old_id)
{
    fixture f = make_fixture();
    const rb_body_id old = make_body(f.world, RB_BODY_DYNAMIC, rb_v2(-100.0, 0.0), 0.0);
    const rb_shape_id old_shape = add_circle(f.world, old, rb_v2(0.0, 0.0), 0.5, 1.0);
    cr_assert_eq(rb_body_destroy(f.world, old), RB_OK, "%s", rb_last_error());
    const rb_body_id fresh = make_body(f.world, RB_BODY_DYNAMIC, rb_v2(-50.0, 0.0), 0.0);
    const rb_shape_id fresh_shape = add_circle(f.world, fresh, rb_v2(0.0, 0.0), 0.5, 1.0);
    /* id.h: a freed slot is reused with a new generation. This test is
     * about that case, so it insists the slots were reused. */
    cr_assert_eq(fresh.index, old.index, "the freed body slot was not reused");
    cr_assert_eq(fresh_shape.index, old_shape.index, "the freed shape slot was not reused");
    cr_expect_neq(fresh.generation, old.generation, "the reused slot kept its generation");

    cr_expect_not(rb_body_is_valid(f.world, old), "the old id is valid again");
    cr_expect(rb_body_is_valid(f.world, fresh), "the new id is not valid");
    const rb_vec2 x = rb_body_position(f.world, old);
    cr_expect(x.x == 0.0 && x.y == 0.0, "the old id reads the new body's position (%g, %g)", x.x, x.y);
    expect_last_failure(RB_ERR_STALE_ID, "rb_body_position", "body");
    expect_failure(rb_body_set_linear_velocity(f.world, old, rb_v2(5.0, 0.0)), RB_ERR_STALE_ID,
                   "rb_body_set_linear_velocity", "body");
    const rb_vec2 v = rb_body_linear_velocity(f.world, fresh);
    cr_expect(v.x == 0.0 && v.y == 0.0, "a call on the old id changed the new body");
    expect_failure(rb_body_destroy(f.world, old), RB_ERR_STALE_ID, "rb_body_destroy", "body");
    cr_expect(rb_body_is_valid(f.world, fresh), "destroying the old id destroyed the new body");
    cr_expect_not(rb_shape_is_valid(f.world, old_shape), "the old shape id is valid again");
    expect_failure(rb_shape_set_friction(f.world, old_shape, 0.1), RB_ERR_STALE_ID, "rb_shape_set_friction", "shape");
    cr_expect_eq(rb_shape_friction(f.world, fresh_shape), rb_default_shape_def().friction,
                 "a call on the old shape id changed the new shape");
    expect_vec_near(rb_body_position(f.world, fresh), rb_v2(-50.0, 0.0), 0.0, "the new body's position");
    expect_usable(&f, 2);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, ids_of_another_world_and_null_ids_are_foreign)
{
    fixture f = make_fixture();
    rb_world *other = make_world(rb_default_world_def().gravity);
    /* Probably the same slot index and generation as the probe: only the
     * world tells them apart. */
    const rb_body_id stranger = make_body(other, RB_BODY_DYNAMIC, rb_v2(7.0, 7.0), 0.0);
    const rb_shape_id stranger_shape = add_circle(other, stranger, rb_v2(0.0, 0.0), 0.5, 1.0);
    const probe_state before = probe_state_of(&f);

    cr_expect_not(rb_body_is_valid(f.world, stranger), "another world's body is valid here");
    const rb_vec2 x = rb_body_position(f.world, stranger);
    cr_expect(x.x == 0.0 && x.y == 0.0, "another world's id reads (%g, %g)", x.x, x.y);
    expect_last_failure(RB_ERR_FOREIGN_ID, "rb_body_position", "body");
    expect_failure(rb_body_set_linear_velocity(f.world, stranger, rb_v2(5.0, 0.0)), RB_ERR_FOREIGN_ID,
                   "rb_body_set_linear_velocity", "body");
    expect_failure(rb_body_destroy(f.world, stranger), RB_ERR_FOREIGN_ID, "rb_body_destroy", "body");
    expect_failure(rb_shape_set_friction(f.world, stranger_shape, 0.1), RB_ERR_FOREIGN_ID, "rb_shape_set_friction",
                   "shape");

    const rb_body_id null_body = {0};
    const rb_shape_id null_shape = {0};
    cr_expect_not(rb_body_is_valid(f.world, null_body), "the null body id is valid");
    cr_expect_eq(rb_body_mass(f.world, null_body), 0.0, "the null id's mass");
    expect_last_failure(RB_ERR_FOREIGN_ID, "rb_body_mass", "body");
    expect_failure(rb_body_apply_torque(f.world, null_body, 1.0), RB_ERR_FOREIGN_ID, "rb_body_apply_torque", "body");
    expect_failure(rb_shape_destroy(f.world, null_shape), RB_ERR_FOREIGN_ID, "rb_shape_destroy", "shape");
    rb_shape_id shape;
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.5};
    const rb_shape_def def = rb_default_shape_def();
    expect_failure(rb_shape_create_circle(f.world, null_body, &def, &circle, &shape), RB_ERR_FOREIGN_ID,
                   "rb_shape_create_circle", "body");

    expect_probe_unchanged(&f, before, "calls with foreign ids");
    cr_expect(rb_body_is_valid(other, stranger), "the other world's body was destroyed");
    expect_vec_near(rb_body_position(other, stranger), rb_v2(7.0, 7.0), 0.0, "the other world's body");
    rb_world_destroy(other);
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

/* ---- NULL world, last error, status names --------------------------------- */

Test(api_errors, null_world)
{
    fixture f = make_fixture();
    expect_failure(rb_body_destroy(NULL, f.probe), RB_ERR_INVALID_ARGUMENT, "rb_body_destroy", "world");
    expect_failure(rb_body_apply_force_to_center(NULL, f.probe, rb_v2(1.0, 0.0)), RB_ERR_INVALID_ARGUMENT,
                   "rb_body_apply_force_to_center", "world");
    const rb_vec2 x = rb_body_position(NULL, f.probe);
    cr_expect(x.x == 0.0 && x.y == 0.0, "position read from a NULL world: (%g, %g)", x.x, x.y);
    expect_last_failure(RB_ERR_INVALID_ARGUMENT, "rb_body_position", "world");
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.5};
    const rb_shape_def def = rb_default_shape_def();
    rb_shape_id shape;
    expect_failure(rb_shape_create_circle(NULL, f.probe, &def, &circle, &shape), RB_ERR_INVALID_ARGUMENT,
                   "rb_shape_create_circle", "world");
    expect_failure(rb_world_set_substep_callback(NULL, NULL, NULL), RB_ERR_INVALID_ARGUMENT,
                   "rb_world_set_substep_callback", "world");
    expect_failure(rb_world_enable_sleep(NULL, false), RB_ERR_INVALID_ARGUMENT, "rb_world_enable_sleep", "world");
    cr_expect_not(rb_world_is_sleep_enabled(NULL));
    expect_failure(rb_body_enable_sleep(NULL, f.probe, false), RB_ERR_INVALID_ARGUMENT, "rb_body_enable_sleep",
                   "world");
    rb_world_destroy(NULL); /* world.h: accepts NULL */
    expect_usable(&f, 1);
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, success_clears_the_last_error)
{
    fixture f = make_fixture();
    expect_failure(rb_world_step(f.world, -1.0), RB_ERR_INVALID_ARGUMENT, "rb_world_step", "dt");
    cr_assert_eq(rb_world_step(f.world, TEST_DT), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_last_status(), RB_OK, "rb_last_status() after a success");
    cr_expect_str_empty(rb_last_error(), "base.h: rb_last_error() is \"\" after a success");
    destroy_world_and_expect_no_leak(f.world);
}

Test(api_errors, status_names)
{
    const struct {
        rb_status status;
        const char *name;
    } names[] = {
        {RB_OK, "RB_OK"},
        {RB_ERR_INVALID_ARGUMENT, "RB_ERR_INVALID_ARGUMENT"},
        {RB_ERR_STALE_ID, "RB_ERR_STALE_ID"},
        {RB_ERR_FOREIGN_ID, "RB_ERR_FOREIGN_ID"},
        {RB_ERR_DEGENERATE_SHAPE, "RB_ERR_DEGENERATE_SHAPE"},
        {RB_ERR_NOT_CONVEX, "RB_ERR_NOT_CONVEX"},
        {RB_ERR_NO_MASS, "RB_ERR_NO_MASS"},
        {RB_ERR_LOCKED, "RB_ERR_LOCKED"},
        {RB_ERR_OUT_OF_MEMORY, "RB_ERR_OUT_OF_MEMORY"},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        cr_expect_str_eq(rb_status_name(names[i].status), names[i].name, "rb_status_name(%d)", (int)names[i].status);
    }
}
