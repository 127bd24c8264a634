/* SPDX-License-Identifier: MIT */
/* A sweep's runs on this machine: at most `jobs` `sinew run` processes at
 * a time, each started with posix_spawn as soon as one ends (a plain
 * pool; the order of the runs is the plan's). Each runs in the output
 * folder, its stdout (the printed summary) dropped and its stderr in
 * NAME.log, exactly as a line of the job list (sweep_jobs.h) runs it, so
 * that its files are the same as under GNU parallel or Slurm.
 */
#ifndef SINEW_SWEEP_POOL_H
#define SINEW_SWEEP_POOL_H

#include <stdbool.h>
#include <stddef.h>

#include "sweep_plan.h"

/* Runs `plan->runs[todo[k]]` for k in 0 .. count - 1 with `program` (the
 * sinew program) in `out_dir`, `jobs` (>= 1) at a time. Prints a line on
 * stderr for each run that fails (the table records it: sweep_gather.h).
 * Returns false, `error` saying why, only when the pool itself fails
 * (waiting for a child). */
bool sweep_pool_run(const sweep_plan *plan, const int *todo, int count, const char *program, const char *out_dir,
                    int jobs, char *error, size_t error_size);

#endif
