/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/option_value.h"

bool option_parse_int(const char *option, const char *text, long min, long max, int *out, char *error,
                      size_t error_size)
{
    char *end = NULL;
    errno = 0;
    long value = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || value < min || value > max) {
        snprintf(error, error_size, "%s expects an integer from %ld to %ld, got \"%s\"", option, min, max, text);
        return false;
    }
    *out = (int)value;
    return true;
}

bool option_parse_double(const char *option, const char *text, double min, bool min_open, double max, double *out,
                         char *error, size_t error_size)
{
    char *end = NULL;
    errno = 0;
    double value = strtod(text, &end);
    bool above_min = min_open ? value > min : value >= min;
    /* isfinite rejects nan and inf, which strtod accepts. */
    if (end == text || *end != '\0' || errno == ERANGE || !isfinite(value) || !above_min || value > max) {
        snprintf(error, error_size, "%s expects a number %s %g and <= %g, got \"%s\"", option,
                 min_open ? ">" : ">=", min, max, text);
        return false;
    }
    *out = value;
    return true;
}

bool option_parse_u64(const char *option, const char *text, uint64_t *out, char *error, size_t error_size)
{
    /* strtoull skips leading blanks and silently negates "-1"; a seed or a
     * count is unsigned, so look past the blanks for the sign. */
    const char *digits = text;
    while (*digits == ' ' || *digits == '\t') {
        ++digits;
    }
    char *end = NULL;
    errno = 0;
    unsigned long long value = strtoull(text, &end, 10);
    if (*digits == '-' || end == text || *end != '\0' || errno == ERANGE) {
        snprintf(error, error_size, "%s expects an integer from 0 to %llu, got \"%s\"", option,
                 (unsigned long long)UINT64_MAX, text);
        return false;
    }
    *out = (uint64_t)value;
    return true;
}

bool option_parse_path(const char *option, const char *text, const char **out, char *error, size_t error_size)
{
    if (text[0] == '\0') {
        snprintf(error, error_size, "%s expects a file name, got an empty one", option);
        return false;
    }
    *out = text;
    return true;
}

const char *option_take_value(int argc, char **argv, int *i, const char *program, const char *const *known,
                              size_t count, const char *usage)
{
    const char *option = argv[*i];
    bool is_known = false;
    for (size_t k = 0; k < count && !is_known; ++k) {
        is_known = strcmp(option, known[k]) == 0;
    }
    if (!is_known) {
        fprintf(stderr, "%s: unknown option \"%s\"\n%s", program, option, usage);
        return NULL;
    }
    if (*i + 1 >= argc) {
        fprintf(stderr, "%s: %s needs a value\n", program, option);
        return NULL;
    }
    *i += 1;
    return argv[*i];
}

bool option_split(int argc, char **argv, int *i, const char *const *known, size_t count, const char **option,
                  const char **value, char *error, size_t error_size)
{
    const char *argument = argv[*i];
    const char *equals = strchr(argument, '=');
    size_t name_length = equals != NULL ? (size_t)(equals - argument) : strlen(argument);
    *option = NULL;
    for (size_t k = 0; k < count && *option == NULL; ++k) {
        if (strlen(known[k]) == name_length && strncmp(argument, known[k], name_length) == 0) {
            *option = known[k];
        }
    }
    if (*option == NULL) {
        snprintf(error, error_size, "unknown option \"%s\"", argument);
        return false;
    }
    if (equals != NULL) {
        *value = equals + 1;
        return true;
    }
    if (*i + 1 >= argc || strncmp(argv[*i + 1], "--", 2) == 0) {
        snprintf(error, error_size, "%s needs a value", *option);
        return false;
    }
    *i += 1;
    *value = argv[*i];
    return true;
}
