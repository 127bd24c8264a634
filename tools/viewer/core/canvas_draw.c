/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "canvas_draw.h"
#include "load_arrows.h"
#include "mu/bone_stress.h"
#include "mu/joint_loads.h"
#include "stress_colours.h"

#define NAIL_RADIUS_PX 3.5
#define LINE_WIDTH_PX 1.5
#define BONE_CORNER_FRACTION 0.3 /* of the bone's shorter side */
#define WEIGHT_HOLE_FRACTION 0.25
/* The weight's disc is filled translucent under the bones and ringed
 * opaque over them: at 200 kg it is larger than the leg's shank, which it
 * hid when drawn whole on top, and at 1 kg it lies under the hand. */
#define WEIGHT_FILL_ALPHA 0.35
#define WEIGHT_RIM_WIDTH_PX 2.5
#define EXERTION_BAR_WIDTH_PX 200.0
#define EXERTION_BAR_HEIGHT_PX 14.0

const char *const canvas_overlay_names[CANVAS_OVERLAY_COUNT] = {"contacts", "normals",   "impulses", "aabbs",
                                                                "joints",   "reactions", "sleeping", "colours"};

void canvas_overlay_flags(canvas_overlays *overlays, bool *flags[CANVAS_OVERLAY_COUNT])
{
    flags[0] = &overlays->contact_points;
    flags[1] = &overlays->contact_normals;
    flags[2] = &overlays->contact_impulses;
    flags[3] = &overlays->aabbs;
    flags[4] = &overlays->joints;
    flags[5] = &overlays->joint_reactions;
    flags[6] = &overlays->sleeping;
    flags[7] = &overlays->contact_colours;
}

typedef struct rgb {
    double r, g, b;
} rgb;

static rgb from_hex(uint32_t colour)
{
    return (rgb){((colour >> 16) & 0xff) / 255.0, ((colour >> 8) & 0xff) / 255.0, (colour & 0xff) / 255.0};
}

static void set_colour(cairo_t *cr, rgb colour) { cairo_set_source_rgb(cr, colour.r, colour.g, colour.b); }

