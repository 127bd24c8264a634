/* SPDX-License-Identifier: MIT */
/* The engine scenes a user can open by name, listed once for every
 * program that offers them (`sinew scene NAME`, `sinew view --scene NAME`
 * and the viewer's scene picker): each scene's name, a line about it, its
 * parameters with their ranges and defaults, the gravity it runs under,
 * and the part of the world worth showing. The scenes themselves are
 * built by scenes.h.
 */
#ifndef SCENES_REGISTRY_H
#define SCENES_REGISTRY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rb/rb.h"
#include "scenes/scenes.h"

typedef enum scene_kind {
    SCENE_PYRAMID,    /* the Box2D and Chipmunk benchmarks' pyramid of boxes */
    SCENE_STACK,      /* a vertical stack of boxes */
    SCENE_BALLS,      /* balls in a closed box, with linear drag */
    SCENE_INCLINE,    /* a box on a tilted plank: sliding or held by friction */
    SCENE_DROP,       /* a ball dropped on the ground: restitution */
    SCENE_CHAIN,      /* the benchmarks' chain with a heavy box, released horizontally */
    SCENE_PENDULUM,   /* a pendulum released horizontally */
    SCENE_JOINT_GRID, /* the benchmarks' grid of circles held by revolute joints */
    SCENE_KIND_COUNT
} scene_kind;

typedef enum scene_parameter_kind {
    SCENE_INTEGER, /* a whole number in [min, max] */
    SCENE_NUMBER,  /* a finite number in [min, max], or (min, max] when min_open */
    SCENE_SEED,    /* a random seed, 0 .. 2^64 - 1 */
} scene_parameter_kind;

/* A parameter's value: `seed` for SCENE_SEED, `number` otherwise. */
typedef union scene_value {
    double number;
    uint64_t seed;
} scene_value;

enum { SCENE_MAX_PARAMETERS = 2 };

typedef struct scene_parameter {
    const char *name;       /* "base": `--base` on a command line */
    const char *value_name; /* what the value is, for a usage text: "N", "M", "DEG" */
    const char *help;       /* what it sets */
    const char *unit;       /* of the value, for a summary: "m", "deg", "" */
    scene_parameter_kind kind;
    double min, max;
    bool min_open;
    scene_value fallback; /* the default */
} scene_parameter;

typedef struct scene_entry {
    const char *name;    /* "joint-grid" */
    const char *summary; /* one line */
    scene_parameter parameters[SCENE_MAX_PARAMETERS];
    int parameter_count;
    const rb_vec2 *gravity; /* m/s²; NULL: the engine's default */
} scene_entry;

/* The scenes, indexed by scene_kind. */
extern const scene_entry scene_registry[SCENE_KIND_COUNT];

/* The scenes' names as a list for a message, "pyramid, stack, ...",
 * truncated to `size` bytes. */
void scene_list_names(char *text, size_t size);

/* The kind named `name`: false when there is none. */
bool scene_kind_from_name(const char *name, scene_kind *kind);

/* Fills values[0 .. parameter_count - 1] with the scene's defaults. */
void scene_default_values(scene_kind kind, scene_value values[SCENE_MAX_PARAMETERS]);

/* The index of the scene's parameter called `name`, or -1. */
int scene_find_parameter(scene_kind kind, const char *name);

/* rb_default_world_def() with the scene's gravity: a caller may change its
 * solver settings before scene_instance_create. */
rb_world_def scene_world_def(scene_kind kind);

/* One scene built in a world of its own. */
typedef struct scene_instance {
    scene_kind kind;
    rb_world *world;
    scene_value values[SCENE_MAX_PARAMETERS]; /* as built */
    union {
        scene_pyramid pyramid;
        scene_stack stack;
        scene_incline incline;
        scene_drop drop;
        scene_pendulum pendulum;
        scene_joint_grid joint_grid;
    } ids;              /* of the scene built, for those that a caller measures */
    scene_balls *balls; /* the balls' ids (their drag needs them); NULL for the other scenes */
    rb_body_id *bodies; /* the dynamic bodies, in the order they were created */
    int body_count;
    rb_vec2 view_centre; /* m: the middle of what is worth showing at the start */
    double view_extent;  /* m: how much of the world a view's shorter side shows at the start */
} scene_instance;

/* Builds the scene with `values` (each in its parameter's range) in a new
 * world made from `def` (scene_world_def(kind), or changed from it). On
 * failure nothing is left, rb_last_error() says why, and the status is
 * RB_ERR_INVALID_ARGUMENT for values the scene refuses. */
rb_status scene_instance_create(scene_kind kind, const scene_value values[SCENE_MAX_PARAMETERS],
                                const rb_world_def *def, scene_instance *out);

/* Accepts an instance that was never created (zeroed) or already destroyed. */
void scene_instance_destroy(scene_instance *scene);

/* What the scene does before every step of its world (the balls' drag);
 * call it before each rb_world_step. */
rb_status scene_instance_before_step(scene_instance *scene);

#endif
