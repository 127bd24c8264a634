/* SPDX-License-Identifier: MIT */
/* `sinew sweep`, run as a user runs it: a sweep of 12 arm runs over weight
 * and activation gives a table whose rows are, number for number, the
 * summaries of the same 12 runs made one by one with `sinew run`; GNU
 * parallel running the emitted job list writes the same bytes; a second
 * sweep runs nothing; a run that fails is recorded and the others
 * complete; bad sweep files are refused before any run, naming the JSON
 * path, with no file written. The Slurm engine has its own test
 * (tests/slurm/sweep_on_slurm.sh).
 */
#define _XOPEN_SOURCE 700 /* nftw, mkdtemp, popen */
#define _DEFAULT_SOURCE   /* scandir, usleep */

#include <criterion/criterion.h>
#include <dirent.h>
#include <ftw.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_support.h"
#include "io/csv_cells.h"

static const double weights[] = {0, 1, 5, 10};
static const char *const activations[] = {"0", "0.5", "1"};

/* The sweep of the tests: 4 weights x 3 activations of the long biceps,
 * half a second each. */
static const char sweep_text[] = "{\n"
                                 "  \"model\": \"arm\",\n"
                                 "  \"set\": {\"duration\": 0.5},\n"
                                 "  \"grid\": {\"weight\": [0, 1, 5, 10],\n"
                                 "           \"activation.Biceps Long\": {\"start\": 0, \"stop\": 1, \"step\": 0.5}},\n"
                                 "  \"figure\": {\"y\": \"Biceps Long.peak_force_N\", \"x\": \"weight\",\n"
                                 "             \"group\": \"activation.Biceps Long\"}\n"
                                 "}\n";

static void write_file(const char *dir, const char *name, const char *text)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file, "cannot write %s", path);
    fputs(text, file);
    fclose(file);
}

static int remove_entry(const char *path, const struct stat *info, int flag, struct FTW *ftw)
{
    (void)info;
    (void)flag;
    (void)ftw;
    return remove(path);
}

static void remove_tree(const char *dir) { nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS); }

static char *read_whole(const char *path, size_t *length)
{
    FILE *file = fopen(path, "rb");
    cr_assert_not_null(file, "cannot read %s", path);
    fseek(file, 0, SEEK_END);
    long size = ftell(file);
    rewind(file);
    char *text = malloc((size_t)size + 1);
    cr_assert_not_null(text);
    *length = fread(text, 1, (size_t)size, file);
    text[*length] = '\0';
    fclose(file);
    return text;
}

/* The cell of column `column` in row `row` of the sweep's summary. */
static double summary_number(const char *summary, const char *column, long row)
{
    csv_cells cells = {0};
    char error[1024];
    cr_assert(csv_cells_read(summary, column, &cells, error, sizeof error), "%s", error);
    cr_assert_lt(row, cells.count);
    char *end;
    double value = strtod(cells.text[row], &end);
    cr_assert(end != cells.text[row] && *end == '\0', "%s row %ld: \"%s\" is not a number", column, row,
              cells.text[row]);
    csv_cells_free(&cells);
    return value;
}

static void check_column_text(const char *summary, const char *column, long row, const char *expected)
{
    csv_cells cells = {0};
    char error[1024];
    cr_assert(csv_cells_read(summary, column, &cells, error, sizeof error), "%s", error);
    cr_assert_lt(row, cells.count);
    cr_assert_str_eq(cells.text[row], expected, "%s row %ld", column, row);
    csv_cells_free(&cells);
}

