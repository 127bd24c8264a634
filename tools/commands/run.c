/* SPDX-License-Identifier: MIT */
/* `sinew run MODEL [options]`: build a muscle model, drive its muscles
 * from the command line and a control file, step it frame by frame,
 * write a CSV of every frame (recorder.h) and print a summary (and, with
 * --summary, write it as JSON: run_summary.h).
 *
 * Everything that can be checked is checked before the first frame: the
 * options, the model file, the variant and weight, every control (names
 * against the model), and that the CSV can be created; a run then fails
 * only if the engine or the disk does.
 */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/model_source.h"
#include "cli/option_value.h"
#include "cli/options.h"
#include "cli/output_path.h"
#include "cli/user_error.h"
#include "commands.h"
#include "control_file.h"
#include "controls.h"
#include "frame_loads.h"
#include "load_peaks.h"
#include "muscle_parameter.h"
#include "progress.h"
#include "recorder.h"
#include "run_summary.h"

enum {
    OPT_VARIANT,
    OPT_WEIGHT,
    OPT_WEIGHT_INDEX,
    OPT_LEVEL,
    OPT_DURATION,
    OPT_ACTIVATION,
    OPT_TENSION,
    OPT_RECRUIT,
    OPT_CONTROL,
    OPT_OUT,
    OPT_WELD_GLUES,
    OPT_STRICT,
    OPT_NAME,
    OPT_SUMMARY,
    OPT_SUBSTEPS,
    OPT_SOLVER,
    OPT_VELOCITY_ITERATIONS,
    OPT_POSITION_ITERATIONS,
    OPT_MUSCLE,
    OPT_DIGITS,
};

static const cli_option options_table[] = {
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
     .help = "0 nothing, 1 bones, 2 + joints, 3 + muscles, 4 + weight",
     .min = 0,
     .max = 4,
     .fallback = "4"},
    {.name = "duration",
     .id = OPT_DURATION,
     .kind = CLI_NUMBER,
     .value_name = "S",
     .help = "simulated time in s",
     .min = 0.0,
     .max = 1e6,
     .min_open = true,
     .fallback = "10"},
    {.name = "activation",
     .id = OPT_ACTIVATION,
     .kind = CLI_TEXT,
     .value_name = "NAME=A",
     .help = "activation 0 .. 1 of a muscle or group from t = 0 (repeatable)"},
    {.name = "tension",
     .id = OPT_TENSION,
     .kind = CLI_TEXT,
     .value_name = "NAME=N",
     .help = "tension target in N of a muscle or group from t = 0 (repeatable)"},
    {.name = "recruit",
     .id = OPT_RECRUIT,
     .kind = CLI_TEXT,
     .value_name = "NAME=N",
     .help = "neurons 0 .. pool size recruited by a torque muscle from t = 0 (repeatable;\n"
             "the worm's is \"Torque Muscle\", `sinew models` lists each model's)"},
    {.name = "control",
     .id = OPT_CONTROL,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "scheduled controls: lines `TIME activation NAME VALUE`,\n"
             "`TIME tension NAME NEWTONS`, `TIME recruit NAME NEURONS`,\n"
             "`TIME pulse NAME [VALUE]`, and shapes of each quantity:\n"
             "`TIME [QUANTITY] ramp NAME FROM TO DURATION`,\n"
             "`... sine NAME MEAN AMPLITUDE FREQUENCY DURATION`,\n"
             "`... pulses NAME LEVEL FREQUENCY WIDTH DURATION` (docs/cli.md);\n"
             "'#' comments; names with spaces in double quotes"},
    {.name = "out",
     .id = OPT_OUT,
     .kind = CLI_PATH,
     .value_name = "DIR",
     .help = "directory of the CSV, DIR/STEM.csv",
     .fallback = "."},
    {.name = "name",
     .id = OPT_NAME,
     .kind = CLI_TEXT,
     .value_name = "STEM",
     .help = "the CSV's name without .csv (letters, digits, . _ + - and =),\n"
             "so that runs can share a folder",
     .fallback = "the model's"},
    {.name = "digits",
     .id = OPT_DIGITS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "significant digits of the CSV's numbers; 17 writes every double exactly",
     .min = RECORDER_MIN_DIGITS,
     .max = RECORDER_EXACT_DIGITS,
     .fallback = "10"},
    {.name = "summary",
     .id = OPT_SUMMARY,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "also write the summary as JSON to FILE (docs/sweeps.md)"},
    {.name = "substeps",
     .id = OPT_SUBSTEPS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "substeps per frame (frame rate x substeps in 60 .. 100000)",
     .min = 1,
     .max = 1000,
     .fallback = "the model's"},
    {.name = "solver",
     .id = OPT_SOLVER,
     .kind = CLI_TEXT,
     .value_name = "TYPE",
     .help = "the engine's solver: baumgarte, ngs or soft_step",
     .fallback = "ngs"},
    {.name = "velocity-iterations",
     .id = OPT_VELOCITY_ITERATIONS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "the solver's velocity iterations per substep",
     .min = 1,
     .max = 1000,
     .fallback = "4"},
    {.name = "position-iterations",
     .id = OPT_POSITION_ITERATIONS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "the solver's position iterations per substep",
     .min = 0,
     .max = 1000,
     .fallback = "1"},
    {.name = "muscle",
     .id = OPT_MUSCLE,
     .kind = CLI_TEXT,
     .value_name = "NAME.PARAM=V",
     .help = "set a muscle's parameter over the model file's (repeatable): max_force (N),\n"
             "max_velocity (m/s), pennation_angle (deg), activation_time, deactivation_time (s)"},
    {.name = "weld-glues",
     .id = OPT_WELD_GLUES,
     .kind = CLI_FLAG,
     .value_name = NULL,
     .help = "keep glues as weld joints instead of merged bodies"},
    {.name = "strict",
     .id = OPT_STRICT,
     .kind = CLI_FLAG,
     .value_name = NULL,
     .help = "stop with an error (exit 1, no CSV) when the run fails: a hinge torn open, a runaway speed"},
};

