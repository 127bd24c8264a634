/* SPDX-License-Identifier: MIT */
/** @file
 * Rigid bodies.
 *
 * A body has a pose (origin position and angle), velocities, and mass
 * properties computed from its shapes or set explicitly. Positions are
 * of the body origin unless a name says "center" (the centre of mass).
 */
#ifndef RB_BODY_H
#define RB_BODY_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/export.h"
#include "rb/geometry.h"
#include "rb/id.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rb_body_type {
    RB_BODY_STATIC,    /**< never moves; infinite mass */
    RB_BODY_KINEMATIC, /**< moves with its set velocity; infinite mass; ignores forces */
    RB_BODY_DYNAMIC,   /**< moved by forces, gravity and contacts */
} rb_body_type;

typedef struct rb_body_def {
    rb_body_type type;       /**< default RB_BODY_STATIC */
    rb_vec2 position;        /**< m, world position of the body origin, within ±RB_MAX_LENGTH */
    double angle;            /**< rad, within ±RB_MAX_ANGLE */
    rb_vec2 linear_velocity; /**< m/s, of the centre of mass, within ±RB_MAX_SPEED */
    double angular_velocity; /**< rad/s, within ±RB_MAX_SPEED */
    /** Damping: each (sub)step of length h, after the constraints are
     * solved, the velocities are divided by (1 + h·c), the backward-Euler
     * step of dv/dt = -c·v, stable for any c and h; over a time t it
     * decays as exp(-c·t) when h·c << 1. Acting after the constraints, it
     * leaves a supported body's full weight on its supports. */
    double linear_damping;  /**< 1/s, 0 .. RB_MAX_DAMPING, default 0 */
    double angular_damping; /**< 1/s, 0 .. RB_MAX_DAMPING, default 0 */
    double gravity_scale;   /**< multiplies the world's gravity, within ±RB_MAX_GRAVITY_SCALE, default 1 */
    bool fixed_rotation;    /**< never rotates (infinite rotational inertia) */
    /** Default true. A sleeping body is not simulated (the solver treats it
     * as static) until something wakes it: a touching awake body, a force,
     * an impulse, a joint, a cable law, or rb_body_set_awake. */
    bool awake;
    bool enable_sleep; /**< default true; false keeps the body, and so its island, awake */
    /** Box2D's flag for a fast body, read back by rb_body_is_bullet. Every
     * body already collides continuously: each pair whose surfaces can
     * meet within the step gets a speculative contact, which the solver
     * does not let close faster than its gap (contact.c); a 0.05 m ball
     * at 300 m/s stops at a 0.1 m wall, static or dynamic
     * (tests/test_tunnelling.c). */
    bool bullet;
    void *user_data;
    /** Set by rb_default_body_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_body_def() and change fields. */
    int32_t internal_value;
} rb_body_def;

RB_API rb_body_def rb_default_body_def(void);

RB_API rb_status rb_body_create(rb_world *world, const rb_body_def *def, rb_body_id *out);
/** Destroys the body, its shapes and its contacts. */
RB_API rb_status rb_body_destroy(rb_world *world, rb_body_id body);
RB_API bool rb_body_is_valid(const rb_world *world, rb_body_id body);

RB_API rb_body_type rb_body_type_of(const rb_world *world, rb_body_id body);
RB_API rb_status rb_body_set_type(rb_world *world, rb_body_id body, rb_body_type type);

/** Pose. */
RB_API rb_vec2 rb_body_position(const rb_world *world, rb_body_id body); /**< m, origin */
RB_API double rb_body_angle(const rb_world *world, rb_body_id body);     /**< rad, continuous (not wrapped) */
RB_API rb_rot rb_body_rotation(const rb_world *world, rb_body_id body);
RB_API rb_transform rb_body_transform(const rb_world *world, rb_body_id body);
RB_API rb_vec2 rb_body_world_center(const rb_world *world, rb_body_id body); /**< m, centre of mass */
RB_API rb_vec2 rb_body_local_center(const rb_world *world, rb_body_id body); /**< m, in the body frame */
RB_API rb_status rb_body_set_transform(rb_world *world, rb_body_id body, rb_vec2 position, double angle);

/** Velocities (of the centre of mass). */
RB_API rb_vec2 rb_body_linear_velocity(const rb_world *world, rb_body_id body);
RB_API double rb_body_angular_velocity(const rb_world *world, rb_body_id body);
RB_API rb_status rb_body_set_linear_velocity(rb_world *world, rb_body_id body, rb_vec2 velocity);
RB_API rb_status rb_body_set_angular_velocity(rb_world *world, rb_body_id body, double omega);
/** Velocity (m/s) of the material point now at world_point: v + ω × r. */
RB_API rb_vec2 rb_body_point_velocity(const rb_world *world, rb_body_id body, rb_vec2 world_point);

/** Frame conversions. */
RB_API rb_vec2 rb_body_world_point(const rb_world *world, rb_body_id body, rb_vec2 local_point);
RB_API rb_vec2 rb_body_local_point(const rb_world *world, rb_body_id body, rb_vec2 world_point);
RB_API rb_vec2 rb_body_world_vector(const rb_world *world, rb_body_id body, rb_vec2 local_vector);
RB_API rb_vec2 rb_body_local_vector(const rb_world *world, rb_body_id body, rb_vec2 world_vector);

