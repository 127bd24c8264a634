/* SPDX-License-Identifier: MIT */
/* The job list, the Slurm script and the JSON list of a sweep
 * (sweep_jobs.h). */
#include <jansson.h>
#include <string.h>

#include "io/atomic_file.h"
#include "sweep_jobs.h"

void sweep_shell_word(FILE *stream, const char *text)
{
    static const char plain[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.,+-=/:@%";
    if (text[0] != '\0' && strspn(text, plain) == strlen(text)) {
        fputs(text, stream);
        return;
    }
    fputc('\'', stream);
    for (const char *c = text; *c != '\0'; ++c) {
        fputs(*c == '\'' ? "'\\''" : (char[]){*c, '\0'}, stream);
    }
    fputc('\'', stream);
}

/* An #SBATCH option's value: sbatch reads these lines itself, not the
 * shell, and takes a value in double quotes whole, spaces and all, with
 * '\\' and '"' escaped by a backslash. */
static void sbatch_value(FILE *stream, const char *text, const char *suffix)
{
    fputc('"', stream);
    for (const char *c = text; *c != '\0'; ++c) {
        if (*c == '"' || *c == '\\') {
            fputc('\\', stream);
        }
        fputc(*c, stream);
    }
    fprintf(stream, "%s\"\n", suffix);
}

/* OUT/NAME, in `path`; false when it does not fit. */
static bool out_path(const char *out_dir, const char *name, char *path, size_t size, char *error, size_t error_size)
{
    int written = snprintf(path, size, "%s/%s", out_dir, name);
    if (written < 0 || (size_t)written >= size) {
        snprintf(error, error_size, "%s: the output folder's path is too long", out_dir);
        return false;
    }
    return true;
}

bool sweep_write_job_list(const sweep_plan *plan, const int *todo, int count, const char *program, const char *out_dir,
                          char *error, size_t error_size)
{
    char path[ATOMIC_FILE_PATH_MAX];
    atomic_file file = {0};
    if (!out_path(out_dir, "jobs.txt", path, sizeof path, error, error_size) ||
        !atomic_file_open(&file, path, error, error_size)) {
        return false;
    }
    for (int k = 0; k < count; ++k) {
        const sweep_run *run = &plan->runs[todo[k]];
        fputs("cd ", file.stream);
        sweep_shell_word(file.stream, out_dir);
        fputs(" && ", file.stream);
        sweep_shell_word(file.stream, program);
        fputs(" run", file.stream);
        for (int a = 0; a < run->argument_count; ++a) {
            fputc(' ', file.stream);
            sweep_shell_word(file.stream, run->arguments[a]);
        }
        fprintf(file.stream, " >/dev/null 2>%s.log\n", run->name);
    }
    return atomic_file_commit(&file, error, error_size);
}

bool sweep_write_slurm_script(const sweep_plan *plan, int count, int chunk, const char *out_dir, char *error,
                              size_t error_size)
{
    char path[ATOMIC_FILE_PATH_MAX];
    char jobs[ATOMIC_FILE_PATH_MAX];
    atomic_file file = {0};
    if (!out_path(out_dir, "jobs.txt", jobs, sizeof jobs, error, error_size) ||
        !out_path(out_dir, "sweep.sbatch", path, sizeof path, error, error_size) ||
        !atomic_file_open(&file, path, error, error_size)) {
        return false;
    }
    int tasks = (count + chunk - 1) / chunk;
    FILE *s = file.stream;
    fputs("#!/bin/bash\n", s);
    fprintf(s, "# A Slurm array job written by `sinew sweep --emit slurm` for %s:\n", plan->file);
    fprintf(s, "# %d runs, %d a task. Task T runs lines T*%d+1 .. T*%d+%d of the job list,\n", count, chunk, chunk,
            chunk, chunk);
    fputs("# each a `sinew run` in the output folder. Submit it with `sbatch` (any\n"
          "# #SBATCH option below may be given on its command line instead: a\n"
          "# partition, a time limit), then gather the summary with\n"
          "# `sinew sweep SWEEP_FILE --out OUT --gather`.\n",
          s);
    fputs("#SBATCH --job-name=sinew-sweep\n", s);
    fprintf(s, "#SBATCH --array=0-%d\n", tasks - 1);
    fputs("#SBATCH --ntasks=1\n", s);
    fputs("#SBATCH --cpus-per-task=1\n", s);
    fputs("#SBATCH --chdir=", s);
    sbatch_value(s, out_dir, "");
    fputs("#SBATCH --output=", s);
    sbatch_value(s, out_dir, "/slurm-%A_%a.out");
    fputs("set -u\n", s);
    fputs("jobs=", s);
    sweep_shell_word(s, jobs);
    fprintf(s, "\nchunk=%d\nruns=%d\n", chunk, count);
    fputs("first=$((SLURM_ARRAY_TASK_ID * chunk))\n"
          "status=0\n"
          "for ((line = first + 1; line <= first + chunk && line <= runs; ++line)); do\n"
          "    bash -c \"$(sed -n \"${line}p\" \"$jobs\")\" || status=1\n"
          "done\n"
          "exit \"$status\"\n",
          s);
    return atomic_file_commit(&file, error, error_size);
}

bool sweep_print_list(const sweep_plan *plan, const bool *complete, const char *program, const char *out_dir,
                      FILE *stream)
{
    json_t *runs = json_array();
    for (int r = 0; runs != NULL && r < plan->run_count; ++r) {
        const sweep_run *run = &plan->runs[r];
        json_t *arguments = json_array();
        for (int a = 0; arguments != NULL && a < run->argument_count; ++a) {
            json_array_append_new(arguments, json_string(run->arguments[a]));
        }
        json_array_append_new(
            runs, json_pack("{s:s, s:o, s:b}", "name", run->name, "arguments", arguments, "complete", complete[r]));
    }
    json_t *root = json_pack("{s:s, s:s, s:o}", "program", program, "out", out_dir, "runs", runs);
    bool ok = root != NULL && json_dumpf(root, stream, JSON_INDENT(1)) == 0 && fputc('\n', stream) != EOF;
    json_decref(root);
    return ok;
}
