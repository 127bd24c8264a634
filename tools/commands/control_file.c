/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* getline, fmemopen */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/words.h"
#include "control_file.h"

/* Fields of a line: time, quantity, shape, name, four arguments, and one
 * more to name in the message for a line that goes on after its last. */
enum { MAX_ARGUMENTS = 4, MAX_FIELDS = 4 + MAX_ARGUMENTS + 1 };

/* The arguments of each shape after the name, as the messages name them. */
typedef struct shape_form {
    control_shape_kind kind;
    int count;
    const char *names[MAX_ARGUMENTS];
} shape_form;

static const shape_form forms[] = {
    {CONTROL_STEP, 1, {"VALUE"}},
    {CONTROL_RAMP, 3, {"FROM", "TO", "DURATION"}},
    {CONTROL_SINE, 4, {"MEAN", "AMPLITUDE", "FREQUENCY", "DURATION"}},
    {CONTROL_PULSES, 4, {"LEVEL", "FREQUENCY", "WIDTH", "DURATION"}},
};

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

static const shape_form *find_shape(const char *text)
{
    for (size_t s = 0; s < sizeof forms / sizeof forms[0]; ++s) {
        if (strcmp(text, control_shape_name(forms[s].kind)) == 0) {
            return &forms[s];
        }
    }
    return NULL;
}

static bool find_quantity(const char *text, control_kind *out)
{
    static const control_kind kinds[] = {CONTROL_ACTIVATION, CONTROL_TENSION, CONTROL_RECRUIT, CONTROL_PULSE};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
        if (strcmp(text, control_kind_name(kinds[k])) == 0) {
            *out = kinds[k];
            return true;
        }
    }
    return false;
}

/* What argument `name` of a line of `kind` is, for messages. */
static const char *argument_meaning(control_kind kind, const char *name)
{
    if (strcmp(name, "DURATION") == 0 || strcmp(name, "WIDTH") == 0) {
        return "a time in s";
    }
    if (strcmp(name, "FREQUENCY") == 0) {
        return "a frequency in Hz";
    }
    switch (kind) {
    case CONTROL_TENSION:
        return "a tension in N";
    case CONTROL_RECRUIT:
        return "a number of neurons";
    default:
        return "an activation from 0 to 1";
    }
}

/* The hint for a number that did not parse where a name may have been
 * split at a space. */