static rgb mix(rgb a, rgb b, double t)
{
    return (rgb){a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

/* Everything a drawing function needs. */
typedef struct painter {
    cairo_t *cr;
    const view_transform *view;
    const canvas_overlays *overlays;
} painter;

static rb_vec2 to_screen(const painter *p, rb_vec2 world) { return view_world_to_screen(p->view, world); }

static void move_to(const painter *p, rb_vec2 world)
{
    rb_vec2 s = to_screen(p, world);
    cairo_move_to(p->cr, s.x, s.y);
}

static void line_to(const painter *p, rb_vec2 world)
{
    rb_vec2 s = to_screen(p, world);
    cairo_line_to(p->cr, s.x, s.y);
}

/* ---- the grid ------------------------------------------------------------------ */

static void draw_grid(const painter *p)
{
    const view_transform *view = p->view;
    double spacing = CANVAS_GRID_SPACING;
    while (spacing * view->scale < CANVAS_GRID_MIN_PX) {
        spacing *= CANVAS_GRID_DIVISIONS;
    }
    rb_vec2 low = view_screen_to_world(view, rb_v2(0.0, view->height));
    rb_vec2 high = view_screen_to_world(view, rb_v2(view->width, 0.0));
    cairo_set_line_width(p->cr, 1.0);
    for (int axis = 0; axis < 2; ++axis) {
        double from = axis == 0 ? low.x : low.y, to = axis == 0 ? high.x : high.y;
        for (long k = (long)floor(from / spacing); k <= (long)ceil(to / spacing); ++k) {
            double at = k * spacing;
            bool major = k % CANVAS_GRID_DIVISIONS == 0;
            double grey = k == 0 ? 0.62 : major ? 0.80 : 0.91;
            cairo_set_source_rgb(p->cr, grey, grey, grey);
            rb_vec2 a = axis == 0 ? rb_v2(at, low.y) : rb_v2(low.x, at);
            rb_vec2 b = axis == 0 ? rb_v2(at, high.y) : rb_v2(high.x, at);
            rb_vec2 sa = to_screen(p, a), sb = to_screen(p, b);
            /* Half-pixel offsets keep one-pixel lines sharp. */
            cairo_move_to(p->cr, floor(sa.x) + 0.5, floor(sa.y) + 0.5);
            cairo_line_to(p->cr, floor(sb.x) + 0.5, floor(sb.y) + 0.5);
            cairo_stroke(p->cr);
        }
    }
}

/* ---- the engine's debug draw ---------------------------------------------------- */

static rgb debug_colour(const painter *p, uint32_t colour)
{
    if (colour == RB_COLOR_SLEEPING && !p->overlays->sleeping) {
        colour = RB_COLOR_DYNAMIC;
    }
    return from_hex(colour);
}

static void debug_polygon(const rb_vec2 *vertices, int count, uint32_t colour, void *context)
{
    const painter *p = context;
    rgb outline = debug_colour(p, colour);
    move_to(p, vertices[0]);
    for (int k = 1; k < count; ++k) {
        line_to(p, vertices[k]);
    }
    cairo_close_path(p->cr);
    /* Bounding boxes are outlines over the shapes; shapes are filled. */
    if (colour != RB_COLOR_AABB) {
        set_colour(p->cr, mix(outline, (rgb){1.0, 1.0, 1.0}, 0.5));
        cairo_fill_preserve(p->cr);
        outline = mix(outline, (rgb){0.0, 0.0, 0.0}, 0.3);
    }
    set_colour(p->cr, outline);
    cairo_set_line_width(p->cr, colour == RB_COLOR_AABB ? 1.0 : LINE_WIDTH_PX);
    cairo_stroke(p->cr);
}

static void debug_circle(rb_vec2 centre, double radius, rb_vec2 axis, uint32_t colour, void *context)
{
    const painter *p = context;
    rgb outline = debug_colour(p, colour);
    rb_vec2 s = to_screen(p, centre);
    cairo_new_sub_path(p->cr);
    cairo_arc(p->cr, s.x, s.y, radius * p->view->scale, 0.0, 2.0 * RB_PI);
    set_colour(p->cr, mix(outline, (rgb){1.0, 1.0, 1.0}, 0.5));
    cairo_fill_preserve(p->cr);
    set_colour(p->cr, mix(outline, (rgb){0.0, 0.0, 0.0}, 0.3));
    cairo_set_line_width(p->cr, LINE_WIDTH_PX);
    cairo_stroke(p->cr);
    move_to(p, centre);
    line_to(p, rb_mul_add(centre, radius, axis));
    cairo_stroke(p->cr);
}

static void debug_segment(rb_vec2 a, rb_vec2 b, uint32_t colour, void *context)
{
    const painter *p = context;
    set_colour(p->cr, mix(debug_colour(p, colour), (rgb){0.0, 0.0, 0.0}, 0.2));
    cairo_set_line_width(p->cr, LINE_WIDTH_PX);
    move_to(p, a);
    line_to(p, b);
    cairo_stroke(p->cr);
}

static void debug_point(rb_vec2 at, double size, uint32_t colour, void *context)
{
    const painter *p = context;
    rb_vec2 s = to_screen(p, at);
    set_colour(p->cr, debug_colour(p, colour));
    cairo_rectangle(p->cr, s.x - 0.5 * size, s.y - 0.5 * size, size, size);
    cairo_fill(p->cr);
}

static void draw_engine(const painter *p, const rb_world *world, bool shapes)
{
    rb_debug_draw draw = rb_default_debug_draw();
    draw.draw_polygon = debug_polygon;
    draw.draw_circle = debug_circle;
    draw.draw_segment = debug_segment;
    draw.draw_point = debug_point;
    draw.draw_shapes = shapes;
    draw.draw_aabbs = p->overlays->aabbs;
    draw.draw_contact_points = p->overlays->contact_points || p->overlays->contact_colours;
    draw.draw_contact_colours = p->overlays->contact_colours;
    draw.draw_contact_normals = p->overlays->contact_normals;
    draw.draw_contact_impulses = p->overlays->contact_impulses;
    draw.draw_joints = p->overlays->joints;
    draw.draw_joint_reactions = p->overlays->joint_reactions;
    draw.context = (void *)p;
    rb_world_draw(world, &draw);
}

/* ---- a model -------------------------------------------------------------------- */

/* Where each part of the description is among the built parts (nails,
 * then bones), -1 when not built. */
typedef struct part_map {
    int *nail_part;
    int *bone_part;
} part_map;

static bool map_parts(const mu_model *model, const mu_model_desc *desc, part_map *map)
{
    map->nail_part = malloc(sizeof(int) * (size_t)(desc->nail_count + 1));
    map->bone_part = malloc(sizeof(int) * (size_t)(desc->bone_count + 1));
    if (map->nail_part == NULL || map->bone_part == NULL) {
        free(map->nail_part);
        free(map->bone_part);
        return false;
    }
    for (int k = 0; k < desc->nail_count; ++k) {
        map->nail_part[k] = -1;
    }
    for (int k = 0; k < desc->bone_count; ++k) {
        map->bone_part[k] = -1;
    }
    for (int part = 0; part < mu_model_part_count(model); ++part) {
        mu_model_ref ref;
        if (!mu_model_desc_find(desc, mu_model_part_name(model, part), &ref)) {
            continue;
        }
        if (ref.kind == MU_MODEL_NAIL) {
            map->nail_part[ref.index] = part;
        } else if (ref.kind == MU_MODEL_BONE) {
            map->bone_part[ref.index] = part;
        }
    }
    return true;
}

static int part_of(const part_map *map, mu_model_ref ref)
{
    return ref.kind == MU_MODEL_NAIL ? map->nail_part[ref.index] : map->bone_part[ref.index];
}

/* A point given in a part's frame (from its centre), in the world now. */
static rb_vec2 part_point(const mu_model *model, int part, rb_vec2 local)
{
    rb_rot rotation = rb_rot_from_angle(mu_model_part_angle(model, part) * RB_PI / 180.0);
    return rb_add(mu_model_part_centre(model, part), rb_rotate(rotation, local));
}

static void draw_bone(const painter *p, const mu_model *model, int part, const mu_model_bone *bone)
{
    double hx = 0.5 * bone->size.x, hy = 0.5 * bone->size.y;
    double radius = BONE_CORNER_FRACTION * fmin(hx, hy) * 2.0;
    rb_vec2 centre = to_screen(p, mu_model_part_centre(model, part));
    cairo_save(p->cr);
    cairo_translate(p->cr, centre.x, centre.y);
    cairo_rotate(p->cr, -mu_model_part_angle(model, part) * RB_PI / 180.0);
    cairo_scale(p->cr, p->view->scale, p->view->scale);
    cairo_new_sub_path(p->cr);
    cairo_arc(p->cr, hx - radius, -hy + radius, radius, -RB_PI / 2.0, 0.0);
    cairo_arc(p->cr, hx - radius, hy - radius, radius, 0.0, RB_PI / 2.0);
    cairo_arc(p->cr, -hx + radius, hy - radius, radius, RB_PI / 2.0, RB_PI);
    cairo_arc(p->cr, -hx + radius, -hy + radius, radius, RB_PI, 1.5 * RB_PI);
    cairo_close_path(p->cr);
    cairo_restore(p->cr);
    set_colour(p->cr, from_hex(CANVAS_BONE));
    cairo_fill_preserve(p->cr);
    cairo_set_source_rgb(p->cr, 0.55, 0.5, 0.4);
    cairo_set_line_width(p->cr, 1.0);
    cairo_stroke(p->cr);
}

static void draw_hinge(const painter *p, const mu_model *model, const part_map *map, const mu_model_hinge *hinge)
{
    int part = part_of(map, hinge->body_a);
    if (part < 0) {
        return;
    }
    rb_vec2 centre = to_screen(p, part_point(model, part, hinge->anchor_a));
    cairo_new_sub_path(p->cr);
    cairo_arc(p->cr, centre.x, centre.y, hinge->radius * p->view->scale, 0.0, 2.0 * RB_PI);
    cairo_set_source_rgb(p->cr, 0.3, 0.3, 0.35);
    cairo_set_line_width(p->cr, LINE_WIDTH_PX);
    cairo_stroke(p->cr);
}

static void draw_dot(const painter *p, rb_vec2 world, double radius_px)
{
    rb_vec2 s = to_screen(p, world);
    cairo_new_sub_path(p->cr);
    cairo_arc(p->cr, s.x, s.y, radius_px, 0.0, 2.0 * RB_PI);
    cairo_fill(p->cr);
}

/* The muscle's colour at activation a: pale pink at 0, dark red at 1. */
static rgb activation_colour(double a)
{
    a = a < 0.0 ? 0.0 : a > 1.0 ? 1.0 : a;
    return mix((rgb){1.0, 0.82, 0.82}, (rgb){0.55, 0.0, 0.04}, a);
}

/* The point `distance` along the path, and the direction there. */
static rb_vec2 along_path(const rb_vec2 *points, int count, double distance, rb_vec2 *direction)
{
    *direction = rb_v2(1.0, 0.0);
    for (int k = 0; k + 1 < count; ++k) {
        double length = rb_distance(points[k], points[k + 1]);
        if (length > 0.0) {
            *direction = rb_scale(1.0 / length, rb_sub(points[k + 1], points[k]));
        }
        if (distance <= length || k + 2 == count) {
            return rb_mul_add(points[k], distance < length ? distance : length, *direction);
        }
        distance -= length;
    }
    return points[0];
}

static void draw_muscle(const painter *p, const rb_world *world, const mu_model *model, int index,
                        const mu_model_muscle *muscle)
{
    rb_vec2 points[RB_MAX_CABLE_POINTS];
    int count =
        rb_cable_points(world, mu_muscle_cable(mu_model_built_muscle(model, index)), points, RB_MAX_CABLE_POINTS);
    if (count < 2) {
        return;
    }
    double path = 0.0;
    for (int k = 0; k + 1 < count; ++k) {
        path += rb_distance(points[k], points[k + 1]);
    }
    /* Tendons and via points. */
    cairo_set_source_rgb(p->cr, 0.45, 0.4, 0.35);
    cairo_set_line_width(p->cr, LINE_WIDTH_PX);
    move_to(p, points[0]);
    for (int k = 1; k < count; ++k) {
        line_to(p, points[k]);
    }
    cairo_stroke(p->cr);
    for (int k = 1; k + 1 < count; ++k) {
        draw_dot(p, points[k], NAIL_RADIUS_PX - 1.0);
    }
    /* The belly: an ellipse along the path whose area stays that of the
     * resting belly, so it thickens as it shortens. */
    mu_muscle_readout readout = mu_model_muscle_readout(model, index);
    double belly = readout.length > 1e-6 ? fmin(readout.length, path) : 1e-6;
    double tendon = path - belly;
    double width = muscle->rest_width > 0.0 ? muscle->rest_width : 0.2 * muscle->rest_length;
    double half_length = 0.5 * belly;
    double half_width = fmin(0.25 * muscle->rest_length * width / half_length, 2.0 * width);
    rb_vec2 direction;
    rb_vec2 middle = along_path(points, count, muscle->symmetry * tendon + half_length, &direction);
    rb_vec2 centre = to_screen(p, middle);
    cairo_save(p->cr);
    cairo_translate(p->cr, centre.x, centre.y);
    cairo_rotate(p->cr, -atan2(direction.y, direction.x));
    cairo_scale(p->cr, half_length * p->view->scale, half_width * p->view->scale);
    cairo_new_sub_path(p->cr);
    cairo_arc(p->cr, 0.0, 0.0, 1.0, 0.0, 2.0 * RB_PI);
    cairo_restore(p->cr);
    set_colour(p->cr, activation_colour(readout.activation));
    cairo_fill_preserve(p->cr);
    cairo_set_source_rgb(p->cr, 0.4, 0.05, 0.05);
    cairo_set_line_width(p->cr, 1.0);
    cairo_stroke(p->cr);
}

typedef struct weight_search {
    const rb_world *world;
    rb_vec2 centre;
    double best_distance;
    double radius;
} weight_search;

/* Keeps the circle whose centre is nearest the weight's. */
static bool find_weight_disc(rb_shape_id shape, void *context)
{
    weight_search *search = context;
    if (rb_shape_type_of(search->world, shape) != RB_SHAPE_CIRCLE) {
        return true;
    }
    rb_circle circle = rb_shape_circle(search->world, shape);
    rb_vec2 centre = rb_body_world_point(search->world, rb_shape_body(search->world, shape), circle.center);
    double distance = rb_distance(centre, search->centre);
    if (distance < search->best_distance) {
        search->best_distance = distance;
        search->radius = circle.radius;
    }
    return true;
}

/* The weight's disc (a ring: the hole is the rod's), in two layers: its
 * fill under the bones, `rim` false, and its rim over them, `rim` true. */
static void draw_weight(const painter *p, const rb_world *world, const mu_model *model, const mu_model_desc *desc,
                        const part_map *map, bool rim)
{
    const mu_model_weight *weight = &desc->weight;
    int part = part_of(map, weight->body);
    if (!desc->has_weight || part < 0) {
        return;
    }
    /* The disc keeps the place on its carrier it had at the start. */
    rb_vec2 start_centre;
    double start_angle = 0.0;
    if (weight->body.kind == MU_MODEL_NAIL) {
        start_centre = desc->nails[weight->body.index].position;
    } else {
        start_centre = desc->bones[weight->body.index].centre;
        start_angle = desc->bones[weight->body.index].angle;
    }
    rb_vec2 local =
        rb_inv_rotate(rb_rot_from_angle(start_angle * RB_PI / 180.0), rb_sub(weight->position, start_centre));
    weight_search search = {.world = world, .centre = part_point(model, part, local), .best_distance = INFINITY};
    rb_world_query_point(world, search.centre, rb_default_query_filter(), true, find_weight_disc, &search);
    if (!(search.radius > 0.0)) {
        return;
    }
    rb_vec2 s = to_screen(p, search.centre);
    double radius = search.radius * p->view->scale;
    cairo_new_sub_path(p->cr);
    cairo_arc(p->cr, s.x, s.y, radius, 0.0, 2.0 * RB_PI);
    cairo_new_sub_path(p->cr);
    cairo_arc_negative(p->cr, s.x, s.y, WEIGHT_HOLE_FRACTION * radius, 2.0 * RB_PI, 0.0);
    rgb colour = from_hex(CANVAS_WEIGHT);
    if (rim) {
        set_colour(p->cr, colour);
        cairo_set_line_width(p->cr, WEIGHT_RIM_WIDTH_PX);
        cairo_stroke(p->cr);
    } else {
        cairo_set_source_rgba(p->cr, colour.r, colour.g, colour.b, WEIGHT_FILL_ALPHA);
        cairo_fill(p->cr);
    }
}

static void draw_exertion_bars(const painter *p, const mu_model *model)
{
    for (int k = 0; k < mu_model_torque_muscle_count(model); ++k) {
        const mu_motor_pool *pool = mu_model_motor_pool(model, k);
        double exertion = mu_motor_pool_exertion(pool);
        double x = 12.0, y = 36.0 + 24.0 * k;
        cairo_set_source_rgb(p->cr, 0.85, 0.85, 0.85);
        cairo_rectangle(p->cr, x, y, EXERTION_BAR_WIDTH_PX, EXERTION_BAR_HEIGHT_PX);
        cairo_fill(p->cr);
        cairo_set_source_rgb(p->cr, 0.75, 0.05, 0.05);
        cairo_rectangle(p->cr, x, y, EXERTION_BAR_WIDTH_PX * exertion, EXERTION_BAR_HEIGHT_PX);
        cairo_fill(p->cr);
        char text[256];
        snprintf(text, sizeof text, "%s: %d / %d neurons, exertion %.2f", mu_model_torque_muscle_name(model, k),
                 mu_motor_pool_recruited(pool), mu_motor_pool_neuron_count(pool), exertion);
        cairo_set_source_rgb(p->cr, 0.1, 0.1, 0.1);
        cairo_move_to(p->cr, x + EXERTION_BAR_WIDTH_PX + 8.0, y + EXERTION_BAR_HEIGHT_PX - 2.0);
        cairo_show_text(p->cr, text);
    }
}

/* ---- joint loads ---------------------------------------------------------------- */

#define LOAD_COLOUR 0.80, 0.35, 0.0 /* orange */

/* An arrow from `base` to `tip` (px) with its head, dashed when cut. */
static void draw_arrow(cairo_t *cr, rb_vec2 base, rb_vec2 tip, bool cut)
{
    const double length = rb_distance(base, tip);
    cairo_set_line_width(cr, 2.0);
    if (cut) {
        const double dashes[] = {6.0, 3.0};
        cairo_set_dash(cr, dashes, 2, 0.0);
    }
    cairo_move_to(cr, base.x, base.y);
    cairo_line_to(cr, tip.x, tip.y);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
    if (length < 1.0) {
        return;
    }
    const rb_vec2 back = rb_scale(fmin(8.0, 0.5 * length) / length, rb_sub(base, tip));
    const rb_vec2 side = rb_scale(0.45, rb_v2(-back.y, back.x));
    cairo_move_to(cr, tip.x, tip.y);
    cairo_line_to(cr, tip.x + back.x + side.x, tip.y + back.y + side.y);
    cairo_line_to(cr, tip.x + back.x - side.x, tip.y + back.y - side.y);
    cairo_close_path(cr);
    cairo_fill(cr);
}

/* One joint's arrow and label: "NAME 230 N, 0.0 N·m (muscles 5.7 N·m)". */
static void draw_load(const painter *p, const mu_model *model, rb_joint_id joint, const char *name, mu_joint_load load,
                      double scale)
{
    const rb_vec2 base = to_screen(p, rb_joint_world_anchor_b(mu_model_world_to_read(model), joint));
    /* Screen y points down. */
    const rb_vec2 tip = rb_add(base, rb_v2(scale * load.force.x, -scale * load.force.y));
    bool cut = false;
    const rb_vec2 end = load_arrow_clip(base, tip, p->view->width, p->view->height, &cut);
    cairo_set_source_rgb(p->cr, LOAD_COLOUR);
    draw_arrow(p->cr, base, end, cut);
    char text[256];
    snprintf(text, sizeof text, "%s %.1f N, %.2f N·m (muscles %.2f N·m)", name, hypot(load.force.x, load.force.y),
             load.torque, load.muscle_torque);
    cairo_text_extents_t extents;
    cairo_text_extents(p->cr, text, &extents);
    /* Beside the tip, kept on the canvas. */
    double x = fmin(end.x + 6.0, p->view->width - extents.x_advance - LOAD_ARROW_MARGIN_PX);
    double y = fmin(fmax(end.y - 4.0, extents.height + LOAD_ARROW_MARGIN_PX), p->view->height - LOAD_ARROW_MARGIN_PX);
    cairo_set_source_rgb(p->cr, 0.35, 0.15, 0.0);
    cairo_move_to(p->cr, fmax(x, LOAD_ARROW_MARGIN_PX), y);
    cairo_show_text(p->cr, text);
}

/* The legend: a bar of a round force at the arrows' scale. */
static void draw_load_legend(const painter *p, double scale)
{
    double length = 0.0;
    const double force = load_arrow_legend_force(scale, &length);
    const double x = 12.0, y = p->view->height - 16.0;
    cairo_set_source_rgb(p->cr, LOAD_COLOUR);
    draw_arrow(p->cr, rb_v2(x, y), rb_v2(x + length, y), false);
    char text[160];
    snprintf(text, sizeof text, "%g N: reaction on the distal bone (torques counter-clockwise)", force);
    cairo_set_source_rgb(p->cr, 0.1, 0.1, 0.1);
    cairo_move_to(p->cr, x + length + 8.0, y + 4.0);
    cairo_show_text(p->cr, text);
}

static void draw_joint_loads(const painter *p, const mu_model *model)
{
    double largest = 0.0;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        const mu_joint_load load = mu_model_hinge_load(model, h);
        largest = isnan(load.force.x) ? largest : fmax(largest, hypot(load.force.x, load.force.y));
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        const mu_joint_load load = mu_model_glue_load(model, g);
        largest = isnan(load.force.x) ? largest : fmax(largest, hypot(load.force.x, load.force.y));
    }
    const double scale = load_arrow_scale(largest);
    if (scale == 0.0) {
        return;
    }
    cairo_set_font_size(p->cr, 11.0);
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        const mu_joint_load load = mu_model_hinge_load(model, h);
        if (!isnan(load.force.x)) {
            draw_load(p, model, mu_model_hinge_joint(model, h), mu_model_hinge_name(model, h), load, scale);
        }
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        const mu_joint_load load = mu_model_glue_load(model, g);
        if (!isnan(load.force.x)) {
            draw_load(p, model, mu_model_glue_joint(model, g), mu_model_glue_name(model, g), load, scale);
        }
    }
    draw_load_legend(p, scale);
}

