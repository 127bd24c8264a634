/* SPDX-License-Identifier: MIT */
/* `sinew plot CSV [--x COL] [--y COL ...] [--out FILE] [--title TEXT]`:
 * draws columns of any CSV file with a header row as a line chart
 * (chart/chart.h), into a PNG or an SVG file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "chart/column_label.h"
#include "cli/options.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/csv_table.h"

enum { OPT_X, OPT_Y, OPT_OUT, OPT_TITLE };

static const cli_option options_table[] = {
    {.name = "x",
     .id = OPT_X,
     .kind = CLI_TEXT,
     .value_name = "COLUMN",
     .help = "the column along x",
     .fallback = "the first"},
    {.name = "y",
     .id = OPT_Y,
     .kind = CLI_TEXT,
     .value_name = "COLUMN",
     .help = "a column along y (repeatable; by default every other numeric column,\n"
             "the first 8 when there are more)"},
    {.name = "out",
     .id = OPT_OUT,
     .kind = CLI_PATH,
     .value_name = "FILE",
     .help = "FILE.png or FILE.svg",
     .fallback = "the CSV's name with .png"},
    {.name = "title",
     .id = OPT_TITLE,
     .kind = CLI_TEXT,
     .value_name = "TEXT",
     .help = "the chart's title",
     .fallback = "the CSV's file name"},
};

static const cli_command command = {
    .name = "sinew plot",
    .operands = "CSV [options]",
    .max_operands = 1,
    .operand = "CSV file",
    .about = "Draws columns of a CSV file with a header row (as `sinew run`, `sinew scene` and\n"
             "`sinew experiment` write) as a line chart.\n",
    .options = options_table,
    .option_count = sizeof options_table / sizeof options_table[0],
    .notes = "Columns are named as in the header, units included: --y \"Biceps Long.total_force_N\".\n",
};

/* Series drawn when --y is not given: more lines than this cannot be
 * told apart. */
#define DEFAULT_MAX_SERIES 8

/* Figure size, px. */
#define PLOT_WIDTH 960
#define PLOT_HEIGHT 600

typedef struct plot_options {
    const char *csv_path;
    const char *x; /* NULL: the first column */
    const char **y;
    int y_count;
    const char *out; /* NULL: the CSV's name with .png */
    const char *title;
} plot_options;

/* Returns 0, PARSE_HELP for --help, or an exit status. */
enum { PARSE_HELP = 100 };
static int parse_arguments(int argc, char **argv, plot_options *opts)
{
    cli_parser parser;
    cli_parser_start(&parser, &command, argc, argv);
    cli_value value;
    int id;
    while ((id = cli_next(&parser, &value)) >= 0) {
        switch (id) {
        case OPT_X:
            opts->x = value.text;
            break;
        case OPT_Y:
            opts->y[opts->y_count++] = value.text;
            break;
        case OPT_OUT:
            opts->out = value.text;
            break;
        default:
            opts->title = value.text;
            break;
        }
    }
    if (id == CLI_END && parser.operand_count == 1) {
        opts->csv_path = parser.operands[0];
    }
    cli_parser_finish(&parser);
    if (id != CLI_END) {
        return id == CLI_HELP ? PARSE_HELP : EXIT_USAGE;
    }
    if (opts->csv_path == NULL) {
        return cli_usage_error(&command, "missing the CSV file");
    }
    if (opts->y_count > CHART_MAX_SERIES) {
        return cli_usage_error(&command, "%d columns with --y; a chart draws at most %d", opts->y_count,
                               CHART_MAX_SERIES);
    }
    return 0;
}

/* The column `name` of the table, which must be numeric; returns its
 * index, or -1 after one line on stderr. */
static int numeric_column(const csv_table *table, const char *path, const char *option, const char *name)
{
    int c = csv_table_find(table, name);
    if (c < 0) {
        fprintf(stderr, "sinew: %s \"%s\": %s has no such column (it has", option, name, path);
        for (int k = 0; k < table->column_count && k < 6; ++k) {
            fprintf(stderr, "%s \"%s\"", k == 0 ? "" : ",", table->columns[k].name);
        }
        fprintf(stderr, "%s)\n", table->column_count > 6 ? ", ..." : "");
        return -1;
    }
    const csv_column *column = &table->columns[c];
    if (!column->numeric) {
        fprintf(stderr, "sinew: %s:%ld: column \"%s\" holds \"%s\", not a number\n", path, column->bad_line, name,
                column->bad_cell);
        return -1;
    }
    return c;
}

/* The output path: --out, or the CSV's path with its extension replaced
 * by .png. */
static int output_path(const plot_options *opts, char *path, size_t path_size)
{
    if (opts->out != NULL) {
        size_t length = strlen(opts->out);
        if (length < 5 ||
            (strcmp(opts->out + length - 4, ".png") != 0 && strcmp(opts->out + length - 4, ".svg") != 0)) {
            fprintf(stderr, "sinew: --out %s: expected a file name ending in .png or .svg\n", opts->out);
            return EXIT_USAGE;
        }
        snprintf(path, path_size, "%s", opts->out);
        return 0;
    }
    const char *slash = strrchr(opts->csv_path, '/');
    const char *dot = strrchr(opts->csv_path, '.');
    size_t stem =
        dot != NULL && (slash == NULL || dot > slash + 1) ? (size_t)(dot - opts->csv_path) : strlen(opts->csv_path);
    int written = snprintf(path, path_size, "%.*s.png", (int)stem, opts->csv_path);
    if (written < 0 || (size_t)written >= path_size) {
        fprintf(stderr, "sinew: %s: the path of the figure is too long\n", opts->csv_path);
        return EXIT_FAILURE;
    }
    return 0;
}

