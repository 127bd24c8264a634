/* SPDX-License-Identifier: MIT */
/* number_text.h: tries 1, 2, ... 17 significant digits, the first text
 * strtod reads back exactly; at least as many as the number has digits
 * before the point, so that 10 is "10", not "1e+01". */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "number_text.h"

void number_text(double value, char text[NUMBER_TEXT_SIZE])
{
    double magnitude = fabs(value);
    int first = magnitude >= 1.0 && magnitude < 1e17 ? (int)floor(log10(magnitude)) + 1 : 1;
    for (int digits = first; digits <= 17; ++digits) {
        snprintf(text, NUMBER_TEXT_SIZE, "%.*g", digits, value);
        if (strtod(text, NULL) == value) {
            return;
        }
    }
}
