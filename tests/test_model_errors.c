/* SPDX-License-Identifier: MIT */
/* Errors while building or running a model name what the user wrote: the
 * model file and the object of it (muscle, bone, hinge), never an engine
 * function. The loader refuses every value these come from, so each case
 * breaks a loaded description in memory, as a program using the API
 * could. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mu/model.h"
#include "mu/model_desc.h"

#define SAMPLE SINEW_SOURCE_DIR "/models/sample.json"

static mu_model_desc *load_sample(void)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load(SAMPLE, &desc), RB_OK, "%s", rb_last_error());
    return desc;
}

/* The message names the file and `object`, says `problem`, and names no
 * engine or muscle-layer function. */
static void expect_message(const char *object, const char *problem)
{
    const char *message = rb_last_error();
    cr_expect(strncmp(message, SAMPLE ": ", strlen(SAMPLE ": ")) == 0, "the file first: %s", message);
    cr_expect(strstr(message, object) != NULL, "names %s: %s", object, message);
    cr_expect(strstr(message, problem) != NULL, "says %s: %s", problem, message);
    cr_expect(strstr(message, "rb_") == NULL && strstr(message, "mu_") == NULL, "names a function: %s", message);
}

Test(model_errors, a_muscle_that_cannot_be_built_is_named)
{
    mu_model_desc *desc = load_sample();
    mu_model_muscle *muscle = &desc->muscles[0];
    muscle->path[1] = muscle->path[0];
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_expect_neq(mu_model_create(desc, &options, &model), RB_OK);
    cr_expect_null(model);
    expect_message("muscle \"Muscle\" (muscles[0]) in variant \"Default\"", "points 0 and 1 coincide");
    mu_model_desc_destroy(desc);
}

Test(model_errors, a_bone_that_cannot_be_built_is_named)
{
    mu_model_desc *desc = load_sample();
    desc->bones[1].size.x = 1e-300;
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_expect_neq(mu_model_create(desc, &options, &model), RB_OK);
    cr_expect_null(model);
    expect_message("bone \"Bone2\" (bones[1]) in variant \"Default\"", "expected both >= 0.0005 m");
    mu_model_desc_destroy(desc);
}

Test(model_errors, a_muscle_that_fails_during_a_step_is_named_with_the_time)
{
    mu_model_desc *desc = load_sample();
    desc->muscles[0].max_velocity = 1e-300;
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    rb_status status = mu_model_create(desc, &options, &model);
    if (status == RB_OK) {
        mu_model_set_activation(model, "Muscle", 1.0);
        for (int frame = 0; frame < 10 && status == RB_OK; ++frame) {
            status = mu_model_step(model);
        }
        cr_expect_neq(status, RB_OK, "a Vmax of 1e-300 m/s ran");
        expect_message("muscle \"Muscle\" (muscles[0])", "at t = ");
    } else {
        expect_message("muscle \"Muscle\" (muscles[0])", "max_velocity");
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}
