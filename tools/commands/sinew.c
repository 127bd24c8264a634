/* SPDX-License-Identifier: MIT */
/* sinew: the command-line program. main() answers --help and --version
 * and dispatches to the subcommands (commands.h), each in its own file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "io/provenance.h"
#include "mu/version.h"
#include "rb/version.h"

typedef struct command {
    const char *name;
    const char *synopsis; /* the arguments, for the usage */
    const char *summary;
    int (*run)(int argc, char **argv);
} command;

static int cmd_version(int argc, char **argv);

static const command commands[] = {
    {"models", "", "list the built-in muscle models", cmd_models},
    {"check", "FILE", "validate a model file", cmd_check},
    {"run", "MODEL [options]", "run a muscle model, write a CSV, print a summary", cmd_run},
    {"sweep", "SWEEP_FILE [options]", "run a model over a grid of parameters: runs, a table, a figure", cmd_sweep},
    {"scene", "NAME [options]", "run an engine scene, print a summary, write a CSV trace", cmd_scene},
    {"plot", "CSV [options]", "draw columns of a CSV file as a PNG or SVG chart", cmd_plot},
    {"moment-arms", "MODEL --hinge NAME [options]", "sweep a hinge: moment arms, lengths, forces (CSV, figure)",
     cmd_moment_arms},
    {"inverse", "MODEL --motion FILE [options]", "inverse dynamics: net hinge torques of a motion (CSV, figure)",
     cmd_inverse},
    {"optimize", "MODEL --motion FILE [options]", "static optimization: muscle activations of a motion (CSV, figure)",
     cmd_optimize},
    {"experiment", "NAME [options]", "run an experiment: a CSV, its figure and a few figures", cmd_experiment},
    {"view", "[MODEL] [options]", "the interactive viewer (GTK 4): models and engine scenes", cmd_view},
    {"version", "", "print the version (also --version)", cmd_version},
};
enum { COMMAND_COUNT = sizeof commands / sizeof commands[0] };

static void print_usage(FILE *stream)
{
    fputs("usage: sinew COMMAND [arguments]\n"
          "       sinew --help | --version\n"
          "\n"
          "commands:\n",
          stream);
    /* A usage longer than the column puts its summary on the next line,
     * under the others. */
    enum { COLUMN = 30 };
    for (int k = 0; k < COMMAND_COUNT; ++k) {
        char label[128];
        const int length = snprintf(label, sizeof label, "%s %s", commands[k].name, commands[k].synopsis);
        if (length > COLUMN) {
            fprintf(stream, "  %s\n  %-*s %s\n", label, COLUMN, "", commands[k].summary);
        } else {
            fprintf(stream, "  %-*s %s\n", COLUMN, label, commands[k].summary);
        }
    }
    fputs("\n"
          "`sinew COMMAND --help` describes a command's arguments and options.\n"
          "Exit status: 0 success, 1 failure (a model or control file, the engine,\n"
          "an unwritable output), 2 bad command line.\n",
          stream);
}

/* The engine's version, which the program shares; the muscle layer is
 * versioned with it, and a difference means mismatched shared libraries. */
static int cmd_version(int argc, char **argv)
{
    static const cli_command version_command = {
        .name = "sinew version",
        .operands = "",
        .operand = "",
        .about = "Prints the version of sinew, as `sinew --version` does.\n",
    };
    const char *operand;
    int id = cli_parse_operand(&version_command, argc, argv, &operand);
    if (id != CLI_END) {
        return id == CLI_HELP ? EXIT_SUCCESS : EXIT_USAGE;
    }
    printf("sinew %s", rb_version());
    if (strcmp(mu_version(), rb_version()) != 0) {
        printf(" (muscle layer %s)", mu_version());
    }
    putchar('\n');
    return EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
    /* Every CSV sidecar and figure names the command that made it. */
    provenance_set_command_line(argc, argv);
    if (argc < 2) {
        print_usage(stderr);
        return EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        print_usage(stdout);
        return EXIT_SUCCESS;
    }
    if (strcmp(argv[1], "--version") == 0) {
        return cmd_version(argc - 2, argv + 2);
    }
    for (int k = 0; k < COMMAND_COUNT; ++k) {
        if (strcmp(argv[1], commands[k].name) == 0) {
            return commands[k].run(argc - 2, argv + 2);
        }
    }
    fprintf(stderr, "sinew: unknown command \"%s\" (", argv[1]);
    for (int k = 0; k < COMMAND_COUNT; ++k) {
        fprintf(stderr, "%s%s", commands[k].name, k + 2 < COMMAND_COUNT ? ", " : k + 1 < COMMAND_COUNT ? " or " : "");
    }
    fputs("; see `sinew --help`)\n", stderr);
    return EXIT_USAGE;
}
