/* SPDX-License-Identifier: MIT */
/* C1 the Hill curves (docs/validation.md; figures 5.14-5.16 of
 * Castanyer, "Implementació d'un model computacional de sistemes musculoesquelètics", 2023-24): the original report's
 * tables (digitised from Ross et al., 2018) as the muscle reads them, with linear interpolation (the original
 * program's) and Steffen's monotone cubic, beside the analytic curves of
 * the MATLAB worksheet "1D Muscle Model based on the Hill 2-Element
 * Model"; and the worksheet's total force against length for its family
 * of constant shortening velocities V = (i/10)·Vmax, i = 0, 0.1, ..., 1.5.
 * docs/README.md ("Sources") cites both sources in full.
 *
 * One table of SAMPLES rows holds four grids side by side: normalized
 * length over [0, 1.5], normalized velocity over [-1.2, 1.2], and the
 * worksheet's length in mm over [0, 1.5·L_rest]. The CSV's columns of
 * the worksheet's set keep the prefix "seed003." that scripts read.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/user_error.h"
#include "experiment.h"
#include "mu/curves.h"

#define SAMPLES 601
#define MAX_NORMALIZED_LENGTH 1.5
#define MAX_NORMALIZED_VELOCITY 1.2
/* The worksheet's constants. */
#define WORKSHEET_REST_LENGTH_MM 0.5
#define WORKSHEET_MAX_FORCE_N 5.0
#define FAMILY_SIZE 16 /* i = 0, 0.1, ..., 1.5 */

enum { SET_LINEAR, SET_STEFFEN, SET_ANALYTIC, SETS };
static const char *const set_labels[SETS] = {"table, linear (original)", "table, Steffen", "worksheet, analytic"};
static const char *const set_suffixes[SETS] = {"table_linear", "table_steffen", "seed003"};

/* Column indices. */
enum {
    COL_LENGTH = 0,
    COL_ACTIVE = 1,                     /* + set */
    COL_PASSIVE = COL_ACTIVE + SETS,    /* + set */
    COL_VELOCITY = COL_PASSIVE + SETS,  /* normalized velocity */
    COL_FV = COL_VELOCITY + 1,          /* + set */
    COL_LENGTH_MM = COL_FV + SETS,      /* the worksheet's length */
    COL_FAMILY = COL_LENGTH_MM + 1,     /* + i */
    COLUMNS = COL_FAMILY + FAMILY_SIZE, /* */
};

enum { NAME_SIZE = 64 };

static void column_names(char names[COLUMNS][NAME_SIZE])
{
    snprintf(names[COL_LENGTH], NAME_SIZE, "normalized_length");
    snprintf(names[COL_VELOCITY], NAME_SIZE, "normalized_velocity");
    snprintf(names[COL_LENGTH_MM], NAME_SIZE, "seed003.length_mm");
    for (int s = 0; s < SETS; ++s) {
        snprintf(names[COL_ACTIVE + s], NAME_SIZE, "active_force_length.%s", set_suffixes[s]);
        snprintf(names[COL_PASSIVE + s], NAME_SIZE, "passive_force_length.%s", set_suffixes[s]);
        snprintf(names[COL_FV + s], NAME_SIZE, "force_velocity.%s", set_suffixes[s]);
    }
    for (int i = 0; i < FAMILY_SIZE; ++i) {
        snprintf(names[COL_FAMILY + i], NAME_SIZE, "seed003.total_force.shortening_%.3fVmax_N", i / 100.0);
    }
}

static int create_curves(mu_curves *sets[SETS])
{
    mu_analytic_curves analytic = mu_default_analytic_curves();
    if (mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &sets[SET_LINEAR]) != RB_OK ||
        mu_curves_create_seed_tables(MU_INTERPOLATION_STEFFEN, &sets[SET_STEFFEN]) != RB_OK ||
        mu_curves_create_analytic(&analytic, &sets[SET_ANALYTIC]) != RB_OK) {
        fprintf(stderr, "sinew: %s\n", user_error());
        return EXIT_FAILURE;
    }
    return 0;
}

