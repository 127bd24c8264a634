/* SPDX-License-Identifier: MIT */
/* `sinew moment-arms MODEL --hinge NAME [options]`: a muscle analysis, as
 * OpenSim's: the hinge swept through its range with the rest of the
 * model held at its start pose, and for every muscle that crosses it the
 * moment arm (mu/moment_arms.h), the muscle-tendon length, and the force
 * held still at full activation (active) and relaxed (passive)
 * (mu_muscle_isometric_forces), against the angle. Writes
 * DIR/STEM-moment-arms-HINGE.csv with its provenance sidecar and a figure
 * DIR/STEM-moment-arms-HINGE.png.
 *
 * Everything is computed before anything is written, so a bad option or
 * a hinge that cannot turn alone leaves no file.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "cli/model_source.h"
#include "cli/option_value.h"
#include "cli/options.h"
#include "cli/output_path.h"
#include "cli/user_error.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/csv_table.h"
#include "io/provenance.h"
#include "mu/moment_arms.h"

enum { OPT_HINGE, OPT_MUSCLE, OPT_VARIANT, OPT_FROM, OPT_TO, OPT_STEP, OPT_OUT };

static const cli_option options_table[] = {
    {.name = "hinge", .id = OPT_HINGE, .kind = CLI_TEXT, .value_name = "NAME", .help = "the hinge to sweep (required)"},
    {.name = "muscle",
     .id = OPT_MUSCLE,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "a muscle to report (repeatable)",
     .fallback = "every muscle crossing the hinge"},
    {.name = "variant",
     .id = OPT_VARIANT,
     .kind = CLI_TEXT,
     .value_name = "NAME|N",
     .help = "the variant, by name or index",
     .fallback = "0"},
    {.name = "from",
     .id = OPT_FROM,
     .kind = CLI_NUMBER,
     .value_name = "DEG",
     .help = "first angle",
     .min = -360.0,
     .max = 360.0,
     .fallback = "the hinge's lower limit (-180 without one)"},
    {.name = "to",
     .id = OPT_TO,
     .kind = CLI_NUMBER,
     .value_name = "DEG",
     .help = "last angle",
     .min = -360.0,
     .max = 360.0,
     .fallback = "the hinge's upper limit (180 without one)"},
    {.name = "step",
     .id = OPT_STEP,
     .kind = CLI_NUMBER,
     .value_name = "DEG",
     .help = "angle step, > 0",
     .min = -1e9,
     .max = 1e9,
     .fallback = "1"},
    {.name = "out", .id = OPT_OUT, .kind = CLI_PATH, .value_name = "DIR", .help = "output directory", .fallback = "."},
};

static const cli_command command = {
    .name = "sinew moment-arms",
    .operands = "MODEL --hinge NAME [options]",
    .max_operands = 1,
    .operand = "model",
    .about = "Sweeps a hinge through its range, the rest of the model held still, and writes each crossing\n"
             "muscle's moment arm, muscle-tendon length and isometric force (active at full activation,\n"
             "passive) against the angle: DIR/MODEL-moment-arms-HINGE.csv and .png.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes = "Columns: angle_deg, then per muscle NAME.moment_arm_m (r = -dL/dθ), NAME.length_m (the\n"
             "muscle-tendon path), NAME.active_force_N, NAME.passive_force_N, NAME.max_torque_N_m\n"
             "((active + passive)·r). docs/loads.md gives the method and signs.\n",
};

/* Most angles one sweep may have. */
#define MAX_ANGLES 100000
#define COLUMNS_PER_MUSCLE 5

typedef struct sweep_options {
    const char *model;
    const char *hinge;
    const char **muscles; /* --muscle, in the order given */
    int muscle_count;
    const char *variant;
    double from, to, step;
    bool has_from, has_to;
    const char *out_dir;
} sweep_options;

enum { PARSE_HELP = 100 };

