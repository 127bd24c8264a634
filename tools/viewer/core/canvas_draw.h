/* SPDX-License-Identifier: MIT */
/* Draws what the viewer simulates onto a cairo_t, in the view's pixels:
 * the grid; a model's bones (ivory rounded boxes), nails (dots), hinges
 * (circles), muscles (ellipses of constant area coloured from pale pink
 * to dark red by activation, on their tendon and via-point lines), the
 * weight (a blue disc with a hole, its fill translucent under the bones
 * and its rim opaque over them: both show) and the worm's exertion bar; an engine
 * scene through the engine's debug draw; the overlays chosen in the
 * engine panel over either (on a model, the "reactions" overlay draws the
 * joint loads as labelled arrows to a legend's scale: load_arrows.h). Pure Cairo: the GTK canvas and the headless
 * screenshot both call it.
 */
#ifndef VIEWER_CANVAS_DRAW_H
#define VIEWER_CANVAS_DRAW_H

#include <cairo.h>
#include <stdbool.h>

#include "simulation.h"
#include "view_transform.h"

/* Colours (0xRRGGBB) a test may look for in a screenshot. */
enum {
    CANVAS_BACKGROUND = 0xfbfbf7,
    CANVAS_BONE = 0xf3ead2,   /* ivory */
    CANVAS_WEIGHT = 0x3366cc, /* iron, drawn blue: the weight's rim (its fill is translucent) */
};

/* What the engine's debug draw adds on top (rb_debug_draw's flags). */
typedef struct canvas_overlays {
    bool contact_points;
    bool contact_normals;
    bool contact_impulses;
    bool aabbs;
    bool joints;          /* anchors and links: a gap between a joint's anchors is its error */
    bool joint_reactions; /* reaction forces */
    bool sleeping;        /* sleeping bodies in grey; otherwise drawn as the awake ones */
    /* contact points in the colour their constraint was solved in: the
     * graph colouring (no two constraints of a colour share a moving body) */
    bool contact_colours;
} canvas_overlays;

/* The overlays one by one, in the order above, for panels and scripts:
 * "contacts", "normals", "impulses", "aabbs", "joints", "reactions",
 * "sleeping", "colours". */
enum { CANVAS_OVERLAY_COUNT = 8 };
extern const char *const canvas_overlay_names[CANVAS_OVERLAY_COUNT];
/* Points flags[k] at the k-th flag of `overlays`. */
void canvas_overlay_flags(canvas_overlays *overlays, bool *flags[CANVAS_OVERLAY_COUNT]);

/* The grid's finest spacing (m) and how many of its cells make a major
 * cell; coarser spacings (× 10) are used while the finest would be
 * closer than CANVAS_GRID_MIN_PX pixels. */
#define CANVAS_GRID_SPACING 0.05
#define CANVAS_GRID_DIVISIONS 10
#define CANVAS_GRID_MIN_PX 8.0

void canvas_draw(cairo_t *cr, const view_transform *view, const simulation *sim, const canvas_overlays *overlays);

#endif
