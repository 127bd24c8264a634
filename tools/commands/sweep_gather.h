/* SPDX-License-Identifier: MIT */
/* What a sweep's runs wrote, gathered into one table: OUT/summary.csv, one
 * row per run in the plan's order, and the plan's figure, OUT/summary.png.
 * The runs may have been made by `sinew sweep` itself, GNU parallel or
 * Slurm: only their files are read.
 *
 * A run is complete when OUT/NAME.summary.json exists and names the
 * arguments the plan gives the run (run_summary.h): a summary left by a
 * sweep of other settings is not taken for this one's. A run that is not
 * complete is "failed", with the last line of OUT/NAME.log (what the run
 * said on stderr) as its message, or "not run" when there is no log.
 *
 * The columns: run (its name), each parameter that varies, status (ok or
 * failed), message, variant_name, weight_kg, NAME.peak_force_N and
 * NAME.peak_time_s of each muscle, NAME.exertion and NAME.torque_N_m of
 * each torque muscle, NAME.final_angle_deg, NAME.min_angle_deg and
 * NAME.max_angle_deg of each hinge, controls_pending, failure, warnings
 * (the model's warnings, joined by " | "), and last the two columns that
 * depend on the machine: wall_time_s and real_time_factor. Muscles and
 * hinges are those of every run, in the order they first appear; a cell a
 * run has no value for is empty. Numbers are exact (number_text.h).
 */
#ifndef SINEW_SWEEP_GATHER_H
#define SINEW_SWEEP_GATHER_H

#include <stdbool.h>
#include <stddef.h>

#include "sweep_plan.h"

/* The columns that depend on the machine, last in the table. */
#define SWEEP_TIMING_COLUMNS "wall_time_s,real_time_factor"

/* Whether `run`'s summary exists in `out_dir` and was made by its arguments. */
bool sweep_run_complete(const char *out_dir, const sweep_run *run);

/* Writes OUT/summary.csv (and OUT/summary.png when the plan has a
 * figure) from what is in `out_dir`, and counts the runs that are ok and
 * those that failed. False, with `error` saying why, when a file cannot
 * be written or the figure's column is not in the table. */
bool sweep_gather(const sweep_plan *plan, const char *out_dir, int *ok_count, int *failed_count, char *error,
                  size_t error_size);

#endif
