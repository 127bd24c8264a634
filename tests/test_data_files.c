/* SPDX-License-Identifier: MIT */
/* The muscle layer's data files: the built-in models and the curve tables
 * are compiled into libmu, so they are found wherever the library is, and
 * SINEW_DATA_DIR points the layer at another folder.
 *
 * The truth is the repository's own files, read here through the public
 * path-taking functions: a built-in copy must describe the same model and
 * the same curves as the file it was made from.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, setenv */

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/curves.h"
#include "mu/model_desc.h"
#include "mu/version.h"
#include "rb/version.h"

static const char *const expected_models[] = {"sample", "arm", "leg", "leg-unlimited", "worm"};

/* A fresh empty folder under /tmp; the test removes what it puts there. */
static void make_folder(char *path, size_t size)
{
    snprintf(path, size, "/tmp/sinew_data_XXXXXX");
    cr_assert_not_null(mkdtemp(path), "mkdtemp failed");
}

/* Copies `from` to `to`, replacing the first `find` with `replace`. */
static void copy_file(const char *from, const char *to, const char *find, const char *replace)
{
    FILE *in = fopen(from, "rb");
    cr_assert_not_null(in, "cannot open %s", from);
    static char text[1 << 20];
    size_t length = fread(text, 1, sizeof text - 1, in);
    fclose(in);
    text[length] = '\0';
    FILE *out = fopen(to, "wb");
    cr_assert_not_null(out, "cannot create %s", to);
    char *at = strstr(text, find);
    cr_assert_not_null(at, "%s has no \"%s\"", from, find);
    fwrite(text, 1, (size_t)(at - text), out);
    fputs(replace, out);
    fputs(at + strlen(find), out);
    fclose(out);
}

Test(data_files, the_built_in_models_are_listed_in_order)
{
    int count = mu_builtin_model_count();
    cr_assert_eq(count, 5, "mu_builtin_model_count() is %d, expected 5", count);
    for (int i = 0; i < count; ++i) {
        cr_expect_str_eq(mu_builtin_model_name(i), expected_models[i]);
    }
    cr_expect_null(mu_builtin_model_name(count));
    cr_expect(strstr(rb_last_error(), "index is 5, expected 0 to 4") != NULL, "%s", rb_last_error());
    cr_expect_null(mu_builtin_model_name(-1));
}

Test(data_files, each_built_in_model_is_its_file_in_the_repository)
{
    unsetenv("SINEW_DATA_DIR");
    for (size_t i = 0; i < sizeof expected_models / sizeof expected_models[0]; ++i) {
        char path[4096];
        snprintf(path, sizeof path, "%s/models/%s.json", SINEW_SOURCE_DIR, expected_models[i]);
        mu_model_desc *from_file = NULL;
        mu_model_desc *built_in = NULL;
        cr_assert_eq(mu_model_desc_load(path, &from_file), RB_OK, "%s", rb_last_error());
        cr_assert_eq(mu_model_desc_load_builtin(expected_models[i], &built_in), RB_OK, "%s", rb_last_error());
        cr_expect_str_eq(built_in->name, from_file->name);
        cr_expect_eq(built_in->bone_count, from_file->bone_count, "%s bones", expected_models[i]);
        cr_expect_eq(built_in->muscle_count, from_file->muscle_count, "%s muscles", expected_models[i]);
        cr_expect_eq(built_in->variant_count, from_file->variant_count, "%s variants", expected_models[i]);
        for (int m = 0; m < built_in->muscle_count && m < from_file->muscle_count; ++m) {
            cr_expect_str_eq(built_in->muscles[m].name, from_file->muscles[m].name);
        }
        /* A torque muscle's pool, read from the image built in beside the
         * model or from the one beside its file: the same strengths. */
        cr_expect_eq(built_in->torque_muscle_count, from_file->torque_muscle_count);
        for (int t = 0; t < built_in->torque_muscle_count && t < from_file->torque_muscle_count; ++t) {
            const mu_model_torque_muscle *a = &built_in->torque_muscles[t], *b = &from_file->torque_muscles[t];
            cr_expect_eq(a->pool_source, b->pool_source);
            cr_assert_eq(a->neurons, b->neurons);
            for (int n = 0; a->strengths != NULL && n < a->neurons; ++n) {
                cr_expect_eq(a->strengths[n], b->strengths[n], "%s neuron %d", expected_models[i], n);
            }
        }
        mu_model_desc_destroy(built_in);
        mu_model_desc_destroy(from_file);
    }
}

Test(data_files, the_built_in_curve_tables_are_the_repository_file)
{
    unsetenv("SINEW_DATA_DIR");
    mu_curves *built_in = NULL;
    mu_curves *from_file = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_STEFFEN, &built_in), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_curves_create_tabulated(SINEW_SOURCE_DIR "/models/data/hill-curves.csv", MU_INTERPOLATION_STEFFEN,
                                            &from_file),
                 RB_OK, "%s", rb_last_error());
    for (double x = -1.5; x <= 2.5; x += 0.01) {
        cr_expect_eq(mu_curve_active_length(built_in, x), mu_curve_active_length(from_file, x), "f_L(%g)", x);
        cr_expect_eq(mu_curve_passive_length(built_in, x), mu_curve_passive_length(from_file, x), "f_P(%g)", x);
        cr_expect_eq(mu_curve_velocity(built_in, x), mu_curve_velocity(from_file, x), "f_V(%g)", x);
    }
    mu_curves_destroy(built_in);
    mu_curves_destroy(from_file);
}

