/* SPDX-License-Identifier: MIT */
/* Cables in the solver's substep. */
#ifndef RB_CABLE_SOLVER_H
#define RB_CABLE_SOLVER_H

#include "world_internal.h"

/* At the start of a step: each point's offset from its body's centre of
 * mass in the body's frame, which no substep changes (masses and shapes
 * stay as they are within a step). */
void rb_cables_prepare_step(rb_world *world);
/* At the start of a substep, before the substep callback: every cable's
 * points in the world at the poses now. The callback cannot move a body
 * (the world is locked) and integrating the velocities moves none, so
 * the muscles' reading of their paths in the callback and
 * rb_cables_prepare then use these points instead of turning each
 * anchor into the world again. */
void rb_cables_locate(rb_world *world);
/* The path at the poses now: each body's share of a unit tension, and
 * the tension law's terms fixed for a substep of h seconds. Uses the
 * located points, and says they are no longer fresh: the positions move
 * next. */
void rb_cables_prepare(rb_world *world, double h);
void rb_cables_warm_start(rb_world *world);
/* One pass of the implicit tension law over the cables, less those a
 * limb block solves in its rows this substep (rb_cable.in_block). */
void rb_cables_solve(rb_world *world, double h);
void rb_cables_reset_impulses(rb_world *world);

#endif
