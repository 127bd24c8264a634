/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/model_source.h"
#include "controls_panel.h"

/* Largest tension target the spin button offers, N. */
#define MAX_TENSION_TARGET 5000.0

typedef enum pending_load { PENDING_NONE, PENDING_MODEL, PENDING_SCENE, PENDING_REBUILD } pending_load;

struct controls_panel {
    viewer *app;
    GtkWidget *box;
    GtkWidget *model, *scene, *variant, *weight, *level;
    GtkWidget *reload, *play, *step;
    GtkWidget *target, *activation, *tension_mode, *tension;
    bool syncing; /* the widgets are being filled: their signals are not the user's */
    /* A load chosen in a drop-down or the level, run from the main loop
     * right after the widget's handler: loading refills the drop-downs,
     * which GTK does not allow from inside one's own change (it hangs). */
    pending_load pending;
    char pending_name[SIMULATION_NAME_SIZE];
    guint pending_source;
};

/* Replaces a drop-down's choices and selects `selected`. */
static void set_choices(GtkWidget *drop_down, const char *const *choices, guint selected)
{
    GtkStringList *list = gtk_string_list_new(choices);
    gtk_drop_down_set_model(GTK_DROP_DOWN(drop_down), G_LIST_MODEL(list));
    g_object_unref(list);
    gtk_drop_down_set_selected(GTK_DROP_DOWN(drop_down), selected);
}

static const char *selected_text(GtkWidget *drop_down)
{
    GtkStringObject *item = gtk_drop_down_get_selected_item(GTK_DROP_DOWN(drop_down));
    return item != NULL ? gtk_string_object_get_string(item) : NULL;
}

/* The build options the pickers show. */
static mu_model_options chosen_options(const controls_panel *panel)
{
    mu_model_options options = mu_default_model_options();
    guint variant = gtk_drop_down_get_selected(GTK_DROP_DOWN(panel->variant));
    guint weight = gtk_drop_down_get_selected(GTK_DROP_DOWN(panel->weight));
    options.variant = variant == GTK_INVALID_LIST_POSITION ? 0 : (int)variant;
    options.weight_index = weight == GTK_INVALID_LIST_POSITION ? 0 : (int)weight;
    options.level = gtk_spin_button_get_value_as_int(GTK_SPIN_BUTTON(panel->level));
    return options;
}

static gboolean run_pending_load(gpointer data)
{
    controls_panel *panel = data;
    pending_load load = panel->pending;
    panel->pending_source = 0;
    panel->pending = PENDING_NONE;
    mu_model_options options = load == PENDING_REBUILD ? chosen_options(panel) : mu_default_model_options();
    scene_kind kind;
    if (load == PENDING_MODEL) {
        viewer_load_model(panel->app, panel->pending_name, &options);
    } else if (load == PENDING_SCENE && scene_kind_from_name(panel->pending_name, &kind)) {
        viewer_load_scene(panel->app, kind);
    } else if (load == PENDING_REBUILD && panel->app->sim.kind == SIMULATION_MODEL) {
        viewer_reload_model(panel->app, &options);
    }
    return G_SOURCE_REMOVE;
}

/* Schedules `load` (of `name`) ahead of everything else the main loop
 * has to do; a later choice replaces one not yet run. */
static void defer_load(controls_panel *panel, pending_load load, const char *name)
{
    panel->pending = load;
    snprintf(panel->pending_name, sizeof panel->pending_name, "%s", name != NULL ? name : "");
    if (panel->pending_source == 0) {
        panel->pending_source = g_idle_add_full(G_PRIORITY_HIGH, run_pending_load, panel, NULL);
    }
}

static void on_model_chosen(GObject *drop_down, GParamSpec *spec, gpointer data)
{
    (void)drop_down;
    (void)spec;
    controls_panel *panel = data;
    const char *name = selected_text(panel->model);
    if (!panel->syncing && name != NULL) {
        defer_load(panel, PENDING_MODEL, name);
    }
}

static void on_scene_chosen(GObject *drop_down, GParamSpec *spec, gpointer data)
{
    (void)drop_down;
    (void)spec;
    controls_panel *panel = data;
    const char *name = selected_text(panel->scene);
    scene_kind kind;
    if (!panel->syncing && name != NULL && scene_kind_from_name(name, &kind)) {
        defer_load(panel, PENDING_SCENE, name);
    }
}

