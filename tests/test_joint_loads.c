/* SPDX-License-Identifier: MIT */
/* Joint loads (mu/joint_loads.h) against statics in closed form: a beam
 * held level by a locked hinge carries its own weight and a weight, so the
 * hinge's reaction is their weight, m·g, and its torque their moment,
 * Σ m·g·d; a bone welded to it (weld_glues) hangs its weight on the weld.
 * And the muscles' torque about a hinge against the moment of the cable's
 * forces about the pivot, computed here from the cable's points. */
#define _DEFAULT_SOURCE /* mkstemps */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "model_support.h"
#include "mu/joint_loads.h"
#include "mu/moment_arms.h"

#define G 9.8
#define DENSITY 1900.0

/* A beam 0.4 m long, 0.02 m square in section, on a hinge at its left end
 * locked at 0°, with a 5 kg weight 0.3 m out (or none) and a block glued
 * under its right end. With weld_glues the 5 kg disc welded to the 0.3 kg
 * beam never settles (it swings by ±0.2° after 10 s: a weld between bodies
 * of 17:1 is soft in the solver), so the weld is tested without it. */
static const char *const beam_model =
    "{\"name\": \"beam\", \"gravity\": [0, -9.8], \"damping\": 0,"
    " \"nails\": [{\"name\": \"Wall\", \"position\": [0, 0]}],"
    " \"bones\": [{\"name\": \"Beam\", \"centre\": [0.2, 0], \"size\": [0.4, 0.02]},"
    "             {\"name\": \"Block\", \"centre\": [0.4, -0.05], \"size\": [0.02, 0.08]}],"
    " \"hinges\": [{\"name\": \"Hinge\", \"body_a\": \"Wall\", \"anchor_a\": [0, 0], \"body_b\": \"Beam\","
    "              \"anchor_b\": [-0.2, 0], \"radius\": 0.01, \"lower\": 0, \"upper\": 0}],"
    " \"glues\": [{\"name\": \"Beam to Block\", \"body_a\": \"Beam\", \"body_b\": \"Block\"}],"
    " \"weight\": {\"name\": \"Weight\", \"body\": \"Beam\", \"position\": [0.3, 0], \"masses\": [5, 0]},"
    " \"muscles\": [], \"groups\": [], \"variants\": [{\"name\": \"all\", \"muscles\": []}]}";

static void expect_relative(double actual, double expected, double tolerance, const char *what)
{
    cr_expect(fabs(actual - expected) <= tolerance * fabs(expected), "%s: %.15g, expected %.15g (relative %.3g)", what,
              actual, expected, fabs(actual - expected) / fabs(expected));
}

static void hold_beam(bool weld_glues)
{
    mu_model_desc *desc = load_model_text(beam_model);
    mu_model_options options = mu_default_model_options();
    options.weld_glues = weld_glues;
    options.weight_index = weld_glues ? 1 : 0;
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    for (int frame = 0; frame < 120; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK);
    }
    /* Masses: the bones' boxes (depth = the smaller extent) and the disc. */
    const double beam = DENSITY * 0.4 * 0.02 * 0.02;
    const double block = DENSITY * 0.02 * 0.08 * 0.02;
    const double weight = weld_glues ? 0.0 : 5.0;
    const mu_joint_load hinge = mu_model_hinge_load(model, 0);
    const double carried = (beam + block + weight) * G;
    expect_relative(hinge.force.y, carried, 1e-9, "hinge reaction force");
    cr_expect(fabs(hinge.force.x) <= 1e-9 * carried, "hinge reaction x: %g N", hinge.force.x);
    /* A nail has the world's axes: along is x, across is y. */
    cr_expect(fabs(hinge.along - hinge.force.x) <= 1e-12 * carried);
    expect_relative(hinge.across, hinge.force.y, 1e-12, "across the wall's frame");
    const double moment = (beam * 0.2 + block * 0.4 + weight * 0.3) * G;
    expect_relative(hinge.torque, moment, 1e-9, "hinge reaction torque");
    cr_expect_eq(hinge.muscle_torque, 0.0);
    const mu_joint_load glue = mu_model_glue_load(model, 0);
    if (weld_glues) {
        /* The block hangs from the weld at its own centre: its weight, no moment. */
        expect_relative(glue.force.y, block * G, 1e-9, "weld reaction force");
        cr_expect(fabs(glue.torque) <= 1e-9 * block * G * 0.4, "weld torque %g N·m", glue.torque);
        /* The beam's axis is x pointing to the block's side: across is up. */
        expect_relative(glue.across, block * G, 1e-9, "weld reaction across the beam");
    } else {
        cr_expect(isnan(glue.force.x) && isnan(glue.torque), "a merged glue carries no joint");
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(joint_loads, a_locked_hinge_carries_the_weight_and_its_moment) { hold_beam(false); }

Test(joint_loads, a_glue_kept_as_a_weld_carries_its_bone) { hold_beam(true); }

/* The bone's axis points from the proximal bone's centre to the joint. */
Test(joint_loads, the_proximal_bone_axis_points_to_the_joint)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK);
    int elbow = -1;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        elbow = strcmp(mu_model_hinge_name(model, h), "Elbow") == 0 ? h : elbow;
    }
    cr_assert_geq(elbow, 0);
    /* The humerus lies along +x, the elbow at its right end. */
    const rb_vec2 axis = mu_model_hinge_bone_axis(model, elbow);
    cr_expect(fabs(axis.x - 1.0) < 1e-12 && fabs(axis.y) < 1e-12, "axis (%g, %g)", axis.x, axis.y);
    cr_expect(isnan(mu_model_hinge_bone_axis(model, 99).x));
    cr_expect(isnan(mu_model_hinge_load(model, -1).force.x));
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The moment about the pivot of the cable's forces on the points that
 * turn with the distal body: at point i, the tension pulls towards each
 * neighbour along the path. */
