/* SPDX-License-Identifier: MIT */
/* What sinew writes, sinew reads back: every CSV writer (sinew run, sinew
 * scene, sinew experiment, and the table writer the experiments and the
 * viewer's graph export share) through the reader `sinew plot` uses
 * (io/csv_table.h), with names a user may give that a CSV treats
 * specially: commas, double quotes, spaces at the ends, '#', ';', UTF-8.
 * The names come back exactly as the model file gave them, and every cell
 * as a number. A name with a control character (a line break would split
 * the header, a tab would make a blank line of it) is refused when the
 * model loads, with the JSON path.
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
#include "mu/model_desc.h"

static char dir[] = "/tmp/sinew-round-trip-XXXXXX";

static void make_dir(void) { cr_assert_not_null(mkdtemp(dir)); }

static void remove_dir(void)
{
    char command[256];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}

static int run_sinew(const char *args)
{
    char command[2048];
    snprintf(command, sizeof command, "cd '%s' && '%s' %s > out.txt 2> err.txt", dir, SINEW_TOOL, args);
    const int status = system(command);
    cr_assert(status != -1 && WIFEXITED(status), "could not run: %s", command);
    return WEXITSTATUS(status);
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    cr_assert_not_null(f, "cannot read %s", path);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    cr_assert_not_null(text);
    cr_assert_eq(fread(text, 1, (size_t)size, f), (size_t)size);
    text[size] = '\0';
    fclose(f);
    return text;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    cr_assert_not_null(f, "cannot write %s", path);
    fputs(text, f);
    fclose(f);
}

/* `text` with every `from` replaced by `to` (a new string). */
static char *replace_all(const char *text, const char *from, const char *to)
{
    size_t count = 0;
    for (const char *at = strstr(text, from); at != NULL; at = strstr(at + strlen(from), from)) {
        ++count;
    }
    cr_assert_gt(count, 0, "%s is not in the text", from);
    char *out = malloc(strlen(text) + count * strlen(to) + 1);
    cr_assert_not_null(out);
    char *write = out;
    for (const char *at = text;;) {
        const char *next = strstr(at, from);
        if (next == NULL) {
            strcpy(write, at);
            break;
        }
        memcpy(write, at, (size_t)(next - at));
        write += next - at;
        strcpy(write, to);
        write += strlen(to);
        at = next + strlen(from);
    }
    return out;
}

/* Every column of the file is read, numeric, and `rows` long at least. */
static void expect_all_numeric(const char *path, const csv_table *table, long rows)
{
    cr_expect_geq(table->row_count, rows, "%s: %ld rows", path, table->row_count);
    for (int c = 0; c < table->column_count; ++c) {
        cr_expect(table->columns[c].numeric, "%s: column \"%s\" is not numeric (line %ld: %s)", path,
                  table->columns[c].name, table->columns[c].bad_line, table->columns[c].bad_cell);
        for (long r = 0; r < table->row_count && table->columns[c].numeric; ++r) {
            if (!isfinite(table->columns[c].values[r])) {
                cr_expect_fail("%s: column \"%s\" row %ld is %g", path, table->columns[c].name, r,
                               table->columns[c].values[r]);
                break;
            }
        }
    }
}

/* The names a user may give (as JSON source) and as they are. */
static const struct {
    const char *original; /* in models/arm.json, quoted */
    const char *json;     /* the new name, quoted, as JSON */
    const char *name;     /* the new name */
} renames[] = {
    {"\"Biceps Long\"", "\"Bi,ceps \\\"Long\\\"\"", "Bi,ceps \"Long\""},
    {"\"Biceps Short\"", "\"#Bíceps; curto\"", "#Bíceps; curto"},
    {"\"Elbow\"", "\"El, bow\"", "El, bow"},
    {"\"Radius\"", "\" Radius \"", " Radius "},
};
#define RENAME_COUNT (sizeof renames / sizeof renames[0])

