/* SPDX-License-Identifier: MIT */
/* The world: creation, destruction, settings, id look-ups and the step. */
#include <assert.h>
#include <float.h>
#include <stdatomic.h>
#include <string.h>

#include "allocator.h"
#include "broad_phase.h"
#include "cable_solver.h"
#include "contact.h"
#include "contact_events.h"
#include "contact_solver.h"
#include "error.h"
#include "joint_solver.h"
#include "joint_tree.h"
#include "sleep.h"
#include "solver.h"
#include "timer.h"
#include "world_internal.h"

/* Serial numbers tell the ids of different worlds apart; 0 is never used,
 * so the all-zero id is null. */
static atomic_uint_least64_t next_world_serial = 1;

rb_solver_settings rb_default_solver_settings(void)
{
    return (rb_solver_settings){
        .type = RB_SOLVER_NGS,
        .velocity_iterations = 2,
        .position_iterations = 1,
        .relax_iterations = 1,
        .substeps = 6,
        .warm_starting = true,
        .block_solver = true,
        .tree_pins = true,
        .baumgarte = 0.2,
        .linear_slop = 0.005,
        .max_linear_correction = 0.2,
        .restitution_threshold = 1.0,
        .contact_hertz = 30.0,
        .contact_damping_ratio = 10.0,
        .joint_hertz = 60.0,
        .joint_damping_ratio = 2.0,
        .max_push_speed = 3.0,
    };
}

static const char *const solver_type_names[RB_SOLVER_TYPE_COUNT] = {"baumgarte", "ngs", "soft_step"};

const char *rb_solver_type_name(rb_solver_type type)
{
    return type >= 0 && type < RB_SOLVER_TYPE_COUNT ? solver_type_names[type] : "unknown";
}

rb_status rb_solver_type_from_name(const char *name, rb_solver_type *type)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_solver_type_from_name", "name", name));
    RB_TRY(rb_check_pointer("rb_solver_type_from_name", "type", type));
    for (int i = 0; i < RB_SOLVER_TYPE_COUNT; ++i) {
        if (strcmp(name, solver_type_names[i]) == 0) {
            *type = (rb_solver_type)i;
            return RB_OK;
        }
    }
    char choices[128] = "";
    for (int i = 0; i < RB_SOLVER_TYPE_COUNT; ++i) {
        strcat(choices, i == 0 ? "" : ", ");
        strcat(choices, solver_type_names[i]);
    }
    return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                           "rb_solver_type_from_name: no solver is called \"%s\"; expected one of %s", name, choices);
}

rb_world_def rb_default_world_def(void)
{
    return (rb_world_def){.gravity = {0.0, -9.8},
                          .solver = rb_default_solver_settings(),
                          .enable_profile = true,
                          .enable_sleep = true,
                          .internal_value = RB_DEF_COOKIE};
}

static rb_status check_settings(const rb_solver_settings *s, const char *function)
{
    RB_TRY(rb_check_pointer(function, "settings", s));
    RB_TRY(rb_check_range(function, "velocity_iterations", s->velocity_iterations, 1, 1000));
    RB_TRY(rb_check_range(function, "position_iterations", s->position_iterations, 0, 1000));
    RB_TRY(rb_check_range(function, "relax_iterations", s->relax_iterations, 0, 1000));
    RB_TRY(rb_check_range(function, "substeps", s->substeps, 1, 1000));
    if (!(s->type >= 0 && s->type < RB_SOLVER_TYPE_COUNT)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: type is %d, expected an rb_solver_type below %d", function,
                               (int)s->type, (int)RB_SOLVER_TYPE_COUNT);
    }
    RB_TRY(rb_check_range(function, "baumgarte", s->baumgarte, 0.0, 1.0));
    RB_TRY(rb_check_range(function, "linear_slop", s->linear_slop, 0.0, 0.1));
    RB_TRY(rb_check_range(function, "max_linear_correction", s->max_linear_correction, DBL_MIN, RB_MAX_LENGTH));
    RB_TRY(rb_check_range(function, "restitution_threshold", s->restitution_threshold, 0.0, RB_MAX_SPEED));
    RB_TRY(rb_check_hertz(function, "contact_hertz", s->contact_hertz, false));
    RB_TRY(rb_check_range(function, "contact_damping_ratio", s->contact_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO));
    RB_TRY(rb_check_hertz(function, "joint_hertz", s->joint_hertz, false));
    RB_TRY(rb_check_range(function, "joint_damping_ratio", s->joint_damping_ratio, 0.0, RB_MAX_DAMPING_RATIO));
    RB_TRY(rb_check_range(function, "max_push_speed", s->max_push_speed, DBL_MIN, RB_MAX_SPEED));
    return RB_OK;
}

