/* SPDX-License-Identifier: MIT */
/* A motor pool's profile image read with libpng (pool_profile.h; the
 * rule is McIntyre's, "Simulated Muscles", given in mu/motor_pool.h).
 *
 * libpng turns every PNG into rows of red, green, blue and maybe alpha
 * samples of 8 or 16 bits: a palette image into its colours, a grey one
 * into red = green = blue, a tRNS chunk (a transparent colour) into an
 * alpha channel. A 16-bit sample s stands for s/257 on the 8-bit scale
 * (65535 = 255 · 257), so a 16-bit image gives strengths between the
 * 8-bit steps and the same strength for the same colour. libpng reports
 * a broken file by calling the error function, which jumps back here.
 */
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>

#include "mu/motor_pool.h"
#include "pool_profile.h"

typedef struct png_failure {
    jmp_buf jump;
    char *problem;
    size_t problem_size;
} png_failure;

static void on_error(png_structp png, png_const_charp message)
{
    png_failure *failure = png_get_error_ptr(png);
    snprintf(failure->problem, failure->problem_size, "libpng cannot read it (%s), expected a whole PNG image",
             message);
    longjmp(failure->jump, 1);
}

/* A warning (an unknown chunk, a colour profile libpng ignores) leaves
 * the samples as the file stores them. */
static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

/* Sample `index` of a row of `depth`-bit samples. */
static uint32_t sample(const png_byte *row, int depth, size_t index)
{
    return depth == 16 ? (uint32_t)row[2 * index] << 8 | row[2 * index + 1] : row[index];
}

/* The strengths of a row of `width` pixels of `channels` samples (3: RGB,
 * 4: RGBA); false, with the problem said, at the first pixel the rule
 * refuses. */
static bool row_strengths(const png_byte *row, int width, int channels, int depth, double *strengths, char *problem,
                          size_t problem_size)
{
    const uint32_t full = depth == 16 ? 65535u : 255u;
    double total = 0.0;
    for (int x = 0; x < width; ++x) {
        const size_t at = (size_t)x * (size_t)channels;
        const uint32_t red = sample(row, depth, at), green = sample(row, depth, at + 1),
                       blue = sample(row, depth, at + 2);
        const uint32_t alpha = channels == 4 ? sample(row, depth, at + 3) : full;
        if (alpha != full) {
            snprintf(problem, problem_size,
                     "pixel %d (counted from 0 at the left) has alpha %u of %u, expected an opaque pixel (a "
                     "translucent colour depends on what is behind it)",
                     x, alpha, full);
            return false;
        }
        if (!(red >= green && green == blue)) {
            snprintf(problem, problem_size,
                     "pixel %d (counted from 0 at the left) is red %u, green %u, blue %u (of %u), off the white-to-red "
                     "scale: expected red >= green = blue (white, pink, red, dark red)",
                     x, red, green, blue, full);
            return false;
        }
        /* 255 − blue on the 8-bit scale; exact for 8 and 16 bits. */
        strengths[x] = 255.0 - (double)blue * 255.0 / (double)full;
        total += strengths[x];
    }
    if (!(total > 0.0)) {
        snprintf(problem, problem_size,
                 "every pixel is white (255 − blue is 0), expected a profile with some strength");
        return false;
    }
    return true;
}

/* Reads the header and decodes the one row; false with the problem said.
 * Runs under the caller's setjmp: libpng's errors jump out of it. */
static bool read_row(png_structp png, png_infop info, png_byte *volatile *row, double *volatile *strengths, int *count,
                     char *problem, size_t problem_size)
{
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info);
    const png_uint_32 height = png_get_image_height(png, info);
    if (height != 1) {
        snprintf(problem, problem_size, "the image is %lu × %lu pixels, expected 1 pixel high (one neuron per pixel)",
                 (unsigned long)width, (unsigned long)height);
        return false;
    }
    if (width > MU_MAX_MOTOR_NEURONS) {
        snprintf(problem, problem_size, "the image is %lu pixels wide, expected at most %d (one neuron per pixel)",
                 (unsigned long)width, MU_MAX_MOTOR_NEURONS);
        return false;
    }
    const int colour = png_get_color_type(png, info);
    if (colour == PNG_COLOR_TYPE_PALETTE) {
        png_set_palette_to_rgb(png);
    }
    if (colour == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) {
        png_set_expand_gray_1_2_4_to_8(png);
    }
    if (png_get_valid(png, info, PNG_INFO_tRNS)) {
        png_set_tRNS_to_alpha(png);
    }
    if (colour == PNG_COLOR_TYPE_GRAY || colour == PNG_COLOR_TYPE_GRAY_ALPHA) {
        png_set_gray_to_rgb(png);
    }
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const int channels = png_get_channels(png, info);
    const int depth = png_get_bit_depth(png, info);
    *row = malloc(png_get_rowbytes(png, info));
    *strengths = malloc((size_t)width * sizeof **strengths);
    if (*row == NULL || *strengths == NULL) {
        snprintf(problem, problem_size, "out of memory for %lu neurons", (unsigned long)width);
        return false;
    }
    /* An interlaced (Adam7) row arrives in passes, each filling its pixels. */
    for (int pass = 0; pass < passes; ++pass) {
        png_read_row(png, *row, NULL);
    }
    *count = (int)width;
    return row_strengths(*row, (int)width, channels, depth, *strengths, problem, problem_size);
}

bool mu_pool_profile_read_png(FILE *stream, double **strengths, int *count, char *problem, size_t problem_size)
{
    *strengths = NULL;
    *count = 0;
    /* The signature first (PNG specification §5.2): a file of another
     * kind is named as such rather than by libpng's complaint. */
    png_byte signature[8];
    if (fread(signature, 1, sizeof signature, stream) != sizeof signature ||
        png_sig_cmp(signature, 0, sizeof signature) != 0) {
        snprintf(problem, problem_size, "not a PNG file (no PNG signature), expected a PNG profile image");
        return false;
    }
    png_failure failure = {.problem = problem, .problem_size = problem_size};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure, on_error, on_warning);
    png_infop info = png != NULL ? png_create_info_struct(png) : NULL;
    if (info == NULL) {
        png_destroy_read_struct(&png, NULL, NULL);
        snprintf(problem, problem_size, "out of memory for libpng");
        return false;
    }
    /* Set after setjmp and freed after a jump back: volatile, so their
     * values survive the longjmp (C17 7.13.2.1). */
    png_byte *volatile row = NULL;
    double *volatile values = NULL;
    bool read = false;
    if (setjmp(failure.jump) == 0) {
        png_init_io(png, stream);
        png_set_sig_bytes(png, sizeof signature);
        read = read_row(png, info, &row, &values, count, problem, problem_size);
    }
    png_destroy_read_struct(&png, &info, NULL);
    free(row);
    if (!read) {
        free(values);
        *count = 0;
        return false;
    }
    *strengths = values;
    return true;
}
