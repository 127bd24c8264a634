/* The seed's experiments (experiments.md) as `sinew experiment` runs
 * them, each qualitative result of the report turned into a measured
 * one, read from the CSV the command writes:
 *   E1   the contraction rises, then returns to rest;
 *   E2   along the relaxation the active force falls and the passive
 *        force rises monotonically with length;
 *   E3.1 with >= 300 N held, the biceps belly length changes < 1 %;
 *   E3.2 during the plateau the tension stays within 5 % of its target
 *        while the length falls; afterwards the muscle lengthens;
 *   E4   two pulses peak higher than one, the train higher than two;
 *   C1   seed 003's family of curves against its closed form.
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

/* Runs experiment `name` into a fresh directory and reads DIR/STEM.csv;
 * checks that the PNG and the SVG were written beside it. */
static void run_experiment(const char *name, const char *options, const char *stem, csv_table *table)
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
    snprintf(path, sizeof path, "%s/log.txt", dir);
    remove(path);
    rmdir(dir);
    strcpy(dir, "/tmp/sinew-experiment-XXXXXX");
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
 * (tools/experiment_pulses.c, experiment_tension.c). */
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

Test(experiment, e1_pulses_have_the_asked_width_in_substeps)
{
    const struct {
        const char *option;
        long substeps; /* at 600 Hz */
    } cases[] = {{"", 10}, {"--pulse-width 0.002", 1}, {"--pulse-width 0.05", 30}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        csv_table table;
        run_experiment("e1", cases[k].option, "e1_twitch", &table);
        const double *activation = column(&table, "Biceps Long.activation");
        long on = 0;
        for (long r = 0; r < table.row_count; ++r) {
            on += activation[r] == 1.0;
        }
        cr_expect_eq(on, cases[k].substeps, "'%s': %ld substeps at activation 1, expected %ld", cases[k].option, on,
                     cases[k].substeps);
        csv_table_free(&table);
    }
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
    /* The seed: "a much larger contraction". */
    cr_expect(peaks[2] - rest > 2.0 * (peaks[0] - rest), "train rise %.4f, one pulse's %.4f", peaks[2] - rest,
              peaks[0] - rest);
    csv_table_free(&table);
}

/* Seed 003's total force (framework.md §9), written out here from its
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

/* The knots of `curve` in the seed's table file (lines curve,x,y). */
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
     * values (it never overshoots), both clamped outside. */
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
            cr_expect(fabs(linear[r] - expected) <= 1e-9, "%s linear at %g: %.9g, expected %.9g", curves[k][0], x[r],
                      linear[r], expected);
            double low = fmin(knot_y[i], knot_y[i + 1]), high = fmax(knot_y[i], knot_y[i + 1]);
            cr_expect(steffen[r] >= low - 1e-9 && steffen[r] <= high + 1e-9, "%s Steffen at %g: %.6g outside [%g, %g]",
                      curves[k][0], x[r], steffen[r], low, high);
        }
    }
    csv_table_free(&table);
}

Test(experiment, bad_arguments_fail_and_an_unknown_name_lists_the_experiments)
{
    cr_assert_not_null(mkdtemp(dir));
    char log[8192];
    cr_expect_neq(run_sinew("experiment"), 0);
    read_log(log, sizeof log);
    const char *names[] = {"e1", "e2", "e3.1", "e3.2", "e4", "c1"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        cr_expect(strstr(log, names[k]) != NULL, "the list lacks %s: %s", names[k], log);
    }
    cr_expect_neq(run_sinew("experiment nosuch"), 0);
    read_log(log, sizeof log);
    cr_expect(strstr(log, "unknown experiment \"nosuch\"") != NULL && strstr(log, "e3.2") != NULL, "%s", log);
    const char *one_line[] = {
        "experiment e1 --pulse-width 0",
        "experiment e1 --pulse-width 2",
        "experiment e1 --pulse-width abc",
        "experiment e1 --out /nonexistent/dir",
        "experiment e1 --frobnicate 1",
        "experiment e1 e2",
        "experiment e1 --out",
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
    char path[600];
    snprintf(path, sizeof path, "%s/log.txt", dir);
    remove(path);
    rmdir(dir);
}
