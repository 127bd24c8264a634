/* SPDX-License-Identifier: MIT */
/* The motor pool: strengths, their running sums, and the recruited count
 * (motor_pool.h). cumulative[n] = s_0 + … + s_{n-1}, so cumulative[0] = 0
 * and e(n) = cumulative[n]/cumulative[count] needs no special case for
 * n = 0. */
#include <cairo.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arguments.h"
#include "csv_reader.h"
#include "mu/motor_pool.h"

struct mu_motor_pool {
    int count;
    int recruited;
    double *strengths;  /* count */
    double *cumulative; /* count + 1 */
};

static rb_status check_strengths(const char *f, const double *strengths, int count)
{
    if (strengths == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: strengths is NULL", f);
    }
    if (count < 1 || count > MU_MAX_MOTOR_NEURONS) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: count is %d, expected 1 to %d neurons", f, count,
                               MU_MAX_MOTOR_NEURONS);
    }
    double total = 0.0;
    for (int i = 0; i < count; ++i) {
        if (!(strengths[i] >= 0.0 && isfinite(strengths[i]))) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: strengths[%d] is %g, expected a finite number >= 0", f,
                                   i, strengths[i]);
        }
        total += strengths[i];
    }
    if (!(total > 0.0 && isfinite(total))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: the strengths sum to %g, expected a finite sum > 0 (a pool of no strength)", f,
                               total);
    }
    return RB_OK;
}

static rb_status create_pool(const char *f, const double *strengths, int count, mu_motor_pool **out)
{
    rb_status status = check_strengths(f, strengths, count);
    if (status != RB_OK) {
        return status;
    }
    mu_motor_pool *pool = calloc(1, sizeof *pool);
    if (pool != NULL) {
        pool->strengths = malloc((size_t)count * sizeof *pool->strengths);
        pool->cumulative = malloc((size_t)(count + 1) * sizeof *pool->cumulative);
    }
    if (pool == NULL || pool->strengths == NULL || pool->cumulative == NULL) {
        mu_motor_pool_destroy(pool);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory for %d neurons", f, count);
    }
    pool->count = count;
    pool->cumulative[0] = 0.0;
    for (int i = 0; i < count; ++i) {
        pool->strengths[i] = strengths[i];
        pool->cumulative[i + 1] = pool->cumulative[i] + strengths[i];
    }
    *out = pool;
    return RB_OK;
}

rb_status mu_motor_pool_create(const double *strengths, int count, mu_motor_pool **out)
{
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_motor_pool_create: out is NULL");
    }
    *out = NULL;
    return create_pool("mu_motor_pool_create", strengths, count, out);
}

rb_status mu_motor_pool_create_exponential(int count, double weakest, double strongest, mu_motor_pool **out)
{
    const char *f = "mu_motor_pool_create_exponential";
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: out is NULL", f);
    }
    *out = NULL;
    if (count < 1 || count > MU_MAX_MOTOR_NEURONS) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: count is %d, expected 1 to %d neurons", f, count,
                               MU_MAX_MOTOR_NEURONS);
    }
    if (!(weakest > 0.0 && strongest >= weakest && isfinite(strongest))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: weakest %g and strongest %g, expected 0 < weakest <= strongest, finite", f, weakest,
                               strongest);
    }
    double *strengths = malloc((size_t)count * sizeof *strengths);
    if (strengths == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory for %d neurons", f, count);
    }
    /* s_i = weakest·r^(i/(count-1)) with r = strongest/weakest: equal
     * ratios between neighbours, from weakest exactly to strongest. */
    const double ratio = strongest / weakest;
    for (int i = 0; i < count; ++i) {
        const double t = count > 1 ? (double)i / (double)(count - 1) : 0.0;
        strengths[i] = weakest * pow(ratio, t);
    }
    rb_status status = create_pool(f, strengths, count, out);
    free(strengths);
    return status;
}

/* 255 − blue of one pixel of a Cairo image surface. The pixel is a native
 * 32-bit word, blue in its low byte; ARGB32 stores colour premultiplied by
 * alpha, undone here (a transparent pixel is white, strength 0). */
static double pixel_strength(uint32_t pixel, cairo_format_t format)
{
    double blue = (double)(pixel & 0xffu);
    if (format == CAIRO_FORMAT_ARGB32) {
        const double alpha = (double)(pixel >> 24);
        blue = alpha > 0.0 ? fmin(255.0, blue * 255.0 / alpha) : 255.0;
    }
    return 255.0 - blue;
}

