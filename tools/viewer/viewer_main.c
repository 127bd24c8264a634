/* SPDX-License-Identifier: MIT */
/* sinew-view, the interactive viewer that `sinew view` starts: the
 * window's layout (the canvas with its message bar over the graphs on the
 * left, the control and engine panels on the right), what is loaded
 * first, the simulation's clock and an optional script, then GTK's main
 * loop until the window closes.
 */
#include <gtk/gtk.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>

#include "canvas_widget.h"
#include "controls_panel.h"
#include "engine_panel.h"
#include "graphs_panel.h"
#include "io/provenance.h"
#include "script.h"
#include "sim_loop.h"
#include "viewer.h"
#include "viewer_options.h"

/* Exit status of a bad command line, as `sinew` (tools/commands/commands.h). */
#define EXIT_USAGE 2

static gboolean on_close(GtkWindow *window, gpointer data)
{
    (void)window;
    viewer *app = data;
    g_main_loop_quit(app->loop);
    return TRUE; /* destroyed after the loop, with the rest */
}

static void on_message_response(GtkInfoBar *bar, int response, gpointer data)
{
    (void)bar;
    (void)response;
    viewer_show_error(data, NULL);
}

static GtkWidget *framed(const char *title, GtkWidget *child)
{
    GtkWidget *frame = gtk_frame_new(title);
    gtk_widget_set_margin_start(child, 6);
    gtk_widget_set_margin_end(child, 6);
    gtk_widget_set_margin_top(child, 6);
    gtk_widget_set_margin_bottom(child, 6);
    gtk_frame_set_child(GTK_FRAME(frame), child);
    return frame;
}

static void build_window(viewer *app, int width, int height)
{
    app->window = gtk_window_new();
    gtk_window_set_title(GTK_WINDOW(app->window), "sinew view");
    gtk_window_set_default_size(GTK_WINDOW(app->window), width, height);
    g_signal_connect(app->window, "close-request", G_CALLBACK(on_close), app);

    app->message_bar = gtk_info_bar_new();
    gtk_info_bar_set_message_type(GTK_INFO_BAR(app->message_bar), GTK_MESSAGE_ERROR);
    gtk_info_bar_set_show_close_button(GTK_INFO_BAR(app->message_bar), TRUE);
    app->message_label = gtk_label_new("");
    gtk_label_set_wrap(GTK_LABEL(app->message_label), TRUE);
    gtk_label_set_selectable(GTK_LABEL(app->message_label), TRUE);
    gtk_info_bar_add_child(GTK_INFO_BAR(app->message_bar), app->message_label);
    gtk_widget_set_visible(app->message_bar, FALSE);
    g_signal_connect(app->message_bar, "response", G_CALLBACK(on_message_response), app);

    GtkWidget *canvas = canvas_widget_new(app);
    app->controls = controls_panel_new(app);
    app->graphs = graphs_panel_new(app);
    app->engine = engine_panel_new(app);

    GtkWidget *canvas_box = gtk_box_new(GTK_ORIENTATION_VERTICAL, 0);
    gtk_box_append(GTK_BOX(canvas_box), app->message_bar);
    gtk_box_append(GTK_BOX(canvas_box), canvas);
    GtkWidget *left = gtk_paned_new(GTK_ORIENTATION_VERTICAL);
    gtk_paned_set_start_child(GTK_PANED(left), canvas_box);
    gtk_paned_set_end_child(GTK_PANED(left), graphs_panel_widget(app->graphs));
    gtk_paned_set_position(GTK_PANED(left), 480);
    /* The graphs keep at least their least size, Export buttons whole:
     * the canvas gives way when the window is short. */
    gtk_paned_set_shrink_start_child(GTK_PANED(left), FALSE);
    gtk_paned_set_shrink_end_child(GTK_PANED(left), FALSE);

    GtkWidget *right = gtk_box_new(GTK_ORIENTATION_VERTICAL, 6);
    gtk_box_append(GTK_BOX(right), framed("Controls", controls_panel_widget(app->controls)));
    gtk_box_append(GTK_BOX(right), framed("Engine", engine_panel_widget(app->engine)));
    GtkWidget *scroll = gtk_scrolled_window_new();
    /* A vertical scrollbar always there, not an overlay: the panels are
     * taller than most windows (at 1400 x 900 the engine panel's bottom
     * looked cut off under an overlay scrollbar that shows only while the
     * pointer moves over it), and GTK counts a scrollbar in the panels'
     * width only when it is always shown (an automatic one would cover
     * their right edge). */
    gtk_scrolled_window_set_policy(GTK_SCROLLED_WINDOW(scroll), GTK_POLICY_NEVER, GTK_POLICY_ALWAYS);
    gtk_scrolled_window_set_overlay_scrolling(GTK_SCROLLED_WINDOW(scroll), FALSE);
    gtk_scrolled_window_set_child(GTK_SCROLLED_WINDOW(scroll), right);
    gtk_widget_set_size_request(scroll, 440, -1);

    GtkWidget *main_pane = gtk_paned_new(GTK_ORIENTATION_HORIZONTAL);
    gtk_paned_set_start_child(GTK_PANED(main_pane), left);
    gtk_paned_set_end_child(GTK_PANED(main_pane), scroll);
    gtk_paned_set_resize_end_child(GTK_PANED(main_pane), FALSE);
    gtk_paned_set_shrink_end_child(GTK_PANED(main_pane), FALSE);
    gtk_window_set_child(GTK_WINDOW(app->window), main_pane);
}

