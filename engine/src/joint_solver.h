/* Joints in the solver: the steps every joint type takes in a substep,
 * dispatched on the type, and the helpers the types share.
 *
 * Conventions: an impulse P acts on body B at its anchor and -P on body A
 * at its anchor; angular impulses likewise (+L on B, -L on A). Rigid
 * parts are corrected by the world's method: a Baumgarte velocity bias,
 * or NGS position passes after the positions are integrated. Joints
 * correct their whole error in an NGS pass (capped), unlike contacts:
 * an equality constraint does not chatter the way a stack of contacts
 * does (Catto, Box2D 2.x). */
#ifndef RB_JOINT_SOLVER_H
#define RB_JOINT_SOLVER_H

#include "world_internal.h"

/* Largest angular correction of one NGS pass (rad), as the linear cap. */
#define RB_MAX_ANGULAR_CORRECTION (8.0 * RB_PI / 180.0)
/* Angles within this are treated as met by NGS (rad). */
#define RB_ANGULAR_SLOP (0.5 * RB_PI / 180.0)

/* ---- the phases, over every joint --------------------------------------- */

/* Refreshes each joint's frame (masses, anchors at the current poses) and
 * its type's per-substep data for a substep of length h. */
void rb_joints_prepare(rb_world *world, double h);
void rb_joints_warm_start(rb_world *world);
/* One pass over the joints, in creation order or (backwards) the reverse.
 * The solver alternates: in a chain an impulse travels one joint per pass
 * in the pass's direction, so alternating sweeps (symmetric Gauss-Seidel)
 * carry both ends' information in half the passes; a 10-link chain's
 * worst gap at 60 Hz drops from 8.3 to 5.6 mm at the same cost. */
void rb_joints_solve_velocities(rb_world *world, double h, bool backwards);
/* One NGS pass, in either order; returns whether every joint was within
 * its tolerance. */
bool rb_joints_correct_positions(rb_world *world, bool backwards);
/* Zeroes the accumulated impulses (warm starting off). */
void rb_joints_reset_impulses(rb_world *world);
/* The largest anchor gap (m) and angle error (rad) over the joints. */
void rb_joints_measure_errors(const rb_world *world, double *max_gap, double *max_angle);

/* ---- shared by the joint types ------------------------------------------- */

/* Soft constraint coefficients (Catto, "Soft Constraints", GDC 2011): a
 * spring of natural frequency `hertz` and damping ratio `zeta` acting on
 * effective mass m, integrated implicitly over h, gives
 *   k = m·ω², c = 2·m·ζ·ω, ω = 2π·hertz,
 *   gamma = 1/(h·(c + h·k)),  bias_rate = h·k·gamma,
 * and the impulse λ = -(Cdot + bias_rate·C + gamma·λ_acc)/(1/m + gamma). */
typedef struct rb_softness {
    double gamma;     /* 1/kg (or 1/(kg·m²)) added to the inverse effective mass */
    double bias_rate; /* 1/s, multiplies the position error */
} rb_softness;
rb_softness rb_make_softness(double hertz, double zeta, double effective_mass, double h);

/* The Baumgarte bias rate (1/s) of a rigid joint part: the velocity bias
 * is rate·C. Zero when the world corrects positions by NGS. It removes the
 * fraction beta of the error per step of dt = h·substeps, not per
 * substep: per substep the fractions compound (beta = 0.2 over 6
 * substeps is 74 % per step), and warm starting carries the bias impulses
 * on, until a hanging chain diverges. */
double rb_joint_baumgarte_rate(const rb_world *world, double h);

rb_body_state *rb_joint_state_a(rb_world *world, const rb_joint *joint); /* NULL for a mouse joint */
rb_body_state *rb_joint_state_b(rb_world *world, const rb_joint *joint);
/* Applies P at the anchors: -P to A, +P to B. */
void rb_joint_apply_linear(const rb_joint *joint, rb_body_state *a, rb_body_state *b, rb_vec2 impulse);
/* Applies L about the centres: -L to A, +L to B. */
void rb_joint_apply_angular(const rb_joint *joint, rb_body_state *a, rb_body_state *b, double impulse);
/* Velocity of anchor B relative to anchor A. */
rb_vec2 rb_joint_relative_velocity(const rb_joint *joint, const rb_body_state *a, const rb_body_state *b);
/* World anchor points at the poses now. */
rb_vec2 rb_joint_anchor_a(const rb_world *world, const rb_joint *joint);
rb_vec2 rb_joint_anchor_b(const rb_world *world, const rb_joint *joint);
/* The force (N) the joint applied to body B in the last substep. */
rb_vec2 rb_joint_force_on_b(const rb_world *world, const rb_joint *joint);
/* angle(B) - angle(A) - reference. */
double rb_joint_relative_angle(const rb_world *world, const rb_joint *joint, double reference);

/* The point constraint shared by revolute and weld joints: the anchors
 * coincide. Optionally solved together with one angular row
 * sign·(ωB - ωA) + bias = 0 whose impulse accumulates in *accumulated,
 * kept >= 0 when one_sided (a limit). */
typedef struct rb_angular_row {
    double sign; /* +1 or -1 */
    double bias; /* rad/s */
    double *accumulated;
    bool one_sided;
} rb_angular_row;

/* Sets the frame's point_mass and point_drift for the substep; after
 * the frame is prepared, before any solve. */
void rb_point_constraint_prepare(const rb_world *world, rb_joint *joint, double h);
/* Velocity solve of the pin (and the row, if not NULL), with the
 * Baumgarte bias when the world uses it. */
void rb_point_constraint_solve(rb_world *world, rb_joint *joint, rb_vec2 *accumulated, double h,
                               const rb_angular_row *row);
/* One NGS pass that moves the bodies to close the gap and, when
 * angle_error is not NULL, to remove that much relative angle (rad,
 * angle(B) - angle(A) - target) at the same time; returns the gap before. */
double rb_point_constraint_correct(rb_world *world, rb_joint *joint, const double *angle_error);

/* ---- the types ------------------------------------------------------------ */

void rb_revolute_prepare(rb_world *world, rb_joint *joint, double h);
void rb_revolute_warm_start(rb_world *world, rb_joint *joint);
void rb_revolute_solve(rb_world *world, rb_joint *joint, double h);
bool rb_revolute_correct(rb_world *world, rb_joint *joint);
double rb_revolute_angle_error(const rb_world *world, const rb_joint *joint);

void rb_weld_prepare(rb_world *world, rb_joint *joint, double h);
void rb_weld_warm_start(rb_world *world, rb_joint *joint);
void rb_weld_solve(rb_world *world, rb_joint *joint, double h);
bool rb_weld_correct(rb_world *world, rb_joint *joint);
double rb_weld_angle_error(const rb_world *world, const rb_joint *joint);

void rb_distance_prepare(rb_world *world, rb_joint *joint, double h);
void rb_distance_warm_start(rb_world *world, rb_joint *joint);
void rb_distance_solve(rb_world *world, rb_joint *joint, double h);
bool rb_distance_correct(rb_world *world, rb_joint *joint);
double rb_distance_error(const rb_world *world, const rb_joint *joint);

void rb_mouse_prepare(rb_world *world, rb_joint *joint, double h);
void rb_mouse_warm_start(rb_world *world, rb_joint *joint);
void rb_mouse_solve(rb_world *world, rb_joint *joint, double h);

#endif
