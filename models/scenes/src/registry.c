/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenes/registry.h"

/* The benchmark scenes of Box2D and Chipmunk that sinew is compared with
 * (the peers) run under 10 m/s²; the original report's balls box under
 * 9.81. */
static const rb_vec2 peers_gravity = {0.0, -10.0};
static const rb_vec2 balls_gravity = {0.0, -9.81};

/* The chain's heavy box, 100 times a link, as in the peers' chain. */
#define CHAIN_HEAVY_DENSITY 20.0 /* kg/m² */

#define INTEGER(name_, value_name_, help_, min_, max_, fallback_)                                                      \
    {                                                                                                                  \
        .name = name_, .value_name = value_name_, .help = help_, .unit = "", .kind = SCENE_INTEGER, .min = min_,       \
        .max = max_, .fallback = {                                                                                     \
            .number = fallback_                                                                                        \
        }                                                                                                              \
    }
#define NUMBER(name_, value_name_, help_, unit_, min_, min_open_, max_, fallback_)                                     \
    {                                                                                                                  \
        .name = name_, .value_name = value_name_, .help = help_, .unit = unit_, .kind = SCENE_NUMBER, .min = min_,     \
        .max = max_, .min_open = min_open_, .fallback = {                                                              \
            .number = fallback_                                                                                        \
        }                                                                                                              \
    }

const scene_entry scene_registry[SCENE_KIND_COUNT] = {
    [SCENE_PYRAMID] = {"pyramid",
                       "a pyramid of boxes, as in the Box2D and Chipmunk benchmarks",
                       {INTEGER("base", "N", "boxes in the bottom row", 1, 1000, 20)},
                       1,
                       &peers_gravity},
    [SCENE_STACK] = {"stack", "a vertical stack of boxes", {INTEGER("count", "N", "boxes", 1, 1000, 10)}, 1, NULL},
    [SCENE_BALLS] = {"balls",
                     "balls of random sizes kicked about a closed box, with linear drag",
                     {INTEGER("count", "N", "balls", 1, SCENE_BALLS_MAX, 50),
                      {.name = "seed",
                       .value_name = "N",
                       .help = "random seed",
                       .unit = "",
                       .kind = SCENE_SEED,
                       .fallback = {.seed = 1}}},
                     2,
                     &balls_gravity},
    [SCENE_INCLINE] = {"incline",
                       "a box on a tilted plank, held by friction or sliding",
                       {NUMBER("angle", "DEG", "the plank's angle", "deg", 0.0, false, 80.0, 25.0),
                        NUMBER("friction", "MU", "friction coefficient", "", 0.0, false, 100.0, 0.6)},
                       2,
                       NULL},
    [SCENE_DROP] = {"drop",
                    "a ball dropped on the ground",
                    {NUMBER("height", "M", "height of the ball above the ground", "m", 0.0, true, 1000.0, 1.0),
                     NUMBER("restitution", "E", "restitution", "", 0.0, false, 1.0, 0.5)},
                    2,
                    NULL},
    [SCENE_CHAIN] = {"chain",
                     "a chain of links and a heavy box released horizontally, as in the benchmarks",
                     {INTEGER("links", "N", "links", 1, SCENE_CHAIN_MAX_LINKS, 30)},
                     1,
                     &peers_gravity},
    [SCENE_PENDULUM] = {"pendulum",
                        "a pendulum released horizontally",
                        {NUMBER("length", "M", "length", "m", 0.0, true, 100.0, 1.0)},
                        1,
                        NULL},
    [SCENE_JOINT_GRID] = {"joint-grid",
                          "a grid of circles held by revolute joints, as in the benchmarks",
                          {INTEGER("size", "N", "circles along each side", 2, 1000, 20)},
                          1,
                          &peers_gravity},
};

void scene_list_names(char *text, size_t size)
{
    size_t used = 0;
    text[0] = '\0';
    for (int k = 0; k < SCENE_KIND_COUNT && used < size; ++k) {
        used += (size_t)snprintf(text + used, size - used, "%s%s", k == 0 ? "" : ", ", scene_registry[k].name);
    }
}

bool scene_kind_from_name(const char *name, scene_kind *kind)
{
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        if (strcmp(name, scene_registry[k].name) == 0) {
            *kind = (scene_kind)k;
            return true;
        }
    }
    return false;
}

void scene_default_values(scene_kind kind, scene_value values[SCENE_MAX_PARAMETERS])
{
    for (int p = 0; p < scene_registry[kind].parameter_count; ++p) {
        values[p] = scene_registry[kind].parameters[p].fallback;
    }
}

int scene_find_parameter(scene_kind kind, const char *name)
{
    for (int p = 0; p < scene_registry[kind].parameter_count; ++p) {
        if (strcmp(name, scene_registry[kind].parameters[p].name) == 0) {
            return p;
        }
    }
    return -1;
}

rb_world_def scene_world_def(scene_kind kind)
{
    rb_world_def def = rb_default_world_def();
    if (scene_registry[kind].gravity != NULL) {
        def.gravity = *scene_registry[kind].gravity;
    }
    return def;
}

/* Builds the scene of scene->kind in scene->world from scene->values,
 * says where it is, and sets *known to one of its bodies. */
