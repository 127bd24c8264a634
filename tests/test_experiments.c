/* SPDX-License-Identifier: MIT */
/* The experiments of Castanyer's report ("Implementació d'un model
 * computacional de sistemes musculoesquelètics", 2023-24; docs/validation.md)
 * as `sinew experiment` runs them, each qualitative result of the report
 * turned into a measured
 * one, read from the CSV the command writes:
 *   E1   the contraction rises, then returns to rest;
 *   E2   along the relaxation the active force falls and the passive
 *        force rises monotonically with length;
 *   E3.1 with >= 300 N held, the biceps belly length changes < 1 %;
 *   E3.2 during the plateau the tension stays within 5 % of its target
 *        while the length falls; afterwards the muscle lengthens;
 *   E4   two pulses peak higher than one, the train higher than two;
 *   C1   the MATLAB Hill worksheet's family of curves against its closed form;
 *   P1   the isometric twitch rises and relaxes, relaxing slower than it
 *        contracts; with the rigid tendon the force is the activation's,
 *        checked against the closed form and an independent integration
 *        of Millard's first-order dynamics; with the compliant tendon a
 *        train fuses by 200 Hz at more than twice the twitch's force;
 *   R1   exertion 0 with no neuron, 1 with all, convex, the cumulative
 *        sum of the worm's strengths worked out here.
 * Also: each writes a PNG and an SVG; --pulse-width gives pulses of whole
 * substeps; bad arguments fail with one line (an unknown name lists the
 * experiments).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/csv_table.h"
#include "worm_pool_image.h"

static char dir[] = "/tmp/sinew-experiment-XXXXXX";

/* Runs `sinew ARGS` with its output in DIR/log.txt; returns its exit status. */
static int run_sinew(const char *args)
{
    char command[2048];
    snprintf(command, sizeof command, "'%s' %s > '%s/log.txt' 2>&1", SINEW_TOOL, args, dir);
    const int status = system(command);
    cr_assert(status != -1 && WIFEXITED(status), "could not run: %s", command);
    return WEXITSTATUS(status);
}

static void read_log(char *text, size_t size)
{
    char path[600];
    snprintf(path, sizeof path, "%s/log.txt", dir);
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f);
    size_t n = fread(text, 1, size - 1, f);
    text[n] = '\0';
    fclose(f);
}

/* Runs experiment `name` into a fresh directory and reads DIR/STEM.csv,
 * and DIR/STEM_PART.csv into `part_table` when `part` is not NULL;
 * checks that the PNG and the SVG were written beside it. */
