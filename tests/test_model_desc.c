/* SPDX-License-Identifier: MIT */
/* Model files: the built-in models load with the geometry of
 * the original report's figures and code, defaults fill what a file leaves out, lookups
 * find objects by name, and every malformed or inconsistent file of the
 * corpus (tests/data/bad_models) fails with its expected message (file,
 * line and column, JSON path, what was expected) and no description.
 *
 * JSON has no NaN: the corpus stands for it with a number that overflows
 * (1e999, which jansson rejects as a syntax error) and with a string where
 * a number is expected ("NaN").
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp, opendir */

#include <criterion/criterion.h>
#include <criterion/parameterized.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mu/model_desc.h"
#include "test_support.h"

#define BAD_MODELS SINEW_SOURCE_DIR "/tests/data/bad_models"

static mu_model_desc *load(const char *path)
{
    mu_model_desc *desc = NULL;
    rb_status status = mu_model_desc_load(path, &desc);
    cr_assert_eq(status, RB_OK, "loading %s: %s", path, rb_last_error());
    cr_assert_not_null(desc);
    return desc;
}

static mu_model_desc *load_builtin(const char *name)
{
    mu_model_desc *desc = NULL;
    rb_status status = mu_model_desc_load_builtin(name, &desc);
    cr_assert_eq(status, RB_OK, "loading built-in %s: %s", name, rb_last_error());
    return desc;
}

/* The object `name` of `kind`, which must exist. */
static int index_of(const mu_model_desc *desc, mu_model_kind kind, const char *name)
{
    mu_model_ref ref;
    cr_assert(mu_model_desc_find(desc, name, &ref), "%s: no object named \"%s\"", desc->name, name);
    cr_assert_eq(ref.kind, kind, "%s: \"%s\" is of kind %d, expected %d", desc->name, name, ref.kind, kind);
    return ref.index;
}

static void expect_ref(mu_model_ref ref, mu_model_kind kind, int index, const char *what)
{
    cr_expect(ref.kind == kind && ref.index == index, "%s: got kind %d index %d, expected kind %d index %d", what,
              ref.kind, ref.index, kind, index);
}

/* Where a body point is in the model's frame, in the pose of the file. */
static rb_vec2 model_point(const mu_model_desc *desc, mu_model_ref body, rb_vec2 local)
{
    if (body.kind == MU_MODEL_NAIL) {
        return rb_add(desc->nails[body.index].position, local);
    }
    const mu_model_bone *bone = &desc->bones[body.index];
    double angle = bone->angle * RB_PI / 180.0;
    return rb_add(bone->centre,
                  rb_v2(cos(angle) * local.x - sin(angle) * local.y, sin(angle) * local.x + cos(angle) * local.y));
}

/* Each hinge's two anchors are one point: the files agree with themselves. */
static void expect_hinges_closed(const mu_model_desc *desc)
{
    for (int i = 0; i < desc->hinge_count; ++i) {
        const mu_model_hinge *hinge = &desc->hinges[i];
        rb_vec2 a = model_point(desc, hinge->body_a, hinge->anchor_a);
        rb_vec2 b = model_point(desc, hinge->body_b, hinge->anchor_b);
        char what[96];
        snprintf(what, sizeof what, "%s: the anchors of hinge %s", desc->name, hinge->name);
        expect_vec_near(a, b, 1e-12, what);
    }
}

static void expect_counts(const mu_model_desc *desc, int nails, int bones, int hinges, int glues, int muscles,
                          int groups, int variants, int weights)
{
    cr_expect_eq(desc->nail_count, nails, "%s: nails", desc->name);
    cr_expect_eq(desc->bone_count, bones, "%s: bones", desc->name);
    cr_expect_eq(desc->hinge_count, hinges, "%s: hinges", desc->name);
    cr_expect_eq(desc->glue_count, glues, "%s: glues", desc->name);
    cr_expect_eq(desc->muscle_count, muscles, "%s: muscles", desc->name);
    cr_expect_eq(desc->group_count, groups, "%s: groups", desc->name);
    cr_expect_eq(desc->variant_count, variants, "%s: variants", desc->name);
    cr_expect(desc->has_weight, "%s: has a weight", desc->name);
    cr_expect_eq(desc->weight.mass_count, weights, "%s: weight choices", desc->name);
}

static void expect_seed_settings(const mu_model_desc *desc, double placement_x, double placement_y)
{
    expect_vec_near(desc->gravity, rb_v2(0.0, -9.8), 0.0, "gravity");
    cr_expect_eq(desc->frame_rate, 60.0);
    cr_expect_eq(desc->substeps, 10);
    expect_vec_near(desc->placement, rb_v2(placement_x, placement_y), 0.0, "placement");
}

static void expect_variant_muscles(const mu_model_desc *desc, const char *variant_name, const char *const *muscles,
                                   int count)
{
    int v = mu_model_desc_find_variant(desc, variant_name);
    cr_assert_geq(v, 0, "%s: no variant \"%s\"", desc->name, variant_name);
    const mu_model_variant *variant = &desc->variants[v];
    cr_expect_eq(variant->muscle_count, count, "%s: muscles of variant %s", desc->name, variant_name);
    for (int i = 0; i < count; ++i) {
        cr_expect(mu_model_variant_has_muscle(variant, index_of(desc, MU_MODEL_MUSCLE, muscles[i])),
                  "%s: variant %s has muscle %s", desc->name, variant_name, muscles[i]);
    }
    cr_expect_eq(variant->bone_count, desc->bone_count, "%s: variant %s keeps every bone", desc->name, variant_name);
}

static void expect_path_point(const mu_model_desc *desc, const mu_model_muscle *muscle, int point, const char *body,
                              double x, double y)
{
    char what[96];
    snprintf(what, sizeof what, "%s: point %d of %s's path", desc->name, point, muscle->name);
    cr_assert_lt(point, muscle->point_count, "%s: missing", what);
    const mu_model_path_point *p = &muscle->path[point];
    mu_model_ref ref;
    cr_assert(mu_model_desc_find(desc, body, &ref), "%s: no body %s", what, body);
    expect_ref(p->body, ref.kind, ref.index, what);
    expect_vec_near(p->point, rb_v2(x, y), 0.0, what);
}

/* ---- the built-in models ------------------------------------------------- */

