/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/model_source.h"
#include "cli/user_error.h"
#include "simulation.h"

/* The mouse joint's pull: this many times the dragged body's weight in
 * the model's gravity (or 10 m/s² without gravity), enough to lift a
 * forearm with its weight, not to tear a model apart. */
#define DRAG_FORCE_PER_WEIGHT 50.0
#define DRAG_HERTZ 5.0
#define DRAG_DAMPING_RATIO 0.7

static bool fail(char *error, size_t error_size, const char *what)
{
    snprintf(error, error_size, "%s", what);
    return false;
}

static bool fail_engine(char *error, size_t error_size) { return fail(error, error_size, user_error()); }

void simulation_init(simulation *sim) { *sim = (simulation){.kind = SIMULATION_NONE}; }

/* Frees what is loaded, leaving the controls' settings. */
static void unload(simulation *sim)
{
    mu_model_destroy(sim->model);
    mu_model_desc_destroy(sim->desc);
    scene_instance_destroy(&sim->scene);
    sim->model = NULL;
    sim->desc = NULL;
    sim->kind = SIMULATION_NONE;
    sim->frame = 0;
    sim->dragging = false;
    sim->pulse_pending = false;
}

void simulation_free(simulation *sim) { unload(sim); }

/* The name of the first muscle group of the built model, else its first
 * muscle, else "". */
static void first_target(const simulation *sim, char *name, size_t name_size)
{
    name[0] = '\0';
    if (mu_model_muscle_count(sim->model) == 0) {
        return;
    }
    const mu_model_variant *variant = &sim->desc->variants[sim->options.variant];
    for (int g = 0; g < sim->desc->group_count; ++g) {
        const mu_model_group *group = &sim->desc->groups[g];
        for (int k = 0; k < group->muscle_count; ++k) {
            if (mu_model_variant_has_muscle(variant, group->muscles[k])) {
                snprintf(name, name_size, "%s", group->name);
                return;
            }
        }
    }
    snprintf(name, name_size, "%s", mu_model_muscle_name(sim->model, 0));
}

static bool apply_command(simulation *sim, char *error, size_t error_size)
{
    if (sim->kind != SIMULATION_MODEL || sim->target[0] == '\0') {
        return true;
    }
    rb_status status = sim->tension_mode ? mu_model_set_tension(sim->model, sim->target, sim->tension)
                                         : mu_model_set_activation(sim->model, sim->target, sim->activation);
    return status == RB_OK || fail_engine(error, error_size);
}

/* Takes ownership of `desc` and builds it; the previous simulation stays
 * when the build fails. */
static bool install_model(simulation *sim, const char *argument, mu_model_desc *desc, const mu_model_options *options,
                          char *error, size_t error_size)
{
    mu_model *model;
    if (mu_model_create(desc, options, &model) != RB_OK) {
        fail_engine(error, error_size);
        mu_model_desc_destroy(desc);
        return false;
    }
    if (argument != sim->model_argument) { /* a reload passes the kept argument itself */
        snprintf(sim->model_argument, sizeof sim->model_argument, "%s", argument);
    }
    unload(sim);
    sim->kind = SIMULATION_MODEL;
    sim->desc = desc;
    sim->model = model;
    sim->failure_reported = false;
    sim->options = *options;
    sim->tension_mode = false;
    sim->activation = 0.0;
    first_target(sim, sim->target, sizeof sim->target);
    return apply_command(sim, error, error_size);
}

bool simulation_load_model(simulation *sim, const char *argument, const mu_model_options *options, char *error,
                           size_t error_size)
{
    mu_model_desc *desc;
    if (model_source_open(argument, &desc, error, error_size) != MODEL_SOURCE_LOADED) {
        return false;
    }
    return install_model(sim, argument, desc, options, error, error_size);
}

bool simulation_reload(simulation *sim, const mu_model_options *options, char *error, size_t error_size)
{
    if (sim->model_argument[0] == '\0') {
        return fail(error, error_size, "no model to reload");
    }
    mu_model_desc *desc;
    if (model_source_open(sim->model_argument, &desc, error, error_size) != MODEL_SOURCE_LOADED) {
        return false;
    }
    return install_model(sim, sim->model_argument, desc, options, error, error_size);
}

