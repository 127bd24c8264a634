/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* locale_t in c_locale.h */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "c_locale.h"
#include "model_json.h"

void mu_json_push_key(mu_json_reader *reader, const char *key)
{
    if (reader->depth < MU_JSON_MAX_DEPTH) {
        reader->path[reader->depth] = (mu_json_step){.key = key};
    }
    ++reader->depth;
}

void mu_json_push_index(mu_json_reader *reader, size_t index)
{
    if (reader->depth < MU_JSON_MAX_DEPTH) {
        reader->path[reader->depth] = (mu_json_step){.key = NULL, .index = index};
    }
    ++reader->depth;
}

void mu_json_pop(mu_json_reader *reader) { --reader->depth; }

/* "muscles[2].path[0].body", or "(top level)" for the root. */
static void format_path(const mu_json_reader *reader, int depth, char *buffer, size_t size)
{
    size_t used = 0;
    buffer[0] = '\0';
    for (int i = 0; i < depth && used < size; ++i) {
        const mu_json_step *step = &reader->path[i];
        int written = step->key != NULL ? snprintf(buffer + used, size - used, "%s%s", i > 0 ? "." : "", step->key)
                                        : snprintf(buffer + used, size - used, "[%zu]", step->index);
        if (written < 0) {
            break;
        }
        used += (size_t)written;
    }
    if (depth == 0) {
        snprintf(buffer, size, "(top level)");
    }
}

rb_status mu_json_fail(const mu_json_reader *reader, mu_json_place place, const char *format, ...)
{
    char problem[384];
    /* Numbers in messages with a '.', as in the file (c_locale.h). */
    mu_c_locale_scope scope = mu_c_locale_begin();
    va_list args;
    va_start(args, format);
    vsnprintf(problem, sizeof problem, format, args);
    va_end(args);
    mu_c_locale_end(scope);

    /* A path deeper than the reader keeps is reported at its deepest kept step. */
    int depth = reader->depth < MU_JSON_MAX_DEPTH ? reader->depth : MU_JSON_MAX_DEPTH;
    char path[192];
    format_path(reader, depth, path, sizeof path);
    mu_json_position position;
    if (mu_json_locate(reader->text, reader->length, reader->path, depth, place == MU_JSON_AT_KEY, &position)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s:%d:%d: %s: %s", reader->file, position.line,
                               position.column, path, problem);
    }
    return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: %s", reader->file, path, problem);
}

static const char *type_name(const json_t *value)
{
    switch (json_typeof(value)) {
    case JSON_OBJECT:
        return "an object";
    case JSON_ARRAY:
        return "an array";
    case JSON_STRING:
        return "a string";
    case JSON_INTEGER:
    case JSON_REAL:
        return "a number";
    case JSON_TRUE:
        return "true";
    case JSON_FALSE:
        return "false";
    case JSON_NULL:
        return "null";
    }
    return "a value";
}

static bool within(double value, mu_json_bounds bounds)
{
    bool above = bounds.lower_open ? value > bounds.lower : value >= bounds.lower;
    bool below = bounds.upper_open ? value < bounds.upper : value <= bounds.upper;
    return above && below;
}

/* " (in [0.5, 1.5])", " (in (0, 100])". */
static void format_bounds(mu_json_bounds bounds, char *buffer, size_t size)
{
    mu_c_locale_scope scope = mu_c_locale_begin(); /* "0.5", as the file spells it */
    snprintf(buffer, size, " (in %c%g, %g%c)", bounds.lower_open ? '(' : '[', bounds.lower, bounds.upper,
             bounds.upper_open ? ')' : ']');
    mu_c_locale_end(scope);
}

rb_status mu_json_check_object(mu_json_reader *reader, const json_t *value, const char *const *allowed)
{
    char keys[256] = "";
    size_t used = 0;
    for (int i = 0; allowed[i] != NULL && used < sizeof keys; ++i) {
        int written = snprintf(keys + used, sizeof keys - used, "%s%s", i > 0 ? ", " : "", allowed[i]);
        used += written > 0 ? (size_t)written : 0;
    }
    if (!json_is_object(value)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected an object with the keys %s", type_name(value),
                            keys);
    }
    const char *key;
    const json_t *member;
    json_object_foreach((json_t *)value, key, member)
    {
        if (strcmp(key, "comment") == 0) {
            mu_json_push_key(reader, key);
            const char *ignored;
            MU_JSON_TRY(mu_json_expect_string(reader, member, "a comment", &ignored));
            mu_json_pop(reader);
            continue;
        }
        bool known = false;
        for (int i = 0; allowed[i] != NULL && !known; ++i) {
            known = strcmp(key, allowed[i]) == 0;
        }
        if (!known) {
            mu_json_push_key(reader, key);
            return mu_json_fail(reader, MU_JSON_AT_KEY, "unknown key \"%s\", expected one of %s (or comment)", key,
                                keys);
        }
    }
    return RB_OK;
}

