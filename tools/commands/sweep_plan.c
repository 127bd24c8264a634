/* SPDX-License-Identifier: MIT */
#define _DEFAULT_SOURCE /* realpath, PATH_MAX, strdup */
/* A sweep file read with jansson, checked against its model and expanded
 * into runs (sweep_plan.h). */
#include <errno.h>
#include <jansson.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "cli/model_source.h"
#include "controls.h"
#include "mu/motor_pool.h"
#include "muscle_parameter.h"
#include "number_text.h"
#include "rb/world.h"
#include "sweep_plan.h"

/* ------------------------------------------------------------ parameters */

/* What a parameter's values are. */
typedef enum value_kind {
    VALUE_INT,     /* an integer in [min, max] */
    VALUE_NUMBER,  /* a number in [min, max], (min, max] when min_open */
    VALUE_VARIANT, /* a variant's name or index */
    VALUE_WEIGHT,  /* one of the model's weight choices, kg */
    VALUE_SOLVER,  /* a solver's name */
    VALUE_FILE,    /* a control file, beside the sweep file */
} value_kind;

/* A parameter a sweep may set or vary: `key` exactly, or, for a prefix
 * ("activation."), the prefix followed by a name of the model. */
typedef struct parameter_kind {
    const char *key;
    bool prefix;
    const char *option; /* of `sinew run` */
    value_kind kind;
    double min, max;
    bool min_open;
} parameter_kind;

static const parameter_kind parameter_kinds[] = {
    {"variant", false, "--variant", VALUE_VARIANT, 0, 0, false},
    {"weight", false, "--weight", VALUE_WEIGHT, 0, 0, false},
    {"weight_index", false, "--weight-index", VALUE_INT, 0, MU_MODEL_MAX_OBJECTS - 1, false},
    {"level", false, "--level", VALUE_INT, 0, 4, false},
    {"duration", false, "--duration", VALUE_NUMBER, 0, 1e6, true},
    {"substeps", false, "--substeps", VALUE_INT, 1, 1000, false},
    {"solver", false, "--solver", VALUE_SOLVER, 0, 0, false},
    {"velocity_iterations", false, "--velocity-iterations", VALUE_INT, 1, 1000, false},
    {"position_iterations", false, "--position-iterations", VALUE_INT, 0, 1000, false},
    {"control", false, "--control", VALUE_FILE, 0, 0, false},
    {"activation.", true, "--activation", VALUE_NUMBER, 0, 1, false},
    {"tension.", true, "--tension", VALUE_NUMBER, 0, CONTROL_MAX_TENSION, false},
    {"recruit.", true, "--recruit", VALUE_INT, 0, MU_MAX_MOTOR_NEURONS, false},
    {"muscle.", true, "--muscle", VALUE_NUMBER, 0, 0, false}, /* the range is the muscle parameter's */
};
enum { PARAMETER_KIND_COUNT = sizeof parameter_kinds / sizeof parameter_kinds[0] };

#define PARAMETER_NAMES                                                                                                \
    "variant, weight, weight_index, level, duration, substeps, solver, velocity_iterations, position_iterations, "     \
    "control, activation.NAME, tension.NAME, recruit.NAME or muscle.NAME.PARAMETER"

/* One parameter of the file, with the text of each of its values. */
typedef struct parameter {
    const char *key; /* as the file spells it (jansson's) */
    const parameter_kind *kind;
    const muscle_parameter *muscle; /* for muscle.NAME.PARAMETER */
    char path[512];                 /* its JSON path: $.grid.weight */
    int axis;                       /* -1 in "set"; else the axis of the grid it moves along */
    int value_count;
    char **texts;      /* as `sinew run` gets them */
    char **name_texts; /* as the run's name shows them */
    char **values;     /* as the table shows them: the value alone */
} parameter;

/* What reading a file needs at hand. */
typedef struct reader {
    const char *file;
    char dir[PATH_MAX]; /* the sweep file's folder, "." for none */
    mu_model_desc *desc;
    char *error;
    size_t error_size;
    parameter *parameters;
    int parameter_count;
} reader;

static bool fail(reader *r, const char *path, const char *format, ...) __attribute__((format(printf, 3, 4)));

/* "FILE: PATH: message"; always false. */
static bool fail(reader *r, const char *path, const char *format, ...)
{
    int used = snprintf(r->error, r->error_size, "%s: %s: ", r->file, path);
    if (used >= 0 && (size_t)used < r->error_size) {
        va_list args;
        va_start(args, format);
        vsnprintf(r->error + used, r->error_size - (size_t)used, format, args);
        va_end(args);
    }
    return false;
}

