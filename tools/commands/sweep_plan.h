/* SPDX-License-Identifier: MIT */
/* A sweep file read, checked and expanded into its runs (`sinew sweep`;
 * the format is in docs/sweeps.md):
 *
 *   {
 *     "model": "arm",
 *     "out": "arm_sweep",                          optional, beside the sweep file
 *     "set":  {"duration": 0.5},                   the same in every run
 *     "grid": {"weight": [0, 1, 5],                every combination of these
 *              "activation.Biceps Long": {"start": 0, "stop": 1, "count": 4}},
 *     "zip":  {"solver": ["ngs", "soft_step"],     these side by side, as one more
 *              "velocity_iterations": [4, 8]},     axis of the grid
 *     "figure": {"y": "Biceps Long.peak_force_N", "x": "weight",
 *                "group": "activation.Biceps Long"}
 *   }
 *
 * Everything is checked before any run is started: each key, each
 * parameter's name against the model (its muscles, groups, torque muscles,
 * variants and weights), each value's type and range, the size of the
 * grid. Every error names the sweep file and the JSON path of the value.
 *
 * A run is `sinew run` with the arguments the plan gives it, in the output
 * folder: MODEL, one option per parameter (the set's, the grid's, the
 * zip's, in the file's order), then --name NAME --summary NAME.summary.json.
 * NAME is the model's stem followed by _PARAMETER=VALUE for each parameter
 * that varies, with every character other than letters, digits and . + -
 * = made '_': deterministic, one file name, no quotes needed in a shell.
 * Values are written with the fewest digits that read back as the same
 * number (0.1, not 0.10000000000000001).
 */
#ifndef SINEW_SWEEP_PLAN_H
#define SINEW_SWEEP_PLAN_H

#include <stdbool.h>
#include <stddef.h>

/* Runs a sweep may have without --yes: more is most likely a typing
 * mistake in a range (a step of 0.001 for 0.1). */
#define SWEEP_RUN_LIMIT 1000

/* Runs a sweep may have at all (with --yes). */
#define SWEEP_MAX_RUNS 1000000

/* Longest run name: with ".csv-metadata.json" it fits the 255 bytes of a
 * file name. */
#define SWEEP_NAME_MAX 200

/* Bytes of an error message of the plan. */
#define SWEEP_ERROR_SIZE 2048

typedef struct sweep_run {
    char *name; /* the files' stem: NAME.csv, NAME.summary.json, NAME.log */
    /* Each varied parameter's value, by plan index, as the file gives it
     * (a control file's absolute path). */
    char **values;
    int argument_count; /* after `sinew run` */
    char **arguments;
} sweep_run;

typedef struct sweep_plan {
    char *file;             /* the sweep file, as given */
    char *out_dir;          /* the output folder: --out, the file's "out" or the file's stem */
    const char *out_source; /* what named it, for messages: "--out", "$.out" or "the default" */
    int varied_count;
    char **varied;        /* the parameters that vary, in the file's order */
    bool *varied_numeric; /* whether each one's values are numbers */
    int run_count;
    sweep_run *runs;
    char *figure_y, *figure_x, *figure_group; /* NULL when not given */
} sweep_plan;

/* Reads, checks and expands the sweep file `path`. `out_dir` (NULL: none)
 * overrides the file's "out". Runs beyond SWEEP_RUN_LIMIT are refused
 * unless `allow_many`. On failure the plan is empty and `error` says what
 * is wrong and where. */
bool sweep_plan_load(const char *path, const char *out_dir, bool allow_many, sweep_plan *plan, char *error,
                     size_t error_size);

/* Frees what the plan holds; a zero plan or a failed load may be freed. */
void sweep_plan_free(sweep_plan *plan);

#endif
