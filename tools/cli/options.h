/* SPDX-License-Identifier: MIT */
/* The command line of each program and subcommand, described once by a
 * table (cli_command) from which both the parser and the --help text are
 * made, so that the two cannot drift apart.
 *
 * Parsing is glibc's getopt_long: options are `--name value` or
 * `--name=value`, in any order among the operands (the model, the scene,
 * the file), POSIXLY_CORRECT or not; a unique prefix of a name is
 * accepted (`--dur 2`); `--` ends the options; `--help` and `-h` are
 * always there. Every value is
 * checked against its option's kind and range before the command sees
 * it. Each error is one line on stderr naming the option and what it
 * expects, ending with where to look: "(see `sinew run --help`)".
 *
 *     cli_parser parser;
 *     cli_parser_start(&parser, &command, argc, argv);
 *     cli_value value;
 *     int id;
 *     while ((id = cli_next(&parser, &value)) >= 0) { switch (id) ... }
 *     if (id == CLI_HELP) ... cli_print_help(&command, stdout);
 *     if (id == CLI_ERROR) ... return the usage status (2)
 *     parser.operands[0 .. parser.operand_count - 1]
 *     cli_parser_finish(&parser);
 */
#ifndef CLI_OPTIONS_H
#define CLI_OPTIONS_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

typedef enum cli_value_kind {
    CLI_FLAG,   /* no value */
    CLI_TEXT,   /* any text but the empty one */
    CLI_PATH,   /* a file or directory name: not empty */
    CLI_INT,    /* a decimal integer in [min, max] */
    CLI_NUMBER, /* a finite number in [min, max], or (min, max] when min_open */
    CLI_U64,    /* a decimal integer in [0, 2^64 - 1] */
} cli_value_kind;

typedef struct cli_option {
    const char *name; /* without the dashes: "duration" */
    int id;           /* what cli_next returns for it, >= 0 */
    cli_value_kind kind;
    const char *value_name; /* in the help: "S", "DIR"; NULL for a flag */
    const char *help;       /* what it does; a '\n' continues it on an aligned line */
    double min, max;        /* CLI_INT and CLI_NUMBER */
    bool min_open;
    const char *fallback; /* the default, as the help shows it ("10", "."); NULL: none */
} cli_option;

typedef struct cli_command {
    const char *name;     /* as typed: "sinew run"; prefixes every error */
    const char *operands; /* after the name in the usage line: "MODEL" */
    int max_operands;     /* 0 or 1: more is an error */
    const char *operand;  /* what the one operand is, for that error: "model" */
    const char *about;    /* between the usage line and the options */
    const cli_option *options;
    int option_count;
    const char *notes; /* after the options; NULL: none */
} cli_command;

/* An option's value: `text` always (NULL for a flag), and the number it
 * holds for the numeric kinds. */
typedef struct cli_value {
    const char *text;
    double number; /* CLI_NUMBER and CLI_INT */
    long integer;  /* CLI_INT */
    uint64_t u64;  /* CLI_U64 */
} cli_value;

enum {
    CLI_END = -1,   /* no more options; the operands are in the parser */
    CLI_HELP = -2,  /* --help or -h: print cli_print_help's text, exit 0 */
    CLI_ERROR = -3, /* one line printed on stderr: exit with the usage status */
};

typedef struct cli_parser {
    const cli_command *command;
    char **operands; /* the arguments that are not options, in order */
    int operand_count;
    /* internal */
    int argc;
    char **argv; /* a copy of the arguments behind a program name */
    void *long_options;
} cli_parser;

/* Starts parsing the arguments that follow the command's name: argv[0 ..
 * argc - 1]. argv itself is left as it is. */
void cli_parser_start(cli_parser *parser, const cli_command *command, int argc, char **argv);

/* The next option's id, with its checked value in *value; or CLI_END,
 * CLI_HELP, or CLI_ERROR after one line on stderr. Too many operands is
 * an error at the end. */
int cli_next(cli_parser *parser, cli_value *value);

/* Frees what the parser holds; its operands go with it. */
void cli_parser_finish(cli_parser *parser);

/* The whole parse of a command without options of its own: sets
 * *operand to its operand, or NULL when none is given; returns CLI_END,
 * CLI_HELP after printing the help on stdout, or CLI_ERROR. */
int cli_parse_operand(const cli_command *command, int argc, char **argv, const char **operand);

/* The help text: the usage line, the `about` text, every option of the
 * table with its value, range and default, --help, and the notes. */
void cli_print_help(const cli_command *command, FILE *stream);

/* Prints "NAME: MESSAGE (see `NAME --help`)" on stderr as one line and
 * returns the usage status, 2. */
int cli_usage_error(const cli_command *command, const char *format, ...) __attribute__((format(printf, 2, 3)));

/* The exit status of a bad command line. */
enum { CLI_EXIT_USAGE = 2 };

#endif