rb_status rb_world_create(const rb_world_def *def, rb_world **out)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_create", "out", out));
    *out = NULL;
    RB_TRY(rb_check_pointer("rb_world_create", "def", def));
    RB_TRY(rb_check_def_cookie("rb_world_create", "rb_default_world_def", def->internal_value));
    RB_TRY(rb_check_vec2_bound("rb_world_create", "gravity", def->gravity, RB_MAX_ACCELERATION, "m/s²"));
    RB_TRY(check_settings(&def->solver, "rb_world_create"));
    rb_world *world = rb_alloc(sizeof *world);
    if (world == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_create: out of memory");
    }
    memset(world, 0, sizeof *world);
    world->serial = atomic_fetch_add(&next_world_serial, 1);
    world->gravity = def->gravity;
    world->settings = def->solver;
    world->profiling = def->enable_profile;
    world->enable_sleep = def->enable_sleep;
    world->body_free = -1;
    world->shape_free = -1;
    world->joint_free = -1;
    world->cable_free = -1;
    world->last_substep = 1.0 / 60.0;
    *out = world;
    return RB_OK;
}

void rb_world_destroy(rb_world *world)
{
    if (world == NULL) {
        return;
    }
    rb_free_array((void **)&world->bodies, &world->body_capacity, sizeof *world->bodies);
    rb_free_array((void **)&world->states, &world->state_capacity, sizeof *world->states);
    rb_free_array((void **)&world->saved_states, &world->saved_state_capacity, sizeof *world->saved_states);
    rb_free_array((void **)&world->shapes, &world->shape_capacity, sizeof *world->shapes);
    rb_free_array((void **)&world->contacts, &world->contact_capacity, sizeof *world->contacts);
    rb_free_array((void **)&world->spare_contacts, &world->spare_capacity, sizeof *world->spare_contacts);
    rb_free_array((void **)&world->pairs, &world->pair_capacity, sizeof *world->pairs);
    rb_free_array((void **)&world->sorted_pairs, &world->sorted_pair_capacity, sizeof *world->sorted_pairs);
    rb_free_array((void **)&world->new_pairs, &world->new_pair_capacity, sizeof *world->new_pairs);
    rb_free_array((void **)&world->ended_pairs, &world->ended_pair_capacity, sizeof *world->ended_pairs);
    rb_free_array((void **)&world->pair_bucket, &world->pair_bucket_capacity, sizeof *world->pair_bucket);
    rb_free_array((void **)&world->active_joints, &world->active_joint_capacity, sizeof *world->active_joints);
    rb_free_array((void **)&world->velocity_joints, &world->velocity_joint_capacity, sizeof *world->velocity_joints);
    rb_free_array((void **)&world->substep_omega, &world->substep_omega_capacity, sizeof *world->substep_omega);
    rb_free_array((void **)&world->point_blocks, &world->point_block_capacity, sizeof *world->point_blocks);
    rb_free_array((void **)&world->pin_rows, &world->pin_row_capacity, sizeof *world->pin_rows);
    rb_free_array((void **)&world->pin_anchors, &world->pin_anchor_capacity, sizeof *world->pin_anchors);
    rb_free_array((void **)&world->pin_row_of, &world->pin_row_of_capacity, sizeof *world->pin_row_of);
    rb_free_array((void **)&world->ordered_joints, &world->ordered_joint_capacity, sizeof *world->ordered_joints);
    rb_free_array((void **)&world->joint_order_scratch, &world->joint_order_scratch_capacity,
                  sizeof *world->joint_order_scratch);
    rb_free_array((void **)&world->joint_keys, &world->joint_key_capacity, sizeof *world->joint_keys);
    rb_free_array((void **)&world->body_depth, &world->body_depth_capacity, sizeof *world->body_depth);
    rb_free_array((void **)&world->body_queue, &world->body_queue_capacity, sizeof *world->body_queue);
    rb_free_array((void **)&world->joint_ends, &world->joint_end_capacity, sizeof *world->joint_ends);
    rb_free_array((void **)&world->body_edge_start, &world->body_edge_start_capacity, sizeof *world->body_edge_start);
    rb_free_array((void **)&world->body_edges, &world->body_edge_capacity, sizeof *world->body_edges);
    rb_colouring_free(&world->joint_colouring);
    rb_free_array((void **)&world->sweep, &world->sweep_capacity, sizeof *world->sweep);
    rb_free_array((void **)&world->refits, &world->refit_capacity, sizeof *world->refits);
    rb_free_array((void **)&world->wide_shapes, &world->wide_shape_capacity, sizeof *world->wide_shapes);
    rb_free_array((void **)&world->band_entries, &world->band_entry_capacity, sizeof *world->band_entries);
    rb_free_array((void **)&world->band_end, &world->band_end_capacity, sizeof *world->band_end);
    rb_free_array((void **)&world->island_parent, &world->island_capacity, sizeof *world->island_parent);
    rb_free_array((void **)&world->island_size, &world->island_size_capacity, sizeof *world->island_size);
    rb_free_array((void **)&world->island_rest, &world->island_rest_capacity, sizeof *world->island_rest);
    rb_free_array((void **)&world->moving_bodies, &world->moving_body_capacity, sizeof *world->moving_bodies);
    rb_free_array((void **)&world->constraints, &world->constraint_capacity, sizeof *world->constraints);
    rb_colouring_free(&world->contact_colouring);
    rb_contact_batches_free(&world->contact_batches);
    rb_contact_rows_free(&world->contact_rows);
    rb_joint_tree_free(world);
    rb_free_array((void **)&world->joints, &world->joint_capacity, sizeof *world->joints);
    rb_free_array((void **)&world->cables, &world->cable_capacity, sizeof *world->cables);
    rb_contact_events_free(world);
    rb_free(world, sizeof *world);
}

