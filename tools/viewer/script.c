/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* strdup */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/words.h"
#include "screenshot.h"
#include "script.h"
#include "script_commands.h"

enum { SCRIPT_MAX_WORDS = 4, SCRIPT_LINE_SIZE = 4096 };
/* Ticks (of about a millisecond) given to the window's input after a
 * `wait-for` file appears. */
enum { SCRIPT_SETTLE_TICKS = 50 };

typedef struct script_line {
    int number; /* in the file, from 1 */
    const script_command_spec *command;
    int word_count;
    char *words[SCRIPT_MAX_WORDS]; /* the command's name, then its arguments */
} script_line;

struct script {
    char *path;
    script_line *lines;
    int count, capacity;
    /* While running: */
    script_run_state state;
    int next;               /* the line to run next */
    int screenshot_line;    /* the line whose screenshot waits for a paint */
    int load_failures_seen; /* the viewer's load_failures when the last command ran */
    int settle_ticks;       /* left after a `wait-for` file appeared */
    gulong paint_handler;   /* on the window's frame clock */
};

static bool add_line(script *commands, int number, char **words, int count, char *error, size_t error_size)
{
    const script_command_spec *command = script_command_find(words[0]);
    if (command == NULL) {
        snprintf(error, error_size, "%s:%d: unknown command \"%s\"", commands->path, number, words[0]);
        return false;
    }
    if (count - 1 != command->arguments) {
        snprintf(error, error_size, "%s:%d: \"%s\" takes %d argument%s, got %d", commands->path, number, words[0],
                 command->arguments, command->arguments == 1 ? "" : "s", count - 1);
        return false;
    }
    if (commands->count == commands->capacity) {
        int capacity = commands->capacity > 0 ? 2 * commands->capacity : 16;
        script_line *grown = realloc(commands->lines, sizeof *grown * (size_t)capacity);
        if (grown == NULL) {
            snprintf(error, error_size, "%s: out of memory", commands->path);
            return false;
        }
        commands->lines = grown;
        commands->capacity = capacity;
    }
    script_line *line = &commands->lines[commands->count++];
    *line = (script_line){.number = number, .command = command};
    for (int k = 0; k < count; ++k) {
        line->words[k] = strdup(words[k]);
        if (line->words[k] == NULL) {
            snprintf(error, error_size, "%s: out of memory", commands->path);
            return false;
        }
        line->word_count = k + 1;
    }
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
    for (int number = 1; ok && fgets(text, sizeof text, file) != NULL; ++number) {
        char *words[SCRIPT_MAX_WORDS];
        const char *problem = NULL;
        int count = words_split(text, words, SCRIPT_MAX_WORDS, &problem);
        if (count < 0) {
            snprintf(error, error_size, "%s:%d: %s", path, number, problem);
            ok = false;
        } else if (count > SCRIPT_MAX_WORDS) {
            snprintf(error, error_size, "%s:%d: more than %d words", path, number, SCRIPT_MAX_WORDS);
            ok = false;
        } else if (count > 0) {
            ok = add_line(commands, number, words, count, error, error_size);
        }
    }
    /* fgets returns NULL on an error as at the end: a directory, or a
     * read that failed, must not pass for an empty script. */
    if (ok && ferror(file)) {
        snprintf(error, error_size, "%s: cannot read the script: %s", path, strerror(errno));
        ok = false;
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
        for (int k = 0; k < commands->lines[c].word_count; ++k) {
            free(commands->lines[c].words[k]);
        }
    }
    free(commands->lines);
    free(commands->path);
    free(commands);
}

/* ---- running ---------------------------------------------------------------------- */

static void fail_and_quit(script *commands, const script_line *line, const char *error)
{
    fprintf(stderr, "sinew view: %s:%d: %s\n", commands->path, line->number, error);
    commands->state.app->exit_status = EXIT_FAILURE;
    g_main_loop_quit(commands->state.app->loop);
}

/* After the window's paint: the screenshot a command waits for. */
static void on_after_paint(GdkFrameClock *clock, gpointer data)
{
    (void)clock;
    script *commands = data;
    const char *path = commands->state.screenshot_path;
    if (path == NULL) {
        return;
    }
    commands->state.screenshot_path = NULL;
    char error[SIMULATION_ERROR_SIZE];
    if (!screenshot_window(commands->state.app->window, path, error, sizeof error)) {
        fail_and_quit(commands, &commands->lines[commands->screenshot_line], error);
    }
}

/* Whether the script must wait before its next command: for the window,
 * a screenshot, a file, or the input that came with it. */
static bool waiting(script *commands)
{
    viewer *app = commands->state.app;
    if (!gtk_widget_get_mapped(app->window) || gtk_widget_get_width(app->canvas) <= 1 ||
        commands->state.screenshot_path != NULL) {
        return true;
    }
    if (commands->state.awaited_file != NULL) {
        if (!g_file_test(commands->state.awaited_file, G_FILE_TEST_EXISTS)) {
            return true;
        }
        /* The input sent before the file appeared has reached the X
         * server; a round trip brings its events in, and a few more
         * ticks of the main loop let the widgets handle them. */
        commands->state.awaited_file = NULL;
        gdk_display_sync(gdk_display_get_default());
        commands->settle_ticks = SCRIPT_SETTLE_TICKS;
    }
    if (commands->settle_ticks > 0) {
        --commands->settle_ticks;
        return true;
    }
    return false;
}

static gboolean on_script_tick(gpointer data)
{
    script *commands = data;
    viewer *app = commands->state.app;
    if (waiting(commands)) {
        return G_SOURCE_CONTINUE;
    }
    if (commands->paint_handler == 0) {
        commands->paint_handler = g_signal_connect(gtk_widget_get_frame_clock(app->window), "after-paint",
                                                   G_CALLBACK(on_after_paint), commands);
    }
    /* A load the last command started (a control's, which runs from the
     * main loop) failed: the script fails at that command's line. */
    if (commands->next > 0 && app->load_failures != commands->load_failures_seen) {
        fail_and_quit(commands, &commands->lines[commands->next - 1], app->load_error);
        return G_SOURCE_REMOVE;
    }
    if (commands->state.frames_left > 0) {
        --commands->state.frames_left;
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
    int index = commands->next++;
    const script_line *line = &commands->lines[index];
    commands->load_failures_seen = app->load_failures;
    char error[SIMULATION_ERROR_SIZE] = "";
    if (!line->command->run(&commands->state, line->words + 1, error, sizeof error)) {
        fail_and_quit(commands, line, error);
        return G_SOURCE_REMOVE;
    }
    if (commands->state.screenshot_path != NULL) {
        commands->screenshot_line = index;
    }
    if (commands->state.quit) {
        g_main_loop_quit(app->loop);
        return G_SOURCE_REMOVE;
    }
    return G_SOURCE_CONTINUE;
}

void script_start(script *commands, viewer *app)
{
    commands->state = (script_run_state){.app = app};
    /* A load that failed before the script (the command line's) is not
     * the script's. */
    commands->load_failures_seen = app->load_failures;
    commands->next = 0;
    commands->settle_ticks = 0;
    g_timeout_add(1, on_script_tick, commands);
}
