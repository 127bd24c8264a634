/* SPDX-License-Identifier: MIT */
/* The range of every number of a model file, against the table of
 * docs/model-format.md written out again here: each number of
 * tests/data/models/every_field.json (a model with every numeric key) set
 * just outside its range is refused naming its JSON path and the range,
 * and set to either end of its range the model either is refused by a
 * check across keys or runs with every value finite. That is the
 * property `sinew check` promises: what it accepts, `sinew run` can
 * simulate. */
#define _POSIX_C_SOURCE 200809L /* mkstemp */

#include <criterion/criterion.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/model.h"
#include "mu/model_desc.h"

#define EVERY_FIELD SINEW_SOURCE_DIR "/tests/data/models/every_field.json"
#define FRAMES 30

typedef struct field_range {
    const char *path; /* in every_field.json */
    double lower, upper;
    bool lower_open, integer;
    const char *range; /* as the message prints it */
} field_range;

static const field_range fields[] = {
    {"gravity[0]", -1e3, 1e3, false, false, "(in [-1000, 1000])"},
    {"gravity[1]", -1e3, 1e3, false, false, "(in [-1000, 1000])"},
    {"frame_rate", 1.0, 1e3, false, false, "(in [1, 1000])"},
    {"substeps", 1, 1000, false, true, "(in [1, 1000])"},
    {"placement[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"placement[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"damping", 0.0, 1e3, false, false, "(in [0, 1000])"},
    {"nails[0].position[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"nails[0].position[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"bones[0].centre[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"bones[0].centre[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"bones[0].size[0]", 1e-3, 100.0, false, false, "(in [0.001, 100])"},
    {"bones[0].size[1]", 1e-3, 100.0, false, false, "(in [0.001, 100])"},
    {"bones[0].angle", -360.0, 360.0, false, false, "(in [-360, 360])"},
    {"bones[0].depth", 1e-3, 100.0, false, false, "(in [0.001, 100])"},
    {"bones[0].density", 1.0, 1e5, false, false, "(in [1, 100000])"},
    {"bones[0].damping", 0.0, 1e3, false, false, "(in [0, 1000])"},
    {"bones[0].wall_thickness", 1e-5, 0.02, false, false, "(in [1e-05, 0.02])"},
    {"bones[0].youngs_modulus", 1e6, 1e12, false, false, "(in [1e+06, 1e+12])"},
    {"bones[0].tensile_strength", 1e5, 1e10, false, false, "(in [100000, 1e+10])"},
    {"bones[0].compressive_strength", 1e5, 1e10, false, false, "(in [100000, 1e+10])"},
    {"hinges[0].anchor_a[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"hinges[0].anchor_a[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"hinges[0].anchor_b[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"hinges[0].anchor_b[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"hinges[0].radius", 0.0, 100.0, true, false, "(in (0, 100])"},
    {"hinges[0].lower", -360.0, 360.0, false, false, "(in [-360, 360])"},
    {"hinges[0].upper", -360.0, 360.0, false, false, "(in [-360, 360])"},
    {"weight.position[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"weight.position[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"weight.masses[1]", 0.0, 1e6, false, false, "(in [0, 1e+06])"},
    {"muscles[0].rest_length", 1e-3, 10.0, false, false, "(in [0.001, 10])"},
    {"muscles[0].rest_width", 1e-4, 1.0, false, false, "(in [0.0001, 1])"},
    {"muscles[0].specific_tension", 1e3, 1e7, false, false, "(in [1000, 1e+07])"},
    {"muscles[0].max_velocity", 1e-3, 100.0, false, false, "(in [0.001, 100])"},
    {"muscles[0].start_normalized_length", 0.5, 1.5, false, false, "(in [0.5, 1.5])"},
    {"muscles[0].symmetry", 0.0, 1.0, false, false, "(in [0, 1])"},
    {"muscles[0].pennation_angle", 0.0, 80.0, false, false, "(in [0, 80])"},
    {"muscles[0].activation_dynamics.activation_time", 1e-4, 10.0, false, false, "(in [0.0001, 10])"},
    {"muscles[0].activation_dynamics.deactivation_time", 1e-4, 10.0, false, false, "(in [0.0001, 10])"},
    {"muscles[0].path[1].point[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[0].path[1].point[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[1].rest_length", 1e-3, 10.0, false, false, "(in [0.001, 10])"},
    {"muscles[1].max_force", 1e-3, 1e6, false, false, "(in [0.001, 1e+06])"},
    {"muscles[1].tendon_length", 0.0, 100.0, false, false, "(in [0, 100])"},
    {"muscles[1].max_velocity_rest_lengths", 0.1, 1e3, false, false, "(in [0.1, 1000])"},
    {"muscles[1].compliant_tendon.strain_at_max_force", 1e-3, 1.0, false, false, "(in [0.001, 1])"},
    {"muscles[1].compliant_tendon.fibre_damping", 1e-3, 10.0, false, false, "(in [0.001, 10])"},
    {"muscles[1].path[0].point[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[1].path[1].point[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[1].path[2].point[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[2].tendon_fraction", 0.0, 1.0, false, false, "(in [0, 1))"},
    {"muscles[2].max_force", 1e-3, 1e6, false, false, "(in [0.001, 1e+06])"},
    {"muscles[2].path[0].point[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[2].path[0].point[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[2].path[1].point[0]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[2].path[1].point[1]", -100.0, 100.0, false, false, "(in [-100, 100])"},
    {"muscles[3].architecture.volume", 1e-9, 0.1, false, false, "(in [1e-09, 0.1])"},
    {"muscles[3].architecture.fibre_length", 1e-3, 10.0, false, false, "(in [0.001, 10])"},
    {"muscles[3].architecture.sarcomere_length", 1e-6, 5e-6, false, false, "(in [1e-06, 5e-06])"},
    {"muscles[4].architecture.sarcomeres", 500.0, 5e6, false, false, "(in [500, 5e+06])"},
    {"muscles[5].architecture.anatomical_cross_section", 1e-8, 0.1, false, false, "(in [1e-08, 0.1])"},
    {"muscles[5].pennation_angle", 0.0, 80.0, false, false, "(in [0, 80])"},
    {"torque_muscles[0].peak_torque", -1e3, 1e3, false, false, "(in [-1000, 1000])"},
    {"torque_muscles[0].motor_pool.neurons", 1, 100000, false, true, "(in [1, 100000])"},
    {"torque_muscles[0].motor_pool.weakest", 1e-6, 1e6, false, false, "(in [1e-06, 1e+06])"},
    {"torque_muscles[0].motor_pool.strongest", 1e-6, 1e6, false, false, "(in [1e-06, 1e+06])"},
    {"torque_muscles[0].recruited", 0, 10, false, true, "(in [0, 10])"},
};

#define FIELD_COUNT (sizeof fields / sizeof fields[0])

/* tendon_fraction's range is [0, 1): its upper end is open. */
static bool upper_open(const field_range *field) { return strcmp(field->path, "muscles[2].tendon_fraction") == 0; }

static json_t *load_document(void)
{
    json_error_t error;
    json_t *root = json_load_file(EVERY_FIELD, 0, &error);
    cr_assert_not_null(root, "%s:%d: %s", EVERY_FIELD, error.line, error.text);
    return root;
}

/* Sets the number at `path` ("muscles[1].path[0].point[1]") to `value`. */
static void set_number(json_t *root, const char *path, json_t *value)
{
    json_t *container = root;
    const char *at = path;
    char key[64];
    for (;;) {
        size_t length = strcspn(at, ".[");
        cr_assert_lt(length, sizeof key);
        memcpy(key, at, length);
        key[length] = '\0';
        at += length;
        json_t *child = json_object_get(container, key);
        cr_assert_not_null(child, "%s: no key %s", path, key);
        size_t index = 0;
        while (*at == '[') {
            index = strtoul(at + 1, NULL, 10);
            at = strchr(at, ']') + 1;
            if (*at == '\0') {
                cr_assert_eq(json_array_set_new(child, index, value), 0, "%s", path);
                return;
            }
            child = json_array_get(child, index);
        }
        if (*at == '\0') {
            cr_assert_eq(json_object_set_new(container, key, value), 0, "%s", path);
            return;
        }
        container = child;
        ++at; /* '.' */
    }
}

static json_t *number(const field_range *field, double value)
{
    return field->integer ? json_integer((json_int_t)value) : json_real(value);
}

/* Writes the document with `path` set to `value` and loads it. */
static rb_status load_with(const field_range *field, double value, mu_model_desc **desc)
{
    json_t *root = load_document();
    set_number(root, field->path, number(field, value));
    char path[] = "/tmp/sinew-ranges-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    cr_assert_eq(json_dump_file(root, path, JSON_REAL_PRECISION(17)), 0);
    json_decref(root);
    *desc = NULL;
    rb_status status = mu_model_desc_load(path, desc);
    remove(path);
    return status;
}

/* The closest value outside each end: one integer, or the next double. */
static double below(const field_range *field)
{
    return field->integer ? field->lower - 1 : field->lower_open ? field->lower : nextafter(field->lower, -INFINITY);
}

static double above(const field_range *field)
{
    return field->integer ? field->upper + 1 : upper_open(field) ? field->upper : nextafter(field->upper, INFINITY);
}

Test(model_ranges, the_unchanged_model_loads)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load(EVERY_FIELD, &desc), RB_OK, "%s", rb_last_error());
    mu_model_desc_destroy(desc);
}

/* "bones[1].size[0]" without its indices: "bones[].size[]". */
static void without_indices(const char *path, char *out, size_t size)
{
    size_t used = 0;
    for (const char *c = path; *c != '\0' && used + 1 < size; ++c) {
        if (*c >= '0' && *c <= '9' && c > path && (c[-1] == '[' || (c[-1] >= '0' && c[-1] <= '9'))) {
            continue;
        }
        out[used++] = *c;
    }
    out[used] = '\0';
}

/* Each number of the file has a key of the table: the table is the whole format's. */
static void collect_paths(const json_t *value, char *path, size_t used, size_t size, int *missing)
{
    if (json_is_number(value)) {
        char key[256], field_key[256];
        without_indices(path, key, sizeof key);
        for (size_t i = 0; i < FIELD_COUNT; ++i) {
            without_indices(fields[i].path, field_key, sizeof field_key);
            if (strcmp(field_key, key) == 0) {
                return;
            }
        }
        cr_expect_fail("%s is a number of the model without a range in the table", path);
        ++*missing;
        return;
    }
    if (json_is_object(value)) {
        const char *key;
        json_t *member;
        json_object_foreach((json_t *)value, key, member)
        {
            int written = snprintf(path + used, size - used, "%s%s", used > 0 ? "." : "", key);
            collect_paths(member, path, used + (size_t)written, size, missing);
        }
    } else if (json_is_array(value)) {
        for (size_t i = 0; i < json_array_size(value); ++i) {
            int written = snprintf(path + used, size - used, "[%zu]", i);
            collect_paths(json_array_get(value, i), path, used + (size_t)written, size, missing);
        }
    }
    path[used] = '\0';
}

Test(model_ranges, the_table_has_every_number_of_the_model)
{
    json_t *root = load_document();
    char path[256] = "";
    int missing = 0;
    collect_paths(root, path, 0, sizeof path, &missing);
    json_decref(root);
    cr_expect_eq(missing, 0);
}

Test(model_ranges, a_number_just_outside_its_range_is_refused_with_its_path_and_range)
{
    for (size_t i = 0; i < FIELD_COUNT; ++i) {
        const field_range *field = &fields[i];
        const double outside[2] = {below(field), above(field)};
        for (int end = 0; end < 2; ++end) {
            mu_model_desc *desc;
            rb_status status = load_with(field, outside[end], &desc);
            cr_expect_eq(status, RB_ERR_INVALID_ARGUMENT, "%s = %.17g was accepted", field->path, outside[end]);
            cr_expect_null(desc);
            char expected[128];
            snprintf(expected, sizeof expected, ": %s: ", field->path);
            const char *message = rb_last_error();
            cr_expect(strstr(message, expected) != NULL && strstr(message, "is out of range") != NULL &&
                          strstr(message, field->range) != NULL,
                      "%s = %.17g:\n  message  %s\n  expected the path, \"is out of range\" and %s", field->path,
                      outside[end], message, field->range);
            cr_expect(strncmp(message, "/tmp/sinew-ranges-", 18) == 0, "the message names the file: %s", message);
            mu_model_desc_destroy(desc);
        }
    }
}

/* Builds every weight choice of `desc`, every muscle fully active and the
 * torque muscle fully recruited, and steps FRAMES frames; false with a
 * message at the first failed step or non-finite value. */
static bool runs_finite(const mu_model_desc *desc, char *why, size_t size, bool *stopped_by_a_named_error)
{
    *stopped_by_a_named_error = false;
    for (int w = 0; w < desc->weight.mass_count; ++w) {
        mu_model_options options = mu_default_model_options();
        options.weight_index = w;
        mu_model *model = NULL;
        if (mu_model_create(desc, &options, &model) != RB_OK) {
            snprintf(why, size, "weight %d: not built: %s", w, rb_last_error());
            return false;
        }
        for (int m = 0; m < mu_model_muscle_count(model); ++m) {
            mu_model_set_activation_at(model, m, 1.0);
        }
        for (int t = 0; t < mu_model_torque_muscle_count(model); ++t) {
            mu_model_recruit_at(model, t, desc->torque_muscles[t].neurons);
        }
        bool finite = true;
        for (int frame = 0; frame < FRAMES && finite; ++frame) {
            if (mu_model_step(model) != RB_OK) {
                snprintf(why, size, "weight %d, frame %d: %s", w, frame, rb_last_error());
                *stopped_by_a_named_error = strncmp(rb_last_error(), desc->source, strlen(desc->source)) == 0;
                finite = false;
            }
            for (int p = 0; p < mu_model_part_count(model) && finite; ++p) {
                rb_vec2 centre = mu_model_part_centre(model, p);
                finite = isfinite(centre.x) && isfinite(centre.y) && isfinite(mu_model_part_angle(model, p));
                if (!finite) {
                    snprintf(why, size, "weight %d, frame %d: part %s at (%g, %g)", w, frame,
                             mu_model_part_name(model, p), centre.x, centre.y);
                }
            }
            for (int m = 0; m < mu_model_muscle_count(model) && finite; ++m) {
                mu_muscle_readout r = mu_model_muscle_readout(model, m);
                finite =
                    isfinite(r.total_force) && isfinite(r.length) && isfinite(r.velocity) && isfinite(r.fibre_length);
                if (!finite) {
                    snprintf(why, size, "weight %d, frame %d: muscle %s force %g length %g velocity %g", w, frame,
                             mu_model_muscle_name(model, m), r.total_force, r.length, r.velocity);
                }
            }
        }
        mu_model_destroy(model);
        if (!finite) {
            return false;
        }
    }
    return true;
}

Test(model_ranges, every_model_at_the_ends_of_the_ranges_is_refused_or_runs_finite, .timeout = 600)
{
    int accepted = 0, refused = 0;
    for (size_t i = 0; i < FIELD_COUNT; ++i) {
        const field_range *field = &fields[i];
        const double ends[2] = {field->lower_open ? nextafter(field->lower, INFINITY) : field->lower,
                                upper_open(field) ? nextafter(field->upper, -INFINITY) : field->upper};
        for (int end = 0; end < 2; ++end) {
            mu_model_desc *desc;
            if (load_with(field, ends[end], &desc) != RB_OK) {
                /* A check across keys (lower > upper, recruited > neurons) may refuse it, but not its range. */
                cr_expect(strstr(rb_last_error(), "is out of range") == NULL ||
                              strstr(rb_last_error(), field->path) == NULL,
                          "%s = %.17g is refused as out of its range: %s", field->path, ends[end], rb_last_error());
                ++refused;
                continue;
            }
            ++accepted;
            char why[512];
            bool stopped;
            cr_expect(runs_finite(desc, why, sizeof why, &stopped), "%s = %.17g: %s", field->path, ends[end], why);
            mu_model_desc_destroy(desc);
        }
    }
    cr_log_info("%d models at the ends of the ranges accepted, %d refused by a check across keys", accepted, refused);
    cr_expect_geq(accepted, (int)FIELD_COUNT, "most ends load");
}

/* Random models: each number of every_field.json but its geometry, with
 * probability 1/3, drawn within its range (log-uniformly over a range of
 * positive numbers spanning decades), from a fixed seed; each is refused by
 * a check across keys, or runs with every value finite, or stops with an
 * error that names the file and the muscle. The last happens to about one
 * in twelve: extremes combined (a 180 t weight on a 0.24 kg block pulled
 * by 370 kN) tear the model apart until a muscle's tension passes the
 * engine's limit, which the ranges of single numbers cannot rule out. */
Test(model_ranges, random_models_within_the_ranges_are_refused_or_run_finite, .timeout = 600)
{
    unsigned long long state = 0x5eed5eedULL;
    int accepted = 0, stopped = 0;
    for (int model = 0; model < 200; ++model) {
        json_t *root = load_document();
        for (size_t i = 0; i < FIELD_COUNT; ++i) {
            const field_range *field = &fields[i];
            double u[2];
            for (int k = 0; k < 2; ++k) {
                state = state * 6364136223846793005ULL + 1442695040888963407ULL;
                u[k] = (double)(state >> 11) / 9007199254740992.0;
            }
            /* The geometry stays: moved at random, hinges open and path points meet, which the loader refuses. */
            const bool geometry = strstr(field->path, "centre") != NULL || strstr(field->path, "anchor") != NULL ||
                                  strstr(field->path, "point") != NULL || strstr(field->path, "angle") != NULL ||
                                  strstr(field->path, "position") != NULL || strstr(field->path, "lower") != NULL ||
                                  strstr(field->path, "upper") != NULL;
            if (u[0] >= 1.0 / 3.0 || geometry) {
                continue;
            }
            const double lower = field->lower_open ? field->upper * 1e-6 : field->lower;
            double value = lower > 0.0 && field->upper / lower > 100.0 ? lower * pow(field->upper / lower, u[1])
                                                                       : lower + (field->upper - lower) * u[1];
            value = field->integer ? floor(value) : value;
            set_number(root, field->path, number(field, value));
        }
        char path[] = "/tmp/sinew-ranges-XXXXXX";
        int fd = mkstemp(path);
        cr_assert_geq(fd, 0);
        close(fd);
        cr_assert_eq(json_dump_file(root, path, JSON_REAL_PRECISION(17)), 0);
        json_decref(root);
        mu_model_desc *desc = NULL;
        if (mu_model_desc_load(path, &desc) == RB_OK) {
            ++accepted;
            char why[512];
            bool named;
            if (!runs_finite(desc, why, sizeof why, &named)) {
                stopped += named;
                cr_expect(named, "random model %d: %s", model, why);
                cr_log_info("random model %d stops with a named error: %s", model, why);
            }
            mu_model_desc_destroy(desc);
        }
        remove(path);
    }
    cr_log_info("%d of 200 random models accepted, %d of them stopped with a named error", accepted, stopped);
    cr_expect_geq(accepted, 20, "only %d random models loaded", accepted);
}
