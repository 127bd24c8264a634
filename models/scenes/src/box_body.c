/* SPDX-License-Identifier: MIT */
/* A body with one box shape: the brick of the stack, the pyramid, the
 * incline and the grounds. */
#include "box_body.h"
#include "scenes/scenes.h"

rb_status scene_create_box_body(rb_world *world, rb_body_type type, rb_vec2 position, double angle, double hx,
                                double hy, rb_vec2 offset, const rb_shape_def *shape_def, rb_body_id *out)
{
    rb_polygon box;
    rb_status status = rb_make_offset_box(hx, hy, offset, 0.0, &box);
    if (status != RB_OK) {
        return status;
    }
    rb_body_def body_def = rb_default_body_def();
    body_def.type = type;
    body_def.position = position;
    body_def.angle = angle;
    rb_body_id body;
    status = rb_body_create(world, &body_def, &body);
    if (status != RB_OK) {
        return status;
    }
    rb_shape_id shape;
    status = rb_shape_create_polygon(world, body, shape_def, &box, &shape);
    if (status != RB_OK) {
        return status;
    }
    *out = body;
    return RB_OK;
}

bool scene_id_follows(rb_body_id first, int k, rb_body_id id) { return rb_body_id_equals(scene_body_at(first, k), id); }