Test(sweep, its_rows_are_the_summaries_of_the_same_runs_made_one_by_one)
{
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "arm_sweep.json", sweep_text);
    char output[8192];
    cr_assert_eq(
        run_sinew_capture(dir, "sweep arm_sweep.json --jobs 2", SINEW_STDOUT_AND_STDERR, output, sizeof output), 0,
        "%s", output);
    cr_assert(strstr(output, "12 runs: 0 complete already, 12 to run") != NULL, "%s", output);
    char summary[1024];
    snprintf(summary, sizeof summary, "%s/arm_sweep/summary.csv", dir);
    long row = 0;
    for (size_t w = 0; w < sizeof weights / sizeof weights[0]; ++w) {
        for (size_t a = 0; a < sizeof activations / sizeof activations[0]; ++a, ++row) {
            /* The same run, alone, in a folder of its own. */
            char alone[1024];
            snprintf(alone, sizeof alone, "%s/alone", dir);
            mkdir(alone, 0777);
            char args[1024];
            snprintf(args, sizeof args,
                     "run arm --duration 0.5 --weight %g --activation 'Biceps Long=%s' --summary run.json", weights[w],
                     activations[a]);
            cr_assert_eq(run_sinew_capture(alone, args, SINEW_STDERR_ONLY, output, sizeof output), 0, "%s", output);
            char path[1100];
            snprintf(path, sizeof path, "%s/run.json", alone);
            json_error_t json_error;
            json_t *root = json_load_file(path, 0, &json_error);
            cr_assert_not_null(root, "%s: %s", path, json_error.text);

            check_column_text(summary, "status", row, "ok");
            cr_assert_eq(summary_number(summary, "weight", row), weights[w]);
            cr_assert_eq(summary_number(summary, "activation.Biceps Long", row), strtod(activations[a], NULL));
            size_t k;
            json_t *item;
            int muscles = 0, hinges = 0;
            json_array_foreach(json_object_get(root, "muscles"), k, item)
            {
                const char *name = json_string_value(json_object_get(item, "name"));
                char column[256];
                snprintf(column, sizeof column, "%s.peak_force_N", name);
                cr_assert_eq(summary_number(summary, column, row),
                             json_real_value(json_object_get(item, "peak_force_N")), "%s row %ld", column, row);
                snprintf(column, sizeof column, "%s.peak_time_s", name);
                cr_assert_eq(summary_number(summary, column, row),
                             json_real_value(json_object_get(item, "peak_time_s")), "%s row %ld", column, row);
                ++muscles;
            }
            json_array_foreach(json_object_get(root, "hinges"), k, item)
            {
                const char *name = json_string_value(json_object_get(item, "name"));
                static const char *const fields[] = {"final_angle_deg", "min_angle_deg", "max_angle_deg"};
                for (int f = 0; f < 3; ++f) {
                    char column[256];
                    snprintf(column, sizeof column, "%s.%s", name, fields[f]);
                    cr_assert_eq(summary_number(summary, column, row),
                                 json_real_value(json_object_get(item, fields[f])), "%s row %ld", column, row);
                }
                ++hinges;
            }
            cr_assert_eq(muscles, 5);
            cr_assert_eq(hinges, 2);
            /* The run made alone and the sweep's run computed the same
             * frames: their CSVs are the same bytes. */
            char sweep_csv[1100];
            snprintf(sweep_csv, sizeof sweep_csv, "%s/arm_sweep/arm_weight=%g_activation.Biceps_Long=%s.csv", dir,
                     weights[w], activations[a]);
            snprintf(path, sizeof path, "%s/arm.csv", alone);
            size_t length_alone, length_sweep;
            char *csv_alone = read_whole(path, &length_alone);
            char *csv_sweep = read_whole(sweep_csv, &length_sweep);
            cr_assert(length_alone == length_sweep && memcmp(csv_alone, csv_sweep, length_alone) == 0,
                      "%s and %s differ", path, sweep_csv);
            free(csv_alone);
            free(csv_sweep);
            json_decref(root);
            remove_tree(alone);
        }
    }
    char figure[1024];
    snprintf(figure, sizeof figure, "%s/arm_sweep/summary.png", dir);
    size_t length;
    char *png = read_whole(figure, &length);
    cr_assert(length > 8 && memcmp(png, "\x89PNG", 4) == 0, "%s is not a PNG", figure);
    free(png);
    remove_tree(dir);
}

/* The modification time of a file, in ns. */
static long long mtime_of(const char *path)
{
    struct stat info;
    cr_assert_eq(stat(path, &info), 0, "no %s", path);
    return (long long)info.st_mtim.tv_sec * 1000000000LL + info.st_mtim.tv_nsec;
}

