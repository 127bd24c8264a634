/* SPDX-License-Identifier: MIT */
/* A figure written as a PNG or an SVG file through an atomic_file: Cairo
 * writes into the temporary file's stream, which is renamed into place
 * only when Cairo and the stream both succeeded. */
#include <cairo-svg.h>
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "chart/chart.h"
#include "io/atomic_file.h"

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

/* Cairo's write callback: everything to the temporary file's stream. */
static cairo_status_t write_to_stream(void *closure, const unsigned char *data, unsigned int length)
{
    FILE *stream = closure;
    return fwrite(data, 1, length, stream) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

typedef enum file_kind { FILE_PNG, FILE_SVG } file_kind;

static bool check_figure(const chart_figure *figure, const char *path, const char *function, char *error,
                         size_t error_size)
{
    if (figure == NULL || path == NULL || path[0] == '\0') {
        return fail(error, error_size, "%s: figure and path must be given", function);
    }
    if (figure->width < 1 || figure->width > CHART_MAX_FIGURE_SIZE || figure->height < 1 ||
        figure->height > CHART_MAX_FIGURE_SIZE) {
        return fail(error, error_size, "%s: figure size %d x %d, expected 1 .. %d each", function, figure->width,
                    figure->height, CHART_MAX_FIGURE_SIZE);
    }
    return true;
}

/* Draws the figure on a fresh surface of `kind` that writes to `file`. */
static bool render(const chart_figure *figure, file_kind kind, atomic_file *file, char *error, size_t error_size)
{
    cairo_surface_t *surface =
        kind == FILE_PNG
            ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, figure->width, figure->height)
            : cairo_svg_surface_create_for_stream(write_to_stream, file->stream, figure->width, figure->height);
    cairo_t *cr = cairo_create(surface);
    bool ok = chart_figure_draw(figure, cr, error, error_size);
    cairo_destroy(cr);
    if (ok && kind == FILE_PNG) {
        cairo_status_t status = cairo_surface_write_to_png_stream(surface, write_to_stream, file->stream);
        if (status != CAIRO_STATUS_SUCCESS) {
            ok = fail(error, error_size, "cannot write %s: %s", file->temp_path, cairo_status_to_string(status));
        }
    }
    /* An SVG surface writes its last bytes when finished. */
    cairo_surface_finish(surface);
    cairo_status_t status = cairo_surface_status(surface);
    if (ok && status != CAIRO_STATUS_SUCCESS) {
        ok = fail(error, error_size, "cannot write %s: %s", file->temp_path, cairo_status_to_string(status));
    }
    cairo_surface_destroy(surface);
    return ok;
}

static bool write_figure(const chart_figure *figure, const char *path, file_kind kind, const char *function,
                         char *error, size_t error_size)
{
    if (!check_figure(figure, path, function, error, error_size)) {
        return false;
    }
    atomic_file file = {.stream = NULL};
    char file_error[ATOMIC_FILE_ERROR_SIZE];
    if (!atomic_file_open(&file, path, file_error, sizeof file_error)) {
        return fail(error, error_size, "%s", file_error);
    }
    if (!render(figure, kind, &file, error, error_size)) {
        atomic_file_abandon(&file);
        return false;
    }
    if (!atomic_file_commit(&file, file_error, sizeof file_error)) {
        return fail(error, error_size, "%s", file_error);
    }
    return true;
}

bool chart_write_png(const chart_figure *figure, const char *path, char *error, size_t error_size)
{
    return write_figure(figure, path, FILE_PNG, "chart_write_png", error, error_size);
}

bool chart_write_svg(const chart_figure *figure, const char *path, char *error, size_t error_size)
{
    return write_figure(figure, path, FILE_SVG, "chart_write_svg", error, error_size);
}

static bool has_extension(const char *path, const char *extension)
{
    size_t length = strlen(path), extension_length = strlen(extension);
    if (length <= extension_length) {
        return false;
    }
    const char *end = path + length - extension_length;
    for (size_t i = 0; i < extension_length; ++i) {
        if (tolower((unsigned char)end[i]) != extension[i]) {
            return false;
        }
    }
    return true;
}

bool chart_write_file(const chart_figure *figure, const char *path, char *error, size_t error_size)
{
    if (path != NULL && has_extension(path, ".png")) {
        return chart_write_png(figure, path, error, error_size);
    }
    if (path != NULL && has_extension(path, ".svg")) {
        return chart_write_svg(figure, path, error, error_size);
    }
    return fail(error, error_size, "chart_write_file: %s: expected a file name ending in .png or .svg",
                path != NULL ? path : "(NULL path)");
}
