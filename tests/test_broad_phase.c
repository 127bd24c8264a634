/* SPDX-License-Identifier: MIT */
/* The broad phase (broad_phase.c) against brute force: after every step,
 * the pairs it handed to the narrow phase must be exactly the pairs of
 * shapes whose swept boxes overlap and which may collide, in
 * (body_key, shape_key) order, however the fat boxes were reused; and a
 * pile at rest must stop sweeping. */
#include <string.h>

#include "broad_phase.h"
#include "scenes/scenes.h"
#include "test_support.h"

static int compare_keys(const rb_pair *p, const rb_pair *q)
{
    if (p->body_key != q->body_key) {
        return p->body_key < q->body_key ? -1 : 1;
    }
    return (p->shape_key > q->shape_key) - (p->shape_key < q->shape_key);
}

/* Every pair of live shapes, lower body first, whose swept boxes overlap
 * and which may collide, checked against world->pairs in order. */
static void expect_pairs_match_brute_force(const rb_world *world, int step)
{
    int found = 0;
    for (int i = 0; i < world->shape_slots; ++i) {
        for (int j = i + 1; j < world->shape_slots; ++j) {
            const rb_shape *a = &world->shapes[i];
            const rb_shape *b = &world->shapes[j];
            if (!a->in_use || !b->in_use || !rb_aabb_overlaps(a->aabb, b->aabb) || !rb_should_collide(world, i, j)) {
                continue;
            }
            int body_a = a->body;
            int body_b = b->body;
            int shape_a = i;
            int shape_b = j;
            if (body_a > body_b) {
                body_a = b->body;
                body_b = a->body;
                shape_a = j;
                shape_b = i;
            }
            rb_pair expected = {
                .body_key = ((uint64_t)(uint32_t)body_a << 32) | (uint32_t)body_b,
                .shape_key = ((uint64_t)(uint32_t)shape_a << 32) | (uint32_t)shape_b,
            };
            bool listed = false;
            for (int k = 0; k < world->pair_count; ++k) {
                listed = listed || compare_keys(&world->pairs[k], &expected) == 0;
            }
            cr_assert(listed, "step %d: shapes %d and %d overlap but are not paired", step, shape_a, shape_b);
            ++found;
        }
    }
    cr_assert_eq(world->pair_count, found, "step %d: %d pairs, brute force finds %d", step, world->pair_count, found);
    for (int k = 1; k < world->pair_count; ++k) {
        cr_assert_lt(compare_keys(&world->pairs[k - 1], &world->pairs[k]), 0, "step %d: pairs %d and %d out of order",
                     step, k - 1, k);
    }
}

/* Balls fall into a pile; on the way one is teleported among the others,
 * two are pinned together (a joint forbids its bodies to collide) and
 * freed again, one is made static for a while (two static bodies never
 * collide) and a box is destroyed: after every step the pairs must be
 * brute force's, whether the candidates were found anew or kept. */
Test(broad_phase, pairs_match_brute_force_while_balls_fall_teleport_and_vanish)
{
    rb_world *world = make_world(rb_v2(0.0, -9.81));
    scene_balls balls;
    cr_assert_eq(scene_balls_create(world, 100, 7, &balls), RB_OK, "%s", rb_last_error());
    /* A box of our own above the balls, to destroy on the way. */
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 1.0), 0.0);
    add_box(world, box, 0.05, 0.05, 1.0);
    rb_joint_id pin = {0};
    for (int step = 0; step < 240; ++step) {
        if (step == 100) {
            rb_revolute_joint_def def = rb_default_revolute_joint_def();
            def.body_a = balls.balls[3];
            def.body_b = balls.balls[4];
            def.local_anchor_b = rb_body_local_point(world, balls.balls[4], rb_body_position(world, balls.balls[3]));
            cr_assert_eq(rb_revolute_joint_create(world, &def, &pin), RB_OK, "%s", rb_last_error());
        }
        if (step == 140) {
            cr_assert_eq(rb_joint_destroy(world, pin), RB_OK, "%s", rb_last_error());
        }
        if (step == 120 || step == 180) {
            rb_body_type type = step == 120 ? RB_BODY_STATIC : RB_BODY_DYNAMIC;
            cr_assert_eq(rb_body_set_type(world, balls.balls[5], type), RB_OK, "%s", rb_last_error());
        }
        if (step == 80) {
            /* A teleport lands a ball among the others. */
            cr_assert_eq(rb_body_set_transform(world, balls.balls[0], rb_body_position(world, balls.balls[1]), 0.0),
                         RB_OK, "%s", rb_last_error());
        }
        if (step == 160) {
            cr_assert_eq(rb_body_destroy(world, box), RB_OK, "%s", rb_last_error());
        }
        cr_assert_eq(scene_balls_apply_drag(world, &balls), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
        expect_pairs_match_brute_force(world, step);
    }
    destroy_world_and_expect_no_leak(world);
}

