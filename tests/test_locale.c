/* SPDX-License-Identifier: MIT */
/* Numbers are read and written with a '.' whatever the locale.
 *
 * The library: a program that calls setlocale(LC_ALL, "de_DE.UTF-8")
 * (decimal comma) still reads the curve tables, motor-pool profiles and
 * model files to the same values as under the C locale, gets messages and
 * warnings whose numbers have a '.', and gets its own locale back after.
 * The programs: `sinew run`, `sinew scene`, `sinew experiment` and `sinew
 * plot` write byte for byte the same files (sidecars included) and output
 * under LC_ALL=de_DE.UTF-8 as under LC_ALL=C (the viewer's twin is in
 * tests/gui/test_viewer_gui.c).
 *
 * de_DE.UTF-8 must exist: tools/setup.sh generates it. A missing locale
 * fails the test rather than skipping it, so CI cannot pass without
 * checking anything.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <criterion/criterion.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mu/curves.h"
#include "mu/model.h"
#include "mu/model_desc.h"
#include "mu/motor_pool.h"

#define COMMA_LOCALE "de_DE.UTF-8"

/* Switches the process to the decimal-comma locale, and checks that the
 * C library really reads and writes numbers with a comma under it, so
 * that a passing test proves something. */
static void use_comma_locale(void)
{
    cr_assert_not_null(setlocale(LC_ALL, COMMA_LOCALE),
                       "the locale %s is missing: run tools/setup.sh (it generates it)", COMMA_LOCALE);
    cr_assert_str_eq(localeconv()->decimal_point, ",", "%s has no decimal comma", COMMA_LOCALE);
    cr_assert_eq(strtod("0.5", NULL), 0.0, "strtod of \"0.5\" stops at the '.' under %s", COMMA_LOCALE);
}

static void make_temp_dir(char *path, size_t size)
{
    snprintf(path, size, "/tmp/sinew-locale-XXXXXX");
    cr_assert_not_null(mkdtemp(path), "mkdtemp failed");
}

static void write_file(const char *path, const char *text)
{
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file, "cannot write %s", path);
    fputs(text, file);
    fclose(file);
}

/* The whole file, malloc'ed, its length in *length. */
static char *read_file(const char *path, size_t *length)
{
    FILE *file = fopen(path, "rb");
    cr_assert_not_null(file, "cannot read %s", path);
    cr_assert_eq(fseek(file, 0, SEEK_END), 0);
    long size = ftell(file);
    cr_assert_geq(size, 0);
    rewind(file);
    char *text = malloc((size_t)size + 1);
    cr_assert_not_null(text);
    *length = fread(text, 1, (size_t)size, file);
    text[*length] = '\0';
    fclose(file);
    return text;
}

Test(locale, curve_tables_read_the_same_under_a_decimal_comma)
{
    /* A small table whose knots are the truth: every value has a
     * fractional part, which a decimal-comma strtod would cut off. */
    char dir[64], path[128];
    make_temp_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/curves.csv", dir);
    write_file(path, "curve,x,y\n"
                     "active_force_length,0.5,0.25\n"
                     "active_force_length,1.5,0.75\n"
                     "passive_force_length,1.25,0.125\n"
                     "passive_force_length,2.5,1.5\n"
                     "force_velocity,-0.75,0.0625\n"
                     "force_velocity,0.5,1.375\n");
    use_comma_locale();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_tabulated(path, MU_INTERPOLATION_LINEAR, &curves), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_curve_active_length(curves, 0.5), 0.25);
    cr_expect_eq(mu_curve_active_length(curves, 1.5), 0.75);
    cr_expect_eq(mu_curve_passive_length(curves, 2.5), 1.5);
    /* (A knot at ṽ <= -1 would read 0: f_V is 0 beyond Vmax, curves.h.) */
    cr_expect_eq(mu_curve_velocity(curves, -0.75), 0.0625);
    cr_expect_eq(mu_curve_velocity(curves, 0.5), 1.375);
    mu_curves_destroy(curves);
    cr_expect_str_eq(localeconv()->decimal_point, ",", "reading a table changed the program's locale");
    remove(path);
    remove(dir);
}

Test(locale, messages_quote_numbers_with_a_point_under_a_decimal_comma)
{
    /* rb_report_error formats in the C locale: the message quotes the
     * knots as the file spells them. */
    char dir[64], path[128];
    make_temp_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/curves.csv", dir);
    write_file(path, "curve,x,y\nforce_velocity,0.5,1\nforce_velocity,0.25,1\n");
    use_comma_locale();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_tabulated(path, MU_INTERPOLATION_LINEAR, &curves), RB_ERR_INVALID_ARGUMENT);
    cr_expect_not_null(strstr(rb_last_error(), "x = 0.25 of force_velocity is not above its previous knot's x = 0.5"),
                       "%s", rb_last_error());
    cr_expect_str_eq(localeconv()->decimal_point, ",", "reporting an error changed the program's locale");
    remove(path);
    remove(dir);
}

