/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/series_groups.h"

void series_groups_free(series_groups *groups)
{
    for (int k = 0; k < groups->count; ++k) {
        free(groups->keys[k]);
        free(groups->x[k]);
        free(groups->y[k]);
    }
    *groups = (series_groups){.count = 0};
}

static int find_key(const series_groups *groups, const char *key)
{
    for (int k = 0; k < groups->count; ++k) {
        if (strcmp(groups->keys[k], key) == 0) {
            return k;
        }
    }
    return -1;
}

/* A point of a series, sorted by x with NaNs last, ties by y so that the
 * order does not depend on qsort's. */
typedef struct point {
    double x, y;
} point;

static int compare_points(const void *a, const void *b)
{
    const point *p = a, *q = b;
    if (isnan(p->x) || isnan(q->x)) {
        return isnan(p->x) - isnan(q->x);
    }
    if (p->x != q->x) {
        return p->x < q->x ? -1 : 1;
    }
    return (p->y > q->y) - (p->y < q->y);
}

/* Sorts series k by x; with `front`, moves its front ahead of the other
 * points, both parts staying in order of x. */
static bool sort_series(series_groups *groups, int k, bool front)
{
    size_t n = groups->points[k];
    point *points = malloc((n > 0 ? n : 1) * sizeof *points);
    if (points == NULL) {
        return false;
    }
    for (size_t i = 0; i < n; ++i) {
        points[i] = (point){groups->x[k][i], groups->y[k][i]};
    }
    qsort(points, n, sizeof *points, compare_points);
    /* Two passes over the sorted points: count the front, then place
     * each point in its part. */
    size_t on = 0;
    double least = INFINITY;
    for (size_t i = 0; front && i < n; ++i) {
        if (isfinite(points[i].x) && points[i].y < least) {
            least = points[i].y;
            ++on;
        }
    }
    groups->front[k] = front ? on : n;
    least = INFINITY;
    size_t next_on = 0, next_off = on;
    for (size_t i = 0; i < n; ++i) {
        bool on_front = front && isfinite(points[i].x) && points[i].y < least;
        least = on_front ? points[i].y : least;
        size_t at = !front ? i : on_front ? next_on++ : next_off++;
        groups->x[k][at] = points[i].x;
        groups->y[k][at] = points[i].y;
    }
    free(points);
    return true;
}

/* Finds the keys and counts each group's rows. */
static bool count_groups(const char *const *keys, const bool *keep, size_t rows, series_groups *groups, char *error,
                         size_t error_size)
{
    for (size_t r = 0; r < rows; ++r) {
        if (keep != NULL && !keep[r]) {
            continue;
        }
        const char *key = keys != NULL ? keys[r] : "";
        int k = find_key(groups, key);
        if (k < 0) {
            if (groups->count == CHART_MAX_SERIES) {
                snprintf(error, error_size,
                         "more than %d distinct values (\"%s\" is the %dth); a chart draws at most %d",
                         CHART_MAX_SERIES, key, CHART_MAX_SERIES + 1, CHART_MAX_SERIES);
                return false;
            }
            k = groups->count;
            size_t length = strlen(key);
            groups->keys[k] = malloc(length + 1);
            if (groups->keys[k] == NULL) {
                snprintf(error, error_size, "out of memory");
                return false;
            }
            memcpy(groups->keys[k], key, length + 1);
            groups->points[k] = 0;
            groups->x[k] = groups->y[k] = NULL;
            groups->count += 1;
        }
        groups->points[k] += 1;
    }
    return true;
}

bool series_groups_build(const char *const *keys, const bool *keep, const double *x, const double *y, size_t rows,
                         series_order order, series_groups *groups, char *error, size_t error_size)
{
    char ignored[8];
    if (error == NULL || error_size == 0) {
        error = ignored;
        error_size = sizeof ignored;
    }
    *groups = (series_groups){.count = 0};
    if (rows > 0 && (x == NULL || y == NULL)) {
        snprintf(error, error_size, "series_groups_build: %zu rows and a NULL x or y", rows);
        return false;
    }
    if (!count_groups(keys, keep, rows, groups, error, error_size)) {
        series_groups_free(groups);
        return false;
    }
    for (int k = 0; k < groups->count; ++k) {
        size_t n = groups->points[k] > 0 ? groups->points[k] : 1;
        groups->x[k] = malloc(n * sizeof(double));
        groups->y[k] = malloc(n * sizeof(double));
        if (groups->x[k] == NULL || groups->y[k] == NULL) {
            snprintf(error, error_size, "out of memory");
            series_groups_free(groups);
            return false;
        }
        groups->points[k] = 0; /* filled again below */
    }
    for (size_t r = 0; r < rows; ++r) {
        if (keep != NULL && !keep[r]) {
            continue;
        }
        int k = find_key(groups, keys != NULL ? keys[r] : "");
        groups->x[k][groups->points[k]] = x[r];
        groups->y[k][groups->points[k]] = y[r];
        groups->points[k] += 1;
    }
    for (int k = 0; k < groups->count; ++k) {
        groups->front[k] = groups->points[k];
        if (order != SERIES_AS_READ && !sort_series(groups, k, order == SERIES_FRONT)) {
            snprintf(error, error_size, "out of memory");
            series_groups_free(groups);
            return false;
        }
    }
    return true;
}
