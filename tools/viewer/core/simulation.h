/* SPDX-License-Identifier: MIT */
/* What the viewer simulates: a muscle model (a built-in name or a model
 * file, at a variant, weight choice and level) or an engine scene, with
 * the user's controls on it: the command of the selected muscle or group
 * (an activation or a tension target), one-frame pulses, the worm's
 * recruitment, and a body dragged by a mouse joint.
 *
 * Only public APIs (rb/, mu/): no GTK, so the same state runs headless.
 * Loading never loses what runs: a model that fails to load or build
 * leaves the previous simulation in place and says why in `error`.
 */
#ifndef VIEWER_SIMULATION_H
#define VIEWER_SIMULATION_H

#include <stdbool.h>
#include <stddef.h>

#include "mu/model.h"
#include "rb/rb.h"
#include "scenes/registry.h"

/* Bytes of an error message of this module. */
#define SIMULATION_ERROR_SIZE 2048
/* Bytes of a model argument or a muscle-or-group name. */
#define SIMULATION_NAME_SIZE 1024
/* Neurons one press of the recruitment keys adds or removes, as in
 * McIntyre's worm demo ("Simulated Muscles"). */
#define SIMULATION_RECRUITMENT_STEP 20
/* The step of an engine scene (scenes/registry.h), s: 60 Hz, as a model's
 * frames. */
#define SIMULATION_SCENE_DT (1.0 / 60.0)

typedef enum simulation_kind { SIMULATION_NONE, SIMULATION_MODEL, SIMULATION_SCENE } simulation_kind;

typedef struct simulation {
    simulation_kind kind;
    /* A model: the argument it was loaded from, its description and the
     * options it was built with. */
    char model_argument[SIMULATION_NAME_SIZE];
    mu_model_desc *desc;
    mu_model_options options;
    mu_model *model;
    scene_instance scene;
    long frame; /* frames stepped since the load */
    /* The controlled muscle or group ("" for none) and its command. */
    char target[SIMULATION_NAME_SIZE];
    bool tension_mode; /* the command is a tension target rather than an activation */
    double activation; /* 0 .. 1 */
    double tension;    /* N, >= 0 */
    bool pulse_pending;
    /* The mouse joint dragging a body, when `dragging`. */
    bool dragging;
    rb_joint_id drag_joint;
    bool failure_reported; /* the model's failure (mu_model_failure) was handed out */
} simulation;

void simulation_init(simulation *sim);
void simulation_free(simulation *sim);

/* The model's failure (mu_model_failure: a hinge torn open, a runaway
 * speed) the first time it is asked for after it happened, else NULL: a
 * viewer says it once per built model. */
const char *simulation_new_failure(simulation *sim);

/* Loads the model `argument` (a built-in name, or a path: one with a '/'
 * or ending in ".json") built with `options`. The first muscle or group
 * becomes the target, at activation 0. */
bool simulation_load_model(simulation *sim, const char *argument, const mu_model_options *options, char *error,
                           size_t error_size);
/* Reads the current model's file again and builds it with `options`. */
bool simulation_reload(simulation *sim, const mu_model_options *options, char *error, size_t error_size);
/* The build options of the loaded model with its variant named `text`
 * (a name, or an index), with its weight choice of `kilograms`, or at
 * `level` (0 .. 4). False, naming the choices, when there is none. */
bool simulation_choose_variant(const simulation *sim, const char *text, mu_model_options *options, char *error,
                               size_t error_size);
bool simulation_choose_weight(const simulation *sim, double kilograms, mu_model_options *options, char *error,
                              size_t error_size);
bool simulation_choose_level(const simulation *sim, int level, mu_model_options *options, char *error,
                             size_t error_size);
bool simulation_load_scene(simulation *sim, scene_kind kind, char *error, size_t error_size);

/* The world being simulated; NULL when nothing is loaded. */
rb_world *simulation_world(const simulation *sim);
double simulation_time(const simulation *sim);           /* s since the load */
double simulation_frame_duration(const simulation *sim); /* s */

/* One frame: a pending pulse drives the target at activation 1 for this
 * frame only, then the target returns to its command. */
bool simulation_step(simulation *sim, char *error, size_t error_size);

/* Makes `name` (a muscle or group of the model) the controlled target and
 * gives it the present command. */
bool simulation_select(simulation *sim, const char *name, char *error, size_t error_size);
bool simulation_set_activation(simulation *sim, double activation, char *error, size_t error_size);
bool simulation_set_tension(simulation *sim, double newtons, char *error, size_t error_size);
/* Asks for a one-frame pulse of the target at activation 1 (next frame). */
void simulation_pulse(simulation *sim);
/* Recruits `delta` more neurons (fewer when negative) of the first torque
 * muscle, clamped to its pool; false when the model has none. */
bool simulation_recruit_more(simulation *sim, int delta, char *error, size_t error_size);

/* Starts dragging the dynamic body under `point` (m, world; sensors
 * included, so a model's bones are picked): false when there is none. */
bool simulation_drag_begin(simulation *sim, rb_vec2 point);
void simulation_drag_move(simulation *sim, rb_vec2 point);
void simulation_drag_end(simulation *sim);

#endif