static const cli_command command = {
    .name = "sinew run",
    .operands = "MODEL [options]",
    .max_operands = 1,
    .operand = "model",
    .about = "Runs a muscle model, writes a CSV of every frame and prints a summary.\n"
             "MODEL is a built-in model (sample, arm, leg, leg-unlimited, worm; see `sinew models`) or a model file\n"
             "(a path containing '/' or ending in .json).\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes = "Controls act in order: the command line's, then the file's. The CSV has one row per\n"
             "frame: time_s, then per muscle NAME.activation, NAME.target_tension_N, NAME.length_m,\n"
             "NAME.normalized_length, NAME.velocity_m_s, NAME.normalized_velocity,\n"
             "NAME.contraction_m, NAME.normalized_contraction, NAME.active_force_N,\n"
             "NAME.passive_force_N, NAME.total_force_N, NAME.excitation, NAME.fibre_length_m,\n"
             "NAME.tendon_length_m, NAME.pennation_angle_deg; per torque muscle NAME.recruited_neurons,\n"
             "NAME.exertion, NAME.torque_N_m; per hinge NAME.angle_deg; per part\n"
             "NAME.x_m, NAME.y_m, NAME.angle_deg; per joint NAME.reaction_x_N, NAME.reaction_y_N,\n"
             "NAME.reaction_along_N, NAME.reaction_across_N, NAME.reaction_torque_N_m,\n"
             "NAME.muscle_torque_N_m; per muscle and hinge it crosses MUSCLE.HINGE.moment_arm_m,\n"
             "MUSCLE.HINGE.torque_N_m; per bone that moves NAME.max_stress_Pa, NAME.max_strain,\n"
             "NAME.safety_factor, NAME.worst_section_m, NAME.axial_force_N, NAME.bending_moment_N_m\n"
             "(docs/cli.md, \"The CSV\"; docs/loads.md).\n",
};

/* Most frames a run may have: beyond any useful run (46 hours of
 * simulated time at 60 Hz), and a bound on the CSV a typing mistake could
 * start writing (one row a frame, about 1 kB a row for the arm). */
#define MAX_FRAMES 1e7

/* --------------------------------------------------------------- options */

typedef struct command_line_control {
    control_kind kind;
    const char *text; /* NAME=VALUE as given */
} command_line_control;

typedef struct run_options {
    const char *model;
    const char *variant; /* NULL: variant 0 */
    double weight_kg;    /* when has_weight_kg */
    bool has_weight_kg;
    int weight_index; /* -1: not given */
    int level;
    double duration;
    command_line_control *controls; /* in the order given */
    int control_count;
    const char **recruits; /* NAME=N of torque muscles, in the order given */
    int recruit_count;
    const char *control_path; /* NULL: none */
    const char *out_dir;
    bool weld_glues;
    bool strict;                  /* a failed run (mu_model_failure) is an error, not a warning */
    const char *name;             /* NULL: the model's stem */
    const char *summary_path;     /* NULL: no JSON summary */
    int digits;                   /* significant digits of the CSV's numbers */
    int substeps;                 /* 0: the model's */
    const char *solver;           /* NULL: the model's */
    int velocity_iterations;      /* 0: the model's */
    int position_iterations;      /* -1: the model's */
    const char **muscle_settings; /* NAME.PARAM=VALUE, in the order given */
    int muscle_setting_count;
    int argc; /* the arguments after `run`, for the JSON summary */
    char **argv;
} run_options;

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

