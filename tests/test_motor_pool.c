/* SPDX-License-Identifier: MIT */
/* The motor pool (after McIntyre, "Simulated Muscles") against running sums by
 * hand, profile images written here with libpng, and the torque actuator
 * against Newton's second law for rotation (α = τ/I) and the conservation
 * of angular momentum under an internal torque pair.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "mu/motor_pool.h"
#include "mu/torque_actuator.h"
#include "png_writer.h"
#include "test_support.h"

/* A scratch file path in a fresh directory; both removed by remove_scratch. */
typedef struct scratch {
    char dir[32];
    char path[64];
} scratch;

static void make_scratch(scratch *s, const char *name)
{
    strcpy(s->dir, "/tmp/sinew-pool-XXXXXX");
    cr_assert_not_null(mkdtemp(s->dir));
    snprintf(s->path, sizeof s->path, "%s/%s", s->dir, name);
}

static void remove_scratch(const scratch *s)
{
    remove(s->path);
    rmdir(s->dir);
}

/* Writes a width × height opaque 8-bit RGB PNG whose pixel x is on the
 * white-to-red scale with blue `blue[x]`: red 255, green = blue (every
 * row alike). */
static void write_profile(const char *path, const int *blue, int width, int height)
{
    unsigned samples[3 * 16 * 2];
    cr_assert(width * height <= 32);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            unsigned *pixel = &samples[3 * (y * width + x)];
            pixel[0] = 255;
            pixel[1] = (unsigned)blue[x];
            pixel[2] = (unsigned)blue[x];
        }
    }
    write_test_png(
        path, &(test_png){
                  .width = width, .height = height, .colour_type = PNG_COLOR_TYPE_RGB, .depth = 8, .samples = samples});
}

Test(motor_pool, exertion_is_the_running_sum_share)
{
    const double strengths[] = {1.0, 2.0, 3.0, 4.0, 10.0};
    /* cumsum by hand: 0, 1, 3, 6, 10, 20. */
    const double cumsum[] = {0.0, 1.0, 3.0, 6.0, 10.0, 20.0};
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_create(strengths, 5, &pool), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_motor_pool_neuron_count(pool), 5);
    expect_near(mu_motor_pool_total_strength(pool), 20.0, 0.0, "total");
    cr_expect_eq(mu_motor_pool_recruited(pool), 0, "nothing recruited at first");
    expect_near(mu_motor_pool_exertion(pool), 0.0, 0.0, "n = 0 exerts nothing (not McIntyre's s_0)");
    for (int n = 0; n <= 5; ++n) {
        cr_assert_eq(mu_motor_pool_recruit(pool, n), RB_OK);
        expect_near(mu_motor_pool_exertion(pool), cumsum[n] / 20.0, 1e-15, "e(n) = cumsum[n]/cumsum[all]");
    }
    expect_near(mu_motor_pool_exertion(pool), 1.0, 0.0, "all recruited");
    /* Beyond the pool refused, leaving the recruitment as it was; one at a
     * time clamped to the pool. */
    cr_expect_eq(mu_motor_pool_recruit(pool, 99), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_motor_pool_recruited(pool), 5);
    cr_assert_eq(mu_motor_pool_recruit_more(pool, -1), RB_OK);
    expect_near(mu_motor_pool_exertion(pool), 0.5, 1e-15, "one fewer: 10/20");
    cr_assert_eq(mu_motor_pool_recruit_more(pool, -40), RB_OK);
    cr_expect_eq(mu_motor_pool_recruited(pool), 0);
    cr_assert_eq(mu_motor_pool_recruit_more(pool, 1), RB_OK);
    expect_near(mu_motor_pool_exertion(pool), 0.05, 1e-15, "one more: 1/20");
    cr_expect_eq(mu_motor_pool_recruit(pool, -3), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_motor_pool_recruited(pool), 1, "a refused count recruits nothing");
    mu_motor_pool_destroy(pool);
}

