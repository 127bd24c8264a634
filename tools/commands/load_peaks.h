/* SPDX-License-Identifier: MIT */
/* The joint loads' extremes over a run, for `sinew run`'s summary: for
 * every built hinge and every glue kept as a weld, the largest reaction
 * force (its magnitude, N), reaction torque and muscle torque (the
 * largest in magnitude, with its sign, N·m), each with the time it was
 * reached, sampled at the end of each frame (mu/joint_loads.h); and for
 * every bone that moves, its lowest safety factor against fracture, with
 * the section, stress and time (mu/bone_stress.h). */
#ifndef SINEW_LOAD_PEAKS_H
#define SINEW_LOAD_PEAKS_H

#include <stdbool.h>

#include "frame_loads.h"
#include "mu/model.h"

typedef struct load_peak {
    double force, force_time;                 /* N, s */
    double torque, torque_time;               /* N·m, s */
    double muscle_torque, muscle_torque_time; /* N·m, s */
} load_peak;

/* A bone's worst section in one frame. */
typedef struct stress_sample {
    double safety_factor, time; /* and when, s; NaN: no such frame yet */
    double stress, section;     /* Pa (> 0 tension) and m along the bone, there and then */
} stress_sample;

typedef struct stress_peak {
    stress_sample lowest; /* the lowest factor */
    /* The first frame whose factor fell below 1: when the bone would
     * break. A load held steady keeps the factor on a plateau, where the
     * lowest frame is chosen by rounding, not by the load. */
    stress_sample first_break;
} stress_peak;

typedef struct load_peaks {
    load_peak *hinges;  /* by model hinge index */
    load_peak *glues;   /* by model glue index */
    stress_peak *bones; /* by description bone index */
} load_peaks;

/* false on memory. */
bool load_peaks_start(load_peaks *peaks, const mu_model *model);
/* Takes the frame's loads, read at `time` (s). */
void load_peaks_track(load_peaks *peaks, const mu_model *model, const frame_loads *frame, double time);
/* Prints the summary's "peak load" lines, one per joint built, and its
 * "bone stress" lines, one per bone that moves, at its lowest factor; a
 * bone whose factor fell below 1 is also warned of on stderr, at the
 * first frame it did (it would break then). */
void load_peaks_print(const load_peaks *peaks, const mu_model *model);
void load_peaks_free(load_peaks *peaks);

#endif
