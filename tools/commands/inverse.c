/* SPDX-License-Identifier: MIT */
/* `sinew inverse MODEL --motion FILE [options]`: inverse dynamics. Reads
 * hinge angles over time (motion_file.h), smooths them with a zero-phase
 * Butterworth low-pass and differentiates them (motion_filter.h), and
 * computes, frame by frame, the net torque about each hinge that moves
 * the model so under gravity and its loads (mu/inverse_dynamics.h).
 * Writes DIR/STEM-inverse.csv with its provenance sidecar and a figure
 * DIR/STEM-inverse.png.
 *
 * Everything is computed before anything is written, so bad input leaves
 * no file.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "cli/model_source.h"
#include "cli/user_error.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "motion_analysis.h"
#include "mu/inverse_dynamics.h"

#define DEGREES (180.0 / RB_PI)

static const cli_option options_table[] = {MOTION_ANALYSIS_INPUT_OPTIONS, MOTION_ANALYSIS_MODEL_OPTIONS};

static const cli_command command = {
    .name = "sinew inverse",
    .operands = "MODEL --motion FILE [options]",
    .max_operands = 1,
    .operand = "model",
    .about = "Inverse dynamics: from hinge angles over time, the net torque about each hinge that produces\n"
             "that motion under gravity, the model's weight and its bones' damping. Writes\n"
             "DIR/MODEL-inverse.csv and .png.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes = "Columns: time_s, then per hinge HINGE.angle_deg (smoothed), HINGE.velocity_deg_s,\n"
             "HINGE.acceleration_deg_s2 and HINGE.net_torque_N_m (on the hinge's body B, counter-clockwise\n"
             "positive). A model whose joints close a loop (the leg) is refused. docs/inverse.md gives\n"
             "the method, the filter and the checks.\n",
};

/* -------------------------------------------------------------- the analysis */

/* Per hinge and frame the net torque (N·m); the smoothed angles and their
 * derivatives are the kinematics'. */
typedef struct result {
    long frames;
    int hinge_count;          /* the model's, built or not */
    motion_kinematics motion; /* smoothed angles (deg), rates (deg/s), accelerations (deg/s²) */
    double *torques;          /* [hinge * frames + frame] */
    const double *const *raw; /* the motion's angles, by hinge */
    const double *time;
} result;

static const double *hinge_values(const result *r, const double *values, int hinge)
{
    return &values[(size_t)hinge * (size_t)r->frames];
}

/* Smooths and differentiates each hinge's angle, then solves every frame;
 * false after a message. */
