/* SPDX-License-Identifier: MIT */
/* `sinew optimize MODEL --motion FILE [options]`: static optimization.
 * Reads hinge angles over time (motion_file.h), smooths and
 * differentiates them as `sinew inverse` does (motion_filter.h), and
 * finds, frame by frame, the activations that produce the
 * inverse-dynamics torques at least cost (mu/static_optimization.h).
 * Writes DIR/STEM-optimize.csv with its provenance sidecar and a figure
 * DIR/STEM-optimize.png.
 *
 * Everything is computed before anything is written, so bad input leaves
 * no file. A frame where SLSQP does not end at a solution is not an
 * error: it is written, counted in the summary with its NLopt code, and
 * flagged in the CSV's `solved` column.
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
#include "mu/static_optimization.h"

#define DEGREES (180.0 / RB_PI)

enum { OPT_EXPONENT, OPT_RESERVE };

static const cli_option options_table[] = {
    MOTION_ANALYSIS_INPUT_OPTIONS,
    {.name = "exponent",
     .id = OPT_EXPONENT,
     .kind = CLI_NUMBER,
     .value_name = "P",
     .help = "the cost is the sum of activation^P (3: Crowninshield and Brand 1981)",
     .min = 1.0,
     .max = 100.0,
     .fallback = "2"},
    {.name = "reserve",
     .id = OPT_RESERVE,
     .kind = CLI_NUMBER,
     .value_name = "NM",
     .help = "reserve scale R, N·m: a reserve torque T costs (T/R)^2; keep it far below the muscles' torques",
     .min = 0.0,
     .min_open = true,
     .max = 1e6,
     .fallback = "0.1"},
    MOTION_ANALYSIS_MODEL_OPTIONS,
};

static const cli_command command = {
    .name = "sinew optimize",
    .operands = "MODEL --motion FILE [options]",
    .max_operands = 1,
    .operand = "model",
    .about = "Static optimization: from hinge angles over time, the muscle activations (0 .. 1) that produce the\n"
             "inverse-dynamics torques through each muscle's force-length-velocity state at least cost\n"
             "(the sum of activation^P), with a reserve torque per hinge where the muscles cannot.\n"
             "Writes DIR/MODEL-optimize.csv and .png.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes = "Columns: time_s, solved (1 when the frame's point meets the constraints and the optimality\n"
             "conditions), solver_result (NLopt's code); per muscle MUSCLE.activation and MUSCLE.total_force_N\n"
             "(a torque muscle: .exertion and .torque_N_m); per hinge HINGE.angle_deg (smoothed),\n"
             "HINGE.net_torque_N_m (inverse dynamics), HINGE.muscle_torque_N_m, HINGE.reserve_torque_N_m and the\n"
             "reaction on its body B, HINGE.reaction_x_N, _y_N, _along_N and _across_N. docs/inverse.md gives\n"
             "the method and the checks.\n",
};

/* The cost's options; the rest are the shared ones. */
typedef struct cost_options {
    double exponent;
    double reserve; /* N·m */
} cost_options;

static bool take_cost_option(int id, const cli_value *value, void *own)
{
    cost_options *cost = own;
    if (id == OPT_EXPONENT) {
        cost->exponent = value->number;
    } else if (id == OPT_RESERVE) {
        cost->reserve = value->number;
    }
    return id == OPT_EXPONENT || id == OPT_RESERVE;
}

/* -------------------------------------------------------------- the table */

/* Columns: time, solved, solver result; per actuator two; per built hinge
 * HINGE_COLUMNS. */
enum { COL_TIME, COL_SOLVED, COL_RESULT, LEADING_COLUMNS };
enum { H_ANGLE, H_NET, H_MUSCLE, H_RESERVE, H_REACTION_X, H_REACTION_Y, H_ALONG, H_ACROSS, HINGE_COLUMNS };
static const char *const hinge_column_names[HINGE_COLUMNS] = {
    "angle_deg",    "net_torque_N_m", "muscle_torque_N_m", "reserve_torque_N_m",
    "reaction_x_N", "reaction_y_N",   "reaction_along_N",  "reaction_across_N"};

typedef struct table {
    long frames;
    int columns;
    int actuators, muscles;
    int built_count;
    int *built;     /* the built hinges' indices */
    double *values; /* [column][frame] */
    char (*names)[300];
} table;

static double *column(const table *t, int c) { return &t->values[(size_t)c * (size_t)t->frames]; }
static int actuator_column(int actuator, int which) { return LEADING_COLUMNS + 2 * actuator + which; }
static int hinge_column(const table *t, int built_index, int which)
{
    return LEADING_COLUMNS + 2 * t->actuators + HINGE_COLUMNS * built_index + which;
}

