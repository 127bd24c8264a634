/* SPDX-License-Identifier: MIT */
/* Bone stress (mu/bone_stress.h) against beam theory in closed form: a
 * level bone on a locked hinge with a weight at its tip is a cantilever,
 * whose root carries M = W·L + w·L²/2 and σ = M·c/I with the tube's
 * I = π(D⁴ - d⁴)/64 and c = D/2; a hanging bone with a weight at its foot
 * is in pure tension, σ = F/A; every bone of a moving arm is in balance
 * under its loads and inertia; all bones read at once are each bone read
 * alone, bit for bit; and bad beam values in a model file are
 * refused with their JSON path. */
#define _DEFAULT_SOURCE /* mkstemps */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/bone_stress.h"

#define G 9.8
#define DENSITY 1900.0
#define PI 3.14159265358979323846

static char *write_text(const char *text)
{
    static char path[64];
    snprintf(path, sizeof path, "/tmp/sinew-bone-stress-XXXXXX.json");
    const int fd = mkstemps(path, 5);
    cr_assert(fd >= 0);
    cr_assert_eq(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    return path;
}

static mu_model_desc *load_text(const char *text)
{
    const char *path = write_text(text);
    mu_model_desc *desc = NULL;
    const rb_status status = mu_model_desc_load(path, &desc);
    unlink(path);
    cr_assert_eq(status, RB_OK, "%s", rb_last_error());
    return desc;
}

/* A model of one bone on a hinge to a wall, with a weight; %s is the
 * bone's extra keys, the rest the bone's and the hinge's geometry. */
static char *one_bone(const char *centre, const char *size, const char *extra, const char *anchor, const char *limits,
                      const char *weight_at, double mass)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "{\"name\": \"beam\", \"gravity\": [0, -9.8], \"damping\": 8,"
             " \"nails\": [{\"name\": \"Wall\", \"position\": [0, 0]}],"
             " \"bones\": [{\"name\": \"Bone\", \"centre\": %s, \"size\": %s%s}],"
             " \"hinges\": [{\"name\": \"Hinge\", \"body_a\": \"Wall\", \"anchor_a\": [0, 0], \"body_b\": \"Bone\","
             "              \"anchor_b\": %s, \"radius\": 0.01%s}],"
             " \"weight\": {\"name\": \"Weight\", \"body\": \"Bone\", \"position\": %s, \"masses\": [%g]},"
             " \"muscles\": [], \"groups\": [], \"variants\": [{\"name\": \"all\", \"muscles\": []}]}",
             centre, size, extra, anchor, limits, weight_at, mass);
    return text;
}

static mu_model *settle(const char *text, mu_model_desc **desc)
{
    *desc = load_text(text);
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(*desc, &options, &model), RB_OK, "%s", rb_last_error());
    for (int frame = 0; frame < 120; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK);
    }
    return model;
}

static void expect_relative(double actual, double expected, double tolerance, const char *what)
{
    cr_expect(fabs(actual - expected) <= tolerance * fabs(expected), "%s: %.15g, expected %.15g (relative %.3g)", what,
              actual, expected, fabs(actual - expected) / fabs(expected));
}

/* A 0.4 m bone of 0.02 m diameter, level, on a hinge at its left end
 * locked at 0°, a 5 kg weight at its right end. */
