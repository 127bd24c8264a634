/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "recorder.h"

static const char *const muscle_columns[RECORDER_MUSCLE_COLUMNS] = {
    "activation",        "target_tension_N",       "length_m",
    "normalized_length", "velocity_m_s",           "normalized_velocity",
    "contraction_m",     "normalized_contraction", "active_force_N",
    "passive_force_N",   "total_force_N",          "excitation",
    "fibre_length_m",    "tendon_length_m",        "pennation_angle_deg",
};
/* Per torque muscle: neurons recruited (a count), the exertion (the pool's
 * share, 0 to 1) and the torque on its body in N·m. */
static const char *const torque_columns[RECORDER_TORQUE_COLUMNS] = {"recruited_neurons", "exertion", "torque_N_m"};
static const char *const part_columns[RECORDER_PART_COLUMNS] = {"x_m", "y_m", "angle_deg"};

/* Writes ",NAME.QUANTITY", quoted when RFC 4180 requires it. */
static void write_header_field(FILE *stream, const char *name, const char *quantity)
{
    if (strpbrk(name, ",\"\r\n") == NULL) {
        fprintf(stream, ",%s.%s", name, quantity);
        return;
    }
    fputs(",\"", stream);
    for (const char *c = name; *c != '\0'; ++c) {
        if (*c == '"') {
            fputc('"', stream); /* a quote inside a quoted field is doubled */
        }
        fputc(*c, stream);
    }
    fprintf(stream, ".%s\"", quantity);
}

static void write_header(FILE *stream, const recorder *csv, const mu_model *model)
{
    fputs("time_s", stream);
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        for (int c = 0; c < RECORDER_MUSCLE_COLUMNS; ++c) {
            write_header_field(stream, mu_model_muscle_name(model, m), muscle_columns[c]);
        }
    }
    for (int t = 0; t < mu_model_torque_muscle_count(model); ++t) {
        for (int c = 0; c < RECORDER_TORQUE_COLUMNS; ++c) {
            write_header_field(stream, mu_model_torque_muscle_name(model, t), torque_columns[c]);
        }
    }
    for (int h = 0; h < csv->hinge_count; ++h) {
        write_header_field(stream, mu_model_hinge_name(model, csv->hinges[h]), "angle_deg");
    }
    for (int p = 0; p < csv->part_count; ++p) {
        for (int c = 0; c < RECORDER_PART_COLUMNS; ++c) {
            write_header_field(stream, mu_model_part_name(model, csv->parts[p]), part_columns[c]);
        }
    }
    recorder_loads_write_header(&csv->loads, stream, model, write_header_field);
    fputc('\n', stream);
}

/* The model reports a hinge or part that the level or the variant left
 * out with a NaN pose; such columns would be NaN all along, so they are
 * left out of the file instead. */
static bool collect_built(recorder *csv, const mu_model *model)
{
    csv->hinges = malloc(((size_t)mu_model_hinge_count(model) + 1) * sizeof *csv->hinges);
    csv->parts = malloc(((size_t)mu_model_part_count(model) + 1) * sizeof *csv->parts);
    if (csv->hinges == NULL || csv->parts == NULL) {
        return false;
    }
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        if (isfinite(mu_model_hinge_angle(model, h))) {
            csv->hinges[csv->hinge_count++] = h;
        }
    }
    for (int p = 0; p < mu_model_part_count(model); ++p) {
        if (isfinite(mu_model_part_centre(model, p).x)) {
            csv->parts[csv->part_count++] = p;
        }
    }
    return true;
}

static void free_lists(recorder *csv)
{
    free(csv->hinges);
    free(csv->parts);
    recorder_loads_close(&csv->loads);
    json_decref(csv->settings);
    csv->hinges = NULL;
    csv->parts = NULL;
    csv->settings = NULL;
}

bool recorder_open(recorder *csv, const char *path, mu_model *model, const mu_model_options *options, int digits,
                   char *error, size_t error_size)
{
    *csv = (recorder){.digits = digits};
    csv->settings = provenance_model_settings(model, options);
    if (csv->settings == NULL || !collect_built(csv, model) || !recorder_loads_open(&csv->loads, model)) {
        snprintf(error, error_size, "out of memory");
        free_lists(csv);
        return false;
    }
    if (!atomic_file_open(&csv->file, path, error, error_size)) {
        free_lists(csv);
        return false;
    }
    write_header(csv->file.stream, csv, model);
    if (ferror(csv->file.stream)) {
        snprintf(error, error_size, "cannot write %s: %s", csv->file.temp_path, strerror(errno));
        recorder_abandon(csv);
        return false;
    }
    return true;
}

