/* SPDX-License-Identifier: MIT */
/** @file
 * Joints: constraints between two bodies, solved with the contacts by
 * sequential impulses (warm started), their drift removed by the world's
 * position-correction method.
 *
 * Anchors are points fixed in each body, given in the body's frame
 * relative to its origin (m). Angles are in radians; the angle of a
 * revolute joint is angle(B) - angle(A) - reference_angle, continuous
 * (not wrapped). Soft constraints take a frequency (Hz) and a damping
 * ratio (dimensionless; 1 is critical): the constraint then behaves as a
 * spring-damper of that natural frequency and damping for the effective
 * mass it acts on (Catto, "Soft Constraints", GDC 2011). A joint between
 * two bodies that cannot move (static or kinematic) is allowed and does
 * nothing.
 *
 * Ranges (rb/base.h), here and in the setters: anchors, targets and
 * ground anchors within ±RB_MAX_LENGTH m in each coordinate; angles within
 * ±RB_MAX_ANGLE rad; lengths and translations up to RB_MAX_LENGTH m;
 * motor speeds within ±RB_MAX_SPEED; forces and torques from 0 to
 * RB_MAX_FORCE; spring frequencies 0 (off) or from RB_MIN_HERTZ to
 * RB_MAX_HERTZ; damping ratios from 0 to RB_MAX_DAMPING_RATIO.
 */
#ifndef RB_JOINT_H
#define RB_JOINT_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/export.h"
#include "rb/id.h"
#include "rb/math.h"
#include "rb/world.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rb_joint_type {
    RB_JOINT_REVOLUTE,  /**< a pin: the anchors coincide, the bodies turn freely about it */
    RB_JOINT_WELD,      /**< the relative pose is frozen (a model file's glue) */
    RB_JOINT_DISTANCE,  /**< bar, spring or rope between the anchors */
    RB_JOINT_MOUSE,     /**< pulls a body point towards a target with a bounded force */
    RB_JOINT_PRISMATIC, /**< body B slides along an axis fixed in body A, without turning */
    RB_JOINT_PULLEY,    /**< a rope over two fixed pulleys: length_a + ratio·length_b at most a constant */
} rb_joint_type;

/** @name Revolute joints */
/** @{ */

typedef struct rb_revolute_joint_def {
    rb_body_id body_a, body_b;
    rb_vec2 local_anchor_a; /**< m, in body A's frame, within ±RB_MAX_LENGTH */
    rb_vec2 local_anchor_b; /**< m, in body B's frame, within ±RB_MAX_LENGTH */
    double reference_angle; /**< rad, within ±RB_MAX_ANGLE: angle(B) - angle(A) at which the joint angle is 0 */
    /** Limits on the joint angle; each side is enabled alone (the leg's
     * ankle has only a lower limit). lower <= upper when both are on. */
    bool enable_lower_limit, enable_upper_limit;
    double lower_angle, upper_angle; /**< rad, within ±RB_MAX_ANGLE */
    /** Motor: drives the joint speed to motor_speed with at most
     * max_motor_torque. */
    bool enable_motor;
    double motor_speed;      /**< rad/s, within ±RB_MAX_SPEED */
    double max_motor_torque; /**< N·m, 0 .. RB_MAX_FORCE */
    /** Spring: pulls the joint angle towards 0 (the reference angle). */
    bool enable_spring;
    double spring_hertz;         /**< Hz, 0 (no spring) or RB_MIN_HERTZ .. RB_MAX_HERTZ */
    double spring_damping_ratio; /**< 0 .. RB_MAX_DAMPING_RATIO */
    bool collide_connected;      /**< whether the two bodies' shapes still collide (default false) */
    void *user_data;
    /** Set by rb_default_revolute_joint_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_revolute_joint_def() and change fields. */
    int32_t internal_value;
} rb_revolute_joint_def;

RB_API rb_revolute_joint_def rb_default_revolute_joint_def(void);

/** Makes *def a complete definition: rb_default_revolute_joint_def() with
 * the bodies, local anchors and reference angle that pin the two bodies
 * at `world_anchor` in their current poses. Set limits, motor or spring
 * afterwards. On failure *def is left as it was. */
RB_API rb_status rb_revolute_joint_def_at(rb_revolute_joint_def *def, const rb_world *world, rb_body_id body_a,
                                          rb_body_id body_b, rb_vec2 world_anchor);

RB_API rb_status rb_revolute_joint_create(rb_world *world, const rb_revolute_joint_def *def, rb_joint_id *out);

