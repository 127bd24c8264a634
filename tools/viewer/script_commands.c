/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <string.h>

#include "cli/option_value.h"
#include "cli/user_error.h"
#include "controls_panel.h"
#include "engine_panel.h"
#include "graphs_panel.h"
#include "layout_check.h"
#include "script_commands.h"
#include "widget_input.h"

/* Bounds of the numbers scripts give: far beyond any use, well inside
 * what the types hold. */
#define MAX_FRAMES 10000000L
#define MAX_RECRUITMENT_STEP 1000000L
#define MAX_SCRIPT_WEIGHT 1e9  /* kg */
#define MAX_SCRIPT_TENSION 1e9 /* N */

/* ---- what the commands print ------------------------------------------------------- */

/* Where a canvas point is in the window, px: what an input tool aims at. */
static graphene_point_t canvas_to_window(const viewer *app, rb_vec2 canvas)
{
    graphene_point_t in = GRAPHENE_POINT_INIT((float)canvas.x, (float)canvas.y), out = in;
    if (!gtk_widget_compute_point(app->canvas, app->window, &in, &out)) {
        out = in;
    }
    return out;
}

/* A control of the panels by its name (script.h lists them), or NULL. */
static GtkWidget *control_named(const viewer *app, const char *name)
{
    GtkWidget *control = controls_panel_control(app->controls, name);
    control = control != NULL ? control : engine_panel_control(app->engine, name);
    return control != NULL ? control : graphs_panel_control(app->graphs, name);
}

static bool run_angles(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)arguments;
    (void)error;
    (void)error_size;
    const simulation *sim = &state->app->sim;
    printf("angles t=%.4f", simulation_time(sim));
    for (int k = 0; sim->kind == SIMULATION_MODEL && k < mu_model_hinge_count(sim->model); ++k) {
        printf(" %s=%.4f", mu_model_hinge_name(sim->model, k), mu_model_hinge_angle(sim->model, k));
    }
    printf("\n");
    fflush(stdout);
    return true;
}

static bool run_status(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)arguments;
    (void)error;
    (void)error_size;
    const viewer *app = state->app;
    const simulation *sim = &app->sim;
    int recruited = sim->kind == SIMULATION_MODEL && mu_model_torque_muscle_count(sim->model) > 0
                        ? mu_motor_pool_recruited(mu_model_motor_pool(sim->model, 0))
                        : -1;
    graphene_point_t corner = canvas_to_window(app, rb_v2(0.0, 0.0));
    printf("status t=%.4f frame=%ld playing=%d dragging=%d scale=%.6g centre=%.6g,%.6g canvas=%.0f,%.0f,%d,%d "
           "recruited=%d",
           simulation_time(sim), sim->frame, app->playing, sim->dragging, app->view.scale, app->view.centre.x,
           app->view.centre.y, corner.x, corner.y, gtk_widget_get_width(app->canvas),
           gtk_widget_get_height(app->canvas), recruited);
    if (sim->kind == SIMULATION_MODEL) {
        printf(" model=%s variant=%d weight=%d level=%d muscles=%d tension_mode=%d activation=%.4g tension=%.4g",
               sim->model_argument, sim->options.variant, sim->options.weight_index, sim->options.level,
               mu_model_muscle_count(sim->model), sim->tension_mode, sim->activation, sim->tension);
    } else if (sim->kind == SIMULATION_SCENE) {
        printf(" scene=%s", scene_registry[sim->scene.kind].name);
    }
    rb_world *world = simulation_world(sim);
    if (world != NULL) {
        rb_solver_settings settings = rb_world_solver_settings(world);
        printf(" solver=%s velocity_iterations=%d position_iterations=%d substeps=%d warm_starting=%d",
               rb_solver_type_name(settings.type), settings.velocity_iterations, settings.position_iterations,
               settings.substeps, settings.warm_starting);
    }
    printf(" target=\"%s\"", sim->target);
    if (gtk_widget_get_visible(app->message_bar)) {
        printf(" message=\"%s\"", gtk_label_get_text(GTK_LABEL(app->message_label)));
    }
    printf("\n");
    fflush(stdout);
    return true;
}

/* Prints where a model's part, or the middle of a control, is in the
 * window: "locate NAME X Y". */
