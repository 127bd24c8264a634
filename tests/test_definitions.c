/* SPDX-License-Identifier: MIT */
/* Definitions: a create function simulates only what a default function
 * made (internal_value), and the rb_*_def_at helpers return complete
 * definitions whatever *def held before.
 *
 * "Garbage" is a definition whose every byte is 1, as memory left over
 * from something else may be, with the fields a careless caller does set
 * (bodies, anchors) filled in: its doubles are 7.7e-304 (finite, >= 0,
 * so they passed every range check), its bools true, its ints 16843009.
 * Such a weld used to give a NaN reaction force. */
#include <criterion/criterion.h>
#include <string.h>

#include "rb/rb.h"
#include "test_support.h"

#define GARBAGE_BYTE 1

typedef struct scene {
    rb_world *world;
    rb_body_id ground, a, b;
} scene;

/* A static ground and two dynamic boxes side by side, 1 m apart. */
static scene make_scene(void)
{
    scene s = {.world = make_world(rb_v2(0.0, -9.8))};
    s.ground = make_body(s.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    s.a = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(0.0, 1.0), 0.0);
    s.b = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(1.0, 1.0), 0.0);
    add_box(s.world, s.a, 0.4, 0.1, 1.0);
    add_box(s.world, s.b, 0.4, 0.1, 1.0);
    return s;
}

/* Every create function, given a garbage definition with its ids and
 * required fields filled in validly; returns its status. */
typedef rb_status create_fn(scene *s);

static rb_status create_world(scene *s)
{
    (void)s;
    rb_world_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.gravity = rb_v2(0.0, -9.8);
    def.solver = rb_default_solver_settings();
    rb_world *world = NULL;
    rb_status status = rb_world_create(&def, &world);
    rb_world_destroy(world);
    return status;
}

static rb_status create_body(scene *s)
{
    rb_body_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.type = RB_BODY_DYNAMIC;
    def.user_data = NULL;
    rb_body_id body;
    return rb_body_create(s->world, &def, &body);
}

static rb_shape_def garbage_shape_def(void)
{
    rb_shape_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.restitution = 0.0;
    def.user_data = NULL;
    return def;
}

static rb_status create_circle(scene *s)
{
    const rb_shape_def def = garbage_shape_def();
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = 0.1};
    rb_shape_id shape;
    return rb_shape_create_circle(s->world, s->a, &def, &circle, &shape);
}

static rb_status create_polygon(scene *s)
{
    const rb_shape_def def = garbage_shape_def();
    rb_polygon box;
    cr_assert_eq(rb_make_box(0.1, 0.1, &box), RB_OK, "%s", rb_last_error());
    rb_shape_id shape;
    return rb_shape_create_polygon(s->world, s->a, &def, &box, &shape);
}

static rb_status create_segment(scene *s)
{
    const rb_shape_def def = garbage_shape_def();
    const rb_segment segment = {.point1 = {-1.0, 0.0}, .point2 = {1.0, 0.0}};
    rb_shape_id shape;
    return rb_shape_create_segment(s->world, s->ground, &def, &segment, &shape);
}

static rb_status create_chain(scene *s)
{
    const rb_shape_def def = garbage_shape_def();
    const rb_vec2 points[3] = {{-2.0, 0.0}, {0.0, 0.0}, {2.0, 0.0}};
    return rb_shape_create_chain(s->world, s->ground, &def, points, 3, false, NULL, 0);
}

static rb_status create_revolute(scene *s)
{
    rb_revolute_joint_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.body_a = s->a;
    def.body_b = s->b;
    def.local_anchor_a = rb_v2(0.5, 0.0);
    def.local_anchor_b = rb_v2(-0.5, 0.0);
    def.reference_angle = 0.0;
    def.enable_lower_limit = def.enable_upper_limit = false;
    def.user_data = NULL;
    rb_joint_id joint;
    return rb_revolute_joint_create(s->world, &def, &joint);
}

static rb_status create_weld(scene *s)
{
    rb_weld_joint_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.body_a = s->a;
    def.body_b = s->b;
    def.local_anchor_a = rb_v2(0.5, 0.0);
    def.local_anchor_b = rb_v2(-0.5, 0.0);
    def.reference_angle = 0.0;
    def.user_data = NULL;
    rb_joint_id joint;
    return rb_weld_joint_create(s->world, &def, &joint);
}

