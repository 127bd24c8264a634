/* SPDX-License-Identifier: MIT */
/* Motor-pool profile images (McIntyre, "Simulated Muscles": strength =
 * 255 − blue, one neuron per pixel) read with libpng, through the API and
 * through a model file: the pool against the pixels the test wrote, each
 * kind of PNG (RGB, RGBA, grey, palette, 16-bit, interlaced), each image
 * refused with what is wrong and where (file, JSON path, image), and the
 * built-in worm's image against the pool it replaced.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, setenv */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/model.h"
#include "png_writer.h"
#include "test_support.h"
#include "worm_pool_image.h"

/* A fresh folder for a test's files. */
typedef struct scratch {
    char dir[40];
} scratch;

static void make_scratch(scratch *s)
{
    strcpy(s->dir, "/tmp/sinew-profile-XXXXXX");
    cr_assert_not_null(mkdtemp(s->dir));
}

static void scratch_path(const scratch *s, const char *name, char *path, size_t size)
{
    snprintf(path, size, "%s/%s", s->dir, name);
}

static void remove_scratch(const scratch *s)
{
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", s->dir);
    cr_expect_eq(system(command), 0);
}

/* Loads `path` as a pool and checks each strength against `expected`. */
static void expect_pool(const char *path, const double *expected, int count, const char *what)
{
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_load_png(path, &pool), RB_OK, "%s: %s", what, rb_last_error());
    cr_assert_eq(mu_motor_pool_neuron_count(pool), count, "%s: one neuron per pixel", what);
    for (int i = 0; i < count; ++i) {
        cr_expect_eq(mu_motor_pool_strength(pool, i), expected[i], "%s: neuron %d: %.17g, expected %.17g", what, i,
                     mu_motor_pool_strength(pool, i), expected[i]);
    }
    mu_motor_pool_destroy(pool);
}

Test(profile_image, each_kind_of_png_gives_255_minus_blue_per_pixel)
{
    scratch s;
    make_scratch(&s);
    char path[128];
    scratch_path(&s, "profile.png", path, sizeof path);
    /* White, pink, red, dark red, black: all on the scale. */
    const unsigned rgb[] = {255, 255, 255, 255, 200, 200, 255, 0, 0, 139, 0, 0, 0, 0, 0};
    const double from_rgb[] = {0, 55, 255, 255, 255};
    write_test_png(path, &(test_png){1 * 5, 1, PNG_COLOR_TYPE_RGB, 8, rgb, NULL, 0, false});
    expect_pool(path, from_rgb, 5, "8-bit RGB");
    write_test_png(path, &(test_png){5, 1, PNG_COLOR_TYPE_RGB, 8, rgb, NULL, 0, true});
    expect_pool(path, from_rgb, 5, "8-bit RGB, interlaced");

    /* Opaque alpha changes nothing. */
    const unsigned rgba[] = {255, 100, 100, 255, 255, 7, 7, 255};
    const double from_rgba[] = {155, 248};
    write_test_png(path, &(test_png){2, 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, rgba, NULL, 0, false});
    expect_pool(path, from_rgba, 2, "8-bit RGBA, opaque");

    /* 16 bits: blue b counts as b/257, between the 8-bit steps. */
    const unsigned rgb16[] = {65535, 65535, 65535, 65535, 1000, 1000, 65535, 257 * 200, 257 * 200};
    const double from_rgb16[] = {0, 255.0 - 1000.0 * 255.0 / 65535.0, 55};
    write_test_png(path, &(test_png){3, 1, PNG_COLOR_TYPE_RGB, 16, rgb16, NULL, 0, false});
    expect_pool(path, from_rgb16, 3, "16-bit RGB");

    /* A grey g is (g, g, g): black is the strongest. */
    const unsigned grey[] = {255, 128, 0};
    const double from_grey[] = {0, 127, 255};
    write_test_png(path, &(test_png){3, 1, PNG_COLOR_TYPE_GRAY, 8, grey, NULL, 0, false});
    expect_pool(path, from_grey, 3, "8-bit grey");

    /* A palette image reads as its colours, here 4-bit indices. */
    const png_color palette[] = {{255, 255, 255}, {255, 155, 155}, {120, 0, 0}};
    const unsigned indices[] = {2, 0, 1, 1};
    const double from_palette[] = {255, 0, 100, 100};
    write_test_png(path, &(test_png){4, 1, PNG_COLOR_TYPE_PALETTE, 4, indices, palette, 3, false});
    expect_pool(path, from_palette, 4, "4-bit palette");
    remove_scratch(&s);
}