/* A full search cuts the sweep into bands in y as tall as the tallest
 * dynamic box. Here boxes of many sizes, laid out in a 2D grid close
 * enough to touch, drift and spin without gravity past a static pillar
 * that reaches every band and under a floor as wide as the grid, so
 * pairs are found across band borders, with shapes in several bands, by
 * full searches and by searches around single shapes: after every step
 * the pairs must be brute force's. */
Test(broad_phase, pairs_match_brute_force_in_a_drifting_grid_of_boxes_of_many_sizes)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id pillar = make_body(world, RB_BODY_STATIC, rb_v2(4.8, 4.5), 0.0);
    add_box(world, pillar, 0.15, 6.0, 1.0);
    rb_body_id floor = make_body(world, RB_BODY_STATIC, rb_v2(4.5, -1.2), 0.0);
    add_box(world, floor, 6.0, 0.2, 1.0);
    unsigned seed = 12345u;
    for (int row = 0; row < 16; ++row) {
        for (int column = 0; column < 16; ++column) {
            /* A linear congruential generator: sizes 0.1 to 0.5 m, speeds
             * up to 3 m/s and 2 rad/s, the same on every run. */
            double draw[5];
            for (int k = 0; k < 5; ++k) {
                seed = seed * 1664525u + 1013904223u;
                draw[k] = (double)(seed >> 8) / (double)(1u << 24);
            }
            rb_vec2 position = rb_v2(0.6 * column, 0.6 * row);
            rb_body_id box = make_body(world, RB_BODY_DYNAMIC, position, draw[0]);
            add_box(world, box, 0.1 + 0.2 * draw[1], 0.1 + 0.2 * draw[2], 1.0);
            cr_assert_eq(rb_body_set_linear_velocity(world, box, rb_v2(6.0 * (draw[3] - 0.5), 6.0 * (draw[4] - 0.5))),
                         RB_OK, "%s", rb_last_error());
            cr_assert_eq(rb_body_set_angular_velocity(world, box, 4.0 * (draw[1] - 0.5)), RB_OK, "%s", rb_last_error());
        }
    }
    for (int step = 0; step < 120; ++step) {
        step_world(world, TEST_DT, 1);
        expect_pairs_match_brute_force(world, step);
    }
    rb_statistics statistics = rb_world_statistics(world);
    cr_expect_geq(statistics.broad_phase_sweeps, 5, "the drift needed only %d full searches",
                  statistics.broad_phase_sweeps);
    cr_expect_gt(statistics.broad_phase_requeries, 10, "the drift needed only %d searches around single shapes",
                 statistics.broad_phase_requeries);
    destroy_world_and_expect_no_leak(world);
}

/* A world with a base-20 pyramid settled for a second. */
static rb_world *make_resting_pyramid(scene_pyramid *pyramid)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    cr_assert_eq(scene_pyramid_create(world, 20, pyramid), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 60);
    return world;
}

/* Steps once to take in shapes just created (the sweep is rebuilt), then
 * `steps` times with the pairs checked against brute force after each;
 * expects none of those steps to sweep all shapes again, and returns how
 * many searched around single shapes. */
static int step_expecting_only_requeries(rb_world *world, int steps, const char *what)
{
    step_world(world, TEST_DT, 1);
    rb_statistics before = rb_world_statistics(world);
    for (int step = 0; step < steps; ++step) {
        step_world(world, TEST_DT, 1);
        expect_pairs_match_brute_force(world, step);
    }
    rb_statistics after = rb_world_statistics(world);
    cr_expect_eq(after.broad_phase_sweeps, before.broad_phase_sweeps, "%s swept all %d shapes again %d times", what,
                 after.shape_count, after.broad_phase_sweeps - before.broad_phase_sweeps);
    return after.broad_phase_requeries - before.broad_phase_requeries;
}

