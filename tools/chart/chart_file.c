/* SPDX-License-Identifier: MIT */
/* A figure written as a PNG or an SVG file through an atomic_file: Cairo
 * writes into memory, the figure's provenance (io/provenance.h) is added,
 * and the whole goes to the temporary file's stream, which is renamed into
 * place only when Cairo and the stream both succeeded.
 *
 * Provenance: Cairo has no API for a PNG's text chunks or an SVG's
 * metadata, so both are added to its output. A PNG gets two iTXt chunks
 * (PNG 1.2 §4.2.3.3; UTF-8, which a command line may hold) right after
 * IHDR: "Software" = "sinew VERSION" and "Comment" = the command line. An
 * SVG gets a <metadata> element, "sinew VERSION: COMMAND LINE", first in
 * its <svg> element. Neither changes what is drawn, and neither holds a
 * date, so a rerun writes the same bytes.
 */
#define _POSIX_C_SOURCE 200809L /* open_memstream */

#include <cairo-svg.h>
#include <ctype.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "chart/chart.h"
#include "io/atomic_file.h"
#include "io/provenance.h"

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

/* Cairo's write callback: everything to a stream. */
static cairo_status_t write_to_stream(void *closure, const unsigned char *data, unsigned int length)
{
    FILE *stream = closure;
    return fwrite(data, 1, length, stream) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

static void put_u32(unsigned char *at, uint32_t value)
{
    at[0] = (unsigned char)(value >> 24);
    at[1] = (unsigned char)(value >> 16);
    at[2] = (unsigned char)(value >> 8);
    at[3] = (unsigned char)value;
}

/* Longest text of a chunk: the command line as provenance_command_text
 * gives it to render(). */
#define PNG_TEXT_MAX 2048

/* Writes an iTXt chunk: `keyword` (at most 79 bytes), no compression, no
 * language, `text` (truncated to PNG_TEXT_MAX bytes). */
static void write_png_text(FILE *stream, const char *keyword, const char *text)
{
    /* type, keyword NUL, compression flag and method, language NUL,
     * translated keyword NUL, text */
    unsigned char chunk[4 + 80 + 4 + PNG_TEXT_MAX];
    size_t keyword_length = strnlen(keyword, 79), text_length = strnlen(text, PNG_TEXT_MAX);
    memcpy(chunk, "iTXt", 4);
    memcpy(chunk + 4, keyword, keyword_length);
    memset(chunk + 4 + keyword_length, 0, 5);
    memcpy(chunk + 4 + keyword_length + 5, text, text_length);
    size_t length = 4 + keyword_length + 5 + text_length;
    unsigned char word[4];
    put_u32(word, (uint32_t)(length - 4));
    fwrite(word, 1, 4, stream);
    fwrite(chunk, 1, length, stream);
    /* The chunk's CRC (PNG 1.2 §3.4) covers its type and data: zlib's
     * crc32 is that CRC (ISO 3309), and Cairo already links zlib. */
    put_u32(word, (uint32_t)crc32(0L, chunk, (uInt)length));
    fwrite(word, 1, 4, stream);
}

/* Size of a PNG's signature and IHDR chunk, which Cairo writes first. */
#define PNG_HEAD 33

static bool write_png(FILE *stream, const unsigned char *png, size_t length, const char *command)
{
    if (length < PNG_HEAD || memcmp(png + 12, "IHDR", 4) != 0) {
        return false;
    }
    fwrite(png, 1, PNG_HEAD, stream);
    write_png_text(stream, "Software", provenance_creator());
    if (command[0] != '\0') {
        write_png_text(stream, "Comment", command);
    }
    fwrite(png + PNG_HEAD, 1, length - PNG_HEAD, stream);
    return true;
}

static bool write_svg(FILE *stream, const char *svg, size_t length, const char *command)
{
    const char *root = strstr(svg, "<svg");
    const char *end = root != NULL ? strchr(root, '>') : NULL;
    if (end == NULL) {
        return false;
    }
    size_t head = (size_t)(end + 1 - svg);
    fwrite(svg, 1, head, stream);
    fprintf(stream, "\n<metadata>%s%s", provenance_creator(), command[0] != '\0' ? ": " : "");
    for (const char *c = command; *c != '\0'; ++c) {
        /* The command line as XML text. */
        switch (*c) {
        case '&':
            fputs("&amp;", stream);
            break;
        case '<':
            fputs("&lt;", stream);
            break;
        case '>':
            fputs("&gt;", stream);
            break;
        default:
            fputc(*c, stream);
        }
    }
    fputs("</metadata>", stream);
    fwrite(svg + head, 1, length - head, stream);
    return true;
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

/* Draws the figure on a fresh surface of `kind` and writes it, with its
 * provenance, to `file`. */
static bool render(const chart_figure *figure, file_kind kind, atomic_file *file, char *error, size_t error_size)
{
    char *bytes = NULL;
    size_t length = 0;
    FILE *memory = open_memstream(&bytes, &length);
    if (memory == NULL) {
        return fail(error, error_size, "cannot write %s: out of memory", file->temp_path);
    }
    cairo_surface_t *surface =
        kind == FILE_PNG ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, figure->width, figure->height)
                         : cairo_svg_surface_create_for_stream(write_to_stream, memory, figure->width, figure->height);
    cairo_t *cr = cairo_create(surface);
    bool ok = chart_figure_draw(figure, cr, error, error_size);
    cairo_destroy(cr);
    if (ok && kind == FILE_PNG) {
        cairo_status_t status = cairo_surface_write_to_png_stream(surface, write_to_stream, memory);
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
    if (fclose(memory) != 0 && ok) {
        ok = fail(error, error_size, "cannot write %s: out of memory", file->temp_path);
    }
    if (ok) {
        char command[PNG_TEXT_MAX];
        provenance_command_text(command, sizeof command);
        bool framed = kind == FILE_PNG ? write_png(file->stream, (const unsigned char *)bytes, length, command)
                                       : write_svg(file->stream, bytes, length, command);
        if (!framed) {
            ok = fail(error, error_size, "cannot write %s: Cairo wrote no %s header", file->temp_path,
                      kind == FILE_PNG ? "PNG" : "SVG");
        } else if (ferror(file->stream)) {
            ok = fail(error, error_size, "cannot write %s", file->temp_path);
        }
    }
    free(bytes);
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

bool chart_write_png_or_say(const chart_figure *figure, const char *path)
{
    char error[CHART_ERROR_SIZE];
    const bool written = chart_write_png(figure, path, error, sizeof error);
    if (!written) {
        fprintf(stderr, "sinew: %s\n", error);
    }
    return written;
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
