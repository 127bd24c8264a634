/* SPDX-License-Identifier: MIT */
/* The table of muscle_parameter.h. */
#include <string.h>

#include "muscle_parameter.h"

/* max_force replaces the force the file gives or derives (from a width or
 * an architecture); the activation times act when the muscle has
 * activation dynamics. */
static const muscle_parameter parameters[] = {
    {"max_force", "N", 0.001, 1e6, offsetof(mu_model_muscle, max_force)},
    {"max_velocity", "m/s", 0.001, 100.0, offsetof(mu_model_muscle, max_velocity)},
    {"pennation_angle", "deg", 0.0, 80.0, offsetof(mu_model_muscle, pennation_angle)},
    {"activation_time", "s", 1e-4, 10.0, offsetof(mu_model_muscle, activation_time)},
    {"deactivation_time", "s", 1e-4, 10.0, offsetof(mu_model_muscle, deactivation_time)},
};

const muscle_parameter *muscle_parameter_find(const char *name, size_t length)
{
    for (size_t p = 0; p < sizeof parameters / sizeof parameters[0]; ++p) {
        if (strlen(parameters[p].name) == length && strncmp(parameters[p].name, name, length) == 0) {
            return &parameters[p];
        }
    }
    return NULL;
}

double *muscle_parameter_field(const muscle_parameter *parameter, mu_model_muscle *muscle)
{
    return (double *)((char *)muscle + parameter->offset);
}