/* PARENT.KEY, or PARENT["KEY"] for a key that is not a plain word. */
static void child_path(char *path, size_t size, const char *parent, const char *key)
{
    bool plain =
        key[0] != '\0' && strspn(key, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == strlen(key);
    snprintf(path, size, plain ? "%s.%s" : "%s[\"%s\"]", parent, key);
}

/* A copy of `text` with every character but letters, digits and . + - =
 * made '_', for a file name. */
static char *name_safe(const char *text)
{
    char *copy = strdup(text);
    for (char *c = copy; c != NULL && *c != '\0'; ++c) {
        if (strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.+-=", *c) == NULL) {
            *c = '_';
        }
    }
    return copy;
}

/* Whether `text` holds a control character (a line break would split a
 * run's line of the job list). */
static bool has_control_character(const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c != '\0'; ++c) {
        if (*c < 0x20 || *c == 0x7f) {
            return true;
        }
    }
    return false;
}

/* The kind of the parameter `key`, and checks the name after a prefix
 * against the model. */
static bool find_kind(reader *r, parameter *p)
{
    const char *key = p->key;
    if (has_control_character(key)) {
        return fail(r, p->path, "a parameter's name holds a control character");
    }
    for (int k = 0; k < PARAMETER_KIND_COUNT; ++k) {
        const parameter_kind *kind = &parameter_kinds[k];
        size_t length = strlen(kind->key);
        if (kind->prefix ? strncmp(key, kind->key, length) != 0 : strcmp(key, kind->key) != 0) {
            continue;
        }
        p->kind = kind;
        if (!kind->prefix) {
            return true;
        }
        const char *name = key + length;
        mu_model_ref ref;
        if (kind->kind == VALUE_INT) { /* recruit.NAME */
            if (!mu_model_desc_find(r->desc, name, &ref) || ref.kind != MU_MODEL_TORQUE_MUSCLE) {
                return fail(r, p->path, "the model %s has no torque muscle \"%s\"", r->desc->name, name);
            }
            return true;
        }
        if (strcmp(kind->key, "muscle.") != 0) { /* activation.NAME, tension.NAME */
            if (!mu_model_desc_find(r->desc, name, &ref) ||
                (ref.kind != MU_MODEL_MUSCLE && ref.kind != MU_MODEL_GROUP)) {
                return fail(r, p->path, "the model %s has no muscle or group \"%s\"", r->desc->name, name);
            }
            return true;
        }
        const char *dot = strrchr(name, '.');
        if (dot == NULL || dot == name) {
            return fail(r, p->path, "expected muscle.NAME.PARAMETER, got \"%s\"", key);
        }
        char muscle[1024];
        snprintf(muscle, sizeof muscle, "%.*s", (int)(dot - name), name);
        if (!mu_model_desc_find(r->desc, muscle, &ref) || ref.kind != MU_MODEL_MUSCLE) {
            return fail(r, p->path, "the model %s has no muscle \"%s\"", r->desc->name, muscle);
        }
        p->muscle = muscle_parameter_find(dot + 1, strlen(dot + 1));
        if (p->muscle == NULL) {
            return fail(r, p->path, "unknown muscle parameter \"%s\" (" MUSCLE_PARAMETER_NAMES ")", dot + 1);
        }
        return true;
    }
    return fail(r, p->path, "unknown parameter \"%s\" (" PARAMETER_NAMES ")", key);
}

/* "NAME=VALUE", allocated. */
static char *name_equals(const char *name, const char *value)
{
    size_t length = strlen(name) + strlen(value) + 2;
    char *text = malloc(length);
    if (text != NULL) {
        snprintf(text, length, "%s=%s", name, value);
    }
    return text;
}

