/* SPDX-License-Identifier: MIT */
/* The muscle parameters a run may set over its model file's (`sinew run
 * --muscle NAME.PARAMETER=VALUE`, a sweep's "muscle.NAME.PARAMETER"):
 * each a double of mu_model_muscle, with the range the model file's
 * format gives it (docs/model-format.md).
 */
#ifndef SINEW_MUSCLE_PARAMETER_H
#define SINEW_MUSCLE_PARAMETER_H

#include <stddef.h>

#include "mu/model_desc.h"

typedef struct muscle_parameter {
    const char *name; /* as typed: "max_force" */
    const char *unit; /* "N" */
    double min, max;  /* the closed range of its values */
    size_t offset;    /* of the double in mu_model_muscle */
} muscle_parameter;

/* The names, for a message: "max_force, max_velocity, ... or deactivation_time". */
#define MUSCLE_PARAMETER_NAMES "max_force, max_velocity, pennation_angle, activation_time or deactivation_time"

/* The parameter called by the `length` bytes at `name`; NULL when none is. */
const muscle_parameter *muscle_parameter_find(const char *name, size_t length);

/* The parameter's field in `muscle`. */
double *muscle_parameter_field(const muscle_parameter *parameter, mu_model_muscle *muscle);

#endif
