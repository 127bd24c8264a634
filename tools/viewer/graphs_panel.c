/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <string.h>

#include "graphs_panel.h"
#include "io/provenance.h"

/* One graph's drawing area and what it shows. */
typedef struct graph_view {
    graphs_panel *panel;
    live_graph graph;
    GtkWidget *area;
    GtkWidget *export_button;
} graph_view;

struct graphs_panel {
    viewer *app;
    GtkWidget *grid;
    graph_view views[LIVE_GRAPH_COUNT];
};

static void draw_graph(GtkDrawingArea *area, cairo_t *cr, int width, int height, gpointer data)
{
    (void)area;
    graph_view *view = data;
    char error[CHART_ERROR_SIZE];
    if (!live_graph_draw(&view->graph, &view->panel->app->samples, cr, width, height, error, sizeof error)) {
        cairo_set_source_rgb(cr, 0.6, 0.0, 0.0);
        cairo_move_to(cr, 8.0, 20.0);
        cairo_show_text(cr, error);
    }
}

/* The sidecar's settings (io/provenance.h): the graph and the model as
 * built (only a model's muscles give a graph data to export). NULL when
 * out of memory. */
static json_t *export_settings(simulation *sim, live_graph_kind kind)
{
    json_t *settings = json_pack("{s:s, s:f}", "graph", live_graph_file_stem(kind), "frame_rate_hz",
                                 1.0 / simulation_frame_duration(sim));
    if (settings != NULL && sim->kind == SIMULATION_MODEL) {
        json_t *model = provenance_model_settings(sim->model, &sim->options);
        if (model == NULL || json_object_update(settings, model) != 0 ||
            json_object_set_new(settings, "model_argument", json_string(sim->model_argument)) != 0) {
            json_decref(settings);
            settings = NULL;
        }
        json_decref(model);
    }
    return settings;
}

bool graphs_panel_export(graphs_panel *panel, live_graph_kind kind, const char *path, char *error, size_t error_size)
{
    json_t *settings = export_settings(&panel->app->sim, kind);
    if (settings == NULL) {
        snprintf(error, error_size, "out of memory");
        return false;
    }
    if (!live_graph_write_csv(&panel->views[kind].graph, &panel->app->samples, path, error, error_size)) {
        json_decref(settings);
        return false;
    }
    return provenance_write_sidecar(path, settings, error, error_size);
}

static void on_export_chosen(GtkNativeDialog *dialog, int response, gpointer data)
{
    graph_view *view = data;
    if (response == GTK_RESPONSE_ACCEPT) {
        GFile *file = gtk_file_chooser_get_file(GTK_FILE_CHOOSER(dialog));
        char *path = file != NULL ? g_file_get_path(file) : NULL;
        char error[CHART_ERROR_SIZE];
        if (path == NULL) {
            viewer_show_error(view->panel->app, "the chosen file has no local path");
        } else if (!graphs_panel_export(view->panel, view->graph.kind, path, error, sizeof error)) {
            viewer_show_error(view->panel->app, error);
        } else {
            viewer_show_error(view->panel->app, NULL);
        }
        g_free(path);
        if (file != NULL) {
            g_object_unref(file);
        }
    }
    g_object_unref(dialog);
}

static void on_export(GtkButton *button, gpointer data)
{
    (void)button;
    graph_view *view = data;
    GtkFileChooserNative *dialog = gtk_file_chooser_native_new(
        "Export graph as CSV", GTK_WINDOW(view->panel->app->window), GTK_FILE_CHOOSER_ACTION_SAVE, "Export", "Cancel");
    char *name = g_strdup_printf("%s.csv", live_graph_file_stem(view->graph.kind));
    gtk_file_chooser_set_current_name(GTK_FILE_CHOOSER(dialog), name);
    g_free(name);
    g_signal_connect(dialog, "response", G_CALLBACK(on_export_chosen), view);
    gtk_native_dialog_show(GTK_NATIVE_DIALOG(dialog));
}

graphs_panel *graphs_panel_new(viewer *app)
{
    graphs_panel *panel = g_new0(graphs_panel, 1);
    panel->app = app;
    panel->grid = gtk_grid_new();
    gtk_grid_set_row_spacing(GTK_GRID(panel->grid), 4);
    gtk_grid_set_column_spacing(GTK_GRID(panel->grid), 4);
    for (int k = 0; k < LIVE_GRAPH_COUNT; ++k) {
        graph_view *view = &panel->views[k];
        view->panel = panel;
        view->graph.kind = (live_graph_kind)k;
        view->area = gtk_drawing_area_new();
        /* Its least size: two rows of graphs and their Export buttons
         * take about 360 px, which the window's left pane keeps for them
         * (viewer_main.c). */
        gtk_widget_set_size_request(view->area, 320, 140);
        gtk_widget_set_hexpand(view->area, TRUE);
        gtk_widget_set_vexpand(view->area, TRUE);
        gtk_drawing_area_set_draw_func(GTK_DRAWING_AREA(view->area), draw_graph, view, NULL);
        char *label = g_strdup_printf("Export %s CSV…", live_graph_file_stem((live_graph_kind)k));
        GtkWidget *button = gtk_button_new_with_label(label);
        view->export_button = button;
        g_free(label);
        g_signal_connect(button, "clicked", G_CALLBACK(on_export), view);
        GtkWidget *column = gtk_box_new(GTK_ORIENTATION_VERTICAL, 2);
        gtk_box_append(GTK_BOX(column), view->area);
        gtk_box_append(GTK_BOX(column), button);
        gtk_grid_attach(GTK_GRID(panel->grid), column, k % 2, k / 2, 1, 1);
    }
    return panel;
}

void graphs_panel_free(graphs_panel *panel) { g_free(panel); }

GtkWidget *graphs_panel_widget(const graphs_panel *panel) { return panel->grid; }

void graphs_panel_select(graphs_panel *panel)
{
    for (int k = 0; k < LIVE_GRAPH_COUNT; ++k) {
        live_graph_select(&panel->views[k].graph, (live_graph_kind)k, &panel->app->sim);
    }
}

void graphs_panel_redraw(graphs_panel *panel)
{
    for (int k = 0; k < LIVE_GRAPH_COUNT; ++k) {
        gtk_widget_queue_draw(panel->views[k].area);
    }
}

GtkWidget *graphs_panel_control(const graphs_panel *panel, const char *name)
{
    const char prefix[] = "export-";
    if (strncmp(name, prefix, sizeof prefix - 1) != 0) {
        return NULL;
    }
    for (int k = 0; k < LIVE_GRAPH_COUNT; ++k) {
        if (strcmp(name + sizeof prefix - 1, live_graph_file_stem((live_graph_kind)k)) == 0) {
            return panel->views[k].export_button;
        }
    }
    return NULL;
}
