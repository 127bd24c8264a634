/* SPDX-License-Identifier: MIT */
/* The broad phase (broad_phase.c) against brute force: after every step,
 * the contacts must be exactly the pairs of shapes whose fat boxes
 * overlap and which may collide, in (body_key, shape_key) order, however
 * they were found; the pairs the step reports as begun and ended must be
 * the difference brute force finds between the contacts before and after
 * it; and a pile at rest must cost the broad phase nothing. */
#include <stdlib.h>
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

static int compare_key_pointers(const void *p, const void *q) { return compare_keys(p, q); }

/* The pairs in `pairs` (count, sorted) that are not in `others`. */
static int count_missing(const rb_pair *pairs, int count, const rb_pair *others, int other_count)
{
    int missing = 0;
    for (int i = 0, j = 0; i < count; ++i) {
        while (j < other_count && compare_keys(&others[j], &pairs[i]) < 0) {
            ++j;
        }
        missing += j < other_count && compare_keys(&others[j], &pairs[i]) == 0 ? 0 : 1;
    }
    return missing;
}

/* A copy of the contacts' pairs, in their order (free it). */
static rb_pair *contact_pairs(const rb_world *world)
{
    rb_pair *pairs = malloc(sizeof *pairs * (size_t)(world->contact_count + 1));
    cr_assert_not_null(pairs);
    for (int i = 0; i < world->contact_count; ++i) {
        pairs[i] = world->contacts[i].pair;
    }
    return pairs;
}

/* Every pair of live shapes, lower body first, whose fat boxes overlap
 * and which may collide, sorted: O(n²) box tests (free it). */
static rb_pair *brute_force_pairs(const rb_world *world, int *count)
{
    int capacity = 64;
    rb_pair *pairs = malloc(sizeof *pairs * (size_t)capacity);
    cr_assert_not_null(pairs);
    *count = 0;
    for (int i = 0; i < world->shape_slots; ++i) {
        for (int j = i + 1; j < world->shape_slots; ++j) {
            const rb_shape *a = &world->shapes[i];
            const rb_shape *b = &world->shapes[j];
            if (!a->in_use || !b->in_use || !rb_aabb_overlaps(a->fat_aabb, b->fat_aabb) ||
                !rb_should_collide(world, i, j)) {
                continue;
            }
            bool swap = a->body > b->body;
            int body_a = swap ? b->body : a->body;
            int body_b = swap ? a->body : b->body;
            int shape_a = swap ? j : i;
            int shape_b = swap ? i : j;
            if (*count == capacity) {
                capacity *= 2;
                pairs = realloc(pairs, sizeof *pairs * (size_t)capacity);
                cr_assert_not_null(pairs);
            }
            pairs[(*count)++] = (rb_pair){
                .body_key = ((uint64_t)(uint32_t)body_a << 32) | (uint32_t)body_b,
                .shape_key = ((uint64_t)(uint32_t)shape_a << 32) | (uint32_t)shape_b,
                .shape_a = shape_a,
                .shape_b = shape_b,
            };
        }
    }
    qsort(pairs, (size_t)*count, sizeof *pairs, compare_key_pointers);
    return pairs;
}

/* Checks the contacts after step `step` against brute force: the same
 * pairs in the same order, every shape's swept box inside its fat box,
 * and the step's begun and ended pairs the difference with `before`
 * (the contacts' pairs before the step). */
