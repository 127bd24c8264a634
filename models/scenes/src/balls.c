/* SPDX-License-Identifier: MIT */
/* The balls box of the first engine in Castanyer's report ("Implementació
 * d'un model computacional de sistemes musculoesquelètics", 2023-24): a
 * 2.44 m x 1.22 m billiard table, with the report's
 * overlapping start replaced by random non-overlapping positions now that
 * the engine has collisions. */
#include <math.h>
#include <stdbool.h>

#include "rng.h"
#include "scenes/scenes.h"

#define BALLS_WALL_HALF_THICKNESS 0.5 /* m: a ball at 15 m/s moves 0.25 m per 1/60 s step */
#define BALLS_FRICTION 0.2
#define BALLS_MIN_RADIUS 0.01 /* m */
#define BALLS_MAX_RADIUS 0.1  /* m */
#define BALLS_BASE_MASS 0.16  /* kg */
#define BALLS_MIN_MASS_FACTOR 0.5
#define BALLS_MAX_MASS_FACTOR 1.5
#define BALLS_MIN_RESTITUTION 0.5
#define BALLS_MAX_RESTITUTION 1.0
#define BALLS_MIN_FORCE 2.0              /* N */
#define BALLS_MAX_FORCE 70.0             /* N */
#define BALLS_KICK_DURATION (1.0 / 60.0) /* s, the original's time step */
#define BALLS_MIN_ANGLE 20.0             /* degrees from +x, counter-clockwise */
#define BALLS_MAX_ANGLE 160.0            /* degrees */

/* The four walls as boxes of one static body at the origin. The floor
 * and ceiling run past the side walls by a full thickness so the
 * corners are closed. */
static rb_status create_walls(rb_world *world, rb_body_id *out)
{
    rb_body_def body_def = rb_default_body_def();
    body_def.type = RB_BODY_STATIC;
    rb_body_id walls;
    rb_status status = rb_body_create(world, &body_def, &walls);
    if (status != RB_OK) {
        return status;
    }
    const double w = SCENE_BALLS_WIDTH;
    const double h = SCENE_BALLS_HEIGHT;
    const double t = BALLS_WALL_HALF_THICKNESS;
    const struct {
        rb_vec2 center, half_extents;
    } boxes[4] = {
        {{0.5 * w, -t}, {0.5 * w + 2.0 * t, t}},    /* floor */
        {{0.5 * w, h + t}, {0.5 * w + 2.0 * t, t}}, /* ceiling */
        {{-t, 0.5 * h}, {t, 0.5 * h}},              /* left */
        {{w + t, 0.5 * h}, {t, 0.5 * h}},           /* right */
    };
    rb_shape_def material = rb_default_shape_def();
    material.friction = BALLS_FRICTION;
    material.restitution = 0.0;
    for (int i = 0; i < 4; ++i) {
        rb_polygon polygon;
        status = rb_make_offset_box(boxes[i].half_extents.x, boxes[i].half_extents.y, boxes[i].center, 0.0, &polygon);
        if (status != RB_OK) {
            return status;
        }
        rb_shape_id shape;
        status = rb_shape_create_polygon(world, walls, &material, &polygon, &shape);
        if (status != RB_OK) {
            return status;
        }
    }
    *out = walls;
    return RB_OK;
}

/* Draws a centre for a ball of `radius` inside the box, clear of the
 * `placed` balls before it, by rejection sampling: uniform candidates
 * until one is free, at most SCENE_BALLS_PLACEMENT_TRIES of them. */
static bool place_ball(scene_rng *rng, double radius, const rb_vec2 *centers, const double *radii, int placed,
                       rb_vec2 *out)
{
    for (int attempt = 0; attempt < SCENE_BALLS_PLACEMENT_TRIES; ++attempt) {
        const double x = scene_rng_uniform(rng, radius, SCENE_BALLS_WIDTH - radius);
        const double y = scene_rng_uniform(rng, radius, SCENE_BALLS_HEIGHT - radius);
        const rb_vec2 candidate = rb_v2(x, y);
        bool clear = true;
        for (int k = 0; k < placed && clear; ++k) {
            const double reach = radius + radii[k];
            clear = rb_length_squared(rb_sub(candidate, centers[k])) > reach * reach;
        }
        if (clear) {
            *out = candidate;
            return true;
        }
    }
    return false;
}

