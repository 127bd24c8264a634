/* SPDX-License-Identifier: MIT */
/* Reading a JSON document against a schema, with errors that say where.
 *
 * The reader keeps the JSON path of the value being read; every failure
 * is reported through the engine's error channel as
 *
 *     FILE:LINE:COLUMN: PATH: PROBLEM, expected WHAT
 *
 * with LINE:COLUMN where the offending value (or unknown key, or the
 * object missing a key) starts in the text. Numbers are accepted as JSON
 * integers or reals; jansson rejects reals that overflow (1e999), so
 * every number read is finite.
 */
#ifndef MU_MODEL_JSON_H
#define MU_MODEL_JSON_H

#include <jansson.h>
#include <stdbool.h>

#include "json_locate.h"
#include "rb/base.h"
#include "rb/math.h"

/* Deepest path the model schema reads (muscles[i].path[j].point[k]), with room to spare. */
#define MU_JSON_MAX_DEPTH 8

typedef struct mu_json_reader {
    const char *file; /* as given to the loader */
    /* The folder of the files the document names by a relative path (a
     * motor pool's image); NULL for a document built into libmu, whose
     * files are built in beside it (data_file.h). */
    const char *folder;
    const char *text;                     /* the document, for positions */
    size_t length;                        /* bytes of text */
    int depth;                            /* 0 .. MU_JSON_MAX_DEPTH */
    mu_json_step path[MU_JSON_MAX_DEPTH]; /* the steps from the root to the value being read */
} mu_json_reader;

/* Returns the status of `call` from the calling function unless it is RB_OK. */
#define MU_JSON_TRY(call)                                                                                              \
    do {                                                                                                               \
        rb_status mu_json_try_status_ = (call);                                                                        \
        if (mu_json_try_status_ != RB_OK) {                                                                            \
            return mu_json_try_status_;                                                                                \
        }                                                                                                              \
    } while (0)

/* Where an error points: the value at the current path, or the key that
 * names it (an unknown key). */
typedef enum mu_json_place {
    MU_JSON_AT_VALUE,
    MU_JSON_AT_KEY,
} mu_json_place;

void mu_json_push_key(mu_json_reader *reader, const char *key);
void mu_json_push_index(mu_json_reader *reader, size_t index);
void mu_json_pop(mu_json_reader *reader);

/* Reports "FILE:LINE:COLUMN: PATH: <format...>" for the current path and
 * returns RB_ERR_INVALID_ARGUMENT. */
rb_status mu_json_fail(const mu_json_reader *reader, mu_json_place place, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Fails unless `value` (at the current path) is an object whose keys are
 * all in the NULL-terminated `allowed`. Every object may also carry a
 * "comment" string, which the reader ignores. */
rb_status mu_json_check_object(mu_json_reader *reader, const json_t *value, const char *const *allowed);

/* Whether the member is required; an optional member that is absent
 * leaves the output as it was (the caller's default). */
typedef enum mu_json_need {
    MU_JSON_OPTIONAL,
    MU_JSON_REQUIRED,
} mu_json_need;

/* Closed or open bounds of a number, both finite: every number a model
 * file gives is bounded (model_schema.c says why). */
typedef struct mu_json_bounds {
    double lower, upper;
    bool lower_open, upper_open; /* > instead of >=, < instead of <= */
} mu_json_bounds;

/* Each reader takes the member `key` of `object` (already checked with
 * mu_json_check_object) and fails when it is required and absent, of the
 * wrong type or out of bounds. `what` describes the value for the
 * message ("a length in m"). */
rb_status mu_json_read_number(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                              mu_json_bounds bounds, const char *what, double *out);
rb_status mu_json_read_int(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need, int lower,
                           int upper, const char *what, int *out);
rb_status mu_json_read_bool(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                            const char *what, bool *out);
/* [x, y], each coordinate within `bounds`. */
rb_status mu_json_read_vec2(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                            mu_json_bounds bounds, const char *what, rb_vec2 *out);
/* A non-empty string; *out borrows jansson's copy (valid while the document lives). */
rb_status mu_json_read_string(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                              const char *what, const char **out);
/* An array of min_count .. max_count elements; *out is NULL when an
 * optional array is absent. */
rb_status mu_json_read_array(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                             size_t min_count, size_t max_count, const char *what, const json_t **out);
/* A number within `bounds`: the value at the current path. */
rb_status mu_json_expect_number(const mu_json_reader *reader, const json_t *value, mu_json_bounds bounds,
                                const char *what, double *out);
/* A non-empty string: the value at the current path. */
rb_status mu_json_expect_string(const mu_json_reader *reader, const json_t *value, const char *what, const char **out);

#endif
