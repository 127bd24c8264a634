/* SPDX-License-Identifier: MIT */
/* Fuzz target: a CSV file's bytes, read as `sinew plot` reads them
 * (csv_table_read) and, when accepted, drawn as it draws them: the first
 * numeric column against the others, each a series named by its header,
 * the axes labelled from the names (column_label), by chart_draw into a
 * small image, then again on logarithmic axes (`sinew plot --log-x
 * --log-y`), where only a value at or below 0 may be refused. The same
 * bytes then go through the muscle layer's CSV
 * reader with the flags of the curve tables and motor-pool profiles
 * (spaces separate, '#' comments), every field read as a number. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */

#include <cairo.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "chart/column_label.h"
#include "csv_reader.h" /* musculo/src: the muscle layer's internal CSV reader */
#include "io/csv_table.h"
#include "memory_file.h"

/* The image drawn into: small, so an input stays quick, and large enough
 * for the legend and tick labels to need their layout. */
enum { WIDTH = 320, HEIGHT = 240 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void draw(const csv_table *table)
{
    int x = -1;
    chart_series series[CHART_MAX_SERIES];
    int count = 0;
    for (int c = 0; c < table->column_count; ++c) {
        if (!table->columns[c].numeric) {
            continue;
        }
        if (x < 0) {
            x = c;
        } else if (count < CHART_MAX_SERIES) {
            /* Every other series marks its points, so both ways of drawing a series run. */
            series[count] = (chart_series){.label = table->columns[c].name,
                                           .x = table->columns[x].values,
                                           .y = table->columns[c].values,
                                           .count = (size_t)table->row_count,
                                           .marker_radius = count % 2 == 0 ? 0.0 : 2.0};
            ++count;
        }
    }
    if (count == 0) {
        return;
    }
    /* Axis labels from the column names, with their units, as `sinew plot` makes them. */
    char x_label[256], y_label[256];
    column_label(table->columns[x].name, x_label, sizeof x_label);
    column_label(series[count - 1].label, y_label, sizeof y_label);
    chart figure = {.title = table->columns[0].name,
                    .x_label = x_label,
                    .y_label = y_label,
                    .series = series,
                    .series_count = count};
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, WIDTH, HEIGHT);
    cairo_t *cr = cairo_create(surface);
    char error[CHART_ERROR_SIZE];
    if (!chart_draw(&figure, cr, 0, 0, WIDTH, HEIGHT, error, sizeof error)) {
        /* Every argument above is valid: a refusal is a defect. */
        fprintf(stderr, "fuzz_csv_chart: chart_draw: %s\n", error);
        abort();
    }
    figure.x_scale = CHART_LOG;
    figure.y_scale = CHART_LOG;
    if (!chart_draw(&figure, cr, 0, 0, WIDTH, HEIGHT, error, sizeof error) && strstr(error, "logarithmic") == NULL) {
        fprintf(stderr, "fuzz_csv_chart: chart_draw on log axes: %s\n", error);
        abort();
    }
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
}

static void read_records(const uint8_t *data, size_t size)
{
    FILE *stream = fmemopen((void *)data, size, "r");
    if (stream == NULL) {
        return; /* fmemopen refuses an empty buffer on older C libraries */
    }
    mu_csv_reader csv;
    mu_csv_reader_init(&csv, "fuzz.csv", stream, MU_CSV_SPACE_SEPARATES | MU_CSV_COMMENTS);
    while (mu_csv_reader_next(&csv) == MU_CSV_RECORD) {
        for (int f = 0; f < csv.field_count; ++f) {
            double value;
            mu_csv_number(csv.fields[f], &value);
        }
    }
    mu_csv_reader_free(&csv);
    fclose(stream);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    memory_file file;
    memory_file_open(&file, data, size);
    csv_table table;
    char error[CHART_ERROR_SIZE];
    if (csv_table_read(file.path, &table, error, sizeof error)) {
        draw(&table);
        csv_table_free(&table);
    }
    memory_file_close(&file);
    read_records(data, size);
    return 0;
}