static double cable_torque(const mu_model *model, int muscle, rb_vec2 pivot, const char *const *distal,
                           int distal_count)
{
    const mu_model_desc *desc = mu_model_description(model);
    const mu_model_muscle *m = &desc->muscles[mu_model_muscle_description_index(model, muscle)];
    const rb_world *world = mu_model_world_to_read(model);
    const rb_cable_id cable = mu_muscle_cable(mu_model_built_muscle(model, muscle));
    rb_vec2 points[RB_MAX_CABLE_POINTS];
    const int count = rb_cable_points(world, cable, points, RB_MAX_CABLE_POINTS);
    const double tension = mu_model_muscle_readout(model, muscle).total_force;
    double torque = 0.0;
    for (int i = 0; i < count; ++i) {
        const char *bone = mu_model_desc_name_of(desc, m->path[i].body);
        bool turns = false;
        for (int d = 0; d < distal_count; ++d) {
            turns = turns || strcmp(bone, distal[d]) == 0;
        }
        if (!turns) {
            continue;
        }
        rb_vec2 force = {0.0, 0.0};
        if (i > 0) {
            force = rb_add(force, rb_scale(tension, rb_normalize(rb_sub(points[i - 1], points[i]))));
        }
        if (i + 1 < count) {
            force = rb_add(force, rb_scale(tension, rb_normalize(rb_sub(points[i + 1], points[i]))));
        }
        torque += rb_cross(rb_sub(points[i], pivot), force);
    }
    return torque;
}

Test(joint_loads, the_muscles_torque_is_the_moment_of_their_cable_forces)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK);
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        cr_assert_eq(mu_model_set_activation_at(model, m, 0.2 + 0.15 * m), RB_OK);
    }
    static const char *const distal[] = {"Ulna",         "Radius",        "Hand",        "Thumb Finger",
                                         "Index Finger", "Middle Finger", "Ring Finger", "Pinky Finger"};
    for (int frame = 0; frame < 30; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK);
        for (int h = 0; h < mu_model_hinge_count(model); ++h) {
            if (strcmp(mu_model_hinge_name(model, h), "Elbow") != 0) {
                continue;
            }
            const rb_vec2 pivot =
                rb_joint_world_anchor_b(mu_model_world_to_read(model), mu_model_hinge_joint(model, h));
            double expected = 0.0, sum = 0.0, scale = 0.0;
            for (int m = 0; m < mu_model_muscle_count(model); ++m) {
                const double torque = cable_torque(model, m, pivot, distal, 8);
                expected += torque;
                scale += fabs(torque);
                sum += mu_model_muscle_torque(model, m, h);
                cr_expect(fabs(mu_model_muscle_torque(model, m, h) - torque) <= 1e-9 * fmax(fabs(torque), 1e-6),
                          "frame %d, %s: F·r %.12g, cable %.12g N·m", frame, mu_model_muscle_name(model, m),
                          mu_model_muscle_torque(model, m, h), torque);
            }
            cr_expect(fabs(sum - expected) <= 1e-9 * scale, "Σ F·r %.12g, cable torque %.12g", sum, expected);
            cr_expect(fabs(mu_model_hinge_load(model, h).muscle_torque - expected) <= 1e-9 * scale);
            cr_expect(fabs(mu_model_hinge_muscle_torque(model, h) - expected) <= 1e-9 * scale);
        }
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The arm at rest, its forearm held by the biceps against gravity and a
 * 1 kg weight: the forearm (one body with the hand, the fingers and the
 * weight) is in equilibrium under the elbow's reaction, the muscles'
 * cable forces and its weight, so the reaction is minus the others' sum
 * and, about the pivot, the muscles' torque balances the weight's moment
 * (the free hinge carries no torque). Both hold to the rest the run
 * reaches (the residual speeds measured below). */