/* Whether the file opens and starts with the PNG signature (PNG spec
 * §5.2). Checked before Cairo reads it because Cairo 1.16 reports a file
 * that is not a PNG as "out of memory". errno is 0 when the file opened. */
static bool has_png_signature(const char *path)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    errno = 0;
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        return false;
    }
    unsigned char head[8];
    const bool png = fread(head, 1, sizeof head, file) == sizeof head && memcmp(head, signature, sizeof head) == 0;
    fclose(file);
    errno = 0;
    return png;
}

rb_status mu_motor_pool_load_png(const char *path, mu_motor_pool **out)
{
    const char *f = "mu_motor_pool_load_png";
    if (path == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: path and out must not be NULL", f);
    }
    *out = NULL;
    if (!has_png_signature(path)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: cannot read: %s, expected a PNG profile image", f,
                               path, errno != 0 ? strerror(errno) : "not a PNG file");
    }
    cairo_surface_t *image = cairo_image_surface_create_from_png(path);
    rb_status status = RB_OK;
    const cairo_status_t read = cairo_surface_status(image);
    if (read != CAIRO_STATUS_SUCCESS) {
        status = rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: cannot read: %s, expected a PNG profile image", f,
                                 path, cairo_status_to_string(read));
        cairo_surface_destroy(image);
        return status;
    }
    const int width = cairo_image_surface_get_width(image);
    const int height = cairo_image_surface_get_height(image);
    const cairo_format_t format = cairo_image_surface_get_format(image);
    if (height != 1) {
        status = rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                 "%s: %s: the image is %d × %d pixels, expected 1 pixel high (one neuron per pixel)", f,
                                 path, width, height);
    } else if (width > MU_MAX_MOTOR_NEURONS) {
        status = rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: the image is %d pixels wide, expected at most %d", f,
                                 path, width, MU_MAX_MOTOR_NEURONS);
    } else if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24) {
        status = rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                 "%s: %s: Cairo read the image in pixel format %d, expected "
                                 "ARGB32 or RGB24",
                                 f, path, (int)format);
    }
    double *strengths = status == RB_OK ? malloc((size_t)width * sizeof *strengths) : NULL;
    if (status == RB_OK && strengths == NULL) {
        status = rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: %s: out of memory for %d neurons", f, path, width);
    }
    if (status == RB_OK) {
        cairo_surface_flush(image);
        const unsigned char *row = cairo_image_surface_get_data(image);
        for (int x = 0; x < width; ++x) {
            uint32_t pixel;
            memcpy(&pixel, row + 4 * x, sizeof pixel);
            strengths[x] = pixel_strength(pixel, format);
        }
        status = create_pool(f, strengths, width, out);
        if (status == RB_ERR_INVALID_ARGUMENT) {
            status = rb_report_error(status,
                                     "%s: %s: every pixel is white (255 − blue is 0), expected a profile "
                                     "with some strength",
                                     f, path);
        }
    }
    free(strengths);
    cairo_surface_destroy(image);
    return status;
}

/* Appends one value to a growing array. */
static bool push_strength(double **values, int *count, int *capacity, double value)
{
    if (*count == *capacity) {
        const int grown = *capacity > 0 ? 2 * *capacity : 64;
        double *more = realloc(*values, (size_t)grown * sizeof *more);
        if (more == NULL) {
            return false;
        }
        *values = more;
        *capacity = grown;
    }
    (*values)[(*count)++] = value;
    return true;
}

/* Every field of every record of the file as a strength, appended. */
static rb_status read_strengths(const char *f, mu_csv_reader *csv, double **values, int *count)
{
    int capacity = 0;
    mu_csv_result result;
    while ((result = mu_csv_reader_next(csv)) == MU_CSV_RECORD) {
        for (int k = 0; k < csv->field_count; ++k) {
            double value = 0.0;
            if (mu_csv_number(csv->fields[k], &value) != MU_CSV_NUMBER || !(value >= 0.0 && isfinite(value))) {
                return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                       "%s: %s:%ld: \"%s\" is not a strength, expected a finite number >= 0", f,
                                       csv->path, csv->line_number, csv->fields[k]);
            }
            if (*count == MU_MAX_MOTOR_NEURONS) {
                return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s:%ld: more than %d strengths", f, csv->path,
                                       csv->line_number, MU_MAX_MOTOR_NEURONS);
            }
            if (!push_strength(values, count, &capacity, value)) {
                return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: %s: out of memory", f, csv->path);
            }
        }
    }
    if (result == MU_CSV_ERROR) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s", f, csv->error);
    }
    return RB_OK;
}

