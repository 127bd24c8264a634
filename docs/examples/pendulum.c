/* SPDX-License-Identifier: MIT */
/* A pendulum checked against its period: the engine alone (librb).
 *
 * A disc of radius r on a massless arm of length L, pinned to the ground by
 * a revolute joint and released at rest from θ₀ = 60°. Its exact period is
 *
 *     T = 4·√(L_eq/g)·K(k),  k = sin(θ₀/2),  L_eq = L + r²/(2L),
 *
 * where K is the complete elliptic integral of the first kind and L_eq the
 * length of the simple pendulum with the disc's moment of inertia about the
 * pin (m·L² + m·r²/2 = m·g·L_eq·L/g). K is computed here with the
 * arithmetic-geometric mean, K(k) = π / (2·AGM(1, √(1 − k²))), so the check
 * needs no library beside sinew. The program measures the period between
 * the bob's passages through the bottom, going the same way, and exits 0
 * when it is within 0.1 % of T.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "rb/rb.h"

static void check(rb_status status)
{
    if (status != RB_OK) {
        fprintf(stderr, "pendulum: %s\n", rb_last_error());
        exit(EXIT_FAILURE);
    }
}

/* The arithmetic-geometric mean of a and b (Gauss): converges
 * quadratically, so a handful of iterations reach double precision. */
static double agm(double a, double b)
{
    for (int i = 0; i < 64 && fabs(a - b) > 1e-15 * a; ++i) {
        double mean = 0.5 * (a + b);
        b = sqrt(a * b);
        a = mean;
    }
    return a;
}

int main(void)
{
    const double g = 9.8, length = 1.0, radius = 0.05, theta0 = 60.0 * RB_PI / 180.0;

    rb_world_def world_def = rb_default_world_def();
    world_def.gravity = rb_v2(0.0, -g);
    rb_world *world = NULL;
    check(rb_world_create(&world_def, &world));

    rb_body_def pivot_def = rb_default_body_def(); /* static, at the origin */
    rb_body_id pivot;
    check(rb_body_create(world, &pivot_def, &pivot));

    /* The bob, θ₀ from the vertical; its shape gives it its mass. */
    rb_body_def bob_def = rb_default_body_def();
    bob_def.type = RB_BODY_DYNAMIC;
    bob_def.position = rb_v2(length * sin(theta0), -length * cos(theta0));
    rb_body_id bob;
    check(rb_body_create(world, &bob_def, &bob));
    rb_shape_def shape_def = rb_default_shape_def();
    rb_circle disc = {{0.0, 0.0}, radius};
    rb_shape_id shape;
    check(rb_shape_create_circle(world, bob, &shape_def, &disc, &shape));

    rb_revolute_joint_def pin = rb_default_revolute_joint_def();
    check(rb_revolute_joint_def_at(&pin, world, pivot, bob, rb_v2(0.0, 0.0)));
    rb_joint_id joint;
    check(rb_revolute_joint_create(world, &pin, &joint));

    /* Times at which the bob passes x = 0 moving left (interpolated within
     * the step); consecutive ones are a period apart. */
    const double dt = 1.0 / 240.0;
    double crossings[8];
    int count = 0;
    double previous_x = rb_body_position(world, bob).x;
    for (int step = 1; step <= 240 * 20 && count < 8; ++step) {
        check(rb_world_step(world, dt));
        double x = rb_body_position(world, bob).x;
        if (previous_x > 0.0 && x <= 0.0) {
            crossings[count++] = (step - 1 + previous_x / (previous_x - x)) * dt;
        }
        previous_x = x;
    }
    rb_world_destroy(world);
    if (count < 2) {
        fprintf(stderr, "pendulum: the bob did not swing\n");
        return EXIT_FAILURE;
    }

    double k = sin(0.5 * theta0);
    double elliptic_k = RB_PI / (2.0 * agm(1.0, sqrt(1.0 - k * k)));
    double equivalent_length = length + radius * radius / (2.0 * length);
    double expected = 4.0 * sqrt(equivalent_length / g) * elliptic_k;
    double measured = (crossings[count - 1] - crossings[0]) / (count - 1);
    double error = fabs(measured - expected) / expected;
    printf("pendulum: period %.6f s over %d swings, elliptic integral %.6f s, error %.2e\n", measured, count - 1,
           expected, error);
    return error < 1e-3 ? EXIT_SUCCESS : EXIT_FAILURE;
}