/* The model (with the command line's variant, weight and level) or scene
 * to start with; an error is shown in the window, which still opens. */
static void load_first(viewer *app, const viewer_options *options)
{
    scene_kind kind;
    /* viewer_options_parse has refused a name that is not a scene. */
    if (options->scene != NULL && scene_kind_from_name(options->scene, &kind)) {
        viewer_load_scene(app, kind);
        return;
    }
    mu_model_options build = mu_default_model_options();
    if (!viewer_load_model(app, options->model, &build)) {
        return;
    }
    char error[SIMULATION_ERROR_SIZE];
    bool chosen =
        options->variant == NULL || simulation_choose_variant(&app->sim, options->variant, &build, error, sizeof error);
    if (chosen && options->has_weight) {
        app->sim.options = build;
        chosen = simulation_choose_weight(&app->sim, options->weight, &build, error, sizeof error);
    }
    if (chosen && options->has_level) {
        app->sim.options = build;
        chosen = simulation_choose_level(&app->sim, options->level, &build, error, sizeof error);
    }
    if (!chosen) {
        viewer_show_error(app, error);
    } else if (options->variant != NULL || options->has_weight || options->has_level) {
        viewer_reload_model(app, &build);
    }
}

int main(int argc, char **argv)
{
    /* Every graph export's sidecar names the command that made it. */
    provenance_set_command_line(argc, argv);
    viewer_options options;
    switch (viewer_options_parse(argc - 1, argv + 1, &options)) {
    case VIEWER_PARSE_HELP:
        viewer_print_usage(stdout);
        return EXIT_SUCCESS;
    case VIEWER_PARSE_ERROR:
        return EXIT_USAGE;
    case VIEWER_PARSE_OK:
        break;
    }
    char error[SIMULATION_ERROR_SIZE];
    script *commands = NULL;
    if (options.script != NULL && (commands = script_load(options.script, error, sizeof error)) == NULL) {
        fprintf(stderr, "sinew view: %s\n", error);
        return EXIT_FAILURE;
    }
    g_set_application_name("sinew view");
    if (!gtk_init_check()) {
        fprintf(stderr, "sinew view: cannot open a display (is DISPLAY or WAYLAND_DISPLAY set?)\n");
        script_free(commands);
        return EXIT_FAILURE;
    }
    /* gtk_init_check took the whole locale from the environment (LANG,
     * LC_ALL): GTK's messages and dialogs stay in the user's language,
     * but numbers go back to the C locale, so that under a decimal-comma
     * locale such as de_DE.UTF-8 the viewer still reads files, control
     * values and scripts with '.', and writes status lines, "angles",
     * graph exports and chart ticks with '.' (tests/gui/test_viewer_gui.c
     * compares them with LC_ALL=C's). */
    setlocale(LC_NUMERIC, "C");
    viewer app = {.exit_status = EXIT_SUCCESS, .overlays = {.joints = false}};
    simulation_init(&app.sim);
    app.view = view_transform_make(rb_v2(0.0, 0.0), 400.0);
    app.loop = g_main_loop_new(NULL, FALSE);
    build_window(&app, options.width, options.height);
    load_first(&app, &options);
    gtk_window_present(GTK_WINDOW(app.window));
    gtk_widget_grab_focus(app.canvas);
    viewer_set_playing(&app, options.play);

    sim_loop clock;
    sim_loop_start(&clock, &app);
    if (commands != NULL) {
        script_start(commands, &app);
    }
    g_main_loop_run(app.loop);

    sim_loop_stop(&clock);
    gtk_window_destroy(GTK_WINDOW(app.window));
    controls_panel_free(app.controls);
    graphs_panel_free(app.graphs);
    engine_panel_free(app.engine);
    simulation_free(&app.sim);
    history_free(&app.samples);
    script_free(commands);
    g_main_loop_unref(app.loop);
    return app.exit_status;
}
