/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csv_reader.h" /* musculo/src: the muscle layer's internal CSV reader */
#include "io/csv_cells.h"

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

void csv_cells_free(csv_cells *cells)
{
    for (long k = 0; k < cells->count && cells->text != NULL; ++k) {
        free(cells->text[k]);
    }
    free(cells->text);
    free(cells->line);
    *cells = (csv_cells){.text = NULL};
}

/* Appends a copy of `text` found on `line`; false when out of memory. */
static bool append(csv_cells *cells, long *capacity, const char *text, long line)
{
    if (cells->count == *capacity) {
        if (*capacity > LONG_MAX / 4) {
            return false;
        }
        long grown = *capacity > 0 ? 2 * *capacity : 64;
        char **texts = realloc(cells->text, (size_t)grown * sizeof *texts);
        if (texts == NULL) {
            return false;
        }
        cells->text = texts;
        long *lines = realloc(cells->line, (size_t)grown * sizeof *lines);
        if (lines == NULL) {
            return false;
        }
        cells->line = lines;
        *capacity = grown;
    }
    size_t length = strlen(text);
    char *copy = malloc(length + 1);
    if (copy == NULL) {
        return false;
    }
    memcpy(copy, text, length + 1);
    cells->text[cells->count] = copy;
    cells->line[cells->count] = line;
    cells->count += 1;
    return true;
}

/* The header's index of `column`, or -1 after setting `error`. */
static int find_column(mu_csv_reader *csv, const char *column, char *error, size_t error_size)
{
    mu_csv_result result = mu_csv_reader_next(csv);
    if (result == MU_CSV_ERROR) {
        fail(error, error_size, "%s", csv->error);
        return -1;
    }
    if (result == MU_CSV_END) {
        fail(error, error_size, "%s: empty file: expected a header row of column names", csv->path);
        return -1;
    }
    for (int c = 0; c < csv->field_count; ++c) {
        if (strcmp(csv->fields[c], column) == 0) {
            return c;
        }
    }
    fail(error, error_size, "%s: the header has no column \"%s\"", csv->path, column);
    return -1;
}

static bool read_cells(mu_csv_reader *csv, const char *column, csv_cells *cells, char *error, size_t error_size)
{
    int index = find_column(csv, column, error, error_size);
    if (index < 0) {
        return false;
    }
    int columns = csv->field_count;
    long capacity = 0;
    mu_csv_result result;
    while ((result = mu_csv_reader_next(csv)) == MU_CSV_RECORD) {
        if (csv->field_count != columns) {
            return fail(error, error_size, "%s:%ld: %d fields, the header has %d", csv->path, csv->line_number,
                        csv->field_count, columns);
        }
        if (!append(cells, &capacity, csv->fields[index], csv->line_number)) {
            return fail(error, error_size, "out of memory");
        }
    }
    return result == MU_CSV_ERROR ? fail(error, error_size, "%s", csv->error) : true;
}

bool csv_cells_read(const char *path, const char *column, csv_cells *cells, char *error, size_t error_size)
{
    if (cells == NULL || path == NULL || column == NULL) {
        return fail(error, error_size, "csv_cells_read: path, column and cells must not be NULL");
    }
    *cells = (csv_cells){.text = NULL};
    FILE *stream = fopen(path, "r");
    if (stream == NULL) {
        return fail(error, error_size, "%s: %s", path, strerror(errno));
    }
    mu_csv_reader csv;
    mu_csv_reader_init(&csv, path, stream, 0);
    bool ok = read_cells(&csv, column, cells, error, error_size);
    mu_csv_reader_free(&csv);
    fclose(stream);
    if (!ok) {
        csv_cells_free(cells);
    }
    return ok;
}
