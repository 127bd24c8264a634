/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <string.h>

#include "cli/user_error.h"
#include "engine_panel.h"

/* Upper ends of the spin buttons: far beyond what a run needs, well
 * inside what the engine accepts (1000). */
#define MAX_ITERATIONS 100
#define MAX_SUBSTEPS 100

struct engine_panel {
    viewer *app;
    GtkWidget *box;
    GtkWidget *solver, *velocity_iterations, *position_iterations, *substeps, *warm_starting;
    GtkWidget *report; /* profile and statistics */
    GtkWidget *overlay_checks[CANVAS_OVERLAY_COUNT];
    bool syncing;
};

static void apply_settings(engine_panel *panel)
{
    rb_world *world = simulation_world(&panel->app->sim);
    if (panel->syncing || world == NULL) {
        return;
    }
    rb_solver_settings settings = rb_world_solver_settings(world);
    guint type = gtk_drop_down_get_selected(GTK_DROP_DOWN(panel->solver));
    if (type != GTK_INVALID_LIST_POSITION) {
        settings.type = (rb_solver_type)type;
    }
    settings.velocity_iterations = gtk_spin_button_get_value_as_int(GTK_SPIN_BUTTON(panel->velocity_iterations));
    settings.position_iterations = gtk_spin_button_get_value_as_int(GTK_SPIN_BUTTON(panel->position_iterations));
    settings.substeps = gtk_spin_button_get_value_as_int(GTK_SPIN_BUTTON(panel->substeps));
    settings.warm_starting = gtk_check_button_get_active(GTK_CHECK_BUTTON(panel->warm_starting));
    if (rb_world_set_solver_settings(world, &settings) != RB_OK) {
        viewer_show_error(panel->app, user_error());
        engine_panel_sync(panel);
    }
}

static void on_setting_changed(GtkWidget *widget, gpointer data)
{
    (void)widget;
    apply_settings(data);
}

static void on_solver_chosen(GObject *drop_down, GParamSpec *spec, gpointer data)
{
    (void)drop_down;
    (void)spec;
    apply_settings(data);
}

/* Each overlay check button writes one flag of app->overlays. */
static void on_overlay_toggled(GtkCheckButton *button, gpointer data)
{
    bool *flag = data;
    *flag = gtk_check_button_get_active(button);
    viewer *app = g_object_get_data(G_OBJECT(button), "viewer");
    gtk_widget_queue_draw(app->canvas);
}

static GtkWidget *spin_row(GtkWidget *grid, int row, const char *text, double min, double max)
{
    GtkWidget *label = gtk_label_new(text);
    gtk_label_set_xalign(GTK_LABEL(label), 0.0f);
    gtk_grid_attach(GTK_GRID(grid), label, 0, row, 1, 1);
    GtkWidget *spin = gtk_spin_button_new_with_range(min, max, 1.0);
    gtk_grid_attach(GTK_GRID(grid), spin, 1, row, 1, 1);
    return spin;
}

engine_panel *engine_panel_new(viewer *app)
{
    engine_panel *panel = g_new0(engine_panel, 1);
    panel->app = app;
    panel->box = gtk_box_new(GTK_ORIENTATION_VERTICAL, 6);
    GtkWidget *grid = gtk_grid_new();
    gtk_grid_set_row_spacing(GTK_GRID(grid), 4);
    gtk_grid_set_column_spacing(GTK_GRID(grid), 8);
    const char *solvers[RB_SOLVER_TYPE_COUNT + 1];
    for (int k = 0; k < RB_SOLVER_TYPE_COUNT; ++k) {
        solvers[k] = rb_solver_type_name((rb_solver_type)k);
    }
    solvers[RB_SOLVER_TYPE_COUNT] = NULL;
    GtkWidget *solver_label = gtk_label_new("Solver");
    gtk_label_set_xalign(GTK_LABEL(solver_label), 0.0f);
    gtk_grid_attach(GTK_GRID(grid), solver_label, 0, 0, 1, 1);
    panel->solver = gtk_drop_down_new_from_strings(solvers);
    gtk_grid_attach(GTK_GRID(grid), panel->solver, 1, 0, 1, 1);
    panel->velocity_iterations = spin_row(grid, 1, "Velocity iterations", 1, MAX_ITERATIONS);
    panel->position_iterations = spin_row(grid, 2, "Position iterations", 0, MAX_ITERATIONS);
    panel->substeps = spin_row(grid, 3, "Substeps", 1, MAX_SUBSTEPS);
    panel->warm_starting = gtk_check_button_new_with_label("Warm starting");
    gtk_grid_attach(GTK_GRID(grid), panel->warm_starting, 0, 4, 2, 1);
    gtk_box_append(GTK_BOX(panel->box), grid);

    g_signal_connect(panel->solver, "notify::selected", G_CALLBACK(on_solver_chosen), panel);
    g_signal_connect(panel->velocity_iterations, "value-changed", G_CALLBACK(on_setting_changed), panel);
    g_signal_connect(panel->position_iterations, "value-changed", G_CALLBACK(on_setting_changed), panel);
    g_signal_connect(panel->substeps, "value-changed", G_CALLBACK(on_setting_changed), panel);
    g_signal_connect(panel->warm_starting, "toggled", G_CALLBACK(on_setting_changed), panel);

    static const char *const overlay_names[CANVAS_OVERLAY_COUNT] = {
        "Contact points",        "Contact normals", "Contact impulses",       "Bounding boxes",
        "Joints and their gaps", "Joint reactions", "Sleeping bodies (grey)", "Contacts by solver colour"};
    bool *flags[CANVAS_OVERLAY_COUNT];
    canvas_overlay_flags(&app->overlays, flags);
    GtkWidget *overlays = gtk_flow_box_new();
    gtk_flow_box_set_selection_mode(GTK_FLOW_BOX(overlays), GTK_SELECTION_NONE);
    gtk_flow_box_set_max_children_per_line(GTK_FLOW_BOX(overlays), 2);
    for (int k = 0; k < CANVAS_OVERLAY_COUNT; ++k) {
        GtkWidget *check = gtk_check_button_new_with_label(overlay_names[k]);
        panel->overlay_checks[k] = check;
        gtk_check_button_set_active(GTK_CHECK_BUTTON(check), *flags[k]);
        g_object_set_data(G_OBJECT(check), "viewer", app);
        g_signal_connect(check, "toggled", G_CALLBACK(on_overlay_toggled), flags[k]);
        gtk_flow_box_append(GTK_FLOW_BOX(overlays), check);
    }
    gtk_box_append(GTK_BOX(panel->box), overlays);

    panel->report = gtk_label_new("");
    gtk_label_set_xalign(GTK_LABEL(panel->report), 0.0f);
    gtk_label_set_yalign(GTK_LABEL(panel->report), 0.0f);
    gtk_widget_add_css_class(panel->report, "monospace");
    gtk_box_append(GTK_BOX(panel->box), panel->report);
    return panel;
}

