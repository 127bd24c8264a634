/* SPDX-License-Identifier: MIT */
/* Line charts drawn with Cairo: the figures of `sinew plot` and `sinew
 * experiment`, and the live graphs of a viewer, which draws the same
 * charts into its widgets' cairo_t.
 *
 * A chart is a title, two axis labels (with their units, e.g. "time (s)")
 * and one or more series of (x, y) points, each drawn as a polyline in its
 * own colour (chart_series_colour) and named in a legend at the right of
 * the plot area. The axes cover the data with "nice" ticks (chart_ticks.h)
 * unless the chart fixes a range. An axis is linear or logarithmic
 * (chart_scale); a logarithmic one has decade ticks (chart_log_ticks.h)
 * and shows only values above 0: chart_draw refuses a finite point at or
 * below 0 on it, naming the series and the point.
 *
 * Degenerate data is drawn, not refused: an empty series draws nothing
 * (the axes of an empty chart span 0 .. 1), a single point is a dot,
 * constant data gets a range around its value, and a point with a NaN or
 * an infinite coordinate is skipped, breaking the line there. Text that is
 * not UTF-8 (a title, label or series name read from a file in another
 * encoding) is drawn with U+FFFD in place of each byte that starts no
 * character.
 *
 * Errors: every function checks its arguments and returns false with a
 * message naming the function and the argument in `error` (truncated to
 * error_size bytes; `error` may be NULL).
 */
#ifndef CHART_CHART_H
#define CHART_CHART_H

#include <cairo.h>
#include <stdbool.h>
#include <stddef.h>

/* Bytes of an error buffer that holds any message of this library whole
 * unless a path is very long. */
#define CHART_ERROR_SIZE 4608

/* Most series one chart draws: beyond this a legend cannot be read. */
#define CHART_MAX_SERIES 64

typedef struct chart_series {
    const char *label; /* legend text; NULL or "" leaves the series out of the legend */
    const double *x;   /* count values, any units */
    const double *y;
    size_t count; /* 0 is allowed */
    /* 0 draws lines; > 0 also marks each point with a dot of this
     * radius, in device units (px). */
    double marker_radius;
    /* Further points, marked with rings (of marker_radius, or 3 px when
     * it is 0) in the series' colour but not joined: the measurements
     * off the line drawn through x and y, when that line is their front
     * (chart/series_groups.h). mark_count 0 (the default) has none. */
    const double *mark_x, *mark_y;
    size_t mark_count;
} chart_series;

/* An axis range fixed by the caller; with `fixed` false the chart picks
 * nice ticks covering the data. */
typedef struct chart_range {
    bool fixed;
    double min, max; /* min < max, finite, when fixed */
} chart_range;

/* How values map to an axis: evenly, or by their logarithm (each decade
 * the same length), for data spanning several decades. */
typedef enum chart_scale { CHART_LINEAR, CHART_LOG } chart_scale;

typedef struct chart {
    const char *title;   /* may be NULL */
    const char *x_label; /* may be NULL; give the unit: "time (s)" */
    const char *y_label;
    const chart_series *series;
    int series_count;             /* 0 .. CHART_MAX_SERIES */
    chart_range x_range, y_range; /* a fixed range on a log axis needs min > 0 */
    chart_scale x_scale, y_scale; /* CHART_LINEAR when zero-initialised */
} chart;

/* Draws the chart onto `cr` inside the rectangle (x, y, width, height) in
 * the user units of `cr` (width and height > 0 and finite), white
 * background included; the state of `cr` is saved and restored. */
bool chart_draw(const chart *chart, cairo_t *cr, double x, double y, double width, double height, char *error,
                size_t error_size);

/* The colour of series `index` (>= 0), as red, green, blue in 0 .. 1:
 * a palette of distinct colours that stays readable for common forms of
 * colour blindness (Okabe & Ito 2008, "Color universal design"); beyond
 * it the colours repeat and chart_draw dashes the repeated lines. */
void chart_series_colour(int index, double rgb[3]);

/* A figure: charts laid out in a grid of `columns` columns (rows as
 * needed), filling width × height px (each > 0 and at most
 * CHART_MAX_FIGURE_SIZE). */
#define CHART_MAX_FIGURE_SIZE 16384
typedef struct chart_figure {
    const chart *charts;
    int chart_count; /* >= 1 */
    int columns;     /* >= 1 */
    int width, height;
} chart_figure;

/* Draws the whole figure onto `cr` at (0, 0). */
bool chart_figure_draw(const chart_figure *figure, cairo_t *cr, char *error, size_t error_size);

/* Writes the figure as a PNG or an SVG file, under a temporary name
 * renamed into place once complete (io/atomic_file.h): a failure leaves
 * no file behind and keeps an earlier one. */
bool chart_write_png(const chart_figure *figure, const char *path, char *error, size_t error_size);
bool chart_write_svg(const chart_figure *figure, const char *path, char *error, size_t error_size);
/* chart_write_png for a command: false after printing "sinew: MESSAGE" on
 * stderr. */
bool chart_write_png_or_say(const chart_figure *figure, const char *path);
/* Either, by the path's extension: ".png" or ".svg" (any case). */
bool chart_write_file(const chart_figure *figure, const char *path, char *error, size_t error_size);

#endif
