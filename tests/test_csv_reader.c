/* SPDX-License-Identifier: MIT */
/* The one CSV reader (musculo/src/csv_reader.h): how a file splits into
 * records and fields, how numbers read, and that its three users (curve
 * tables, motor-pool profiles, `sinew plot`) report the same malformed
 * line in the same words.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, fmemopen */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "csv_reader.h"
#include "mu/curves.h"
#include "mu/motor_pool.h"

/* The records of `text` read with `flags`, written as "[a|b|c]" lines
 * into `out`; a reader's error ends them with "error: MESSAGE". */
static void records_of(const char *text, unsigned flags, char *out, size_t out_size)
{
    FILE *file = fmemopen((void *)text, strlen(text), "r");
    cr_assert_not_null(file);
    mu_csv_reader reader;
    mu_csv_reader_init(&reader, "t.csv", file, flags);
    size_t used = 0;
    out[0] = '\0';
    mu_csv_result result;
    while ((result = mu_csv_reader_next(&reader)) == MU_CSV_RECORD) {
        used += (size_t)snprintf(out + used, out_size - used, "%ld[", reader.line_number);
        for (int k = 0; k < reader.field_count; ++k) {
            used += (size_t)snprintf(out + used, out_size - used, "%s%s", k > 0 ? "|" : "", reader.fields[k]);
        }
        used += (size_t)snprintf(out + used, out_size - used, "]");
        cr_assert_lt(used, out_size);
    }
    if (result == MU_CSV_ERROR) {
        snprintf(out + used, out_size - used, "error: %s", reader.error);
    }
    mu_csv_reader_free(&reader);
    fclose(file);
}

static void expect_records(const char *text, unsigned flags, const char *expected)
{
    char got[1024];
    records_of(text, flags, got, sizeof got);
    cr_expect_str_eq(got, expected, "records of \"%s\"", text);
}

Test(csv_reader, splits_records_as_rfc_4180_with_a_hand_edited_file_s_tolerances)
{
    expect_records("a,b,c\n1,2,3\n", 0, "1[a|b|c]2[1|2|3]");
    /* CRLF, a byte-order mark, blank lines, no final line break. */
    expect_records("\xEF\xBB\xBFx,y\r\n\r\n  \t\n1,2", 0, "1[x|y]4[1|2]");
    /* Quotes hold commas and doubled quotes; empty fields are kept. */
    expect_records("\"a,b\",\"say \"\"hi\"\"\",,\n", 0, "1[a,b|say \"hi\"||]");
    /* Spaces belong to an unquoted field unless they separate. */
    expect_records(" 1 , 2\n", 0, "1[ 1 | 2]");
    expect_records("1, 2\t3,,4\n", MU_CSV_SPACE_SEPARATES, "1[1|2|3|4]");
    expect_records("# a comment\n1 # one\n#\n2,\"#3\"\n", MU_CSV_SPACE_SEPARATES | MU_CSV_COMMENTS, "2[1]4[2|#3]");
    /* Without the flag, '#' is text. */
    expect_records("#a,b\n", 0, "1[#a|b]");
    expect_records("", 0, "");
}

Test(csv_reader, lines_of_any_length_are_read)
{
    enum { FIELDS = 5000 };
    char *text = malloc(FIELDS * 8 + 16);
    cr_assert_not_null(text);
    size_t used = 0;
    for (int k = 0; k < FIELDS; ++k) {
        used += (size_t)sprintf(text + used, "%s%d", k > 0 ? "," : "", k);
    }
    sprintf(text + used, "\n");
    FILE *file = fmemopen(text, strlen(text), "r");
    mu_csv_reader reader;
    mu_csv_reader_init(&reader, "long.csv", file, 0);
    cr_assert_eq(mu_csv_reader_next(&reader), MU_CSV_RECORD, "%s", reader.error);
    cr_assert_eq(reader.field_count, FIELDS);
    cr_expect_str_eq(reader.fields[FIELDS - 1], "4999");
    cr_expect_eq(mu_csv_reader_next(&reader), MU_CSV_END);
    mu_csv_reader_free(&reader);
    fclose(file);
    free(text);
}