/* Each moving bone's stress along its axis, a strip of STRESS_PIECES
 * pieces as wide as half the bone, coloured by the use of its strength
 * at each piece's middle (stress_colours.h). */
#define STRESS_PIECES 24
static void draw_bone_stress(const painter *p, const mu_model *model, const mu_model_desc *desc)
{
    mu_bone_section sections[STRESS_PIECES];
    cairo_set_line_cap(p->cr, CAIRO_LINE_CAP_BUTT);
    for (int b = 0; b < desc->bone_count; ++b) {
        if (isnan(mu_model_bone_stress(model, b).worst.stress) ||
            mu_model_bone_sections(model, b, STRESS_PIECES, sections) != RB_OK) {
            continue; /* not built, or the ground's */
        }
        const mu_bone_beam beam = mu_model_bone_beam(model, b);
        const int part = desc->nail_count + b;
        const bool along_x = desc->bones[b].size.x >= desc->bones[b].size.y;
        const rb_vec2 axis = rb_rotate(rb_rot_from_angle(mu_model_part_angle(model, part) * RB_PI / 180.0),
                                       along_x ? rb_v2(1.0, 0.0) : rb_v2(0.0, 1.0));
        const rb_vec2 centre = mu_model_part_centre(model, part);
        const double piece = beam.length / STRESS_PIECES;
        cairo_set_line_width(p->cr, fmax(2.0, 0.5 * beam.outer_diameter * p->view->scale));
        for (int k = 0; k < STRESS_PIECES; ++k) {
            double rgb[3];
            stress_colour(sections[k].safety_factor, rgb);
            cairo_set_source_rgb(p->cr, rgb[0], rgb[1], rgb[2]);
            move_to(p, rb_add(centre, rb_scale(sections[k].s - 0.5 * piece, axis)));
            line_to(p, rb_add(centre, rb_scale(sections[k].s + 0.5 * piece, axis)));
            cairo_stroke(p->cr);
        }
    }
    cairo_set_source_rgb(p->cr, 0.1, 0.1, 0.1);
    cairo_set_font_size(p->cr, 11.0);
    cairo_move_to(p->cr, 12.0, p->view->height - 36.0);
    cairo_show_text(p->cr, "bones: stress over strength, green 0, yellow 1/2, red 1 (it would break)");
}

