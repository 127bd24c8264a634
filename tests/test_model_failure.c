/* SPDX-License-Identifier: MIT */
/* A run that has left physics says so (mu_model_failure): a weight, a
 * muscle or a torque far beyond what the joints' solver can hold within a
 * frame tears the hinges open or flings the bones, and the model reports
 * it with the time and the hinge or bone, while every built-in model, in
 * every variant, with every weight and at rest or fully active, stays
 * inside the limits.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"
#include "mu/model.h"
#include "mu/model_desc.h"
#include "simulation.h"

/* Builds `desc` at `variant` and `weight` (its glues kept as welds when
 * `welded`), holds every muscle at `activation` (and every torque muscle
 * at full recruitment when activation is 1) for `seconds`, and returns
 * the model for inspection. */
static mu_model *run_glued(const mu_model_desc *desc, int variant, int weight, double activation, double seconds,
                           bool welded)
{
    mu_model_options options = mu_default_model_options();
    options.variant = variant;
    options.weight_index = weight;
    options.weld_glues = welded;
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        cr_assert_eq(mu_model_set_activation_at(model, m, activation), RB_OK, "%s", rb_last_error());
    }
    if (activation > 0.0) {
        for (int t = 0; t < desc->torque_muscle_count; ++t) {
            mu_model_recruit(model, desc->torque_muscles[t].name, desc->torque_muscles[t].neurons);
        }
    }
    int frames = (int)lround(seconds * desc->frame_rate);
    for (int f = 0; f < frames; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
    return model;
}

static mu_model *run(const mu_model_desc *desc, int variant, int weight, double activation, double seconds)
{
    return run_glued(desc, variant, weight, activation, seconds, false);
}

Test(model_failure, built_in_models_stay_inside_the_limits)
{
    for (int k = 0; k < mu_builtin_model_count(); ++k) {
        mu_model_desc *desc = NULL;
        cr_assert_eq(mu_model_desc_load_builtin(mu_builtin_model_name(k), &desc), RB_OK, "%s", rb_last_error());
        int weights = desc->has_weight ? desc->weight.mass_count : 1;
        for (int v = 0; v < desc->variant_count; ++v) {
            for (int w = 0; w < weights; ++w) {
                for (int a = 0; a <= 1; ++a) {
                    mu_model *model = run(desc, v, w, (double)a, 3.0);
                    cr_expect_null(mu_model_failure(model), "%s, variant %d, weight %d, activation %d: %s",
                                   mu_builtin_model_name(k), v, w, a,
                                   mu_model_failure(model) != NULL ? mu_model_failure(model) : "");
                    mu_model_destroy(model);
                }
            }
        }
        mu_model_desc_destroy(desc);
    }
}

/* The index of the object named `name` in `desc`. */
static int find_index(const mu_model_desc *desc, const char *name)
{
    mu_model_ref ref;
    cr_assert(mu_model_desc_find(desc, name, &ref), "no %s", name);
    return ref.index;
}

/* The arm's bones merged, its two limited hinges and a weight 20 or more
 * times its forearm are one block the engine solves exactly
 * (engine/src/joint_block.h), which holds any weight. With its glues
 * kept as welds the limb is Gauss-Seidel's, one joint at a time, whose
 * passes cannot carry a million kilograms within a frame. */
Test(model_failure, a_million_kilograms_on_the_welded_arm_tears_a_hinge_open)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    desc->weight.masses[1] = 1e6;
    mu_model *model = run_glued(desc, 0, 1, 0.0, 1.0, true);
    const char *failure = mu_model_failure(model);
    cr_assert_not_null(failure, "a 1e6 kg weight on the arm raised no failure");
    cr_expect(strstr(failure, "hinge \"") != NULL || strstr(failure, "moves at") != NULL ||
                  strstr(failure, "turns at") != NULL,
              "%s", failure);
    cr_expect(strncmp(failure, "t = ", 4) == 0, "%s", failure);
    /* The first failure is kept, and stepping goes on. */
    char first[512];
    snprintf(first, sizeof first, "%s", failure);
    cr_expect_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    cr_expect_str_eq(mu_model_failure(model), first);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_failure, a_billion_newton_biceps_flings_the_arm)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    desc->muscles[find_index(desc, "Biceps Long")].max_force = 1e9;
    mu_model *model = run(desc, 0, 0, 1.0, 1.0);
    cr_expect_not_null(mu_model_failure(model), "Fmax 1e9 N raised no failure");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_failure, a_megatorque_worm_reports_its_hinges)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("worm", &desc), RB_OK, "%s", rb_last_error());
    cr_assert_gt(desc->torque_muscle_count, 0);
    desc->torque_muscles[0].peak_torque = 1e6;
    mu_model *model = run(desc, 0, 0, 1.0, 1.0);
    cr_expect_not_null(mu_model_failure(model), "a 1e6 N·m torque raised no failure");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* Runs `sinew ARGS` with stdout and stderr in `output`; returns its exit
 * status. */
