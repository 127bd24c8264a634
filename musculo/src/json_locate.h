/* SPDX-License-Identifier: MIT */
/* Where a value sits in the text of a JSON document.
 *
 * jansson's values carry no position, so a model file's semantic errors
 * (an unknown body, a negative size) re-scan the text for the value's
 * JSON path to report a line and column like a syntax error's.
 */
#ifndef MU_JSON_LOCATE_H
#define MU_JSON_LOCATE_H

#include <stdbool.h>
#include <stddef.h>

/* One step of a JSON path: an object key, or an array index when key is
 * NULL. */
typedef struct mu_json_step {
    const char *key; /* UTF-8, as jansson decoded it */
    size_t index;
} mu_json_step;

/* A place in the text, counted as jansson counts them in its errors. */
typedef struct mu_json_position {
    int line;   /* 1-based */
    int column; /* 1-based, in Unicode characters */
} mu_json_position;

/* Finds the value at the path `steps` (or, with at_key, the key that
 * names its last step, which must be a key) in `text`, a document jansson
 * accepted with duplicate keys rejected. False if the path is not there. */
bool mu_json_locate(const char *text, size_t length, const mu_json_step *steps, int step_count, bool at_key,
                    mu_json_position *out);

#endif
