/* SPDX-License-Identifier: MIT */
/* The command line of `sinew view` (the sinew-view program):
 *   sinew view [MODEL] [--variant NAME|N] [--weight KG] [--level N]
 *              [--scene NAME] [--play] [--script FILE]
 */
#ifndef VIEWER_VIEWER_OPTIONS_H
#define VIEWER_VIEWER_OPTIONS_H

#include <stdbool.h>
#include <stdio.h>

typedef struct viewer_options {
    const char *model;   /* default "arm" */
    const char *variant; /* NULL: the first */
    bool has_weight;
    double weight; /* kg */
    bool has_level;
    int level;
    const char *scene;  /* NULL: the model */
    const char *script; /* NULL: none */
    bool play;          /* start playing */
} viewer_options;

/* The help of `sinew view`: its options and the engine scenes. */
void viewer_print_usage(FILE *stream);

typedef enum viewer_parse_result { VIEWER_PARSE_OK, VIEWER_PARSE_HELP, VIEWER_PARSE_ERROR } viewer_parse_result;

/* Parses the arguments after the program's name (cli/options.h); an
 * error, an unknown scene among them, is one line on stderr. */
viewer_parse_result viewer_options_parse(int argc, char **argv, viewer_options *options);

#endif