/* ---- settings ------------------------------------------------------------ */

rb_status rb_world_set_gravity(rb_world *world, rb_vec2 gravity)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_set_gravity", "world", world));
    RB_TRY(rb_world_check_unlocked(world, "rb_world_set_gravity"));
    RB_TRY(rb_check_vec2_bound("rb_world_set_gravity", "gravity", gravity, RB_MAX_ACCELERATION, "m/s²"));
    world->gravity = gravity;
    return RB_OK;
}

rb_vec2 rb_world_gravity(const rb_world *world) { return world != NULL ? world->gravity : rb_v2(0.0, 0.0); }

rb_status rb_world_set_solver_settings(rb_world *world, const rb_solver_settings *settings)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_set_solver_settings", "world", world));
    RB_TRY(rb_world_check_unlocked(world, "rb_world_set_solver_settings"));
    RB_TRY(check_settings(settings, "rb_world_set_solver_settings"));
    world->settings = *settings;
    world->boxes_stale = true; /* the speculative margin may have changed */
    return RB_OK;
}

rb_status rb_world_set_substep_callback(rb_world *world, rb_substep_fn *callback, void *context)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_set_substep_callback", "world", world));
    RB_TRY(rb_world_check_unlocked(world, "rb_world_set_substep_callback"));
    world->substep_callback = callback;
    world->substep_context = context;
    return RB_OK;
}

rb_status rb_world_enable_sleep(rb_world *world, bool enable)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_enable_sleep", "world", world));
    RB_TRY(rb_world_check_unlocked(world, "rb_world_enable_sleep"));
    world->enable_sleep = enable;
    for (int i = 0; !enable && i < world->body_slots; ++i) {
        if (world->bodies[i].in_use) {
            rb_body_wake(world, i);
        }
    }
    return RB_OK;
}

bool rb_world_is_sleep_enabled(const rb_world *world) { return world != NULL && world->enable_sleep; }

rb_solver_settings rb_world_solver_settings(const rb_world *world)
{
    return world != NULL ? world->settings : rb_default_solver_settings();
}

double rb_world_clock(const rb_world *world) { return world->profiling ? rb_now_ms() : 0.0; }

