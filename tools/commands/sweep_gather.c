/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* strdup */
/* The summaries of a sweep's runs gathered into one table and a figure
 * (sweep_gather.h). */
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "chart/series_groups.h"
#include "io/atomic_file.h"
#include "number_text.h"
#include "sweep_gather.h"

/* ---------------------------------------------------------------- a run */

static char *path_in(const char *dir, const char *name, const char *suffix)
{
    size_t length = strlen(dir) + strlen(name) + strlen(suffix) + 2;
    char *path = malloc(length);
    if (path != NULL) {
        snprintf(path, length, "%s/%s%s", dir, name, suffix);
    }
    return path;
}

/* The run's summary when it is complete, else NULL. */
static json_t *load_summary(const char *out_dir, const sweep_run *run)
{
    char *path = path_in(out_dir, run->name, ".summary.json");
    json_t *root = path != NULL ? json_load_file(path, 0, NULL) : NULL;
    free(path);
    const json_t *arguments = json_object_get(root, "arguments");
    bool same = json_is_array(arguments) && json_array_size(arguments) == (size_t)run->argument_count;
    for (int k = 0; same && k < run->argument_count; ++k) {
        const char *text = json_string_value(json_array_get(arguments, (size_t)k));
        same = text != NULL && strcmp(text, run->arguments[k]) == 0;
    }
    if (!same) {
        json_decref(root);
        return NULL;
    }
    return root;
}

bool sweep_run_complete(const char *out_dir, const sweep_run *run)
{
    json_t *root = load_summary(out_dir, run);
    json_decref(root);
    return root != NULL;
}

/* Why a run is not complete: the last line its log holds. */
static void failure_message(const char *out_dir, const sweep_run *run, char *message, size_t size)
{
    char *path = path_in(out_dir, run->name, ".log");
    FILE *log = path != NULL ? fopen(path, "r") : NULL;
    free(path);
    snprintf(message, size, "%s", log != NULL ? "no summary, nothing in its log" : "not run");
    char line[1024];
    while (log != NULL && fgets(line, sizeof line, log) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        if (line[0] != '\0') {
            snprintf(message, size, "%s", line);
        }
    }
    if (log != NULL) {
        fclose(log);
    }
    char *summary = path_in(out_dir, run->name, ".summary.json");
    FILE *stale = summary != NULL ? fopen(summary, "r") : NULL;
    free(summary);
    if (stale != NULL) {
        fclose(stale);
        snprintf(message, size, "its summary was made by other arguments (an older sweep): run the sweep again");
    }
}

/* ---------------------------------------------------------------- table */

typedef struct table {
    int column_count;
    char **columns;
    int row_count;
    char ***cells; /* [row][column], NULL for empty */
} table;

static int column_index(table *t, const char *name, bool add)
{
    for (int c = 0; c < t->column_count; ++c) {
        if (strcmp(t->columns[c], name) == 0) {
            return c;
        }
    }
    if (!add) {
        return -1;
    }
    char **more = realloc(t->columns, ((size_t)t->column_count + 1) * sizeof *more);
    if (more == NULL) {
        return -1;
    }
    t->columns = more;
    t->columns[t->column_count] = strdup(name);
    return t->columns[t->column_count] != NULL ? t->column_count++ : -1;
}

/* Puts `text` (taken over) in the row's cell of column `name`; a column
 * that could not be added (out of memory) leaves the cell empty. */
static void set_cell(table *t, char **row, const char *name, char *text)
{
    int c = column_index(t, name, false);
    if (c >= 0) {
        free(row[c]);
        row[c] = text;
    } else {
        free(text);
    }
}

static char *number_cell(const json_t *value)
{
    if (!json_is_number(value)) {
        return NULL;
    }
    char text[NUMBER_TEXT_SIZE];
    number_text(json_number_value(value), text);
    return strdup(text);
}

/* The value's cell: a number exactly, a string as it is, null empty. */
static char *value_cell(const json_t *value)
{
    return json_is_string(value) ? strdup(json_string_value(value)) : number_cell(value);
}

/* Adds the columns of a list of the summary ("muscles"): NAME.FIELD for
 * each of `fields`. */
static void add_list_columns(table *t, const json_t *root, const char *list, const char *const *fields, int count)
{
    size_t k;
    const json_t *item;
    json_array_foreach(json_object_get(root, list), k, item)
    {
        const char *item_name = json_string_value(json_object_get(item, "name"));
        for (int f = 0; item_name != NULL && f < count; ++f) {
            char name[512];
            snprintf(name, sizeof name, "%s.%s", item_name, fields[f]);
            column_index(t, name, true);
        }
    }
}

static void set_list_cells(table *t, char **row, const json_t *root, const char *list, const char *const *fields,
                           int count)
{
    size_t k;
    const json_t *item;
    json_array_foreach(json_object_get(root, list), k, item)
    {
        const char *item_name = json_string_value(json_object_get(item, "name"));
        for (int f = 0; item_name != NULL && f < count; ++f) {
            char name[512];
            snprintf(name, sizeof name, "%s.%s", item_name, fields[f]);
            set_cell(t, row, name, value_cell(json_object_get(item, fields[f])));
        }
    }
}

