/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* getopt_long */

#include <getopt.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "cli/option_value.h"
#include "cli/options.h"

/* getopt_long's value for option k of the table: above every character,
 * so that no option can be mistaken for a short one. */
enum { LONG_BASE = 256 };

int cli_usage_error(const cli_command *command, const char *format, ...)
{
    fprintf(stderr, "%s: ", command->name);
    va_list args;
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fprintf(stderr, " (see `%s --help`)\n", command->name);
    return CLI_EXIT_USAGE;
}

void cli_parser_start(cli_parser *parser, const cli_command *command, int argc, char **argv)
{
    *parser = (cli_parser){.command = command, .argc = argc + 1};
    /* getopt_long may reorder the arguments it is given and reads argv[0]
     * as the program: it gets a copy behind the command's name. */
    parser->argv = calloc((size_t)argc + 2, sizeof *parser->argv);
    parser->operands = calloc((size_t)argc + 1, sizeof *parser->operands);
    struct option *options = calloc((size_t)command->option_count + 2, sizeof *options);
    parser->long_options = options;
    if (parser->argv == NULL || parser->operands == NULL || options == NULL) {
        return; /* cli_next reports it */
    }
    parser->argv[0] = (char *)command->name;
    for (int k = 0; k < argc; ++k) {
        parser->argv[k + 1] = argv[k];
    }
    for (int k = 0; k < command->option_count; ++k) {
        const cli_option *option = &command->options[k];
        options[k] = (struct option){
            .name = option->name,
            .has_arg = option->kind == CLI_FLAG ? no_argument : required_argument,
            .val = LONG_BASE + k,
        };
    }
    options[command->option_count] = (struct option){.name = "help", .has_arg = no_argument, .val = 'h'};
    /* optind 0 makes glibc start afresh, as a second parse in one process
     * (a test) needs; opterr 0 keeps its own messages out: ours name the
     * command and say where to look. */
    optind = 0;
    opterr = 0;
}

void cli_parser_finish(cli_parser *parser)
{
    free(parser->argv);
    free(parser->operands);
    free(parser->long_options);
    *parser = (cli_parser){.command = parser->command};
}

/* How many options (--help among them) begin with the name written in
 * `argument` ("--na=1" -> "na"): more than one makes an ambiguous prefix,
 * told apart from a name that matches none. */
static int count_prefix_matches(const cli_command *command, const char *argument)
{
    const char *name = argument + strspn(argument, "-");
    size_t length = strcspn(name, "=");
    int matches = strncmp("help", name, length) == 0;
    for (int k = 0; k < command->option_count; ++k) {
        matches += strncmp(command->options[k].name, name, length) == 0;
    }
    return matches;
}

/* Checks the value of option k against its kind and range. */
static bool check_value(const cli_command *command, int k, const char *text, cli_value *value)
{
    const cli_option *option = &command->options[k];
    char name[128];
    snprintf(name, sizeof name, "--%s", option->name);
    char error[OPTION_ERROR_SIZE];
    bool ok = true;
    int integer = 0;
    *value = (cli_value){.text = text};
    switch (option->kind) {
    case CLI_FLAG:
        break;
    case CLI_TEXT:
        ok = text[0] != '\0';
        snprintf(error, sizeof error, "%s needs a non-empty value", name);
        break;
    case CLI_PATH:
        ok = option_parse_path(name, text, &value->text, error, sizeof error);
        break;
    case CLI_INT:
        ok = option_parse_int(name, text, (long)option->min, (long)option->max, &integer, error, sizeof error);
        value->integer = integer;
        value->number = integer;
        break;
    case CLI_NUMBER:
        ok = option_parse_double(name, text, option->min, option->min_open, option->max, &value->number, error,
                                 sizeof error);
        break;
    case CLI_U64:
        ok = option_parse_u64(name, text, &value->u64, error, sizeof error);
        break;
    }
    if (!ok) {
        cli_usage_error(command, "%s", error);
    }
    return ok;
}

/* Why getopt_long returned '?' or ':' for `argument`, as one line. */
static void report_bad_option(const cli_command *command, int found, const char *argument)
{
    /* optopt holds the option's value when a flag was given a value or a
     * value is missing, the letter of an unknown short option, and 0 for
     * an unknown long one. */
    if (found == ':') {
        cli_usage_error(command, "--%s needs a value", command->options[optopt - LONG_BASE].name);
    } else if (optopt >= LONG_BASE || (optopt == 'h' && strncmp(argument, "--", 2) == 0)) {
        cli_usage_error(command, "--%s takes no value, got \"%s\"",
                        optopt == 'h' ? "help" : command->options[optopt - LONG_BASE].name, argument);
    } else if (optopt != 0) {
        cli_usage_error(command, "unknown option \"-%c\"", optopt);
    } else if (count_prefix_matches(command, argument) > 1) {
        cli_usage_error(command, "ambiguous option \"%s\": give more of its name", argument);
    } else {
        cli_usage_error(command, "unknown option \"%s\"", argument);
    }
}

