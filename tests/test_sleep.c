/* SPDX-License-Identifier: MIT */
/* Islands and sleeping: resting islands fall asleep after 0.5 s below
 * the tolerances (1 cm/s, 2 degrees/s), stay exactly where they are, and
 * wake together when touched, pushed, jointed or asked.
 */
#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"
#include "test_support.h"

#define STACK_HEIGHT 5

typedef struct stack {
    rb_body_id boxes[STACK_HEIGHT];
} stack;

/* Unit boxes (half-extent 0.5 m) resting on each other on the ground at x. */
static stack make_stack(rb_world *world, double x)
{
    stack s;
    for (int i = 0; i < STACK_HEIGHT; ++i) {
        s.boxes[i] = make_body(world, RB_BODY_DYNAMIC, rb_v2(x, 0.5 + i), 0.0);
        add_box(world, s.boxes[i], 0.5, 0.5, 1.0);
    }
    return s;
}

static rb_world *world_with_ground(void)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, -1.0), 0.0);
    add_box(world, ground, 50.0, 1.0, 0.0);
    return world;
}

static int awake_count(const rb_world *world, const stack *s)
{
    int awake = 0;
    for (int i = 0; i < STACK_HEIGHT; ++i) {
        awake += rb_body_is_awake(world, s->boxes[i]);
    }
    return awake;
}

