/* SPDX-License-Identifier: MIT */
/* Built models: counts at every level, variant and weight (worked out by
 * hand from the original report's geometry), joints that start met, the muscles'
 * actions on the joints, the Triceps Medial warning, and stability under
 * full activation switched on and off.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/model.h"
#include "test_support.h"

static mu_model_desc *load(const char *name)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin(name, &desc), RB_OK, "%s", rb_last_error());
    return desc;
}

static mu_model *build(const mu_model_desc *desc, int level, int variant, int weight_index, bool weld_glues)
{
    mu_model_options options = mu_default_model_options();
    options.level = level;
    options.variant = variant;
    options.weight_index = weight_index;
    options.weld_glues = weld_glues;
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "level %d variant %d weight %d: %s", level, variant,
                 weight_index, rb_last_error());
    return model;
}

/* Expected counts per level (0 .. 4): engine bodies, joints. Bodies: the
 * nails and bones, glued ones merged from level 2 on; joints: the hinges
 * from level 2 on. Muscles per variant from level 3 on. */
typedef struct expectation {
    const char *model;
    int bodies_level1; /* nails + bones */
    int bodies_merged; /* after merging the glued ones */
    int hinges;
    int muscles_per_variant[5];
    int variant_count;
} expectation;

static const expectation expectations[] = {
    /* sample: Nail, Bone1, Bone2; no glues; one hinge; one muscle. */
    {"sample", 3, 3, 1, {1}, 1},
    /* arm: 1 nail + 10 bones. Glues nail-scapula, ulna-radius,
     * hand-radius, hand-each finger merge them into {nail, scapula}
     * (static), {humerus} and {ulna, radius, hand, 5 fingers}; hinges
     * shoulder and elbow. Variants: all 5 muscles, Biceps Short, both
     * biceps, the 3 triceps, all 5. */
    {"arm", 11, 3, 2, {5, 1, 2, 3, 5}, 5},
    /* leg: 2 nails + 6 bones. Glues nail top-pelvis, nail bottom-toe,
     * fibula-tibia give {nail top, pelvis}, {femur}, {fibula, tibia},
     * {foot}, {nail bottom, toe}; hinges hip, knee, ankle, sole. Variants:
     * all 4, both gastrocnemii, those and the soleus, tibialis anterior,
     * soleus and tibialis anterior. */
    {"leg", 8, 5, 4, {4, 2, 3, 1, 2}, 5},
};

Test(model, every_builtin_builds_at_every_level_variant_and_weight)
{
    for (size_t e = 0; e < sizeof expectations / sizeof expectations[0]; ++e) {
        const expectation *x = &expectations[e];
        mu_model_desc *desc = load(x->model);
        cr_assert_eq(desc->variant_count, x->variant_count, "%s: %d variants", x->model, desc->variant_count);
        for (int level = 0; level <= 4; ++level) {
            for (int v = 0; v < desc->variant_count; ++v) {
                for (int w = 0; w < (desc->has_weight ? desc->weight.mass_count : 1); ++w) {
                    mu_model *model = build(desc, level, v, w, false);
                    const int bodies = level == 0 ? 0 : level == 1 ? x->bodies_level1 : x->bodies_merged;
                    cr_expect_eq(mu_model_body_count(model), bodies, "%s level %d: %d bodies, expected %d", x->model,
                                 level, mu_model_body_count(model), bodies);
                    cr_expect_eq(mu_model_joint_count(model), level >= 2 ? x->hinges : 0, "%s level %d: %d joints",
                                 x->model, level, mu_model_joint_count(model));
                    const int muscles = level >= 3 ? x->muscles_per_variant[v] : 0;
                    cr_expect_eq(mu_model_muscle_count(model), muscles, "%s level %d variant %d: %d muscles", x->model,
                                 level, v, mu_model_muscle_count(model));
                    mu_model_destroy(model);
                }
            }
        }
        mu_model_desc_destroy(desc);
    }
}

