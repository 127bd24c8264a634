/* SPDX-License-Identifier: MIT */
/* E1 twitch and E4 summation and tetanus (docs/validation.md;
 * sections 6.4.2 and 6.4.5 of Castanyer, "Implementació d'un model computacional de sistemes musculoesquelètics",
 * 2023-24): the arm, variant "All Muscles", hangs until it is at rest, then both biceps get activation pulses of 1,
 * each one frame long as the original program's space bar gave them (or --pulse-width, at substep resolution), with
 * activation 0 between them. The trace is Biceps Long's normalized contraction (the muscle the report plots), sampled
 * at the end of every substep.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/user_error.h"
#include "experiment.h"
#include "substep_model.h"

/* The arm starts horizontal and swings down; from 2.5 s to 3 s its
 * elbow angle moves by less than 0.01 degree with 1, 5 or 100 kg. */
#define SETTLE_TIME 3.0 /* s */
/* Recorded after the first pulse: the original report saw the arm back at rest about
 * half a second after a twitch; a train of 9 at 8 Hz lasts 1 s. */
#define RECORD_AFTER 2.5 /* s */
/* The figure starts this long before the first pulse. */
#define FIGURE_LEAD 0.25 /* s */
#define BICEPS_GROUP "Biceps Short + Biceps Long"
#define MAX_PULSES 16

enum { TRACE_TIME, TRACE_ACTIVATION, TRACE_LONG, TRACE_SHORT, TRACE_ELBOW, TRACE_COLUMNS };
static const char *const trace_names[TRACE_COLUMNS] = {
    "time_s",
    "Biceps Long.activation",
    "Biceps Long.normalized_contraction",
    "Biceps Short.normalized_contraction",
    "Elbow.angle_deg",
};

typedef struct pulse_plan {
    double weight_kg;
    double offsets[MAX_PULSES]; /* s after SETTLE_TIME */
    int count;
} pulse_plan;

/* Runs the plan, one row per substep; returns 0 or an exit status. The
 * table is initialised here and must be freed by the caller either way. */
