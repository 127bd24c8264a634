/* SPDX-License-Identifier: MIT */
/* A motor pool's strengths read from an open stream (private to the
 * muscle layer): a profile image (pool_image.c) or a CSV of numbers
 * (pool_csv.c). mu_motor_pool_load_png and mu_motor_pool_load_csv read a
 * file through them, and a model file's "motor_pool" its "image" or
 * "csv", which may be a file built into libmu (model_schema.c).
 *
 * On success *strengths holds *count (1 .. MU_MAX_MOTOR_NEURONS) finite
 * strengths >= 0 with a positive sum, in recruitment order, for the
 * caller to free. On failure *strengths is NULL and `problem` says what
 * is wrong, without naming the file ("the image is 3 × 2 pixels, expected
 * 1 pixel high"), or, for a CSV, "LABEL:LINE: ..." as the CSV reader
 * words it; the caller adds the file and where it was named.
 */
#ifndef MU_POOL_PROFILE_H
#define MU_POOL_PROFILE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Bytes of a problem: a CSV problem holds a path and a field. */
#define MU_POOL_PROBLEM_SIZE 4608

/* Opens the regular file `path` for reading; NULL, with the problem said
 * ("cannot open: No such file or directory", "cannot read: not a regular
 * file"), otherwise. */
FILE *mu_pool_profile_open(const char *path, char *problem, size_t problem_size);

/* McIntyre's profile image (mu/motor_pool.h gives the rule): a PNG 1
 * pixel high; each pixel's strength is 255 − blue, on the scale red >=
 * green = blue; opaque. Read with libpng. */
bool mu_pool_profile_read_png(FILE *stream, double **strengths, int *count, char *problem, size_t problem_size);

/* Numbers separated by commas or blanks, '#' comments; `label` names the
 * stream in the problem's "LABEL:LINE:". */
bool mu_pool_profile_read_csv(FILE *stream, const char *label, double **strengths, int *count, char *problem,
                              size_t problem_size);

#endif
