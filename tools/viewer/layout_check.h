/* SPDX-License-Identifier: MIT */
/* Whether a window shows every one of its controls and graphs: each
 * widget lies within its parent's allocation, so nothing is cut off by a
 * pane or the window's edge, except the content of a scrolled window,
 * which may be larger than its view as long as the scrollbar that
 * reaches it is shown (not an overlay scrollbar, which appears only
 * while the pointer moves over it). Controls (buttons, drop-downs, spin
 * buttons, sliders, check buttons, labels) and drawing areas are checked
 * whole, not their inner parts, and popovers not at all (they are
 * windows of their own, shown on demand).
 *
 * What the script command `visible` (script.h) runs, so that a test can
 * check the viewer's layout at a window size without reading pixels.
 */
#ifndef VIEWER_LAYOUT_CHECK_H
#define VIEWER_LAYOUT_CHECK_H

#include <gtk/gtk.h>
#include <stdbool.h>
#include <stddef.h>

/* Checks every visible widget of `window` (allocated: call after it has
 * been drawn); counts them in *checked. Returns false at the first cut
 * one, with `error` naming it, its parent and by how much it passes the
 * parent's edge, px. */
bool layout_check_window(GtkWidget *window, int *checked, char *error, size_t error_size);

#endif
