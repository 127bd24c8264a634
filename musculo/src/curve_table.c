/* SPDX-License-Identifier: MIT */
/* The CSV reader of the digitised Hill curves (Ross et al. 2018, PLOS
 * Comput Biol, as tabulated by the seed; framework.md §4).
 *
 * A curve file is data a person edits by hand, so the reader trusts none of
 * it: every failure names the file, the line and what was expected, and
 * nothing is interpolated until the whole file has been checked (GSL's
 * default error handler aborts the process on non-increasing x or too few
 * points, so those must never reach it).
 */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curve_table.h"

#define HEADER "curve,x,y"

/* Longest line accepted, newline included; a knot row is about 30
 * characters, so a longer line is a broken file, not data. */
#define MAX_LINE 256

static const char *const curve_names[MU_CURVE_KIND_COUNT] = {
    [MU_CURVE_ACTIVE_LENGTH] = "active_force_length",
    [MU_CURVE_PASSIVE_LENGTH] = "passive_force_length",
    [MU_CURVE_VELOCITY] = "force_velocity",
};

/* Every message starts with the public function that reads files. */
static const char *const function_name = "mu_curves_create_tabulated";

typedef struct reader {
    const char *path;
    FILE *file;
    size_t line_number;                    /* of the line in `line` */
    char line[MAX_LINE];                   /* without its line ending */
    size_t capacity[MU_CURVE_KIND_COUNT];  /* allocated knots per table */
    size_t last_line[MU_CURVE_KIND_COUNT]; /* line of each curve's last knot, 0 before one */
} reader;

/* Reads the next line into r->line without its "\n" or "\r\n" (files
 * saved on Windows). Sets *got_line to false at the end of the file. */
static rb_status next_line(reader *r, bool *got_line)
{
    if (fgets(r->line, sizeof r->line, r->file) == NULL) {
        *got_line = false;
        if (ferror(r->file)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%zu: read error after this line", function_name,
                                   r->path, r->line_number);
        }
        return RB_OK;
    }
    r->line_number++;
    size_t length = strlen(r->line);
    bool ended = length > 0 && r->line[length - 1] == '\n';
    if (!ended && !feof(r->file)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: %s:%zu: line longer than %d characters, expected a row curve,x,y", function_name,
                               r->path, r->line_number, MAX_LINE - 2);
    }
    while (length > 0 && (r->line[length - 1] == '\n' || r->line[length - 1] == '\r')) {
        r->line[--length] = '\0';
    }
    *got_line = true;
    return RB_OK;
}

static rb_status read_header(reader *r)
{
    bool got_line = false;
    rb_status status = next_line(r, &got_line);
    if (status != RB_OK) {
        return status;
    }
    if (!got_line) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:1: the file is empty, expected the header row '%s'",
                               function_name, r->path, HEADER);
    }
    /* Spreadsheets often start a UTF-8 CSV with a byte-order mark. */
    const char *header = r->line;
    if (strncmp(header, "\xEF\xBB\xBF", 3) == 0) {
        header += 3;
    }
    if (strcmp(header, HEADER) != 0) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:1: header row is '%s', expected '%s'", function_name,
                               r->path, header, HEADER);
    }
    return RB_OK;
}

/* `text` (field `field` of the current line) as a finite number. strtod
 * follows the C locale's decimal point; under a decimal-comma locale a
 * knot would not parse to its end and the row fails loudly rather than
 * being misread. */
static rb_status parse_number(const reader *r, const char *field, const char *text, double *out)
{
    char *end = NULL;
    *out = strtod(text, &end);
    if (end == text || *end != '\0') {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%zu: %s is '%s', expected a number", function_name,
                               r->path, r->line_number, field, text);
    }
    if (!isfinite(*out)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%zu: %s is '%s', expected a finite number",
                               function_name, r->path, r->line_number, field, text);
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
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: %s:%zu: out of memory for %zu knots", function_name,
                                   r->path, r->line_number, capacity);
        }
        table->x = xs;
        double *ys = realloc(table->y, capacity * sizeof *ys);
        if (ys == NULL) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: %s:%zu: out of memory for %zu knots", function_name,
                                   r->path, r->line_number, capacity);
        }
        table->y = ys;
        r->capacity[kind] = capacity;
    }
    table->x[table->count] = x;
    table->y[table->count] = y;
    table->count++;
    r->last_line[kind] = r->line_number;
    return RB_OK;
}

/* One row curve,x,y (r->line, modified in place) into its table. */
static rb_status read_row(reader *r, mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    char *x_text = strchr(r->line, ',');
    char *y_text = x_text == NULL ? NULL : strchr(x_text + 1, ',');
    if (y_text == NULL || strchr(y_text + 1, ',') != NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%zu: row is '%s', expected three fields curve,x,y",
                               function_name, r->path, r->line_number, r->line);
    }
    *x_text++ = '\0';
    *y_text++ = '\0';
    const char *name = r->line;

    size_t kind = 0;
    while (kind < MU_CURVE_KIND_COUNT && strcmp(name, curve_names[kind]) != 0) {
        kind++;
    }
    if (kind == MU_CURVE_KIND_COUNT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%zu: unknown curve '%s', expected %s, %s or %s",
                               function_name, r->path, r->line_number, name, curve_names[0], curve_names[1],
                               curve_names[2]);
    }
    double x = 0.0;
    double y = 0.0;
    rb_status status = parse_number(r, "x", x_text, &x);
    if (status == RB_OK) {
        status = parse_number(r, "y", y_text, &y);
    }
    if (status != RB_OK) {
        return status;
    }
    mu_curve_table *table = &tables[kind];
    if (table->count > 0 && !(x > table->x[table->count - 1])) {
        return rb_report_error(
            RB_ERR_INVALID_ARGUMENT,
            "%s: %s:%zu: x = %.10g of %s is not above its previous knot's x = %.10g (line %zu), expected x "
            "strictly increasing within a curve",
            function_name, r->path, r->line_number, x, name, table->x[table->count - 1], r->last_line[kind]);
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
                                   "%s: %s:%zu: the file ends without a row of curve %s, expected at least %zu knots "
                                   "(%s interpolation)",
                                   function_name, r->path, r->line_number, curve_names[kind], minimum_points,
                                   interpolation_name);
        }
        return rb_report_error(
            RB_ERR_INVALID_ARGUMENT,
            "%s: %s:%zu: curve %s ends here with %zu knots, expected at least %zu (%s interpolation)", function_name,
            r->path, r->last_line[kind], curve_names[kind], tables[kind].count, minimum_points, interpolation_name);
    }
    return RB_OK;
}

static rb_status read_rows(reader *r, mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    rb_status status = read_header(r);
    while (status == RB_OK) {
        bool got_line = false;
        status = next_line(r, &got_line);
        if (status != RB_OK || !got_line) {
            break;
        }
        /* Blank lines (a trailing one, or spacing between the curves)
         * carry no knot. */
        if (r->line[0] != '\0') {
            status = read_row(r, tables);
        }
    }
    return status;
}

rb_status mu_curve_tables_read(const char *path, size_t minimum_points, const char *interpolation_name,
                               mu_curve_table tables[MU_CURVE_KIND_COUNT])
{
    memset(tables, 0, MU_CURVE_KIND_COUNT * sizeof tables[0]);
    FILE *file = fopen(path, "r");
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: cannot open the file: %s", function_name, path,
                               strerror(errno));
    }
    reader r = {.path = path, .file = file};
    rb_status status = read_rows(&r, tables);
    if (status == RB_OK) {
        status = check_counts(&r, minimum_points, interpolation_name, tables);
    }
    fclose(file);
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
