/* SPDX-License-Identifier: MIT */
/* A built-in model run substep by substep for an experiment: loaded and
 * built as `sinew run` does (model_source.h, mu/model.h), driven by the
 * experiment between substeps, so that a pulse may be shorter than a frame.
 */
#ifndef SINEW_EXPERIMENT_MODEL_H
#define SINEW_EXPERIMENT_MODEL_H

#include <stdbool.h>

#include "mu/model.h"

typedef struct experiment_model {
    mu_model_desc *desc;
    mu_model *model;
    int substeps; /* per frame */
    double h;     /* s, one substep */
    long taken;   /* substeps taken */
} experiment_model;

/* Loads the built-in model `name` and builds its variant named `variant`
 * with the weight choice of `weight_kg` kg (a model without a weight
 * takes none). Returns 0, or an exit status after one line on stderr. */
int experiment_model_open(experiment_model *run, const char *name, const char *variant, double weight_kg);

/* The index among the built muscles of the muscle `name`, or -1. */
int experiment_model_muscle(const experiment_model *run, const char *name);

/* The substep that starts at `time` s (rounded to the nearest). */
long experiment_model_substep_at(const experiment_model *run, double time);

/* Substeps in a pulse of `width` s: a frame for 0, else `width` rounded
 * to whole substeps, at least one. */
long experiment_model_pulse_substeps(const experiment_model *run, double width);

/* Advances one substep; returns 0, or EXIT_FAILURE after one line on
 * stderr. */
int experiment_model_substep(experiment_model *run);

/* The time at the end of the last substep, s. */
double experiment_model_time(const experiment_model *run);

/* Accepts a run that failed to open. */
void experiment_model_close(experiment_model *run);

#endif
