/* SPDX-License-Identifier: MIT */
/* Rigid bodies: creation, pose, velocity, forces, mass. */
#include <float.h>
#include <string.h>

#include "allocator.h"
#include "error.h"
#include "sleep.h"
#include "world_internal.h"

rb_body_def rb_default_body_def(void)
{
    return (rb_body_def){
        .type = RB_BODY_STATIC,
        .gravity_scale = 1.0,
        .awake = true,
        .enable_sleep = true,
        .internal_value = RB_DEF_COOKIE,
    };
}

static rb_status check_body_def(const rb_body_def *def)
{
    const char *f = "rb_body_create";
    RB_TRY(rb_check_pointer(f, "def", def));
    RB_TRY(rb_check_def_cookie(f, "rb_default_body_def", def->internal_value));
    if (def->type != RB_BODY_STATIC && def->type != RB_BODY_KINEMATIC && def->type != RB_BODY_DYNAMIC) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: type is %d, expected a rb_body_type", f, (int)def->type);
    }
    RB_TRY(rb_check_point(f, "position", def->position));
    RB_TRY(rb_check_bound(f, "angle", def->angle, RB_MAX_ANGLE, "rad"));
    RB_TRY(rb_check_vec2_bound(f, "linear_velocity", def->linear_velocity, RB_MAX_SPEED, "m/s"));
    RB_TRY(rb_check_bound(f, "angular_velocity", def->angular_velocity, RB_MAX_SPEED, "rad/s"));
    RB_TRY(rb_check_range(f, "linear_damping", def->linear_damping, 0.0, RB_MAX_DAMPING));
    RB_TRY(rb_check_range(f, "angular_damping", def->angular_damping, 0.0, RB_MAX_DAMPING));
    RB_TRY(rb_check_bound(f, "gravity_scale", def->gravity_scale, RB_MAX_GRAVITY_SCALE, ""));
    return RB_OK;
}

/* A slot for a new body: from the free list, else past the last one. */
static rb_status allocate_body_slot(rb_world *world, int *index)
{
    if (world->body_free >= 0) {
        *index = world->body_free;
        world->body_free = world->bodies[*index].next_free;
        return RB_OK;
    }
    int needed = world->body_slots + 1;
    if (rb_grow_array((void **)&world->bodies, &world->body_capacity, needed, sizeof *world->bodies) != 0 ||
        rb_grow_array((void **)&world->states, &world->state_capacity, needed, sizeof *world->states) != 0 ||
        rb_grow_array((void **)&world->saved_states, &world->saved_state_capacity, needed,
                      sizeof *world->saved_states) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_body_create: out of memory");
    }
    *index = world->body_slots++;
    world->bodies[*index].generation = 0;
    return RB_OK;
}

rb_status rb_body_create(rb_world *world, const rb_body_def *def, rb_body_id *out)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_body_create", "world", world));
    RB_TRY(rb_check_pointer("rb_body_create", "out", out));
    *out = (rb_body_id){0};
    RB_TRY(rb_world_check_unlocked(world, "rb_body_create"));
    RB_TRY(check_body_def(def));
    int index = -1;
    RB_TRY(allocate_body_slot(world, &index));

    rb_body *body = &world->bodies[index];
    uint32_t generation = body->generation + 1u;
    memset(body, 0, sizeof *body);
    body->generation = generation;
    body->in_use = true;
    body->type = def->type;
    body->linear_damping = def->linear_damping;
    body->angular_damping = def->angular_damping;
    body->gravity_scale = def->gravity_scale;
    body->fixed_rotation = def->fixed_rotation;
    body->awake = def->awake;
    body->enable_sleep = def->enable_sleep;
    body->sleep_time = 0.0;
    body->bullet = def->bullet;
    body->user_data = def->user_data;
    body->first_shape = -1;
    body->first_joint = -1;

    bool moves = def->type != RB_BODY_STATIC;
    world->states[index] = (rb_body_state){
        .linear_velocity = moves ? def->linear_velocity : rb_v2(0.0, 0.0),
        .angular_velocity = moves && !def->fixed_rotation ? def->angular_velocity : 0.0,
        .center = def->position,
        .rotation = rb_rot_from_angle(def->angle),
        .angle = def->angle,
    };
    world->body_count++;
    rb_body_update_mass(world, index);
    *out = rb_make_body_id(world, index);
    return RB_OK;
}