rb_status rb_world_enable_profile(rb_world *world, bool enable)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_enable_profile", "world", world));
    world->profiling = enable;
    return RB_OK;
}

rb_profile rb_world_profile(const rb_world *world) { return world != NULL ? world->profile : (rb_profile){0}; }

rb_statistics rb_world_statistics(const rb_world *world)
{
    return world != NULL ? world->statistics : (rb_statistics){0};
}

size_t rb_world_bytes_in_use(const rb_world *world)
{
    if (world == NULL) {
        return 0;
    }
    return sizeof *world + (size_t)world->body_capacity * sizeof *world->bodies +
           (size_t)world->state_capacity * sizeof *world->states +
           (size_t)world->saved_state_capacity * sizeof *world->saved_states +
           (size_t)world->shape_capacity * sizeof *world->shapes +
           (size_t)world->contact_capacity * sizeof *world->contacts +
           (size_t)world->spare_capacity * sizeof *world->spare_contacts +
           (size_t)world->pair_capacity * sizeof *world->pairs +
           (size_t)world->sorted_pair_capacity * sizeof *world->sorted_pairs +
           (size_t)world->new_pair_capacity * sizeof *world->new_pairs +
           (size_t)world->ended_pair_capacity * sizeof *world->ended_pairs +
           (size_t)world->pair_bucket_capacity * sizeof *world->pair_bucket +
           (size_t)world->sweep_capacity * sizeof *world->sweep +
           (size_t)world->refit_capacity * sizeof *world->refits +
           (size_t)world->wide_shape_capacity * sizeof *world->wide_shapes +
           (size_t)world->band_entry_capacity * sizeof *world->band_entries +
           (size_t)world->band_end_capacity * sizeof *world->band_end +
           (size_t)world->moving_body_capacity * sizeof *world->moving_bodies +
           (size_t)world->constraint_capacity * sizeof *world->constraints +
           (size_t)world->contact_colouring.body_capacity * sizeof *world->contact_colouring.body_colours +
           rb_contact_batches_bytes(&world->contact_batches) + rb_contact_rows_bytes(&world->contact_rows) +
           (size_t)world->joint_capacity * sizeof *world->joints +
           (size_t)world->point_block_capacity * sizeof *world->point_blocks +
           (size_t)world->pin_row_capacity * sizeof *world->pin_rows +
           (size_t)world->pin_anchor_capacity * sizeof *world->pin_anchors +
           (size_t)world->pin_row_of_capacity * sizeof *world->pin_row_of +
           (size_t)world->ordered_joint_capacity * sizeof *world->ordered_joints +
           (size_t)world->joint_order_scratch_capacity * sizeof *world->joint_order_scratch +
           (size_t)world->joint_key_capacity * sizeof *world->joint_keys +
           (size_t)world->body_depth_capacity * sizeof *world->body_depth +
           (size_t)world->body_queue_capacity * sizeof *world->body_queue +
           (size_t)world->joint_end_capacity * sizeof *world->joint_ends +
           (size_t)world->body_edge_start_capacity * sizeof *world->body_edge_start +
           (size_t)world->body_edge_capacity * sizeof *world->body_edges +
           (size_t)world->joint_colouring.body_capacity * sizeof *world->joint_colouring.body_colours +
           (size_t)world->cable_capacity * sizeof *world->cables + rb_contact_events_bytes(world);
}

/* ---- ids ----------------------------------------------------------------- */

rb_status rb_world_check_unlocked(const rb_world *world, const char *function)
{
    if (world->locked) {
        return rb_report_error(RB_ERR_LOCKED, "%s: the world is stepping; change it between steps", function);
    }
    return RB_OK;
}

rb_status rb_world_check_unlocked_or_in_substep_callback(const rb_world *world, const char *function)
{
    return world->in_substep_callback ? RB_OK : rb_world_check_unlocked(world, function);
}

