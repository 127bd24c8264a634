/* SPDX-License-Identifier: MIT */
/* A motion for inverse dynamics: hinge angles over time, read from a CSV
 * file with a header row. The file is either `sinew run`'s CSV or any
 * table with a column `time_s` (s; `time` is accepted too) and, for each
 * of the model's built hinges, a column `HINGE.angle_deg` (degrees, as
 * the run CSV's); other columns are ignored, except one ending in
 * `.angle_deg` that names neither a hinge nor a part of the model, which
 * is taken for a misspelt hinge.
 *
 * The samples must be finite, at least MOTION_MIN_ROWS of them, at times
 * that increase by an even step (within MOTION_STEP_TOLERANCE of the mean
 * step): the filter and the finite differences (motion_filter.h) assume
 * uniform sampling. Every refusal prints one message naming the file, the
 * line (the header is line 1) and what was expected.
 */
#ifndef MOTION_FILE_H
#define MOTION_FILE_H

#include "mu/model.h"

/* Two differences at each end need four samples. */
#define MOTION_MIN_ROWS 4
/* Relative: a step may differ from the mean step by this much (a CSV's
 * times printed to 10 digits are far closer). */
#define MOTION_STEP_TOLERANCE 1e-3

typedef struct motion {
    long frames;
    double step;     /* s, the mean time step */
    double *time;    /* s, frames values */
    double **angles; /* by model hinge: frames angles in degrees; NULL for a hinge not built */
    int hinge_count;
} motion;

/* Reads the motion of `model`'s hinges from `path`; true, or false after
 * printing the message to stderr. */
bool motion_file_read(const char *path, const mu_model *model, motion *out);

void motion_free(motion *m);

#endif
