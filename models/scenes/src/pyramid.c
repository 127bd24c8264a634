/* The pyramid of the peer benchmarks (shared/peers/README.md), built
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
    rb_shape_def material = rb_default_shape_def();
    material.friction = PYRAMID_FRICTION;
    material.restitution = 0.0;
    material.density = PYRAMID_DENSITY;

    scene_pyramid pyramid = {.box_count = 0};
    rb_status status = scene_create_box_body(world, RB_BODY_STATIC, rb_v2(0.0, -PYRAMID_GROUND_HALF_HEIGHT), 0.0,
                                             PYRAMID_GROUND_HALF_WIDTH, PYRAMID_GROUND_HALF_HEIGHT, rb_v2(0.0, 0.0),
                                             &material, &pyramid.ground);
    if (status != RB_OK) {
        return status;
    }
    const double a = PYRAMID_HALF_EXTENT;
    for (int i = 0; i < base; ++i) {
        /* Row i sits on row i - 1; each row is shifted half a box to the
         * right of the one below, so every box rests on two. */
        const double y = (2.0 * i + 1.0) * a;
        for (int j = i; j < base; ++j) {
            const double x = (i + 1.0) * a + 2.0 * (j - i) * a - a * base;
            rb_body_id box;
            status =
                scene_create_box_body(world, RB_BODY_DYNAMIC, rb_v2(x, y), 0.0, a, a, rb_v2(0.0, 0.0), &material, &box);
            if (status != RB_OK) {
                return status;
            }
            if (pyramid.box_count == 0) {
                pyramid.first_box = box;
            } else if (!scene_id_follows(pyramid.first_box, pyramid.box_count, box)) {
                return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                       "scene_pyramid_create: the world reused a destroyed body slot, so the "
                                       "boxes do not form one run of ids; build the scene in a fresh world");
            }
            pyramid.top = box;
            pyramid.box_count += 1;
        }
    }
    *out = pyramid;
    return RB_OK;
}