static void expect_contacts_match_brute_force(const rb_world *world, int step, const rb_pair *before, int before_count)
{
    int count = 0;
    rb_pair *expected = brute_force_pairs(world, &count);
    for (int i = 0; i < world->shape_slots; ++i) {
        const rb_shape *shape = &world->shapes[i];
        cr_assert(
            !shape->in_use || world->sweep_count == 0 ||
                (shape->fat_aabb.lower.x <= shape->aabb.lower.x && shape->fat_aabb.lower.y <= shape->aabb.lower.y &&
                 shape->aabb.upper.x <= shape->fat_aabb.upper.x && shape->aabb.upper.y <= shape->fat_aabb.upper.y),
            "step %d: shape %d's swept box is outside its fat box", step, i);
    }
    for (int i = 0; i < count && i < world->contact_count; ++i) {
        cr_assert_eq(compare_keys(&world->contacts[i].pair, &expected[i]), 0,
                     "step %d: contact %d is shapes %d, %d, brute force's pair %d is shapes %d, %d", step, i,
                     world->contacts[i].pair.shape_a, world->contacts[i].pair.shape_b, i, expected[i].shape_a,
                     expected[i].shape_b);
    }
    cr_assert_eq(world->contact_count, count, "step %d: %d contacts, brute force finds %d pairs", step,
                 world->contact_count, count);
    rb_statistics statistics = rb_world_statistics(world);
    int begun = count_missing(expected, count, before, before_count);
    int ended = count_missing(before, before_count, expected, count);
    cr_assert_eq(statistics.broad_phase_new_pairs, begun, "step %d: %d pairs reported begun, brute force finds %d",
                 step, statistics.broad_phase_new_pairs, begun);
    cr_assert_eq(statistics.broad_phase_ended_pairs, ended, "step %d: %d pairs reported ended, brute force finds %d",
                 step, statistics.broad_phase_ended_pairs, ended);
    free(expected);
}

/* One step, checked against brute force. */
static void step_and_check(rb_world *world, int step)
{
    int before_count = world->contact_count;
    rb_pair *before = contact_pairs(world);
    step_world(world, TEST_DT, 1);
    expect_contacts_match_brute_force(world, step, before, before_count);
    free(before);
}

/* Balls fall into a pile; on the way one is teleported among the others,
 * two are pinned together (a joint forbids its bodies to collide) and
 * freed again, one is made static for a while (two static bodies never
 * collide), one stops colliding with anything for a while (its filter)
 * and a box is destroyed: after every step the contacts must be brute
 * force's, whether the pairs were found anew or around moved shapes. */
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
        if (step == 200 || step == 220) {
            rb_shape_id shape;
            cr_assert_eq(rb_body_shapes(world, balls.balls[6], &shape, 1), 1, "%s", rb_last_error());
            rb_filter filter = rb_default_filter();
            filter.mask_bits = step == 200 ? 0u : filter.mask_bits;
            cr_assert_eq(rb_shape_set_filter(world, shape, filter), RB_OK, "%s", rb_last_error());
        }
        cr_assert_eq(scene_balls_apply_drag(world, &balls), RB_OK, "%s", rb_last_error());
        step_and_check(world, step);
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
    int begun = 0;
    int ended = 0;
    for (int step = 0; step < 120; ++step) {
        step_and_check(world, step);
        begun += rb_world_statistics(world).broad_phase_new_pairs;
        ended += rb_world_statistics(world).broad_phase_ended_pairs;
    }
    cr_expect_gt(begun, 100, "only %d pairs began in the drift", begun);
    cr_expect_gt(ended, 100, "only %d pairs ended in the drift", ended);
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
        step_and_check(world, step);
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

/* A pyramid at rest sweeps no more, yet its contacts follow every change
 * of which shapes may collide (steps numbered from 1000 in the messages). */
