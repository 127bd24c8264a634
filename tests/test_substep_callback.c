/* SPDX-License-Identifier: MIT */
/* The substep callback: when it runs, what it may change, and a force
 * law updated from it every substep against the analytic oscillator.
 */
#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"
#include "test_support.h"

typedef struct call_log {
    int calls;
    int indices[16];
    double lengths[16];
} call_log;

static void log_call(rb_world *world, int substep, double h, void *context)
{
    (void)world;
    call_log *log = context;
    if (log->calls < 16) {
        log->indices[log->calls] = substep;
        log->lengths[log->calls] = h;
    }
    log->calls++;
}

Test(substep_callback, runs_once_per_substep_with_its_index_and_length)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    set_substeps(world, 6);
    make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    call_log log = {0};
    cr_assert_eq(rb_world_set_substep_callback(world, log_call, &log), RB_OK, "%s", rb_last_error());
    const double dt = 1.0 / 60.0;
    cr_assert_eq(rb_world_step(world, dt), RB_OK, "%s", rb_last_error());
    cr_assert_eq(log.calls, 6);
    for (int i = 0; i < 6; ++i) {
        cr_expect_eq(log.indices[i], i);
        cr_expect_eq(log.lengths[i], dt / 6.0, "substep %d: h = %.17g", i, log.lengths[i]);
    }
    cr_assert_eq(rb_world_set_substep_callback(world, NULL, NULL), RB_OK);
    cr_assert_eq(rb_world_step(world, dt), RB_OK);
    cr_expect_eq(log.calls, 6, "a removed callback is not called");
    destroy_world_and_expect_no_leak(world);
}

typedef struct change_attempts {
    rb_cable_id cable;
    rb_status create_body, set_gravity, set_callback, set_law;
} change_attempts;

static void try_changes(rb_world *world, int substep, double h, void *context)
{
    (void)h;
    change_attempts *attempts = context;
    if (substep != 0) {
        return;
    }
    rb_body_def def = rb_default_body_def();
    rb_body_id body;
    attempts->create_body = rb_body_create(world, &def, &body);
    attempts->set_gravity = rb_world_set_gravity(world, rb_v2(0.0, 0.0));
    attempts->set_callback = rb_world_set_substep_callback(world, NULL, NULL);
    attempts->set_law = rb_cable_set_tension_law(world, attempts->cable, 1.0, 0.0);
}

Test(substep_callback, may_set_cable_laws_but_not_change_the_world)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -1.0), 0.0);
    add_circle(world, bob, rb_v2(0.0, 0.0), 0.1, 1.0);
    rb_cable_def def = rb_default_cable_def();
    def.point_count = 2;
    def.bodies[0] = ground;
    def.bodies[1] = bob;
    change_attempts attempts = {0};
    cr_assert_eq(rb_cable_create(world, &def, &attempts.cable), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_world_set_substep_callback(world, try_changes, &attempts), RB_OK);
    cr_assert_eq(rb_world_step(world, 1.0 / 60.0), RB_OK, "%s", rb_last_error());
    cr_expect_eq(attempts.create_body, RB_ERR_LOCKED);
    cr_expect_eq(attempts.set_gravity, RB_ERR_LOCKED);
    cr_expect_eq(attempts.set_callback, RB_ERR_LOCKED);
    cr_expect_eq(attempts.set_law, RB_OK, "a cable law may change between substeps");
    cr_expect_eq(rb_world_gravity(world).y, -9.8);
    cr_expect_eq(rb_world_statistics(world).body_count, 2);
    destroy_world_and_expect_no_leak(world);
}

/* A spring made of a cable whose law the callback sets every substep
 * from the length: T = k·(L - L0), no damping. */
typedef struct cable_spring {
    rb_cable_id cable;
    double stiffness, rest_length;
} cable_spring;

static void update_spring(rb_world *world, int substep, double h, void *context)
{
    (void)substep;
    (void)h;
    const cable_spring *spring = context;
    double tension = spring->stiffness * (rb_cable_length(world, spring->cable) - spring->rest_length);
    rb_cable_set_tension_law(world, spring->cable, tension, 0.0);
}

Test(substep_callback, a_law_set_every_substep_makes_a_spring_of_the_analytic_period)
{
    /* A 1 kg bob hangs from a static point on a spring of k = 100 N/m:
     * equilibrium m·g/k = 0.098 m below the rest length; pulled 0.05 m
     * further down it oscillates with period 2π·sqrt(m/k) = 0.6283 s, and
     * the tension never falls to 0 (the cable could not push). The
     * semi-implicit Euler period differs by about (ω·h)²/24 (2e-5 at
     * 600 Hz); the crossings are read at 60 Hz, 0.5 % of the period. */
    const double g = 9.8;
    const double k = 100.0;
    rb_world *world = make_world(rb_v2(0.0, -g));
    set_substeps(world, 10);
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    const double rest_length = 1.0;
    const double equilibrium = rest_length + g / k;
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -(equilibrium + 0.05)), 0.0);
    const rb_mass_data mass = {1.0, {0.0, 0.0}, 0.0};
    cr_assert_eq(rb_body_set_mass_data(world, bob, &mass), RB_OK);
    rb_cable_def def = rb_default_cable_def();
    def.point_count = 2;
    def.bodies[0] = ground;
    def.bodies[1] = bob;
    cable_spring spring = {.stiffness = k, .rest_length = rest_length};
    cr_assert_eq(rb_cable_create(world, &def, &spring.cable), RB_OK);
    cr_assert_eq(rb_world_set_substep_callback(world, update_spring, &spring), RB_OK);

    /* Upward crossings of the equilibrium, interpolated within a step. */
    const double dt = 1.0 / 60.0;
    double crossings[8];
    int count = 0;
    double previous = rb_body_position(world, bob).y + equilibrium;
    for (int step = 1; step <= 600 && count < 8; ++step) {
        cr_assert_eq(rb_world_step(world, dt), RB_OK, "%s", rb_last_error());
        double offset = rb_body_position(world, bob).y + equilibrium;
        cr_assert(rb_cable_tension(world, spring.cable) > 0.0, "the cable went slack at step %d", step);
        if (previous < 0.0 && offset >= 0.0) {
            crossings[count++] = dt * (step - 1 + previous / (previous - offset));
        }
        previous = offset;
    }
    cr_assert_geq(count, 4);
    double period = (crossings[count - 1] - crossings[0]) / (count - 1);
    expect_near(period, 2.0 * RB_PI * sqrt(1.0 / k), 0.005 * 2.0 * RB_PI * sqrt(1.0 / k), "period");
    destroy_world_and_expect_no_leak(world);
}
