/* SPDX-License-Identifier: MIT */
#include <math.h>

#include "arguments.h"
#include "rb/base.h"

bool mu_refuse_null(const char *function, const char *name, const void *pointer)
{
    if (pointer != NULL) {
        return false;
    }
    rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is NULL", function, name);
    return true;
}

bool mu_refuse_index(const char *function, const char *name, int index, int count)
{
    if (index >= 0 && index < count) {
        return false;
    }
    if (count > 0) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %d, expected 0 .. %d", function, name, index, count - 1);
    } else {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %d, but there are none", function, name, index);
    }
    return true;
}

bool mu_refuse_non_finite(const char *function, const char *name, double value)
{
    if (isfinite(value)) {
        return false;
    }
    rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is %g, expected a finite number", function, name, value);
    return true;
}

mu_muscle_readout mu_nan_readout(void)
{
    return (mu_muscle_readout){NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
}