Test(sweep, a_second_sweep_runs_only_what_is_not_complete)
{
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "arm_sweep.json", sweep_text);
    char output[8192];
    cr_assert_eq(run_sinew_capture(dir, "sweep arm_sweep.json", SINEW_STDOUT_AND_STDERR, output, sizeof output), 0,
                 "%s", output);
    char kept[1024], removed[1024];
    snprintf(kept, sizeof kept, "%s/arm_sweep/arm_weight=5_activation.Biceps_Long=1.summary.json", dir);
    snprintf(removed, sizeof removed, "%s/arm_sweep/arm_weight=1_activation.Biceps_Long=0.5.summary.json", dir);
    long long kept_time = mtime_of(kept);
    cr_assert_eq(remove(removed), 0);
    usleep(20000);
    cr_assert_eq(run_sinew_capture(dir, "sweep arm_sweep.json", SINEW_STDOUT_AND_STDERR, output, sizeof output), 0,
                 "%s", output);
    cr_assert(strstr(output, "12 runs: 11 complete already, 1 to run") != NULL, "%s", output);
    cr_assert_eq(mtime_of(kept), kept_time, "a complete run was run again");
    mtime_of(removed);
    /* A summary made by other arguments is not taken for the run's. */
    size_t length;
    char *text = read_whole(kept, &length);
    char *weight = strstr(text, "\"--weight\",\n    \"5\"");
    cr_assert_not_null(weight, "%s", text);
    weight[strlen("\"--weight\",\n    \"")] = '1';
    write_file(dir, "arm_sweep/arm_weight=5_activation.Biceps_Long=1.summary.json", text);
    free(text);
    cr_assert_eq(
        run_sinew_capture(dir, "sweep arm_sweep.json --gather", SINEW_STDOUT_AND_STDERR, output, sizeof output), 1,
        "%s", output);
    cr_assert(strstr(output, "11 runs ok, 1 failed") != NULL, "%s", output);
    cr_assert_eq(run_sinew_capture(dir, "sweep arm_sweep.json", SINEW_STDOUT_AND_STDERR, output, sizeof output), 0,
                 "%s", output);
    cr_assert(strstr(output, "11 complete already, 1 to run") != NULL, "%s", output);
    remove_tree(dir);
}

/* The names of a folder's files, sorted, one a line. */
static void list_files(const char *dir, char *list, size_t size)
{
    struct dirent **entries;
    int count = scandir(dir, &entries, NULL, alphasort);
    cr_assert_geq(count, 0, "cannot list %s", dir);
    list[0] = '\0';
    for (int k = 0; k < count; ++k) {
        if (entries[k]->d_name[0] != '.') {
            snprintf(list + strlen(list), size - strlen(list), "%s\n", entries[k]->d_name);
        }
        free(entries[k]);
    }
    free(entries);
}

/* A run's summary without its last member, "timing". */
static char *without_timing_member(const char *path)
{
    size_t length;
    char *text = read_whole(path, &length);
    char *timing = strstr(text, "\"timing\"");
    cr_assert_not_null(timing, "%s has no timing", path);
    *timing = '\0';
    return text;
}

/* The summary without its last two columns, the timing ones. */
static char *without_timing(const char *path)
{
    size_t length;
    char *text = read_whole(path, &length);
    char *out = text;
    for (char *line = text; *line != '\0';) {
        char *end = strchr(line, '\n');
        cr_assert_not_null(end);
        char *cut = end;
        for (int commas = 0; commas < 2; --cut) {
            commas += cut[-1] == ',';
        }
        size_t keep = (size_t)(cut - line);
        memmove(out, line, keep);
        out += keep;
        *out++ = '\n';
        line = end + 1;
    }
    *out = '\0';
    return text;
}

