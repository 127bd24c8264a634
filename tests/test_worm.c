/* SPDX-License-Identifier: MIT */
/* The worm of McIntyre's "Simulated Muscles": its file loads as described,
 * and its torque muscle turns the top segment only when neurons are
 * recruited, by the torque its exertion gives; a wrong name is answered
 * with the right ones.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/model.h"
#include "test_support.h"

static mu_model *build_worm(mu_model_desc **desc)
{
    cr_assert_eq(mu_model_desc_load_builtin("worm", desc), RB_OK, "%s", rb_last_error());
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(*desc, &options, &model), RB_OK, "%s", rb_last_error());
    return model;
}

Test(worm, loads_as_models_md_gives_it)
{
    mu_model_desc *desc = NULL;
    mu_model *model = build_worm(&desc);
    cr_expect_eq(desc->bone_count, 6);
    cr_expect_eq(desc->hinge_count, 5);
    cr_expect(desc->bones[0].is_static, "the bottom segment is static");
    for (int b = 0; b < 6; ++b) {
        cr_expect(!desc->bones[b].is_static || b == 0);
        expect_near(desc->bones[b].size.x, 0.05, 0.0, "segment width");
        expect_near(desc->bones[b].size.y, 0.2, 0.0, "segment height");
    }
    cr_assert_eq(mu_model_torque_muscle_count(model), 1);
    const mu_motor_pool *pool = mu_model_motor_pool(model, 0);
    cr_expect_eq(mu_motor_pool_neuron_count(pool), 200);
    /* Its profile image (models/worm-pool.png) draws the strengths 1 .. 100
     * as 2.55 .. 255 (255 − blue), to half a 16-bit step. */
    expect_near(mu_motor_pool_strength(pool, 0), 2.55, 0.5 / 257.0, "weakest");
    expect_near(mu_motor_pool_strength(pool, 199), 255.0, 0.0, "strongest");
    for (int i = 1; i < 200; ++i) {
        expect_near(mu_motor_pool_strength(pool, i) / mu_motor_pool_strength(pool, i - 1), pow(100.0, 1.0 / 199.0),
                    2e-3, "equal ratios between neighbours");
    }
    cr_expect_eq(mu_motor_pool_recruited(pool), 0);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The top hinge's angle after one second at the given recruitment. */
static double top_joint_after_one_second(int neurons, double *exertion)
{
    mu_model_desc *desc = NULL;
    mu_model *model = build_worm(&desc);
    cr_assert_eq(mu_model_recruit(model, "Torque Muscle", neurons), RB_OK, "%s", rb_last_error());
    *exertion = mu_motor_pool_exertion(mu_model_motor_pool(model, 0));
    expect_near(mu_torque_actuator_torque(mu_model_torque_actuator(model, 0)), *exertion * 0.01, 1e-15,
                "τ = exertion · peak torque");
    for (int frame = 0; frame < 60; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
    const double angle = mu_model_hinge_angle(model, 4);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    return angle;
}

Test(worm, recruitment_turns_the_top_segment)
{
    double exertion = NAN;
    const double at_rest = top_joint_after_one_second(0, &exertion);
    expect_near(exertion, 0.0, 0.0, "no neurons, no exertion");
    expect_near(at_rest, 0.0, 1e-9, "without recruitment nothing moves (zero gravity)");
    const double weak = top_joint_after_one_second(60, &exertion);
    cr_expect(exertion > 0.02 && exertion < 0.04, "the first 30 %% give about 3 %%: %g", exertion);
    double full_exertion = NAN;
    const double full = top_joint_after_one_second(200, &full_exertion);
    expect_near(full_exertion, 1.0, 1e-15, "all neurons");
    /* From rest, over a short time the angle grows with the torque. The
     * hinge angle is angle(top) − angle(below): the top turns
     * counter-clockwise against its reaction. */
    cr_expect(full > 10.0, "full recruitment turns the top joint visibly: %g°", full);
    cr_expect(weak > 0.0 && weak < full, "60 neurons turn it less: %g° vs %g°", weak, full);
    expect_near(weak / full, exertion, 0.2 * exertion, "small angles scale with the exertion");
}

Test(worm, bad_recruit_calls_are_errors)
{
    mu_model_desc *desc = NULL;
    mu_model *model = build_worm(&desc);
    cr_expect_eq(mu_model_recruit(model, "Nobody", 10), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "Nobody") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_model_recruit_at(model, 1, 10), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(mu_model_motor_pool(model, -1));
    cr_expect_eq(mu_model_recruit(model, "Torque Muscle", 500), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "500") != NULL && strstr(rb_last_error(), "200") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_motor_pool_recruited(mu_model_motor_pool(model, 0)), 0, "refused, not clamped to the pool");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(worm, an_unknown_torque_muscle_is_answered_with_the_names_built)
{
    mu_model_desc *desc = NULL;
    mu_model *model = build_worm(&desc);
    cr_expect_eq(mu_model_recruit(model, "Torque", 10), RB_ERR_INVALID_ARGUMENT);
    cr_expect_str_eq(rb_last_error(),
                     "mu_model_recruit: no torque muscle named \"Torque\" is built in this model, expected \"Torque "
                     "Muscle\"");
    cr_expect_eq(mu_motor_pool_recruited(mu_model_motor_pool(model, 0)), 0, "nothing recruited");
    cr_expect_eq(mu_model_recruit(model, "Torque Muscle", 201), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "neurons") != NULL, "%s", rb_last_error());
    mu_model_destroy(model);
    /* Below level 3 no torque muscle is built: the message says so. */
    mu_model_options options = mu_default_model_options();
    options.level = 2;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_model_recruit(model, "Torque Muscle", 10), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "this model builds no torque muscle") != NULL, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}