bool simulation_choose_variant(const simulation *sim, const char *text, mu_model_options *options, char *error,
                               size_t error_size)
{
    if (sim->kind != SIMULATION_MODEL) {
        return fail(error, error_size, "no muscle model is loaded");
    }
    *options = sim->options;
    int index = mu_model_desc_find_variant(sim->desc, text);
    char *end;
    long number = strtol(text, &end, 10);
    if (index < 0 && end != text && *end == '\0' && number >= 0 && number < sim->desc->variant_count) {
        index = (int)number;
    }
    if (index < 0) {
        int written = snprintf(error, error_size, "no variant \"%s\" in the model (variants:", text);
        for (int k = 0; k < sim->desc->variant_count && written >= 0 && (size_t)written < error_size; ++k) {
            written += snprintf(error + written, error_size - (size_t)written, "%s \"%s\"", k == 0 ? "" : ",",
                                sim->desc->variants[k].name);
        }
        if (written >= 0 && (size_t)written < error_size) {
            snprintf(error + written, error_size - (size_t)written, ", or an index from 0)");
        }
        return false;
    }
    options->variant = index;
    return true;
}

bool simulation_choose_weight(const simulation *sim, double kilograms, mu_model_options *options, char *error,
                              size_t error_size)
{
    if (sim->kind != SIMULATION_MODEL) {
        return fail(error, error_size, "no muscle model is loaded");
    }
    *options = sim->options;
    const mu_model_weight *weight = &sim->desc->weight;
    for (int k = 0; sim->desc->has_weight && k < weight->mass_count; ++k) {
        if (fabs(weight->masses[k] - kilograms) <= 1e-9 * fmax(1.0, kilograms)) {
            options->weight_index = k;
            return true;
        }
    }
    int written = snprintf(error, error_size, "no weight choice of %g kg in the model (choices:", kilograms);
    for (int k = 0; sim->desc->has_weight && k < weight->mass_count && written >= 0 && (size_t)written < error_size;
         ++k) {
        written += snprintf(error + written, error_size - (size_t)written, " %g", weight->masses[k]);
    }
    if (written >= 0 && (size_t)written < error_size) {
        snprintf(error + written, error_size - (size_t)written, " kg)");
    }
    return false;
}

bool simulation_choose_level(const simulation *sim, int level, mu_model_options *options, char *error,
                             size_t error_size)
{
    if (sim->kind != SIMULATION_MODEL) {
        return fail(error, error_size, "no muscle model is loaded");
    }
    if (level < 0 || level > 4) {
        return fail(error, error_size, "the level is 0 .. 4 (0 nothing, 1 bones, 2 + joints, 3 + muscles, 4 + weight)");
    }
    *options = sim->options;
    options->level = level;
    return true;
}

bool simulation_load_scene(simulation *sim, scene_kind kind, char *error, size_t error_size)
{
    scene_value values[SCENE_MAX_PARAMETERS];
    scene_default_values(kind, values);
    rb_world_def def = scene_world_def(kind);
    scene_instance scene;
    if (scene_instance_create(kind, values, &def, &scene) != RB_OK) {
        return fail_engine(error, error_size);
    }
    unload(sim);
    sim->kind = SIMULATION_SCENE;
    sim->scene = scene;
    sim->target[0] = '\0';
    return true;
}

rb_world *simulation_world(const simulation *sim)
{
    switch (sim->kind) {
    case SIMULATION_MODEL:
        return mu_model_world(sim->model);
    case SIMULATION_SCENE:
        return sim->scene.world;
    case SIMULATION_NONE:
        break;
    }
    return NULL;
}

double simulation_frame_duration(const simulation *sim)
{
    return sim->kind == SIMULATION_MODEL ? mu_model_frame_duration(sim->model) : SIMULATION_SCENE_DT;
}

double simulation_time(const simulation *sim)
{
    return sim->kind == SIMULATION_MODEL ? mu_model_time(sim->model) : (double)sim->frame * SIMULATION_SCENE_DT;
}

bool simulation_step(simulation *sim, char *error, size_t error_size)
{
    rb_status status = RB_OK;
    switch (sim->kind) {
    case SIMULATION_NONE:
        return true;
    case SIMULATION_SCENE:
        status = scene_instance_before_step(&sim->scene);
        if (status == RB_OK) {
            status = rb_world_step(sim->scene.world, SIMULATION_SCENE_DT);
        }
        break;
    case SIMULATION_MODEL: {
        bool pulse = sim->pulse_pending && sim->target[0] != '\0';
        sim->pulse_pending = false;
        if (pulse && mu_model_set_activation(sim->model, sim->target, 1.0) != RB_OK) {
            return fail_engine(error, error_size);
        }
        status = mu_model_step(sim->model);
        if (pulse && status == RB_OK && !apply_command(sim, error, error_size)) {
            return false;
        }
        break;
    }
    }
    if (status != RB_OK) {
        return fail_engine(error, error_size);
    }
    ++sim->frame;
    return true;
}