Test(bone_stress, a_cantilever_root_carries_w_l_and_m_c_over_i)
{
    mu_model_desc *desc = NULL;
    mu_model *model = settle(one_bone("[0.2, 0]", "[0.4, 0.02]", ", \"wall_thickness\": 0.004", "[-0.2, 0]",
                                      ", \"lower\": 0, \"upper\": 0", "[0.4, 0]", 5.0),
                             &desc);
    const double length = 0.4, outer = 0.02, inner = outer - 2.0 * 0.004;
    const double bone_weight = DENSITY * 0.4 * 0.02 * 0.02 * G, weight = 5.0 * G;
    const double moment = weight * length + bone_weight * length / 2.0;
    const double second_moment = PI * (pow(outer, 4) - pow(inner, 4)) / 64.0;
    const double stress = moment * (outer / 2.0) / second_moment;

    const mu_bone_beam beam = mu_model_bone_beam(model, 0);
    expect_relative(beam.second_moment, second_moment, 1e-12, "I");
    expect_relative(beam.area, PI * (outer * outer - inner * inner) / 4.0, 1e-12, "A");
    /* The root, just beyond the hinge: the moment hangs the beam clockwise. */
    const mu_bone_section root = mu_model_bone_section(model, 0, -length / 2.0, false);
    expect_relative(root.bending_moment, -moment, 1e-6, "root bending moment");
    expect_relative(root.shear_force, -(weight + bone_weight), 1e-6, "root shear force");
    cr_expect(fabs(root.axial_force) <= 1e-6 * weight, "no axial force: %g N", root.axial_force);
    expect_relative(fabs(root.stress), stress, 1e-6, "root stress M·c/I");
    /* Midway the moment is W·L/2 + w·(L/2)²/2. */
    const mu_bone_section middle = mu_model_bone_section(model, 0, 0.0, false);
    expect_relative(middle.bending_moment, -(weight * length / 2.0 + bone_weight / 2.0 * length / 4.0), 1e-6,
                    "midway bending moment");
    /* The worst section is the root, in tension on top and compression
     * below; tension's strength is the smaller, so it sets the factor. */
    const mu_bone_stress worst = mu_model_bone_stress(model, 0);
    expect_relative(worst.worst.s, -length / 2.0, 1e-12, "the worst section is the root");
    expect_relative(worst.worst.safety_factor, 133e6 / stress, 1e-6, "safety factor S_t/σ");
    expect_relative(worst.strain, fabs(worst.worst.stress) / 17e9, 1e-12, "strain σ/E");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The same bone hanging from its top, free to turn, a 10 kg weight at its
 * foot: every section pulls the part below up by the weight below it. */
Test(bone_stress, a_hanging_bone_is_in_pure_tension)
{
    mu_model_desc *desc = NULL;
    mu_model *model = settle(one_bone("[0, -0.2]", "[0.02, 0.4]", "", "[0, 0.2]", "", "[0, -0.4]", 10.0), &desc);
    const double outer = 0.02, inner = outer / 2.0; /* the default wall, D/4 */
    const double area = PI * (outer * outer - inner * inner) / 4.0;
    const double bone_weight = DENSITY * 0.4 * 0.02 * 0.02 * G, weight = 10.0 * G;
    /* The axis is the bone's y, pointing up: the foot is at s = -0.2. */
    const mu_bone_section foot = mu_model_bone_section(model, 0, -0.2, false);
    expect_relative(foot.axial_force, weight, 1e-6, "tension at the foot");
    expect_relative(foot.stress, weight / area, 1e-6, "σ = F/A at the foot");
    cr_expect(fabs(foot.bending_moment) <= 1e-6 * weight * 0.4, "no bending: %g N·m", foot.bending_moment);
    const mu_bone_section middle = mu_model_bone_section(model, 0, 0.0, false);
    expect_relative(middle.stress, (weight + bone_weight / 2.0) / area, 1e-6, "σ = F/A midway");
    const mu_bone_stress worst = mu_model_bone_stress(model, 0);
    expect_relative(worst.worst.stress, (weight + bone_weight) / area, 1e-6, "the top carries everything");
    expect_relative(worst.worst.safety_factor, 133e6 * area / (weight + bone_weight), 1e-6, "S_t/σ");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The worst stress of a bone hanging from its top with the weight hung
 * at the hinge's anchor, `below` metres under it. */
static double worst_with_weight_below_the_hinge(double below)
{
    char weight_at[64];
    snprintf(weight_at, sizeof weight_at, "[0, %.17g]", -below);
    mu_model_desc *desc = NULL;
    mu_model *model = settle(one_bone("[0, -0.2]", "[0.02, 0.4]", "", "[0, 0.2]", "", weight_at, 10.0), &desc);
    const double stress = mu_model_bone_stress(model, 0).worst.stress;
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    return stress;
}

/* Two loads at one point, as a weight hung from the hinge's pin or a
 * muscle inserted at a joint's anchor, reach the bone at coordinates that
 * rounding may set a few units in the last place apart. No section lies
 * between them: the hinge carries the weight, and the bone only its own
 * weight, however the roundings fall. Loads a micrometre apart do have
 * bone between them, which carries the weight. */
Test(bone_stress, loads_at_one_point_have_no_section_between_them)
{
    const double outer = 0.02, inner = outer / 2.0;
    const double area = PI * (outer * outer - inner * inner) / 4.0;
    const double bone_weight = DENSITY * 0.4 * 0.02 * 0.02 * G, weight = 10.0 * G;
    expect_relative(worst_with_weight_below_the_hinge(0.0), bone_weight / area, 1e-6, "weight on the pin");
    expect_relative(worst_with_weight_below_the_hinge(1e-15), bone_weight / area, 1e-6, "weight 1e-15 m under it");
    expect_relative(worst_with_weight_below_the_hinge(1e-6), (weight + bone_weight) / area, 1e-6,
                    "weight 1 µm under it");
}

/* The arm with a weight, its flexors pulling hard: every bone that moves
 * balances its loads and inertia, frame by frame. */
Test(bone_stress, every_bone_of_the_moving_arm_is_in_balance)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    mu_model_options options = mu_default_model_options();
    options.weight_index = 2; /* 5 kg */
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_set_activation(model, "Biceps Short", 1.0), RB_OK);
    cr_assert_eq(mu_model_set_activation(model, "Biceps Long", 0.8), RB_OK);
    int checked = 0;
    for (int frame = 0; frame < 60; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK);
        for (int b = 0; b < desc->bone_count; ++b) {
            rb_vec2 force;
            double moment, scale;
            if (mu_model_bone_balance(model, b, &force, &moment, &scale) != RB_OK) {
                continue; /* the scapula, glued to the nail */
            }
            const double size = fmax(desc->bones[b].size.x, desc->bones[b].size.y);
            cr_expect(rb_length(force) <= 1e-9 * scale, "%s frame %d: force residual %g N of %g N", desc->bones[b].name,
                      frame, rb_length(force), scale);
            cr_expect(fabs(moment) <= 1e-9 * scale * size, "%s frame %d: moment residual %g N·m", desc->bones[b].name,
                      frame, moment);
            const mu_bone_stress stress = mu_model_bone_stress(model, b);
            cr_expect(stress.worst.safety_factor > 0.0 && isfinite(stress.worst.stress), "%s: factor %g",
                      desc->bones[b].name, stress.worst.safety_factor);
            ++checked;
        }
    }
    cr_expect_eq(checked, 60 * 9, "the nine moving bones every frame (%d)", checked);
    cr_expect(isnan(mu_model_bone_stress(model, 0).worst.stress), "the scapula is the ground's");
    cr_expect(isnan(mu_model_bone_stress(model, 99).worst.stress));
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* Two readouts agree bit for bit, NaN matching NaN. */
static bool same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0 || (isnan(a) && isnan(b)); }

