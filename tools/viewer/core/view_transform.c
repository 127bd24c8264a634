/* SPDX-License-Identifier: MIT */
#include "view_transform.h"

static double clamp_scale(double scale)
{
    if (!(scale >= VIEW_MIN_SCALE)) {
        return VIEW_MIN_SCALE;
    }
    return scale > VIEW_MAX_SCALE ? VIEW_MAX_SCALE : scale;
}

view_transform view_transform_make(rb_vec2 home_centre, double home_scale)
{
    double scale = clamp_scale(home_scale);
    return (view_transform){
        .centre = home_centre,
        .scale = scale,
        .width = 1.0,
        .height = 1.0,
        .home_centre = home_centre,
        .home_scale = scale,
    };
}

void view_transform_resize(view_transform *view, double width, double height)
{
    view->width = width;
    view->height = height;
}

rb_vec2 view_world_to_screen(const view_transform *view, rb_vec2 world)
{
    return rb_v2(0.5 * view->width + (world.x - view->centre.x) * view->scale,
                 0.5 * view->height - (world.y - view->centre.y) * view->scale);
}

rb_vec2 view_screen_to_world(const view_transform *view, rb_vec2 screen)
{
    return rb_v2(view->centre.x + (screen.x - 0.5 * view->width) / view->scale,
                 view->centre.y - (screen.y - 0.5 * view->height) / view->scale);
}

void view_zoom_about(view_transform *view, rb_vec2 anchor, double factor)
{
    if (!(factor > 0.0)) {
        return;
    }
    rb_vec2 fixed = view_screen_to_world(view, anchor);
    view->scale = clamp_scale(view->scale * factor);
    rb_vec2 moved = view_screen_to_world(view, anchor);
    view->centre = rb_add(view->centre, rb_sub(fixed, moved));
}

void view_pan(view_transform *view, rb_vec2 delta)
{
    view->centre = rb_add(view->centre, rb_v2(-delta.x / view->scale, delta.y / view->scale));
}

void view_reset(view_transform *view)
{
    view->centre = view->home_centre;
    view->scale = view->home_scale;
}
