/* SPDX-License-Identifier: MIT */
/* The vertical stack of boxes (scenes.h): the classic test of a solver's
 * ability to hold a tall column still (Catto, "Iterative Dynamics with
 * Temporal Coherence", GDC 2005, whose warm starting it needs). */
#include "box_body.h"
#include "scenes/scenes.h"

#define STACK_MAX_COUNT 1000
#define STACK_HALF_EXTENT 0.5 /* m */
#define STACK_FRICTION 0.6
#define STACK_DENSITY 1.0            /* kg/m² */
#define STACK_GROUND_HALF_WIDTH 20.0 /* m */
#define STACK_GROUND_HALF_HEIGHT 1.0 /* m */

rb_status scene_stack_create(rb_world *world, int count, scene_stack *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_stack_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (count < 1 || count > STACK_MAX_COUNT) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_stack_create: count must be 1 .. %d, got %d",
                               STACK_MAX_COUNT, count);
    }
    rb_shape_def material = rb_default_shape_def();
    material.friction = STACK_FRICTION;
    material.restitution = 0.0;
    material.density = STACK_DENSITY;

    scene_stack stack = {.count = count};
    /* Ground top face at y = 0: centre one half-height below it. */
    rb_status status = scene_create_box_body(world, RB_BODY_STATIC, rb_v2(0.0, -STACK_GROUND_HALF_HEIGHT), 0.0,
                                             STACK_GROUND_HALF_WIDTH, STACK_GROUND_HALF_HEIGHT, rb_v2(0.0, 0.0),
                                             &material, &stack.ground);
    if (status != RB_OK) {
        return status;
    }
    for (int i = 0; i < count; ++i) {
        /* Box i rests on box i - 1: bottom face at y = 2·0.5·i, exactly touching. */
        rb_vec2 position = rb_v2(0.0, STACK_HALF_EXTENT + 2.0 * STACK_HALF_EXTENT * i);
        rb_body_id box;
        status = scene_create_box_body(world, RB_BODY_DYNAMIC, position, 0.0, STACK_HALF_EXTENT, STACK_HALF_EXTENT,
                                       rb_v2(0.0, 0.0), &material, &box);
        if (status != RB_OK) {
            return status;
        }
        if (i == 0) {
            stack.first_box = box;
        } else if (!scene_id_follows(stack.first_box, i, box)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "scene_stack_create: the world reused a destroyed body slot, so the boxes do "
                                   "not form one run of ids; build the scene in a fresh world");
        }
        stack.top = box;
    }
    *out = stack;
    return RB_OK;
}
