/* SPDX-License-Identifier: MIT */
/* The model's energy account (mu_model_energy_account) and the failure it
 * watches for: energy no muscle gave the bodies.
 *
 * The truths: a rigid pendulum without damping keeps its energy (any
 * change is the integrator's error, which semi-implicit Euler keeps
 * bounded); with damping it only loses; a muscle pulling a free block in
 * no gravity gives it exactly the work tension × shortening; and energy
 * put into a body from outside is reported, while the viewer's mouse,
 * also from outside, restarts the account instead.
 */
#define _DEFAULT_SOURCE /* mkstemps (model_support.h) */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "model_support.h"
#include "mu/model.h"
#include "mu/model_desc.h"
#include "rb/rb.h"

#define ROD_LENGTH 0.5 /* m */
#define GRAVITY 9.8    /* m/s² */

/* A rod hinged at one end to a nail, released horizontal; damping in 1/s. */
static mu_model *pendulum(double damping, mu_model_desc **desc)
{
    char text[1024];
    snprintf(text, sizeof text,
             "{\"name\": \"pendulum\", \"gravity\": [0, -%g], \"frame_rate\": 60, \"substeps\": 10,"
             " \"damping\": %g,"
             " \"nails\": [{\"name\": \"Nail\", \"position\": [0, 0]}],"
             " \"bones\": [{\"name\": \"Rod\", \"centre\": [0.25, 0], \"size\": [0.5, 0.05], \"density\": 800}],"
             " \"hinges\": [{\"name\": \"Pivot\", \"body_a\": \"Nail\", \"anchor_a\": [0, 0], \"body_b\": \"Rod\","
             " \"anchor_b\": [-0.25, 0], \"radius\": 0.02}]}",
             GRAVITY, damping);
    *desc = load_model_text(text);
    mu_model *model = NULL;
    mu_model_options options = mu_default_model_options();
    cr_assert_eq(mu_model_create(*desc, &options, &model), RB_OK, "%s", rb_last_error());
    return model;
}

/* The rod's body: the one whose shape holds the rod's middle at the
 * start (bones are sensors: they do not collide). */
static rb_body_id rod_body(mu_model *model)
{
    rb_world *world = mu_model_world(model);
    rb_shape_id shapes[4];
    int count = 0;
    cr_assert_eq(rb_world_overlap_point(world, rb_v2(0.25, 0.0), rb_default_query_filter(), true, shapes, 4, &count),
                 RB_OK, "%s", rb_last_error());
    cr_assert_eq(count, 1);
    return rb_shape_body(world, shapes[0]);
}

/* J: the rod's fall from horizontal to hanging, m·g·L/2. */
static double fall_energy(mu_model *model)
{
    return rb_body_mass(mu_model_world(model), rod_body(model)) * GRAVITY * ROD_LENGTH / 2.0;
}

