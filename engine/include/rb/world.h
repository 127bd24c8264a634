/* SPDX-License-Identifier: MIT */
/** @file
 * The world: bodies, shapes, contacts and the step that advances them.
 */
#ifndef RB_WORLD_H
#define RB_WORLD_H

#include <stdbool.h>
#include <stdint.h>

#include "rb/base.h"
#include "rb/collision.h"
#include "rb/export.h"
#include "rb/id.h"
#include "rb/math.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rb_world rb_world;

/** The world's solver: which algorithm turns contacts and joints into
 * impulses, and how it removes overlap and joint drift. All share the
 * same contact and joint data and can be switched between steps; each is
 * a file of its own in engine/src (solver_*.c). */
typedef enum rb_solver_type {
    /** Sequential impulses with a Baumgarte velocity bias
     * beta·(penetration - slop)/h inside the velocity iterations
     * (Baumgarte 1972; Box2D 2.0). Cheap; adds some energy. */
    RB_SOLVER_BAUMGARTE,
    /** Sequential impulses, then non-linear Gauss-Seidel: after the
     * positions are integrated, the solver moves the bodies directly, one
     * constraint at a time, for `position_iterations` passes (Catto,
     * Box2D 2.4). No energy added. */
    RB_SOLVER_NGS,
    /** Soft step (Catto, "Solver2D", 2024; Box2D v3): rigid rows become
     * stiff, heavily damped springs (contact_hertz, joint_hertz) solved
     * once per substep with their bias, then the positions move, then a
     * relax pass solves them again without bias so that the push-out
     * leaves no velocity behind. Stable for large mass ratios; the error
     * it leaves decays at the spring's rate. */
    RB_SOLVER_SOFT_STEP,
    RB_SOLVER_TYPE_COUNT
} rb_solver_type;

/** "baumgarte", "ngs", "soft_step"; "unknown" for a value out of range. */
RB_API const char *rb_solver_type_name(rb_solver_type type);
/** The type whose name is `name`; RB_ERR_INVALID_ARGUMENT naming the
 * choices when there is none. */
RB_API rb_status rb_solver_type_from_name(const char *name, rb_solver_type *type);

/** Solver settings, held by the world; see rb_world_set_solver_settings. */
typedef struct rb_solver_settings {
    rb_solver_type type;     /**< default RB_SOLVER_NGS */
    int velocity_iterations; /**< 1 .. 1000, per substep, default 2 */
    int position_iterations; /**< 0 .. 1000, per substep, default 1 (NGS; the soft step's joint trees) */
    int relax_iterations;    /**< 0 .. 1000, per substep, default 1 (soft step only) */
    int substeps;            /**< 1 .. 1000, default 6: the step dt is split into this many substeps */
    bool warm_starting;      /**< default true: start from last step's impulses */
    bool block_solver;       /**< default true: solve two-point manifolds as one 2x2 LCP (Baumgarte, NGS) */
    /** default true (NGS and soft step): solve the pins of joint trees whose heaviest
     * body is at least 100 times their lightest together, exactly, in every
     * pass (a rope with a heavy end stays a rope), and under NGS a small limb
     * of limited hinges whose heaviest body is at least 20 times its lightest
     * as one block (a stop holds a heavy load through a light bone); false
     * leaves every pin to Gauss-Seidel, one joint at a time, to study how mass
     * ratios defeat it */
    bool tree_pins;
    double baumgarte;   /**< 0 .. 1, fraction of the error removed per (sub)step, default 0.2 */
    double linear_slop; /**< m, 0 .. 0.1: penetration allowed without correction, default 0.005 */
    /** m, > 0 .. RB_MAX_LENGTH: largest position correction per iteration, default 0.2 */
    double max_linear_correction;
    double restitution_threshold; /**< m/s, 0 .. RB_MAX_SPEED: slower impacts do not bounce, default 1 */
    /** Soft step only. A contact is a spring of contact_hertz against a
     * body that moves and twice that against one that cannot; it pushes
     * overlapping bodies apart no faster than max_push_speed. Joints'
     * rigid rows are springs of joint_hertz. Each frequency is capped at
     * a quarter of the substep rate, where the implicit spring stays
     * accurate (Catto, Solver2D). */
    double contact_hertz;         /**< Hz, RB_MIN_HERTZ .. RB_MAX_HERTZ, default 30 */
    double contact_damping_ratio; /**< 0 .. RB_MAX_DAMPING_RATIO, default 10 (critically damped is 1) */
    double joint_hertz;           /**< Hz, RB_MIN_HERTZ .. RB_MAX_HERTZ, default 60 */
    double joint_damping_ratio;   /**< 0 .. RB_MAX_DAMPING_RATIO, default 2 */
    double max_push_speed;        /**< m/s, > 0 .. RB_MAX_SPEED, default 3 */
} rb_solver_settings;