static const char *quote_hint(const char *name)
{
    return strchr(name, ' ') == NULL ? " (a name with spaces goes in double quotes)" : "";
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
    control_shape shape = {.kind = CONTROL_STEP};
    if (!parse_number(fields[0], &shape.start)) {
        snprintf(message, message_size, "expected a time in seconds, got \"%s\"", fields[0]);
        return false;
    }
    /* TIME [QUANTITY] SHAPE NAME ..., TIME QUANTITY NAME VALUE, TIME pulse NAME [VALUE] */
    control_kind kind = CONTROL_ACTIVATION;
    const shape_form *form = NULL;
    int name_field = 2;
    if (count >= 2 && find_quantity(fields[1], &kind)) {
        form = kind != CONTROL_PULSE && count >= 3 ? find_shape(fields[2]) : NULL;
        name_field = form != NULL ? 3 : 2;
        form = form != NULL ? form : &forms[0];
    } else if (count >= 2) {
        form = find_shape(fields[1]);
    }
    if (form == NULL) {
        snprintf(message, message_size,
                 "expected activation, tension, recruit, pulse, step, ramp, sine or pulses after the time, got %s%s%s",
                 count < 2 ? "the end of the line" : "\"", count < 2 ? "" : fields[1], count < 2 ? "" : "\"");
        return false;
    }
    shape.kind = form->kind;
    const char *word = fields[name_field - 1];
    if (count <= name_field || fields[name_field][0] == '\0') {
        snprintf(message, message_size, "expected a %s name after \"%s\"",
                 kind == CONTROL_RECRUIT ? "torque muscle" : "muscle or group", word);
        return false;
    }
    const char *name = fields[name_field];
    double arguments[MAX_ARGUMENTS] = {1.0}; /* a pulse's default: the muscle at full activation */
    const int given = count - name_field - 1;
    for (int a = 0; a < form->count; ++a) {
        const char *what = form->names[a];
        const char *after = a == 0 ? "the name" : form->names[a - 1];
        if (a >= given && kind == CONTROL_PULSE) {
            break;
        }
        if (a >= given && form->kind == CONTROL_STEP) {
            snprintf(message, message_size, "expected %s after the name \"%s\"", argument_meaning(kind, what), name);
            return false;
        }
        if (a >= given) {
            char usage[128];
            int used = snprintf(usage, sizeof usage, "TIME [QUANTITY] %s NAME", control_shape_name(form->kind));
            for (int u = 0; u < form->count && used > 0 && (size_t)used < sizeof usage; ++u) {
                used += snprintf(usage + used, sizeof usage - (size_t)used, " %s", form->names[u]);
            }
            snprintf(message, message_size, "a %s reads %s: expected %s (%s) after %s, got the end of the line",
                     control_shape_name(form->kind), usage, what, argument_meaning(kind, what), after);
            return false;
        }
        const char *text = fields[name_field + 1 + a];
        if (!parse_number(text, &arguments[a])) {
            if (form->kind == CONTROL_STEP) {
                snprintf(message, message_size, "expected %s after the name \"%s\", got \"%s\"%s",
                         argument_meaning(kind, what), name, text, quote_hint(name));
            } else {
                snprintf(message, message_size, "expected the %s's %s (%s) after %s, got \"%s\"%s",
                         control_shape_name(form->kind), what, argument_meaning(kind, what), after, text,
                         a == 0 ? quote_hint(name) : "");
            }
            return false;
        }
    }
    if (given > form->count) {
        snprintf(message, message_size, "unexpected \"%s\" after the %s%s%s", fields[name_field + 1 + form->count],
                 form->kind == CONTROL_STEP ? control_kind_name(kind) : control_shape_name(form->kind),
                 form->kind == CONTROL_STEP ? " value" : "'s ",
                 form->kind == CONTROL_STEP ? "" : form->names[form->count - 1]);
        if (form->kind == CONTROL_STEP) {
            size_t length = strlen(message);
            snprintf(message + length, message_size - length, "%s", quote_hint(name));
        }
        return false;
    }
    shape.first = arguments[0];
    switch (form->kind) {
    case CONTROL_STEP:
        break;
    case CONTROL_RAMP:
        shape.second = arguments[1];
        shape.duration = arguments[2];
        break;
    case CONTROL_SINE:
        shape.second = arguments[1];
        shape.frequency = arguments[2];
        shape.duration = arguments[3];
        break;
    case CONTROL_PULSES:
        shape.frequency = arguments[1];
        shape.width = arguments[2];
        shape.duration = arguments[3];
        break;
    }
    return controls_add_shape(schedule, kind, name, &shape, message, message_size);
}

/* Reads every line of `file`, named `name` in the messages. */
static bool read_stream(FILE *file, const char *name, controls *schedule, char *error, size_t error_size)
{
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
        snprintf(error, error_size, "%s:%ld: %s", name, number, message);
    } else if (ferror(file)) {
        /* A directory opens but does not read (EISDIR). */
        snprintf(error, error_size, "cannot read %s: %s", name, strerror(errno));
        ok = false;
    }
    free(line);
    return ok;
}

bool control_file_read(const char *path, controls *schedule, char *error, size_t error_size)
{
    FILE *file = fopen(path, "r");
    if (file == NULL) {
        snprintf(error, error_size, "cannot read %s: %s", path, strerror(errno));
        return false;
    }
    bool ok = read_stream(file, path, schedule, error, error_size);
    fclose(file);
    return ok;
}

bool control_text_read(const char *name, const char *text, controls *schedule, char *error, size_t error_size)
{
    if (*text == '\0') {
        return true; /* fmemopen may refuse an empty buffer */
    }
    FILE *file = fmemopen((void *)text, strlen(text), "r");
    if (file == NULL) {
        snprintf(error, error_size, "cannot read %s: %s", name, strerror(errno));
        return false;
    }
    bool ok = read_stream(file, name, schedule, error, error_size);
    fclose(file);
    return ok;
}
