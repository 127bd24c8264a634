/* SPDX-License-Identifier: MIT */
/** @file
 * Cables: a path of points fixed on bodies (origin, via points,
 * insertion) that carries a tension, as a muscle-tendon unit or a rope
 * over pulleys does.
 *
 * The path's length L is the sum of its segments; its lengthening speed
 * L' comes from the points' velocities. Under a tension T each point is
 * pulled along the unit vectors towards its neighbours, T·(u_i - u_{i-1}),
 * so a via point gets the sum of the two pulls and a path whose ends are
 * on one body exerts no net force or torque on it.
 *
 * The tension follows the law T = base_tension + damping·L', never below 0
 * (a cable pulls, never pushes), set for each step by the caller. The
 * solver makes T consistent with the velocities at the end of each
 * substep (linearly implicit), so a stiff damping (a Hill muscle's
 * force-velocity slope) stays stable at any substep: an explicit force
 * c·L' is unstable once h·c·k > 2, k the path's inverse effective mass.
 */
#ifndef RB_CABLE_H
#define RB_CABLE_H

#include <stdint.h>

#include "rb/base.h"
#include "rb/export.h"
#include "rb/id.h"
#include "rb/math.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RB_MAX_CABLE_POINTS 8

typedef struct rb_cable_def {
    int point_count;                        /**< 2 .. RB_MAX_CABLE_POINTS */
    rb_body_id bodies[RB_MAX_CABLE_POINTS]; /**< the body of each point, in path order */
    /** m, each point in its body's frame (from the origin), within ±RB_MAX_LENGTH */
    rb_vec2 local_points[RB_MAX_CABLE_POINTS];
    void *user_data;
    /** Set by rb_default_cable_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_cable_def() and change fields. */
    int32_t internal_value;
} rb_cable_def;

RB_API rb_cable_def rb_default_cable_def(void);

/** Fails when a body id is invalid, a point is not finite, the count is out
 * of range, or two consecutive points coincide (the direction between
 * them would be undefined). */
RB_API rb_status rb_cable_create(rb_world *world, const rb_cable_def *def, rb_cable_id *out);
RB_API rb_status rb_cable_destroy(rb_world *world, rb_cable_id cable);
RB_API bool rb_cable_is_valid(const rb_world *world, rb_cable_id cable);

/** The tension law for the following steps: base_tension (N, within
 * ±RB_MAX_FORCE) and damping (N·s/m, 0 .. RB_MAX_FORCE). Both 0 (the default): a slack cable.
 * Wakes the cable's bodies and restarts their time at rest: a cable
 * driven by a law set every substep keeps them awake. */
RB_API rb_status rb_cable_set_tension_law(rb_world *world, rb_cable_id cable, double base_tension, double damping);

/** Length (m) and lengthening speed (m/s, < 0 while shortening) now, in
 * one pass over the path. */
RB_API rb_status rb_cable_state(const rb_world *world, rb_cable_id cable, double *length, double *lengthening_speed);
RB_API double rb_cable_length(const rb_world *world, rb_cable_id cable); /**< m, now */
RB_API double rb_cable_lengthening_speed(const rb_world *world,
                                         rb_cable_id cable); /**< m/s, now; < 0 while shortening */
/** The tension (N, >= 0) the cable carried in the last substep: what the
 * solver applied; between bodies that cannot move, the law at rest. */
RB_API double rb_cable_tension(const rb_world *world, rb_cable_id cable);
/** What the owner of a cable (a muscle) reads of it once a substep. */
typedef struct rb_cable_reading {
    double length;            /**< m, now */
    double lengthening_speed; /**< m/s, now; < 0 while shortening */
    double tension;           /**< N, >= 0: what the cable carried in the last substep (rb_cable_tension) */
} rb_cable_reading;

/** rb_cable_state and rb_cable_tension in one call, with one look-up of
 * the id: the same numbers, bit for bit. Fails (RB_ERR_INVALID_ARGUMENT,
 * RB_ERR_FOREIGN_ID, RB_ERR_STALE_ID) on a NULL world or out, or an id
 * that is not a live cable of the world; *out is then all 0. */
RB_API rb_status rb_cable_read(const rb_world *world, rb_cable_id cable, rb_cable_reading *out);
/** The world positions of the path's points now; returns the count. */
RB_API int rb_cable_points(const rb_world *world, rb_cable_id cable, rb_vec2 *out, int capacity);

#ifdef __cplusplus
}
#endif

#endif
