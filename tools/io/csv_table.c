/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* getline */

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "io/csv_table.h"

static bool fail(char *error, size_t error_size, const char *format, ...)
{
    if (error != NULL && error_size > 0) {
        va_list args;
        va_start(args, format);
        vsnprintf(error, error_size, format, args);
        va_end(args);
    }
    return false;
}

void csv_table_free(csv_table *table)
{
    for (int c = 0; c < table->column_count && table->columns != NULL; ++c) {
        free(table->columns[c].name);
        free(table->columns[c].values);
    }
    free(table->columns);
    *table = (csv_table){.columns = NULL};
}

static char *copy_text(const char *text)
{
    size_t length = strlen(text);
    char *copy = malloc(length + 1);
    if (copy != NULL) {
        memcpy(copy, text, length + 1);
    }
    return copy;
}

bool csv_table_init(csv_table *table, int count, const char *const *names, char *error, size_t error_size)
{
    if (table == NULL) {
        return fail(error, error_size, "csv_table_init: table is NULL");
    }
    *table = (csv_table){.columns = NULL};
    if (count < 1 || names == NULL) {
        return fail(error, error_size, "csv_table_init: %d columns, expected at least 1 name", count);
    }
    for (int c = 0; c < count; ++c) {
        if (names[c] == NULL || names[c][0] == '\0') {
            return fail(error, error_size, "csv_table_init: column %d has no name", c);
        }
    }
    table->columns = calloc((size_t)count, sizeof *table->columns);
    if (table->columns == NULL) {
        return fail(error, error_size, "out of memory");
    }
    table->column_count = count;
    for (int c = 0; c < count; ++c) {
        table->columns[c].numeric = true;
        table->columns[c].name = copy_text(names[c]);
        if (table->columns[c].name == NULL) {
            csv_table_free(table);
            return fail(error, error_size, "out of memory");
        }
    }
    return true;
}

/* Room for one more row in every column. */
static bool grow(csv_table *table)
{
    if (table->row_count < table->row_capacity) {
        return true;
    }
    if (table->row_capacity > LONG_MAX / 4) {
        return false;
    }
    long capacity = table->row_capacity > 0 ? 2 * table->row_capacity : 256;
    for (int c = 0; c < table->column_count; ++c) {
        double *values = realloc(table->columns[c].values, (size_t)capacity * sizeof *values);
        if (values == NULL) {
            return false;
        }
        table->columns[c].values = values;
    }
    table->row_capacity = capacity;
    return true;
}

bool csv_table_add_row(csv_table *table, const double *values, char *error, size_t error_size)
{
    if (table == NULL || values == NULL || table->column_count < 1) {
        return fail(error, error_size, "csv_table_add_row: an initialised table and values are needed");
    }
    if (!grow(table)) {
        return fail(error, error_size, "out of memory");
    }
    for (int c = 0; c < table->column_count; ++c) {
        table->columns[c].values[table->row_count] = values[c];
    }
    table->row_count += 1;
    return true;
}

int csv_table_find(const csv_table *table, const char *name)
{
    for (int c = 0; table != NULL && name != NULL && c < table->column_count; ++c) {
        if (strcmp(table->columns[c].name, name) == 0) {
            return c;
        }
    }
    return -1;
}

/* ---------------------------------------------------------------- reading */

/* Splits `line` in place into at most `capacity` fields (stored in
 * `fields`, unquoted); returns the number of fields, or -1 with `problem`
 * set for an unterminated quote or more than `capacity` fields. The line
 * has no line break. */
static int split_fields(char *line, char **fields, int capacity, const char **problem)
{
    int count = 0;
    char *read = line;
    while (true) {
        if (count == capacity) {
            *problem = "more fields than the header";
            return -1;
        }
        char *write = read;
        fields[count++] = write;
        if (*read == '"') {
            ++read;
            while (true) {
                if (*read == '\0') {
                    *problem = "a quoted field is not closed on its line";
                    return -1;
                }
                if (*read == '"' && read[1] == '"') {
                    *write++ = '"';
                    read += 2;
                } else if (*read == '"') {
                    ++read;
                    break;
                } else {
                    *write++ = *read++;
                }
            }
            if (*read != ',' && *read != '\0') {
                *problem = "text after a closing quote";
                return -1;
            }
        } else {
            while (*read != ',' && *read != '\0') {
                *write++ = *read++;
            }
        }
        char separator = *read;
        *write = '\0';
        if (separator == '\0') {
            return count;
        }
        ++read;
    }
}

/* Reads one line into *line without its line break; false at the end. */
static bool read_line(FILE *stream, char **line, size_t *size)
{
    ssize_t length = getline(line, size, stream);
    if (length < 0) {
        return false;
    }
    while (length > 0 && ((*line)[length - 1] == '\n' || (*line)[length - 1] == '\r')) {
        (*line)[--length] = '\0';
    }
    return true;
}

static bool blank(const char *line) { return line[strspn(line, " \t")] == '\0'; }

static double parse_cell(const char *text, bool *ok)
{
    const char *start = text + strspn(text, " \t");
    if (*start == '\0') {
        *ok = true;
        return NAN;
    }
    char *end;
    errno = 0;
    double value = strtod(start, &end);
    *ok = end != start && end[strspn(end, " \t")] == '\0';
    return *ok ? value : NAN;
}

