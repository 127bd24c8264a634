/* SPDX-License-Identifier: MIT */
/* One frame's load readouts (frame_loads.h). */
#include <stdlib.h>

#include "frame_loads.h"

bool frame_loads_start(frame_loads *frame, const mu_model *model)
{
    frame->hinges = malloc(((size_t)mu_model_hinge_count(model) + 1) * sizeof *frame->hinges);
    frame->glues = malloc(((size_t)mu_model_glue_count(model) + 1) * sizeof *frame->glues);
    frame->bones = malloc(((size_t)mu_model_description(model)->bone_count + 1) * sizeof *frame->bones);
    if (frame->hinges == NULL || frame->glues == NULL || frame->bones == NULL) {
        frame_loads_free(frame);
        return false;
    }
    return true;
}

bool frame_loads_read(frame_loads *frame, const mu_model *model)
{
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        frame->hinges[h] = mu_model_hinge_load(model, h);
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        frame->glues[g] = mu_model_glue_load(model, g);
    }
    return mu_model_bone_stresses(model, frame->bones) == RB_OK;
}

void frame_loads_free(frame_loads *frame)
{
    free(frame->hinges);
    free(frame->glues);
    free(frame->bones);
    frame->hinges = NULL;
    frame->glues = NULL;
    frame->bones = NULL;
}