Test(model, weld_glues_keeps_the_parts_as_bodies)
{
    /* The arm without merging: 11 bodies, and a weld per glue between
     * two bodies of which one moves: nail-scapula, ulna-radius,
     * hand-radius and the 5 fingers = 8 welds, plus the 2 hinges. */
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc, 2, 0, 0, true);
    cr_expect_eq(mu_model_body_count(model), 11);
    cr_expect_eq(mu_model_joint_count(model), 10);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model, joints_start_met)
{
    /* Every hinge's two anchors coincide in the initial pose, so with no
     * gravity and no muscles one frame leaves every gap at rounding level
     * and every hinge at 0 degrees. */
    const char *names[] = {"sample", "arm", "leg"};
    for (int n = 0; n < 3; ++n) {
        for (int weld = 0; weld < 2; ++weld) {
            mu_model_desc *desc = load(names[n]);
            mu_model *model = build(desc, 2, 0, 0, weld == 1);
            cr_assert_eq(mu_model_set_gravity(model, rb_v2(0.0, 0.0)), RB_OK);
            cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
            const rb_statistics stats = rb_world_statistics(mu_model_world(model));
            cr_expect(stats.max_joint_gap < 1e-9, "%s: joint gap %g m after a still frame", names[n],
                      stats.max_joint_gap);
            for (int h = 0; h < mu_model_hinge_count(model); ++h) {
                expect_near(mu_model_hinge_angle(model, h), 0.0, 1e-9, mu_model_hinge_name(model, h));
            }
            mu_model_destroy(model);
            mu_model_desc_destroy(desc);
        }
    }
}

static int hinge_index(const mu_model *model, const char *name)
{
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        if (strcmp(mu_model_hinge_name(model, h), name) == 0) {
            return h;
        }
    }
    cr_assert_fail("no hinge named %s", name);
    return -1;
}

static void run_seconds(mu_model *model, double seconds)
{
    const int frames = (int)lround(seconds / mu_model_frame_duration(model));
    for (int f = 0; f < frames; ++f) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
}

/* The change of a hinge's angle (degrees) over one second of full
 * activation of `group`, after the model has settled for two seconds. */
static double action_on(const char *model_name, int weight_index, const char *group, const char *hinge)
{
    mu_model_desc *desc = load(model_name);
    mu_model *model = build(desc, 4, 0, weight_index, false);
    const int h = hinge_index(model, hinge);
    run_seconds(model, 2.0);
    const double before = mu_model_hinge_angle(model, h);
    cr_assert_eq(mu_model_set_activation(model, group, 1.0), RB_OK, "%s", rb_last_error());
    run_seconds(model, 1.0);
    const double change = mu_model_hinge_angle(model, h) - before;
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    return change;
}

Test(model, the_muscles_move_their_joints_the_right_way)
{
    /* The elbow's angle is angle(ulna) - angle(humerus): flexion raises
     * it. The ankle's is angle(foot) - angle(tibia): plantarflexion (toes
     * down against the shin) lowers it. 10 degrees is far above the
     * settled arm's and leg's drift (below 0.5 degrees in a second). */
    const double biceps = action_on("arm", 1, "Biceps Short + Biceps Long", "Elbow");
    cr_expect(biceps > 10.0, "the biceps moved the elbow by %g degrees, expected flexion", biceps);
    const double triceps = action_on("arm", 1, "Triceps Long + Triceps Medial + Triceps Lateral", "Elbow");
    cr_expect(triceps < -10.0, "the triceps moved the elbow by %g degrees, expected extension", triceps);
    const double gastrocnemius = action_on("leg", 0, "Gastrocnemius Lateral + Gastrocnemius Medial", "Ankle");
    cr_expect(gastrocnemius < -10.0, "the gastrocnemius moved the ankle by %g degrees, expected plantarflexion",
              gastrocnemius);
}

