/* SPDX-License-Identifier: MIT */
/* The round trip (docs/inverse.md, "The round trip"): the arm holding
 * 1 kg, driven by a known pattern of activations (the protocol below);
 * its motion; the net hinge torques of that motion by inverse dynamics
 * (mu/inverse_dynamics.h) after the 6 Hz zero-phase filter of `sinew
 * inverse`; the activations that produce them by static optimization
 * (mu/static_optimization.h, p = 2); and a second forward run driven by
 * the activations found.
 *
 * Both runs go through the same first SETTLE_TIME seconds with the
 * pattern (the arm swings down from horizontal and settles; the engine
 * is deterministic, so the two states are equal there); from then on the
 * second run takes the activations found, each substep the value at its
 * middle, linearly interpolated between frames. What is compared is that
 * window: the torques (inverse dynamics, the first run's own muscle
 * torques, the activations found), the activations (the pattern's and
 * the ones found) and the angles of the two runs.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands/motion_filter.h"
#include "experiment.h"
#include "mu/moment_arms.h"
#include "mu/static_optimization.h"
#include "protocol.h"
#include "substep_model.h"

/* The known pattern, as a control file: the long biceps on a 1 Hz sine,
 * the short biceps rising slowly, the lateral triceps steady. */
static const char protocol[] = "# TIME  SHAPE                 NAME               ARGUMENTS\n"
                               "0       activation sine       \"Biceps Long\"      0.3 0.15 1 8\n"
                               "0       activation ramp       \"Biceps Short\"     0.02 0.2 8\n"
                               "0       activation            \"Triceps Lateral\"  0.1\n";

#define SETTLE_TIME 2.0 /* s: both runs follow the pattern */
#define WINDOW_TIME 4.0 /* s: then the second run follows the activations found */
#define WEIGHT_KG 1.0
#define HINGES 2
#define MUSCLES 5

static const char *const hinge_names[HINGES] = {"Shoulder", "Elbow"};
static const char *const muscle_names[MUSCLES] = {"Biceps Short", "Biceps Long", "Triceps Medial", "Triceps Long",
                                                  "Triceps Lateral"};

/* Everything recorded, by frame (frames values each). */
typedef struct round_trip {
    long frames;
    double step; /* s, one frame */
    double *time;
    double *angle[HINGES], *replayed[HINGES];   /* deg: the first run's, the second's */
    double *run_torque[HINGES];                 /* N·m: the first run's muscles' */
    double *net[HINGES], *found_torque[HINGES]; /* N·m: inverse dynamics, the activations found */
    double *reserve[HINGES];                    /* N·m */
    double *pattern[MUSCLES], *found[MUSCLES];  /* activations */
    double *solved;                             /* 1 or 0 */
    double *drift[HINGES];                      /* deg: replayed − angle, for the figure */
    double *storage;
} round_trip;

enum { SERIES = 7 * HINGES + 2 * MUSCLES + 2 };

static bool allocate(round_trip *r, long frames)
{
    r->frames = frames;
    r->storage = calloc((size_t)SERIES * (size_t)frames, sizeof *r->storage);
    if (r->storage == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return false;
    }
    double *next = r->storage;
    double **all[SERIES];
    int k = 0;
    all[k++] = &r->time;
    all[k++] = &r->solved;
    for (int h = 0; h < HINGES; ++h) {
        all[k++] = &r->angle[h];
        all[k++] = &r->replayed[h];
        all[k++] = &r->run_torque[h];
        all[k++] = &r->net[h];
        all[k++] = &r->found_torque[h];
        all[k++] = &r->reserve[h];
        all[k++] = &r->drift[h];
    }
    for (int m = 0; m < MUSCLES; ++m) {
        all[k++] = &r->pattern[m];
        all[k++] = &r->found[m];
    }
    for (int s = 0; s < SERIES; ++s) {
        *all[s] = next;
        next += frames;
    }
    return true;
}

/* Opens the arm and checks that its hinges and muscles are the ones named
 * above, in that order (the tables index them so). */
static int open_arm(experiment_model *run)
{
    int code = experiment_model_open(run, "arm", "All Muscles", WEIGHT_KG);
    for (int h = 0; code == 0 && h < HINGES; ++h) {
        if (h >= mu_model_hinge_count(run->model) || strcmp(mu_model_hinge_name(run->model, h), hinge_names[h]) != 0) {
            fprintf(stderr, "sinew: the arm's hinge %d is not \"%s\"\n", h, hinge_names[h]);
            code = EXIT_FAILURE;
        }
    }
    for (int m = 0; code == 0 && m < MUSCLES; ++m) {
        if (experiment_model_muscle(run, muscle_names[m]) != m) {
            fprintf(stderr, "sinew: the arm's muscle %d is not \"%s\"\n", m, muscle_names[m]);
            code = EXIT_FAILURE;
        }
    }
    return code;
}