void engine_panel_free(engine_panel *panel) { g_free(panel); }

GtkWidget *engine_panel_widget(const engine_panel *panel) { return panel->box; }

void engine_panel_sync(engine_panel *panel)
{
    rb_world *world = simulation_world(&panel->app->sim);
    gtk_widget_set_sensitive(panel->box, world != NULL);
    if (world == NULL) {
        return;
    }
    bool *flags[CANVAS_OVERLAY_COUNT];
    canvas_overlay_flags(&panel->app->overlays, flags);
    for (int k = 0; k < CANVAS_OVERLAY_COUNT; ++k) {
        gtk_check_button_set_active(GTK_CHECK_BUTTON(panel->overlay_checks[k]), *flags[k]);
    }
    rb_solver_settings settings = rb_world_solver_settings(world);
    panel->syncing = true;
    gtk_drop_down_set_selected(GTK_DROP_DOWN(panel->solver), (guint)settings.type);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(panel->velocity_iterations), settings.velocity_iterations);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(panel->position_iterations), settings.position_iterations);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(panel->substeps), settings.substeps);
    gtk_check_button_set_active(GTK_CHECK_BUTTON(panel->warm_starting), settings.warm_starting);
    panel->syncing = false;
    engine_panel_update(panel);
}

void engine_panel_update(engine_panel *panel)
{
    rb_world *world = simulation_world(&panel->app->sim);
    if (world == NULL) {
        gtk_label_set_text(GTK_LABEL(panel->report), "");
        return;
    }
    rb_profile profile = rb_world_profile(world);
    rb_statistics stats = rb_world_statistics(world);
    char text[2048];
    snprintf(text, sizeof text,
             "Last step (ms)            Statistics\n"
             "  step        %7.3f      bodies      %6d (%d awake)\n"
             "  pairs       %7.3f      islands     %6d\n"
             "  collide     %7.3f      shapes      %6d\n"
             "  prepare     %7.3f      pairs       %6d (swept %d, requeried %d)\n"
             "  callback    %7.3f      contacts    %6d (%d points, %d colours)\n"
             "  velocities  %7.3f      iterations  %d vel, %d pos, %d relax\n"
             "  positions   %7.3f      joints      %6d\n"
             "  correction  %7.3f      penetration %.2e m\n"
             "  relax       %7.3f      joint gap   %.2e m\n"
             "  islands     %7.3f      joint angle %.2e rad\n"
             "  finalize    %7.3f      energy      %.4g J",
             profile.step, stats.body_count, stats.awake_body_count, profile.pairs, stats.island_count, profile.collide,
             stats.shape_count, profile.prepare, stats.pair_count, stats.broad_phase_sweeps,
             stats.broad_phase_requeries, profile.substep_callback, stats.contact_count, stats.manifold_point_count,
             stats.contact_colours, profile.solve_velocities, stats.velocity_iterations, stats.position_iterations,
             stats.relax_iterations, profile.integrate_positions, stats.joint_count, profile.correct_positions,
             stats.max_penetration, profile.relax, stats.max_joint_gap, profile.islands, stats.max_joint_angle_error,
             profile.finalize, stats.energy);
    gtk_label_set_text(GTK_LABEL(panel->report), text);
}

GtkWidget *engine_panel_control(const engine_panel *panel, const char *name)
{
    const struct {
        const char *name;
        GtkWidget *widget;
    } controls[] = {
        {"solver", panel->solver},
        {"velocity-iterations", panel->velocity_iterations},
        {"position-iterations", panel->position_iterations},
        {"substeps", panel->substeps},
        {"warm-starting", panel->warm_starting},
    };
    for (size_t k = 0; k < sizeof controls / sizeof controls[0]; ++k) {
        if (strcmp(name, controls[k].name) == 0) {
            return controls[k].widget;
        }
    }
    for (int k = 0; k < CANVAS_OVERLAY_COUNT; ++k) {
        if (strcmp(name, canvas_overlay_names[k]) == 0) {
            return panel->overlay_checks[k];
        }
    }
    return NULL;
}
