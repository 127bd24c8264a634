/* SPDX-License-Identifier: MIT */
/* The joint-load and moment-arm columns of a run's CSV (recorder.h), after
 * the columns of the parts:
 *
 * - for every built hinge, then every glue kept as a weld joint
 *   (--weld-glues), NAME.reaction_x_N, NAME.reaction_y_N (the force on the
 *   distal body, world frame), NAME.reaction_along_N,
 *   NAME.reaction_across_N (in the proximal bone's frame),
 *   NAME.reaction_torque_N_m and NAME.muscle_torque_N_m (mu/joint_loads.h);
 * - for every built muscle and every built hinge its path crosses,
 *   MUSCLE.HINGE.moment_arm_m and MUSCLE.HINGE.torque_N_m
 *   (mu/moment_arms.h);
 * - for every bone that moves (built, not fixed to the ground), at its
 *   worst section (mu/bone_stress.h): BONE.max_stress_Pa (the peak normal
 *   stress, > 0 tension), BONE.max_strain, BONE.safety_factor,
 *   BONE.worst_section_m (along the bone's axis from its centre),
 *   BONE.axial_force_N and BONE.bending_moment_N_m.
 */
#ifndef SINEW_RECORDER_LOADS_H
#define SINEW_RECORDER_LOADS_H

#include <stdbool.h>
#include <stdio.h>

#include "frame_loads.h"
#include "mu/model.h"

enum { RECORDER_JOINT_LOAD_COLUMNS = 6, RECORDER_MOMENT_ARM_COLUMNS = 2, RECORDER_BONE_STRESS_COLUMNS = 6 };

typedef struct recorder_loads {
    int *hinges; /* model indices of the built hinges */
    int hinge_count;
    int *glues; /* model indices of the glues kept as welds */
    int glue_count;
    bool *crossing; /* [hinge slot · muscles + muscle]: whether the muscle crosses the hinge */
    int crossing_count;
    double *arms; /* one hinge's moment arms, by muscle: scratch for a row */
    int *bones;   /* description indices of the bones that move */
    int bone_count;
} recorder_loads;

/* Finds the joints and crossings of the model as built; false on memory.
 * Closing frees the lists and keeps the counts. */
bool recorder_loads_open(recorder_loads *loads, const mu_model *model);
void recorder_loads_close(recorder_loads *loads);

/* `write_field(stream, name, quantity)` writes ",NAME.QUANTITY" as the
 * recorder quotes it. */
void recorder_loads_write_header(const recorder_loads *loads, FILE *stream, const mu_model *model,
                                 void (*write_field)(FILE *, const char *, const char *));
/* Writes the row's loads, the frame's as read (frame_loads.h) and the
 * moment arms, with `digits` significant digits; false when the moment
 * arms cannot be computed (rb_last_error says why). */
bool recorder_loads_write_row(const recorder_loads *loads, FILE *stream, int digits, const mu_model *model,
                              const frame_loads *frame);

/* Writes ",V" for each of `count` values with `digits` significant digits:
 * every number of a run's CSV goes through here. */
void recorder_write_values(FILE *stream, int digits, const double *values, int count);

int recorder_loads_column_count(const recorder_loads *loads);

#endif