RB_API double rb_revolute_joint_angle(const rb_world *world, rb_joint_id joint); /**< rad */
RB_API double rb_revolute_joint_speed(const rb_world *world, rb_joint_id joint); /**< rad/s, ωB - ωA */
/** The torque the motor applied in the last step (N·m). */
RB_API double rb_revolute_joint_motor_torque(const rb_world *world, rb_joint_id joint);
RB_API rb_status rb_revolute_joint_set_motor(rb_world *world, rb_joint_id joint, bool enable, double speed,
                                             double max_torque);
RB_API rb_status rb_revolute_joint_set_limits(rb_world *world, rb_joint_id joint, bool enable_lower, double lower,
                                              bool enable_upper, double upper);
RB_API rb_status rb_revolute_joint_set_spring(rb_world *world, rb_joint_id joint, bool enable, double hertz,
                                              double damping_ratio);
/** @} */

/** @name Weld joints */
/** @{ */

typedef struct rb_weld_joint_def {
    rb_body_id body_a, body_b;
    rb_vec2 local_anchor_a, local_anchor_b; /**< m, within ±RB_MAX_LENGTH */
    double reference_angle;                 /**< rad, within ±RB_MAX_ANGLE: angle(B) - angle(A) held */
    /** 0 Hz means rigid; a positive frequency makes that part soft. */
    double linear_hertz, linear_damping_ratio; /**< Hz, 0 or RB_MIN_HERTZ .. RB_MAX_HERTZ; 0 .. RB_MAX_DAMPING_RATIO */
    double angular_hertz,
        angular_damping_ratio; /**< Hz, 0 or RB_MIN_HERTZ .. RB_MAX_HERTZ; 0 .. RB_MAX_DAMPING_RATIO */
    bool collide_connected;
    void *user_data;
    /** Set by rb_default_weld_joint_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_weld_joint_def() and change fields. */
    int32_t internal_value;
} rb_weld_joint_def;

RB_API rb_weld_joint_def rb_default_weld_joint_def(void);

/** Makes *def a complete definition: rb_default_weld_joint_def() with the
 * bodies, anchors and reference angle that freeze the two bodies' current
 * relative pose about `world_anchor`. On failure *def is left as it was. */
RB_API rb_status rb_weld_joint_def_at(rb_weld_joint_def *def, const rb_world *world, rb_body_id body_a,
                                      rb_body_id body_b, rb_vec2 world_anchor);

RB_API rb_status rb_weld_joint_create(rb_world *world, const rb_weld_joint_def *def, rb_joint_id *out);
/** @} */

/** @name Distance joints */
/** @{ */

typedef struct rb_distance_joint_def {
    rb_body_id body_a, body_b;
    rb_vec2 local_anchor_a, local_anchor_b; /**< m, within ±RB_MAX_LENGTH */
    double length; /**< m, 1e-9 .. RB_MAX_LENGTH: the bar's length, or the spring's rest length */
    /** Without the spring the joint is a rigid bar of `length`. With it the
     * anchors are pulled towards `length` by a spring of spring_hertz (0: no
     * pull at all, as a rope). */
    bool enable_spring;
    double spring_hertz;         /**< Hz, 0 (no spring) or RB_MIN_HERTZ .. RB_MAX_HERTZ */
    double spring_damping_ratio; /**< 0 .. RB_MAX_DAMPING_RATIO */
    /** Limits keep the distance in [min_length, max_length] whatever the
     * spring does: a rope is enable_spring with 0 Hz and a max_length. */
    bool enable_limit;
    /** m: 0 <= min_length <= max_length, min_length at most RB_MAX_LENGTH;
     * max_length may be larger, up to DBL_MAX (the default: no upper
     * limit), since the limit only compares it with the length. */
    double min_length, max_length;
    bool collide_connected;
    void *user_data;
    /** Set by rb_default_distance_joint_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_distance_joint_def() and change fields. */
    int32_t internal_value;
} rb_distance_joint_def;

RB_API rb_distance_joint_def rb_default_distance_joint_def(void);

/** Makes *def a complete definition: rb_default_distance_joint_def() with
 * the bodies, the anchors of two world points, and length, min_length and
 * max_length set to their current distance. On failure *def is left as it
 * was. */
RB_API rb_status rb_distance_joint_def_between(rb_distance_joint_def *def, const rb_world *world, rb_body_id body_a,
                                               rb_body_id body_b, rb_vec2 world_anchor_a, rb_vec2 world_anchor_b);

RB_API rb_status rb_distance_joint_create(rb_world *world, const rb_distance_joint_def *def, rb_joint_id *out);

RB_API double rb_distance_joint_current_length(const rb_world *world, rb_joint_id joint); /**< m */
/** @} */