static int run_sinew(const char *args, char *output, size_t size)
{
    return run_sinew_capture(NULL, args, SINEW_STDOUT_AND_STDERR, output, size);
}

/* Writes DIR/heavy_arm.json, the arm with its 1 kg weight choice (index 1)
 * made a million kilograms, and puts its path in `path`; the tests run it
 * with its glues welded (see above). */
static void write_heavy_arm(const char *dir, char *path, size_t size)
{
    snprintf(path, size, "%s/heavy_arm.json", dir);
    FILE *in = fopen(SINEW_SOURCE_DIR "/models/arm.json", "rb");
    cr_assert_not_null(in);
    static char text[1 << 16];
    text[fread(text, 1, sizeof text - 1, in)] = '\0';
    fclose(in);
    char *masses = strstr(text, "[0, 1, 5");
    cr_assert_not_null(masses, "arm.json's weight choices moved");
    FILE *out = fopen(path, "wb");
    cr_assert_not_null(out);
    fwrite(text, 1, (size_t)(masses - text), out);
    fputs("[0, 1e6, 5", out);
    fputs(masses + strlen("[0, 1, 5"), out);
    fclose(out);
}

Test(model_failure, sinew_run_warns_once_and_strict_makes_it_an_error)
{
    char dir[] = "/tmp/sinew-failure-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char model[256];
    write_heavy_arm(dir, model, sizeof model);

    char args[512];
    char output[16384];
    snprintf(args, sizeof args, "run '%s' --weight-index 1 --weld-glues --duration 1 --out '%s'", model, dir);
    cr_expect_eq(run_sinew(args, output, sizeof output), 0, "%s", output);
    const char *warning = strstr(output, "sinew: warning: the run failed: t = ");
    cr_expect_not_null(warning, "%s", output);
    cr_expect(warning == NULL || strstr(warning + 1, "sinew: warning: the run failed") == NULL, "warned twice: %s",
              output);
    cr_expect_not_null(strstr(output, "\nfailure      t = "), "the summary says nothing: %s", output);
    char csv[512];
    snprintf(csv, sizeof csv, "%s/heavy_arm.csv", dir);
    cr_expect_eq(access(csv, F_OK), 0, "without --strict the CSV is written");
    remove(csv);
    char sidecar[600];
    snprintf(sidecar, sizeof sidecar, "%s-metadata.json", csv);
    remove(sidecar);

    snprintf(args, sizeof args, "run '%s' --weight-index 1 --weld-glues --duration 1 --out '%s' --strict", model, dir);
    cr_expect_eq(run_sinew(args, output, sizeof output), 1, "%s", output);
    cr_expect_not_null(strstr(output, "sinew: the run failed (--strict): t = "), "%s", output);
    cr_expect_neq(access(csv, F_OK), 0, "--strict leaves no CSV");

    /* A run that holds says so too. */
    snprintf(args, sizeof args, "run arm --duration 1 --out '%s' --strict", dir);
    cr_expect_eq(run_sinew(args, output, sizeof output), 0, "%s", output);
    cr_expect_not_null(strstr(output, "failure      none"), "%s", output);
    snprintf(csv, sizeof csv, "%s/arm.csv", dir);
    remove(csv);
    snprintf(sidecar, sizeof sidecar, "%s-metadata.json", csv);
    remove(sidecar);
    remove(model);
    cr_expect_eq(rmdir(dir), 0, "files left in %s", dir);
}

Test(model_failure, the_viewer_is_told_once_per_built_model)
{
    char dir[] = "/tmp/sinew-failure-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char model[256];
    write_heavy_arm(dir, model, sizeof model);
    simulation sim;
    simulation_init(&sim);
    mu_model_options options = mu_default_model_options();
    options.weight_index = 1;
    options.weld_glues = true; /* Gauss-Seidel's limb (see above) */
    char error[SIMULATION_ERROR_SIZE];
    for (int load = 0; load < 2; ++load) {
        cr_assert(load == 0 ? simulation_load_model(&sim, model, &options, error, sizeof error)
                            : simulation_reload(&sim, &options, error, sizeof error),
                  "%s", error);
        int told = 0;
        for (int frame = 0; frame < 60; ++frame) {
            cr_assert(simulation_step(&sim, error, sizeof error), "%s", error);
            const char *failure = simulation_new_failure(&sim);
            told += failure != NULL;
            cr_expect(failure == NULL || strstr(failure, "hinge \"") != NULL, "%s", failure);
        }
        cr_expect_eq(told, 1, "load %d: told %d times, expected once", load, told);
    }
    simulation_free(&sim);
    remove(model);
    rmdir(dir);
}