/* The first run: the pattern throughout. */
static int run_pattern(round_trip *r)
{
    experiment_model run;
    controls schedule = {.desc = NULL};
    int code = open_arm(&run);
    code = code == 0 ? experiment_protocol_read(&schedule, &run, "All Muscles", "loop protocol", protocol) : code;
    if (code == 0) {
        r->step = run.h * run.substeps;
        code = allocate(r, (long)lround((SETTLE_TIME + WINDOW_TIME) / r->step) + 1) ? 0 : EXIT_FAILURE;
    }
    for (long i = 0; code == 0 && i < r->frames; ++i) {
        for (int s = 0; i > 0 && code == 0 && s < run.substeps; ++s) {
            code = experiment_protocol_apply(&schedule, &run);
            code = code == 0 ? experiment_model_substep(&run) : code;
        }
        r->time[i] = i * r->step;
        for (int h = 0; h < HINGES; ++h) {
            r->angle[h][i] = mu_model_hinge_angle(run.model, h);
            r->run_torque[h][i] = mu_model_hinge_muscle_torque(run.model, h);
        }
        for (int m = 0; m < MUSCLES; ++m) {
            r->pattern[m][i] = mu_model_muscle_readout(run.model, m).activation;
        }
    }
    controls_free(&schedule);
    experiment_model_close(&run);
    return code;
}

/* Inverse dynamics and static optimization of the first run's motion. */
static int optimize(round_trip *r)
{
    const size_t n = (size_t)r->frames;
    double *smooth = malloc(3 * HINGES * n * sizeof *smooth);
    experiment_model arm;
    int code = smooth == NULL ? EXIT_FAILURE : open_arm(&arm);
    for (int h = 0; code == 0 && h < HINGES; ++h) {
        double *angle = smooth + 3 * (size_t)h * n, *rate = angle + n, *acceleration = rate + n;
        memcpy(angle, r->angle[h], n * sizeof *angle);
        if (!motion_filter_low_pass(angle, n, MOTION_FILTER_DEFAULT_CUTOFF, 1.0 / r->step)) {
            code = EXIT_FAILURE;
        }
        motion_filter_differentiate(angle, n, r->step, rate, acceleration);
    }
    mu_static_optimizer *optimizer = NULL;
    const mu_static_optimization_settings settings = mu_default_static_optimization_settings();
    if (code == 0 && mu_static_optimizer_create(arm.model, &settings, &optimizer) != RB_OK) {
        fprintf(stderr, "sinew: static optimization of the arm: %s\n", rb_last_error());
        code = EXIT_FAILURE;
    }
    for (size_t i = 0; code == 0 && i < n; ++i) {
        double angles[HINGES], rates[HINGES], accelerations[HINGES], net[HINGES], torque[HINGES], reserve[HINGES],
            activations[MUSCLES];
        for (int h = 0; h < HINGES; ++h) {
            const double *angle = smooth + 3 * (size_t)h * n;
            angles[h] = angle[i];
            rates[h] = angle[n + i] * RB_PI / 180.0;
            accelerations[h] = angle[2 * n + i] * RB_PI / 180.0;
        }
        mu_static_frame frame = {
            .activations = activations, .net_torques = net, .actuator_torques = torque, .reserves = reserve};
        if (mu_static_optimizer_solve(optimizer, angles, rates, accelerations, &frame) != RB_OK) {
            fprintf(stderr, "sinew: static optimization at t = %g s: %s\n", r->time[i], rb_last_error());
            code = EXIT_FAILURE;
            break;
        }
        r->solved[i] = frame.solved ? 1.0 : 0.0;
        for (int h = 0; h < HINGES; ++h) {
            r->net[h][i] = net[h];
            r->found_torque[h][i] = torque[h];
            r->reserve[h][i] = reserve[h];
        }
        for (int m = 0; m < MUSCLES; ++m) {
            r->found[m][i] = activations[m];
        }
    }
    if (smooth == NULL) {
        fputs("sinew: out of memory\n", stderr);
    }
    mu_static_optimizer_destroy(optimizer);
    experiment_model_close(&arm);
    free(smooth);
    return code;
}

/* The activation found for muscle m at time t, linear between frames. */
static double found_at(const round_trip *r, int m, double t)
{
    const double position = fmin(fmax(t / r->step, 0.0), (double)(r->frames - 1));
    const long i = (long)fmin(floor(position), (double)(r->frames - 2));
    const double share = position - (double)i;
    return (1.0 - share) * r->found[m][i] + share * r->found[m][i + 1];
}

