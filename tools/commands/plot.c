/* SPDX-License-Identifier: MIT */
/* `sinew plot CSV [--x COL] [--y COL ...] [--group COL] [--where COL=VALUE ...]
 *  [--log-x] [--log-y] [--points] [--out FILE] [--title TEXT]`:
 * draws columns of any CSV file with a header row as a line chart
 * (chart/chart.h), into a PNG or an SVG file.
 *
 * A benchmark's CSV (bench/bench_solver.c) holds one row per scene and
 * setting: --where keeps one scene's rows, --group draws one series per
 * solver (chart/series_groups.h), --points marks each measurement and
 * joins a series' points in order of x (cost), and --log-x, --log-y put
 * data spanning decades on logarithmic axes.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "chart/column_label.h"
#include "chart/series_groups.h"
#include "cli/options.h"
#include "commands.h"
#include "io/atomic_file.h"
#include "io/csv_cells.h"
#include "io/csv_table.h"

enum {
    OPT_X,
    OPT_Y,
    OPT_GROUP,
    OPT_WHERE,
    OPT_LOG_X,
    OPT_LOG_Y,
    OPT_POINTS,
    OPT_FRONT,
    OPT_X_LABEL,
    OPT_Y_LABEL,
    OPT_OUT,
    OPT_TITLE
};

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
    {.name = "group",
     .id = OPT_GROUP,
     .kind = CLI_TEXT,
     .value_name = "COLUMN",
     .help = "one series per distinct value of COLUMN (text or numbers), named by\n"
             "the value in the legend"},
    {.name = "where",
     .id = OPT_WHERE,
     .kind = CLI_TEXT,
     .value_name = "COLUMN=VALUE",
     .help = "only the rows whose COLUMN holds VALUE, as written in the file\n"
             "(repeatable: rows that match every one)"},
    {.name = "log-x", .id = OPT_LOG_X, .kind = CLI_FLAG, .help = "a logarithmic x axis (values above 0 only)"},
    {.name = "log-y", .id = OPT_LOG_Y, .kind = CLI_FLAG, .help = "a logarithmic y axis (values above 0 only)"},
    {.name = "points",
     .id = OPT_POINTS,
     .kind = CLI_FLAG,
     .help = "mark every point and join each series' points in order of x\n"
             "(measurements rather than a time series)"},
    {.name = "front",
     .id = OPT_FRONT,
     .kind = CLI_FLAG,
     .help = "mark every point and join only each series' front: the points no\n"
             "point of lower or equal x matches in y (with x a cost and y an\n"
             "error, the best accuracy each cost buys); the others are rings"},
    {.name = "x-label",
     .id = OPT_X_LABEL,
     .kind = CLI_TEXT,
     .value_name = "TEXT",
     .help = "the x axis's label",
     .fallback = "the column's name with its unit"},
    {.name = "y-label",
     .id = OPT_Y_LABEL,
     .kind = CLI_TEXT,
     .value_name = "TEXT",
     .help = "the y axis's label",
     .fallback = "from the columns' names"},
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
    .notes = "Columns are named as in the header, units included: --y \"Biceps Long.total_force_N\".\n"
             "A solver benchmark's accuracy against cost, one curve per solver:\n"
             "  sinew plot bench_solver.csv --where scene=pendulum --where diverged=no --x median_ms\n"
             "    --y energy_drift_max --group correction --front --log-x --log-y\n",
};

/* Series drawn when --y is not given: more lines than this cannot be
 * told apart. */
#define DEFAULT_MAX_SERIES 8

/* Figure size, px. */
#define PLOT_WIDTH 960
#define PLOT_HEIGHT 600

/* Radius of a point's mark with --points, px. */
#define POINT_RADIUS 3.5

