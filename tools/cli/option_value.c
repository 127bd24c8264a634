/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

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