typedef struct rb_world_def {
    rb_vec2 gravity;           /**< m/s², each component within ±RB_MAX_ACCELERATION, default (0, -9.8) */
    rb_solver_settings solver; /**< default rb_default_solver_settings() */
    /** Time each phase of the step into rb_world_profile() (default true).
     * The clock reads cost about 0.3 µs a step: a tenth of a small
     * model's step, nothing for a large scene. */
    bool enable_profile;
    /** Let resting islands fall asleep (default true; see rb_body_def.awake). */
    bool enable_sleep;
    /** Set by rb_default_world_def() and checked by the create function, which refuses a
     * definition that does not carry it (left uninitialised, or garbage)
     * rather than simulate it: start from rb_default_world_def() and change fields. */
    int32_t internal_value;
} rb_world_def;

/** Time spent in each phase of the last step, in milliseconds. */
typedef struct rb_profile {
    double step;
    double pairs;            /**< broad phase: find overlapping bounding boxes */
    double collide;          /**< narrow phase: manifolds, impulse carry-over */
    double prepare;          /**< constraint set-up */
    double substep_callback; /**< the user's, see rb_world_set_substep_callback */
    double integrate_velocities;
    double warm_start;
    double solve_velocities;
    double integrate_positions;
    double correct_positions; /**< NGS position passes; the soft step's pass over joint trees */
    double relax;             /**< soft step's relax passes */
    double restitution;
    double store_impulses;
    double islands;  /**< islands: wake the ones touched, put the resting ones to sleep */
    double sensors;  /**< sensor overlaps at the final poses */
    double finalize; /**< transforms, bounding boxes, clearing forces */
} rb_profile;

/** Counters of the last step. */
typedef struct rb_statistics {
    int body_count;
    int awake_body_count; /**< dynamic bodies awake after the step */
    int island_count;     /**< groups of dynamic bodies linked by touching contacts, joints and cables */
    int shape_count;
    int pair_count; /**< shape pairs that may collide and whose fat bounding boxes overlap: the contacts */
    /** steps so far in which the broad phase found all its candidate
     * pairs anew (shapes came or went, which shapes may collide changed,
     * or many shapes had left their fat boxes) */
    int broad_phase_sweeps;
    /** steps so far in which a few shapes had left their fat boxes and
     * only their candidate pairs were found anew */
    int broad_phase_requeries;
    /** shapes whose fat box was made anew in the last step, having left
     * it (every shape in a step with a full search); 0 for a pile at rest */
    int broad_phase_moved;
    /** fat-box overlap tests the broad phase made in the last step around
     * the moved shapes (0 in a step with a full search, or with nothing moved) */
    int broad_phase_box_tests;
    /** shapes whose swept box was made in the last step: those of the
     * bodies awake or moving (every shape after shapes came or went, a
     * body was placed or the settings changed); 0 for a pile asleep */
    int broad_phase_boxes;
    /** pairs of shapes whose fat boxes began or stopped overlapping in the
     * last step: the contacts made and ended */
    int broad_phase_new_pairs;
    int broad_phase_ended_pairs;
    int contact_count; /**< pairs with at least one manifold point */
    int manifold_point_count;
    /** colours the contact constraints were solved in (a colour's
     * constraints share no moving body; the overflow colour counts) */
    int contact_colours;
    int velocity_iterations; /**< done in the last step, summed over substeps */
    int position_iterations; /**< NGS passes done in the last step, summed over substeps */
    int relax_iterations;    /**< soft step relax passes done in the last step, summed over substeps */
    /** m, >= 0: deepest overlap left after the step at the step's contact
     * points. Their overlap is read at the points as the solver carries
     * them with the bodies (first-order); beyond four linear slops it is
     * measured again by the narrow phase at the final poses. Two shapes
     * that met within the step without a contact point (pushed together
     * by a third faster than the speculative margin allowed for) are not
     * counted before the next step. */
    double max_penetration;
    int joint_count;
    /** m, >= 0, after the step: the largest distance between the two
     * anchors of a pin or rigid weld, between a distance joint's length
     * and what its bar or limits allow, of a prismatic joint's anchor B
     * off its axis or beyond a limit, or of a pulley's rope beyond its
     * length or a side beyond its stop. */
    double max_joint_gap;
    /** rad, >= 0, after the step: the largest rigid weld or prismatic
     * angle error, or revolute limit violation. */
    double max_joint_angle_error;
    /** J, after the step: the dynamic bodies' kinetic energy ½m·v² + ½I·ω²
     * plus their potential energy -m·(gravity_scale·g)·x in the world's
     * gravity (zero at the origin). Constant for a conservative system up
     * to the integrator's error; what solvers add or remove shows here. */
    double energy;
} rb_statistics;