/* mu_model_bone_stresses against mu_model_bone_stress bone by bone, over
 * `frames` frames of the built-in model `name`, its first muscle pulling:
 * sharing a body's loads among its glued bones must change no bit. */
static void expect_all_at_once_is_each_alone(const char *name, bool weld_glues, int frames)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin(name, &desc), RB_OK);
    mu_model_options options = mu_default_model_options();
    options.weld_glues = weld_glues;
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    if (mu_model_muscle_count(model) > 0) {
        cr_assert_eq(mu_model_set_activation(model, mu_model_muscle_name(model, 0), 1.0), RB_OK);
    }
    mu_bone_stress *all = malloc(((size_t)desc->bone_count + 1) * sizeof *all);
    cr_assert_not_null(all);
    int finite = 0;
    for (int frame = 0; frame < frames; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK);
        cr_assert_eq(mu_model_bone_stresses(model, all), RB_OK, "%s", rb_last_error());
        for (int b = 0; b < desc->bone_count; ++b) {
            const mu_bone_stress alone = mu_model_bone_stress(model, b);
            const mu_bone_section *w = &all[b].worst, *v = &alone.worst;
            cr_expect(same(w->s, v->s) && same(w->axial_force, v->axial_force) &&
                          same(w->shear_force, v->shear_force) && same(w->bending_moment, v->bending_moment) &&
                          same(w->stress, v->stress) && same(w->safety_factor, v->safety_factor) &&
                          same(all[b].strain, alone.strain),
                      "%s%s frame %d bone %s: %.17g Pa at %.17g m at once, %.17g Pa at %.17g m alone", name,
                      weld_glues ? " (welded)" : "", frame, desc->bones[b].name, w->stress, w->s, v->stress, v->s);
            finite += isfinite(alone.worst.stress);
        }
    }
    cr_expect_gt(finite, 0, "%s: some bone moves", name);
    free(all);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(bone_stress, all_bones_at_once_are_each_bone_alone)
{
    expect_all_at_once_is_each_alone("arm", false, 30);
    expect_all_at_once_is_each_alone("arm", true, 30);
    expect_all_at_once_is_each_alone("leg", false, 30);
    expect_all_at_once_is_each_alone("worm", false, 30);
    expect_all_at_once_is_each_alone("sample", false, 30);
}

