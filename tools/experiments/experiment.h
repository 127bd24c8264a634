/* SPDX-License-Identifier: MIT */
/* `sinew experiment NAME`: the experiments of docs/validation.md, most
 * of them those of the original report (Castanyer, "Implementació d'un
 * model computacional de sistemes musculoesquelètics", 2023-2024; see
 * docs/README.md, "Sources"), each a scripted run or computation that
 * writes a CSV, a figure (PNG and SVG, chart/chart.h) and a few lines of
 * figures on stdout.
 *
 * An experiment is one entry of experiment_list (list.c): a
 * name, the stem of its files and a function. Adding one is one more
 * function and one more entry.
 */
#ifndef SINEW_EXPERIMENT_H
#define SINEW_EXPERIMENT_H

#include <stdbool.h>
#include <stddef.h>

#include "chart/chart.h"
#include "io/csv_table.h"

typedef struct experiment_options {
    const char *out_dir; /* an existing directory */
    /* Width of an activation pulse, s, rounded to whole substeps (at
     * least one); 0 when not given, for each experiment's own: one frame
     * of the model for E1 and E4 (the original program's space bar), 2 ms for P1. */
    double pulse_width;
    /* The muscle's activation dynamics, for the experiments that take
     * them (P1): NULL for the experiment's own (P1: first order, Millard
     * et al. 2013), else one of experiment_dynamics_names. */
    const char *dynamics;
} experiment_options;

/* --dynamics: "first_order" (mu/activation.h), "fast" and "slow" (the
 * two-stage calcium-force dynamics of mu/calcium_force.h with the fast or
 * the slow fibres' times); NULL-terminated. */
extern const char *const experiment_dynamics_names[];

/* Longest pulse width accepted, s; P1 takes pulses up to its own
 * maximum, since a longer stimulus gives no twitch. */
#define EXPERIMENT_MAX_PULSE_WIDTH 1.0
#define EXPERIMENT_P1_MAX_PULSE_WIDTH 0.1

typedef struct experiment {
    const char *name;    /* on the command line: "e1" */
    const char *stem;    /* of the files written: "e1_twitch" */
    const char *summary; /* one line for the list */
    /* The longest --pulse-width it takes, s; 0 when it gives no pulses. */
    double max_pulse_width;
    /* Runs the experiment, writes its files and prints its figures;
     * returns the exit status, after one line on stderr on failure. */
    int (*run)(const struct experiment *self, const experiment_options *options);
    /* Whether it takes --dynamics. */
    bool takes_dynamics;
} experiment;

extern const experiment experiment_list[];
extern const int experiment_count;

/* The experiments, each in its own file. */
int experiment_e1_twitch(const experiment *self, const experiment_options *options);
int experiment_e2_relaxation(const experiment *self, const experiment_options *options);
int experiment_e3_isometric(const experiment *self, const experiment_options *options);
int experiment_e3_isotonic(const experiment *self, const experiment_options *options);
int experiment_e4_summation(const experiment *self, const experiment_options *options);
int experiment_c1_hill_curves(const experiment *self, const experiment_options *options);
int experiment_p1_twitch_tetanus(const experiment *self, const experiment_options *options);
int experiment_r1_recruitment(const experiment *self, const experiment_options *options);
int experiment_loop_round_trip(const experiment *self, const experiment_options *options);

/* Writes the table as DIR/STEM.csv and the figure as DIR/STEM.png and
 * DIR/STEM.svg, and prints their paths; returns 0 or EXIT_FAILURE after
 * one line on stderr. */
int experiment_write(const experiment *self, const experiment_options *options, const csv_table *table,
                     const chart_figure *figure);

/* Writes a further table of the experiment as DIR/STEM_PART.csv and
 * prints its path; returns 0 or EXIT_FAILURE after one line on stderr.
 * An experiment writes its further tables before experiment_write. */
int experiment_write_table(const experiment *self, const experiment_options *options, const char *part,
                           const csv_table *table);

/* A series of the table: column `y` against column `x` (indices), from
 * row `first` on. */
chart_series experiment_series(const csv_table *table, int x, int y, long first, const char *label);

#endif
