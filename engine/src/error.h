/* SPDX-License-Identifier: MIT */
/* Recording errors, and the checks every API entry point runs on its
 * arguments before touching the world. */
#ifndef RB_ERROR_H
#define RB_ERROR_H

#include <stdbool.h>

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

/* Runs a check and returns its status from the calling function on failure. */
#define RB_TRY(check)                                                                                                  \
    do {                                                                                                               \
        rb_status rb_try_status_ = (check);                                                                            \
        if (rb_try_status_ != RB_OK) {                                                                                 \
            return rb_try_status_;                                                                                     \
        }                                                                                                              \
    } while (0)

#endif
