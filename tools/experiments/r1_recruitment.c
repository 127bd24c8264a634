/* SPDX-License-Identifier: MIT */
/* R1 recruitment (docs/validation.md; McIntyre, "Simulated Muscles",
 * cited in docs/README.md): the worm's torque muscle, its motor pool recruited from 0 to every neuron,
 * weakest first (Henneman's size principle, mu/motor_pool.h). For each
 * count n: the share of the pool, the strength of the n-th neuron, the
 * exertion e(n) (the pool's cumulative strength over its total) and the
 * torque the actuator then applies. The pool is read from the worm's
 * profile image (models/worm-pool.png). With strengths rising exponentially
 * the curve is convex: each neuron added is stronger than the last, so
 * the first 30 % of the pool give only a few per cent of the force.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/user_error.h"
#include "experiment.h"
#include "substep_model.h"

#define TORQUE_MUSCLE 0 /* the worm's only one */

enum { COL_NEURONS, COL_SHARE, COL_STRENGTH, COL_EXERTION, COL_TORQUE, COLUMNS };
static const char *const names[COLUMNS] = {
    "recruited_neurons", "pool_fraction", "last_recruited_strength", "exertion", "torque_N_m",
};

/* One row per count n = 0 .. N, recruited through the model. */
static int tabulate(experiment_model *worm, csv_table *table)
{
    char error[256];
    if (!csv_table_init(table, COLUMNS, names, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    const mu_motor_pool *pool = mu_model_motor_pool(worm->model, TORQUE_MUSCLE);
    const mu_torque_actuator *actuator = mu_model_torque_actuator(worm->model, TORQUE_MUSCLE);
    int count = mu_motor_pool_neuron_count(pool);
    for (int n = 0; n <= count; ++n) {
        if (mu_model_recruit_at(worm->model, TORQUE_MUSCLE, n) != RB_OK) {
            fprintf(stderr, "sinew: %s\n", user_error());
            return EXIT_FAILURE;
        }
        double row[COLUMNS] = {
            [COL_NEURONS] = mu_motor_pool_recruited(pool),
            [COL_SHARE] = (double)n / count,
            [COL_STRENGTH] = n > 0 ? mu_motor_pool_strength(pool, n - 1) : NAN,
            [COL_EXERTION] = mu_motor_pool_exertion(pool),
            [COL_TORQUE] = mu_torque_actuator_torque(actuator),
        };
        if (!csv_table_add_row(table, row, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
    }
    return 0;
}

static int draw(const experiment *self, const experiment_options *options, const csv_table *table)
{
    chart_series exertion[2] = {
        experiment_series(table, COL_SHARE, COL_EXERTION, 0, "the worm's pool (weak first)"),
        experiment_series(table, COL_SHARE, COL_SHARE, 0, "equal neurons"),
    };
    chart_series strength = experiment_series(table, COL_NEURONS, COL_STRENGTH, 1, "strength");
    chart charts[2] = {
        {.title = "R1 recruitment: exertion against the share of the pool recruited (worm, 200 neurons "
                  "read from worm-pool.png)",
         .x_label = "recruited share of the pool",
         .y_label = "exertion",
         .series = exertion,
         .series_count = 2},
        {.title = "each neuron's strength (255 − blue of its pixel), in recruitment order",
         .x_label = "neuron",
         .y_label = "strength",
         .series = &strength,
         .series_count = 1},
    };
    chart_figure figure = {.charts = charts, .chart_count = 2, .columns = 1, .width = 960, .height = 760};
    return experiment_write(self, options, table, &figure);
}

static void print_figures(const experiment_model *worm, const csv_table *table)
{
    const mu_motor_pool *pool = mu_model_motor_pool(worm->model, TORQUE_MUSCLE);
    int count = mu_motor_pool_neuron_count(pool);
    const mu_model_torque_muscle *muscle = &worm->desc->torque_muscles[0];
    printf("pool         %s: %d neurons from %s, strengths %g to %g (weak first), total %.1f; peak torque "
           "%g N m\n",
           mu_model_torque_muscle_name(worm->model, TORQUE_MUSCLE), count,
           muscle->pool_file != NULL ? muscle->pool_file : "a generated profile", mu_motor_pool_strength(pool, 0),
           mu_motor_pool_strength(pool, count - 1), mu_motor_pool_total_strength(pool),
           mu_torque_actuator_peak_torque(mu_model_torque_actuator(worm->model, TORQUE_MUSCLE)));
    static const double shares[] = {0.1, 0.3, 0.5, 0.7, 0.9};
    for (size_t k = 0; k < sizeof shares / sizeof shares[0]; ++k) {
        long n = lround(shares[k] * count);
        printf("%3.0f %% of it  %3ld neurons: exertion %.4f, torque %.3g N m\n", 100.0 * shares[k], n,
               table->columns[COL_EXERTION].values[n], table->columns[COL_TORQUE].values[n]);
    }
    long half = 0;
    while (half < count && table->columns[COL_EXERTION].values[half] < 0.5) {
        ++half;
    }
    printf("half force   from %ld neurons (%.0f %% of the pool)\n", half, 100.0 * (double)half / count);
}

int experiment_r1_recruitment(const experiment *self, const experiment_options *options)
{
    experiment_model worm;
    csv_table table = {.columns = NULL};
    int code = experiment_model_open(&worm, "worm", "Default", 0.0);
    if (code == 0 && mu_model_torque_muscle_count(worm.model) <= TORQUE_MUSCLE) {
        fputs("sinew: the worm model has no torque muscle\n", stderr);
        code = EXIT_FAILURE;
    }
    code = code == 0 ? tabulate(&worm, &table) : code;
    code = code == 0 ? draw(self, options, &table) : code;
    if (code == 0) {
        print_figures(&worm, &table);
    }
    experiment_model_close(&worm);
    csv_table_free(&table);
    return code;
}