static bool solve(const mu_model *model, const motion *m, double cutoff, result *r)
{
    const size_t n = (size_t)m->frames;
    r->frames = m->frames;
    r->hinge_count = m->hinge_count;
    r->raw = (const double *const *)m->angles;
    r->time = m->time;
    r->torques = malloc((size_t)m->hinge_count * n * sizeof *r->torques + 1);
    double *frame = malloc((4 * (size_t)m->hinge_count + 1) * sizeof *frame);
    if (r->torques == NULL || frame == NULL || !motion_kinematics_compute(m, cutoff, &r->motion)) {
        free(frame);
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    double *angles = frame, *rates = frame + m->hinge_count, *accelerations = frame + 2 * m->hinge_count,
           *torques = frame + 3 * m->hinge_count;
    bool ok = true;
    for (size_t i = 0; ok && i < n; ++i) {
        for (int h = 0; h < m->hinge_count; ++h) {
            angles[h] = r->motion.angles[(size_t)h * n + i];
            rates[h] = r->motion.rates[(size_t)h * n + i] / DEGREES;
            accelerations[h] = r->motion.accelerations[(size_t)h * n + i] / DEGREES;
        }
        ok = mu_model_inverse_dynamics(model, angles, rates, accelerations, torques) == RB_OK;
        for (int h = 0; ok && h < m->hinge_count; ++h) {
            r->torques[(size_t)h * n + i] = torques[h];
        }
    }
    if (!ok) {
        fprintf(stderr, "sinew: %s\n", user_error());
    }
    free(frame);
    return ok;
}

static void result_free(result *r)
{
    motion_kinematics_free(&r->motion);
    free(r->torques);
}

/* ------------------------------------------------------------------ output */

/* Per built hinge four columns: the smoothed angle, its rate and
 * acceleration, and the net torque. */
enum { COLUMNS_PER_HINGE = 4 };
static const char *const column_names[COLUMNS_PER_HINGE] = {"angle_deg", "velocity_deg_s", "acceleration_deg_s2",
                                                            "net_torque_N_m"};

static bool write_csv(const char *path, const result *r, const mu_model *model, json_t *settings)
{
    const int most = 1 + COLUMNS_PER_HINGE * r->hinge_count;
    char(*names)[512] = malloc((size_t)most * sizeof *names);
    const char **name_of = malloc((size_t)most * sizeof *name_of);
    const double **values = malloc((size_t)most * sizeof *values);
    if (names == NULL || name_of == NULL || values == NULL) {
        free(names);
        free(name_of);
        free(values);
        json_decref(settings);
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    snprintf(names[0], sizeof names[0], "time_s");
    values[0] = r->time;
    int count = 1;
    for (int h = 0; h < r->hinge_count; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            continue;
        }
        const double *const columns[COLUMNS_PER_HINGE] = {
            hinge_values(r, r->motion.angles, h), hinge_values(r, r->motion.rates, h),
            hinge_values(r, r->motion.accelerations, h), hinge_values(r, r->torques, h)};
        for (int c = 0; c < COLUMNS_PER_HINGE; ++c, ++count) {
            snprintf(names[count], sizeof names[0], "%s.%s", mu_model_hinge_name(model, h), column_names[c]);
            values[count] = columns[c];
        }
    }
    for (int c = 0; c < count; ++c) {
        name_of[c] = names[c];
    }
    const bool ok = motion_analysis_write_csv(path, count, name_of, values, r->frames, settings);
    free(names);
    free(name_of);
    free(values);
    return ok;
}

/* Two charts against time: the net torques, and the angles as read and
 * as smoothed. A chart draws at most CHART_MAX_SERIES lines, so the
 * figure shows the first CHART_MAX_SERIES / 2 hinges; the CSV has all. */
static bool write_figure(const char *path, const result *r, const mu_model *model, double cutoff)
{
    chart_series torque_series[CHART_MAX_SERIES], angle_series[CHART_MAX_SERIES];
    char labels[CHART_MAX_SERIES][300];
    int torques = 0, angles = 0;
    for (int h = 0; h < r->hinge_count && angles + 2 <= CHART_MAX_SERIES; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            continue;
        }
        const size_t count = (size_t)r->frames;
        const char *name = mu_model_hinge_name(model, h);
        torque_series[torques++] =
            (chart_series){.label = name, .x = r->time, .y = hinge_values(r, r->torques, h), .count = count};
        if (cutoff > 0.0) {
            snprintf(labels[angles], sizeof labels[angles], "%s as read", name);
            angle_series[angles] =
                (chart_series){.label = labels[angles], .x = r->time, .y = r->raw[h], .count = count};
            ++angles;
            snprintf(labels[angles], sizeof labels[angles], "%s smoothed (%g Hz)", name, cutoff);
        } else {
            snprintf(labels[angles], sizeof labels[angles], "%s (not smoothed)", name);
        }
        angle_series[angles] = (chart_series){
            .label = labels[angles], .x = r->time, .y = hinge_values(r, r->motion.angles, h), .count = count};
        ++angles;
    }
    const chart charts[2] = {
        {.title = "net joint torque (inverse dynamics)",
         .x_label = "time (s)",
         .y_label = "torque on the distal bone (N·m)",
         .series = torque_series,
         .series_count = torques},
        {.title = "hinge angle",
         .x_label = "time (s)",
         .y_label = "angle (deg)",
         .series = angle_series,
         .series_count = angles},
    };
    const chart_figure figure = {.charts = charts, .chart_count = 2, .columns = 1, .width = 1000, .height = 1000};
    return chart_write_png_or_say(&figure, path);
}

