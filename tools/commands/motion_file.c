/* SPDX-License-Identifier: MIT */
/* Reading a motion (motion_file.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/csv_table.h"
#include "motion_file.h"

#define ANGLE_SUFFIX ".angle_deg"

/* The file's line of data row r: the header is line 1. */
static long line_of(long row) { return row + 2; }

static void list_hinges(const mu_model *model)
{
    int listed = 0;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        if (!rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            fprintf(stderr, "%s\"%s%s\"", listed++ == 0 ? " " : ", ", mu_model_hinge_name(model, h), ANGLE_SUFFIX);
        }
    }
    fputs(listed == 0 ? " none\n" : "\n", stderr);
}

/* Whether `name` (without the suffix, `length` bytes) is a hinge or a part. */
static bool names_hinge_or_part(const mu_model *model, const char *name, size_t length)
{
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        const char *hinge = mu_model_hinge_name(model, h);
        if (strlen(hinge) == length && strncmp(hinge, name, length) == 0) {
            return true;
        }
    }
    for (int p = 0; p < mu_model_part_count(model); ++p) {
        const char *part = mu_model_part_name(model, p);
        if (strlen(part) == length && strncmp(part, name, length) == 0) {
            return true;
        }
    }
    return false;
}

/* A column of the table the motion needs: numeric and finite throughout. */
static bool check_column(const char *path, const csv_column *column, const char *expected)
{
    if (!column->numeric) {
        fprintf(stderr, "sinew: %s:%ld: column \"%s\" has \"%s\"; expected %s\n", path, column->bad_line, column->name,
                column->bad_cell, expected);
        return false;
    }
    return true;
}

static bool check_finite(const char *path, const csv_table *table, const csv_column *column, const char *expected)
{
    for (long r = 0; r < table->row_count; ++r) {
        if (!isfinite(column->values[r])) {
            fprintf(stderr, "sinew: %s:%ld: column \"%s\" is %s; expected %s\n", path, line_of(r), column->name,
                    isnan(column->values[r]) ? "not a number (empty or nan)" : "infinite", expected);
            return false;
        }
    }
    return true;
}

/* Increasing times at an even step. */
static bool check_times(const char *path, const csv_table *table, const csv_column *time, double *step)
{
    const long n = table->row_count;
    for (long r = 1; r < n; ++r) {
        if (!(time->values[r] > time->values[r - 1])) {
            fprintf(stderr,
                    "sinew: %s:%ld: %s = %.10g does not increase (the line before has %.10g); expected times "
                    "in increasing order\n",
                    path, line_of(r), time->name, time->values[r], time->values[r - 1]);
            return false;
        }
    }
    *step = (time->values[n - 1] - time->values[0]) / (double)(n - 1);
    for (long r = 1; r < n; ++r) {
        const double dt = time->values[r] - time->values[r - 1];
        if (fabs(dt - *step) > MOTION_STEP_TOLERANCE * *step) {
            fprintf(stderr,
                    "sinew: %s:%ld: a time step of %.10g s where the mean step is %.10g s; expected evenly spaced "
                    "samples (the filter and the differences need them: resample the motion)\n",
                    path, line_of(r), dt, *step);
            return false;
        }
    }
    return true;
}

/* Every column ending in ".angle_deg" names a hinge or a part. */
static bool check_angle_names(const char *path, const csv_table *table, const mu_model *model)
{
    const size_t suffix = strlen(ANGLE_SUFFIX);
    for (int c = 0; c < table->column_count; ++c) {
        const char *name = table->columns[c].name;
        const size_t length = strlen(name);
        if (length > suffix && strcmp(name + length - suffix, ANGLE_SUFFIX) == 0 &&
            !names_hinge_or_part(model, name, length - suffix)) {
            fprintf(stderr, "sinew: %s:1: column \"%s\" names no hinge of model %s; its hinges' columns are", path,
                    name, mu_model_description(model)->name);
            list_hinges(model);
            return false;
        }
    }
    return true;
}

static bool fill_motion(const char *path, const csv_table *table, const mu_model *model, motion *out)
{
    int time = csv_table_find(table, "time_s");
    time = time >= 0 ? time : csv_table_find(table, "time");
    if (time < 0) {
        fprintf(stderr, "sinew: %s:1: no column \"time_s\"; expected the time in s in a column \"time_s\"\n", path);
        return false;
    }
    if (!check_angle_names(path, table, model)) {
        return false;
    }
    const char *seconds = "a time in s";
    if (!check_column(path, &table->columns[time], seconds)) {
        return false;
    }
    if (table->row_count < MOTION_MIN_ROWS) {
        fprintf(stderr, "sinew: %s: %ld rows of data; expected at least %d (evenly spaced in time)\n", path,
                table->row_count, MOTION_MIN_ROWS);
        return false;
    }
    out->hinge_count = mu_model_hinge_count(model);
    out->frames = table->row_count;
    out->time = malloc((size_t)out->frames * sizeof *out->time);
    out->angles = calloc((size_t)out->hinge_count + 1, sizeof *out->angles);
    if (out->time == NULL || out->angles == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    const char *degrees = "an angle in degrees";
    for (int h = 0; h < out->hinge_count; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(model, h))) {
            continue;
        }
        char name[1024];
        snprintf(name, sizeof name, "%s%s", mu_model_hinge_name(model, h), ANGLE_SUFFIX);
        const int c = csv_table_find(table, name);
        if (c < 0) {
            fprintf(stderr, "sinew: %s:1: no column \"%s\"; expected a column for each of model %s's hinges:", path,
                    name, mu_model_description(model)->name);
            list_hinges(model);
            return false;
        }
        if (!check_column(path, &table->columns[c], degrees) ||
            !check_finite(path, table, &table->columns[c], degrees)) {
            return false;
        }
        out->angles[h] = malloc((size_t)out->frames * sizeof *out->angles[h]);
        if (out->angles[h] == NULL) {
            fputs("sinew: out of memory\n", stderr);
            return false;
        }
        memcpy(out->angles[h], table->columns[c].values, (size_t)out->frames * sizeof *out->angles[h]);
    }
    if (!check_finite(path, table, &table->columns[time], seconds) ||
        !check_times(path, table, &table->columns[time], &out->step)) {
        return false;
    }
    memcpy(out->time, table->columns[time].values, (size_t)out->frames * sizeof *out->time);
    return true;
}

bool motion_file_read(const char *path, const mu_model *model, motion *out)
{
    *out = (motion){0};
    csv_table table = {0};
    char error[1024];
    if (!csv_table_read(path, &table, error, sizeof error)) {
        fprintf(stderr, "sinew: --motion: %s\n", error);
        return false;
    }
    const bool ok = fill_motion(path, &table, model, out);
    csv_table_free(&table);
    if (!ok) {
        motion_free(out);
    }
    return ok;
}

void motion_free(motion *m)
{
    for (int h = 0; m->angles != NULL && h < m->hinge_count; ++h) {
        free(m->angles[h]);
    }
    free(m->angles);
    free(m->time);
    *m = (motion){0};
}
