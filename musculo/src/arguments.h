/* SPDX-License-Identifier: MIT */
/* Checks the muscle layer's API runs on its arguments before using them,
 * with the engine's reporting (rb/base.h): each returns true when the
 * argument is refused, after recording RB_ERR_INVALID_ARGUMENT and a
 * message naming the function, the argument and what was expected. The
 * caller then returns its documented error value (a status, NaN, NULL,
 * false, -1 or 0). */
#ifndef MU_ARGUMENTS_H
#define MU_ARGUMENTS_H

#include <stdbool.h>

#include "mu/muscle.h"

/* `pointer` is NULL. */
bool mu_refuse_null(const char *function, const char *name, const void *pointer);
/* `index` is outside 0 .. count - 1. */
bool mu_refuse_index(const char *function, const char *name, int index, int count);
/* `value` is NaN or infinite. */
bool mu_refuse_non_finite(const char *function, const char *name, double value);

/* The readout a refused call returns: every field NaN, so that no value
 * passes for a real one. */
mu_muscle_readout mu_nan_readout(void);

#endif
