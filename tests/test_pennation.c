/* SPDX-License-Identifier: MIT */
/* Pennation with a fixed-width belly: the angle against sin α = w/l_f by
 * hand, its rise as the fibre shortens and its cap, and the muscle's
 * force projected on the tendon (cos α) and its fibre velocity
 * (L'·cos α).
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/muscle.h"
#include "mu/pennation.h"
#include "test_support.h"

#define DEG (RB_PI / 180.0)

Test(pennation, angle_follows_the_fixed_width)
{
    /* l_opt = 0.1 m at 20°: w = 0.1·sin 20° = 0.034202 m. */
    const double width = mu_pennation_width(0.1, 20.0 * DEG);
    expect_near(width, 0.1 * sin(20.0 * DEG), 1e-15, "w");
    expect_near(mu_pennation_angle(0.1, width), 20.0 * DEG, 1e-12, "α at l_opt is α_opt");
    double previous = 0.0;
    for (int i = 0; i < 40; ++i) {
        const double fibre = 0.16 - 0.003 * i; /* shortening from 1.6 to 0.43 l_opt */
        const double angle = mu_pennation_angle(fibre, width);
        expect_near(sin(angle), width / fibre, 1e-12, "sin α = w/l_f");
        cr_expect(angle > previous, "the angle rises as the fibre shortens: %g after %g", angle, previous);
        cr_expect(angle < MU_MAX_PENNATION_ANGLE);
        /* The belly's extent along the path gives the fibre back. */
        expect_near(mu_pennation_fibre_length(fibre * cos(angle), width), fibre, 1e-12, "√(x² + w²)");
        previous = angle;
    }
}

Test(pennation, angle_is_capped_below_ninety_degrees)
{
    /* The cap is acos(0.1) = 84.26°; the shortest fibre w/sin(84.26°). */
    expect_near(MU_MAX_PENNATION_ANGLE, acos(0.1), 1e-15, "cap");
    expect_near(MU_MAX_PENNATION_ANGLE / DEG, 84.26, 0.005, "cap in degrees");
    const double width = mu_pennation_width(0.1, 30.0 * DEG); /* 0.05 m */
    const double shortest = mu_pennation_min_fibre_length(width);
    expect_near(shortest, 0.05 / sqrt(0.99), 1e-15, "shortest fibre");
    const double fibres[] = {shortest, 0.05, 0.03, 0.0, -1.0};
    for (size_t i = 0; i < sizeof fibres / sizeof *fibres; ++i) {
        const double angle = mu_pennation_angle(fibres[i], width);
        expect_near(angle, MU_MAX_PENNATION_ANGLE, 1e-12, "capped angle");
        cr_expect(angle < 0.5 * RB_PI);
    }
    /* A belly shorter than the shortest fibre's extent gets the shortest fibre. */
    expect_near(mu_pennation_fibre_length(0.001, width), shortest, 1e-15, "fibre at the cap");
    /* Unpennated: no angle, and the belly is the fibre (any sign, as the original). */
    cr_expect_eq(mu_pennation_angle(0.01, 0.0), 0.0);
    cr_expect_eq(mu_pennation_fibre_length(-0.01, 0.0), -0.01);
    cr_expect(isnan(mu_pennation_width(0.1, MU_MAX_PENNATION_ANGLE)), "α_opt at the cap");
    cr_expect(strstr(rb_last_error(), "mu_pennation_width") != NULL, "%s", rb_last_error());
    cr_expect(isnan(mu_pennation_angle(0.1, -0.01)), "negative width");
    cr_expect(isnan(mu_pennation_fibre_length(NAN, 0.01)), "NaN belly");
}

/* A pennated muscle (l_opt 0.2 m, Fmax 1000 N, α_opt 30°, analytic
 * curves) from a static origin to `insertion` at (0.25, 0), tendon 0.05 m. */
static mu_muscle *make_muscle(rb_world *world, rb_body_id insertion, const mu_curves *curves, double tendon)
{
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = origin;
    def.bodies[1] = insertion;
    def.rest_length = 0.2;
    def.max_force = 1000.0;
    def.tendon_length = tendon;
    def.pennation_angle = 30.0 * DEG;
    def.curves = curves;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    return muscle;
}

