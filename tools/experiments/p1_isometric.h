/* SPDX-License-Identifier: MIT */
/* P1's isometric muscle (docs/validation.md, P1): the arm's Biceps Long, the
 * muscle E1 plots, taken out of the arm and held between two static
 * bodies with its belly at rest length, activation dynamics on, driven
 * by excitation pulses of whole substeps. The dynamics are first order by
 * default (mu/activation.h: Millard et al. 2013, τ_act 10 ms, τ_deact
 * 40 ms), or the two stages of mu/calcium_force.h, calcium then force,
 * with the fast or the slow fibres' times.
 *
 * Two tendons, each the real muscle code (mu/muscle.h):
 * - rigid, as the arm builds it: the fibre cannot move, so the force is
 *   Fmax·(a·f_L(1)·f_V(0) + f_P(1)) and follows the activation alone;
 * - compliant (mu/tendon.h, Thelen 2003, strain 0.049 at Fmax) of the
 *   arm's tendon length as slack length: the fibre shortens against the
 *   stretching tendon at a speed its force-velocity curve allows, the
 *   series elastic element of Hill (1938), which slows the force's rise.
 */
#ifndef SINEW_EXPERIMENT_P1_ISOMETRIC_H
#define SINEW_EXPERIMENT_P1_ISOMETRIC_H

#include "mu/activation.h"
#include "mu/calcium_force.h"
#include "mu/curves.h"

/* 6 kHz, ten times the models' 600 Hz: 2 ms and the period of every
 * frequency of P1's sweep are whole substeps. */
#define P1_SUBSTEP (1.0 / 6000.0) /* s */

typedef enum p1_tendon { P1_TENDON_RIGID, P1_TENDON_COMPLIANT, P1_TENDON_COUNT } p1_tendon;

typedef struct p1_muscle {
    const char *name;
    double max_force;     /* N */
    double rest_length;   /* m, the belly's, held */
    double max_velocity;  /* m/s */
    double tendon_length; /* m, the arm's rigid tendon; the compliant one's slack length */
    mu_curves *curves;    /* the arm's set, owned */
    mu_activation_model dynamics;
    mu_calcium_force_times calcium_force; /* the two stages' times, when those are the dynamics */
} p1_muscle;

/* Reads Biceps Long from the arm as the arm builds it, with the named
 * dynamics: NULL or "first_order", "fast" or "slow" (experiment.h).
 * Returns 0, or EXIT_FAILURE after one line on stderr. */
int p1_muscle_load(p1_muscle *muscle, const char *dynamics);
/* Accepts a muscle that failed to load. */
void p1_muscle_free(p1_muscle *muscle);

/* Pulses of excitation 1 (0 between them), the first after `lead`
 * substeps at rest. */
typedef struct p1_train {
    long lead;     /* substeps at excitation 0 first, >= 1 */
    long width;    /* substeps of each pulse, >= 1 */
    long period;   /* substeps from one pulse's onset to the next's, > width; 0 for one pulse */
    long substeps; /* of the whole run, > lead */
} p1_train;

/* What each substep ended with. Developed force is the tension above the
 * one at rest (the passive force, constant while isometric), as a
 * physiologist's isometric recording reads it. */
typedef struct p1_trace {
    long count;
    double rest_force;                                           /* N, the tension at the end of the lead */
    double *excitation, *calcium, *activation, *developed_force; /* calcium: the readout's (mu/muscle.h) */
} p1_trace;

/* Runs the train on a fresh world holding the muscle with the given
 * tendon. Returns 0, or EXIT_FAILURE after one line on stderr; the trace
 * must be freed either way. */
int p1_run_train(const p1_muscle *muscle, p1_tendon tendon, const p1_train *train, p1_trace *trace);
/* Accepts a zero-initialised trace. */
void p1_trace_free(p1_trace *trace);

#endif
