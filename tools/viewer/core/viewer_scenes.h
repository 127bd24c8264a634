/* SPDX-License-Identifier: MIT */
/* The engine scenes the viewer loads like models (models/scenes, plus a
 * pendulum of its own): each in a world of its own, with the gravity its
 * source gives it, stepped at 60 Hz, and the part of the world to show.
 */
#ifndef VIEWER_VIEWER_SCENES_H
#define VIEWER_VIEWER_SCENES_H

#include <stdbool.h>

#include "rb/rb.h"
#include "scenes/scenes.h"

typedef enum viewer_scene_kind {
    VIEWER_SCENE_PYRAMID,    /* base 20, as the peers' benchmark */
    VIEWER_SCENE_CHAIN,      /* 30 links and a box 100 times heavier, released horizontally */
    VIEWER_SCENE_PENDULUM,   /* a 1 m pendulum released at 90° */
    VIEWER_SCENE_BALLS,      /* the seed's 50 balls in a box, with its drag */
    VIEWER_SCENE_JOINT_GRID, /* 20 × 20 circles held by revolute joints */
    VIEWER_SCENE_COUNT
} viewer_scene_kind;

typedef struct viewer_scene {
    viewer_scene_kind kind;
    rb_world *world;
    scene_balls *balls;  /* the balls scene's ids (it applies their drag); NULL for the others */
    rb_vec2 view_centre; /* m: where the view starts */
    double view_extent;  /* m: how much of the world the view's shorter side starts showing */
} viewer_scene;

/* "pyramid", "chain", "pendulum", "balls", "joint-grid". */
const char *viewer_scene_name(viewer_scene_kind kind);
/* The kind named `name`: false when there is none. */
bool viewer_scene_from_name(const char *name, viewer_scene_kind *kind);

/* Builds the scene in a new world; on failure nothing is left and
 * rb_last_error() says why. */
rb_status viewer_scene_create(viewer_scene_kind kind, viewer_scene *out);
/* Accepts a scene that was never created (zeroed) or already destroyed. */
void viewer_scene_destroy(viewer_scene *scene);
/* One step of VIEWER_SCENE_DT. */
rb_status viewer_scene_step(viewer_scene *scene);

#define VIEWER_SCENE_DT (1.0 / 60.0)

#endif
