/* SPDX-License-Identifier: MIT */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/csv_table.h"
#include "live_graph.h"

static const char *const titles[LIVE_GRAPH_COUNT] = {
    "Activation", "Total tension (N)", "Selected muscle: active, passive, total (N)", "Normalized contraction"};
static const char *const stems[LIVE_GRAPH_COUNT] = {"activation", "tension", "selected_forces", "contraction"};
static const char *const y_labels[LIVE_GRAPH_COUNT] = {"activation (0 .. 1)", "tension (N)", "force (N)",
                                                       "contraction / rest length"};

/* What each quantity is called in a legend (after the muscle's name) and
 * in a CSV header (with its unit). */
static const char *const quantity_legends[HISTORY_QUANTITY_COUNT] = {"", " total", " active", " passive", ""};
static const char *const quantity_columns[HISTORY_QUANTITY_COUNT] = {"activation", "total_force_N", "active_force_N",
                                                                     "passive_force_N", "normalized_contraction"};

const char *live_graph_file_stem(live_graph_kind kind) { return stems[kind]; }

static void add_channel(live_graph *graph, const simulation *sim, int muscle, history_quantity quantity)
{
    if (graph->channel_count >= CHART_MAX_SERIES) {
        return;
    }
    live_graph_channel *channel = &graph->channels[graph->channel_count++];
    const char *name = mu_model_muscle_name(sim->model, muscle);
    channel->muscle = muscle;
    channel->quantity = quantity;
    const char *legend = graph->kind == LIVE_GRAPH_SELECTED_FORCES ? quantity_legends[quantity] : "";
    snprintf(channel->label, sizeof channel->label, "%s%s", name, legend);
    snprintf(channel->csv_column, sizeof channel->csv_column, "%s.%s", name, quantity_columns[quantity]);
}

/* Whether built muscle `muscle` is the target or one of the target group's. */
static bool is_selected(const simulation *sim, int muscle)
{
    const char *name = mu_model_muscle_name(sim->model, muscle);
    mu_model_ref ref;
    if (!mu_model_desc_find(sim->desc, sim->target, &ref)) {
        return false;
    }
    if (ref.kind == MU_MODEL_MUSCLE) {
        return strcmp(sim->desc->muscles[ref.index].name, name) == 0;
    }
    if (ref.kind != MU_MODEL_GROUP) {
        return false;
    }
    const mu_model_group *group = &sim->desc->groups[ref.index];
    for (int k = 0; k < group->muscle_count; ++k) {
        if (strcmp(sim->desc->muscles[group->muscles[k]].name, name) == 0) {
            return true;
        }
    }
    return false;
}

void live_graph_select(live_graph *graph, live_graph_kind kind, const simulation *sim)
{
    graph->kind = kind;
    graph->channel_count = 0;
    if (sim->kind != SIMULATION_MODEL) {
        return;
    }
    int muscles = mu_model_muscle_count(sim->model);
    muscles = muscles < CHART_MAX_SERIES ? muscles : CHART_MAX_SERIES; /* as many as the history keeps */
    for (int m = 0; m < muscles; ++m) {
        switch (kind) {
        case LIVE_GRAPH_ACTIVATION:
            add_channel(graph, sim, m, HISTORY_ACTIVATION);
            break;
        case LIVE_GRAPH_TENSION:
            add_channel(graph, sim, m, HISTORY_TOTAL_FORCE);
            break;
        case LIVE_GRAPH_SELECTED_FORCES:
            if (graph->channel_count == 0 && is_selected(sim, m)) {
                add_channel(graph, sim, m, HISTORY_ACTIVE_FORCE);
                add_channel(graph, sim, m, HISTORY_PASSIVE_FORCE);
                add_channel(graph, sim, m, HISTORY_TOTAL_FORCE);
            }
            break;
        case LIVE_GRAPH_CONTRACTION:
            if (is_selected(sim, m)) {
                add_channel(graph, sim, m, HISTORY_NORMALIZED_CONTRACTION);
            }
            break;
        case LIVE_GRAPH_COUNT:
            break;
        }
    }
}

/* The held samples of every channel: one time array and one value array
 * per channel, allocated in one block that the caller frees. */
typedef struct series_block {
    double *block;
    double *times;
    double *values[CHART_MAX_SERIES];
    long count;
} series_block;

