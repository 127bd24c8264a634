/* SPDX-License-Identifier: MIT */
/* Drawing a chart onto a cairo_t: layout (title, tick labels, axis labels
 * and legend around the plot area), grid, axes, series, legend. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chart/chart.h"
#include "chart/chart_log_ticks.h"
#include "chart/chart_ticks.h"

/* Okabe & Ito's palette without its yellow, which is hard to see on white. */
static const double palette[][3] = {
    {0.000, 0.447, 0.698}, /* blue */
    {0.835, 0.369, 0.000}, /* vermillion */
    {0.000, 0.620, 0.451}, /* bluish green */
    {0.800, 0.475, 0.655}, /* reddish purple */
    {0.902, 0.624, 0.000}, /* orange */
    {0.337, 0.706, 0.914}, /* sky blue */
    {0.000, 0.000, 0.000}, /* black */
};
enum { PALETTE_SIZE = sizeof palette / sizeof palette[0] };

#define PI 3.14159265358979323846

/* Longest legend entry drawn, in characters; longer labels end in "...". */
#define LEGEND_MAX_CHARS 48

void chart_series_colour(int index, double rgb[3])
{
    int k = index < 0 ? 0 : index % PALETTE_SIZE;
    rgb[0] = palette[k][0];
    rgb[1] = palette[k][1];
    rgb[2] = palette[k][2];
}

static bool fail(char *error, size_t error_size, const char *format, ...)
{
    if (error != NULL && error_size > 0) {
        va_list args;
        va_start(args, format);
        vsnprintf(error, error_size, format, args);
        va_end(args);
    }
    return false;
}

/* ------------------------------------------------------------ checks */

static bool check_range(const chart_range *range, chart_scale scale, const char *name, char *error, size_t error_size)
{
    if (range->fixed && !(isfinite(range->min) && isfinite(range->max) && range->min < range->max)) {
        return fail(error, error_size, "chart_draw: chart->%s is fixed to [%g, %g]; expected finite min < max", name,
                    range->min, range->max);
    }
    if (range->fixed && scale == CHART_LOG && !(range->min > 0.0)) {
        return fail(error, error_size,
                    "chart_draw: chart->%s is fixed to [%g, %g] on a logarithmic axis; expected 0 < min < max", name,
                    range->min, range->max);
    }
    return true;
}

/* A logarithmic axis shows only values above 0: the first finite point
 * of the series at or below 0 on one is refused (a NaN or infinite point
 * is a gap in the line, as on a linear axis). */
static bool check_log_points(const chart *chart, int s, const double *x, const double *y, size_t count,
                             const char *what, const char *function, char *error, size_t error_size)
{
    const chart_series *series = &chart->series[s];
    for (size_t i = 0; i < count; ++i) {
        if (!isfinite(x[i]) || !isfinite(y[i])) {
            continue;
        }
        bool bad_x = chart->x_scale == CHART_LOG && x[i] <= 0.0;
        if (bad_x || (chart->y_scale == CHART_LOG && y[i] <= 0.0)) {
            return fail(error, error_size,
                        "%s: chart->series[%d] (\"%s\") %s %zu has %s = %g; a logarithmic %s axis shows only "
                        "values above 0",
                        function, s, series->label != NULL ? series->label : "", what, i, bad_x ? "x" : "y",
                        bad_x ? x[i] : y[i], bad_x ? "x" : "y");
        }
    }
    return true;
}

static bool check_log_values(const chart *chart, int s, const char *function, char *error, size_t error_size)
{
    const chart_series *series = &chart->series[s];
    return check_log_points(chart, s, series->x, series->y, series->count, "point", function, error, error_size) &&
           check_log_points(chart, s, series->mark_x, series->mark_y, series->mark_count, "mark", function, error,
                            error_size);
}

