/* SPDX-License-Identifier: MIT */
/* A double as the shortest decimal text that reads back as the same
 * double: 0.1, not 0.10000000000000001; 10, not 1e+01; 17 significant
 * digits at most
 * (IEEE 754 doubles need no more; Steele and White, "How to Print
 * Floating-Point Numbers Accurately", 1990). For names and tables that
 * must be both readable and exact.
 */
#ifndef SINEW_NUMBER_TEXT_H
#define SINEW_NUMBER_TEXT_H

#include <stddef.h>

/* Bytes that hold any such text, its NUL included. */
#define NUMBER_TEXT_SIZE 32

/* Writes `value` (finite) to `text`. */
void number_text(double value, char text[NUMBER_TEXT_SIZE]);

#endif
