/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* newlocale, uselocale */

#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#include "error.h"

static _Thread_local char last_message[512];
static _Thread_local rb_status last_status = RB_OK;

const char *rb_status_name(rb_status status)
{
    switch (status) {
    case RB_OK:
        return "RB_OK";
    case RB_ERR_INVALID_ARGUMENT:
        return "RB_ERR_INVALID_ARGUMENT";
    case RB_ERR_STALE_ID:
        return "RB_ERR_STALE_ID";
    case RB_ERR_FOREIGN_ID:
        return "RB_ERR_FOREIGN_ID";
    case RB_ERR_DEGENERATE_SHAPE:
        return "RB_ERR_DEGENERATE_SHAPE";
    case RB_ERR_NOT_CONVEX:
        return "RB_ERR_NOT_CONVEX";
    case RB_ERR_NO_MASS:
        return "RB_ERR_NO_MASS";
    case RB_ERR_LOCKED:
        return "RB_ERR_LOCKED";
    case RB_ERR_OUT_OF_MEMORY:
        return "RB_ERR_OUT_OF_MEMORY";
    case RB_ERR_NOT_FINITE:
        return "RB_ERR_NOT_FINITE";
    }
    return "RB_ERR_UNKNOWN";
}

const char *rb_last_error(void) { return last_message; }

rb_status rb_last_status(void) { return last_status; }

void rb_clear_error(void)
{
    last_status = RB_OK;
    last_message[0] = '\0';
}

rb_status rb_report_error(rb_status status, const char *format, ...)
{
    /* A message quotes numbers as files and code spell them, with a '.',
     * even in a program that chose a decimal-comma LC_NUMERIC: the
     * calling thread formats in the "C" locale (uselocale, POSIX 2008)
     * and gets its own back. The muscle layer's parsing does the same
     * through its c_locale.h; the engine, which it reaches only through
     * the public API, makes its own locale here, on the error path only.
     * Should newlocale fail, the message is formatted as before. */
    locale_t c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    locale_t previous = c_locale != (locale_t)0 ? uselocale(c_locale) : (locale_t)0;
    va_list args;
    va_start(args, format);
    vsnprintf(last_message, sizeof last_message, format, args);
    va_end(args);
    if (previous != (locale_t)0) {
        uselocale(previous);
    }
    if (c_locale != (locale_t)0) {
        freelocale(c_locale);
    }
    last_status = status;
    return status;
}

rb_status rb_check_finite(const char *function, const char *name, double value)
{
    if (!isfinite(value)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %g, expected a finite number", function, name,
                               value);
    }
    return RB_OK;
}

rb_status rb_check_vec2(const char *function, const char *name, rb_vec2 value)
{
    if (!rb_vec2_is_finite(value)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is (%g, %g), expected finite coordinates", function,
                               name, value.x, value.y);
    }
    return RB_OK;
}

rb_status rb_check_range(const char *function, const char *name, double value, double lower, double upper)
{
    if (!(value >= lower && value <= upper)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %g, expected a value in [%g, %g]", function, name,
                               value, lower, upper);
    }
    return RB_OK;
}

rb_status rb_check_bound(const char *function, const char *name, double value, double bound, const char *unit)
{
    if (!(fabs(value) <= bound)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %g %s, expected a value in [%g, %g] %s", function,
                               name, value, unit, -bound, bound, unit);
    }
    return RB_OK;
}

rb_status rb_check_vec2_bound(const char *function, const char *name, rb_vec2 value, double bound, const char *unit)
{
    if (!(fabs(value.x) <= bound && fabs(value.y) <= bound)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is (%g, %g) %s, expected coordinates in [%g, %g] %s",
                               function, name, value.x, value.y, unit, -bound, bound, unit);
    }
    return RB_OK;
}

rb_status rb_check_hertz(const char *function, const char *name, double value, bool zero_allowed)
{
    if (!((value >= RB_MIN_HERTZ && value <= RB_MAX_HERTZ) || (zero_allowed && value == 0.0))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %g Hz, expected %s[%g, %g] Hz", function, name,
                               value, zero_allowed ? "0 or a value in " : "a value in ", RB_MIN_HERTZ, RB_MAX_HERTZ);
    }
    return RB_OK;
}

rb_status rb_check_point(const char *function, const char *name, rb_vec2 point)
{
    return rb_check_vec2_bound(function, name, point, RB_MAX_LENGTH, "m");
}

rb_status rb_check_pointer(const char *function, const char *name, const void *pointer)
{
    if (pointer == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is NULL", function, name);
    }
    return RB_OK;
}

rb_status rb_check_def_cookie(const char *function, const char *maker, int32_t internal_value)
{
    if (internal_value != RB_DEF_COOKIE) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: def was not made by %s() (its internal_value is %ld): it is uninitialised or "
                               "garbage; start from %s() and change the fields you need",
                               function, maker, (long)internal_value, maker);
    }
    return RB_OK;
}
