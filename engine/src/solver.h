/* SPDX-License-Identifier: MIT */
/* The solver's step: the frame every solver shares (contact constraints
 * built, impulses stored), the body phases they all use, and the three
 * solvers, each a script in a file of its own:
 *   solver_baumgarte.c  sequential impulses with a Baumgarte bias
 *   solver_ngs.c        sequential impulses, then NGS position passes
 *   solver_soft_step.c  soft constraints with a relax pass
 */
#ifndef RB_SOLVER_H
#define RB_SOLVER_H

#include "world_internal.h"

/* Advances the bodies by dt with the world's contacts and the world's
 * solver, filling the solver's part of the profile and statistics. Fails
 * only when memory for the constraints or the list of moving bodies runs
 * out; the bodies are then left unmoved. */
rb_status rb_solver_step(rb_world *world, double dt);

/* What a solver did in a step, summed over its substeps. */
typedef struct rb_solver_counts {
    int velocity_iterations;
    int position_iterations; /* NGS passes */
    int relax_iterations;    /* soft step's relax passes */
} rb_solver_counts;

/* ---- the solvers; the contact constraints are prepared ------------------- */

rb_solver_counts rb_solve_baumgarte(rb_world *world, double dt);
rb_solver_counts rb_solve_ngs(rb_world *world, double dt);
rb_solver_counts rb_solve_soft_step(rb_world *world, double dt);

/* ---- phases they share (solver.c) ---------------------------------------- */

/* The user's substep callback, if any, with the world opened to cable laws. */
void rb_solver_call_substep_callback(rb_world *world, int substep, double h);
/* v += h·(g·gravity_scale + F/m), ω += h·τ/I for the awake dynamic bodies;
 * records each moving body's ω as the substep's starting one, which the
 * pins' drift reads (rb_point_drift). */
void rb_solver_integrate_velocities(rb_world *world, double h);
/* v /= 1 + h·c, then x += h·v, θ += h·ω (semi-implicit Euler). */
void rb_solver_damp_and_integrate_positions(rb_world *world, double h);

/* One substep of sequential impulses, shared by the Baumgarte and NGS
 * solvers: callback, velocities integrated, cables, joints and contacts
 * prepared at the poses now and warm started, velocity_iterations passes
 * (cables, joints, contacts), then damping and positions. With
 * contact_bias the contacts push overlap out by a Baumgarte bias. */
void rb_solver_sequential_substep(rb_world *world, int substep, double h, bool contact_bias);

#endif