Test(model_desc, sample_loads_as_models_md_gives_it)
{
    mu_model_desc *desc = load(SINEW_SOURCE_DIR "/models/sample.json");
    cr_expect_str_eq(desc->name, "sample");
    expect_counts(desc, 1, 2, 1, 0, 1, 0, 1, 5);
    expect_seed_settings(desc, 0.0, 0.3);

    const mu_model_bone *bar = &desc->bones[index_of(desc, MU_MODEL_BONE, "Bone1")];
    expect_vec_near(bar->centre, rb_v2(0.0, -0.1), 0.0, "Bone1 centre");
    expect_vec_near(bar->size, rb_v2(0.05, 0.2), 0.0, "Bone1 size");
    cr_expect_eq(bar->depth, 0.05, "Bone1's depth is its thickness, the smaller extent");
    cr_expect_eq(bar->density, 1900.0);
    cr_expect_not(bar->is_static);

    const mu_model_hinge *hinge = &desc->hinges[index_of(desc, MU_MODEL_HINGE, "Hinge")];
    expect_ref(hinge->body_a, MU_MODEL_NAIL, 0, "the hinge's body A");
    cr_expect_eq(hinge->radius, 0.025);
    cr_expect(!hinge->has_lower && !hinge->has_upper, "the sample's hinge has no limits");

    const mu_model_muscle *muscle = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Muscle")];
    cr_expect_eq(muscle->rest_length, 0.3);
    cr_expect_eq(muscle->rest_width, 0.05);
    cr_expect_eq(muscle->start_normalized_length, 1.0);
    cr_expect_eq(muscle->point_count, 2);
    expect_path_point(desc, muscle, 0, "Bone1", 0.0, -0.1);
    expect_path_point(desc, muscle, 1, "Bone2", 0.0, 0.0);

    static const double masses[] = {0, 1, 5, 10, 50};
    for (int i = 0; i < 5; ++i) {
        cr_expect_eq(desc->weight.masses[i], masses[i], "weight choice %d", i);
    }
    expect_ref(desc->weight.body, MU_MODEL_BONE, index_of(desc, MU_MODEL_BONE, "Bone2"), "the weight's body");
    expect_vec_near(desc->weight.position, desc->bones[1].centre, 0.0, "the weight sits at Bone2's centre");
    cr_expect_str_eq(desc->variants[0].name, "Default");
    expect_hinges_closed(desc);
    mu_model_desc_destroy(desc);
}

Test(model_desc, arm_loads_as_models_md_gives_it)
{
    mu_model_desc *desc = load_builtin("arm");
    cr_expect_str_eq(desc->name, "arm");
    expect_counts(desc, 1, 10, 2, 8, 5, 2, 5, 6);
    expect_seed_settings(desc, -0.20, 0.30);
    expect_hinges_closed(desc);

    const mu_model_bone *humerus = &desc->bones[index_of(desc, MU_MODEL_BONE, "Humerus")];
    expect_vec_near(humerus->centre, rb_v2(0.152, 0.0), 0.0, "humerus centre");
    expect_vec_near(humerus->size, rb_v2(0.304, 0.048), 0.0, "humerus size");
    cr_expect_eq(humerus->depth, 0.048);
    cr_expect_eq(desc->bones[index_of(desc, MU_MODEL_BONE, "Hand")].depth, 0.020, "the hand's depth is given");
    const mu_model_bone *pinky = &desc->bones[index_of(desc, MU_MODEL_BONE, "Pinky Finger")];
    expect_vec_near(pinky->centre, rb_v2(0.6535, -0.0265), 0.0, "pinky centre");
    expect_vec_near(pinky->size, rb_v2(0.049, 0.007), 0.0, "pinky size");

    const mu_model_hinge *shoulder = &desc->hinges[index_of(desc, MU_MODEL_HINGE, "Shoulder")];
    cr_expect(shoulder->has_lower && shoulder->has_upper);
    cr_expect(shoulder->lower == -160.0 && shoulder->upper == 90.0, "shoulder limits [%g, %g]", shoulder->lower,
              shoulder->upper);
    cr_expect_eq(shoulder->radius, 0.048);
    const mu_model_hinge *elbow = &desc->hinges[index_of(desc, MU_MODEL_HINGE, "Elbow")];
    cr_expect(elbow->lower == -10.0 && elbow->upper == 150.0, "elbow limits [%g, %g]", elbow->lower, elbow->upper);
    expect_ref(elbow->body_b, MU_MODEL_BONE, index_of(desc, MU_MODEL_BONE, "Ulna"), "the elbow's body B");

    /* The nail is glued to the scapula; the hand to the radius and to each finger. */
    const mu_model_glue *nail_glue = &desc->glues[0];
    expect_ref(nail_glue->body_a, MU_MODEL_NAIL, 0, "glue 0 body A");
    expect_ref(nail_glue->body_b, MU_MODEL_BONE, index_of(desc, MU_MODEL_BONE, "Scapula"), "glue 0 body B");

    const mu_model_muscle *biceps_short = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Biceps Short")];
    cr_expect_eq(biceps_short->rest_length, 0.2087);
    cr_expect_eq(biceps_short->rest_width, 0.0328);
    cr_expect_eq(biceps_short->specific_tension, 1.5e6);
    cr_expect_eq(biceps_short->start_normalized_length, 1.1);
    cr_expect_eq(biceps_short->symmetry, 0.6);
    cr_expect_eq(biceps_short->max_force, 0.0, "the force comes from the width and σ");
    expect_near(0.25 * RB_PI * biceps_short->rest_width * biceps_short->rest_width * biceps_short->specific_tension,
                1267.0, 0.5, "the biceps' Fmax (about 1267 N)");
    cr_expect_eq(biceps_short->point_count, 2);
    expect_path_point(desc, biceps_short, 0, "Scapula", 0.05, 0.0);
    expect_path_point(desc, biceps_short, 1, "Radius", -0.0859, 0.012);

    /* The original's pulley is the path's origin, its tendon anchor a via point. */
    const mu_model_muscle *biceps_long = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Biceps Long")];
    cr_expect_eq(biceps_long->start_normalized_length, 1.25);
    cr_expect_eq(biceps_long->point_count, 3);
    expect_path_point(desc, biceps_long, 0, "Scapula", 0.0, 0.0);
    expect_path_point(desc, biceps_long, 1, "Humerus", -0.162, 0.024);
    expect_path_point(desc, biceps_long, 2, "Radius", -0.0859, 0.012);

    /* On the insertion side the pulley is the path's end. */
    const mu_model_muscle *medial = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Triceps Medial")];
    cr_expect_eq(medial->point_count, 3);
    expect_path_point(desc, medial, 0, "Humerus", 0.0, -0.024);
    expect_path_point(desc, medial, 1, "Humerus", 0.162, -0.034);
    expect_path_point(desc, medial, 2, "Ulna", -0.0919, -0.0095);
    double path = 0.0;
    for (int i = 0; i + 1 < medial->point_count; ++i) {
        path += rb_length(rb_sub(model_point(desc, medial->path[i + 1].body, medial->path[i + 1].point),
                                 model_point(desc, medial->path[i].body, medial->path[i].point)));
    }
    expect_near(path, 0.185, 0.001, "Triceps Medial's path (about 0.185 m, below its rest length)");
    const mu_model_muscle *triceps_long = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Triceps Long")];
    expect_path_point(desc, triceps_long, 0, "Scapula", -0.05, 0.0167);

    static const char *const all[] = {"Biceps Short", "Biceps Long", "Triceps Medial", "Triceps Long",
                                      "Triceps Lateral"};
    static const char *const biceps[] = {"Biceps Short", "Biceps Long"};
    static const char *const triceps[] = {"Triceps Medial", "Triceps Long", "Triceps Lateral"};
    expect_variant_muscles(desc, "All Muscles", all, 5);
    expect_variant_muscles(desc, "Biceps Short", biceps, 1);
    expect_variant_muscles(desc, "All Biceps", biceps, 2);
    expect_variant_muscles(desc, "All Triceps", triceps, 3);
    expect_variant_muscles(desc, "All Biceps + Triceps", all, 5);
    cr_expect_eq(mu_model_desc_find_variant(desc, "Biceps Short"), 1, "variants are numbered as in the original");

    const mu_model_group *group = &desc->groups[index_of(desc, MU_MODEL_GROUP, "Biceps Short + Biceps Long")];
    cr_expect_eq(group->muscle_count, 2);
    cr_expect_eq(group->muscles[1], index_of(desc, MU_MODEL_MUSCLE, "Biceps Long"));
    cr_expect_eq(desc->groups[1].muscle_count, 3);

    static const double masses[] = {0, 1, 5, 10, 50, 100};
    for (int i = 0; i < 6; ++i) {
        cr_expect_eq(desc->weight.masses[i], masses[i], "weight choice %d", i);
    }
    expect_vec_near(desc->weight.position, rb_v2(0.60625, 0.012), 0.0, "the weight's position");
    expect_ref(desc->weight.body, MU_MODEL_BONE, index_of(desc, MU_MODEL_BONE, "Radius"), "the weight's body");
    mu_model_desc_destroy(desc);
}