/* The second run: the pattern until SETTLE_TIME, then the activations found. */
static int replay(round_trip *r)
{
    experiment_model run;
    controls schedule = {.desc = NULL};
    int code = open_arm(&run);
    code = code == 0 ? experiment_protocol_read(&schedule, &run, "All Muscles", "loop protocol", protocol) : code;
    const long settle = lround(SETTLE_TIME / run.h);
    for (long i = 0; code == 0 && i < r->frames; ++i) {
        for (int s = 0; i > 0 && code == 0 && s < run.substeps; ++s) {
            if (run.taken < settle) {
                code = experiment_protocol_apply(&schedule, &run);
            } else {
                const double middle = (run.taken + 0.5) * run.h;
                for (int m = 0; code == 0 && m < MUSCLES; ++m) {
                    code = mu_model_set_activation_at(run.model, m, found_at(r, m, middle)) == RB_OK ? 0 : EXIT_FAILURE;
                }
            }
            code = code == 0 ? experiment_model_substep(&run) : code;
        }
        for (int h = 0; h < HINGES; ++h) {
            r->replayed[h][i] = mu_model_hinge_angle(run.model, h);
        }
    }
    if (code != 0 && run.model != NULL) {
        fprintf(stderr, "sinew: the second run failed: %s\n", rb_last_error());
    }
    controls_free(&schedule);
    experiment_model_close(&run);
    return code;
}

/* ------------------------------------------------------------------ output */

static int table_of(const round_trip *r, csv_table *table)
{
    enum { HINGE_COLUMNS = 6, MUSCLE_COLUMNS = 2 };
    static const char *const hinge_columns[HINGE_COLUMNS] = {
        "angle_deg",      "replayed_angle_deg",      "run_muscle_torque_N_m",
        "net_torque_N_m", "found_muscle_torque_N_m", "reserve_torque_N_m"};
    static const char *const muscle_columns[MUSCLE_COLUMNS] = {"activation", "found_activation"};
    const int count = 2 + HINGES * HINGE_COLUMNS + MUSCLES * MUSCLE_COLUMNS;
    char names[2 + HINGES * HINGE_COLUMNS + MUSCLES * MUSCLE_COLUMNS][80];
    const char *name_of[2 + HINGES * HINGE_COLUMNS + MUSCLES * MUSCLE_COLUMNS];
    const double *columns[2 + HINGES * HINGE_COLUMNS + MUSCLES * MUSCLE_COLUMNS];
    int c = 0;
    snprintf(names[c], sizeof names[c], "time_s");
    columns[c++] = r->time;
    snprintf(names[c], sizeof names[c], "solved");
    columns[c++] = r->solved;
    for (int h = 0; h < HINGES; ++h) {
        const double *values[HINGE_COLUMNS] = {r->angle[h], r->replayed[h],     r->run_torque[h],
                                               r->net[h],   r->found_torque[h], r->reserve[h]};
        for (int k = 0; k < HINGE_COLUMNS; ++k) {
            snprintf(names[c], sizeof names[c], "%s.%s", hinge_names[h], hinge_columns[k]);
            columns[c++] = values[k];
        }
    }
    for (int m = 0; m < MUSCLES; ++m) {
        const double *values[MUSCLE_COLUMNS] = {r->pattern[m], r->found[m]};
        for (int k = 0; k < MUSCLE_COLUMNS; ++k) {
            snprintf(names[c], sizeof names[c], "%s.%s", muscle_names[m], muscle_columns[k]);
            columns[c++] = values[k];
        }
    }
    for (int k = 0; k < count; ++k) {
        name_of[k] = names[k];
    }
    char error[256];
    bool ok = csv_table_init(table, count, name_of, error, sizeof error);
    for (long i = 0; ok && i < r->frames; ++i) {
        double row[2 + HINGES * HINGE_COLUMNS + MUSCLES * MUSCLE_COLUMNS];
        for (int k = 0; k < count; ++k) {
            row[k] = columns[k][i];
        }
        ok = csv_table_add_row(table, row, error, sizeof error);
    }
    if (!ok) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    return 0;
}

/* The first frame of the window. */
static long window_start(const round_trip *r) { return lround(SETTLE_TIME / r->step); }