static rb_status find_slot(const rb_world *world, int32_t index, uint64_t id_world, uint32_t generation,
                           const char *function, const char *kind, int slots, bool in_use, uint32_t slot_generation)
{
    if (world == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: world is NULL", function);
    }
    if (generation == 0) {
        return rb_report_error(RB_ERR_FOREIGN_ID, "%s: the %s id is null", function, kind);
    }
    if (id_world != world->serial || index < 0 || index >= slots) {
        return rb_report_error(RB_ERR_FOREIGN_ID, "%s: the %s id (index %d) belongs to another world", function, kind,
                               (int)index);
    }
    if (!in_use || slot_generation != generation) {
        return rb_report_error(RB_ERR_STALE_ID, "%s: the %s id (index %d, generation %u) refers to a destroyed %s",
                               function, kind, (int)index, (unsigned)generation, kind);
    }
    return RB_OK;
}

rb_status rb_world_find_body(const rb_world *world, rb_body_id id, const char *function, int *index)
{
    /* A live body's id, the common case (every getter asks), in one test;
     * a slot in use never has generation 0, so the null id fails it. */
    if (world != NULL && id.world == world->serial && id.index >= 0 && id.index < world->body_slots &&
        world->bodies[id.index].in_use && world->bodies[id.index].generation == id.generation) {
        *index = id.index;
        return RB_OK;
    }
    bool valid_index = world != NULL && id.index >= 0 && id.index < world->body_slots;
    const rb_body *body = valid_index ? &world->bodies[id.index] : NULL;
    RB_TRY(find_slot(world, id.index, id.world, id.generation, function, "body", world != NULL ? world->body_slots : 0,
                     body != NULL && body->in_use, body != NULL ? body->generation : 0));
    *index = id.index;
    return RB_OK;
}

rb_status rb_world_find_shape(const rb_world *world, rb_shape_id id, const char *function, int *index)
{
    bool valid_index = world != NULL && id.index >= 0 && id.index < world->shape_slots;
    const rb_shape *shape = valid_index ? &world->shapes[id.index] : NULL;
    RB_TRY(find_slot(world, id.index, id.world, id.generation, function, "shape",
                     world != NULL ? world->shape_slots : 0, shape != NULL && shape->in_use,
                     shape != NULL ? shape->generation : 0));
    *index = id.index;
    return RB_OK;
}

rb_status rb_world_find_joint(const rb_world *world, rb_joint_id id, const char *function, int *index)
{
    bool valid_index = world != NULL && id.index >= 0 && id.index < world->joint_slots;
    const rb_joint *joint = valid_index ? &world->joints[id.index] : NULL;
    RB_TRY(find_slot(world, id.index, id.world, id.generation, function, "joint",
                     world != NULL ? world->joint_slots : 0, joint != NULL && joint->in_use,
                     joint != NULL ? joint->generation : 0));
    *index = id.index;
    return RB_OK;
}

rb_joint_id rb_make_joint_id(const rb_world *world, int index)
{
    assert(index >= 0 && index < world->joint_slots && world->joints[index].in_use);
    return (rb_joint_id){index, world->joints[index].generation, world->serial};
}

rb_body_id rb_make_body_id(const rb_world *world, int index)
{
    assert(index >= 0 && index < world->body_slots && world->bodies[index].in_use);
    return (rb_body_id){index, world->bodies[index].generation, world->serial};
}

rb_shape_id rb_make_shape_id(const rb_world *world, int index)
{
    assert(index >= 0 && index < world->shape_slots && world->shapes[index].in_use);
    return (rb_shape_id){index, world->shapes[index].generation, world->serial};
}

/* ---- the step ------------------------------------------------------------ */

/* A dynamic body's kinetic energy and potential energy in gravity. */
static double mechanical_energy(const rb_world *world, int i)
{
    const rb_body *body = &world->bodies[i];
    const rb_body_state *s = &world->states[i];
    rb_vec2 gravity = rb_scale(body->gravity_scale, world->gravity);
    return 0.5 * body->mass * rb_length_squared(s->linear_velocity) +
           0.5 * body->inertia * s->angular_velocity * s->angular_velocity - body->mass * rb_dot(gravity, s->center);
}

/* Clears the forces applied for this step, recomputes each moving body's
 * rotation from its angle (the solvers composed small turns,
 * rb_body_state_turn), sums the energy and refreshes the counters, in one
 * pass over the bodies. */