bool recorder_write_row(recorder *csv, const mu_model *model, const frame_loads *frame, double time, char *error,
                        size_t error_size)
{
    FILE *stream = csv->file.stream;
    const int digits = csv->digits;
    fprintf(stream, "%.*g", digits, time);
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        mu_muscle_readout r = mu_model_muscle_readout(model, m);
        const double values[RECORDER_MUSCLE_COLUMNS] = {r.activation,
                                                        r.target_tension,
                                                        r.length,
                                                        r.normalized_length,
                                                        r.velocity,
                                                        r.normalized_velocity,
                                                        r.contraction,
                                                        r.normalized_contraction,
                                                        r.active_force,
                                                        r.passive_force,
                                                        r.total_force,
                                                        r.excitation,
                                                        r.fibre_length,
                                                        r.tendon_length,
                                                        r.pennation_angle * 180.0 / RB_PI};
        recorder_write_values(stream, digits, values, RECORDER_MUSCLE_COLUMNS);
    }
    for (int t = 0; t < mu_model_torque_muscle_count(model); ++t) {
        const mu_motor_pool *pool = mu_model_motor_pool(model, t);
        const double values[RECORDER_TORQUE_COLUMNS - 1] = {
            mu_motor_pool_exertion(pool), mu_torque_actuator_torque(mu_model_torque_actuator(model, t))};
        fprintf(stream, ",%d", mu_motor_pool_recruited(pool));
        recorder_write_values(stream, digits, values, RECORDER_TORQUE_COLUMNS - 1);
    }
    for (int h = 0; h < csv->hinge_count; ++h) {
        const double angle = mu_model_hinge_angle(model, csv->hinges[h]);
        recorder_write_values(stream, digits, &angle, RECORDER_HINGE_COLUMNS);
    }
    for (int p = 0; p < csv->part_count; ++p) {
        const rb_vec2 centre = mu_model_part_centre(model, csv->parts[p]);
        const double values[RECORDER_PART_COLUMNS] = {centre.x, centre.y, mu_model_part_angle(model, csv->parts[p])};
        recorder_write_values(stream, digits, values, RECORDER_PART_COLUMNS);
    }
    if (!recorder_loads_write_row(&csv->loads, stream, digits, model, frame)) {
        snprintf(error, error_size, "cannot compute the moment arms: %s", rb_last_error());
        return false;
    }
    /* A failed write (a full disk) stops the run at once rather than at
     * the commit. */
    if (fputc('\n', stream) == EOF || ferror(stream)) {
        snprintf(error, error_size, "cannot write %s: %s", csv->file.temp_path, strerror(errno));
        return false;
    }
    csv->rows += 1;
    return true;
}

bool recorder_commit(recorder *csv, char *error, size_t error_size)
{
    json_t *settings = csv->settings;
    csv->settings = NULL;
    free_lists(csv);
    char path[ATOMIC_FILE_PATH_MAX];
    snprintf(path, sizeof path, "%s", csv->file.path);
    if (!atomic_file_commit(&csv->file, error, error_size)) {
        json_decref(settings);
        return false;
    }
    /* Frame rate from the model's own settings: rows / rate is the run's
     * duration, as --duration rounded it to whole frames. */
    double frame_rate = json_real_value(json_object_get(settings, "frame_rate_hz"));
    json_object_set_new(settings, "frames", json_integer(csv->rows));
    json_object_set_new(settings, "duration_s", json_real((double)csv->rows / frame_rate));
    return provenance_write_sidecar(path, settings, error, error_size);
}

void recorder_abandon(recorder *csv)
{
    free_lists(csv);
    atomic_file_abandon(&csv->file);
}

int recorder_column_count(const recorder *csv, const mu_model *model)
{
    return 1 + RECORDER_MUSCLE_COLUMNS * mu_model_muscle_count(model) +
           RECORDER_TORQUE_COLUMNS * mu_model_torque_muscle_count(model) + RECORDER_HINGE_COLUMNS * csv->hinge_count +
           RECORDER_PART_COLUMNS * csv->part_count + recorder_loads_column_count(&csv->loads);
}