Test(model, triceps_medial_too_short_is_reported)
{
    /* Its whole path is about 0.185 m, shorter than its rest
     * length 0.2087 m at the asked normalized length 1.0. */
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc, 3, 0, 0, false);
    cr_expect(strstr(mu_model_warnings(model), "Triceps Medial") != NULL, "warnings: '%s'", mu_model_warnings(model));
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        if (strcmp(mu_model_muscle_name(model, m), "Triceps Medial") == 0) {
            const double l = mu_model_muscle_readout(model, m).normalized_length;
            cr_expect(l > 0.85 && l < 0.92, "Triceps Medial starts at %g of its rest length, expected about 0.89", l);
        }
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model, full_activation_switched_every_half_second_stays_stable)
{
    /* Every built-in model at every variant and load, all its muscles at
     * full activation switched on and off every 0.5 s for 20 s: no part's
     * pose becomes NaN, and no part moves faster than 20 m/s (a 0.7 m arm
     * would need more than 25 rad/s; the bodies are damped at 8/s). */
    const char *names[] = {"sample", "arm", "leg"};
    for (int n = 0; n < 3; ++n) {
        mu_model_desc *desc = load(names[n]);
        for (int v = 0; v < desc->variant_count; ++v) {
            for (int w = 0; w < (desc->has_weight ? desc->weight.mass_count : 1); ++w) {
                mu_model *model = build(desc, 4, v, w, false);
                const int frames = (int)lround(20.0 / mu_model_frame_duration(model));
                const int half_second = (int)lround(0.5 / mu_model_frame_duration(model));
                rb_vec2 previous[64];
                const int parts = mu_model_part_count(model) < 64 ? mu_model_part_count(model) : 64;
                for (int p = 0; p < parts; ++p) {
                    previous[p] = mu_model_part_centre(model, p);
                }
                double fastest = 0.0;
                for (int f = 0; f < frames; ++f) {
                    if (f % half_second == 0) {
                        const double a = (f / half_second) % 2 == 0 ? 1.0 : 0.0;
                        for (int m = 0; m < mu_model_muscle_count(model); ++m) {
                            cr_assert_eq(mu_model_set_activation(model, mu_model_muscle_name(model, m), a), RB_OK);
                        }
                    }
                    cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
                    for (int p = 0; p < parts; ++p) {
                        const rb_vec2 c = mu_model_part_centre(model, p);
                        if (isnan(previous[p].x)) {
                            continue; /* a part not built in this variant */
                        }
                        cr_assert(rb_vec2_is_finite(c), "%s variant %d weight %d: part %s is at (%g, %g) at frame %d",
                                  names[n], v, w, mu_model_part_name(model, p), c.x, c.y, f);
                        fastest = fmax(fastest, rb_distance(c, previous[p]) / mu_model_frame_duration(model));
                        previous[p] = c;
                    }
                }
                cr_expect(fastest < 20.0, "%s variant %d weight %d: a part moved at %g m/s", names[n], v, w, fastest);
                mu_model_destroy(model);
            }
        }
        mu_model_desc_destroy(desc);
    }
}

/* The fastest any part moves (m/s, from its centre frame to frame) while
 * every muscle's activation is switched between 1 and 0 every 0.5 s for
 * `seconds`; fails at a NaN pose or readout. */
static double fastest_part_under_switching(mu_model *model, double seconds, const char *what)
{
    const int frames = (int)lround(seconds / mu_model_frame_duration(model));
    const int half_second = (int)lround(0.5 / mu_model_frame_duration(model));
    rb_vec2 previous[64];
    const int parts = mu_model_part_count(model) < 64 ? mu_model_part_count(model) : 64;
    for (int p = 0; p < parts; ++p) {
        previous[p] = mu_model_part_centre(model, p);
    }
    double fastest = 0.0;
    for (int f = 0; f < frames; ++f) {
        if (f % half_second == 0) {
            for (int m = 0; m < mu_model_muscle_count(model); ++m) {
                cr_assert_eq(mu_model_set_activation_at(model, m, (f / half_second) % 2 == 0 ? 1.0 : 0.0), RB_OK);
            }
        }
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
        for (int m = 0; m < mu_model_muscle_count(model); ++m) {
            const mu_muscle_readout r = mu_model_muscle_readout(model, m);
            cr_assert(isfinite(r.total_force) && isfinite(r.fibre_length) && isfinite(r.tendon_length),
                      "%s: muscle %s at frame %d: force %g N, fibre %g m, tendon %g m", what,
                      mu_model_muscle_name(model, m), f, r.total_force, r.fibre_length, r.tendon_length);
        }
        for (int p = 0; p < parts; ++p) {
            const rb_vec2 c = mu_model_part_centre(model, p);
            if (isnan(previous[p].x)) {
                continue; /* a part not built in this variant */
            }
            cr_assert(rb_vec2_is_finite(c), "%s: part %s at frame %d", what, mu_model_part_name(model, p), f);
            fastest = fmax(fastest, rb_distance(c, previous[p]) / mu_model_frame_duration(model));
            previous[p] = c;
        }
    }
    return fastest;
}

