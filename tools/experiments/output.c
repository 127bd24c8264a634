/* SPDX-License-Identifier: MIT */
/* The files of an experiment: its table as CSV, its figure as PNG and SVG,
 * each written whole or not at all. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "experiment.h"
#include "io/atomic_file.h"
#include "io/provenance.h"

/* DIR/STEM.EXTENSION, or DIR/STEM_PART.EXTENSION for a part other than
 * ""; false when it does not fit. */
static bool part_path(const experiment *self, const experiment_options *options, const char *part,
                      const char *extension, char *path, size_t path_size)
{
    size_t length = strlen(options->out_dir);
    const char *separator = length > 0 && options->out_dir[length - 1] == '/' ? "" : "/";
    int written = snprintf(path, path_size, "%s%s%s%s%s.%s", options->out_dir, separator, self->stem,
                           part[0] != '\0' ? "_" : "", part, extension);
    return written > 0 && (size_t)written < path_size;
}

/* The CSV file `csv`, then its sidecar (io/provenance.h) naming the
 * experiment and its options. */
static bool write_table(const experiment *self, const experiment_options *options, const csv_table *table,
                        const char *csv, char *error, size_t error_size)
{
    json_t *settings = json_pack("{s:s, s:s, s:o, s:s?}", "experiment", self->name, "stem", self->stem, "pulse_width_s",
                                 options->pulse_width > 0.0 ? json_real(options->pulse_width) : json_null(), "dynamics",
                                 options->dynamics);
    if (settings == NULL) {
        snprintf(error, error_size, "out of memory");
        return false;
    }
    if (!csv_table_write(table, csv, error, error_size)) {
        json_decref(settings);
        return false;
    }
    return provenance_write_sidecar(csv, settings, error, error_size);
}

static bool output_path(const experiment *self, const experiment_options *options, const char *extension, char *path,
                        size_t path_size)
{
    return part_path(self, options, "", extension, path, path_size);
}

int experiment_write(const experiment *self, const experiment_options *options, const csv_table *table,
                     const chart_figure *figure)
{
    char csv[ATOMIC_FILE_PATH_MAX], png[ATOMIC_FILE_PATH_MAX], svg[ATOMIC_FILE_PATH_MAX];
    if (!output_path(self, options, "csv", csv, sizeof csv) || !output_path(self, options, "png", png, sizeof png) ||
        !output_path(self, options, "svg", svg, sizeof svg)) {
        fprintf(stderr, "sinew: --out %s: the paths of the files are too long\n", options->out_dir);
        return EXIT_FAILURE;
    }
    char error[CHART_ERROR_SIZE];
    if (!write_table(self, options, table, csv, error, sizeof error) ||
        !chart_write_png(figure, png, error, sizeof error) || !chart_write_svg(figure, svg, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("csv          %s (%ld rows, %d columns)\n", csv, table->row_count, table->column_count);
    printf("figure       %s, %s\n", png, svg);
    return 0;
}

int experiment_write_table(const experiment *self, const experiment_options *options, const char *part,
                           const csv_table *table)
{
    char csv[ATOMIC_FILE_PATH_MAX];
    if (!part_path(self, options, part, "csv", csv, sizeof csv)) {
        fprintf(stderr, "sinew: --out %s: the paths of the files are too long\n", options->out_dir);
        return EXIT_FAILURE;
    }
    char error[CHART_ERROR_SIZE];
    if (!write_table(self, options, table, csv, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    printf("csv          %s (%ld rows, %d columns)\n", csv, table->row_count, table->column_count);
    return 0;
}

chart_series experiment_series(const csv_table *table, int x, int y, long first, const char *label)
{
    long count = table->row_count > first ? table->row_count - first : 0;
    return (chart_series){
        .label = label,
        .x = table->columns[x].values + (count > 0 ? first : 0),
        .y = table->columns[y].values + (count > 0 ? first : 0),
        .count = (size_t)count,
    };
}
