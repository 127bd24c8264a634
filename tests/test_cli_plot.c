/* SPDX-License-Identifier: MIT */
/* `sinew plot` as a user runs it: a CSV with units in its header becomes
 * a PNG of the documented size, or an SVG; bad arguments (a missing file,
 * an unknown or non-numeric column, an unwritable or unknown output) give
 * one line on stderr, a non-zero status and no figure.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <cairo.h>
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"

static char dir[] = "/tmp/sinew-plot-XXXXXX";

static int run_sinew(const char *args, char *log, size_t log_size)
{
    return run_sinew_capture(dir, args, SINEW_STDOUT_AND_STDERR, log, log_size);
}

static void write_file(const char *name, const char *text)
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fputs(text, f);
    fclose(f);
}

static const char data[] = "time_s,Muscle.total_force_N,Muscle.length_m,note\n"
                           "0,0,0.30,a\n"
                           "0.5,120,0.28,b\n"
                           "1.0,250,0.25,c\n";

Test(cli_plot, draws_a_csv_as_png_and_svg)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("data.csv", data);
    char log[4096];
    cr_assert_eq(run_sinew("plot data.csv", log, sizeof log), 0, "%s", log);
    char path[600];
    snprintf(path, sizeof path, "%s/data.png", dir);
    cairo_surface_t *image = cairo_image_surface_create_from_png(path);
    cr_assert_eq(cairo_surface_status(image), CAIRO_STATUS_SUCCESS, "no PNG at %s: %s", path, log);
    cr_expect_eq(cairo_image_surface_get_width(image), 960);
    cr_expect_eq(cairo_image_surface_get_height(image), 600);
    cairo_surface_destroy(image);
    remove(path);
    cr_expect(strstr(log, "2 series") != NULL, "the text column is left out by default: %s", log);

    cr_assert_eq(
        run_sinew("plot data.csv --x Muscle.length_m --y Muscle.total_force_N --out f.svg --title T", log, sizeof log),
        0, "%s", log);
    snprintf(path, sizeof path, "%s/f.svg", dir);
    cr_expect_eq(access(path, F_OK), 0, "no %s", path);
    remove(path);
    snprintf(path, sizeof path, "%s/data.csv", dir);
    remove(path);
    rmdir(dir);
}

Test(cli_plot, bad_arguments_fail_with_one_line_and_no_figure)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("data.csv", data);
    write_file("ragged.csv", "a,b\n1,2\n3\n");
    const char *cases[] = {
        "plot",
        "plot nosuch.csv",
        "plot data.csv --y nosuch",
        "plot data.csv --x nosuch",
        "plot data.csv --y note",
        "plot data.csv --out /nonexistent/dir/f.png",
        "plot data.csv --out f.jpg",
        "plot data.csv --frobnicate 1",
        "plot data.csv --y",
        "plot data.csv other.csv",
        "plot ragged.csv",
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char log[4096];
        cr_expect_neq(run_sinew(cases[k], log, sizeof log), 0, "'sinew %s' exited 0", cases[k]);
        int lines = 0;
        for (const char *c = log; *c != '\0'; ++c) {
            lines += *c == '\n';
        }
        cr_expect_eq(lines, 1, "'sinew %s' printed %d lines: %s", cases[k], lines, log);
    }
    const char *left[] = {"data.png", "f.jpg", "ragged.png", "nosuch.png"};
    for (size_t k = 0; k < sizeof left / sizeof left[0]; ++k) {
        char path[600];
        snprintf(path, sizeof path, "%s/%s", dir, left[k]);
        cr_expect_neq(access(path, F_OK), 0, "a failed plot left %s", path);
    }
    char path[600];
    snprintf(path, sizeof path, "%s/data.csv", dir);
    remove(path);
    snprintf(path, sizeof path, "%s/ragged.csv", dir);
    remove(path);
    rmdir(dir);
}

/* Values at the ends of what a double holds (a denormal, the widest
 * range) are plotted like any others: a figure and status 0. */
