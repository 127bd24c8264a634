/* SPDX-License-Identifier: MIT */
/* A table of named columns of numbers, read from or written to a CSV file
 * with one header row (the format of `sinew run` and `sinew experiment`:
 * names carry their unit, "time_s", "Biceps Long.total_force_N" or
 * "force [N]").
 *
 * Reading goes through the muscle layer's CSV reader, the one reader of
 * every CSV file sinew reads (musculo/src/csv_reader.h): fields are
 * separated by commas; a field in double quotes may hold commas and
 * doubled quotes (RFC 4180), but not line breaks; a line may end in CRLF;
 * a byte-order mark and blank lines are skipped. Every row must have as
 * many fields as the header. A cell is a number as strtod reads it in the
 * C locale (nan and inf included) with only spaces around it; an empty
 * cell is a NaN.
 * A column with any other cell is not numeric: it is kept, its values
 * NaN, with the first such cell remembered for the message of whoever
 * asks for the column.
 *
 * Writing goes through an atomic_file (io/atomic_file.h): all or nothing.
 */
#ifndef IO_CSV_TABLE_H
#define IO_CSV_TABLE_H

#include <stdbool.h>
#include <stddef.h>

/* Bytes of a cell kept for a message about a non-numeric column. */
#define CSV_TABLE_CELL_SIZE 48

typedef struct csv_column {
    char *name;
    double *values; /* row_count values */
    bool numeric;
    long bad_line;                      /* when not numeric: the file's line of the first bad cell */
    char bad_cell[CSV_TABLE_CELL_SIZE]; /* and its text, truncated */
} csv_column;

typedef struct csv_table {
    csv_column *columns;
    int column_count;
    long row_count, row_capacity;
} csv_table;

/* An empty table with the given column names (count >= 1, each non-empty);
 * false when out of memory or on a bad argument, with `error` saying
 * which. */
bool csv_table_init(csv_table *table, int count, const char *const *names, char *error, size_t error_size);

/* Appends a row of column_count values. */
bool csv_table_add_row(csv_table *table, const double *values, char *error, size_t error_size);

/* Reads the CSV file `path`. On failure the table is empty and `error`
 * names the file, the line and what was wrong ("data.csv:7: 3 fields, the
 * header has 4"). */
bool csv_table_read(const char *path, csv_table *table, char *error, size_t error_size);

/* Writes the table to `path` (header quoted where RFC 4180 requires,
 * numbers with 10 significant digits). */
bool csv_table_write(const csv_table *table, const char *path, char *error, size_t error_size);

/* The index of the column named `name`, or -1. */
int csv_table_find(const csv_table *table, const char *name);

/* Frees the table; it is empty after. Accepts a zero-initialised table. */
void csv_table_free(csv_table *table);

#endif
