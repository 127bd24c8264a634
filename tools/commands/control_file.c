/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* getline */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/words.h"
#include "control_file.h"

/* Fields of a line: time, kind, name, value, and one more to name in the
 * message for a line that goes on after its value. */
enum { MAX_FIELDS = 5 };

/* A whole field as a finite number. */
static bool parse_number(const char *text, double *out)
{
    char *end = NULL;
    errno = 0;
    double value = strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !isfinite(value)) {
        return false;
    }
    *out = value;
    return true;
}

static bool parse_kind(const char *text, control_kind *out)
{
    static const control_kind kinds[] = {CONTROL_ACTIVATION, CONTROL_TENSION, CONTROL_PULSE};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
        if (strcmp(text, control_kind_name(kinds[k])) == 0) {
            *out = kinds[k];
            return true;
        }
    }
    return false;
}

/* Reads one line's fields into the schedule; on failure `message` says
 * what was expected (without the file and line). */
static bool read_line(controls *schedule, char *line, char *message, size_t message_size)
{
    char *fields[MAX_FIELDS];
    const char *problem = NULL;
    int count = words_split(line, fields, MAX_FIELDS, &problem);
    if (count < 0) {
        snprintf(message, message_size, "%s", problem);
        return false;
    }
    if (count == 0) {
        return true;
    }
    double time;
    control_kind kind;
    if (!parse_number(fields[0], &time)) {
        snprintf(message, message_size, "expected a time in seconds, got \"%s\"", fields[0]);
        return false;
    }
    if (count < 2 || !parse_kind(fields[1], &kind)) {
        snprintf(message, message_size, "expected activation, tension or pulse after the time, got %s%s%s",
                 count < 2 ? "the end of the line" : "\"", count < 2 ? "" : fields[1], count < 2 ? "" : "\"");
        return false;
    }
    if (count < 3 || fields[2][0] == '\0') {
        snprintf(message, message_size, "expected a muscle or group name after \"%s\"", fields[1]);
        return false;
    }
    const char *expected = kind == CONTROL_TENSION ? "a tension in N" : "an activation from 0 to 1";
    double value = 1.0; /* a pulse's default: the muscle at full activation */
    if (count < 4 && kind != CONTROL_PULSE) {
        snprintf(message, message_size, "expected %s after the name \"%s\"", expected, fields[2]);
        return false;
    }
    if (count >= 4 && !parse_number(fields[3], &value)) {
        snprintf(message, message_size, "expected %s after the name \"%s\", got \"%s\"%s", expected, fields[2],
                 fields[3], strchr(fields[2], ' ') == NULL ? " (a name with spaces goes in double quotes)" : "");
        return false;
    }
    if (count >= MAX_FIELDS) {
        snprintf(message, message_size, "unexpected \"%s\" after the %s value%s", fields[4], control_kind_name(kind),
                 strchr(fields[2], ' ') == NULL ? " (a name with spaces goes in double quotes)" : "");
        return false;
    }
    return controls_add(schedule, time, kind, fields[2], value, message, message_size);
}

bool control_file_read(const char *path, controls *schedule, char *error, size_t error_size)
{
    FILE *file = fopen(path, "r");
    if (file == NULL) {
        snprintf(error, error_size, "cannot read %s: %s", path, strerror(errno));
        return false;
    }
    char *line = NULL;
    size_t capacity = 0;
    ssize_t length;
    long number = 0;
    bool ok = true;
    char message[1024];
    while (ok && (length = getline(&line, &capacity, file)) >= 0) {
        ++number;
        if (strlen(line) != (size_t)length) {
            snprintf(message, sizeof message, "a NUL byte; a control file is text");
            ok = false;
            break;
        }
        ok = read_line(schedule, line, message, sizeof message);
    }
    if (!ok) {
        snprintf(error, error_size, "%s:%ld: %s", path, number, message);
    } else if (ferror(file)) {
        /* A directory opens but does not read (EISDIR). */
        snprintf(error, error_size, "cannot read %s: %s", path, strerror(errno));
        ok = false;
    }
    free(line);
    fclose(file);
    return ok;
}
