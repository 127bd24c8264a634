/* SPDX-License-Identifier: MIT */
/* sinew: the command-line program. main() only dispatches to the
 * subcommands (commands.h), each in its own cmd_*.c.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "io/provenance.h"

static const char usage_text[] = "usage: sinew COMMAND [arguments]\n"
                                 "\n"
                                 "commands:\n"
                                 "  models                 list the built-in muscle models\n"
                                 "  check FILE             validate a model file\n"
                                 "  run MODEL [options]    run a muscle model, write a CSV, print a summary\n"
                                 "  scene NAME [options]   run an engine scene, print a summary\n"
                                 "  plot CSV [options]     draw columns of a CSV file as a PNG or SVG chart\n"
                                 "  experiment NAME        run one of the seed's experiments: CSV, figure, figures\n"
                                 "  view [MODEL]           the interactive viewer (GTK 4): models and engine scenes\n"
                                 "\n"
                                 "`sinew COMMAND --help` describes a command's arguments.\n"
                                 "Exit status: 0 success, 1 failure (a model or control file, the engine,\n"
                                 "an unwritable output), 2 bad command line.\n";

int main(int argc, char **argv)
{
    /* Every CSV sidecar and figure names the command that made it. */
    provenance_set_command_line(argc, argv);
    static const struct {
        const char *name;
        int (*run)(int argc, char **argv);
    } commands[] = {{"models", cmd_models}, {"check", cmd_check},           {"run", cmd_run},  {"scene", cmd_scene},
                    {"plot", cmd_plot},     {"experiment", cmd_experiment}, {"view", cmd_view}};
    if (argc < 2) {
        fputs(usage_text, stderr);
        return EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        fputs(usage_text, stdout);
        return EXIT_SUCCESS;
    }
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; ++k) {
        if (strcmp(argv[1], commands[k].name) == 0) {
            return commands[k].run(argc - 2, argv + 2);
        }
    }
    fprintf(stderr,
            "sinew: unknown command \"%s\" (models, check, run, scene, plot, experiment or view; see `sinew --help`)\n",
            argv[1]);
    return EXIT_USAGE;
}
