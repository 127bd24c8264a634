/* SPDX-License-Identifier: MIT */
/* The last seconds of a model's muscles, sampled once per frame, for the
 * live graphs: a ring of samples (time and, for every built muscle, the
 * quantities the graphs show), oldest dropped first.
 */
#ifndef VIEWER_HISTORY_H
#define VIEWER_HISTORY_H

#include <stdbool.h>
#include <stddef.h>

#include "mu/muscle.h"

typedef enum history_quantity {
    HISTORY_ACTIVATION,
    HISTORY_TOTAL_FORCE,   /* N */
    HISTORY_ACTIVE_FORCE,  /* N */
    HISTORY_PASSIVE_FORCE, /* N */
    HISTORY_NORMALIZED_CONTRACTION,
    HISTORY_QUANTITY_COUNT
} history_quantity;

typedef struct history {
    int muscle_count;
    long capacity; /* samples kept */
    long count;    /* samples held, <= capacity */
    long next;     /* where the next sample goes */
    double *times; /* s, capacity */
    /* capacity × muscle_count × HISTORY_QUANTITY_COUNT, by sample, then
     * muscle, then quantity */
    double *values;
} history;

/* A history of `capacity` (>= 1) samples of `muscle_count` (>= 0)
 * muscles; false when out of memory. */
bool history_init(history *samples, int muscle_count, long capacity);
/* Accepts a zeroed or freed history. */
void history_free(history *samples);

/* Adds the sample of time `time` (s): one readout per muscle. */
void history_record(history *samples, double time, const mu_muscle_readout *readouts);

/* Copies the held samples of one muscle's quantity, oldest first, into
 * times and values (each of history->count elements); returns how many. */
long history_series(const history *samples, int muscle, history_quantity quantity, double *times, double *values);

#endif
