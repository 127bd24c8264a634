/* SPDX-License-Identifier: MIT */
/* Recording errors, and the checks every API entry point runs on its
 * arguments before touching the world. */
#ifndef RB_ERROR_H
#define RB_ERROR_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/base.h"
#include "rb/math.h"

/* Marks the start of a call that can fail: clears the last status. */
void rb_clear_error(void);

/* Each check returns RB_OK, or records a message naming the function and
 * the argument and returns RB_ERR_INVALID_ARGUMENT. */
rb_status rb_check_finite(const char *function, const char *name, double value);
rb_status rb_check_vec2(const char *function, const char *name, rb_vec2 value);
rb_status rb_check_range(const char *function, const char *name, double value, double lower, double upper);
rb_status rb_check_pointer(const char *function, const char *name, const void *pointer);
/* |value| <= bound (rb/base.h's ranges), in `unit`. */
rb_status rb_check_bound(const char *function, const char *name, double value, double bound, const char *unit);
/* Both components within ±bound. */
rb_status rb_check_vec2_bound(const char *function, const char *name, rb_vec2 value, double bound, const char *unit);
/* A frequency: RB_MIN_HERTZ .. RB_MAX_HERTZ Hz, or 0 when `zero_allowed`
 * (where 0 means off, or rigid). */
rb_status rb_check_hertz(const char *function, const char *name, double value, bool zero_allowed);
/* A point, anchor or position: both coordinates within ±RB_MAX_LENGTH m. */
rb_status rb_check_point(const char *function, const char *name, rb_vec2 point);

/* What the rb_default_*_def() functions put in a definition's
 * internal_value. A definition without it was not made by them (left
 * uninitialised, or garbage) and is refused rather than simulated; the
 * value is one a stray integer is unlikely to hold. */
#define RB_DEF_COOKIE 1152023

/* RB_OK when internal_value is RB_DEF_COOKIE; otherwise names `maker`,
 * the default function the definition should have come from. */
rb_status rb_check_def_cookie(const char *function, const char *maker, int32_t internal_value);

/* Runs a check and returns its status from the calling function on failure. */
#define RB_TRY(check)                                                                                                  \
    do {                                                                                                               \
        rb_status rb_try_status_ = (check);                                                                            \
        if (rb_try_status_ != RB_OK) {                                                                                 \
            return rb_try_status_;                                                                                     \
        }                                                                                                              \
    } while (0)

#endif