/* Variant, weight and level rebuild the model. */
static void on_build_option(GObject *widget, GParamSpec *spec, gpointer data)
{
    (void)widget;
    (void)spec;
    controls_panel *panel = data;
    if (!panel->syncing && panel->app->sim.kind == SIMULATION_MODEL) {
        defer_load(panel, PENDING_REBUILD, NULL);
    }
}

static void on_reload(GtkButton *button, gpointer data)
{
    (void)button;
    controls_panel *panel = data;
    if (panel->app->sim.kind == SIMULATION_SCENE) {
        viewer_load_scene(panel->app, panel->app->sim.scene.kind);
        return;
    }
    mu_model_options options = chosen_options(panel);
    viewer_reload_model(panel->app, &options);
}

static void on_play(GtkToggleButton *button, gpointer data)
{
    controls_panel *panel = data;
    if (!panel->syncing) {
        viewer_set_playing(panel->app, gtk_toggle_button_get_active(button));
    }
}

static void on_step(GtkButton *button, gpointer data)
{
    (void)button;
    controls_panel *panel = data;
    viewer_step(panel->app);
    viewer_refresh(panel->app);
}

/* Gives the target the command the widgets show. */
static void apply_command(controls_panel *panel)
{
    char error[SIMULATION_ERROR_SIZE];
    simulation *sim = &panel->app->sim;
    bool applied =
        gtk_check_button_get_active(GTK_CHECK_BUTTON(panel->tension_mode))
            ? simulation_set_tension(sim, gtk_spin_button_get_value(GTK_SPIN_BUTTON(panel->tension)), error,
                                     sizeof error)
            : simulation_set_activation(sim, gtk_range_get_value(GTK_RANGE(panel->activation)), error, sizeof error);
    if (!applied) {
        viewer_show_error(panel->app, error);
    }
}

static void on_target_chosen(GObject *drop_down, GParamSpec *spec, gpointer data)
{
    (void)drop_down;
    (void)spec;
    controls_panel *panel = data;
    const char *name = selected_text(panel->target);
    char error[SIMULATION_ERROR_SIZE];
    if (panel->syncing || name == NULL) {
        return;
    }
    if (!simulation_select(&panel->app->sim, name, error, sizeof error)) {
        viewer_show_error(panel->app, error);
        return;
    }
    apply_command(panel);
    viewer_target_changed(panel->app);
}

static void on_command_changed(GtkWidget *widget, gpointer data)
{
    (void)widget;
    controls_panel *panel = data;
    if (!panel->syncing) {
        apply_command(panel);
    }
}

static GtkWidget *labelled(GtkWidget *grid, int row, const char *text, GtkWidget *widget)
{
    GtkWidget *label = gtk_label_new(text);
    gtk_label_set_xalign(GTK_LABEL(label), 0.0f);
    gtk_grid_attach(GTK_GRID(grid), label, 0, row, 1, 1);
    gtk_widget_set_hexpand(widget, TRUE);
    gtk_grid_attach(GTK_GRID(grid), widget, 1, row, 1, 1);
    return widget;
}

