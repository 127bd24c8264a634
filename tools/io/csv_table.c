/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csv_reader.h" /* musculo/src: the muscle layer's internal CSV reader */
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

/* The file's records come from the muscle layer's CSV reader, the one
 * reader of every CSV file sinew reads (musculo/src/csv_reader.h). */

static bool read_header(mu_csv_reader *csv, csv_table *table, char *error, size_t error_size)
{
    mu_csv_result result = mu_csv_reader_next(csv);
    if (result == MU_CSV_ERROR) {
        return fail(error, error_size, "%s", csv->error);
    }
    if (result == MU_CSV_END) {
        return fail(error, error_size, "%s: empty file: expected a header row of column names", csv->path);
    }
    for (int c = 0; c < csv->field_count; ++c) {
        if (csv->fields[c][0] == '\0') {
            return fail(error, error_size, "%s:%ld: header: column %d has no name", csv->path, csv->line_number, c + 1);
        }
    }
    return csv_table_init(table, csv->field_count, (const char *const *)csv->fields, error, error_size);
}

static bool read_rows(mu_csv_reader *csv, csv_table *table, char *error, size_t error_size)
{
    int columns = table->column_count;
    double *values = malloc((size_t)columns * sizeof *values);
    if (values == NULL) {
        return fail(error, error_size, "out of memory");
    }
    bool ok = true;
    mu_csv_result result = MU_CSV_END;
    while (ok && (result = mu_csv_reader_next(csv)) == MU_CSV_RECORD) {
        if (csv->field_count != columns) {
            ok = fail(error, error_size, "%s:%ld: %d fields, the header has %d", csv->path, csv->line_number,
                      csv->field_count, columns);
            break;
        }
        for (int c = 0; c < columns; ++c) {
            mu_csv_cell cell = mu_csv_number(csv->fields[c], &values[c]);
            if (cell != MU_CSV_NUMBER) {
                values[c] = NAN; /* an empty cell is a gap; anything else makes the column not numeric */
            }
            csv_column *column = &table->columns[c];
            if (cell == MU_CSV_NOT_A_NUMBER && column->numeric) {
                column->numeric = false;
                column->bad_line = csv->line_number;
                snprintf(column->bad_cell, sizeof column->bad_cell, "%s", csv->fields[c]);
            }
        }
        ok = csv_table_add_row(table, values, error, error_size);
    }
    if (ok && result == MU_CSV_ERROR) {
        ok = fail(error, error_size, "%s", csv->error);
    }
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
    mu_csv_reader csv;
    mu_csv_reader_init(&csv, path, stream, 0);
    bool ok = read_header(&csv, table, error, error_size) && read_rows(&csv, table, error, error_size);
    mu_csv_reader_free(&csv);
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