Test(broad_phase, a_pyramid_at_rest_stops_sweeping)
{
    scene_pyramid pyramid;
    rb_world *world = make_resting_pyramid(&pyramid);
    int sweeps = rb_world_statistics(world).broad_phase_sweeps;
    cr_expect_leq(sweeps, 2, "settling took %d sweeps", sweeps);
    for (int step = 0; step < 60; ++step) {
        step_and_check(world, step);
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
    step_and_check(world, 1000);
    cr_assert_eq(rb_joint_destroy(world, pin), RB_OK, "%s", rb_last_error());
    step_and_check(world, 1001);
    cr_assert_eq(rb_body_set_type(world, first, RB_BODY_STATIC), RB_OK, "%s", rb_last_error());
    step_and_check(world, 1002);
    destroy_world_and_expect_no_leak(world);
}

/* A pyramid at rest costs the broad phase nothing beyond the boxes of
 * its shapes: no shape leaves its fat box, so none is searched around,
 * no box is compared with another, no pair begins or ends, and the
 * contacts are not copied (a merge writes them to the other of its two
 * arrays, so an array that stays put is one that was not merged). A ball
 * dropped on it is searched around alone: its pairs, and only those,
 * begin as it lands (brute force checks it at every step), and the
 * pyramid's cost nothing again once it rests. A box destroyed and made
 * again in its slots, and a box taken out, and the contacts follow. */
Test(broad_phase, a_pyramid_at_rest_costs_the_broad_phase_nothing)
{
    scene_pyramid pyramid;
    rb_world *world = make_resting_pyramid(&pyramid);
    step_world(world, TEST_DT, 1);
    const rb_contact *contacts = world->contacts;
    for (int step = 0; step < 30; ++step) {
        step_and_check(world, step);
        rb_statistics statistics = rb_world_statistics(world);
        cr_expect_eq(statistics.broad_phase_moved, 0, "step %d: %d shapes moved in the pyramid at rest", step,
                     statistics.broad_phase_moved);
        cr_expect_eq(statistics.broad_phase_box_tests, 0, "step %d: %d box tests in the pyramid at rest", step,
                     statistics.broad_phase_box_tests);
        cr_expect_eq(world->contacts, contacts, "step %d: the contacts were merged again", step);
    }

    rb_vec2 top = rb_body_position(world, pyramid.top);
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_add(top, rb_v2(0.1, 1.5)), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.25, 1.0);
    step_and_check(world, 99); /* the new shape: a full search */
    int begun = 0;
    int most_moved = 0;
    for (int step = 100; step < 160; ++step) {
        step_and_check(world, step);
        rb_statistics statistics = rb_world_statistics(world);
        begun += statistics.broad_phase_new_pairs;
        most_moved = statistics.broad_phase_moved > most_moved ? statistics.broad_phase_moved : most_moved;
    }
    cr_expect_geq(begun, 1, "the ball's landing began no pair");
    cr_expect_eq(most_moved, 1, "up to %d shapes moved at once, where only the ball falls", most_moved);
    expect_near(rb_body_position(world, ball).y, top.y + 0.75, 0.02, "the ball resting on the top box");
    for (int step = 160; step < 190; ++step) {
        step_and_check(world, step);
        cr_expect_eq(rb_world_statistics(world).broad_phase_box_tests, 0, "step %d: box tests with the ball at rest",
                     step);
    }

    /* The top box destroyed and made again in its place before the next
     * step: the new body and shape take the old ones' slots, but the old
     * box's contacts went with it and the new one's must be made. */
    rb_vec2 where = rb_body_position(world, pyramid.top);
    cr_assert_eq(rb_body_destroy(world, pyramid.top), RB_OK, "%s", rb_last_error());
    rb_body_id again = make_body(world, RB_BODY_DYNAMIC, where, 0.0);
    add_box(world, again, 0.5, 0.5, 1.0);
    step_and_check(world, 200);

    /* A box of the bottom row destroyed: its contacts go with it. */
    cr_assert_eq(rb_body_destroy(world, scene_body_at(pyramid.first_box, 0)), RB_OK, "%s", rb_last_error());
    step_and_check(world, 201);
    destroy_world_and_expect_no_leak(world);
}

/* Expects every shape of a sleeping or static body to have the swept box
 * a body at rest gets: its tight box grown by the speculative margin alone, exactly
 * as if it had been made in the last step. */
static void expect_sleeping_boxes_fresh(const rb_world *world, const char *when)
{
    double margin = RB_SPECULATIVE_SLOPS * world->settings.linear_slop;
    for (int i = 0; i < world->shape_slots; ++i) {
        const rb_shape *shape = &world->shapes[i];
        const rb_body *body = &world->bodies[shape->body];
        if (!shape->in_use || (body->awake && body->type != RB_BODY_STATIC)) {
            continue;
        }
        rb_aabb tight = rb_shape_tight_aabb(world, i);
        bool fresh = shape->aabb.lower.x == tight.lower.x - margin && shape->aabb.lower.y == tight.lower.y - margin &&
                     shape->aabb.upper.x == tight.upper.x + margin && shape->aabb.upper.y == tight.upper.y + margin;
        cr_assert(fresh, "%s: shape %d of a body at rest has a stale swept box", when, i);
    }
}