/* Whether a --name is one file name on every file system and in every
 * shell without quotes: no '/', no space, no leading '.' (hidden, "..").
 */
static bool name_is_safe(const char *name)
{
    size_t length = strlen(name);
    return length > 0 && length < MODEL_STEM_SIZE && name[0] != '.' &&
           strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._+-=") == length;
}

/* Parses the arguments after `sinew run`: one MODEL and options, in any
 * order. opts->controls, opts->recruits and opts->muscle_settings must
 * hold argc entries. */
static parse_result parse_arguments(int argc, char **argv, run_options *opts)
{
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
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
        case OPT_DURATION:
            opts->duration = value.number;
            break;
        case OPT_ACTIVATION:
        case OPT_TENSION:
            opts->controls[opts->control_count++] = (command_line_control){
                .kind = id == OPT_ACTIVATION ? CONTROL_ACTIVATION : CONTROL_TENSION,
                .text = value.text,
            };
            break;
        case OPT_RECRUIT:
            opts->recruits[opts->recruit_count++] = value.text;
            break;
        case OPT_CONTROL:
            opts->control_path = value.text;
            break;
        case OPT_OUT:
            opts->out_dir = value.text;
            break;
        case OPT_WELD_GLUES:
            opts->weld_glues = true;
            break;
        case OPT_STRICT:
            opts->strict = true;
            break;
        case OPT_NAME:
            opts->name = value.text;
            break;
        case OPT_SUMMARY:
            opts->summary_path = value.text;
            break;
        case OPT_DIGITS:
            opts->digits = (int)value.integer;
            break;
        case OPT_SUBSTEPS:
            opts->substeps = (int)value.integer;
            break;
        case OPT_SOLVER:
            opts->solver = value.text;
            break;
        case OPT_VELOCITY_ITERATIONS:
            opts->velocity_iterations = (int)value.integer;
            break;
        case OPT_POSITION_ITERATIONS:
            opts->position_iterations = (int)value.integer;
            break;
        case OPT_MUSCLE:
            opts->muscle_settings[opts->muscle_setting_count++] = value.text;
            break;
        default:
            break;
        }
    }
    if (id == CLI_END && parser.operand_count == 1) {
        opts->model = parser.operands[0];
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? PARSE_HELP : PARSE_ERROR;
    }
    if (opts->model == NULL) {
        cli_usage_error(&command, "missing the model (sample, arm, leg, leg-unlimited, worm or a model file)");
        return PARSE_ERROR;
    }
    if (opts->has_weight_kg && opts->weight_index >= 0) {
        cli_usage_error(&command, "give --weight or --weight-index, not both");
        return PARSE_ERROR;
    }
    if (opts->name != NULL && !name_is_safe(opts->name)) {
        cli_usage_error(&command,
                        "--name \"%s\": expected at most %d letters, digits, '.', '_', '+', '-' or '=', not "
                        "starting with '.'",
                        opts->name, MODEL_STEM_SIZE - 1);
        return PARSE_ERROR;
    }
    return PARSE_OK;
}

/* ------------------------------------------- choices against the model */

/* Adds the command line's controls at t = 0, in the order given; returns
 * 0 or an exit status. */
static int add_command_line_controls(const run_options *opts, controls *schedule)
{
    for (int k = 0; k < opts->control_count; ++k) {
        const command_line_control *control = &opts->controls[k];
        const char *option = control->kind == CONTROL_ACTIVATION ? "--activation" : "--tension";
        /* The last '=': a model's names may hold one, its numbers cannot. */
        const char *equals = strrchr(control->text, '=');
        if (equals == NULL || equals == control->text) {
            fprintf(stderr, "sinew: %s expects MUSCLE_OR_GROUP=VALUE, got \"%s\"\n", option, control->text);
            return EXIT_USAGE;
        }
        char name[1024];
        snprintf(name, sizeof name, "%.*s", (int)(equals - control->text), control->text);
        double value;
        char error[OPTION_ERROR_SIZE];
        double max = control->kind == CONTROL_ACTIVATION ? 1.0 : CONTROL_MAX_TENSION;
        const char *quantity = control->kind == CONTROL_ACTIVATION ? "the activation" : "the tension in N";
        if (!option_parse_double(quantity, equals + 1, 0.0, false, max, &value, error, sizeof error) ||
            !controls_add(schedule, 0.0, control->kind, name, value, error, sizeof error)) {
            fprintf(stderr, "sinew: %s \"%s\": %s\n", option, control->text, error);
            return EXIT_USAGE;
        }
    }
    return 0;
}

