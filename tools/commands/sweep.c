/* SPDX-License-Identifier: MIT */
#define _DEFAULT_SOURCE /* realpath, readlink, PATH_MAX */
/* `sinew sweep SWEEP_FILE [options]`: a parameter sweep. The sweep file
 * (sweep_plan.h) names a model and the parameters to vary; the sweep
 * expands it into `sinew run`s, runs those not yet complete on a pool of
 * worker processes (sweep_pool.h) or writes them out for GNU parallel or
 * Slurm (sweep_jobs.h), and gathers what they wrote into one table and a
 * figure (sweep_gather.h). docs/sweeps.md describes it all.
 */
#include <errno.h>
#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/options.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "sweep_gather.h"
#include "sweep_jobs.h"
#include "sweep_plan.h"
#include "sweep_pool.h"

enum { OPT_OUT, OPT_JOBS, OPT_YES, OPT_EMIT, OPT_CHUNK, OPT_GATHER };

static const cli_option options_table[] = {
    {.name = "out",
     .id = OPT_OUT,
     .kind = CLI_PATH,
     .value_name = "DIR",
     .help = "the output folder, made when missing",
     .fallback = "the file's \"out\", else its stem"},
    {.name = "jobs",
     .id = OPT_JOBS,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "runs at a time on this machine",
     .min = 1,
     .max = 1024,
     .fallback = "the cores"},
    {.name = "yes", .id = OPT_YES, .kind = CLI_FLAG, .help = "allow more than 1000 runs (up to 1000000)"},
    {.name = "emit",
     .id = OPT_EMIT,
     .kind = CLI_TEXT,
     .value_name = "WHAT",
     .help = "run nothing; write the runs for another engine: parallel (OUT/jobs.txt,\n"
             "the runs not complete), slurm (also OUT/sweep.sbatch) or list (every run\n"
             "and whether it is complete, as JSON on stdout)"},
    {.name = "chunk",
     .id = OPT_CHUNK,
     .kind = CLI_INT,
     .value_name = "K",
     .help = "runs per Slurm array task (with --emit slurm)",
     .min = 1,
     .max = SWEEP_RUN_LIMIT,
     .fallback = "1"},
    {.name = "gather",
     .id = OPT_GATHER,
     .kind = CLI_FLAG,
     .help = "run nothing; build OUT/summary.csv (and the figure) from what the runs wrote"},
};

static const cli_command command = {
    .name = "sinew sweep",
    .operands = "SWEEP_FILE [options]",
    .max_operands = 1,
    .operand = "sweep file",
    .about = "Runs a model over a grid of parameters: one `sinew run` per combination, each writing\n"
             "OUT/NAME.csv and OUT/NAME.summary.json (NAME made of its parameters), then one table\n"
             "OUT/summary.csv, a row per run, and a figure OUT/summary.png when the file asks for one.\n"
             "Runs already complete are skipped; a run that fails is recorded as failed.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes =
        "The sweep file (JSON; docs/sweeps.md):\n"
        "  {\"model\": \"arm\", \"set\": {\"duration\": 0.5},\n"
        "   \"grid\": {\"weight\": [0, 1, 5], \"activation.Biceps Long\": {\"start\": 0, \"stop\": 1, \"count\": 4}},\n"
        "   \"figure\": {\"y\": \"Biceps Long.peak_force_N\", \"x\": \"weight\", \"group\": \"activation.Biceps "
        "Long\"}}\n"
        "Parameters: variant, weight, weight_index, level, duration, substeps, solver,\n"
        "velocity_iterations, position_iterations, control, activation.NAME, tension.NAME,\n"
        "recruit.NAME, muscle.NAME.PARAMETER; \"zip\" varies lists side by side.\n"
        "GNU parallel: sinew sweep FILE --emit parallel; parallel -a OUT/jobs.txt; sinew sweep FILE --gather\n"
        "Slurm:        sinew sweep FILE --emit slurm; sbatch OUT/sweep.sbatch; (when done) --gather\n"
        "Exit status 1 when a run failed (the table is written all the same).\n",
};

typedef enum emit_kind { EMIT_NONE, EMIT_LIST, EMIT_PARALLEL, EMIT_SLURM } emit_kind;

typedef struct sweep_options {
    const char *file;
    const char *out;
    int jobs;
    bool yes;
    emit_kind emit;
    int chunk; /* 0: not given */
    bool gather;
} sweep_options;

