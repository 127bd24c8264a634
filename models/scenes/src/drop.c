/* SPDX-License-Identifier: MIT */
/* A ball dropped on the ground: the check of restitution (a ball of
 * restitution e dropped from h rebounds to e²·h, Newton's experimental law
 * of impact) and of resting contact once it settles. */
#include "box_body.h"
#include "scenes/scenes.h"

#define DROP_RADIUS 0.1  /* m */
#define DROP_DENSITY 1.0 /* kg/m² */
#define DROP_FRICTION 0.6
#define DROP_MAX_HEIGHT 1000.0      /* m */
#define DROP_GROUND_HALF_WIDTH 20.0 /* m */
#define DROP_GROUND_HALF_HEIGHT 1.0 /* m */

rb_status scene_drop_create(rb_world *world, double height, double restitution, scene_drop *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_drop_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    /* Written so that NaN fails the tests too. */
    if (!(height > 0.0 && height <= DROP_MAX_HEIGHT)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_drop_create: height must be > 0 and <= %g m, got %g",
                               DROP_MAX_HEIGHT, height);
    }
    if (!(restitution >= 0.0 && restitution <= 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_drop_create: restitution must be 0 .. 1, got %g",
                               restitution);
    }
    rb_shape_def material = rb_default_shape_def();
    material.friction = DROP_FRICTION;
    material.restitution = restitution;
    material.density = DROP_DENSITY;

    scene_drop drop = {.radius = DROP_RADIUS};
    rb_status status =
        scene_create_box_body(world, RB_BODY_STATIC, rb_v2(0.0, -DROP_GROUND_HALF_HEIGHT), 0.0, DROP_GROUND_HALF_WIDTH,
                              DROP_GROUND_HALF_HEIGHT, rb_v2(0.0, 0.0), &material, &drop.ground);
    if (status != RB_OK) {
        return status;
    }
    rb_body_def body_def = rb_default_body_def();
    body_def.type = RB_BODY_DYNAMIC;
    body_def.position = rb_v2(0.0, height + DROP_RADIUS);
    status = rb_body_create(world, &body_def, &drop.ball);
    if (status != RB_OK) {
        return status;
    }
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = DROP_RADIUS};
    rb_shape_id shape;
    status = rb_shape_create_circle(world, drop.ball, &material, &circle, &shape);
    if (status != RB_OK) {
        return status;
    }
    *out = drop;
    return RB_OK;
}