static void finalize_step(rb_world *world)
{
    double energy = 0.0;
    for (int i = 0; i < world->body_slots; ++i) {
        rb_body *body = &world->bodies[i];
        body->force = rb_v2(0.0, 0.0);
        body->torque = 0.0;
        if (body->in_use && body->awake && body->type != RB_BODY_STATIC) {
            world->states[i].rotation = rb_rot_from_angle(world->states[i].angle);
        }
        if (body->in_use && body->type == RB_BODY_DYNAMIC) {
            energy += mechanical_energy(world, i);
        }
    }
    rb_statistics *stats = &world->statistics;
    stats->energy = energy;
    stats->body_count = world->body_count;
    stats->shape_count = world->shape_count;
    stats->pair_count = world->contact_count;
    stats->contact_count = 0;
    stats->manifold_point_count = 0;
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *contact = &world->contacts[i];
        stats->contact_count += contact->manifold.point_count > 0 ? 1 : 0;
        stats->manifold_point_count += contact->manifold.point_count;
    }
    stats->joint_count = world->joint_count;
    rb_joints_measure_errors(world, &stats->max_joint_gap, &stats->max_joint_angle_error);
}

/* The first dynamic body whose pose or velocity is NaN or infinite,
 * else the first other such body, else -1. (A static body's state turns
 * NaN too once the impulses are infinite: the solvers add them times its
 * inverse mass, 0.) A product 0·x is NaN exactly when x is not finite,
 * so one sum per body tests all six numbers: a few thousand instructions
 * a step for 200 bodies, a twentieth of a percent of a pyramid's step. */
static int first_non_finite_body(const rb_world *world)
{
    int found = -1;
    for (int i = 0; i < world->body_slots; ++i) {
        const rb_body_state *s = &world->states[i];
        double probe = 0.0 * s->center.x + 0.0 * s->center.y + 0.0 * s->angle + 0.0 * s->linear_velocity.x +
                       0.0 * s->linear_velocity.y + 0.0 * s->angular_velocity;
        if (probe != 0.0 && world->bodies[i].in_use) {
            if (world->bodies[i].type == RB_BODY_DYNAMIC) {
                return i;
            }
            found = found < 0 ? i : found;
        }
    }
    return found;
}

/* Copies the live bodies' states to saved_states before the solver runs.
 * A loop of its own rather than memcpy: glibc copies a block that size
 * with `rep movsb`, which callgrind counts as one instruction a byte
 * (13 k a step for a 210-body pyramid, bench/count_instructions.sh); the
 * test of in_use keeps the compiler from turning the loop into memcpy. */
static void save_states(rb_world *world)
{
    for (int i = 0; i < world->body_slots; ++i) {
        if (world->bodies[i].in_use) {
            world->saved_states[i] = world->states[i];
        }
    }
}

/* Puts the bodies back where the step found them, after the solver left
 * `body` non-finite; the warm-start impulses, which the same failure
 * made non-finite, start again from 0. */
static rb_status restore_failed_step(rb_world *world, int body, const rb_statistics *statistics, double last_substep)
{
    const rb_body_state s = world->states[body];
    const rb_body_state before = world->saved_states[body];
    for (int i = 0; i < world->body_slots; ++i) {
        if (world->bodies[i].in_use) {
            world->states[i] = world->saved_states[i];
        }
    }
    rb_joints_reset_impulses(world);
    rb_cables_reset_impulses(world);
    for (int i = 0; i < world->contact_count; ++i) {
        rb_manifold *manifold = &world->contacts[i].manifold;
        for (int k = 0; k < manifold->point_count; ++k) {
            manifold->points[k].normal_impulse = 0.0;
            manifold->points[k].tangent_impulse = 0.0;
        }
    }
    world->statistics = *statistics;
    world->last_substep = last_substep;
    return rb_report_error(RB_ERR_NOT_FINITE,
                           "rb_world_step: body %d (mass %g kg, at (%g, %g) m moving at (%g, %g) m/s before the "
                           "step) became non-finite in the solver's substeps (forces, joints, cables and contacts): "
                           "centre (%g, %g) m, angle %g rad, velocity (%g, %g) m/s, angular velocity %g rad/s. The "
                           "world is as it was before the step, without its warm-start impulses",
                           body, world->bodies[body].mass, before.center.x, before.center.y, before.linear_velocity.x,
                           before.linear_velocity.y, s.center.x, s.center.y, s.angle, s.linear_velocity.x,
                           s.linear_velocity.y, s.angular_velocity);
}

