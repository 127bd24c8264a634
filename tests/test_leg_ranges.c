/* SPDX-License-Identifier: MIT */
/* The built-in leg bends like a leg: its hinges carry the normal ranges of
 * motion of the American Academy of Orthopaedic Surgeons' handbook ("Joint
 * Motion: Method of Measuring and Recording", 1965), converted to the
 * model's hinge angles, and every variant, at every weight, relaxed or
 * fully active, stays inside them for the ten seconds `sinew run` runs.
 * The source's unlimited hinges (leg-unlimited) still fold as the source's
 * do.
 *
 * The conversions (models/leg.json's comments say the same): a hinge angle
 * is angle(B) - angle(A), counter-clockwise positive, 0 in the start pose
 * (seated: femur horizontal, tibia vertical, foot square to it), the leg
 * facing +x. Hip flexion = 90° + hip angle; knee flexion = 90° - knee
 * angle; ankle dorsiflexion = ankle angle; toe (first MTP) extension = sole
 * angle.
 *
 * The tolerance: a limit is held through the bodies between it and the
 * load, and a 200 kg weight dropping onto the ankle's stop is held
 * through the 0.5 kg foot, a mass ratio of 400. Gauss-Seidel passes,
 * one joint at a time, carry it a little at a time: at the leg's 10
 * substeps a frame they let the ankle pass its stop by 20°. The engine
 * solves the leg's limited hinges as one block (engine/src/joint_block.h),
 * and every variant then stays within 0.001° of its ranges; the test
 * allows 0.01°.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mu/model.h"
#include "mu/model_desc.h"

#define TOLERANCE_DEG 0.01
#define SECONDS 10.0

/* AAOS (1965), degrees of normal active motion. */
#define HIP_FLEXION 120.0
#define HIP_EXTENSION 30.0
#define KNEE_FLEXION 135.0
#define KNEE_EXTENSION 0.0
#define ANKLE_DORSIFLEXION 20.0
#define ANKLE_PLANTARFLEXION 50.0
#define TOE_EXTENSION 70.0
#define TOE_FLEXION 45.0

typedef struct range {
    const char *hinge;
    double lower, upper; /* degrees of hinge angle */
} range;

static const mu_model_hinge *hinge_named(const mu_model_desc *desc, const char *name)
{
    for (int h = 0; h < desc->hinge_count; ++h) {
        if (strcmp(desc->hinges[h].name, name) == 0) {
            return &desc->hinges[h];
        }
    }
    cr_assert_fail("the leg has no hinge \"%s\"", name);
    return NULL;
}

Test(leg_ranges, the_hinges_carry_the_published_ranges_converted_to_hinge_angles)
{
    const range expected[] = {
        {"Hip", -HIP_EXTENSION - 90.0, HIP_FLEXION - 90.0},
        {"Knee", 90.0 - KNEE_FLEXION, 90.0 - KNEE_EXTENSION},
        {"Ankle", -ANKLE_PLANTARFLEXION, ANKLE_DORSIFLEXION},
        {"Sole", -TOE_FLEXION, TOE_EXTENSION},
    };
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("leg", &desc), RB_OK, "%s", rb_last_error());
    cr_assert_eq(desc->hinge_count, 4);
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; ++i) {
        const mu_model_hinge *hinge = hinge_named(desc, expected[i].hinge);
        cr_expect(hinge->has_lower && hinge->has_upper, "%s has both limits", hinge->name);
        cr_expect_float_eq(hinge->lower, expected[i].lower, 1e-12, "%s lower %g, expected %g", hinge->name,
                           hinge->lower, expected[i].lower);
        cr_expect_float_eq(hinge->upper, expected[i].upper, 1e-12, "%s upper %g, expected %g", hinge->name,
                           hinge->upper, expected[i].upper);
    }
    mu_model_desc_destroy(desc);
}

/* Runs `desc` at `variant` and `weight` for SECONDS with every muscle of
 * the variant at `activation`, recording each hinge's extremes over every
 * substep (a pass between two frames counts). */
static void run_extremes(const mu_model_desc *desc, int variant, int weight, double activation, double *lowest,
                         double *highest)
{
    mu_model_options options = mu_default_model_options();
    options.variant = variant;
    options.weight_index = weight;
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        cr_assert_eq(mu_model_set_activation_at(model, m, activation), RB_OK, "%s", rb_last_error());
    }
    for (int h = 0; h < desc->hinge_count; ++h) {
        lowest[h] = INFINITY;
        highest[h] = -INFINITY;
    }
    long substeps = lround(SECONDS * desc->frame_rate) * desc->substeps;
    for (long s = 0; s < substeps; ++s) {
        cr_assert_eq(mu_model_substep(model), RB_OK, "%s", rb_last_error());
        for (int h = 0; h < desc->hinge_count; ++h) {
            double angle = mu_model_hinge_angle(model, h);
            lowest[h] = fmin(lowest[h], angle);
            highest[h] = fmax(highest[h], angle);
        }
    }
    cr_expect_null(mu_model_failure(model), "%s", mu_model_failure(model));
    mu_model_destroy(model);
}

