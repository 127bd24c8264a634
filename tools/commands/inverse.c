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
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "chart/chart.h"
#include "cli/model_source.h"
#include "cli/option_value.h"
#include "cli/options.h"
#include "cli/user_error.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/csv_table.h"
#include "io/provenance.h"
#include "motion_file.h"
#include "motion_filter.h"
#include "mu/inverse_dynamics.h"

#define DEGREES (180.0 / RB_PI)

enum { OPT_MOTION, OPT_CUTOFF, OPT_VARIANT, OPT_WEIGHT, OPT_WEIGHT_INDEX, OPT_LEVEL, OPT_OUT };

static const cli_option options_table[] = {
    {.name = "motion",
     .id = OPT_MOTION,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "the motion: a `sinew run` CSV, or a CSV of time_s and HINGE.angle_deg columns (required)"},
    {.name = "cutoff",
     .id = OPT_CUTOFF,
     .kind = CLI_NUMBER,
     .value_name = "HZ",
     .help = "cut-off of the zero-phase 4th-order Butterworth low-pass; 0 turns it off",
     .min = 0.0,
     .max = 1e6,
     .fallback = "6"},
    {.name = "variant",
     .id = OPT_VARIANT,
     .kind = CLI_TEXT,
     .value_name = "NAME|N",
     .help = "the variant, by name or index",
     .fallback = "0"},
    {.name = "weight",
     .id = OPT_WEIGHT,
     .kind = CLI_NUMBER,
     .value_name = "KG",
     .help = "the weight choice of that mass",
     .min = 0.0,
     .max = 1e9,
     .fallback = "the first"},
    {.name = "weight-index",
     .id = OPT_WEIGHT_INDEX,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "the weight choice by index",
     .min = 0,
     .max = MU_MODEL_MAX_OBJECTS - 1},
    {.name = "level",
     .id = OPT_LEVEL,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "2 joints, 3 + muscles, 4 + weight",
     .min = 0,
     .max = 4,
     .fallback = "4"},
    {.name = "out", .id = OPT_OUT, .kind = CLI_PATH, .value_name = "DIR", .help = "output directory", .fallback = "."},
};

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

typedef struct inverse_options {
    const char *model;
    const char *motion;
    double cutoff;
    const char *variant;
    double weight_kg;
    bool has_weight_kg;
    int weight_index; /* -1: not given */
    int level;
    const char *out_dir;
} inverse_options;

enum { PARSE_HELP = 100 };

static int parse_arguments(int argc, char **argv, inverse_options *opts)
{
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_MOTION:
            opts->motion = value.text;
            break;
        case OPT_CUTOFF:
            opts->cutoff = value.number;
            break;
        case OPT_VARIANT:
            opts->variant = value.text;
            break;
        case OPT_WEIGHT:
            opts->weight_kg = value.number;
            opts->has_weight_kg = true;
            break;
        case OPT_WEIGHT_INDEX:
            opts->weight_index = (int)value.integer;
            break;
        case OPT_LEVEL:
            opts->level = (int)value.integer;
            break;
        default:
            opts->out_dir = value.text;
            break;
        }
    }
    if (id == CLI_END && parser.operand_count == 1) {
        opts->model = parser.operands[0];
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? PARSE_HELP : EXIT_USAGE;
    }
    if (opts->model == NULL) {
        return cli_usage_error(&command, "missing the model (sample, arm, leg, worm or a model file)");
    }
    if (opts->motion == NULL) {
        return cli_usage_error(&command, "missing --motion FILE");
    }
    if (opts->has_weight_kg && opts->weight_index >= 0) {
        return cli_usage_error(&command, "give --weight or --weight-index, not both");
    }
    return 0;
}

/* ---------------------------------------------------- choices against the model */

/* -------------------------------------------------------------- the analysis */

/* Per built hinge and frame: the smoothed angle (deg), its rate (deg/s),
 * acceleration (deg/s²) and the net torque (N·m). */
enum { COL_ANGLE, COL_RATE, COL_ACCELERATION, COL_TORQUE, COLUMNS_PER_HINGE };

typedef struct result {
    long frames;
    int hinge_count;          /* the model's, built or not */
    double *values;           /* [hinge][column][frame] */
    const double *const *raw; /* the motion's angles, by hinge */
    const double *time;
} result;