Test(locale, model_files_read_and_report_the_same_under_a_decimal_comma)
{
    /* jansson reads model files whatever the locale; the messages and
     * warnings that quote their numbers keep the '.'. */
    use_comma_locale();
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load(SINEW_SOURCE_DIR "/tests/data/bad_models/negative_size.json", &desc),
                 RB_ERR_INVALID_ARGUMENT);
    cr_expect_not_null(strstr(rb_last_error(), "bones[1].size[1]: -0.05 is out of range"), "%s", rb_last_error());
    cr_expect_not_null(strstr(rb_last_error(), "(in [0.001, 100])"), "%s", rb_last_error());

    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    cr_expect_eq(desc->gravity.y, -9.8, "gravity read as %g", desc->gravity.y);
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    /* The arm's Triceps Medial is built shorter than its rest length. */
    cr_expect_not_null(strstr(mu_model_warnings(model), "(0.2087 m)"), "%s", mu_model_warnings(model));
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    cr_expect_str_eq(localeconv()->decimal_point, ",", "loading a model changed the program's locale");
}

Test(locale, the_built_in_curve_tables_are_the_same_under_a_decimal_comma)
{
    /* The C locale's reading of hill-curves.csv is the truth. */
    mu_curves *plain = NULL, *comma = NULL;
    cr_assert_not_null(setlocale(LC_ALL, "C"));
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_STEFFEN, &plain), RB_OK, "%s", rb_last_error());
    use_comma_locale();
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_STEFFEN, &comma), RB_OK, "under %s: %s", COMMA_LOCALE,
                 rb_last_error());
    for (int k = 0; k <= 100; ++k) {
        const double length = 0.4 + 1.4 * k / 100.0, velocity = -1.0 + 2.0 * k / 100.0;
        cr_expect_eq(mu_curve_active_length(comma, length), mu_curve_active_length(plain, length), "f_L(%g)", length);
        cr_expect_eq(mu_curve_passive_length(comma, length), mu_curve_passive_length(plain, length), "f_P(%g)", length);
        cr_expect_eq(mu_curve_velocity(comma, velocity), mu_curve_velocity(plain, velocity), "f_V(%g)", velocity);
    }
    mu_curves_destroy(plain);
    mu_curves_destroy(comma);
}

Test(locale, motor_pool_profiles_read_the_same_under_a_decimal_comma)
{
    char dir[64], path[128];
    make_temp_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/profile.csv", dir);
    write_file(path, "# strengths\n0.5, 1.25\n2.75 1e-1\n");
    use_comma_locale();
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_load_csv(path, &pool), RB_OK, "%s", rb_last_error());
    const double expected[] = {0.5, 1.25, 2.75, 0.1};
    cr_assert_eq(mu_motor_pool_neuron_count(pool), 4);
    for (int i = 0; i < 4; ++i) {
        cr_expect_eq(mu_motor_pool_strength(pool, i), expected[i], "strength %d", i);
    }
    mu_motor_pool_destroy(pool);
    cr_expect_str_eq(localeconv()->decimal_point, ",", "reading a profile changed the program's locale");
    remove(path);
    remove(dir);
}

/* Runs `sinew ARGUMENTS` in DIR under LC_ALL=LOCALE (LANG and LC_ALL
 * both, as a user's shell sets them); stdout and stderr go to
 * DIR/out.txt. Fails the test unless it exits with 0. */
static void run_sinew(const char *dir, const char *locale, const char *arguments)
{
    char command[2048];
    snprintf(command, sizeof command, "cd '%s' && LANG=%s LC_ALL=%s '%s' %s >out.txt 2>&1", dir, locale, locale,
             SINEW_TOOL, arguments);
    int status = system(command);
    cr_assert(status != -1 && WIFEXITED(status), "could not run: %s", command);
    if (WEXITSTATUS(status) != 0) {
        char path[128];
        snprintf(path, sizeof path, "%s/out.txt", dir);
        size_t length;
        char *output = read_file(path, &length);
        cr_assert_fail("sinew %s under %s exited with %d:\n%s", arguments, locale, WEXITSTATUS(status), output);
    }
}