static bool read_header(FILE *stream, const char *path, csv_table *table, char **line, size_t *size, long *line_number,
                        char *error, size_t error_size)
{
    do {
        if (!read_line(stream, line, size)) {
            return fail(error, error_size, "%s: empty file: expected a header row of column names", path);
        }
        ++*line_number;
    } while (blank(*line));
    /* A header of n fields has n - 1 commas outside quotes at most. */
    int capacity = 1;
    for (const char *c = *line; *c != '\0'; ++c) {
        capacity += *c == ',';
    }
    char **fields = malloc((size_t)capacity * sizeof *fields);
    if (fields == NULL) {
        return fail(error, error_size, "out of memory");
    }
    const char *problem = NULL;
    int count = split_fields(*line, fields, capacity, &problem);
    bool ok = count > 0;
    if (!ok) {
        fail(error, error_size, "%s:%ld: header: %s", path, *line_number, problem);
    }
    for (int c = 0; ok && c < count; ++c) {
        if (fields[c][0] == '\0') {
            ok = fail(error, error_size, "%s:%ld: header: column %d has no name", path, *line_number, c + 1);
        }
    }
    if (ok) {
        ok = csv_table_init(table, count, (const char *const *)fields, error, error_size);
    }
    free(fields);
    return ok;
}

static bool read_rows(FILE *stream, const char *path, csv_table *table, char **line, size_t *size, long *line_number,
                      char *error, size_t error_size)
{
    int columns = table->column_count;
    char **fields = malloc((size_t)columns * sizeof *fields);
    double *values = malloc((size_t)columns * sizeof *values);
    bool ok = fields != NULL && values != NULL;
    if (!ok) {
        fail(error, error_size, "out of memory");
    }
    while (ok && read_line(stream, line, size)) {
        ++*line_number;
        if (blank(*line)) {
            continue;
        }
        const char *problem = NULL;
        int count = split_fields(*line, fields, columns, &problem);
        if (count < 0) {
            ok = fail(error, error_size, "%s:%ld: %s (the header has %d fields)", path, *line_number, problem, columns);
            break;
        }
        if (count != columns) {
            ok = fail(error, error_size, "%s:%ld: %d fields, the header has %d", path, *line_number, count, columns);
            break;
        }
        for (int c = 0; c < columns; ++c) {
            bool number;
            values[c] = parse_cell(fields[c], &number);
            csv_column *column = &table->columns[c];
            if (!number && column->numeric) {
                column->numeric = false;
                column->bad_line = *line_number;
                snprintf(column->bad_cell, sizeof column->bad_cell, "%s", fields[c]);
            }
        }
        ok = csv_table_add_row(table, values, error, error_size);
    }
    if (ok && ferror(stream)) {
        ok = fail(error, error_size, "%s: cannot read: %s", path, strerror(errno));
    }
    free(fields);
    free(values);
    return ok;
}

bool csv_table_read(const char *path, csv_table *table, char *error, size_t error_size)
{
    if (table == NULL || path == NULL) {
        return fail(error, error_size, "csv_table_read: path and table must not be NULL");
    }
    *table = (csv_table){.columns = NULL};
    FILE *stream = fopen(path, "r");
    if (stream == NULL) {
        return fail(error, error_size, "%s: %s", path, strerror(errno));
    }
    char *line = NULL;
    size_t size = 0;
    long line_number = 0;
    bool ok = read_header(stream, path, table, &line, &size, &line_number, error, error_size) &&
              read_rows(stream, path, table, &line, &size, &line_number, error, error_size);
    free(line);
    fclose(stream);
    if (!ok) {
        csv_table_free(table);
    }
    return ok;
}

/* ---------------------------------------------------------------- writing */

static void write_name(FILE *stream, const char *name)
{
    if (strpbrk(name, ",\"\r\n") == NULL) {
        fputs(name, stream);
        return;
    }
    fputc('"', stream);
    for (const char *c = name; *c != '\0'; ++c) {
        if (*c == '"') {
            fputc('"', stream); /* a quote inside a quoted field is doubled */
        }
        fputc(*c, stream);
    }
    fputc('"', stream);
}

bool csv_table_write(const csv_table *table, const char *path, char *error, size_t error_size)
{
    if (table == NULL || path == NULL || table->column_count < 1) {
        return fail(error, error_size, "csv_table_write: a table with columns and a path are needed");
    }
    atomic_file file = {.stream = NULL};
    char file_error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_open(&file, path, file_error, sizeof file_error)) {
        return fail(error, error_size, "%s", file_error);
    }
    for (int c = 0; c < table->column_count; ++c) {
        if (c > 0) {
            fputc(',', file.stream);
        }
        write_name(file.stream, table->columns[c].name);
    }
    fputc('\n', file.stream);
    for (long r = 0; r < table->row_count; ++r) {
        for (int c = 0; c < table->column_count; ++c) {
            fprintf(file.stream, c == 0 ? "%.10g" : ",%.10g", table->columns[c].values[r]);
        }
        fputc('\n', file.stream);
    }
    if (!atomic_file_commit(&file, file_error, sizeof file_error)) {
        return fail(error, error_size, "%s", file_error);
    }
    return true;
}
