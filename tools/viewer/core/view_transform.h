/* SPDX-License-Identifier: MIT */
/* The canvas's view: which part of the world (m, y up) the widget (px,
 * y down) shows. A uniform scale in px per metre and the world point at
 * the widget's centre; zooming keeps the world point under the cursor in
 * place, panning moves the centre by a drag of the background.
 */
#ifndef VIEWER_VIEW_TRANSFORM_H
#define VIEWER_VIEW_TRANSFORM_H

#include "rb/math.h"

/* Bounds of the zoom, px per metre: from a 100 m pyramid on a small
 * window down to a tenth of a millimetre across a pixel. */
#define VIEW_MIN_SCALE 2.0
#define VIEW_MAX_SCALE 1e5

typedef struct view_transform {
    rb_vec2 centre;       /* m, the world point at the widget's centre */
    double scale;         /* px per m */
    double width, height; /* px, the widget's size */
    rb_vec2 home_centre;  /* what a reset returns to */
    double home_scale;
} view_transform;

/* A view of `home_centre` at `home_scale` px/m (clamped to the bounds). */
view_transform view_transform_make(rb_vec2 home_centre, double home_scale);
void view_transform_resize(view_transform *view, double width, double height);

rb_vec2 view_world_to_screen(const view_transform *view, rb_vec2 world);
rb_vec2 view_screen_to_world(const view_transform *view, rb_vec2 screen);

/* Multiplies the scale by `factor` (> 0; the result clamped to the
 * bounds), keeping the world point under the screen point `anchor` there. */
void view_zoom_about(view_transform *view, rb_vec2 anchor, double factor);
/* Moves the view so that the world follows a drag of `delta` px. */
void view_pan(view_transform *view, rb_vec2 delta);
/* Back to the home centre and scale. */
void view_reset(view_transform *view);

#endif
