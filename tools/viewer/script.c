#define _POSIX_C_SOURCE 200809L /* strdup */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "controls_panel.h"
#include "engine_panel.h"
#include "graphs_panel.h"
#include "screenshot.h"
#include "script.h"
#include "widget_input.h"

enum { SCRIPT_MAX_WORDS = 4, SCRIPT_LINE_SIZE = 4096 };
/* Ticks (of about a millisecond) given to the window's input after a
 * `wait-for` file appears. */
enum { SCRIPT_SETTLE_TICKS = 50 };

typedef struct script_command {
    int line;
    int word_count;
    char *words[SCRIPT_MAX_WORDS];
} script_command;

struct script {
    char *path;
    script_command *commands;
    int count, capacity;
    /* While running: */
    viewer *app;
    int next;         /* the command to run next */
    long frames_left; /* of the running `play` */
    /* A screenshot waits for the window's next paint, so that it shows
     * what the commands before it did: the command's index, or -1. */
    int screenshot_waiting;
    /* `wait-for FILE`: the file waited for (NULL when none), then the
     * ticks left for the window's input to be handled once it exists. */
    const char *awaited_file;
    int settle_ticks;
    gulong paint_handler;
};

/* The commands, with the number of words each takes after its name. */
static const struct {
    const char *name;
    int arguments;
} known_commands[] = {
    {"model", 1},   {"variant", 1}, {"weight", 1},   {"level", 1},  {"scene", 1},      {"play", 1},   {"activation", 2},
    {"tension", 2}, {"pulse", 1},   {"recruit", 1},  {"solver", 1}, {"overlay", 2},    {"angles", 0}, {"status", 0},
    {"locate", 1},  {"print", 1},   {"wait-for", 1}, {"set", 2},    {"screenshot", 1}, {"export", 2}, {"quit", 0},
};

/* Splits `text` into words in place: spaces and tabs separate, double
 * quotes group, '#' outside quotes ends the line. Returns the count, or
 * -1 for an unclosed quote or too many words. */
static int split_words(char *text, char **words)
{
    int count = 0;
    char *at = text;
    for (;;) {
        while (*at == ' ' || *at == '\t' || *at == '\r' || *at == '\n') {
            ++at;
        }
        if (*at == '\0' || *at == '#') {
            return count;
        }
        if (count == SCRIPT_MAX_WORDS) {
            return -1;
        }
        if (*at == '"') {
            char *close = strchr(at + 1, '"');
            if (close == NULL) {
                return -1;
            }
            *close = '\0';
            words[count++] = at + 1;
            at = close + 1;
            continue;
        }
        words[count++] = at;
        while (*at != '\0' && *at != ' ' && *at != '\t' && *at != '\r' && *at != '\n') {
            ++at;
        }
        if (*at != '\0') {
            *at++ = '\0';
        }
    }
}

static int arguments_of(const char *name)
{
    for (size_t k = 0; k < sizeof known_commands / sizeof known_commands[0]; ++k) {
        if (strcmp(name, known_commands[k].name) == 0) {
            return known_commands[k].arguments;
        }
    }
    return -1;
}

static bool add_command(script *commands, int line, char **words, int count, char *error, size_t error_size)
{
    int arguments = arguments_of(words[0]);
    if (arguments < 0) {
        snprintf(error, error_size, "%s:%d: unknown command \"%s\"", commands->path, line, words[0]);
        return false;
    }
    if (count - 1 != arguments) {
        snprintf(error, error_size, "%s:%d: \"%s\" takes %d argument%s, got %d", commands->path, line, words[0],
                 arguments, arguments == 1 ? "" : "s", count - 1);
        return false;
    }
    if (commands->count == commands->capacity) {
        int capacity = commands->capacity > 0 ? 2 * commands->capacity : 16;
        script_command *grown = realloc(commands->commands, sizeof *grown * (size_t)capacity);
        if (grown == NULL) {
            snprintf(error, error_size, "%s: out of memory", commands->path);
            return false;
        }
        commands->commands = grown;
        commands->capacity = capacity;
    }
    script_command *command = &commands->commands[commands->count];
    *command = (script_command){.line = line, .word_count = count};
    for (int k = 0; k < count; ++k) {
        command->words[k] = strdup(words[k]);
        if (command->words[k] == NULL) {
            snprintf(error, error_size, "%s: out of memory", commands->path);
            command->word_count = k;
            ++commands->count;
            return false;
        }
    }
    ++commands->count;
    return true;
}