static int parse_arguments(int argc, char **argv, sweep_options *opts)
{
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_HINGE:
            opts->hinge = value.text;
            break;
        case OPT_MUSCLE:
            opts->muscles[opts->muscle_count++] = value.text;
            break;
        case OPT_VARIANT:
            opts->variant = value.text;
            break;
        case OPT_FROM:
            opts->from = value.number;
            opts->has_from = true;
            break;
        case OPT_TO:
            opts->to = value.number;
            opts->has_to = true;
            break;
        case OPT_STEP:
            opts->step = value.number;
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
    if (opts->hinge == NULL) {
        return cli_usage_error(&command, "missing --hinge NAME");
    }
    if (!(opts->step > 0.0)) {
        return cli_usage_error(&command, "--step %g: expected an angle step > 0", opts->step);
    }
    return 0;
}

/* ---------------------------------------------------- choices against the model */

static int find_hinge(const mu_model_desc *desc, const char *name)
{
    for (int h = 0; h < desc->hinge_count; ++h) {
        if (strcmp(desc->hinges[h].name, name) == 0) {
            return h;
        }
    }
    fprintf(stderr, "sinew: --hinge \"%s\": model %s has no such hinge; its hinges are", name, desc->name);
    for (int h = 0; h < desc->hinge_count; ++h) {
        fprintf(stderr, "%s \"%s\"", h == 0 ? "" : ",", desc->hinges[h].name);
    }
    fputs(desc->hinge_count == 0 ? " none\n" : "\n", stderr);
    return -1;
}

/* The range swept: the options within the hinge's limits; returns 0 or
 * an exit status. */
static int choose_range(const mu_model_hinge *hinge, sweep_options *opts)
{
    const double lower = hinge->has_lower ? hinge->lower : -180.0;
    const double upper = hinge->has_upper ? hinge->upper : 180.0;
    opts->from = opts->has_from ? opts->from : lower;
    opts->to = opts->has_to ? opts->to : upper;
    if ((hinge->has_lower && opts->from < lower) || (hinge->has_upper && opts->to > upper) || opts->from > upper ||
        opts->to < lower) {
        fprintf(stderr, "sinew: --from %g --to %g: outside hinge \"%s\"'s range %g .. %g deg\n", opts->from, opts->to,
                hinge->name, lower, upper);
        return EXIT_USAGE;
    }
    if (opts->from > opts->to) {
        fprintf(stderr, "sinew: --from %g is above --to %g; expected from <= to\n", opts->from, opts->to);
        return EXIT_USAGE;
    }
    if ((opts->to - opts->from) / opts->step + 1.0 > MAX_ANGLES) {
        fprintf(stderr, "sinew: --step %g: %g .. %g deg would be more than %d angles; give a larger step\n", opts->step,
                opts->from, opts->to, MAX_ANGLES);
        return EXIT_USAGE;
    }
    return 0;
}

/* The built muscles reported, by index; returns their count, or -1 after
 * a message. */
static int choose_muscles(const mu_model *model, int hinge, const sweep_options *opts, int *chosen)
{
    const int muscles = mu_model_muscle_count(model);
    if (opts->muscle_count == 0) {
        int count = 0;
        for (int m = 0; m < muscles; ++m) {
            if (mu_model_muscle_crosses(model, m, hinge)) {
                chosen[count++] = m;
            }
        }
        if (count == 0) {
            fprintf(stderr, "sinew: no muscle of this variant crosses hinge \"%s\"\n", opts->hinge);
            return -1;
        }
        return count;
    }
    for (int k = 0; k < opts->muscle_count; ++k) {
        chosen[k] = -1;
        for (int m = 0; m < muscles; ++m) {
            if (strcmp(mu_model_muscle_name(model, m), opts->muscles[k]) == 0) {
                chosen[k] = m;
            }
        }
        if (chosen[k] < 0) {
            fprintf(stderr, "sinew: --muscle \"%s\": no such muscle built; the muscles are", opts->muscles[k]);
            for (int m = 0; m < muscles; ++m) {
                fprintf(stderr, "%s \"%s\"", m == 0 ? "" : ",", mu_model_muscle_name(model, m));
            }
            fputs("\n", stderr);
            return -1;
        }
    }
    return opts->muscle_count;
}

