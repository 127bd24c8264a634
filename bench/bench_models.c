/* SPDX-License-Identifier: MIT */
/* bench_models: how much faster than real time the muscle models run.
 *
 * Each built-in model runs headless (no CSV, no drawing) with every muscle
 * of its variant at activation 1 from the start, at its own frame rate and
 * substeps (60 Hz, 10 substeps for all three): the arm in its variant
 * "All Muscles", the leg in "All Muscles", the sample in "Default", each
 * at its first weight choice. A run builds the model (not timed), then
 * steps `seconds` of simulated time, timed as a whole with
 * clock_gettime(CLOCK_MONOTONIC). Over `runs` runs, each on a freshly built
 * model, the report gives the median wall time, the real-time factor
 * (simulated seconds / median wall seconds) and µs per substep. The target
 * is 2000× real time, 0.83 µs per substep at 600 substeps per second.
 *
 * Prints one `model=... realtime_factor=... us_per_substep=...` line per
 * model and writes a CSV (header row; written to a temporary name and
 * renamed). Exit status: 0 success, 1 failure, 2 bad command line.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/options.h"
#include "io/atomic_file.h"
#include "mu/model.h"

enum { OPT_MODEL, OPT_RUNS, OPT_SECONDS, OPT_CSV, OPT_QUICK };

static const cli_option options_table[] = {
    {.name = "model",
     .id = OPT_MODEL,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "sample, arm, leg or all",
     .fallback = "all"},
    {.name = "runs",
     .id = OPT_RUNS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "repetitions, each on a fresh model",
     .min = 1,
     .max = 1000,
     .fallback = "5"},
    {.name = "seconds",
     .id = OPT_SECONDS,
     .kind = CLI_NUMBER,
     .value_name = "S",
     .help = "simulated time per run",
     .min = 0.0,
     .min_open = true,
     .max = 1e5,
     .fallback = "20"},
    {.name = "csv",
     .id = OPT_CSV,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "results",
     .fallback = "bench_models.csv"},
    {.name = "quick",
     .id = OPT_QUICK,
     .kind = CLI_FLAG,
     .help = "smoke test: 1 run of 1 s (explicit --runs, --seconds win)"},
};

static const cli_command command = {
    .name = "bench_models",
    .operands = "[options]",
    .about = "Real-time factor of the built-in muscle models, every muscle active.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
};

#define TARGET_FACTOR 2000.0 /* the real-time factor asked for */

typedef struct bench_model {
    const char *name;    /* built-in model */
    const char *variant; /* variant name */
} bench_model;

static const bench_model bench_models[] = {{"arm", "All Muscles"}, {"leg", "All Muscles"}, {"sample", "Default"}};
enum { BENCH_MODEL_COUNT = sizeof bench_models / sizeof bench_models[0] };

/* ------------------------------------------------------------- options */

typedef struct bench_options {
    bool models[BENCH_MODEL_COUNT];
    int runs;
    double seconds;
    const char *csv_path;
} bench_options;

typedef enum parse_result { PARSE_OK, PARSE_HELP, PARSE_ERROR } parse_result;

static parse_result parse_options(int argc, char **argv, bench_options *opts)
{
    *opts = (bench_options){.runs = -1, .seconds = -1.0, .csv_path = "bench_models.csv"};
    bool quick = false;
    const char *model = "all";
    cli_parser parser;
    cli_parser_start(&parser, &command, argc - 1, argv + 1);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_MODEL:
            model = value.text;
            break;
        case OPT_RUNS:
            opts->runs = (int)value.integer;
            break;
        case OPT_SECONDS:
            opts->seconds = value.number;
            break;
        case OPT_CSV:
            opts->csv_path = value.text;
            break;
        default:
            quick = true;
            break;
        }
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? PARSE_HELP : PARSE_ERROR;
    }
    bool all = strcmp(model, "all") == 0;
    bool any = all;
    for (int k = 0; k < BENCH_MODEL_COUNT; ++k) {
        opts->models[k] = all || strcmp(model, bench_models[k].name) == 0;
        any = any || opts->models[k];
    }
    if (!any) {
        fprintf(stderr, "bench_models: --model expects sample, arm, leg or all, got \"%s\"\n", model);
        return PARSE_ERROR;
    }
    if (opts->runs < 0) {
        opts->runs = quick ? 1 : 5;
    }
    if (opts->seconds < 0.0) {
        opts->seconds = quick ? 1.0 : 20.0;
    }
    return PARSE_OK;
}