rb_status rb_body_destroy(rb_world *world, rb_body_id id)
{
    rb_clear_error();
    int index;
    RB_TRY(rb_world_find_body(world, id, "rb_body_destroy", &index));
    RB_TRY(rb_world_check_unlocked(world, "rb_body_destroy"));
    rb_joints_remove_body(world, index);
    rb_cables_remove_body(world, index);
    rb_body *body = &world->bodies[index];
    while (body->first_shape >= 0) {
        RB_TRY(rb_shape_destroy(world, rb_make_shape_id(world, body->first_shape)));
    }
    body->in_use = false;
    if (body->generation != RB_RETIRED_GENERATION) {
        body->next_free = world->body_free;
        world->body_free = index;
    }
    world->body_count--;
    return RB_OK;
}

bool rb_body_is_valid(const rb_world *world, rb_body_id id)
{
    bool valid = world != NULL && id.generation != 0 && id.world == world->serial && id.index >= 0 &&
                 id.index < world->body_slots && world->bodies[id.index].in_use &&
                 world->bodies[id.index].generation == id.generation;
    return valid;
}

/* ---- mass ---------------------------------------------------------------- */

/* The farthest any point of the shape lies from the body's centre of mass:
 * bounds how fast the shape's surface moves when the body spins. */
static double shape_extent(const rb_shape *shape, rb_vec2 local_center)
{
    if (shape->type == RB_SHAPE_CIRCLE) {
        return rb_distance(shape->geometry.circle.center, local_center) + shape->geometry.circle.radius;
    }
    if (shape->type == RB_SHAPE_SEGMENT || shape->type == RB_SHAPE_CHAIN_SEGMENT) {
        const rb_segment *segment =
            shape->type == RB_SHAPE_SEGMENT ? &shape->geometry.segment : &shape->geometry.chain_segment.segment;
        return fmax(rb_distance(segment->point1, local_center), rb_distance(segment->point2, local_center));
    }
    double extent = 0.0;
    for (int i = 0; i < shape->geometry.polygon.count; ++i) {
        extent = fmax(extent, rb_distance(shape->geometry.polygon.vertices[i], local_center));
    }
    return extent;
}

static rb_mass_data shapes_mass(const rb_world *world, const rb_body *body)
{
    double mass = 0.0;
    rb_vec2 moment = {0.0, 0.0};
    double inertia_at_origin = 0.0;
    for (int s = body->first_shape; s >= 0; s = world->shapes[s].next_in_body) {
        const rb_shape *shape = &world->shapes[s];
        if (shape->type != RB_SHAPE_CIRCLE && shape->type != RB_SHAPE_POLYGON) {
            continue; /* segments have no area, hence no mass */
        }
        rb_mass_data m = shape->type == RB_SHAPE_CIRCLE ? rb_circle_mass(&shape->geometry.circle, shape->density)
                                                        : rb_polygon_mass(&shape->geometry.polygon, shape->density);
        mass += m.mass;
        moment = rb_mul_add(moment, m.mass, m.center);
        /* Parallel-axis theorem: move each shape's inertia to the body origin. */
        inertia_at_origin += m.rotational_inertia + m.mass * rb_dot(m.center, m.center);
    }
    if (mass <= 0.0) {
        return (rb_mass_data){0.0, {0.0, 0.0}, 0.0};
    }
    rb_vec2 center = rb_scale(1.0 / mass, moment);
    return (rb_mass_data){mass, center, inertia_at_origin - mass * rb_dot(center, center)};
}