/* ------------------------------------------------------------------- sweep */

typedef struct sweep {
    int angle_count;
    int muscle_count;
    int *muscles;   /* built muscle indices */
    double *angles; /* deg */
    double *values; /* [angle][muscle][COLUMNS_PER_MUSCLE] */
} sweep;

static double *value_at(const sweep *s, int a, int m, int c)
{
    return &s->values[((size_t)a * (size_t)s->muscle_count + (size_t)m) * COLUMNS_PER_MUSCLE + (size_t)c];
}

/* Poses the hinge at every angle and reads the muscles; false after a
 * message. */
static bool run_sweep(mu_model *model, int hinge, sweep *s)
{
    const rb_world *world = mu_model_world_to_read(model);
    for (int a = 0; a < s->angle_count; ++a) {
        if (mu_model_pose_hinge(model, hinge, s->angles[a]) != RB_OK) {
            fprintf(stderr, "sinew: %s\n", user_error());
            return false;
        }
        for (int k = 0; k < s->muscle_count; ++k) {
            const int m = s->muscles[k];
            const mu_muscle *muscle = mu_model_built_muscle(model, m);
            double active = 0.0, passive = 0.0, unused = 0.0;
            const double arm = mu_model_moment_arm(model, m, hinge);
            if (mu_muscle_isometric_forces(muscle, world, 1.0, &active, &unused) != RB_OK ||
                mu_muscle_isometric_forces(muscle, world, 0.0, &unused, &passive) != RB_OK || isnan(arm)) {
                fprintf(stderr, "sinew: %s\n", user_error());
                return false;
            }
            *value_at(s, a, k, 0) = arm;
            *value_at(s, a, k, 1) = rb_cable_length(world, mu_muscle_cable(muscle));
            *value_at(s, a, k, 2) = active;
            *value_at(s, a, k, 3) = passive;
            *value_at(s, a, k, 4) = (active + passive) * arm;
        }
    }
    return true;
}

/* ------------------------------------------------------------------ output */

static const char *const column_names[COLUMNS_PER_MUSCLE] = {"moment_arm_m", "length_m", "active_force_N",
                                                             "passive_force_N", "max_torque_N_m"};

/* The sweep as a table (io/csv_table.h: names quoted as RFC 4180 needs,
 * written all or nothing), then its sidecar, which takes `settings`. */
