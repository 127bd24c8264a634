/* SPDX-License-Identifier: MIT */
/* What the analyses of a motion share, `sinew inverse` and `sinew
 * optimize`: their command line (MODEL, --motion, --cutoff, --variant,
 * --weight, --weight-index, --level, --out), the model they build, the
 * motion they read (motion_file.h), smooth and differentiate
 * (motion_filter.h), where they write, and the provenance and the summary
 * lines that say which motion and which filter.
 *
 * A command lists the shared options in its table with the two macros
 * below, around options of its own, and hands motion_analysis_parse a
 * function that takes its own.
 */
#ifndef MOTION_ANALYSIS_H
#define MOTION_ANALYSIS_H

#include <jansson.h>
#include <stdbool.h>

#include "cli/options.h"
#include "motion_file.h"
#include "mu/model.h"
#include "mu/model_desc.h"

/* The shared options' ids; a command's own ids stay below them. */
enum {
    MOTION_OPT_MOTION = 1000,
    MOTION_OPT_CUTOFF,
    MOTION_OPT_VARIANT,
    MOTION_OPT_WEIGHT,
    MOTION_OPT_WEIGHT_INDEX,
    MOTION_OPT_LEVEL,
    MOTION_OPT_OUT,
};

/* --motion and --cutoff, for the start of an options table. */
#define MOTION_ANALYSIS_INPUT_OPTIONS                                                                                  \
    {.name = "motion",                                                                                                 \
     .id = MOTION_OPT_MOTION,                                                                                          \
     .kind = CLI_PATH,                                                                                                 \
     .value_name = "FILE",                                                                                             \
     .help = "the motion: a `sinew run` CSV, or a CSV of time_s and HINGE.angle_deg columns (required)"},              \
    {                                                                                                                  \
        .name = "cutoff", .id = MOTION_OPT_CUTOFF, .kind = CLI_NUMBER, .value_name = "HZ",                             \
        .help = "cut-off of the zero-phase 4th-order Butterworth low-pass; 0 turns it off", .min = 0.0, .max = 1e6,    \
        .fallback = "6"                                                                                                \
    }

/* `sinew run`'s model options and --out, for the end of an options table. */
#define MOTION_ANALYSIS_MODEL_OPTIONS                                                                                  \
    {.name = "variant",                                                                                                \
     .id = MOTION_OPT_VARIANT,                                                                                         \
     .kind = CLI_TEXT,                                                                                                 \
     .value_name = "NAME|N",                                                                                           \
     .help = "the variant, by name or index",                                                                          \
     .fallback = "0"},                                                                                                 \
        {.name = "weight",                                                                                             \
         .id = MOTION_OPT_WEIGHT,                                                                                      \
         .kind = CLI_NUMBER,                                                                                           \
         .value_name = "KG",                                                                                           \
         .help = "the weight choice of that mass",                                                                     \
         .min = 0.0,                                                                                                   \
         .max = 1e9,                                                                                                   \
         .fallback = "the first"},                                                                                     \
        {.name = "weight-index",                                                                                       \
         .id = MOTION_OPT_WEIGHT_INDEX,                                                                                \
         .kind = CLI_INT,                                                                                              \
         .value_name = "N",                                                                                            \
         .help = "the weight choice by index",                                                                         \
         .min = 0,                                                                                                     \
         .max = MU_MODEL_MAX_OBJECTS - 1},                                                                             \
        {.name = "level",                                                                                              \
         .id = MOTION_OPT_LEVEL,                                                                                       \
         .kind = CLI_INT,                                                                                              \
         .value_name = "N",                                                                                            \
         .help = "2 joints, 3 + muscles, 4 + weight",                                                                  \
         .min = 0,                                                                                                     \
         .max = 4,                                                                                                     \
         .fallback = "4"},                                                                                             \
    {                                                                                                                  \
        .name = "out", .id = MOTION_OPT_OUT, .kind = CLI_PATH, .value_name = "DIR", .help = "output directory",        \
        .fallback = "."                                                                                                \
    }

typedef struct motion_analysis_options {
    const char *model;
    const char *motion;
    double cutoff; /* Hz; 0: no filter */
    const char *variant;
    double weight_kg;
    bool has_weight_kg;
    int weight_index; /* -1: not given */
    int level;
    const char *out_dir;
} motion_analysis_options;

/* The defaults: the 6 Hz filter, level 4, the current folder. */
motion_analysis_options motion_analysis_default_options(void);

/* What motion_analysis_parse returns for --help (the caller prints it). */
enum { MOTION_ANALYSIS_HELP = 100 };

/* Takes one of the command's own options; false when `id` is not one. */
typedef bool (*motion_analysis_take_option)(int id, const cli_value *value, void *own);

/* Parses the command line into `opts` and, through `take`, the command's
 * own options; returns 0, MOTION_ANALYSIS_HELP, or the usage status after
 * one line on stderr (no model, no --motion, --weight with
 * --weight-index). */
int motion_analysis_parse(const cli_command *command, int argc, char **argv, motion_analysis_options *opts,
                          motion_analysis_take_option take, void *own);

/* Builds the model of `desc` with the options' variant, weight and level
 * into *model (options filled in as built); returns 0, or an exit status
 * after a message (a variant or weight that does not exist, a model that
 * cannot be built, or one without a hinge at that level). */
int motion_analysis_build_model(const motion_analysis_options *opts, const mu_model_desc *desc,
                                mu_model_options *options, mu_model **model);

/* Reads the motion of the model's hinges and checks the cut-off against
 * its sampling; returns 0, or an exit status after a message. */
int motion_analysis_read(const motion_analysis_options *opts, const mu_model *model, motion *m);

/* A motion smoothed and differentiated: per hinge of the model
 * [hinge * frames + frame], the angle (deg), its rate (deg/s) and
 * acceleration (deg/s²); zeros for a hinge that is not built. */
typedef struct motion_kinematics {
    long frames;
    double *angles, *rates, *accelerations;
} motion_kinematics;

/* Low-passes each hinge's angle at `cutoff` Hz (none at 0) and
 * differentiates it (motion_filter.h); false when memory runs out. */
bool motion_kinematics_compute(const motion *m, double cutoff, motion_kinematics *k);

void motion_kinematics_free(motion_kinematics *k);

/* DIR/STEMSUFFIX.EXTENSION, STEM the model's (model_source_stem); returns
 * 0 or an exit status after a message. */
int motion_analysis_output_path(const motion_analysis_options *opts, const char *suffix, const char *extension,
                                char *path, size_t path_size);

/* The provenance of an analysis: the model's settings, the motion, its
 * sample rate and the filter; NULL when memory runs out. */
json_t *motion_analysis_settings(mu_model *model, const mu_model_options *options, const motion_analysis_options *opts,
                                 double step);

/* Writes a table of `columns` columns of `frames` values each
 * (values[column][frame]) to the CSV `path` with the provenance sidecar,
 * whose `settings` it takes; false after a message. */
bool motion_analysis_write_csv(const char *path, int columns, const char *const *names, const double *const *values,
                               long frames, json_t *settings);

/* The summary's first lines: the motion, its frames and rate, the filter. */
void motion_analysis_print_header(const motion_analysis_options *opts, long frames, double step);

#endif
