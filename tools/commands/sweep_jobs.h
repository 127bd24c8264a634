/* SPDX-License-Identifier: MIT */
/* A sweep's runs handed to the engines HPC users already have, as files
 * in the output folder (docs/sweeps.md):
 *
 *   OUT/jobs.txt      the job list: one shell command line per run,
 *                     `cd OUT && SINEW run ARGS... >/dev/null 2>NAME.log`,
 *                     every word quoted as a POSIX shell reads it back; GNU
 *                     parallel runs it (`parallel -a OUT/jobs.txt`, with
 *                     `--sshlogin` on several hosts that share the folder);
 *   OUT/sweep.sbatch  a Slurm array job over that list: task T runs lines
 *                     T·K + 1 .. T·K + K (K runs a task, --chunk), so
 *                     `sbatch OUT/sweep.sbatch` runs the sweep on a cluster.
 *
 * Each run works in the output folder and names its files relatively, so
 * every engine writes the same bytes there (the CSV's sidecar records the
 * run's command line, which is the same whoever started it).
 */
#ifndef SINEW_SWEEP_JOBS_H
#define SINEW_SWEEP_JOBS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "sweep_plan.h"

/* Writes `text` as one word of a POSIX shell: as it is when it holds only
 * letters, digits and _ . , + - = / : @ %, else in single quotes, each
 * quote inside written '\''. */
void sweep_shell_word(FILE *stream, const char *text);

/* Writes OUT/jobs.txt with the runs `todo[0 .. count - 1]` of the plan,
 * run by `program` in `out_dir` (both absolute). */
bool sweep_write_job_list(const sweep_plan *plan, const int *todo, int count, const char *program, const char *out_dir,
                          char *error, size_t error_size);

/* Writes OUT/sweep.sbatch: an array of ceil(count / chunk) tasks over the
 * job list of `count` runs. */
bool sweep_write_slurm_script(const sweep_plan *plan, int count, int chunk, const char *out_dir, char *error,
                              size_t error_size);

/* Prints the plan as JSON on `stream`, for programs that run the runs
 * themselves (python/sinew/sweep.py): {"program", "out", "runs": [{"name",
 * "arguments", "complete"}]}, the arguments those after `sinew run`. */
bool sweep_print_list(const sweep_plan *plan, const bool *complete, const char *program, const char *out_dir,
                      FILE *stream);

#endif