Test(sweep, gnu_parallel_running_the_job_list_writes_the_same_bytes)
{
    if (system("parallel --version > /dev/null 2>&1") != 0) {
        cr_skip_test("GNU parallel is not installed (tools/setup.sh installs it)");
    }
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "arm_sweep.json", sweep_text);
    char output[8192];
    cr_assert_eq(
        run_sinew_capture(dir, "sweep arm_sweep.json --out local", SINEW_STDOUT_AND_STDERR, output, sizeof output), 0,
        "%s", output);
    cr_assert_eq(run_sinew_capture(dir, "sweep arm_sweep.json --out by_parallel --emit parallel",
                                   SINEW_STDOUT_AND_STDERR, output, sizeof output),
                 0, "%s", output);
    char command[2048];
    snprintf(command, sizeof command, "cd '%s' && parallel -j2 -a by_parallel/jobs.txt > parallel.log 2>&1", dir);
    cr_assert_eq(system(command), 0, "GNU parallel failed; see %s/parallel.log", dir);
    cr_assert_eq(run_sinew_capture(dir, "sweep arm_sweep.json --out by_parallel --gather", SINEW_STDOUT_AND_STDERR,
                                   output, sizeof output),
                 0, "%s", output);
    char local[1024], by_parallel[1024];
    snprintf(local, sizeof local, "%s/local", dir);
    snprintf(by_parallel, sizeof by_parallel, "%s/by_parallel", dir);
    static char local_files[1 << 14], parallel_files[1 << 14];
    list_files(local, local_files, sizeof local_files);
    list_files(by_parallel, parallel_files, sizeof parallel_files);
    /* The job list is the one file only the parallel folder has. */
    char *jobs = strstr(parallel_files, "jobs.txt\n");
    cr_assert_not_null(jobs);
    memmove(jobs, jobs + strlen("jobs.txt\n"), strlen(jobs + strlen("jobs.txt\n")) + 1);
    cr_assert_str_eq(local_files, parallel_files);
    int compared = 0;
    for (char *name = local_files; *name != '\0'; name = strchr(name, '\n') + 1) {
        *strchr(name, '\n') = '\0';
        char a[1 << 15], b[1 << 15];
        snprintf(a, sizeof a, "%s/%s", local, name);
        snprintf(b, sizeof b, "%s/%s", by_parallel, name);
        if (strcmp(name, "summary.png") == 0) {
            /* The figure names the command that drew it, whose --out differs. */
        } else if (strcmp(name, "summary.csv") == 0) {
            char *x = without_timing(a);
            char *y = without_timing(b);
            cr_assert_str_eq(x, y, "%s and %s differ before the timing columns", a, b);
            free(x);
            free(y);
        } else if (strstr(name, ".summary.json") != NULL) {
            char *x = without_timing_member(a);
            char *y = without_timing_member(b);
            cr_assert_str_eq(x, y, "%s and %s differ before their timing", a, b);
            free(x);
            free(y);
        } else {
            size_t length_a, length_b;
            char *x = read_whole(a, &length_a);
            char *y = read_whole(b, &length_b);
            cr_assert(length_a == length_b && memcmp(x, y, length_a) == 0, "%s and %s differ", a, b);
            free(x);
            free(y);
        }
        ++compared;
        name[strlen(name)] = '\n';
    }
    /* 12 runs x (CSV, sidecar, summary, log) and the table and figure. */
    cr_assert_eq(compared, 12 * 4 + 2);
    remove_tree(dir);
}

Test(sweep, a_run_that_fails_is_recorded_and_the_others_complete)
{
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "good.txt", "0.1 activation \"Biceps Long\" 1\n");
    write_file(dir, "bad.txt", "0.1 activation Nobody 1\n");
    write_file(dir, "controls.json",
               "{\"model\": \"arm\", \"set\": {\"duration\": 0.25},\n"
               " \"grid\": {\"control\": [\"good.txt\", \"bad.txt\"], \"weight\": [0, 1]}}\n");
    char output[8192];
    cr_assert_eq(run_sinew_capture(dir, "sweep controls.json", SINEW_STDOUT_AND_STDERR, output, sizeof output), 1, "%s",
                 output);
    cr_assert(strstr(output, "2 runs ok, 2 failed") != NULL, "%s", output);
    char summary[1024];
    snprintf(summary, sizeof summary, "%s/controls/summary.csv", dir);
    static const char *const status[] = {"ok", "ok", "failed", "failed"};
    for (long row = 0; row < 4; ++row) {
        check_column_text(summary, "status", row, status[row]);
    }
    csv_cells messages = {0};
    char error[1024];
    cr_assert(csv_cells_read(summary, "message", &messages, error, sizeof error), "%s", error);
    cr_assert_str_empty(messages.text[0]);
    cr_assert(strstr(messages.text[2], "bad.txt") != NULL && strstr(messages.text[2], "Nobody") != NULL, "%s",
              messages.text[2]);
    csv_cells_free(&messages);
    remove_tree(dir);
}

