/* SPDX-License-Identifier: MIT */
/* The pieces every command line and hand-written file of the tools goes
 * through: the option parser made from a table (cli/options.h), whose
 * help lists what it accepts, and the quoted-word splitter (cli/words.h)
 * shared by control files and viewer scripts.
 */
#define _GNU_SOURCE /* open_memstream */

#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/options.h"
#include "cli/words.h"

enum { OPT_DURATION, OPT_COUNT, OPT_SEED, OPT_OUT, OPT_NAME, OPT_QUIET, OPT_DURATION_LIMIT };

static const cli_option table[] = {
    {.name = "duration",
     .id = OPT_DURATION,
     .kind = CLI_NUMBER,
     .value_name = "S",
     .help = "time",
     .min = 0.0,
     .max = 10.0,
     .min_open = true,
     .fallback = "1"},
    {.name = "count", .id = OPT_COUNT, .kind = CLI_INT, .value_name = "N", .help = "how many", .min = 1, .max = 5},
    {.name = "seed", .id = OPT_SEED, .kind = CLI_U64, .value_name = "N", .help = "a seed"},
    {.name = "out", .id = OPT_OUT, .kind = CLI_PATH, .value_name = "DIR", .help = "where\nand more", .fallback = "."},
    {.name = "name", .id = OPT_NAME, .kind = CLI_TEXT, .value_name = "TEXT", .help = "a name"},
    {.name = "quiet", .id = OPT_QUIET, .kind = CLI_FLAG, .help = "say less"},
    {.name = "duration-limit",
     .id = OPT_DURATION_LIMIT,
     .kind = CLI_NUMBER,
     .value_name = "S",
     .help = "a limit",
     .max = 1},
};

static const cli_command command = {
    .name = "tool",
    .operands = "THING [options]",
    .max_operands = 1,
    .operand = "thing",
    .about = "Does a thing.\n",
    .options = table,
    .option_count = sizeof table / sizeof table[0],
    .notes = "Notes.\n",
};

/* The result of parsing `words` (split at spaces): the ids in order, the
 * last values, the operand, and what went to stderr. */
typedef struct parse_outcome {
    int ids[16];
    int id_count;
    int end; /* CLI_END, CLI_HELP or CLI_ERROR */
    double duration;
    long count;
    uint64_t seed;
    char out[64], name[64], operand[64];
    char errors[1024];
} parse_outcome;

static parse_outcome parse(const char *words)
{
    parse_outcome outcome = {.end = 0};
    char text[512];
    snprintf(text, sizeof text, "%s", words);
    char *argv[32];
    int argc = 0;
    for (char *word = strtok(text, " "); word != NULL && argc < 32; word = strtok(NULL, " ")) {
        argv[argc++] = word;
    }
    /* stderr into a buffer, for the messages. */
    fflush(stderr);
    FILE *saved = stderr;
    char *errors = NULL;
    size_t size = 0;
    stderr = open_memstream(&errors, &size);
    cr_assert_not_null(stderr);
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        outcome.ids[outcome.id_count++] = id;
        outcome.duration = id == OPT_DURATION ? value.number : outcome.duration;
        outcome.count = id == OPT_COUNT ? value.integer : outcome.count;
        outcome.seed = id == OPT_SEED ? value.u64 : outcome.seed;
        if (id == OPT_OUT || id == OPT_NAME) {
            snprintf(id == OPT_OUT ? outcome.out : outcome.name, sizeof outcome.out, "%s", value.text);
        }
    }
    outcome.end = id;
    if (id == CLI_END && parser.operand_count > 0) {
        snprintf(outcome.operand, sizeof outcome.operand, "%s", parser.operands[0]);
    }
    cli_parser_finish(&parser);
    fclose(stderr);
    stderr = saved;
    snprintf(outcome.errors, sizeof outcome.errors, "%s", errors);
    free(errors);
    return outcome;
}