Test(csv_reader, malformed_quotes_name_the_file_the_line_and_the_field)
{
    expect_records("a,b\n1,\"2\n", 0, "1[a|b]error: t.csv:2: field 2: a quoted field is not closed on its line");
    expect_records("a,\"b\"c\n", 0, "error: t.csv:1: field 2: text after its closing quote");
}

Test(csv_reader, numbers_read_with_strtod_s_syntax_and_only_spaces_around)
{
    const struct {
        const char *text;
        mu_csv_cell cell;
        double value;
    } cases[] = {
        {"0.3422", MU_CSV_NUMBER, 0.3422},  {" -1.5e-3\t", MU_CSV_NUMBER, -1.5e-3},
        {"7", MU_CSV_NUMBER, 7.0},          {"", MU_CSV_EMPTY, 0.0},
        {" \t", MU_CSV_EMPTY, 0.0},         {"0,5", MU_CSV_NOT_A_NUMBER, 0.0},
        {"1.5x", MU_CSV_NOT_A_NUMBER, 0.0}, {"two", MU_CSV_NOT_A_NUMBER, 0.0},
        {"1 2", MU_CSV_NOT_A_NUMBER, 0.0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        double value = -99.0;
        mu_csv_cell cell = mu_csv_number(cases[k].text, &value);
        cr_expect_eq(cell, cases[k].cell, "\"%s\": cell kind %d, expected %d", cases[k].text, cell, cases[k].cell);
        if (cases[k].cell == MU_CSV_NUMBER) {
            cr_expect_eq(value, cases[k].value, "\"%s\" read as %.17g", cases[k].text, value);
        } else {
            cr_expect_eq(value, -99.0, "\"%s\" changed the value", cases[k].text);
        }
    }
    double value = 0.0;
    cr_expect_eq(mu_csv_number("nan", &value), MU_CSV_NUMBER);
    cr_expect(isnan(value));
}

static char dir[] = "/tmp/sinew-csv-XXXXXX";

static void make_dir(void) { cr_assert_not_null(mkdtemp(dir), "mkdtemp failed"); }

static void remove_dir(void)
{
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}

static void write_text(const char *path, const char *text)
{
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file, "cannot write %s", path);
    fputs(text, file);
    fclose(file);
}

Test(csv_reader, its_three_users_report_a_malformed_line_the_same_way, .init = make_dir, .fini = remove_dir)
{
    /* Each file is good on its first line and has an unclosed quote on
     * its second. */
    char curves_path[64], pool_path[64], plot_path[64], expected[256];
    snprintf(curves_path, sizeof curves_path, "%s/curves.csv", dir);
    snprintf(pool_path, sizeof pool_path, "%s/pool.csv", dir);
    snprintf(plot_path, sizeof plot_path, "%s/plot.csv", dir);
    write_text(curves_path, "curve,x,y\n\"force_velocity,0,1\n");
    write_text(pool_path, "1, 2\n\"3, 4\n");
    write_text(plot_path, "time_s,force_N\n\"0,1\n");
    const char *problem = "2: field 1: a quoted field is not closed on its line";

    mu_curves *curves = NULL;
    cr_expect_eq(mu_curves_create_tabulated(curves_path, MU_INTERPOLATION_LINEAR, &curves), RB_ERR_INVALID_ARGUMENT);
    snprintf(expected, sizeof expected, "mu_curves_create_tabulated: %s:%s", curves_path, problem);
    cr_expect_str_eq(rb_last_error(), expected);

    mu_motor_pool *pool = NULL;
    cr_expect_eq(mu_motor_pool_load_csv(pool_path, &pool), RB_ERR_INVALID_ARGUMENT);
    snprintf(expected, sizeof expected, "mu_motor_pool_load_csv: %s:%s", pool_path, problem);
    cr_expect_str_eq(rb_last_error(), expected);

    char command[512], output[512] = "";
    snprintf(command, sizeof command, "'%s' plot '%s' 2>&1", SINEW_TOOL, plot_path);
    FILE *pipe = popen(command, "r");
    cr_assert_not_null(pipe);
    size_t length = fread(output, 1, sizeof output - 1, pipe);
    output[length] = '\0';
    int status = pclose(pipe);
    cr_expect(WIFEXITED(status) && WEXITSTATUS(status) == 1, "sinew plot exited with status %d", status);
    snprintf(expected, sizeof expected, "sinew: %s:%s\n", plot_path, problem);
    cr_expect_str_eq(output, expected);
}
