/* SPDX-License-Identifier: MIT */
/* `sinew run`'s options for sweeps: --summary writes the summary as JSON,
 * whose figures are those of the run's own CSV (each muscle's peak force
 * and its time, each hinge's last, least and largest angle, read back
 * from the rows); --name names the run's files; --solver, the iterations
 * and --substeps reach the engine (the CSV's sidecar records its
 * settings); --muscle sets a muscle's parameter (a force of 1 mN bounds
 * the muscle's force); --digits 17 writes the very doubles the summary
 * holds (jansson writes a JSON number with 17 digits); bad values are refused with one line naming the
 * option, and no file.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, popen */

#include <criterion/criterion.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli_support.h"
#include "io/csv_table.h"

static json_t *load_json(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    json_error_t error;
    json_t *root = json_load_file(path, 0, &error);
    cr_assert_not_null(root, "%s: %s", path, error.text);
    return root;
}

static void remove_in(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    cr_assert_eq(remove(path), 0, "no %s", path);
}

static const double *column_of(const csv_table *table, const char *name)
{
    int c = csv_table_find(table, name);
    cr_assert_geq(c, 0, "the CSV has no column %s", name);
    return table->columns[c].values;
}

/* Each muscle's peak force and its time, each hinge's last, least and
 * largest angle in the JSON summary `root` are those of the run's CSV to
 * `relative` (the CSV's digits: 10 give 5e-10, 17 the doubles: 0). */
static void figures_are_the_csvs(const json_t *root, const csv_table *table, double relative, int *muscles, int *hinges)
{
    const double *time = column_of(table, "time_s");
    size_t k;
    json_t *item;
    *muscles = *hinges = 0;
    json_array_foreach(json_object_get(root, "muscles"), k, item)
    {
        char name[256];
        snprintf(name, sizeof name, "%s.total_force_N", json_string_value(json_object_get(item, "name")));
        const double *force = column_of(table, name);
        long at = 0;
        for (long row = 1; row < table->row_count; ++row) {
            at = force[row] > force[at] ? row : at;
        }
        const double peak = json_real_value(json_object_get(item, "peak_force_N"));
        cr_assert_float_eq(peak, force[at], relative * fabs(peak), "%s: %.17g in the CSV", name, force[at]);
        cr_assert_float_eq(json_real_value(json_object_get(item, "peak_time_s")), time[at], relative * time[at], "%s",
                           name);
        ++*muscles;
    }
    json_array_foreach(json_object_get(root, "hinges"), k, item)
    {
        char name[256];
        snprintf(name, sizeof name, "%s.angle_deg", json_string_value(json_object_get(item, "name")));
        const double *angle = column_of(table, name);
        double least = angle[0], largest = angle[0];
        for (long row = 1; row < table->row_count; ++row) {
            least = fmin(least, angle[row]);
            largest = fmax(largest, angle[row]);
        }
        const double last = angle[table->row_count - 1];
        cr_assert_float_eq(json_real_value(json_object_get(item, "final_angle_deg")), last, relative * fabs(last),
                           "%s: %.17g in the CSV", name, last);
        cr_assert_float_eq(json_real_value(json_object_get(item, "min_angle_deg")), least, relative * fabs(least), "%s",
                           name);
        cr_assert_float_eq(json_real_value(json_object_get(item, "max_angle_deg")), largest, relative * fabs(largest),
                           "%s", name);
        ++*hinges;
    }
}