/* Writes `image` and expects mu_motor_pool_load_png to refuse it with a
 * message holding `expected`. */
static void expect_refused(const char *path, const test_png *image, const char *expected)
{
    if (image != NULL) {
        write_test_png(path, image);
    }
    mu_motor_pool *pool = NULL;
    cr_expect_eq(mu_motor_pool_load_png(path, &pool), RB_ERR_INVALID_ARGUMENT, "%s", expected);
    cr_expect_null(pool);
    cr_expect(strstr(rb_last_error(), expected) != NULL, "expected \"%s\" in: %s", expected, rb_last_error());
    cr_expect(strstr(rb_last_error(), path) != NULL, "the message names the file: %s", rb_last_error());
}

Test(profile_image, bad_images_are_refused_saying_what_and_where)
{
    scratch s;
    make_scratch(&s);
    char path[128];
    scratch_path(&s, "bad.png", path, sizeof path);
    const unsigned two_high[] = {255, 0, 0, 255, 0, 0};
    expect_refused(path, &(test_png){1, 2, PNG_COLOR_TYPE_RGB, 8, two_high, NULL, 0, false},
                   "the image is 1 × 2 pixels, expected 1 pixel high");
    const unsigned blue_pixel[] = {255, 0, 0, 0, 0, 255};
    expect_refused(path, &(test_png){2, 1, PNG_COLOR_TYPE_RGB, 8, blue_pixel, NULL, 0, false},
                   "pixel 1 (counted from 0 at the left) is red 0, green 0, blue 255 (of 255), off the white-to-red "
                   "scale");
    const unsigned green_tint[] = {255, 10, 0};
    expect_refused(path, &(test_png){1, 1, PNG_COLOR_TYPE_RGB, 8, green_tint, NULL, 0, false},
                   "pixel 0 (counted from 0 at the left) is red 255, green 10, blue 0");
    const unsigned translucent[] = {255, 0, 0, 255, 255, 0, 0, 128};
    expect_refused(path, &(test_png){2, 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, translucent, NULL, 0, false},
                   "pixel 1 (counted from 0 at the left) has alpha 128 of 255, expected an opaque pixel");
    const unsigned white[] = {255, 255, 255};
    expect_refused(path, &(test_png){1, 1, PNG_COLOR_TYPE_RGB, 8, white, NULL, 0, false}, "every pixel is white");

    /* Wider than a pool may be. */
    unsigned *wide = calloc(3 * (MU_MAX_MOTOR_NEURONS + 1), sizeof *wide);
    cr_assert_not_null(wide);
    expect_refused(path, &(test_png){MU_MAX_MOTOR_NEURONS + 1, 1, PNG_COLOR_TYPE_RGB, 8, wide, NULL, 0, false},
                   "the image is 100001 pixels wide, expected at most 100000");
    free(wide);

    /* Not a PNG, a PNG cut short, no file. */
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file);
    fputs("1, 2, 3\n", file);
    fclose(file);
    expect_refused(path, NULL, "not a PNG file (no PNG signature)");
    const unsigned red[] = {255, 0, 0, 255, 0, 0, 255, 0, 0};
    write_test_png(path, &(test_png){3, 1, PNG_COLOR_TYPE_RGB, 8, red, NULL, 0, false});
    cr_assert_eq(truncate(path, 40), 0);
    expect_refused(path, NULL, "libpng cannot read it");
    remove(path);
    expect_refused(path, NULL, "cannot open: No such file or directory");
    remove_scratch(&s);
}

