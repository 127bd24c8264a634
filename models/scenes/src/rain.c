/* SPDX-License-Identifier: MIT */
/* Rain on a pyramid: the peers' pyramid with balls falling on it a few at
 * a time, the case of a broad phase whose candidates change only around
 * the shapes that move (engine/src/broad_phase.c). */
#include "box_body.h"
#include "rng.h"
#include "scenes/scenes.h"

#define RAIN_BALL_RADIUS 0.2     /* m */
#define RAIN_BALL_DENSITY 1.0    /* kg/m², as the boxes */
#define RAIN_FRICTION 0.6        /* as the boxes */
#define RAIN_LOWEST_ROW 2.0      /* m above the pyramid's top box */
#define RAIN_ROW_SPACING 2.0     /* m */
#define RAIN_HEIGHT_JITTER 1.0   /* m: a row's balls start up to this much higher */
#define RAIN_SIDEWAYS_JITTER 0.2 /* m either side of a column; balls stay 0.2 m apart */
#define RAIN_MAX_THROW 3.0       /* m/s, sideways either way */

static rb_status add_ball(rb_world *world, rb_vec2 position, double sideways_speed, rb_body_id *out)
{
    rb_body_def body_def = rb_default_body_def();
    body_def.type = RB_BODY_DYNAMIC;
    body_def.position = position;
    body_def.linear_velocity = rb_v2(sideways_speed, 0.0);
    rb_status status = rb_body_create(world, &body_def, out);
    if (status != RB_OK) {
        return status;
    }
    rb_shape_def material = rb_default_shape_def();
    material.density = RAIN_BALL_DENSITY;
    material.friction = RAIN_FRICTION;
    material.restitution = 0.0;
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = RAIN_BALL_RADIUS};
    rb_shape_id shape;
    return rb_shape_create_circle(world, *out, &material, &circle, &shape);
}

rb_status scene_rain_create(rb_world *world, int base, int ball_count, uint64_t seed, scene_rain *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_rain_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (ball_count < 0 || ball_count > SCENE_RAIN_MAX_BALLS) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_rain_create: ball_count must be 0 .. %d, got %d",
                               SCENE_RAIN_MAX_BALLS, ball_count);
    }
    scene_rain rain = {.ball_count = 0};
    rb_status status = scene_pyramid_create(world, base, &rain.pyramid);
    if (status != RB_OK) {
        return status;
    }
    const rb_vec2 top = rb_body_position(world, rain.pyramid.top);
    scene_rng rng;
    scene_rng_seed(&rng, seed);
    /* Columns 1 m apart over the pyramid's base, rows above its top. */
    for (int k = 0; k < ball_count; ++k) {
        const int column = k % base;
        const int row = k / base;
        const double x =
            -0.5 * base + column + 0.5 + scene_rng_uniform(&rng, -RAIN_SIDEWAYS_JITTER, RAIN_SIDEWAYS_JITTER);
        const double y =
            top.y + RAIN_LOWEST_ROW + RAIN_ROW_SPACING * row + scene_rng_uniform(&rng, 0.0, RAIN_HEIGHT_JITTER);
        const double throw_speed = scene_rng_uniform(&rng, -RAIN_MAX_THROW, RAIN_MAX_THROW);
        rb_body_id ball;
        status = add_ball(world, rb_v2(x, y), throw_speed, &ball);
        if (status != RB_OK) {
            return status;
        }
        if (k == 0) {
            rain.first_ball = ball;
        } else if (!scene_id_follows(rain.first_ball, k, ball)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_rain_create: the world reused a destroyed body "
                                                            "slot; build the scene in a fresh world");
        }
        rain.ball_count += 1;
    }
    *out = rain;
    return RB_OK;
}