/* Recruits the torque muscles' neurons named by --recruit NAME=N;
 * returns 0 or an exit status. */
static int apply_recruits(const run_options *opts, mu_model *model)
{
    for (int k = 0; k < opts->recruit_count; ++k) {
        const char *text = opts->recruits[k];
        const char *equals = strrchr(text, '=');
        if (equals == NULL || equals == text) {
            fprintf(stderr, "sinew: --recruit expects TORQUE_MUSCLE=NEURONS, got \"%s\"\n", text);
            return EXIT_USAGE;
        }
        char name[1024];
        snprintf(name, sizeof name, "%.*s", (int)(equals - text), text);
        int neurons;
        char error[OPTION_ERROR_SIZE];
        if (!option_parse_int("the neurons recruited", equals + 1, 0, MU_MAX_MOTOR_NEURONS, &neurons, error,
                              sizeof error)) {
            fprintf(stderr, "sinew: --recruit \"%s\": %s\n", text, error);
            return EXIT_USAGE;
        }
        if (mu_model_recruit(model, name, neurons) != RB_OK) {
            fprintf(stderr, "sinew: --recruit \"%s\": %s\n", text, user_error());
            return EXIT_USAGE;
        }
    }
    return 0;
}

static int engine_failure(const char *what)
{
    fprintf(stderr, "sinew: %s failed: %s (%s)\n", what, user_error(), rb_status_name(rb_last_status()));
    return EXIT_FAILURE;
}

/* Sets the description's muscle parameters named by --muscle
 * NAME.PARAM=VALUE, before the model is built from it (so a max_force
 * replaces the one the file gives or derives); returns 0 or an exit
 * status. */
static int apply_muscle_settings(const run_options *opts, mu_model_desc *desc)
{
    for (int k = 0; k < opts->muscle_setting_count; ++k) {
        const char *text = opts->muscle_settings[k];
        /* The last '=' and the last '.' before it: a muscle's name may hold either. */
        const char *equals = strrchr(text, '=');
        const char *dot = NULL;
        for (const char *c = text; equals != NULL && c < equals; ++c) {
            dot = *c == '.' ? c : dot;
        }
        if (equals == NULL || dot == NULL || dot == text) {
            fprintf(stderr, "sinew: --muscle expects MUSCLE.PARAMETER=VALUE, got \"%s\"\n", text);
            return EXIT_USAGE;
        }
        char name[1024];
        snprintf(name, sizeof name, "%.*s", (int)(dot - text), text);
        mu_model_ref ref;
        if (!mu_model_desc_find(desc, name, &ref) || ref.kind != MU_MODEL_MUSCLE) {
            fprintf(stderr, "sinew: --muscle \"%s\": the model has no muscle \"%s\"\n", text, name);
            return EXIT_USAGE;
        }
        size_t parameter_length = (size_t)(equals - dot - 1);
        const muscle_parameter *parameter = muscle_parameter_find(dot + 1, parameter_length);
        if (parameter == NULL) {
            fprintf(stderr, "sinew: --muscle \"%s\": unknown parameter \"%.*s\" (" MUSCLE_PARAMETER_NAMES ")\n", text,
                    (int)parameter_length, dot + 1);
            return EXIT_USAGE;
        }
        double value;
        char error[OPTION_ERROR_SIZE];
        char quantity[64];
        snprintf(quantity, sizeof quantity, "%s in %s", parameter->name, parameter->unit);
        if (!option_parse_double(quantity, equals + 1, parameter->min, false, parameter->max, &value, error,
                                 sizeof error)) {
            fprintf(stderr, "sinew: --muscle \"%s\": %s\n", text, error);
            return EXIT_USAGE;
        }
        *muscle_parameter_field(parameter, &desc->muscles[ref.index]) = value;
    }
    return 0;
}

/* --substeps over the description's, within the format's bound on the
 * substep rate; returns 0 or an exit status. */
