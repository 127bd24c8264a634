/* SPDX-License-Identifier: MIT */
/* Building block shared by the scenes: a body carrying one box shape.
 * Private to the scenes library.
 */
#ifndef SCENES_BOX_BODY_H
#define SCENES_BOX_BODY_H

#include <stdbool.h>

#include "rb/rb.h"

/* Creates a body of `type` whose origin is at `position` (m) turned by
 * `angle` (rad), with one box of half-extents hx, hy (m, > 0) centred at
 * `offset` (m, body frame, unrotated) and the material of `shape_def`.
 * On failure the engine's message is kept and the body, if it was made,
 * stays in the world. */
rb_status scene_create_box_body(rb_world *world, rb_body_type type, rb_vec2 position, double angle, double hx,
                                double hy, rb_vec2 offset, const rb_shape_def *shape_def, rb_body_id *out);

/* Whether `id` is the k-th of a run of bodies starting at `first`, as
 * scene_body_at() would rebuild it. The stack and pyramid promise that
 * their boxes form such a run, which holds in a world without destroyed
 * bodies (the engine then hands out fresh slots in order). */
bool scene_id_follows(rb_body_id first, int k, rb_body_id id);

#endif