static void run_experiment_parts(const char *name, const char *options, const char *stem, const char *part,
                                 csv_table *table, csv_table *part_table)
{
    cr_assert_not_null(mkdtemp(dir));
    char args[1024];
    snprintf(args, sizeof args, "experiment %s --out '%s' %s", name, dir, options);
    char log[8192];
    int status = run_sinew(args);
    read_log(log, sizeof log);
    cr_assert_eq(status, 0, "sinew %s failed: %s", args, log);
    const char *extensions[] = {"png", "svg"};
    for (int k = 0; k < 2; ++k) {
        char path[600];
        snprintf(path, sizeof path, "%s/%s.%s", dir, stem, extensions[k]);
        cr_expect_eq(access(path, F_OK), 0, "no %s", path);
        remove(path);
    }
    char path[600], error[1024];
    snprintf(path, sizeof path, "%s/%s.csv", dir, stem);
    cr_assert(csv_table_read(path, table, error, sizeof error), "%s", error);
    remove(path);
    if (part != NULL) {
        snprintf(path, sizeof path, "%s/%s_%s.csv", dir, stem, part);
        cr_assert(csv_table_read(path, part_table, error, sizeof error), "%s", error);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/log.txt", dir);
    remove(path);
    rmdir(dir);
    strcpy(dir, "/tmp/sinew-experiment-XXXXXX");
}

static void run_experiment(const char *name, const char *options, const char *stem, csv_table *table)
{
    run_experiment_parts(name, options, stem, NULL, table, NULL);
}

/* |actual - expected| <= tolerance·|expected|, and actual is a number. */
static void expect_near_relative(double actual, double expected, double tolerance, const char *what)
{
    cr_expect(fabs(actual - expected) <= tolerance * fabs(expected), "%s: %.15g, expected %.15g", what, actual,
              expected);
}

static const double *column(const csv_table *table, const char *name)
{
    int c = csv_table_find(table, name);
    cr_assert(c >= 0, "no column \"%s\"", name);
    return table->columns[c].values;
}

/* The first row at or after `time`. */
static long row_at(const csv_table *table, double time)
{
    const double *t = column(table, "time_s");
    long r = 0;
    while (r < table->row_count && t[r] < time - 1e-9) {
        ++r;
    }
    return r;
}

/* The arm hangs at rest by 3 s, when the experiments act
 * (tools/experiments/e1_e4_pulses.c, e3_tension.c). */
#define ACTION_TIME 3.0

Test(experiment, e1_the_twitch_rises_then_returns_to_rest)
{
    csv_table table;
    run_experiment("e1", "", "e1_twitch", &table);
    const double *time = column(&table, "time_s");
    const double *contraction = column(&table, "Biceps Long.normalized_contraction");
    long start = row_at(&table, ACTION_TIME);
    double rest = contraction[start - 1];
    /* At rest before the pulse: still within 1e-4 over the last 0.5 s. */
    for (long r = row_at(&table, ACTION_TIME - 0.5); r < start; ++r) {
        cr_expect(fabs(contraction[r] - rest) < 1e-4, "not at rest at %.3f s: %g against %g", time[r], contraction[r],
                  rest);
    }
    long peak = start;
    for (long r = start; r < table.row_count; ++r) {
        peak = contraction[r] > contraction[peak] ? r : peak;
    }
    double rise = contraction[peak] - rest;
    /* It rises: by more than 1 % of the rest length, after the pulse. */
    cr_expect(rise > 0.01, "the twitch rose by %g of the rest length", rise);
    cr_expect(time[peak] > ACTION_TIME + 0.02 && time[peak] < ACTION_TIME + 0.5, "peak at %.3f s", time[peak]);
    /* And returns to rest: over the last second within 5 % of the rise. */
    for (long r = row_at(&table, time[table.row_count - 1] - 1.0); r < table.row_count; ++r) {
        cr_expect(fabs(contraction[r] - rest) <= 0.05 * rise, "at %.3f s %g, at rest %g (rise %g)", time[r],
                  contraction[r], rest, rise);
    }
    csv_table_free(&table);
}

/* A run of an experiment with its --pulse-width option (or none), and
 * how many substeps its pulse should then last. */
typedef struct pulse_case {
    const char *option;
    long substeps;
} pulse_case;

/* Runs `experiment` for each case and counts the rows of its CSV `stem`
 * where `column_name` is 1: the substeps the pulse lasted. */
static void expect_pulse_widths(const char *experiment, const char *stem, const char *column_name,
                                const pulse_case *cases, size_t count)
{
    for (size_t k = 0; k < count; ++k) {
        csv_table table;
        run_experiment(experiment, cases[k].option, stem, &table);
        const double *values = column(&table, column_name);
        long on = 0;
        for (long r = 0; r < table.row_count; ++r) {
            on += values[r] == 1.0;
        }
        cr_expect_eq(on, cases[k].substeps, "%s '%s': %ld substeps at %s 1, expected %ld", experiment, cases[k].option,
                     on, column_name, cases[k].substeps);
        csv_table_free(&table);
    }
}

Test(experiment, e1_pulses_have_the_asked_width_in_substeps)
{
    /* At 600 Hz. */
    const pulse_case cases[] = {{"", 10}, {"--pulse-width 0.002", 1}, {"--pulse-width 0.05", 30}};
    expect_pulse_widths("e1", "e1_twitch", "Biceps Long.activation", cases, sizeof cases / sizeof cases[0]);
}

Test(experiment, e2_active_force_falls_and_passive_rises_with_length)
{
    csv_table table;
    run_experiment("e2", "", "e2_relaxation", &table);
    const double *length = column(&table, "Muscle.normalized_length");
    const double *active = column(&table, "Muscle.active_force_N");
    const double *passive = column(&table, "Muscle.passive_force_N");
    /* The relaxation: activation from 1 at 2 s to 0 at 5 s. */
    long first = row_at(&table, 2.0 + 1e-6), end = row_at(&table, 5.0 + 1e-6);
    cr_assert(end - first > 1000, "%ld rows in the relaxation", end - first);
    double start_active = active[first];
    cr_expect(start_active > 400.0, "active force %g N at activation 1 (the weight is 490 N)", start_active);
    cr_expect(active[end - 1] < 1.0, "active force %g N at activation 0", active[end - 1]);
    /* Falls: never up by more than 0.1 % of its start from one substep to
     * the next (the implicit solve's iterations leave ~0.01 % of noise). */
    for (long r = first + 1; r < end; ++r) {
        cr_expect(active[r] <= active[r - 1] + 1e-3 * start_active, "active force up from %g to %g N at row %ld",
                  active[r - 1], active[r], r);
    }
    cr_expect(length[end - 1] > length[first] + 0.3, "the muscle lengthened from %g to %g", length[first],
              length[end - 1]);
    cr_expect(passive[end - 1] > passive[first] + 100.0, "passive force from %g to %g N", passive[first],
              passive[end - 1]);
    /* Passive force against length, over every pair of rows: a longer
     * muscle never carries less passive force. */
    long disorder = 0;
    for (long r = first; r < end; ++r) {
        for (long s = first; s < end; s += 7) {
            disorder += length[s] > length[r] && passive[s] < passive[r];
        }
    }
    cr_expect_eq(disorder, 0, "%ld pairs where a longer muscle had less passive force", disorder);
    csv_table_free(&table);
}

Test(experiment, e3_1_isometric_length_holds_within_one_percent)
{
    csv_table table;
    run_experiment("e3.1", "", "e3_1_isometric", &table);
    const double *time = column(&table, "time_s");
    const double *length = column(&table, "Biceps Short.length_m");
    const double *active = column(&table, "Biceps Short.active_force_N");
    double shortest = INFINITY, longest = -INFINITY, held_from = NAN, held_to = NAN;
    long held = 0;
    for (long r = 0; r < table.row_count; ++r) {
        if (active[r] >= 300.0) {
            shortest = fmin(shortest, length[r]);
            longest = fmax(longest, length[r]);
            held_from = held == 0 ? time[r] : held_from;
            held_to = time[r];
            ++held;
        }
    }
    /* "hold a few seconds": 600 substeps a second. */
    cr_assert(held > 2 * 600, "300 N or more held for %ld substeps only", held);
    double change = (longest - shortest) / shortest;
    cr_expect(change < 0.01, "with >= 300 N (%.2f .. %.2f s) the length went %.4f .. %.4f m (%.2f %%)", held_from,
              held_to, shortest, longest, 100.0 * change);
    csv_table_free(&table);
}

Test(experiment, e3_2_isotonic_constant_tension_while_shortening_then_lengthens)
{
    csv_table table;
    run_experiment("e3.2", "", "e3_2_isotonic", &table);
    const double *time = column(&table, "time_s");
    const double *target = column(&table, "Biceps Short.target_tension_N");
    const double *active = column(&table, "Biceps Short.active_force_N");
    const double *length = column(&table, "Biceps Short.length_m");
    double plateau = 0.0;
    for (long r = 0; r < table.row_count; ++r) {
        plateau = fmax(plateau, target[r]);
    }
    long first = -1, last = -1;
    for (long r = 0; r < table.row_count; ++r) {
        if (target[r] >= plateau - 1e-9) {
            first = first < 0 ? r : first;
            last = r;
        }
    }
    cr_assert(first >= 0 && last - first > 300, "a plateau of %ld substeps", last - first);
    for (long r = first; r <= last; ++r) {
        cr_expect(fabs(active[r] - plateau) <= 0.05 * plateau, "at %.3f s the tension is %.1f N, target %.0f N",
                  time[r], active[r], plateau);
        if (r > first) {
            cr_expect(length[r] <= length[r - 1], "the length rose at %.3f s: %.6f -> %.6f m", time[r], length[r - 1],
                      length[r]);
        }
    }
    cr_expect(length[last] < 0.97 * length[first], "over the plateau the length went from %.4f to %.4f m",
              length[first], length[last]);
    /* Afterwards: no tension, and the muscle lengthens (eccentric). */
    long end = table.row_count - 1;
    cr_expect(active[end] < 1.0, "%.2f N of active force at the end", active[end]);
    cr_expect(length[end] > 1.05 * length[last], "after the plateau the length went from %.4f to %.4f m", length[last],
              length[end]);
    csv_table_free(&table);
}

Test(experiment, e4_two_pulses_peak_higher_than_one_and_the_train_higher_than_two)
{
    csv_table table;
    run_experiment("e4", "", "e4_summation", &table);
    const char *runs[3] = {"one_pulse.normalized_contraction", "two_pulses.normalized_contraction",
                           "train_8Hz.normalized_contraction"};
    long start = row_at(&table, ACTION_TIME);
    double peaks[3];
    for (int k = 0; k < 3; ++k) {
        const double *contraction = column(&table, runs[k]);
        peaks[k] = -INFINITY;
        for (long r = start; r < table.row_count; ++r) {
            peaks[k] = isnan(contraction[r]) ? peaks[k] : fmax(peaks[k], contraction[r]);
        }
    }
    const double *one = column(&table, runs[0]);
    double rest = one[start - 1];
    cr_expect(peaks[1] > peaks[0], "two pulses peak at %.4f, one at %.4f", peaks[1], peaks[0]);
    cr_expect(peaks[2] > peaks[1], "the train peaks at %.4f, two pulses at %.4f", peaks[2], peaks[1]);
    /* The report: "a much larger contraction". */
    cr_expect(peaks[2] - rest > 2.0 * (peaks[0] - rest), "train rise %.4f, one pulse's %.4f", peaks[2] - rest,
              peaks[0] - rest);
    csv_table_free(&table);
}

/* The total force of the MATLAB worksheet "1D Muscle Model based on the
 * Hill 2-Element Model", written out here from its
 * formulas: F = F_MAX·(f_L·f_V + max(F_PE, 0)), f_L = exp(-((l-1)/0.25)²),
 * f_V = (1 - V')/(1 + V'/0.05), F_PE = 0.01·(exp(10·(l-1)) - 1). */
static double seed003_force(double length_mm, double shortening)
{
    double l = length_mm / 0.5;
    double fl = exp(-pow((l - 1.0) / 0.25, 2.0));
    double fv = (1.0 - shortening) / (1.0 + shortening / 0.05);
    double passive = fmax(0.01 * (exp(10.0 * (l - 1.0)) - 1.0), 0.0);
    return 5.0 * (fl * fv + passive);
}

/* The knots of `curve` in the curve table file (lines curve,x,y). */
static int read_knots(const char *curve, double *x, double *y, int capacity)
{
    FILE *f = fopen(SINEW_SOURCE_DIR "/models/data/hill-curves.csv", "r");
    cr_assert_not_null(f);
    char line[256], name[64];
    int count = 0;
    while (fgets(line, sizeof line, f) != NULL && count < capacity) {
        double a, b;
        if (sscanf(line, "%63[^,],%lf,%lf", name, &a, &b) == 3 && strcmp(name, curve) == 0) {
            x[count] = a;
            y[count] = b;
            ++count;
        }
    }
    fclose(f);
    return count;
}

Test(experiment, c1_curves_match_seed003s_closed_form_and_the_tables)
{
    csv_table table;
    run_experiment("c1", "", "c1_hill_curves", &table);
    const double *length = column(&table, "seed003.length_mm");
    for (int i = 0; i <= 15; ++i) {
        char name[80];
        snprintf(name, sizeof name, "seed003.total_force.shortening_%.3fVmax_N", i / 100.0);
        const double *force = column(&table, name);
        for (long r = 0; r < table.row_count; ++r) {
            double expected = seed003_force(length[r], i / 100.0);
            cr_expect(fabs(force[r] - expected) <= 1e-6 * fmax(1.0, expected), "%s at %.4f mm: %.9g N, expected %.9g",
                      name, length[r], force[r], expected);
        }
    }
    /* The tables against their knots in models/data/hill-curves.csv:
     * linear interpolation exactly, Steffen's within each interval's
     * values (it never overshoots), both clamped outside, except where
     * docs/muscle.md ends them at 0: f_L outside its table, f_V from
     * ṽ = -1 down. */
    const char *curves[3][3] = {
        {"active_force_length", "normalized_length", "active_force_length"},
        {"passive_force_length", "normalized_length", "passive_force_length"},
        {"force_velocity", "normalized_velocity", "force_velocity"},
    };
    for (int k = 0; k < 3; ++k) {
        double knot_x[128], knot_y[128];
        int knots = read_knots(curves[k][0], knot_x, knot_y, 128);
        cr_assert(knots >= 2, "%s: %d knots", curves[k][0], knots);
        const double *x = column(&table, curves[k][1]);
        char name[80];
        snprintf(name, sizeof name, "%s.table_linear", curves[k][2]);
        const double *linear = column(&table, name);
        snprintf(name, sizeof name, "%s.table_steffen", curves[k][2]);
        const double *steffen = column(&table, name);
        for (long r = 0; r < table.row_count; ++r) {
            int i = 0;
            while (i < knots - 2 && x[r] > knot_x[i + 1]) {
                ++i;
            }
            double u = fmin(fmax((x[r] - knot_x[i]) / (knot_x[i + 1] - knot_x[i]), 0.0), 1.0);
            double expected = knot_y[i] + u * (knot_y[i + 1] - knot_y[i]);
            const bool zero = (k == 0 && (x[r] < knot_x[0] || x[r] > knot_x[knots - 1])) || (k == 2 && x[r] <= -1.0);
            expected = zero ? 0.0 : expected;
            cr_expect(fabs(linear[r] - expected) <= 1e-9, "%s linear at %g: %.9g, expected %.9g", curves[k][0], x[r],
                      linear[r], expected);
            double low = zero ? 0.0 : fmin(knot_y[i], knot_y[i + 1]),
                   high = zero ? 0.0 : fmax(knot_y[i], knot_y[i + 1]);
            cr_expect(steffen[r] >= low - 1e-9 && steffen[r] <= high + 1e-9, "%s Steffen at %g: %.6g outside [%g, %g]",
                      curves[k][0], x[r], steffen[r], low, high);
        }
    }
    csv_table_free(&table);
}

/* P1 (tools/experiments/p1_twitch_tetanus.c): the pulses' onset is at
 * time 0 of STEM.csv; substeps of 1/6000 s; Millard's time constants. */
#define P1_SUBSTEP (1.0 / 6000.0)
#define TAU_ACT 0.010
#define TAU_DEACT 0.040
static const char *const p1_tendons[2] = {"rigid_tendon", "compliant_tendon"};

typedef struct twitch_times {
    double peak, time_to_peak, half_relaxation; /* N, s, s */
} twitch_times;

/* Measured here from the trace, to the nearest substep. */
static twitch_times measure_twitch(const double *time, const double *force, long rows)
{
    long peak = 0;
    for (long r = 0; r < rows; ++r) {
        peak = force[r] > force[peak] ? r : peak;
    }
    long half = peak;
    while (half < rows && force[half] > 0.5 * force[peak]) {
        ++half;
    }
    cr_assert(half < rows, "the twitch never fell to half of its peak %g N", force[peak]);
    return (twitch_times){force[peak], time[peak], time[half] - time[peak]};
}

Test(experiment, p1_twitch_rises_and_relaxes_slower_than_it_contracts)
{
    csv_table table;
    run_experiment("p1", "", "p1_twitch_tetanus", &table);
    const double *time = column(&table, "time_s");
    long onset = row_at(&table, 0.0);
    for (int t = 0; t < 2; ++t) {
        char name[96];
        snprintf(name, sizeof name, "%s.twitch.developed_force_N", p1_tendons[t]);
        const double *force = column(&table, name);
        for (long r = 0; r < onset; ++r) {
            cr_expect(fabs(force[r]) < 1e-6, "%s: %g N at rest, %.4f s", name, force[r], time[r]);
        }
        twitch_times twitch = measure_twitch(time, force, table.row_count);
        cr_expect(twitch.peak > 10.0, "%s: the twitch peaks at %g N", name, twitch.peak);
        cr_expect(twitch.half_relaxation > twitch.time_to_peak, "%s: half-relaxation %.1f ms, time to peak %.1f ms",
                  name, 1e3 * twitch.half_relaxation, 1e3 * twitch.time_to_peak);
        double last = force[table.row_count - 1];
        cr_expect(last >= 0.0 && last < 0.05 * twitch.peak, "%s: %g N at %.2f s, peak %g N", name, last,
                  time[table.row_count - 1], twitch.peak);
    }
    csv_table_free(&table);
}

/* Millard's activation from rest under excitation 1 for `duration` s:
 * da/dt = (1 - a)/(τ_act·(0.5 + 1.5·a)) separates into
 * t(a) = τ_act·(-1.5·a - 2·ln(1 - a)), solved here by bisection. */
static double activation_after_pulse(double duration)
{
    double low = 0.0, high = 1.0;
    for (int i = 0; i < 100; ++i) {
        double a = 0.5 * (low + high);
        double t = TAU_ACT * (-1.5 * a - 2.0 * log(1.0 - a));
        *(t < duration ? &low : &high) = a;
    }
    return 0.5 * (low + high);
}

Test(experiment, p1_rigid_tendon_twitch_is_the_activations_closed_form)
{
    /* With a rigid tendon between static bodies the fibre cannot move:
     * the developed force is a·Fmax·f_L(1)·f_V(0), the activation's
     * shape. From rest a 2 ms pulse raises a to a_p (above); then u = 0,
     * da/dt = -a·(0.5 + 1.5·a)/τ_deact, which separates into a
     * half-relaxation time of 2·τ_deact·ln((1 + 1.5·a_p)/(0.5 + 1.5·a_p)). */
    csv_table table;
    run_experiment("p1", "", "p1_twitch_tetanus", &table);
    const double *time = column(&table, "time_s");
    const double *activation = column(&table, "twitch.activation");
    const double *force = column(&table, "rigid_tendon.twitch.developed_force_N");
    double a_p = activation_after_pulse(0.002);
    twitch_times twitch = measure_twitch(time, force, table.row_count);
    double peak_activation = 0.0;
    for (long r = 0; r < table.row_count; ++r) {
        peak_activation = fmax(peak_activation, activation[r]);
    }
    double scale = twitch.peak / peak_activation; /* Fmax·f_L(1)·f_V(0) */
    for (long r = row_at(&table, 0.0); r < table.row_count; ++r) {
        cr_expect(fabs(force[r] - scale * activation[r]) <= 1e-8 * twitch.peak,
                  "at %.4f s the force %g N is not the activation %g times %g N", time[r], force[r], activation[r],
                  scale);
    }
    expect_near_relative(peak_activation, a_p, 1e-3, "the twitch's peak activation");
    cr_expect(fabs(twitch.time_to_peak - 0.002) < 0.5 * P1_SUBSTEP, "time to peak %.4f ms, the pulse is 2 ms",
              1e3 * twitch.time_to_peak);
    double half = 2.0 * TAU_DEACT * log((1.0 + 1.5 * a_p) / (0.5 + 1.5 * a_p));
    cr_expect(fabs(twitch.half_relaxation - half) <= 2.0 * P1_SUBSTEP, "half-relaxation %.3f ms, closed form %.3f ms",
              1e3 * twitch.half_relaxation, 1e3 * half);
    csv_table_free(&table);
}

/* Millard's da/dt for excitation u (activation.h), written out here. */
static double activation_rate(double a, double u)
{
    double tau = u > a ? TAU_ACT * (0.5 + 1.5 * a) : TAU_DEACT / (0.5 + 1.5 * a);
    return (u - a) / tau;
}

/* The periodic state of a train of 2 ms pulses at `rate` Hz, by classic
 * Runge-Kutta at a tenth of the tool's substep for 1.5 s: the ripple
 * (max - min)/mean of the activation over the last period. */
static double activation_ripple(double rate)
{
    const int fine = 10;
    const double h = P1_SUBSTEP / fine;
    const long period = lround(1.0 / (rate * P1_SUBSTEP)) * fine, width = 12 * fine;
    const long steps = (lround(1.5 / P1_SUBSTEP) * fine / period + 1) * period;
    double a = 0.0, low = INFINITY, high = -INFINITY, sum = 0.0;
    for (long k = 0; k < steps; ++k) {
        double u = k % period < width ? 1.0 : 0.0;
        double k1 = activation_rate(a, u), k2 = activation_rate(a + 0.5 * h * k1, u);
        double k3 = activation_rate(a + 0.5 * h * k2, u), k4 = activation_rate(a + h * k3, u);
        a += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if (k >= steps - period && (k + 1) % fine == 0) {
            low = fmin(low, a);
            high = fmax(high, a);
            sum += a;
        }
    }
    return (high - low) / (sum / (double)(period / fine));
}

Test(experiment, p1_rigid_tendon_ripple_is_first_order_activations)
{
    /* The force is the activation's: its ripple over a train's last
     * cycles is the activation's, integrated here independently of the
     * muscle's exponential midpoint step. */
    csv_table traces, sweep;
    run_experiment_parts("p1", "", "p1_twitch_tetanus", "sweep", &traces, &sweep);
    const double *rate = column(&sweep, "frequency_Hz");
    const double *ripple = column(&sweep, "rigid_tendon.ripple");
    cr_assert_eq(sweep.row_count, 18, "%ld rates in the sweep", sweep.row_count);
    cr_expect(rate[0] == 1.0 && rate[sweep.row_count - 1] == 400.0, "the sweep covers %g .. %g Hz", rate[0],
              rate[sweep.row_count - 1]);
    for (long r = 0; r < sweep.row_count; ++r) {
        double expected = activation_ripple(rate[r]);
        cr_expect(fabs(ripple[r] - expected) <= 0.01 * expected + 1e-3, "%g Hz: ripple %.5f, first order %.5f", rate[r],
                  ripple[r], expected);
    }
    csv_table_free(&traces);
    csv_table_free(&sweep);
}

Test(experiment, p1_trains_fuse_by_200_Hz_at_over_twice_the_twitch_with_a_compliant_tendon)
{
    /* The demands: some train up to 200 Hz with a ripple under
     * 5 %, and tetanic force (the largest mean up to 200 Hz) at least
     * twice the twitch's peak. The rigid tendon gives the ratio but
     * fuses only above 200 Hz (its ripple is the activation's, checked
     * above); the compliant one meets both. */
    csv_table traces, sweep;
    run_experiment_parts("p1", "", "p1_twitch_tetanus", "sweep", &traces, &sweep);
    const double *time = column(&traces, "time_s");
    const double *rate = column(&sweep, "frequency_Hz");
    for (int t = 0; t < 2; ++t) {
        char name[96];
        snprintf(name, sizeof name, "%s.twitch.developed_force_N", p1_tendons[t]);
        twitch_times twitch = measure_twitch(time, column(&traces, name), traces.row_count);
        snprintf(name, sizeof name, "%s.mean_developed_force_N", p1_tendons[t]);
        const double *mean = column(&sweep, name);
        snprintf(name, sizeof name, "%s.ripple", p1_tendons[t]);
        const double *ripple = column(&sweep, name);
        double tetanic = 0.0, fusion = NAN;
        for (long r = sweep.row_count - 1; r >= 0; --r) {
            tetanic = rate[r] <= 200.0 ? fmax(tetanic, mean[r]) : tetanic;
            fusion = ripple[r] < 0.05 ? rate[r] : fusion;
        }
        cr_expect(tetanic >= 2.0 * twitch.peak, "%s: tetanic %.1f N, twitch %.1f N", p1_tendons[t], tetanic,
                  twitch.peak);
        if (t == 1) {
            cr_expect(fusion <= 200.0, "%s: fuses at %g Hz", p1_tendons[t], fusion);
        }
    }
    csv_table_free(&traces);
    csv_table_free(&sweep);
}

Test(experiment, p1_pulses_have_the_asked_width_in_substeps)
{
    /* At 6000 Hz. */
    const pulse_case cases[] = {{"", 12}, {"--pulse-width 0.005", 30}, {"--pulse-width 0.00001", 1}};
    expect_pulse_widths("p1", "p1_twitch_tetanus", "twitch.excitation", cases, sizeof cases / sizeof cases[0]);
}

Test(experiment, r1_exertion_is_the_cumulative_share_of_the_worms_pool)
{
    /* models/worm.json: 200 neurons read from models/worm-pool.png, which
     * draws s_i = 100^(i/199) on the white-to-red scale (255 − blue =
     * 2.55·s_i to a 16-bit step, worm_pool_image.h), weakest first; peak
     * torque 0.01 N·m. */
    csv_table table;
    run_experiment("r1", "", "r1_recruitment", &table);
    const double *neurons = column(&table, "recruited_neurons");
    const double *exertion = column(&table, "exertion");
    const double *strength = column(&table, "last_recruited_strength");
    const double *torque = column(&table, "torque_N_m");
    cr_assert_eq(table.row_count, 201, "%ld rows", table.row_count);
    double total = 0.0;
    for (int i = 0; i < 200; ++i) {
        total += worm_pool_image_strength(i);
    }
    double sum = 0.0;
    for (long n = 0; n <= 200; ++n) {
        cr_expect_eq(neurons[n], (double)n);
        if (n > 0) {
            double s = worm_pool_image_strength((int)n - 1);
            sum += s;
            expect_near_relative(strength[n], s, 1e-9, "a neuron's strength");
        }
        expect_near_relative(exertion[n], sum / total, 1e-9, "the exertion");
        expect_near_relative(torque[n], 0.01 * exertion[n], 1e-9, "the torque");
        if (n >= 2) {
            cr_expect(exertion[n] - exertion[n - 1] >= exertion[n - 1] - exertion[n - 2],
                      "not convex at %ld neurons: %.12g, %.12g, %.12g", n, exertion[n - 2], exertion[n - 1],
                      exertion[n]);
        }
    }
    cr_expect_eq(exertion[0], 0.0, "no neuron exerts %g", exertion[0]);
    expect_near_relative(exertion[200], 1.0, 1e-12, "every neuron");
    /* The worm's pool: the first 30 % give about 3 % of the force. */
    cr_expect(exertion[60] > 0.02 && exertion[60] < 0.04, "30 %% of the pool exert %.4f", exertion[60]);
    csv_table_free(&table);
}

Test(experiment, bad_arguments_fail_and_an_unknown_name_lists_the_experiments)
{
    cr_assert_not_null(mkdtemp(dir));
    char log[8192];
    cr_expect_neq(run_sinew("experiment"), 0);
    read_log(log, sizeof log);
    const char *names[] = {"e1", "e2", "e3.1", "e3.2", "e4", "c1", "p1", "r1"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        cr_expect(strstr(log, names[k]) != NULL, "the list lacks %s: %s", names[k], log);
    }
    cr_expect_neq(run_sinew("experiment nosuch"), 0);
    read_log(log, sizeof log);
    cr_expect(strstr(log, "unknown experiment \"nosuch\"") != NULL && strstr(log, "e3.2") != NULL, "%s", log);
    const char *one_line[] = {
        "experiment",
        "experiment nosuch",
        "experiment e1 --pulse-width 0",
        "experiment e1 --pulse-width 2",
        "experiment e1 --pulse-width abc",
        "experiment e1 --out /nonexistent/dir",
        "experiment e1 --frobnicate 1",
        "experiment e1 e2",
        "experiment e1 --out",
        "experiment p1 --pulse-width 0.2",
        "experiment r1 --pulse-width 0.002",
    };
    for (size_t k = 0; k < sizeof one_line / sizeof one_line[0]; ++k) {
        cr_expect_neq(run_sinew(one_line[k]), 0, "'sinew %s' exited 0", one_line[k]);
        read_log(log, sizeof log);
        int lines = 0;
        for (const char *c = log; *c != '\0'; ++c) {
            lines += *c == '\n';
        }
        cr_expect_eq(lines, 1, "'sinew %s' printed %d lines: %s", one_line[k], lines, log);
    }
    /* Refused before anything is written. */
    char args[700], stray[600];
    snprintf(args, sizeof args, "experiment p1 --pulse-width 0.5 --out '%s'", dir);
    cr_expect_eq(run_sinew(args), 2, "'sinew %s' is a usage error", args);
    const char *files[] = {"p1_twitch_tetanus_sweep.csv", "p1_twitch_tetanus.csv", "p1_twitch_tetanus.png"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; ++k) {
        snprintf(stray, sizeof stray, "%s/%s", dir, files[k]);
        cr_expect_neq(access(stray, F_OK), 0, "%s was written", stray);
    }
    char path[600];
    snprintf(path, sizeof path, "%s/log.txt", dir);
    remove(path);
    rmdir(dir);
}
