/* SPDX-License-Identifier: MIT */
/* A progress bar on stderr for long runs. It is drawn only when stderr is
 * a terminal (a log or a pipe gets nothing extra) and the run is long: more
 * than PROGRESS_LONG_SIMULATION s simulated, or more than PROGRESS_LONG_WALL
 * s of wall time expected from the pace of its first PROGRESS_PROBE s.
 */
#ifndef SINEW_PROGRESS_H
#define SINEW_PROGRESS_H

#include <stdbool.h>

#define PROGRESS_LONG_SIMULATION 10.0 /* s simulated */
#define PROGRESS_LONG_WALL 2.0        /* s of wall time expected */
#define PROGRESS_PROBE 0.2            /* s of wall time before the pace is judged */
#define PROGRESS_REDRAW 0.1           /* s between redraws */

typedef struct progress {
    bool watching; /* stderr is a terminal, and the bar is shown or may yet be */
    bool shown;    /* the bar is on screen */
    long total;    /* frames */
    double seconds_per_frame;
    double start, last_draw; /* s, CLOCK_MONOTONIC */
} progress;

/* Seconds of CLOCK_MONOTONIC, for the run's own timing too. */
double progress_now(void);

void progress_start(progress *bar, long total_frames, double seconds_per_frame);
/* After each frame: `done` frames of `total`. */
void progress_update(progress *bar, long done);
/* Clears the bar, so that what follows starts on a clean line. */
void progress_finish(progress *bar);

#endif