static bool check_chart(const chart *chart, const char *function, char *error, size_t error_size)
{
    if (chart == NULL) {
        return fail(error, error_size, "%s: chart is NULL", function);
    }
    if (chart->series_count < 0 || chart->series_count > CHART_MAX_SERIES) {
        return fail(error, error_size, "%s: chart->series_count %d, expected 0 .. %d", function, chart->series_count,
                    CHART_MAX_SERIES);
    }
    if (chart->series_count > 0 && chart->series == NULL) {
        return fail(error, error_size, "%s: chart->series is NULL with %d series", function, chart->series_count);
    }
    for (int s = 0; s < chart->series_count; ++s) {
        const chart_series *series = &chart->series[s];
        if (series->count > 0 && (series->x == NULL || series->y == NULL)) {
            return fail(error, error_size, "%s: chart->series[%d] has %zu points and a NULL x or y", function, s,
                        series->count);
        }
        if (series->mark_count > 0 && (series->mark_x == NULL || series->mark_y == NULL)) {
            return fail(error, error_size, "%s: chart->series[%d] has %zu marks and a NULL mark_x or mark_y", function,
                        s, series->mark_count);
        }
        if (!(series->marker_radius >= 0.0 && series->marker_radius <= 100.0)) {
            return fail(error, error_size, "%s: chart->series[%d].marker_radius %g, expected 0 .. 100", function, s,
                        series->marker_radius);
        }
        if (!check_log_values(chart, s, function, error, error_size)) {
            return false;
        }
    }
    if ((chart->x_scale != CHART_LINEAR && chart->x_scale != CHART_LOG) ||
        (chart->y_scale != CHART_LINEAR && chart->y_scale != CHART_LOG)) {
        return fail(error, error_size, "%s: chart->x_scale %d, y_scale %d: expected CHART_LINEAR or CHART_LOG",
                    function, (int)chart->x_scale, (int)chart->y_scale);
    }
    return check_range(&chart->x_range, chart->x_scale, "x_range", error, error_size) &&
           check_range(&chart->y_range, chart->y_scale, "y_range", error, error_size);
}

/* ------------------------------------------------------------ layout */

typedef struct axis {
    bool log;                  /* logarithmic: log_ticks, else ticks */
    chart_ticks ticks;         /* linear */
    chart_log_ticks log_ticks; /* logarithmic */
    double min, max;           /* the values at the two ends of the plot area */
} axis;

static int tick_count(const axis *a) { return a->log ? a->log_ticks.count : a->ticks.count; }

static double tick_value(const axis *a, int i)
{
    return a->log ? a->log_ticks.values[i] : chart_tick_value(&a->ticks, i);
}

static void tick_label(const axis *a, int i, char *text, size_t text_size)
{
    if (a->log) {
        chart_log_tick_label(a->log_ticks.values[i], text, text_size);
    } else {
        chart_tick_label(&a->ticks, i, text, text_size);
    }
}

/* The axis covering the finite values of the series (x when `use_x`),
 * or the caller's fixed range. */
static void fit_axis(const chart *chart, bool use_x, const chart_range *range, chart_scale scale, int intervals,
                     axis *out)
{
    out->log = scale == CHART_LOG;
    double low = INFINITY, high = -INFINITY;
    if (range->fixed) {
        low = range->min;
        high = range->max;
    } else {
        for (int s = 0; s < chart->series_count; ++s) {
            const chart_series *series = &chart->series[s];
            size_t total = series->count + series->mark_count;
            for (size_t k = 0; k < total; ++k) {
                bool mark = k >= series->count;
                size_t i = mark ? k - series->count : k;
                const double *xs = mark ? series->mark_x : series->x, *ys = mark ? series->mark_y : series->y;
                double v = use_x ? xs[i] : ys[i];
                double other = use_x ? ys[i] : xs[i];
                if (isfinite(v) && isfinite(other)) {
                    low = fmin(low, v);
                    high = fmax(high, v);
                }
            }
        }
        if (!(low <= high)) {
            low = out->log ? 0.1 : 0.0; /* nothing to draw */
            high = 1.0;
        }
    }
    /* Both ends are finite and ordered here, and above 0 on a log axis
     * (check_chart), so this cannot fail. */
    if (out->log) {
        chart_log_ticks_make(low, high, intervals, &out->log_ticks, NULL, 0);
    } else {
        chart_nice_ticks(low, high, intervals, &out->ticks, NULL, 0);
    }
    if (range->fixed) {
        out->min = low;
        out->max = high;
    } else {
        /* The end ticks, or the data's end where no finite tick lies
         * beyond it (near ±DBL_MAX, or below 10^-323). */
        out->min = fmin(tick_value(out, 0), low);
        out->max = fmax(tick_value(out, tick_count(out) - 1), high);
    }
}

