/* SPDX-License-Identifier: MIT */
#include <stdlib.h>

#include "history.h"

bool history_init(history *samples, int muscle_count, long capacity)
{
    *samples = (history){.muscle_count = muscle_count, .capacity = capacity};
    size_t per_sample = (size_t)muscle_count * HISTORY_QUANTITY_COUNT;
    samples->times = calloc((size_t)capacity, sizeof *samples->times);
    samples->values = calloc((size_t)capacity * (per_sample > 0 ? per_sample : 1), sizeof *samples->values);
    if (samples->times == NULL || samples->values == NULL) {
        history_free(samples);
        return false;
    }
    return true;
}

void history_free(history *samples)
{
    free(samples->times);
    free(samples->values);
    *samples = (history){0};
}

static double *sample_values(const history *samples, long slot)
{
    return samples->values + (size_t)slot * (size_t)samples->muscle_count * HISTORY_QUANTITY_COUNT;
}

void history_record(history *samples, double time, const mu_muscle_readout *readouts)
{
    if (samples->capacity == 0) {
        return;
    }
    samples->times[samples->next] = time;
    double *values = sample_values(samples, samples->next);
    for (int m = 0; m < samples->muscle_count; ++m) {
        double *muscle = values + (size_t)m * HISTORY_QUANTITY_COUNT;
        muscle[HISTORY_ACTIVATION] = readouts[m].activation;
        muscle[HISTORY_TOTAL_FORCE] = readouts[m].total_force;
        muscle[HISTORY_ACTIVE_FORCE] = readouts[m].active_force;
        muscle[HISTORY_PASSIVE_FORCE] = readouts[m].passive_force;
        muscle[HISTORY_NORMALIZED_CONTRACTION] = readouts[m].normalized_contraction;
    }
    samples->next = (samples->next + 1) % samples->capacity;
    if (samples->count < samples->capacity) {
        ++samples->count;
    }
}

long history_series(const history *samples, int muscle, history_quantity quantity, double *times, double *values)
{
    long oldest =
        (samples->next - samples->count + samples->capacity) % (samples->capacity > 0 ? samples->capacity : 1);
    for (long k = 0; k < samples->count; ++k) {
        long slot = (oldest + k) % samples->capacity;
        times[k] = samples->times[slot];
        values[k] = sample_values(samples, slot)[(size_t)muscle * HISTORY_QUANTITY_COUNT + quantity];
    }
    return samples->count;
}