static int count_lines(const char *text)
{
    int lines = 0;
    for (const char *c = text; *c != '\0'; ++c) {
        lines += *c == '\n';
    }
    return lines;
}

Test(cli_options, values_come_checked_in_either_spelling_and_operands_anywhere)
{
    parse_outcome o = parse("--duration 2.5 thing --count=3 --seed 18446744073709551615 --out=d --name n --quiet");
    cr_assert_eq(o.end, CLI_END, "%s", o.errors);
    cr_expect_eq(o.id_count, 6);
    cr_expect_float_eq(o.duration, 2.5, 1e-12);
    cr_expect_eq(o.count, 3);
    cr_expect_eq(o.seed, UINT64_MAX);
    cr_expect_str_eq(o.out, "d");
    cr_expect_str_eq(o.name, "n");
    cr_expect_str_eq(o.operand, "thing");
    cr_expect_str_eq(o.errors, "");

    /* A unique prefix is the option (getopt_long's rule); an exact name
     * wins over a longer one it begins. */
    o = parse("--cou 3 --duration-l 0.5 --duration 2");
    cr_assert_eq(o.end, CLI_END, "%s", o.errors);
    cr_expect_eq(o.ids[0], OPT_COUNT);
    cr_expect_eq(o.ids[1], OPT_DURATION_LIMIT);
    cr_expect_eq(o.ids[2], OPT_DURATION);
    /* After `--`, everything is an operand. */
    o = parse("-- --count");
    cr_assert_eq(o.end, CLI_END, "%s", o.errors);
    cr_expect_str_eq(o.operand, "--count");
    /* A negative number is a value, not an option. */
    o = parse("--duration -1");
    cr_expect_eq(o.end, CLI_ERROR);
    cr_expect(strstr(o.errors, "--duration expects a number > 0") != NULL, "%s", o.errors);
}

/* POSIXLY_CORRECT makes getopt stop at the first operand; the commands'
 * options may follow their operand all the same. */
Test(cli_options, options_may_follow_the_operand_under_posixly_correct)
{
    setenv("POSIXLY_CORRECT", "1", 1);
    parse_outcome o = parse("thing --count 2");
    unsetenv("POSIXLY_CORRECT");
    cr_assert_eq(o.end, CLI_END, "%s", o.errors);
    cr_expect_str_eq(o.operand, "thing");
    cr_expect_eq(o.count, 2);
}

Test(cli_options, help_comes_first_wherever_it_is)
{
    cr_expect_eq(parse("thing --count 2 --help").end, CLI_HELP);
    cr_expect_eq(parse("-h").end, CLI_HELP);
}