Test(model, compliant_tendons_with_activation_dynamics_stay_stable)
{
    /* The arm and the leg with every muscle given activation dynamics and
     * a compliant tendon (each whose rigid tendon is longer than 1 mm:
     * Triceps Medial has none), at the default 10 substeps per frame,
     * their muscles switched fully on and off every 0.5 s for 10 s: no NaN
     * anywhere, and no part faster than the bound the rigid models keep
     * (20 m/s, so the kinetic energy stays bounded), nor more than twice
     * as fast as with the original muscles plus 0.5 m/s. */
    const char *names[] = {"arm", "leg"};
    for (int n = 0; n < 2; ++n) {
        mu_model_desc *desc = load(names[n]);
        for (int w = 0; w < desc->weight.mass_count; ++w) {
            mu_model *rigid = build(desc, 4, 0, w, false);
            /* Variant 0 builds every muscle, in the description's order. */
            bool has_tendon[16] = {false};
            cr_assert_eq(mu_model_muscle_count(rigid), desc->muscle_count);
            for (int m = 0; m < desc->muscle_count && m < 16; ++m) {
                has_tendon[m] = mu_model_muscle_readout(rigid, m).tendon_length > 1e-3;
            }
            const double rigid_fastest = fastest_part_under_switching(rigid, 10.0, names[n]);
            mu_model_destroy(rigid);
            for (int m = 0; m < desc->muscle_count && m < 16; ++m) {
                desc->muscles[m].activation_dynamics = true;
                desc->muscles[m].compliant_tendon = has_tendon[m];
            }
            mu_model *compliant = build(desc, 4, 0, w, false);
            const double fastest = fastest_part_under_switching(compliant, 10.0, names[n]);
            cr_expect(fastest < 20.0 && fastest < 2.0 * rigid_fastest + 0.5,
                      "%s weight %d: a part moved at %g m/s (%g with the original muscles)", names[n], w, fastest,
                      rigid_fastest);
            cr_log_info("%s weight %d: fastest part %g m/s compliant, %g m/s rigid", names[n], w, fastest,
                        rigid_fastest);
            mu_model_destroy(compliant);
            for (int m = 0; m < desc->muscle_count; ++m) {
                desc->muscles[m].activation_dynamics = false;
                desc->muscles[m].compliant_tendon = false;
            }
        }
        mu_model_desc_destroy(desc);
    }
}