rb_status scene_balls_create(rb_world *world, int count, uint64_t seed, scene_balls *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_balls_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (count < 1 || count > SCENE_BALLS_MAX) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_balls_create: count must be 1 .. %d, got %d",
                               SCENE_BALLS_MAX, count);
    }
    rb_status status = create_walls(world, &out->walls);
    if (status != RB_OK) {
        return status;
    }
    out->count = 0;
    /* 24 kB on the stack at SCENE_BALLS_MAX = 1000. */
    rb_vec2 centers[SCENE_BALLS_MAX];
    double radii[SCENE_BALLS_MAX];
    scene_rng rng;
    scene_rng_seed(&rng, seed);
    for (int i = 0; i < count; ++i) {
        /* Fixed draw order per ball, so that a seed names one scene:
         * radius, mass, restitution, force, angle, then the position tries. */
        const double radius = scene_rng_uniform(&rng, BALLS_MIN_RADIUS, BALLS_MAX_RADIUS);
        const double mass = BALLS_BASE_MASS * scene_rng_uniform(&rng, BALLS_MIN_MASS_FACTOR, BALLS_MAX_MASS_FACTOR);
        const double restitution = scene_rng_uniform(&rng, BALLS_MIN_RESTITUTION, BALLS_MAX_RESTITUTION);
        const double force = scene_rng_uniform(&rng, BALLS_MIN_FORCE, BALLS_MAX_FORCE);
        const double angle = scene_rng_uniform(&rng, BALLS_MIN_ANGLE, BALLS_MAX_ANGLE) * (RB_PI / 180.0);
        rb_vec2 center;
        if (!place_ball(&rng, radius, centers, radii, i, &center)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "scene_balls_create: no free place for ball %d of %d (radius %.3f m) after %d "
                                   "tries; the box is too full, use fewer balls",
                                   i + 1, count, radius, SCENE_BALLS_PLACEMENT_TRIES);
        }
        centers[i] = center;
        radii[i] = radius;

        rb_body_def body_def = rb_default_body_def();
        body_def.type = RB_BODY_DYNAMIC;
        body_def.position = center;
        rb_body_id ball;
        status = rb_body_create(world, &body_def, &ball);
        if (status != RB_OK) {
            return status;
        }
        /* The engine computes mass from density; this density gives the
         * drawn mass for the drawn radius. */
        rb_shape_def material = rb_default_shape_def();
        material.friction = BALLS_FRICTION;
        material.restitution = restitution;
        material.density = mass / (RB_PI * radius * radius);
        const rb_circle circle = {.center = {0.0, 0.0}, .radius = radius};
        rb_shape_id shape;
        status = rb_shape_create_circle(world, ball, &material, &circle, &shape);
        if (status != RB_OK) {
            return status;
        }
        /* The original pushed each ball with a force held for one of its
         * 1/60 s steps: the impulse F·Δt, given at once. */
        const rb_vec2 impulse = rb_scale(force * BALLS_KICK_DURATION, rb_v2(cos(angle), sin(angle)));
        status = rb_body_apply_linear_impulse_to_center(world, ball, impulse);
        if (status != RB_OK) {
            return status;
        }
        out->balls[i] = ball;
        out->count = i + 1;
    }
    return RB_OK;
}

rb_status scene_balls_apply_drag(rb_world *world, const scene_balls *balls)
{
    if (world == NULL || balls == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_balls_apply_drag: %s is NULL",
                               world == NULL ? "world" : "balls");
    }
    if (balls->count < 1 || balls->count > SCENE_BALLS_MAX) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_balls_apply_drag: balls->count must be 1 .. %d, got %d",
                               SCENE_BALLS_MAX, balls->count);
    }
    for (int i = 0; i < balls->count; ++i) {
        const rb_vec2 velocity = rb_body_linear_velocity(world, balls->balls[i]);
        if (rb_last_status() != RB_OK) {
            return rb_last_status();
        }
        rb_status status = rb_body_apply_force_to_center(world, balls->balls[i], rb_scale(-SCENE_BALLS_DRAG, velocity));
        if (status != RB_OK) {
            return status;
        }
    }
    return RB_OK;
}
