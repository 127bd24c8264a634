/* SPDX-License-Identifier: MIT */
/* The chain of the peer benchmarks (docs/benchmarks.md), built as
 * box2d24_bench.cpp and chipmunk_bench.c build it, so that its joint gaps
 * compare one to one: light links ending in a box 100 times heavier, the
 * classic case where an iterative solver lets the joints stretch, since
 * each pass carries the heavy box's pull only one link further. */
#include <math.h>

#include "box_body.h"
#include "scenes/scenes.h"

#define CHAIN_LINK_HALF_LENGTH 0.25    /* m, along the chain */
#define CHAIN_LINK_HALF_THICKNESS 0.05 /* m */
#define CHAIN_LINK_DENSITY 1.0         /* kg/m²: 0.05 kg a link */
#define CHAIN_HEAVY_HALF_EXTENT 0.25   /* m */
#define CHAIN_FRICTION 0.6
/* Shared by every shape of the chain: a negative group never collides
 * with itself, so neighbouring links may overlap at their pins. */
#define CHAIN_GROUP (-1)

rb_status scene_chain_create(rb_world *world, int links, double heavy_density, scene_chain_layout layout,
                             scene_chain *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_chain_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (links < 1 || links > SCENE_CHAIN_MAX_LINKS) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_chain_create: links must be 1 .. %d, got %d",
                               SCENE_CHAIN_MAX_LINKS, links);
    }
    if (!(heavy_density >= 0.0 && isfinite(heavy_density))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "scene_chain_create: heavy_density must be finite and >= 0 kg/m², got %g",
                               heavy_density);
    }
    if (layout != SCENE_CHAIN_HANG && layout != SCENE_CHAIN_SWING) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "scene_chain_create: layout must be SCENE_CHAIN_HANG or SCENE_CHAIN_SWING, got %d",
                               (int)layout);
    }
    /* The chain's direction from the pin and the bodies' angle. The peers
     * take (cos, sin) of the angle; the exact unit vectors differ from
     * those by less than 1e-7 m over the chain. */
    const double angle = layout == SCENE_CHAIN_HANG ? -0.5 * RB_PI : 0.0;
    const rb_vec2 direction = layout == SCENE_CHAIN_HANG ? rb_v2(0.0, -1.0) : rb_v2(1.0, 0.0);

    scene_chain chain = {.joint_count = 0};
    rb_body_def pin_def = rb_default_body_def();
    pin_def.type = RB_BODY_STATIC;
    rb_status status = rb_body_create(world, &pin_def, &chain.pin);
    if (status != RB_OK) {
        return status;
    }
    rb_shape_def material = rb_default_shape_def();
    material.friction = CHAIN_FRICTION;
    material.restitution = 0.0;
    material.filter.group_index = CHAIN_GROUP;

    rb_body_id previous = chain.pin;
    double previous_angle = 0.0;
    rb_vec2 previous_anchor = rb_v2(0.0, 0.0); /* on the pin: the origin */
    const int bodies = heavy_density > 0.0 ? links + 1 : links;
    for (int i = 0; i < bodies; ++i) {
        /* Body i spans [0.5·i, 0.5·(i + 1)] m from the pin along the chain;
         * the heavy box is the square of the same length after the links. */
        const bool heavy = i == links;
        const double hx = CHAIN_LINK_HALF_LENGTH;
        const double hy = heavy ? CHAIN_HEAVY_HALF_EXTENT : CHAIN_LINK_HALF_THICKNESS;
        material.density = heavy ? heavy_density : CHAIN_LINK_DENSITY;
        const double along = 2.0 * CHAIN_LINK_HALF_LENGTH * i + CHAIN_LINK_HALF_LENGTH;
        rb_body_id body;
        status = scene_create_box_body(world, RB_BODY_DYNAMIC, rb_scale(along, direction), angle, hx, hy,
                                       rb_v2(0.0, 0.0), &material, &body);
        if (status != RB_OK) {
            return status;
        }
        /* Body A is the one nearer the pin, as in the peers, so that the
         * joints are solved from the pin outwards. */
        rb_revolute_joint_def joint_def = rb_default_revolute_joint_def();
        joint_def.body_a = previous;
        joint_def.body_b = body;
        joint_def.local_anchor_a = previous_anchor;
        joint_def.local_anchor_b = rb_v2(-CHAIN_LINK_HALF_LENGTH, 0.0);
        joint_def.reference_angle = angle - previous_angle;
        status = rb_revolute_joint_create(world, &joint_def, &chain.joints[i]);
        if (status != RB_OK) {
            return status;
        }
        chain.joint_count = i + 1;
        previous = body;
        previous_angle = angle;
        previous_anchor = rb_v2(CHAIN_LINK_HALF_LENGTH, 0.0);
    }
    chain.heavy = previous;
    *out = chain;
    return RB_OK;
}