static int parse_arguments(int argc, char **argv, sweep_options *opts)
{
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_OUT:
            opts->out = value.text;
            break;
        case OPT_JOBS:
            opts->jobs = (int)value.integer;
            break;
        case OPT_YES:
            opts->yes = true;
            break;
        case OPT_EMIT:
            opts->emit = strcmp(value.text, "list") == 0       ? EMIT_LIST
                         : strcmp(value.text, "parallel") == 0 ? EMIT_PARALLEL
                         : strcmp(value.text, "slurm") == 0    ? EMIT_SLURM
                                                               : EMIT_NONE;
            if (opts->emit == EMIT_NONE) {
                cli_parser_finish(&parser);
                return cli_usage_error(&command, "--emit \"%s\": expected parallel, slurm or list", value.text);
            }
            break;
        case OPT_CHUNK:
            opts->chunk = (int)value.integer;
            break;
        case OPT_GATHER:
            opts->gather = true;
            break;
        default:
            break;
        }
    }
    if (id == CLI_END && parser.operand_count == 1) {
        opts->file = parser.operands[0];
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? CLI_HELP : EXIT_USAGE;
    }
    if (opts->file == NULL) {
        return cli_usage_error(&command, "missing the sweep file");
    }
    if (opts->gather && opts->emit != EMIT_NONE) {
        return cli_usage_error(&command, "give --emit or --gather, not both");
    }
    if (opts->chunk > 0 && opts->emit != EMIT_SLURM) {
        return cli_usage_error(&command, "--chunk is for --emit slurm");
    }
    return 0;
}

/* Makes the output folder when missing (not its parents), checks that a
 * file can be written in it, and gives its absolute path; returns 0 or an
 * exit status after one line on stderr. */
static int prepare_out(const sweep_plan *plan, bool create, char *absolute)
{
    const char *out = plan->out_dir;
    const char *named = strcmp(plan->out_source, "$.out") == 0 ? "$.out" : plan->out_source;
    if (create && mkdir(out, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "sinew: %s: %s: the output folder %s cannot be made: %s\n", plan->file, named, out,
                strerror(errno));
        return EXIT_FAILURE;
    }
    struct stat info;
    if (stat(out, &info) != 0 || !S_ISDIR(info.st_mode)) {
        fprintf(stderr, "sinew: %s: %s: the output folder %s %s\n", plan->file, named, out,
                errno == ENOENT || !create ? "does not exist" : "is not a folder");
        return EXIT_FAILURE;
    }
    if (realpath(out, absolute) == NULL) {
        fprintf(stderr, "sinew: %s: %s: %s: %s\n", plan->file, named, out, strerror(errno));
        return EXIT_FAILURE;
    }
    /* A file made and removed, as the runs will make theirs. */
    char probe[ATOMIC_FILE_PATH_MAX];
    char error[ATOMIC_FILE_ERROR_SIZE];
    int written = snprintf(probe, sizeof probe, "%s/summary.csv", absolute);
    atomic_file file = {0};
    if (written < 0 || (size_t)written >= sizeof probe) {
        fprintf(stderr, "sinew: %s: %s: the output folder's path %s is too long\n", plan->file, named, absolute);
        return EXIT_FAILURE;
    }
    if (!atomic_file_open(&file, probe, error, sizeof error)) {
        fprintf(stderr, "sinew: %s: %s: the output folder %s cannot be written: %s\n", plan->file, named, out, error);
        return EXIT_FAILURE;
    }
    atomic_file_abandon(&file);
    return 0;
}

/* The runs not complete, in the plan's order; their count. */
static int runs_to_do(const sweep_plan *plan, const bool *complete, int *todo)
{
    int count = 0;
    for (int r = 0; r < plan->run_count; ++r) {
        if (!complete[r]) {
            todo[count++] = r;
        }
    }
    return count;
}

