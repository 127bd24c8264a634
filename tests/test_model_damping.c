/* SPDX-License-Identifier: MIT */
/* Bone damping, set in the model file per model and per bone (default
 * 8/s, linear and angular): two free bones fall under gravity, and each
 * falls as the engine's damping step predicts for its own damping c. The
 * truth is that step worked by hand: each substep of h, v ← (v + h·g)/(1 +
 * h·c), then y ← y + h·v (docs/engine.md, "The step"), whose velocity
 * tends to the terminal g/c. */
#define _POSIX_C_SOURCE 200809L /* mkstemp */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/model.h"
#include "mu/model_desc.h"

#define GRAVITY 9.8
#define FRAME_RATE 60.0
#define SUBSTEPS 10
#define FRAMES 120

/* Writes `text` to a temporary model file and loads it. */
static rb_status load_text(const char *text, mu_model_desc **desc)
{
    char path[] = "/tmp/sinew-damping-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    FILE *file = fdopen(fd, "wb");
    cr_assert_not_null(file);
    fputs(text, file);
    fclose(file);
    rb_status status = mu_model_desc_load(path, desc);
    remove(path);
    return status;
}

/* Two free bones; `model_damping` and `bone_damping` are JSON members or "". */
static void two_bones(char *text, size_t size, const char *model_damping, const char *bone_damping)
{
    snprintf(text, size,
             "{\"name\": \"falling\", \"frame_rate\": %g, \"substeps\": %d %s,\n"
             " \"bones\": [\n"
             "  {\"name\": \"Own\", \"centre\": [0, 0], \"size\": [0.1, 0.1] %s},\n"
             "  {\"name\": \"Model's\", \"centre\": [1, 0], \"size\": [0.1, 0.1]}]}\n",
             FRAME_RATE, SUBSTEPS, model_damping, bone_damping);
}

/* The drop after FRAMES frames of a body starting at rest with damping c. */
static double expected_drop(double c)
{
    const double h = 1.0 / (FRAME_RATE * SUBSTEPS);
    double v = 0.0, y = 0.0;
    for (int i = 0; i < FRAMES * SUBSTEPS; ++i) {
        v = (v + h * GRAVITY) / (1.0 + h * c);
        y += h * v;
    }
    return y;
}

static void expect_drops(const char *model_damping, const char *bone_damping, double own, double models)
{
    char text[1024];
    two_bones(text, sizeof text, model_damping, bone_damping);
    mu_model_desc *desc = NULL;
    cr_assert_eq(load_text(text, &desc), RB_OK, "%s", rb_last_error());
    cr_expect_eq(desc->bones[0].damping, own);
    cr_expect_eq(desc->bones[1].damping, models);
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    for (int frame = 0; frame < FRAMES; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
    const double drops[2] = {-mu_model_part_centre(model, 0).y, -mu_model_part_centre(model, 1).y};
    const double dampings[2] = {own, models};
    for (int b = 0; b < 2; ++b) {
        const double expected = expected_drop(dampings[b]);
        cr_expect(fabs(drops[b] - expected) <= 1e-9 * expected,
                  "bone %d, damping %g/s: dropped %.12g m, expected %.12g", b, dampings[b], drops[b], expected);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_damping, the_default_is_8_per_second)
{
    expect_drops("", "", 8.0, 8.0);
    /* Against the continuous drag: terminal speed g/c = 1.225 m/s, reached
     * to within e^-16 after 2 s; the drop is g/c·(t - (1 - e^(-ct))/c). */
    const double t = FRAMES / FRAME_RATE, c = 8.0;
    const double continuous = GRAVITY / c * (t - (1.0 - exp(-c * t)) / c);
    cr_expect(fabs(expected_drop(c) - continuous) <= 0.01 * continuous, "the damping step drops %g m, the drag %g m",
              expected_drop(c), continuous);
}

Test(model_damping, a_model_sets_every_bones_damping_and_a_bone_its_own)
{
    expect_drops(", \"damping\": 2", "", 2.0, 2.0);
    expect_drops(", \"damping\": 2", ", \"damping\": 20", 20.0, 2.0);
    expect_drops("", ", \"damping\": 0", 0.0, 8.0);
}

Test(model_damping, damping_out_of_range_is_refused_with_its_path)
{
    char text[1024];
    mu_model_desc *desc = NULL;
    two_bones(text, sizeof text, ", \"damping\": -1", "");
    cr_expect_eq(load_text(text, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), ": damping: -1 is out of range, expected the bones' damping in 1/s (in [0, "
                                      "1000])") != NULL,
              "%s", rb_last_error());
    two_bones(text, sizeof text, "", ", \"damping\": 1001");
    cr_expect_eq(load_text(text, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), ": bones[0].damping: 1001 is out of range, expected the bone's damping in 1/s "
                                      "(in [0, 1000])") != NULL,
              "%s", rb_last_error());
    cr_expect_null(desc);
}