/* Checks one value of `p` at `path` and keeps its texts in the next slot. */
static bool add_value(reader *r, parameter *p, const json_t *value, const char *path)
{
    const parameter_kind *kind = p->kind;
    char text[PATH_MAX];
    char name_text[PATH_MAX];
    double min = p->muscle != NULL ? p->muscle->min : kind->min;
    double max = p->muscle != NULL ? p->muscle->max : kind->max;
    switch (kind->kind) {
    case VALUE_INT:
        if (!json_is_integer(value) || json_integer_value(value) < (json_int_t)min ||
            json_integer_value(value) > (json_int_t)max) {
            return fail(r, path, "expected an integer in %.0f .. %.0f", min, max);
        }
        snprintf(text, sizeof text, "%lld", (long long)json_integer_value(value));
        break;
    case VALUE_NUMBER: {
        double number = json_number_value(value);
        if (!json_is_number(value) || !(p->kind->min_open ? number > min : number >= min) || number > max) {
            return fail(r, path, "expected a number in %s%g .. %g%s", kind->min_open ? "(" : "", min, max,
                        p->muscle != NULL ? " (the muscle parameter's range)" : "");
        }
        number_text(number, text);
        break;
    }
    case VALUE_WEIGHT: {
        double kilograms = json_number_value(value);
        if (!r->desc->has_weight) {
            return fail(r, path, "the model %s has no weight", r->desc->name);
        }
        bool found = false;
        for (int w = 0; w < r->desc->weight.mass_count; ++w) {
            found = found || (json_is_number(value) && r->desc->weight.masses[w] == kilograms);
        }
        if (!found) {
            char choices[512] = "";
            for (int w = 0; w < r->desc->weight.mass_count && strlen(choices) + 32 < sizeof choices; ++w) {
                snprintf(choices + strlen(choices), sizeof choices - strlen(choices), "%s%g", w > 0 ? ", " : "",
                         r->desc->weight.masses[w]);
            }
            return fail(r, path, "expected one of the model's weights in kg (%s)", choices);
        }
        number_text(kilograms, text);
        break;
    }
    case VALUE_VARIANT:
        if (json_is_string(value) && mu_model_desc_find_variant(r->desc, json_string_value(value)) >= 0) {
            snprintf(text, sizeof text, "%s", json_string_value(value));
        } else if (json_is_integer(value) && json_integer_value(value) >= 0 &&
                   json_integer_value(value) < r->desc->variant_count) {
            snprintf(text, sizeof text, "%lld", (long long)json_integer_value(value));
        } else {
            return fail(r, path, "expected a variant of the model %s: a name or an index 0 .. %d", r->desc->name,
                        r->desc->variant_count - 1);
        }
        break;
    case VALUE_SOLVER: {
        rb_solver_type type;
        if (!json_is_string(value) || rb_solver_type_from_name(json_string_value(value), &type) != RB_OK) {
            return fail(r, path, "expected a solver: baumgarte, ngs or soft_step");
        }
        snprintf(text, sizeof text, "%s", json_string_value(value));
        break;
    }
    case VALUE_FILE: {
        if (!json_is_string(value) || json_string_length(value) == 0) {
            return fail(r, path, "expected the path of a control file");
        }
        const char *given = json_string_value(value);
        char joined[2 * PATH_MAX];
        snprintf(joined, sizeof joined, "%s%s%s", given[0] == '/' ? "" : r->dir, given[0] == '/' ? "" : "/", given);
        /* Absolute, so that a run finds it from the output folder. */
        if (realpath(joined, text) == NULL) {
            return fail(r, path, "control file %s: %s", joined, strerror(errno));
        }
        break;
    }
    }
    if (has_control_character(text)) {
        return fail(r, path, "the value holds a control character");
    }
    /* A control file is named by its file name alone. */
    const char *slash = kind->kind == VALUE_FILE ? strrchr(text, '/') : NULL;
    snprintf(name_text, sizeof name_text, "%s", slash != NULL ? slash + 1 : text);
    /* NAME=VALUE, NAME.PARAMETER=VALUE: the option's value. */
    p->texts[p->value_count] = kind->prefix ? name_equals(p->key + strlen(kind->key), text) : strdup(text);
    p->name_texts[p->value_count] = name_safe(name_text);
    p->values[p->value_count] = strdup(text);
    if (p->texts[p->value_count] == NULL || p->name_texts[p->value_count] == NULL ||
        p->values[p->value_count] == NULL) {
        return fail(r, path, "out of memory");
    }
    p->value_count++;
    return true;
}

/* ---------------------------------------------------------- value lists */

/* How many values `spec` gives: 1 for "set", a list's length or a
 * range's count; 0 after an error. */