/* The member `key`: RB_OK with *out NULL when it is optional and absent. */
static rb_status member(const mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                        const char *what, const json_t **out)
{
    *out = json_object_get(object, key);
    if (*out == NULL && need == MU_JSON_REQUIRED) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "missing key \"%s\", expected %s", key, what);
    }
    return RB_OK;
}

rb_status mu_json_expect_number(const mu_json_reader *reader, const json_t *value, mu_json_bounds bounds,
                                const char *what, double *out)
{
    char range[64];
    format_bounds(bounds, range, sizeof range);
    if (!json_is_number(value)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected %s%s", type_name(value), what, range);
    }
    double number = json_number_value(value);
    if (!within(number, bounds)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "%g is out of range, expected %s%s", number, what, range);
    }
    *out = number;
    return RB_OK;
}

rb_status mu_json_expect_string(const mu_json_reader *reader, const json_t *value, const char *what, const char **out)
{
    if (!json_is_string(value)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected %s (a string)", type_name(value), what);
    }
    if (json_string_length(value) == 0) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found an empty string, expected %s", what);
    }
    *out = json_string_value(value);
    return RB_OK;
}

rb_status mu_json_read_number(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                              mu_json_bounds bounds, const char *what, double *out)
{
    const json_t *value;
    MU_JSON_TRY(member(reader, object, key, need, what, &value));
    if (value == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    MU_JSON_TRY(mu_json_expect_number(reader, value, bounds, what, out));
    mu_json_pop(reader);
    return RB_OK;
}

rb_status mu_json_read_int(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need, int lower,
                           int upper, const char *what, int *out)
{
    const json_t *value;
    MU_JSON_TRY(member(reader, object, key, need, what, &value));
    if (value == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    if (!json_is_integer(value)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected %s (an integer in [%d, %d])",
                            json_is_real(value) ? "a real number" : type_name(value), what, lower, upper);
    }
    json_int_t number = json_integer_value(value);
    if (number < lower || number > upper) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE,
                            "%" JSON_INTEGER_FORMAT " is out of range, expected %s (in [%d, %d])", number, what, lower,
                            upper);
    }
    *out = (int)number;
    mu_json_pop(reader);
    return RB_OK;
}

rb_status mu_json_read_bool(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                            const char *what, bool *out)
{
    const json_t *value;
    MU_JSON_TRY(member(reader, object, key, need, what, &value));
    if (value == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    if (!json_is_boolean(value)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected %s (true or false)", type_name(value), what);
    }
    *out = json_is_true(value);
    mu_json_pop(reader);
    return RB_OK;
}

rb_status mu_json_read_vec2(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                            mu_json_bounds bounds, const char *what, rb_vec2 *out)
{
    const json_t *value;
    MU_JSON_TRY(member(reader, object, key, need, what, &value));
    if (value == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    if (!json_is_array(value) || json_array_size(value) != 2) {
        char found[32];
        snprintf(found, sizeof found, "an array of %zu numbers", json_array_size(value));
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected %s: [x, y]",
                            json_is_array(value) ? found : type_name(value), what);
    }
    double coordinates[2];
    for (size_t i = 0; i < 2; ++i) {
        mu_json_push_index(reader, i);
        MU_JSON_TRY(mu_json_expect_number(reader, json_array_get(value, i), bounds, what, &coordinates[i]));
        mu_json_pop(reader);
    }
    *out = rb_v2(coordinates[0], coordinates[1]);
    mu_json_pop(reader);
    return RB_OK;
}

rb_status mu_json_read_string(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                              const char *what, const char **out)
{
    const json_t *value;
    MU_JSON_TRY(member(reader, object, key, need, what, &value));
    if (value == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    MU_JSON_TRY(mu_json_expect_string(reader, value, what, out));
    mu_json_pop(reader);
    return RB_OK;
}

rb_status mu_json_read_array(mu_json_reader *reader, const json_t *object, const char *key, mu_json_need need,
                             size_t min_count, size_t max_count, const char *what, const json_t **out)
{
    const json_t *value;
    MU_JSON_TRY(member(reader, object, key, need, what, &value));
    *out = NULL;
    if (value == NULL) {
        return RB_OK;
    }
    mu_json_push_key(reader, key);
    if (!json_is_array(value)) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %s, expected an array of %s", type_name(value), what);
    }
    size_t count = json_array_size(value);
    if (count < min_count || count > max_count) {
        return mu_json_fail(reader, MU_JSON_AT_VALUE, "found %zu element%s, expected %zu to %zu %s", count,
                            count == 1 ? "" : "s", min_count, max_count, what);
    }
    *out = value;
    mu_json_pop(reader);
    return RB_OK;
}