/* A ball dropped onto a pyramid at rest leaves its fat box nearly every
 * step: only its own candidates are found anew (a search around it), the
 * pyramid's are kept, and the pairs stay brute force's while it falls,
 * lands and comes to rest on the top box. */
Test(broad_phase, a_ball_falling_onto_a_resting_pyramid_is_requeried_alone)
{
    scene_pyramid pyramid;
    rb_world *world = make_resting_pyramid(&pyramid);
    rb_vec2 top = rb_body_position(world, pyramid.top);
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_add(top, rb_v2(0.1, 3.0)), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.25, 1.0);
    int requeries = step_expecting_only_requeries(world, 120, "the fall");
    /* The falling ball outgrows its fat box each time it has fallen
     * about RB_FAT_MARGIN beyond the step's travel the box allowed for:
     * 17 times in a fall of 3 m (47 steps). */
    cr_expect_geq(requeries, 5, "the ball was searched for alone in only %d steps", requeries);
    expect_near(rb_body_position(world, ball).y, top.y + 0.75, 0.02, "the ball resting on the top box");
    destroy_world_and_expect_no_leak(world);
}

/* Balls raining on a pyramid (the rain scene: 20 balls over a base-20
 * pyramid, thrown sideways so that their boxes change places in the
 * sweep's order) leave their fat boxes a few at a time, fewer than one
 * shape in eight: each step finds only their candidates anew, however
 * many of them move at once, and the pairs stay brute force's. */
Test(broad_phase, balls_raining_on_a_pyramid_are_requeried_together)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    scene_rain rain;
    cr_assert_eq(scene_rain_create(world, 20, 20, 3, &rain), RB_OK, "%s", rb_last_error());
    int requeries = step_expecting_only_requeries(world, 90, "the rain");
    cr_expect_geq(requeries, 10, "the balls were searched for alone in only %d steps", requeries);
    destroy_world_and_expect_no_leak(world);
}

Test(broad_phase, the_rain_scene_refuses_bad_arguments)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    scene_rain rain;
    cr_expect_eq(scene_rain_create(world, 20, -1, 3, &rain), RB_ERR_INVALID_ARGUMENT, "a negative ball count");
    cr_expect(strstr(rb_last_error(), "ball_count") != NULL, "the message names the field: %s", rb_last_error());
    cr_expect_eq(scene_rain_create(world, 20, SCENE_RAIN_MAX_BALLS + 1, 3, &rain), RB_ERR_INVALID_ARGUMENT,
                 "too many balls");
    cr_expect_eq(scene_rain_create(world, 0, 10, 3, &rain), RB_ERR_INVALID_ARGUMENT, "no pyramid");
    cr_expect_eq(scene_rain_create(NULL, 20, 10, 3, &rain), RB_ERR_INVALID_ARGUMENT, "no world");
    cr_expect_eq(scene_rain_create(world, 20, 10, 3, NULL), RB_ERR_INVALID_ARGUMENT, "no result");
    cr_expect_eq(rb_world_statistics(world).body_count, 0, "nothing was built");
    destroy_world_and_expect_no_leak(world);
}

/* A pyramid at rest sweeps no more, yet its pairs follow every change of
 * which shapes may collide (steps numbered from 1000 in the messages). */
Test(broad_phase, a_pyramid_at_rest_stops_sweeping)
{
    scene_pyramid pyramid;
    rb_world *world = make_resting_pyramid(&pyramid);
    int sweeps = rb_world_statistics(world).broad_phase_sweeps;
    cr_expect_leq(sweeps, 2, "settling took %d sweeps", sweeps);
    for (int step = 0; step < 60; ++step) {
        step_world(world, TEST_DT, 1);
        expect_pairs_match_brute_force(world, step);
    }
    cr_expect_eq(rb_world_statistics(world).broad_phase_sweeps, sweeps, "the pyramid at rest swept again");

    /* Nothing moves, so only a change of which shapes may collide can
     * make the pairs change: pinning the first two boxes of the bottom
     * row together, freeing them, then making the first one static (it
     * rests on the static ground). */
    rb_body_id first = scene_body_at(pyramid.first_box, 0);
    rb_body_id second = scene_body_at(pyramid.first_box, 1);
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    def.body_a = first;
    def.body_b = second;
    def.local_anchor_a = rb_v2(0.5, 0.0);
    def.local_anchor_b = rb_v2(-0.5, 0.0);
    rb_joint_id pin;
    cr_assert_eq(rb_revolute_joint_create(world, &def, &pin), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 1);
    expect_pairs_match_brute_force(world, 1000);
    cr_assert_eq(rb_joint_destroy(world, pin), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 1);
    expect_pairs_match_brute_force(world, 1001);
    cr_assert_eq(rb_body_set_type(world, first, RB_BODY_STATIC), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 1);
    expect_pairs_match_brute_force(world, 1002);
    destroy_world_and_expect_no_leak(world);
}

