/* SPDX-License-Identifier: MIT */
/* The API's ranges (rb/base.h) are those the solver can take: for every
 * create function and every numeric field of its definition or geometry,
 * a value at either end of the documented range is accepted and steps to
 * a finite state with RB_OK, and a value just beyond it, a huge one, an
 * infinite one and NaN are refused with RB_ERR_INVALID_ARGUMENT naming
 * the field. Then the failures the issue found (a revolute spring of
 * 1e160 Hz, boxes of 1e150 and 1e154 m, a density of 1e307 kg/m²,
 * rb_make_box(1e308)), and what a step does when the motion, not the
 * input, goes non-finite. */
#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "rb/rb.h"
#include "test_support.h"
#include "world_internal.h"

/* A ground box and two dynamic boxes (0.8 × 0.2 m, 1 kg/m²) side by side
 * above it: what every case below adds its object to. */
typedef struct scene {
    rb_world *world;
    rb_body_id ground, a, b;
} scene;

static void populate(scene *s)
{
    s->ground = make_body(s->world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    add_box(s->world, s->ground, 5.0, 0.5, 1.0);
    s->a = make_body(s->world, RB_BODY_DYNAMIC, rb_v2(0.0, 2.0), 0.0);
    s->b = make_body(s->world, RB_BODY_DYNAMIC, rb_v2(1.0, 2.0), 0.0);
    add_box(s->world, s->a, 0.4, 0.1, 1.0);
    add_box(s->world, s->b, 0.4, 0.1, 1.0);
}

static void make_scene(scene *s)
{
    s->world = make_world(rb_v2(0.0, -9.8));
    populate(s);
}

/* Each case creates its world (s->world), and returns the status of the
 * one call that takes `value` in the field under test. */
typedef rb_status apply_fn(scene *s, double value);

/* ---- world ---------------------------------------------------------------- */

#define WORLD_CASE(name, statement)                                                                                    \
    static rb_status name(scene *s, double v)                                                                          \
    {                                                                                                                  \
        rb_world_def def = rb_default_world_def();                                                                     \
        statement;                                                                                                     \
        rb_status status = rb_world_create(&def, &s->world);                                                           \
        if (status == RB_OK) {                                                                                         \
            populate(s);                                                                                               \
        }                                                                                                              \
        return status;                                                                                                 \
    }

WORLD_CASE(world_gravity_x, def.gravity.x = v)
WORLD_CASE(world_gravity_y, def.gravity.y = v)
WORLD_CASE(world_baumgarte, (def.solver.baumgarte = v, def.solver.type = RB_SOLVER_BAUMGARTE))
WORLD_CASE(world_linear_slop, def.solver.linear_slop = v)
WORLD_CASE(world_max_linear_correction, def.solver.max_linear_correction = v)
WORLD_CASE(world_restitution_threshold, def.solver.restitution_threshold = v)
WORLD_CASE(world_contact_hertz, (def.solver.contact_hertz = v, def.solver.type = RB_SOLVER_SOFT_STEP))
WORLD_CASE(world_contact_damping_ratio, (def.solver.contact_damping_ratio = v, def.solver.type = RB_SOLVER_SOFT_STEP))
WORLD_CASE(world_joint_hertz, (def.solver.joint_hertz = v, def.solver.type = RB_SOLVER_SOFT_STEP))
WORLD_CASE(world_joint_damping_ratio, (def.solver.joint_damping_ratio = v, def.solver.type = RB_SOLVER_SOFT_STEP))
WORLD_CASE(world_max_push_speed, (def.solver.max_push_speed = v, def.solver.type = RB_SOLVER_SOFT_STEP))

/* ---- bodies --------------------------------------------------------------- */

#define BODY_CASE(name, statement)                                                                                     \
    static rb_status name(scene *s, double v)                                                                          \
    {                                                                                                                  \
        make_scene(s);                                                                                                 \
        rb_body_def def = rb_default_body_def();                                                                       \
        def.type = RB_BODY_DYNAMIC;                                                                                    \
        def.position = rb_v2(0.0, 5.0);                                                                                \
        statement;                                                                                                     \
        rb_body_id body;                                                                                               \
        rb_status status = rb_body_create(s->world, &def, &body);                                                      \
        if (status == RB_OK) {                                                                                         \
            add_circle(s->world, body, rb_v2(0.0, 0.0), 0.2, 1.0);                                                     \
        }                                                                                                              \
        return status;                                                                                                 \
    }

BODY_CASE(body_position_x, def.position.x = v)
BODY_CASE(body_position_y, def.position.y = v)
BODY_CASE(body_angle, def.angle = v)
BODY_CASE(body_linear_velocity_x, def.linear_velocity.x = v)
BODY_CASE(body_linear_velocity_y, def.linear_velocity.y = v)
BODY_CASE(body_angular_velocity, def.angular_velocity = v)
BODY_CASE(body_linear_damping, def.linear_damping = v)
BODY_CASE(body_angular_damping, def.angular_damping = v)
BODY_CASE(body_gravity_scale, def.gravity_scale = v)

/* ---- shapes --------------------------------------------------------------- */

/* A shape on a new dynamic body above the ground. */
#define SHAPE_CASE(name, statement, create)                                                                            \
    static rb_status name(scene *s, double v)                                                                          \
    {                                                                                                                  \
        make_scene(s);                                                                                                 \
        rb_body_id body = make_body(s->world, RB_BODY_DYNAMIC, rb_v2(0.0, 5.0), 0.0);                                  \
        rb_shape_def def = rb_default_shape_def();                                                                     \
        rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.2};                                                      \
        double hx = 0.2, hy = 0.2;                                                                                     \
        statement;                                                                                                     \
        (void)circle;                                                                                                  \
        (void)hx;                                                                                                      \
        (void)hy;                                                                                                      \
        rb_shape_id shape;                                                                                             \
        return create;                                                                                                 \
    }

