/* SPDX-License-Identifier: MIT */
/* The one reader of the CSV files sinew reads (private to the muscle
 * layer; the in-tree tools use it too): the Hill curve tables
 * (curve_table.c), motor-pool profiles (motor_pool.c) and any table
 * `sinew plot` draws (tools/io/csv_table.c). It splits a file into
 * records of text fields and reads numbers; what the fields mean is the
 * caller's.
 *
 * The format is RFC 4180's, as spreadsheets write it, with the
 * tolerances a hand-edited file needs:
 *   - fields are separated by commas; a field in double quotes may hold
 *     commas and doubled quotes, but not a line break;
 *   - a line ends in LF or CRLF; a UTF-8 byte-order mark before the first
 *     line is skipped;
 *   - a blank line (nothing, or only spaces and tabs) is no record;
 *   - with MU_CSV_SPACE_SEPARATES, spaces and tabs separate fields too and
 *     runs of separators make no empty fields ("1, 2\t3" is 3 fields);
 *   - with MU_CSV_COMMENTS, '#' outside quotes starts a comment that runs
 *     to the end of its line.
 * Lines may be of any length.
 *
 * Every message of the reader is "PATH:LINE: what was wrong", for the
 * caller to prefix with its own name; callers report their own problems
 * with a field in the same form, from mu_csv_reader.line_number.
 */
#ifndef MU_CSV_READER_H
#define MU_CSV_READER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

typedef enum mu_csv_flags {
    MU_CSV_SPACE_SEPARATES = 1u << 0,
    MU_CSV_COMMENTS = 1u << 1,
} mu_csv_flags;

/* Bytes of a reader's message: a long path and a short problem. */
#define MU_CSV_ERROR_SIZE 4608

typedef struct mu_csv_reader {
    const char *path; /* names the file in messages */
    FILE *file;       /* not owned */
    unsigned flags;   /* mu_csv_flags */
    long line_number; /* of the record last read (lines counted from 1) */
    char *line;       /* that record's line as in the file, without its line break */
    size_t line_size;
    char **fields; /* field_count fields of that record, unquoted */
    int field_count;
    int field_capacity;
    char *text; /* storage of the fields */
    size_t text_size;
    char error[MU_CSV_ERROR_SIZE]; /* after mu_csv_reader_next returned MU_CSV_ERROR */
} mu_csv_reader;

typedef enum mu_csv_result {
    MU_CSV_RECORD, /* fields holds the next record */
    MU_CSV_END,    /* no more records */
    MU_CSV_ERROR,  /* error says what and where */
} mu_csv_result;

/* A reader of `file` (open for reading, left open), named `path` in
 * messages; `flags` is a combination of mu_csv_flags. */
void mu_csv_reader_init(mu_csv_reader *reader, const char *path, FILE *file, unsigned flags);

/* Reads the next record, skipping blank and comment-only lines. */
mu_csv_result mu_csv_reader_next(mu_csv_reader *reader);

/* Frees what the reader holds; the file stays open. */
void mu_csv_reader_free(mu_csv_reader *reader);

typedef enum mu_csv_cell {
    MU_CSV_NUMBER,       /* *value holds it (NaN and infinities included) */
    MU_CSV_EMPTY,        /* nothing but spaces and tabs */
    MU_CSV_NOT_A_NUMBER, /* anything else */
} mu_csv_cell;

/* A field as a number: strtod's syntax in the "C" locale (a '.' decimal
 * point whatever the process locale, c_locale.h), spaces and tabs allowed
 * around it, nothing else. */
mu_csv_cell mu_csv_number(const char *field, double *value);

#endif