static bool run_locate(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    const viewer *app = state->app;
    const simulation *sim = &app->sim;
    const char *name = arguments[0];
    GtkWidget *control = control_named(app, name);
    if (control != NULL) {
        graphene_point_t middle = GRAPHENE_POINT_INIT(0.5f * (float)gtk_widget_get_width(control),
                                                      0.5f * (float)gtk_widget_get_height(control));
        graphene_point_t at = middle;
        if (!gtk_widget_compute_point(control, app->window, &middle, &at)) {
            snprintf(error, error_size, "the control \"%s\" is not in the window now", name);
            return false;
        }
        printf("locate %s %.0f %.0f\n", name, at.x, at.y);
        fflush(stdout);
        return true;
    }
    for (int k = 0; sim->kind == SIMULATION_MODEL && k < mu_model_part_count(sim->model); ++k) {
        if (strcmp(mu_model_part_name(sim->model, k), name) == 0) {
            rb_vec2 screen = view_world_to_screen(&app->view, mu_model_part_centre(sim->model, k));
            graphene_point_t at = canvas_to_window(app, screen);
            printf("locate %s %.0f %.0f\n", name, at.x, at.y);
            fflush(stdout);
            return true;
        }
    }
    snprintf(error, error_size, "no part or control named \"%s\"", name);
    return false;
}

static bool run_print(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)state;
    (void)error;
    (void)error_size;
    printf("%s\n", arguments[0]);
    fflush(stdout);
    return true;
}

/* ---- what is loaded ------------------------------------------------------------- */

static bool run_model(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    mu_model_options options = mu_default_model_options();
    if (!viewer_load_model(state->app, arguments[0], &options)) {
        snprintf(error, error_size, "%s", state->app->load_error);
        return false;
    }
    return true;
}

/* Rebuilds the model with `options` when they were chosen. */
static bool rebuild(viewer *app, bool chosen, const mu_model_options *options, char *error, size_t error_size)
{
    if (!chosen) {
        return false;
    }
    if (!viewer_reload_model(app, options)) {
        snprintf(error, error_size, "%s", app->load_error);
        return false;
    }
    return true;
}

static bool run_variant(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    mu_model_options options;
    bool chosen = simulation_choose_variant(&state->app->sim, arguments[0], &options, error, error_size);
    return rebuild(state->app, chosen, &options, error, error_size);
}

static bool run_weight(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    double kilograms;
    mu_model_options options;
    bool chosen =
        option_parse_double("weight", arguments[0], 0.0, false, MAX_SCRIPT_WEIGHT, &kilograms, error, error_size) &&
        simulation_choose_weight(&state->app->sim, kilograms, &options, error, error_size);
    return rebuild(state->app, chosen, &options, error, error_size);
}

static bool run_level(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    int level;
    mu_model_options options;
    bool chosen = option_parse_int("level", arguments[0], 0, 4, &level, error, error_size) &&
                  simulation_choose_level(&state->app->sim, level, &options, error, error_size);
    return rebuild(state->app, chosen, &options, error, error_size);
}

static bool run_scene(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    scene_kind kind;
    if (!scene_kind_from_name(arguments[0], &kind)) {
        char names[256];
        scene_list_names(names, sizeof names);
        snprintf(error, error_size, "unknown scene \"%s\" (%s)", arguments[0], names);
        return false;
    }
    if (!viewer_load_scene(state->app, kind)) {
        snprintf(error, error_size, "%s", state->app->load_error);
        return false;
    }
    return true;
}

/* ---- the simulation -------------------------------------------------------------- */

static bool run_play(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    int frames;
    if (!option_parse_int("play", arguments[0], 0, MAX_FRAMES, &frames, error, error_size)) {
        return false;
    }
    state->frames_left = frames;
    return true;
}

/* Selects the muscle or group `name` and shows it in the panels. */
static bool select_target(viewer *app, const char *name, char *error, size_t error_size)
{
    if (!simulation_select(&app->sim, name, error, error_size)) {
        return false;
    }
    controls_panel_sync(app->controls);
    viewer_target_changed(app);
    return true;
}

static bool run_activation(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    double activation;
    viewer *app = state->app;
    bool done = option_parse_double("activation", arguments[1], 0.0, false, 1.0, &activation, error, error_size) &&
                select_target(app, arguments[0], error, error_size) &&
                simulation_set_activation(&app->sim, activation, error, error_size);
    controls_panel_sync(app->controls);
    return done;
}

static bool run_tension(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    double newtons;
    viewer *app = state->app;
    bool done =
        option_parse_double("tension", arguments[1], 0.0, false, MAX_SCRIPT_TENSION, &newtons, error, error_size) &&
        select_target(app, arguments[0], error, error_size) &&
        simulation_set_tension(&app->sim, newtons, error, error_size);
    controls_panel_sync(app->controls);
    return done;
}

static bool run_pulse(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    if (!select_target(state->app, arguments[0], error, error_size)) {
        return false;
    }
    simulation_pulse(&state->app->sim);
    return true;
}