Test(model, physiology_options_reach_the_muscles)
{
    /* tests/data/models/physiology.json: Lifter has pennation (20°),
     * activation dynamics and a compliant tendon; Seed has none. */
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load(SINEW_SOURCE_DIR "/tests/data/models/physiology.json", &desc), RB_OK, "%s",
                 rb_last_error());
    mu_model *model = build(desc, 4, 0, 0, false);
    cr_expect_str_eq(mu_model_warnings(model), "");
    mu_muscle_readout lifter = mu_model_muscle_readout(model, 0);
    /* At creation: the fibre in equilibrium near 1.1 l_opt, so its angle
     * near asin(sin 20°/1.1), the tendon near its slack length. */
    expect_near(lifter.normalized_length, 1.1, 0.02, "start fibre length");
    expect_near(lifter.pennation_angle, asin(sin(20.0 * RB_PI / 180.0) / lifter.normalized_length), 1e-12, "angle");
    expect_near(lifter.tendon_length, 0.12 * sqrt(2.0), 0.12 * sqrt(2.0) * 0.04, "tendon near its slack length");
    cr_assert_eq(mu_model_set_activation(model, "Lifter", 1.0), RB_OK);
    cr_assert_eq(mu_model_set_activation(model, "Seed", 1.0), RB_OK);
    cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    lifter = mu_model_muscle_readout(model, 0);
    const mu_muscle_readout seed = mu_model_muscle_readout(model, 1);
    cr_expect_eq(lifter.excitation, 1.0);
    /* After one frame (1/60 s) of activation dynamics from rest with
     * τ_act = 15 ms: well on its way, not there. */
    cr_expect(lifter.activation > 0.3 && lifter.activation < 0.95, "activation %g after a frame", lifter.activation);
    cr_expect_eq(seed.activation, 1.0, "set at once");
    cr_expect_eq(seed.pennation_angle, 0.0);
    cr_expect_eq(seed.fibre_length, seed.length, "no pennation: the fibre is the belly");
    run_seconds(model, 2.0);
    lifter = mu_model_muscle_readout(model, 0);
    cr_expect(isfinite(lifter.total_force) && lifter.total_force > 0.0, "force %g N", lifter.total_force);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model, muscles_do_not_ring_at_the_substep_frequency)
{
    /* The arm with 1 kg, one substep per "frame" of 1/600 s, so each
     * step is one substep: with the biceps fully active, after 1 s no
     * muscle's velocity changes sign between consecutive substeps more
     * than a few times over the next 0.5 s. An explicit force-velocity
     * term would flip it every substep. */
    mu_model_desc *desc = load("arm");
    desc->frame_rate = 600.0;
    desc->substeps = 1;
    mu_model *model = build(desc, 4, 0, 1, false);
    cr_assert_eq(mu_model_set_activation(model, "Biceps Short + Biceps Long", 1.0), RB_OK);
    run_seconds(model, 1.0);
    const int muscles = mu_model_muscle_count(model);
    double previous[8] = {0};
    int flips[8] = {0};
    for (int s = 0; s < 300; ++s) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
        for (int m = 0; m < muscles && m < 8; ++m) {
            const double v = mu_model_muscle_readout(model, m).velocity;
            flips[m] += s > 0 && v * previous[m] < 0.0;
            previous[m] = v;
        }
    }
    for (int m = 0; m < muscles && m < 8; ++m) {
        cr_expect(flips[m] < 10, "%s: its velocity changed sign %d times in 300 substeps",
                  mu_model_muscle_name(model, m), flips[m]);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model, a_hanging_load_is_held_by_the_tension_its_weight_asks)
{
    /* The sample's Bone2 hangs from its muscle alone, straight below
     * Bone1. At rest the muscle carries exactly the weight
     * below it: Bone2 (1900 kg/m³ · 0.05 · 0.05 · 0.05 m = 0.2375 kg) and
     * the 5 kg disc, times g = 9.8. 1 % leaves room for the last of the
     * settling; a force read from the wrong place is off by far more. */
    mu_model_desc *desc = load("sample");
    mu_model *model = build(desc, 4, 0, 2, false);
    cr_assert_eq(desc->weight.masses[2], 5.0, "weight choice 2 of the sample is 5 kg");
    cr_assert_eq(mu_model_set_activation(model, "Muscle", 0.5), RB_OK);
    run_seconds(model, 8.0);
    const double weight = (1900.0 * 0.05 * 0.05 * 0.05 + 5.0) * 9.8;
    const mu_muscle_readout r = mu_model_muscle_readout(model, 0);
    expect_near(r.total_force, weight, 0.01 * weight, "the muscle's tension holding the load");
    cr_expect(fabs(r.velocity) < 1e-4, "the load still moves at %g m/s", r.velocity);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(model, muscles_are_addressed_by_name_index_or_group)
{
    /* The arm's "All Biceps" variant builds Biceps Short and Biceps Long,
     * in the file's order. A group's mean activation is the mean of its
     * built muscles'; an unknown name or an index out of range is an
     * error that changes nothing. */
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc, 3, 2, 0, false);
    cr_assert_eq(mu_model_muscle_count(model), 2);
    cr_expect_str_eq(mu_model_muscle_name(model, 0), "Biceps Short");
    cr_assert_eq(mu_model_set_activation_at(model, 0, 0.2), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_set_activation(model, "Biceps Long", 0.6), RB_OK, "%s", rb_last_error());
    run_seconds(model, 1.0 / 60.0);
    expect_near(mu_model_group_activation(model, "Biceps Short + Biceps Long"), 0.4, 1e-12, "mean activation");
    cr_assert_eq(mu_model_set_activation(model, "Biceps Short + Biceps Long", 1.0), RB_OK);
    run_seconds(model, 1.0 / 60.0);
    expect_near(mu_model_group_activation(model, "Biceps Short"), 1.0, 1e-12, "a muscle is its own group");
    cr_expect_eq(mu_model_set_activation_at(model, 2, 1.0), RB_ERR_INVALID_ARGUMENT, "index out of range");
    cr_expect_eq(mu_model_set_tension_at(model, -1, 10.0), RB_ERR_INVALID_ARGUMENT, "negative index");
    cr_expect_eq(mu_model_set_activation(model, "Deltoid", 1.0), RB_ERR_INVALID_ARGUMENT, "unknown muscle");
    cr_expect(isnan(mu_model_group_activation(model, "Deltoid")), "unknown group");
    cr_assert_eq(mu_model_set_tension_at(model, 1, 100.0), RB_OK, "%s", rb_last_error());
    run_seconds(model, 1.0 / 60.0); /* readouts are taken as the model steps */
    cr_expect_eq(mu_model_muscle_readout(model, 1).target_tension, 100.0);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}