static void draw_model(const painter *p, const simulation *sim)
{
    const mu_model *model = sim->model;
    const mu_model_desc *desc = sim->desc;
    rb_world *world = mu_model_world(sim->model);
    part_map map;
    if (!map_parts(model, desc, &map)) {
        return;
    }
    /* The weight's fill first, the bones on it, then its rim, so that
     * both the bones and the weight show. */
    draw_weight(p, world, model, desc, &map, false);
    for (int k = 0; k < desc->bone_count; ++k) {
        if (map.bone_part[k] >= 0) {
            draw_bone(p, model, map.bone_part[k], &desc->bones[k]);
        }
    }
    draw_weight(p, world, model, desc, &map, true);
    if (p->overlays->joint_reactions) {
        draw_bone_stress(p, model, desc);
    }
    for (int k = 0; k < mu_model_hinge_count(model); ++k) {
        mu_model_ref ref;
        if (mu_model_desc_find(desc, mu_model_hinge_name(model, k), &ref) && ref.kind == MU_MODEL_HINGE) {
            draw_hinge(p, model, &map, &desc->hinges[ref.index]);
        }
    }
    for (int k = 0; k < mu_model_muscle_count(model); ++k) {
        mu_model_ref ref;
        if (mu_model_desc_find(desc, mu_model_muscle_name(model, k), &ref) && ref.kind == MU_MODEL_MUSCLE) {
            draw_muscle(p, world, model, k, &desc->muscles[ref.index]);
        }
    }
    cairo_set_source_rgb(p->cr, 0.1, 0.1, 0.1);
    for (int k = 0; k < desc->nail_count; ++k) {
        if (map.nail_part[k] >= 0) {
            draw_dot(p, mu_model_part_centre(model, map.nail_part[k]), NAIL_RADIUS_PX);
        }
    }
    /* The joints' reactions drawn here, labelled and to a legend's scale,
     * rather than as the engine's bare segments. */
    canvas_overlays overlays = *p->overlays;
    overlays.joint_reactions = false;
    const painter engine = {.cr = p->cr, .view = p->view, .overlays = &overlays};
    draw_engine(&engine, world, false);
    if (p->overlays->joint_reactions) {
        draw_joint_loads(p, model);
    }
    draw_exertion_bars(p, model);
    free(map.nail_part);
    free(map.bone_part);
}