static bool gather(const live_graph *graph, const history *samples, series_block *out, char *error, size_t error_size)
{
    size_t count = (size_t)samples->count;
    out->count = samples->count;
    out->block = malloc(sizeof(double) * (count * (size_t)(graph->channel_count + 1) + 1));
    if (out->block == NULL) {
        snprintf(error, error_size, "out of memory for the graph's %ld samples", samples->count);
        return false;
    }
    out->times = out->block;
    for (int c = 0; c < graph->channel_count; ++c) {
        out->values[c] = out->block + count * (size_t)(c + 1);
        history_series(samples, graph->channels[c].muscle, graph->channels[c].quantity, out->times, out->values[c]);
    }
    return true;
}

chart_range live_graph_y_range(live_graph_kind kind, double low, double high)
{
    if (!(low <= high) || !isfinite(low) || !isfinite(high)) {
        low = 0.0; /* nothing shown yet */
        high = kind == LIVE_GRAPH_ACTIVATION ? 1.0 : 0.0;
    }
    if (kind == LIVE_GRAPH_ACTIVATION) {
        low = fmin(low, 0.0);
        high = fmax(high, 1.0);
    }
    if (high - low <= 1e-12 * fmax(fabs(low), fabs(high))) {
        double half = low != 0.0 ? 0.1 * fabs(low) : 1.0;
        low -= half;
        high += half;
    }
    /* Halves, so that a span near ±DBL_MAX does not overflow. */
    double margin = LIVE_GRAPH_HEADROOM * (high / 2.0 - low / 2.0) * 2.0;
    return (chart_range){.fixed = true, .min = fmax(low - margin, -DBL_MAX), .max = fmin(high + margin, DBL_MAX)};
}

bool live_graph_draw(const live_graph *graph, const history *samples, cairo_t *cr, double width, double height,
                     char *error, size_t error_size)
{
    series_block data;
    if (graph->channel_count == 0) {
        data = (series_block){.count = 0};
    } else if (!gather(graph, samples, &data, error, error_size)) {
        return false;
    }
    chart_series series[CHART_MAX_SERIES];
    for (int c = 0; c < graph->channel_count; ++c) {
        series[c] = (chart_series){
            .label = graph->channels[c].label, .x = data.times, .y = data.values[c], .count = (size_t)data.count};
    }
    /* The last LIVE_GRAPH_SECONDS, or the first ones until then. */
    double end = data.count > 0 ? data.times[data.count - 1] : 0.0;
    end = end > LIVE_GRAPH_SECONDS ? end : LIVE_GRAPH_SECONDS;
    double start = end - LIVE_GRAPH_SECONDS;
    /* The y range of the samples shown, with headroom. */
    double low = INFINITY, high = -INFINITY;
    for (int c = 0; c < graph->channel_count; ++c) {
        for (long k = 0; k < data.count; ++k) {
            double v = data.values[c][k];
            if (data.times[k] >= start && isfinite(v)) {
                low = fmin(low, v);
                high = fmax(high, v);
            }
        }
    }
    chart figure = {
        .title = titles[graph->kind],
        .x_label = "time (s)",
        .y_label = y_labels[graph->kind],
        .series = series,
        .series_count = graph->channel_count,
        .x_range = {.fixed = true, .min = start, .max = end},
        .y_range = live_graph_y_range(graph->kind, low, high),
    };
    bool drawn = chart_draw(&figure, cr, 0.0, 0.0, width, height, error, error_size);
    free(data.block);
    return drawn;
}

bool live_graph_write_csv(const live_graph *graph, const history *samples, const char *path, char *error,
                          size_t error_size)
{
    if (graph->channel_count == 0) {
        snprintf(error, error_size, "the graph \"%s\" has no data to export (load a model with muscles)",
                 titles[graph->kind]);
        return false;
    }
    const char *names[CHART_MAX_SERIES + 1] = {"time_s"};
    for (int c = 0; c < graph->channel_count; ++c) {
        names[c + 1] = graph->channels[c].csv_column;
    }
    series_block data;
    if (!gather(graph, samples, &data, error, error_size)) {
        return false;
    }
    csv_table table;
    bool written = csv_table_init(&table, graph->channel_count + 1, names, error, error_size);
    for (long k = 0; written && k < data.count; ++k) {
        double row[CHART_MAX_SERIES + 1] = {data.times[k]};
        for (int c = 0; c < graph->channel_count; ++c) {
            row[c + 1] = data.values[c][k];
        }
        written = csv_table_add_row(&table, row, error, error_size);
    }
    written = written && csv_table_write(&table, path, error, error_size);
    csv_table_free(&table);
    free(data.block);
    return written;
}