/* A sweep file that must be refused: the status, the words of the message,
 * and no output folder made. */
static void check_refused(const char *text, const char *options, const char *expected)
{
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "bad.json", text);
    char args[512];
    snprintf(args, sizeof args, "sweep bad.json %s", options);
    char output[8192];
    int status = run_sinew_capture(dir, args, SINEW_STDOUT_AND_STDERR, output, sizeof output);
    cr_assert_eq(status, 1, "%s: status %d: %s", text, status, output);
    cr_assert(strstr(output, expected) != NULL, "expected \"%s\" in: %s", expected, output);
    cr_assert(strncmp(output, "sinew: bad.json", 15) == 0, "the message names no file: %s", output);
    cr_assert(!file_exists_in(dir, "bad"), "a refused sweep made its output folder");
    remove_tree(dir);
}

Test(sweep, bad_sweep_files_are_refused_before_any_run)
{
    check_refused("{\"model\": \"arm\", \"grid\": {\"wieght\": [0, 1]}}", "",
                  "$.grid.wieght: unknown parameter \"wieght\"");
    check_refused("{\"model\": \"arm\", \"grid\": {\"weight\": [0, 7]}}", "",
                  "$.grid.weight[1]: expected one of the model's weights in kg (0, 1, 5, 10, 50, 100)");
    check_refused("{\"model\": \"arm\", \"grid\": {\"activation.Bicep\": [0, 1]}}", "",
                  "$.grid[\"activation.Bicep\"]: the model arm has no muscle or group \"Bicep\"");
    check_refused("{\"model\": \"arm\", \"grid\": {\"activation.Biceps Long\": [0, 1.5]}}", "",
                  "$.grid[\"activation.Biceps Long\"][1]: expected a number in 0 .. 1");
    check_refused("{\"model\": \"arm\", \"grid\": {\"solver\": [\"ngs\", \"gauss\"]}}", "",
                  "$.grid.solver[1]: expected a solver: baumgarte, ngs or soft_step");
    check_refused("{\"model\": \"arm\", \"grid\": {\"muscle.Biceps Long.strength\": [1, 2]}}", "",
                  "unknown muscle parameter \"strength\"");
    check_refused("{\"model\": \"arm\", \"set\": {\"weight\": 1}}", "", "$.grid: no parameter varies");
    check_refused("{\"model\": \"arm\", \"grid\": {}}", "", "$.grid: no parameter varies");
    check_refused("{\"model\": \"arm\", \"grid\": {\"weight\": []}}", "", "$.grid.weight: an empty list");
    check_refused("{\"model\": \"arm\", \"grid\": {\"level\": {\"start\": 4, \"stop\": 0, \"step\": 1}}}", "",
                  "$.grid.level: an empty range");
    check_refused("{\"model\": \"arm\", \"zip\": {\"weight\": [0, 1], \"level\": [3]}}", "",
                  "$.zip.level: 1 values, but $.zip.weight has 2");
    check_refused("{\"model\": \"arm\", \"grid\": {\"activation.Biceps Long\": {\"start\": 0, \"stop\": 1, "
                  "\"count\": 1001}}}",
                  "", "1001 runs, more than 1000: give --yes");
    check_refused("{\"model\": \"arm\", \"grid\": {\"weight\": [0, 1]}, \"figure\": {\"x\": \"level\", \"y\": "
                  "\"Elbow.final_angle_deg\"}}",
                  "", "$.figure.x: \"level\" is not a parameter the sweep varies");
    check_refused("{\"model\": \"arm\", \"grid\": {\"weight\": [0, 1], \"activation.Biceps Long\": {\"start\": "
                  "0, \"stop\": 1, \"count\": 65}}, \"figure\": {\"x\": \"weight\", \"y\": \"Elbow.final_angle_deg\", "
                  "\"group\": \"activation.Biceps Long\"}}",
                  "", "$.figure.group: \"activation.Biceps Long\" has more than 64 values");
    check_refused("{\"model\": \"arm\", \"grid\": {\"variant\": [\"All\\nBiceps\"]}}", "",
                  "$.grid.variant[0]: expected a variant of the model arm");
    check_refused("{\"model\": \"arm\", \"grid\": {\"activation.Biceps\\nLong\": [0]}}", "",
                  "a parameter's name holds a control character");
    check_refused("{\"model\": \"arm\", \"grid\": {\"weight\": [0, 1]}, \"extra\": 1}", "", "$.extra: unknown key");
    check_refused("{\"model\": \"arms\", \"grid\": {\"weight\": [0, 1]}}", "", "$.model: ");
    check_refused("{\"model\": \"arm\", \"grid\": {\"weight\": [0, 1]}}", "--out /proc",
                  "--out: the output folder /proc cannot be written");
    check_refused("{\"model\": \"arm\", \"out\": \"/proc/sinew\", \"grid\": {\"weight\": [0, 1]}}", "",
                  "$.out: the output folder /proc/sinew cannot be made");
    check_refused("{\"model\": \"arm\",\n \"grid\": {\"weight\": [0, 1]},,}", "",
                  "bad.json:2:29: string or '}' expected");
}

