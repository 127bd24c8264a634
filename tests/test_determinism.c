/* SPDX-License-Identifier: MIT */
/* Determinism: a scene run twice gives bit-identical states, and the state
 * of a reference run matches a stored hash, so any change to the
 * simulation's arithmetic shows up here. */
#include <stdint.h>
#include <string.h>

#include "scenes/scenes.h"
#include "test_support.h"

#define PYRAMID_BASE 20
#define PYRAMID_BOXES (PYRAMID_BASE * (PYRAMID_BASE + 1) / 2)
#define PYRAMID_STEPS 120
#define BALL_COUNT 50
#define BALL_SEED 2024
#define BALL_STEPS 120

/* rb_world_state_hash of the base-20 pyramid after 120 steps of 1/60 s with
 * the default world definition (gravity (0, -9.8), default solver
 * settings). Obtained by running this test once and copying the value its
 * failure message printed (the release and the ASan builds print the same
 * value). It must change only with a deliberate change to the solver, the
 * integrator or the scene, recorded again the same way in the same commit
 * with a note saying why. Last recorded when the contact constraints
 * began to be solved colour by colour (constraint_colouring.c), the
 * sequential passes sweeping forward and backward in turn: the order of
 * the sweeps changed, so the rounding did. */
#define PYRAMID_REFERENCE_HASH UINT64_C(0x32ff693240599060)

/* The final state of a run: the hash and every moving body's pose. */
typedef struct run_state {
    uint64_t hash;
    int count;
    rb_vec2 positions[PYRAMID_BOXES > BALL_COUNT ? PYRAMID_BOXES : BALL_COUNT];
    double angles[PYRAMID_BOXES > BALL_COUNT ? PYRAMID_BOXES : BALL_COUNT];
} run_state;

static void record_body(const rb_world *world, rb_body_id body, run_state *state)
{
    cr_assert(rb_body_is_valid(world, body), "body %d of the run is not valid", state->count);
    state->positions[state->count] = rb_body_position(world, body);
    state->angles[state->count] = rb_body_angle(world, body);
    state->count++;
}

static void run_pyramid(run_state *state)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, PYRAMID_BASE, &pyramid), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, PYRAMID_STEPS);
    state->hash = rb_world_state_hash(world);
    state->count = 0;
    for (int k = 0; k < pyramid.box_count; ++k) {
        record_body(world, scene_body_at(pyramid.first_box, k), state);
    }
    destroy_world_and_expect_no_leak(world);
}

