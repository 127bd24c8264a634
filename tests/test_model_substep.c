/* SPDX-License-Identifier: MIT */
/* mu_model_substep: a frame is the model's substeps, so stepping
 * substep by substep gives the state mu_model_step gives (to rounding),
 * and the model's time counts substeps without drifting.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/model.h"

Test(model_substep, substeps_add_up_to_frames)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    mu_model_options options = mu_default_model_options();
    mu_model *by_frame = NULL, *by_substep = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &by_frame), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_create(desc, &options, &by_substep), RB_OK, "%s", rb_last_error());
    /* Sleep is judged once per engine step, so it would tell the two
     * apart; experiments run with it off (tools/experiments/substep_model.c). */
    cr_assert_eq(rb_world_enable_sleep(mu_model_world(by_frame), false), RB_OK);
    cr_assert_eq(rb_world_enable_sleep(mu_model_world(by_substep), false), RB_OK);
    cr_assert_eq(mu_model_set_activation(by_frame, "Biceps Short", 0.7), RB_OK);
    cr_assert_eq(mu_model_set_activation(by_substep, "Biceps Short", 0.7), RB_OK);
    const int frames = 120;
    for (int f = 0; f < frames; ++f) {
        cr_assert_eq(mu_model_step(by_frame), RB_OK, "%s", rb_last_error());
        for (int s = 0; s < desc->substeps; ++s) {
            cr_assert_eq(mu_model_substep(by_substep), RB_OK, "%s", rb_last_error());
        }
    }
    /* The same solve, substep for substep: only collision (once per
     * engine step) and the order of a few sums differ, and the arm's parts
     * never touch, so the states agree to rounding. */
    for (int m = 0; m < mu_model_muscle_count(by_frame); ++m) {
        mu_muscle_readout f = mu_model_muscle_readout(by_frame, m), s = mu_model_muscle_readout(by_substep, m);
        cr_expect(fabs(f.total_force - s.total_force) <= 1e-9 * fmax(1.0, f.total_force), "muscle %d: %.15g N, %.15g N",
                  m, f.total_force, s.total_force);
        cr_expect(fabs(f.length - s.length) <= 1e-12, "muscle %d: %.15g m, %.15g m", m, f.length, s.length);
    }
    for (int h = 0; h < mu_model_hinge_count(by_frame); ++h) {
        double f = mu_model_hinge_angle(by_frame, h), s = mu_model_hinge_angle(by_substep, h);
        cr_expect(fabs(f - s) <= 1e-9, "hinge %d: %.15g deg, %.15g deg", h, f, s);
    }
    /* 120 frames at 60 Hz: 2 s exactly, counted rather than summed. */
    cr_expect_eq(mu_model_time(by_frame), 2.0);
    cr_expect_eq(mu_model_time(by_substep), 2.0);
    cr_expect_eq(mu_model_substep_duration(by_frame), 1.0 / (desc->frame_rate * desc->substeps));
    /* One substep further: a tenth of a frame later. */
    cr_assert_eq(mu_model_substep(by_substep), RB_OK);
    cr_expect_float_eq(mu_model_time(by_substep), 2.0 + 1.0 / 600.0, 1e-15);
    cr_expect_neq(mu_model_substep(NULL), RB_OK);
    cr_expect(strstr(rb_last_error(), "mu_model_substep") != NULL, "%s", rb_last_error());
    mu_model_destroy(by_frame);
    mu_model_destroy(by_substep);
    mu_model_desc_destroy(desc);
    cr_expect_eq(rb_bytes_in_use(), 0);
}