rb_status rb_world_step(rb_world *world, double dt)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_step", "world", world));
    RB_TRY(rb_world_check_unlocked(world, "rb_world_step"));
    RB_TRY(rb_check_range("rb_world_step", "dt", dt, RB_MIN_STEP, RB_MAX_STEP));
    world->locked = true;
    rb_profile *profile = &world->profile;
    *profile = (rb_profile){0};
    const double start = rb_world_clock(world);

    rb_status status = rb_broad_phase_update_pairs(world, dt);
    if (status == RB_OK) {
        status = rb_contacts_update(world);
    }
    double t = rb_world_lap(world, &profile->pairs, start);

    if (status == RB_OK) {
        rb_contacts_collide(world, dt);
        t = rb_world_lap(world, &profile->collide, t);
        status = rb_islands_wake(world);
        (void)rb_world_lap(world, &profile->islands, t);
    }
    const rb_statistics statistics = world->statistics;
    const double last_substep = world->last_substep;
    if (status == RB_OK) {
        save_states(world);
        status = rb_solver_step(world, dt);
    }
    int failed_body = status == RB_OK ? first_non_finite_body(world) : -1;
    if (failed_body >= 0) {
        status = restore_failed_step(world, failed_body, &statistics, last_substep);
    }
    if (status != RB_OK) {
        world->locked = false;
        return status;
    }

    t = rb_world_clock(world);
    if (world->solid_shape_count < world->shape_count) {
        rb_contacts_update_sensors(world); /* a world without sensors need not look for their contacts */
    }
    t = rb_world_lap(world, &profile->sensors, t);
    finalize_step(world);
    t = rb_world_lap(world, &profile->finalize, t);
    rb_islands_sleep(world, dt);
    t = rb_world_lap(world, &profile->islands, t);
    profile->step = t - start;
    world->locked = false;
    return RB_OK;
}

/* ---- inspection ---------------------------------------------------------- */

/* FNV-1a, 64 bits (Fowler, Noll, Vo), over the bytes of each value. */
static uint64_t hash_bytes(uint64_t hash, const void *data, size_t size)
{
    const unsigned char *bytes = data;
    for (size_t i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= 1099511628211ull;
    }
    return hash;
}

uint64_t rb_world_state_hash(const rb_world *world)
{
    uint64_t hash = 14695981039346656037ull;
    if (world == NULL) {
        return hash;
    }
    for (int i = 0; i < world->body_slots; ++i) {
        if (!world->bodies[i].in_use) {
            continue;
        }
        const rb_body_state *s = &world->states[i];
        const double values[6] = {s->center.x,          s->center.y,          s->angle,
                                  s->linear_velocity.x, s->linear_velocity.y, s->angular_velocity};
        hash = hash_bytes(hash, values, sizeof values);
    }
    return hash;
}

/* The contacts reported are those the narrow phase looked at in the last
 * step: the broad phase's pairs whose swept boxes overlapped. A pair whose
 * fat boxes overlap but whose shapes could not meet within the step is
 * kept by the engine, with no point, and not reported. */
int rb_world_contact_count(const rb_world *world)
{
    int count = 0;
    for (int i = 0; world != NULL && i < world->contact_count; ++i) {
        count += rb_contact_may_meet_in_step(world, &world->contacts[i]) ? 1 : 0;
    }
    return count;
}

int rb_world_contacts(const rb_world *world, rb_contact_data *out, int capacity)
{
    rb_clear_error();
    if (world == NULL || (out == NULL && capacity > 0)) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_world_contacts: world or out is NULL");
        return 0;
    }
    int count = 0;
    for (int i = 0; i < world->contact_count && count < capacity; ++i) {
        const rb_contact *c = &world->contacts[i];
        if (!rb_contact_may_meet_in_step(world, c)) {
            continue;
        }
        out[count++] = (rb_contact_data){
            .shape_a = rb_make_shape_id(world, c->pair.shape_a),
            .shape_b = rb_make_shape_id(world, c->pair.shape_b),
            .body_a = rb_make_body_id(world, c->body_a),
            .body_b = rb_make_body_id(world, c->body_b),
            .touching = c->touching,
            .sensor = c->sensor,
            .manifold = c->manifold,
        };
    }
    return count;
}
