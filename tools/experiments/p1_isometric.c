/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/user_error.h"
#include "mu/muscle.h"
#include "p1_isometric.h"
#include "substep_model.h"

#define P1_MUSCLE "Biceps Long"

static int engine_failure(const char *what)
{
    fprintf(stderr, "sinew: P1: %s failed: %s\n", what, user_error());
    return EXIT_FAILURE;
}

/* The curves the model gives a muscle of this set (mu/model.h builds
 * the tables with linear interpolation, the analytic set with its
 * defaults). */
static rb_status create_curves(mu_model_curve_set set, mu_curves **out)
{
    if (set == MU_MODEL_CURVES_ANALYTIC) {
        mu_analytic_curves analytic = mu_default_analytic_curves();
        return mu_curves_create_analytic(&analytic, out);
    }
    return mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, out);
}

int p1_muscle_load(p1_muscle *muscle, const char *dynamics)
{
    *muscle = (p1_muscle){.name = P1_MUSCLE, .dynamics = MU_ACTIVATION_FIRST_ORDER};
    if (dynamics != NULL && strcmp(dynamics, "first_order") != 0) {
        const bool slow = strcmp(dynamics, "slow") == 0;
        if (!slow && strcmp(dynamics, "fast") != 0) {
            fprintf(stderr, "sinew: P1: unknown dynamics \"%s\", expected first_order, fast or slow\n", dynamics);
            return EXIT_FAILURE;
        }
        muscle->dynamics = MU_ACTIVATION_CALCIUM_FORCE;
        muscle->calcium_force = mu_calcium_force_times_of(slow ? MU_FIBRE_SLOW : MU_FIBRE_FAST);
    }
    experiment_model arm;
    int code = experiment_model_open(&arm, "arm", "All Muscles", 1.0);
    int built = code == 0 ? experiment_model_muscle(&arm, P1_MUSCLE) : -1;
    const mu_model_muscle *described = NULL;
    for (int m = 0; code == 0 && m < arm.desc->muscle_count; ++m) {
        described = strcmp(arm.desc->muscles[m].name, P1_MUSCLE) == 0 ? &arm.desc->muscles[m] : described;
    }
    if (code == 0 && (built < 0 || described == NULL)) {
        fprintf(stderr, "sinew: the arm model has no %s\n", P1_MUSCLE);
        code = EXIT_FAILURE;
    }
    if (code == 0) {
        const mu_muscle *biceps = mu_model_built_muscle(arm.model, built);
        muscle->max_force = mu_muscle_max_force(biceps);
        muscle->tendon_length = mu_muscle_tendon_length(biceps);
        muscle->rest_length = described->rest_length;
        muscle->max_velocity = described->max_velocity;
        if (create_curves(described->curves, &muscle->curves) != RB_OK) {
            code = engine_failure("creating the curves");
        }
    }
    experiment_model_close(&arm);
    return code;
}

void p1_muscle_free(p1_muscle *muscle)
{
    mu_curves_destroy(muscle->curves);
    *muscle = (p1_muscle){.name = NULL};
}

/* A world without gravity holding two static bodies the muscle's belly
 * plus its tendon apart, and the muscle between them along x. */
static int create_rig(const p1_muscle *muscle, p1_tendon tendon, rb_world **world, mu_muscle **out)
{
    rb_world_def world_def = rb_default_world_def();
    world_def.gravity = rb_v2(0.0, 0.0);
    world_def.solver.substeps = 1;
    world_def.enable_profile = false;
    world_def.enable_sleep = false;
    if (rb_world_create(&world_def, world) != RB_OK) {
        return engine_failure("creating the world");
    }
    rb_body_def body_def = rb_default_body_def();
    body_def.type = RB_BODY_STATIC;
    rb_body_id origin, insertion;
    rb_status status = rb_body_create(*world, &body_def, &origin);
    body_def.position = rb_v2(muscle->rest_length + muscle->tendon_length, 0.0);
    status = status == RB_OK ? rb_body_create(*world, &body_def, &insertion) : status;
    if (status != RB_OK) {
        return engine_failure("creating the bodies");
    }
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = origin;
    def.bodies[1] = insertion;
    def.rest_length = muscle->rest_length;
    def.max_force = muscle->max_force;
    def.max_velocity = muscle->max_velocity;
    def.tendon_length = muscle->tendon_length;
    def.curves = muscle->curves;
    def.activation_dynamics = true;
    def.activation_model = muscle->dynamics;
    def.calcium_force = muscle->calcium_force;
    def.compliant_tendon = tendon == P1_TENDON_COMPLIANT;
    if (mu_muscle_create(*world, &def, out) != RB_OK) {
        return engine_failure("creating the muscle");
    }
    return 0;
}

/* Excitation 1 during each pulse of the train, else 0. */
static double excitation_at(const p1_train *train, long substep)
{
    long since = substep - train->lead;
    if (since < 0) {
        return 0.0;
    }
    long phase = train->period > 0 ? since % train->period : since;
    return phase < train->width ? 1.0 : 0.0;
}

int p1_run_train(const p1_muscle *muscle, p1_tendon tendon, const p1_train *train, p1_trace *trace)
{
    *trace = (p1_trace){.count = 0};
    double *values = calloc(4 * (size_t)train->substeps, sizeof *values);
    if (values == NULL) {
        fputs("sinew: P1: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    trace->excitation = values;
    trace->calcium = values + train->substeps;
    trace->activation = values + 2 * train->substeps;
    trace->developed_force = values + 3 * train->substeps;
    rb_world *world = NULL;
    mu_muscle *rig = NULL;
    int code = create_rig(muscle, tendon, &world, &rig);
    for (long k = 0; code == 0 && k < train->substeps; ++k) {
        if (mu_muscle_set_activation(rig, excitation_at(train, k)) != RB_OK ||
            mu_muscle_prepare(rig, world, P1_SUBSTEP) != RB_OK || rb_world_step(world, P1_SUBSTEP) != RB_OK ||
            mu_muscle_measure(rig, world) != RB_OK) {
            code = engine_failure("a substep");
            break;
        }
        mu_muscle_readout r = mu_muscle_read(rig);
        trace->rest_force = k == train->lead - 1 ? r.total_force : trace->rest_force;
        trace->excitation[k] = r.excitation;
        trace->calcium[k] = r.calcium;
        trace->activation[k] = r.activation;
        trace->developed_force[k] = r.total_force;
        trace->count = k + 1;
    }
    for (long k = 0; k < trace->count; ++k) {
        trace->developed_force[k] -= trace->rest_force;
    }
    mu_muscle_destroy(rig, world);
    rb_world_destroy(world);
    return code;
}

void p1_trace_free(p1_trace *trace)
{
    free(trace->excitation);
    *trace = (p1_trace){.count = 0};
}