/* The source's leg, hinges and substeps as the report has them;
 * test_leg_ranges.c checks the built-in leg's anatomical ranges. */
Test(model_desc, leg_unlimited_loads_as_models_md_gives_it)
{
    mu_model_desc *desc = load_builtin("leg-unlimited");
    cr_expect_str_eq(desc->name, "leg-unlimited");
    expect_counts(desc, 2, 6, 4, 3, 4, 2, 5, 4);
    expect_seed_settings(desc, -0.30, 0.30);
    expect_hinges_closed(desc);

    const mu_model_bone *toe = &desc->bones[index_of(desc, MU_MODEL_BONE, "Toe")];
    cr_expect(toe->is_static, "the toe is static");
    expect_vec_near(toe->centre, rb_v2(0.62, -0.45315), 0.0, "the toe where its hinge says");
    const mu_model_nail *bottom = &desc->nails[index_of(desc, MU_MODEL_NAIL, "Nail Bottom")];
    expect_vec_near(bottom->position, toe->centre, 0.0, "the bottom nail on the toe");
    const mu_model_bone *tibia = &desc->bones[index_of(desc, MU_MODEL_BONE, "Tibia")];
    cr_expect_eq(tibia->depth, 0.0258, "the vertical tibia's depth is its thickness, not its y extent");
    cr_expect_not(tibia->is_static);

    const mu_model_hinge *ankle = &desc->hinges[index_of(desc, MU_MODEL_HINGE, "Ankle")];
    cr_expect(ankle->has_lower && !ankle->has_upper, "the ankle's limit is one-sided");
    cr_expect_eq(ankle->lower, -70.0);
    cr_expect_eq(ankle->radius, 0.0258);
    expect_vec_near(ankle->anchor_b, rb_v2(-0.035, 0.0), 0.0, "the ankle's anchor on the foot");
    static const char *const free_hinges[] = {"Hip", "Knee", "Sole"};
    for (int i = 0; i < 3; ++i) {
        const mu_model_hinge *hinge = &desc->hinges[index_of(desc, MU_MODEL_HINGE, free_hinges[i])];
        cr_expect(!hinge->has_lower && !hinge->has_upper, "%s has no limits", free_hinges[i]);
    }
    cr_expect_eq(desc->hinges[index_of(desc, MU_MODEL_HINGE, "Hip")].radius, 0.0537);
    cr_expect_eq(desc->hinges[index_of(desc, MU_MODEL_HINGE, "Sole")].radius, 0.02);

    const mu_model_muscle *gastrocnemius = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Gastrocnemius Medial")];
    cr_expect_eq(gastrocnemius->rest_length, 0.20);
    cr_expect_eq(gastrocnemius->rest_width, 0.047);
    cr_expect_eq(gastrocnemius->symmetry, 0.25);
    expect_path_point(desc, gastrocnemius, 0, "Femur", 0.22, -0.02685);
    expect_path_point(desc, gastrocnemius, 1, "Foot", -0.085, -0.02);
    const mu_model_muscle *tibialis = &desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Tibialis Anterior")];
    cr_expect_eq(tibialis->start_normalized_length, 0.75);
    expect_path_point(desc, tibialis, 1, "Foot", 0.0, 0.02);

    static const char *const all[] = {"Soleus", "Gastrocnemius Lateral", "Gastrocnemius Medial", "Tibialis Anterior"};
    static const char *const gastrocnemii[] = {"Gastrocnemius Lateral", "Gastrocnemius Medial", "Soleus"};
    static const char *const front[] = {"Tibialis Anterior", "Soleus"};
    expect_variant_muscles(desc, "All Muscles", all, 4);
    expect_variant_muscles(desc, "All Gastrocnemius", gastrocnemii, 2);
    expect_variant_muscles(desc, "All Gas + Soleus", gastrocnemii, 3);
    expect_variant_muscles(desc, "Tibialis Anterior", front, 1);
    expect_variant_muscles(desc, "Soleus + Tibialis Anterior", front, 2);
    cr_expect_not(mu_model_variant_has_muscle(&desc->variants[3], index_of(desc, MU_MODEL_MUSCLE, "Soleus")));

    static const double masses[] = {10, 50, 100, 200};
    for (int i = 0; i < 4; ++i) {
        cr_expect_eq(desc->weight.masses[i], masses[i], "weight choice %d", i);
    }
    expect_vec_near(desc->weight.position, rb_v2(0.48, -0.08315), 0.0, "the weight on the knee");
    expect_ref(desc->weight.body, MU_MODEL_BONE, index_of(desc, MU_MODEL_BONE, "Femur"), "the weight's body");
    mu_model_desc_destroy(desc);
}

/* ---- defaults and lookups ------------------------------------------------ */

