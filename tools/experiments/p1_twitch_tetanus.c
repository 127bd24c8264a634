/* SPDX-License-Identifier: MIT */
/* P1 isometric twitch and tetanus (docs/validation.md, P1): the muscle of
 * p1_isometric.h, with a rigid and with a compliant tendon,
 * given one pulse of excitation (2 ms by default, --pulse-width) and
 * trains of such pulses at 1 ... 400 Hz.
 *
 * Measured, on the developed force (the tension above rest):
 * - the twitch's peak, its time to peak from the pulse's onset
 *   (contraction time) and its half-relaxation time, from the peak until
 *   the force is down to half of it (interpolated between substeps);
 * - for each train, over its last whole cycles (at least 0.2 s) after
 *   1 s to settle: mean, minimum, maximum and the ripple
 *   (max - min)/mean;
 * - the fusion frequency, the lowest of the sweep with a ripple under
 *   5 %, and the tetanic force, the largest mean force of the trains up
 *   to 200 Hz (the rates at which isolated muscles are tetanised for
 *   their maximal force), over the twitch's peak.
 *
 * The muscle's activation dynamics are first order unless --dynamics
 * asks for the two stages of mu/calcium_force.h (p1_isometric.h).
 *
 * Files: STEM.csv, the first 0.5 s of the twitch and of three trains;
 * STEM_sweep.csv, the sweep; one figure of both.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "experiment.h"
#include "p1_isometric.h"

#define DEFAULT_PULSE_WIDTH 0.002 /* s */
#define LEAD_TIME 0.01            /* s at rest before the first pulse */
#define TRACE_TIME 0.5            /* s recorded in STEM.csv after the onset */
#define SETTLE_TIME 1.0           /* s of a train before its measured cycles */
#define WINDOW_TIME 0.2           /* s of measured cycles, at least one */
#define FUSION_RIPPLE 0.05        /* ripple below which a train is fused */
#define TETANUS_RATE 200.0        /* Hz: the fastest train counted for the tetanic force */
#define SWEEP_MAX 18

static const double sweep_rates[SWEEP_MAX] = {1,  2,  5,   10,  15,  20,  30,  40,  50,
                                              60, 80, 100, 120, 150, 200, 250, 300, 400};

/* The runs of STEM.csv: the twitch, then trains at these rates. */
enum { SHOWN_TRAINS = 3, RUNS = 1 + SHOWN_TRAINS };
static const double shown_rates[SHOWN_TRAINS] = {10, 30, 100};
static const char *const run_names[RUNS] = {"twitch", "train_10Hz", "train_30Hz", "train_100Hz"};
static const char *const run_labels[RUNS] = {"twitch", "10 Hz", "30 Hz", "100 Hz"};

static const char *const tendon_names[P1_TENDON_COUNT] = {"rigid_tendon", "compliant_tendon"};
static const char *const tendon_labels[P1_TENDON_COUNT] = {"rigid tendon", "compliant tendon"};

typedef struct twitch_measure {
    double peak;            /* N */
    double time_to_peak;    /* s from the onset */
    double half_relaxation; /* s from the peak; NaN if it never falls to half */
} twitch_measure;

typedef struct train_measure {
    double mean, min, max; /* N */
    double ripple;         /* (max - min)/mean */
} train_measure;

typedef struct p1_results {
    long lead, width; /* substeps */
    twitch_measure twitch[P1_TENDON_COUNT];
    int rate_count; /* rates of the sweep whose period is longer than a pulse */
    double rates[SWEEP_MAX];
    train_measure trains[P1_TENDON_COUNT][SWEEP_MAX];
    double fusion_rate[P1_TENDON_COUNT];   /* Hz; NaN when no train fused */
    double tetanic_force[P1_TENDON_COUNT]; /* N */
    double tetanic_rate[P1_TENDON_COUNT];  /* Hz */
} p1_results;

/* The time of the end of substep k, from the first pulse's onset. */
static double time_of(long lead, long k) { return (double)(k + 1 - lead) * P1_SUBSTEP; }

