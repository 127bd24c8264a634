/* SPDX-License-Identifier: MIT */
/* Debug drawing: walks the world and calls the caller's callbacks. */
#include "error.h"
#include "joint_solver.h"
#include "rb/debug_draw.h"
#include "world_internal.h"

rb_debug_draw rb_default_debug_draw(void)
{
    return (rb_debug_draw){
        .draw_shapes = true,
        .impulse_scale = 0.1,
        .normal_length = 0.1,
        .force_scale = 0.01,
    };
}

static uint32_t shape_color(const rb_body *body, const rb_shape *shape)
{
    if (shape->sensor) {
        return RB_COLOR_SENSOR;
    }
    if (!body->awake) {
        return RB_COLOR_SLEEPING;
    }
    switch (body->type) {
    case RB_BODY_STATIC:
        return RB_COLOR_STATIC;
    case RB_BODY_KINEMATIC:
        return RB_COLOR_KINEMATIC;
    case RB_BODY_DYNAMIC:
        break;
    }
    return RB_COLOR_DYNAMIC;
}

static void draw_shape(const rb_world *world, int index, const rb_debug_draw *draw)
{
    const rb_shape *shape = &world->shapes[index];
    const rb_body *body = &world->bodies[shape->body];
    rb_transform xf = rb_body_origin_transform(world, shape->body);
    uint32_t color = shape_color(body, shape);
    switch (shape->type) {
    case RB_SHAPE_CIRCLE:
        if (draw->draw_circle != NULL) {
            draw->draw_circle(rb_transform_point(xf, shape->geometry.circle.center), shape->geometry.circle.radius,
                              rb_rotate(xf.q, rb_v2(1.0, 0.0)), color, draw->context);
        }
        break;
    case RB_SHAPE_POLYGON:
        if (draw->draw_polygon != NULL) {
            rb_vec2 vertices[RB_MAX_POLYGON_VERTICES];
            const rb_polygon *polygon = &shape->geometry.polygon;
            for (int i = 0; i < polygon->count; ++i) {
                vertices[i] = rb_transform_point(xf, polygon->vertices[i]);
            }
            draw->draw_polygon(vertices, polygon->count, color, draw->context);
        }
        break;
    case RB_SHAPE_SEGMENT:
    case RB_SHAPE_CHAIN_SEGMENT:
        if (draw->draw_segment != NULL) {
            const rb_segment *segment =
                shape->type == RB_SHAPE_SEGMENT ? &shape->geometry.segment : &shape->geometry.chain_segment.segment;
            draw->draw_segment(rb_transform_point(xf, segment->point1), rb_transform_point(xf, segment->point2), color,
                               draw->context);
        }
        break;
    }
}

static void draw_aabb(rb_aabb box, const rb_debug_draw *draw)
{
    rb_vec2 corners[4] = {box.lower, {box.upper.x, box.lower.y}, box.upper, {box.lower.x, box.upper.y}};
    draw->draw_polygon(corners, 4, RB_COLOR_AABB, draw->context);
}

uint32_t rb_constraint_colour_rgb(int colour)
{
    static const uint32_t palette[RB_CONSTRAINT_PALETTE_SIZE] = {
        0xe6194b, 0x3cb44b, 0x4363d8, 0xf58231, 0x911eb4, 0x42d4f4, 0xf032e6, 0xbfef45,
    };
    if (colour == RB_OVERFLOW_COLOUR) {
        return 0xffffff;
    }
    return colour >= 0 && colour < RB_COLOUR_COUNT ? palette[colour % RB_CONSTRAINT_PALETTE_SIZE]
                                                   : RB_COLOR_CONTACT_POINT;
}

static void draw_contacts(const rb_world *world, const rb_debug_draw *draw)
{
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *contact = &world->contacts[i];
        const rb_manifold *m = &contact->manifold;
        uint32_t point_color = draw->draw_contact_colours && contact->colour >= 0
                                   ? rb_constraint_colour_rgb(contact->colour)
                                   : RB_COLOR_CONTACT_POINT;
        for (int j = 0; j < m->point_count; ++j) {
            rb_vec2 p = m->points[j].point;
            if (draw->draw_contact_points && draw->draw_point != NULL) {
                draw->draw_point(p, 5.0, point_color, draw->context);
            }
            if (draw->draw_contact_normals && draw->draw_segment != NULL) {
                draw->draw_segment(p, rb_mul_add(p, draw->normal_length, m->normal), RB_COLOR_CONTACT_NORMAL,
                                   draw->context);
            }
            if (draw->draw_contact_impulses && draw->draw_segment != NULL) {
                double length = draw->impulse_scale * m->points[j].normal_impulse;
                draw->draw_segment(p, rb_mul_add(p, length, m->normal), RB_COLOR_CONTACT_IMPULSE, draw->context);
            }
        }
    }
}

/* A revolute limit is drawn as a ray from the anchor at the limit's angle
 * in body A's frame: where body B's reference direction stops. */
static void draw_limit(const rb_world *world, const rb_joint *joint, double limit, const rb_debug_draw *draw)
{
    const rb_revolute_data *r = &joint->as.revolute;
    rb_vec2 anchor = rb_joint_anchor_a(world, joint);
    double angle = world->states[joint->body_a].angle + r->reference_angle + limit;
    draw->draw_segment(anchor, rb_mul_add(anchor, 2.0 * draw->normal_length, rb_v2(cos(angle), sin(angle))),
                       RB_COLOR_JOINT_LIMIT, draw->context);
}

