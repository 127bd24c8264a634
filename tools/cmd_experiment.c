/* SPDX-License-Identifier: MIT */
/* `sinew experiment NAME [--out DIR] [--pulse-width S]`: runs one of the
 * seed's experiments (experiment.h) and writes DIR/STEM.csv, .png, .svg.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/option_value.h"
#include "commands.h"
#include "experiment.h"

static void print_usage(FILE *stream)
{
    fputs("usage: sinew experiment NAME [--out DIR] [--pulse-width S]\n"
          "\n"
          "Runs one of the seed's experiments (docs: experiments.md) and writes DIR/STEM.csv, its figure\n"
          "DIR/STEM.png and DIR/STEM.svg, and a few lines of figures.\n"
          "\n"
          "experiments:\n",
          stream);
    for (int k = 0; k < experiment_count; ++k) {
        fprintf(stream, "  %-6s %-15s %s\n", experiment_list[k].name, experiment_list[k].stem,
                experiment_list[k].summary);
    }
    fprintf(stream,
            "\n"
            "options:\n"
            "  --out DIR          directory of the files (default .)\n"
            "  --pulse-width S    width of E1's, E4's and P1's pulses, > 0 .. %g s (P1: .. %g s), rounded to\n"
            "                     whole substeps (default: one frame for E1 and E4, as the seed's space bar;\n"
            "                     2 ms for P1)\n"
            "  --help             print this text\n",
            EXPERIMENT_MAX_PULSE_WIDTH, EXPERIMENT_P1_MAX_PULSE_WIDTH);
}

static int usage_error(const char *message)
{
    fprintf(stderr, "sinew: %s (see `sinew experiment --help`)\n", message);
    return EXIT_USAGE;
}

static const experiment *find_experiment(const char *name)
{
    for (int k = 0; k < experiment_count; ++k) {
        if (strcmp(experiment_list[k].name, name) == 0) {
            return &experiment_list[k];
        }
    }
    return NULL;
}

/* An unknown or missing name: the list, on stderr, and EXIT_USAGE. */
static int list_experiments(const char *name)
{
    if (name != NULL) {
        fprintf(stderr, "sinew: unknown experiment \"%s\"; the experiments are:\n", name);
    } else {
        fputs("sinew: missing the experiment's name; the experiments are:\n", stderr);
    }
    for (int k = 0; k < experiment_count; ++k) {
        fprintf(stderr, "  %-6s %s\n", experiment_list[k].name, experiment_list[k].summary);
    }
    return EXIT_USAGE;
}

int cmd_experiment(int argc, char **argv)
{
    static const char *const with_value[] = {"--out", "--pulse-width"};
    experiment_options options = {.out_dir = ".", .pulse_width = 0.0};
    const char *name = NULL;
    char error[OPTION_ERROR_SIZE];
    for (int i = 0; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            print_usage(stdout);
            return EXIT_SUCCESS;
        }
        if (strncmp(argv[i], "--", 2) != 0) {
            if (name != NULL) {
                snprintf(error, sizeof error, "unexpected argument \"%s\": give one experiment", argv[i]);
                return usage_error(error);
            }
            name = argv[i];
            continue;
        }
        const char *option, *value;
        if (!option_split(argc, argv, &i, with_value, sizeof with_value / sizeof with_value[0], &option, &value, error,
                          sizeof error)) {
            return usage_error(error);
        }
        bool ok = strcmp(option, "--out") == 0
                      ? option_parse_path(option, value, &options.out_dir, error, sizeof error)
                      : option_parse_double(option, value, 0.0, true, EXPERIMENT_MAX_PULSE_WIDTH, &options.pulse_width,
                                            error, sizeof error);
        if (!ok) {
            return usage_error(error);
        }
    }
    const experiment *chosen = name != NULL ? find_experiment(name) : NULL;
    if (chosen == NULL) {
        return list_experiments(name);
    }
    if (options.pulse_width > chosen->max_pulse_width) {
        if (chosen->max_pulse_width > 0.0) {
            snprintf(error, sizeof error, "--pulse-width %g: %s takes pulses of at most %g s", options.pulse_width,
                     chosen->name, chosen->max_pulse_width);
        } else {
            snprintf(error, sizeof error, "--pulse-width: %s gives no pulses", chosen->name);
        }
        return usage_error(error);
    }
    struct stat info;
    if (stat(options.out_dir, &info) != 0) {
        fprintf(stderr, "sinew: --out %s: %s\n", options.out_dir, strerror(errno));
        return EXIT_FAILURE;
    }
    if (!S_ISDIR(info.st_mode)) {
        fprintf(stderr, "sinew: --out %s: not a directory\n", options.out_dir);
        return EXIT_FAILURE;
    }
    printf("experiment   %s: %s\n", chosen->name, chosen->summary);
    return chosen->run(chosen, &options);
}
