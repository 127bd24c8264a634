/* SPDX-License-Identifier: MIT */
/* Cables in the solver's substep. */
#ifndef RB_CABLE_SOLVER_H
#define RB_CABLE_SOLVER_H

#include "world_internal.h"

/* The path at the poses now: each body's share of a unit tension. */
void rb_cables_prepare(rb_world *world);
void rb_cables_warm_start(rb_world *world);
/* One pass of the implicit tension law over the cables. */
void rb_cables_solve(rb_world *world, double h);
void rb_cables_reset_impulses(rb_world *world);

#endif
