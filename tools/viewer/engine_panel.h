/* SPDX-License-Identifier: MIT */
/* The engine panel: the world's solver (type, velocity and position
 * iterations, substeps, warm starting) changed live, the canvas's
 * overlays (contacts, normals, impulses, bounding boxes, joints and their
 * errors, reactions, sleeping bodies), and the profile and statistics of
 * the last step.
 */
#ifndef VIEWER_ENGINE_PANEL_H
#define VIEWER_ENGINE_PANEL_H

#include <gtk/gtk.h>

#include "viewer.h"

engine_panel *engine_panel_new(viewer *app);
void engine_panel_free(engine_panel *panel);
GtkWidget *engine_panel_widget(const engine_panel *panel);

/* Shows the loaded world's solver settings (after every load). */
void engine_panel_sync(engine_panel *panel);
/* Shows the last step's profile and statistics. */
void engine_panel_update(engine_panel *panel);

/* The control named `name` (solver, velocity-iterations,
 * position-iterations, substeps, warm-starting, or an overlay by its name
 * in canvas_overlay_names), or NULL. */
GtkWidget *engine_panel_control(const engine_panel *panel, const char *name);

#endif