static bool table_init(table *t, const mu_model *model, int actuators, long frames)
{
    const int hinges = mu_model_hinge_count(model);
    t->frames = frames;
    t->actuators = actuators;
    t->muscles = mu_model_muscle_count(model);
    t->built = malloc(((size_t)hinges + 1) * sizeof *t->built);
    for (int h = 0; t->built != NULL && h < hinges; ++h) {
        if (!rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            t->built[t->built_count++] = h;
        }
    }
    t->columns = LEADING_COLUMNS + 2 * actuators + HINGE_COLUMNS * t->built_count;
    t->values = malloc((size_t)t->columns * (size_t)frames * sizeof *t->values + 1);
    t->names = malloc((size_t)t->columns * sizeof *t->names);
    if (t->built == NULL || t->values == NULL || t->names == NULL) {
        return false;
    }
    snprintf(t->names[COL_TIME], sizeof t->names[0], "time_s");
    snprintf(t->names[COL_SOLVED], sizeof t->names[0], "solved");
    snprintf(t->names[COL_RESULT], sizeof t->names[0], "solver_result");
    for (int i = 0; i < actuators; ++i) {
        const bool muscle = i < t->muscles;
        const char *name = muscle ? mu_model_muscle_name(model, i) : mu_model_torque_muscle_name(model, i - t->muscles);
        snprintf(t->names[actuator_column(i, 0)], sizeof t->names[0], "%s.%s", name,
                 muscle ? "activation" : "exertion");
        snprintf(t->names[actuator_column(i, 1)], sizeof t->names[0], "%s.%s", name,
                 muscle ? "total_force_N" : "torque_N_m");
    }
    for (int k = 0; k < t->built_count; ++k) {
        for (int c = 0; c < HINGE_COLUMNS; ++c) {
            snprintf(t->names[hinge_column(t, k, c)], sizeof t->names[0], "%s.%s",
                     mu_model_hinge_name(model, t->built[k]), hinge_column_names[c]);
        }
    }
    return true;
}

static void table_free(table *t)
{
    free(t->built);
    free(t->values);
    free(t->names);
}

/* ------------------------------------------------------------ the analysis */

/* Solves every frame into the table; returns 0 or an exit status after a
 * message naming the motion's line. */