static rb_status create_distance(scene *s)
{
    rb_distance_joint_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.body_a = s->a;
    def.body_b = s->b;
    def.local_anchor_a = def.local_anchor_b = rb_v2(0.0, 0.0);
    def.length = 1.0;
    def.enable_limit = false;
    def.user_data = NULL;
    rb_joint_id joint;
    return rb_distance_joint_create(s->world, &def, &joint);
}

static rb_status create_mouse(scene *s)
{
    rb_mouse_joint_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.body = s->a;
    def.local_anchor = rb_v2(0.0, 0.0);
    def.target = rb_v2(0.0, 2.0);
    def.user_data = NULL;
    rb_joint_id joint;
    return rb_mouse_joint_create(s->world, &def, &joint);
}

static rb_status create_prismatic(scene *s)
{
    rb_prismatic_joint_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.body_a = s->a;
    def.body_b = s->b;
    def.local_anchor_a = def.local_anchor_b = rb_v2(0.0, 0.0);
    def.local_axis_a = rb_v2(1.0, 0.0);
    def.reference_angle = 0.0;
    def.enable_lower_limit = def.enable_upper_limit = false;
    def.user_data = NULL;
    rb_joint_id joint;
    return rb_prismatic_joint_create(s->world, &def, &joint);
}

static rb_status create_pulley(scene *s)
{
    rb_pulley_joint_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.body_a = s->a;
    def.body_b = s->b;
    def.ground_anchor_a = rb_v2(0.0, 3.0);
    def.ground_anchor_b = rb_v2(1.0, 3.0);
    def.local_anchor_a = def.local_anchor_b = rb_v2(0.0, 0.0);
    def.length_a = def.length_b = 2.0;
    def.ratio = 1.0;
    def.min_length = 0.05;
    def.user_data = NULL;
    rb_joint_id joint;
    return rb_pulley_joint_create(s->world, &def, &joint);
}

static rb_status create_cable(scene *s)
{
    rb_cable_def def;
    memset(&def, GARBAGE_BYTE, sizeof def);
    def.point_count = 2;
    def.bodies[0] = s->a;
    def.bodies[1] = s->b;
    def.local_points[0] = def.local_points[1] = rb_v2(0.0, 0.0);
    def.user_data = NULL;
    rb_cable_id cable;
    return rb_cable_create(s->world, &def, &cable);
}

typedef struct create_case {
    const char *function;
    const char *maker; /* the default function the refusal must name */
    create_fn *create;
} create_case;

static const create_case create_cases[] = {
    {"rb_world_create", "rb_default_world_def", create_world},
    {"rb_body_create", "rb_default_body_def", create_body},
    {"rb_shape_create_circle", "rb_default_shape_def", create_circle},
    {"rb_shape_create_polygon", "rb_default_shape_def", create_polygon},
    {"rb_shape_create_segment", "rb_default_shape_def", create_segment},
    {"rb_shape_create_chain", "rb_default_shape_def", create_chain},
    {"rb_revolute_joint_create", "rb_default_revolute_joint_def", create_revolute},
    {"rb_weld_joint_create", "rb_default_weld_joint_def", create_weld},
    {"rb_distance_joint_create", "rb_default_distance_joint_def", create_distance},
    {"rb_mouse_joint_create", "rb_default_mouse_joint_def", create_mouse},
    {"rb_prismatic_joint_create", "rb_default_prismatic_joint_def", create_prismatic},
    {"rb_pulley_joint_create", "rb_default_pulley_joint_def", create_pulley},
    {"rb_cable_create", "rb_default_cable_def", create_cable},
};

Test(definitions, every_create_function_refuses_a_definition_not_made_by_its_default_function)
{
    for (size_t i = 0; i < sizeof create_cases / sizeof create_cases[0]; ++i) {
        const create_case *c = &create_cases[i];
        scene s = make_scene();
        const rb_status status = c->create(&s);
        cr_expect_eq(status, RB_ERR_INVALID_ARGUMENT, "%s accepted a garbage definition (status %s)", c->function,
                     rb_status_name(status));
        cr_expect(strstr(rb_last_error(), c->function) != NULL && strstr(rb_last_error(), c->maker) != NULL,
                  "%s's message does not name itself and %s: \"%s\"", c->function, c->maker, rb_last_error());
        cr_expect_eq(rb_world_statistics(s.world).joint_count, 0, "%s", c->function);
        destroy_world_and_expect_no_leak(s.world);
    }
}