Test(sweep, more_than_the_limit_runs_with_yes)
{
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "many.json",
               "{\"model\": \"arm\", \"set\": {\"duration\": 0.1}, \"grid\": "
               "{\"activation.Biceps Long\": {\"start\": 0, \"stop\": 1, \"count\": 1001}}}");
    char output[8192];
    /* --emit list runs nothing: the expansion alone. */
    cr_assert_eq(run_sinew_capture(dir, "sweep many.json --yes --emit list > list.json", SINEW_STDOUT_AND_STDERR,
                                   output, sizeof output),
                 0, "%s", output);
    cr_assert(!file_exists_in(dir, "many/many.csv"));
    char path[1024];
    snprintf(path, sizeof path, "%s/list.json", dir);
    json_error_t json_error;
    json_t *root = json_load_file(path, 0, &json_error);
    cr_assert_not_null(root, "%s", json_error.text);
    cr_assert_eq(json_array_size(json_object_get(root, "runs")), 1001);
    json_decref(root);
    remove_tree(dir);
}

Test(sweep, bad_command_lines_are_refused)
{
    static const struct {
        const char *args;
        const char *message;
    } cases[] = {
        {"sweep", "sinew sweep: missing the sweep file"},
        {"sweep s.json --emit make", "--emit \"make\": expected parallel, slurm or list"},
        {"sweep s.json --chunk 4", "--chunk is for --emit slurm"},
        {"sweep s.json --emit slurm --gather", "give --emit or --gather, not both"},
        {"sweep s.json --jobs 0", "--jobs"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char output[4096];
        int status = run_sinew_capture(NULL, cases[k].args, SINEW_STDOUT_AND_STDERR, output, sizeof output);
        cr_expect_eq(status, 2, "%s: status %d: %s", cases[k].args, status, output);
        cr_expect(strstr(output, cases[k].message) != NULL, "%s: expected \"%s\" in: %s", cases[k].args,
                  cases[k].message, output);
    }
}

Test(sweep, the_table_holds_each_value_as_given_and_the_variant_built)
{
    char dir[] = "/tmp/sinew-sweep-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    write_file(dir, "variants.json",
               "{\"model\": \"arm\", \"set\": {\"duration\": 0.1},\n"
               " \"grid\": {\"variant\": [\"All Biceps\", 0], \"weight\": [5]}}\n");
    char output[8192];
    cr_assert_eq(run_sinew_capture(dir, "sweep variants.json", SINEW_STDOUT_AND_STDERR, output, sizeof output), 0, "%s",
                 output);
    char summary[1024];
    snprintf(summary, sizeof summary, "%s/variants/summary.csv", dir);
    check_column_text(summary, "run", 0, "arm_variant=All_Biceps_weight=5");
    check_column_text(summary, "variant", 0, "All Biceps");
    check_column_text(summary, "variant_name", 0, "All Biceps");
    check_column_text(summary, "variant", 1, "0");
    check_column_text(summary, "variant_name", 1, "All Muscles");
    cr_assert_eq(summary_number(summary, "weight_kg", 1), 5.0);
    remove_tree(dir);
}