static int write_files(const experiment *self, const experiment_options *options, const round_trip *r,
                       const csv_table *table)
{
    const long first = window_start(r);
    const size_t count = (size_t)(r->frames - first);
    chart_series torques[3 * HINGES], activations[2 * MUSCLES], angles[HINGES];
    char labels[3 * HINGES + 2 * MUSCLES + HINGES][96];
    for (int h = 0; h < HINGES; ++h) {
        for (long i = 0; i < r->frames; ++i) {
            r->drift[h][i] = r->replayed[h][i] - r->angle[h][i];
        }
    }
    int label = 0;
    for (int h = 0; h < HINGES; ++h) {
        const double *values[3] = {r->net[h], r->run_torque[h], r->found_torque[h]};
        const char *what[3] = {"inverse dynamics", "first run's muscles", "activations found"};
        for (int k = 0; k < 3; ++k) {
            snprintf(labels[label], sizeof labels[label], "%s: %s", hinge_names[h], what[k]);
            torques[3 * h + k] =
                (chart_series){.label = labels[label++], .x = r->time + first, .y = values[k] + first, .count = count};
        }
        snprintf(labels[label], sizeof labels[label], "%s", hinge_names[h]);
        angles[h] =
            (chart_series){.label = labels[label++], .x = r->time + first, .y = r->drift[h] + first, .count = count};
    }
    for (int m = 0; m < MUSCLES; ++m) {
        const double *values[2] = {r->pattern[m], r->found[m]};
        const char *which[2] = {"pattern", "found"};
        for (int k = 0; k < 2; ++k) {
            snprintf(labels[label], sizeof labels[label], "%s %s", muscle_names[m], which[k]);
            activations[2 * m + k] =
                (chart_series){.label = labels[label++], .x = r->time + first, .y = values[k] + first, .count = count};
        }
    }
    const chart charts[3] = {
        {.title = "torque about each hinge: inverse dynamics, the first run's muscles, the activations found",
         .x_label = "time (s)",
         .y_label = "torque on the distal bone (N·m)",
         .series = torques,
         .series_count = 3 * HINGES},
        {.title = "activations: the pattern and the ones static optimization found (p = 2)",
         .x_label = "time (s)",
         .y_label = "activation",
         .series = activations,
         .series_count = 2 * MUSCLES},
        {.title = "the second run's angle less the first's: the tracking error",
         .x_label = "time (s)",
         .y_label = "angle difference (deg)",
         .series = angles,
         .series_count = HINGES},
    };
    const chart_figure figure = {.charts = charts, .chart_count = 3, .columns = 1, .width = 1000, .height = 1250};
    return experiment_write(self, options, table, &figure);
}

static void print_figures(const round_trip *r)
{
    const long first = window_start(r);
    long unsolved = 0;
    for (long i = first; i < r->frames; ++i) {
        unsolved += r->solved[i] == 0.0;
    }
    printf("window       %.1f s to %.1f s (%ld frames; %ld not solved)\n", r->time[first], r->time[r->frames - 1],
           r->frames - first, unsolved);
    for (int h = 0; h < HINGES; ++h) {
        double low = INFINITY, high = -INFINITY, id_error = 0.0, reserve = 0.0, worst = 0.0, squares = 0.0;
        double at[3] = {0};
        /* The inverse torques against the run's own, leaving out the
         * filter's last half second. */
        for (long i = first; i < r->frames; ++i) {
            low = fmin(low, r->run_torque[h][i]);
            high = fmax(high, r->run_torque[h][i]);
            if (r->time[i] <= SETTLE_TIME + WINDOW_TIME - 0.5) {
                id_error = fmax(id_error, fabs(r->net[h][i] - r->run_torque[h][i]));
            }
            reserve = fmax(reserve, fabs(r->reserve[h][i]));
            const double error = fabs(r->replayed[h][i] - r->angle[h][i]);
            worst = fmax(worst, error);
            squares += error * error;
            for (int k = 0; k < 3; ++k) {
                if (fabs(r->time[i] - (SETTLE_TIME + 1.0 + 1.5 * k)) < 0.5 * r->step) {
                    at[k] = error;
                }
            }
        }
        printf("%-13s inverse vs the run's muscle torques %.1f %% of their range; max |reserve| %.2g N·m\n",
               hinge_names[h], 100.0 * id_error / (high - low), reserve);
        printf("%-13s second run vs first: max |Δθ| %.2f°, rms %.2f°; |Δθ| %.2f°, %.2f°, %.2f° after 1, 2.5, 4 s\n", "",
               worst, sqrt(squares / (double)(r->frames - first)), at[0], at[1], at[2]);
    }
    printf("activation   mean over the window, pattern → found:");
    for (int m = 0; m < MUSCLES; ++m) {
        double pattern = 0.0, found = 0.0;
        for (long i = first; i < r->frames; ++i) {
            pattern += r->pattern[m][i];
            found += r->found[m][i];
        }
        printf("%s %s %.3f → %.3f", m == 0 ? "" : ",", muscle_names[m], pattern / (double)(r->frames - first),
               found / (double)(r->frames - first));
    }
    printf("\n");
}

int experiment_loop_round_trip(const experiment *self, const experiment_options *options)
{
    round_trip r = {0};
    csv_table table = {0};
    int code = run_pattern(&r);
    code = code == 0 ? optimize(&r) : code;
    code = code == 0 ? replay(&r) : code;
    code = code == 0 ? table_of(&r, &table) : code;
    code = code == 0 ? write_files(self, options, &r, &table) : code;
    if (code == 0) {
        print_figures(&r);
    }
    csv_table_free(&table);
    free(r.storage);
    return code;
}