Test(model_desc, defaults_fill_what_the_file_leaves_out)
{
    mu_model_desc *desc = load(SINEW_SOURCE_DIR "/tests/data/models/defaults.json");
    expect_seed_settings(desc, 0.0, 0.0);
    cr_expect_eq(desc->group_count, 0);
    cr_expect_eq(desc->glue_count, 0);

    const mu_model_bone *bar = &desc->bones[0];
    cr_expect_eq(bar->angle, 90.0);
    cr_expect_eq(bar->depth, 0.05);
    cr_expect_eq(bar->density, 1900.0);
    cr_expect_not(bar->is_static);
    const mu_model_bone *block = &desc->bones[1];
    cr_expect_str_eq(block->name, "Bl\xc3\xb8kk", "a \\u escape in a name is decoded");
    cr_expect(block->is_static);
    cr_expect_eq(block->depth, 0.02);
    cr_expect_eq(block->density, 1000.0);

    const mu_model_hinge *pin = &desc->hinges[0];
    cr_expect(!pin->has_lower && pin->has_upper && pin->upper == 45.0, "only the upper limit");
    expect_hinges_closed(desc);

    const mu_model_muscle *strap = &desc->muscles[0];
    cr_expect_eq(strap->max_force, 250.0);
    cr_expect_eq(strap->rest_width, 0.0, "no width when max_force is given");
    cr_expect_eq(strap->tendon_length, 0.05);
    cr_expect_eq(strap->curves, MU_MODEL_CURVES_ANALYTIC);
    cr_expect_eq(strap->point_count, 3);
    expect_ref(strap->path[1].body, MU_MODEL_NAIL, 0, "a path point on a nail");
    const mu_model_muscle *belly = &desc->muscles[1];
    cr_expect_eq(belly->max_force, 0.0);
    cr_expect_eq(belly->specific_tension, 1.5e6);
    cr_expect_eq(belly->max_velocity, 0.25);
    cr_expect_eq(belly->start_normalized_length, 1.0);
    cr_expect_eq(belly->tendon_length, -1.0, "the tendon comes from the start length");
    cr_expect_eq(belly->symmetry, 0.5);
    cr_expect_eq(belly->curves, MU_MODEL_CURVES_TABULATED);

    cr_expect_eq(desc->variant_count, 1, "without variants, one with everything");
    cr_expect_str_eq(desc->variants[0].name, "Default");
    cr_expect_eq(desc->variants[0].muscle_count, 2);
    cr_expect_eq(desc->variants[0].bone_count, 2);
    expect_ref(desc->weight.body, MU_MODEL_NAIL, 0, "a weight on a nail");
    cr_expect_eq(desc->weight.mass_count, 1);
    mu_model_desc_destroy(desc);
}

Test(model_desc, physiology_options_are_read_and_lengths_derived)
{
    /* Lifter: path from the nail to (0.3, -0.3) at the start, 0.3·√2 m;
     * 40 % tendon: 0.12·√2 m; belly 0.18·√2 m at s = 1.1 and 20° of
     * pennation: l_opt = 0.18·√2/√(1.21 - sin² 20°); Vmax 10 l_opt/s. */
    mu_model_desc *desc = load(SINEW_SOURCE_DIR "/tests/data/models/physiology.json");
    const mu_model_muscle *lifter = &desc->muscles[0];
    const double s20 = sin(20.0 * RB_PI / 180.0);
    const double rest = 0.18 * sqrt(2.0) / sqrt(1.21 - s20 * s20);
    cr_expect_eq(lifter->tendon_fraction, 0.4);
    expect_near(lifter->tendon_length, 0.12 * sqrt(2.0), 1e-15, "derived tendon length");
    expect_near(lifter->rest_length, rest, 1e-15, "derived rest length");
    expect_near(lifter->max_velocity, 10.0 * rest, 1e-14, "Vmax in derived rest lengths");
    cr_expect_eq(lifter->pennation_angle, 20.0);
    cr_expect(lifter->activation_dynamics);
    cr_expect_eq(lifter->activation_time, 0.015);
    cr_expect_eq(lifter->deactivation_time, 0.040, "the default");
    cr_expect(lifter->compliant_tendon);
    cr_expect_eq(lifter->tendon_strain_at_max_force, 0.04);
    cr_expect_eq(lifter->fibre_damping, 0.05);
    const mu_model_muscle *seed = &desc->muscles[1];
    cr_expect_eq(seed->tendon_fraction, -1.0);
    cr_expect_eq(seed->pennation_angle, 0.0);
    cr_expect_not(seed->activation_dynamics);
    cr_expect_not(seed->compliant_tendon);
    cr_expect_eq(seed->tendon_strain_at_max_force, 0.049);
    cr_expect_eq(seed->fibre_damping, 0.1);
    mu_model_desc_destroy(desc);
}

/* The complete example of docs/model-format.md is a model file that loads. */
Test(model_desc, the_readme_example_loads)
{
    FILE *readme = fopen(SINEW_SOURCE_DIR "/docs/model-format.md", "rb");
    cr_assert_not_null(readme);
    static char text[65536];
    size_t length = fread(text, 1, sizeof text - 1, readme);
    fclose(readme);
    text[length] = '\0';
    const char *fence = "```json\n";
    char *start = strstr(text, fence);
    cr_assert_not_null(start, "docs/model-format.md has no ```json block");
    start += strlen(fence);
    char *end = strstr(start, "```");
    cr_assert_not_null(end);

    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    FILE *file = fdopen(fd, "wb");
    cr_assert_not_null(file);
    fwrite(start, 1, (size_t)(end - start), file);
    fclose(file);
    mu_model_desc *desc = NULL;
    rb_status status = mu_model_desc_load(path, &desc);
    remove(path);
    cr_assert_eq(status, RB_OK, "%s", rb_last_error());
    expect_counts(desc, 1, 3, 1, 1, 3, 1, 2, 3);
    /* Calf: 0.3 MPa × 1e-5 m³ / (0.05 m · 2 µm / 2.5 µm). */
    expect_near(desc->muscles[index_of(desc, MU_MODEL_MUSCLE, "Calf")].max_force, 3e5 * 1e-5 / 0.04, 1e-9,
                "the force from the architecture");
    const mu_model_variant *strap_alone = &desc->variants[1];
    cr_expect_eq(strap_alone->bone_count, 2, "a variant that lists its bones");
    cr_expect_not(mu_model_variant_has_bone(strap_alone, index_of(desc, MU_MODEL_BONE, "Hook")));
    mu_model_desc_destroy(desc);
}

Test(model_desc, objects_are_found_by_name)
{
    mu_model_desc *desc = load_builtin("arm");
    mu_model_ref ref;
    cr_assert(mu_model_desc_find(desc, "Nail", &ref));
    expect_ref(ref, MU_MODEL_NAIL, 0, "Nail");
    cr_assert(mu_model_desc_find(desc, "Humerus", &ref));
    expect_ref(ref, MU_MODEL_BONE, 1, "Humerus");
    cr_assert(mu_model_desc_find(desc, "Elbow", &ref));
    expect_ref(ref, MU_MODEL_HINGE, 1, "Elbow");
    cr_assert(mu_model_desc_find(desc, "Hand to Radius", &ref));
    expect_ref(ref, MU_MODEL_GLUE, 2, "Hand to Radius");
    cr_assert(mu_model_desc_find(desc, "Weight", &ref));
    expect_ref(ref, MU_MODEL_WEIGHT, 0, "Weight");
    cr_assert(mu_model_desc_find(desc, "Biceps Short", &ref), "a muscle, not the variant of that name");
    expect_ref(ref, MU_MODEL_MUSCLE, 0, "Biceps Short");
    cr_assert(mu_model_desc_find(desc, "Triceps Long + Triceps Medial + Triceps Lateral", &ref));
    expect_ref(ref, MU_MODEL_GROUP, 1, "the triceps group");
    cr_expect_str_eq(mu_model_desc_name_of(desc, ref), "Triceps Long + Triceps Medial + Triceps Lateral");

    cr_expect_not(mu_model_desc_find(desc, "humerus", &ref), "names are case-sensitive");
    cr_expect_not(mu_model_desc_find(desc, "All Triceps", &ref), "variants have their own namespace");
    cr_expect_eq(mu_model_desc_find_variant(desc, "All Triceps"), 3);
    cr_expect_eq(mu_model_desc_find_variant(desc, "Triceps"), -1);
    cr_expect_not(mu_model_desc_find(desc, NULL, &ref));
    cr_expect_not(mu_model_desc_find(NULL, "Humerus", &ref));
    cr_expect_null(mu_model_desc_name_of(desc, (mu_model_ref){MU_MODEL_BONE, 10}));
    cr_expect_not(mu_model_variant_has_bone(&desc->variants[0], 10));
    cr_expect(mu_model_variant_has_bone(&desc->variants[0], 9));
    mu_model_desc_destroy(desc);
    mu_model_desc_destroy(NULL);
}

