/* SPDX-License-Identifier: MIT */
/* The command line of `sinew view` (the sinew-view program):
 *   sinew view [MODEL] [--variant NAME|N] [--weight KG] [--level N]
 *              [--scene NAME] [--play] [--script FILE] [--size WxH]
 */
#ifndef VIEWER_VIEWER_OPTIONS_H
#define VIEWER_VIEWER_OPTIONS_H

#include <stdbool.h>
#include <stdio.h>

/* The window's size at the start, px: the default, and the bounds of
 * --size (the smallest is far below what the panels need: the window
 * then opens at their least size). */
#define VIEWER_DEFAULT_WIDTH 1400
#define VIEWER_DEFAULT_HEIGHT 900
#define VIEWER_MIN_SIZE 320
#define VIEWER_MAX_SIZE 16384

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
    int width, height;  /* the window's size at the start, px */
} viewer_options;

/* The help of `sinew view`: its options and the engine scenes. */
void viewer_print_usage(FILE *stream);

typedef enum viewer_parse_result { VIEWER_PARSE_OK, VIEWER_PARSE_HELP, VIEWER_PARSE_ERROR } viewer_parse_result;

/* Parses the arguments after the program's name (cli/options.h); an
 * error, an unknown scene among them, is one line on stderr. */
viewer_parse_result viewer_options_parse(int argc, char **argv, viewer_options *options);

#endif
