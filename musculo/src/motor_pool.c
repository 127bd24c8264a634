/* SPDX-License-Identifier: MIT */
/* The motor pool: strengths, their running sums, and the recruited count
 * (motor_pool.h). cumulative[n] = s_0 + … + s_{n-1}, so cumulative[0] = 0
 * and e(n) = cumulative[n]/cumulative[count] needs no special case for
 * n = 0. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arguments.h"
#include "mu/motor_pool.h"
#include "pool_profile.h"

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

/* Reads the profile image (`image`) or CSV at `path` into a new pool. */
static rb_status load_profile(const char *f, const char *path, bool image, mu_motor_pool **out)
{
    if (path == NULL || out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: path and out must not be NULL", f);
    }
    *out = NULL;
    char problem[MU_POOL_PROBLEM_SIZE];
    FILE *file = mu_pool_profile_open(path, problem, sizeof problem);
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: %s, expected %s", f, path, problem,
                               image ? "a PNG profile image" : "a CSV of strengths");
    }
    double *strengths = NULL;
    int count = 0;
    const bool read = image ? mu_pool_profile_read_png(file, &strengths, &count, problem, sizeof problem)
                            : mu_pool_profile_read_csv(file, path, &strengths, &count, problem, sizeof problem);
    fclose(file);
    if (!read) {
        /* A CSV's problem names the file and line itself. */
        return image ? rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s: %s", f, path, problem)
                     : rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s", f, problem);
    }
    rb_status status = create_pool(f, strengths, count, out);
    free(strengths);
    return status;
}

rb_status mu_motor_pool_load_png(const char *path, mu_motor_pool **out)
{
    return load_profile("mu_motor_pool_load_png", path, true, out);
}

rb_status mu_motor_pool_load_csv(const char *path, mu_motor_pool **out)
{
    return load_profile("mu_motor_pool_load_csv", path, false, out);
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