/* The contacts, one for each pair and in its order, after step `step`. */
static void expect_contacts_follow_pairs(const rb_world *world, int step)
{
    cr_assert_eq(world->contact_count, world->pair_count, "step %d: %d contacts for %d pairs", step,
                 world->contact_count, world->pair_count);
    for (int i = 0; i < world->pair_count; ++i) {
        cr_assert_eq(compare_keys(&world->contacts[i].pair, &world->pairs[i]), 0,
                     "step %d: contact %d is not the pair's (shapes %d, %d against %d, %d)", step, i,
                     world->contacts[i].pair.shape_a, world->contacts[i].pair.shape_b, world->pairs[i].shape_a,
                     world->pairs[i].shape_b);
    }
}

/* A pyramid at rest keeps its contacts where they are: the step finds
 * the same pairs and does not merge them with the contacts again (the
 * merge writes the contacts to the other of its two arrays, so an array
 * that stays put is one that was not merged). A ball dropped on it, a
 * box destroyed and made again in its slots, and a box taken out of it,
 * and the contacts follow the pairs. */
Test(broad_phase, a_pyramid_at_rest_keeps_its_contacts_in_place)
{
    scene_pyramid pyramid;
    rb_world *world = make_resting_pyramid(&pyramid);
    step_world(world, TEST_DT, 1);
    const rb_contact *contacts = world->contacts;
    for (int step = 0; step < 30; ++step) {
        step_world(world, TEST_DT, 1);
        cr_expect(!world->pairs_changed, "step %d: the pairs of the pyramid at rest changed", step);
        cr_expect_eq(world->contacts, contacts, "step %d: the contacts were merged again", step);
        expect_contacts_follow_pairs(world, step);
    }

    rb_vec2 top = rb_body_position(world, pyramid.top);
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_add(top, rb_v2(0.1, 1.5)), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.25, 1.0);
    int changes = 0;
    for (int step = 100; step < 160; ++step) {
        step_world(world, TEST_DT, 1);
        changes += world->pairs_changed;
        expect_pairs_match_brute_force(world, step);
        expect_contacts_follow_pairs(world, step);
    }
    cr_expect_geq(changes, 1, "the ball's landing changed no pair");
    expect_near(rb_body_position(world, ball).y, top.y + 0.75, 0.02, "the ball resting on the top box");

    /* The top box destroyed and made again in its place before the next
     * step: the new body and shape take the old ones' slots, so the
     * pairs are the last step's, but the old box's contacts went with it
     * and the new one's must be made. */
    rb_vec2 where = rb_body_position(world, pyramid.top);
    cr_assert_eq(rb_body_destroy(world, pyramid.top), RB_OK, "%s", rb_last_error());
    rb_body_id again = make_body(world, RB_BODY_DYNAMIC, where, 0.0);
    add_box(world, again, 0.5, 0.5, 1.0);
    step_world(world, TEST_DT, 1);
    cr_expect(!world->pairs_changed, "the new box took the old one's slots and pairs");
    expect_pairs_match_brute_force(world, 200);
    expect_contacts_follow_pairs(world, 200);

    /* A box of the bottom row destroyed: its contacts go with it. */
    cr_assert_eq(rb_body_destroy(world, scene_body_at(pyramid.first_box, 0)), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 1);
    expect_pairs_match_brute_force(world, 201);
    expect_contacts_follow_pairs(world, 201);
    destroy_world_and_expect_no_leak(world);
}