/* A pyramid asleep costs the broad phase nothing at all: the swept boxes
 * of bodies that stand still are not made again, yet stay exactly what
 * they would be. A box moved in its sleep (placed, not woken) gets its
 * boxes and contacts anew. */
Test(broad_phase, a_pyramid_asleep_makes_no_box)
{
    scene_pyramid pyramid;
    rb_world *world = make_resting_pyramid(&pyramid);
    int steps = 0;
    for (; steps < 600 && rb_world_statistics(world).awake_body_count > 0; ++steps) {
        step_world(world, TEST_DT, 1);
    }
    cr_assert_eq(rb_world_statistics(world).awake_body_count, 0, "the pyramid is still awake after %d steps", steps);
    step_world(world, TEST_DT, 1); /* the boxes made once more at rest */
    for (int step = 0; step < 30; ++step) {
        step_and_check(world, step);
        rb_statistics statistics = rb_world_statistics(world);
        cr_expect_eq(statistics.broad_phase_boxes, 0, "step %d: %d swept boxes made for a pyramid asleep", step,
                     statistics.broad_phase_boxes);
        cr_expect_eq(statistics.broad_phase_box_tests, 0, "step %d: %d box tests for a pyramid asleep", step,
                     statistics.broad_phase_box_tests);
        expect_sleeping_boxes_fresh(world, "asleep");
    }

    /* The top box placed half a box to the side, asleep. */
    rb_vec2 top = rb_body_position(world, pyramid.top);
    cr_assert_eq(rb_body_set_transform(world, pyramid.top, rb_add(top, rb_v2(0.5, 0.0)), 0.0), RB_OK, "%s",
                 rb_last_error());
    cr_assert(!rb_body_is_awake(world, pyramid.top), "placing the box woke it");
    step_and_check(world, 100);
    cr_expect_gt(rb_world_statistics(world).broad_phase_boxes, 0, "no box made after the top box was placed");
    expect_sleeping_boxes_fresh(world, "placed");
    destroy_world_and_expect_no_leak(world);
}

/* Balls bouncing without gravity in a closed box, with no friction and
 * full restitution, meet and part for ever: pairs begin and end in every
 * second. Once the arrays have grown to what such a scene needs, a step
 * allocates nothing: rb_allocation_count() counts every allocation the
 * engine makes, through its one allocator. */
Test(broad_phase, steps_that_begin_and_end_pairs_allocate_nothing)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id walls = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    const double half = 3.0;
    const rb_vec2 wall_centres[4] = {{0.0, -half}, {0.0, half}, {-half, 0.0}, {half, 0.0}};
    for (int w = 0; w < 4; ++w) {
        rb_polygon wall;
        cr_assert_eq(
            rb_make_offset_box(w < 2 ? half + 0.2 : 0.2, w < 2 ? 0.2 : half + 0.2, wall_centres[w], 0.0, &wall), RB_OK,
            "%s", rb_last_error());
        rb_shape_def def = rb_default_shape_def();
        rb_shape_id shape;
        cr_assert_eq(rb_shape_create_polygon(world, walls, &def, &wall, &shape), RB_OK, "%s", rb_last_error());
    }
    unsigned seed = 2026u;
    for (int i = 0; i < 80; ++i) {
        double draw[2];
        for (int k = 0; k < 2; ++k) {
            seed = seed * 1664525u + 1013904223u;
            draw[k] = (double)(seed >> 8) / (double)(1u << 24) - 0.5;
        }
        rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.6 * (i % 9) - 2.4, 0.6 * (i / 9) - 2.4), 0.0);
        rb_shape_def def = rb_default_shape_def();
        def.friction = 0.0;
        def.restitution = 1.0;
        rb_circle circle = {rb_v2(0.0, 0.0), 0.15};
        rb_shape_id shape;
        cr_assert_eq(rb_shape_create_circle(world, ball, &def, &circle, &shape), RB_OK, "%s", rb_last_error());
        cr_assert_eq(rb_body_set_linear_velocity(world, ball, rb_v2(8.0 * draw[0], 8.0 * draw[1])), RB_OK, "%s",
                     rb_last_error());
    }
    step_world(world, TEST_DT, 1200); /* the arrays grow to what the scene needs */
    const uint64_t allocations = rb_allocation_count();
    int begun = 0;
    int ended = 0;
    for (int step = 0; step < 600; ++step) {
        step_world(world, TEST_DT, 1);
        begun += rb_world_statistics(world).broad_phase_new_pairs;
        ended += rb_world_statistics(world).broad_phase_ended_pairs;
    }
    cr_expect_eq(rb_allocation_count(), allocations, "%llu allocations in 600 steps",
                 (unsigned long long)(rb_allocation_count() - allocations));
    cr_expect_gt(begun, 100, "only %d pairs began", begun);
    cr_expect_gt(ended, 100, "only %d pairs ended", ended);
    destroy_world_and_expect_no_leak(world);
}