Test(pennation, force_is_projected_on_the_tendon)
{
    /* Isometric, belly extent x = 0.25 - tendon along the path; the fibre
     * √(x² + w²) with w = 0.2·sin 30° = 0.1 m; the tension
     * a·Fmax·f_L(l_f/l_opt)·cos α with cos α = x/l_f. Tendons of 0.05 m
     * (x = 0.2: l_f = 0.2236, α = 26.6°) and 0.12 m (x = 0.13: l_f = 0.164,
     * α = 37.6°: a shorter fibre, a larger angle). */
    mu_analytic_curves parameters = mu_default_analytic_curves();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_analytic(&parameters, &curves), RB_OK);
    const double tendons[] = {0.05, 0.12};
    double previous_angle = 0.0;
    for (int i = 0; i < 2; ++i) {
        rb_world *world = make_world(rb_v2(0.0, 0.0));
        rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(0.25, 0.0), 0.0);
        mu_muscle *muscle = make_muscle(world, insertion, curves, tendons[i]);
        cr_assert_eq(mu_muscle_set_activation(muscle, 0.8), RB_OK);
        cr_assert_eq(mu_muscle_prepare(muscle, world, 1.0 / 600.0), RB_OK);
        step_world(world, 1.0 / 600.0, 1);
        cr_assert_eq(mu_muscle_measure(muscle, world), RB_OK);
        const mu_muscle_readout r = mu_muscle_read(muscle);
        const double x = 0.25 - tendons[i];
        const double fibre = sqrt(x * x + 0.01);
        const double cosine = x / fibre;
        const double z = (fibre / 0.2 - 1.0) / 0.25;
        const double passive = fibre > 0.2 ? 0.01 * (exp(10.0 * (fibre / 0.2 - 1.0)) - 1.0) : 0.0;
        const double expected = 1000.0 * (0.8 * exp(-z * z) + passive) * cosine;
        expect_near(r.fibre_length, fibre, 1e-12, "fibre length");
        expect_near(r.length, x, 1e-12, "belly extent along the path");
        expect_near(r.normalized_length, fibre / 0.2, 1e-12, "normalized fibre length");
        expect_near(r.pennation_angle, acos(cosine), 1e-12, "angle");
        expect_near(r.total_force, expected, 1e-9 * expected, "projected force");
        expect_near(r.passive_force, 1000.0 * passive * cosine, 1e-9, "projected passive force");
        cr_expect(r.pennation_angle > previous_angle);
        previous_angle = r.pennation_angle;
        mu_muscle_destroy(muscle, world);
        destroy_world_and_expect_no_leak(world);
    }
    mu_curves_destroy(curves);
}

Test(pennation, fibre_moves_slower_than_the_path)
{
    /* Fixed width: l_f·l_f' = x·x', so the fibre lengthens at L'·cos α. The
     * insertion is kinematic at 0.02 m/s along the path. */
    mu_analytic_curves parameters = mu_default_analytic_curves();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_analytic(&parameters, &curves), RB_OK);
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id insertion = make_body(world, RB_BODY_KINEMATIC, rb_v2(0.25, 0.0), 0.0);
    cr_assert_eq(rb_body_set_linear_velocity(world, insertion, rb_v2(0.02, 0.0)), RB_OK);
    mu_muscle *muscle = make_muscle(world, insertion, curves, 0.05);
    cr_assert_eq(mu_muscle_set_activation(muscle, 1.0), RB_OK);
    cr_assert_eq(mu_muscle_prepare(muscle, world, 1.0 / 600.0), RB_OK);
    step_world(world, 1.0 / 600.0, 1);
    cr_assert_eq(mu_muscle_measure(muscle, world), RB_OK);
    const mu_muscle_readout r = mu_muscle_read(muscle);
    expect_near(r.velocity, 0.02 * cos(r.pennation_angle), 1e-12, "fibre velocity L'·cos α");
    expect_near(r.normalized_velocity, r.velocity / 0.25, 1e-15, "over Vmax");
    mu_muscle_destroy(muscle, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}
