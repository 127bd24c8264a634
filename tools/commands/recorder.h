/* SPDX-License-Identifier: MIT */
/* The CSV of a run (`sinew run`): one row per frame, written through an
 * atomic_file (io/atomic_file.h), so a failed or interrupted run leaves
 * no half-written file and an earlier file of that name is kept.
 *
 * Columns: time_s (the end of the frame), then for every built muscle, in
 * the model's order, NAME.activation, NAME.target_tension_N, NAME.length_m,
 * NAME.normalized_length, NAME.velocity_m_s, NAME.normalized_velocity,
 * NAME.contraction_m, NAME.normalized_contraction, NAME.active_force_N,
 * NAME.passive_force_N, NAME.total_force_N, NAME.excitation,
 * NAME.fibre_length_m, NAME.tendon_length_m, NAME.pennation_angle_deg
 * (mu_muscle_readout); for every built torque muscle
 * NAME.recruited_neurons, NAME.exertion (0 to 1) and NAME.torque_N_m; for
 * every built hinge NAME.angle_deg; for every built part (nails, then bones)
 * NAME.x_m, NAME.y_m, NAME.angle_deg; then the joint loads and moment
 * arms (recorder_loads.h). A header field holding a comma, a
 * quote or a line break is quoted as RFC 4180 says.
 *
 * Numbers are written with RECORDER_DEFAULT_DIGITS significant digits, or
 * as many as the caller asks up to RECORDER_EXACT_DIGITS, which read back
 * as the very doubles the run computed.
 *
 * Beside it, PATH-metadata.json names the version, the command line and
 * the model's settings as built (io/provenance.h), with the frames
 * recorded.
 */
#ifndef SINEW_RECORDER_H
#define SINEW_RECORDER_H

#include <stdbool.h>
#include <stddef.h>

#include "io/atomic_file.h"
#include "io/provenance.h"
#include "mu/model.h"
#include "recorder_loads.h"

/* Quantities recorded per muscle, per hinge and per part. */
enum {
    RECORDER_MUSCLE_COLUMNS = 15,
    RECORDER_TORQUE_COLUMNS = 3,
    RECORDER_HINGE_COLUMNS = 1,
    RECORDER_PART_COLUMNS = 3
};

/* Ten significant digits resolve 1e-9 of a metre-sized value, below any
 * effect the file is read for, and keep a row of the arm under 1.5 kB;
 * seventeen give every IEEE 754 double back exactly (a file compared bit
 * for bit with another computation, as the Python package's tests do). */
enum { RECORDER_MIN_DIGITS = 1, RECORDER_DEFAULT_DIGITS = 10, RECORDER_EXACT_DIGITS = 17 };

typedef struct recorder {
    atomic_file file;
    int *hinges; /* model indices of the built hinges */
    int hinge_count;
    int *parts; /* model indices of the built parts */
    int part_count;
    recorder_loads loads;
    long rows;
    int digits;       /* significant digits of every number */
    json_t *settings; /* of the sidecar: the model's, taken at the start */
} recorder;

/* Opens `path` and writes the header for the model as built with
 * `options`; its numbers will have `digits` significant digits
 * (RECORDER_MIN_DIGITS .. RECORDER_EXACT_DIGITS). On failure nothing is
 * left on disk and `error` says why. */
bool recorder_open(recorder *csv, const char *path, mu_model *model, const mu_model_options *options, int digits,
                   char *error, size_t error_size);

/* Writes the row of the model's present state at `time` s, its loads as
 * `frame` read them (frame_loads.h). */
bool recorder_write_row(recorder *csv, const mu_model *model, const frame_loads *frame, double time, char *error,
                        size_t error_size);

/* Renames the file into place, then writes its sidecar; either way the
 * recorder is closed after. */
bool recorder_commit(recorder *csv, char *error, size_t error_size);

/* Removes the temporary file; the recorder is closed after. */
void recorder_abandon(recorder *csv);

int recorder_column_count(const recorder *csv, const mu_model *model);

#endif