/* ---- everything ------------------------------------------------------------------ */

static void draw_drag(const painter *p, const simulation *sim)
{
    rb_world *world = simulation_world(sim);
    if (!sim->dragging || world == NULL || !rb_joint_is_valid(world, sim->drag_joint)) {
        return;
    }
    rb_vec2 target = rb_joint_world_anchor_a(world, sim->drag_joint);
    cairo_set_source_rgb(p->cr, 0.1, 0.3, 0.8);
    cairo_set_line_width(p->cr, LINE_WIDTH_PX);
    move_to(p, rb_joint_world_anchor_b(world, sim->drag_joint));
    line_to(p, target);
    cairo_stroke(p->cr);
    draw_dot(p, target, NAIL_RADIUS_PX);
}

static void draw_clock(const painter *p, const simulation *sim)
{
    char text[128];
    snprintf(text, sizeof text, "t = %.2f s, frame %ld", simulation_time(sim), sim->frame);
    cairo_set_source_rgb(p->cr, 0.1, 0.1, 0.1);
    cairo_set_font_size(p->cr, 13.0);
    cairo_move_to(p->cr, 12.0, 22.0);
    cairo_show_text(p->cr, text);
}

void canvas_draw(cairo_t *cr, const view_transform *view, const simulation *sim, const canvas_overlays *overlays)
{
    painter p = {.cr = cr, .view = view, .overlays = overlays};
    cairo_save(cr);
    set_colour(cr, from_hex(CANVAS_BACKGROUND));
    cairo_paint(cr);
    draw_grid(&p);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    if (sim->kind == SIMULATION_MODEL) {
        draw_model(&p, sim);
    } else if (sim->kind == SIMULATION_SCENE) {
        draw_engine(&p, sim->scene.world, true);
    }
    draw_drag(&p, sim);
    if (sim->kind != SIMULATION_NONE) {
        draw_clock(&p, sim);
    }
    cairo_restore(cr);
}
