/* SPDX-License-Identifier: MIT */
/* The control file of `sinew run --control FILE`: a schedule of controls
 * as text, one per line (docs/cli.md, "Control files"):
 *
 *   # a comment, from '#' to the end of the line; blank lines are skipped
 *   TIME activation NAME VALUE     activation 0 .. 1 from TIME s on
 *   TIME tension NAME NEWTONS      tension target from TIME s on
 *   TIME pulse NAME [VALUE]        activation VALUE (default 1) for one frame
 *
 * NAME is a muscle or a group of the model; one with spaces is written in
 * double quotes ("Biceps Short"). Fields are words as cli/words.h splits
 * them (spaces or tabs between them; the viewer's scripts quote alike).
 * Times are in seconds and must not decrease from one line to the next.
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

#endif
