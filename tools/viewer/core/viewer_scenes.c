/* SPDX-License-Identifier: MIT */
#include <stdlib.h>
#include <string.h>

#include "viewer_scenes.h"

static const char *const scene_names[VIEWER_SCENE_COUNT] = {"pyramid", "chain", "pendulum", "balls", "joint-grid"};

enum { PYRAMID_BASE = 20, CHAIN_LINKS = 30, GRID_SIZE = 20, BALL_COUNT = 50 };
#define CHAIN_HEAVY_DENSITY 20.0 /* kg/m²: the heavy box is 100 times a link */
#define PENDULUM_LENGTH 1.0      /* m */
#define PENDULUM_BOB_RADIUS 0.05 /* m */
#define BALLS_SEED 1

const char *viewer_scene_name(viewer_scene_kind kind)
{
    return kind >= 0 && kind < VIEWER_SCENE_COUNT ? scene_names[kind] : "unknown";
}

bool viewer_scene_from_name(const char *name, viewer_scene_kind *kind)
{
    for (int k = 0; k < VIEWER_SCENE_COUNT; ++k) {
        if (strcmp(name, scene_names[k]) == 0) {
            *kind = (viewer_scene_kind)k;
            return true;
        }
    }
    return false;
}

/* A static pivot at the origin and a bob PENDULUM_LENGTH to its right,
 * pinned to it: released, it swings down through the vertical. */
static rb_status create_pendulum(rb_world *world)
{
    rb_body_def pivot_def = rb_default_body_def();
    rb_body_id pivot;
    rb_status status = rb_body_create(world, &pivot_def, &pivot);
    rb_body_def bob_def = rb_default_body_def();
    bob_def.type = RB_BODY_DYNAMIC;
    bob_def.position = rb_v2(PENDULUM_LENGTH, 0.0);
    rb_body_id bob;
    if (status == RB_OK) {
        status = rb_body_create(world, &bob_def, &bob);
    }
    rb_shape_def shape_def = rb_default_shape_def();
    rb_circle circle = {{0.0, 0.0}, PENDULUM_BOB_RADIUS};
    rb_shape_id shape;
    if (status == RB_OK) {
        status = rb_shape_create_circle(world, bob, &shape_def, &circle, &shape);
    }
    rb_revolute_joint_def pin = rb_default_revolute_joint_def();
    if (status == RB_OK) {
        status = rb_revolute_joint_def_at(&pin, world, pivot, bob, rb_v2(0.0, 0.0));
    }
    rb_joint_id joint;
    if (status == RB_OK) {
        status = rb_revolute_joint_create(world, &pin, &joint);
    }
    return status;
}

static rb_status populate(viewer_scene *scene)
{
    switch (scene->kind) {
    case VIEWER_SCENE_PYRAMID: {
        scene_pyramid pyramid;
        scene->view_centre = rb_v2(0.0, 0.45 * PYRAMID_BASE);
        scene->view_extent = 1.2 * PYRAMID_BASE;
        return scene_pyramid_create(scene->world, PYRAMID_BASE, &pyramid);
    }
    case VIEWER_SCENE_CHAIN: {
        scene_chain *chain = malloc(sizeof *chain);
        if (chain == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "viewer_scene_create: no memory for the chain");
        }
        double length = 0.5 * CHAIN_LINKS + 0.5;
        scene->view_centre = rb_v2(0.0, -0.45 * length);
        scene->view_extent = 2.2 * length;
        rb_status status = scene_chain_create(scene->world, CHAIN_LINKS, CHAIN_HEAVY_DENSITY, SCENE_CHAIN_SWING, chain);
        free(chain);
        return status;
    }
    case VIEWER_SCENE_PENDULUM:
        scene->view_centre = rb_v2(0.0, -0.4 * PENDULUM_LENGTH);
        scene->view_extent = 2.5 * PENDULUM_LENGTH;
        return create_pendulum(scene->world);
    case VIEWER_SCENE_BALLS:
        scene->balls = malloc(sizeof *scene->balls);
        if (scene->balls == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "viewer_scene_create: no memory for the balls");
        }
        scene->view_centre = rb_v2(0.5 * SCENE_BALLS_WIDTH, 0.5 * SCENE_BALLS_HEIGHT);
        scene->view_extent = 1.3 * SCENE_BALLS_WIDTH;
        return scene_balls_create(scene->world, BALL_COUNT, BALLS_SEED, scene->balls);
    case VIEWER_SCENE_JOINT_GRID: {
        scene_joint_grid grid;
        scene->view_centre = rb_v2(0.5 * (GRID_SIZE - 1), -0.5 * (GRID_SIZE - 1));
        scene->view_extent = 1.3 * GRID_SIZE;
        return scene_joint_grid_create(scene->world, GRID_SIZE, &grid);
    }
    case VIEWER_SCENE_COUNT:
        break;
    }
    return rb_report_error(RB_ERR_INVALID_ARGUMENT, "viewer_scene_create: unknown scene %d", (int)scene->kind);
}

rb_status viewer_scene_create(viewer_scene_kind kind, viewer_scene *out)
{
    *out = (viewer_scene){.kind = kind};
    rb_world_def def = rb_default_world_def();
    if (kind == VIEWER_SCENE_PYRAMID || kind == VIEWER_SCENE_CHAIN || kind == VIEWER_SCENE_JOINT_GRID) {
        def.gravity = rb_v2(0.0, -10.0); /* the peers' gravity, shared/peers/README.md */
    } else if (kind == VIEWER_SCENE_BALLS) {
        def.gravity = rb_v2(0.0, -9.81); /* the seed's, shared/spec/models.md */
    }
    rb_status status = rb_world_create(&def, &out->world);
    if (status == RB_OK) {
        status = populate(out);
    }
    if (status != RB_OK) {
        viewer_scene_destroy(out);
    }
    return status;
}

void viewer_scene_destroy(viewer_scene *scene)
{
    rb_world_destroy(scene->world);
    free(scene->balls);
    *scene = (viewer_scene){.kind = scene->kind};
}

rb_status viewer_scene_step(viewer_scene *scene)
{
    if (scene->balls != NULL) {
        rb_status status = scene_balls_apply_drag(scene->world, scene->balls);
        if (status != RB_OK) {
            return status;
        }
    }
    return rb_world_step(scene->world, VIEWER_SCENE_DT);
}