const char *simulation_new_failure(simulation *sim)
{
    const char *failure = sim->kind == SIMULATION_MODEL ? mu_model_failure(sim->model) : NULL;
    if (failure == NULL || sim->failure_reported) {
        return NULL;
    }
    sim->failure_reported = true;
    return failure;
}

bool simulation_select(simulation *sim, const char *name, char *error, size_t error_size)
{
    if (sim->kind != SIMULATION_MODEL) {
        return fail(error, error_size, "no muscle model is loaded");
    }
    if (!isnan(mu_model_group_activation(sim->model, name))) {
        snprintf(sim->target, sizeof sim->target, "%s", name);
        return apply_command(sim, error, error_size);
    }
    return fail_engine(error, error_size);
}

bool simulation_set_activation(simulation *sim, double activation, char *error, size_t error_size)
{
    sim->tension_mode = false;
    sim->activation = activation < 0.0 ? 0.0 : activation > 1.0 ? 1.0 : activation;
    return apply_command(sim, error, error_size);
}

bool simulation_set_tension(simulation *sim, double newtons, char *error, size_t error_size)
{
    if (!(newtons >= 0.0) || !isfinite(newtons)) {
        return fail(error, error_size, "a tension target is a finite number of newtons, >= 0");
    }
    sim->tension_mode = true;
    sim->tension = newtons;
    return apply_command(sim, error, error_size);
}

void simulation_pulse(simulation *sim) { sim->pulse_pending = sim->kind == SIMULATION_MODEL; }

bool simulation_recruit_more(simulation *sim, int delta, char *error, size_t error_size)
{
    if (sim->kind != SIMULATION_MODEL || mu_model_torque_muscle_count(sim->model) == 0) {
        return fail(error, error_size, "this model has no torque muscle to recruit (the worm has one)");
    }
    const mu_motor_pool *pool = mu_model_motor_pool(sim->model, 0);
    int wanted = mu_motor_pool_recruited(pool) + delta;
    int count = mu_motor_pool_neuron_count(pool);
    wanted = wanted < 0 ? 0 : wanted > count ? count : wanted;
    return mu_model_recruit_at(sim->model, 0, wanted) == RB_OK || fail_engine(error, error_size);
}

typedef struct pick {
    const rb_world *world;
    rb_body_id body;
    bool found;
} pick;

static bool pick_dynamic_body(rb_shape_id shape, void *context)
{
    pick *found = context;
    rb_body_id body = rb_shape_body(found->world, shape);
    if (rb_body_type_of(found->world, body) != RB_BODY_DYNAMIC) {
        return true;
    }
    found->body = body;
    found->found = true;
    return false;
}

bool simulation_drag_begin(simulation *sim, rb_vec2 point)
{
    rb_world *world = simulation_world(sim);
    simulation_drag_end(sim);
    if (world == NULL) {
        return false;
    }
    pick found = {.world = world, .found = false};
    if (rb_world_query_point(world, point, rb_default_query_filter(), true, pick_dynamic_body, &found) != RB_OK ||
        !found.found) {
        return false;
    }
    double gravity = rb_length(rb_world_gravity(world));
    rb_mouse_joint_def def = rb_default_mouse_joint_def();
    def.body = found.body;
    def.local_anchor = rb_body_local_point(world, found.body, point);
    def.target = point;
    def.max_force = DRAG_FORCE_PER_WEIGHT * rb_body_mass(world, found.body) * (gravity > 0.0 ? gravity : 10.0);
    def.hertz = DRAG_HERTZ;
    def.damping_ratio = DRAG_DAMPING_RATIO;
    if (rb_mouse_joint_create(world, &def, &sim->drag_joint) != RB_OK) {
        return false;
    }
    rb_body_set_awake(world, found.body, true);
    sim->dragging = true;
    return true;
}

void simulation_drag_move(simulation *sim, rb_vec2 point)
{
    rb_world *world = simulation_world(sim);
    if (sim->dragging && world != NULL) {
        rb_mouse_joint_set_target(world, sim->drag_joint, point);
    }
}

void simulation_drag_end(simulation *sim)
{
    rb_world *world = simulation_world(sim);
    if (sim->dragging && world != NULL && rb_joint_is_valid(world, sim->drag_joint)) {
        rb_joint_destroy(world, sim->drag_joint);
    }
    sim->dragging = false;
}