/* ---- files that fail --------------------------------------------------------- */

/* Fixed-size strings: Criterion copies the parameters into each test's
 * process, where a pointer into this one would mean nothing. */
typedef struct bad_model {
    char file[48];
    char expected[256]; /* a fragment of the message: file:line:column: path: problem, expected ... */
} bad_model;

static const bad_model bad_models[] = {
    {"torque_muscle_strongest_below_weakest.json",
     "torque_muscle_strongest_below_weakest.json:10:65: torque_muscles[0].motor_pool.strongest: 1 is below weakest "
     "(5), expected a strength >= weakest"},
    {"torque_muscle_on_a_nail.json",
     "torque_muscle_on_a_nail.json:10:32: torque_muscles[0].body: \"Nail\" is a nail, expected the name of a bone"},
    {"torque_muscle_without_pool.json",
     "torque_muscle_without_pool.json:7:5: torque_muscles[0]: missing key \"motor_pool\", expected the motor pool "
     "{\"image\": PNG}, {\"csv\": CSV} or {neurons, weakest, strongest}"},
    {"vmax_twice.json", "vmax_twice.json:7:114: muscles[0].max_velocity_rest_lengths: given with max_velocity, "
                        "expected either max_velocity (m/s) or max_velocity_rest_lengths (rest lengths per second)"},
    {"syntax_error.json", "syntax_error.json:7:49: invalid JSON: '}' expected near '\"size\"'"},
    {"number_overflow.json", "number_overflow.json:7:58: invalid JSON: real number overflow near '1e999'"},
    {"duplicate_key.json", "duplicate_key.json:7:71: invalid JSON: duplicate object key near '\"size\"'"},
    {"empty_file.json", "empty_file.json:1:0: invalid JSON: '[' or '{' expected near end of file"},
    {"not_an_object.json", "not_an_object.json:1:1: (top level): found an array, expected an object with the keys "
                           "name, gravity"},
    {"missing_model_name.json",
     "missing_model_name.json:1:1: (top level): missing key \"name\", expected the model's name"},
    {"missing_bone_size.json",
     "missing_bone_size.json:7:5: bones[0]: missing key \"size\", expected the bone's x and y extents in m"},
    {"mistyped_size.json",
     "mistyped_size.json:7:53: bones[0].size: found a string, expected the bone's x and y extents in m: [x, y]"},
    {"string_for_number.json", "string_for_number.json:20:22: muscles[0].rest_length: found a string, expected the "
                               "fibres' rest (optimal) length in m (in [0.001, 10])"},
    {"mistyped_static.json", "mistyped_static.json:7:76: bones[0].static: found a string, expected whether the bone "
                             "is static (true or false)"},
    {"real_substeps.json", "real_substeps.json:3:15: substeps: found a real number, expected the substeps per frame "
                           "(an integer in [1, 1000])"},
    {"position_three_numbers.json", "position_three_numbers.json:3:16: placement: found an array of 3 numbers, "
                                    "expected the model's offset in m: [x, y]"},
    {"weight_not_an_object.json", "weight_not_an_object.json:16:13: weight: found an array, expected an object with "
                                  "the keys name, body, position, masses"},
    {"comment_not_a_string.json",
     "comment_not_a_string.json:3:14: comment: found a number, expected a comment (a string)"},
    {"unknown_key.json", "unknown_key.json:7:66: bones[0].colour: unknown key \"colour\", expected one of name, "
                         "centre, size, angle, depth, static, density, damping, wall_thickness, youngs_modulus, "
                         "tensile_strength, compressive_strength (or comment)"},
    {"unknown_top_level_key.json", "unknown_top_level_key.json:3:3: gravitation: unknown key \"gravitation\", "
                                   "expected one of name, gravity"},
    {"negative_size.json", "negative_size.json:8:62: bones[1].size[1]: -0.05 is out of range, expected the bone's x "
                           "and y extents in m (in [0.001, 100])"},
    {"escaped_key_position.json", "escaped_key_position.json:5:68: bones[0].size[1]: -0.2 is out of range"},
    {"zero_density.json", "zero_density.json:7:77: bones[0].density: 0 is out of range, expected the bone's density in "
                          "kg/m³ (in [1, 100000])"},
    {"empty_name.json", "empty_name.json:7:15: bones[0].name: found an empty string, expected the object's name"},
    {"zero_frame_rate.json",
     "zero_frame_rate.json:3:17: frame_rate: 0 is out of range, expected the frame rate in Hz (in [1, 1000])"},
    {"negative_weight_mass.json", "negative_weight_mass.json:16:92: weight.masses[2]: -5 is out of range, expected a "
                                  "mass in kg, 0 for no weight (in [0, 1e+06])"},
    {"empty_weight_list.json", "empty_weight_list.json:16:85: weight.masses: found 0 elements, expected 1 to 65535 "
                               "weight choices in kg"},
    {"unknown_body_in_hinge.json", "unknown_body_in_hinge.json:11:72: hinges[0].body_b: no nail or bone is named "
                                   "\"Bone3\", expected the name of a nail or bone"},
    {"unknown_body_in_glue.json", "unknown_body_in_glue.json:14:33: glues[0].body_a: no nail or bone is named "
                                  "\"Humerus\", expected the name of a nail or bone"},
    {"unknown_body_in_path.json", "unknown_body_in_path.json:23:19: muscles[0].path[1].body: no nail or bone is "
                                  "named \"bone2\", expected the name of a nail or bone"},
    {"unknown_body_in_weight.json", "unknown_body_in_weight.json:16:41: weight.body: no nail or bone is named "
                                    "\"Radius\", expected the name of a nail or bone"},
    {"joint_as_body.json",
     "joint_as_body.json:14:33: glues[0].body_a: \"Hinge\" is a hinge, expected the name of a nail or bone"},
    {"duplicate_name.json", "duplicate_name.json:14:15: glues[0].name: \"Bone2\" is already the name of bones[1], "
                            "expected a name that no other nail, bone, hinge, glue, weight, muscle, group or "
                            "torque muscle has"},
    {"duplicate_variant_name.json", "duplicate_variant_name.json:32:15: variants[1].name: \"Default\" is already the "
                                    "name of variants[0], expected a name that no other variant has"},
    {"variant_unknown_muscle.json", "variant_unknown_muscle.json:31:48: variants[0].muscles[1]: no muscle is named "
                                    "\"Biceps\", expected the name of a muscle"},
    {"variant_unknown_bone.json", "variant_unknown_bone.json:31:68: variants[0].bones[1]: no bone is named "
                                  "\"Bone3\", expected the name of a bone"},
    {"variant_without_muscle_bone.json",
     "variant_without_muscle_bone.json:31:38: variants[0].muscles[0]: muscle \"Muscle\" runs over bone \"Bone2\", "
     "which the variant's bones leave out"},
    {"no_variants.json", "no_variants.json:30:15: variants: found 0 elements, expected 1 to 65535 variants"},
    {"group_unknown_muscle.json", "group_unknown_muscle.json:28:36: groups[0].muscles[0]: no muscle is named "
                                  "\"Muscles\", expected the name of a muscle"},
    {"group_muscle_twice.json",
     "group_muscle_twice.json:28:46: groups[0].muscles[1]: \"Muscle\" is listed twice, expected each muscle once"},
    {"limits_wrong_order.json",
     "limits_wrong_order.json:13:16: hinges[0].lower: 90 is above upper (-10), expected lower <= upper"},
    {"limit_999.json", "limit_999.json:13:16: hinges[0].lower: -999 is out of range, expected a joint angle limit in "
                       "degrees, left out for no limit (in [-360, 360])"},
    {"path_one_point.json", "path_one_point.json:21:15: muscles[0].path: found 1 element, expected 2 to 8 path "
                            "points {body, point}"},
    {"path_too_long.json", "path_too_long.json:21:15: muscles[0].path: found 9 elements, expected 2 to 8 path "
                           "points {body, point}"},
    {"glue_to_itself.json",
     "glue_to_itself.json:14:52: glues[0].body_b: \"Bone1\" is body_a too, expected a different body"},
    {"hinge_to_itself.json",
     "hinge_to_itself.json:11:72: hinges[0].body_b: \"Nail\" is body_a too, expected a different body"},
    {"negative_specific_tension.json", "negative_specific_tension.json:20:67: muscles[0].specific_tension: -1.5e+06 "
                                       "is out of range, expected the specific tension in N/m² (in [1000, 1e+07])"},
    {"zero_max_velocity.json", "zero_max_velocity.json:20:63: muscles[0].max_velocity: 0 is out of range, expected "
                               "the maximal shortening speed in m/s (in [0.001, 100])"},
    {"start_length_out_of_range.json",
     "start_length_out_of_range.json:20:74: muscles[0].start_normalized_length: 2 is out of range, expected the "
     "belly's length at creation over its rest length (in [0.5, 1.5])"},
    {"start_length_and_tendon.json", "start_length_and_tendon.json:20:96: muscles[0].tendon_length: given with "
                                     "start_normalized_length, expected one of the two"},
    {"max_force_and_specific_tension.json",
     "max_force_and_specific_tension.json:20:66: muscles[0].specific_tension: given with max_force, expected either "
     "max_force or rest_width with specific_tension"},
    {"missing_rest_width.json", "missing_rest_width.json:18:5: muscles[0]: missing key \"rest_width\", expected the "
                                "belly's width at rest in m, max_force or architecture"},
    {"negative_rest_width.json", "negative_rest_width.json:20:41: muscles[0].rest_width: -0.05 is out of range, "
                                 "expected the belly's width at rest in m (in [0.0001, 1])"},
    {"symmetry_out_of_range.json", "symmetry_out_of_range.json:20:59: muscles[0].symmetry: 1.5 is out of range, "
                                   "expected where the belly sits between the path's ends (in [0, 1])"},
    {"tendon_fraction_and_rest_length.json",
     "tendon_fraction_and_rest_length.json:20:66: muscles[0].tendon_fraction: given with rest_length, expected one of "
     "the two"},
    {"compliant_tendon_zero_strain.json",
     "compliant_tendon_zero_strain.json:20:92: muscles[0].compliant_tendon.strain_at_max_force: 0 is out of range, "
     "expected the tendon's strain at the maximal isometric force (in [0.001, 1])"},
    {"activation_dynamics_unknown_key.json",
     "activation_dynamics_unknown_key.json:20:72: muscles[0].activation_dynamics.tau: unknown key \"tau\", expected "
     "one of model, activation_time, deactivation_time, fibre_type, calcium_rise_time, calcium_decay_time, "
     "force_rise_time, force_decay_time (or comment)"},
    {"pennation_out_of_range.json", "pennation_out_of_range.json:20:66: muscles[0].pennation_angle: 90 is out of "
                                    "range, expected the pennation angle at the optimal fibre length in degrees (in "
                                    "[0, 80])"},
    {"compliant_tendon_without_tendon.json",
     "compliant_tendon_without_tendon.json:20:99: muscles[0].compliant_tendon: the tendon's slack length would be "
     "-0.0027864 m (path 0.447214 m at the start pose), expected a compliant tendon longer than 0"},
    {"unknown_curve_set.json", "unknown_curve_set.json:20:57: muscles[0].curves: \"hill\" is no curve set, expected "
                               "the curve set, \"tabulated\" or \"analytic\""},
    /* Numbers the simulation cannot take (issue 17, item 4): each key's
     * range is tested in test_model_ranges.c; these are the issue's. */
    {"placement_far.json", "placement_far.json:3:17: placement[0]: 1e+200 is out of range, expected the model's offset "
                           "in m (in [-100, 100])"},
    {"frame_rate_huge.json",
     "frame_rate_huge.json:3:17: frame_rate: 1e+09 is out of range, expected the frame rate in Hz (in [1, 1000])"},
    {"substep_rate_too_low.json", "substep_rate_too_low.json:3:32: substeps: frame_rate × substeps is 10 Hz, expected "
                                  "a substep rate in [60, 100000] Hz (a substep of 1/60 s at most)"},
    {"gravity_huge.json",
     "gravity_huge.json:3:18: gravity[1]: -1e+308 is out of range, expected the gravity in m/s² (in [-1000, 1000])"},
    {"centre_far.json", "centre_far.json:8:35: bones[1].centre[0]: -1e+308 is out of range, expected the bone's centre "
                        "in m (in [-100, 100])"},
    {"density_tiny.json", "density_tiny.json:7:77: bones[0].density: 1e-300 is out of range, expected the bone's "
                          "density in kg/m³ (in [1, 100000])"},
    {"weight_mass_huge.json", "weight_mass_huge.json:16:92: weight.masses[2]: 1e+308 is out of range, expected a mass "
                              "in kg, 0 for no weight (in [0, 1e+06])"},
    {"max_force_huge.json", "max_force_huge.json:20:40: muscles[0].max_force: 1e+308 is out of range, expected the "
                            "maximal isometric force in N (in [0.001, 1e+06])"},
    {"rest_width_huge.json", "rest_width_huge.json:20:41: muscles[0].rest_width: 1e+200 is out of range, expected the "
                             "belly's width at rest in m (in [0.0001, 1])"},
    {"specific_tension_huge.json", "specific_tension_huge.json:20:67: muscles[0].specific_tension: 1e+308 is out of "
                                   "range, expected the specific tension in N/m² (in [1000, 1e+07])"},
    {"strain_tiny.json", "strain_tiny.json:20:114: muscles[0].compliant_tendon.strain_at_max_force: 1e-300 is out of "
                         "range, expected the tendon's strain at the maximal isometric force (in [0.001, 1])"},
    {"path_point_far.json", "path_point_far.json:23:41: muscles[0].path[1].point[1]: 1e+308 is out of range, expected "
                            "the point in the body's frame, in m (in [-100, 100])"},
    {"force_from_width_too_small.json",
     "force_from_width_too_small.json:20:41: muscles[0].rest_width: the maximal force π·rest_width²/4·specific_tension "
     "in N is 7.85398e-06, expected a value in [0.001, 1e+06]"},
    {"hinge_open.json", "hinge_open.json:11:93: hinges[0].anchor_b: the anchors are 0.1 m apart at the start pose, "
                        "expected them to meet (within 0.01 m)"},
    {"tendon_fraction_tiny_rest_length.json",
     "tendon_fraction_tiny_rest_length.json:20:26: muscles[0].tendon_fraction: the rest length it derives from the "
     "path at the start pose, in m, is 4.47214e-05, expected a value in [0.001, 10]"},
    {"vmax_rest_lengths_too_slow.json",
     "vmax_rest_lengths_too_slow.json:20:78: muscles[0].max_velocity_rest_lengths: the maximal shortening speed it "
     "gives with the rest length, in m/s, is 0.0001, expected a value in [0.001, 100]"},
    {"path_points_coincide.json", "path_points_coincide.json:23:9: muscles[0].path[1]: is 0 m from path[0] at the "
                                  "start pose, expected consecutive path points at least 0.0005 m apart"},
};