#define CIRCLE_CASE(name, statement)                                                                                   \
    SHAPE_CASE(name, statement, rb_shape_create_circle(s->world, body, &def, &circle, &shape))

/* rb_make_box takes the half-extents: its status, then the polygon's. */
static rb_status create_box(rb_world *world, rb_body_id body, const rb_shape_def *def, double hx, double hy,
                            rb_shape_id *shape)
{
    rb_polygon box;
    rb_status status = rb_make_box(hx, hy, &box);
    return status != RB_OK ? status : rb_shape_create_polygon(world, body, def, &box, shape);
}

#define BOX_CASE(name, statement) SHAPE_CASE(name, statement, create_box(s->world, body, &def, hx, hy, &shape))

CIRCLE_CASE(shape_friction, def.friction = v)
CIRCLE_CASE(shape_restitution, def.restitution = v)
/* On a static body: on a dynamic one the shape's mass must also reach
 * RB_MIN_MASS, which the_inputs_that_made_nan_are_refused tries. */
static rb_status shape_density(scene *s, double v)
{
    make_scene(s);
    rb_shape_def def = rb_default_shape_def();
    def.density = v;
    rb_shape_id shape;
    return create_box(s->world, s->ground, &def, 0.2, 0.2, &shape);
}
CIRCLE_CASE(circle_center_x, circle.center.x = v)
CIRCLE_CASE(circle_radius, circle.radius = v)
BOX_CASE(box_half_width, hx = v)
BOX_CASE(box_half_height, hy = v)

/* A hand-made polygon: a triangle with one vertex at x = v. */
static rb_status polygon_vertex_x(scene *s, double v)
{
    make_scene(s);
    rb_body_id body = make_body(s->world, RB_BODY_STATIC, rb_v2(0.0, -5.0), 0.0);
    rb_polygon triangle = {.count = 3, .vertices = {{v - 1.0, 0.0}, {v, 0.0}, {v, 1.0}}};
    const rb_shape_def def = rb_default_shape_def();
    rb_shape_id shape;
    return rb_shape_create_polygon(s->world, body, &def, &triangle, &shape);
}

static rb_status segment_point_x(scene *s, double v)
{
    make_scene(s);
    const rb_segment segment = {.point1 = {v, -5.0}, .point2 = {v > 0.0 ? v - 1.0 : v + 1.0, -5.0}};
    const rb_shape_def def = rb_default_shape_def();
    rb_shape_id shape;
    return rb_shape_create_segment(s->world, s->ground, &def, &segment, &shape);
}

static rb_status chain_point_y(scene *s, double v)
{
    make_scene(s);
    const rb_vec2 points[3] = {{-1.0, -5.0}, {0.0, v}, {1.0, -5.0}};
    const rb_shape_def def = rb_default_shape_def();
    return rb_shape_create_chain(s->world, s->ground, &def, points, 3, false, NULL, 0);
}