/* A model file with one torque muscle whose "motor_pool" is `pool` (JSON). */
static void write_model(const char *path, const char *pool)
{
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file);
    fprintf(file,
            "{\"name\": \"pool test\", \"gravity\": [0, 0],\n"
            " \"bones\": [{\"name\": \"A\", \"centre\": [0, 0], \"size\": [0.05, 0.2], \"static\": true},\n"
            "           {\"name\": \"B\", \"centre\": [0, 0.2], \"size\": [0.05, 0.2]}],\n"
            " \"torque_muscles\": [{\"name\": \"T\", \"body\": \"B\", \"reaction_body\": \"A\", \"peak_torque\": 1,\n"
            "                     \"motor_pool\": %s}]}\n",
            pool);
    fclose(file);
}

Test(profile_image, a_model_file_names_an_image_or_a_csv_beside_it)
{
    scratch s;
    make_scratch(&s);
    char image[128], csv[128], model_path[128];
    scratch_path(&s, "pool.png", image, sizeof image);
    scratch_path(&s, "pool.csv", csv, sizeof csv);
    scratch_path(&s, "model.json", model_path, sizeof model_path);
    const unsigned rgb[] = {255, 235, 235, 255, 155, 155, 200, 0, 0};
    write_test_png(image, &(test_png){3, 1, PNG_COLOR_TYPE_RGB, 8, rgb, NULL, 0, false});
    /* Relative to the model file's folder, not to the working directory. */
    write_model(model_path, "{\"image\": \"pool.png\"}");
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load(model_path, &desc), RB_OK, "%s", rb_last_error());
    const mu_model_torque_muscle *muscle = &desc->torque_muscles[0];
    cr_expect_eq(muscle->pool_source, MU_MODEL_POOL_IMAGE);
    cr_expect_str_eq(muscle->pool_file, "pool.png");
    cr_expect_str_eq(muscle->pool_path, image);
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &(mu_model_options){.level = 4}, &model), RB_OK, "%s", rb_last_error());
    const mu_motor_pool *pool = mu_model_motor_pool(model, 0);
    cr_assert_eq(mu_motor_pool_neuron_count(pool), 3);
    const double strengths[] = {20, 100, 255};
    for (int i = 0; i < 3; ++i) {
        cr_expect_eq(mu_motor_pool_strength(pool, i), strengths[i], "neuron %d", i);
    }
    cr_assert_eq(mu_model_recruit(model, "T", 2), RB_OK, "%s", rb_last_error());
    expect_near(mu_torque_actuator_torque(mu_model_torque_actuator(model, 0)), 120.0 / 375.0, 1e-15,
                "torque = (20 + 100)/(20 + 100 + 255) · 1 N·m");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);

    FILE *file = fopen(csv, "w");
    cr_assert_not_null(file);
    fputs("# strengths\n1, 2\n3\n", file);
    fclose(file);
    write_model(model_path, "{\"csv\": \"pool.csv\"}");
    cr_assert_eq(mu_model_desc_load(model_path, &desc), RB_OK, "%s", rb_last_error());
    cr_expect_eq(desc->torque_muscles[0].pool_source, MU_MODEL_POOL_CSV);
    cr_expect_eq(desc->torque_muscles[0].neurons, 3);
    cr_expect_eq(desc->torque_muscles[0].strengths[2], 3.0);
    mu_model_desc_destroy(desc);
    remove_scratch(&s);
}

/* Loads the model `path` and expects a refusal whose message holds each
 * of `parts` (NULL-terminated). */
