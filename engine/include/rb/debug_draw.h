/* SPDX-License-Identifier: MIT */
/** @file
 * Debug drawing through callbacks: the engine says what to draw, the
 * caller draws it (Cairo figure, GTK viewer, a test that counts calls).
 * Every callback may be NULL. Colours are 0xRRGGBB.
 */
#ifndef RB_DEBUG_DRAW_H
#define RB_DEBUG_DRAW_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/export.h"
#include "rb/math.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rb_debug_draw {
    /** A closed convex polygon in world coordinates. */
    void (*draw_polygon)(const rb_vec2 *vertices, int count, uint32_t color, void *context);
    /** A circle; `axis` is a unit vector showing the body's rotation. */
    void (*draw_circle)(rb_vec2 center, double radius, rb_vec2 axis, uint32_t color, void *context);
    /** A line: segment shapes (in their shape colour), normals, joints. */
    void (*draw_segment)(rb_vec2 p1, rb_vec2 p2, uint32_t color, void *context);
    /** A point of `size` pixels. */
    void (*draw_point)(rb_vec2 p, double size, uint32_t color, void *context);
    /** A frame: the x axis red, the y axis green. */
    void (*draw_transform)(rb_transform xf, void *context);

    bool draw_shapes;
    bool draw_aabbs;
    bool draw_mass; /**< centre of mass as a transform */
    bool draw_contact_points;
    /** With draw_contact_points: each point in the colour its constraint
     * was solved in at the last step (rb_constraint_colour_rgb), so that
     * the graph colouring shows; contacts not solved keep
     * RB_COLOR_CONTACT_POINT. */
    bool draw_contact_colours;
    bool draw_contact_normals;
    bool draw_contact_impulses; /**< normal impulse as a segment along the normal */
    /** Anchors, segments from each body's centre to its anchor, and each
     * type's lines: a distance or mouse link, a prismatic slide from
     * anchor A to anchor B with a tick across the axis at each enabled
     * limit, a pulley's rope over its two ground anchors, revolute limit
     * rays. */
    bool draw_joints;
    bool draw_joint_reactions; /**< reaction force on body B as a segment from its anchor */
    double force_scale;        /**< m per N for reaction forces, default 0.01 */
    double impulse_scale;      /**< m per N·s for impulses, default 0.1 */
    double normal_length;      /**< m, default 0.1 */
    void *context;
} rb_debug_draw;

RB_API rb_debug_draw rb_default_debug_draw(void);

/** Colours used, so a test or a legend can name them. */
enum {
    RB_COLOR_STATIC = 0x80e080,
    RB_COLOR_KINEMATIC = 0x8080e0,
    RB_COLOR_DYNAMIC = 0xe6b380,
    RB_COLOR_SLEEPING = 0x999999,
    RB_COLOR_SENSOR = 0xe0e040,
    RB_COLOR_AABB = 0xe050e0,
    RB_COLOR_CONTACT_POINT = 0xff3030,
    RB_COLOR_CONTACT_NORMAL = 0x30a0ff,
    RB_COLOR_CONTACT_IMPULSE = 0xffff40,
    RB_COLOR_JOINT = 0x80cccc,
    RB_COLOR_JOINT_LIMIT = 0xff8040,
    RB_COLOR_JOINT_REACTION = 0xff40ff,
};

/** The colour that draws constraint colour `colour` (0 .. 63, or 64 for
 * the overflow colour): a palette of RB_CONSTRAINT_PALETTE_SIZE colours in
 * turn, white for overflow; any other value (a contact not solved, -1)
 * gets RB_COLOR_CONTACT_POINT. */
#define RB_CONSTRAINT_PALETTE_SIZE 8
RB_API uint32_t rb_constraint_colour_rgb(int colour);

RB_API rb_status rb_world_draw(const rb_world *world, const rb_debug_draw *draw);

#ifdef __cplusplus
}
#endif

#endif