rb_status mu_motor_pool_load_csv(const char *path, mu_motor_pool **out)
{
    const char *f = "mu_motor_pool_load_csv";
    if (path == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: path and out must not be NULL", f);
    }
    *out = NULL;
    FILE *file = fopen(path, "r");
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: cannot open: %s, expected a CSV of strengths", f, path,
                               strerror(errno));
    }
    /* The profile's own format (mu/motor_pool.h): numbers separated by
     * commas or blanks, '#' comments. */
    mu_csv_reader csv;
    mu_csv_reader_init(&csv, path, file, MU_CSV_SPACE_SEPARATES | MU_CSV_COMMENTS);
    double *values = NULL;
    int count = 0;
    rb_status status = read_strengths(f, &csv, &values, &count);
    mu_csv_reader_free(&csv);
    fclose(file);
    if (status == RB_OK && count == 0) {
        status =
            rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: no strengths, expected at least one number", f, path);
    }
    if (status == RB_OK) {
        status = create_pool(f, values, count, out);
        if (status == RB_ERR_INVALID_ARGUMENT) {
            status = rb_report_error(status, "%s: %s: the strengths sum to 0, expected a profile with some strength", f,
                                     path);
        }
    }
    free(values);
    return status;
}

void mu_motor_pool_destroy(mu_motor_pool *pool)
{
    if (pool != NULL) {
        free(pool->strengths);
        free(pool->cumulative);
        free(pool);
    }
}

int mu_motor_pool_neuron_count(const mu_motor_pool *pool)
{
    return mu_refuse_null("mu_motor_pool_neuron_count", "pool", pool) ? 0 : pool->count;
}

double mu_motor_pool_strength(const mu_motor_pool *pool, int index)
{
    const char *f = "mu_motor_pool_strength";
    if (mu_refuse_null(f, "pool", pool) || mu_refuse_index(f, "index", index, pool->count)) {
        return NAN;
    }
    return pool->strengths[index];
}

double mu_motor_pool_total_strength(const mu_motor_pool *pool)
{
    return mu_refuse_null("mu_motor_pool_total_strength", "pool", pool) ? NAN : pool->cumulative[pool->count];
}

static int clamp_count(const mu_motor_pool *pool, long n) { return n < 0 ? 0 : n > pool->count ? pool->count : (int)n; }

rb_status mu_motor_pool_recruit(mu_motor_pool *pool, int n)
{
    const char *f = "mu_motor_pool_recruit";
    if (mu_refuse_null(f, "pool", pool) || mu_refuse_index(f, "n", n, pool->count + 1)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    pool->recruited = n;
    return RB_OK;
}

rb_status mu_motor_pool_recruit_more(mu_motor_pool *pool, int delta)
{
    if (pool == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_motor_pool_recruit_more: pool is NULL");
    }
    pool->recruited = clamp_count(pool, (long)pool->recruited + (long)delta);
    return RB_OK;
}

int mu_motor_pool_recruited(const mu_motor_pool *pool)
{
    return mu_refuse_null("mu_motor_pool_recruited", "pool", pool) ? -1 : pool->recruited;
}

double mu_motor_pool_exertion_at(const mu_motor_pool *pool, int n)
{
    if (mu_refuse_null("mu_motor_pool_exertion_at", "pool", pool)) {
        return NAN;
    }
    return pool->cumulative[clamp_count(pool, n)] / pool->cumulative[pool->count];
}

double mu_motor_pool_exertion(const mu_motor_pool *pool)
{
    return mu_refuse_null("mu_motor_pool_exertion", "pool", pool) ? NAN
                                                                  : mu_motor_pool_exertion_at(pool, pool->recruited);
}

rb_status mu_motor_pool_drive_muscle(const mu_motor_pool *pool, mu_muscle *muscle)
{
    if (pool == NULL || muscle == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_motor_pool_drive_muscle: pool and muscle must not be NULL");
    }
    return mu_muscle_set_activation(muscle, mu_motor_pool_exertion(pool));
}

rb_status mu_motor_pool_drive_torque(const mu_motor_pool *pool, mu_torque_actuator *actuator)
{
    if (pool == NULL || actuator == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_motor_pool_drive_torque: pool and actuator must not be NULL");
    }
    return mu_torque_actuator_set_exertion(actuator, mu_motor_pool_exertion(pool));
}
