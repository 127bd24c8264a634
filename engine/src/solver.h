/* The solver's step: the substep loop that integrates bodies and runs the
 * constraint solvers. */
#ifndef RB_SOLVER_H
#define RB_SOLVER_H

#include "world_internal.h"

/* Advances the bodies by dt with the world's contacts, filling the
 * solver's part of the profile and statistics. */
void rb_solver_step(rb_world *world, double dt);

#endif