static int solve(mu_static_optimizer *optimizer, const motion *m, const motion_kinematics *k, const char *motion_path,
                 table *t)
{
    const int hinges = m->hinge_count;
    const size_t n = (size_t)m->frames;
    double *scratch = malloc(((size_t)hinges * 7 + (size_t)t->actuators * 2 + 1) * sizeof *scratch);
    mu_joint_load *loads = malloc(((size_t)hinges + 1) * sizeof *loads);
    if (scratch == NULL || loads == NULL) {
        free(scratch);
        free(loads);
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    double *angles = scratch, *rates = angles + hinges, *accelerations = rates + hinges, *net = accelerations + hinges,
           *actuator = net + hinges, *reserves = actuator + hinges, *activations = reserves + hinges,
           *forces = activations + t->actuators;
    int code = 0;
    for (size_t i = 0; code == 0 && i < n; ++i) {
        for (int h = 0; h < hinges; ++h) {
            angles[h] = k->angles[(size_t)h * n + i];
            rates[h] = k->rates[(size_t)h * n + i] / DEGREES;
            accelerations[h] = k->accelerations[(size_t)h * n + i] / DEGREES;
        }
        mu_static_frame frame = {.activations = activations,
                                 .forces = forces,
                                 .net_torques = net,
                                 .actuator_torques = actuator,
                                 .reserves = reserves,
                                 .loads = loads};
        if (mu_static_optimizer_solve(optimizer, angles, rates, accelerations, &frame) != RB_OK) {
            fprintf(stderr, "sinew: %s line %zu (t = %g s): %s\n", motion_path, i + 2, m->time[i], user_error());
            code = EXIT_FAILURE;
            break;
        }
        column(t, COL_TIME)[i] = m->time[i];
        column(t, COL_SOLVED)[i] = frame.solved ? 1.0 : 0.0;
        column(t, COL_RESULT)[i] = frame.solver_result;
        for (int a = 0; a < t->actuators; ++a) {
            column(t, actuator_column(a, 0))[i] = activations[a];
            column(t, actuator_column(a, 1))[i] = forces[a];
        }
        for (int b = 0; b < t->built_count; ++b) {
            const int h = t->built[b];
            const double values[HINGE_COLUMNS] = {angles[h],        net[h],           actuator[h],    reserves[h],
                                                  loads[h].force.x, loads[h].force.y, loads[h].along, loads[h].across};
            for (int c = 0; c < HINGE_COLUMNS; ++c) {
                column(t, hinge_column(t, b, c))[i] = values[c];
            }
        }
    }
    free(scratch);
    free(loads);
    return code;
}

/* ------------------------------------------------------------------ output */

static bool write_csv(const char *path, const table *t, json_t *settings)
{
    const char **names = malloc((size_t)t->columns * sizeof *names);
    const double **values = malloc((size_t)t->columns * sizeof *values);
    if (names == NULL || values == NULL) {
        free(names);
        free(values);
        json_decref(settings);
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    for (int c = 0; c < t->columns; ++c) {
        names[c] = t->names[c];
        values[c] = column(t, c);
    }
    const bool ok = motion_analysis_write_csv(path, t->columns, names, values, t->frames, settings);
    free(names);
    free(values);
    return ok;
}

/* Three charts against time: per hinge the net torque of inverse dynamics
 * beside the muscles' and the reserve; the activations; the reactions
 * along the proximal bones. */
static bool write_figure(const char *path, const table *t)
{
    chart_series torques[CHART_MAX_SERIES], activations[CHART_MAX_SERIES], reactions[CHART_MAX_SERIES];
    char labels[CHART_MAX_SERIES][320];
    int torque_count = 0, activation_count = 0, reaction_count = 0, label = 0;
    const size_t n = (size_t)t->frames;
    const double *time = column(t, COL_TIME);
    for (int b = 0; b < t->built_count && torque_count + 3 <= CHART_MAX_SERIES; ++b) {
        const int which[3] = {H_NET, H_MUSCLE, H_RESERVE};
        const char *const what[3] = {"inverse dynamics", "muscles", "reserve"};
        for (int w = 0; w < 3; ++w) {
            const char *name = t->names[hinge_column(t, b, 0)];
            const int length = (int)(strchr(name, '.') - name);
            snprintf(labels[label], sizeof labels[label], "%.*s %s", length, name, what[w]);
            torques[torque_count++] = (chart_series){
                .label = labels[label++], .x = time, .y = column(t, hinge_column(t, b, which[w])), .count = n};
        }
        reactions[reaction_count] = (chart_series){.label = t->names[hinge_column(t, b, H_ALONG)],
                                                   .x = time,
                                                   .y = column(t, hinge_column(t, b, H_ALONG)),
                                                   .count = n};
        ++reaction_count;
    }
    for (int a = 0; a < t->actuators && activation_count < CHART_MAX_SERIES; ++a) {
        activations[activation_count++] = (chart_series){
            .label = t->names[actuator_column(a, 0)], .x = time, .y = column(t, actuator_column(a, 0)), .count = n};
    }
    const chart charts[3] = {
        {.title = "torque about each hinge: inverse dynamics, muscles and reserve",
         .x_label = "time (s)",
         .y_label = "torque on the distal bone (N·m)",
         .series = torques,
         .series_count = torque_count},
        {.title = "activations found",
         .x_label = "time (s)",
         .y_label = "activation",
         .series = activations,
         .series_count = activation_count,
         .y_range = {.fixed = true, .min = 0.0, .max = 1.0}},
        {.title = "joint reaction along the proximal bone (> 0 compresses the joint)",
         .x_label = "time (s)",
         .y_label = "force (N)",
         .series = reactions,
         .series_count = reaction_count},
    };
    const chart_figure figure = {.charts = charts, .chart_count = 3, .columns = 1, .width = 1000, .height = 1200};
    return chart_write_png_or_say(&figure, path);
}

static json_t *optimize_settings(mu_model *model, const mu_model_options *options, const motion_analysis_options *opts,
                                 const cost_options *cost, double step)
{
    json_t *settings = motion_analysis_settings(model, options, opts, step);
    if (settings != NULL) {
        json_object_set_new(settings, "exponent", json_real(cost->exponent));
        json_object_set_new(settings, "reserve_scale_N_m", json_real(cost->reserve));
        json_object_set_new(settings, "method",
                            json_string("inverse dynamics, then per frame minimize sum a^p + sum (reserve/R)^2 "
                                        "subject to the hinge torques, NLopt SLSQP, warm-started"));
    }
    return settings;
}

static void print_summary(const table *t, const motion_analysis_options *opts, const cost_options *cost, double step,
                          const char *csv_path, const char *png_path)
{
    motion_analysis_print_header(opts, t->frames, step);
    printf("cost         sum of activation^%g, reserve scale %g N·m\n", cost->exponent, cost->reserve);
    long failures = 0, first_failure = -1;
    for (long i = 0; i < t->frames; ++i) {
        if (column(t, COL_SOLVED)[i] == 0.0) {
            first_failure = failures++ == 0 ? i : first_failure;
        }
    }
    for (int b = 0; b < t->built_count; ++b) {
        const double *net = column(t, hinge_column(t, b, H_NET)), *muscle = column(t, hinge_column(t, b, H_MUSCLE)),
                     *reserve = column(t, hinge_column(t, b, H_RESERVE));
        long peak = 0;
        double mismatch = 0.0;
        for (long i = 0; i < t->frames; ++i) {
            peak = fabs(reserve[i]) > fabs(reserve[peak]) ? i : peak;
            mismatch = fmax(mismatch, fabs(net[i] - muscle[i] - reserve[i]));
        }
        const char *name = t->names[hinge_column(t, b, 0)];
        const int length = (int)(strchr(name, '.') - name);
        printf("%-13s%-12.*s max |reserve| %.4g N·m at %.4f s, worst |net - muscles - reserve| %.2g N·m\n",
               b == 0 ? "hinge" : "", length, name, fabs(reserve[peak]), column(t, COL_TIME)[peak], mismatch);
    }
    printf("solved       %ld of %ld frames", t->frames - failures, t->frames);
    if (failures > 0) {
        const int code = (int)column(t, COL_RESULT)[first_failure];
        const char *name = mu_static_optimizer_result_name(code);
        printf("; %ld not (the first at %.4f s: NLopt result %d, %s)", failures, column(t, COL_TIME)[first_failure],
               code, name != NULL ? name : "unknown");
    }
    printf("\ncsv          %s\nfigure       %s\n", csv_path, png_path);
}

/* Builds the model and the optimizer, reads, smooths and solves the
 * motion, and writes; returns 0 or an exit status. */
static int analyse(const motion_analysis_options *opts, const cost_options *cost, const mu_model_desc *desc)
{
    mu_model_options options;
    mu_model *model = NULL;
    int code = motion_analysis_build_model(opts, desc, &options, &model);
    if (code != 0) {
        return code;
    }
    mu_static_optimization_settings settings = mu_default_static_optimization_settings();
    settings.exponent = cost->exponent;
    settings.reserve_scale = cost->reserve;
    mu_static_optimizer *optimizer = NULL;
    motion m = {0};
    motion_kinematics k = {0};
    table t = {0};
    if (mu_static_optimizer_create(model, &settings, &optimizer) != RB_OK) {
        fprintf(stderr, "sinew: model %s (variant \"%s\", level %d): %s\n", desc->name,
                desc->variants[options.variant].name, opts->level, user_error());
        code = EXIT_USAGE;
    }
    code = code == 0 ? motion_analysis_read(opts, model, &m) : code;
    if (code == 0 && (!motion_kinematics_compute(&m, opts->cutoff, &k) ||
                      !table_init(&t, model, mu_static_optimizer_actuator_count(optimizer), m.frames))) {
        fputs("sinew: out of memory\n", stderr);
        code = EXIT_FAILURE;
    }
    code = code == 0 ? solve(optimizer, &m, &k, opts->motion, &t) : code;
    char csv_path[ATOMIC_FILE_PATH_MAX], png_path[ATOMIC_FILE_PATH_MAX];
    code = code == 0 ? motion_analysis_output_path(opts, "-optimize", "csv", csv_path, sizeof csv_path) : code;
    code = code == 0 ? motion_analysis_output_path(opts, "-optimize", "png", png_path, sizeof png_path) : code;
    if (code == 0 && !write_csv(csv_path, &t, optimize_settings(model, &options, opts, cost, m.step))) {
        code = EXIT_FAILURE;
    }
    if (code == 0 && !write_figure(png_path, &t)) {
        code = EXIT_FAILURE;
    }
    if (code == 0) {
        print_summary(&t, opts, cost, m.step, csv_path, png_path);
    }
    table_free(&t);
    motion_kinematics_free(&k);
    motion_free(&m);
    mu_static_optimizer_destroy(optimizer);
    mu_model_destroy(model);
    return code;
}

int cmd_optimize(int argc, char **argv)
{
    motion_analysis_options opts = motion_analysis_default_options();
    cost_options cost = {.exponent = MU_STATIC_OPTIMIZATION_DEFAULT_EXPONENT,
                         .reserve = MU_STATIC_OPTIMIZATION_DEFAULT_RESERVE_SCALE};
    int code = motion_analysis_parse(&command, argc, argv, &opts, take_cost_option, &cost);
    if (code == MOTION_ANALYSIS_HELP) {
        cli_print_help(&command, stdout);
        return EXIT_SUCCESS;
    }
    mu_model_desc *desc = NULL;
    if (code == 0) {
        code = model_source_load(opts.model, &desc);
    }
    if (code == 0) {
        code = analyse(&opts, &cost, desc);
    }
    mu_model_desc_destroy(desc);
    return code;
}