static long range_count(reader *r, const parameter *p, const json_t *spec)
{
    if (p->axis < 0) {
        return 1;
    }
    if (json_is_array(spec)) {
        if (json_array_size(spec) == 0) {
            fail(r, p->path, "an empty list: give at least one value");
            return 0;
        }
        return (long)json_array_size(spec);
    }
    if (!json_is_object(spec)) {
        fail(r, p->path, "expected a list of values or a range {\"start\", \"stop\", \"step\" or \"count\"}");
        return 0;
    }
    const json_t *start = json_object_get(spec, "start");
    const json_t *stop = json_object_get(spec, "stop");
    const json_t *step = json_object_get(spec, "step");
    const json_t *count = json_object_get(spec, "count");
    const char *key;
    const json_t *member;
    json_object_foreach((json_t *)spec, key, member)
    {
        if (strcmp(key, "start") != 0 && strcmp(key, "stop") != 0 && strcmp(key, "step") != 0 &&
            strcmp(key, "count") != 0) {
            char path[600];
            child_path(path, sizeof path, p->path, key);
            fail(r, path, "unknown key of a range (start, stop, step or count)");
            return 0;
        }
    }
    if (p->kind->kind != VALUE_INT && p->kind->kind != VALUE_NUMBER && p->kind->kind != VALUE_WEIGHT) {
        fail(r, p->path, "a range of %s: give a list of its values", p->key);
        return 0;
    }
    if (!json_is_number(start) || !json_is_number(stop) || (step == NULL) == (count == NULL)) {
        fail(r, p->path, "a range needs a number \"start\", a number \"stop\", and \"step\" or \"count\"");
        return 0;
    }
    double span = json_number_value(stop) - json_number_value(start);
    if (count != NULL) {
        if (!json_is_integer(count) || json_integer_value(count) < 1 || json_integer_value(count) > SWEEP_MAX_RUNS) {
            fail(r, p->path, "\"count\": expected an integer in 1 .. %d", SWEEP_MAX_RUNS);
            return 0;
        }
        if (json_integer_value(count) == 1 && span != 0.0) {
            fail(r, p->path, "\"count\" 1 with \"stop\" other than \"start\": give \"count\" >= 2");
            return 0;
        }
        return (long)json_integer_value(count);
    }
    double increment = json_number_value(step);
    if (!json_is_number(step) || !(increment != 0.0) || !isfinite(increment)) {
        fail(r, p->path, "\"step\": expected a number other than 0");
        return 0;
    }
    /* The values start + k·step up to stop, stop itself included when the
     * step divides the span to within rounding (0.1 steps to 1). */
    double steps = span / increment;
    if (steps < -1e-9) {
        fail(r, p->path, "an empty range: \"step\" goes away from \"stop\"");
        return 0;
    }
    if (steps > SWEEP_MAX_RUNS) {
        fail(r, p->path, "a range of more than %d values", SWEEP_MAX_RUNS);
        return 0;
    }
    return (long)floor(steps + 1e-9) + 1;
}

/* Value `k` of a range, as jansson would have read it from the file. */
static json_t *range_value(const parameter *p, const json_t *spec, long k, long count)
{
    double start = json_number_value(json_object_get(spec, "start"));
    double stop = json_number_value(json_object_get(spec, "stop"));
    const json_t *step = json_object_get(spec, "step");
    double value = step != NULL ? start + (double)k * json_number_value(step)
                   : count == 1 ? start
                                : start + (stop - start) * (double)k / (double)(count - 1);
    if (step == NULL && k == count - 1) {
        value = stop; /* exactly, whatever the rounding */
    }
    if (p->kind->kind == VALUE_INT && value == nearbyint(value) && fabs(value) < 9e15) {
        return json_integer((json_int_t)value);
    }
    return json_real(value);
}

/* Reads parameter `key` with its value or values `spec` into the reader's
 * next parameter. */
static bool read_parameter(reader *r, const char *section, const char *key, const json_t *spec, int axis)
{
    for (int k = 0; k < r->parameter_count; ++k) {
        if (strcmp(r->parameters[k].key, key) == 0) {
            char path[600];
            child_path(path, sizeof path, section, key);
            return fail(r, path, "also given at %s", r->parameters[k].path);
        }
    }
    parameter *p = &r->parameters[r->parameter_count++];
    *p = (parameter){.key = key, .axis = axis};
    child_path(p->path, sizeof p->path, section, key);
    if (!find_kind(r, p)) {
        return false;
    }
    long count = range_count(r, p, spec);
    if (count == 0) {
        return false;
    }
    p->texts = calloc((size_t)count, sizeof *p->texts);
    p->name_texts = calloc((size_t)count, sizeof *p->name_texts);
    p->values = calloc((size_t)count, sizeof *p->values);
    if (p->texts == NULL || p->name_texts == NULL || p->values == NULL) {
        return fail(r, p->path, "out of memory");
    }
    for (long k = 0; k < count; ++k) {
        char path[640];
        bool ok;
        if (axis < 0) {
            ok = add_value(r, p, spec, p->path);
        } else if (json_is_array(spec)) {
            snprintf(path, sizeof path, "%s[%ld]", p->path, k);
            ok = add_value(r, p, json_array_get(spec, (size_t)k), path);
        } else {
            json_t *value = range_value(p, spec, k, count);
            snprintf(path, sizeof path, "%s (value %ld of the range, %g)", p->path, k, json_number_value(value));
            ok = value != NULL && add_value(r, p, value, path);
            json_decref(value);
        }
        if (!ok) {
            return false;
        }
    }
    return true;
}

