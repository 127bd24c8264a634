/* SPDX-License-Identifier: MIT */
/* Axis labels from CSV column names. sinew's CSV files put the unit in
 * the name: as a suffix, "time_s", "Biceps Long.total_force_N",
 * "velocity_m_s" (recorder.h), or in brackets, "force [N]". A label reads
 * "time (s)", "Biceps Long.total force (N)", "force (N)".
 */
#ifndef CHART_COLUMN_LABEL_H
#define CHART_COLUMN_LABEL_H

#include <stdbool.h>
#include <stddef.h>

/* The unit of a column name ("N", "m/s"), or "" when it shows none. */
void column_unit(const char *name, char *unit, size_t unit_size);

/* "quantity (unit)" for a column name, underscores of the quantity as
 * spaces; the name as it is when it shows no unit. */
void column_label(const char *name, char *label, size_t label_size);

#endif