#define BAD_MODEL_COUNT (sizeof bad_models / sizeof bad_models[0])

ParameterizedTestParameters(model_desc, bad_model_fails_with_its_message)
{
    return cr_make_param_array(bad_model, bad_models, BAD_MODEL_COUNT);
}

ParameterizedTest(const bad_model *bad, model_desc, bad_model_fails_with_its_message)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", BAD_MODELS, bad->file);
    static mu_model_desc sentinel;
    mu_model_desc *desc = &sentinel; /* not NULL, so that a failure must clear it */
    rb_status status = mu_model_desc_load(path, &desc);
    cr_expect_eq(status, RB_ERR_INVALID_ARGUMENT, "%s: status %s", bad->file, rb_status_name(status));
    cr_expect_null(desc, "%s: a description came back", bad->file);
    const char *message = rb_last_error();
    cr_expect(strncmp(message, path, strlen(path)) == 0, "%s: the message does not start with the file's path: %s",
              bad->file, message);
    cr_expect(strstr(message, bad->expected) != NULL, "%s:\n  message  %s\n  expected %s", bad->file, message,
              bad->expected);
}

Test(model_desc, every_file_of_the_corpus_has_its_expected_message)
{
    DIR *directory = opendir(BAD_MODELS);
    cr_assert_not_null(directory);
    size_t files = 0;
    for (struct dirent *entry = readdir(directory); entry != NULL; entry = readdir(directory)) {
        if (entry->d_name[0] == '.') {
            continue;
        }
        ++files;
        bool listed = false;
        for (size_t i = 0; i < BAD_MODEL_COUNT && !listed; ++i) {
            listed = strcmp(bad_models[i].file, entry->d_name) == 0;
        }
        cr_expect(listed, "%s is in the corpus but not in bad_models[]", entry->d_name);
    }
    closedir(directory);
    cr_expect_eq(files, BAD_MODEL_COUNT, "files in the corpus");
    cr_expect_geq(files, 20);
}