/* A garbage weld used to be simulated, with a NaN reaction force. */
Test(definitions, a_garbage_weld_is_refused_not_simulated)
{
    scene s = make_scene();
    cr_expect_eq(create_weld(&s), RB_ERR_INVALID_ARGUMENT, "a garbage weld was created");
    step_world(s.world, TEST_DT, 10);
    cr_expect(rb_vec2_is_finite(rb_body_position(s.world, s.b)), "body B's position");
    destroy_world_and_expect_no_leak(s.world);
}

/* Each helper, given garbage, returns a complete definition: one that
 * simulates bit for bit as the helper's result from the default
 * definition, with a finite reaction. (Compared by the state they make,
 * since the structs' padding bytes need not match.) */
#define EXPECT_HELPER_COMPLETES(type, maker, create, call)                                                             \
    do {                                                                                                               \
        scene scenes[2] = {make_scene(), make_scene()};                                                                \
        type defs[2] = {maker(), maker()};                                                                             \
        memset(&defs[1], GARBAGE_BYTE, sizeof defs[1]);                                                                \
        rb_joint_id joints[2];                                                                                         \
        for (int k = 0; k < 2; ++k) {                                                                                  \
            const scene s = scenes[k];                                                                                 \
            type *def = &defs[k];                                                                                      \
            cr_assert_eq(call, RB_OK, "%s", rb_last_error());                                                          \
            cr_assert_eq(create(s.world, def, &joints[k]), RB_OK, #call " from %s: %s",                                \
                         k == 0 ? #maker "()" : "garbage", rb_last_error());                                           \
            step_world(s.world, TEST_DT, 30);                                                                          \
        }                                                                                                              \
        cr_expect_eq(rb_world_state_hash(scenes[1].world), rb_world_state_hash(scenes[0].world),                       \
                     #call " from garbage simulates otherwise than from " #maker "()");                                \
        const rb_vec2 force = rb_joint_reaction_force(scenes[1].world, joints[1]);                                     \
        cr_expect(rb_vec2_is_finite(force) && isfinite(rb_joint_reaction_torque(scenes[1].world, joints[1])),          \
                  #create ": reaction (%g, %g)", force.x, force.y);                                                    \
        rb_world_destroy(scenes[0].world);                                                                             \
        destroy_world_and_expect_no_leak(scenes[1].world);                                                             \
    } while (0)

Test(definitions, the_helpers_return_complete_definitions)
{
    EXPECT_HELPER_COMPLETES(rb_revolute_joint_def, rb_default_revolute_joint_def, rb_revolute_joint_create,
                            rb_revolute_joint_def_at(def, s.world, s.a, s.b, rb_v2(0.5, 1.0)));
    EXPECT_HELPER_COMPLETES(rb_weld_joint_def, rb_default_weld_joint_def, rb_weld_joint_create,
                            rb_weld_joint_def_at(def, s.world, s.a, s.b, rb_v2(0.5, 1.0)));
    EXPECT_HELPER_COMPLETES(rb_distance_joint_def, rb_default_distance_joint_def, rb_distance_joint_create,
                            rb_distance_joint_def_between(def, s.world, s.a, s.b, rb_v2(0.0, 1.0), rb_v2(1.0, 1.0)));
    EXPECT_HELPER_COMPLETES(rb_prismatic_joint_def, rb_default_prismatic_joint_def, rb_prismatic_joint_create,
                            rb_prismatic_joint_def_at(def, s.world, s.a, s.b, rb_v2(0.5, 1.0), rb_v2(1.0, 0.0)));
    EXPECT_HELPER_COMPLETES(rb_pulley_joint_def, rb_default_pulley_joint_def, rb_pulley_joint_create,
                            rb_pulley_joint_def_between(def, s.world, s.a, s.b, rb_v2(0.0, 3.0), rb_v2(1.0, 3.0),
                                                        rb_v2(0.0, 1.0), rb_v2(1.0, 1.0)));
}

/* A helper that fails leaves *def as it was. */
Test(definitions, a_failed_helper_leaves_the_definition_alone)
{
    scene s = make_scene();
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    def.enable_motor = true;
    const rb_revolute_joint_def before = def;
    cr_expect_eq(rb_revolute_joint_def_at(&def, s.world, s.a, s.a, rb_v2(0.0, 0.0)), RB_ERR_INVALID_ARGUMENT,
                 "one body twice");
    cr_expect(memcmp(&def, &before, sizeof def) == 0, "the failed helper changed the definition");
    destroy_world_and_expect_no_leak(s.world);
}
