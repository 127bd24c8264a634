/* SPDX-License-Identifier: MIT */
/* Inverse dynamics with the forces the hinges pass on (private to the
 * muscle layer, for static optimization's joint loads).
 *
 * Cut the model at a hinge: the side that leaves the ground (B's, or A's
 * when B's holds to the ground) is a set S of bodies, and Newton's law
 * for S alone gives the net force that everything crossing the hinge (the
 * hinge's reaction, the muscles' pulls on S's path points) applies to S:
 *
 *   F = Σ over bodies k in S of  m_k·(a_k − g_k + d_k·v_k)
 *
 * with the terms of mu/inverse_dynamics.h's moment sum. Subtracting the
 * muscles' pulls leaves the hinge's reaction on S.
 */
#ifndef MU_INVERSE_DYNAMICS_FORCES_H
#define MU_INVERSE_DYNAMICS_FORCES_H

#include <stdbool.h>

#include "mu/model.h"

typedef struct mu_hinge_force {
    rb_vec2 moving;    /* N, world frame: F above, on the side that leaves the ground */
    bool b_side_moves; /* whether that side is B's (else A's) */
} mu_hinge_force;

/* mu_model_inverse_dynamics, its refusals named after `function`, with
 * forces[h] for every built hinge (the hinge count of them; a hinge not
 * built is left as it is). */
rb_status mu_inverse_dynamics_with_forces(const mu_model *model, const char *function, const double *angles_deg,
                                          const double *rates, const double *accelerations, double *torques,
                                          mu_hinge_force *forces);

#endif