Test(cli_options, each_bad_command_line_is_one_line_naming_the_option)
{
    static const struct {
        const char *words;
        const char *message;
    } cases[] = {
        {"--frobnicate", "tool: unknown option \"--frobnicate\" (see `tool --help`)"},
        {"-x", "unknown option \"-x\""},
        {"--d 1", "ambiguous option \"--d\""},
        {"--count", "--count needs a value"},
        {"--out --count 2", "--out needs a value"},
        {"--count 6", "--count expects an integer from 1 to 5, got \"6\""},
        {"--count 2x", "--count expects an integer"},
        {"--duration nan", "--duration expects a number > 0 and <= 10"},
        {"--seed -1", "--seed expects an integer from 0"},
        {"--out=", "--out expects a file name"},
        {"--name=", "--name needs a non-empty value"},
        {"--quiet=yes", "--quiet takes no value"},
        {"--help=yes", "--help takes no value"},
        {"one two", "unexpected argument \"two\": give one thing"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        parse_outcome o = parse(cases[k].words);
        cr_expect_eq(o.end, CLI_ERROR, "'%s' was accepted", cases[k].words);
        cr_expect_eq(count_lines(o.errors), 1, "'%s' gave: %s", cases[k].words, o.errors);
        cr_expect(strstr(o.errors, cases[k].message) != NULL, "'%s' gave: %s", cases[k].words, o.errors);
    }
    /* A value that starts with "--" is still possible with '='. */
    parse_outcome o = parse("--out=--odd");
    cr_expect_eq(o.end, CLI_END, "%s", o.errors);
    cr_expect_str_eq(o.out, "--odd");
}

Test(cli_options, the_help_lists_every_option_with_its_value_range_and_default)
{
    char *text = NULL;
    size_t size = 0;
    FILE *stream = open_memstream(&text, &size);
    cli_print_help(&command, stream);
    fclose(stream);
    static const char top[] = "usage: tool THING [options]\n\nDoes a thing.\n";
    cr_expect(strncmp(text, top, sizeof top - 1) == 0, "%s", text);
    for (size_t k = 0; k < sizeof table / sizeof table[0]; ++k) {
        char label[64];
        snprintf(label, sizeof label, "\n  --%s%s%s ", table[k].name, table[k].value_name != NULL ? " " : "",
                 table[k].value_name != NULL ? table[k].value_name : "");
        cr_expect(strstr(text, label) != NULL, "no \"%s\" in:\n%s", label + 1, text);
    }
    cr_expect(strstr(text, "time, > 0 .. 10 (default 1)\n") != NULL, "%s", text);
    cr_expect(strstr(text, "how many, 1 .. 5\n") != NULL, "%s", text);
    cr_expect(strstr(text, "a seed, 0 .. 2^64-1\n") != NULL, "%s", text);
    /* A help of two lines: the second aligned under the first. */
    const char *where = strstr(text, "where (default .)\n");
    cr_assert_not_null(where, "%s", text);
    const char *line = where;
    while (line > text && line[-1] != '\n') {
        --line;
    }
    char continued[64];
    snprintf(continued, sizeof continued, "where (default .)\n%*sand more\n", (int)(where - line), "");
    cr_expect(strstr(text, continued) != NULL, "%s", text);
    cr_expect(strstr(text, "\n  --help ") != NULL, "%s", text);
    cr_expect(strstr(text, "\n\nNotes.\n") != NULL, "%s", text);
    free(text);
}

/* words_split on a copy of `line`, joined back as "[w1][w2]..." or
 * "error: PROBLEM". */
static void split(const char *line, int capacity, char *joined, size_t size)
{
    char copy[256];
    snprintf(copy, sizeof copy, "%s", line);
    char *words[8];
    const char *problem = NULL;
    int count = words_split(copy, words, capacity, &problem);
    if (count < 0) {
        snprintf(joined, size, "error: %s", problem);
        return;
    }
    size_t used = (size_t)snprintf(joined, size, "%d:", count);
    for (int k = 0; k < count && k < capacity; ++k) {
        used += (size_t)snprintf(joined + used, size - used, "[%s]", words[k]);
    }
}

Test(words, quotes_group_hash_comments_and_the_end_of_line_ends)
{
    static const struct {
        const char *line;
        const char *words;
    } cases[] = {
        {"", "0:"},
        {"   \t  \r\n", "0:"},
        {"# all comment", "0:"},
        {"0.5 activation Biceps 1\n", "4:[0.5][activation][Biceps][1]"},
        {"0\tpulse\t\"Biceps Short\"\r\n", "3:[0][pulse][Biceps Short]"},
        {"set muscle \"a # b\" # comment", "3:[set][muscle][a # b]"},
        {"word#comment", "1:[word]"},
        {"\"quoted\"# comment", "1:[quoted]"},
        {"empty \"\" word", "3:[empty][][word]"},
        {"a b c d e f", "6:[a][b][c][d]"},
        {"\"open", "error: a quote is not closed"},
        {"\"closed\"text", "error: a closing quote is followed by other text; put a space after it"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char joined[256];
        split(cases[k].line, 4, joined, sizeof joined);
        cr_expect_str_eq(joined, cases[k].words, "\"%s\"", cases[k].line);
    }
}
