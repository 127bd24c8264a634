/* SPDX-License-Identifier: MIT */
/* Fuzz target: a sweep file's bytes (`sinew sweep FILE`), read, checked
 * and expanded as sweep_plan_load does before any run. Whatever the input:
 * no crash, no leak; a refusal is a message naming the file; an accepted
 * sweep has 1 to SWEEP_RUN_LIMIT runs with distinct names of file-name
 * characters, each run's arguments ending in --name NAME --summary
 * NAME.summary.json. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "memory_file.h"
#include "sweep_plan.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check(bool condition, const char *what)
{
    if (!condition) {
        fprintf(stderr, "fuzz_sweep_plan: %s\n", what);
        abort();
    }
}

static void check_run(const sweep_run *run)
{
    size_t length = strlen(run->name);
    check(length > 0 && length <= SWEEP_NAME_MAX, "a run name's length");
    check(strspn(run->name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._+-=") == length,
          "a run name holds a character a file name should not");
    int n = run->argument_count;
    check(n >= 5, "a run has too few arguments");
    check(strcmp(run->arguments[n - 4], "--name") == 0 && strcmp(run->arguments[n - 3], run->name) == 0,
          "a run's --name is not its name");
    char summary[SWEEP_NAME_MAX + 32];
    snprintf(summary, sizeof summary, "%s.summary.json", run->name);
    check(strcmp(run->arguments[n - 2], "--summary") == 0 && strcmp(run->arguments[n - 1], summary) == 0,
          "a run's --summary is not NAME.summary.json");
}

static int compare_names(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    memory_file file;
    memory_file_open(&file, data, size);
    sweep_plan plan;
    char error[SWEEP_ERROR_SIZE];
    bool ok = sweep_plan_load(file.path, "/nonexistent/out", false, &plan, error, sizeof error);
    if (!ok) {
        check(strncmp(error, file.path, strlen(file.path)) == 0, "a refusal does not name the file");
    } else {
        check(plan.run_count >= 1 && plan.run_count <= SWEEP_RUN_LIMIT, "the count of runs");
        char **names = malloc((size_t)plan.run_count * sizeof *names);
        check(names != NULL, "out of memory");
        for (int k = 0; k < plan.run_count; ++k) {
            check_run(&plan.runs[k]);
            names[k] = plan.runs[k].name;
        }
        qsort(names, (size_t)plan.run_count, sizeof *names, compare_names);
        for (int k = 1; k < plan.run_count; ++k) {
            check(strcmp(names[k - 1], names[k]) != 0, "two runs of one name");
        }
        free(names);
        sweep_plan_free(&plan);
    }
    memory_file_close(&file);
    return 0;
}