controls_panel *controls_panel_new(viewer *app)
{
    controls_panel *panel = g_new0(controls_panel, 1);
    panel->app = app;
    GtkWidget *grid = gtk_grid_new();
    panel->box = grid;
    gtk_grid_set_row_spacing(GTK_GRID(grid), 4);
    gtk_grid_set_column_spacing(GTK_GRID(grid), 8);
    int row = 0;
    panel->model = labelled(grid, row++, "Model", gtk_drop_down_new(NULL, NULL));
    const char *scenes[SCENE_KIND_COUNT + 2] = {"(none)"};
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        scenes[k + 1] = scene_registry[k].name;
    }
    panel->scene = labelled(grid, row++, "Scene", gtk_drop_down_new_from_strings(scenes));
    panel->variant = labelled(grid, row++, "Variant", gtk_drop_down_new(NULL, NULL));
    panel->weight = labelled(grid, row++, "Weight", gtk_drop_down_new(NULL, NULL));
    panel->level = labelled(grid, row++, "Level", gtk_spin_button_new_with_range(0, 4, 1));
    gtk_widget_set_tooltip_text(panel->level, "0 nothing, 1 bones, 2 + joints, 3 + muscles, 4 + the weight");

    GtkWidget *buttons = gtk_box_new(GTK_ORIENTATION_HORIZONTAL, 4);
    GtkWidget *reload = gtk_button_new_with_label("Reload");
    panel->reload = reload;
    panel->play = gtk_toggle_button_new_with_label("Play");
    panel->step = gtk_button_new_with_label("Step");
    gtk_box_append(GTK_BOX(buttons), reload);
    gtk_box_append(GTK_BOX(buttons), panel->play);
    gtk_box_append(GTK_BOX(buttons), panel->step);
    gtk_grid_attach(GTK_GRID(grid), buttons, 0, row++, 2, 1);

    panel->target = labelled(grid, row++, "Muscle", gtk_drop_down_new(NULL, NULL));
    panel->activation =
        labelled(grid, row++, "Activation", gtk_scale_new_with_range(GTK_ORIENTATION_HORIZONTAL, 0.0, 1.0, 0.01));
    gtk_scale_set_draw_value(GTK_SCALE(panel->activation), TRUE);
    gtk_scale_set_digits(GTK_SCALE(panel->activation), 2);
    panel->tension_mode = gtk_check_button_new_with_label("Tension (N)");
    panel->tension = gtk_spin_button_new_with_range(0.0, MAX_TENSION_TARGET, 1.0);
    gtk_grid_attach(GTK_GRID(grid), panel->tension_mode, 0, row, 1, 1);
    gtk_grid_attach(GTK_GRID(grid), panel->tension, 1, row++, 1, 1);

    GtkWidget *keys = gtk_label_new("Keys: space pulse (1 frame at activation 1), P play/pause, S step,\n"
                                    "Up/Down recruit ±20 neurons (worm). Mouse: wheel zooms, right click\n"
                                    "resets, drag the background pans, drag a body pulls it.");
    gtk_label_set_xalign(GTK_LABEL(keys), 0.0f);
    gtk_widget_add_css_class(keys, "dim-label");
    gtk_grid_attach(GTK_GRID(grid), keys, 0, row++, 2, 1);

    g_signal_connect(panel->model, "notify::selected", G_CALLBACK(on_model_chosen), panel);
    g_signal_connect(panel->scene, "notify::selected", G_CALLBACK(on_scene_chosen), panel);
    g_signal_connect(panel->variant, "notify::selected", G_CALLBACK(on_build_option), panel);
    g_signal_connect(panel->weight, "notify::selected", G_CALLBACK(on_build_option), panel);
    g_signal_connect(panel->level, "notify::value", G_CALLBACK(on_build_option), panel);
    g_signal_connect(reload, "clicked", G_CALLBACK(on_reload), panel);
    g_signal_connect(panel->play, "toggled", G_CALLBACK(on_play), panel);
    g_signal_connect(panel->step, "clicked", G_CALLBACK(on_step), panel);
    g_signal_connect(panel->target, "notify::selected", G_CALLBACK(on_target_chosen), panel);
    g_signal_connect(panel->activation, "value-changed", G_CALLBACK(on_command_changed), panel);
    g_signal_connect(panel->tension_mode, "toggled", G_CALLBACK(on_command_changed), panel);
    g_signal_connect(panel->tension, "value-changed", G_CALLBACK(on_command_changed), panel);
    return panel;
}

void controls_panel_free(controls_panel *panel)
{
    if (panel->pending_source != 0) {
        g_source_remove(panel->pending_source);
    }
    g_free(panel);
}

GtkWidget *controls_panel_widget(const controls_panel *panel) { return panel->box; }

/* The model picker's choices: the built-in names, and the loaded file
 * when it is not one of them. */
static void sync_model_picker(controls_panel *panel, const simulation *sim)
{
    int builtins = mu_builtin_model_count();
    const char **choices = g_new(const char *, (gsize)builtins + 2);
    guint selected = GTK_INVALID_LIST_POSITION;
    int count = 0;
    for (int k = 0; k < builtins; ++k) {
        if (sim->kind == SIMULATION_MODEL && strcmp(sim->model_argument, mu_builtin_model_name(k)) == 0) {
            selected = (guint)k;
        }
        choices[count++] = mu_builtin_model_name(k);
    }
    if (sim->model_argument[0] != '\0' && !model_source_is_builtin(sim->model_argument)) {
        if (sim->kind == SIMULATION_MODEL) {
            selected = (guint)count;
        }
        choices[count++] = sim->model_argument;
    }
    choices[count] = NULL;
    set_choices(panel->model, choices, selected);
    g_free(choices);
}