static bool tick_inside(const axis *a, int i)
{
    double v = tick_value(a, i);
    if (a->log) {
        return v >= a->min * (1.0 - 1e-9) && v <= a->max * (1.0 + 1e-9);
    }
    double slack = 2e-9 * (a->max / 2.0 - a->min / 2.0);
    return v >= a->min - slack && v <= a->max + slack;
}

/* Bytes of the character starting at `s` when it is one Cairo draws, else 0.
 * Cairo takes UTF-8 of 1 to 4 bytes, not overlong, of a code point below
 * U+110000 that is neither a surrogate nor a noncharacter (U+FDD0 ..
 * U+FDEF, U+xxFFFE, U+xxFFFF): it refuses anything else. */
static size_t drawable_char_length(const unsigned char *s)
{
    if (s[0] < 0x80) {
        return 1;
    }
    size_t length;
    if (s[0] >= 0xC0 && s[0] < 0xE0) {
        length = 2;
    } else if (s[0] >= 0xE0 && s[0] < 0xF0) {
        length = 3;
    } else if (s[0] >= 0xF0 && s[0] < 0xF8) {
        length = 4;
    } else {
        return 0; /* a continuation byte, or the lead of a 5- or 6-byte form */
    }
    unsigned long code = s[0] & (0x7Fu >> length);
    for (size_t k = 1; k < length; ++k) {
        if ((s[k] & 0xC0) != 0x80) {
            return 0; /* the terminating NUL included */
        }
        code = code << 6 | (s[k] & 0x3Fu);
    }
    static const unsigned long least[] = {0, 0, 0x80, 0x800, 0x10000};
    bool valid = code >= least[length] && code < 0x110000 && (code & 0xFFFFF800) != 0xD800 &&
                 (code < 0xFDD0 || code > 0xFDEF) && (code & 0xFFFE) != 0xFFFE;
    return valid ? length : 0;
}

/* Text as Cairo can draw it. Names come from files (a CSV header), and
 * text Cairo refuses puts the whole cairo_t in error, losing the figure:
 * each byte that starts no drawable character is drawn as U+FFFD instead.
 * Returns `text` itself when it is all drawable, else a copy in *copy for
 * the caller to free ("" when out of memory: the text is left out). */
static const char *drawable_text(const char *text, char **copy)
{
    *copy = NULL;
    const unsigned char *s = (const unsigned char *)text;
    size_t length = 0, bad = 0;
    while (s[length] != '\0') {
        size_t n = drawable_char_length(s + length);
        bad += n == 0;
        length += n > 0 ? n : 1;
    }
    if (bad == 0) {
        return text;
    }
    static const char replacement[] = "\xEF\xBF\xBD"; /* U+FFFD in UTF-8 */
    *copy = malloc(length + 2 * bad + 1);
    if (*copy == NULL) {
        return "";
    }
    char *out = *copy;
    for (size_t k = 0; k < length;) {
        size_t n = drawable_char_length(s + k);
        if (n == 0) {
            memcpy(out, replacement, 3);
            out += 3;
            k += 1;
        } else {
            memcpy(out, s + k, n);
            out += n;
            k += n;
        }
    }
    *out = '\0';
    return *copy;
}

static double text_width(cairo_t *cr, const char *text)
{
    char *copy;
    cairo_text_extents_t extents;
    cairo_text_extents(cr, drawable_text(text, &copy), &extents);
    free(copy);
    return extents.x_advance;
}

/* cairo_show_text for any text: see drawable_text. */
static void show_text(cairo_t *cr, const char *text)
{
    char *copy;
    cairo_show_text(cr, drawable_text(text, &copy));
    free(copy);
}

/* A legend label cut to LEGEND_MAX_CHARS characters (bytes of UTF-8 are
 * never split: the cut moves back to a character's first byte). */
static void legend_text(const char *label, char *text, size_t text_size)
{
    size_t length = strlen(label);
    if (length <= LEGEND_MAX_CHARS) {
        snprintf(text, text_size, "%s", label);
        return;
    }
    size_t cut = LEGEND_MAX_CHARS - 3;
    while (cut > 0 && ((unsigned char)label[cut] & 0xC0) == 0x80) {
        --cut;
    }
    snprintf(text, text_size, "%.*s...", (int)cut, label);
}