Test(csv_round_trip, sinew_run_writes_names_it_reads_back)
{
    make_dir();
    char path[600];
    snprintf(path, sizeof path, "%s/models/arm.json", SINEW_SOURCE_DIR);
    char *text = read_text(path);
    for (size_t k = 0; k < RENAME_COUNT; ++k) {
        char *renamed = replace_all(text, renames[k].original, renames[k].json);
        free(text);
        text = renamed;
    }
    snprintf(path, sizeof path, "%s/names.json", dir);
    write_text(path, text);
    free(text);
    cr_assert_eq(run_sinew("run names.json --duration 0.1 --out ."), 0, "sinew run failed");
    snprintf(path, sizeof path, "%s/names.csv", dir);
    csv_table table;
    char error[1024];
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    for (size_t k = 0; k < RENAME_COUNT; ++k) {
        int found = 0;
        for (int c = 0; c < table.column_count; ++c) {
            const char *column = table.columns[c].name;
            const size_t length = strlen(renames[k].name);
            found += strncmp(column, renames[k].name, length) == 0 && column[length] == '.' &&
                     strchr(column + length + 1, '.') == NULL;
        }
        cr_expect_gt(found, 0, "no column of \"%s\" read back", renames[k].name);
    }
    cr_expect_geq(csv_table_find(&table, "Bi,ceps \"Long\".total_force_N"), 0);
    cr_expect_geq(csv_table_find(&table, "El, bow.angle_deg"), 0);
    cr_expect_geq(csv_table_find(&table, " Radius .x_m"), 0);
    cr_expect_geq(csv_table_find(&table, "El, bow.reaction_along_N"), 0);
    cr_expect_geq(csv_table_find(&table, "Bi,ceps \"Long\".El, bow.moment_arm_m"), 0);
    expect_all_numeric(path, &table, 6);
    csv_table_free(&table);
    /* The hinge sweep's table, named after the hinge with '-' for what is
     * not a letter or a digit. */
    cr_assert_eq(run_sinew("moment-arms names.json --hinge \"El, bow\" --step 10 --out ."), 0,
                 "sinew moment-arms failed");
    snprintf(path, sizeof path, "%s/names-moment-arms-El--bow.csv", dir);
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    cr_expect_geq(csv_table_find(&table, "Bi,ceps \"Long\".moment_arm_m"), 0);
    cr_expect_geq(csv_table_find(&table, "#Bíceps; curto.passive_force_N"), 0);
    expect_all_numeric(path, &table, 17);
    csv_table_free(&table);
    cr_expect_eq(run_sinew("plot names.csv --y \"Bi,ceps \\\"Long\\\".total_force_N\" --out names.png"), 0,
                 "sinew plot of the run failed");
    remove_dir();
}

Test(csv_round_trip, the_table_writer_writes_names_it_reads_back)
{
    make_dir();
    const char *names[] = {"time_s", "a,b", "quote \"q\"", " spaced ", "#hash", "ünï;cödé", "x"};
    const int count = (int)(sizeof names / sizeof names[0]);
    csv_table table;
    char error[1024];
    cr_assert(csv_table_init(&table, count, names, error, sizeof error), "%s", error);
    double row[sizeof names / sizeof names[0]];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < count; ++c) {
            row[c] = r * 10.0 + c + 0.25;
        }
        cr_assert(csv_table_add_row(&table, row, error, sizeof error), "%s", error);
    }
    char path[600];
    snprintf(path, sizeof path, "%s/table.csv", dir);
    cr_assert(csv_table_write(&table, path, error, sizeof error), "%s", error);
    csv_table_free(&table);
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    cr_assert_eq(table.column_count, count);
    cr_assert_eq(table.row_count, 3);
    for (int c = 0; c < count; ++c) {
        cr_expect_str_eq(table.columns[c].name, names[c]);
        for (int r = 0; r < 3; ++r) {
            cr_expect_eq(table.columns[c].values[r], r * 10.0 + c + 0.25);
        }
    }
    csv_table_free(&table);
    remove_dir();
}

Test(csv_round_trip, scenes_and_experiments_are_read_back)
{
    make_dir();
    cr_assert_eq(run_sinew("scene pendulum --duration 0.1 --out ."), 0, "sinew scene failed");
    cr_assert_eq(run_sinew("experiment c1 --out ."), 0, "sinew experiment failed");
    const char *files[] = {"pendulum.csv", "c1_hill_curves.csv"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; ++k) {
        char path[600], error[1024];
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        csv_table table;
        cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
        expect_all_numeric(path, &table, 2);
        csv_table_free(&table);
    }
    remove_dir();
}

Test(csv_round_trip, names_with_control_characters_are_refused_at_load)
{
    make_dir();
    char path[600];
    snprintf(path, sizeof path, "%s/models/arm.json", SINEW_SOURCE_DIR);
    char *text = read_text(path);
    const struct {
        const char *original, *json;
    } bad[] = {
        {"\"Biceps Long\"", "\"Biceps\\nLong\""}, {"\"Elbow\"", "\"\\t\""},
        {"\"Radius\"", "\"Ra\\u007fdius\""},      {"\"arm\"", "\"arm\\r\""},
        {"\"Nail\"", "\"Nail\\u001b\""},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        char *renamed = replace_all(text, bad[k].original, bad[k].json);
        snprintf(path, sizeof path, "%s/bad.json", dir);
        write_text(path, renamed);
        free(renamed);
        mu_model_desc *desc = NULL;
        cr_expect_eq(mu_model_desc_load(path, &desc), RB_ERR_INVALID_ARGUMENT, "%s was accepted", bad[k].json);
        cr_expect_null(desc);
        const char *message = rb_last_error();
        cr_expect(strstr(message, "bad.json:") != NULL && strstr(message, "name") != NULL &&
                      strstr(message, "control character") != NULL,
                  "%s: %s", bad[k].json, message);
        mu_model_desc_destroy(desc);
    }
    free(text);
    remove_dir();
}
