/* SPDX-License-Identifier: MIT */
/** @file
 * A musculoskeletal model built from its description (model_desc.h):
 * the engine world with its bodies and joints, and the muscles, at a
 * simulation level, a variant and a weight choice.
 *
 * Levels: 0 nothing, 1 bones (and nails), 2 + joints (hinges, glues),
 * 3 + muscles, 4 + the weight. Glued bones are merged into one compound
 * rigid body by default (exact for a rigid weld, and it removes the
 * 400:1 mass ratio of a 100 kg weight glued to a 0.25 kg radius);
 * `weld_glues` keeps them as weld joints instead, for study. Names still
 * address the parts either way.
 *
 * One frame of 1/frame_rate s is one engine step split into the model's
 * substeps (the built-in models: 60 Hz, 10 substeps); at the start of each substep
 * every muscle reads what the previous substep did and sets its tension
 * law from its state (the engine's substep callback). Collision runs
 * once per frame.
 *
 * Arguments are checked as the engine's are (rb/base.h): a NULL model or
 * name, an index out of its list, or a non-finite number is refused with
 * RB_ERR_INVALID_ARGUMENT and a message (rb_last_error()) naming the
 * function, the argument and what was expected. A function returning a
 * status returns that; a getter returns its error value, given with each
 * below, and records the same error.
 */
#ifndef MU_MODEL_H
#define MU_MODEL_H

#include <stdbool.h>

#include "mu/export.h"
#include "mu/model_desc.h"
#include "mu/motor_pool.h"
#include "mu/muscle.h"
#include "mu/torque_actuator.h"
#include "rb/rb.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_model mu_model;

typedef struct mu_model_options {
    int level;        /**< 0 .. 4, default 4 */
    int variant;      /**< index into the description's variants, default 0 */
    int weight_index; /**< index into the weight's masses, default 0 */
    bool weld_glues;  /**< keep glues as weld joints instead of merging (default false) */
} mu_model_options;

MU_API mu_model_options mu_default_model_options(void);

/** Builds the model; the description must outlive it. Fails with a message
 * naming the option or the object that could not be built. */
MU_API rb_status mu_model_create(const mu_model_desc *desc, const mu_model_options *options, mu_model **out);
/** Frees the model and its world. Accepts NULL. */
MU_API void mu_model_destroy(mu_model *model);

/** The model's world; NULL for a NULL model. */
MU_API rb_world *mu_model_world(mu_model *model);
/** The same, to read only. */
MU_API const rb_world *mu_model_world_to_read(const mu_model *model);
/** The description it was built from; NULL for a NULL model. */
MU_API const mu_model_desc *mu_model_description(const mu_model *model);

/** Advances one frame: the model's substeps, one after the other. */
MU_API rb_status mu_model_step(mu_model *model);
/** Advances one substep (frame duration / substeps), for controls finer
 * than a frame (a pulse of 2 ms at 600 Hz is one substep): one engine
 * step of one substep. The solve is a frame's substep; collision runs
 * before each substep instead of once per frame, which a model whose
 * parts never touch (the built-in ones: bones are sensors) does not feel. */
MU_API rb_status mu_model_substep(mu_model *model);
MU_API double mu_model_time(const mu_model *model);             /**< s since creation; NaN for a NULL model */
MU_API double mu_model_frame_duration(const mu_model *model);   /**< s; NaN for a NULL model */
MU_API double mu_model_substep_duration(const mu_model *model); /**< s; NaN for a NULL model */

/** Controls, by muscle or group name (each muscle is also its own group):
 * every muscle of the group that exists in the built variant. */
MU_API rb_status mu_model_set_activation(mu_model *model, const char *name, double activation);
MU_API rb_status mu_model_set_tension(mu_model *model, const char *name, double newtons);
/** The same by index among the built muscles (0 .. mu_model_muscle_count - 1). */
MU_API rb_status mu_model_set_activation_at(mu_model *model, int index, double activation);
MU_API rb_status mu_model_set_tension_at(mu_model *model, int index, double newtons);
/** Mean activation of the group's built muscles; NaN with an error for an
 * unknown name. */
MU_API double mu_model_group_activation(const mu_model *model, const char *name);
MU_API rb_status mu_model_set_gravity(mu_model *model, rb_vec2 gravity);

/** The built muscles, in the description's order: their count (0 for a
 * NULL model), and by index their name and muscle (NULL for a bad index)
 * and readout (every field NaN for a bad index). */