/* ---- joints and cables ---------------------------------------------------- */

/* A joint between the two boxes, pinned where they meet (x = 0.5). */
#define JOINT_CASE(name, type, maker, create, statement)                                                               \
    static rb_status name(scene *s, double v)                                                                          \
    {                                                                                                                  \
        make_scene(s);                                                                                                 \
        type def = maker();                                                                                            \
        def.body_a = s->a;                                                                                             \
        def.body_b = s->b;                                                                                             \
        def.local_anchor_a = rb_v2(0.5, 0.0);                                                                          \
        def.local_anchor_b = rb_v2(-0.5, 0.0);                                                                         \
        statement;                                                                                                     \
        rb_joint_id joint;                                                                                             \
        return create(s->world, &def, &joint);                                                                         \
    }

#define REVOLUTE_CASE(name, statement)                                                                                 \
    JOINT_CASE(name, rb_revolute_joint_def, rb_default_revolute_joint_def, rb_revolute_joint_create, statement)
#define WELD_CASE(name, statement)                                                                                     \
    JOINT_CASE(name, rb_weld_joint_def, rb_default_weld_joint_def, rb_weld_joint_create, statement)
#define DISTANCE_CASE(name, statement)                                                                                 \
    JOINT_CASE(name, rb_distance_joint_def, rb_default_distance_joint_def, rb_distance_joint_create, statement)
#define PRISMATIC_CASE(name, statement)                                                                                \
    JOINT_CASE(name, rb_prismatic_joint_def, rb_default_prismatic_joint_def, rb_prismatic_joint_create, statement)
#define PULLEY_CASE(name, statement)                                                                                   \
    JOINT_CASE(name, rb_pulley_joint_def, rb_default_pulley_joint_def, rb_pulley_joint_create,                         \
               (def.ground_anchor_a = rb_v2(0.0, 4.0), def.ground_anchor_b = rb_v2(1.0, 4.0),                          \
                def.local_anchor_a = def.local_anchor_b = rb_v2(0.0, 0.0), def.length_a = def.length_b = 2.0,          \
                statement))

REVOLUTE_CASE(revolute_anchor_x, def.local_anchor_a.x = v)
REVOLUTE_CASE(revolute_reference_angle, def.reference_angle = v)
REVOLUTE_CASE(revolute_lower_angle, (def.enable_lower_limit = true, def.lower_angle = v))
REVOLUTE_CASE(revolute_upper_angle, (def.enable_upper_limit = true, def.upper_angle = v))
REVOLUTE_CASE(revolute_motor_speed, (def.enable_motor = true, def.max_motor_torque = 10.0, def.motor_speed = v))
REVOLUTE_CASE(revolute_max_motor_torque, (def.enable_motor = true, def.motor_speed = 1.0, def.max_motor_torque = v))
REVOLUTE_CASE(revolute_spring_hertz, (def.enable_spring = true, def.spring_hertz = v))
REVOLUTE_CASE(revolute_spring_damping_ratio,
              (def.enable_spring = true, def.spring_hertz = 5.0, def.spring_damping_ratio = v))
WELD_CASE(weld_anchor_y, def.local_anchor_b.y = v)
WELD_CASE(weld_reference_angle, def.reference_angle = v)
WELD_CASE(weld_linear_hertz, def.linear_hertz = v)
WELD_CASE(weld_linear_damping_ratio, (def.linear_hertz = 5.0, def.linear_damping_ratio = v))
WELD_CASE(weld_angular_hertz, def.angular_hertz = v)
WELD_CASE(weld_angular_damping_ratio, (def.angular_hertz = 5.0, def.angular_damping_ratio = v))
DISTANCE_CASE(distance_length, def.length = v)
DISTANCE_CASE(distance_spring_hertz, (def.enable_spring = true, def.spring_hertz = v))
DISTANCE_CASE(distance_spring_damping_ratio,
              (def.enable_spring = true, def.spring_hertz = 5.0, def.spring_damping_ratio = v))