static const char *const muscle_fields[] = {"peak_force_N", "peak_time_s"};
static const char *const torque_fields[] = {"exertion", "torque_N_m"};
static const char *const hinge_fields[] = {"final_angle_deg", "min_angle_deg", "max_angle_deg"};

/* The model's warnings joined by " | ". */
static char *warnings_cell(const json_t *root)
{
    size_t length = 1;
    size_t k;
    const json_t *line;
    json_array_foreach(json_object_get(root, "warnings"), k, line) { length += json_string_length(line) + 3; }
    char *text = calloc(length, 1);
    json_array_foreach(json_object_get(root, "warnings"), k, line)
    {
        if (text != NULL && json_is_string(line)) {
            strcat(strcat(text, k > 0 ? " | " : ""), json_string_value(line));
        }
    }
    return text;
}

/* Fills the table from the runs' summaries (NULL for a run not complete). */
static bool fill_table(table *t, const sweep_plan *plan, const char *out_dir, json_t *const *roots)
{
    static const char *const first[] = {"run"};
    static const char *const middle[] = {"status", "message", "variant_name", "weight_kg"};
    static const char *const last[] = {"controls_pending", "failure", "warnings", "wall_time_s", "real_time_factor"};
    column_index(t, first[0], true);
    for (int v = 0; v < plan->varied_count; ++v) {
        column_index(t, plan->varied[v], true);
    }
    for (size_t k = 0; k < sizeof middle / sizeof middle[0]; ++k) {
        column_index(t, middle[k], true);
    }
    /* The run's name and parameters go to columns 0 .. varied_count. */
    if (t->column_count != 1 + plan->varied_count + (int)(sizeof middle / sizeof middle[0])) {
        return false;
    }
    for (int r = 0; r < plan->run_count; ++r) {
        add_list_columns(t, roots[r], "muscles", muscle_fields, 2);
        add_list_columns(t, roots[r], "torque_muscles", torque_fields, 2);
        add_list_columns(t, roots[r], "hinges", hinge_fields, 3);
    }
    for (size_t k = 0; k < sizeof last / sizeof last[0]; ++k) {
        column_index(t, last[k], true);
    }
    t->cells = calloc((size_t)plan->run_count + 1, sizeof *t->cells);
    if (t->cells == NULL) {
        return false;
    }
    for (int r = 0; r < plan->run_count; ++r) {
        char **row = calloc((size_t)t->column_count, sizeof *row);
        if (row == NULL) {
            return false;
        }
        t->cells[t->row_count++] = row;
        const sweep_run *run = &plan->runs[r];
        const json_t *root = roots[r];
        row[0] = strdup(run->name);
        for (int v = 0; v < plan->varied_count; ++v) {
            row[1 + v] = strdup(run->values[v]);
        }
        set_cell(t, row, "status", strdup(root != NULL ? "ok" : "failed"));
        if (root == NULL) {
            char message[1024];
            failure_message(out_dir, run, message, sizeof message);
            set_cell(t, row, "message", strdup(message));
            continue;
        }
        set_cell(t, row, "variant_name", value_cell(json_object_get(root, "variant")));
        set_cell(t, row, "weight_kg", value_cell(json_object_get(root, "weight_kg")));
        set_list_cells(t, row, root, "muscles", muscle_fields, 2);
        set_list_cells(t, row, root, "torque_muscles", torque_fields, 2);
        set_list_cells(t, row, root, "hinges", hinge_fields, 3);
        set_cell(t, row, "controls_pending", value_cell(json_object_get(root, "controls_pending")));
        set_cell(t, row, "failure", value_cell(json_object_get(root, "failure")));
        set_cell(t, row, "warnings", warnings_cell(root));
        const json_t *timing = json_object_get(root, "timing");
        set_cell(t, row, "wall_time_s", value_cell(json_object_get(timing, "wall_s")));
        set_cell(t, row, "real_time_factor", value_cell(json_object_get(timing, "real_time_factor")));
    }
    return true;
}

static void free_table(table *t)
{
    for (int r = 0; r < t->row_count; ++r) {
        for (int c = 0; c < t->column_count; ++c) {
            free(t->cells[r][c]);
        }
        free(t->cells[r]);
    }
    for (int c = 0; c < t->column_count; ++c) {
        free(t->columns[c]);
    }
    free(t->cells);
    free(t->columns);
}

/* A cell as RFC 4180 writes it: in double quotes, its quotes doubled,
 * when it holds a comma, a quote or a line break. */
static void write_cell(FILE *stream, const char *text)
{
    if (text == NULL) {
        return;
    }
    if (strpbrk(text, ",\"\r\n") == NULL) {
        fputs(text, stream);
        return;
    }
    fputc('"', stream);
    for (const char *c = text; *c != '\0'; ++c) {
        if (*c == '"') {
            fputc('"', stream);
        }
        fputc(*c, stream);
    }
    fputc('"', stream);
}

