/* SPDX-License-Identifier: MIT */
/* The static formulas of Castanyer's report and the lengths derived from the
 * anchor geometry, against hand calculations; a muscle built with the
 * derived lengths starts where they say.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/geometry_lengths.h"
#include "mu/muscle.h"
#include "mu/muscle_statics.h"
#include "test_support.h"

#define DEG (RB_PI / 180.0)

Test(statics, max_force_and_pcsa_by_hand)
{
    /* 10 cm² at 30 N/cm² (0.3 MPa): 300 N. */
    expect_near(mu_max_force_from_pcsa(10e-4, 3e5), 300.0, 1e-12, "Fmax = PCSA·σ");
    /* 300 cm³ of fibres 10 cm long: 30 cm². */
    expect_near(mu_pcsa_from_volume(300e-6, 0.1), 30e-4, 1e-18, "PCSA = V/l_f");
    /* 20 cm² at 60°: 40 cm² (cos 60° = 1/2); at 0° the section itself. */
    expect_near(mu_pcsa_from_anatomical(20e-4, 60.0 * DEG), 40e-4, 1e-15, "PCSA = ACSA/cos β");
    expect_near(mu_pcsa_from_anatomical(20e-4, 0.0), 20e-4, 0.0, "unpennated");
    /* 50 000 sarcomeres of 2 µm: 10 cm; 12 cm measured at 2.4 µm: 10 cm. */
    expect_near(mu_fibre_length_from_sarcomeres(50000.0), 0.1, 1e-15, "n·2 µm");
    expect_near(mu_fibre_length_normalized(0.12, 2.4e-6), 0.1, 1e-15, "l·2 µm/s");
    /* The original biceps: π·(0.0328 m)²/4 at 1.5 MPa. */
    expect_near(mu_max_force_from_pcsa(RB_PI * 0.0328 * 0.0328 / 4.0, 1.5e6), 1267.4, 0.05, "the original biceps");
}

Test(statics, bad_arguments_are_errors)
{
    cr_expect(isnan(mu_max_force_from_pcsa(-1e-4, 3e5)));
    cr_expect(strstr(rb_last_error(), "mu_max_force_from_pcsa") != NULL, "%s", rb_last_error());
    cr_expect(isnan(mu_max_force_from_pcsa(1e-4, 0.0)));
    cr_expect(isnan(mu_pcsa_from_volume(1e-4, 0.0)));
    cr_expect(isnan(mu_pcsa_from_anatomical(1e-4, 0.5 * RB_PI)));
    cr_expect(strstr(rb_last_error(), "pennation_angle") != NULL, "%s", rb_last_error());
    cr_expect(isnan(mu_fibre_length_from_sarcomeres(NAN)));
    cr_expect(isnan(mu_fibre_length_normalized(0.1, -2e-6)));
}

Test(geometry_lengths, tendon_fraction_splits_the_path)
{
    /* L = 0.3 m, a quarter tendon: l_T = 0.075 m, belly 0.225 m; at s = 1
     * that is l_opt, at s = 1.1 l_opt = 0.225/1.1; at 20° of pennation
     * l_opt = 0.225/√(1.1² - sin² 20°). */
    mu_derived_lengths d;
    cr_assert_eq(mu_lengths_from_geometry(0.3, 0.25, 1.0, 0.0, &d), RB_OK, "%s", rb_last_error());
    expect_near(d.tendon_length, 0.075, 1e-15, "tendon");
    expect_near(d.rest_length, 0.225, 1e-15, "rest length");
    cr_assert_eq(mu_lengths_from_geometry(0.3, 0.25, 1.1, 0.0, &d), RB_OK);
    expect_near(d.rest_length, 0.225 / 1.1, 1e-15, "rest length at s = 1.1");
    cr_assert_eq(mu_lengths_from_geometry(0.3, 0.25, 1.1, 20.0 * DEG, &d), RB_OK);
    const double s20 = sin(20.0 * DEG);
    expect_near(d.rest_length, 0.225 / sqrt(1.21 - s20 * s20), 1e-15, "rest length, pennated");
    cr_assert_eq(mu_lengths_from_geometry(0.3, 0.0, 1.0, 0.0, &d), RB_OK);
    expect_near(d.tendon_length, 0.0, 0.0, "no tendon");
    cr_expect_eq(mu_lengths_from_geometry(0.3, 1.0, 1.0, 0.0, &d), RB_ERR_INVALID_ARGUMENT, "all tendon");
    cr_expect(strstr(rb_last_error(), "tendon_fraction") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_lengths_from_geometry(0.0, 0.2, 1.0, 0.0, &d), RB_ERR_INVALID_ARGUMENT, "no path");
    cr_expect_eq(mu_lengths_from_geometry(0.3, 0.2, 0.4, 30.0 * DEG, &d), RB_ERR_INVALID_ARGUMENT,
                 "start fibre below the shortest");
    cr_expect(strstr(rb_last_error(), "start_normalized_length") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_lengths_from_geometry(0.3, 0.2, 1.0, 0.0, NULL), RB_ERR_INVALID_ARGUMENT, "NULL out");
}

Test(geometry_lengths, a_muscle_built_with_them_starts_at_its_start_length)
{
    /* A path over a via point, 0.2 + 0.15 m long, 30 % tendon, s = 1.2 and
     * 15° of pennation: built with the derived lengths (rigid tendon), the
     * muscle's fibre starts at 1.2·l_opt and belly + tendon = path. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    mu_analytic_curves parameters = mu_default_analytic_curves();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_analytic(&parameters, &curves), RB_OK);
    rb_body_id a = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id b = make_body(world, RB_BODY_STATIC, rb_v2(0.2, 0.0), 0.0);
    rb_body_id c = make_body(world, RB_BODY_STATIC, rb_v2(0.2, 0.15), 0.0);
    mu_derived_lengths d;
    cr_assert_eq(mu_lengths_from_geometry(0.35, 0.3, 1.2, 15.0 * DEG, &d), RB_OK);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 3;
    def.bodies[0] = a;
    def.bodies[1] = b;
    def.bodies[2] = c;
    def.rest_length = d.rest_length;
    def.tendon_length = d.tendon_length;
    def.pennation_angle = 15.0 * DEG;
    def.max_force = 500.0;
    def.curves = curves;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    const mu_muscle_readout r = mu_muscle_read(muscle);
    expect_near(r.normalized_length, 1.2, 1e-12, "start normalized fibre length");
    expect_near(r.length + r.tendon_length, 0.35, 1e-12, "belly + tendon = path");
    expect_near(r.tendon_length, 0.105, 1e-12, "tendon = 30 % of the path");
    mu_muscle_destroy(muscle, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}