Test(motor_pool, exponential_profile_of_the_worm)
{
    /* 200 neurons from 1 to 100: s_i = 100^(i/199), a geometric series
     * of ratio q = 100^(1/199), so cumsum[n] = (q^n − 1)/(q − 1). */
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_create_exponential(200, 1.0, 100.0, &pool), RB_OK, "%s", rb_last_error());
    expect_near(mu_motor_pool_strength(pool, 0), 1.0, 1e-15, "weakest");
    expect_near(mu_motor_pool_strength(pool, 199), 100.0, 1e-12, "strongest");
    const double q = pow(100.0, 1.0 / 199.0);
    for (int n = 0; n <= 200; n += 20) {
        const double expected = (pow(q, n) - 1.0) / (pow(q, 200) - 1.0);
        expect_near(mu_motor_pool_exertion_at(pool, n), expected, 1e-12, "geometric sum share");
    }
    /* The worm's pool: the first 30 % give about 3 % of the force. */
    const double first_30 = mu_motor_pool_exertion_at(pool, 60);
    cr_expect(first_30 > 0.02 && first_30 < 0.04, "first 30 %% give %g", first_30);
    mu_motor_pool_destroy(pool);
}

Test(motor_pool, png_profile_is_255_minus_blue)
{
    scratch s;
    make_scratch(&s, "profile.png");
    const int blue[] = {255, 250, 200, 128, 0, 55};
    write_profile(s.path, blue, 6, 1);
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_load_png(s.path, &pool), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_motor_pool_neuron_count(pool), 6, "one neuron per pixel");
    for (int i = 0; i < 6; ++i) {
        expect_near(mu_motor_pool_strength(pool, i), 255.0 - blue[i], 0.0, "255 − blue");
    }
    /* cumsum of 0, 5, 55, 127, 255, 200: 0, 0, 5, 60, 187, 442, 642. */
    cr_assert_eq(mu_motor_pool_recruit(pool, 4), RB_OK);
    expect_near(mu_motor_pool_exertion(pool), 187.0 / 642.0, 1e-15, "e(4)");
    mu_motor_pool_destroy(pool);
    remove_scratch(&s);
}