/* The file NAME is byte for byte the same in both directories. */
static void expect_same_file(const char *plain_dir, const char *comma_dir, const char *name)
{
    char plain_path[160], comma_path[160];
    snprintf(plain_path, sizeof plain_path, "%s/%s", plain_dir, name);
    snprintf(comma_path, sizeof comma_path, "%s/%s", comma_dir, name);
    size_t plain_length, comma_length;
    char *plain = read_file(plain_path, &plain_length);
    char *comma = read_file(comma_path, &comma_length);
    cr_expect_gt(plain_length, 0, "%s is empty", plain_path);
    cr_expect(plain_length == comma_length && memcmp(plain, comma, plain_length) == 0,
              "%s differs under %s (%zu bytes) from under C (%zu bytes)", name, COMMA_LOCALE, comma_length,
              plain_length);
    free(plain);
    free(comma);
}

/* Runs the same commands in two fresh directories, under C and under
 * the decimal-comma locale, and compares the files they leave. */
typedef struct twin_run {
    char plain[64], comma[64];
} twin_run;

static void twin_start(twin_run *twin)
{
    make_temp_dir(twin->plain, sizeof twin->plain);
    make_temp_dir(twin->comma, sizeof twin->comma);
}

static void twin_write(const twin_run *twin, const char *name, const char *text)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s", twin->plain, name);
    write_file(path, text);
    snprintf(path, sizeof path, "%s/%s", twin->comma, name);
    write_file(path, text);
}

/* Removes from DIR/out.txt the lines of measured times ("wall time",
 * "real time"), which differ from run to run in any locale. */
static void drop_timing_lines(const char *dir)
{
    char path[160];
    snprintf(path, sizeof path, "%s/out.txt", dir);
    size_t length;
    char *text = read_file(path, &length);
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file);
    for (char *line = strtok(text, "\n"); line != NULL; line = strtok(NULL, "\n")) {
        if (strncmp(line, "wall time", 9) != 0 && strncmp(line, "real time", 9) != 0) {
            fprintf(file, "%s\n", line);
        }
    }
    fclose(file);
    free(text);
}

/* Runs `sinew ARGUMENTS` in both directories; what it prints must be the
 * same but for measured times. */
static void twin_run_sinew(const twin_run *twin, const char *arguments)
{
    run_sinew(twin->plain, "C", arguments);
    run_sinew(twin->comma, COMMA_LOCALE, arguments);
    drop_timing_lines(twin->plain);
    drop_timing_lines(twin->comma);
    expect_same_file(twin->plain, twin->comma, "out.txt");
}

static void twin_remove(const twin_run *twin)
{
    char command[256];
    snprintf(command, sizeof command, "rm -rf '%s' '%s'", twin->plain, twin->comma);
    cr_expect_eq(system(command), 0);
}

Test(locale, sinew_run_and_scene_write_the_same_bytes_under_a_decimal_comma, .timeout = 120)
{
    twin_run twin;
    twin_start(&twin);
    /* Decimals in the options and in a control file. */
    twin_write(&twin, "controls.txt", "0.25 activation \"Biceps Long\" 0.5\n0.75 activation \"Biceps Long\" 0.125\n");
    twin_run_sinew(&twin, "run arm --duration 1 --weight 1 --activation 'Biceps Short=0.25' --control controls.txt "
                          "--out .");
    expect_same_file(twin.plain, twin.comma, "arm.csv");
    expect_same_file(twin.plain, twin.comma, "arm.csv-metadata.json");
    twin_run_sinew(&twin, "scene incline --duration 0.5 --angle 20.5 --friction 0.25 --out .");
    expect_same_file(twin.plain, twin.comma, "incline.csv");
    expect_same_file(twin.plain, twin.comma, "incline.csv-metadata.json");
    twin_remove(&twin);
}

Test(locale, sinew_experiment_and_plot_write_the_same_bytes_under_a_decimal_comma, .timeout = 240)
{
    twin_run twin;
    twin_start(&twin);
    twin_run_sinew(&twin, "experiment c1 --out .");
    expect_same_file(twin.plain, twin.comma, "c1_hill_curves.csv");
    expect_same_file(twin.plain, twin.comma, "c1_hill_curves.csv-metadata.json");
    expect_same_file(twin.plain, twin.comma, "c1_hill_curves.svg");
    expect_same_file(twin.plain, twin.comma, "c1_hill_curves.png");
    twin_write(&twin, "data.csv", "time_s,force_N\n0,0.5\n0.25,1.75\n0.5,2.125\n");
    twin_run_sinew(&twin, "plot data.csv --out data.svg");
    expect_same_file(twin.plain, twin.comma, "data.svg");
    twin_remove(&twin);
}