/* ---------------------------------------------------------------- runs */

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a;
    double y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n values (sorted in place), averaging the middle two
 * when n is even. */
static double median(double *values, int n)
{
    qsort(values, (size_t)n, sizeof *values, compare_doubles);
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/* Figures of one model over all its runs. */
typedef struct bench_result {
    const bench_model *model;
    double weight_kg;
    int muscles, bodies, joints;            /* as built: muscles, engine bodies and joints */
    double frame_rate;                      /* Hz */
    int substeps;                           /* per frame */
    long frames;                            /* per run */
    double median_wall, min_wall, max_wall; /* s */
    double realtime_factor;                 /* simulated s / median wall s */
    double us_per_substep;                  /* µs, at the median */
    bool deterministic;                     /* every run ended in the same state */
} bench_result;

static bool report_failure(const char *what, const char *model)
{
    fprintf(stderr, "bench_models: %s: %s failed: %s\n", model, what, rb_last_error());
    return false;
}

/* One run: builds the model, activates every muscle, steps `frames`
 * frames; *wall is the stepping time alone. */
static bool run_once(const mu_model_desc *desc, const mu_model_options *options, long frames, bench_result *result,
                     double *wall, uint64_t *hash)
{
    const char *name = result->model->name;
    mu_model *model;
    if (mu_model_create(desc, options, &model) != RB_OK) {
        return report_failure("building the model", name);
    }
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        if (mu_model_set_activation(model, mu_model_muscle_name(model, m), 1.0) != RB_OK) {
            mu_model_destroy(model);
            return report_failure("mu_model_set_activation", name);
        }
    }
    double start = now_seconds();
    for (long frame = 0; frame < frames; ++frame) {
        if (mu_model_step(model) != RB_OK) {
            mu_model_destroy(model);
            return report_failure("mu_model_step", name);
        }
    }
    *wall = now_seconds() - start;
    *hash = rb_world_state_hash(mu_model_world(model));
    result->muscles = mu_model_muscle_count(model);
    result->bodies = mu_model_body_count(model);
    result->joints = mu_model_joint_count(model);
    mu_model_destroy(model);
    return true;
}

static bool bench_model_run(const bench_model *which, const bench_options *opts, double *walls, bench_result *result)
{
    *result = (bench_result){.model = which, .deterministic = true};
    mu_model_desc *desc;
    if (mu_model_desc_load_builtin(which->name, &desc) != RB_OK) {
        fprintf(stderr, "bench_models: %s\n", rb_last_error());
        return false;
    }
    mu_model_options options = mu_default_model_options();
    options.variant = mu_model_desc_find_variant(desc, which->variant);
    if (options.variant < 0) {
        fprintf(stderr, "bench_models: %s has no variant \"%s\"\n", which->name, which->variant);
        mu_model_desc_destroy(desc);
        return false;
    }
    result->weight_kg = desc->has_weight ? desc->weight.masses[0] : 0.0;
    result->frame_rate = desc->frame_rate;
    result->substeps = desc->substeps;
    result->frames = (long)(opts->seconds * desc->frame_rate + 0.5);
    if (result->frames < 1) {
        result->frames = 1;
    }
    uint64_t first_hash = 0;
    bool ok = true;
    for (int run = 0; ok && run < opts->runs; ++run) {
        uint64_t hash = 0;
        ok = run_once(desc, &options, result->frames, result, &walls[run], &hash);
        result->deterministic = result->deterministic && (run == 0 || hash == first_hash);
        first_hash = run == 0 ? hash : first_hash;
    }
    mu_model_desc_destroy(desc);
    if (!ok) {
        return false;
    }
    result->median_wall = median(walls, opts->runs); /* sorts walls */
    result->min_wall = walls[0];
    result->max_wall = walls[opts->runs - 1];
    double simulated = (double)result->frames / result->frame_rate;
    result->realtime_factor = simulated / result->median_wall;
    result->us_per_substep = 1e6 * result->median_wall / ((double)result->frames * result->substeps);
    return true;
}

