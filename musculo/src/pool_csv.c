/* SPDX-License-Identifier: MIT */
/* A motor pool's strengths from a CSV (pool_profile.h): numbers separated
 * by commas, spaces, tabs or line breaks, in recruitment order, '#'
 * starting a comment; read with the layer's CSV reader (csv_reader.h). */
#include <math.h>
#include <stdlib.h>

#include "csv_reader.h"
#include "mu/motor_pool.h"
#include "pool_profile.h"

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

/* Every field of every record as a strength, appended; the sum kept. */
static bool read_fields(mu_csv_reader *csv, double **values, int *count, double *total, char *problem,
                        size_t problem_size)
{
    int capacity = 0;
    mu_csv_result result;
    while ((result = mu_csv_reader_next(csv)) == MU_CSV_RECORD) {
        for (int k = 0; k < csv->field_count; ++k) {
            double value = 0.0;
            if (mu_csv_number(csv->fields[k], &value) != MU_CSV_NUMBER || !(value >= 0.0 && isfinite(value))) {
                snprintf(problem, problem_size, "%s:%ld: \"%s\" is not a strength, expected a finite number >= 0",
                         csv->path, csv->line_number, csv->fields[k]);
                return false;
            }
            if (*count == MU_MAX_MOTOR_NEURONS) {
                snprintf(problem, problem_size, "%s:%ld: more than %d strengths, expected one per neuron", csv->path,
                         csv->line_number, MU_MAX_MOTOR_NEURONS);
                return false;
            }
            if (!push_strength(values, count, &capacity, value)) {
                snprintf(problem, problem_size, "%s: out of memory", csv->path);
                return false;
            }
            *total += value;
        }
    }
    if (result == MU_CSV_ERROR) {
        snprintf(problem, problem_size, "%s", csv->error);
        return false;
    }
    return true;
}

bool mu_pool_profile_read_csv(FILE *stream, const char *label, double **strengths, int *count, char *problem,
                              size_t problem_size)
{
    *strengths = NULL;
    *count = 0;
    mu_csv_reader csv;
    mu_csv_reader_init(&csv, label, stream, MU_CSV_SPACE_SEPARATES | MU_CSV_COMMENTS);
    double *values = NULL;
    double total = 0.0;
    bool read = read_fields(&csv, &values, count, &total, problem, problem_size);
    mu_csv_reader_free(&csv);
    if (read && *count == 0) {
        snprintf(problem, problem_size, "%s: no strengths, expected at least one number", label);
        read = false;
    } else if (read && !(total > 0.0 && isfinite(total))) {
        snprintf(problem, problem_size,
                 "%s: the strengths sum to %g, expected a finite sum > 0 (a profile with some "
                 "strength)",
                 label, total);
        read = false;
    }
    if (!read) {
        free(values);
        *count = 0;
        return false;
    }
    *strengths = values;
    return true;
}
