/* SPDX-License-Identifier: MIT */
/* What sinew tells a user when their input is wrong: one line naming
 * their argument, file or object, never the library function that failed
 * (an rb_ or mu_ name, which they never called); and out-of-range values
 * are refused, not clamped (--recruit beyond the worm's pool of 200).
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <criterion/criterion.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/user_error.h"
#include "cli_support.h"
#include "mu/model_desc.h"

static char dir[] = "/tmp/sinew-messages-XXXXXX";

/* Runs sinew with `args` in `dir`; its stderr in `log`. Returns the status. */
static int run_sinew(const char *args, char *log, size_t log_size)
{
    return run_sinew_capture(dir, args, SINEW_STDERR_ONLY, log, log_size);
}

/* Whether `text` holds a word that starts "rb_" or "mu_" and goes on in
 * lower case: a library function's name. */
static bool names_a_library_function(const char *text)
{
    for (const char *at = text; *at != '\0'; ++at) {
        const bool word_start = at == text || !(isalnum((unsigned char)at[-1]) || at[-1] == '_');
        if (word_start && (strncmp(at, "rb_", 3) == 0 || strncmp(at, "mu_", 3) == 0) && islower((unsigned char)at[3])) {
            return true;
        }
    }
    return false;
}

Test(cli_messages, bad_input_is_refused_in_the_users_words)
{
    cr_assert_not_null(mkdtemp(dir));
    char path[600];
    snprintf(path, sizeof path, "%s/bad.json", dir);
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fputs("{\"name\": \"bad\", \"bones\": [{\"name\": \"b\", \"size\": [0.1, 0.1], \"colour\": 1}]}\n", f);
    fclose(f);
    const struct {
        const char *args;
        const char *expected; /* a part of the message */
    } cases[] = {
        {"run worm --recruit \"Torque Muscle=300\" --duration 0.1", "300"},
        {"run worm --recruit \"Torque Muscle=-1\" --duration 0.1", "-1"},
        {"run worm --recruit \"Nobody=3\" --duration 0.1", "Nobody"},
        {"run arm --weight 99 --duration 0.1", "99"},
        {"run nosuch --duration 0.1", "nosuch"},
        {"run bad.json --duration 0.1", "colour"},
        {"check bad.json", "colour"},
        {"check /nonexistent/model.json", "/nonexistent/model.json"},
    };
    char log[8192];
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const int status = run_sinew(cases[k].args, log, sizeof log);
        cr_expect_neq(status, 0, "sinew %s succeeded:\n%s", cases[k].args, log);
        cr_expect(strstr(log, cases[k].expected) != NULL, "sinew %s: the message should name \"%s\":\n%s",
                  cases[k].args, cases[k].expected, log);
        cr_expect(!names_a_library_function(log), "sinew %s: the message names a library function:\n%s", cases[k].args,
                  log);
    }
    remove(path);
    rmdir(dir);
}

Test(cli_messages, library_function_names_are_taken_off)
{
    cr_expect_str_eq(user_error_text("mu_model_recruit: neurons is 300, expected 0 .. 200"),
                     "neurons is 300, expected 0 .. 200");
    cr_expect_str_eq(user_error_text("mu_model_desc_load: rb_world_create: gravity is nan"), "gravity is nan");
    cr_expect_str_eq(user_error_text("arm.json:3:5: bones[0].size: expected two numbers"),
                     "arm.json:3:5: bones[0].size: expected two numbers");
    cr_expect_str_eq(user_error_text("mu_ is not a name: x"), "mu_ is not a name: x");
    cr_expect_str_eq(user_error_text(""), "");
    cr_expect_str_eq(user_error_text("arm.json: muscle 'X': rb_cable_create: points 0 and 1 coincide"),
                     "arm.json: muscle 'X': points 0 and 1 coincide");
    cr_expect_str_eq(user_error_text("sum_mu_x: kept, and so is mu_x without its colon"),
                     "sum_mu_x: kept, and so is mu_x without its colon");
}

/* The help of `sinew run` and the README's layout name every built-in
 * model the library has (the worm was missing from the layout). */
Test(cli_messages, run_help_and_the_readme_name_every_builtin_model)
{
    cr_assert_not_null(mkdtemp(dir));
    char command[1024], path[600];
    snprintf(path, sizeof path, "%s/help.txt", dir);
    snprintf(command, sizeof command, "'%s' run --help > '%s' 2>&1", SINEW_TOOL, path);
    cr_assert_eq(system(command), 0);
    static char help[16384], readme[65536];
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f);
    help[fread(help, 1, sizeof help - 1, f)] = '\0';
    fclose(f);
    remove(path);
    rmdir(dir);
    f = fopen(SINEW_SOURCE_DIR "/README.md", "r");
    cr_assert_not_null(f);
    readme[fread(readme, 1, sizeof readme - 1, f)] = '\0';
    fclose(f);
    const char *layout = strstr(readme, "## Layout");
    cr_assert_not_null(layout, "the README has no Layout section");
    const char *models = strstr(layout, "- `models/`");
    cr_assert_not_null(models, "the Layout has no models/ entry");
    const char *entry_end = strstr(models + 1, "\n- ");
    for (int k = 0; k < mu_builtin_model_count(); ++k) {
        const char *name = mu_builtin_model_name(k);
        cr_expect(strstr(help, name) != NULL, "sinew run --help does not name %s", name);
        char quoted[64];
        snprintf(quoted, sizeof quoted, "`%s`", name);
        const char *at = strstr(models, quoted);
        cr_expect(at != NULL && (entry_end == NULL || at < entry_end), "the README's models/ entry does not name %s",
                  name);
    }
}

/* `sinew --help` keeps its summaries in one column: a usage longer than
 * the column puts its summary on the next line, so no line runs past 100
 * characters and every summary starts at the same place (moment-arms,
 * inverse and optimize ran theirs on from the usage). */
Test(cli_messages, the_command_list_keeps_one_column)
{
    char command[1024];
    snprintf(command, sizeof command, "'%s' --help", SINEW_TOOL);
    FILE *p = popen(command, "r");
    cr_assert_not_null(p);
    char line[512];
    bool listing = false;
    int column = -1, lines = 0;
    while (fgets(line, sizeof line, p) != NULL) {
        cr_expect_leq(strlen(line), 101, "a line of %zu characters: %s", strlen(line), line);
        if (strcmp(line, "commands:\n") == 0) {
            listing = true;
            continue;
        }
        if (!listing || line[0] == '\n') {
            listing = listing && line[0] != '\n';
            continue;
        }
        /* The summary starts after the usage's run of two or more spaces. */
        const char *gap = strstr(line + 2, "  ");
        if (gap == NULL) {
            continue; /* a usage on its own line */
        }
        const int start = (int)(gap - line) + (int)strspn(gap, " ");
        column = column < 0 ? start : column;
        cr_expect_eq(start, column, "a summary at column %d, not %d: %s", start, column, line);
        ++lines;
    }
    cr_assert_eq(pclose(p), 0);
    cr_assert_geq(lines, 10, "the command list has %d summaries", lines);
}