void rb_body_update_mass(rb_world *world, int index)
{
    rb_body *body = &world->bodies[index];
    rb_body_state *state = &world->states[index];
    rb_mass_data data = {0.0, {0.0, 0.0}, 0.0};
    if (body->type == RB_BODY_DYNAMIC) {
        data = body->has_mass_override ? body->mass_override : shapes_mass(world, body);
        if (data.mass <= 0.0) {
            /* No shapes with mass yet: 1 kg that does not rotate. */
            data = (rb_mass_data){1.0, {0.0, 0.0}, 0.0};
        }
    }
    body->mass = data.mass;
    body->inv_mass = data.mass > 0.0 ? 1.0 / data.mass : 0.0;
    body->inertia = data.rotational_inertia;
    body->inv_inertia = data.rotational_inertia > 0.0 && !body->fixed_rotation ? 1.0 / data.rotational_inertia : 0.0;
    if (body->fixed_rotation && body->type == RB_BODY_DYNAMIC) {
        state->angular_velocity = 0.0;
    }

    /* Keep the origin in place: the centre of mass moves with the new
     * local centre, and its velocity picks up ω × (its displacement). */
    rb_vec2 old_center = state->center;
    rb_vec2 origin = rb_sub(old_center, rb_rotate(state->rotation, body->local_center));
    body->local_center = data.center;
    state->center = rb_add(origin, rb_rotate(state->rotation, data.center));
    state->linear_velocity =
        rb_add(state->linear_velocity, rb_cross_sv(state->angular_velocity, rb_sub(state->center, old_center)));

    for (int s = body->first_shape; s >= 0; s = world->shapes[s].next_in_body) {
        world->shapes[s].extent = shape_extent(&world->shapes[s], body->local_center);
    }
}

/* ---- getters ------------------------------------------------------------- */

/* Every getter looks its body up the same way and returns `zero` for a
 * bad id (with the error recorded). */