DISTANCE_CASE(distance_min_length, (def.enable_limit = true, def.min_length = v))
PRISMATIC_CASE(prismatic_anchor_x, def.local_anchor_b.x = v)
PRISMATIC_CASE(prismatic_reference_angle, def.reference_angle = v)
PRISMATIC_CASE(prismatic_lower_translation, (def.enable_lower_limit = true, def.lower_translation = v))
PRISMATIC_CASE(prismatic_upper_translation, (def.enable_upper_limit = true, def.upper_translation = v))
PRISMATIC_CASE(prismatic_motor_speed, (def.enable_motor = true, def.max_motor_force = 10.0, def.motor_speed = v))
PRISMATIC_CASE(prismatic_max_motor_force, (def.enable_motor = true, def.motor_speed = 1.0, def.max_motor_force = v))
PRISMATIC_CASE(prismatic_spring_hertz, (def.enable_spring = true, def.spring_hertz = v))
PRISMATIC_CASE(prismatic_spring_damping_ratio,
               (def.enable_spring = true, def.spring_hertz = 5.0, def.spring_damping_ratio = v))
PULLEY_CASE(pulley_ground_anchor_x, def.ground_anchor_a.x = v)
PULLEY_CASE(pulley_length_a, def.length_a = v)
PULLEY_CASE(pulley_ratio, def.ratio = v)
PULLEY_CASE(pulley_min_length, (def.min_length = v, def.length_a = def.length_b = fmax(v, 2.0)))

#define MOUSE_CASE(name, statement)                                                                                    \
    static rb_status name(scene *s, double v)                                                                          \
    {                                                                                                                  \
        make_scene(s);                                                                                                 \
        rb_mouse_joint_def def = rb_default_mouse_joint_def();                                                         \
        def.body = s->a;                                                                                               \
        def.target = rb_v2(0.0, 3.0);                                                                                  \
        statement;                                                                                                     \
        rb_joint_id joint;                                                                                             \
        return rb_mouse_joint_create(s->world, &def, &joint);                                                          \
    }

MOUSE_CASE(mouse_local_anchor_x, def.local_anchor.x = v)
MOUSE_CASE(mouse_target_y, def.target.y = v)
MOUSE_CASE(mouse_max_force, def.max_force = v)
MOUSE_CASE(mouse_hertz, def.hertz = v)
MOUSE_CASE(mouse_damping_ratio, def.damping_ratio = v)

/* A cable from box A to box B; `law` cases set its tension law. */
static rb_status make_cable(scene *s, rb_vec2 point_a, rb_cable_id *cable)
{
    make_scene(s);
    rb_cable_def def = rb_default_cable_def();
    def.point_count = 2;
    def.bodies[0] = s->a;
    def.bodies[1] = s->b;
    def.local_points[0] = point_a;
    return rb_cable_create(s->world, &def, cable);
}

static rb_status cable_point_x(scene *s, double v)
{
    rb_cable_id cable;
    return make_cable(s, rb_v2(v, 0.0), &cable);
}

static rb_status cable_base_tension(scene *s, double v)
{
    rb_cable_id cable;
    cr_assert_eq(make_cable(s, rb_v2(-0.4, 0.0), &cable), RB_OK, "%s", rb_last_error());
    return rb_cable_set_tension_law(s->world, cable, v, 0.0);
}

static rb_status cable_damping(scene *s, double v)
{
    rb_cable_id cable;
    cr_assert_eq(make_cable(s, rb_v2(-0.4, 0.0), &cable), RB_OK, "%s", rb_last_error());
    return rb_cable_set_tension_law(s->world, cable, 0.0, v);
}

/* ---- the table ------------------------------------------------------------ */

typedef struct range_case {
    const char *field; /* as the error message names it */
    apply_fn *apply;
    double lowest, highest; /* the documented range, both ends included */
} range_case;

/* What a field holds at either end when its range is open at 0. */
#define ABOVE_ZERO DBL_MIN

