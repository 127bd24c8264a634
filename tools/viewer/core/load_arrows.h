/* SPDX-License-Identifier: MIT */
/* The joint loads drawn on the canvas (the "reactions" overlay on a
 * model): for every hinge and every glue kept as a weld, the reaction
 * force on the distal bone (mu/joint_loads.h) as an arrow from the joint,
 * labelled with its size and the joint's torques, and a legend with the
 * arrows' scale.
 *
 * The scale is one for all arrows of a frame, so arrows compare: the
 * largest force is drawn LOAD_ARROW_MAX_PX long, the scale rounded down
 * to a 1-2-5 step of px per N so that it stays put while the loads vary
 * a little. An arrow whose tip would leave the canvas is cut at the
 * canvas's margin (its label still gives its size) and drawn dashed.
 */
#ifndef VIEWER_LOAD_ARROWS_H
#define VIEWER_LOAD_ARROWS_H

#include <stdbool.h>

#include "rb/math.h"

#define LOAD_ARROW_MAX_PX 120.0
#define LOAD_ARROW_MARGIN_PX 8.0

/* px per N for arrows whose largest force is `largest_force` (N, >= 0):
 * the largest 1-2-5 step at most LOAD_ARROW_MAX_PX / largest_force; 0
 * when there is no force. */
double load_arrow_scale(double largest_force);

/* The tip of an arrow from `base` to `tip` (px) kept within the canvas
 * (width × height px, less the margin): `tip` itself when it is inside,
 * else the point where the arrow leaves it (the base is taken as inside);
 * *cut says which. */
rb_vec2 load_arrow_clip(rb_vec2 base, rb_vec2 tip, double width, double height, bool *cut);

/* The legend's bar: a round force (N, a 1-2-5 step) drawn between 40 and
 * 100 px at `scale` px per N, and its length in px. */
double load_arrow_legend_force(double scale, double *length_px);

#endif