#define BODY_GETTER(type, name, zero, expression)                                                                      \
    type name(const rb_world *world, rb_body_id id)                                                                    \
    {                                                                                                                  \
        rb_clear_error();                                                                                              \
        int index;                                                                                                     \
        if (rb_world_find_body(world, id, #name, &index) != RB_OK) {                                                   \
            return zero;                                                                                               \
        }                                                                                                              \
        const rb_body *body = &world->bodies[index];                                                                   \
        const rb_body_state *state = &world->states[index];                                                            \
        (void)body;                                                                                                    \
        (void)state;                                                                                                   \
        return expression;                                                                                             \
    }

static const rb_vec2 zero_vec2 = {0.0, 0.0};
static const rb_transform identity_transform = {{0.0, 0.0}, {1.0, 0.0}};
static const rb_rot identity_rot = {1.0, 0.0};
static const rb_mass_data zero_mass = {0.0, {0.0, 0.0}, 0.0};

BODY_GETTER(rb_body_type, rb_body_type_of, RB_BODY_STATIC, body->type)
BODY_GETTER(rb_vec2, rb_body_position, zero_vec2, rb_body_origin_transform(world, index).p)
BODY_GETTER(double, rb_body_angle, 0.0, state->angle)
BODY_GETTER(rb_rot, rb_body_rotation, identity_rot, state->rotation)
BODY_GETTER(rb_transform, rb_body_transform, identity_transform, rb_body_origin_transform(world, index))
BODY_GETTER(rb_vec2, rb_body_world_center, zero_vec2, state->center)
BODY_GETTER(rb_vec2, rb_body_local_center, zero_vec2, body->local_center)
BODY_GETTER(rb_vec2, rb_body_linear_velocity, zero_vec2, state->linear_velocity)
BODY_GETTER(double, rb_body_angular_velocity, 0.0, state->angular_velocity)
BODY_GETTER(rb_vec2, rb_body_force, zero_vec2, body->force)
BODY_GETTER(double, rb_body_torque, 0.0, body->torque)
BODY_GETTER(double, rb_body_mass, 0.0, body->mass)
BODY_GETTER(double, rb_body_rotational_inertia, 0.0, body->inertia)
BODY_GETTER(rb_mass_data, rb_body_mass_data, zero_mass, ((rb_mass_data){body->mass, body->local_center, body->inertia}))
BODY_GETTER(double, rb_body_linear_damping, 0.0, body->linear_damping)
BODY_GETTER(double, rb_body_angular_damping, 0.0, body->angular_damping)
BODY_GETTER(double, rb_body_gravity_scale, 0.0, body->gravity_scale)
BODY_GETTER(bool, rb_body_is_fixed_rotation, false, body->fixed_rotation)
BODY_GETTER(bool, rb_body_is_awake, false, body->awake)
BODY_GETTER(bool, rb_body_is_sleep_enabled, false, body->enable_sleep)
BODY_GETTER(bool, rb_body_is_bullet, false, body->bullet)
BODY_GETTER(void *, rb_body_user_data, NULL, body->user_data)
BODY_GETTER(int, rb_body_shape_count, 0, body->shape_count)

/* Getters that take a point or vector: the same look-up, then a check of
 * the argument. */
#define BODY_POINT_GETTER(name, argument, expression)                                                                  \
    rb_vec2 name(const rb_world *world, rb_body_id id, rb_vec2 argument)                                               \
    {                                                                                                                  \
        rb_clear_error();                                                                                              \
        int index;                                                                                                     \
        if (rb_world_find_body(world, id, #name, &index) != RB_OK ||                                                   \
            rb_check_vec2(#name, #argument, argument) != RB_OK) {                                                      \
            return zero_vec2;                                                                                          \
        }                                                                                                              \
        const rb_body_state *state = &world->states[index];                                                            \
        rb_transform xf = rb_body_origin_transform(world, index);                                                      \
        (void)state;                                                                                                   \
        (void)xf;                                                                                                      \
        return expression;                                                                                             \
    }

BODY_POINT_GETTER(rb_body_point_velocity, world_point,
                  rb_add(state->linear_velocity,
                         rb_cross_sv(state->angular_velocity, rb_sub(world_point, state->center))))
BODY_POINT_GETTER(rb_body_world_point, local_point, rb_transform_point(xf, local_point))
BODY_POINT_GETTER(rb_body_local_point, world_point, rb_inv_transform_point(xf, world_point))
BODY_POINT_GETTER(rb_body_world_vector, local_vector, rb_rotate(xf.q, local_vector))
BODY_POINT_GETTER(rb_body_local_vector, world_vector, rb_inv_rotate(xf.q, world_vector))

int rb_body_shapes(const rb_world *world, rb_body_id id, rb_shape_id *out, int capacity)
{
    rb_clear_error();
    int index;
    if (rb_world_find_body(world, id, "rb_body_shapes", &index) != RB_OK) {
        return 0;
    }
    if (out == NULL && capacity > 0) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_body_shapes: out is NULL");
        return 0;
    }
    int count = 0;
    for (int s = world->bodies[index].first_shape; s >= 0 && count < capacity; s = world->shapes[s].next_in_body) {
        out[count++] = rb_make_shape_id(world, s);
    }
    return count;
}

/* ---- setters ------------------------------------------------------------- */

/* Looks up the body for a call that changes it. */
static rb_status find_for_change(rb_world *world, rb_body_id id, const char *function, int *index)
{
    rb_clear_error();
    RB_TRY(rb_world_find_body(world, id, function, index));
    return rb_world_check_unlocked(world, function);
}

static rb_status check_moveable(const rb_world *world, int index, const char *function)
{
    if (world->bodies[index].type == RB_BODY_STATIC) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: the body is static and cannot move", function);
    }
    return RB_OK;
}

rb_status rb_body_set_transform(rb_world *world, rb_body_id id, rb_vec2 position, double angle)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_transform", &index));
    RB_TRY(rb_check_point("rb_body_set_transform", "position", position));
    RB_TRY(rb_check_bound("rb_body_set_transform", "angle", angle, RB_MAX_ANGLE, "rad"));
    rb_body_state *state = &world->states[index];
    state->angle = angle;
    state->rotation = rb_rot_from_angle(angle);
    state->center = rb_add(position, rb_rotate(state->rotation, world->bodies[index].local_center));
    world->boxes_stale = true; /* the broad phase's boxes of a sleeping body no longer fit it */
    return RB_OK;
}

