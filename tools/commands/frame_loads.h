/* SPDX-License-Identifier: MIT */
/* One frame's load readouts, read once at the end of the frame and shared
 * by the CSV's row (recorder_loads.h) and the summary's peaks
 * (load_peaks.h): every hinge's and glue's load (mu/joint_loads.h) and
 * every bone's worst section (mu/bone_stress.h). Bone stress is the
 * costly one (every load on the bone's rigid body, at some 90 sections),
 * so reading it for each consumer would double the run's readout time;
 * it is read for all bones at once (mu_model_bone_stresses), which
 * collects each rigid body's loads once for the bones glued into it.
 * A joint not built and a bone that does not move hold NaN fields, as
 * the library gives them. */
#ifndef SINEW_FRAME_LOADS_H
#define SINEW_FRAME_LOADS_H

#include <stdbool.h>

#include "mu/bone_stress.h"
#include "mu/joint_loads.h"

typedef struct frame_loads {
    mu_joint_load *hinges; /* by model hinge index */
    mu_joint_load *glues;  /* by model glue index */
    mu_bone_stress *bones; /* by description bone index */
} frame_loads;

/* false on memory. */
bool frame_loads_start(frame_loads *frame, const mu_model *model);
/* Reads the model's present frame; false when the bone stress cannot be
 * read (rb_last_error says why). */
bool frame_loads_read(frame_loads *frame, const mu_model *model);
void frame_loads_free(frame_loads *frame);

#endif