Test(motor_pool, bad_profiles_are_clear_errors)
{
    mu_motor_pool *pool = NULL;
    cr_expect_eq(mu_motor_pool_load_png("/nonexistent/profile.png", &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(pool);
    cr_expect(strstr(rb_last_error(), "/nonexistent/profile.png: cannot open") != NULL, "%s", rb_last_error());

    scratch s;
    make_scratch(&s, "tall.png");
    const int blue[] = {0, 100, 200};
    write_profile(s.path, blue, 3, 2);
    cr_expect_eq(mu_motor_pool_load_png(s.path, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "3 × 2 pixels, expected 1 pixel high") != NULL, "%s", rb_last_error());
    const int white[] = {255, 255};
    write_profile(s.path, white, 2, 1);
    cr_expect_eq(mu_motor_pool_load_png(s.path, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "every pixel is white") != NULL, "%s", rb_last_error());
    /* A text file is not a PNG. */
    FILE *file = fopen(s.path, "w");
    cr_assert_not_null(file);
    fputs("1, 2, 3\n", file);
    fclose(file);
    cr_expect_eq(mu_motor_pool_load_png(s.path, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "tall.png: not a PNG file") != NULL, "%s", rb_last_error());
    cr_expect_null(pool);
    remove_scratch(&s);
}

Test(motor_pool, csv_profile_and_its_errors)
{
    scratch s;
    make_scratch(&s, "profile.csv");
    FILE *file = fopen(s.path, "w");
    cr_assert_not_null(file);
    fputs("# strengths, weakest first\n1, 2,3\n\n4\t10  # the strongest\n", file);
    fclose(file);
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_load_csv(s.path, &pool), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_motor_pool_neuron_count(pool), 5);
    cr_assert_eq(mu_motor_pool_recruit(pool, 3), RB_OK);
    expect_near(mu_motor_pool_exertion(pool), 6.0 / 20.0, 1e-15, "e(3) = 6/20");
    mu_motor_pool_destroy(pool);
    pool = NULL;

    file = fopen(s.path, "w");
    cr_assert_not_null(file);
    fputs("1, 2\n3, -4\n", file);
    fclose(file);
    cr_expect_eq(mu_motor_pool_load_csv(s.path, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "profile.csv:2: \"-4\" is not a strength") != NULL, "%s", rb_last_error());
    file = fopen(s.path, "w");
    cr_assert_not_null(file);
    fputs("# nothing\n", file);
    fclose(file);
    cr_expect_eq(mu_motor_pool_load_csv(s.path, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "no strengths") != NULL, "%s", rb_last_error());
    cr_expect_null(pool);
    remove_scratch(&s);
    cr_expect_eq(mu_motor_pool_load_csv(s.path, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "cannot open") != NULL, "%s", rb_last_error());
}

Test(motor_pool, bad_arguments_are_errors)
{
    mu_motor_pool *pool = NULL;
    const double zeros[] = {0.0, 0.0};
    cr_expect_eq(mu_motor_pool_create(zeros, 2, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "sum to 0") != NULL, "%s", rb_last_error());
    const double negative[] = {1.0, -1.0};
    cr_expect_eq(mu_motor_pool_create(negative, 2, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "strengths[1]") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_motor_pool_create(NULL, 2, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_motor_pool_create(zeros, 0, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_motor_pool_create_exponential(10, 0.0, 1.0, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_motor_pool_create_exponential(10, 2.0, 1.0, &pool), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_motor_pool_recruit(NULL, 1), RB_ERR_INVALID_ARGUMENT);
    cr_expect(isnan(mu_motor_pool_exertion(NULL)));
    cr_expect_null(pool);
}

/* A free disc of radius r and density ρ in zero gravity: I = ½·m·r². */
static rb_body_id make_disc(rb_world *world, rb_vec2 position, double radius, double density)
{
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, position, 0.0);
    add_circle(world, body, rb_v2(0.0, 0.0), radius, density);
    return body;
}

Test(torque_actuator, angular_acceleration_is_torque_over_inertia)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id disc = make_disc(world, rb_v2(0.0, 0.0), 0.1, 1000.0);
    const double m = 1000.0 * RB_PI * 0.01;
    const double inertia = 0.5 * m * 0.01;
    expect_near(rb_body_mass_data(world, disc).rotational_inertia, inertia, 1e-12 * inertia, "I = ½mr²");

    mu_torque_actuator_def def = mu_default_torque_actuator_def();
    def.body = disc;
    def.peak_torque = 2.0;
    mu_torque_actuator *actuator = NULL;
    cr_assert_eq(mu_torque_actuator_create(world, &def, &actuator), RB_OK, "%s", rb_last_error());
    const double exertion = 0.25;
    cr_assert_eq(mu_torque_actuator_set_exertion(actuator, exertion), RB_OK);
    expect_near(mu_torque_actuator_torque(actuator), 0.5, 0.0, "τ = e·τ_peak");
    /* The torque holds over the whole step: ω grows by τ/I·dt per step. */
    for (int step = 1; step <= 10; ++step) {
        cr_assert_eq(mu_torque_actuator_apply(actuator, world), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
        expect_near(rb_body_angular_velocity(world, disc), 0.5 / inertia * TEST_DT * step, 1e-9, "ω = (τ/I)·t");
    }
    expect_vec_near(rb_body_linear_velocity(world, disc), rb_v2(0.0, 0.0), 0.0, "a pure torque does not translate");
    mu_torque_actuator_destroy(actuator);
    destroy_world_and_expect_no_leak(world);
}

/* Angular momentum about the origin: Σ I·ω + m·(r × v). */
static double angular_momentum(const rb_world *world, const rb_body_id *bodies, int count)
{
    double total = 0.0;
    for (int i = 0; i < count; ++i) {
        const rb_mass_data mass = rb_body_mass_data(world, bodies[i]);
        const rb_vec2 r = rb_body_world_center(world, bodies[i]);
        const rb_vec2 v = rb_body_linear_velocity(world, bodies[i]);
        total +=
            mass.rotational_inertia * rb_body_angular_velocity(world, bodies[i]) + mass.mass * (r.x * v.y - r.y * v.x);
    }
    return total;
}

Test(torque_actuator, joint_actuator_conserves_angular_momentum)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    /* Two unconnected discs: each spins alone, I_a·ω_a = −I_b·ω_b. */
    rb_body_id a = make_disc(world, rb_v2(-1.0, 0.0), 0.1, 1000.0);
    rb_body_id b = make_disc(world, rb_v2(1.0, 0.0), 0.2, 500.0);
    mu_torque_actuator_def def = mu_default_torque_actuator_def();
    def.body = a;
    def.reaction_body = b;
    def.peak_torque = -3.0;
    mu_torque_actuator *actuator = NULL;
    cr_assert_eq(mu_torque_actuator_create(world, &def, &actuator), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_torque_actuator_set_exertion(actuator, 1.0), RB_OK);
    const double ia = rb_body_mass_data(world, a).rotational_inertia;
    const double ib = rb_body_mass_data(world, b).rotational_inertia;
    cr_assert_eq(mu_torque_actuator_apply(actuator, world), RB_OK);
    step_world(world, TEST_DT, 1);
    expect_near(rb_body_angular_velocity(world, a), -3.0 / ia * TEST_DT, 1e-9, "ω_a = τ/I_a·dt");
    expect_near(rb_body_angular_velocity(world, b), 3.0 / ib * TEST_DT, 1e-9, "ω_b = −τ/I_b·dt");
    mu_torque_actuator_destroy(actuator);

    /* Two boxes pinned end to end: the pair turns, the pin's forces are
     * internal, and the total angular momentum stays 0. */
    rb_body_id lower = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 2.0), 0.0);
    add_box(world, lower, 0.025, 0.1, 1000.0);
    rb_body_id upper = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 2.2), 0.0);
    add_box(world, upper, 0.025, 0.1, 1000.0);
    make_pin(world, lower, upper, rb_v2(0.0, 2.1));
    def.body = upper;
    def.reaction_body = lower;
    def.peak_torque = 0.05;
    cr_assert_eq(mu_torque_actuator_create(world, &def, &actuator), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_torque_actuator_set_exertion(actuator, 1.0), RB_OK);
    const rb_body_id pair[] = {lower, upper};
    for (int step = 0; step < 30; ++step) {
        cr_assert_eq(mu_torque_actuator_apply(actuator, world), RB_OK);
        step_world(world, TEST_DT, 1);
        expect_near(angular_momentum(world, pair, 2), 0.0, 1e-9, "L of the pinned pair");
    }
    cr_expect(rb_body_angular_velocity(world, upper) > 0.1, "the upper box turns: ω = %g",
              rb_body_angular_velocity(world, upper));
    cr_expect(rb_body_angular_velocity(world, lower) < -0.1, "the lower box turns back: ω = %g",
              rb_body_angular_velocity(world, lower));
    mu_torque_actuator_destroy(actuator);
    destroy_world_and_expect_no_leak(world);
}

