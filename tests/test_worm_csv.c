/* SPDX-License-Identifier: MIT */
/* The worm through the sinew program, as a user meets it: its torque
 * muscle's CSV columns against McIntyre's exertion formula computed here
 * (exertion = sum of the first n strengths / sum of all, the torque that
 * share of the peak), its name in `sinew models` and `sinew run --help`,
 * a wrong name answered with the right one, `sinew check` reading the
 * image its file names, and its runs unchanged by the
 * move of its pool into a profile image.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"
#include "test_support.h"
#include "worm_pool_image.h"

#define WORM_PEAK_TORQUE 0.01 /* N·m, models/worm.json */

/* Runs `sinew ARGS` with stdout and stderr into `output`; returns its exit status. */
static int run_sinew(const char *args, char *output, size_t size)
{
    return run_sinew_capture(NULL, args, SINEW_STDOUT_AND_STDERR, output, size);
}

/* The whole of a file, for the test to free. */
static char *read_whole(const char *path)
{
    FILE *file = fopen(path, "rb");
    cr_assert_not_null(file, "cannot open %s", path);
    fseek(file, 0, SEEK_END);
    const long length = ftell(file);
    rewind(file);
    char *text = malloc((size_t)length + 1);
    cr_assert_not_null(text);
    cr_assert_eq(fread(text, 1, (size_t)length, file), (size_t)length);
    text[length] = '\0';
    fclose(file);
    return text;
}

/* Index of the field `name` in the CSV header line `header`; -1 if absent. */
static int column_of(const char *header, const char *name)
{
    int index = 0;
    const size_t length = strlen(name);
    for (const char *field = header;; ++index) {
        const size_t field_length = strcspn(field, ",\n");
        if (field_length == length && strncmp(field, name, length) == 0) {
            return index;
        }
        if (field[field_length] != ',') {
            return -1;
        }
        field += field_length + 1;
    }
}

/* Field `index` of the line as a number. */
static double field_at(const char *line, int index)
{
    for (int k = 0; k < index; ++k) {
        line = strchr(line, ',');
        cr_assert_not_null(line);
        ++line;
    }
    return strtod(line, NULL);
}

Test(worm_csv, the_torque_muscles_columns_follow_the_exertion_formula)
{
    char dir[] = "/tmp/sinew-worm-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    const int neurons = 60;
    char args[256], output[8192];
    snprintf(args, sizeof args, "run worm --duration 0.5 --recruit 'Torque Muscle=%d' --out %s", neurons, dir);
    cr_assert_eq(run_sinew(args, output, sizeof output), 0, "%s", output);
    cr_expect(strstr(output, "Torque Muscle            60 of 200 neurons: exertion 0.0297") != NULL,
              "the summary gives the torque muscle: %s", output);

    /* The seed's formula, summed here from the image's strengths (and
     * from the exponential profile they draw). */
    double first = 0.0, total = 0.0, first_exponential = 0.0, total_exponential = 0.0;
    for (int i = 0; i < WORM_POOL_NEURONS; ++i) {
        first += i < neurons ? worm_pool_image_strength(i) : 0.0;
        total += worm_pool_image_strength(i);
        first_exponential += i < neurons ? worm_pool_exponential(i) : 0.0;
        total_exponential += worm_pool_exponential(i);
    }
    const double exertion = first / total;
    expect_near(exertion, first_exponential / total_exponential, 2e-6,
                "the image keeps the exponential pool's exertion");

    char path[96];
    snprintf(path, sizeof path, "%s/worm.csv", dir);
    char *text = read_whole(path);
    const int recruited_column = column_of(text, "Torque Muscle.recruited_neurons");
    const int exertion_column = column_of(text, "Torque Muscle.exertion");
    const int torque_column = column_of(text, "Torque Muscle.torque_N_m");
    cr_assert(recruited_column > 0 && exertion_column == recruited_column + 1 && torque_column == exertion_column + 1,
              "the three columns, in order: %.200s", text);
    int rows = 0;
    for (const char *line = strchr(text, '\n') + 1; *line != '\0'; line = strchr(line, '\n') + 1, ++rows) {
        cr_expect_eq(field_at(line, recruited_column), (double)neurons, "row %d: neurons recruited", rows);
        /* Ten significant digits in the file. */
        expect_near(field_at(line, exertion_column), exertion, 1e-10, "exertion = first n strengths / all");
        expect_near(field_at(line, torque_column), exertion * WORM_PEAK_TORQUE, 1e-12,
                    "torque = exertion · peak torque (N·m)");
    }
    cr_expect_eq(rows, 30, "0.5 s at 60 Hz");
    free(text);
    remove(path);
    snprintf(path, sizeof path, "%s/worm.csv-metadata.json", dir);
    remove(path);
    cr_expect_eq(rmdir(dir), 0, "only the CSV and its sidecar were written");
}