rb_status rb_body_set_linear_velocity(rb_world *world, rb_body_id id, rb_vec2 velocity)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_linear_velocity", &index));
    RB_TRY(rb_check_vec2_bound("rb_body_set_linear_velocity", "velocity", velocity, RB_MAX_SPEED, "m/s"));
    RB_TRY(check_moveable(world, index, "rb_body_set_linear_velocity"));
    world->states[index].linear_velocity = velocity;
    world->bodies[index].awake = true;
    return RB_OK;
}

rb_status rb_body_set_angular_velocity(rb_world *world, rb_body_id id, double omega)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_angular_velocity", &index));
    RB_TRY(rb_check_bound("rb_body_set_angular_velocity", "omega", omega, RB_MAX_SPEED, "rad/s"));
    RB_TRY(check_moveable(world, index, "rb_body_set_angular_velocity"));
    if (!world->bodies[index].fixed_rotation) {
        world->states[index].angular_velocity = omega;
    }
    world->bodies[index].awake = true;
    return RB_OK;
}

/* Forces and impulses act on dynamic bodies only, and wake them; on a
 * static or kinematic body they are accepted and ignored. */
static void add_force(rb_world *world, int index, rb_vec2 force, double torque)
{
    rb_body *body = &world->bodies[index];
    if (body->type == RB_BODY_DYNAMIC) {
        body->force = rb_add(body->force, force);
        body->torque += torque;
        body->awake = true;
    }
}

static void add_impulse(rb_world *world, int index, rb_vec2 impulse, double angular_impulse)
{
    rb_body *body = &world->bodies[index];
    rb_body_state *state = &world->states[index];
    if (body->type == RB_BODY_DYNAMIC) {
        state->linear_velocity = rb_mul_add(state->linear_velocity, body->inv_mass, impulse);
        state->angular_velocity += body->inv_inertia * angular_impulse;
        body->awake = true;
    }
}

/* The moment r × v about the body's centre of mass of v applied at p. */
static double moment_about_center(const rb_world *world, int index, rb_vec2 p, rb_vec2 v)
{
    return rb_cross(rb_sub(p, world->states[index].center), v);
}

rb_status rb_body_apply_force(rb_world *world, rb_body_id id, rb_vec2 force, rb_vec2 world_point)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_apply_force", &index));
    RB_TRY(rb_check_vec2_bound("rb_body_apply_force", "force", force, RB_MAX_FORCE, "N"));
    RB_TRY(rb_check_point("rb_body_apply_force", "world_point", world_point));
    add_force(world, index, force, moment_about_center(world, index, world_point, force));
    return RB_OK;
}

rb_status rb_body_apply_force_to_center(rb_world *world, rb_body_id id, rb_vec2 force)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_apply_force_to_center", &index));
    RB_TRY(rb_check_vec2_bound("rb_body_apply_force_to_center", "force", force, RB_MAX_FORCE, "N"));
    add_force(world, index, force, 0.0);
    return RB_OK;
}