Test(torque_actuator, bad_arguments_are_errors)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id disc = make_disc(world, rb_v2(0.0, 0.0), 0.1, 1000.0);
    mu_torque_actuator_def def = mu_default_torque_actuator_def();
    mu_torque_actuator *actuator = NULL;
    cr_expect_eq(mu_torque_actuator_create(world, &def, &actuator), RB_ERR_INVALID_ARGUMENT, "null body");
    cr_expect(strstr(rb_last_error(), "def.body") != NULL, "%s", rb_last_error());
    def.body = disc;
    def.reaction_body = disc;
    cr_expect_eq(mu_torque_actuator_create(world, &def, &actuator), RB_ERR_INVALID_ARGUMENT, "itself");
    cr_expect(strstr(rb_last_error(), "def.reaction_body") != NULL, "%s", rb_last_error());
    def.reaction_body = (rb_body_id){0};
    def.peak_torque = NAN;
    cr_expect_eq(mu_torque_actuator_create(world, &def, &actuator), RB_ERR_INVALID_ARGUMENT, "NaN torque");
    cr_expect(strstr(rb_last_error(), "peak_torque") != NULL, "%s", rb_last_error());
    cr_expect_null(actuator);
    def.peak_torque = 1.0;
    cr_assert_eq(mu_torque_actuator_create(world, &def, &actuator), RB_OK);
    cr_expect_eq(mu_torque_actuator_set_exertion(actuator, 1.5), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "exertion") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_torque_actuator_apply(NULL, world), RB_ERR_INVALID_ARGUMENT);
    mu_torque_actuator_destroy(actuator);
    destroy_world_and_expect_no_leak(world);
}