MU_API int mu_model_muscle_count(const mu_model *model);
MU_API const char *mu_model_muscle_name(const mu_model *model, int index);
MU_API mu_muscle_readout mu_model_muscle_readout(const mu_model *model, int index);
MU_API const mu_muscle *mu_model_built_muscle(const mu_model *model, int index);
/** The warnings of the build (e.g. a muscle whose path is shorter than its
 * rest length starts below the asked normalized length): one per line;
 * NULL for a NULL model. */
MU_API const char *mu_model_warnings(const mu_model *model);

/** Past these, after any step, a run is reported as failed by
 * mu_model_failure: a hinge whose two anchors are farther apart than
 * MU_MODEL_MAX_HINGE_GAP (m), a body whose centre moves faster than
 * MU_MODEL_MAX_SPEED (m/s) or that turns faster than
 * MU_MODEL_MAX_ANGULAR_SPEED (rad/s, about 11,500°/s), or a non-finite
 * speed, or energy created beyond MU_MODEL_MAX_CREATED_ENERGY. A human limb's joints do not open; a pitched ball leaves
 * the hand at about 40 m/s, and the shoulder's internal rotation while pitching, the fastest joint rotation measured in
 * people, peaks near 7,000°/s (Fleisig et al., "Kinetics of baseball pitching with implications about injury
 * mechanisms", 1995). The built-in models, in every variant, with every weight, at activation 0 and 1 for 3 s, stay
 * inside all three (at most 0.016 m, 4 m/s and 39 rad/s measured over frames; tests/test_model_failure.c). */
#define MU_MODEL_MAX_HINGE_GAP 0.05
/** J: a run has also failed when its energy account (mu_model_energy_account)
 * shows more energy created than this plus the muscles' gross work: the
 * solver (or something outside the model) has added energy no muscle
 * did. Over the built-in models' sweep above the most created was 2.8 J
 * (the arm, all biceps fully active, no weight, with 5.4 J of muscle
 * work); damping, contacts and limits otherwise take energy away. */
#define MU_MODEL_MAX_CREATED_ENERGY 1.0
#define MU_MODEL_MAX_SPEED 50.0
#define MU_MODEL_MAX_ANGULAR_SPEED 200.0
/** NULL while the run looks physical; after the first step that ended past
 * one of the limits above, one line saying when and where ("t = 2.3500 s:
 * hinge \"Shoulder\" opened by 3.7 m (more than 0.05 m): ..."). The first
 * failure is kept; stepping goes on, so a program decides whether to stop
 * (`sinew run --strict` does). Typical causes: a weight or a muscle force
 * far beyond what the joints' solver can hold within a frame. */
MU_API const char *mu_model_failure(const mu_model *model);

/** The model's mechanical energy account, in J. `mechanical` is the
 * kinetic energy of the moving bodies (½·m·v² + ½·I·ω²) plus their
 * potential energy in gravity (−m·g·x of the centre of mass) now;
 * `muscle_work` is the work the muscles' tensions and the torque muscles'
 * torques did on the bodies since the account started, summed substep by
 * substep (tension × shortening, torque × turn). What nothing else
 * explains, `created` = mechanical − at_start − muscle_work, is what the
 * solver added: damping, contacts and limits only take energy away, so a
 * sound run keeps it at or below zero up to the integrator's error.
 * The account starts at the first step, and starts again (created back
 * to 0) after a step in which something outside the model acted on its
 * world (a joint the model did not build, such as the viewer's mouse) or
 * gravity changed. Before the first step every field is 0; NaN fields
 * (and an error) for a NULL model. */
typedef struct mu_model_energy {
    double mechanical;        /**< J, now */
    double at_start;          /**< J, when the account (re)started */
    double muscle_work;       /**< J, done on the bodies since then */
    double muscle_work_gross; /**< J, the same with every substep's work counted positive */
    double created;           /**< J, mechanical − at_start − muscle_work */
} mu_model_energy;
MU_API mu_model_energy mu_model_energy_account(const mu_model *model);

/** The built hinges, in the description's order, with their joint angle
 * (degrees, angle(bone B) - angle(bone A), as the file's limits): 0
 * hinges for a NULL model, a NULL name and a NaN angle for a bad index
 * (the angle is NaN, without an error, for a hinge the variant does not
 * build). */
MU_API int mu_model_hinge_count(const mu_model *model);
MU_API const char *mu_model_hinge_name(const mu_model *model, int index);
MU_API double mu_model_hinge_angle(const mu_model *model, int index);

