/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* getline, and locale_t in c_locale.h */

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "c_locale.h"
#include "csv_reader.h"

static mu_csv_result fail(mu_csv_reader *r, const char *format, ...)
{
    int written = snprintf(r->error, sizeof r->error, "%s:%ld: ", r->path, r->line_number);
    if (written >= 0 && (size_t)written < sizeof r->error) {
        va_list args;
        va_start(args, format);
        vsnprintf(r->error + written, sizeof r->error - (size_t)written, format, args);
        va_end(args);
    }
    return MU_CSV_ERROR;
}

void mu_csv_reader_init(mu_csv_reader *reader, const char *path, FILE *file, unsigned flags)
{
    *reader = (mu_csv_reader){.path = path, .file = file, .flags = flags};
}

void mu_csv_reader_free(mu_csv_reader *reader)
{
    free(reader->line);
    free(reader->fields);
    free(reader->text);
    reader->line = NULL;
    reader->fields = NULL;
    reader->text = NULL;
    reader->line_size = reader->text_size = 0;
    reader->field_count = reader->field_capacity = 0;
}

/* The next line into r->line without its line break (and, on the first
 * line, without a byte-order mark); MU_CSV_END at the end of the file. */
static mu_csv_result read_line(mu_csv_reader *r)
{
    errno = 0;
    ssize_t length = getline(&r->line, &r->line_size, r->file);
    if (length < 0) {
        if (ferror(r->file) || !feof(r->file)) {
            return fail(r, "cannot read after this line: %s", strerror(errno != 0 ? errno : EIO));
        }
        return MU_CSV_END;
    }
    r->line_number++;
    while (length > 0 && (r->line[length - 1] == '\n' || r->line[length - 1] == '\r')) {
        r->line[--length] = '\0';
    }
    /* Spreadsheets often start a UTF-8 CSV with a byte-order mark. */
    if (r->line_number == 1 && strncmp(r->line, "\xEF\xBB\xBF", 3) == 0) {
        memmove(r->line, r->line + 3, (size_t)length - 2);
    }
    return MU_CSV_RECORD;
}

static bool is_space(char c) { return c == ' ' || c == '\t'; }

/* Whether `c` ends an unquoted field, or follows a closing quote. */
static bool ends_field(const mu_csv_reader *r, char c)
{
    return c == '\0' || c == ',' || ((r->flags & MU_CSV_SPACE_SEPARATES) && is_space(c)) ||
           ((r->flags & MU_CSV_COMMENTS) && c == '#');
}

static bool add_field(mu_csv_reader *r, char *field)
{
    if (r->field_count == r->field_capacity) {
        int capacity = r->field_capacity > 0 ? 2 * r->field_capacity : 16;
        char **fields = realloc(r->fields, (size_t)capacity * sizeof *fields);
        if (fields == NULL) {
            return false;
        }
        r->fields = fields;
        r->field_capacity = capacity;
    }
    r->fields[r->field_count++] = field;
    return true;
}

/* Splits r->line into r->fields (unquoted copies in r->text). Sets *blank
 * when the line holds no record: nothing but spaces, tabs and a comment. */
static mu_csv_result split(mu_csv_reader *r, bool *blank)
{
    const bool spaces_separate = (r->flags & MU_CSV_SPACE_SEPARATES) != 0;
    const bool comments = (r->flags & MU_CSV_COMMENTS) != 0;
    size_t length = strlen(r->line);
    if (length + 1 > r->text_size) {
        char *text = realloc(r->text, length + 1);
        if (text == NULL) {
            return fail(r, "out of memory for a line of %zu characters", length);
        }
        r->text = text;
        r->text_size = length + 1;
    }
    r->field_count = 0;
    const char *read = r->line;
    while (is_space(*read)) {
        read++;
    }
    *blank = *read == '\0' || (comments && *read == '#');
    if (*blank) {
        return MU_CSV_RECORD;
    }
    read = r->line;
    char *write = r->text;
    for (;;) {
        if (spaces_separate) {
            /* Runs of separators make no empty fields. */
            while (*read == ',' || is_space(*read)) {
                read++;
            }
            if (*read == '\0' || (comments && *read == '#')) {
                return MU_CSV_RECORD;
            }
        }
        if (!add_field(r, write)) {
            return fail(r, "out of memory for %d fields", r->field_count + 1);
        }
        if (*read == '"') {
            read++;
            for (;;) {
                if (*read == '\0') {
                    return fail(r, "field %d: a quoted field is not closed on its line", r->field_count);
                }
                if (read[0] == '"' && read[1] == '"') {
                    *write++ = '"'; /* a doubled quote is one quote */
                    read += 2;
                } else if (*read == '"') {
                    read++;
                    break;
                } else {
                    *write++ = *read++;
                }
            }
            if (!ends_field(r, *read)) {
                return fail(r, "field %d: text after its closing quote", r->field_count);
            }
        } else {
            while (!ends_field(r, *read)) {
                *write++ = *read++;
            }
        }
        *write++ = '\0';
        if (*read == '\0' || (comments && *read == '#')) {
            return MU_CSV_RECORD;
        }
        if (!spaces_separate) {
            read++; /* the comma; a field, perhaps empty, follows it */
        }
    }
}

mu_csv_result mu_csv_reader_next(mu_csv_reader *reader)
{
    for (;;) {
        mu_csv_result result = read_line(reader);
        if (result != MU_CSV_RECORD) {
            return result;
        }
        bool blank = false;
        result = split(reader, &blank);
        if (result != MU_CSV_RECORD || !blank) {
            return result;
        }
    }
}

mu_csv_cell mu_csv_number(const char *field, double *value)
{
    const char *start = field;
    while (is_space(*start)) {
        start++;
    }
    if (*start == '\0') {
        return MU_CSV_EMPTY;
    }
    char *end = NULL;
    mu_c_locale_scope scope = mu_c_locale_begin();
    const double number = strtod(start, &end);
    mu_c_locale_end(scope);
    while (is_space(*end)) {
        end++;
    }
    if (end == start || *end != '\0') {
        return MU_CSV_NOT_A_NUMBER;
    }
    *value = number;
    return MU_CSV_NUMBER;
}
