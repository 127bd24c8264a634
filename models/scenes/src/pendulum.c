/* SPDX-License-Identifier: MIT */
/* A simple pendulum: the check of a revolute joint against the period of
 * an ideal pendulum (2·pi·sqrt(L/g) for small swings). */
#include "scenes/scenes.h"

#define PENDULUM_MAX_LENGTH 100.0 /* m */
#define PENDULUM_BOB_RADIUS 0.05  /* m */

rb_status scene_pendulum_create(rb_world *world, double length, scene_pendulum *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_pendulum_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    /* Written so that NaN fails the test too. */
    if (!(length > 0.0 && length <= PENDULUM_MAX_LENGTH)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_pendulum_create: length must be > 0 and <= %g m, got %g",
                               PENDULUM_MAX_LENGTH, length);
    }
    scene_pendulum pendulum = {.radius = PENDULUM_BOB_RADIUS};
    rb_body_def pivot_def = rb_default_body_def();
    rb_status status = rb_body_create(world, &pivot_def, &pendulum.pivot);
    rb_body_def bob_def = rb_default_body_def();
    bob_def.type = RB_BODY_DYNAMIC;
    bob_def.position = rb_v2(length, 0.0);
    if (status == RB_OK) {
        status = rb_body_create(world, &bob_def, &pendulum.bob);
    }
    rb_shape_def shape_def = rb_default_shape_def();
    rb_circle circle = {{0.0, 0.0}, PENDULUM_BOB_RADIUS};
    rb_shape_id shape;
    if (status == RB_OK) {
        status = rb_shape_create_circle(world, pendulum.bob, &shape_def, &circle, &shape);
    }
    rb_revolute_joint_def pin = rb_default_revolute_joint_def();
    if (status == RB_OK) {
        status = rb_revolute_joint_def_at(&pin, world, pendulum.pivot, pendulum.bob, rb_v2(0.0, 0.0));
    }
    if (status == RB_OK) {
        status = rb_revolute_joint_create(world, &pin, &pendulum.joint);
    }
    if (status == RB_OK) {
        *out = pendulum;
    }
    return status;
}