static bool write_table(const table *t, const char *path, char *error, size_t error_size)
{
    atomic_file file = {0};
    if (!atomic_file_open(&file, path, error, error_size)) {
        return false;
    }
    for (int r = -1; r < t->row_count; ++r) {
        for (int c = 0; c < t->column_count; ++c) {
            if (c > 0) {
                fputc(',', file.stream);
            }
            write_cell(file.stream, r < 0 ? t->columns[c] : t->cells[r][c]);
        }
        fputc('\n', file.stream);
    }
    return atomic_file_commit(&file, error, error_size);
}

/* --------------------------------------------------------------- figure */

/* The plan's figure: y against x over the runs that are ok, one series
 * per value of the group parameter. */
static bool write_figure(const sweep_plan *plan, const table *t, const char *path, char *error, size_t error_size)
{
    int y_column = column_index((table *)t, plan->figure_y, false);
    int x_column = column_index((table *)t, plan->figure_x, false);
    int group_column = plan->figure_group != NULL ? column_index((table *)t, plan->figure_group, false) : -1;
    if (y_column < 0 || x_column < 0) {
        snprintf(error, error_size, "%s: $.figure.y: the summary has no column \"%s\" (see the header of %s)",
                 plan->file, plan->figure_y, path);
        return false;
    }
    size_t rows = (size_t)t->row_count;
    double *x = calloc(rows + 1, sizeof *x);
    double *y = calloc(rows + 1, sizeof *y);
    bool *keep = calloc(rows + 1, sizeof *keep);
    const char **keys = calloc(rows + 1, sizeof *keys);
    bool ok = x != NULL && y != NULL && keep != NULL && keys != NULL;
    for (size_t r = 0; ok && r < rows; ++r) {
        char *const *row = t->cells[r];
        keep[r] = row[y_column] != NULL && row[x_column] != NULL;
        x[r] = keep[r] ? strtod(row[x_column], NULL) : NAN;
        y[r] = keep[r] ? strtod(row[y_column], NULL) : NAN;
        keys[r] = group_column >= 0 ? row[group_column] : "";
    }
    series_groups groups = {0};
    ok = ok && series_groups_build(keys, keep, x, y, rows, SERIES_BY_X, &groups, error, error_size);
    if (ok) {
        chart_series series[CHART_MAX_SERIES];
        char labels[CHART_MAX_SERIES][256];
        for (int s = 0; s < groups.count; ++s) {
            snprintf(labels[s], sizeof labels[s], "%s = %s", plan->figure_group != NULL ? plan->figure_group : "",
                     groups.keys[s]);
            series[s] = (chart_series){.label = plan->figure_group != NULL ? labels[s] : NULL,
                                       .x = groups.x[s],
                                       .y = groups.y[s],
                                       .count = groups.points[s],
                                       .marker_radius = 3.0};
        }
        char title[512];
        snprintf(title, sizeof title, "%s against %s", plan->figure_y, plan->figure_x);
        const chart chart = {.title = title,
                             .x_label = plan->figure_x,
                             .y_label = plan->figure_y,
                             .series = series,
                             .series_count = groups.count};
        const chart_figure figure = {.charts = &chart, .chart_count = 1, .columns = 1, .width = 900, .height = 600};
        ok = chart_write_file(&figure, path, error, error_size);
    } else if (x == NULL || y == NULL || keep == NULL || keys == NULL) {
        snprintf(error, error_size, "%s: out of memory", path);
    }
    series_groups_free(&groups);
    free(x);
    free(y);
    free(keep);
    free(keys);
    return ok;
}

/* ----------------------------------------------------------------- both */

bool sweep_gather(const sweep_plan *plan, const char *out_dir, int *ok_count, int *failed_count, char *error,
                  size_t error_size)
{
    json_t **roots = calloc((size_t)plan->run_count + 1, sizeof *roots);
    if (roots == NULL) {
        snprintf(error, error_size, "out of memory");
        return false;
    }
    *ok_count = 0;
    *failed_count = 0;
    for (int r = 0; r < plan->run_count; ++r) {
        roots[r] = load_summary(out_dir, &plan->runs[r]);
        *(roots[r] != NULL ? ok_count : failed_count) += 1;
    }
    table t = {0};
    char *csv = path_in(out_dir, "summary", ".csv");
    char *png = path_in(out_dir, "summary", ".png");
    bool ok = csv != NULL && png != NULL && fill_table(&t, plan, out_dir, roots);
    if (!ok) {
        snprintf(error, error_size, "out of memory");
    }
    ok = ok && write_table(&t, csv, error, error_size);
    ok = ok && (plan->figure_y == NULL || write_figure(plan, &t, png, error, error_size));
    free_table(&t);
    free(csv);
    free(png);
    for (int r = 0; r < plan->run_count; ++r) {
        json_decref(roots[r]);
    }
    free(roots);
    return ok;
}
