/* SPDX-License-Identifier: MIT */
/* The control file of `sinew run --control FILE`: a schedule of controls
 * as text, one per line (docs/cli.md, "Control files"):
 *
 *   # a comment, from '#' to the end of the line; blank lines are skipped
 *   TIME [QUANTITY] SHAPE NAME ARGUMENTS...
 *   TIME QUANTITY NAME VALUE              a step: the same as `QUANTITY step`
 *   TIME pulse NAME [VALUE]               activation VALUE (default 1) for one frame
 *
 * QUANTITY is what the line drives, activation when left out:
 *   activation   of a muscle or group, 0 .. 1
 *   tension      target tension of a muscle or group, N, >= 0
 *   recruit      neurons a torque muscle recruits, 0 .. its pool's size
 *                (whole numbers; a sine's samples are rounded to the nearest)
 * SHAPE and its ARGUMENTS (control_shape.h), the durations in s and the
 * frequencies in Hz:
 *   step    VALUE
 *   ramp    FROM TO DURATION
 *   sine    MEAN AMPLITUDE FREQUENCY DURATION
 *   pulses  LEVEL FREQUENCY WIDTH DURATION
 * so `0.5 ramp "Biceps Short" 0 0.8 1.0` ramps that muscle's activation
 * from 0 at 0.5 s to 0.8 at 1.5 s. After QUANTITY, step, ramp, sine and
 * pulses are always the shape; a muscle with such a name is written after
 * an explicit shape (`0 activation step ramp 0.5`).
 *
 * NAME is a muscle, a group or a torque muscle of the model; one with
 * spaces is written in double quotes ("Biceps Short"). Fields are words as
 * cli/words.h splits them (spaces or tabs between them; the viewer's
 * scripts quote alike). Times are in seconds and must not decrease from
 * one line to the next; controls.h says how lines act and overlap.
 */
#ifndef SINEW_CONTROL_FILE_H
#define SINEW_CONTROL_FILE_H

#include <stdbool.h>
#include <stddef.h>

#include "controls.h"

/* Reads the whole file into `schedule`, checking every line first (so a
 * bad line is found before a run starts). On failure writes
 * "PATH:LINE: what was expected, and what was found" to `error` and
 * returns false; events of the lines before it may have been added. */
bool control_file_read(const char *path, controls *schedule, char *error, size_t error_size);

/* The same for control text held in memory (an experiment's protocol),
 * its errors naming it `name` ("NAME:LINE: ..."). */
bool control_text_read(const char *name, const char *text, controls *schedule, char *error, size_t error_size);

#endif