static void free_parameters(reader *r)
{
    for (int k = 0; k < r->parameter_count; ++k) {
        for (int v = 0; v < r->parameters[k].value_count; ++v) {
            free(r->parameters[k].texts[v]);
            free(r->parameters[k].name_texts[v]);
            free(r->parameters[k].values[v]);
        }
        free(r->parameters[k].texts);
        free(r->parameters[k].name_texts);
        free(r->parameters[k].values);
    }
    free(r->parameters);
}

/* ------------------------------------------------------------- the file */

static bool check_keys(reader *r, const json_t *root)
{
    static const char *const keys[] = {"model", "out", "set", "grid", "zip", "figure"};
    const char *key;
    const json_t *value;
    json_object_foreach((json_t *)root, key, value)
    {
        bool known = false;
        for (size_t k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
            known = known || strcmp(key, keys[k]) == 0;
        }
        char path[600];
        child_path(path, sizeof path, "$", key);
        if (!known) {
            return fail(r, path, "unknown key (model, out, set, grid, zip or figure)");
        }
        if (strcmp(key, "model") != 0 && strcmp(key, "out") != 0 && !json_is_object(value)) {
            return fail(r, path, "expected an object");
        }
    }
    return true;
}

/* The model: a built-in name, or a file beside the sweep file, made
 * absolute so that runs find it from the output folder. */
static bool read_model(reader *r, const json_t *root, char *model, size_t model_size)
{
    const json_t *value = json_object_get(root, "model");
    if (!json_is_string(value) || json_string_length(value) == 0) {
        return fail(r, "$.model", "expected the model: a built-in name (see `sinew models`) or a model file");
    }
    const char *given = json_string_value(value);
    snprintf(model, model_size, "%s", given);
    if (!model_source_is_builtin(given) && given[0] != '/' &&
        (strchr(given, '/') != NULL || (strlen(given) > 5 && strcmp(given + strlen(given) - 5, ".json") == 0))) {
        char joined[2 * PATH_MAX];
        snprintf(joined, sizeof joined, "%s/%s", r->dir, given);
        if (realpath(joined, model) == NULL) {
            return fail(r, "$.model", "model file %s: %s", joined, strerror(errno));
        }
    }
    char message[MODEL_SOURCE_ERROR_SIZE];
    if (model_source_open(model, &r->desc, message, sizeof message) != MODEL_SOURCE_LOADED) {
        return fail(r, "$.model", "%s", message);
    }
    return true;
}

/* The parameters of "set", "grid" and "zip", the grid's axes' lengths. */
static bool read_parameters(reader *r, const json_t *root, long *axis_length, int *axis_count)
{
    size_t total = 0;
    static const char *const sections[] = {"set", "grid", "zip"};
    for (int s = 0; s < 3; ++s) {
        total += json_object_size(json_object_get(root, sections[s]));
    }
    r->parameters = calloc(total + 1, sizeof *r->parameters);
    if (r->parameters == NULL) {
        return fail(r, "$", "out of memory");
    }
    *axis_count = 0;
    const char *key;
    const json_t *spec;
    json_object_foreach(json_object_get(root, "set"), key, spec)
    {
        if (!read_parameter(r, "$.set", key, spec, -1)) {
            return false;
        }
    }
    json_object_foreach(json_object_get(root, "grid"), key, spec)
    {
        if (!read_parameter(r, "$.grid", key, spec, *axis_count)) {
            return false;
        }
        axis_length[(*axis_count)++] = r->parameters[r->parameter_count - 1].value_count;
    }
    const json_t *zip = json_object_get(root, "zip");
    json_object_foreach((json_t *)zip, key, spec)
    {
        if (!read_parameter(r, "$.zip", key, spec, *axis_count)) {
            return false;
        }
        const parameter *p = &r->parameters[r->parameter_count - 1];
        const parameter *first = &r->parameters[r->parameter_count - 1];
        while (first > r->parameters && first[-1].axis == *axis_count) {
            --first;
        }
        if (p->value_count != first->value_count) {
            return fail(r, p->path, "%d values, but %s has %d: zipped lists go side by side", p->value_count,
                        first->path, first->value_count);
        }
    }
    if (json_object_size(zip) > 0) {
        for (int k = 0; k < r->parameter_count; ++k) {
            if (r->parameters[k].axis == *axis_count) {
                axis_length[(*axis_count)++] = r->parameters[k].value_count;
                break;
            }
        }
    }
    if (*axis_count == 0) {
        return fail(r, "$.grid", "no parameter varies: give \"grid\" or \"zip\" at least one list or range");
    }
    bool weight = false, weight_index = false;
    for (int k = 0; k < r->parameter_count; ++k) {
        weight = weight || strcmp(r->parameters[k].key, "weight") == 0;
        weight_index = weight_index || strcmp(r->parameters[k].key, "weight_index") == 0;
    }
    if (weight && weight_index) {
        return fail(r, "$", "give weight or weight_index, not both");
    }
    return true;
}