static twitch_measure measure_twitch(const p1_trace *trace, long lead)
{
    const double *force = trace->developed_force;
    long peak = lead;
    for (long k = lead; k < trace->count; ++k) {
        peak = force[k] > force[peak] ? k : peak;
    }
    twitch_measure m = {.peak = force[peak], .time_to_peak = time_of(lead, peak), .half_relaxation = NAN};
    double half = 0.5 * force[peak];
    for (long k = peak + 1; k < trace->count; ++k) {
        if (force[k] <= half) {
            double fraction = (force[k - 1] - half) / (force[k - 1] - force[k]);
            m.half_relaxation = time_of(lead, k - 1) + fraction * P1_SUBSTEP - m.time_to_peak;
            break;
        }
    }
    return m;
}

static train_measure measure_train(const p1_trace *trace, long first)
{
    train_measure m = {.mean = 0.0, .min = INFINITY, .max = -INFINITY};
    for (long k = first; k < trace->count; ++k) {
        m.mean += trace->developed_force[k];
        m.min = fmin(m.min, trace->developed_force[k]);
        m.max = fmax(m.max, trace->developed_force[k]);
    }
    m.mean /= (double)(trace->count - first);
    m.ripple = (m.max - m.min) / m.mean;
    return m;
}

/* Column indices of STEM.csv. */
enum {
    COL_TIME,
    COL_EXCITATION,                        /* + 3·run */
    COL_CALCIUM,                           /* + 3·run */
    COL_ACTIVATION,                        /* + 3·run */
    COL_FORCE = COL_EXCITATION + 3 * RUNS, /* + tendon·RUNS + run */
    TRACE_COLUMNS = COL_FORCE + P1_TENDON_COUNT * RUNS,
};
/* Column indices of STEM_sweep.csv: the rate, then per tendon these. */
enum { SWEEP_MEAN, SWEEP_MIN, SWEEP_MAX_FORCE, SWEEP_RIPPLE, SWEEP_OVER_TWITCH, SWEEP_PER_TENDON };
enum { SWEEP_COLUMNS = 1 + P1_TENDON_COUNT * SWEEP_PER_TENDON };
enum { NAME_SIZE = 64 };

