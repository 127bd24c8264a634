/* SPDX-License-Identifier: MIT */
/* Continuous collision: fast bodies do not pass through thin ones.
 *
 * A circle of radius 0.05 m at 300 m/s moves 5 m per 1/60 s step, fifty
 * times the thickness of the 0.1 m walls below: a discrete test at the
 * step's poses would miss the wall in almost every step. The engine's
 * speculative contacts (each pair that may meet within the step gets a
 * contact whose gap the solver must not close faster than it is) stop
 * it. The starting offsets sweep a whole step's travel, so every phase
 * of the wall crossing between two step poses is tried.
 */
#include <criterion/criterion.h>
#include <math.h>

#include "rb/rb.h"
#include "test_support.h"

#define BULLET_RADIUS 0.05
#define BULLET_SPEED 300.0
#define WALL_HALF_THICKNESS 0.05
#define OFFSETS 25

static rb_body_id launch_bullet(rb_world *world, double x, bool bullet_flag)
{
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = rb_v2(x, 0.0);
    def.linear_velocity = rb_v2(BULLET_SPEED, 0.0);
    def.bullet = bullet_flag;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    add_circle(world, body, rb_v2(0.0, 0.0), BULLET_RADIUS, 7800.0);
    return body;
}

Test(tunnelling, a_fast_circle_never_passes_a_thin_static_wall)
{
    const double travel = BULLET_SPEED * TEST_DT;
    for (int k = 0; k < OFFSETS; ++k) {
        rb_world *world = make_world(rb_v2(0.0, 0.0));
        rb_body_id wall = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
        add_box(world, wall, WALL_HALF_THICKNESS, 1.0, 0.0);
        const double start = -2.0 * travel - travel * k / OFFSETS;
        rb_body_id ball = launch_bullet(world, start, false);
        double farthest = start;
        for (int step = 0; step < 30; ++step) {
            step_world(world, TEST_DT, 1);
            farthest = fmax(farthest, rb_body_position(world, ball).x);
        }
        /* Stopped at the near face, up to the linear slop. */
        cr_expect(farthest <= -WALL_HALF_THICKNESS - BULLET_RADIUS + 0.01,
                  "start %g m: the ball's centre reached x = %g m (the near face stops it at %g)", start, farthest,
                  -WALL_HALF_THICKNESS - BULLET_RADIUS);
        rb_world_destroy(world);
    }
}

Test(tunnelling, a_bullet_never_passes_a_thin_dynamic_box)
{
    /* A 0.1 m thick, 2 m tall box of 1 kg floats free; the 0.48 kg steel
     * bullet hits it and the two move on together (the collision is
     * inelastic). The bullet's centre stays on the near side of the box. */
    const double travel = BULLET_SPEED * TEST_DT;
    for (int k = 0; k < OFFSETS; ++k) {
        rb_world *world = make_world(rb_v2(0.0, 0.0));
        rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
        add_box(world, box, WALL_HALF_THICKNESS, 1.0, 1.0 / (4.0 * WALL_HALF_THICKNESS));
        const double start = -2.0 * travel - travel * k / OFFSETS;
        rb_body_id ball = launch_bullet(world, start, true);
        double worst = -INFINITY;
        for (int step = 0; step < 30; ++step) {
            step_world(world, TEST_DT, 1);
            double behind = rb_body_position(world, ball).x - rb_body_position(world, box).x;
            worst = fmax(worst, behind);
        }
        cr_expect(worst <= -WALL_HALF_THICKNESS - BULLET_RADIUS + 0.01,
                  "start %g m: the bullet's centre got %g m from the box's centre (contact at %g)", start, worst,
                  -WALL_HALF_THICKNESS - BULLET_RADIUS);
        /* Momentum is conserved: m·v before = (m + M)·v after. */
        double m = rb_body_mass(world, ball);
        double M = rb_body_mass(world, box);
        double p = m * rb_body_linear_velocity(world, ball).x + M * rb_body_linear_velocity(world, box).x;
        expect_near(p, m * BULLET_SPEED, 1e-9 * m * BULLET_SPEED, "momentum");
        rb_world_destroy(world);
    }
}
