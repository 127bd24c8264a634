/* SPDX-License-Identifier: MIT */
/* E2 active and passive force during relaxation (docs/validation.md;
 * section 6.4.3 of Castanyer, "Implementació d'un model computacional de sistemes musculoesquelètics", 2023-24): the
 * sample model with 50 kg, its muscle at activation 1 until the weight hangs still, then the activation falls linearly
 * to 0 over 3 s. The original report plots active, passive and total force against the normalized length along the
 * relaxation.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "experiment.h"
#include "protocol.h"
#include "substep_model.h"

/* The protocol, as a control file (the times below give the same). */
static const char protocol[] = "# TIME  SHAPE       NAME    ARGUMENTS\n"
                               "0       activation  Muscle  1        # until the weight hangs still\n"
                               "2       ramp        Muscle  1 0 3    # activation 1 to 0 over 3 s, then 0\n";

#define HOLD_TIME 2.0  /* s at activation 1 first: the weight comes to rest */
#define RAMP_TIME 3.0  /* s from activation 1 to 0 */
#define AFTER_TIME 1.0 /* s at activation 0 after */

enum { COL_TIME, COL_ACTIVATION, COL_LENGTH, COL_ACTIVE, COL_PASSIVE, COL_TOTAL, COLUMNS };
static const char *const names[COLUMNS] = {
    "time_s",
    "Muscle.activation",
    "Muscle.normalized_length",
    "Muscle.active_force_N",
    "Muscle.passive_force_N",
    "Muscle.total_force_N",
};

static int run(csv_table *table)
{
    char error[256];
    if (!csv_table_init(table, COLUMNS, names, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    experiment_model model;
    int code = experiment_model_open(&model, "sample", "Default", 50.0);
    int muscle = code == 0 ? experiment_model_muscle(&model, "Muscle") : -1;
    if (code == 0 && muscle < 0) {
        fprintf(stderr, "sinew: the sample model has no muscle named \"Muscle\"\n");
        code = EXIT_FAILURE;
    }
    controls schedule = {.desc = NULL};
    if (code == 0) {
        code = experiment_protocol_read(&schedule, &model, "Default", "e2 protocol", protocol);
    }
    long total = code == 0 ? experiment_model_substep_at(&model, HOLD_TIME + RAMP_TIME + AFTER_TIME) : 0;
    for (long k = 0; k < total && code == 0; ++k) {
        code = experiment_protocol_apply(&schedule, &model);
        if (code != 0) {
            break;
        }
        code = experiment_model_substep(&model);
        mu_muscle_readout r = mu_model_muscle_readout(model.model, muscle);
        double row[COLUMNS] = {experiment_model_time(&model),
                               r.activation,
                               r.normalized_length,
                               r.active_force,
                               r.passive_force,
                               r.total_force};
        if (code == 0 && !csv_table_add_row(table, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            code = EXIT_FAILURE;
        }
    }
    controls_free(&schedule);
    experiment_model_close(&model);
    return code;
}

/* The rows of the relaxation: from the ramp's start to its end. */
static void relaxation_rows(const csv_table *table, long *first, long *end)
{
    const double *time = table->columns[COL_TIME].values;
    *first = 0;
    while (*first < table->row_count && time[*first] <= HOLD_TIME + 1e-9) {
        ++*first;
    }
    *end = *first;
    while (*end < table->row_count && time[*end] <= HOLD_TIME + RAMP_TIME + 1e-9) {
        ++*end;
    }
}

static void print_figures(const csv_table *table)
{
    long first, end;
    relaxation_rows(table, &first, &end);
    const double *length = table->columns[COL_LENGTH].values;
    const double *active = table->columns[COL_ACTIVE].values;
    const double *passive = table->columns[COL_PASSIVE].values;
    double shortest = INFINITY;
    for (long r = first; r < end; ++r) {
        shortest = fmin(shortest, length[r]);
    }
    printf("start        normalized length %.4f, active %.1f N, passive %.1f N (activation 1, at rest)\n",
           length[first], active[first], passive[first]);
    printf("shortest     normalized length %.4f during the relaxation\n", shortest);
    printf("end          normalized length %.4f, active %.1f N, passive %.1f N (activation 0)\n", length[end - 1],
           active[end - 1], passive[end - 1]);
}

int experiment_e2_relaxation(const experiment *self, const experiment_options *options)
{
    csv_table table;
    int code = run(&table);
    if (code == 0) {
        long first, end;
        relaxation_rows(&table, &first, &end);
        /* The time chart leaves out the weight's fall at the start. */
        long time_first = 0;
        while (time_first < table.row_count && table.columns[COL_TIME].values[time_first] < HOLD_TIME - 0.5) {
            ++time_first;
        }
        chart_series against_length[3], against_time[3];
        const char *labels[3] = {"active", "passive", "total"};
        for (int s = 0; s < 3; ++s) {
            against_length[s] = experiment_series(&table, COL_LENGTH, COL_ACTIVE + s, first, labels[s]);
            against_length[s].count = (size_t)(end - first);
            against_time[s] = experiment_series(&table, COL_TIME, COL_ACTIVE + s, time_first, labels[s]);
        }
        chart charts[2] = {
            {.title = "E2 relaxation: activation 1 to 0 over 3 s (sample model, 50 kg)",
             .x_label = "normalized length",
             .y_label = "force (N)",
             .series = against_length,
             .series_count = 3},
            {.title = "the same against time (activation 1 until 2 s, 0 from 5 s)",
             .x_label = "time (s)",
             .y_label = "force (N)",
             .series = against_time,
             .series_count = 3},
        };
        chart_figure figure = {.charts = charts, .chart_count = 2, .columns = 1, .width = 960, .height = 760};
        code = experiment_write(self, options, &table, &figure);
    }
    if (code == 0) {
        print_figures(&table);
    }
    csv_table_free(&table);
    return code;
}
