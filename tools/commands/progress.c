/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, fileno */

#include <stdio.h>
#include <time.h>
#include <unistd.h>

#include "progress.h"

enum { BAR_WIDTH = 30 };

double progress_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void progress_start(progress *bar, long total_frames, double seconds_per_frame)
{
    double now = progress_now();
    *bar = (progress){
        .watching = isatty(fileno(stderr)) == 1,
        .total = total_frames,
        .seconds_per_frame = seconds_per_frame,
        .start = now,
        .last_draw = now,
    };
    bar->shown = bar->watching && (double)total_frames * seconds_per_frame > PROGRESS_LONG_SIMULATION;
}

static void draw(progress *bar, long done, double now)
{
    double fraction = (double)done / (double)bar->total;
    int filled = (int)(fraction * BAR_WIDTH);
    char cells[BAR_WIDTH + 1];
    for (int k = 0; k < BAR_WIDTH; ++k) {
        cells[k] = k < filled ? '#' : '-';
    }
    cells[BAR_WIDTH] = '\0';
    double elapsed = now - bar->start;
    double left = done > 0 ? elapsed * (double)(bar->total - done) / (double)done : 0.0;
    /* \033[K clears what a longer previous line left to the right. */
    fprintf(stderr, "\r[%s] %3.0f%%  %.1f of %.1f s simulated, %.1f s left\033[K", cells, 100.0 * fraction,
            (double)done * bar->seconds_per_frame, (double)bar->total * bar->seconds_per_frame, left);
    fflush(stderr);
    bar->last_draw = now;
}

void progress_update(progress *bar, long done)
{
    if (!bar->watching || done <= 0) {
        return;
    }
    double now = progress_now();
    double elapsed = now - bar->start;
    if (!bar->shown && elapsed >= PROGRESS_PROBE) {
        bar->shown = elapsed * (double)bar->total / (double)done > PROGRESS_LONG_WALL;
        /* Judged once: a run found short stays without a bar. */
        bar->watching = bar->shown;
    }
    if (bar->shown && now - bar->last_draw >= PROGRESS_REDRAW) {
        draw(bar, done, now);
    }
}

void progress_finish(progress *bar)
{
    if (bar->shown) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
        bar->shown = false;
    }
}