/** @name Forces and impulses
 * Forces and torques accumulate until the end of
 * the next rb_world_step and act during all of its substeps. Each force,
 * torque or impulse given is at most RB_MAX_FORCE (N, N·m, N·s, N·m·s) in
 * each component, each point within ±RB_MAX_LENGTH m. They are
 * ignored (RB_OK) on static and kinematic bodies. Applying one wakes the
 * body. */
/** @{ */
/** A force (N) at a world point: also a torque r × F about the centre of mass. */
RB_API rb_status rb_body_apply_force(rb_world *world, rb_body_id body, rb_vec2 force, rb_vec2 world_point);
RB_API rb_status rb_body_apply_force_to_center(rb_world *world, rb_body_id body, rb_vec2 force);
RB_API rb_status rb_body_apply_torque(rb_world *world, rb_body_id body, double torque); /**< N·m */
/** An impulse (N·s) at a world point: Δv = J/m, Δω = (r × J)/I at once. */
RB_API rb_status rb_body_apply_linear_impulse(rb_world *world, rb_body_id body, rb_vec2 impulse, rb_vec2 world_point);
RB_API rb_status rb_body_apply_linear_impulse_to_center(rb_world *world, rb_body_id body, rb_vec2 impulse);
RB_API rb_status rb_body_apply_angular_impulse(rb_world *world, rb_body_id body, double impulse); /**< N·m·s */
/** The force and torque accumulated so far for the next step. */
RB_API rb_vec2 rb_body_force(const rb_world *world, rb_body_id body);
RB_API double rb_body_torque(const rb_world *world, rb_body_id body);
/** @} */

/** Mass. A dynamic body's mass comes from its shapes' densities; until it
 * has a shape with mass, or after rb_body_set_mass_data, it has the
 * explicit value. A dynamic body without shapes or override has mass
 * 1 kg and does not rotate. */
RB_API double rb_body_mass(const rb_world *world, rb_body_id body); /**< kg; 0 for static, kinematic */
RB_API double rb_body_rotational_inertia(const rb_world *world,
                                         rb_body_id body); /**< kg·m², about the centre of mass */
RB_API rb_mass_data rb_body_mass_data(const rb_world *world, rb_body_id body);
/** Overrides the shapes' mass (mass RB_MIN_MASS .. RB_MAX_MASS kg,
 * rotational inertia 0 .. RB_MAX_MASS·RB_MAX_LENGTH² kg·m², centre within
 * ±RB_MAX_LENGTH m); the override holds until rb_body_reset_mass_data. */
RB_API rb_status rb_body_set_mass_data(rb_world *world, rb_body_id body, const rb_mass_data *mass_data);
RB_API rb_status rb_body_reset_mass_data(rb_world *world, rb_body_id body);

/** Damping (1/s, 0 .. RB_MAX_DAMPING), gravity scale (within
 * ±RB_MAX_GRAVITY_SCALE), flags. Positions set by rb_body_set_transform
 * and velocities by the setters below have the ranges of rb_body_def. */
RB_API rb_status rb_body_set_linear_damping(rb_world *world, rb_body_id body, double damping);
RB_API rb_status rb_body_set_angular_damping(rb_world *world, rb_body_id body, double damping);
RB_API double rb_body_linear_damping(const rb_world *world, rb_body_id body);
RB_API double rb_body_angular_damping(const rb_world *world, rb_body_id body);
RB_API rb_status rb_body_set_gravity_scale(rb_world *world, rb_body_id body, double scale);
RB_API double rb_body_gravity_scale(const rb_world *world, rb_body_id body);
RB_API rb_status rb_body_set_fixed_rotation(rb_world *world, rb_body_id body, bool fixed);
RB_API bool rb_body_is_fixed_rotation(const rb_world *world, rb_body_id body);
/** Waking a body wakes its island at the start of the next step; putting
 * it to sleep stops it where it is. */
RB_API rb_status rb_body_set_awake(rb_world *world, rb_body_id body, bool awake);
/** Disabling sleep wakes the body. */
RB_API rb_status rb_body_enable_sleep(rb_world *world, rb_body_id body, bool enable);
RB_API bool rb_body_is_sleep_enabled(const rb_world *world, rb_body_id body);
RB_API bool rb_body_is_awake(const rb_world *world, rb_body_id body);
RB_API rb_status rb_body_set_bullet(rb_world *world, rb_body_id body, bool bullet);
RB_API bool rb_body_is_bullet(const rb_world *world, rb_body_id body);
RB_API rb_status rb_body_set_user_data(rb_world *world, rb_body_id body, void *user_data);
RB_API void *rb_body_user_data(const rb_world *world, rb_body_id body);

/** Shapes attached to the body, in creation order; returns how many it
 * copied (at most capacity). */
RB_API int rb_body_shape_count(const rb_world *world, rb_body_id body);
RB_API int rb_body_shapes(const rb_world *world, rb_body_id body, rb_shape_id *out, int capacity);

#ifdef __cplusplus
}
#endif

#endif
