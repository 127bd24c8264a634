/* SPDX-License-Identifier: MIT */
/* The joint loads' extremes over a run, for `sinew run`'s summary: for
 * every built hinge and every glue kept as a weld, the largest reaction
 * force (its magnitude, N), reaction torque and muscle torque (the
 * largest in magnitude, with its sign, N·m), each with the time it was
 * reached, sampled at the end of each frame (mu/joint_loads.h). */
#ifndef SINEW_LOAD_PEAKS_H
#define SINEW_LOAD_PEAKS_H

#include <stdbool.h>

#include "mu/model.h"

typedef struct load_peak {
    double force, force_time;                 /* N, s */
    double torque, torque_time;               /* N·m, s */
    double muscle_torque, muscle_torque_time; /* N·m, s */
} load_peak;

typedef struct load_peaks {
    load_peak *hinges; /* by model hinge index */
    load_peak *glues;  /* by model glue index */
} load_peaks;

/* false on memory. */
bool load_peaks_start(load_peaks *peaks, const mu_model *model);
void load_peaks_track(load_peaks *peaks, const mu_model *model, double time);
/* Prints the summary's "peak load" lines: one per joint built. */
void load_peaks_print(const load_peaks *peaks, const mu_model *model);
void load_peaks_free(load_peaks *peaks);

#endif