/* A prismatic limit is drawn as a tick across the axis where anchor B
 * stops, normal_length long on each side. */
static void draw_slide_limit(const rb_world *world, const rb_joint *joint, double limit, const rb_debug_draw *draw)
{
    rb_vec2 axis = rb_rotate(world->states[joint->body_a].rotation, joint->as.prismatic.local_axis_a);
    rb_vec2 stop = rb_mul_add(rb_joint_anchor_a(world, joint), limit, axis);
    rb_vec2 across = rb_scale(draw->normal_length, rb_left_perp(axis));
    draw->draw_segment(rb_sub(stop, across), rb_add(stop, across), RB_COLOR_JOINT_LIMIT, draw->context);
}

/* The lines a joint type adds between its anchors: a distance or mouse
 * joint's link, a prismatic joint's slide, a pulley's rope. */
static void draw_joint_lines(const rb_world *world, const rb_joint *joint, rb_vec2 anchor_a, rb_vec2 anchor_b,
                             const rb_debug_draw *draw)
{
    switch (joint->type) {
    case RB_JOINT_DISTANCE:
    case RB_JOINT_MOUSE:
        draw->draw_segment(anchor_a, anchor_b, RB_COLOR_JOINT, draw->context);
        break;
    case RB_JOINT_PRISMATIC: {
        const rb_prismatic_data *p = &joint->as.prismatic;
        draw->draw_segment(anchor_a, anchor_b, RB_COLOR_JOINT, draw->context);
        if (p->enable_lower) {
            draw_slide_limit(world, joint, p->lower, draw);
        }
        if (p->enable_upper) {
            draw_slide_limit(world, joint, p->upper, draw);
        }
        break;
    }
    case RB_JOINT_PULLEY: {
        const rb_pulley_data *p = &joint->as.pulley;
        draw->draw_segment(p->ground_a, anchor_a, RB_COLOR_JOINT, draw->context);
        draw->draw_segment(p->ground_a, p->ground_b, RB_COLOR_JOINT, draw->context);
        draw->draw_segment(p->ground_b, anchor_b, RB_COLOR_JOINT, draw->context);
        break;
    }
    case RB_JOINT_REVOLUTE:
        if (joint->as.revolute.enable_lower) {
            draw_limit(world, joint, joint->as.revolute.lower, draw);
        }
        if (joint->as.revolute.enable_upper) {
            draw_limit(world, joint, joint->as.revolute.upper, draw);
        }
        break;
    case RB_JOINT_WELD:
        break;
    }
}

static void draw_joint(const rb_world *world, const rb_joint *joint, const rb_debug_draw *draw)
{
    rb_vec2 anchor_a = rb_joint_anchor_a(world, joint);
    rb_vec2 anchor_b = rb_joint_anchor_b(world, joint);
    if (draw->draw_joints && draw->draw_segment != NULL) {
        if (joint->body_a >= 0) {
            draw->draw_segment(world->states[joint->body_a].center, anchor_a, RB_COLOR_JOINT, draw->context);
        }
        draw->draw_segment(world->states[joint->body_b].center, anchor_b, RB_COLOR_JOINT, draw->context);
        draw_joint_lines(world, joint, anchor_a, anchor_b, draw);
    }
    if (draw->draw_joints && draw->draw_point != NULL) {
        draw->draw_point(anchor_a, 4.0, RB_COLOR_JOINT, draw->context);
        draw->draw_point(anchor_b, 4.0, RB_COLOR_JOINT, draw->context);
    }
    if (draw->draw_joint_reactions && draw->draw_segment != NULL) {
        rb_vec2 force = rb_joint_force_on_b(world, joint);
        draw->draw_segment(anchor_b, rb_mul_add(anchor_b, draw->force_scale, force), RB_COLOR_JOINT_REACTION,
                           draw->context);
    }
}

rb_status rb_world_draw(const rb_world *world, const rb_debug_draw *draw)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_world_draw", "world", world));
    RB_TRY(rb_check_pointer("rb_world_draw", "draw", draw));
    RB_TRY(rb_check_finite("rb_world_draw", "impulse_scale", draw->impulse_scale));
    RB_TRY(rb_check_finite("rb_world_draw", "normal_length", draw->normal_length));
    RB_TRY(rb_check_finite("rb_world_draw", "force_scale", draw->force_scale));
    for (int i = 0; i < world->shape_slots; ++i) {
        if (!world->shapes[i].in_use) {
            continue;
        }
        if (draw->draw_shapes) {
            draw_shape(world, i, draw);
        }
        if (draw->draw_aabbs && draw->draw_polygon != NULL) {
            draw_aabb(rb_shape_tight_aabb(world, i), draw);
        }
    }
    if (draw->draw_mass && draw->draw_transform != NULL) {
        for (int i = 0; i < world->body_slots; ++i) {
            if (world->bodies[i].in_use) {
                const rb_body_state *s = &world->states[i];
                draw->draw_transform((rb_transform){s->center, s->rotation}, draw->context);
            }
        }
    }
    draw_contacts(world, draw);
    for (int i = 0; i < world->joint_slots; ++i) {
        if (world->joints[i].in_use) {
            draw_joint(world, &world->joints[i], draw);
        }
    }
    return RB_OK;
}
