/* The solver's step: the substep loop that integrates bodies and runs the
 * constraint solvers. */
#ifndef RB_SOLVER_H
#define RB_SOLVER_H

#include "world_internal.h"

/* Advances the bodies by dt with the world's contacts, filling the
 * solver's part of the profile and statistics. Fails only when memory
 * for the constraints runs out; the bodies are then left unmoved. */
rb_status rb_solver_step(rb_world *world, double dt);

#endif
