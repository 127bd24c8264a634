/* SPDX-License-Identifier: MIT */
/* A bouncing ball: the engine alone (librb).
 *
 * A ball of radius 0.1 m falls from 1 m onto the ground with a coefficient
 * of restitution e = 0.5. An impact with restitution e sends the ball back
 * up at e times its impact speed, so it climbs back to e²·h = 0.25 m. The
 * program drops it, finds the top of the first rebound and checks it
 * against e²·h (the time step's own error is about 1 %).
 *
 * Build: see docs/examples/CMakeLists.txt (find_package) or Makefile
 * (pkg-config). Exit status 0 when the rebound is within 3 % of e²·h.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "rb/rb.h"

/* Stops the program with the engine's message when a call fails. */
static void check(rb_status status)
{
    if (status != RB_OK) {
        fprintf(stderr, "bouncing_ball: %s\n", rb_last_error());
        exit(EXIT_FAILURE);
    }
}

int main(void)
{
    const double radius = 0.1, drop_height = 1.0, restitution = 0.5;

    rb_world_def world_def = rb_default_world_def(); /* gravity (0, -9.8) m/s² */
    rb_world *world = NULL;
    check(rb_world_create(&world_def, &world));

    /* The ground: a static body with a segment along y = 0. */
    rb_body_def ground_def = rb_default_body_def(); /* static */
    rb_body_id ground;
    check(rb_body_create(world, &ground_def, &ground));
    rb_shape_def shape_def = rb_default_shape_def();
    shape_def.restitution = restitution; /* a contact takes the larger of the two */
    rb_segment floor = {{-5.0, 0.0}, {5.0, 0.0}};
    rb_shape_id floor_shape;
    check(rb_shape_create_segment(world, ground, &shape_def, &floor, &floor_shape));

    /* The ball, its lowest point drop_height above the ground. */
    rb_body_def ball_def = rb_default_body_def();
    ball_def.type = RB_BODY_DYNAMIC;
    ball_def.position = rb_v2(0.0, drop_height + radius);
    rb_body_id ball;
    check(rb_body_create(world, &ball_def, &ball));
    rb_circle circle = {{0.0, 0.0}, radius};
    rb_shape_id ball_shape;
    check(rb_shape_create_circle(world, ball, &shape_def, &circle, &ball_shape));

    /* Step at 60 Hz until the ball has bounced and starts down again. */
    bool bounced = false;
    double top = 0.0;
    for (int step = 0; step < 600; ++step) {
        check(rb_world_step(world, 1.0 / 60.0));
        double height = rb_body_position(world, ball).y - radius;
        double vy = rb_body_linear_velocity(world, ball).y;
        if (!bounced && vy > 0.0) {
            bounced = true;
        }
        if (bounced) {
            top = fmax(top, height);
            if (vy < 0.0) {
                break;
            }
        }
    }
    rb_world_destroy(world);

    double expected = restitution * restitution * drop_height;
    double error = fabs(top - expected) / expected;
    printf("bouncing_ball: rebound %.4f m, e²·h = %.4f m, error %.2f %%\n", top, expected, 100.0 * error);
    return bounced && error < 0.03 ? EXIT_SUCCESS : EXIT_FAILURE;
}