static double *column_of(const result *r, int hinge, int column)
{
    return &r->values[((size_t)hinge * COLUMNS_PER_HINGE + (size_t)column) * (size_t)r->frames];
}

/* Smooths and differentiates each hinge's angle, then solves every frame;
 * false after a message. */
static bool solve(const mu_model *model, const motion *m, double cutoff, result *r)
{
    const size_t n = (size_t)m->frames;
    r->frames = m->frames;
    r->hinge_count = m->hinge_count;
    r->values = malloc((size_t)m->hinge_count * COLUMNS_PER_HINGE * n * sizeof *r->values + 1);
    double *frame = malloc((4 * (size_t)m->hinge_count + 1) * sizeof *frame);
    if (r->values == NULL || frame == NULL) {
        free(frame);
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    for (int h = 0; h < m->hinge_count; ++h) {
        for (int c = 0; c < COLUMNS_PER_HINGE; ++c) {
            for (size_t i = 0; i < n; ++i) {
                column_of(r, h, c)[i] = NAN;
            }
        }
        if (m->angles[h] == NULL) {
            continue;
        }
        double *angle = column_of(r, h, COL_ANGLE);
        memcpy(angle, m->angles[h], n * sizeof *angle);
        if (cutoff > 0.0 && !motion_filter_low_pass(angle, n, cutoff, 1.0 / m->step)) {
            free(frame);
            fputs("sinew: out of memory\n", stderr);
            return false;
        }
        motion_filter_differentiate(angle, n, m->step, column_of(r, h, COL_RATE), column_of(r, h, COL_ACCELERATION));
    }
    double *angles = frame, *rates = frame + m->hinge_count, *accelerations = frame + 2 * m->hinge_count,
           *torques = frame + 3 * m->hinge_count;
    bool ok = true;
    for (size_t i = 0; ok && i < n; ++i) {
        for (int h = 0; h < m->hinge_count; ++h) {
            const bool built = m->angles[h] != NULL;
            angles[h] = built ? column_of(r, h, COL_ANGLE)[i] : 0.0;
            rates[h] = built ? column_of(r, h, COL_RATE)[i] / DEGREES : 0.0;
            accelerations[h] = built ? column_of(r, h, COL_ACCELERATION)[i] / DEGREES : 0.0;
        }
        ok = mu_model_inverse_dynamics(model, angles, rates, accelerations, torques) == RB_OK;
        for (int h = 0; ok && h < m->hinge_count; ++h) {
            column_of(r, h, COL_TORQUE)[i] = torques[h];
        }
    }
    if (!ok) {
        fprintf(stderr, "sinew: %s\n", user_error());
    }
    free(frame);
    return ok;
}

/* ------------------------------------------------------------------ output */

static const char *const column_names[COLUMNS_PER_HINGE] = {"angle_deg", "velocity_deg_s", "acceleration_deg_s2",
                                                            "net_torque_N_m"};

static bool write_csv(const char *path, const result *r, const mu_model *model, json_t *settings)
{
    int *built = malloc(((size_t)r->hinge_count + 1) * sizeof *built);
    int built_count = 0;
    for (int h = 0; built != NULL && h < r->hinge_count; ++h) {
        if (!rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            built[built_count++] = h;
        }
    }
    const int count = 1 + COLUMNS_PER_HINGE * built_count;
    char *names = malloc((size_t)count * 512);
    const char **name_of = malloc((size_t)count * sizeof *name_of);
    double *row = malloc((size_t)count * sizeof *row);
    csv_table table = {0};
    char error[ATOMIC_FILE_ERROR_SIZE] = "out of memory";
    bool ok = built != NULL && names != NULL && name_of != NULL && row != NULL;
    for (int c = 0; ok && c < count; ++c) {
        char *name = names + (size_t)c * 512;
        if (c == 0) {
            snprintf(name, 512, "time_s");
        } else {
            snprintf(name, 512, "%s.%s", mu_model_hinge_name(model, built[(c - 1) / COLUMNS_PER_HINGE]),
                     column_names[(c - 1) % COLUMNS_PER_HINGE]);
        }
        name_of[c] = name;
    }
    ok = ok && csv_table_init(&table, count, name_of, error, sizeof error);
    for (long i = 0; ok && i < r->frames; ++i) {
        row[0] = r->time[i];
        for (int c = 1; c < count; ++c) {
            row[c] = column_of(r, built[(c - 1) / COLUMNS_PER_HINGE], (c - 1) % COLUMNS_PER_HINGE)[i];
        }
        ok = csv_table_add_row(&table, row, error, sizeof error);
    }
    ok = ok && csv_table_write(&table, path, error, sizeof error);
    if (ok) {
        ok = provenance_write_sidecar(path, settings, error, sizeof error);
    } else {
        json_decref(settings);
    }
    if (!ok) {
        fprintf(stderr, "sinew: %s\n", error);
    }
    csv_table_free(&table);
    free(built);
    free(names);
    free(name_of);
    free(row);
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
            (chart_series){.label = name, .x = r->time, .y = column_of(r, h, COL_TORQUE), .count = count};
        if (cutoff > 0.0) {
            snprintf(labels[angles], sizeof labels[angles], "%s as read", name);
            angle_series[angles] =
                (chart_series){.label = labels[angles], .x = r->time, .y = r->raw[h], .count = count};
            ++angles;
            snprintf(labels[angles], sizeof labels[angles], "%s smoothed (%g Hz)", name, cutoff);
        } else {
            snprintf(labels[angles], sizeof labels[angles], "%s (not smoothed)", name);
        }
        angle_series[angles] =
            (chart_series){.label = labels[angles], .x = r->time, .y = column_of(r, h, COL_ANGLE), .count = count};
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
    char error[CHART_ERROR_SIZE];
    const bool written = chart_write_png(&figure, path, error, sizeof error);
    if (!written) {
        fprintf(stderr, "sinew: %s\n", error);
    }
    return written;
}

/* DIR/STEM-inverse.EXTENSION; returns 0 or an exit status. */
static int output_path(const inverse_options *opts, const char *extension, char *path, size_t path_size)
{
    struct stat info;
    if (stat(opts->out_dir, &info) != 0) {
        fprintf(stderr, "sinew: --out %s: %s\n", opts->out_dir, strerror(errno));
        return EXIT_FAILURE;
    }
    if (!S_ISDIR(info.st_mode)) {
        fprintf(stderr, "sinew: --out %s: not a directory\n", opts->out_dir);
        return EXIT_FAILURE;
    }
    char stem[MODEL_STEM_SIZE];
    model_source_stem(opts->model, stem, sizeof stem);
    const size_t length = strlen(opts->out_dir);
    const char *separator = opts->out_dir[length - 1] == '/' ? "" : "/";
    const int written = snprintf(path, path_size, "%s%s%s-inverse.%s", opts->out_dir, separator, stem, extension);
    if (written < 0 || (size_t)written >= path_size) {
        fprintf(stderr, "sinew: --out %s: the output path is too long\n", opts->out_dir);
        return EXIT_FAILURE;
    }
    return 0;
}

static json_t *inverse_settings(mu_model *model, const mu_model_options *options, const inverse_options *opts,
                                double step)
{
    json_t *settings = provenance_model_settings(model, options);
    if (settings != NULL) {
        json_object_set_new(settings, "motion", json_string(opts->motion));
        json_object_set_new(settings, "sample_rate_Hz", json_real(1.0 / step));
        json_object_set_new(settings, "cutoff_Hz", json_real(opts->cutoff));
        json_object_set_new(settings, "filter",
                            json_string(opts->cutoff > 0.0 ? "zero-phase 4th-order Butterworth low-pass (a 2nd-order "
                                                             "section forwards and backwards, Winter's 0.802 "
                                                             "correction), ends extended by point reflection"
                                                           : "none"));
        json_object_set_new(settings, "derivatives", json_string("second-order finite differences"));
        json_object_set_new(settings, "method", json_string("Newton-Euler over the tree of joints from the ground"));
    }
    return settings;
}

/* The cut-off against the motion's sampling; returns 0 or an exit status. */
static int check_cutoff(const inverse_options *opts, double step)
{
    if (opts->cutoff > 0.0 && !motion_filter_cutoff_valid(opts->cutoff, 1.0 / step)) {
        fprintf(stderr,
                "sinew: --cutoff %g Hz: %s is sampled at %g Hz, so the cut-off must be below %g Hz (or 0 to turn the "
                "filter off)\n",
                opts->cutoff, opts->motion, 1.0 / step, 0.5 / step * MOTION_FILTER_TWO_PASS_CORRECTION);
        return EXIT_USAGE;
    }
    return 0;
}

static void print_summary(const result *r, const mu_model *model, const inverse_options *opts, double step,
                          const char *csv_path, const char *png_path)
{
    printf("motion       %s: %ld frames at %g Hz\n", opts->motion, r->frames, 1.0 / step);
    if (opts->cutoff > 0.0) {
        printf("filter       zero-phase 4th-order Butterworth low-pass at %g Hz\n", opts->cutoff);
    } else {
        printf("filter       none\n");
    }
    const char *label = "peak torque";
    for (int h = 0; h < r->hinge_count; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            continue;
        }
        const double *torque = column_of(r, h, COL_TORQUE);
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
static int analyse(const inverse_options *opts, mu_model_desc *desc, motion *m, result *r)
{
    int variant = 0, weight = 0;
    int code = model_source_choose_variant(desc, opts->variant, &variant);
    code = code == 0
               ? model_source_choose_weight(desc, opts->has_weight_kg, opts->weight_kg, opts->weight_index, &weight)
               : code;
    if (code != 0) {
        return code;
    }
    mu_model_options options = mu_default_model_options();
    options.variant = variant;
    options.weight_index = weight;
    options.level = opts->level;
    mu_model *model = NULL;
    if (mu_model_create(desc, &options, &model) != RB_OK) {
        fprintf(stderr, "sinew: building the model failed: %s\n", user_error());
        return EXIT_FAILURE;
    }
    int built = 0;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        built += !rb_joint_id_is_null(mu_model_hinge_joint(model, h));
    }
    if (built == 0) {
        fprintf(stderr, "sinew: model %s has no hinge at level %d in variant \"%s\": nothing to compute\n", desc->name,
                opts->level, desc->variants[variant].name);
        code = EXIT_USAGE;
    } else if (mu_model_check_tree(model) != RB_OK) {
        fprintf(stderr, "sinew: model %s: %s\n", desc->name, user_error());
        code = EXIT_FAILURE;
    } else if (!motion_file_read(opts->motion, model, m)) {
        code = EXIT_FAILURE;
    }
    code = code == 0 ? check_cutoff(opts, m->step) : code;
    r->raw = (const double *const *)m->angles;
    r->time = m->time;
    code = code == 0 && !solve(model, m, opts->cutoff, r) ? EXIT_FAILURE : code;
    char csv_path[ATOMIC_FILE_PATH_MAX], png_path[ATOMIC_FILE_PATH_MAX];
    code = code == 0 ? output_path(opts, "csv", csv_path, sizeof csv_path) : code;
    code = code == 0 ? output_path(opts, "png", png_path, sizeof png_path) : code;
    if (code == 0 && !write_csv(csv_path, r, model, inverse_settings(model, &options, opts, m->step))) {
        code = EXIT_FAILURE;
    }
    if (code == 0 && !write_figure(png_path, r, model, opts->cutoff)) {
        code = EXIT_FAILURE;
    }
    if (code == 0) {
        print_summary(r, model, opts, m->step, csv_path, png_path);
    }
    mu_model_destroy(model);
    return code;
}

int cmd_inverse(int argc, char **argv)
{
    inverse_options opts = {.cutoff = MOTION_FILTER_DEFAULT_CUTOFF, .weight_index = -1, .level = 4, .out_dir = "."};
    int code = parse_arguments(argc, argv, &opts);
    if (code == PARSE_HELP) {
        cli_print_help(&command, stdout);
        return EXIT_SUCCESS;
    }
    mu_model_desc *desc = NULL;
    if (code == 0) {
        code = model_source_load(opts.model, &desc);
    }
    motion m = {0};
    result r = {0};
    if (code == 0) {
        code = analyse(&opts, desc, &m, &r);
    }
    free(r.values);
    motion_free(&m);
    mu_model_desc_destroy(desc);
    return code;
}