static bool write_csv(const char *path, const sweep *s, const mu_model *model, json_t *settings)
{
    const int count = 1 + COLUMNS_PER_MUSCLE * s->muscle_count;
    char *names = malloc((size_t)count * 512);
    const char **name_of = malloc((size_t)count * sizeof *name_of);
    double *row = malloc((size_t)count * sizeof *row);
    csv_table table = {0};
    char error[ATOMIC_FILE_ERROR_SIZE] = "out of memory";
    bool ok = names != NULL && name_of != NULL && row != NULL;
    for (int c = 0; ok && c < count; ++c) {
        char *name = names + (size_t)c * 512;
        const int k = (c - 1) / COLUMNS_PER_MUSCLE;
        if (c == 0) {
            snprintf(name, 512, "angle_deg");
        } else {
            snprintf(name, 512, "%s.%s", mu_model_muscle_name(model, s->muscles[k]),
                     column_names[(c - 1) % COLUMNS_PER_MUSCLE]);
        }
        name_of[c] = name;
    }
    ok = ok && csv_table_init(&table, count, name_of, error, sizeof error);
    for (int a = 0; ok && a < s->angle_count; ++a) {
        row[0] = s->angles[a];
        for (int c = 1; c < count; ++c) {
            row[c] = *value_at(s, a, (c - 1) / COLUMNS_PER_MUSCLE, (c - 1) % COLUMNS_PER_MUSCLE);
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
    free(names);
    free(name_of);
    free(row);
    return ok;
}

/* Four charts against the angle: moment arm, length, active and passive
 * force, one line per muscle. */
static bool write_figure(const char *path, const sweep *s, const mu_model *model, const char *hinge)
{
    static const char *const y_labels[4] = {"moment arm (m)", "muscle-tendon length (m)",
                                            "active force at full activation (N)", "passive force (N)"};
    const int muscles = s->muscle_count < CHART_MAX_SERIES ? s->muscle_count : CHART_MAX_SERIES;
    double *columns = malloc((size_t)4 * (size_t)muscles * (size_t)s->angle_count * sizeof *columns + 1);
    chart_series *series = malloc((size_t)4 * (size_t)muscles * sizeof *series + 1);
    if (columns == NULL || series == NULL) {
        free(columns);
        free(series);
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    chart charts[4];
    char titles[4][256];
    char x_label[256];
    snprintf(x_label, sizeof x_label, "%s angle (deg)", hinge);
    for (int q = 0; q < 4; ++q) {
        for (int k = 0; k < muscles; ++k) {
            double *y = &columns[((size_t)q * (size_t)muscles + (size_t)k) * (size_t)s->angle_count];
            for (int a = 0; a < s->angle_count; ++a) {
                y[a] = *value_at(s, a, k, q);
            }
            series[q * muscles + k] = (chart_series){.label = mu_model_muscle_name(model, s->muscles[k]),
                                                     .x = s->angles,
                                                     .y = y,
                                                     .count = (size_t)s->angle_count};
        }
        snprintf(titles[q], sizeof titles[q], "%s", y_labels[q]);
        charts[q] = (chart){.title = titles[q],
                            .x_label = x_label,
                            .y_label = y_labels[q],
                            .series = &series[q * muscles],
                            .series_count = muscles};
    }
    const chart_figure figure = {.charts = charts, .chart_count = 4, .columns = 2, .width = 1400, .height = 1000};
    const bool written = chart_write_png_or_say(&figure, path);
    free(columns);
    free(series);
    return written;
}

/* DIR/STEM-moment-arms-HINGE.EXTENSION, the hinge's name with every
 * character but letters and digits as '-'; returns 0 or an exit status. */
static int output_path(const sweep_options *opts, const char *extension, char *path, size_t path_size)
{
    char stem[MODEL_STEM_SIZE];
    model_source_stem(opts->model, stem, sizeof stem);
    char suffix[300];
    snprintf(suffix, sizeof suffix, "-moment-arms-%s", opts->hinge);
    for (char *c = suffix + strlen("-moment-arms-"); *c != '\0'; ++c) {
        const bool plain = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9');
        *c = plain ? *c : '-';
    }
    return output_path_in_folder(opts->out_dir, stem, suffix, extension, path, path_size);
}

static json_t *sweep_settings(mu_model *model, const mu_model_options *options, const sweep_options *opts)
{
    json_t *settings = provenance_model_settings(model, options);
    if (settings != NULL) {
        json_object_set_new(settings, "hinge", json_string(opts->hinge));
        json_object_set_new(settings, "from_deg", json_real(opts->from));
        json_object_set_new(settings, "to_deg", json_real(opts->to));
        json_object_set_new(settings, "step_deg", json_real(opts->step));
        json_object_set_new(settings, "moment_arm_method", json_string("analytic: -dL/dθ of the path's segments"));
    }
    return settings;
}

/* Builds the model, checks the choices, sweeps and writes; returns 0 or
 * an exit status. */
static int analyse(sweep_options *opts, mu_model_desc *desc, sweep *s)
{
    int variant = 0;
    int code = model_source_choose_variant(desc, opts->variant, &variant);
    const int hinge = code == 0 ? find_hinge(desc, opts->hinge) : -1;
    if (code != 0 || hinge < 0) {
        return code != 0 ? code : EXIT_USAGE;
    }
    code = choose_range(&desc->hinges[hinge], opts);
    if (code != 0) {
        return code;
    }
    /* Statics: the activation is set, not reached through its dynamics. */
    for (int m = 0; m < desc->muscle_count; ++m) {
        desc->muscles[m].activation_dynamics = false;
    }
    mu_model_options options = mu_default_model_options();
    options.variant = variant;
    mu_model *model = NULL;
    if (mu_model_create(desc, &options, &model) != RB_OK) {
        fprintf(stderr, "sinew: building the model failed: %s\n", user_error());
        return EXIT_FAILURE;
    }
    if (rb_joint_id_is_null(mu_model_hinge_joint(model, hinge))) {
        fprintf(stderr, "sinew: hinge \"%s\" is not built in variant \"%s\"\n", opts->hinge,
                desc->variants[variant].name);
        mu_model_destroy(model);
        return EXIT_USAGE;
    }
    s->angle_count = (int)floor((opts->to - opts->from) / opts->step + 1e-9) + 1;
    s->muscles = malloc(((size_t)mu_model_muscle_count(model) + (size_t)opts->muscle_count + 1) * sizeof *s->muscles);
    s->angles = malloc((size_t)s->angle_count * sizeof *s->angles);
    s->muscle_count = s->muscles != NULL ? choose_muscles(model, hinge, opts, s->muscles) : -1;
    if (s->muscle_count > 0) {
        s->values = malloc((size_t)s->angle_count * (size_t)s->muscle_count * COLUMNS_PER_MUSCLE * sizeof *s->values);
    }
    code = s->muscle_count < 0 ? EXIT_USAGE : 0;
    if (code == 0 && (s->angles == NULL || s->values == NULL)) {
        fputs("sinew: out of memory\n", stderr);
        code = EXIT_FAILURE;
    }
    for (int a = 0; code == 0 && a < s->angle_count; ++a) {
        s->angles[a] = opts->from + a * opts->step;
    }
    code = code == 0 && !run_sweep(model, hinge, s) ? EXIT_FAILURE : code;
    char csv_path[ATOMIC_FILE_PATH_MAX], png_path[ATOMIC_FILE_PATH_MAX];
    if (code == 0) {
        code = output_path(opts, "csv", csv_path, sizeof csv_path);
    }
    if (code == 0) {
        code = output_path(opts, "png", png_path, sizeof png_path);
    }
    if (code == 0 && !write_csv(csv_path, s, model, sweep_settings(model, &options, opts))) {
        code = EXIT_FAILURE;
    }
    if (code == 0 && !write_figure(png_path, s, model, opts->hinge)) {
        code = EXIT_FAILURE;
    }
    if (code == 0) {
        printf("hinge        %s, %g .. %g deg by %g (%d angles), the rest of the model held\n", opts->hinge, opts->from,
               opts->to, opts->step, s->angle_count);
        for (int k = 0; k < s->muscle_count; ++k) {
            int peak = 0;
            for (int a = 1; a < s->angle_count; ++a) {
                peak = fabs(*value_at(s, a, k, 0)) > fabs(*value_at(s, peak, k, 0)) ? a : peak;
            }
            printf("%-13s%-24s %8.4f m at %g deg\n", k == 0 ? "peak arm" : "",
                   mu_model_muscle_name(model, s->muscles[k]), *value_at(s, peak, k, 0), s->angles[peak]);
        }
        printf("csv          %s\nfigure       %s\n", csv_path, png_path);
    }
    mu_model_destroy(model);
    return code;
}

int cmd_moment_arms(int argc, char **argv)
{
    sweep_options opts = {.step = 1.0, .out_dir = "."};
    opts.muscles = malloc(((size_t)argc + 1) * sizeof *opts.muscles);
    if (opts.muscles == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    int code = parse_arguments(argc, argv, &opts);
    if (code == PARSE_HELP) {
        cli_print_help(&command, stdout);
        free(opts.muscles);
        return EXIT_SUCCESS;
    }
    mu_model_desc *desc = NULL;
    if (code == 0) {
        code = model_source_load(opts.model, &desc);
    }
    sweep s = {0};
    if (code == 0) {
        code = analyse(&opts, desc, &s);
    }
    free(s.muscles);
    free(s.angles);
    free(s.values);
    mu_model_desc_destroy(desc);
    free(opts.muscles);
    return code;
}