typedef struct plot_options {
    const char *csv_path;
    const char *x; /* NULL: the first column */
    const char **y;
    int y_count;
    const char *group;  /* NULL: no grouping */
    const char **where; /* "COLUMN=VALUE" each */
    int where_count;
    bool log_x, log_y, points, front;
    const char *x_label, *y_label; /* NULL: from the columns' names */
    const char *out;               /* NULL: the CSV's name with .png */
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
        case OPT_GROUP:
            opts->group = value.text;
            break;
        case OPT_WHERE:
            opts->where[opts->where_count++] = value.text;
            break;
        case OPT_LOG_X:
            opts->log_x = true;
            break;
        case OPT_LOG_Y:
            opts->log_y = true;
            break;
        case OPT_POINTS:
            opts->points = true;
            break;
        case OPT_FRONT:
            opts->front = true;
            break;
        case OPT_X_LABEL:
            opts->x_label = value.text;
            break;
        case OPT_Y_LABEL:
            opts->y_label = value.text;
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
    for (int k = 0; k < opts->where_count; ++k) {
        const char *equals = strchr(opts->where[k], '=');
        if (equals == NULL || equals == opts->where[k]) {
            return cli_usage_error(&command, "--where \"%s\": expected COLUMN=VALUE", opts->where[k]);
        }
    }
    return 0;
}

/* The column `name` of the table; returns its index, or -1 after one
 * line on stderr naming the option, the column and the file. */
static int find_column(const csv_table *table, const char *path, const char *option, const char *name)
{
    int c = csv_table_find(table, name);
    if (c < 0) {
        fprintf(stderr, "sinew: %s \"%s\": %s has no such column (it has", option, name, path);
        for (int k = 0; k < table->column_count && k < 6; ++k) {
            fprintf(stderr, "%s \"%s\"", k == 0 ? "" : ",", table->columns[k].name);
        }
        fprintf(stderr, "%s)\n", table->column_count > 6 ? ", ..." : "");
    }
    return c;
}

/* The column `name` of the table, which must be numeric; returns its
 * index, or -1 after one line on stderr. */