script *script_load(const char *path, char *error, size_t error_size)
{
    script *commands = calloc(1, sizeof *commands);
    FILE *file = fopen(path, "r");
    if (commands == NULL || file == NULL) {
        snprintf(error, error_size, "%s: %s", path, commands == NULL ? "out of memory" : strerror(errno));
        free(commands);
        if (file != NULL) {
            fclose(file);
        }
        return NULL;
    }
    commands->path = strdup(path);
    char text[SCRIPT_LINE_SIZE];
    bool ok = commands->path != NULL;
    for (int line = 1; ok && fgets(text, sizeof text, file) != NULL; ++line) {
        char *words[SCRIPT_MAX_WORDS];
        int count = split_words(text, words);
        if (count < 0) {
            snprintf(error, error_size, "%s:%d: an unclosed quote, or more than %d words", path, line,
                     SCRIPT_MAX_WORDS);
            ok = false;
        } else if (count > 0) {
            ok = add_command(commands, line, words, count, error, error_size);
        }
    }
    fclose(file);
    if (!ok) {
        script_free(commands);
        return NULL;
    }
    return commands;
}

void script_free(script *commands)
{
    if (commands == NULL) {
        return;
    }
    for (int c = 0; c < commands->count; ++c) {
        for (int k = 0; k < commands->commands[c].word_count; ++k) {
            free(commands->commands[c].words[k]);
        }
    }
    free(commands->commands);
    free(commands->path);
    free(commands);
}

/* ---- running ---------------------------------------------------------------------- */

static bool parse_number(const char *text, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    return end != text && *end == '\0' && errno == 0;
}

static void print_angles(const viewer *app)
{
    printf("angles t=%.4f", simulation_time(&app->sim));
    if (app->sim.kind == SIMULATION_MODEL) {
        for (int k = 0; k < mu_model_hinge_count(app->sim.model); ++k) {
            printf(" %s=%.4f", mu_model_hinge_name(app->sim.model, k), mu_model_hinge_angle(app->sim.model, k));
        }
    }
    printf("\n");
    fflush(stdout);
}

/* Where a canvas point is in the window, px: what an input tool aims at. */
static graphene_point_t canvas_to_window(const viewer *app, rb_vec2 canvas)
{
    graphene_point_t in = GRAPHENE_POINT_INIT((float)canvas.x, (float)canvas.y), out = in;
    if (!gtk_widget_compute_point(app->canvas, app->window, &in, &out)) {
        out = in;
    }
    return out;
}

static void print_status(const viewer *app)
{
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
        printf(" scene=%s", viewer_scene_name(sim->scene.kind));
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
}

/* A control of the panels by its name (script.h lists them), or NULL. */
static GtkWidget *control_named(const viewer *app, const char *name)
{
    GtkWidget *control = controls_panel_control(app->controls, name);
    control = control != NULL ? control : engine_panel_control(app->engine, name);
    return control != NULL ? control : graphs_panel_control(app->graphs, name);
}

/* Prints where a model's part, or the middle of a control, is in the
 * window: "locate NAME X Y". */