rb_status rb_body_apply_torque(rb_world *world, rb_body_id id, double torque)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_apply_torque", &index));
    RB_TRY(rb_check_bound("rb_body_apply_torque", "torque", torque, RB_MAX_FORCE, "N·m"));
    add_force(world, index, rb_v2(0.0, 0.0), torque);
    return RB_OK;
}

rb_status rb_body_apply_linear_impulse(rb_world *world, rb_body_id id, rb_vec2 impulse, rb_vec2 world_point)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_apply_linear_impulse", &index));
    RB_TRY(rb_check_vec2_bound("rb_body_apply_linear_impulse", "impulse", impulse, RB_MAX_FORCE, "N·s"));
    RB_TRY(rb_check_point("rb_body_apply_linear_impulse", "world_point", world_point));
    add_impulse(world, index, impulse, moment_about_center(world, index, world_point, impulse));
    return RB_OK;
}

rb_status rb_body_apply_linear_impulse_to_center(rb_world *world, rb_body_id id, rb_vec2 impulse)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_apply_linear_impulse_to_center", &index));
    RB_TRY(rb_check_vec2_bound("rb_body_apply_linear_impulse_to_center", "impulse", impulse, RB_MAX_FORCE, "N·s"));
    add_impulse(world, index, impulse, 0.0);
    return RB_OK;
}

rb_status rb_body_apply_angular_impulse(rb_world *world, rb_body_id id, double impulse)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_apply_angular_impulse", &index));
    RB_TRY(rb_check_bound("rb_body_apply_angular_impulse", "impulse", impulse, RB_MAX_FORCE, "N·m·s"));
    add_impulse(world, index, rb_v2(0.0, 0.0), impulse);
    return RB_OK;
}

/* Every shape of a dynamic body without a mass override needs a positive
 * density, or the body's mass would silently fall back to a default. */
static rb_status check_shapes_have_mass(const rb_world *world, int index, const char *function)
{
    const rb_body *body = &world->bodies[index];
    if (body->type != RB_BODY_DYNAMIC || body->has_mass_override) {
        return RB_OK;
    }
    for (int s = body->first_shape; s >= 0; s = world->shapes[s].next_in_body) {
        rb_shape_type type = world->shapes[s].type;
        if (type == RB_SHAPE_SEGMENT || type == RB_SHAPE_CHAIN_SEGMENT) {
            return rb_report_error(RB_ERR_NO_MASS,
                                   "%s: shape %d is a segment (no mass) on a dynamic body without a mass override; "
                                   "expected rb_body_set_mass_data first",
                                   function, s);
        }
        if (!(world->shapes[s].density > 0.0)) {
            return rb_report_error(RB_ERR_NO_MASS,
                                   "%s: shape %d has density %g on a dynamic body without a mass override; "
                                   "expected a density > 0 or rb_body_set_mass_data",
                                   function, s, world->shapes[s].density);
        }
        RB_TRY(rb_shape_check_mass(function, type, &world->shapes[s].geometry, world->shapes[s].density, true));
    }
    return RB_OK;
}

rb_status rb_body_set_type(rb_world *world, rb_body_id id, rb_body_type type)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_type", &index));
    if (type != RB_BODY_STATIC && type != RB_BODY_KINEMATIC && type != RB_BODY_DYNAMIC) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_body_set_type: type is %d, expected a rb_body_type",
                               (int)type);
    }
    rb_body *body = &world->bodies[index];
    rb_body_type old_type = body->type;
    body->type = type;
    rb_status status = check_shapes_have_mass(world, index, "rb_body_set_type");
    if (status != RB_OK) {
        body->type = old_type;
        return status;
    }
    if (type == RB_BODY_STATIC) {
        world->states[index].linear_velocity = rb_v2(0.0, 0.0);
        world->states[index].angular_velocity = 0.0;
    }
    body->awake = true;
    world->candidates_stale = true; /* two static or kinematic bodies never collide */
    rb_body_update_mass(world, index);
    return RB_OK;
}

