/* SPDX-License-Identifier: MIT */
/* The CSV reader of the digitised Hill curves (private to the muscle layer).
 *
 * The file has the header row `curve,x,y` and one knot per row; a row's
 * curve is one of active_force_length, passive_force_length and
 * force_velocity. The rows of a curve may be spread over the file but its x
 * must be strictly increasing in file order, which is what an interpolant
 * needs.
 */
#ifndef MU_CURVE_TABLE_H
#define MU_CURVE_TABLE_H

#include <stddef.h>
#include <stdio.h>

#include "rb/base.h"

typedef enum mu_curve_kind {
    MU_CURVE_ACTIVE_LENGTH,  /* f_L, row name active_force_length */
    MU_CURVE_PASSIVE_LENGTH, /* f_P, row name passive_force_length */
    MU_CURVE_VELOCITY,       /* f_V, row name force_velocity */
    MU_CURVE_KIND_COUNT,
} mu_curve_kind;

/* The knots of one curve: x strictly increasing, every value finite. */
typedef struct mu_curve_table {
    double *x;
    double *y;
    size_t count;
} mu_curve_table;

/* Reads the three curves from `file` (open for reading, left open), each
 * with at least `minimum_points` knots (`interpolation_name` says why, for
 * the message); `path` names the file in messages. On failure nothing is
 * held, `tables` is left zeroed and the message names the file, the line
 * and what was expected. */
rb_status mu_curve_tables_read(const char *path, FILE *file, size_t minimum_points, const char *interpolation_name,
                               mu_curve_table tables[MU_CURVE_KIND_COUNT]);

/* Frees the knots of every table and zeroes them; accepts zeroed tables. */
void mu_curve_tables_free(mu_curve_table tables[MU_CURVE_KIND_COUNT]);

#endif
