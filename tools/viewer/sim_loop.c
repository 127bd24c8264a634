/* SPDX-License-Identifier: MIT */
#include "sim_loop.h"

static gboolean on_wake(gpointer data)
{
    sim_loop *loop = data;
    viewer *app = loop->app;
    gint64 now = g_get_monotonic_time();
    double elapsed = (double)(now - loop->last_wake) * 1e-6;
    loop->last_wake = now;
    if (!app->playing || app->sim.kind == SIMULATION_NONE) {
        loop->backlog = 0.0;
        return G_SOURCE_CONTINUE;
    }
    double frame = simulation_frame_duration(&app->sim);
    loop->backlog += elapsed;
    int stepped = 0;
    while (loop->backlog >= frame && stepped < SIM_LOOP_MAX_FRAMES_PER_WAKE && app->playing) {
        loop->backlog -= frame;
        if (!viewer_step(app)) {
            break;
        }
        ++stepped;
    }
    if (loop->backlog >= frame) {
        loop->backlog = 0.0; /* behind: drop the backlog rather than fall further behind */
    }
    if (stepped > 0) {
        viewer_refresh(app);
    }
    return G_SOURCE_CONTINUE;
}

void sim_loop_start(sim_loop *loop, viewer *app)
{
    loop->app = app;
    loop->last_wake = g_get_monotonic_time();
    loop->backlog = 0.0;
    loop->source = g_timeout_add(SIM_LOOP_WAKE_MS, on_wake, loop);
}

void sim_loop_stop(sim_loop *loop)
{
    if (loop->source != 0) {
        g_source_remove(loop->source);
        loop->source = 0;
    }
}