static int run_pulses(const experiment_options *options, const pulse_plan *plan, csv_table *trace, double *pulse_width)
{
    char error[256];
    if (!csv_table_init(trace, TRACE_COLUMNS, trace_names, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    experiment_model run;
    int code = experiment_model_open(&run, "arm", "All Muscles", plan->weight_kg);
    int biceps_long = code == 0 ? experiment_model_muscle(&run, "Biceps Long") : -1;
    int biceps_short = code == 0 ? experiment_model_muscle(&run, "Biceps Short") : -1;
    int elbow = -1;
    for (int h = 0; code == 0 && h < mu_model_hinge_count(run.model); ++h) {
        elbow = strcmp(mu_model_hinge_name(run.model, h), "Elbow") == 0 ? h : elbow;
    }
    if (code == 0 && (biceps_long < 0 || biceps_short < 0 || elbow < 0)) {
        fprintf(stderr, "sinew: the arm model has no Biceps Long, Biceps Short or Elbow\n");
        code = EXIT_FAILURE;
    }
    if (code != 0) {
        experiment_model_close(&run);
        return code;
    }
    long width = experiment_model_pulse_substeps(&run, options->pulse_width);
    *pulse_width = (double)width * run.h;
    long starts[MAX_PULSES];
    for (int p = 0; p < plan->count; ++p) {
        starts[p] = experiment_model_substep_at(&run, SETTLE_TIME + plan->offsets[p]);
    }
    long total = experiment_model_substep_at(&run, SETTLE_TIME + plan->offsets[plan->count - 1] + RECORD_AFTER);
    for (long k = 0; k < total && code == 0; ++k) {
        bool on = false;
        for (int p = 0; p < plan->count; ++p) {
            on = on || (k >= starts[p] && k < starts[p] + width);
        }
        if (mu_model_set_activation(run.model, BICEPS_GROUP, on ? 1.0 : 0.0) != RB_OK) {
            fprintf(stderr, "sinew: %s\n", user_error());
            code = EXIT_FAILURE;
            break;
        }
        code = experiment_model_substep(&run);
        mu_muscle_readout long_head = mu_model_muscle_readout(run.model, biceps_long);
        double row[TRACE_COLUMNS] = {
            [TRACE_TIME] = experiment_model_time(&run),
            [TRACE_ACTIVATION] = long_head.activation,
            [TRACE_LONG] = long_head.normalized_contraction,
            [TRACE_SHORT] = mu_model_muscle_readout(run.model, biceps_short).normalized_contraction,
            [TRACE_ELBOW] = mu_model_hinge_angle(run.model, elbow),
        };
        if (code == 0 && !csv_table_add_row(trace, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            code = EXIT_FAILURE;
        }
    }
    experiment_model_close(&run);
    return code;
}

/* The first row at or after `time`. */
static long row_at(const csv_table *trace, double time)
{
    long r = 0;
    while (r < trace->row_count && trace->columns[TRACE_TIME].values[r] < time - 1e-9) {
        ++r;
    }
    return r;
}

typedef struct twitch_figures {
    double baseline; /* normalized contraction as the first pulse starts */
    double peak, peak_time;
    double settled_time; /* from when it stays within 5 % of the rise of the baseline; NaN if never */
} twitch_figures;

static twitch_figures measure(const csv_table *trace, int column)
{
    const double *time = trace->columns[TRACE_TIME].values;
    const double *value = trace->columns[column].values;
    long start = row_at(trace, SETTLE_TIME);
    twitch_figures f = {.baseline = value[start > 0 ? start - 1 : 0], .peak = -INFINITY, .settled_time = NAN};
    for (long r = start; r < trace->row_count; ++r) {
        if (value[r] > f.peak) {
            f.peak = value[r];
            f.peak_time = time[r];
        }
    }
    double tolerance = 0.05 * (f.peak - f.baseline);
    for (long r = trace->row_count - 1; r >= start && fabs(value[r] - f.baseline) <= tolerance; --r) {
        f.settled_time = time[r];
    }
    return f;
}

int experiment_e1_twitch(const experiment *self, const experiment_options *options)
{
    pulse_plan plan = {.weight_kg = 1.0, .offsets = {0.0}, .count = 1};
    csv_table trace;
    double width = 0.0;
    int code = run_pulses(options, &plan, &trace, &width);
    if (code == 0) {
        long first = row_at(&trace, SETTLE_TIME - FIGURE_LEAD);
        chart_series contraction[2] = {
            experiment_series(&trace, TRACE_TIME, TRACE_LONG, first, "Biceps Long"),
            experiment_series(&trace, TRACE_TIME, TRACE_SHORT, first, "Biceps Short"),
        };
        chart_series activation = experiment_series(&trace, TRACE_TIME, TRACE_ACTIVATION, first, "both biceps");
        char title[160];
        snprintf(title, sizeof title, "E1 twitch: both biceps pulsed to activation 1 for %.1f ms (arm, 1 kg)",
                 1e3 * width);
        chart charts[2] = {
            {.title = title,
             .x_label = "time (s)",
             .y_label = "normalized contraction",
             .series = contraction,
             .series_count = 2},
            {.title = "activation",
             .x_label = "time (s)",
             .y_label = "activation",
             .series = &activation,
             .series_count = 1},
        };
        chart_figure figure = {.charts = charts, .chart_count = 2, .columns = 1, .width = 960, .height = 760};
        code = experiment_write(self, options, &trace, &figure);
    }
    if (code == 0) {
        twitch_figures f = measure(&trace, TRACE_LONG);
        printf("pulse        %.1f ms at activation 1 on both biceps at %.3f s\n", 1e3 * width, SETTLE_TIME);
        printf("Biceps Long  normalized contraction %.4f at rest, peak %.4f at %.3f s (%.0f ms after the pulse)\n",
               f.baseline, f.peak, f.peak_time, 1e3 * (f.peak_time - SETTLE_TIME));
        printf("             back within 5 %% of the rise from %.3f s (%.0f ms after the pulse)\n", f.settled_time,
               1e3 * (f.settled_time - SETTLE_TIME));
    }
    csv_table_free(&trace);
    return code;
}

/* E4's runs: one pulse; two pulses 0.45 s apart ("a little less than
 * 0.5 s"); a train of 9 pulses at 8 Hz (1 s). */
enum { RUN_ONE, RUN_TWO, RUN_TRAIN, RUN_COUNT };
static const char *const run_labels[RUN_COUNT] = {"one pulse", "two pulses", "train of 9 at 8 Hz"};
static const char *const run_columns[RUN_COUNT][2] = {
    {"one_pulse.activation", "one_pulse.normalized_contraction"},
    {"two_pulses.activation", "two_pulses.normalized_contraction"},
    {"train_8Hz.activation", "train_8Hz.normalized_contraction"},
};

/* time_s, then per run its activation and Biceps Long's contraction. */
static int combine(const csv_table traces[RUN_COUNT], csv_table *table)
{
    const char *names[1 + 2 * RUN_COUNT] = {"time_s"};
    for (int r = 0; r < RUN_COUNT; ++r) {
        names[1 + 2 * r] = run_columns[r][0];
        names[2 + 2 * r] = run_columns[r][1];
    }
    char error[256];
    if (!csv_table_init(table, 1 + 2 * RUN_COUNT, names, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    long rows = traces[RUN_TRAIN].row_count; /* the longest run */
    for (long i = 0; i < rows; ++i) {
        double row[1 + 2 * RUN_COUNT] = {traces[RUN_TRAIN].columns[TRACE_TIME].values[i]};
        for (int r = 0; r < RUN_COUNT; ++r) {
            bool has = i < traces[r].row_count;
            row[1 + 2 * r] = has ? traces[r].columns[TRACE_ACTIVATION].values[i] : NAN;
            row[2 + 2 * r] = has ? traces[r].columns[TRACE_LONG].values[i] : NAN;
        }
        if (!csv_table_add_row(table, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
    }
    return 0;
}

int experiment_e4_summation(const experiment *self, const experiment_options *options)
{
    pulse_plan plans[RUN_COUNT] = {
        {.weight_kg = 5.0, .offsets = {0.0}, .count = 1},
        {.weight_kg = 5.0, .offsets = {0.0, 0.45}, .count = 2},
        {.weight_kg = 5.0, .count = 9},
    };
    for (int p = 0; p < plans[RUN_TRAIN].count; ++p) {
        plans[RUN_TRAIN].offsets[p] = p / 8.0;
    }
    csv_table traces[RUN_COUNT] = {{.columns = NULL}};
    csv_table table = {.columns = NULL};
    double width = 0.0;
    int code = 0;
    for (int r = 0; r < RUN_COUNT && code == 0; ++r) {
        code = run_pulses(options, &plans[r], &traces[r], &width);
    }
    if (code == 0) {
        code = combine(traces, &table);
    }
    if (code == 0) {
        long first = row_at(&table, SETTLE_TIME - FIGURE_LEAD);
        chart_series contraction[RUN_COUNT], activation[RUN_COUNT];
        for (int r = 0; r < RUN_COUNT; ++r) {
            contraction[r] = experiment_series(&table, 0, 2 + 2 * r, first, run_labels[r]);
            activation[r] = experiment_series(&table, 0, 1 + 2 * r, first, run_labels[r]);
        }
        char title[160];
        snprintf(title, sizeof title, "E4 summation and tetanus: Biceps Long, pulses of %.1f ms (arm, 5 kg)",
                 1e3 * width);
        chart charts[2] = {
            {.title = title,
             .x_label = "time (s)",
             .y_label = "normalized contraction",
             .series = contraction,
             .series_count = RUN_COUNT},
            {.title = "activation of both biceps",
             .x_label = "time (s)",
             .y_label = "activation",
             .series = activation,
             .series_count = RUN_COUNT},
        };
        chart_figure figure = {.charts = charts, .chart_count = 2, .columns = 1, .width = 960, .height = 760};
        code = experiment_write(self, options, &table, &figure);
    }
    if (code == 0) {
        printf("pulses       %.1f ms at activation 1 on both biceps from %.3f s\n", 1e3 * width, SETTLE_TIME);
        double single = NAN;
        for (int r = 0; r < RUN_COUNT; ++r) {
            twitch_figures f = measure(&traces[r], TRACE_LONG);
            single = r == RUN_ONE ? f.peak - f.baseline : single;
            printf("%-19s peak normalized contraction %.4f at %.3f s, rise %.4f (%.2f x one pulse's)\n", run_labels[r],
                   f.peak, f.peak_time, f.peak - f.baseline, (f.peak - f.baseline) / single);
        }
    }
    for (int r = 0; r < RUN_COUNT; ++r) {
        csv_table_free(&traces[r]);
    }
    csv_table_free(&table);
    return code;
}