/* The y axis's label: a single column's own label; for several, their
 * common unit, if any. */
static void y_axis_label(const csv_table *table, const int *columns, int count, char *label, size_t label_size)
{
    if (count == 1) {
        column_label(table->columns[columns[0]].name, label, label_size);
        return;
    }
    char first[64], unit[64];
    column_unit(table->columns[columns[0]].name, first, sizeof first);
    for (int k = 1; k < count; ++k) {
        column_unit(table->columns[columns[k]].name, unit, sizeof unit);
        if (strcmp(unit, first) != 0) {
            snprintf(label, label_size, "value");
            return;
        }
    }
    snprintf(label, label_size, first[0] != '\0' ? "value (%s)" : "value", first);
}

static int draw(const plot_options *opts, const csv_table *table, int x, const int *y, int y_count)
{
    chart_series series[CHART_MAX_SERIES];
    for (int k = 0; k < y_count; ++k) {
        series[k] = (chart_series){
            .label = table->columns[y[k]].name,
            .x = table->columns[x].values,
            .y = table->columns[y[k]].values,
            .count = (size_t)table->row_count,
        };
    }
    char x_label[256], y_label[256], path[ATOMIC_FILE_PATH_MAX];
    column_label(table->columns[x].name, x_label, sizeof x_label);
    y_axis_label(table, y, y_count, y_label, sizeof y_label);
    const char *slash = strrchr(opts->csv_path, '/');
    chart plot = {
        .title = opts->title != NULL ? opts->title
                 : slash != NULL     ? slash + 1
                                     : opts->csv_path,
        .x_label = x_label,
        .y_label = y_label,
        .series = series,
        .series_count = y_count,
    };
    int code = output_path(opts, path, sizeof path);
    if (code != 0) {
        return code;
    }
    chart_figure figure = {.charts = &plot, .chart_count = 1, .columns = 1, .width = PLOT_WIDTH, .height = PLOT_HEIGHT};
    char error[CHART_ERROR_SIZE];
    if (!chart_write_file(&figure, path, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("%s: %ld rows, %d series against %s\n", path, table->row_count, y_count, table->columns[x].name);
    return EXIT_SUCCESS;
}

/* Chooses the columns and draws them; returns the exit status. */
static int plot_table(const plot_options *opts, const csv_table *table)
{
    int x = opts->x != NULL ? numeric_column(table, opts->csv_path, "--x", opts->x) : 0;
    if (x < 0) {
        return EXIT_FAILURE;
    }
    if (opts->x == NULL && !table->columns[0].numeric) {
        fprintf(stderr, "sinew: %s:%ld: the first column \"%s\" holds \"%s\", not a number; choose one with --x\n",
                opts->csv_path, table->columns[0].bad_line, table->columns[0].name, table->columns[0].bad_cell);
        return EXIT_FAILURE;
    }
    int y[CHART_MAX_SERIES];
    int y_count = 0;
    for (int k = 0; k < opts->y_count; ++k) {
        y[y_count] = numeric_column(table, opts->csv_path, "--y", opts->y[k]);
        if (y[y_count++] < 0) {
            return EXIT_FAILURE;
        }
    }
    int candidates = 0;
    for (int c = 0; opts->y_count == 0 && c < table->column_count; ++c) {
        if (c != x && table->columns[c].numeric) {
            if (y_count < DEFAULT_MAX_SERIES) {
                y[y_count++] = c;
            }
            ++candidates;
        }
    }
    if (y_count == 0) {
        fprintf(stderr, "sinew: %s: no numeric column to draw against \"%s\"\n", opts->csv_path,
                table->columns[x].name);
        return EXIT_FAILURE;
    }
    if (candidates > y_count) {
        fprintf(stderr, "sinew: drawing the first %d of %d numeric columns; choose others with --y\n", y_count,
                candidates);
    }
    return draw(opts, table, x, y, y_count);
}

int cmd_plot(int argc, char **argv)
{
    plot_options opts = {.csv_path = NULL};
    opts.y = malloc(((size_t)argc + 1) * sizeof *opts.y);
    if (opts.y == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    int code = parse_arguments(argc, argv, &opts);
    if (code == PARSE_HELP) {
        cli_print_help(&command, stdout);
        free(opts.y);
        return EXIT_SUCCESS;
    }
    if (code == 0) {
        csv_table table;
        char error[ATOMIC_FILE_ERROR_SIZE];
        if (!csv_table_read(opts.csv_path, &table, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            code = EXIT_FAILURE;
        } else {
            code = plot_table(&opts, &table);
            csv_table_free(&table);
        }
    }
    free(opts.y);
    return code;
}
