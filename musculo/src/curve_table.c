/* SPDX-License-Identifier: MIT */
/* The digitised Hill curves (Ross et al. 2018, PLOS Comput Biol), read
 * with the one CSV reader (csv_reader.h): it splits records, this file
 * gives them their meaning.
 *
 * A curve file is data a person edits by hand, so the reader trusts none of
 * it: every failure names the file, the line and what was expected, and
 * nothing is interpolated until the whole file has been checked (GSL's
 * default error handler aborts the process on non-increasing x or too few
 * points, so those must never reach it).
 */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csv_reader.h"
#include "curve_table.h"

#define HEADER "curve,x,y"

static const char *const curve_names[MU_CURVE_KIND_COUNT] = {
    [MU_CURVE_ACTIVE_LENGTH] = "active_force_length",
    [MU_CURVE_PASSIVE_LENGTH] = "passive_force_length",
    [MU_CURVE_VELOCITY] = "force_velocity",
};

/* Every message starts with the public function that reads files. */
static const char *const function_name = "mu_curves_create_tabulated";

typedef struct reader {
    mu_csv_reader csv;                    /* the file's records (csv_reader.h) */
    size_t capacity[MU_CURVE_KIND_COUNT]; /* allocated knots per table */
    long last_line[MU_CURVE_KIND_COUNT];  /* line of each curve's last knot, 0 before one */
} reader;

/* The next record; *got_record is false at the end of the file. */
static rb_status next_record(reader *r, bool *got_record)
{
    mu_csv_result result = mu_csv_reader_next(&r->csv);
    *got_record = result == MU_CSV_RECORD;
    if (result == MU_CSV_ERROR) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s", function_name, r->csv.error);
    }
    return RB_OK;
}

static rb_status read_header(reader *r)
{
    bool got_record = false;
    rb_status status = next_record(r, &got_record);
    if (status != RB_OK) {
        return status;
    }
    if (!got_record) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: %s:1: the file is empty or blank, expected the header row '%s'", function_name,
                               r->csv.path, HEADER);
    }
    const mu_csv_reader *csv = &r->csv;
    if (csv->field_count != 3 || strcmp(csv->fields[0], "curve") != 0 || strcmp(csv->fields[1], "x") != 0 ||
        strcmp(csv->fields[2], "y") != 0) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%ld: header row is '%s', expected '%s'", function_name,
                               csv->path, csv->line_number, csv->line, HEADER);
    }
    return RB_OK;
}

/* Field `field` (named `name` in messages) of the current record as a
 * finite number. */
static rb_status parse_number(const reader *r, const char *name, const char *field, double *out)
{
    if (mu_csv_number(field, out) != MU_CSV_NUMBER) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%ld: %s is '%s', expected a number", function_name,
                               r->csv.path, r->csv.line_number, name, field);
    }
    if (!isfinite(*out)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%ld: %s is '%s', expected a finite number",
                               function_name, r->csv.path, r->csv.line_number, name, field);
    }
    return RB_OK;
}

/* Appends a knot, doubling the table's storage when it is full. */
static rb_status append_knot(reader *r, mu_curve_table *table, mu_curve_kind kind, double x, double y)
{
    if (table->count == r->capacity[kind]) {
        size_t capacity = r->capacity[kind] == 0 ? 64 : 2 * r->capacity[kind];
        double *xs = realloc(table->x, capacity * sizeof *xs);
        if (xs == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: %s:%ld: out of memory for %zu knots", function_name,
                                   r->csv.path, r->csv.line_number, capacity);
        }
        table->x = xs;
        double *ys = realloc(table->y, capacity * sizeof *ys);
        if (ys == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: %s:%ld: out of memory for %zu knots", function_name,
                                   r->csv.path, r->csv.line_number, capacity);
        }
        table->y = ys;
        r->capacity[kind] = capacity;
    }
    table->x[table->count] = x;
    table->y[table->count] = y;
    table->count++;
    r->last_line[kind] = r->csv.line_number;
    return RB_OK;
}

/* The current record, curve,x,y, into its table. */
static rb_status read_row(reader *r, mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    const mu_csv_reader *csv = &r->csv;
    if (csv->field_count != 3) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%ld: row is '%s', expected three fields curve,x,y",
                               function_name, csv->path, csv->line_number, csv->line);
    }
    const char *name = csv->fields[0];
    size_t kind = 0;
    while (kind < MU_CURVE_KIND_COUNT && strcmp(name, curve_names[kind]) != 0) {
        kind++;
    }
    if (kind == MU_CURVE_KIND_COUNT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%ld: unknown curve '%s', expected %s, %s or %s",
                               function_name, csv->path, csv->line_number, name, curve_names[0], curve_names[1],
                               curve_names[2]);
    }
    double x = 0.0;
    double y = 0.0;
    rb_status status = parse_number(r, "x", csv->fields[1], &x);
    if (status == RB_OK) {
        status = parse_number(r, "y", csv->fields[2], &y);
    }
    if (status != RB_OK) {
        return status;
    }
    mu_curve_table *table = &tables[kind];
    if (table->count > 0 && !(x > table->x[table->count - 1])) {
        return rb_report_error(
            RB_ERR_INVALID_ARGUMENT,
            "%s: %s:%ld: x = %.10g of %s is not above its previous knot's x = %.10g (line %ld), expected x "
            "strictly increasing within a curve",
            function_name, csv->path, csv->line_number, x, name, table->x[table->count - 1], r->last_line[kind]);
    }
    return append_knot(r, table, (mu_curve_kind)kind, x, y);
}

/* Every curve present with enough knots for the interpolation. */
static rb_status check_counts(const reader *r, size_t minimum_points, const char *interpolation_name,
                              const mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    for (size_t kind = 0; kind < MU_CURVE_KIND_COUNT; kind++) {
        if (tables[kind].count >= minimum_points) {
            continue;
        }
        if (tables[kind].count == 0) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "%s: %s:%ld: the file ends without a row of curve %s, expected at least %zu knots "
                                   "(%s interpolation)",
                                   function_name, r->csv.path, r->csv.line_number, curve_names[kind], minimum_points,
                                   interpolation_name);
        }
        return rb_report_error(
            RB_ERR_INVALID_ARGUMENT,
            "%s: %s:%ld: curve %s ends here with %zu knots, expected at least %zu (%s interpolation)", function_name,
            r->csv.path, r->last_line[kind], curve_names[kind], tables[kind].count, minimum_points, interpolation_name);
    }
    return RB_OK;
}

static rb_status read_rows(reader *r, mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    rb_status status = read_header(r);
    while (status == RB_OK) {
        bool got_record = false;
        status = next_record(r, &got_record);
        if (status != RB_OK || !got_record) {
            break;
        }
        status = read_row(r, tables);
    }
    return status;
}

rb_status mu_curve_tables_read(const char *path, FILE *file, size_t minimum_points, const char *interpolation_name,
                               mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    memset(tables, 0, MU_CURVE_KIND_COUNT * sizeof tables[0]);
    reader r = {.capacity = {0}};
    mu_csv_reader_init(&r.csv, path, file, 0);
    rb_status status = read_rows(&r, tables);
    if (status == RB_OK) {
        status = check_counts(&r, minimum_points, interpolation_name, tables);
    }
    mu_csv_reader_free(&r.csv);
    if (status != RB_OK) {
        mu_curve_tables_free(tables);
    }
    return status;
}

void mu_curve_tables_free(mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    for (size_t kind = 0; kind < MU_CURVE_KIND_COUNT; kind++) {
        free(tables[kind].x);
        free(tables[kind].y);
        tables[kind] = (mu_curve_table){0};
    }
}