int cli_next(cli_parser *parser, cli_value *value)
{
    const cli_command *command = parser->command;
    *value = (cli_value){.text = NULL};
    if (parser->argv == NULL || parser->operands == NULL || parser->long_options == NULL) {
        fprintf(stderr, "%s: out of memory\n", command->name);
        return CLI_ERROR;
    }
    /* "-": operands come back in order as 1, so that options may follow
     * them even when POSIXLY_CORRECT is set; ":": a missing value is ':'
     * rather than '?'. */
    int found;
    while ((found = getopt_long(parser->argc, parser->argv, "-:h", parser->long_options, NULL)) == 1) {
        parser->operands[parser->operand_count++] = optarg;
    }
    if (found == 'h') {
        return CLI_HELP;
    }
    if (found == '?' || found == ':') {
        report_bad_option(command, found, parser->argv[optind - 1]);
        return CLI_ERROR;
    }
    if (found >= LONG_BASE) {
        int k = found - LONG_BASE;
        /* `--out --duration 2` is a missing value, not a directory called
         * "--duration"; such a value can still be given as --out=--x. */
        if (optarg != NULL && optarg == parser->argv[optind - 1] && strncmp(optarg, "--", 2) == 0) {
            cli_usage_error(command, "--%s needs a value", command->options[k].name);
            return CLI_ERROR;
        }
        return check_value(command, k, optarg, value) ? command->options[k].id : CLI_ERROR;
    }
    /* The end: after "--", the rest are operands. */
    for (int k = optind; k < parser->argc; ++k) {
        parser->operands[parser->operand_count++] = parser->argv[k];
    }
    if (parser->operand_count > command->max_operands) {
        const char *extra = parser->operands[command->max_operands];
        if (command->max_operands == 0) {
            cli_usage_error(command, "unexpected argument \"%s\": it takes none", extra);
        } else {
            cli_usage_error(command, "unexpected argument \"%s\": give one %s", extra, command->operand);
        }
        return CLI_ERROR;
    }
    return CLI_END;
}

/* "--name VALUE" of an option, as the help shows it. */
static int option_label(const char *name, const char *value_name, char *label, size_t size)
{
    return snprintf(label, size, "--%s%s%s", name, value_name != NULL ? " " : "", value_name != NULL ? value_name : "");
}

/* The range and default of an option, after its help's first line,
 * where a reader looks for them. */
static void print_range_and_default(const cli_option *option, FILE *stream)
{
    switch (option->kind) {
    case CLI_INT:
        fprintf(stream, ", %g .. %g", option->min, option->max);
        break;
    case CLI_NUMBER:
        fprintf(stream, ", %s%g .. %g", option->min_open ? "> " : "", option->min, option->max);
        break;
    case CLI_U64:
        fputs(", 0 .. 2^64-1", stream);
        break;
    case CLI_FLAG:
    case CLI_TEXT:
    case CLI_PATH:
        break;
    }
    if (option->fallback != NULL) {
        fprintf(stream, " (default %s)", option->fallback);
    }
}

/* The help of one option: its first line with the range and default,
 * then any further lines aligned at `column`. */
static void print_option_help(const cli_option *option, int column, FILE *stream)
{
    const char *text = option->help;
    size_t length = strcspn(text, "\n");
    fprintf(stream, "%.*s", (int)length, text);
    print_range_and_default(option, stream);
    for (text += length; *text == '\n'; text += length) {
        ++text;
        length = strcspn(text, "\n");
        fprintf(stream, "\n%*s%.*s", column, "", (int)length, text);
    }
    fputc('\n', stream);
}

void cli_print_help(const cli_command *command, FILE *stream)
{
    fprintf(stream, "usage: %s%s%s\n\n%s", command->name, command->operands[0] != '\0' ? " " : "", command->operands,
            command->about);
    /* The help texts start in one column, past the longest label. */
    char label[128];
    int column = option_label("help", NULL, label, sizeof label);
    for (int k = 0; k < command->option_count; ++k) {
        int width = option_label(command->options[k].name, command->options[k].value_name, label, sizeof label);
        column = width > column ? width : column;
    }
    column += 4;
    fputs("\noptions:\n", stream);
    for (int k = 0; k < command->option_count; ++k) {
        const cli_option *option = &command->options[k];
        option_label(option->name, option->value_name, label, sizeof label);
        fprintf(stream, "  %-*s", column - 2, label);
        print_option_help(option, column, stream);
    }
    fprintf(stream, "  %-*sprint this text\n", column - 2, "--help");
    if (command->notes != NULL) {
        fprintf(stream, "\n%s", command->notes);
    }
}

int cli_parse_operand(const cli_command *command, int argc, char **argv, const char **operand)
{
    cli_parser parser;
    cli_parser_start(&parser, command, argc, argv);
    cli_value value;
    int id = cli_next(&parser, &value);
    *operand = id == CLI_END && parser.operand_count > 0 ? parser.operands[0] : NULL;
    cli_parser_finish(&parser);
    if (id == CLI_HELP) {
        cli_print_help(command, stdout);
    }
    return id;
}
