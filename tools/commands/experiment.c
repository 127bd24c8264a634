/* SPDX-License-Identifier: MIT */
/* `sinew experiment NAME [--out DIR] [--pulse-width S] [--dynamics NAME]`: runs one of the
 * experiments (experiment.h) and writes DIR/STEM.csv, .png, .svg.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/options.h"
#include "commands.h"
#include "experiments/experiment.h"

enum { OPT_OUT, OPT_PULSE_WIDTH, OPT_DYNAMICS };

static const cli_option options_table[] = {
    {.name = "out",
     .id = OPT_OUT,
     .kind = CLI_PATH,
     .value_name = "DIR",
     .help = "directory of the files",
     .fallback = "."},
    {.name = "pulse-width",
     .id = OPT_PULSE_WIDTH,
     .kind = CLI_NUMBER,
     .value_name = "S",
     .help = "width of the pulses in s\n"
             "rounded to whole substeps, for the experiments that give pulses\n"
             "(each one's longest is listed below); by default one frame for e1\n"
             "and e4, as the original program's space bar, and 2 ms for p1",
     .min = 0.0,
     .max = EXPERIMENT_MAX_PULSE_WIDTH,
     .min_open = true},
    {.name = "dynamics",
     .id = OPT_DYNAMICS,
     .kind = CLI_TEXT,
     .value_name = "NAME",
     .help = "the muscle's activation dynamics, for p1\n"
             "first_order: one lag (Millard et al. 2013); fast or slow: a calcium\n"
             "stage then a force-generating stage, with the fast or the slow\n"
             "fibres' times",
     .fallback = "first_order"},
};

static const cli_command command = {
    .name = "sinew experiment",
    .operands = "NAME [options]",
    .max_operands = 1,
    .operand = "experiment",
    .about = "Runs one of the experiments listed below and writes DIR/STEM.csv, its figure\n"
             "DIR/STEM.png and DIR/STEM.svg, and a few lines of figures.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
};

static void print_help(FILE *stream)
{
    cli_print_help(&command, stream);
    fputs("\nexperiments (NAME, STEM, what it shows; the longest --pulse-width):\n", stream);
    for (int k = 0; k < experiment_count; ++k) {
        const experiment *entry = &experiment_list[k];
        fprintf(stream, "  %-6s %-17s %s", entry->name, entry->stem, entry->summary);
        if (entry->max_pulse_width > 0.0) {
            fprintf(stream, "; pulses up to %g s", entry->max_pulse_width);
        }
        fputc('\n', stream);
    }
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

/* An unknown or missing name: one line naming the experiments, and
 * EXIT_USAGE. */
static int name_experiments(const char *name)
{
    char names[256] = "";
    size_t used = 0;
    for (int k = 0; k < experiment_count && used < sizeof names; ++k) {
        used +=
            (size_t)snprintf(names + used, sizeof names - used, "%s%s", k == 0 ? "" : ", ", experiment_list[k].name);
    }
    if (name != NULL) {
        return cli_usage_error(&command, "unknown experiment \"%s\" (%s)", name, names);
    }
    return cli_usage_error(&command, "missing the experiment's name (%s)", names);
}

static bool known_dynamics(const char *name)
{
    for (int k = 0; experiment_dynamics_names[k] != NULL; ++k) {
        if (strcmp(experiment_dynamics_names[k], name) == 0) {
            return true;
        }
    }
    return false;
}

int cmd_experiment(int argc, char **argv)
{
    experiment_options options = {.out_dir = ".", .pulse_width = 0.0, .dynamics = NULL};
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        if (id == OPT_OUT) {
            options.out_dir = value.text;
        } else if (id == OPT_DYNAMICS) {
            options.dynamics = value.text;
        } else {
            options.pulse_width = value.number;
        }
    }
    const char *name = id == CLI_END && parser.operand_count == 1 ? parser.operands[0] : NULL;
    cli_parser_finish(&parser);
    if (id == CLI_HELP) {
        print_help(stdout);
        return EXIT_SUCCESS;
    }
    if (id == CLI_ERROR) {
        return EXIT_USAGE;
    }
    const experiment *chosen = name != NULL ? find_experiment(name) : NULL;
    if (chosen == NULL) {
        return name_experiments(name);
    }
    if (options.pulse_width > chosen->max_pulse_width) {
        if (chosen->max_pulse_width > 0.0) {
            return cli_usage_error(&command, "--pulse-width %g: %s takes pulses of at most %g s", options.pulse_width,
                                   chosen->name, chosen->max_pulse_width);
        }
        return cli_usage_error(&command, "--pulse-width: %s gives no pulses", chosen->name);
    }
    if (options.dynamics != NULL) {
        if (!chosen->takes_dynamics) {
            return cli_usage_error(&command, "--dynamics: %s takes its muscles' dynamics from its model", chosen->name);
        }
        if (!known_dynamics(options.dynamics)) {
            return cli_usage_error(&command, "--dynamics \"%s\": unknown, expected first_order, fast or slow",
                                   options.dynamics);
        }
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