static bool has_legend_entry(const chart_series *series) { return series->label != NULL && series->label[0] != '\0'; }

/* --------------------------------------------------------------- drawing */

typedef struct plot_area {
    double left, top, width, height;
    axis x, y;
} plot_area;

/* Where v lies between the axis's ends, 0 .. 1: on a linear axis in
 * halves (the width of an axis from -DBL_MAX to DBL_MAX overflows), on a
 * logarithmic one by the logarithms (each decade the same length). */
static double axis_fraction(const axis *a, double v)
{
    if (a->log) {
        return (log10(v) - log10(a->min)) / (log10(a->max) - log10(a->min));
    }
    return (v / 2.0 - a->min / 2.0) / (a->max / 2.0 - a->min / 2.0);
}

static double map_x(const plot_area *p, double v) { return p->left + axis_fraction(&p->x, v) * p->width; }

static double map_y(const plot_area *p, double v) { return p->top + p->height - axis_fraction(&p->y, v) * p->height; }

static void draw_grid_and_ticks(cairo_t *cr, const plot_area *p, double font_size)
{
    char label[64];
    cairo_set_line_width(cr, 1.0);
    for (int i = 0; i < tick_count(&p->x); ++i) {
        if (!tick_inside(&p->x, i)) {
            continue;
        }
        double px = map_x(p, tick_value(&p->x, i));
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_move_to(cr, px, p->top);
        cairo_line_to(cr, px, p->top + p->height);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_move_to(cr, px, p->top + p->height);
        cairo_line_to(cr, px, p->top + p->height + 0.4 * font_size);
        cairo_stroke(cr);
        tick_label(&p->x, i, label, sizeof label);
        cairo_move_to(cr, px - 0.5 * text_width(cr, label), p->top + p->height + 1.5 * font_size);
        show_text(cr, label);
    }
    for (int i = 0; i < tick_count(&p->y); ++i) {
        if (!tick_inside(&p->y, i)) {
            continue;
        }
        double py = map_y(p, tick_value(&p->y, i));
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_move_to(cr, p->left, py);
        cairo_line_to(cr, p->left + p->width, py);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_move_to(cr, p->left - 0.4 * font_size, py);
        cairo_line_to(cr, p->left, py);
        cairo_stroke(cr);
        tick_label(&p->y, i, label, sizeof label);
        cairo_move_to(cr, p->left - 0.6 * font_size - text_width(cr, label), py + 0.35 * font_size);
        show_text(cr, label);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_rectangle(cr, p->left, p->top, p->width, p->height);
    cairo_stroke(cr);
}

/* Dashes for the colours' second and later rounds through the palette. */
static void set_series_style(cairo_t *cr, int index, double line_width)
{
    double rgb[3];
    chart_series_colour(index, rgb);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, line_width);
    int round = index / PALETTE_SIZE;
    if (round == 0) {
        cairo_set_dash(cr, NULL, 0, 0.0);
    } else {
        double dashes[2] = {3.0 * round * line_width, 2.0 * line_width};
        cairo_set_dash(cr, dashes, 2, 0.0);
    }
}

static void dot(cairo_t *cr, double x, double y, double radius)
{
    cairo_new_sub_path(cr);
    cairo_arc(cr, x, y, radius, 0.0, 2.0 * PI);
    cairo_fill(cr);
}

/* A polyline through the series' finite points, broken at the others; a
 * point alone between two breaks gets a dot so that it shows. */
