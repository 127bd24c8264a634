/* SPDX-License-Identifier: MIT */
/* One column of a CSV file as its cells' text, with the file's line of
 * each: what csv_table (io/csv_table.h) does not keep, for the columns a
 * reader picks rows by (`sinew plot --group`, `--where`: "ngs",
 * "chain_swing") and for messages that name a row's line.
 *
 * The file is read by the same reader and rules as csv_table_read, so
 * row k here is row k of the table read from the same file.
 */
#ifndef IO_CSV_CELLS_H
#define IO_CSV_CELLS_H

#include <stdbool.h>
#include <stddef.h>

typedef struct csv_cells {
    char **text; /* count cells, unquoted, as in the file */
    long *line;  /* the file's line of each row, counted from 1 */
    long count;
} csv_cells;

/* Reads the cells of the column named `column` of the CSV file `path`.
 * On failure the cells are empty and `error` names the file (and the line,
 * or that the header has no such column). */
bool csv_cells_read(const char *path, const char *column, csv_cells *cells, char *error, size_t error_size);

/* Frees the cells; they are empty after. Accepts zero-initialised cells. */
void csv_cells_free(csv_cells *cells);

#endif
