/* SPDX-License-Identifier: MIT */
#include <string.h>

#include "cli/option_value.h"
#include "viewer_options.h"

const char viewer_usage_text[] =
    "usage: sinew view [MODEL] [options]\n"
    "\n"
    "Opens the interactive viewer (GTK 4) on a muscle model or an engine scene.\n"
    "MODEL is a built-in model (sample, arm, leg, worm; default arm) or a model file.\n"
    "\n"
    "options:\n"
    "  --variant NAME|N   the model's variant, by name or index (default 0)\n"
    "  --weight KG        the weight choice of that mass (default the first)\n"
    "  --level N          0 nothing, 1 bones, 2 + joints, 3 + muscles, 4 + the weight (default 4)\n"
    "  --scene NAME       open an engine scene instead: pyramid, chain, pendulum, balls, joint-grid\n"
    "  --play             start playing\n"
    "  --script FILE      run scripted commands (tools/viewer/script.h lists them)\n"
    "  --help             print this text\n"
    "\n"
    "Keys: space pulses the selected muscle or group (one frame at activation 1), P plays or\n"
    "pauses, S steps, Up/Down recruit 20 neurons more or fewer (worm). Mouse: the wheel zooms\n"
    "about the cursor, a right click resets the view, dragging the background pans, dragging a\n"
    "body pulls it.\n";

viewer_parse_result viewer_options_parse(int argc, char **argv, viewer_options *options)
{
    static const char *const known[] = {"--variant", "--weight", "--level", "--scene", "--script"};
    *options = (viewer_options){.model = "arm"};
    bool model_given = false;
    char error[OPTION_ERROR_SIZE];
    for (int i = 0; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            return VIEWER_PARSE_HELP;
        }
        if (strcmp(argv[i], "--play") == 0) {
            options->play = true;
            continue;
        }
        if (strncmp(argv[i], "--", 2) != 0) {
            if (model_given) {
                fprintf(stderr, "sinew view: one model only, got \"%s\" after \"%s\"\n", argv[i], options->model);
                return VIEWER_PARSE_ERROR;
            }
            options->model = argv[i];
            model_given = true;
            continue;
        }
        const char *option, *value;
        bool ok =
            option_split(argc, argv, &i, known, sizeof known / sizeof known[0], &option, &value, error, sizeof error);
        if (ok && strcmp(option, "--variant") == 0) {
            options->variant = value;
        } else if (ok && strcmp(option, "--weight") == 0) {
            ok = option_parse_double(option, value, 0.0, false, 1e9, &options->weight, error, sizeof error);
            options->has_weight = true;
        } else if (ok && strcmp(option, "--level") == 0) {
            ok = option_parse_int(option, value, 0, 4, &options->level, error, sizeof error);
            options->has_level = true;
        } else if (ok && strcmp(option, "--scene") == 0) {
            options->scene = value;
        } else if (ok) {
            options->script = value;
        }
        if (!ok) {
            fprintf(stderr, "sinew view: %s\n(run `sinew view --help` for the options)\n", error);
            return VIEWER_PARSE_ERROR;
        }
    }
    return VIEWER_PARSE_OK;
}
