/* SPDX-License-Identifier: MIT */
/* The graph panel: the four live graphs of the model's last seconds
 * (live_graph.h), each with an Export button that writes its channels as
 * CSV to a file chosen in a file chooser.
 */
#ifndef VIEWER_GRAPHS_PANEL_H
#define VIEWER_GRAPHS_PANEL_H

#include <gtk/gtk.h>
#include <stdbool.h>
#include <stddef.h>

#include "live_graph.h"
#include "viewer.h"

graphs_panel *graphs_panel_new(viewer *app);
void graphs_panel_free(graphs_panel *panel);
GtkWidget *graphs_panel_widget(const graphs_panel *panel);

/* Picks each graph's channels again (after a load or a new target). */
void graphs_panel_select(graphs_panel *panel);
void graphs_panel_redraw(graphs_panel *panel);
/* The Export button of a graph, named "export-" and the graph's file
 * stem ("export-activation", "export-tension", "export-selected_forces",
 * "export-contraction"), or NULL. */
GtkWidget *graphs_panel_control(const graphs_panel *panel, const char *name);
/* What the Export button does once a path is chosen. */
bool graphs_panel_export(graphs_panel *panel, live_graph_kind kind, const char *path, char *error, size_t error_size);

#endif