static json_t *inverse_settings(mu_model *model, const mu_model_options *options, const motion_analysis_options *opts,
                                double step)
{
    json_t *settings = motion_analysis_settings(model, options, opts, step);
    if (settings != NULL) {
        json_object_set_new(settings, "method", json_string("Newton-Euler over the tree of joints from the ground"));
    }
    return settings;
}

static void print_summary(const result *r, const mu_model *model, const motion_analysis_options *opts, double step,
                          const char *csv_path, const char *png_path)
{
    motion_analysis_print_header(opts, r->frames, step);
    const char *label = "peak torque";
    for (int h = 0; h < r->hinge_count; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            continue;
        }
        const double *torque = hinge_values(r, r->torques, h);
        long peak = 0;
        for (long i = 1; i < r->frames; ++i) {
            peak = fabs(torque[i]) > fabs(torque[peak]) ? i : peak;
        }
        printf("%-13s%-12s %10.4f N·m at %.4f s\n", label, mu_model_hinge_name(model, h), torque[peak], r->time[peak]);
        label = "";
    }
    printf("csv          %s\nfigure       %s\n", csv_path, png_path);
}

/* Builds the model, reads and solves the motion, and writes; returns 0 or
 * an exit status. */
static int analyse(const motion_analysis_options *opts, const mu_model_desc *desc)
{
    mu_model_options options;
    mu_model *model = NULL;
    int code = motion_analysis_build_model(opts, desc, &options, &model);
    if (code != 0) {
        return code;
    }
    motion m = {0};
    result r = {0};
    if (mu_model_check_tree(model) != RB_OK) {
        fprintf(stderr, "sinew: model %s: %s\n", desc->name, user_error());
        code = EXIT_FAILURE;
    }
    code = code == 0 ? motion_analysis_read(opts, model, &m) : code;
    code = code == 0 && !solve(model, &m, opts->cutoff, &r) ? EXIT_FAILURE : code;
    char csv_path[ATOMIC_FILE_PATH_MAX], png_path[ATOMIC_FILE_PATH_MAX];
    code = code == 0 ? motion_analysis_output_path(opts, "-inverse", "csv", csv_path, sizeof csv_path) : code;
    code = code == 0 ? motion_analysis_output_path(opts, "-inverse", "png", png_path, sizeof png_path) : code;
    if (code == 0 && !write_csv(csv_path, &r, model, inverse_settings(model, &options, opts, m.step))) {
        code = EXIT_FAILURE;
    }
    if (code == 0 && !write_figure(png_path, &r, model, opts->cutoff)) {
        code = EXIT_FAILURE;
    }
    if (code == 0) {
        print_summary(&r, model, opts, m.step, csv_path, png_path);
    }
    result_free(&r);
    motion_free(&m);
    mu_model_destroy(model);
    return code;
}

/* `sinew inverse` has no options of its own. */
static bool take_no_option(int id, const cli_value *value, void *own)
{
    (void)id;
    (void)value;
    (void)own;
    return false;
}

int cmd_inverse(int argc, char **argv)
{
    motion_analysis_options opts = motion_analysis_default_options();
    int code = motion_analysis_parse(&command, argc, argv, &opts, take_no_option, NULL);
    if (code == MOTION_ANALYSIS_HELP) {
        cli_print_help(&command, stdout);
        return EXIT_SUCCESS;
    }
    mu_model_desc *desc = NULL;
    if (code == 0) {
        code = model_source_load(opts.model, &desc);
    }
    if (code == 0) {
        code = analyse(&opts, desc);
    }
    mu_model_desc_destroy(desc);
    return code;
}
