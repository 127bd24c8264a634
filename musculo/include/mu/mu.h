/* SPDX-License-Identifier: MIT */
/** @file
 * sinew muscle layer: the whole public API (and, through rb/rb.h, the
 * engine's). */
#ifndef MU_MU_H
#define MU_MU_H

#include "mu/activation.h"
#include "mu/calcium_force.h"
#include "mu/curves.h"
#include "mu/geometry_lengths.h"
#include "mu/inverse_dynamics.h"
#include "mu/joint_loads.h"
#include "mu/model.h"
#include "mu/model_desc.h"
#include "mu/moment_arms.h"
#include "mu/motor_pool.h"
#include "mu/muscle.h"
#include "mu/muscle_statics.h"
#include "mu/pennation.h"
#include "mu/tendon.h"
#include "mu/torque_actuator.h"
#include "mu/version.h"
#include "rb/rb.h"

#endif
