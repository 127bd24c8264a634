/* SPDX-License-Identifier: MIT */
/* The viewer's state, shared by its panels: the simulation and its
 * history, the canvas's view and overlays, whether it plays, and the
 * window's widgets. Every change of what is loaded goes through the
 * functions here, which keep the panels, the graphs and the view in step
 * and show any error in the window's message bar (the program goes on).
 */
#ifndef VIEWER_VIEWER_H
#define VIEWER_VIEWER_H

#include <gtk/gtk.h>
#include <stdbool.h>

#include "canvas_draw.h"
#include "history.h"
#include "simulation.h"
#include "view_transform.h"

typedef struct controls_panel controls_panel;
typedef struct graphs_panel graphs_panel;
typedef struct engine_panel engine_panel;

typedef struct viewer {
    simulation sim;
    history samples; /* the last LIVE_GRAPH_SECONDS of the model's muscles */
    view_transform view;
    bool view_placed; /* the view has been fitted to the loaded world */
    canvas_overlays overlays;
    bool playing;
    GtkWidget *window;
    GtkWidget *canvas;
    GtkWidget *message_bar;   /* a GtkInfoBar showing the last error */
    GtkWidget *message_label; /* its text */
    controls_panel *controls;
    graphs_panel *graphs;
    engine_panel *engine;
    GMainLoop *loop; /* runs until the window closes or a script quits */
    int exit_status;
    /* Model or scene loads that failed, and the last one's message: a
     * script fails at the line whose load failed. */
    int load_failures;
    char load_error[SIMULATION_ERROR_SIZE];
} viewer;

/* Shows `message` in the window's message bar (and on stderr), or hides
 * the bar for NULL. */
void viewer_show_error(viewer *app, const char *message);

/* Fits the view to what is loaded and to the canvas's size, when the
 * canvas has one (else view_placed stays false and the next draw does it). */
void viewer_place_view(viewer *app);

/* Loads a model or a scene; on failure the previous one stays and the
 * error is shown. */
bool viewer_load_model(viewer *app, const char *argument, const mu_model_options *options);
bool viewer_reload_model(viewer *app, const mu_model_options *options);
bool viewer_load_scene(viewer *app, scene_kind kind);

/* One frame of the simulation, its sample recorded and the view redrawn;
 * an error pauses the simulation and is shown. */
bool viewer_step(viewer *app);
/* Play or pause (the controls panel shows which). */
void viewer_set_playing(viewer *app, bool playing);
/* Redraws the canvas, and the graphs and engine statistics. */
void viewer_refresh(viewer *app);
/* The controlled muscle or group changed: the graphs follow it. */
void viewer_target_changed(viewer *app);

#endif