Test(cli_plot, denormal_and_extreme_values_are_plotted)
{
    cr_assert_not_null(mkdtemp(dir));
    const char *tables[] = {"t,y\n0,5e-324\n", "t,y\n0,0\n1,5e-324\n",
                            "t,y\n1e-320,-1.7976931348623157e308\n1e308,1.7976931348623157e308\n", "t,y\n0,-3\n1,-3\n"};
    char log[4096], path[600];
    snprintf(path, sizeof path, "%s/data.png", dir);
    for (size_t k = 0; k < sizeof tables / sizeof tables[0]; ++k) {
        write_file("data.csv", tables[k]);
        cr_expect_eq(run_sinew("plot data.csv", log, sizeof log), 0, "table %zu: %s", k, log);
        cr_expect_eq(access(path, F_OK), 0, "table %zu: no figure", k);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/data.csv", dir);
    remove(path);
    rmdir(dir);
}

/* A solver benchmark's CSV in miniature (bench/bench_solver.c's columns):
 * two scenes, three solvers, one setting that diverged. */
static const char bench[] = "scene,correction,substeps,median_ms,worst_gap_m,diverged\n"
                            "chain,ngs,1,0.02,5.0,no\n"
                            "chain,ngs,2,0.03,0.04,no\n"
                            "chain,soft_step,1,0.01,7.0,no\n"
                            "chain,ngs,4,0.05,1e-4,no\n"
                            "\n"
                            "chain,baumgarte,1,0.01,9.0,no\n"
                            "chain,soft_step,2,0.02,0.06,no\n"
                            "chain,baumgarte,2,0.02,1e6,yes\n"
                            "grid,ngs,1,6.0,3.0,no\n"
                            "grid,ngs,2,9.0,0,no\n";

static bool has_line(const char *log, const char *line)
{
    char wanted[256];
    snprintf(wanted, sizeof wanted, "%s\n", line);
    return strstr(log, wanted) != NULL;
}

Test(cli_plot, group_draws_one_series_per_value_of_a_column)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("bench.csv", bench);
    char log[4096];
    cr_assert_eq(run_sinew("plot bench.csv --where scene=chain --where diverged=no --x median_ms --y worst_gap_m "
                           "--group correction --front --log-x --log-y --out f.svg",
                           log, sizeof log),
                 0, "%s", log);
    /* The chain's 6 rows that did not diverge; per solver, in order of
     * first appearance, its rows, and its front worked out by hand: ngs
     * (0.02, 5), (0.03, 0.04), (0.05, 1e-4) each beat every cheaper one. */
    cr_expect(has_line(log, "f.svg: 6 rows, 3 series against median_ms"), "%s", log);
    cr_expect(has_line(log, "  ngs: 3 points, 3 on the front"), "%s", log);
    cr_expect(has_line(log, "  soft_step: 2 points, 2 on the front"), "%s", log);
    cr_expect(has_line(log, "  baumgarte: 1 points, 1 on the front"), "%s", log);
    char path[600];
    snprintf(path, sizeof path, "%s/f.svg", dir);
    cr_expect_eq(access(path, F_OK), 0, "no %s", path);
    remove(path);

    /* Grouped by a numeric column, without --where: 9 rows (the blank
     * line is none), substeps 1 and 2 and 4. */
    cr_assert_eq(run_sinew("plot bench.csv --x median_ms --y worst_gap_m --group substeps --points --out g.png", log,
                           sizeof log),
                 0, "%s", log);
    cr_expect(has_line(log, "g.png: 9 rows, 3 series against median_ms"), "%s", log);
    cr_expect(has_line(log, "  1: 4 points") && has_line(log, "  2: 4 points") && has_line(log, "  4: 1 points"), "%s",
              log);
    /* Two columns of each group: named by both. */
    cr_assert_eq(run_sinew("plot bench.csv --x median_ms --y worst_gap_m --y substeps --group scene --out g.png", log,
                           sizeof log),
                 0, "%s", log);
    cr_expect(has_line(log, "  chain: worst_gap_m: 7 points") && has_line(log, "  grid: substeps: 2 points"), "%s",
              log);
    snprintf(path, sizeof path, "%s/g.png", dir);
    cr_expect_eq(access(path, F_OK), 0, "no %s", path);
    remove(path);
    snprintf(path, sizeof path, "%s/bench.csv", dir);
    remove(path);
    rmdir(dir);
}

Test(cli_plot, bad_group_where_and_log_values_are_named_with_the_file)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("bench.csv", bench);
    const struct {
        const char *args;
        const char *expected[3];
    } cases[] = {
        {"plot bench.csv --x median_ms --group solver", {"--group \"solver\"", "bench.csv has no such column"}},
        {"plot bench.csv --x median_ms --where solver=ngs", {"--where \"solver\"", "bench.csv has no such column"}},
        {"plot bench.csv --x median_ms --where scene=pyramid",
         {"no row of bench.csv has \"pyramid\" in column \"scene\"", "\"chain\", \"grid\""}},
        {"plot bench.csv --x median_ms --where scene", {"--where \"scene\": expected COLUMN=VALUE"}},
        /* The grid's last row holds a gap of 0, on the file's line 11. */
        {"plot bench.csv --x median_ms --y worst_gap_m --log-y",
         {"bench.csv:11: --log-y: column \"worst_gap_m\" holds 0", "above 0"}},
        {"plot bench.csv --x worst_gap_m --y median_ms --log-x", {"bench.csv:11: --log-x", "\"worst_gap_m\" holds 0"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char log[4096];
        cr_expect_neq(run_sinew(cases[k].args, log, sizeof log), 0, "'sinew %s' exited 0", cases[k].args);
        for (int e = 0; e < 3 && cases[k].expected[e] != NULL; ++e) {
            cr_expect(strstr(log, cases[k].expected[e]) != NULL, "'sinew %s' does not say %s: %s", cases[k].args,
                      cases[k].expected[e], log);
        }
        int lines = 0;
        for (const char *c = log; *c != '\0'; ++c) {
            lines += *c == '\n';
        }
        cr_expect_eq(lines, 1, "'sinew %s' printed %d lines: %s", cases[k].args, lines, log);
    }
    /* Left out with --where, the 0 is no longer in the way. */
    char log[4096];
    cr_expect_eq(run_sinew("plot bench.csv --x median_ms --y worst_gap_m --log-y --where scene=chain", log, sizeof log),
                 0, "%s", log);
    char path[600];
    snprintf(path, sizeof path, "%s/bench.png", dir);
    cr_expect_eq(access(path, F_OK), 0, "no %s", path);
    remove(path);
    snprintf(path, sizeof path, "%s/bench.csv", dir);
    remove(path);
    rmdir(dir);
}