static void draw_series(cairo_t *cr, const plot_area *p, const chart_series *series, int index, double line_width)
{
    set_series_style(cr, index, line_width);
    size_t run = 0; /* finite points in the present piece of line */
    double last_x = 0.0, last_y = 0.0;
    for (size_t i = 0; i <= series->count; ++i) {
        bool finite = i < series->count && isfinite(series->x[i]) && isfinite(series->y[i]);
        if (!finite) {
            if (run == 1) {
                cairo_new_path(cr);
                dot(cr, last_x, last_y, 1.5 * line_width);
            } else if (run > 1) {
                cairo_stroke(cr);
            }
            run = 0;
            continue;
        }
        last_x = map_x(p, series->x[i]);
        last_y = map_y(p, series->y[i]);
        if (run == 0) {
            cairo_move_to(cr, last_x, last_y);
        } else {
            cairo_line_to(cr, last_x, last_y);
        }
        ++run;
    }
    cairo_new_path(cr);
    if (series->marker_radius > 0.0) {
        for (size_t i = 0; i < series->count; ++i) {
            if (isfinite(series->x[i]) && isfinite(series->y[i])) {
                dot(cr, map_x(p, series->x[i]), map_y(p, series->y[i]), series->marker_radius);
            }
        }
    }
    /* Marks are rings, told apart from the line's filled dots. */
    double mark_radius = series->marker_radius > 0.0 ? series->marker_radius : 3.0;
    cairo_set_dash(cr, NULL, 0, 0.0);
    cairo_set_line_width(cr, fmax(1.0, 0.3 * mark_radius));
    for (size_t i = 0; i < series->mark_count; ++i) {
        if (isfinite(series->mark_x[i]) && isfinite(series->mark_y[i])) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, map_x(p, series->mark_x[i]), map_y(p, series->mark_y[i]), mark_radius, 0.0, 2.0 * PI);
            cairo_stroke(cr);
        }
    }
}

static void draw_legend(cairo_t *cr, const chart *chart, double left, double top, double bottom, double font_size)
{
    double row = 1.4 * font_size;
    double sample = 1.8 * font_size;
    double y = top + 0.5 * row;
    char text[LEGEND_MAX_CHARS + 8];
    int shown = 0, entries = 0;
    for (int s = 0; s < chart->series_count; ++s) {
        entries += has_legend_entry(&chart->series[s]);
    }
    for (int s = 0; s < chart->series_count; ++s) {
        if (!has_legend_entry(&chart->series[s])) {
            continue;
        }
        if (y + 1.5 * row > bottom && shown + 1 < entries) {
            cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
            snprintf(text, sizeof text, "(%d more)", entries - shown);
            cairo_move_to(cr, left, y + 0.35 * font_size);
            show_text(cr, text);
            return;
        }
        set_series_style(cr, s, 2.0);
        cairo_move_to(cr, left, y);
        cairo_line_to(cr, left + sample, y);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0.0);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        legend_text(chart->series[s].label, text, sizeof text);
        cairo_move_to(cr, left + sample + 0.5 * font_size, y + 0.35 * font_size);
        show_text(cr, text);
        y += row;
        ++shown;
    }
}

/* The widest tick label of an axis. */
static double widest_label(cairo_t *cr, const axis *a)
{
    char label[64];
    double widest = 0.0;
    for (int i = 0; i < tick_count(a); ++i) {
        tick_label(a, i, label, sizeof label);
        widest = fmax(widest, text_width(cr, label));
    }
    return widest;
}

static double legend_width(cairo_t *cr, const chart *chart, double font_size)
{
    char text[LEGEND_MAX_CHARS + 8];
    double widest = 0.0;
    for (int s = 0; s < chart->series_count; ++s) {
        if (has_legend_entry(&chart->series[s])) {
            legend_text(chart->series[s].label, text, sizeof text);
            widest = fmax(widest, text_width(cr, text));
        }
    }
    return widest > 0.0 ? widest + 2.3 * font_size : 0.0;
}