/** @name Mouse joints */
/** @{ */

typedef struct rb_mouse_joint_def {
    rb_body_id body;      /**< the dragged body (dynamic) */
    rb_vec2 local_anchor; /**< m, the dragged point in the body's frame, within ±RB_MAX_LENGTH */
    rb_vec2 target;       /**< m, world, within ±RB_MAX_LENGTH */
    double max_force;     /**< N, 0 .. RB_MAX_FORCE */
    double hertz;         /**< Hz, RB_MIN_HERTZ .. RB_MAX_HERTZ, default 5 */
    double damping_ratio; /**< 0 .. RB_MAX_DAMPING_RATIO, default 0.7 */
    void *user_data;
    /** Set by rb_default_mouse_joint_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_mouse_joint_def() and change fields. */
    int32_t internal_value;
} rb_mouse_joint_def;

RB_API rb_mouse_joint_def rb_default_mouse_joint_def(void);
RB_API rb_status rb_mouse_joint_create(rb_world *world, const rb_mouse_joint_def *def, rb_joint_id *out);
RB_API rb_status rb_mouse_joint_set_target(rb_world *world, rb_joint_id joint, rb_vec2 target);
/** @} */

/** @name Prismatic joints */
/** @{ */

/** Body B slides along an axis fixed in body A through anchor A; the
 * relative angle is held at the reference angle. The joint translation
 * is s = (anchor B - anchor A)·axis (m), 0 where the anchors coincide. */
typedef struct rb_prismatic_joint_def {
    rb_body_id body_a, body_b;
    rb_vec2 local_anchor_a; /**< m, in body A's frame, within ±RB_MAX_LENGTH */
    rb_vec2 local_anchor_b; /**< m, in body B's frame, within ±RB_MAX_LENGTH */
    rb_vec2 local_axis_a; /**< in body A's frame: any non-zero finite vector, normalised on creation; default (1, 0) */
    double reference_angle; /**< rad, within ±RB_MAX_ANGLE: angle(B) - angle(A) held */
    /** Limits on the translation; each side is enabled alone. lower <=
     * upper when both are on. */
    bool enable_lower_limit, enable_upper_limit;
    double lower_translation, upper_translation; /**< m, within ±RB_MAX_LENGTH */
    /** Motor: drives the translation speed to motor_speed with at most
     * max_motor_force. */
    bool enable_motor;
    double motor_speed;     /**< m/s, within ±RB_MAX_SPEED */
    double max_motor_force; /**< N, 0 .. RB_MAX_FORCE */
    /** Spring: pulls the translation towards 0 (anchor B on anchor A). */
    bool enable_spring;
    double spring_hertz;         /**< Hz, 0 (no spring) or RB_MIN_HERTZ .. RB_MAX_HERTZ */
    double spring_damping_ratio; /**< 0 .. RB_MAX_DAMPING_RATIO */
    bool collide_connected;      /**< whether the two bodies' shapes still collide (default false) */
    void *user_data;
    /** Set by rb_default_prismatic_joint_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_prismatic_joint_def() and change fields. */
    int32_t internal_value;
} rb_prismatic_joint_def;

RB_API rb_prismatic_joint_def rb_default_prismatic_joint_def(void);

/** Makes *def a complete definition: rb_default_prismatic_joint_def() with
 * the bodies, local anchors, local axis and reference angle by which body
 * B slides along `world_axis` (non-zero) through `world_anchor`, at
 * translation 0 and with the relative angle it has now. Set limits, motor
 * or spring afterwards. On failure *def is left as it was. */
RB_API rb_status rb_prismatic_joint_def_at(rb_prismatic_joint_def *def, const rb_world *world, rb_body_id body_a,
                                           rb_body_id body_b, rb_vec2 world_anchor, rb_vec2 world_axis);

RB_API rb_status rb_prismatic_joint_create(rb_world *world, const rb_prismatic_joint_def *def, rb_joint_id *out);

RB_API double rb_prismatic_joint_translation(const rb_world *world, rb_joint_id joint); /**< m */
RB_API double rb_prismatic_joint_speed(const rb_world *world, rb_joint_id joint); /**< m/s, the translation's rate */
/** The force the motor applied along the axis in the last step (N). */
RB_API double rb_prismatic_joint_motor_force(const rb_world *world, rb_joint_id joint);
RB_API rb_status rb_prismatic_joint_set_motor(rb_world *world, rb_joint_id joint, bool enable, double speed,
                                              double max_force);
RB_API rb_status rb_prismatic_joint_set_limits(rb_world *world, rb_joint_id joint, bool enable_lower, double lower,
                                               bool enable_upper, double upper);
