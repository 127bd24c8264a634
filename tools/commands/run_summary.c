/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* strdup */
/* The JSON summary of a run (run_summary.h), built with jansson. */
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/atomic_file.h"
#include "mu/version.h"
#include "run_summary.h"

/* A finite number, or null: JSON has no NaN. */
static json_t *number_or_null(double value) { return isfinite(value) ? json_real(value) : json_null(); }

/* The model's warnings, one string per line of mu_model_warnings. */
static json_t *warning_lines(const mu_model *model)
{
    json_t *lines = json_array();
    const char *text = mu_model_warnings(model);
    while (lines != NULL && text != NULL && *text != '\0') {
        size_t length = strcspn(text, "\n");
        json_array_append_new(lines, json_stringn(text, length));
        text += length + (text[length] == '\n');
    }
    return lines;
}

static json_t *muscles_of(const run_summary *summary)
{
    json_t *list = json_array();
    for (int m = 0; list != NULL && m < mu_model_muscle_count(summary->model); ++m) {
        json_array_append_new(list, json_pack("{s:s, s:o, s:o}", "name", mu_model_muscle_name(summary->model, m),
                                              "peak_force_N", number_or_null(summary->peak_force[m]), "peak_time_s",
                                              number_or_null(summary->peak_time[m])));
    }
    return list;
}

static json_t *torque_muscles_of(const run_summary *summary)
{
    json_t *list = json_array();
    for (int t = 0; list != NULL && t < mu_model_torque_muscle_count(summary->model); ++t) {
        const mu_motor_pool *pool = mu_model_motor_pool(summary->model, t);
        double torque = mu_torque_actuator_torque(mu_model_torque_actuator(summary->model, t));
        json_array_append_new(
            list,
            json_pack("{s:s, s:i, s:i, s:o, s:o}", "name", mu_model_torque_muscle_name(summary->model, t), "recruited",
                      mu_motor_pool_recruited(pool), "neurons", mu_motor_pool_neuron_count(pool), "exertion",
                      number_or_null(mu_motor_pool_exertion(pool)), "torque_N_m", number_or_null(torque)));
    }
    return list;
}

/* The hinges built (a hinge of another variant reads NaN and is left out). */
static json_t *hinges_of(const run_summary *summary)
{
    json_t *list = json_array();
    for (int h = 0; list != NULL && h < mu_model_hinge_count(summary->model); ++h) {
        double angle = mu_model_hinge_angle(summary->model, h);
        if (isnan(angle)) {
            continue;
        }
        json_array_append_new(list, json_pack("{s:s, s:o, s:o, s:o}", "name", mu_model_hinge_name(summary->model, h),
                                              "final_angle_deg", number_or_null(angle), "min_angle_deg",
                                              number_or_null(summary->angle_min[h]), "max_angle_deg",
                                              number_or_null(summary->angle_max[h])));
    }
    return list;
}

static json_t *summary_object(const run_summary *summary)
{
    json_t *arguments = json_array();
    for (int k = 0; arguments != NULL && k < summary->argument_count; ++k) {
        json_array_append_new(arguments, json_string(summary->arguments[k]));
    }
    const mu_model_desc *desc = mu_model_description(summary->model);
    const char *slash = strrchr(summary->csv_path, '/');
    const char *failure = mu_model_failure(summary->model);
    double simulated = summary->simulated_seconds;
    return json_pack("{s:s, s:o, s:s, s:s, s:i, s:o, s:i, s:I, s:f, s:s, s:I, s:i, s:o, s:o, s:i, s:i, s:o, s:o, "
                     "s:o, s:{s:f, s:f, s:o}}",
                     "sinew", mu_version(), "arguments", arguments, "model", summary->model_name, "variant",
                     desc->variants[summary->variant].name, "variant_index", summary->variant, "weight_kg",
                     number_or_null(summary->weight_kg), "level", summary->level, "frames", (json_int_t)summary->frames,
                     "simulated_s", simulated, "csv", slash != NULL ? slash + 1 : summary->csv_path, "rows",
                     (json_int_t)summary->rows, "columns", summary->columns, "warnings", warning_lines(summary->model),
                     "failure", failure != NULL ? json_string(failure) : json_null(), "controls_applied",
                     summary->controls_applied, "controls_pending", summary->controls_pending, "muscles",
                     muscles_of(summary), "torque_muscles", torque_muscles_of(summary), "hinges", hinges_of(summary),
                     "timing", "wall_s", summary->wall_seconds, "stepping_s", summary->step_seconds, "real_time_factor",
                     number_or_null(simulated / summary->wall_seconds));
}

bool run_summary_write(const char *path, const run_summary *summary, char *error, size_t error_size)
{
    json_t *root = summary_object(summary);
    if (root == NULL) {
        snprintf(error, error_size, "--summary %s: out of memory", path);
        return false;
    }
    atomic_file file = {0};
    bool ok = atomic_file_open(&file, path, error, error_size);
    if (ok) {
        /* JSON_REAL_PRECISION(17): every double read back exactly. */
        if (json_dumpf(root, file.stream, JSON_INDENT(2) | JSON_REAL_PRECISION(17)) != 0 ||
            fputc('\n', file.stream) == EOF) {
            snprintf(error, error_size, "--summary %s: could not write the summary", path);
            atomic_file_abandon(&file);
            ok = false;
        } else {
            ok = atomic_file_commit(&file, error, error_size);
        }
    }
    json_decref(root);
    return ok;
}
