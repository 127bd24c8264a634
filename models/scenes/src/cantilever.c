/* SPDX-License-Identifier: MIT */
/* Two planks welded end to end out from a wall: the static check of a
 * rigid weld. Each weld must carry the weight beyond it and its moment,
 * and the tip may sag only as far as the solver lets the welds give. */
#include "box_body.h"
#include "scenes/scenes.h"

#define CANTILEVER_WALL_HALF_WIDTH 0.1   /* m */
#define CANTILEVER_WALL_HALF_HEIGHT 1.0  /* m */
#define CANTILEVER_PLANK_HALF_LENGTH 0.5 /* m */
#define CANTILEVER_PLANK_HALF_HEIGHT 0.1 /* m */
#define CANTILEVER_PLANK1_DENSITY 1.0    /* kg/m²: 0.2 kg */
#define CANTILEVER_PLANK2_DENSITY 2.0    /* kg/m²: 0.4 kg */

/* Welds `inner` (body A) and `outer` (body B) at the world point `at`. */
static rb_status weld(rb_world *world, rb_body_id inner, rb_body_id outer, rb_vec2 at, rb_joint_id *out)
{
    rb_weld_joint_def def = rb_default_weld_joint_def();
    rb_status status = rb_weld_joint_def_at(&def, world, inner, outer, at);
    return status == RB_OK ? rb_weld_joint_create(world, &def, out) : status;
}

rb_status scene_cantilever_create(rb_world *world, scene_cantilever *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_cantilever_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    scene_cantilever cantilever;
    rb_shape_def material = rb_default_shape_def();
    const double plank_length = 2.0 * CANTILEVER_PLANK_HALF_LENGTH;
    rb_status status = scene_create_box_body(world, RB_BODY_STATIC, rb_v2(-CANTILEVER_WALL_HALF_WIDTH, 0.0), 0.0,
                                             CANTILEVER_WALL_HALF_WIDTH, CANTILEVER_WALL_HALF_HEIGHT, rb_v2(0.0, 0.0),
                                             &material, &cantilever.wall);
    if (status != RB_OK) {
        return status;
    }
    material.density = CANTILEVER_PLANK1_DENSITY;
    status = scene_create_box_body(world, RB_BODY_DYNAMIC, rb_v2(CANTILEVER_PLANK_HALF_LENGTH, 0.0), 0.0,
                                   CANTILEVER_PLANK_HALF_LENGTH, CANTILEVER_PLANK_HALF_HEIGHT, rb_v2(0.0, 0.0),
                                   &material, &cantilever.plank1);
    if (status != RB_OK) {
        return status;
    }
    material.density = CANTILEVER_PLANK2_DENSITY;
    status = scene_create_box_body(world, RB_BODY_DYNAMIC, rb_v2(plank_length + CANTILEVER_PLANK_HALF_LENGTH, 0.0), 0.0,
                                   CANTILEVER_PLANK_HALF_LENGTH, CANTILEVER_PLANK_HALF_HEIGHT, rb_v2(0.0, 0.0),
                                   &material, &cantilever.plank2);
    if (status != RB_OK) {
        return status;
    }
    status = weld(world, cantilever.wall, cantilever.plank1, rb_v2(0.0, 0.0), &cantilever.root);
    if (status == RB_OK) {
        status = weld(world, cantilever.plank1, cantilever.plank2, rb_v2(plank_length, 0.0), &cantilever.tip);
    }
    if (status != RB_OK) {
        return status;
    }
    *out = cantilever;
    return RB_OK;
}
