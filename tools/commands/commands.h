/* SPDX-License-Identifier: MIT */
/* The subcommands of `sinew`, one per file of tools/commands/, and the exit
 * statuses they share. Each takes the arguments after its own name and
 * returns the program's exit status; every error is one line on stderr.
 */
#ifndef SINEW_COMMANDS_H
#define SINEW_COMMANDS_H

#include "cli/options.h"

/* Exit statuses: EXIT_SUCCESS (0); EXIT_FAILURE (1) when the engine, a
 * model or control file, or the file system failed; EXIT_USAGE for a bad
 * command line. */
enum { EXIT_USAGE = CLI_EXIT_USAGE };

int cmd_scene(int argc, char **argv);       /* sinew scene NAME [options] */
int cmd_models(int argc, char **argv);      /* sinew models */
int cmd_check(int argc, char **argv);       /* sinew check FILE */
int cmd_run(int argc, char **argv);         /* sinew run MODEL [options] */
int cmd_sweep(int argc, char **argv);       /* sinew sweep SWEEP_FILE [options] */
int cmd_plot(int argc, char **argv);        /* sinew plot CSV [options] */
int cmd_experiment(int argc, char **argv);  /* sinew experiment NAME [options] */
int cmd_moment_arms(int argc, char **argv); /* sinew moment-arms MODEL --hinge NAME [options] */
int cmd_inverse(int argc, char **argv);     /* sinew inverse MODEL --motion FILE [options] */
int cmd_optimize(int argc, char **argv);    /* sinew optimize MODEL --motion FILE [options] */
int cmd_view(int argc, char **argv);        /* sinew view [MODEL] [options]: runs sinew-view */

#endif
