/* SPDX-License-Identifier: MIT */
/* The summary of a `sinew run` as a JSON file (--summary FILE), the
 * machine-readable twin of the summary it prints, which `sinew sweep`
 * gathers into its table:
 *
 *   {
 *     "sinew": "0.2.0",
 *     "arguments": ["arm", "--weight", "1", ...],  the run's command line after `run`
 *     "model": "arm", "variant": "...", "variant_index": 0,
 *     "weight_kg": 1 (null without a weight), "level": 4,
 *     "frames": 30, "simulated_s": 0.5, "csv": "STEM.csv", "rows": 30, "columns": 120,
 *     "warnings": ["..."], "failure": null or "...",
 *     "controls_applied": 2, "controls_pending": 0,
 *     "muscles": [{"name": "Biceps", "peak_force_N": 101.2, "peak_time_s": 0.3}],
 *     "torque_muscles": [{"name": ..., "recruited": 3, "neurons": 10,
 *                         "exertion": 0.4, "torque_N_m": 1.2}],
 *     "hinges": [{"name": "Elbow", "final_angle_deg": 80, "min_angle_deg": 60,
 *                 "max_angle_deg": 90}],
 *     "timing": {"wall_s": 0.01, "stepping_s": 0.008, "real_time_factor": 50}
 *   }
 *
 * Everything but "timing" follows from the arguments alone (runs are
 * deterministic), so two machines write the same bytes up to "timing",
 * the last member. Numbers are written with 17 significant digits: read
 * back, each is the double the run computed. The "csv" is the file's
 * name without its folder, which may differ between machines.
 */
#ifndef SINEW_RUN_SUMMARY_H
#define SINEW_RUN_SUMMARY_H

#include <stdbool.h>
#include <stddef.h>

#include "mu/model.h"

typedef struct run_summary {
    int argument_count; /* the run's arguments after `run` */
    char **arguments;
    const mu_model *model;
    const char *model_name; /* as the run names it: a built-in's name or the model file's stem */
    int variant;            /* index among the description's variants */
    int level;
    double weight_kg; /* NaN without a weight */
    long frames;
    double simulated_seconds;
    const char *csv_path; /* its folder is left out */
    long rows;
    int columns;
    int controls_applied, controls_pending;
    const double *peak_force, *peak_time; /* N and s, by built muscle */
    const double *angle_min, *angle_max;  /* deg, by hinge; NaN for a hinge not built */
    double wall_seconds, step_seconds;
} run_summary;

/* Writes the summary to `path`, whole or not at all (io/atomic_file.h).
 * On failure `error` names the file and the reason. */
bool run_summary_write(const char *path, const run_summary *summary, char *error, size_t error_size);

#endif