static int apply_substeps(const run_options *opts, mu_model_desc *desc)
{
    if (opts->substeps == 0) {
        return 0;
    }
    double rate = desc->frame_rate * opts->substeps;
    if (rate < 60.0 || rate > 1e5) {
        fprintf(stderr,
                "sinew: --substeps %d at %g frames per second is %g substeps per second, expected 60 .. 100000\n",
                opts->substeps, desc->frame_rate, rate);
        return EXIT_USAGE;
    }
    desc->substeps = opts->substeps;
    return 0;
}

/* --solver and the iterations over the engine settings the model chose
 * (the model's substeps are kept); returns 0 or an exit status. */
static int apply_solver(const run_options *opts, mu_model *model)
{
    rb_world *world = mu_model_world(model);
    rb_solver_settings settings = rb_world_solver_settings(world);
    if (opts->solver != NULL && rb_solver_type_from_name(opts->solver, &settings.type) != RB_OK) {
        fprintf(stderr, "sinew: --solver \"%s\": %s\n", opts->solver, user_error());
        return EXIT_USAGE;
    }
    if (opts->velocity_iterations > 0) {
        settings.velocity_iterations = opts->velocity_iterations;
    }
    if (opts->position_iterations >= 0) {
        settings.position_iterations = opts->position_iterations;
    }
    if (rb_world_set_solver_settings(world, &settings) != RB_OK) {
        return engine_failure("setting the solver");
    }
    return 0;
}

/* DIR/STEM.csv; returns 0 or an exit status. The directory is checked
 * here so that the message names --out rather than a temporary file. */
static int csv_path_for(const run_options *opts, char *path, size_t path_size)
{
    char stem[MODEL_STEM_SIZE];
    if (opts->name != NULL) {
        snprintf(stem, sizeof stem, "%s", opts->name);
    } else {
        model_source_stem(opts->model, stem, sizeof stem);
    }
    return output_path_in_folder(opts->out_dir, stem, "", "csv", path, path_size);
}

/* The folder of --summary FILE exists, so that a run is not lost for a
 * summary that cannot be written; returns 0 or an exit status. */
static int check_summary_folder(const run_options *opts)
{
    if (opts->summary_path == NULL) {
        return 0;
    }
    const char *slash = strrchr(opts->summary_path, '/');
    char folder[ATOMIC_FILE_PATH_MAX];
    snprintf(folder, sizeof folder, "%.*s",
             slash == NULL                 ? 1
             : slash == opts->summary_path ? 1
                                           : (int)(slash - opts->summary_path),
             slash == NULL ? "." : opts->summary_path);
    struct stat info;
    if (stat(folder, &info) != 0 || !S_ISDIR(info.st_mode)) {
        fprintf(stderr, "sinew: --summary %s: the folder %s does not exist\n", opts->summary_path, folder);
        return EXIT_FAILURE;
    }
    return 0;
}

/* ------------------------------------------------------------------ run */

typedef struct run_state {
    const run_options *opts;
    mu_model_desc *desc;
    int variant;
    int weight_index;
    long frames;
    mu_model *model;
    controls schedule;
    recorder csv;
    char csv_path[ATOMIC_FILE_PATH_MAX];
    double *peak_force; /* N, by built muscle */
    double *peak_time;  /* s */
    double *angle_min;  /* deg, by hinge; NaN for a hinge not built */
    double *angle_max;
    frame_loads frame; /* the present frame's loads, read once for the CSV and the peaks */
    load_peaks loads;  /* the joints' peak loads */
    double wall_seconds, step_seconds;
    bool failure_reported; /* mu_model_failure said on stderr */
} run_state;

/* The extremes the summary reports, sampled at the end of each frame. */
static void track_extremes(run_state *run, double time)
{
    for (int m = 0; m < mu_model_muscle_count(run->model); ++m) {
        double force = mu_model_muscle_readout(run->model, m).total_force;
        if (force > run->peak_force[m]) {
            run->peak_force[m] = force;
            run->peak_time[m] = time;
        }
    }
    for (int h = 0; h < mu_model_hinge_count(run->model); ++h) {
        double angle = mu_model_hinge_angle(run->model, h);
        /* fmin and fmax ignore a NaN start, so the first frame sets both. */
        run->angle_min[h] = fmin(run->angle_min[h], angle);
        run->angle_max[h] = fmax(run->angle_max[h], angle);
    }
    load_peaks_track(&run->loads, run->model, &run->frame, time);
}