static int init_table(csv_table *table, int count, char names[][NAME_SIZE])
{
    const char *pointers[(int)TRACE_COLUMNS + (int)SWEEP_COLUMNS]; /* room for either table */
    for (int c = 0; c < count; ++c) {
        pointers[c] = names[c];
    }
    char error[256];
    if (!csv_table_init(table, count, pointers, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    return 0;
}

static int init_trace_table(csv_table *table)
{
    char names[TRACE_COLUMNS][NAME_SIZE];
    snprintf(names[COL_TIME], NAME_SIZE, "time_s");
    for (int r = 0; r < RUNS; ++r) {
        snprintf(names[COL_EXCITATION + 3 * r], NAME_SIZE, "%s.excitation", run_names[r]);
        snprintf(names[COL_CALCIUM + 3 * r], NAME_SIZE, "%s.calcium", run_names[r]);
        snprintf(names[COL_ACTIVATION + 3 * r], NAME_SIZE, "%s.activation", run_names[r]);
        for (int t = 0; t < P1_TENDON_COUNT; ++t) {
            snprintf(names[COL_FORCE + t * RUNS + r], NAME_SIZE, "%s.%s.developed_force_N", tendon_names[t],
                     run_names[r]);
        }
    }
    return init_table(table, TRACE_COLUMNS, names);
}

static int init_sweep_table(csv_table *table)
{
    static const char *const quantities[SWEEP_PER_TENDON] = {
        "mean_developed_force_N", "min_developed_force_N", "max_developed_force_N", "ripple", "mean_over_twitch_peak",
    };
    char names[SWEEP_COLUMNS][NAME_SIZE];
    snprintf(names[0], NAME_SIZE, "frequency_Hz");
    for (int t = 0; t < P1_TENDON_COUNT; ++t) {
        for (int q = 0; q < SWEEP_PER_TENDON; ++q) {
            snprintf(names[1 + t * SWEEP_PER_TENDON + q], NAME_SIZE, "%s.%s", tendon_names[t], quantities[q]);
        }
    }
    return init_table(table, SWEEP_COLUMNS, names);
}

/* Rows of STEM.csv: the lead and TRACE_TIME after the onset. */
static long trace_rows(long lead) { return lead + lround(TRACE_TIME / P1_SUBSTEP); }

/* Copies the first rows of a run into the trace table, filled with NaN
 * beforehand. */
static void copy_run(csv_table *table, int run, p1_tendon tendon, const p1_trace *trace)
{
    for (long k = 0; k < table->row_count && k < trace->count; ++k) {
        if (tendon == P1_TENDON_RIGID) {
            table->columns[COL_EXCITATION + 3 * run].values[k] = trace->excitation[k];
            table->columns[COL_CALCIUM + 3 * run].values[k] = trace->calcium[k];
            table->columns[COL_ACTIVATION + 3 * run].values[k] = trace->activation[k];
        }
        table->columns[COL_FORCE + tendon * RUNS + run].values[k] = trace->developed_force[k];
    }
}

static int fill_trace_rows(csv_table *table, long lead)
{
    char error[256];
    for (long k = 0; k < trace_rows(lead); ++k) {
        double row[TRACE_COLUMNS];
        for (int c = 0; c < TRACE_COLUMNS; ++c) {
            row[c] = NAN;
        }
        row[COL_TIME] = time_of(lead, k);
        if (!csv_table_add_row(table, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
    }
    return 0;
}

/* The run of STEM.csv showing this rate, or -1. */
static int shown_run(double rate)
{
    for (int s = 0; s < SHOWN_TRAINS; ++s) {
        if (shown_rates[s] == rate) {
            return 1 + s;
        }
    }
    return -1;
}

/* The twitch and the sweep under one tendon. */
static int run_tendon(const p1_muscle *muscle, p1_tendon tendon, p1_results *results, csv_table *traces)
{
    p1_train twitch = {.lead = results->lead, .width = results->width, .substeps = trace_rows(results->lead)};
    p1_trace trace;
    int code = p1_run_train(muscle, tendon, &twitch, &trace);
    if (code == 0) {
        results->twitch[tendon] = measure_twitch(&trace, results->lead);
        copy_run(traces, 0, tendon, &trace);
    }
    p1_trace_free(&trace);
    results->rate_count = 0;
    for (int f = 0; f < SWEEP_MAX && code == 0; ++f) {
        long period = lround(1.0 / (sweep_rates[f] * P1_SUBSTEP));
        if (period <= results->width) {
            continue; /* pulses that touch are a constant excitation, not a train */
        }
        long cycles = (long)ceil(WINDOW_TIME * sweep_rates[f] - 1e-9);
        long window = (cycles < 1 ? 1 : cycles) * period;
        p1_train train = {
            .lead = results->lead,
            .width = results->width,
            .period = period,
            .substeps = results->lead + lround(SETTLE_TIME / P1_SUBSTEP) + window,
        };
        code = p1_run_train(muscle, tendon, &train, &trace);
        if (code == 0) {
            int i = results->rate_count++;
            results->rates[i] = sweep_rates[f];
            results->trains[tendon][i] = measure_train(&trace, train.substeps - window);
            int run = shown_run(sweep_rates[f]);
            if (run > 0) {
                copy_run(traces, run, tendon, &trace);
            }
        }
        p1_trace_free(&trace);
    }
    results->fusion_rate[tendon] = NAN;
    results->tetanic_force[tendon] = results->twitch[tendon].peak;
    results->tetanic_rate[tendon] = NAN;
    for (int i = results->rate_count - 1; i >= 0; --i) {
        const train_measure *m = &results->trains[tendon][i];
        results->fusion_rate[tendon] = m->ripple < FUSION_RIPPLE ? results->rates[i] : results->fusion_rate[tendon];
        if (results->rates[i] <= TETANUS_RATE && m->mean > results->tetanic_force[tendon]) {
            results->tetanic_force[tendon] = m->mean;
            results->tetanic_rate[tendon] = results->rates[i];
        }
    }
    return code;
}

static int fill_sweep(const p1_results *results, csv_table *table)
{
    char error[256];
    for (int i = 0; i < results->rate_count; ++i) {
        double row[SWEEP_COLUMNS] = {results->rates[i]};
        for (int t = 0; t < P1_TENDON_COUNT; ++t) {
            const train_measure *m = &results->trains[t][i];
            double *cells = row + 1 + t * SWEEP_PER_TENDON;
            cells[SWEEP_MEAN] = m->mean;
            cells[SWEEP_MIN] = m->min;
            cells[SWEEP_MAX_FORCE] = m->max;
            cells[SWEEP_RIPPLE] = m->ripple;
            cells[SWEEP_OVER_TWITCH] = m->mean / results->twitch[t].peak;
        }
        if (!csv_table_add_row(table, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
    }
    return 0;
}

/* The dynamics in a few words, for the figure and stdout. */
static const char *dynamics_label(const p1_muscle *muscle)
{
    if (muscle->dynamics == MU_ACTIVATION_FIRST_ORDER) {
        return "first-order activation";
    }
    mu_calcium_force_times fast = mu_calcium_force_times_of(MU_FIBRE_FAST);
    return memcmp(&muscle->calcium_force, &fast, sizeof fast) == 0 ? "calcium-force, fast fibres"
                                                                   : "calcium-force, slow fibres";
}

static int draw(const experiment *self, const experiment_options *options, const p1_muscle *muscle,
                const p1_results *results, const csv_table *traces, const csv_table *sweep)
{
    chart_series twitch_force[P1_TENDON_COUNT], twitch_drive[3], trains[P1_TENDON_COUNT][SHOWN_TRAINS];
    chart_series ripple[P1_TENDON_COUNT + 1], ratio[P1_TENDON_COUNT];
    for (int t = 0; t < P1_TENDON_COUNT; ++t) {
        twitch_force[t] = experiment_series(traces, COL_TIME, COL_FORCE + t * RUNS, 0, tendon_labels[t]);
        for (int s = 0; s < SHOWN_TRAINS; ++s) {
            trains[t][s] = experiment_series(traces, COL_TIME, COL_FORCE + t * RUNS + 1 + s, 0, run_labels[1 + s]);
        }
        ripple[t] = experiment_series(sweep, 0, 1 + t * SWEEP_PER_TENDON + SWEEP_RIPPLE, 0, tendon_labels[t]);
        ratio[t] = experiment_series(sweep, 0, 1 + t * SWEEP_PER_TENDON + SWEEP_OVER_TWITCH, 0, tendon_labels[t]);
        ripple[t].marker_radius = ratio[t].marker_radius = 3.0;
    }
    twitch_drive[0] = experiment_series(traces, COL_TIME, COL_EXCITATION, 0, "excitation");
    twitch_drive[1] = experiment_series(traces, COL_TIME, COL_ACTIVATION, 0, "activation");
    twitch_drive[2] = experiment_series(traces, COL_TIME, COL_CALCIUM, 0, "calcium");
    const bool two_stage = muscle->dynamics == MU_ACTIVATION_CALCIUM_FORCE;
    static const double fusion_x[2] = {0.0, 400.0}, fusion_y[2] = {FUSION_RIPPLE, FUSION_RIPPLE};
    ripple[P1_TENDON_COUNT] = (chart_series){.label = "fusion: 5 %", .x = fusion_x, .y = fusion_y, .count = 2};
    char title[128];
    snprintf(title, sizeof title, "P1 twitch: Biceps Long held isometric, one pulse of %.1f ms, %s",
             1e3 * (double)results->width * P1_SUBSTEP, dynamics_label(muscle));
    chart charts[6] = {
        {.title = title,
         .x_label = "time from the onset (s)",
         .y_label = "developed force (N)",
         .series = twitch_force,
         .series_count = P1_TENDON_COUNT},
        {.title = two_stage ? "the twitch's excitation, calcium and activation (either tendon)"
                            : "the twitch's excitation and activation (either tendon)",
         .x_label = "time from the onset (s)",
         .y_label = two_stage ? "excitation, calcium, activation" : "excitation, activation",
         .series = twitch_drive,
         .series_count = two_stage ? 3 : 2},
        {.title = "trains, rigid tendon",
         .x_label = "time from the onset (s)",
         .y_label = "developed force (N)",
         .series = trains[P1_TENDON_RIGID],
         .series_count = SHOWN_TRAINS},
        {.title = "trains, compliant tendon",
         .x_label = "time from the onset (s)",
         .y_label = "developed force (N)",
         .series = trains[P1_TENDON_COMPLIANT],
         .series_count = SHOWN_TRAINS},
        {.title = "ripple (max - min)/mean of the last cycles (up to 0.5 shown)",
         .x_label = "frequency (Hz)",
         .y_label = "ripple",
         .series = ripple,
         .series_count = P1_TENDON_COUNT + 1,
         .y_range = {.fixed = true, .min = 0.0, .max = 0.5}},
        {.title = "mean force of the last cycles over the twitch's peak",
         .x_label = "frequency (Hz)",
         .y_label = "mean / twitch peak",
         .series = ratio,
         .series_count = P1_TENDON_COUNT},
    };
    chart_figure figure = {.charts = charts, .chart_count = 6, .columns = 2, .width = 1400, .height = 1200};
    int code = experiment_write_table(self, options, "sweep", sweep);
    return code == 0 ? experiment_write(self, options, traces, &figure) : code;
}

static void print_results(const p1_muscle *muscle, const p1_results *results)
{
    printf("muscle       %s of the arm, isometric at its rest length %.4f m: Fmax %.1f N, Vmax %.3f m/s, "
           "tendon %.4f m\n",
           muscle->name, muscle->rest_length, muscle->max_force, muscle->max_velocity, muscle->tendon_length);
    printf("pulses       excitation 1 for %.1f ms (%ld substeps of 1/6000 s)\n",
           1e3 * (double)results->width * P1_SUBSTEP, results->width);
    if (muscle->dynamics == MU_ACTIVATION_FIRST_ORDER) {
        printf("dynamics     first-order activation (Millard et al. 2013): tau_act 10 ms, tau_deact 40 ms\n");
    } else {
        const mu_calcium_force_times *t = &muscle->calcium_force;
        printf("dynamics     %s: calcium rise %g ms, decay %g ms; force rise %g ms, decay %g ms\n",
               dynamics_label(muscle), 1e3 * t->calcium_rise_time, 1e3 * t->calcium_decay_time,
               1e3 * t->force_rise_time, 1e3 * t->force_decay_time);
    }
    printf("%-17s %11s %13s %17s %15s %25s\n", "", "twitch peak", "time to peak", "half-relaxation", "fusion (< 5 %)",
           "tetanic / twitch");
    for (int t = 0; t < P1_TENDON_COUNT; ++t) {
        const twitch_measure *m = &results->twitch[t];
        char fusion[32];
        if (isnan(results->fusion_rate[t])) {
            snprintf(fusion, sizeof fusion, "none <= %g Hz", results->rates[results->rate_count - 1]);
        } else {
            snprintf(fusion, sizeof fusion, "%g Hz", results->fusion_rate[t]);
        }
        printf("%-17s %9.1f N %10.1f ms %14.1f ms %15s %12.2f (%g Hz, %.0f N)\n", tendon_labels[t], m->peak,
               1e3 * m->time_to_peak, 1e3 * m->half_relaxation, fusion, results->tetanic_force[t] / m->peak,
               results->tetanic_rate[t], results->tetanic_force[t]);
    }
    printf("%-10s %28s %28s\n", "sweep", "rigid: mean N, ripple", "compliant: mean N, ripple");
    for (int i = 0; i < results->rate_count; ++i) {
        printf("%7g Hz %20.1f N %6.1f %% %20.1f N %6.1f %%\n", results->rates[i],
               results->trains[P1_TENDON_RIGID][i].mean, 100.0 * results->trains[P1_TENDON_RIGID][i].ripple,
               results->trains[P1_TENDON_COMPLIANT][i].mean, 100.0 * results->trains[P1_TENDON_COMPLIANT][i].ripple);
    }
}

int experiment_p1_twitch_tetanus(const experiment *self, const experiment_options *options)
{
    double width = options->pulse_width > 0.0 ? options->pulse_width : DEFAULT_PULSE_WIDTH;
    p1_results results = (p1_results){.lead = lround(LEAD_TIME / P1_SUBSTEP), .width = lround(width / P1_SUBSTEP)};
    results.width = results.width < 1 ? 1 : results.width;
    p1_muscle muscle;
    csv_table traces = {.columns = NULL}, sweep = {.columns = NULL};
    int code = p1_muscle_load(&muscle, options->dynamics);
    code = code == 0 ? init_trace_table(&traces) : code;
    code = code == 0 ? fill_trace_rows(&traces, results.lead) : code;
    code = code == 0 ? init_sweep_table(&sweep) : code;
    for (int t = 0; t < P1_TENDON_COUNT && code == 0; ++t) {
        code = run_tendon(&muscle, (p1_tendon)t, &results, &traces);
    }
    code = code == 0 ? fill_sweep(&results, &sweep) : code;
    code = code == 0 ? draw(self, options, &muscle, &results, &traces, &sweep) : code;
    if (code == 0) {
        print_results(&muscle, &results);
    }
    p1_muscle_free(&muscle);
    csv_table_free(&traces);
    csv_table_free(&sweep);
    return code;
}
