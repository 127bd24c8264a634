/* SPDX-License-Identifier: MIT */
#include <math.h>

#include "canvas_widget.h"

/* Per-canvas input state, owned by the drawing area (freed with it). */
typedef struct canvas_input {
    viewer *app;
    rb_vec2 pointer;    /* px, last position of the pointer over the canvas */
    bool panning;       /* the drag started on the background */
    rb_vec2 drag_start; /* px, where the drag started */
    rb_vec2 drag_last;  /* px, the drag's offset at the last update */
} canvas_input;

static void draw_canvas(GtkDrawingArea *area, cairo_t *cr, int width, int height, gpointer data)
{
    (void)area;
    canvas_input *input = data;
    viewer *app = input->app;
    view_transform_resize(&app->view, width, height);
    if (!app->view_placed) {
        viewer_place_view(app);
    }
    canvas_draw(cr, &app->view, &app->sim, &app->overlays);
}

static void on_resize(GtkDrawingArea *area, int width, int height, gpointer data)
{
    (void)area;
    canvas_input *input = data;
    view_transform_resize(&input->app->view, width, height);
}

static void on_motion(GtkEventControllerMotion *motion, double x, double y, gpointer data)
{
    (void)motion;
    canvas_input *input = data;
    input->pointer = rb_v2(x, y);
}

static gboolean on_scroll(GtkEventControllerScroll *scroll, double dx, double dy, gpointer data)
{
    (void)scroll;
    (void)dx;
    canvas_input *input = data;
    view_zoom_about(&input->app->view, input->pointer, pow(CANVAS_ZOOM_STEP, -dy));
    gtk_widget_queue_draw(input->app->canvas);
    return TRUE;
}

static void on_right_click(GtkGestureClick *click, int presses, double x, double y, gpointer data)
{
    (void)click;
    (void)presses;
    (void)x;
    (void)y;
    canvas_input *input = data;
    view_reset(&input->app->view);
    gtk_widget_queue_draw(input->app->canvas);
}

static void on_drag_begin(GtkGestureDrag *drag, double x, double y, gpointer data)
{
    (void)drag;
    canvas_input *input = data;
    viewer *app = input->app;
    gtk_widget_grab_focus(app->canvas);
    input->drag_start = rb_v2(x, y);
    input->drag_last = rb_v2(0.0, 0.0);
    input->panning = !simulation_drag_begin(&app->sim, view_screen_to_world(&app->view, input->drag_start));
    gtk_widget_queue_draw(app->canvas);
}

static void on_drag_update(GtkGestureDrag *drag, double dx, double dy, gpointer data)
{
    (void)drag;
    canvas_input *input = data;
    viewer *app = input->app;
    if (input->panning) {
        view_pan(&app->view, rb_v2(dx - input->drag_last.x, dy - input->drag_last.y));
    } else {
        rb_vec2 at = rb_add(input->drag_start, rb_v2(dx, dy));
        simulation_drag_move(&app->sim, view_screen_to_world(&app->view, at));
    }
    input->drag_last = rb_v2(dx, dy);
    gtk_widget_queue_draw(app->canvas);
}

static void on_drag_end(GtkGestureDrag *drag, double dx, double dy, gpointer data)
{
    (void)drag;
    (void)dx;
    (void)dy;
    canvas_input *input = data;
    simulation_drag_end(&input->app->sim);
    input->panning = false;
    gtk_widget_queue_draw(input->app->canvas);
}

static gboolean on_key(GtkEventControllerKey *keys, guint keyval, guint keycode, GdkModifierType state, gpointer data)
{
    (void)keys;
    (void)keycode;
    (void)state;
    canvas_input *input = data;
    viewer *app = input->app;
    char error[SIMULATION_ERROR_SIZE];
    switch (keyval) {
    case GDK_KEY_space:
        simulation_pulse(&app->sim);
        if (!app->playing) {
            viewer_step(app);
            viewer_refresh(app);
        }
        return TRUE;
    case GDK_KEY_Up:
    case GDK_KEY_Down: {
        int delta = keyval == GDK_KEY_Up ? SIMULATION_RECRUITMENT_STEP : -SIMULATION_RECRUITMENT_STEP;
        if (!simulation_recruit_more(&app->sim, delta, error, sizeof error)) {
            viewer_show_error(app, error);
        }
        gtk_widget_queue_draw(app->canvas);
        return TRUE;
    }
    case GDK_KEY_p:
    case GDK_KEY_P:
        viewer_set_playing(app, !app->playing);
        return TRUE;
    case GDK_KEY_s:
    case GDK_KEY_S:
        viewer_step(app);
        viewer_refresh(app);
        return TRUE;
    default:
        return FALSE;
    }
}

GtkWidget *canvas_widget_new(viewer *app)
{
    canvas_input *input = g_new0(canvas_input, 1);
    input->app = app;
    GtkWidget *area = gtk_drawing_area_new();
    app->canvas = area;
    gtk_widget_set_hexpand(area, TRUE);
    gtk_widget_set_vexpand(area, TRUE);
    /* Its least size: with the graphs' (graphs_panel.c) and the panes'
     * handles, a 1280 x 720 window holds it all. */
    gtk_widget_set_size_request(area, 480, 240);
    gtk_drawing_area_set_draw_func(GTK_DRAWING_AREA(area), draw_canvas, input, g_free);
    g_signal_connect(area, "resize", G_CALLBACK(on_resize), input);

    GtkEventController *motion = gtk_event_controller_motion_new();
    g_signal_connect(motion, "motion", G_CALLBACK(on_motion), input);
    gtk_widget_add_controller(area, motion);

    GtkEventController *scroll = gtk_event_controller_scroll_new(GTK_EVENT_CONTROLLER_SCROLL_VERTICAL);
    g_signal_connect(scroll, "scroll", G_CALLBACK(on_scroll), input);
    gtk_widget_add_controller(area, scroll);

    GtkGesture *right_click = gtk_gesture_click_new();
    gtk_gesture_single_set_button(GTK_GESTURE_SINGLE(right_click), GDK_BUTTON_SECONDARY);
    g_signal_connect(right_click, "pressed", G_CALLBACK(on_right_click), input);
    gtk_widget_add_controller(area, GTK_EVENT_CONTROLLER(right_click));

    GtkGesture *drag = gtk_gesture_drag_new();
    gtk_gesture_single_set_button(GTK_GESTURE_SINGLE(drag), GDK_BUTTON_PRIMARY);
    g_signal_connect(drag, "drag-begin", G_CALLBACK(on_drag_begin), input);
    g_signal_connect(drag, "drag-update", G_CALLBACK(on_drag_update), input);
    g_signal_connect(drag, "drag-end", G_CALLBACK(on_drag_end), input);
    gtk_widget_add_controller(area, GTK_EVENT_CONTROLLER(drag));

    /* The keys reach the window after the focused widget has declined
     * them, so typing in a spin button or moving a slider with the arrows
     * works as usual; the canvas takes the focus when clicked. */
    gtk_widget_set_focusable(area, TRUE);
    GtkEventController *keys = gtk_event_controller_key_new();
    g_signal_connect(keys, "key-pressed", G_CALLBACK(on_key), input);
    gtk_widget_add_controller(app->window, keys);
    return area;
}