static int gather(const sweep_plan *plan, const char *out)
{
    int ok_count, failed_count;
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (!sweep_gather(plan, out, &ok_count, &failed_count, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("summary      %s/summary.csv: %d run%s ok, %d failed\n", out, ok_count, ok_count == 1 ? "" : "s",
           failed_count);
    if (plan->figure_y != NULL) {
        printf("figure       %s/summary.png: %s against %s\n", out, plan->figure_y, plan->figure_x);
    }
    return failed_count == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

/* Writes the job list (and the Slurm script) of the runs to do. */
static int emit(const sweep_plan *plan, const sweep_options *opts, const int *todo, int count, const char *program,
                const char *out)
{
    if (count == 0) {
        printf("all %d runs are complete: nothing to emit (gather with `sinew sweep %s --gather`)\n", plan->run_count,
               plan->file);
        return EXIT_SUCCESS;
    }
    char error[ATOMIC_FILE_ERROR_SIZE];
    int chunk = opts->chunk > 0 ? opts->chunk : 1;
    if (!sweep_write_job_list(plan, todo, count, program, out, error, sizeof error) ||
        (opts->emit == EMIT_SLURM && !sweep_write_slurm_script(plan, count, chunk, out, error, sizeof error))) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("jobs         %s/jobs.txt: %d of %d runs (the others are complete)\n", out, count, plan->run_count);
    if (opts->emit == EMIT_PARALLEL) {
        printf("run them     parallel -a %s/jobs.txt   (--sshlogin HOSTS: hosts that share this folder)\n", out);
    } else {
        int tasks = (count + chunk - 1) / chunk;
        printf("slurm        %s/sweep.sbatch: %d array task%s of %d run%s\n", out, tasks, tasks == 1 ? "" : "s", chunk,
               chunk == 1 ? "" : "s");
        printf("run them     sbatch %s/sweep.sbatch\n", out);
        if (tasks > 1000) {
            printf("note         Slurm's default MaxArraySize allows 1001 tasks: give --chunk %d or more\n",
                   (count + 999) / 1000);
        }
    }
    printf("then         sinew sweep %s --out %s --gather\n", plan->file, out);
    return EXIT_SUCCESS;
}

static int sweep(const sweep_plan *plan, const sweep_options *opts)
{
    char out[PATH_MAX];
    int code = prepare_out(plan, !opts->gather, out);
    if (code != 0) {
        return code;
    }
    if (opts->gather) {
        return gather(plan, out);
    }
    char program[PATH_MAX];
    ssize_t length = readlink("/proc/self/exe", program, sizeof program - 1);
    if (length < 0) {
        fprintf(stderr, "sinew: cannot find this program (/proc/self/exe): %s\n", strerror(errno));
        return EXIT_FAILURE;
    }
    program[length] = '\0';
    bool *complete = calloc((size_t)plan->run_count, sizeof *complete);
    int *todo = calloc((size_t)plan->run_count, sizeof *todo);
    if (complete == NULL || todo == NULL) {
        fputs("sinew: out of memory\n", stderr);
        code = EXIT_FAILURE;
    }
    for (int r = 0; code == 0 && r < plan->run_count; ++r) {
        complete[r] = sweep_run_complete(out, &plan->runs[r]);
    }
    int count = code == 0 ? runs_to_do(plan, complete, todo) : 0;
    if (code == 0 && opts->emit == EMIT_LIST) {
        code = sweep_print_list(plan, complete, program, out, stdout) ? EXIT_SUCCESS : EXIT_FAILURE;
    } else if (code == 0 && opts->emit != EMIT_NONE) {
        code = emit(plan, opts, todo, count, program, out);
    } else if (code == 0) {
        int jobs = opts->jobs > 0 ? opts->jobs : (int)sysconf(_SC_NPROCESSORS_ONLN);
        jobs = jobs < 1 ? 1 : jobs;
        printf("sweep        %d runs: %d complete already, %d to run, %d at a time\n", plan->run_count,
               plan->run_count - count, count, jobs);
        fflush(stdout);
        char error[ATOMIC_FILE_ERROR_SIZE];
        if (!sweep_pool_run(plan, todo, count, program, out, jobs, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            code = EXIT_FAILURE;
        } else {
            code = gather(plan, out);
        }
    }
    free(complete);
    free(todo);
    return code;
}

int cmd_sweep(int argc, char **argv)
{
    sweep_options opts = {0};
    int code = parse_arguments(argc, argv, &opts);
    if (code == CLI_HELP) {
        cli_print_help(&command, stdout);
        return EXIT_SUCCESS;
    }
    if (code != 0) {
        return code;
    }
    sweep_plan plan;
    char error[SWEEP_ERROR_SIZE];
    if (!sweep_plan_load(opts.file, opts.out, opts.yes, &plan, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    code = sweep(&plan, &opts);
    sweep_plan_free(&plan);
    return code;
}
