/* SPDX-License-Identifier: MIT */
/* The joint grid of the peer benchmarks (docs/benchmarks.md, after
 * Box2D v3's CreateJointGrid), built as box2d24_bench.cpp builds it: same
 * creation order of bodies and joints, hence the same order in which a
 * sequential solver visits the joints. A net hung from seven static bodies
 * in the middle of its top row: the benchmark of the joint solver at scale
 * (10,000 bodies and 19,800 joints at n = 100). */
#include "box_body.h"
#include "scenes/scenes.h"

#define GRID_MAX_N 1000
#define GRID_RADIUS 0.4  /* m */
#define GRID_DENSITY 1.0 /* kg/m² */
#define GRID_FRICTION 0.6
#define GRID_SPACING 1.0        /* m between neighbouring centres */
#define GRID_STATIC_HALF_SPAN 3 /* top-row bodies within this many columns of n/2 are static */
#define GRID_GROUP (-1)         /* shared by every circle: a negative group never collides with itself */

rb_status scene_joint_grid_create(rb_world *world, int n, scene_joint_grid *out)
{
    if (world == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_joint_grid_create: %s is NULL",
                               world == NULL ? "world" : "out");
    }
    if (n < 2 || n > GRID_MAX_N) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "scene_joint_grid_create: n must be 2 .. %d, got %d",
                               GRID_MAX_N, n);
    }
    rb_shape_def material = rb_default_shape_def();
    material.friction = GRID_FRICTION;
    material.restitution = 0.0;
    material.density = GRID_DENSITY;
    material.filter.group_index = GRID_GROUP;
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = GRID_RADIUS};
    const double half = 0.5 * GRID_SPACING;

    scene_joint_grid grid = {.n = n, .joint_count = 0};
    /* Column by column, each from the top row down, as the peers: body
     * (i, k) is then number k·n + i, its upper neighbour number - 1 and its
     * left neighbour number - n, all found with scene_body_at. */
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            const int number = k * n + i;
            rb_body_def body_def = rb_default_body_def();
            /* n / 2 in integers, as the peers compute it. */
            const bool fixed = i == 0 && k >= n / 2 - GRID_STATIC_HALF_SPAN && k <= n / 2 + GRID_STATIC_HALF_SPAN;
            body_def.type = fixed ? RB_BODY_STATIC : RB_BODY_DYNAMIC;
            body_def.position = rb_v2(GRID_SPACING * k, -GRID_SPACING * i);
            rb_body_id body;
            rb_status status = rb_body_create(world, &body_def, &body);
            if (status != RB_OK) {
                return status;
            }
            if (number == 0) {
                grid.first_body = body;
            } else if (!scene_id_follows(grid.first_body, number, body)) {
                return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                       "scene_joint_grid_create: the world reused a destroyed body slot, so the "
                                       "bodies do not form one run of ids; build the scene in a fresh world");
            }
            rb_shape_id shape;
            status = rb_shape_create_circle(world, body, &material, &circle, &shape);
            if (status != RB_OK) {
                return status;
            }
            /* The joint to the body above, then the one to the left; body A
             * is the neighbour, the anchors meet half-way. The six joints
             * between two static top-row bodies are made too (they do
             * nothing), as in Box2D's grid. */
            rb_revolute_joint_def joint_def = rb_default_revolute_joint_def();
            joint_def.body_b = body;
            rb_joint_id joint;
            if (i > 0) {
                joint_def.body_a = scene_body_at(grid.first_body, number - 1);
                joint_def.local_anchor_a = rb_v2(0.0, -half);
                joint_def.local_anchor_b = rb_v2(0.0, half);
                status = rb_revolute_joint_create(world, &joint_def, &joint);
                if (status != RB_OK) {
                    return status;
                }
                grid.joint_count += 1;
            }
            if (k > 0) {
                joint_def.body_a = scene_body_at(grid.first_body, number - n);
                joint_def.local_anchor_a = rb_v2(half, 0.0);
                joint_def.local_anchor_b = rb_v2(-half, 0.0);
                status = rb_revolute_joint_create(world, &joint_def, &joint);
                if (status != RB_OK) {
                    return status;
                }
                grid.joint_count += 1;
            }
        }
    }
    *out = grid;
    return RB_OK;
}
