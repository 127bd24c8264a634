/* SPDX-License-Identifier: MIT */
/* Writes small PNG files with libpng for the tests of profile images
 * (tests/test_motor_pool.c, tests/test_profile_image.c), sample by
 * sample, so a test knows every pixel it reads back. Static inline
 * helpers only, as tests/test_support.h.
 */
#ifndef TESTS_PNG_WRITER_H
#define TESTS_PNG_WRITER_H

#include <criterion/criterion.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>

/* An image to write: width × height pixels of `channels` samples each, in
 * rows, each sample 0 .. 2^depth − 1. colour_type is libpng's
 * (PNG_COLOR_TYPE_RGB: 3 samples, _RGB_ALPHA: 4, _GRAY: 1,
 * _GRAY_ALPHA: 2, _PALETTE: 1, an index into `palette`). */
typedef struct test_png {
    int width, height;
    int colour_type;
    int depth; /* 8 or 16 (1, 2, 4 or 8 for a palette) */
    const unsigned *samples;
    const png_color *palette; /* _PALETTE only */
    int palette_size;
    bool interlaced; /* Adam7 */
} test_png;

static inline int test_png_channels(int colour_type)
{
    switch (colour_type) {
    case PNG_COLOR_TYPE_RGB:
        return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA:
        return 4;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
        return 2;
    default:
        return 1;
    }
}

/* Writes `image` to `path`; the test stops if libpng fails. */
static inline void write_test_png(const char *path, const test_png *image)
{
    FILE *file = fopen(path, "wb");
    cr_assert_not_null(file, "cannot create %s", path);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png != NULL ? png_create_info_struct(png) : NULL;
    cr_assert_not_null(info, "libpng: out of memory");
    if (setjmp(png_jmpbuf(png)) != 0) {
        cr_assert_fail("libpng failed writing %s", path);
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, (png_uint_32)image->width, (png_uint_32)image->height, image->depth, image->colour_type,
                 image->interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (image->colour_type == PNG_COLOR_TYPE_PALETTE) {
        png_set_PLTE(png, info, image->palette, image->palette_size);
    }
    png_write_info(png, info);
    if (image->depth < 8) {
        png_set_packing(png); /* one index a byte in, packed in the file */
    }
    const int channels = test_png_channels(image->colour_type);
    const size_t bytes_per_sample = image->depth == 16 ? 2 : 1;
    const size_t row_size = (size_t)image->width * (size_t)channels * bytes_per_sample;
    png_byte *rows = malloc(row_size * (size_t)image->height);
    png_bytep *row_pointers = malloc((size_t)image->height * sizeof *row_pointers);
    cr_assert(rows != NULL && row_pointers != NULL);
    for (int y = 0; y < image->height; ++y) {
        row_pointers[y] = rows + (size_t)y * row_size;
        for (int k = 0; k < image->width * channels; ++k) {
            const unsigned value = image->samples[(size_t)y * (size_t)image->width * (size_t)channels + (size_t)k];
            if (image->depth == 16) { /* big-endian, as PNG stores it */
                row_pointers[y][2 * k] = (png_byte)(value >> 8);
                row_pointers[y][2 * k + 1] = (png_byte)(value & 0xffu);
            } else {
                row_pointers[y][k] = (png_byte)value;
            }
        }
    }
    png_write_image(png, row_pointers);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row_pointers);
    free(rows);
    cr_assert_eq(fclose(file), 0, "cannot write %s", path);
}

#endif