/** The built bones and nails, in the description's order (nails first),
 * with their pose: the centre (m) and angle (degrees) of the part itself,
 * also when merged into a compound body: 0 parts for a NULL model, a
 * NULL name and NaN poses for a bad index (NaN poses, without an error,
 * for a part the variant does not build). */
MU_API int mu_model_part_count(const mu_model *model);
MU_API const char *mu_model_part_name(const mu_model *model, int index);
MU_API rb_vec2 mu_model_part_centre(const mu_model *model, int index);
MU_API double mu_model_part_angle(const mu_model *model, int index);

/** The built torque muscles (motor-pool muscles after McIntyre,
 * "Simulated Muscles"), in the description's order: each a motor pool
 * (its profile image, CSV or generated strengths) whose exertion drives a
 * torque actuator, applied before every step. 0 of them for a NULL model;
 * the name is NULL for a bad index. */
MU_API int mu_model_torque_muscle_count(const mu_model *model);
MU_API const char *mu_model_torque_muscle_name(const mu_model *model, int index); /**< NULL for a bad index */
/** Recruits the first `neurons` (0 .. the pool's size) of the torque
 * muscle named `name`, or of the one at `index` (0 ..
 * mu_model_torque_muscle_count - 1): the pool's exertion, and so the
 * actuator's torque, from the next step on, until recruited again (the
 * command line's `--recruit NAME=N` and a control file's `recruit` lines
 * call these). A count outside the pool is refused and recruits nothing,
 * as is an unknown name, whose message lists the names of the torque
 * muscles built (RB_ERR_INVALID_ARGUMENT, rb_last_error()). */
MU_API rb_status mu_model_recruit(mu_model *model, const char *name, int neurons);
MU_API rb_status mu_model_recruit_at(mu_model *model, int index, int neurons);
/** The pool (recruited count, exertion) and actuator (torque, N·m); NULL
 * for a bad index. */
MU_API const mu_motor_pool *mu_model_motor_pool(const mu_model *model, int index);
MU_API const mu_torque_actuator *mu_model_torque_actuator(const mu_model *model, int index);

/** Counts of the engine objects made: bodies, joints; 0 for a NULL model. */
MU_API int mu_model_body_count(const mu_model *model);
MU_API int mu_model_joint_count(const mu_model *model);

/** The engine objects behind the names, for analyses that work on the
 * bodies themselves (joint_loads.h, moment_arms.h). Bad indices are
 * refused as above, giving a null id, -1 or NULL.
 * - mu_model_hinge_joint: the hinge's revolute joint (body A the file's
 *   body_a); the null id when the variant does not build it.
 * - mu_model_glue_count/name/joint: the description's glues (0 for a NULL
 *   model); the joint is the weld kept with weld_glues (body A the file's
 *   body_a, anchored at part B's centre), the null id when the glue was
 *   merged or not built.
 * - mu_model_weight_joint: the weight disc's weld to its carrier with
 *   weld_glues; the null id otherwise (merged, 0 kg, or no weight).
 * - mu_model_weight_mass: the weight disc's mass built, kg (0 without
 *   one: no weight, 0 kg, or its carrier not built).
 * - mu_model_body: engine body `index` (0 .. mu_model_body_count - 1).
 * - mu_model_part_body: the index of the body a part (as
 *   mu_model_part_name) became part of; -1 when it is not built.
 * - mu_model_muscle_description_index: a built muscle's index in the
 *   description's muscles.
 * - mu_model_muscle_at: a built muscle, to change (NULL for a bad index). */
MU_API rb_joint_id mu_model_hinge_joint(const mu_model *model, int index);
MU_API int mu_model_glue_count(const mu_model *model);
MU_API const char *mu_model_glue_name(const mu_model *model, int index);
MU_API rb_joint_id mu_model_glue_joint(const mu_model *model, int index);
MU_API rb_joint_id mu_model_weight_joint(const mu_model *model);
MU_API double mu_model_weight_mass(const mu_model *model);
MU_API rb_body_id mu_model_body(const mu_model *model, int index);
MU_API int mu_model_part_body(const mu_model *model, int index);
MU_API int mu_model_muscle_description_index(const mu_model *model, int index);
MU_API mu_muscle *mu_model_muscle_at(mu_model *model, int index);

#ifdef __cplusplus
}
#endif

#endif