/* Every prefix of a good file is a bad one: each fails cleanly. */
Test(model_desc, truncated_files_fail_cleanly)
{
    FILE *source = fopen(SINEW_SOURCE_DIR "/models/arm.json", "rb");
    cr_assert_not_null(source);
    static char text[32768];
    size_t length = fread(text, 1, sizeof text, source);
    fclose(source);
    cr_assert_lt(length, sizeof text);
    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    for (size_t cut = 0; cut + 2 < length; cut += 37) {
        FILE *file = fopen(path, "wb");
        cr_assert_not_null(file);
        fwrite(text, 1, cut, file);
        fclose(file);
        mu_model_desc *desc = NULL;
        cr_expect_eq(mu_model_desc_load(path, &desc), RB_ERR_INVALID_ARGUMENT, "cut at %zu", cut);
        cr_expect_null(desc);
        cr_expect(strstr(rb_last_error(), "invalid JSON") != NULL, "cut at %zu: %s", cut, rb_last_error());
    }
    remove(path);
}

Test(model_desc, missing_and_unreadable_files_fail)
{
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load(BAD_MODELS "/no_such_file.json", &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(desc);
    cr_expect(strstr(rb_last_error(), "no_such_file.json: cannot open: No such file or directory") != NULL, "%s",
              rb_last_error());

    cr_expect_eq(mu_model_desc_load(BAD_MODELS, &desc), RB_ERR_INVALID_ARGUMENT, "a directory");
    cr_expect_null(desc);
    cr_expect(strstr(rb_last_error(), "bad_models: cannot read: Is a directory") != NULL, "%s", rb_last_error());

    cr_expect_eq(mu_model_desc_load("", &desc), RB_ERR_INVALID_ARGUMENT, "an empty path");
    cr_expect_eq(mu_model_desc_load(NULL, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "path is NULL") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_model_desc_load(SINEW_SOURCE_DIR "/models/arm.json", NULL), RB_ERR_INVALID_ARGUMENT);

    cr_expect_eq(mu_model_desc_load_builtin("worm-of-doom", &desc), RB_ERR_INVALID_ARGUMENT, "no such model");
    cr_expect(strstr(rb_last_error(), "no built-in model is named \"worm-of-doom\", expected one of sample, arm, "
                                      "leg, leg-unlimited, worm") != NULL,
              "%s", rb_last_error());
    cr_expect_eq(mu_model_desc_load_builtin("../models/arm", &desc), RB_ERR_INVALID_ARGUMENT, "a path, not a name");
    cr_expect(strstr(rb_last_error(), "expected a built-in model's name") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_model_desc_load_builtin(NULL, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(desc);
}

Test(model_desc, a_file_without_read_permission_fails)
{
    if (geteuid() == 0) {
        cr_skip_test("root reads every file");
    }
    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    cr_assert_eq(chmod(path, 0), 0);
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load(path, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(desc);
    cr_expect(strstr(rb_last_error(), "cannot open: Permission denied") != NULL, "%s", rb_last_error());
    remove(path);
}

Test(model_desc, max_velocity_in_rest_lengths_per_second)
{
    /* 10 rest lengths per second of a 0.3 m muscle: Vmax = 3 m/s. */
    mu_model_desc *desc = load(SINEW_SOURCE_DIR "/tests/data/models/vmax_rest_lengths.json");
    cr_expect_eq(desc->muscles[0].max_velocity, 3.0, "Vmax %g m/s, expected 3", desc->muscles[0].max_velocity);
    mu_model_desc_destroy(desc);
}

/* ---- any bytes end in bounded time ------------------------------------------- */

/* Writes `length` bytes to the temporary file `path` and loads it; the
 * result may be a description or an error, but it must come back. */
static void load_bytes(const char *path, const char *bytes, size_t length)
{
    FILE *file = fopen(path, "wb");
    cr_assert_not_null(file);
    cr_assert_eq(fwrite(bytes, 1, length, file), length);
    fclose(file);
    mu_model_desc *desc = NULL;
    rb_status status = mu_model_desc_load(path, &desc);
    cr_expect(status == RB_OK ? desc != NULL : desc == NULL, "a description comes back exactly on success");
    mu_model_desc_destroy(desc);
}

/* The 39 bytes of the issue: jansson passes over the NUL, and the error
 * about "zz" is then located by a scan that used to stop at the NUL. */
Test(model_desc, a_nul_byte_inside_an_array_ends_in_an_error, .timeout = 10)
{
    static const char bytes[] = "{\"name\":\"x\",\"gravity\":[0,-9.8\0],\"zz\":1}";
    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    load_bytes(path, bytes, sizeof bytes - 1);
    remove(path);
    cr_expect(strstr(rb_last_error(), "zz") != NULL, "%s", rb_last_error());
}

/* A NUL written over, or inserted before, every byte of a small model, a
 * structural byte written over it (each of 11 in turn), and every prefix
 * of the model: each load ends (the test's timeout is the bound).
 * jansson passes over a NUL between tokens, so most of these files parse;
 * an unknown key at the end then makes the loader locate an error past
 * every value of the file. */
Test(model_desc, a_nul_at_every_position_and_every_truncation_end, .timeout = 60)
{
    FILE *source = fopen(SINEW_SOURCE_DIR "/models/sample.json", "rb");
    cr_assert_not_null(source);
    static char text[4096], changed[4097];
    size_t length = fread(text, 1, sizeof text, source);
    fclose(source);
    cr_assert_lt(length + 16, sizeof text);
    char *last_brace = strrchr(text, '}');
    cr_assert_not_null(last_brace);
    length = (size_t)(last_brace - text);
    length += (size_t)sprintf(last_brace, ", \"zz\": 1}\n");
    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    close(fd);
    load_bytes(path, text, length);
    cr_expect(strstr(rb_last_error(), ": zz: unknown key") != NULL, "%s", rb_last_error());
    for (size_t at = 0; at < length; ++at) {
        memcpy(changed, text, length);
        changed[at] = '\0';
        load_bytes(path, changed, length);
        /* A byte the scanner treats apart written over this one, each in turn. */
        static const char structural[] = "[]{}\",:\\ 1e";
        memcpy(changed, text, length);
        changed[at] = structural[at % (sizeof structural - 1)];
        load_bytes(path, changed, length);
        memcpy(changed, text, at);
        changed[at] = '\0';
        memcpy(changed + at + 1, text + at, length - at);
        load_bytes(path, changed, length + 1);
        load_bytes(path, text, at);
    }
    remove(path);
}

/* ---- what a file may hold -------------------------------------------------------- */

/* A file that never ends, or a huge one, is refused after
 * MU_MODEL_MAX_FILE_BYTES, with the limit in the message. */
Test(model_desc, endless_and_huge_files_are_refused_at_the_limit, .timeout = 30)
{
    static const char *const endless[] = {"/dev/zero", "/dev/urandom"};
    for (size_t i = 0; i < sizeof endless / sizeof endless[0]; ++i) {
        mu_model_desc *desc = NULL;
        cr_expect_eq(mu_model_desc_load(endless[i], &desc), RB_ERR_INVALID_ARGUMENT, "%s", endless[i]);
        cr_expect_null(desc);
        cr_expect(strstr(rb_last_error(), "longer than 16777216 bytes, expected a model file of at most 16777216 "
                                          "bytes") != NULL,
                  "%s: %s", endless[i], rb_last_error());
    }
    /* Sparse files of zeros: one byte over is refused for its size, the
     * limit itself is read (and then is no JSON). */
    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    cr_assert_eq(ftruncate(fd, MU_MODEL_MAX_FILE_BYTES + 1), 0);
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load(path, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "longer than 16777216 bytes") != NULL, "%s", rb_last_error());
    cr_assert_eq(ftruncate(fd, MU_MODEL_MAX_FILE_BYTES), 0);
    close(fd);
    cr_expect_eq(mu_model_desc_load(path, &desc), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "invalid JSON") != NULL, "%s", rb_last_error());
    remove(path);
}

/* Finding names does not scan: a file of 65,535 nails, or of 65,535
 * muscles listed by a group and a variant, loads in linear time. (Each
 * name was once checked against every name before it: the nails took a
 * minute.) The timeout is the bound. */
Test(model_desc, full_lists_load_in_linear_time, .timeout = 60)
{
    char path[] = "/tmp/sinew-model-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    FILE *file = fdopen(fd, "wb");
    cr_assert_not_null(file);
    fputs("{\"name\": \"many\", \"nails\": [", file);
    for (int i = 0; i < MU_MODEL_MAX_OBJECTS; ++i) {
        fprintf(file, "%s{\"name\": \"n%d\", \"position\": [0, %d]}", i > 0 ? "," : "", i, i % 2);
    }
    fputs("], \"muscles\": [", file);
    for (int i = 0; i < MU_MODEL_MAX_OBJECTS; ++i) {
        fprintf(file,
                "%s{\"name\": \"m%d\", \"rest_length\": 1, \"max_force\": 1, \"path\": [{\"body\": \"n0\", "
                "\"point\": [0, 0]}, {\"body\": \"n1\", \"point\": [0, 0]}]}",
                i > 0 ? "," : "", i);
    }
    const char *lists[2] = {"], \"groups\": [{\"name\": \"all\", \"muscles\": [",
                            "]}], \"variants\": [{\"name\": \"all\", \"muscles\": ["};
    for (int l = 0; l < 2; ++l) {
        fputs(lists[l], file);
        for (int i = 0; i < MU_MODEL_MAX_OBJECTS; ++i) {
            fprintf(file, "%s\"m%d\"", i > 0 ? "," : "", i);
        }
    }
    fputs("]}]}\n", file);
    fclose(file);
    mu_model_desc *desc = NULL;
    cr_expect_eq(mu_model_desc_load(path, &desc), RB_OK, "%s", rb_last_error());
    remove(path);
    cr_assert_not_null(desc);
    cr_expect_eq(desc->nail_count, MU_MODEL_MAX_OBJECTS);
    cr_expect_eq(desc->groups[0].muscle_count, MU_MODEL_MAX_OBJECTS);
    mu_model_ref ref;
    cr_expect(mu_model_desc_find(desc, "m65534", &ref) && ref.kind == MU_MODEL_MUSCLE && ref.index == 65534);
    cr_expect(mu_model_desc_find(desc, "n7", &ref) && ref.kind == MU_MODEL_NAIL && ref.index == 7);
    cr_expect_not(mu_model_desc_find(desc, "n65535", &ref));
    cr_expect_eq(mu_model_desc_find_variant(desc, "all"), 0);
    mu_model_desc_destroy(desc);
}
