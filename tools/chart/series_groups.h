/* SPDX-License-Identifier: MIT */
/* Rows of a table split into series by the value of a key column: one
 * series per distinct key, in the order the keys first appear (what
 * `sinew plot --group COLUMN` draws). A benchmark's CSV holds one row per
 * setting, the solver named in a column; split by that column, each
 * solver is a series of its own instead of one line zig-zagging from the
 * last setting of a solver to the first of the next.
 *
 * Each series can be sorted by x, so that measurements taken in any
 * order read from the cheapest to the dearest; rows whose x is a NaN go
 * last (chart_draw breaks the line there). Or each can be split into its
 * lower front and the rest: with x a cost and y an error, the front is
 * the measurements that no other one beats, none being as cheap or
 * cheaper and as accurate or more (the Pareto front of the two; Deb,
 * "Multi-Objective Optimization using Evolutionary Algorithms", 2001,
 * ch. 2). Along x it is the running least of y: walking the points in
 * order of x (ties by y), a point is on it when its y is below every
 * earlier one's. Joined, it is the best accuracy each cost buys with
 * that solver; a sweep along several settings at once (iterations and
 * substeps) reads as one curve however its rows are ordered.
 */
#ifndef CHART_SERIES_GROUPS_H
#define CHART_SERIES_GROUPS_H

#include <stdbool.h>
#include <stddef.h>

#include "chart/chart.h"

/* The order of each series' points. */
typedef enum series_order {
    SERIES_AS_READ, /* the rows' order */
    SERIES_BY_X,    /* sorted by x */
    SERIES_FRONT,   /* sorted by x, the front first (file comment) */
} series_order;

typedef struct series_groups {
    int count;                    /* series, 0 .. CHART_MAX_SERIES */
    char *keys[CHART_MAX_SERIES]; /* each series' key */
    double *x[CHART_MAX_SERIES];  /* points[k] values each */
    double *y[CHART_MAX_SERIES];
    size_t points[CHART_MAX_SERIES];
    /* SERIES_FRONT: the first front[k] of the points are the front, in
     * order of x, and the others (off the front, in order of x) follow;
     * otherwise front[k] is points[k]. */
    size_t front[CHART_MAX_SERIES];
} series_groups;

/* Splits `rows` rows of x and y by `keys` (rows texts; NULL: one series
 * keyed ""), keeping only the rows whose `keep` is true (NULL: all), each
 * series in `order`. Fails, the groups empty, with `error` saying why,
 * when out of memory or when the kept rows have more than
 * CHART_MAX_SERIES distinct keys. */
bool series_groups_build(const char *const *keys, const bool *keep, const double *x, const double *y, size_t rows,
                         series_order order, series_groups *groups, char *error, size_t error_size);

/* Frees the groups; they are empty after. Accepts zero-initialised groups. */
void series_groups_free(series_groups *groups);

#endif
