/* SPDX-License-Identifier: MIT */
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
    va_list args;
    va_start(args, format);
    vsnprintf(last_message, sizeof last_message, format, args);
    va_end(args);
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

rb_status rb_check_pointer(const char *function, const char *name, const void *pointer)
{
    if (pointer == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is NULL", function, name);
    }
    return RB_OK;
}