rb_status rb_body_set_mass_data(rb_world *world, rb_body_id id, const rb_mass_data *mass_data)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_mass_data", &index));
    RB_TRY(rb_check_pointer("rb_body_set_mass_data", "mass_data", mass_data));
    RB_TRY(rb_check_range("rb_body_set_mass_data", "mass", mass_data->mass, RB_MIN_MASS, RB_MAX_MASS));
    RB_TRY(rb_check_point("rb_body_set_mass_data", "center", mass_data->center));
    RB_TRY(rb_check_range("rb_body_set_mass_data", "rotational_inertia", mass_data->rotational_inertia, 0.0,
                          RB_MAX_MASS * RB_MAX_LENGTH * RB_MAX_LENGTH));
    rb_body *body = &world->bodies[index];
    body->has_mass_override = true;
    body->mass_override = *mass_data;
    rb_body_update_mass(world, index);
    return RB_OK;
}

rb_status rb_body_reset_mass_data(rb_world *world, rb_body_id id)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_reset_mass_data", &index));
    rb_body *body = &world->bodies[index];
    body->has_mass_override = false;
    rb_status status = check_shapes_have_mass(world, index, "rb_body_reset_mass_data");
    if (status != RB_OK) {
        body->has_mass_override = true;
        return status;
    }
    rb_body_update_mass(world, index);
    return RB_OK;
}

/* A setter that checks its argument, then stores it in one body field. */
#define BODY_FIELD_SETTER(name, type, argument, field, check)                                                          \
    rb_status name(rb_world *world, rb_body_id id, type argument)                                                      \
    {                                                                                                                  \
        const char *function = #name;                                                                                  \
        int index;                                                                                                     \
        RB_TRY(find_for_change(world, id, function, &index));                                                          \
        RB_TRY(check);                                                                                                 \
        world->bodies[index].field = argument;                                                                         \
        return RB_OK;                                                                                                  \
    }

BODY_FIELD_SETTER(rb_body_set_linear_damping, double, damping, linear_damping,
                  rb_check_range(function, "damping", damping, 0.0, RB_MAX_DAMPING))
BODY_FIELD_SETTER(rb_body_set_angular_damping, double, damping, angular_damping,
                  rb_check_range(function, "damping", damping, 0.0, RB_MAX_DAMPING))
BODY_FIELD_SETTER(rb_body_set_gravity_scale, double, scale, gravity_scale,
                  rb_check_bound(function, "scale", scale, RB_MAX_GRAVITY_SCALE, ""))
BODY_FIELD_SETTER(rb_body_set_bullet, bool, bullet, bullet, RB_OK)
BODY_FIELD_SETTER(rb_body_set_user_data, void *, user_data, user_data, RB_OK)

rb_status rb_body_set_fixed_rotation(rb_world *world, rb_body_id id, bool fixed)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_fixed_rotation", &index));
    world->bodies[index].fixed_rotation = fixed;
    rb_body_update_mass(world, index);
    return RB_OK;
}

rb_status rb_body_set_awake(rb_world *world, rb_body_id id, bool awake)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_set_awake", &index));
    rb_body *body = &world->bodies[index];
    if (awake) {
        rb_body_wake(world, index);
    } else {
        body->awake = false;
        /* A body put to sleep stops where it is. */
        world->states[index].linear_velocity = rb_v2(0.0, 0.0);
        world->states[index].angular_velocity = 0.0;
        world->boxes_stale = true; /* its swept boxes, made moving, are made once more at rest */
        body->force = rb_v2(0.0, 0.0);
        body->torque = 0.0;
    }
    return RB_OK;
}

rb_status rb_body_enable_sleep(rb_world *world, rb_body_id id, bool enable)
{
    int index;
    RB_TRY(find_for_change(world, id, "rb_body_enable_sleep", &index));
    world->bodies[index].enable_sleep = enable;
    if (!enable) {
        rb_body_wake(world, index);
    }
    return RB_OK;
}