/* Steps every frame, applying the controls before it and recording it
 * after; returns 0 or an exit status, the CSV committed or abandoned. */
static int run_frames(run_state *run)
{
    const double frame_rate = run->desc->frame_rate;
    char error[ATOMIC_FILE_ERROR_SIZE];
    progress bar;
    progress_start(&bar, run->frames, 1.0 / frame_rate);
    const double start = progress_now();
    for (long frame = 0; frame < run->frames; ++frame) {
        /* The controls act before every substep whose values they change. */
        const double step_start = progress_now();
        rb_status status = controls_step_frame(&run->schedule, run->model, frame);
        run->step_seconds += progress_now() - step_start;
        if (status != RB_OK) {
            progress_finish(&bar);
            recorder_abandon(&run->csv);
            return engine_failure("stepping the model");
        }
        /* The first sign that the run has left physics: said at once on
         * stderr (and again in the summary), or, with --strict, the end. */
        const char *failure = mu_model_failure(run->model);
        if (failure != NULL && !run->failure_reported) {
            run->failure_reported = true;
            if (run->opts->strict) {
                progress_finish(&bar);
                recorder_abandon(&run->csv);
                fprintf(stderr, "sinew: the run failed (--strict): %s\n", failure);
                return EXIT_FAILURE;
            }
            fprintf(stderr,
                    "sinew: warning: the run failed: %s; its results past that time describe no body "
                    "(--strict makes this an error)\n",
                    failure);
        }
        /* (frame + 1)/rate rather than a running sum, which would drift. */
        const double time = (double)(frame + 1) / frame_rate;
        if (!frame_loads_read(&run->frame, run->model)) {
            progress_finish(&bar);
            recorder_abandon(&run->csv);
            fprintf(stderr, "sinew: cannot read the bone stress: %s\n", rb_last_error());
            return EXIT_FAILURE;
        }
        track_extremes(run, time);
        if (!recorder_write_row(&run->csv, run->model, &run->frame, time, error, sizeof error)) {
            progress_finish(&bar);
            recorder_abandon(&run->csv);
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
        progress_update(&bar, frame + 1);
    }
    progress_finish(&bar);
    if (!recorder_commit(&run->csv, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    run->wall_seconds = progress_now() - start;
    return 0;
}

/* -------------------------------------------------------------- summary */

static const char *const level_names[] = {"nothing built", "bones and nails", "bones, joints", "bones, joints, muscles",
                                          "bones, joints, muscles, weight"};

static void print_lines(const char *label, const char *text)
{
    if (*text == '\0') {
        printf("%-13s(none)\n", label);
    }
    for (bool first = true; *text != '\0'; first = false) {
        size_t length = strcspn(text, "\n");
        printf("%-13s%.*s\n", first ? label : "", (int)length, text);
        text += length + (text[length] == '\n');
    }
}

static void print_summary(const run_state *run)
{
    const mu_model_desc *desc = run->desc;
    const mu_model_variant *variant = &desc->variants[run->variant];
    double simulated = (double)run->frames / desc->frame_rate;
    long substeps = run->frames * desc->substeps;
    if (model_source_is_builtin(run->opts->model)) {
        printf("model        %s (built-in)\n", desc->name);
    } else {
        printf("model        %s (from %s)\n", desc->name, run->opts->model);
    }
    printf("variant      %d \"%s\" (%d muscle%s)\n", run->variant, variant->name, variant->muscle_count,
           variant->muscle_count == 1 ? "" : "s");
    if (desc->has_weight) {
        printf("weight       %g kg, choice %d of ", desc->weight.masses[run->weight_index], run->weight_index);
        model_source_print_weights(stdout, desc);
        printf("%s\n", run->opts->level < 4 ? " (not built below level 4)" : "");
    } else {
        printf("weight       none in this model\n");
    }
    printf("level        %d (%s)%s\n", run->opts->level, level_names[run->opts->level],
           run->opts->weld_glues ? ", glues as weld joints" : "");
    printf("frames       %ld at %g Hz, %d substeps each: %d bodies, %d joints in the engine\n", run->frames,
           desc->frame_rate, desc->substeps, mu_model_body_count(run->model), mu_model_joint_count(run->model));
    printf("simulated    %g s\n", simulated);
    printf("wall time    %.3f s, %.3f s of it stepping (%.2f us per substep)\n", run->wall_seconds, run->step_seconds,
           1e6 * run->step_seconds / (double)substeps);
    printf("real time    %.1fx (stepping alone %.1fx)\n", simulated / run->wall_seconds, simulated / run->step_seconds);
    print_lines("warnings", mu_model_warnings(run->model));
    const char *failure = mu_model_failure(run->model);
    printf("failure      %s\n", failure != NULL ? failure : "none (hinges held, speeds physical)");
    int pending = controls_pending(&run->schedule);
    printf("controls     %d applied", run->schedule.event_count - pending);
    printf(pending > 0 ? ", %d after the end of the run not applied\n" : "\n", pending);
    int muscles = mu_model_muscle_count(run->model);
    for (int m = 0; m < muscles; ++m) {
        printf("%-13s%-24s %10.2f N at %.3f s\n", m == 0 ? "peak force" : "", mu_model_muscle_name(run->model, m),
               run->peak_force[m], run->peak_time[m]);
    }
    if (muscles == 0) {
        printf("peak force   (no muscles built)\n");
    }
    for (int t = 0; t < mu_model_torque_muscle_count(run->model); ++t) {
        const mu_motor_pool *pool = mu_model_motor_pool(run->model, t);
        printf("%-13s%-24s %d of %d neurons: exertion %.4f, torque %.4g N·m at the end\n", t == 0 ? "torque" : "",
               mu_model_torque_muscle_name(run->model, t), mu_motor_pool_recruited(pool),
               mu_motor_pool_neuron_count(pool), mu_motor_pool_exertion(pool),
               mu_torque_actuator_torque(mu_model_torque_actuator(run->model, t)));
    }
    bool any_hinge = false;
    for (int h = 0; h < mu_model_hinge_count(run->model); ++h) {
        double angle = mu_model_hinge_angle(run->model, h);
        if (!isnan(angle)) {
            printf("%-13s%-24s %10.2f deg (%.2f .. %.2f over the run)\n", any_hinge ? "" : "final angle",
                   mu_model_hinge_name(run->model, h), angle, run->angle_min[h], run->angle_max[h]);
            any_hinge = true;
        }
    }
    if (!any_hinge) {
        printf("final angle  (no hinges built)\n");
    }
    load_peaks_print(&run->loads, run->model);
    printf("csv          %s (%ld rows, %d columns)\n", run->csv_path, run->csv.rows,
           recorder_column_count(&run->csv, run->model));
}

/* The JSON summary of --summary FILE; returns 0 or an exit status. */
static int write_summary(const run_state *run)
{
    const run_options *opts = run->opts;
    if (opts->summary_path == NULL) {
        return 0;
    }
    char stem[MODEL_STEM_SIZE];
    model_source_stem(opts->model, stem, sizeof stem);
    const mu_model_desc *desc = run->desc;
    int pending = controls_pending(&run->schedule);
    run_summary summary = {
        .argument_count = opts->argc,
        .arguments = opts->argv,
        .model = run->model,
        .model_name = stem,
        .variant = run->variant,
        .level = opts->level,
        .weight_kg = desc->has_weight ? desc->weight.masses[run->weight_index] : NAN,
        .frames = run->frames,
        .simulated_seconds = (double)run->frames / desc->frame_rate,
        .csv_path = run->csv_path,
        .rows = run->csv.rows,
        .columns = recorder_column_count(&run->csv, run->model),
        .controls_applied = run->schedule.event_count - pending,
        .controls_pending = pending,
        .peak_force = run->peak_force,
        .peak_time = run->peak_time,
        .angle_min = run->angle_min,
        .angle_max = run->angle_max,
        .wall_seconds = run->wall_seconds,
        .step_seconds = run->step_seconds,
    };
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!run_summary_write(opts->summary_path, &summary, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    return 0;
}

/* -------------------------------------------------------------- command */

/* Everything before the first frame; returns 0 or an exit status. */
static int prepare(run_state *run)
{
    const run_options *opts = run->opts;
    int code = model_source_load(opts->model, &run->desc);
    if (code == 0) {
        code = model_source_choose_variant(run->desc, opts->variant, &run->variant);
    }
    if (code == 0) {
        code = model_source_choose_weight(run->desc, opts->has_weight_kg, opts->weight_kg, opts->weight_index,
                                          &run->weight_index);
    }
    if (code == 0) {
        code = apply_substeps(opts, run->desc);
    }
    if (code == 0) {
        code = apply_muscle_settings(opts, run->desc);
    }
    if (code != 0) {
        return code;
    }
    double frames = nearbyint(opts->duration * run->desc->frame_rate);
    if (frames < 1.0) {
        fprintf(stderr, "sinew: --duration %g s is %.0f frames at %g Hz, expected at least 1\n", opts->duration, frames,
                run->desc->frame_rate);
        return EXIT_USAGE;
    }
    if (frames > MAX_FRAMES) {
        fprintf(stderr,
                "sinew: --duration %g s is %.0f frames at %g Hz, more than the %.0f a run may write (one CSV "
                "row each); give a shorter --duration\n",
                opts->duration, frames, run->desc->frame_rate, MAX_FRAMES);
        return EXIT_USAGE;
    }
    run->frames = (long)frames;
    if (!controls_init(&run->schedule, run->desc, run->variant)) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    code = add_command_line_controls(opts, &run->schedule);
    if (code != 0) {
        return code;
    }
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (opts->control_path != NULL && !control_file_read(opts->control_path, &run->schedule, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    code = csv_path_for(opts, run->csv_path, sizeof run->csv_path);
    if (code == 0) {
        code = check_summary_folder(opts);
    }
    if (code != 0) {
        return code;
    }
    mu_model_options options = mu_default_model_options();
    options.level = opts->level;
    options.variant = run->variant;
    options.weight_index = run->weight_index;
    options.weld_glues = opts->weld_glues;
    if (mu_model_create(run->desc, &options, &run->model) != RB_OK) {
        return engine_failure("building the model");
    }
    code = apply_solver(opts, run->model);
    if (code == 0) {
        code = apply_recruits(opts, run->model);
    }
    if (code != 0) {
        return code;
    }
    size_t muscles = (size_t)mu_model_muscle_count(run->model) + 1;
    run->peak_force = calloc(muscles, sizeof *run->peak_force);
    run->peak_time = calloc(muscles, sizeof *run->peak_time);
    size_t hinges = (size_t)mu_model_hinge_count(run->model) + 1;
    run->angle_min = malloc(hinges * sizeof *run->angle_min);
    run->angle_max = malloc(hinges * sizeof *run->angle_max);
    if (run->peak_force == NULL || run->peak_time == NULL || run->angle_min == NULL || run->angle_max == NULL ||
        !load_peaks_start(&run->loads, run->model) || !frame_loads_start(&run->frame, run->model)) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    for (size_t h = 0; h < hinges; ++h) {
        run->angle_min[h] = NAN;
        run->angle_max[h] = NAN;
    }
    if (!recorder_open(&run->csv, run->csv_path, run->model, &options, run->opts->digits, error, sizeof error)) {
        fprintf(stderr, "sinew: --out: %s\n", error);
        return EXIT_FAILURE;
    }
    return 0;
}

int cmd_run(int argc, char **argv)
{
    run_options opts = {.weight_index = -1,
                        .level = 4,
                        .duration = 10.0,
                        .out_dir = ".",
                        .position_iterations = -1,
                        .digits = RECORDER_DEFAULT_DIGITS,
                        .argc = argc,
                        .argv = argv};
    opts.controls = malloc(((size_t)argc + 1) * sizeof *opts.controls);
    opts.recruits = malloc(((size_t)argc + 1) * sizeof *opts.recruits);
    opts.muscle_settings = malloc(((size_t)argc + 1) * sizeof *opts.muscle_settings);
    if (opts.controls == NULL || opts.recruits == NULL || opts.muscle_settings == NULL) {
        free(opts.controls);
        free(opts.recruits);
        free(opts.muscle_settings);
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    switch (parse_arguments(argc, argv, &opts)) {
    case PARSE_HELP:
        cli_print_help(&command, stdout);
        free(opts.controls);
        free(opts.recruits);
        free(opts.muscle_settings);
        return EXIT_SUCCESS;
    case PARSE_ERROR:
        free(opts.controls);
        free(opts.recruits);
        free(opts.muscle_settings);
        return EXIT_USAGE;
    case PARSE_OK:
        break;
    }
    run_state run = {.opts = &opts};
    int code = prepare(&run);
    if (code == 0) {
        code = run_frames(&run);
    }
    if (code == 0) {
        print_summary(&run);
        code = write_summary(&run);
    }
    mu_model_destroy(run.model);
    controls_free(&run.schedule);
    mu_model_desc_destroy(run.desc);
    free(run.peak_force);
    free(run.peak_time);
    free(run.angle_min);
    free(run.angle_max);
    load_peaks_free(&run.loads);
    frame_loads_free(&run.frame);
    free(opts.controls);
    free(opts.recruits);
    free(opts.muscle_settings);
    return code;
}
