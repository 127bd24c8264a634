/* SPDX-License-Identifier: MIT */
/* The control panel: model and scene pickers, the model's variant, weight
 * and level with Reload; Play/Pause and Step; the muscle-or-group picker
 * with its activation slider (0 .. 1) or tension target (N).
 */
#ifndef VIEWER_CONTROLS_PANEL_H
#define VIEWER_CONTROLS_PANEL_H

#include <gtk/gtk.h>
#include <stdbool.h>

#include "viewer.h"

controls_panel *controls_panel_new(viewer *app);
void controls_panel_free(controls_panel *panel);
GtkWidget *controls_panel_widget(const controls_panel *panel);

/* Fills the pickers from what is loaded (after every load). */
void controls_panel_sync(controls_panel *panel);
void controls_panel_show_playing(controls_panel *panel, bool playing);

/* The control named `name` (model, scene, variant, weight, level, reload,
 * play, step, muscle, activation, tension-mode, tension), or NULL. */
GtkWidget *controls_panel_control(const controls_panel *panel, const char *name);

#endif
