/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>

#include "controls_panel.h"
#include "engine_panel.h"
#include "graphs_panel.h"
#include "live_graph.h"
#include "viewer.h"

/* How much of a model the view's shorter side starts showing at least,
 * m: the arm and the leg are about 0.7 m long, and the arm swings down
 * that far below its shoulder. */
#define MODEL_VIEW_EXTENT 1.5

void viewer_show_error(viewer *app, const char *message)
{
    if (message == NULL) {
        gtk_widget_set_visible(app->message_bar, FALSE);
        return;
    }
    fprintf(stderr, "sinew view: %s\n", message);
    gtk_label_set_text(GTK_LABEL(app->message_label), message);
    gtk_widget_set_visible(app->message_bar, TRUE);
}

/* A model's view is its parts' box; a scene has its own framing. */
void viewer_place_view(viewer *app)
{
    double width = gtk_widget_get_width(app->canvas), height = gtk_widget_get_height(app->canvas);
    if (width <= 1.0 || height <= 1.0) {
        app->view_placed = false;
        return;
    }
    rb_vec2 centre = rb_v2(0.0, 0.0);
    double extent = MODEL_VIEW_EXTENT;
    if (app->sim.kind == SIMULATION_SCENE) {
        centre = app->sim.scene.view_centre;
        extent = app->sim.scene.view_extent;
    } else if (app->sim.kind == SIMULATION_MODEL && mu_model_part_count(app->sim.model) > 0) {
        rb_vec2 low = mu_model_part_centre(app->sim.model, 0), high = low;
        for (int k = 1; k < mu_model_part_count(app->sim.model); ++k) {
            low = rb_vmin(low, mu_model_part_centre(app->sim.model, k));
            high = rb_vmax(high, mu_model_part_centre(app->sim.model, k));
        }
        centre = rb_scale(0.5, rb_add(low, high));
        extent = fmax(MODEL_VIEW_EXTENT, 1.6 * fmax(high.x - low.x, high.y - low.y));
    }
    app->view = view_transform_make(centre, fmin(width, height) / extent);
    view_transform_resize(&app->view, width, height);
    app->view_placed = true;
}

static void after_load(viewer *app)
{
    /* The engine panel shows the profile of every step. */
    rb_world_enable_profile(simulation_world(&app->sim), true);
    int muscles = app->sim.kind == SIMULATION_MODEL ? mu_model_muscle_count(app->sim.model) : 0;
    muscles = muscles < CHART_MAX_SERIES ? muscles : CHART_MAX_SERIES; /* the graphs show no more */
    long capacity = (long)ceil(LIVE_GRAPH_SECONDS / simulation_frame_duration(&app->sim)) + 1;
    history_free(&app->samples);
    if (!history_init(&app->samples, muscles, capacity)) {
        viewer_show_error(app, "out of memory for the graphs' history");
    }
    viewer_place_view(app);
    controls_panel_sync(app->controls);
    engine_panel_sync(app->engine);
    graphs_panel_select(app->graphs);
    viewer_refresh(app);
}

/* Shows a load's error and counts it for a script. */
static void note_load_failure(viewer *app, const char *error)
{
    viewer_show_error(app, error);
    snprintf(app->load_error, sizeof app->load_error, "%s", error);
    ++app->load_failures;
}

/* After a model load or reload: the error in the window and the panels
 * back to the model still loaded, or the new model shown. */
static bool finish_model_load(viewer *app, bool loaded, const char *error)
{
    if (!loaded) {
        note_load_failure(app, error);
        controls_panel_sync(app->controls);
        return false;
    }
    viewer_show_error(app, NULL);
    after_load(app);
    return true;
}

bool viewer_load_model(viewer *app, const char *argument, const mu_model_options *options)
{
    char error[SIMULATION_ERROR_SIZE];
    return finish_model_load(app, simulation_load_model(&app->sim, argument, options, error, sizeof error), error);
}

bool viewer_reload_model(viewer *app, const mu_model_options *options)
{
    char error[SIMULATION_ERROR_SIZE];
    return finish_model_load(app, simulation_reload(&app->sim, options, error, sizeof error), error);
}

bool viewer_load_scene(viewer *app, scene_kind kind)
{
    char error[SIMULATION_ERROR_SIZE];
    if (!simulation_load_scene(&app->sim, kind, error, sizeof error)) {
        note_load_failure(app, error);
        return false;
    }
    viewer_show_error(app, NULL);
    after_load(app);
    return true;
}

static void record_sample(viewer *app)
{
    if (app->sim.kind != SIMULATION_MODEL || app->samples.capacity == 0) {
        return;
    }
    mu_muscle_readout readouts[CHART_MAX_SERIES];
    for (int m = 0; m < app->samples.muscle_count; ++m) {
        readouts[m] = mu_model_muscle_readout(app->sim.model, m);
    }
    history_record(&app->samples, simulation_time(&app->sim), readouts);
}

bool viewer_step(viewer *app)
{
    char error[SIMULATION_ERROR_SIZE];
    if (!simulation_step(&app->sim, error, sizeof error)) {
        viewer_set_playing(app, false);
        viewer_show_error(app, error);
        return false;
    }
    const char *failure = simulation_new_failure(&app->sim);
    if (failure != NULL) {
        /* Said once, in the message bar and on stderr; the run goes on. */
        char message[SIMULATION_ERROR_SIZE];
        snprintf(message, sizeof message, "the run failed: %s", failure);
        viewer_show_error(app, message);
        fprintf(stderr, "sinew view: warning: %s\n", message);
    }
    record_sample(app);
    return true;
}

void viewer_set_playing(viewer *app, bool playing)
{
    app->playing = playing;
    controls_panel_show_playing(app->controls, playing);
}

void viewer_refresh(viewer *app)
{
    gtk_widget_queue_draw(app->canvas);
    graphs_panel_redraw(app->graphs);
    engine_panel_update(app->engine);
}

void viewer_target_changed(viewer *app)
{
    graphs_panel_select(app->graphs);
    graphs_panel_redraw(app->graphs);
}
