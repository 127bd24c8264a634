/* SPDX-License-Identifier: MIT */
/* Restitution does not depend on where in the step the impact falls: a
 * ball of restitution e dropped from h rebounds to e²·h within 1 % at
 * 60 Hz with the default solver settings, for every drop height.
 *
 * The heights from 0.95 to 1.05 m in steps of 5 mm put the impact at
 * every phase of a 60 Hz step (the ball covers 7 cm a step there). When
 * restitution took the approach speed at the start of the step, the
 * rebound fell short by 0.9 % to 7.8 % over this range, as the ball kept
 * accelerating until it met the ground later in the step. */
#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"
#include "scenes/scenes.h"
#include "test_support.h"

#define TOLERANCE 0.01

/* The height of the ball's lowest point at the top of its first rebound,
 * sampled after each step: the apex falls between two samples, at most
 * ½·g·(dt/2)² = 0.34 mm below the highest one, 0.14 % of the lowest
 * rebound here. */
static double rebound_apex(rb_world *world, const scene_drop *drop, double dt)
{
    bool rising = false;
    double apex = 0.0;
    for (int n = 0; n < (int)(5.0 / dt); ++n) {
        step_world(world, dt, 1);
        const double vy = rb_body_linear_velocity(world, drop->ball).y;
        const double lowest = rb_body_position(world, drop->ball).y - drop->radius;
        if (vy > 0.0) {
            apex = rising ? fmax(apex, lowest) : lowest;
            rising = true;
        } else if (rising) {
            return apex;
        }
    }
    cr_assert_fail("the ball did not rebound and fall again within 5 s");
    return apex;
}

/* Each drop from `lowest` to `highest` m in steps of `increment`, with the
 * given solver at 60 Hz, rebounds to e²·h within TOLERANCE. */
static void expect_rebounds(rb_solver_type solver, double e, double lowest, double highest, double increment)
{
    for (double h = lowest; h <= highest + 0.5 * increment; h += increment) {
        rb_world *world = make_world(rb_default_world_def().gravity);
        rb_solver_settings settings = rb_default_solver_settings();
        settings.type = solver;
        cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
        scene_drop drop;
        cr_assert_eq(scene_drop_create(world, h, e, &drop), RB_OK, "%s", rb_last_error());
        const double expected = e * e * h;
        const double apex = rebound_apex(world, &drop, TEST_DT);
        const double error = apex / expected - 1.0;
        cr_expect(fabs(error) <= TOLERANCE,
                  "%s, e = %g, dropped from %.3f m: rebound to %.5f m, e²·h = %.5f m (%+.2f %%)",
                  rb_solver_type_name(solver), e, h, apex, expected, 100.0 * error);
        destroy_world_and_expect_no_leak(world);
    }
}

Test(restitution, the_rebound_does_not_depend_on_the_impact_phase_at_60_hz)
{
    expect_rebounds(rb_default_solver_settings().type, 0.5, 0.95, 1.05, 0.005);
}

Test(restitution, other_heights_and_restitutions_at_60_hz)
{
    expect_rebounds(rb_default_solver_settings().type, 0.5, 0.4, 3.0, 0.2);
    expect_rebounds(rb_default_solver_settings().type, 0.8, 0.4, 3.0, 0.2);
}

/* Baumgarte's velocity bias pushes out overlap, which a speculative
 * contact does not leave: the same law holds. */
Test(restitution, the_baumgarte_solver_rebounds_alike) { expect_rebounds(RB_SOLVER_BAUMGARTE, 0.5, 0.95, 1.05, 0.005); }
