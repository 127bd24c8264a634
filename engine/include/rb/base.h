/* SPDX-License-Identifier: MIT */
/** @file
 * sinew rigid-body engine: status codes, error messages and the allocator.
 *
 * Every API call that can fail returns an rb_status. On failure it also
 * records a readable message, retrieved with rb_last_error(); the message
 * names the function, the argument and what was expected. Getters that
 * return a value directly (rb_body_position, ...) return a zero value on a
 * bad id and record the error the same way, so rb_last_status() tells a
 * caller whether the value is real.
 */
#ifndef RB_BASE_H
#define RB_BASE_H

#include <stddef.h>
#include <stdint.h>

#include "rb/export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rb_status {
    RB_OK = 0,
    RB_ERR_INVALID_ARGUMENT, /**< NaN, infinity, out of range, NULL pointer */
    RB_ERR_STALE_ID,         /**< the object was destroyed */
    RB_ERR_FOREIGN_ID,       /**< the id belongs to another world, or is null */
    RB_ERR_DEGENERATE_SHAPE, /**< zero size, collinear or coincident points */
    RB_ERR_NOT_CONVEX,       /**< a polygon whose points are not its own convex hull */
    RB_ERR_NO_MASS,          /**< a dynamic body would get zero or negative mass */
    RB_ERR_LOCKED,           /**< the world is inside rb_world_step (a callback changed it) */
    RB_ERR_OUT_OF_MEMORY,
    /** A step made a body's pose or velocity NaN or infinite (the inputs
     * were in range, the motion was not); rb_world_step put the world back
     * as it was before the step (see there). */
    RB_ERR_NOT_FINITE,
} rb_status;

/** @name Ranges
 * What the API accepts, in SI units. Each bound lies far beyond what a
 * simulation of bodies and muscles needs, and they are chosen together
 * so that every product the solver forms of them stays finite: a mass
 * times a squared frequency (at most 1e15 · (2π·1e6)² ≈ 4e28), a mass
 * times a squared speed or length (1e27), an impulse over the shortest
 * substep (1e-9 s), an inverse mass or inertia (1e9 /kg), with many
 * orders of magnitude to spare below the largest double (1.8e308).
 * Beyond a bound a call fails with RB_ERR_INVALID_ARGUMENT naming the
 * field, its value and the range. Motion that leaves them (a body falling
 * for ever, an unstable stack) is not refused; a step whose state turns
 * non-finite fails with RB_ERR_NOT_FINITE. */
/** @{ */
/** m: largest |coordinate| of a position, anchor, target or shape point,
 * and largest shape size, joint length, translation limit or slop. */
#define RB_MAX_LENGTH 1.0e6
/** rad: largest |angle| of a body, reference angle or angle limit. */
#define RB_MAX_ANGLE 1.0e6
/** kg: the lightest a dynamic body, or a shape with density on one, may be. */
#define RB_MIN_MASS 1.0e-9
/** kg: the heaviest a body or shape may be (density · area included). */
#define RB_MAX_MASS 1.0e15
/** kg/m²: largest shape density. */
#define RB_MAX_DENSITY 1.0e12
/** m/s and rad/s: largest |velocity|, motor speed, push speed or
 * restitution threshold. */
#define RB_MAX_SPEED 1.0e6
/** m/s²: largest |gravity| component; gravity scales are at most
 * RB_MAX_GRAVITY_SCALE in magnitude. */
#define RB_MAX_ACCELERATION 1.0e6
/** Largest |gravity_scale|. */
#define RB_MAX_GRAVITY_SCALE 1.0e6
/** N, N·m, N·s, N·m·s and N·s/m: largest |force|, torque, impulse, motor
 * force or torque, mouse force, cable tension or cable damping. */
#define RB_MAX_FORCE 1.0e15
/** Hz: lowest positive spring or soft-constraint frequency (0, where it
 * means off or rigid, is allowed too): below it the spring's stiffness
 * m·ω² underflows and its softness 1/(h·(c + h·k)) becomes infinite. */
#define RB_MIN_HERTZ 1.0e-6
/** Hz: largest spring or soft-constraint frequency. */
#define RB_MAX_HERTZ 1.0e6
/** Largest damping ratio (1 is critical). */
#define RB_MAX_DAMPING_RATIO 1.0e6
/** 1/s: largest body linear or angular damping. */
#define RB_MAX_DAMPING 1.0e6
/** Largest friction coefficient. */
#define RB_MAX_FRICTION 1.0e3
/** s: shortest step rb_world_step takes (a substep is at least a
 * thousandth of it). */
#define RB_MIN_STEP 1.0e-6
/** s: longest step rb_world_step takes. */
#define RB_MAX_STEP 10.0
/** @} */

/** Short constant name of a status ("RB_ERR_STALE_ID"). */
RB_API const char *rb_status_name(rb_status status);

/** The message of the last failed call on this thread ("" after success). */
RB_API const char *rb_last_error(void);

/** The status of the last call on this thread that can fail. */
RB_API rb_status rb_last_status(void);

/** Records a failure with a printf-style message and returns `status`.
 * For libraries built on the engine (scenes, the muscle layer), so that
 * one rb_last_error() carries their messages too. */
RB_API rb_status rb_report_error(rb_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/** Bytes currently allocated by the engine, over all worlds of the process.
 * Zero once every world is destroyed. */
RB_API size_t rb_bytes_in_use(void);

/** Number of allocations made so far (never decreases); lets a benchmark
 * count heap allocations in a step. */
RB_API uint64_t rb_allocation_count(void);

#ifdef __cplusplus
}
#endif

#endif