static const range_case cases[] = {
    {"gravity", world_gravity_x, -RB_MAX_ACCELERATION, RB_MAX_ACCELERATION},
    {"gravity", world_gravity_y, -RB_MAX_ACCELERATION, RB_MAX_ACCELERATION},
    {"baumgarte", world_baumgarte, 0.0, 1.0},
    {"linear_slop", world_linear_slop, 0.0, 0.1},
    {"max_linear_correction", world_max_linear_correction, ABOVE_ZERO, RB_MAX_LENGTH},
    {"restitution_threshold", world_restitution_threshold, 0.0, RB_MAX_SPEED},
    {"contact_hertz", world_contact_hertz, RB_MIN_HERTZ, RB_MAX_HERTZ},
    {"contact_damping_ratio", world_contact_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"joint_hertz", world_joint_hertz, RB_MIN_HERTZ, RB_MAX_HERTZ},
    {"joint_damping_ratio", world_joint_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"max_push_speed", world_max_push_speed, ABOVE_ZERO, RB_MAX_SPEED},
    {"position", body_position_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"position", body_position_y, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"angle", body_angle, -RB_MAX_ANGLE, RB_MAX_ANGLE},
    {"linear_velocity", body_linear_velocity_x, -RB_MAX_SPEED, RB_MAX_SPEED},
    {"linear_velocity", body_linear_velocity_y, -RB_MAX_SPEED, RB_MAX_SPEED},
    {"angular_velocity", body_angular_velocity, -RB_MAX_SPEED, RB_MAX_SPEED},
    {"linear_damping", body_linear_damping, 0.0, RB_MAX_DAMPING},
    {"angular_damping", body_angular_damping, 0.0, RB_MAX_DAMPING},
    {"gravity_scale", body_gravity_scale, -RB_MAX_GRAVITY_SCALE, RB_MAX_GRAVITY_SCALE},
    {"friction", shape_friction, 0.0, RB_MAX_FRICTION},
    {"restitution", shape_restitution, 0.0, 1.0},
    {"density", shape_density, 0.0, RB_MAX_DENSITY},
    {"circle center", circle_center_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"circle radius", circle_radius, RB_POLYGON_WELD_DISTANCE, RB_MAX_LENGTH},
    {"hx", box_half_width, RB_POLYGON_WELD_DISTANCE, RB_MAX_LENGTH},
    {"hy", box_half_height, RB_POLYGON_WELD_DISTANCE, RB_MAX_LENGTH},
    {"polygon vertex", polygon_vertex_x, -RB_MAX_LENGTH + 1.0, RB_MAX_LENGTH},
    {"segment", segment_point_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"segment", chain_point_y, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"local_anchor_a", revolute_anchor_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"reference_angle", revolute_reference_angle, -RB_MAX_ANGLE, RB_MAX_ANGLE},
    {"lower_angle", revolute_lower_angle, -RB_MAX_ANGLE, RB_MAX_ANGLE},
    {"upper_angle", revolute_upper_angle, -RB_MAX_ANGLE, RB_MAX_ANGLE},
    {"motor_speed", revolute_motor_speed, -RB_MAX_SPEED, RB_MAX_SPEED},
    {"max_motor_torque", revolute_max_motor_torque, 0.0, RB_MAX_FORCE},
    {"spring_hertz", revolute_spring_hertz, 0.0, RB_MAX_HERTZ},
    {"spring_damping_ratio", revolute_spring_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"local_anchor_b", weld_anchor_y, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"reference_angle", weld_reference_angle, -RB_MAX_ANGLE, RB_MAX_ANGLE},
    {"linear_hertz", weld_linear_hertz, 0.0, RB_MAX_HERTZ},
    {"linear_damping_ratio", weld_linear_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"angular_hertz", weld_angular_hertz, 0.0, RB_MAX_HERTZ},
    {"angular_damping_ratio", weld_angular_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"length", distance_length, 1e-9, RB_MAX_LENGTH},
    {"spring_hertz", distance_spring_hertz, 0.0, RB_MAX_HERTZ},
    {"spring_damping_ratio", distance_spring_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"min_length", distance_min_length, 0.0, RB_MAX_LENGTH},
    {"local_anchor_b", prismatic_anchor_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"reference_angle", prismatic_reference_angle, -RB_MAX_ANGLE, RB_MAX_ANGLE},
    {"lower_translation", prismatic_lower_translation, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"upper_translation", prismatic_upper_translation, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"motor_speed", prismatic_motor_speed, -RB_MAX_SPEED, RB_MAX_SPEED},
    {"max_motor_force", prismatic_max_motor_force, 0.0, RB_MAX_FORCE},
    {"spring_hertz", prismatic_spring_hertz, 0.0, RB_MAX_HERTZ},
    {"spring_damping_ratio", prismatic_spring_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"ground_anchor_a", pulley_ground_anchor_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"length_a", pulley_length_a, 0.05, RB_MAX_LENGTH},
    {"ratio", pulley_ratio, 1e-6, 1e6},
    {"min_length", pulley_min_length, ABOVE_ZERO, RB_MAX_LENGTH},
    {"local_anchor", mouse_local_anchor_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"target", mouse_target_y, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"max_force", mouse_max_force, 0.0, RB_MAX_FORCE},
    {"hertz", mouse_hertz, RB_MIN_HERTZ, RB_MAX_HERTZ},
    {"damping_ratio", mouse_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO},
    {"local_points[i]", cable_point_x, -RB_MAX_LENGTH, RB_MAX_LENGTH},
    {"base_tension", cable_base_tension, -RB_MAX_FORCE, RB_MAX_FORCE},
    {"damping", cable_damping, 0.0, RB_MAX_FORCE},
};

