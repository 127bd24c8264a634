/* SPDX-License-Identifier: MIT */
/* The colour of a bone's stress (stress_colours.h). */
#include <math.h>

#include "stress_colours.h"

static const double green[3] = {0.15, 0.65, 0.25};
static const double yellow[3] = {0.95, 0.8, 0.1};
static const double red[3] = {0.85, 0.1, 0.1};

void stress_colour(double safety_factor, double rgb[3])
{
    const double use = safety_factor > 1.0 ? 1.0 / safety_factor : 1.0; /* +inf gives 0 */
    const double *from = use < 0.5 ? green : yellow;
    const double *to = use < 0.5 ? yellow : red;
    const double t = use < 0.5 ? 2.0 * use : 2.0 * use - 1.0;
    for (int c = 0; c < 3; ++c) {
        rgb[c] = from[c] + (to[c] - from[c]) * t;
    }
}