static void run_balls(run_state *state)
{
    /* scenes.h: the caller sets gravity (0, -9.81) and applies the drag
     * before every step. */
    rb_world *world = make_world(rb_v2(0.0, -9.81));
    scene_balls balls;
    cr_assert_eq(scene_balls_create(world, BALL_COUNT, BALL_SEED, &balls), RB_OK, "%s", rb_last_error());
    for (int n = 0; n < BALL_STEPS; ++n) {
        cr_assert_eq(scene_balls_apply_drag(world, &balls), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
    }
    state->hash = rb_world_state_hash(world);
    state->count = 0;
    for (int k = 0; k < balls.count; ++k) {
        record_body(world, balls.balls[k], state);
    }
    destroy_world_and_expect_no_leak(world);
}

static void expect_identical(const run_state *first, const run_state *second)
{
    cr_expect_eq(first->hash, second->hash, "state hashes differ: %016llx and %016llx", (unsigned long long)first->hash,
                 (unsigned long long)second->hash);
    cr_assert_eq(first->count, second->count, "the runs have different body counts");
    for (int k = 0; k < first->count; ++k) {
        cr_expect(memcmp(&first->positions[k], &second->positions[k], sizeof first->positions[k]) == 0 &&
                      memcmp(&first->angles[k], &second->angles[k], sizeof first->angles[k]) == 0,
                  "body %d: (%.17g, %.17g, %.17g) in one run, (%.17g, %.17g, %.17g) in the other", k,
                  first->positions[k].x, first->positions[k].y, first->angles[k], second->positions[k].x,
                  second->positions[k].y, second->angles[k]);
    }
}

/* The run states are large; static keeps them off the stack. */
static run_state first_run, second_run;

Test(determinism, pyramid_runs_are_bit_identical)
{
    run_pyramid(&first_run);
    run_pyramid(&second_run);
    expect_identical(&first_run, &second_run);
}

Test(determinism, balls_runs_are_bit_identical)
{
    run_balls(&first_run);
    run_balls(&second_run);
    expect_identical(&first_run, &second_run);
}

Test(determinism, pyramid_matches_the_stored_hash)
{
    run_pyramid(&first_run);
    cr_expect_eq(first_run.hash, PYRAMID_REFERENCE_HASH,
                 "pyramid state hash after %d steps is 0x%016llx, stored 0x%016llx: the simulation changed",
                 PYRAMID_STEPS, (unsigned long long)first_run.hash, (unsigned long long)PYRAMID_REFERENCE_HASH);
}

/* The hash must see every part of the state it covers: two worlds that
 * differ by one unit in the last place of one number hash differently. */
Test(determinism, hash_sees_a_one_ulp_change)
{
    rb_world *worlds[2];
    rb_body_id bodies[2];
    for (int w = 0; w < 2; ++w) {
        worlds[w] = make_world(rb_default_world_def().gravity);
        bodies[w] = make_body(worlds[w], RB_BODY_DYNAMIC, rb_v2(1.0, 2.0), 0.5);
        add_circle(worlds[w], bodies[w], rb_v2(0.0, 0.0), 0.5, 1.0);
        cr_assert_eq(rb_body_set_linear_velocity(worlds[w], bodies[w], rb_v2(3.0, -4.0)), RB_OK, "%s", rb_last_error());
        cr_assert_eq(rb_body_set_angular_velocity(worlds[w], bodies[w], 0.25), RB_OK, "%s", rb_last_error());
    }
    cr_assert_eq(rb_world_state_hash(worlds[0]), rb_world_state_hash(worlds[1]), "equal states hash equally");

    const uint64_t same = rb_world_state_hash(worlds[0]);
    cr_assert_eq(rb_body_set_transform(worlds[1], bodies[1], rb_v2(nextafter(1.0, 2.0), 2.0), 0.5), RB_OK, "%s",
                 rb_last_error());
    cr_expect_neq(rb_world_state_hash(worlds[1]), same, "a one-ulp change of x is not hashed");
    cr_assert_eq(rb_body_set_transform(worlds[1], bodies[1], rb_v2(1.0, 2.0), nextafter(0.5, 1.0)), RB_OK, "%s",
                 rb_last_error());
    cr_expect_neq(rb_world_state_hash(worlds[1]), same, "a one-ulp change of the angle is not hashed");
    cr_assert_eq(rb_body_set_transform(worlds[1], bodies[1], rb_v2(1.0, 2.0), 0.5), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_linear_velocity(worlds[1], bodies[1], rb_v2(3.0, nextafter(-4.0, 0.0))), RB_OK, "%s",
                 rb_last_error());
    cr_expect_neq(rb_world_state_hash(worlds[1]), same, "a one-ulp change of the velocity is not hashed");
    cr_assert_eq(rb_body_set_linear_velocity(worlds[1], bodies[1], rb_v2(3.0, -4.0)), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_angular_velocity(worlds[1], bodies[1], nextafter(0.25, 1.0)), RB_OK, "%s",
                 rb_last_error());
    cr_expect_neq(rb_world_state_hash(worlds[1]), same, "a one-ulp change of ω is not hashed");
    cr_assert_eq(rb_body_set_angular_velocity(worlds[1], bodies[1], 0.25), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_world_state_hash(worlds[1]), same, "the state restored, the hash is back");

    rb_world_destroy(worlds[0]);
    destroy_world_and_expect_no_leak(worlds[1]);
}
