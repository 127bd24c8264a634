/* SPDX-License-Identifier: MIT */
/* An experiment's protocol: what it does to the model over time, written
 * as a control file of `sinew run --control` (docs/cli.md, "Control
 * files") and read by the same parser, so that each experiment's schedule
 * reads as text a user can copy into a file of their own. The experiment
 * applies it before every substep (commands/controls.h).
 */
#ifndef SINEW_EXPERIMENT_PROTOCOL_H
#define SINEW_EXPERIMENT_PROTOCOL_H

#include "commands/controls.h"
#include "substep_model.h"

/* Reads the protocol `text`, named `name` in its messages ("e2
 * protocol"), into `schedule` for the model's variant `variant`. Returns
 * 0, or EXIT_FAILURE after one line on stderr ("sinew: NAME:LINE: ..."). */
int experiment_protocol_read(controls *schedule, const experiment_model *run, const char *variant, const char *name,
                             const char *text);

/* Applies the protocol before the model's next substep; returns 0, or
 * EXIT_FAILURE after one line on stderr. */
int experiment_protocol_apply(controls *schedule, experiment_model *run);

#endif