static void expect_model_refused(const char *path, const char *const *parts)
{
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load(path, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(desc);
    for (int k = 0; parts[k] != NULL; ++k) {
        cr_expect(strstr(rb_last_error(), parts[k]) != NULL, "expected \"%s\" in: %s", parts[k], rb_last_error());
    }
}

Test(profile_image, a_model_files_bad_image_names_the_file_the_path_and_the_image)
{
    scratch s;
    make_scratch(&s);
    char image[128], model_path[128];
    scratch_path(&s, "tall.png", image, sizeof image);
    scratch_path(&s, "model.json", model_path, sizeof model_path);
    const unsigned two_high[] = {255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 0};
    write_test_png(image, &(test_png){2, 2, PNG_COLOR_TYPE_RGB, 8, two_high, NULL, 0, false});
    write_model(model_path, "{\"image\": \"tall.png\"}");
    char where[400];
    snprintf(where, sizeof where, "%s:5:46: torque_muscles[0].motor_pool.image: %s: the image is 2 × 2 pixels",
             model_path, image);
    expect_model_refused(model_path, (const char *const[]){where, "expected 1 pixel high", NULL});

    write_model(model_path, "{\"image\": \"missing.png\"}");
    expect_model_refused(model_path, (const char *const[]){"torque_muscles[0].motor_pool.image",
                                                           "missing.png: cannot "
                                                           "open: No such file or directory",
                                                           NULL});

    write_model(model_path, "{\"image\": \"model.json\"}");
    expect_model_refused(model_path, (const char *const[]){"torque_muscles[0].motor_pool.image",
                                                           "model.json: not a "
                                                           "PNG file",
                                                           NULL});

    /* A device or a folder could feed a reader without end: only regular
     * files are read. */
    write_model(model_path, "{\"csv\": \"/dev/zero\"}");
    expect_model_refused(model_path, (const char *const[]){"torque_muscles[0].motor_pool.csv: /dev/zero: cannot read: "
                                                           "not a regular file",
                                                           NULL});
    write_model(model_path, "{\"image\": \".\"}");
    expect_model_refused(model_path,
                         (const char *const[]){"motor_pool.image", "/.: cannot read: not a regular file", NULL});
    mu_motor_pool *pool = NULL;
    cr_expect_eq(mu_motor_pool_load_csv("/dev/zero", &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "mu_motor_pool_load_csv: /dev/zero: cannot read: not a regular file") != NULL,
              "%s", rb_last_error());

    write_model(model_path, "{\"image\": \"tall.png\", \"neurons\": 3}");
    expect_model_refused(model_path, (const char *const[]){"torque_muscles[0].motor_pool.neurons: \"neurons\" beside "
                                                           "\"image\", expected one form of motor pool",
                                                           NULL});
    remove_scratch(&s);
}

/* The built-in worm's image is the formula of worm_pool_image.h, pixel for
 * pixel; with SINEW_WRITE_WORM_POOL=PATH set, the test first writes the
 * image from the formula to PATH (how models/worm-pool.png was made:
 * docs/model-format.md). */
Test(profile_image, the_worms_image_is_its_former_exponential_pool)
{
    unsigned samples[3 * WORM_POOL_NEURONS];
    for (int i = 0; i < WORM_POOL_NEURONS; ++i) {
        worm_pool_pixel(i, &samples[3 * i], &samples[3 * i + 2]);
        samples[3 * i + 1] = samples[3 * i + 2];
    }
    const char *write_to = getenv("SINEW_WRITE_WORM_POOL");
    if (write_to != NULL && write_to[0] != '\0') {
        write_test_png(write_to, &(test_png){WORM_POOL_NEURONS, 1, PNG_COLOR_TYPE_RGB, 16, samples, NULL, 0, false});
    }
    double expected[WORM_POOL_NEURONS];
    for (int i = 0; i < WORM_POOL_NEURONS; ++i) {
        expected[i] = worm_pool_image_strength(i);
        /* The image draws the former pool 1 .. 100 as 2.55 .. 255, to half
         * a 16-bit step. */
        expect_near(expected[i], 2.55 * worm_pool_exponential(i), 0.5 / 257.0, "2.55 · 100^(i/199)");
    }
    expect_pool(SINEW_SOURCE_DIR "/models/worm-pool.png", expected, WORM_POOL_NEURONS, "models/worm-pool.png");

    /* The built-in worm (embedded in libmu) reads it. */
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("worm", &desc), RB_OK, "%s", rb_last_error());
    cr_expect_eq(desc->torque_muscles[0].pool_source, MU_MODEL_POOL_IMAGE);
    cr_expect_str_eq(desc->torque_muscles[0].pool_path, "worm-pool.png (built into libmu)");
    for (int i = 0; i < WORM_POOL_NEURONS; ++i) {
        cr_expect_eq(desc->torque_muscles[0].strengths[i], expected[i], "built-in neuron %d", i);
    }
    mu_model_desc_destroy(desc);
}