/* Variant, weight and muscle pickers of the loaded model. */
static void sync_model_choices(controls_panel *panel, const simulation *sim)
{
    const mu_model_desc *desc = sim->desc;
    int variants = desc != NULL ? desc->variant_count : 0;
    int weights = desc != NULL && desc->has_weight ? desc->weight.mass_count : 0;
    int muscles = sim->kind == SIMULATION_MODEL ? mu_model_muscle_count(sim->model) : 0;
    int groups = desc != NULL ? desc->group_count : 0;
    size_t most = (size_t)(variants + weights + muscles + groups) + 4;
    const char **choices = g_new0(const char *, most);
    char **texts = g_new0(char *, most);

    for (int k = 0; k < variants; ++k) {
        choices[k] = desc->variants[k].name;
    }
    choices[variants] = NULL;
    set_choices(panel->variant, choices, variants > 0 ? (guint)sim->options.variant : GTK_INVALID_LIST_POSITION);

    for (int k = 0; k < weights; ++k) {
        texts[k] = g_strdup_printf("%g kg", desc->weight.masses[k]);
        choices[k] = texts[k];
    }
    choices[weights] = NULL;
    set_choices(panel->weight, choices, weights > 0 ? (guint)sim->options.weight_index : GTK_INVALID_LIST_POSITION);

    /* Muscles and groups: the groups that have a built muscle, then the
     * built muscles themselves. */
    int count = 0;
    guint selected = GTK_INVALID_LIST_POSITION;
    for (int g = 0; g < groups && muscles > 0; ++g) {
        if (!isnan(mu_model_group_activation(sim->model, desc->groups[g].name))) {
            choices[count++] = desc->groups[g].name;
        }
    }
    for (int m = 0; m < muscles; ++m) {
        choices[count++] = mu_model_muscle_name(sim->model, m);
    }
    for (int k = 0; k < count; ++k) {
        if (strcmp(choices[k], sim->target) == 0) {
            selected = (guint)k;
        }
    }
    choices[count] = NULL;
    set_choices(panel->target, choices, selected);

    for (int k = 0; k < weights; ++k) {
        g_free(texts[k]);
    }
    g_free(texts);
    g_free(choices);
}

void controls_panel_sync(controls_panel *panel)
{
    const simulation *sim = &panel->app->sim;
    panel->syncing = true;
    sync_model_picker(panel, sim);
    gtk_drop_down_set_selected(GTK_DROP_DOWN(panel->scene),
                               sim->kind == SIMULATION_SCENE ? (guint)sim->scene.kind + 1 : 0);
    sync_model_choices(panel, sim);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(panel->level), sim->desc != NULL ? sim->options.level : 4);
    gtk_range_set_value(GTK_RANGE(panel->activation), sim->activation);
    gtk_check_button_set_active(GTK_CHECK_BUTTON(panel->tension_mode), sim->tension_mode);
    gtk_spin_button_set_value(GTK_SPIN_BUTTON(panel->tension), sim->tension);
    bool model = sim->kind == SIMULATION_MODEL;
    gtk_widget_set_sensitive(panel->variant, model);
    gtk_widget_set_sensitive(panel->weight, model);
    gtk_widget_set_sensitive(panel->level, model);
    gtk_widget_set_sensitive(panel->target, model);
    gtk_widget_set_sensitive(panel->activation, model);
    gtk_widget_set_sensitive(panel->tension_mode, model);
    gtk_widget_set_sensitive(panel->tension, model);
    panel->syncing = false;
}

void controls_panel_show_playing(controls_panel *panel, bool playing)
{
    panel->syncing = true;
    gtk_toggle_button_set_active(GTK_TOGGLE_BUTTON(panel->play), playing);
    gtk_button_set_label(GTK_BUTTON(panel->play), playing ? "Pause" : "Play");
    panel->syncing = false;
}

GtkWidget *controls_panel_control(const controls_panel *panel, const char *name)
{
    const struct {
        const char *name;
        GtkWidget *widget;
    } controls[] = {
        {"model", panel->model},
        {"scene", panel->scene},
        {"variant", panel->variant},
        {"weight", panel->weight},
        {"level", panel->level},
        {"reload", panel->reload},
        {"play", panel->play},
        {"step", panel->step},
        {"muscle", panel->target},
        {"activation", panel->activation},
        {"tension-mode", panel->tension_mode},
        {"tension", panel->tension},
    };
    for (size_t k = 0; k < sizeof controls / sizeof controls[0]; ++k) {
        if (strcmp(name, controls[k].name) == 0) {
            return controls[k].widget;
        }
    }
    return NULL;
}