Test(model_energy, a_pendulum_without_damping_keeps_its_energy)
{
    mu_model_desc *desc = NULL;
    mu_model *model = pendulum(0.0, &desc);
    const double scale = fall_energy(model);
    double worst = 0.0;
    for (int f = 0; f < 180; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
        mu_model_energy e = mu_model_energy_account(model);
        worst = fmax(worst, fabs(e.created));
        cr_assert_eq(e.muscle_work, 0.0, "no muscle, no work");
    }
    cr_expect_lt(worst, 0.01 * scale, "the energy changed by %.3g J (of %.3g J)", worst, scale);
    cr_expect_null(mu_model_failure(model));
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_energy, damping_only_takes_energy_away)
{
    mu_model_desc *desc = NULL;
    mu_model *model = pendulum(8.0, &desc);
    const double scale = fall_energy(model);
    double created = 0.0;
    for (int f = 0; f < 180; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
        mu_model_energy e = mu_model_energy_account(model);
        cr_expect_leq(e.created, 1e-3 * scale, "frame %d: %.4g J created", f, e.created);
        created = e.created;
    }
    /* At 8/s the rod comes to rest hanging within 3 s: damping took its
     * whole fall. */
    cr_expect_lt(fabs(created + scale), 0.01 * scale, "damping took %.4g J of the fall's %.4g J", -created, scale);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_energy, a_muscle_gives_a_free_block_the_work_it_does)
{
    /* A block held only by a muscle to a nail, no gravity, no damping:
     * every joule the block gains is the muscle's. */
    mu_model_desc *desc = load_model_text(
        "{\"name\": \"pull\", \"gravity\": [0, 0], \"frame_rate\": 60, \"substeps\": 10, \"damping\": 0,"
        " \"nails\": [{\"name\": \"Nail\", \"position\": [0, 0]}],"
        " \"bones\": [{\"name\": \"Block\", \"centre\": [0.35, 0], \"size\": [0.1, 0.1], \"density\": 100}],"
        " \"muscles\": [{\"name\": \"Muscle\", \"rest_length\": 0.3, \"rest_width\": 0.02, \"specific_tension\": 3e5,"
        " \"start_normalized_length\": 1.0,"
        " \"path\": [{\"body\": \"Nail\", \"point\": [0, 0]}, {\"body\": \"Block\", \"point\": [-0.05, 0]}]}],"
        " \"variants\": [{\"name\": \"Default\", \"muscles\": [\"Muscle\"]}]}");
    mu_model *model = NULL;
    mu_model_options options = mu_default_model_options();
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_set_activation(model, "Muscle", 1.0), RB_OK, "%s", rb_last_error());
    mu_model_energy e = {0};
    for (int f = 0; f < 6; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
        e = mu_model_energy_account(model);
    }
    cr_expect_gt(e.muscle_work, 0.01, "the muscle did %.4g J", e.muscle_work);
    cr_expect_lt(fabs(e.created), 0.02 * e.muscle_work, "the block gained %.4g J against the muscle's %.4g J",
                 e.mechanical - e.at_start, e.muscle_work);
    cr_expect_null(mu_model_failure(model));
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_energy, energy_put_in_from_outside_is_a_failure)
{
    mu_model_desc *desc = NULL;
    mu_model *model = pendulum(0.0, &desc);
    cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    /* Spin the rod at 10 rad/s about its pin: ½·(m·L²/3)·ω² = 4.2 J per
     * kilogram from nowhere, at speeds (2.5 m/s, 10 rad/s) far inside the
     * other limits. */
    rb_world *world = mu_model_world(model);
    rb_body_id rod = rod_body(model);
    cr_assert_gt(rb_body_mass(world, rod) * 4.2, MU_MODEL_MAX_CREATED_ENERGY, "the rod is too light for the test");
    cr_assert_eq(rb_body_set_angular_velocity(world, rod, -10.0), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_linear_velocity(world, rod, rb_v2(0.0, -2.5)), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    const char *failure = mu_model_failure(model);
    cr_assert_not_null(failure, "no failure; created %.3g J", mu_model_energy_account(model).created);
    cr_expect(strstr(failure, "that no muscle gave them") != NULL, "%s", failure);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model_energy, the_mouse_restarts_the_account)
{
    mu_model_desc *desc = NULL;
    mu_model *model = pendulum(0.0, &desc);
    cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    rb_world *world = mu_model_world(model);
    rb_mouse_joint_def def = rb_default_mouse_joint_def();
    def.body = rod_body(model);
    def.local_anchor = rb_v2(0.25, 0.0);
    def.target = rb_v2(0.0, 0.5);
    def.max_force = 1000.0;
    rb_joint_id mouse;
    cr_assert_eq(rb_mouse_joint_create(world, &def, &mouse), RB_OK, "%s", rb_last_error());
    for (int f = 0; f < 30; ++f) { /* the mouse lifts the rod: energy from outside */
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
        cr_expect_eq(mu_model_energy_account(model).created, 0.0, "the account restarts while dragged");
    }
    cr_assert_eq(rb_joint_destroy(world, mouse), RB_OK, "%s", rb_last_error());
    for (int f = 0; f < 60; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
    mu_model_energy e = mu_model_energy_account(model);
    cr_expect_lt(fabs(e.created), 0.05, "after the drag %.3g J created", e.created);
    cr_expect_null(mu_model_failure(model), "%s", mu_model_failure(model) ? mu_model_failure(model) : "");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}
