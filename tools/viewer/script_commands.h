/* SPDX-License-Identifier: MIT */
/* The commands of a viewer script (script.h lists them): each with the
 * number of arguments it takes and the function that runs it. A command
 * that waits (play, screenshot, wait-for) records what it waits for in
 * the run state, which the script's runner honours before the next one.
 */
#ifndef VIEWER_SCRIPT_COMMANDS_H
#define VIEWER_SCRIPT_COMMANDS_H

#include <stdbool.h>
#include <stddef.h>

#include "viewer.h"

typedef struct script_run_state {
    viewer *app;
    long frames_left;            /* of the running `play`, stepped one per tick */
    const char *screenshot_path; /* taken after the window's next paint; NULL when none */
    const char *awaited_file;    /* `wait-for`: NULL when none */
    bool quit;                   /* `quit` ran */
} script_run_state;

/* Runs a command with its arguments (as many as it takes; they outlive
 * the run); false with `error` saying what went wrong. */
typedef bool script_command_fn(script_run_state *state, char *const *arguments, char *error, size_t error_size);

typedef struct script_command_spec {
    const char *name;
    int arguments;
    script_command_fn *run;
} script_command_spec;

/* The command named `name`, or NULL. */
const script_command_spec *script_command_find(const char *name);

#endif