/* The peers' swinging chain (40 links, a box of 100 times a link's mass at
 * its end, released horizontally) sweeps through new heights as it swings,
 * so its boxes cross the edges of the sweep's bands and fall into two
 * bands, then one, from step to step. After a second, when the arrays have
 * grown to what the scene needs, a step allocates nothing. */
Test(broad_phase, a_swinging_chain_crossing_bands_allocates_nothing)
{
    rb_world *world = make_world(rb_v2(0.0, -9.81));
    scene_chain chain;
    cr_assert_eq(scene_chain_create(world, 40, 20.0, SCENE_CHAIN_SWING, &chain), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 60);
    const uint64_t allocations = rb_allocation_count();
    step_world(world, TEST_DT, 600);
    cr_expect_eq(rb_allocation_count(), allocations, "%llu allocations in 600 steps",
                 (unsigned long long)(rb_allocation_count() - allocations));
    destroy_world_and_expect_no_leak(world);
}

/* The sweep is kept sorted by insertion, which gives up past eight
 * shifts an entry and heapsorts instead. Boxes made from right to left
 * come into the sweep in the reverse of its order, n·(n - 1)/2 shifts for
 * n of them (1,770 for 60, against 480 allowed), so the first full search
 * heapsorts the whole sweep, swapping its 40-byte entries. Each entry
 * must then hold its own shape's fat box, in strictly increasing
 * (lower x, shape) order, and the pairs must be brute force's. */
Test(broad_phase, a_sweep_made_in_reverse_is_heapsorted_whole)
{
    enum { BOXES = 60 };
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    for (int k = 0; k < BOXES; ++k) {
        /* 0.3 m apart, 0.4 m wide, alternately 0.1 m up and down: every
         * box overlaps its neighbours. */
        rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.3 * (BOXES - 1 - k), 0.1 * (k % 2)), 0.0);
        add_box(world, body, 0.2, 0.2, 1.0);
    }
    step_and_check(world, 0);
    cr_assert_eq(world->sweep_count, BOXES, "every box is in the sweep");
    for (int k = 0; k < world->sweep_count; ++k) {
        const struct rb_sweep_entry *entry = &world->sweep[k];
        const rb_aabb fat = world->shapes[entry->shape].fat_aabb;
        cr_assert(entry->box.lower.x == fat.lower.x && entry->box.lower.y == fat.lower.y &&
                      entry->box.upper.x == fat.upper.x && entry->box.upper.y == fat.upper.y,
                  "entry %d holds shape %d's fat box", k, entry->shape);
        if (k > 0) {
            const struct rb_sweep_entry *before = &world->sweep[k - 1];
            cr_assert(before->box.lower.x < entry->box.lower.x ||
                          (before->box.lower.x == entry->box.lower.x && before->shape < entry->shape),
                      "entries %d and %d (shapes %d, %d) are out of order", k - 1, k, before->shape, entry->shape);
        }
    }
    cr_assert_gt(world->contact_count, BOXES - 2, "neighbours overlap: %d pairs", world->contact_count);
    destroy_world_and_expect_no_leak(world);
}
