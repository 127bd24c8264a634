/* SPDX-License-Identifier: MIT */
/* The simulation's clock: while the viewer plays, frames are stepped at
 * the simulation's own frame rate (60 Hz for the built-in models and the
 * scenes), whatever the drawing rate. A GLib timeout wakes every few
 * milliseconds, adds the wall time that passed to an accumulator and
 * steps one frame per frame duration in it; when the simulation cannot
 * keep up, it steps at most SIM_LOOP_MAX_FRAMES_PER_WAKE frames and drops
 * the rest of the backlog, so it slows down instead of freezing the
 * interface. Drawing follows with one redraw per wake that stepped.
 */
#ifndef VIEWER_SIM_LOOP_H
#define VIEWER_SIM_LOOP_H

#include <glib.h>

#include "viewer.h"

#define SIM_LOOP_WAKE_MS 4
#define SIM_LOOP_MAX_FRAMES_PER_WAKE 4

typedef struct sim_loop {
    viewer *app;
    gint64 last_wake; /* µs, g_get_monotonic_time() */
    double backlog;   /* s of wall time not yet simulated */
    guint source;     /* the timeout's id */
} sim_loop;

void sim_loop_start(sim_loop *loop, viewer *app);
void sim_loop_stop(sim_loop *loop);

#endif
