/* SPDX-License-Identifier: MIT */
/* The joint-load and moment-arm columns of a run's CSV (recorder_loads.h). */
#include <math.h>
#include <stdlib.h>

#include "mu/bone_stress.h"
#include "mu/joint_loads.h"
#include "mu/moment_arms.h"
#include "recorder_loads.h"

static const char *const stress_columns[RECORDER_BONE_STRESS_COLUMNS] = {
    "max_stress_Pa", "max_strain", "safety_factor", "worst_section_m", "axial_force_N", "bending_moment_N_m",
};

static const char *const load_columns[RECORDER_JOINT_LOAD_COLUMNS] = {
    "reaction_x_N", "reaction_y_N", "reaction_along_N", "reaction_across_N", "reaction_torque_N_m", "muscle_torque_N_m",
};

bool recorder_loads_open(recorder_loads *loads, const mu_model *model)
{
    *loads = (recorder_loads){.hinges = NULL};
    const int hinges = mu_model_hinge_count(model);
    const int muscles = mu_model_muscle_count(model);
    loads->hinges = malloc(((size_t)hinges + 1) * sizeof *loads->hinges);
    loads->glues = malloc(((size_t)mu_model_glue_count(model) + 1) * sizeof *loads->glues);
    loads->crossing = calloc((size_t)hinges * (size_t)muscles + 1, sizeof *loads->crossing);
    loads->arms = malloc(((size_t)muscles + 1) * sizeof *loads->arms);
    const int bones = mu_model_description(model)->bone_count;
    loads->bones = malloc(((size_t)bones + 1) * sizeof *loads->bones);
    if (loads->hinges == NULL || loads->glues == NULL || loads->crossing == NULL || loads->arms == NULL ||
        loads->bones == NULL) {
        recorder_loads_close(loads);
        return false;
    }
    for (int h = 0; h < hinges; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            continue;
        }
        const int slot = loads->hinge_count++;
        loads->hinges[slot] = h;
        for (int m = 0; m < muscles; ++m) {
            loads->crossing[slot * muscles + m] = mu_model_muscle_crosses(model, m, h);
            loads->crossing_count += loads->crossing[slot * muscles + m];
        }
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        if (!rb_joint_id_is_null(mu_model_glue_joint(model, g))) {
            loads->glues[loads->glue_count++] = g;
        }
    }
    for (int b = 0; b < bones; ++b) {
        if (!isnan(mu_model_bone_stress(model, b).worst.stress)) {
            loads->bones[loads->bone_count++] = b;
        }
    }
    return true;
}

void recorder_loads_close(recorder_loads *loads)
{
    free(loads->hinges);
    free(loads->glues);
    free(loads->crossing);
    free(loads->arms);
    free(loads->bones);
    /* The counts stay: the summary reports the columns after the commit. */
    loads->hinges = NULL;
    loads->glues = NULL;
    loads->crossing = NULL;
    loads->arms = NULL;
    loads->bones = NULL;
}

void recorder_loads_write_header(const recorder_loads *loads, FILE *stream, const mu_model *model,
                                 void (*write_field)(FILE *, const char *, const char *))
{
    for (int h = 0; h < loads->hinge_count; ++h) {
        for (int c = 0; c < RECORDER_JOINT_LOAD_COLUMNS; ++c) {
            write_field(stream, mu_model_hinge_name(model, loads->hinges[h]), load_columns[c]);
        }
    }
    for (int g = 0; g < loads->glue_count; ++g) {
        for (int c = 0; c < RECORDER_JOINT_LOAD_COLUMNS; ++c) {
            write_field(stream, mu_model_glue_name(model, loads->glues[g]), load_columns[c]);
        }
    }
    const int muscles = mu_model_muscle_count(model);
    for (int h = 0; h < loads->hinge_count; ++h) {
        for (int m = 0; m < muscles; ++m) {
            if (!loads->crossing[h * muscles + m]) {
                continue;
            }
            char name[1024];
            snprintf(name, sizeof name, "%s.%s", mu_model_muscle_name(model, m),
                     mu_model_hinge_name(model, loads->hinges[h]));
            write_field(stream, name, "moment_arm_m");
            write_field(stream, name, "torque_N_m");
        }
    }
    const mu_model_desc *desc = mu_model_description(model);
    for (int b = 0; b < loads->bone_count; ++b) {
        for (int c = 0; c < RECORDER_BONE_STRESS_COLUMNS; ++c) {
            write_field(stream, desc->bones[loads->bones[b]].name, stress_columns[c]);
        }
    }
}

void recorder_write_values(FILE *stream, int digits, const double *values, int count)
{
    for (int i = 0; i < count; ++i) {
        fprintf(stream, ",%.*g", digits, values[i]);
    }
}

static void write_load(FILE *stream, int digits, mu_joint_load load)
{
    const double values[RECORDER_JOINT_LOAD_COLUMNS] = {load.force.x, load.force.y, load.along,
                                                        load.across,  load.torque,  load.muscle_torque};
    recorder_write_values(stream, digits, values, RECORDER_JOINT_LOAD_COLUMNS);
}

bool recorder_loads_write_row(const recorder_loads *loads, FILE *stream, int digits, const mu_model *model,
                              const frame_loads *frame)
{
    for (int h = 0; h < loads->hinge_count; ++h) {
        write_load(stream, digits, frame->hinges[loads->hinges[h]]);
    }
    for (int g = 0; g < loads->glue_count; ++g) {
        write_load(stream, digits, frame->glues[loads->glues[g]]);
    }
    const int muscles = mu_model_muscle_count(model);
    for (int h = 0; h < loads->hinge_count; ++h) {
        if (mu_model_moment_arms(model, loads->hinges[h], loads->arms) != RB_OK) {
            return false;
        }
        for (int m = 0; m < muscles; ++m) {
            if (loads->crossing[h * muscles + m]) {
                const double force = mu_model_muscle_readout(model, m).total_force;
                const double values[RECORDER_MOMENT_ARM_COLUMNS] = {loads->arms[m], force * loads->arms[m]};
                recorder_write_values(stream, digits, values, RECORDER_MOMENT_ARM_COLUMNS);
            }
        }
    }
    for (int b = 0; b < loads->bone_count; ++b) {
        const mu_bone_stress stress = frame->bones[loads->bones[b]];
        const double values[RECORDER_BONE_STRESS_COLUMNS] = {stress.worst.stress,        stress.strain,
                                                             stress.worst.safety_factor, stress.worst.s,
                                                             stress.worst.axial_force,   stress.worst.bending_moment};
        recorder_write_values(stream, digits, values, RECORDER_BONE_STRESS_COLUMNS);
    }
    return true;
}

int recorder_loads_column_count(const recorder_loads *loads)
{
    return RECORDER_JOINT_LOAD_COLUMNS * (loads->hinge_count + loads->glue_count) +
           RECORDER_MOMENT_ARM_COLUMNS * loads->crossing_count + RECORDER_BONE_STRESS_COLUMNS * loads->bone_count;
}