Test(run_summary, its_figures_are_those_of_the_runs_csv)
{
    char dir[] = "/tmp/sinew-run-summary-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char output[8192];
    cr_assert_eq(run_sinew_capture(dir,
                                   "run arm --duration 1 --weight 5 --activation 'Biceps Long=0.7' --name "
                                   "lifted --summary lifted.summary.json",
                                   SINEW_STDERR_ONLY, output, sizeof output),
                 0, "%s", output);
    cr_assert(file_exists_in(dir, "lifted.csv") && file_exists_in(dir, "lifted.csv-metadata.json"));
    cr_assert(!file_exists_in(dir, "arm.csv"), "--name did not name the CSV");
    json_t *root = load_json(dir, "lifted.summary.json");
    char path[1024];
    snprintf(path, sizeof path, "%s/lifted.csv", dir);
    csv_table table;
    char error[1024];
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    cr_assert_eq(json_integer_value(json_object_get(root, "rows")), table.row_count);
    cr_assert_str_eq(json_string_value(json_object_get(root, "csv")), "lifted.csv");
    cr_assert_eq(json_real_value(json_object_get(root, "weight_kg")), 5.0);
    const json_t *arguments = json_object_get(root, "arguments");
    cr_assert_eq(json_array_size(arguments), 11);
    cr_assert_str_eq(json_string_value(json_array_get(arguments, 6)), "Biceps Long=0.7");
    int muscles, hinges;
    figures_are_the_csvs(root, &table, 1e-9, &muscles, &hinges);
    cr_assert_eq(muscles, 5);
    cr_assert_eq(hinges, 2);
    const json_t *timing = json_object_get(root, "timing");
    cr_assert_gt(json_real_value(json_object_get(timing, "real_time_factor")), 0.0);
    csv_table_free(&table);
    json_decref(root);
    remove_in(dir, "lifted.csv");
    remove_in(dir, "lifted.csv-metadata.json");
    remove_in(dir, "lifted.summary.json");
    cr_assert_eq(rmdir(dir), 0, "%s is not empty", dir);
}

Test(run_summary, the_solver_options_reach_the_engine)
{
    char dir[] = "/tmp/sinew-run-summary-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char output[8192];
    cr_assert_eq(run_sinew_capture(dir,
                                   "run arm --duration 0.2 --solver soft_step --velocity-iterations 7 "
                                   "--position-iterations 3 --substeps 20",
                                   SINEW_STDERR_ONLY, output, sizeof output),
                 0, "%s", output);
    json_t *root = load_json(dir, "arm.csv-metadata.json");
    const json_t *settings = json_object_get(json_object_get(root, "sinew"), "settings");
    const json_t *solver = json_object_get(settings, "solver");
    cr_assert_str_eq(json_string_value(json_object_get(solver, "type")), "soft_step");
    cr_assert_eq(json_integer_value(json_object_get(solver, "velocity_iterations")), 7);
    cr_assert_eq(json_integer_value(json_object_get(solver, "position_iterations")), 3);
    cr_assert_eq(json_integer_value(json_object_get(settings, "substeps_per_frame")), 20);
    json_decref(root);
    remove_in(dir, "arm.csv");
    remove_in(dir, "arm.csv-metadata.json");
    cr_assert_eq(rmdir(dir), 0, "%s is not empty", dir);
}

Test(run_summary, a_muscle_parameter_set_on_the_command_line_bounds_its_force)
{
    char dir[] = "/tmp/sinew-run-summary-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char output[8192];
    /* A Hill muscle's force is max_force times its curves (active up to
     * about 1.8 when lengthening, passive a few at most): 1 mN gives at
     * most some 10 mN, where the arm's biceps pulls hundreds of N. */
    cr_assert_eq(run_sinew_capture(dir,
                                   "run arm --duration 0.5 --activation 'Biceps Long=1' "
                                   "--muscle 'Biceps Long.max_force=0.001' --summary weak.json",
                                   SINEW_STDERR_ONLY, output, sizeof output),
                 0, "%s", output);
    cr_assert_eq(run_sinew_capture(dir, "run arm --duration 0.5 --activation 'Biceps Long=1' --summary strong.json",
                                   SINEW_STDERR_ONLY, output, sizeof output),
                 0, "%s", output);
    json_t *weak = load_json(dir, "weak.json");
    json_t *strong = load_json(dir, "strong.json");
    const json_t *weak_biceps = json_array_get(json_object_get(weak, "muscles"), 1);
    const json_t *strong_biceps = json_array_get(json_object_get(strong, "muscles"), 1);
    cr_assert_str_eq(json_string_value(json_object_get(weak_biceps, "name")), "Biceps Long");
    cr_assert_lt(json_real_value(json_object_get(weak_biceps, "peak_force_N")), 0.01);
    cr_assert_gt(json_real_value(json_object_get(strong_biceps, "peak_force_N")), 100.0);
    json_decref(weak);
    json_decref(strong);
    remove_in(dir, "arm.csv");
    remove_in(dir, "arm.csv-metadata.json");
    remove_in(dir, "weak.json");
    remove_in(dir, "strong.json");
    cr_assert_eq(rmdir(dir), 0, "%s is not empty", dir);
}