/* -------------------------------------------------------------- output */

static void print_result(const bench_options *opts, const bench_result *r)
{
    printf("model=%s variant=\"%s\" weight_kg=%g muscles=%d bodies=%d joints=%d frame_rate_hz=%g substeps=%d "
           "simulated_s=%g runs=%d median_wall_s=%.4f min_wall_s=%.4f max_wall_s=%.4f realtime_factor=%.1f "
           "us_per_substep=%.3f target=%s deterministic=%s\n",
           r->model->name, r->model->variant, r->weight_kg, r->muscles, r->bodies, r->joints, r->frame_rate,
           r->substeps, (double)r->frames / r->frame_rate, opts->runs, r->median_wall, r->min_wall, r->max_wall,
           r->realtime_factor, r->us_per_substep, r->realtime_factor >= TARGET_FACTOR ? "met" : "missed",
           r->deterministic ? "yes" : "no");
}

/* A failed write shows in the stream's error flag, which
 * atomic_file_commit checks. */
static void write_csv(FILE *file, const bench_options *opts, const bench_result *results, int count)
{
    fputs("model,variant,weight_kg,muscles,bodies,joints,frame_rate_hz,substeps,simulated_s,runs,median_wall_s,"
          "min_wall_s,max_wall_s,realtime_factor,us_per_substep\n",
          file);
    for (int k = 0; k < count; ++k) {
        const bench_result *r = &results[k];
        fprintf(file, "%s,%s,%g,%d,%d,%d,%g,%d,%g,%d,%.6g,%.6g,%.6g,%.6g,%.6g\n", r->model->name, r->model->variant,
                r->weight_kg, r->muscles, r->bodies, r->joints, r->frame_rate, r->substeps,
                (double)r->frames / r->frame_rate, opts->runs, r->median_wall, r->min_wall, r->max_wall,
                r->realtime_factor, r->us_per_substep);
    }
}

int main(int argc, char **argv)
{
    bench_options opts;
    switch (parse_options(argc, argv, &opts)) {
    case PARSE_HELP:
        cli_print_help(&command, stdout);
        return EXIT_SUCCESS;
    case PARSE_ERROR:
        return CLI_EXIT_USAGE;
    case PARSE_OK:
        break;
    }
    /* Opened before the runs, so that a bad path fails at once. */
    atomic_file csv;
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_open(&csv, opts.csv_path, error, sizeof error)) {
        fprintf(stderr, "bench_models: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    double *walls = malloc((size_t)opts.runs * sizeof *walls);
    if (walls == NULL) {
        fputs("bench_models: out of memory\n", stderr);
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    bench_result results[BENCH_MODEL_COUNT];
    int count = 0;
    bool ok = true;
    for (int k = 0; ok && k < BENCH_MODEL_COUNT; ++k) {
        if (!opts.models[k]) {
            continue;
        }
        ok = bench_model_run(&bench_models[k], &opts, walls, &results[count]);
        if (ok) {
            print_result(&opts, &results[count]);
            fflush(stdout);
            if (!results[count].deterministic) {
                fprintf(stderr, "bench_models: warning: %s ended in different states across runs\n",
                        bench_models[k].name);
            }
            count += 1;
        }
    }
    free(walls);
    if (!ok) {
        atomic_file_abandon(&csv);
        return EXIT_FAILURE;
    }
    write_csv(csv.stream, &opts, results, count);
    if (!atomic_file_commit(&csv, error, sizeof error)) {
        fprintf(stderr, "bench_models: --csv: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("csv=%s\n", opts.csv_path);
    return EXIT_SUCCESS;
}