Test(joint_loads, the_forearm_at_rest_balances_its_loads)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    mu_model_options options = mu_default_model_options();
    options.weight_index = 1; /* 1 kg */
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK);
    cr_assert_eq(mu_model_set_activation(model, "Biceps Long", 0.3), RB_OK);
    for (int frame = 0; frame < 600; ++frame) {
        cr_assert_eq(mu_model_step(model), RB_OK);
    }
    int elbow = -1;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        elbow = strcmp(mu_model_hinge_name(model, h), "Elbow") == 0 ? h : elbow;
    }
    const rb_world *world = mu_model_world_to_read(model);
    const rb_joint_id joint = mu_model_hinge_joint(model, elbow);
    const rb_body_id forearm = rb_joint_body_b(world, joint);
    cr_assert_lt(rb_length(rb_body_linear_velocity(world, forearm)), 1e-6, "the forearm is at rest");
    const double angle = mu_model_hinge_angle(model, elbow);
    cr_expect(angle > -10.0 && angle < 150.0, "the elbow rests inside its limits (%g deg)", angle);
    const rb_vec2 pivot = rb_joint_world_anchor_b(world, joint);
    const rb_vec2 weight = rb_scale(rb_body_mass(world, forearm), rb_v2(0.0, -G));
    /* The cable forces on the forearm's points: each pulled towards its neighbours. */
    rb_vec2 cables = {0.0, 0.0};
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        const mu_model_muscle *muscle = &desc->muscles[mu_model_muscle_description_index(model, m)];
        rb_vec2 points[RB_MAX_CABLE_POINTS];
        const int count =
            rb_cable_points(world, mu_muscle_cable(mu_model_built_muscle(model, m)), points, RB_MAX_CABLE_POINTS);
        const double tension = mu_model_muscle_readout(model, m).total_force;
        for (int i = 0; i < count; ++i) {
            const mu_model_ref ref = muscle->path[i].body;
            const int part = ref.kind == MU_MODEL_NAIL ? ref.index : desc->nail_count + ref.index;
            if (!rb_body_id_equals(mu_model_body(model, mu_model_part_body(model, part)), forearm)) {
                continue;
            }
            if (i > 0) {
                cables = rb_mul_add(cables, tension, rb_normalize(rb_sub(points[i - 1], points[i])));
            }
            if (i + 1 < count) {
                cables = rb_mul_add(cables, tension, rb_normalize(rb_sub(points[i + 1], points[i])));
            }
        }
    }
    const mu_joint_load load = mu_model_hinge_load(model, elbow);
    const rb_vec2 expected = rb_neg(rb_add(weight, cables));
    cr_expect(rb_distance(load.force, expected) <= 1e-6 * rb_length(expected),
              "reaction (%.9g, %.9g), expected (%.9g, %.9g) N", load.force.x, load.force.y, expected.x, expected.y);
    const double gravity_moment = rb_cross(rb_sub(rb_body_world_center(world, forearm), pivot), weight);
    cr_expect(fabs(load.muscle_torque + gravity_moment) <= 1e-6 * fabs(gravity_moment),
              "muscles %.9g N·m against the weight's %.9g N·m", load.muscle_torque, gravity_moment);
    cr_expect_eq(load.torque, 0.0, "a free hinge carries no torque");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}