RB_API rb_status rb_prismatic_joint_set_spring(rb_world *world, rb_joint_id joint, bool enable, double hertz,
                                               double damping_ratio);
/** @} */

/** @name Pulley joints */
/** @{ */

/** A rope from anchor A over a pulley at ground_anchor_a, then over one at
 * ground_anchor_b down to anchor B (the pulleys are fixed world points):
 * with length_a = |anchor A - ground A| and length_b likewise,
 *   length_a + ratio·length_b <= constant = def.length_a + ratio·def.length_b.
 * A rope only pulls: it goes slack when the bodies come closer to their
 * pulleys. A body meets its pulley min_length from it and stops there
 * (the pulley pushes back), which keeps the rope's directions defined.
 * The reaction force is what the joint applied to body B: the rope's pull,
 * ratio times its tension, plus the push of B's pulley; body A is pulled
 * by the tension itself (the pulleys take the rest). */
typedef struct rb_pulley_joint_def {
    rb_body_id body_a, body_b;
    rb_vec2 ground_anchor_a, ground_anchor_b; /**< m, world, within ±RB_MAX_LENGTH */
    rb_vec2 local_anchor_a, local_anchor_b;   /**< m, in each body's frame, within ±RB_MAX_LENGTH */
    double length_a, length_b;                /**< m, min_length .. RB_MAX_LENGTH: the rope's two sides when taut */
    /** 1e-6 .. 1e6, default 1: how much side A pays out per metre of side B */
    double ratio;
    double min_length; /**< m, > 0 .. RB_MAX_LENGTH, default 0.05: how near a body comes to its pulley */
    bool collide_connected;
    void *user_data;
    /** Set by rb_default_pulley_joint_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_pulley_joint_def() and change fields. */
    int32_t internal_value;
} rb_pulley_joint_def;

RB_API rb_pulley_joint_def rb_default_pulley_joint_def(void);

/** Makes *def a complete definition: rb_default_pulley_joint_def() with the
 * bodies, ground anchors, local anchors (from the world points anchor_a
 * and anchor_b) and both lengths from the current poses, so that the rope
 * is just taut. Set ratio and min_length afterwards (the constant is
 * length_a + ratio·length_b). On failure *def is left as it was. */
RB_API rb_status rb_pulley_joint_def_between(rb_pulley_joint_def *def, const rb_world *world, rb_body_id body_a,
                                             rb_body_id body_b, rb_vec2 ground_anchor_a, rb_vec2 ground_anchor_b,
                                             rb_vec2 anchor_a, rb_vec2 anchor_b);

RB_API rb_status rb_pulley_joint_create(rb_world *world, const rb_pulley_joint_def *def, rb_joint_id *out);

/** The rope's two sides now: |anchor - ground anchor| (m). */
RB_API double rb_pulley_joint_length_a(const rb_world *world, rb_joint_id joint);
RB_API double rb_pulley_joint_length_b(const rb_world *world, rb_joint_id joint);
/** @} */

/** @name Every joint */
/** @{ */

RB_API rb_status rb_joint_destroy(rb_world *world, rb_joint_id joint);
RB_API bool rb_joint_is_valid(const rb_world *world, rb_joint_id joint);
RB_API rb_joint_type rb_joint_type_of(const rb_world *world, rb_joint_id joint);
/** A mouse joint has only body B; its body A is the null id. */
RB_API rb_body_id rb_joint_body_a(const rb_world *world, rb_joint_id joint);
RB_API rb_body_id rb_joint_body_b(const rb_world *world, rb_joint_id joint);
RB_API rb_vec2 rb_joint_world_anchor_a(const rb_world *world,
                                       rb_joint_id joint); /**< m; the target for a mouse joint */
RB_API rb_vec2 rb_joint_world_anchor_b(const rb_world *world, rb_joint_id joint); /**< m */
/** The force (N, world frame) and torque (N·m) the joint applied to body
 * B during the last substep of the last step: that substep's accumulated
 * impulses divided by the substep's duration h (at rest, the static
 * reaction). Body A received the opposite. */
RB_API rb_vec2 rb_joint_reaction_force(const rb_world *world, rb_joint_id joint);
RB_API double rb_joint_reaction_torque(const rb_world *world, rb_joint_id joint);
RB_API void *rb_joint_user_data(const rb_world *world, rb_joint_id joint);
RB_API rb_status rb_joint_set_user_data(rb_world *world, rb_joint_id joint, void *user_data);
/** @} */

#ifdef __cplusplus
}
#endif

#endif
