/* SPDX-License-Identifier: MIT */
/* The four live graphs of a model (docs/viewer.md): what each shows
 * (its channels: a muscle's quantity from the history), drawn as a chart
 * of the last seconds (chart/chart.h) and exported as CSV (time plus one
 * column per channel, written atomically: io/csv_table.h).
 */
#ifndef VIEWER_LIVE_GRAPH_H
#define VIEWER_LIVE_GRAPH_H

#include <cairo.h>
#include <stdbool.h>
#include <stddef.h>

#include "chart/chart.h"
#include "history.h"
#include "simulation.h"

typedef enum live_graph_kind {
    LIVE_GRAPH_ACTIVATION,      /* every muscle's activation */
    LIVE_GRAPH_TENSION,         /* every muscle's total tension, N */
    LIVE_GRAPH_SELECTED_FORCES, /* active, passive and total tension of the selected muscle (a group's first) */
    LIVE_GRAPH_CONTRACTION,     /* normalized contraction of the selected muscles */
    LIVE_GRAPH_COUNT
} live_graph_kind;

/* Seconds a graph shows, ending at the last sample. */
#define LIVE_GRAPH_SECONDS 5.0

typedef struct live_graph_channel {
    int muscle; /* index among the built muscles */
    history_quantity quantity;
    char label[256];      /* legend: the muscle's name, and which force */
    char csv_column[320]; /* the CSV header: label and unit, "Biceps Short.total_force_N" */
} live_graph_channel;

typedef struct live_graph {
    live_graph_kind kind;
    int channel_count;
    live_graph_channel channels[CHART_MAX_SERIES];
} live_graph;

/* A short name for files and buttons: "activation", "tension", ... */
const char *live_graph_file_stem(live_graph_kind kind);

/* The channels of graph `kind` for what `sim` runs and selects (none
 * without a model). */
void live_graph_select(live_graph *graph, live_graph_kind kind, const simulation *sim);

/* Fraction of the shown span left free above and below the data, so
 * that a line at the data's least or greatest value (a constant
 * activation of 1, a tension at rest at 0) is drawn inside the plot, not
 * on its frame. */
#define LIVE_GRAPH_HEADROOM 0.06

/* The y range graph `kind` shows for data from `low` to `high` (the least
 * and greatest finite values shown; low > high, or NaN, when there are
 * none): the data, and for the activation graph all of 0 .. 1 (its
 * scale then never changes), widened by LIVE_GRAPH_HEADROOM of the span
 * on either side; constant data gets ±10 % of its value around it (±1
 * about 0) before that. Always fixed, finite, min < max. */
chart_range live_graph_y_range(live_graph_kind kind, double low, double high);

/* Draws the graph of the held samples onto `cr` inside (0, 0, width,
 * height). */
bool live_graph_draw(const live_graph *graph, const history *samples, cairo_t *cr, double width, double height,
                     char *error, size_t error_size);

/* Writes the held samples of the graph's channels to `path` as CSV. */
bool live_graph_write_csv(const live_graph *graph, const history *samples, const char *path, char *error,
                          size_t error_size);

#endif
