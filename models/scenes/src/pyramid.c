/* SPDX-License-Identifier: MIT */
/* The pyramid of the peer benchmarks (docs/benchmarks.md), built
 * exactly as box2d24_bench.cpp and chipmunk_bench.c build it so that
 * timings and figures compare one to one. Every coordinate is a multiple
 * of 0.5 with a small integer numerator, hence exact in float and double:
 * the peers' float arithmetic and ours give the same positions. */
#include "box_body.h"
#include "scenes/scenes.h"

#define PYRAMID_MAX_BASE 1000
#define PYRAMID_HALF_EXTENT 0.5 /* m, the peers' `a` */
#define PYRAMID_FRICTION 0.6
#define PYRAMID_DENSITY 1.0             /* kg/m² */
#define PYRAMID_GROUND_HALF_WIDTH 100.0 /* m */
#define PYRAMID_GROUND_HALF_HEIGHT 1.0  /* m */

/* Adds the boxes of a pyramid of `base` centred at x = centre_x to
 * `pyramid`, which counts them and keeps the first and the top. */
static rb_status add_pyramid_boxes(rb_world *world, int base, double centre_x, const rb_shape_def *material,
                                   scene_pyramid *pyramid, const char *function)
{
    const double a = PYRAMID_HALF_EXTENT;
    for (int i = 0; i < base; ++i) {
        /* Row i sits on row i - 1; each row is shifted half a box to the
         * right of the one below, so every box rests on two. */
        const double y = (2.0 * i + 1.0) * a;
        for (int j = i; j < base; ++j) {
            const double x = centre_x + (i + 1.0) * a + 2.0 * (j - i) * a - a * base;
            rb_body_id box;
            rb_status status =
                scene_create_box_body(world, RB_BODY_DYNAMIC, rb_v2(x, y), 0.0, a, a, rb_v2(0.0, 0.0), material, &box);
            if (status != RB_OK) {
                return status;
            }
            if (pyramid->box_count == 0) {
                pyramid->first_box = box;
            } else if (!scene_id_follows(pyramid->first_box, pyramid->box_count, box)) {
                return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                       "%s: the world reused a destroyed body slot, so the "
                                       "boxes do not form one run of ids; build the scene in a fresh world",
                                       function);
            }
            pyramid->top = box;
            pyramid->box_count += 1;
        }
    }
    return RB_OK;
}

static rb_shape_def pyramid_material(void)
{
    rb_shape_def material = rb_default_shape_def();
    material.friction = PYRAMID_FRICTION;
    material.restitution = 0.0;
    material.density = PYRAMID_DENSITY;
    return material;
}

rb_status scene_pyramid_create(rb_world *world, int base, scene_pyramid *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_pyramid_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (base < 1 || base > PYRAMID_MAX_BASE) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_pyramid_create: base must be 1 .. %d, got %d",
                               PYRAMID_MAX_BASE, base);
    }
    rb_shape_def material = pyramid_material();
    scene_pyramid pyramid = {.box_count = 0};
    rb_status status = scene_create_box_body(world, RB_BODY_STATIC, rb_v2(0.0, -PYRAMID_GROUND_HALF_HEIGHT), 0.0,
                                             PYRAMID_GROUND_HALF_WIDTH, PYRAMID_GROUND_HALF_HEIGHT, rb_v2(0.0, 0.0),
                                             &material, &pyramid.ground);
    if (status == RB_OK) {
        status = add_pyramid_boxes(world, base, 0.0, &material, &pyramid, "scene_pyramid_create");
    }
    if (status == RB_OK) {
        *out = pyramid;
    }
    return status;
}

rb_status scene_many_pyramids_create(rb_world *world, int count, int base, scene_pyramid *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_many_pyramids_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (count < 1 || count > SCENE_MANY_PYRAMIDS_MAX) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_many_pyramids_create: count must be 1 .. %d, got %d",
                               SCENE_MANY_PYRAMIDS_MAX, count);
    }
    if (base < 1 || base > SCENE_MANY_PYRAMIDS_MAX_BASE) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_many_pyramids_create: base must be 1 .. %d, got %d",
                               SCENE_MANY_PYRAMIDS_MAX_BASE, base);
    }
    rb_shape_def material = pyramid_material();
    scene_pyramid pyramids = {.box_count = 0};
    /* Pyramid k is centred at x = k·(base + 1), so neighbours stand one
     * box width apart; the ground reaches a box width past either end. */
    const double spacing = base + 1.0;
    const double half_width = 0.5 * (count * spacing + 1.0);
    rb_status status = scene_create_box_body(
        world, RB_BODY_STATIC, rb_v2(0.5 * (count - 1) * spacing, -PYRAMID_GROUND_HALF_HEIGHT), 0.0, half_width,
        PYRAMID_GROUND_HALF_HEIGHT, rb_v2(0.0, 0.0), &material, &pyramids.ground);
    for (int k = 0; status == RB_OK && k < count; ++k) {
        status = add_pyramid_boxes(world, base, k * spacing, &material, &pyramids, "scene_many_pyramids_create");
    }
    if (status == RB_OK) {
        *out = pyramids;
    }
    return status;
}