/* Newton's acceleration, from the loads the readout sees, against the
 * engine's own change of velocity over one substep of a pendulum (the
 * bone on a free hinge, let fall from level), which applies the hinge's
 * impulse and gravity and then the damping: v' = (v + h·(g + F/m))/(1 +
 * h·c), i.e. (v' - v)/h = g + F/m - c·v', the readout's form. The
 * engine applies the impulse at the pose the substep began with, the
 * readout takes the pose it ended with: the lever arm r of the hinge's
 * force F about the centre has turned by ω·h, so the angular
 * accelerations may differ by up to |F|·|r|·|ω|·h/I. */
Test(bone_stress, the_acceleration_is_the_engines)
{
    mu_model_desc *desc = load_text(one_bone("[0.2, 0]", "[0.4, 0.02]", "", "[-0.2, 0]", "", "[0.4, 0]", 2.0));
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    const rb_world *world = mu_model_world_to_read(model);
    const rb_body_id body = mu_model_body(model, mu_model_part_body(model, 1));
    const double inertia = rb_body_rotational_inertia(world, body);
    const double h = mu_model_substep_duration(model);
    for (int step = 0; step < 300; ++step) {
        const rb_vec2 v = rb_body_linear_velocity(world, body);
        const double omega = rb_body_angular_velocity(world, body);
        cr_assert_eq(mu_model_substep(model), RB_OK);
        rb_vec2 a;
        double alpha;
        cr_assert_eq(mu_model_bone_acceleration(model, 0, &a, &alpha), RB_OK, "%s", rb_last_error());
        const rb_vec2 engine = rb_scale(1.0 / h, rb_sub(rb_body_linear_velocity(world, body), v));
        const double engine_alpha = (rb_body_angular_velocity(world, body) - omega) / h;
        cr_expect(rb_length(rb_sub(a, engine)) <= 1e-9 * rb_length(engine), "substep %d: a (%g, %g), engine (%g, %g)",
                  step, a.x, a.y, engine.x, engine.y);
        const rb_joint_id hinge = mu_model_hinge_joint(model, 0);
        const double lever = rb_distance(rb_joint_world_anchor_b(world, hinge), rb_body_world_center(world, body));
        const double bound = rb_length(rb_joint_reaction_force(world, hinge)) * lever * fabs(omega) * h / inertia;
        cr_expect(fabs(alpha - engine_alpha) <= 1.01 * bound + 1e-6 * fabs(engine_alpha),
                  "substep %d: α %g, engine %g, bound %g", step, alpha, engine_alpha, bound);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void expect_refused(const char *extra, const char *message)
{
    const char *path = write_text(one_bone("[0.2, 0]", "[0.4, 0.02]", extra, "[-0.2, 0]", "", "[0.4, 0]", 1.0));
    mu_model_desc *desc = NULL;
    cr_expect_neq(mu_model_desc_load(path, &desc), RB_OK, "%s accepted", extra);
    unlink(path);
    cr_expect_null(desc);
    cr_expect_not_null(strstr(rb_last_error(), message), "%s: %s", extra, rb_last_error());
}

Test(bone_stress, bad_beam_values_are_refused_with_their_path)
{
    expect_refused(", \"wall_thickness\": 0.011",
                   "bones[0].wall_thickness: 0.011 is out of range, expected the cortical wall's thickness");
    expect_refused(", \"wall_thickness\": 0", "bones[0].wall_thickness");
    expect_refused(", \"youngs_modulus\": 0",
                   "bones[0].youngs_modulus: 0 is out of range, expected the bone's Young's modulus in Pa");
    expect_refused(", \"tensile_strength\": -1", "bones[0].tensile_strength");
    expect_refused(", \"compressive_strength\": \"hard\"", "bones[0].compressive_strength");
    expect_refused(", \"compressive_strength\": 1e11", "compressive strength in Pa (in [100000, 1e+10])");
}