static char *joined(const char *a, const char *b)
{
    size_t length = strlen(a) + strlen(b) + 1;
    char *text = malloc(length);
    if (text != NULL) {
        snprintf(text, length, "%s%s", a, b);
    }
    return text;
}

/* Run `index`'s name, values and arguments. */
static bool expand_run(reader *r, sweep_plan *plan, const char *model, const long *axis_length, int axis_count,
                       long index, sweep_run *run)
{
    long value_of_axis[64];
    for (int a = axis_count - 1; a >= 0; --a) {
        value_of_axis[a] = index % axis_length[a];
        index /= axis_length[a];
    }
    char stem[MODEL_STEM_SIZE];
    model_source_stem(model, stem, sizeof stem);
    char *safe_stem = name_safe(stem);
    char name[4 * SWEEP_NAME_MAX];
    snprintf(name, sizeof name, "%s", safe_stem != NULL ? safe_stem : "model");
    free(safe_stem);
    run->values = calloc((size_t)plan->varied_count + 1, sizeof *run->values);
    run->arguments = calloc((size_t)r->parameter_count * 2 + 6, sizeof *run->arguments);
    if (run->values == NULL || run->arguments == NULL) {
        return fail(r, "$", "out of memory");
    }
    run->arguments[run->argument_count++] = strdup(model);
    int varied = 0;
    for (int k = 0; k < r->parameter_count; ++k) {
        const parameter *p = &r->parameters[k];
        long v = p->axis < 0 ? 0 : value_of_axis[p->axis];
        run->arguments[run->argument_count++] = strdup(p->kind->option);
        run->arguments[run->argument_count++] = strdup(p->texts[v]);
        if (p->axis >= 0) {
            run->values[varied++] = strdup(p->values[v]);
            char *key = name_safe(p->key);
            size_t used = strlen(name);
            snprintf(name + used, sizeof name - used, "_%s=%s", key != NULL ? key : "", p->name_texts[v]);
            free(key);
        }
    }
    if (strlen(name) > SWEEP_NAME_MAX) {
        return fail(r, "$.grid", "the run name %.60s... is longer than %d bytes: vary fewer parameters at once", name,
                    SWEEP_NAME_MAX);
    }
    run->name = strdup(name);
    run->arguments[run->argument_count++] = strdup("--name");
    run->arguments[run->argument_count++] = strdup(name);
    run->arguments[run->argument_count++] = strdup("--summary");
    run->arguments[run->argument_count++] = joined(name, ".summary.json");
    for (int k = 0; k < run->argument_count; ++k) {
        if (run->arguments[k] == NULL) {
            return fail(r, "$", "out of memory");
        }
    }
    return run->name != NULL;
}

static int compare_names(const void *a, const void *b)
{
    return strcmp((*(const sweep_run *const *)a)->name, (*(const sweep_run *const *)b)->name);
}

/* Two runs of one name would write the same files: values that differ
 * only in characters the name replaces ("a b" and "a_b"). */
