/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/model_source.h"
#include "cli/user_error.h"
#include "substep_model.h"

static int engine_failure(const char *what)
{
    fprintf(stderr, "sinew: %s failed: %s (%s)\n", what, user_error(), rb_status_name(rb_last_status()));
    return EXIT_FAILURE;
}

int experiment_model_open(experiment_model *run, const char *name, const char *variant, double weight_kg)
{
    *run = (experiment_model){.desc = NULL};
    int code = model_source_load(name, &run->desc);
    if (code != 0) {
        return code;
    }
    mu_model_options options = mu_default_model_options();
    options.variant = mu_model_desc_find_variant(run->desc, variant);
    if (options.variant < 0) {
        fprintf(stderr, "sinew: model %s has no variant \"%s\"\n", name, variant);
        return EXIT_FAILURE;
    }
    options.weight_index = -1;
    for (int w = 0; w < run->desc->weight.mass_count; ++w) {
        if (fabs(run->desc->weight.masses[w] - weight_kg) <= 1e-9 * fmax(1.0, weight_kg)) {
            options.weight_index = w;
        }
    }
    if (run->desc->has_weight && options.weight_index < 0) {
        fprintf(stderr, "sinew: model %s has no weight choice of %g kg\n", name, weight_kg);
        return EXIT_FAILURE;
    }
    options.weight_index = options.weight_index < 0 ? 0 : options.weight_index;
    if (mu_model_create(run->desc, &options, &run->model) != RB_OK) {
        return engine_failure("building the model");
    }
    run->substeps = run->desc->substeps;
    run->h = mu_model_substep_duration(run->model);
    return 0;
}

int experiment_model_muscle(const experiment_model *run, const char *name)
{
    for (int m = 0; m < mu_model_muscle_count(run->model); ++m) {
        if (strcmp(mu_model_muscle_name(run->model, m), name) == 0) {
            return m;
        }
    }
    return -1;
}

long experiment_model_substep_at(const experiment_model *run, double time) { return lround(time / run->h); }

long experiment_model_pulse_substeps(const experiment_model *run, double width)
{
    if (width <= 0.0) {
        return run->substeps;
    }
    long substeps = lround(width / run->h);
    return substeps < 1 ? 1 : substeps;
}

int experiment_model_substep(experiment_model *run)
{
    if (mu_model_substep(run->model) != RB_OK) {
        return engine_failure("stepping the model by a substep");
    }
    run->taken += 1;
    return 0;
}

double experiment_model_time(const experiment_model *run) { return mu_model_time(run->model); }

void experiment_model_close(experiment_model *run)
{
    mu_model_destroy(run->model);
    mu_model_desc_destroy(run->desc);
    *run = (experiment_model){.desc = NULL};
}