static rb_status build(scene_instance *scene, rb_body_id *known)
{
    rb_status status = RB_OK;
    rb_world *world = scene->world;
    const scene_value *values = scene->values;
    switch (scene->kind) {
    case SCENE_PYRAMID: {
        double base = values[0].number;
        scene->view_centre = rb_v2(0.0, 0.45 * base);
        scene->view_extent = 1.2 * base + 2.0;
        status = scene_pyramid_create(world, (int)base, &scene->ids.pyramid);
        *known = scene->ids.pyramid.ground;
        return status;
    }
    case SCENE_STACK: {
        double count = values[0].number;
        scene->view_centre = rb_v2(0.0, 0.5 * count);
        scene->view_extent = 1.2 * count + 2.0;
        status = scene_stack_create(world, (int)count, &scene->ids.stack);
        *known = scene->ids.stack.ground;
        return status;
    }
    case SCENE_BALLS:
        scene->balls = calloc(1, sizeof *scene->balls);
        if (scene->balls == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "scene_instance_create: no memory for the balls");
        }
        scene->view_centre = rb_v2(0.5 * SCENE_BALLS_WIDTH, 0.5 * SCENE_BALLS_HEIGHT);
        scene->view_extent = 1.3 * SCENE_BALLS_WIDTH;
        status = scene_balls_create(world, (int)values[0].number, values[1].seed, scene->balls);
        *known = scene->balls->walls;
        return status;
    case SCENE_INCLINE:
        scene->view_centre = rb_v2(0.0, 0.0);
        scene->view_extent = 12.0;
        status = scene_incline_create(world, values[0].number * (RB_PI / 180.0), values[1].number, &scene->ids.incline);
        *known = scene->ids.incline.plank;
        return status;
    case SCENE_DROP: {
        double height = values[0].number;
        scene->view_centre = rb_v2(0.0, 0.5 * height);
        scene->view_extent = 1.4 * height + 1.0;
        status = scene_drop_create(world, height, values[1].number, &scene->ids.drop);
        *known = scene->ids.drop.ground;
        return status;
    }
    case SCENE_CHAIN: {
        /* The chain is too large to keep: nothing measures its joints. */
        scene_chain *chain = calloc(1, sizeof *chain);
        if (chain == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "scene_instance_create: no memory for the chain");
        }
        double length = 0.5 * values[0].number + 0.5;
        scene->view_centre = rb_v2(0.0, -0.45 * length);
        scene->view_extent = 2.2 * length;
        status = scene_chain_create(world, (int)values[0].number, CHAIN_HEAVY_DENSITY, SCENE_CHAIN_SWING, chain);
        *known = chain->pin;
        free(chain);
        return status;
    }
    case SCENE_PENDULUM: {
        double length = values[0].number;
        scene->view_centre = rb_v2(0.0, -0.4 * length);
        scene->view_extent = 2.5 * length;
        status = scene_pendulum_create(world, length, &scene->ids.pendulum);
        *known = scene->ids.pendulum.pivot;
        return status;
    }
    case SCENE_JOINT_GRID: {
        double size = values[0].number;
        scene->view_centre = rb_v2(0.5 * (size - 1.0), -0.5 * (size - 1.0));
        scene->view_extent = 1.3 * size;
        status = scene_joint_grid_create(world, (int)size, &scene->ids.joint_grid);
        *known = scene->ids.joint_grid.first_body;
        return status;
    }
    case SCENE_KIND_COUNT:
        break;
    }
    return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_instance_create: unknown scene %d", (int)scene->kind);
}

/* The world's dynamic bodies in creation order. The scenes build in a
 * fresh world, where the engine hands out slots 0, 1, 2, ... in order
 * (scenes.h relies on it for its runs of boxes), so the valid slots from
 * 0 up are every body. */
static rb_status collect_bodies(scene_instance *scene, rb_body_id known)
{
    int capacity = 0;
    rb_body_id id = known;
    for (id.index = 0; rb_body_is_valid(scene->world, id); ++id.index) {
        if (rb_body_type_of(scene->world, id) != RB_BODY_DYNAMIC) {
            continue;
        }
        if (scene->body_count == capacity) {
            capacity = capacity > 0 ? 2 * capacity : 64;
            rb_body_id *grown = realloc(scene->bodies, (size_t)capacity * sizeof *grown);
            if (grown == NULL) {
                return rb_report_error(RB_ERR_OUT_OF_MEMORY, "scene_instance_create: no memory for the list of bodies");
            }
            scene->bodies = grown;
        }
        scene->bodies[scene->body_count++] = id;
    }
    return RB_OK;
}

rb_status scene_instance_create(scene_kind kind, const scene_value values[SCENE_MAX_PARAMETERS],
                                const rb_world_def *def, scene_instance *out)
{
    *out = (scene_instance){.kind = kind};
    if ((int)kind < 0 || kind >= SCENE_KIND_COUNT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_instance_create: unknown scene %d", (int)kind);
    }
    for (int p = 0; p < scene_registry[kind].parameter_count; ++p) {
        out->values[p] = values[p];
    }
    rb_status status = rb_world_create(def, &out->world);
    rb_body_id known = {0};
    if (status == RB_OK) {
        status = build(out, &known);
    }
    if (status == RB_OK) {
        status = collect_bodies(out, known);
    }
    if (status != RB_OK) {
        scene_instance_destroy(out);
    }
    return status;
}

void scene_instance_destroy(scene_instance *scene)
{
    rb_world_destroy(scene->world);
    free(scene->balls);
    free(scene->bodies);
    *scene = (scene_instance){.kind = scene->kind};
}

rb_status scene_instance_before_step(scene_instance *scene)
{
    return scene->balls != NULL ? scene_balls_apply_drag(scene->world, scene->balls) : RB_OK;
}