static bool locate(const viewer *app, const char *name, char *error, size_t error_size)
{
    const simulation *sim = &app->sim;
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

static bool *overlay_named(viewer *app, const char *name)
{
    bool *flags[CANVAS_OVERLAY_COUNT];
    canvas_overlay_flags(&app->overlays, flags);
    for (int k = 0; k < CANVAS_OVERLAY_COUNT; ++k) {
        if (strcmp(name, canvas_overlay_names[k]) == 0) {
            return flags[k];
        }
    }
    return NULL;
}

static bool graph_named(const char *name, live_graph_kind *kind)
{
    for (int k = 0; k < LIVE_GRAPH_COUNT; ++k) {
        if (strcmp(name, live_graph_file_stem((live_graph_kind)k)) == 0) {
            *kind = (live_graph_kind)k;
            return true;
        }
    }
    return false;
}

/* Rebuilds the model with `options` when they were chosen. */
static bool rebuild(viewer *app, bool chosen, const mu_model_options *options, char *error, size_t error_size)
{
    if (!chosen) {
        return false;
    }
    if (!viewer_reload_model(app, options)) {
        snprintf(error, error_size, "the model did not build (the message above says why)");
        return false;
    }
    return true;
}

/* Runs one command; `error` gets what went wrong. */
static bool run_command(script *commands, const script_command *command, char *error, size_t error_size)
{
    viewer *app = commands->app;
    const char *name = command->words[0];
    const char *first = command->word_count > 1 ? command->words[1] : "";
    const char *second = command->word_count > 2 ? command->words[2] : "";
    simulation *sim = &app->sim;
    mu_model_options options;
    double number;
    if (strcmp(name, "model") == 0) {
        options = mu_default_model_options();
        if (!viewer_load_model(app, first, &options)) {
            snprintf(error, error_size, "the model \"%s\" did not load (the message above says why)", first);
            return false;
        }
        return true;
    }
    if (strcmp(name, "variant") == 0) {
        return rebuild(app, simulation_choose_variant(sim, first, &options, error, error_size), &options, error,
                       error_size);
    }
    if (strcmp(name, "weight") == 0) {
        if (!parse_number(first, &number)) {
            snprintf(error, error_size, "expected a weight in kg, got \"%s\"", first);
            return false;
        }
        return rebuild(app, simulation_choose_weight(sim, number, &options, error, error_size), &options, error,
                       error_size);
    }
    if (strcmp(name, "level") == 0) {
        if (!parse_number(first, &number) || number != (int)number) {
            snprintf(error, error_size, "expected a level 0 .. 4, got \"%s\"", first);
            return false;
        }
        return rebuild(app, simulation_choose_level(sim, (int)number, &options, error, error_size), &options, error,
                       error_size);
    }
    if (strcmp(name, "scene") == 0) {
        viewer_scene_kind kind;
        if (!viewer_scene_from_name(first, &kind)) {
            snprintf(error, error_size, "unknown scene \"%s\" (pyramid, chain, pendulum, balls, joint-grid)", first);
            return false;
        }
        if (!viewer_load_scene(app, kind)) {
            snprintf(error, error_size, "the scene \"%s\" did not load (the message above says why)", first);
            return false;
        }
        return true;
    }
    if (strcmp(name, "play") == 0) {
        if (!parse_number(first, &number) || number < 0 || number > 1e7 || number != (long)number) {
            snprintf(error, error_size, "expected a number of frames, got \"%s\"", first);
            return false;
        }
        commands->frames_left = (long)number;
        return true;
    }
    if (strcmp(name, "activation") == 0 || strcmp(name, "tension") == 0) {
        if (!parse_number(second, &number)) {
            snprintf(error, error_size, "expected a number after the name, got \"%s\"", second);
            return false;
        }
        bool tension = strcmp(name, "tension") == 0;
        bool done = simulation_select(sim, first, error, error_size) &&
                    (tension ? simulation_set_tension(sim, number, error, error_size)
                             : simulation_set_activation(sim, number, error, error_size));
        controls_panel_sync(app->controls);
        viewer_target_changed(app);
        return done;
    }
    if (strcmp(name, "pulse") == 0) {
        if (!simulation_select(sim, first, error, error_size)) {
            return false;
        }
        simulation_pulse(sim);
        controls_panel_sync(app->controls);
        viewer_target_changed(app);
        return true;
    }
    if (strcmp(name, "recruit") == 0) {
        if (!parse_number(first, &number) || number != (int)number) {
            snprintf(error, error_size, "expected a whole number of neurons, got \"%s\"", first);
            return false;
        }
        return simulation_recruit_more(sim, (int)number, error, error_size);
    }
    if (strcmp(name, "solver") == 0) {
        rb_world *world = simulation_world(sim);
        rb_solver_settings settings;
        if (world == NULL) {
            snprintf(error, error_size, "nothing is loaded");
            return false;
        }
        settings = rb_world_solver_settings(world);
        if (rb_solver_type_from_name(first, &settings.type) != RB_OK ||
            rb_world_set_solver_settings(world, &settings) != RB_OK) {
            snprintf(error, error_size, "%s", rb_last_error());
            return false;
        }
        engine_panel_sync(app->engine);
        return true;
    }
    if (strcmp(name, "overlay") == 0) {
        bool *flag = overlay_named(app, first);
        if (flag == NULL || (strcmp(second, "on") != 0 && strcmp(second, "off") != 0)) {
            snprintf(error, error_size,
                     "expected overlay contacts|normals|impulses|aabbs|joints|reactions|sleeping on|off");
            return false;
        }
        *flag = strcmp(second, "on") == 0;
        engine_panel_sync(app->engine);
        gtk_widget_queue_draw(app->canvas);
        return true;
    }
    if (strcmp(name, "angles") == 0) {
        print_angles(app);
        return true;
    }
    if (strcmp(name, "status") == 0) {
        print_status(app);
        return true;
    }
    if (strcmp(name, "locate") == 0) {
        return locate(app, first, error, error_size);
    }
    if (strcmp(name, "set") == 0) {
        GtkWidget *control = control_named(app, first);
        if (control == NULL) {
            snprintf(error, error_size, "no control named \"%s\" (tools/viewer/script.h lists them)", first);
            return false;
        }
        return widget_input_set(control, second, error, error_size);
    }
    if (strcmp(name, "print") == 0) {
        printf("%s\n", first);
        fflush(stdout);
        return true;
    }
    if (strcmp(name, "wait-for") == 0) {
        commands->awaited_file = first;
        return true;
    }
    if (strcmp(name, "screenshot") == 0) {
        commands->screenshot_waiting = commands->next - 1;
        gtk_widget_queue_draw(app->window);
        return true;
    }
    if (strcmp(name, "export") == 0) {
        live_graph_kind kind;
        if (!graph_named(first, &kind)) {
            snprintf(error, error_size, "unknown graph \"%s\" (activation, tension, selected_forces, contraction)",
                     first);
            return false;
        }
        return graphs_panel_export(app->graphs, kind, second, error, error_size);
    }
    g_main_loop_quit(app->loop);
    return true;
}

static void fail_and_quit(script *commands, const script_command *command, const char *error)
{
    fprintf(stderr, "sinew view: %s:%d: %s\n", commands->path, command->line, error);
    commands->app->exit_status = EXIT_FAILURE;
    g_main_loop_quit(commands->app->loop);
}

/* After the window's paint: the screenshot a command waits for. */
static void on_after_paint(GdkFrameClock *clock, gpointer data)
{
    (void)clock;
    script *commands = data;
    if (commands->screenshot_waiting < 0) {
        return;
    }
    const script_command *command = &commands->commands[commands->screenshot_waiting];
    commands->screenshot_waiting = -1;
    char error[SIMULATION_ERROR_SIZE];
    if (!screenshot_window(commands->app->window, command->words[1], error, sizeof error)) {
        fail_and_quit(commands, command, error);
    }
}

static gboolean on_script_tick(gpointer data)
{
    script *commands = data;
    viewer *app = commands->app;
    if (!gtk_widget_get_mapped(app->window) || gtk_widget_get_width(app->canvas) <= 1 ||
        commands->screenshot_waiting >= 0) {
        return G_SOURCE_CONTINUE;
    }
    if (commands->awaited_file != NULL) {
        if (!g_file_test(commands->awaited_file, G_FILE_TEST_EXISTS)) {
            return G_SOURCE_CONTINUE;
        }
        /* The input sent before the file appeared has reached the X
         * server; a round trip brings its events in, and a few more
         * ticks of the main loop let the widgets handle them. */
        commands->awaited_file = NULL;
        gdk_display_sync(gdk_display_get_default());
        commands->settle_ticks = SCRIPT_SETTLE_TICKS;
    }
    if (commands->settle_ticks > 0) {
        --commands->settle_ticks;
        return G_SOURCE_CONTINUE;
    }
    if (commands->paint_handler == 0) {
        commands->paint_handler = g_signal_connect(gtk_widget_get_frame_clock(app->window), "after-paint",
                                                   G_CALLBACK(on_after_paint), commands);
    }
    if (commands->frames_left > 0) {
        --commands->frames_left;
        if (!viewer_step(app)) {
            app->exit_status = EXIT_FAILURE;
            g_main_loop_quit(app->loop);
            return G_SOURCE_REMOVE;
        }
        viewer_refresh(app);
        return G_SOURCE_CONTINUE;
    }
    if (commands->next == commands->count) {
        return G_SOURCE_REMOVE;
    }
    const script_command *command = &commands->commands[commands->next++];
    char error[SIMULATION_ERROR_SIZE] = "";
    if (!run_command(commands, command, error, sizeof error)) {
        fail_and_quit(commands, command, error);
        return G_SOURCE_REMOVE;
    }
    return G_SOURCE_CONTINUE;
}

void script_start(script *commands, viewer *app)
{
    commands->app = app;
    commands->next = 0;
    commands->frames_left = 0;
    commands->screenshot_waiting = -1;
    commands->awaited_file = NULL;
    commands->settle_ticks = 0;
    g_timeout_add(1, on_script_tick, commands);
}