Test(run_summary, seventeen_digits_write_the_runs_own_doubles)
{
    char dir[] = "/tmp/sinew-run-summary-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char output[8192];
    cr_assert_eq(run_sinew_capture(dir,
                                   "run arm --duration 1 --activation 'Biceps Long=0.7' --digits 17 --summary "
                                   "exact.json",
                                   SINEW_STDERR_ONLY, output, sizeof output),
                 0, "%s", output);
    json_t *root = load_json(dir, "exact.json");
    char path[1024];
    snprintf(path, sizeof path, "%s/arm.csv", dir);
    csv_table table;
    char error[1024];
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    int muscles, hinges;
    figures_are_the_csvs(root, &table, 0.0, &muscles, &hinges);
    cr_assert(muscles > 0 && hinges > 0);
    csv_table_free(&table);
    json_decref(root);
    remove_in(dir, "arm.csv");
    remove_in(dir, "arm.csv-metadata.json");
    remove_in(dir, "exact.json");
    cr_assert_eq(rmdir(dir), 0, "%s is not empty", dir);
}

Test(run_summary, bad_values_are_refused_with_no_file)
{
    static const struct {
        const char *args;
        int status;
        const char *message;
    } cases[] = {
        {"--name ../up", 2, "--name \"../up\": expected at most 255 letters, digits"},
        {"--name 'a b'", 2, "--name \"a b\": expected"},
        {"--solver gauss", 2, "--solver \"gauss\": no solver is called \"gauss\""},
        {"--substeps 1001", 2, "--substeps"},
        {"--substeps 0", 2, "--substeps"},
        {"--muscle 'Biceps Long=3'", 2, "--muscle expects MUSCLE.PARAMETER=VALUE"},
        {"--muscle 'Bicep.max_force=3'", 2, "the model has no muscle \"Bicep\""},
        {"--muscle 'Biceps Long.strength=3'", 2, "unknown parameter \"strength\""},
        {"--muscle 'Biceps Long.pennation_angle=90'", 2, "pennation_angle in deg"},
        {"--velocity-iterations 0", 2, "--velocity-iterations"},
        {"--digits 0", 2, "--digits"},
        {"--digits 18", 2, "--digits"},
        {"--summary no/such/folder/s.json", 1,
         "--summary no/such/folder/s.json: the folder no/such/folder does not exist"},
    };
    char dir[] = "/tmp/sinew-run-summary-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char args[512];
        snprintf(args, sizeof args, "run arm --duration 0.1 --summary s.json %s", cases[k].args);
        char output[8192];
        int status = run_sinew_capture(dir, args, SINEW_STDERR_ONLY, output, sizeof output);
        cr_expect_eq(status, cases[k].status, "%s: status %d: %s", cases[k].args, status, output);
        cr_expect(strstr(output, cases[k].message) != NULL, "%s: expected \"%s\" in: %s", cases[k].args,
                  cases[k].message, output);
        cr_expect_eq(strchr(output, '\n'), output + strlen(output) - 1, "%s: not one line: %s", cases[k].args, output);
    }
    cr_assert_eq(rmdir(dir), 0, "a refused run left a file in %s", dir);
}