bool chart_draw(const chart *chart, cairo_t *cr, double x, double y, double width, double height, char *error,
                size_t error_size)
{
    if (!check_chart(chart, "chart_draw", error, error_size)) {
        return false;
    }
    if (cr == NULL) {
        return fail(error, error_size, "chart_draw: cr is NULL");
    }
    if (!(isfinite(x) && isfinite(y) && isfinite(width) && isfinite(height) && width > 0.0 && height > 0.0)) {
        return fail(error, error_size, "chart_draw: the rectangle (%g, %g, %g, %g) needs finite values, width > 0", x,
                    y, width, height);
    }
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        return fail(error, error_size, "chart_draw: cr is in error: %s", cairo_status_to_string(cairo_status(cr)));
    }
    cairo_save(cr);
    cairo_rectangle(cr, x, y, width, height);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);

    const double font_size = fmin(fmax(fmin(width, height) / 36.0, 7.0), 15.0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, font_size);
    const double pad = 0.8 * font_size;

    plot_area p;
    /* Tick density: one label per ~7 font sizes across, ~3 up. */
    fit_axis(chart, true, &chart->x_range, chart->x_scale, (int)fmax(2.0, fmin(10.0, width / (7.0 * font_size))), &p.x);
    fit_axis(chart, false, &chart->y_range, chart->y_scale, (int)fmax(2.0, fmin(10.0, height / (3.5 * font_size))),
             &p.y);
    bool has_title = chart->title != NULL && chart->title[0] != '\0';
    bool has_x_label = chart->x_label != NULL && chart->x_label[0] != '\0';
    bool has_y_label = chart->y_label != NULL && chart->y_label[0] != '\0';
    double legend = fmin(legend_width(cr, chart, font_size), 0.4 * width);
    p.left = x + pad + (has_y_label ? 1.5 * font_size : 0.0) + widest_label(cr, &p.y) + 0.6 * font_size;
    p.top = y + pad + (has_title ? 1.6 * font_size : 0.5 * font_size);
    double right = x + width - pad - (legend > 0.0 ? legend + pad : 0.5 * font_size);
    double bottom = y + height - pad - 1.6 * font_size - (has_x_label ? 1.5 * font_size : 0.0);
    p.width = fmax(right - p.left, 1.0);
    p.height = fmax(bottom - p.top, 1.0);

    draw_grid_and_ticks(cr, &p, font_size);
    if (has_title) {
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
        cairo_set_font_size(cr, 1.15 * font_size);
        cairo_move_to(cr, fmax(x + pad, p.left + 0.5 * p.width - 0.5 * text_width(cr, chart->title)),
                      y + pad + 1.1 * font_size);
        show_text(cr, chart->title);
        cairo_set_font_size(cr, font_size);
    }
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    if (has_x_label) {
        cairo_move_to(cr, p.left + 0.5 * p.width - 0.5 * text_width(cr, chart->x_label), y + height - pad);
        show_text(cr, chart->x_label);
    }
    if (has_y_label) {
        cairo_save(cr);
        cairo_move_to(cr, x + pad + font_size, p.top + 0.5 * p.height + 0.5 * text_width(cr, chart->y_label));
        cairo_rotate(cr, -0.5 * PI);
        show_text(cr, chart->y_label);
        cairo_restore(cr);
    }

    cairo_save(cr);
    cairo_rectangle(cr, p.left, p.top, p.width, p.height);
    cairo_clip(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    double line_width = fmax(1.0, font_size / 7.0);
    for (int s = 0; s < chart->series_count; ++s) {
        draw_series(cr, &p, &chart->series[s], s, line_width);
    }
    cairo_restore(cr);
    if (legend > 0.0) {
        draw_legend(cr, chart, right + pad, p.top, p.top + p.height, font_size);
    }
    cairo_restore(cr);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        return fail(error, error_size, "chart_draw: cairo failed: %s", cairo_status_to_string(cairo_status(cr)));
    }
    return true;
}

bool chart_figure_draw(const chart_figure *figure, cairo_t *cr, char *error, size_t error_size)
{
    if (figure == NULL || cr == NULL) {
        return fail(error, error_size, "chart_figure_draw: figure and cr must not be NULL");
    }
    if (figure->chart_count < 1 || figure->charts == NULL) {
        return fail(error, error_size, "chart_figure_draw: figure->chart_count %d, expected >= 1 charts",
                    figure->chart_count);
    }
    if (figure->columns < 1) {
        return fail(error, error_size, "chart_figure_draw: figure->columns %d, expected >= 1", figure->columns);
    }
    if (figure->width < 1 || figure->width > CHART_MAX_FIGURE_SIZE || figure->height < 1 ||
        figure->height > CHART_MAX_FIGURE_SIZE) {
        return fail(error, error_size, "chart_figure_draw: figure size %d x %d, expected 1 .. %d each", figure->width,
                    figure->height, CHART_MAX_FIGURE_SIZE);
    }
    int columns = figure->columns < figure->chart_count ? figure->columns : figure->chart_count;
    int rows = (figure->chart_count + columns - 1) / columns;
    double cell_width = (double)figure->width / columns;
    double cell_height = (double)figure->height / rows;
    cairo_save(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    cairo_restore(cr);
    for (int k = 0; k < figure->chart_count; ++k) {
        if (!chart_draw(&figure->charts[k], cr, (k % columns) * cell_width, (k / columns) * cell_height, cell_width,
                        cell_height, error, error_size)) {
            return false;
        }
    }
    return true;
}
