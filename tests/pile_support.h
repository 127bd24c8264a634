/* SPDX-License-Identifier: MIT */
/* The pile the contact solver's byte-for-byte tests start from: a base-20
 * pyramid (590 contacts of two points) with nine balls beside it
 * (contacts of one point), under gravity 10 m/s², never sleeping. */
#ifndef SINEW_TESTS_PILE_SUPPORT_H
#define SINEW_TESTS_PILE_SUPPORT_H

#include "scenes/scenes.h"
#include "test_support.h"

/* The pile in a new world of the given solver, not yet stepped; the
 * pyramid's boxes go to *pyramid. */
static inline rb_world *make_pile(rb_solver_type type, scene_pyramid *pyramid)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, -10.0);
    def.enable_sleep = false;
    def.solver.type = type;
    rb_world *world = NULL;
    cr_assert_eq(rb_world_create(&def, &world), RB_OK, "%s", rb_last_error());
    cr_assert_eq(scene_pyramid_create(world, 20, pyramid), RB_OK, "%s", rb_last_error());
    for (int k = 0; k < 9; ++k) {
        rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(12.0 + 1.5 * k, 0.5), 0.0);
        add_circle(world, ball, rb_v2(0.0, 0.0), 0.5, 1.0);
    }
    return world;
}

#endif