RB_API rb_solver_settings rb_default_solver_settings(void);
RB_API rb_world_def rb_default_world_def(void);

/** Validates every field of def; on failure *out is NULL. */
RB_API rb_status rb_world_create(const rb_world_def *def, rb_world **out);

/** Frees the world and everything in it. Accepts NULL. */
RB_API void rb_world_destroy(rb_world *world);

/** Advances the world by dt seconds (RB_MIN_STEP .. RB_MAX_STEP).
 *
 * Should the step leave a body's pose or velocity NaN or infinite (the
 * arguments were in range, but the motion overflowed: a stack fed
 * energy until it blew up), it fails with RB_ERR_NOT_FINITE, naming the
 * first such body, its state and where it was before the step, and puts
 * every body's pose and velocity back as they were before the step. The
 * joints', cables' and contacts' warm-start impulses, made non-finite by
 * the same failure, start again from 0; the forces applied for the step
 * are kept, and the contact events of the step are reported as usual.
 * The world can then be changed (a body moved, a joint removed, the
 * settings made stiffer) and stepped again; stepped again unchanged it
 * fails again. */
RB_API rb_status rb_world_step(rb_world *world, double dt);

RB_API rb_status rb_world_set_gravity(rb_world *world, rb_vec2 gravity);
RB_API rb_vec2 rb_world_gravity(const rb_world *world);

RB_API rb_status rb_world_set_solver_settings(rb_world *world, const rb_solver_settings *settings);
RB_API rb_solver_settings rb_world_solver_settings(const rb_world *world);

/** A function the step calls at the start of every substep, before
 * gravity and forces act, with the substep's index (0 .. substeps - 1)
 * and length h (s). The bodies are at the substep's starting poses and
 * velocities, and rb_cable_tension() gives the previous substep's
 * tension. It may read anything and set cable tension laws
 * (rb_cable_set_tension_law); every other change is refused with
 * RB_ERR_LOCKED, since the step is under way.
 *
 * This is how a force that depends on the state (a muscle's) is updated
 * every substep while the broad and narrow phases run once per step. */
typedef void rb_substep_fn(rb_world *world, int substep, double h, void *context);

/** Replaces the callback; NULL removes it. Not allowed during a step. */
RB_API rb_status rb_world_set_substep_callback(rb_world *world, rb_substep_fn *callback, void *context);

/** All zero while profiling is off. */
RB_API rb_profile rb_world_profile(const rb_world *world);
RB_API rb_status rb_world_enable_profile(rb_world *world, bool enable);
RB_API rb_statistics rb_world_statistics(const rb_world *world);

/** Disabling sleep wakes every body. */
RB_API rb_status rb_world_enable_sleep(rb_world *world, bool enable);
RB_API bool rb_world_is_sleep_enabled(const rb_world *world);

/** Bytes this world holds now. */
RB_API size_t rb_world_bytes_in_use(const rb_world *world);

/** A 64-bit hash (FNV-1a) of the bit patterns of every body's position,
 * angle and velocities, in body order: equal hashes mean bit-identical
 * states. */
RB_API uint64_t rb_world_state_hash(const rb_world *world);

/** Contacts, in the world's deterministic order. */
typedef struct rb_contact_data {
    rb_shape_id shape_a, shape_b;
    rb_body_id body_a, body_b;
    bool touching;        /**< some point has separation <= 0 */
    bool sensor;          /**< one shape is a sensor: overlap only, no response */
    rb_manifold manifold; /**< world-space manifold, normal from A to B */
} rb_contact_data;

RB_API int rb_world_contact_count(const rb_world *world);
/** Copies up to `capacity` contacts into out; returns how many it copied. */
RB_API int rb_world_contacts(const rb_world *world, rb_contact_data *out, int capacity);

#ifdef __cplusplus
}
#endif

#endif
