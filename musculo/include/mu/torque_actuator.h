/* SPDX-License-Identifier: MIT */
/** @file
 * A torque actuator (the torque muscle of Robert McIntyre's "Simulated
 * Muscles", aurellem): a torque
 * about the axis out of the plane, exertion · peak_torque, on one body,
 * and the opposite torque on a second body when one is given (a joint
 * actuator between two segments, which conserves their total angular
 * momentum); without one, the reaction goes to the world, as in McIntyre's.
 *
 * The torque is applied through rb_body_apply_torque, which holds it over
 * every substep of the next rb_world_step: call mu_torque_actuator_apply
 * once before each step.
 */
#ifndef MU_TORQUE_ACTUATOR_H
#define MU_TORQUE_ACTUATOR_H

#include <stdbool.h>

#include "mu/export.h"
#include "rb/rb.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mu_torque_actuator mu_torque_actuator;

typedef struct mu_torque_actuator_def {
    rb_body_id body; /**< the body turned by +torque (counter-clockwise when positive) */
    /** The body that takes −torque; the null id (the default) for the world. */
    rb_body_id reaction_body;
    double peak_torque; /**< N·m, finite: the torque at exertion 1; its sign sets the direction */
} mu_torque_actuator_def;

/** Null bodies, peak torque 0. */
MU_API mu_torque_actuator_def mu_default_torque_actuator_def(void);

/** Checks that the bodies exist in the world and differ, and that the peak
 * torque is finite. The exertion starts at 0. */
MU_API rb_status mu_torque_actuator_create(const rb_world *world, const mu_torque_actuator_def *def,
                                           mu_torque_actuator **out);
/** Accepts NULL. */
MU_API void mu_torque_actuator_destroy(mu_torque_actuator *actuator);

/** The share of the peak torque, in [0, 1]. */
MU_API rb_status mu_torque_actuator_set_exertion(mu_torque_actuator *actuator, double exertion);
/** The share set; NaN (and an error) for NULL. */
MU_API double mu_torque_actuator_exertion(const mu_torque_actuator *actuator);
/** N·m: exertion · peak_torque, on the body (its reaction on the other).
 * NaN (and an error) for NULL. */
MU_API double mu_torque_actuator_torque(const mu_torque_actuator *actuator);
/** N·m; NaN (and an error) for NULL. */
MU_API double mu_torque_actuator_peak_torque(const mu_torque_actuator *actuator);

/** W: the rate at which the torque does work on the bodies now,
 * torque · (ω(body) − ω(reaction body)) (the world's ω is 0); NaN (and
 * an error) for a NULL argument or a body no longer in the world. */
MU_API double mu_torque_actuator_power(const mu_torque_actuator *actuator, const rb_world *world);

/** Adds the torque to the body and its opposite to the reaction body for
 * the next step. A static or kinematic body takes none (the engine's rule). */
MU_API rb_status mu_torque_actuator_apply(const mu_torque_actuator *actuator, rb_world *world);

#ifdef __cplusplus
}
#endif

#endif