Test(worm_csv, the_torque_muscle_is_named_where_a_user_looks)
{
    char output[16384];
    cr_assert_eq(run_sinew("models", output, sizeof output), 0, "%s", output);
    cr_expect(strstr(output, "torque muscles: \"Torque Muscle\" (200 neurons from the image worm-pool.png, peak "
                             "0.01 N·m") != NULL,
              "sinew models: %s", output);
    cr_assert_eq(run_sinew("run --help", output, sizeof output), 0, "%s", output);
    cr_expect(strstr(output, "\"Torque Muscle\"") != NULL, "sinew run --help: %s", output);
    cr_expect(strstr(output, "NAME.recruited_neurons") != NULL, "sinew run --help names the columns: %s", output);

    cr_expect_eq(run_sinew("run worm --duration 0.1 --out /tmp --recruit 'Torque=5'", output, sizeof output), 2);
    cr_expect(strstr(output, "sinew: --recruit \"Torque=5\": no torque muscle named \"Torque\" is "
                             "built in this model, expected \"Torque Muscle\"") != NULL,
              "the wrong name is answered with the right one: %s", output);
    cr_expect_eq(run_sinew("run worm --duration 0.1 --out /tmp --recruit 'Torque Muscle=201'", output, sizeof output),
                 2);
    cr_expect(strstr(output, "neurons") != NULL && strstr(output, "200") != NULL, "too many neurons: %s", output);
    cr_expect_eq(run_sinew("run arm --duration 0.1 --out /tmp --recruit 'Torque Muscle=5'", output, sizeof output), 2);
    cr_expect(strstr(output, "this model builds no torque muscle") != NULL, "a model without any: %s", output);
}

/* Runs the worm from `model` recruiting `neurons` for 3 s into `dir`;
 * returns the CSV's text. */
static char *worm_run(const char *model, const char *dir, int neurons)
{
    char args[512], output[8192], path[160];
    snprintf(args, sizeof args, "run %s --duration 3 --recruit 'Torque Muscle=%d' --out %s", model, neurons, dir);
    cr_assert_eq(run_sinew(args, output, sizeof output), 0, "%s", output);
    const char *stem = strstr(model, "worm_exponential") != NULL ? "worm_exponential" : "worm";
    snprintf(path, sizeof path, "%s/%s.csv", dir, stem);
    char *text = read_whole(path);
    remove(path);
    snprintf(path, sizeof path, "%s/%s.csv-metadata.json", dir, stem);
    remove(path);
    return text;
}

Test(worm_csv, the_image_leaves_the_worms_runs_as_they_were)
{
    char dir[] = "/tmp/sinew-worm-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    /* The worm as it was (its pool generated) and as it is (its image),
     * at rest, at full recruitment and in between. */
    const char *before = SINEW_SOURCE_DIR "/tests/data/models/worm_exponential.json";
    for (int k = 0; k < 3; ++k) {
        const int neurons = (int[]){0, 200, 100}[k];
        char *was = worm_run(before, dir, neurons);
        char *is = worm_run("worm", dir, neurons);
        if (neurons == 0 || neurons == 200) {
            /* e(0) = 0 and e(N) = 1 whatever the strengths: the same bytes. */
            cr_expect_str_eq(is, was, "recruiting %d: the CSV is byte for byte the same", neurons);
        } else {
            /* In between, the image's 16-bit steps move the exertion by
             * parts in 10^5, and the top joint's angle with it. */
            const int exertion = column_of(was, "Torque Muscle.exertion");
            const int angle = column_of(was, "Joint 5.angle_deg");
            cr_assert(exertion > 0 && angle > 0 && column_of(is, "Joint 5.angle_deg") == angle);
            const char *a = strrchr(was, '\n');
            const char *b = strrchr(is, '\n');
            while (a > was && a[-1] != '\n') {
                --a;
            }
            while (b > is && b[-1] != '\n') {
                --b;
            }
            const double e_was = field_at(a, exertion), e_is = field_at(b, exertion);
            expect_near(e_is, e_was, 5e-5 * e_was, "exertion at 100 neurons");
            expect_near(field_at(b, angle), field_at(a, angle), 5e-5 * fabs(field_at(a, angle)),
                        "top joint's angle after 3 s");
        }
        free(was);
        free(is);
    }
    cr_expect_eq(rmdir(dir), 0);
}

Test(worm_csv, sinew_check_reads_the_image_a_model_names)
{
    char dir[] = "/tmp/sinew-worm-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    /* The worm's own file and image, copied: valid; the image removed: the
     * error names the model file, the JSON path and the image. */
    char command[512], output[8192], args[256];
    snprintf(command, sizeof command, "cp '%s/models/worm.json' '%s/models/worm-pool.png' '%s'", SINEW_SOURCE_DIR,
             SINEW_SOURCE_DIR, dir);
    cr_assert_eq(system(command), 0);
    snprintf(args, sizeof args, "check '%s/worm.json'", dir);
    cr_expect_eq(run_sinew(args, output, sizeof output), 0, "%s", output);
    cr_expect(strstr(output, "valid model \"worm\"") != NULL && strstr(output, "1 torque muscle") != NULL, "%s",
              output);
    char image[96];
    snprintf(image, sizeof image, "%s/worm-pool.png", dir);
    cr_assert_eq(remove(image), 0);
    cr_expect_eq(run_sinew(args, output, sizeof output), 1, "%s", output);
    char expected[256];
    snprintf(expected, sizeof expected,
             "sinew: %s/worm.json:22:32: torque_muscles[0].motor_pool.image: %s: cannot open", dir, image);
    cr_expect(strstr(output, expected) != NULL, "expected \"%s\" in: %s", expected, output);
    snprintf(image, sizeof image, "%s/worm.json", dir);
    remove(image);
    cr_expect_eq(rmdir(dir), 0);
}