static int tabulate(mu_curves *const sets[SETS], csv_table *table)
{
    char names[COLUMNS][NAME_SIZE];
    column_names(names);
    const char *name_pointers[COLUMNS];
    for (int c = 0; c < COLUMNS; ++c) {
        name_pointers[c] = names[c];
    }
    char error[256];
    if (!csv_table_init(table, COLUMNS, name_pointers, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    for (int i = 0; i < SAMPLES; ++i) {
        double u = (double)i / (SAMPLES - 1);
        double row[COLUMNS];
        row[COL_LENGTH] = MAX_NORMALIZED_LENGTH * u;
        row[COL_VELOCITY] = MAX_NORMALIZED_VELOCITY * (2.0 * u - 1.0);
        row[COL_LENGTH_MM] = MAX_NORMALIZED_LENGTH * WORKSHEET_REST_LENGTH_MM * u;
        for (int s = 0; s < SETS; ++s) {
            row[COL_ACTIVE + s] = mu_curve_active_length(sets[s], row[COL_LENGTH]);
            row[COL_PASSIVE + s] = mu_curve_passive_length(sets[s], row[COL_LENGTH]);
            row[COL_FV + s] = mu_curve_velocity(sets[s], row[COL_VELOCITY]);
        }
        /* F = F_MAX·(a·f_L·f_V + f_P) with a = 1; the worksheet's velocity is a
         * shortening speed, ours a lengthening one: ṽ = -V/Vmax. */
        double length = row[COL_LENGTH_MM] / WORKSHEET_REST_LENGTH_MM;
        const mu_curves *analytic = sets[SET_ANALYTIC];
        for (int k = 0; k < FAMILY_SIZE; ++k) {
            double shortening = k / 100.0;
            row[COL_FAMILY + k] = WORKSHEET_MAX_FORCE_N *
                                  (mu_curve_active_length(analytic, length) * mu_curve_velocity(analytic, -shortening) +
                                   mu_curve_passive_length(analytic, length));
        }
        if (!csv_table_add_row(table, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
    }
    return 0;
}

static int draw(const experiment *self, const experiment_options *options, const csv_table *table)
{
    chart_series active[SETS], passive[SETS], velocity[SETS], family[FAMILY_SIZE];
    char family_labels[FAMILY_SIZE][32];
    for (int s = 0; s < SETS; ++s) {
        active[s] = experiment_series(table, COL_LENGTH, COL_ACTIVE + s, 0, set_labels[s]);
        passive[s] = experiment_series(table, COL_LENGTH, COL_PASSIVE + s, 0, set_labels[s]);
        velocity[s] = experiment_series(table, COL_VELOCITY, COL_FV + s, 0, set_labels[s]);
    }
    for (int k = 0; k < FAMILY_SIZE; ++k) {
        snprintf(family_labels[k], sizeof family_labels[k], "V = %.2f Vmax", k / 100.0);
        family[k] = experiment_series(table, COL_LENGTH_MM, COL_FAMILY + k, 0, family_labels[k]);
    }
    chart charts[4] = {
        {.title = "active force-length f_L",
         .x_label = "normalized length",
         .y_label = "f_L",
         .series = active,
         .series_count = SETS},
        {.title = "passive force-length f_P",
         .x_label = "normalized length",
         .y_label = "f_P",
         .series = passive,
         .series_count = SETS},
        {.title = "force-velocity f_V (lengthening > 0)",
         .x_label = "normalized velocity",
         .y_label = "f_V",
         .series = velocity,
         .series_count = SETS},
        {.title = "worksheet: total force at constant shortening speeds",
         .x_label = "length (mm)",
         .y_label = "force (N)",
         .series = family,
         .series_count = FAMILY_SIZE},
    };
    chart_figure figure = {.charts = charts, .chart_count = 4, .columns = 2, .width = 1400, .height = 900};
    return experiment_write(self, options, table, &figure);
}

static void print_figures(mu_curves *const sets[SETS])
{
    printf("%-25s %9s %9s %9s %9s %9s %9s %9s\n", "", "f_L(0.5)", "f_L(1.5)", "f_P(1.25)", "f_P(1.5)", "f_V(-0.5)",
           "f_V(1)", "f_V'(0)");
    for (int s = 0; s < SETS; ++s) {
        const mu_curves *c = sets[s];
        printf("%-25s %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.2f\n", set_labels[s], mu_curve_active_length(c, 0.5),
               mu_curve_active_length(c, 1.5), mu_curve_passive_length(c, 1.25), mu_curve_passive_length(c, 1.5),
               mu_curve_velocity(c, -0.5), mu_curve_velocity(c, 1.0), mu_curve_velocity_slope(c, 0.0));
    }
    const mu_curves *analytic = sets[SET_ANALYTIC];
    printf("worksheet    isometric peak %.2f N at L_rest; at V = 0.15 Vmax %.2f N (f_V %.3f)\n",
           WORKSHEET_MAX_FORCE_N * (1.0 + mu_curve_passive_length(analytic, 1.0)),
           WORKSHEET_MAX_FORCE_N * mu_curve_velocity(analytic, -0.15), mu_curve_velocity(analytic, -0.15));
}

int experiment_c1_hill_curves(const experiment *self, const experiment_options *options)
{
    mu_curves *sets[SETS] = {NULL};
    csv_table table = {.columns = NULL};
    int code = create_curves(sets);
    if (code == 0) {
        code = tabulate(sets, &table);
    }
    if (code == 0) {
        code = draw(self, options, &table);
    }
    if (code == 0) {
        print_figures(sets);
    }
    for (int s = 0; s < SETS; ++s) {
        mu_curves_destroy(sets[s]);
    }
    csv_table_free(&table);
    return code;
}