/* The next double beyond `limit`, away from the range; 0's neighbour
 * below is -DBL_MIN's neighbour, a negative subnormal. */
static double just_beyond(double limit, double direction) { return nextafter(limit, direction * INFINITY); }

static void expect_simulated(const range_case *c, double value)
{
    scene s = {0};
    rb_status status = c->apply(&s, value);
    cr_expect_eq(status, RB_OK, "%s = %.17g (in range) refused: %s", c->field, value, rb_last_error());
    for (int i = 0; status == RB_OK && i < 10; ++i) {
        status = rb_world_step(s.world, TEST_DT);
        cr_expect_eq(status, RB_OK, "%s = %.17g: step %d: %s", c->field, value, i, rb_last_error());
    }
    for (int i = 0; status == RB_OK && i < s.world->body_slots; ++i) {
        const rb_body_state *state = &s.world->states[i];
        cr_expect(rb_vec2_is_finite(state->center) && rb_vec2_is_finite(state->linear_velocity) &&
                      isfinite(state->angle) && isfinite(state->angular_velocity),
                  "%s = %.17g: body %d is not finite", c->field, value, i);
    }
    rb_world_destroy(s.world);
}

/* A size below its range is a degenerate shape (rb/base.h's status). */
static void expect_refused(const range_case *c, double value)
{
    scene s = {0};
    rb_status status = c->apply(&s, value);
    cr_expect(status == RB_ERR_INVALID_ARGUMENT || status == RB_ERR_DEGENERATE_SHAPE,
              "%s = %.17g (out of range) gave %s", c->field, value, rb_status_name(status));
    cr_expect(strstr(rb_last_error(), c->field) != NULL, "the message does not name %s: \"%s\"", c->field,
              rb_last_error());
    rb_world_destroy(s.world);
}

Test(ranges, every_field_of_every_create_function_at_and_beyond_its_range)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const range_case *c = &cases[i];
        expect_simulated(c, c->lowest);
        expect_simulated(c, c->highest);
        expect_refused(c, just_beyond(c->lowest, -1.0));
        expect_refused(c, just_beyond(c->highest, 1.0));
        expect_refused(c, 1e300);
        expect_refused(c, -1e300);
        expect_refused(c, INFINITY);
        expect_refused(c, NAN);
    }
    cr_expect_eq(rb_bytes_in_use(), 0, "the cases leaked %zu bytes", rb_bytes_in_use());
}

/* ---- the examples --------------------------------------------------- */

