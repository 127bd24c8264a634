/* SPDX-License-Identifier: MIT */
/* A box on an inclined plank: the textbook check of Coulomb friction
 * (static below the friction angle atan(mu), sliding with
 * a = g·(sin θ - mu·cos θ) above it). */
#include <math.h>

#include "box_body.h"
#include "scenes/scenes.h"

#define INCLINE_MAX_ANGLE 1.4            /* rad, about 80°: steeper is a wall */
#define INCLINE_PLANK_HALF_LENGTH 10.0   /* m */
#define INCLINE_PLANK_HALF_THICKNESS 0.1 /* m */
#define INCLINE_BOX_HALF_EXTENT 0.25     /* m */
#define INCLINE_BOX_DENSITY 1.0          /* kg/m² */
#define INCLINE_BOX_DISTANCE 1.0         /* m up the slope from the origin */

rb_status scene_incline_create(rb_world *world, double angle, double friction, scene_incline *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_incline_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    /* Written so that NaN fails the test too. */
    if (!(angle >= 0.0 && angle <= INCLINE_MAX_ANGLE)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_incline_create: angle must be 0 .. %g rad, got %g",
                               INCLINE_MAX_ANGLE, angle);
    }
    if (!(friction >= 0.0 && isfinite(friction))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "scene_incline_create: friction must be finite and >= 0, got %g", friction);
    }
    rb_shape_def material = rb_default_shape_def();
    material.friction = friction;
    material.restitution = 0.0;
    material.density = INCLINE_BOX_DENSITY;

    scene_incline incline;
    /* The plank's body origin is at the world origin, turned by `angle`;
     * its box hangs one half-thickness below the body's x axis, so in the
     * body frame the top face is the line y = 0, which the rotation maps
     * onto the slope line through the origin. */
    rb_status status = scene_create_box_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), angle, INCLINE_PLANK_HALF_LENGTH,
                                             INCLINE_PLANK_HALF_THICKNESS, rb_v2(0.0, -INCLINE_PLANK_HALF_THICKNESS),
                                             &material, &incline.plank);
    if (status != RB_OK) {
        return status;
    }
    /* Up-slope unit vector u and top-face normal n of the plank, from the
     * same cos/sin the engine uses for the plank's rotation. The box has
     * the plank's angle, so its bottom face is parallel to the top face;
     * its centre one half-extent along n from the point d·u puts that
     * face exactly on the slope line, centred at distance d. */
    const rb_rot rotation = rb_rot_from_angle(angle);
    const rb_vec2 up_slope = rb_v2(rotation.c, rotation.s);
    const rb_vec2 normal = rb_left_perp(up_slope);
    const rb_vec2 contact = rb_scale(INCLINE_BOX_DISTANCE, up_slope);
    const rb_vec2 center = rb_mul_add(contact, INCLINE_BOX_HALF_EXTENT, normal);
    status = scene_create_box_body(world, RB_BODY_DYNAMIC, center, angle, INCLINE_BOX_HALF_EXTENT,
                                   INCLINE_BOX_HALF_EXTENT, rb_v2(0.0, 0.0), &material, &incline.box);
    if (status != RB_OK) {
        return status;
    }
    incline.slope_direction = rb_neg(up_slope);
    *out = incline;
    return RB_OK;
}