static bool run_recruit(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    int delta;
    return option_parse_int("recruit", arguments[0], -MAX_RECRUITMENT_STEP, MAX_RECRUITMENT_STEP, &delta, error,
                            error_size) &&
           simulation_recruit_more(&state->app->sim, delta, error, error_size);
}

/* ---- the engine and the window ------------------------------------------------------ */

static bool run_solver(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    rb_world *world = simulation_world(&state->app->sim);
    if (world == NULL) {
        snprintf(error, error_size, "nothing is loaded");
        return false;
    }
    rb_solver_settings settings = rb_world_solver_settings(world);
    if (rb_solver_type_from_name(arguments[0], &settings.type) != RB_OK ||
        rb_world_set_solver_settings(world, &settings) != RB_OK) {
        snprintf(error, error_size, "%s", user_error());
        return false;
    }
    engine_panel_sync(state->app->engine);
    return true;
}

static bool run_overlay(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    viewer *app = state->app;
    bool *flags[CANVAS_OVERLAY_COUNT];
    canvas_overlay_flags(&app->overlays, flags);
    for (int k = 0; k < CANVAS_OVERLAY_COUNT; ++k) {
        if (strcmp(arguments[0], canvas_overlay_names[k]) == 0 &&
            (strcmp(arguments[1], "on") == 0 || strcmp(arguments[1], "off") == 0)) {
            *flags[k] = strcmp(arguments[1], "on") == 0;
            engine_panel_sync(app->engine);
            gtk_widget_queue_draw(app->canvas);
            return true;
        }
    }
    snprintf(error, error_size, "expected overlay contacts|normals|impulses|aabbs|joints|reactions|sleeping on|off");
    return false;
}

static bool run_set(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    GtkWidget *control = control_named(state->app, arguments[0]);
    if (control == NULL) {
        snprintf(error, error_size, "no control named \"%s\" (tools/viewer/script.h lists them)", arguments[0]);
        return false;
    }
    char problem[SIMULATION_ERROR_SIZE];
    if (!widget_input_set(control, arguments[1], problem, sizeof problem)) {
        snprintf(error, error_size, "%s: %s", arguments[0], problem);
        return false;
    }
    return true;
}

static bool run_wait_for(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)error;
    (void)error_size;
    state->awaited_file = arguments[0];
    return true;
}

static bool run_screenshot(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)error;
    (void)error_size;
    state->screenshot_path = arguments[0];
    gtk_widget_queue_draw(state->app->window);
    return true;
}

static bool run_export(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    for (int k = 0; k < LIVE_GRAPH_COUNT; ++k) {
        if (strcmp(arguments[0], live_graph_file_stem((live_graph_kind)k)) == 0) {
            return graphs_panel_export(state->app->graphs, (live_graph_kind)k, arguments[1], error, error_size);
        }
    }
    snprintf(error, error_size, "unknown graph \"%s\" (activation, tension, selected_forces, contraction)",
             arguments[0]);
    return false;
}

/* Every control and graph drawn whole, or in a scrolled window with a
 * scrollbar (layout_check.h): prints "visible WIDTHxHEIGHT: N widgets". */
static bool run_visible(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)arguments;
    GtkWidget *window = state->app->window;
    int checked = 0;
    if (!layout_check_window(window, &checked, error, error_size)) {
        return false;
    }
    printf("visible %dx%d: %d widgets\n", gtk_widget_get_width(window), gtk_widget_get_height(window), checked);
    fflush(stdout);
    return true;
}

static bool run_quit(script_run_state *state, char *const *arguments, char *error, size_t error_size)
{
    (void)arguments;
    (void)error;
    (void)error_size;
    state->quit = true;
    return true;
}

static const script_command_spec commands[] = {
    {"model", 1, run_model},
    {"variant", 1, run_variant},
    {"weight", 1, run_weight},
    {"level", 1, run_level},
    {"scene", 1, run_scene},
    {"play", 1, run_play},
    {"activation", 2, run_activation},
    {"tension", 2, run_tension},
    {"pulse", 1, run_pulse},
    {"recruit", 1, run_recruit},
    {"solver", 1, run_solver},
    {"overlay", 2, run_overlay},
    {"set", 2, run_set},
    {"angles", 0, run_angles},
    {"status", 0, run_status},
    {"locate", 1, run_locate},
    {"print", 1, run_print},
    {"wait-for", 1, run_wait_for},
    {"screenshot", 1, run_screenshot},
    {"visible", 0, run_visible},
    {"export", 2, run_export},
    {"quit", 0, run_quit},
};

const script_command_spec *script_command_find(const char *name)
{
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; ++k) {
        if (strcmp(name, commands[k].name) == 0) {
            return &commands[k];
        }
    }
    return NULL;
}