static bool check_names_unique(reader *r, const sweep_plan *plan)
{
    const sweep_run **sorted = malloc((size_t)plan->run_count * sizeof *sorted);
    if (sorted == NULL) {
        return fail(r, "$", "out of memory");
    }
    for (int k = 0; k < plan->run_count; ++k) {
        sorted[k] = &plan->runs[k];
    }
    qsort(sorted, (size_t)plan->run_count, sizeof *sorted, compare_names);
    for (int k = 1; k < plan->run_count; ++k) {
        if (strcmp(sorted[k - 1]->name, sorted[k]->name) == 0) {
            fail(r, "$.grid", "two runs would both be called %s: make the values differ in letters or digits",
                 sorted[k]->name);
            free(sorted);
            return false;
        }
    }
    free(sorted);
    return true;
}

/* How many different values varied parameter `index` takes, counted up
 * to CHART_MAX_SERIES + 1. */
static int distinct_values(const sweep_plan *plan, int index)
{
    const char *seen[CHART_MAX_SERIES + 1];
    int count = 0;
    for (int k = 0; k < plan->run_count && count <= CHART_MAX_SERIES; ++k) {
        const char *value = plan->runs[k].values[index];
        bool known = false;
        for (int s = 0; s < count && !known; ++s) {
            known = strcmp(seen[s], value) == 0;
        }
        if (!known) {
            seen[count++] = value;
        }
    }
    return count;
}

static bool read_figure(reader *r, const json_t *root, sweep_plan *plan)
{
    const json_t *figure = json_object_get(root, "figure");
    if (figure == NULL) {
        return true;
    }
    const char *key;
    const json_t *value;
    json_object_foreach((json_t *)figure, key, value)
    {
        char path[600];
        child_path(path, sizeof path, "$.figure", key);
        if (strcmp(key, "x") != 0 && strcmp(key, "y") != 0 && strcmp(key, "group") != 0) {
            return fail(r, path, "unknown key (x, y or group)");
        }
        if (!json_is_string(value)) {
            return fail(r, path, "expected a column's name");
        }
        if (strcmp(key, "y") == 0) {
            continue; /* a column of the summary, checked when it is made */
        }
        int found = -1;
        for (int k = 0; k < plan->varied_count; ++k) {
            found = strcmp(plan->varied[k], json_string_value(value)) == 0 ? k : found;
        }
        if (found < 0) {
            return fail(r, path, "\"%s\" is not a parameter the sweep varies", json_string_value(value));
        }
        if (strcmp(key, "x") == 0 && !plan->varied_numeric[found]) {
            return fail(r, path, "\"%s\" is not a number: the x axis needs numbers (group by it instead)",
                        json_string_value(value));
        }
        if (strcmp(key, "group") == 0 && distinct_values(plan, found) > CHART_MAX_SERIES) {
            return fail(r, path, "\"%s\" has more than %d values: a figure draws at most %d series",
                        json_string_value(value), CHART_MAX_SERIES, CHART_MAX_SERIES);
        }
    }
    const char *y = json_string_value(json_object_get(figure, "y"));
    const char *x = json_string_value(json_object_get(figure, "x"));
    const char *group = json_string_value(json_object_get(figure, "group"));
    if (y == NULL || x == NULL) {
        return fail(r, "$.figure", "expected \"y\" (a column of the summary) and \"x\" (a parameter that varies)");
    }
    plan->figure_y = strdup(y);
    plan->figure_x = strdup(x);
    plan->figure_group = group != NULL ? strdup(group) : NULL;
    return true;
}

/* The output folder: `out_dir`, else "out" beside the sweep file, else
 * the sweep file's stem in the current folder. */
static bool read_out(reader *r, const json_t *root, const char *out_dir, sweep_plan *plan)
{
    const json_t *out = json_object_get(root, "out");
    if (out_dir != NULL) {
        plan->out_dir = strdup(out_dir);
        plan->out_source = "--out";
    } else if (out != NULL) {
        if (!json_is_string(out) || json_string_length(out) == 0) {
            return fail(r, "$.out", "expected the output folder's path");
        }
        const char *given = json_string_value(out);
        size_t length = strlen(r->dir) + strlen(given) + 2;
        plan->out_dir = malloc(length);
        if (plan->out_dir != NULL) {
            snprintf(plan->out_dir, length, "%s%s%s", given[0] == '/' ? "" : r->dir, given[0] == '/' ? "" : "/", given);
        }
        plan->out_source = "$.out";
    } else {
        char stem[MODEL_STEM_SIZE];
        model_source_stem(r->file, stem, sizeof stem);
        plan->out_dir = strdup(stem);
        plan->out_source = "the sweep file's stem";
    }
    return plan->out_dir != NULL || fail(r, "$.out", "out of memory");
}