static int numeric_column(const csv_table *table, const char *path, const char *option, const char *name)
{
    int c = find_column(table, path, option, name);
    if (c < 0) {
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

/* The rows --where keeps, into `keep` (row_count values). Returns 0, or
 * an exit status after one line on stderr. */
static int select_rows(const plot_options *opts, const csv_table *table, bool *keep)
{
    for (long r = 0; r < table->row_count; ++r) {
        keep[r] = true;
    }
    for (int k = 0; k < opts->where_count; ++k) {
        const char *equals = strchr(opts->where[k], '=');
        char name[512];
        snprintf(name, sizeof name, "%.*s", (int)(equals - opts->where[k]), opts->where[k]);
        if (find_column(table, opts->csv_path, "--where", name) < 0) {
            return EXIT_FAILURE;
        }
        csv_cells cells;
        char error[ATOMIC_FILE_ERROR_SIZE];
        if (!csv_cells_read(opts->csv_path, name, &cells, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
        bool any = false;
        for (long r = 0; r < table->row_count && r < cells.count; ++r) {
            keep[r] = keep[r] && strcmp(cells.text[r], equals + 1) == 0;
            any = any || strcmp(cells.text[r], equals + 1) == 0;
        }
        if (!any) {
            /* Say what the column does hold: its first few values. */
            fprintf(stderr, "sinew: --where %s: no row of %s has \"%s\" in column \"%s\" (it holds", opts->where[k],
                    opts->csv_path, equals + 1, name);
            int shown = 0;
            for (long r = 0; r < cells.count && shown < 6; ++r) {
                bool seen = false;
                for (long q = 0; q < r && !seen; ++q) {
                    seen = strcmp(cells.text[q], cells.text[r]) == 0;
                }
                if (!seen) {
                    fprintf(stderr, "%s \"%s\"", shown++ == 0 ? "" : ",", cells.text[r]);
                }
            }
            fprintf(stderr, "%s)\n", shown == 0 ? " no rows" : "");
            csv_cells_free(&cells);
            return EXIT_FAILURE;
        }
        csv_cells_free(&cells);
    }
    return 0;
}

/* A logarithmic axis shows only values above 0: the first kept row whose
 * column `c` holds 0 or less is named by its line. Returns 0, or an exit
 * status after one line on stderr. */
static int check_log_column(const plot_options *opts, const csv_table *table, int c, const char *option,
                            const bool *keep)
{
    const csv_column *column = &table->columns[c];
    for (long r = 0; r < table->row_count; ++r) {
        if (!keep[r] || !(column->values[r] <= 0.0)) {
            continue;
        }
        /* The row's line, from the file itself (blank lines are skipped). */
        csv_cells cells;
        char error[ATOMIC_FILE_ERROR_SIZE];
        long line = csv_cells_read(opts->csv_path, column->name, &cells, error, sizeof error) && r < cells.count
                        ? cells.line[r]
                        : 0;
        csv_cells_free(&cells);
        fprintf(stderr,
                "sinew: %s:%ld: %s: column \"%s\" holds %g; a logarithmic axis shows only values above 0 (leave such "
                "rows out with --where, or drop %s)\n",
                opts->csv_path, line, option, column->name, column->values[r], option);
        return EXIT_FAILURE;
    }
    return 0;
}

/* The series of the chart: each y column, split by --group's column when
 * given, of the rows kept. Returns 0, or an exit status after one line on
 * stderr. */
static int build_series(const plot_options *opts, const csv_table *table, int x, const int *y, int y_count,
                        const bool *keep, series_groups *groups, chart_series *series, char (*labels)[256],
                        int *series_count)
{
    csv_cells keys = {.text = NULL};
    char error[ATOMIC_FILE_ERROR_SIZE];
    if (opts->group != NULL) {
        if (find_column(table, opts->csv_path, "--group", opts->group) < 0) {
            return EXIT_FAILURE;
        }
        if (!csv_cells_read(opts->csv_path, opts->group, &keys, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            return EXIT_FAILURE;
        }
    }
    int code = 0;
    *series_count = 0;
    for (int k = 0; code == 0 && k < y_count; ++k) {
        if (!series_groups_build((const char *const *)keys.text, keep, table->columns[x].values,
                                 table->columns[y[k]].values, (size_t)table->row_count,
                                 opts->front    ? SERIES_FRONT
                                 : opts->points ? SERIES_BY_X
                                                : SERIES_AS_READ,
                                 &groups[k], error, sizeof error)) {
            fprintf(stderr, "sinew: --group %s: %s: %s\n", opts->group != NULL ? opts->group : "", opts->csv_path,
                    error);
            code = EXIT_FAILURE;
            break;
        }
        if (*series_count + groups[k].count > CHART_MAX_SERIES) {
            fprintf(stderr, "sinew: %s: %d columns of %d groups each; a chart draws at most %d series\n",
                    opts->csv_path, y_count, groups[k].count, CHART_MAX_SERIES);
            code = EXIT_FAILURE;
            break;
        }
        for (int g = 0; g < groups[k].count; ++g) {
            char *label = labels[*series_count];
            const char *column = table->columns[y[k]].name;
            if (opts->group == NULL) {
                snprintf(label, 256, "%s", column);
            } else if (y_count == 1) {
                snprintf(label, 256, "%s", groups[k].keys[g]);
            } else {
                snprintf(label, 256, "%s: %s", groups[k].keys[g], column);
            }
            size_t front = groups[k].front[g];
            series[(*series_count)++] = (chart_series){
                .label = label,
                .x = groups[k].x[g],
                .y = groups[k].y[g],
                .count = front,
                .marker_radius = opts->points || opts->front ? POINT_RADIUS : 0.0,
                .mark_x = groups[k].x[g] + front,
                .mark_y = groups[k].y[g] + front,
                .mark_count = groups[k].points[g] - front,
            };
        }
    }
    csv_cells_free(&keys);
    return code;
}

static int draw(const plot_options *opts, const csv_table *table, int x, const int *y, int y_count, const bool *keep)
{
    series_groups groups[CHART_MAX_SERIES] = {{.count = 0}};
    chart_series series[CHART_MAX_SERIES];
    char labels[CHART_MAX_SERIES][256];
    int series_count = 0;
    int code = build_series(opts, table, x, y, y_count, keep, groups, series, labels, &series_count);
    char x_label[256], y_label[256], path[ATOMIC_FILE_PATH_MAX];
    column_label(table->columns[x].name, x_label, sizeof x_label);
    y_axis_label(table, y, y_count, y_label, sizeof y_label);
    const char *slash = strrchr(opts->csv_path, '/');
    chart plot = {
        .title = opts->title != NULL ? opts->title
                 : slash != NULL     ? slash + 1
                                     : opts->csv_path,
        .x_label = opts->x_label != NULL ? opts->x_label : x_label,
        .y_label = opts->y_label != NULL ? opts->y_label : y_label,
        .series = series,
        .series_count = series_count,
        .x_scale = opts->log_x ? CHART_LOG : CHART_LINEAR,
        .y_scale = opts->log_y ? CHART_LOG : CHART_LINEAR,
    };
    code = code != 0 ? code : output_path(opts, path, sizeof path);
    if (code == 0) {
        chart_figure figure = {
            .charts = &plot, .chart_count = 1, .columns = 1, .width = PLOT_WIDTH, .height = PLOT_HEIGHT};
        char error[CHART_ERROR_SIZE];
        if (!chart_write_file(&figure, path, error, sizeof error)) {
            fprintf(stderr, "sinew: %s\n", error);
            code = EXIT_FAILURE;
        } else {
            long rows = 0;
            for (long r = 0; r < table->row_count; ++r) {
                rows += keep[r];
            }
            printf("%s: %ld rows, %d series against %s\n", path, rows, series_count, table->columns[x].name);
            /* Each series and its points, for a reader (or a test) to check
             * what was drawn. */
            for (int s = 0; opts->group != NULL && s < series_count; ++s) {
                printf("  %s: %zu points", series[s].label, series[s].count + series[s].mark_count);
                if (opts->front) {
                    printf(", %zu on the front", series[s].count);
                }
                printf("\n");
            }
        }
    }
    for (int k = 0; k < y_count; ++k) {
        series_groups_free(&groups[k]);
    }
    return code;
}

/* Chooses the columns and rows and draws them; returns the exit status. */
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
    bool *keep = malloc(((size_t)table->row_count + 1) * sizeof *keep);
    if (keep == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    int code = select_rows(opts, table, keep);
    if (code == 0 && opts->log_x) {
        code = check_log_column(opts, table, x, "--log-x", keep);
    }
    for (int k = 0; code == 0 && opts->log_y && k < y_count; ++k) {
        code = check_log_column(opts, table, y[k], "--log-y", keep);
    }
    if (code == 0) {
        code = draw(opts, table, x, y, y_count, keep);
    }
    free(keep);
    return code;
}

int cmd_plot(int argc, char **argv)
{
    plot_options opts = {.csv_path = NULL};
    opts.y = malloc(((size_t)argc + 1) * sizeof *opts.y);
    opts.where = malloc(((size_t)argc + 1) * sizeof *opts.where);
    if (opts.y == NULL || opts.where == NULL) {
        fputs("sinew: out of memory\n", stderr);
        free(opts.y);
        free(opts.where);
        return EXIT_FAILURE;
    }
    int code = parse_arguments(argc, argv, &opts);
    if (code == PARSE_HELP) {
        cli_print_help(&command, stdout);
        free(opts.y);
        free(opts.where);
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
    free(opts.where);
    return code;
}