Test(ranges, the_inputs_that_made_nan_are_refused)
{
    scene s = {0};
    cr_expect_eq(revolute_spring_hertz(&s, 1e160), RB_ERR_INVALID_ARGUMENT, "a revolute spring of 1e160 Hz");
    rb_world_destroy(s.world);
    cr_expect_eq(box_half_width(&s, 1e150), RB_ERR_INVALID_ARGUMENT, "a box of half-extent 1e150 m");
    rb_world_destroy(s.world);
    cr_expect_eq(box_half_width(&s, 1e154), RB_ERR_INVALID_ARGUMENT, "a box of half-extent 1e154 m");
    rb_world_destroy(s.world);
    cr_expect_eq(shape_density(&s, 1e307), RB_ERR_INVALID_ARGUMENT, "a density of 1e307 kg/m²");
    rb_world_destroy(s.world);
    rb_polygon box;
    cr_expect_eq(rb_make_box(1e308, 1e308, &box), RB_ERR_INVALID_ARGUMENT, "rb_make_box(1e308)");
    /* A positive frequency below RB_MIN_HERTZ, whose stiffness underflows. */
    cr_expect_eq(revolute_spring_hertz(&s, DBL_MIN), RB_ERR_INVALID_ARGUMENT, "a revolute spring of %g Hz", DBL_MIN);
    rb_world_destroy(s.world);
    cr_expect_eq(mouse_hertz(&s, 0.0), RB_ERR_INVALID_ARGUMENT, "a mouse joint of 0 Hz");
    rb_world_destroy(s.world);
    /* In range one by one, too heavy together: 2e5 m × 2e5 m at 1e12 kg/m². */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    def.density = RB_MAX_DENSITY;
    rb_shape_id shape;
    cr_assert_eq(rb_make_box(1e5, 1e5, &box), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_shape_create_polygon(world, body, &def, &box, &shape), RB_ERR_INVALID_ARGUMENT,
                 "a shape of 4e22 kg");
    cr_expect(strstr(rb_last_error(), "mass") != NULL, "%s", rb_last_error());
    /* Nor a dynamic body lighter than RB_MIN_MASS: 0.16 m² at 1e-9 kg/m². */
    def.density = 1e-9;
    cr_assert_eq(rb_make_box(0.2, 0.2, &box), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_shape_create_polygon(world, body, &def, &box, &shape), RB_ERR_INVALID_ARGUMENT,
                 "a shape of 1.6e-10 kg");
    cr_expect(strstr(rb_last_error(), "mass") != NULL, "%s", rb_last_error());
    /* Nor by a later change of density. */
    shape = add_circle(world, body, rb_v2(0.0, 0.0), 1e3, 1.0);
    cr_expect_eq(rb_shape_set_density(world, shape, RB_MAX_DENSITY), RB_ERR_INVALID_ARGUMENT, "set_density");
    cr_expect_eq(rb_shape_density(world, shape), 1.0, "the refused density was kept");
    destroy_world_and_expect_no_leak(world);
}

/* ---- a step that goes non-finite ------------------------------------------ */

/* The motion, not the input, goes non-finite: a body whose velocity is
 * set (through the internals, as a solver blow-up would leave it) to the
 * largest double, which the step's integration turns into infinity. The
 * step fails naming the body, and every body is back as before it (the
 * velocity included: the one set here). */
Test(ranges, a_step_that_goes_non_finite_fails_and_restores_the_world)
{
    scene s;
    make_scene(&s);
    rb_joint_id pin = make_pin(s.world, s.a, s.b, rb_v2(0.5, 2.0));
    step_world(s.world, TEST_DT, 30);
    /* Body A, the first dynamic body: the one the message names, since
     * through the pin body B goes non-finite in the same substep. */
    int index_a = s.a.index;
    s.world->states[index_a].linear_velocity = rb_v2(DBL_MAX, DBL_MAX);
    const uint64_t before = rb_world_state_hash(s.world);
    const rb_vec2 position_b = rb_body_position(s.world, s.b);
    const rb_statistics statistics = rb_world_statistics(s.world);

    cr_expect_eq(rb_world_step(s.world, TEST_DT), RB_ERR_NOT_FINITE, "the step's status: %s", rb_last_error());
    char name[32];
    snprintf(name, sizeof name, "body %d", index_a);
    cr_expect(strstr(rb_last_error(), "rb_world_step") != NULL && strstr(rb_last_error(), name) != NULL,
              "the message does not name the body (%s): \"%s\"", name, rb_last_error());
    cr_expect_eq(rb_world_state_hash(s.world), before, "the world is not as it was before the step");
    expect_vec_near(rb_body_position(s.world, s.b), position_b, 0.0, "body B's position");
    cr_expect_eq(rb_world_statistics(s.world).energy, statistics.energy, "the statistics changed");
    const rb_vec2 reaction = rb_joint_reaction_force(s.world, pin);
    cr_expect(rb_vec2_is_finite(reaction), "the pin's reaction (%g, %g)", reaction.x, reaction.y);

    /* Unchanged, it fails again; once the body is given a sane velocity
     * the world steps on. */
    cr_expect_eq(rb_world_step(s.world, TEST_DT), RB_ERR_NOT_FINITE, "the second step: %s", rb_last_error());
    cr_assert_eq(rb_body_set_linear_velocity(s.world, s.a, rb_v2(0.0, 0.0)), RB_OK, "%s", rb_last_error());
    step_world(s.world, TEST_DT, 30);
    cr_expect(rb_vec2_is_finite(rb_body_position(s.world, s.a)), "body A after the recovery");
    destroy_world_and_expect_no_leak(s.world);
}
