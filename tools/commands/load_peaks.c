/* SPDX-License-Identifier: MIT */
/* The joint loads' extremes over a run (load_peaks.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "load_peaks.h"

/* A bone's factor is lower than the lowest so far when it is lower by
 * more than this fraction, well above the last bits a steady load's
 * rounding moves it by (the leg's fibula under its muscles: 1e-12). */
#define LOWER_BY 1e-9

static void reset(load_peak *peaks, int count)
{
    for (int i = 0; i < count; ++i) {
        peaks[i] = (load_peak){.force = -1.0};
    }
}

bool load_peaks_start(load_peaks *peaks, const mu_model *model)
{
    const int hinges = mu_model_hinge_count(model);
    const int glues = mu_model_glue_count(model);
    peaks->hinges = malloc(((size_t)hinges + 1) * sizeof *peaks->hinges);
    peaks->glues = malloc(((size_t)glues + 1) * sizeof *peaks->glues);
    const int bones = mu_model_description(model)->bone_count;
    peaks->bones = malloc(((size_t)bones + 1) * sizeof *peaks->bones);
    if (peaks->hinges == NULL || peaks->glues == NULL || peaks->bones == NULL) {
        load_peaks_free(peaks);
        return false;
    }
    for (int b = 0; b < bones; ++b) {
        const stress_sample none = {NAN, NAN, NAN, NAN};
        peaks->bones[b] = (stress_peak){none, none};
    }
    reset(peaks->hinges, hinges);
    reset(peaks->glues, glues);
    return true;
}

/* Keeps `value` and `time` when |value| is the largest yet. */
static void keep_largest(double *peak, double *peak_time, double value, double time)
{
    if (fabs(value) > fabs(*peak)) {
        *peak = value;
        *peak_time = time;
    }
}

static void track(load_peak *peak, mu_joint_load load, double time)
{
    if (isnan(load.force.x)) {
        return; /* not built as a joint */
    }
    const double force = hypot(load.force.x, load.force.y);
    if (force > peak->force) {
        peak->force = force;
        peak->force_time = time;
    }
    keep_largest(&peak->torque, &peak->torque_time, load.torque, time);
    keep_largest(&peak->muscle_torque, &peak->muscle_torque_time, load.muscle_torque, time);
}

void load_peaks_track(load_peaks *peaks, const mu_model *model, const frame_loads *frame, double time)
{
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        track(&peaks->hinges[h], frame->hinges[h], time);
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        track(&peaks->glues[g], frame->glues[g], time);
    }
    for (int b = 0; b < mu_model_description(model)->bone_count; ++b) {
        const mu_bone_stress stress = frame->bones[b];
        stress_peak *peak = &peaks->bones[b];
        if (isnan(stress.worst.stress)) {
            continue; /* the bone does not move */
        }
        const stress_sample now = {stress.worst.safety_factor, time, stress.worst.stress, stress.worst.s};
        /* The first frame's, then any lower by more than rounding: a
         * plateau keeps its first frame. */
        if (!(now.safety_factor >= peak->lowest.safety_factor * (1.0 - LOWER_BY))) {
            peak->lowest = now;
        }
        if (isnan(peak->first_break.time) && now.safety_factor < 1.0) {
            peak->first_break = now;
        }
    }
}

static void print_peak(const load_peak *peak, const char *name, bool *first)
{
    if (peak->force < 0.0) {
        return; /* never tracked: not built */
    }
    printf("%-13s%-24s %10.2f N at %.3f s; reaction torque %.2f N·m at %.3f s; muscles %.2f N·m at %.3f s\n",
           *first ? "peak load" : "", name, peak->force, peak->force_time, peak->torque, peak->torque_time,
           peak->muscle_torque, peak->muscle_torque_time);
    *first = false;
}

void load_peaks_print(const load_peaks *peaks, const mu_model *model)
{
    bool first = true;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        print_peak(&peaks->hinges[h], mu_model_hinge_name(model, h), &first);
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        print_peak(&peaks->glues[g], mu_model_glue_name(model, g), &first);
    }
    if (first) {
        printf("peak load    (no joints built)\n");
    }
    const mu_model_desc *desc = mu_model_description(model);
    first = true;
    for (int b = 0; b < desc->bone_count; ++b) {
        const stress_sample *lowest = &peaks->bones[b].lowest;
        const stress_sample *breaks = &peaks->bones[b].first_break;
        if (isnan(lowest->time)) {
            continue;
        }
        printf("%-13s%-24s safety factor %.3g at %.3f s: %.4g MPa at %+.4f m from its centre%s\n",
               first ? "bone stress" : "", desc->bones[b].name, lowest->safety_factor, lowest->time,
               lowest->stress / 1e6, lowest->section, isnan(breaks->time) ? "" : " (below 1: it would break)");
        if (!isnan(breaks->time)) {
            fprintf(stderr,
                    "warning: bone \"%s\" would break at %.3f s: safety factor %.3g, stress %.4g MPa at %+.4f m "
                    "from its centre\n",
                    desc->bones[b].name, breaks->time, breaks->safety_factor, breaks->stress / 1e6, breaks->section);
        }
        first = false;
    }
}

void load_peaks_free(load_peaks *peaks)
{
    free(peaks->hinges);
    free(peaks->glues);
    free(peaks->bones);
    peaks->hinges = NULL;
    peaks->glues = NULL;
    peaks->bones = NULL;
}