Test(sleep, a_resting_stack_falls_asleep_after_half_a_second_and_stays_put)
{
    rb_world *world = world_with_ground();
    stack s = make_stack(world, 0.0);
    step_world(world, TEST_DT, 24);
    cr_expect_eq(awake_count(world, &s), STACK_HEIGHT, "0.4 s at rest is not enough to sleep");
    step_world(world, TEST_DT, 36);
    cr_expect_eq(awake_count(world, &s), 0, "after 1 s at rest every box sleeps");
    rb_statistics stats = rb_world_statistics(world);
    cr_expect_eq(stats.awake_body_count, 0);
    cr_expect_eq(stats.island_count, 1, "the boxes touch: one island");
    rb_vec2 before[STACK_HEIGHT];
    for (int i = 0; i < STACK_HEIGHT; ++i) {
        before[i] = rb_body_position(world, s.boxes[i]);
        cr_expect_eq(rb_body_linear_velocity(world, s.boxes[i]).y, 0.0);
    }
    step_world(world, TEST_DT, 120);
    for (int i = 0; i < STACK_HEIGHT; ++i) {
        rb_vec2 after = rb_body_position(world, s.boxes[i]);
        cr_expect(after.x == before[i].x && after.y == before[i].y, "box %d moved while asleep", i);
    }
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, a_dropped_ball_wakes_the_whole_stack_in_the_step_it_lands)
{
    rb_world *world = world_with_ground();
    stack s = make_stack(world, 0.0);
    step_world(world, TEST_DT, 60);
    cr_assert_eq(awake_count(world, &s), 0);
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, STACK_HEIGHT + 1.0), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.25, 1.0);
    int landed = -1;
    for (int n = 1; n <= 60 && landed < 0; ++n) {
        step_world(world, TEST_DT, 1);
        cr_expect(awake_count(world, &s) == 0 || awake_count(world, &s) == STACK_HEIGHT,
                  "step %d: %d of the boxes are awake, the island wakes whole", n, awake_count(world, &s));
        if (awake_count(world, &s) == STACK_HEIGHT) {
            landed = n;
        }
    }
    /* It falls 0.75 m to the top box: sqrt(2·0.75/9.8) = 0.39 s, step 24. */
    cr_expect(landed >= 20 && landed <= 26, "the stack woke at step %d", landed);
    step_world(world, TEST_DT, 300);
    cr_expect_eq(awake_count(world, &s), 0, "the stack and the ball sleep again");
    cr_expect(!rb_body_is_awake(world, ball));
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, a_force_on_the_bottom_box_wakes_its_island_before_the_solve)
{
    rb_world *world = world_with_ground();
    stack s = make_stack(world, 0.0);
    step_world(world, TEST_DT, 60);
    cr_assert_eq(awake_count(world, &s), 0);
    rb_vec2 top_before = rb_body_position(world, s.boxes[STACK_HEIGHT - 1]);
    /* Lift the bottom box with 3 times the stack's weight: the whole
     * stack must rise with it (a box left asleep above would act as static
     * and the bottom box would be pushed into it). */
    cr_assert_eq(rb_body_apply_force_to_center(world, s.boxes[0], rb_v2(0.0, 3.0 * STACK_HEIGHT * 9.8)), RB_OK, "%s",
                 rb_last_error());
    step_world(world, TEST_DT, 1);
    cr_expect_eq(awake_count(world, &s), STACK_HEIGHT);
    cr_expect_gt(rb_body_position(world, s.boxes[STACK_HEIGHT - 1]).y, top_before.y, "the top box rose");
    cr_expect_lt(rb_world_statistics(world).max_penetration, 0.01, "no box was pushed into a sleeping one");
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, joints_link_islands)
{
    /* A chain of three links hanging at rest from a static pivot: one
     * island. Waking the last link wakes all of them at the next step. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id pivot = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id links[3];
    rb_body_id previous = pivot;
    for (int i = 0; i < 3; ++i) {
        links[i] = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -0.5 - i), 0.0);
        add_box(world, links[i], 0.05, 0.5, 1.0);
        make_pin(world, previous, links[i], rb_v2(0.0, -(double)i));
        previous = links[i];
    }
    step_world(world, TEST_DT, 90);
    for (int i = 0; i < 3; ++i) {
        cr_expect(!rb_body_is_awake(world, links[i]), "link %d sleeps", i);
    }
    cr_expect_eq(rb_world_statistics(world).island_count, 1);
    cr_assert_eq(rb_body_set_awake(world, links[2], true), RB_OK);
    cr_assert_eq(rb_body_set_linear_velocity(world, links[2], rb_v2(1.0, 0.0)), RB_OK);
    step_world(world, TEST_DT, 1);
    for (int i = 0; i < 3; ++i) {
        cr_expect(rb_body_is_awake(world, links[i]), "link %d woke with its island", i);
    }
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, the_world_or_one_body_can_refuse_to_sleep)
{
    rb_world *world = world_with_ground();
    stack left = make_stack(world, -5.0);
    stack right = make_stack(world, 5.0);
    cr_assert_eq(rb_body_enable_sleep(world, left.boxes[STACK_HEIGHT - 1], false), RB_OK);
    cr_expect(!rb_body_is_sleep_enabled(world, left.boxes[STACK_HEIGHT - 1]));
    step_world(world, TEST_DT, 120);
    cr_expect_eq(awake_count(world, &left), STACK_HEIGHT, "one sleepless box keeps its whole island awake");
    cr_expect_eq(awake_count(world, &right), 0, "the other island sleeps");
    cr_expect_eq(rb_world_statistics(world).island_count, 2);

    cr_assert_eq(rb_world_enable_sleep(world, false), RB_OK);
    cr_expect(!rb_world_is_sleep_enabled(world));
    cr_expect_eq(awake_count(world, &right), STACK_HEIGHT, "disabling sleep wakes everything");
    step_world(world, TEST_DT, 120);
    cr_expect_eq(awake_count(world, &right), STACK_HEIGHT, "and nothing sleeps");
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, a_slow_kinematic_platform_keeps_its_rider_awake)
{
    /* The platform creeps at 5 mm/s, below the sleep tolerance; friction
     * carries the box along at the same speed. Alone, the box would sleep
     * and be left behind; touching a moving kinematic body, it stays awake
     * and rides on. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_KINEMATIC;
    def.position = rb_v2(0.0, -0.5);
    def.linear_velocity = rb_v2(0.005, 0.0);
    rb_body_id platform;
    cr_assert_eq(rb_body_create(world, &def, &platform), RB_OK);
    add_box(world, platform, 5.0, 0.5, 0.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.5), 0.0);
    add_box(world, box, 0.5, 0.5, 1.0);
    step_world(world, TEST_DT, 240);
    cr_expect(rb_body_is_awake(world, box), "the rider sleeps on a moving platform");
    expect_near(rb_body_position(world, box).x, 0.005 * 4.0, 0.002, "the box rides with the platform");
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, a_body_put_to_sleep_in_the_air_stays_there)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 10.0), 0.0);
    add_circle(world, body, rb_v2(0.0, 0.0), 0.5, 1.0);
    cr_assert_eq(rb_body_set_awake(world, body, false), RB_OK);
    step_world(world, TEST_DT, 60);
    cr_expect_eq(rb_body_position(world, body).y, 10.0);
    cr_assert_eq(rb_body_set_awake(world, body, true), RB_OK);
    step_world(world, TEST_DT, 1);
    cr_expect_lt(rb_body_position(world, body).y, 10.0, "awake again, it falls");
    destroy_world_and_expect_no_leak(world);
}

/* A cable law set every substep: the tension equal to the bob's weight. */
static void hold_weight(rb_world *world, int substep, double h, void *context)
{
    (void)substep;
    (void)h;
    const rb_cable_id *cable = context;
    rb_cable_set_tension_law(world, *cable, 9.8, 0.0);
}

Test(sleep, a_body_held_by_a_cable_law_never_sleeps)
{
    /* A 1 kg bob hangs at rest from a cable whose tension, set every
     * substep, balances its weight: it rests, but a muscle drives it. Put
     * to sleep, it would lose its velocity between substeps and jolt when
     * the next law woke it; a cable law keeps its bodies awake, as a
     * motor does. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -1.0), 0.0);
    const rb_mass_data mass = {1.0, {0.0, 0.0}, 0.0};
    cr_assert_eq(rb_body_set_mass_data(world, bob, &mass), RB_OK);
    rb_cable_def def = rb_default_cable_def();
    def.point_count = 2;
    def.bodies[0] = ground;
    def.bodies[1] = bob;
    rb_cable_id cable;
    cr_assert_eq(rb_cable_create(world, &def, &cable), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_world_set_substep_callback(world, hold_weight, &cable), RB_OK);
    for (int n = 1; n <= 120; ++n) {
        step_world(world, TEST_DT, 1);
        cr_assert(rb_body_is_awake(world, bob), "the bob fell asleep at step %d", n);
    }
    destroy_world_and_expect_no_leak(world);
}

Test(sleep, switching_on_a_motor_wakes_the_joint_bodies)
{
    /* A pendulum at rest sleeps; a motor switched on must turn it at once,
     * without waiting for something else to wake it. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id pivot = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id rod = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -0.5), 0.0);
    add_box(world, rod, 0.05, 0.5, 1.0);
    rb_joint_id pin = make_pin(world, pivot, rod, rb_v2(0.0, 0.0));
    step_world(world, TEST_DT, 60);
    cr_assert(!rb_body_is_awake(world, rod), "the pendulum sleeps");
    cr_assert_eq(rb_revolute_joint_set_motor(world, pin, true, 1.0, 100.0), RB_OK, "%s", rb_last_error());
    cr_expect(rb_body_is_awake(world, rod), "the motor woke the rod");
    step_world(world, TEST_DT, 30);
    expect_near(rb_revolute_joint_speed(world, pin), 1.0, 1e-4, "the rod turns at the motor's speed");
    destroy_world_and_expect_no_leak(world);
}

/* Sets a slack law on the cable from the third substep of the step on:
 * the law wakes the cable's bodies there, within the step. */
static void slack_law_from_third_substep(rb_world *world, int substep, double h, void *context)
{
    (void)h;
    const rb_cable_id *cable = context;
    if (substep >= 2) {
        rb_cable_set_tension_law(world, *cable, 0.0, 0.0);
    }
}

Test(sleep, a_body_woken_within_a_step_moves_from_that_substep_on)
{
    /* A bob put to sleep in the air hangs on a slack cable. The substep
     * callback sets the cable's law in substeps 2 to 5 of 6, which wakes
     * the bob before substep 2's velocities are integrated: it falls for
     * 4 substeps of h, semi-implicit Euler, v = -4·g·h and y moves by
     * -g·h²·(1 + 2 + 3 + 4), not by a whole step's fall nor by nothing. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id hook = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 10.0), 0.0);
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 5.0), 0.0);
    add_circle(world, bob, rb_v2(0.0, 0.0), 0.25, 1.0);
    rb_cable_def def = rb_default_cable_def();
    def.point_count = 2;
    def.bodies[0] = hook;
    def.bodies[1] = bob;
    rb_cable_id cable;
    cr_assert_eq(rb_cable_create(world, &def, &cable), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_awake(world, bob, false), RB_OK);
    step_world(world, TEST_DT, 1);
    cr_assert_eq(rb_body_position(world, bob).y, 5.0, "asleep, the bob stays put");
    cr_assert_eq(rb_world_set_substep_callback(world, slack_law_from_third_substep, &cable), RB_OK);
    step_world(world, TEST_DT, 1);
    cr_expect(rb_body_is_awake(world, bob));
    double h = substep_of(world, TEST_DT);
    expect_near(rb_body_linear_velocity(world, bob).y, -4.0 * 9.8 * h, 1e-12, "velocity after 4 substeps");
    expect_near(rb_body_position(world, bob).y, 5.0 - 9.8 * h * h * 10.0, 1e-12, "fall over 4 substeps");
    destroy_world_and_expect_no_leak(world);
}