Test(data_files, sinew_data_dir_replaces_the_built_in_files)
{
    char folder[64];
    make_folder(folder, sizeof folder);
    char arm[128];
    char curves[128];
    snprintf(arm, sizeof arm, "%s/arm.json", folder);
    snprintf(curves, sizeof curves, "%s/hill-curves.csv", folder);
    copy_file(SINEW_SOURCE_DIR "/models/arm.json", arm, "\"name\": \"arm\"", "\"name\": \"arm from elsewhere\"");
    /* The active curve's first knot raised from 0.0031 to 0.5: f_L at that
     * knot reads it (outside the table f_L is 0, docs/muscle.md). */
    copy_file(SINEW_SOURCE_DIR "/models/data/hill-curves.csv", curves, "active_force_length,0.3422,0.0031",
              "active_force_length,0.3422,0.5");

    mu_curves *original = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &original), RB_OK, "%s", rb_last_error());
    cr_assert_eq(setenv("SINEW_DATA_DIR", folder, 1), 0);

    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    cr_expect_str_eq(desc->name, "arm from elsewhere");
    mu_model_desc_destroy(desc);

    mu_curves *copied = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &copied), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_curve_active_length(original, 0.3422), 0.0031);
    cr_expect_eq(mu_curve_active_length(copied, 0.3422), 0.5);

    /* A model missing from that folder is an error naming the path and the
     * variable, not a silent fall-back to the built-in copy. */
    cr_expect_eq(mu_model_desc_load_builtin("leg", &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(desc);
    cr_expect(strstr(rb_last_error(), "/leg.json: cannot open") != NULL, "%s", rb_last_error());

    /* Likewise a missing table. */
    cr_assert_eq(unlink(curves), 0);
    mu_curves *missing = NULL;
    cr_expect_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &missing), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(missing);
    cr_expect(strstr(rb_last_error(), "hill-curves.csv: cannot open the file") != NULL, "%s", rb_last_error());
    cr_expect(strstr(rb_last_error(), "SINEW_DATA_DIR is set") != NULL, "%s", rb_last_error());

    /* An empty value means unset. */
    cr_assert_eq(setenv("SINEW_DATA_DIR", "", 1), 0);
    cr_expect_eq(mu_model_desc_load_builtin("leg", &desc), RB_OK, "%s", rb_last_error());
    mu_model_desc_destroy(desc);

    mu_curves_destroy(copied);
    mu_curves_destroy(original);
    unlink(arm);
    rmdir(folder);
}

Test(data_files, sinew_data_dir_holds_the_worms_image_too)
{
    char folder[64];
    make_folder(folder, sizeof folder);
    char worm[128], image[128];
    snprintf(worm, sizeof worm, "%s/worm.json", folder);
    snprintf(image, sizeof image, "%s/worm-pool.png", folder);
    copy_file(SINEW_SOURCE_DIR "/models/worm.json", worm, "\"name\": \"worm\"", "\"name\": \"worm from elsewhere\"");
    cr_assert_eq(setenv("SINEW_DATA_DIR", folder, 1), 0);
    /* The model there names its image there, not the built-in one. */
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load_builtin("worm", &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(desc);
    cr_expect(strstr(rb_last_error(), "torque_muscles[0].motor_pool.image") != NULL &&
                  strstr(rb_last_error(), "/worm-pool.png: cannot open") != NULL,
              "%s", rb_last_error());
    char command[512];
    snprintf(command, sizeof command, "cp '%s/models/worm-pool.png' '%s'", SINEW_SOURCE_DIR, image);
    cr_assert_eq(system(command), 0);
    cr_assert_eq(mu_model_desc_load_builtin("worm", &desc), RB_OK, "%s", rb_last_error());
    cr_expect_str_eq(desc->name, "worm from elsewhere");
    cr_expect_str_eq(desc->torque_muscles[0].pool_path, image);
    mu_model_desc_destroy(desc);
    unsetenv("SINEW_DATA_DIR");
    unlink(image);
    unlink(worm);
    rmdir(folder);
}

Test(data_files, errors_in_a_built_in_copy_name_it)
{
    unsetenv("SINEW_DATA_DIR");
    mu_curves *curves = NULL;
    cr_expect_eq(mu_curves_create_seed_tables((mu_interpolation)99, &curves), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(curves);
    cr_expect(strstr(rb_last_error(), "interpolation is 99") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, NULL), RB_ERR_INVALID_ARGUMENT);
}

Test(data_files, the_libraries_report_the_headers_version)
{
    cr_expect_str_eq(rb_version(), RB_VERSION_STRING);
    cr_expect_str_eq(mu_version(), MU_VERSION_STRING);
    char expected[32];
    snprintf(expected, sizeof expected, "%d.%d.%d", RB_VERSION_MAJOR, RB_VERSION_MINOR, RB_VERSION_PATCH);
    cr_expect_str_eq(rb_version(), expected);
    cr_expect_eq(RB_VERSION_NUMBER, RB_VERSION_MAJOR * 10000 + RB_VERSION_MINOR * 100 + RB_VERSION_PATCH);
}
