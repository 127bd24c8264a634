/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/options.h"
#include "scenes/registry.h"
#include "viewer_options.h"

enum { OPT_VARIANT, OPT_WEIGHT, OPT_LEVEL, OPT_SCENE, OPT_PLAY, OPT_SCRIPT, OPT_SIZE };

static const cli_option options_table[] = {
    {.name = "variant",
     .id = OPT_VARIANT,
     .kind = CLI_TEXT,
     .value_name = "NAME|N",
     .help = "the model's variant, by name or index",
     .fallback = "0"},
    {.name = "weight",
     .id = OPT_WEIGHT,
     .kind = CLI_NUMBER,
     .value_name = "KG",
     .help = "the weight choice of that mass",
     .min = 0.0,
     .max = 1e9,
     .fallback = "the first"},
    {.name = "level",
     .id = OPT_LEVEL,
     .kind = CLI_INT,
     .value_name = "N",
     .help = "0 nothing, 1 bones, 2 + joints, 3 + muscles, 4 + the weight",
     .min = 0,
     .max = 4,
     .fallback = "4"},
    {.name = "scene",
     .id = OPT_SCENE,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "open an engine scene instead (listed below)"},
    {.name = "play", .id = OPT_PLAY, .kind = CLI_FLAG, .value_name = NULL, .help = "start playing"},
    {.name = "script",
     .id = OPT_SCRIPT,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "run scripted commands (tools/viewer/script.h lists them)"},
    {.name = "size",
     .id = OPT_SIZE,
     .kind = CLI_TEXT,
     .value_name = "WxH",
     .help = "the window's size at the start, px (each 320 .. 16384)",
     .fallback = "1400x900"},
};

static const cli_command command = {
    .name = "sinew view",
    .operands = "[MODEL] [options]",
    .max_operands = 1,
    .operand = "model",
    .about = "Opens the interactive viewer (GTK 4) on a muscle model or an engine scene.\n"
             "MODEL is a built-in model (sample, arm, leg, leg-unlimited, worm; default arm) or a model file.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes = "Keys: space pulses the selected muscle or group (one frame at activation 1), P plays or\n"
             "pauses, S steps, Up/Down recruit 20 neurons more or fewer (worm). Mouse: the wheel zooms\n"
             "about the cursor, a right click resets the view, dragging the background pans, dragging a\n"
             "body pulls it.\n",
};

void viewer_print_usage(FILE *stream)
{
    cli_print_help(&command, stream);
    fputs("\nscenes (`sinew scene --help` runs them without a window, with their options):\n", stream);
    for (int k = 0; k < SCENE_KIND_COUNT; ++k) {
        fprintf(stream, "  %-12s %s\n", scene_registry[k].name, scene_registry[k].summary);
    }
}

/* "WIDTHxHEIGHT", each a whole number in VIEWER_MIN_SIZE .. VIEWER_MAX_SIZE
 * and nothing after. */
static bool parse_size(const char *text, int *width, int *height)
{
    int w, h, end = 0;
    if (sscanf(text, "%5dx%5d%n", &w, &h, &end) != 2 || text[end] != '\0' || text[0] < '0' || text[0] > '9') {
        return false;
    }
    if (w < VIEWER_MIN_SIZE || w > VIEWER_MAX_SIZE || h < VIEWER_MIN_SIZE || h > VIEWER_MAX_SIZE) {
        return false;
    }
    *width = w;
    *height = h;
    return true;
}

viewer_parse_result viewer_options_parse(int argc, char **argv, viewer_options *options)
{
    *options = (viewer_options){.model = "arm", .width = VIEWER_DEFAULT_WIDTH, .height = VIEWER_DEFAULT_HEIGHT};
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    scene_kind kind;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_VARIANT:
            options->variant = value.text;
            break;
        case OPT_WEIGHT:
            options->weight = value.number;
            options->has_weight = true;
            break;
        case OPT_LEVEL:
            options->level = (int)value.integer;
            options->has_level = true;
            break;
        case OPT_SCENE:
            if (!scene_kind_from_name(value.text, &kind)) {
                char names[256];
                scene_list_names(names, sizeof names);
                cli_usage_error(&command, "unknown scene \"%s\" (%s)", value.text, names);
                id = CLI_ERROR;
            }
            options->scene = value.text;
            break;
        case OPT_PLAY:
            options->play = true;
            break;
        case OPT_SCRIPT:
            options->script = value.text;
            break;
        case OPT_SIZE:
            if (!parse_size(value.text, &options->width, &options->height)) {
                cli_usage_error(&command, "--size \"%s\": expected WIDTHxHEIGHT in px, each %d .. %d (1280x720)",
                                value.text, VIEWER_MIN_SIZE, VIEWER_MAX_SIZE);
                id = CLI_ERROR;
            }
            break;
        default:
            break;
        }
        if (id == CLI_ERROR) {
            break;
        }
    }
    if (id == CLI_END && parser.operand_count == 1) {
        options->model = parser.operands[0];
    }
    cli_parser_finish(&parser);
    return id == CLI_HELP ? VIEWER_PARSE_HELP : id == CLI_END ? VIEWER_PARSE_OK : VIEWER_PARSE_ERROR;
}
