/* SPDX-License-Identifier: MIT */
/* number_text.h: tries 1, 2, ... 17 significant digits, the first text
 * strtod reads back exactly. */
#include <stdio.h>
#include <stdlib.h>

#include "number_text.h"

void number_text(double value, char text[NUMBER_TEXT_SIZE])
{
    for (int digits = 1; digits <= 17; ++digits) {
        snprintf(text, NUMBER_TEXT_SIZE, "%.*g", digits, value);
        if (strtod(text, NULL) == value) {
            return;
        }
    }
}