static bool load(reader *r, const char *out_dir, bool allow_many, sweep_plan *plan)
{
    json_error_t json_error;
    json_t *root = json_load_file(r->file, JSON_REJECT_DUPLICATES, &json_error);
    if (root == NULL) {
        snprintf(r->error, r->error_size, "%s:%d:%d: %s", r->file, json_error.line, json_error.column, json_error.text);
        return false;
    }
    long axis_length[64];
    int axis_count = 0;
    char model[PATH_MAX];
    bool ok = json_is_object(root) || fail(r, "$", "expected an object");
    ok = ok && check_keys(r, root) && read_model(r, root, model, sizeof model) && read_out(r, root, out_dir, plan);
    if (ok && json_object_size(json_object_get(root, "grid")) + 1 > 63) {
        ok = fail(r, "$.grid", "more than 62 parameters vary");
    }
    ok = ok && read_parameters(r, root, axis_length, &axis_count);
    double runs = 1.0;
    for (int a = 0; ok && a < axis_count; ++a) {
        runs *= (double)axis_length[a];
    }
    if (ok && runs > SWEEP_MAX_RUNS) {
        ok = fail(r, "$.grid", "%.0f runs, more than the %d a sweep may have", runs, SWEEP_MAX_RUNS);
    }
    if (ok && runs > SWEEP_RUN_LIMIT && !allow_many) {
        ok = fail(r, "$.grid", "%.0f runs, more than %d: give --yes to run them all (docs/sweeps.md)", runs,
                  SWEEP_RUN_LIMIT);
    }
    if (ok) {
        plan->varied = calloc((size_t)r->parameter_count + 1, sizeof *plan->varied);
        plan->varied_numeric = calloc((size_t)r->parameter_count + 1, sizeof *plan->varied_numeric);
        plan->runs = calloc((size_t)runs, sizeof *plan->runs);
        ok = (plan->varied != NULL && plan->varied_numeric != NULL && plan->runs != NULL) ||
             fail(r, "$", "out of memory");
    }
    for (int k = 0; ok && k < r->parameter_count; ++k) {
        const parameter *p = &r->parameters[k];
        if (p->axis >= 0) {
            value_kind kind = p->kind->kind;
            plan->varied_numeric[plan->varied_count] =
                kind == VALUE_INT || kind == VALUE_NUMBER || kind == VALUE_WEIGHT;
            plan->varied[plan->varied_count++] = strdup(p->key);
        }
    }
    for (long k = 0; ok && k < (long)runs; ++k) {
        /* Counted even when it fails half-way, so that it is freed. */
        ok = expand_run(r, plan, model, axis_length, axis_count, k, &plan->runs[k]);
        plan->run_count++;
    }
    ok = ok && check_names_unique(r, plan) && read_figure(r, root, plan);
    json_decref(root);
    return ok;
}

bool sweep_plan_load(const char *path, const char *out_dir, bool allow_many, sweep_plan *plan, char *error,
                     size_t error_size)
{
    *plan = (sweep_plan){.file = strdup(path)};
    reader r = {.file = path, .error = error, .error_size = error_size};
    const char *slash = strrchr(path, '/');
    snprintf(r.dir, sizeof r.dir, "%.*s", slash != NULL ? (int)(slash - path) : 1, slash != NULL ? path : ".");
    if (slash == path) {
        snprintf(r.dir, sizeof r.dir, "/");
    }
    bool ok = plan->file != NULL && load(&r, out_dir, allow_many, plan);
    free_parameters(&r);
    mu_model_desc_destroy(r.desc);
    if (!ok) {
        sweep_plan_free(plan);
    }
    return ok;
}

void sweep_plan_free(sweep_plan *plan)
{
    for (int k = 0; k < plan->run_count; ++k) {
        sweep_run *run = &plan->runs[k];
        for (int a = 0; a < run->argument_count; ++a) {
            free(run->arguments[a]);
        }
        for (int v = 0; run->values != NULL && v < plan->varied_count; ++v) {
            free(run->values[v]);
        }
        free(run->arguments);
        free(run->values);
        free(run->name);
    }
    for (int k = 0; k < plan->varied_count; ++k) {
        free(plan->varied[k]);
    }
    free(plan->varied);
    free(plan->varied_numeric);
    free(plan->runs);
    free(plan->file);
    free(plan->out_dir);
    free(plan->figure_y);
    free(plan->figure_x);
    free(plan->figure_group);
    *plan = (sweep_plan){0};
}