Test(leg_ranges, every_variant_and_weight_stays_within_the_ranges_relaxed_and_fully_active, .timeout = 240)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("leg", &desc), RB_OK, "%s", rb_last_error());
    cr_assert(desc->has_weight);
    double worst = 0.0;
    for (int v = 0; v < desc->variant_count; ++v) {
        for (int w = 0; w < desc->weight.mass_count; ++w) {
            for (int a = 0; a <= 1; ++a) {
                double lowest[4], highest[4];
                run_extremes(desc, v, w, (double)a, lowest, highest);
                for (int h = 0; h < desc->hinge_count; ++h) {
                    const mu_model_hinge *hinge = &desc->hinges[h];
                    double below = hinge->lower - lowest[h], above = highest[h] - hinge->upper;
                    worst = fmax(worst, fmax(below, above));
                    cr_expect(below <= TOLERANCE_DEG && above <= TOLERANCE_DEG,
                              "variant \"%s\", %g kg, activation %d: %s went over [%g, %g] to %.2f .. %.2f",
                              desc->variants[v].name, desc->weight.masses[w], a, hinge->name, hinge->lower,
                              hinge->upper, lowest[h], highest[h]);
                }
            }
        }
    }
    cr_log_info("the leg's hinges passed their limits by at most %.4f degrees", worst);
    mu_model_desc_destroy(desc);
}

/* Where the foot's heel (its back end, 0.085 m behind its centre) is, m. */
static double heel_height(const mu_model *model, int foot)
{
    rb_vec2 centre = mu_model_part_centre(model, foot);
    double angle = mu_model_part_angle(model, foot) * RB_PI / 180.0;
    return centre.y - 0.085 * sin(angle);
}

Test(leg_ranges, plantarflexion_is_the_negative_ankle_angle_and_lifts_the_heel)
{
    /* The sign convention checked on the geometry: the calf muscles, fully
     * active at the lightest weight, raise the heel about the held toe and
     * turn the ankle to its negative (plantarflexion) stop. */
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("leg", &desc), RB_OK, "%s", rb_last_error());
    mu_model_options options = mu_default_model_options();
    options.variant = 2; /* All Gas + Soleus */
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    int foot = -1, ankle = -1;
    for (int p = 0; p < mu_model_part_count(model); ++p) {
        foot = strcmp(mu_model_part_name(model, p), "Foot") == 0 ? p : foot;
    }
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        ankle = strcmp(mu_model_hinge_name(model, h), "Ankle") == 0 ? h : ankle;
    }
    cr_assert(foot >= 0 && ankle >= 0);
    double start = heel_height(model, foot);
    cr_assert_eq(mu_model_set_activation(model, "Gastrocnemius Lateral + Gastrocnemius Medial + Soleus", 1.0), RB_OK,
                 "%s", rb_last_error());
    for (int f = 0; f < 120; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
    cr_expect_gt(heel_height(model, foot) - start, 0.05, "the heel rose %.3f m", heel_height(model, foot) - start);
    cr_expect_lt(mu_model_hinge_angle(model, ankle), -ANKLE_PLANTARFLEXION + TOLERANCE_DEG, "ankle at %.2f degrees",
                 mu_model_hinge_angle(model, ankle));
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(leg_ranges, the_unlimited_leg_folds_as_the_sources_does)
{
    /* The source's hinges: 100 kg on the relaxed leg folds the knee over
     * (about 176° against the 90° of a straight knee), turns the ankle
     * round (about 270°) and winds the toe hinge past -360°; the ankle's
     * one limit, -70°, is never reached from above. */
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("leg-unlimited", &desc), RB_OK, "%s", rb_last_error());
    cr_assert_eq(desc->substeps, 10, "the source's substeps");
    int with_limits = 0;
    for (int h = 0; h < desc->hinge_count; ++h) {
        with_limits += desc->hinges[h].has_lower || desc->hinges[h].has_upper;
    }
    const mu_model_hinge *ankle = hinge_named(desc, "Ankle");
    cr_expect(with_limits == 1 && ankle->has_lower && !ankle->has_upper && ankle->lower == -70.0,
              "only the ankle's lower limit, -70 degrees");
    int hundred = -1;
    for (int w = 0; w < desc->weight.mass_count; ++w) {
        hundred = desc->weight.masses[w] == 100.0 ? w : hundred;
    }
    cr_assert(hundred >= 0);
    double lowest[4], highest[4];
    run_extremes(desc, 0, hundred, 0.0, lowest, highest);
    cr_expect_gt(highest[1], 150.0, "the knee reached %.1f degrees", highest[1]);
    cr_expect_gt(highest[2], 240.0, "the ankle reached %.1f degrees", highest[2]);
    cr_expect_lt(lowest[3], -360.0, "the toe hinge reached %.1f degrees", lowest[3]);
    mu_model_desc_destroy(desc);
}
