/* SPDX-License-Identifier: MIT */
/* Joints in the solver: the steps every joint type takes in a substep,
 * dispatched on the type, and the helpers the types share.
 *
 * Conventions: an impulse P acts on body B at its anchor and -P on body A
 * at its anchor; angular impulses likewise (+L on B, -L on A). Rigid
 * parts are corrected as the world's solver sets world->joint_response:
 * a Baumgarte velocity bias, a soft step's spring, or nothing in the
 * velocity pass when NGS position passes follow the integration. Joints
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

/* Lists the joints the step solves (in use, with a dynamic awake body), in
 * creation order; the phases below visit only these. Bodies neither fall
 * asleep nor wake within a step, so the list holds for the whole step.
 * Prepares, once for the step, what the step cannot change: each frame's
 * masses and anchors in the body frames, and its type's constants (the
 * axial masses, the impulses of disabled motors, springs and limits
 * zeroed). */
rb_status rb_joints_collect_active(rb_world *world);

/* The joints the passes below visit this step, in the order they visit
 * them: the active ones less the plain pins the trees solve whole
 * (joint_tree.h), in creation order, or in the order of
 * rb_joints_order has run. */
const int *rb_joint_pass_list(const rb_world *world, int *count);
/* The passes' order (joint_order.c): from now until the next
 * rb_joints_collect_active, the passes visit the joints `scope` names
 * from the deepest (the most joints away from a body they cannot move)
 * to those at the supports, colour by colour within a depth; with
 * RB_ORDER_PLAIN_PINS the other joints come first, in the order they
 * were made. After the trees are found, before rb_pins_gather. */
void rb_joints_order(rb_world *world, rb_joint_order_scope scope);

/* At the step's first substep, after its velocities are integrated and
 * before any warm start: records every body's angular velocity, from
 * which the pins' drift is computed. In later substeps the integration
 * records the moving bodies' (rb_solver_integrate_velocities); the
 * others' cannot change within a step. */
void rb_joints_prepare(rb_world *world);
/* Visits each joint once a substep of length h, in the pass list's order
 * (rb_joint_pass_list) or (backwards) the reverse: prepares what moves with the bodies (the
 * anchors turned into the world at the poses now, the pins' mass matrices
 * and drift, the distance joints' axes), then warm starts it with its
 * accumulated impulses. One pass where two passes over every joint would
 * each read it from memory. */
void rb_joints_warm_start(rb_world *world, double h, bool backwards);
/* One pass over the joints, in the pass list's order or (backwards) the
 * reverse, but for the plain pins their trees solve (joint_tree.h), which both
 * passes leave to the trees. NGS and Baumgarte alternate: in a chain an
 * impulse travels one joint per pass in the pass's direction, so
 * alternating sweeps (symmetric Gauss-Seidel) carry both ends'
 * information in half the passes; a 10-link chain's worst gap at 60 Hz
 * drops from 8.3 to 5.6 mm at the same cost. The soft step sweeps one way
 * only, in its own order (solver_soft_step.c, joint_order.c). */
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

/* The soft step's spring on a rigid row (Catto, "Solver2D", 2024): the
 * coefficients of rb_make_softness written for any effective mass m.
 * With k = m·ω² and c = 2·m·ζ·ω, gamma = 1/(m·a2) and bias_rate = ω/a1,
 * where a1 = 2ζ + h·ω and a2 = h·ω·a1; the impulse
 * -(Cdot + bias_rate·C + gamma·λ)/(1/m + gamma) then reads
 * -mass_scale·m·(Cdot + bias_rate·C) - impulse_scale·λ with
 * mass_scale = a2/(1 + a2) and impulse_scale = 1/(1 + a2). */
rb_rigid_response rb_make_rigid_softness(double hertz, double zeta, double h);

/* The impulse of a two-sided rigid row of effective mass `mass`, rate
 * cdot and position error c under the pass's response. */
static inline double rb_rigid_row_impulse(const rb_world *world, double mass, double cdot, double c, double accumulated)
{
    const rb_rigid_response *r = &world->joint_response;
    return -r->mass_scale * mass * (cdot + r->bias_rate * c) - r->impulse_scale * accumulated;
}

/* A block's rigid solution x = -K⁻¹·(Cdot + bias) as the pass's
 * response delivers it: mass_scale·x - impulse_scale·λ_accumulated. */
static inline rb_vec2 rb_soften(const rb_rigid_response *response, rb_vec2 rigid, rb_vec2 accumulated)
{
    return rb_sub(rb_scale(response->mass_scale, rigid), rb_scale(response->impulse_scale, accumulated));
}

/* The velocity bias of a one-sided row whose margin c is >= 0 while met:
 * while open it may close at c/h, no faster (speculative); once violated,
 * the pass's response pushes it back (nothing under NGS, which moves the
 * bodies instead). */
static inline double rb_one_sided_bias(const rb_world *world, double c, double h)
{
    return c > 0.0 ? c / h : world->joint_response.bias_rate * c;
}

/* The new accumulated impulse (>= 0) of a one-sided row: an open row is
 * rigid with its speculative bias; a violated one answers as the pass's
 * response. */
static inline double rb_one_sided_row_total(const rb_world *world, double mass, double cdot, double c, double h,
                                            double accumulated)
{
    double impulse = c > 0.0 ? -mass * (cdot + c / h) : rb_rigid_row_impulse(world, mass, cdot, c, accumulated);
    const double total = accumulated + impulse;
    return total > 0.0 ? total : 0.0; /* fmax(total, 0), NaN and -0 included, without libm's call */
}

rb_body_state *rb_joint_state_a(rb_world *world, const rb_joint *joint); /* NULL for a mouse joint */
rb_body_state *rb_joint_state_b(rb_world *world, const rb_joint *joint);
/* Applies P at anchors ra of A and rb of B (world offsets from the
 * centres), on bodies of these inverse masses: -P to A (NULL: a fixed
 * point), +P to B. Inline, with the next ones: every joint row calls them
 * in every pass. */
static inline void rb_apply_at_anchors(rb_body_state *a, rb_body_state *b, double inv_mass_a, double inv_inertia_a,
                                       double inv_mass_b, double inv_inertia_b, rb_vec2 ra, rb_vec2 rb, rb_vec2 impulse)
{
    if (a != NULL) {
        a->linear_velocity = rb_mul_sub(a->linear_velocity, inv_mass_a, impulse);
        a->angular_velocity -= inv_inertia_a * rb_cross(ra, impulse);
    }
    b->linear_velocity = rb_mul_add(b->linear_velocity, inv_mass_b, impulse);
    b->angular_velocity += inv_inertia_b * rb_cross(rb, impulse);
}

static inline void rb_frame_apply_linear(const rb_joint_frame *f, rb_body_state *a, rb_body_state *b, rb_vec2 impulse)
{
    rb_apply_at_anchors(a, b, f->inv_mass_a, f->inv_inertia_a, f->inv_mass_b, f->inv_inertia_b, f->ra, f->rb, impulse);
}

static inline void rb_joint_apply_linear(const rb_joint *joint, rb_body_state *a, rb_body_state *b, rb_vec2 impulse)
{
    rb_frame_apply_linear(&joint->frame, a, b, impulse);
}

/* Applies L about the centres: -L to A, +L to B. */
static inline void rb_joint_apply_angular(const rb_joint *joint, rb_body_state *a, rb_body_state *b, double impulse)
{
    if (a != NULL) {
        a->angular_velocity -= joint->frame.inv_inertia_a * impulse;
    }
    b->angular_velocity += joint->frame.inv_inertia_b * impulse;
}

/* Velocity of anchor B relative to anchor A. */
static inline rb_vec2 rb_frame_relative_velocity(const rb_joint_frame *f, const rb_body_state *a,
                                                 const rb_body_state *b)
{
    rb_vec2 vb = rb_add(b->linear_velocity, rb_cross_sv(b->angular_velocity, f->rb));
    if (a == NULL) {
        return vb;
    }
    rb_vec2 va = rb_add(a->linear_velocity, rb_cross_sv(a->angular_velocity, f->ra));
    return rb_sub(vb, va);
}

static inline rb_vec2 rb_joint_relative_velocity(const rb_joint *joint, const rb_body_state *a, const rb_body_state *b)
{
    return rb_frame_relative_velocity(&joint->frame, a, b);
}
/* World anchor points at the poses now. */
rb_vec2 rb_joint_anchor_a(const rb_world *world, const rb_joint *joint);
rb_vec2 rb_joint_anchor_b(const rb_world *world, const rb_joint *joint);
/* The force (N) the joint applied to body B in the last substep. */
rb_vec2 rb_joint_force_on_b(const rb_world *world, const rb_joint *joint);
/* angle(B) - angle(A) - reference. */
double rb_joint_relative_angle(const rb_world *world, const rb_joint *joint, double reference);

/* Solves the 2x2 block K2·x = v; false when K2 is not positive definite.
 * Inline: it runs in the innermost loop of every pin. */
static inline bool rb_block_solve2(const rb_block_matrix *k, rb_vec2 v, rb_vec2 *x)
{
    double det = k->k11 * k->k22 - k->k12 * k->k12;
    if (!(det > 0.0)) {
        return false;
    }
    double inverse_det = 1.0 / det; /* one division instead of two */
    *x = rb_v2((k->k22 * v.x - k->k12 * v.y) * inverse_det, (k->k11 * v.y - k->k12 * v.x) * inverse_det);
    return true;
}

/* Solves K·(x, z) = (v, w) by Cramer's rule; false when K is singular
 * (a body that cannot turn makes an angle row redundant). */
static inline bool rb_block_solve3(const rb_block_matrix *k, rb_vec2 v, double w, rb_vec2 *x, double *z)
{
    double c11 = k->k22 * k->k33 - k->k23 * k->k23;
    double c12 = k->k13 * k->k23 - k->k12 * k->k33;
    double c13 = k->k12 * k->k23 - k->k13 * k->k22;
    double det = k->k11 * c11 + k->k12 * c12 + k->k13 * c13;
    if (!(fabs(det) > 1e-300)) {
        return false;
    }
    double c22 = k->k11 * k->k33 - k->k13 * k->k13;
    double c23 = k->k13 * k->k12 - k->k11 * k->k23;
    double c33 = k->k11 * k->k22 - k->k12 * k->k12;
    *x = rb_v2((c11 * v.x + c12 * v.y + c13 * w) / det, (c12 * v.x + c22 * v.y + c23 * w) / det);
    *z = (c13 * v.x + c23 * v.y + c33 * w) / det;
    return true;
}

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

/* The point's velocity error in a pass: Cdot less the substep's
 * centripetal drift (rb_point_constraint_prepare_drift), plus the
 * response's bias on the anchors' gap at the current poses. */
static inline rb_vec2 rb_point_frame_velocity_error(const rb_world *world, const rb_joint_frame *f,
                                                    const rb_body_state *a, const rb_body_state *b)
{
    rb_vec2 cdot = rb_sub(rb_frame_relative_velocity(f, a, b), f->point_drift);
    const rb_rigid_response *response = &world->joint_response;
    if (response->bias_rate > 0.0) {
        rb_vec2 gap = rb_sub(rb_add(b->center, f->rb), rb_add(a->center, f->ra));
        cdot = rb_mul_add(cdot, response->bias_rate, gap);
    }
    return cdot;
}

static inline rb_vec2 rb_point_velocity_error(const rb_world *world, const rb_joint *joint, const rb_body_state *a,
                                              const rb_body_state *b)
{
    return rb_point_frame_velocity_error(world, &joint->frame, a, b);
}

/* The pin alone, for its velocity error cdot: x = -K⁻¹·cdot with the
 * substep's inverse (0 when K is singular, which only two bodies that
 * cannot move make), as the pass's response delivers it, added to
 * *accumulated and applied at the anchors. Inline: the joint grid's and
 * the chains' pins run it in every velocity pass. */
static inline void rb_point_alone_solve(const rb_world *world, const rb_joint_frame *f, rb_body_state *a,
                                        rb_body_state *b, rb_vec2 cdot, rb_vec2 *accumulated)
{
    rb_vec2 impulse = rb_v2(-(f->point_inverse11 * cdot.x + f->point_inverse12 * cdot.y),
                            -(f->point_inverse12 * cdot.x + f->point_inverse22 * cdot.y));
    impulse = rb_soften(&world->joint_response, impulse, *accumulated);
    *accumulated = rb_add(*accumulated, impulse);
    rb_frame_apply_linear(f, a, b, impulse);
}

/* Sets the joint's point block (K, and its cofactors for a pin with an
 * angular row) and the frame's point_drift for the substep; after
 * the frame is prepared, before any solve. A pin its limb block solves
 * (joint->in_block) gets only the drift: the block makes its own K, and
 * gives the pin the rest when it cannot factor (joint_block.h). */
void rb_point_constraint_prepare(const rb_world *world, rb_joint *joint, double h);
/* The point block alone, from the frame as it is. */
void rb_point_constraint_prepare_matrices(const rb_world *world, rb_joint *joint);
/* The largest drift rb_point_drift asks for in a substep of length h:
 * one linear slop per substep (m/s). */
static inline double rb_point_drift_cap(const rb_world *world, double h) { return world->settings.linear_slop / h; }

/* The velocity a pin asks of its anchors' separation in a substep of
 * length h so that they still meet at its end while their offsets ra and
 * rb turn with the bodies (m/s; the centripetal drift). Inline: every
 * pin's substep computes it. */
static inline rb_vec2 rb_point_drift(const rb_world *world, int body_a, int body_b, rb_vec2 ra, rb_vec2 rb, double h,
                                     double drift_cap)
{
    /* Solve for the velocities that keep the anchors together at the end
     * of the substep, not just momentarily (SHAKE; Ryckaert, Ciccotti,
     * Berendsen, J. Comput. Phys. 23, 1977): the anchor offsets turn with
     * their bodies while the positions advance, each by
     * h·ω × r - ½·(h·ω)²·r to second order, so the gap grows by h times
     * Cdot - ½·h·(ωB²·rB - ωA²·rA). Asking for Cdot alone leaves that
     * centripetal drift for the position pass, which removes it without
     * the matching velocity, and a pendulum then loses energy every
     * swing (Box2D 2.4 loses 86 % of a 90° swing's energy in 200 s).
     *
     * The drift is the curvature of one substep's path: millimetres for
     * any body the solver can follow. A larger one means bodies spin
     * faster than the iterations converge (a light link beside a heavy
     * one), and asking for it then feeds the spin until it explodes; it is
     * capped at one linear slop per substep (drift_cap, m/s, from
     * rb_point_drift_cap). The angular velocities are
     * the substep's starting ones (rb_joints_prepare recorded them before
     * any warm start), so the drift is fixed for the substep. */
    const double omega_a = world->substep_omega[body_a];
    const double omega_b = world->substep_omega[body_b];
    rb_vec2 drift = rb_scale(0.5 * h, rb_sub(rb_scale(omega_b * omega_b, rb), rb_scale(omega_a * omega_a, ra)));
    if (rb_length_squared(drift) > drift_cap * drift_cap) { /* a square root only when capping */
        drift = rb_scale(drift_cap / rb_length(drift), drift);
    }
    return drift;
}

/* Sets only the frame's point_drift: what a pin its tree solves needs
 * (joint_tree.h). */
void rb_point_constraint_prepare_drift(const rb_world *world, rb_joint *joint, double h);
/* Velocity solve of the pin (and the row, if not NULL) under the pass's
 * response; the row's bias is its own. a and b are the joint's body
 * states, which the caller has already looked up. */
void rb_point_constraint_solve(const rb_world *world, const rb_joint *joint, rb_body_state *a, rb_body_state *b,
                               rb_vec2 *accumulated, const rb_angular_row *row);
/* One NGS pass that moves the bodies to close the gap and, when
 * angle_error is not NULL, to remove that much relative angle (rad,
 * angle(B) - angle(A) - target) at the same time; returns the gap before. */
double rb_point_constraint_correct(rb_world *world, rb_joint *joint, const double *angle_error);

/* ---- the plain pins' rows (joint_pin.c) ------------------------------------ */

/* At the first substep, once the trees are found: gathers the active
 * plain pins that no tree solves into world->pin_rows, in the order of
 * the pass list (rb_joint_pass_list), with their masses, anchors and impulses; from then
 * on the phases below read the rows for them, not the joints. */
void rb_pins_gather(rb_world *world);
/* Row `row`'s substep: its anchors in the world at the poses now, its
 * point inverse and drift, as rb_point_constraint_prepare sets a joint's,
 * then the warm start with its impulse (joint_pin.c). */
void rb_pin_warm_start(rb_world *world, int row, double h);
/* A velocity pass of the row, under the pass's response. Inline: the
 * joint grid runs it 160,000 to 240,000 times a step. */
static inline void rb_pin_solve(rb_world *world, rb_pin_row *row)
{
    /* The row's frame, as the joint's would be; the compiler keeps it in
     * registers. */
    const rb_joint_frame f = {
        .inv_mass_a = row->inv_mass_a,
        .inv_inertia_a = row->inv_inertia_a,
        .inv_mass_b = row->inv_mass_b,
        .inv_inertia_b = row->inv_inertia_b,
        .ra = row->ra,
        .rb = row->rb,
        .point_inverse11 = row->point_inverse11,
        .point_inverse12 = row->point_inverse12,
        .point_inverse22 = row->point_inverse22,
        .point_drift = row->point_drift,
    };
    rb_body_state *a = &world->states[row->body_a];
    rb_body_state *b = &world->states[row->body_b];
    rb_point_alone_solve(world, &f, a, b, rb_point_frame_velocity_error(world, &f, a, b), &row->impulse);
}
/* A velocity pass of a row under a rigid response (NGS's and 2.4's:
 * mass scale 1, impulse scale 0, no bias), where rb_pin_solve's
 * softening, P·1 - 0·(accumulated), returns the rigid impulse itself:
 * the same arithmetic less six products and a branch a pin, to the same
 * bits. Inline, as rb_pin_solve. The pin's velocity error Cdot = vB + ωB × rB - vA - ωA × rA,
 * less the drift its substep asks for (joint_point.c), is removed by
 * P = -K⁻¹·Cdot with the substep's inverse. */
static inline void rb_pin_solve_rigid(rb_body_state *states, rb_pin_row *row)
{
    rb_body_state *a = &states[row->body_a];
    rb_body_state *b = &states[row->body_b];
    const rb_vec2 ra = row->ra;
    const rb_vec2 rb = row->rb;
    const rb_vec2 vb = rb_add(b->linear_velocity, rb_cross_sv(b->angular_velocity, rb));
    const rb_vec2 va = rb_add(a->linear_velocity, rb_cross_sv(a->angular_velocity, ra));
    const rb_vec2 cdot = rb_sub(rb_sub(vb, va), row->point_drift);
    const rb_vec2 impulse = rb_v2(-(row->point_inverse11 * cdot.x + row->point_inverse12 * cdot.y),
                                  -(row->point_inverse12 * cdot.x + row->point_inverse22 * cdot.y));
    row->impulse = rb_add(row->impulse, impulse);
    rb_apply_at_anchors(a, b, row->inv_mass_a, row->inv_inertia_a, row->inv_mass_b, row->inv_inertia_b, ra, rb,
                        impulse);
}

/* An NGS pass of row `row`; true when its gap was within the linear slop. */
bool rb_pin_correct(rb_world *world, int row);
/* Whole passes over the rows, in their order or backwards, for a pass
 * whose joints are all rows (the joint grid): a warm start, an NGS
 * position pass (true when every gap was within the linear slop). */
void rb_pins_warm_start(rb_world *world, double h, bool backwards);
bool rb_pins_correct_positions(rb_world *world, bool backwards);
/* A velocity pass over every row: under the rigid response, as
 * rb_pin_solve_rigid solves each; under any, as rb_pin_solve does. These
 * passes take two rows at once where they can (pin_rows_two.c), to the
 * same bits. */
void rb_pins_solve_rigid(rb_world *world, bool backwards);
void rb_pins_solve(rb_world *world, bool backwards);
/* At the end of the step: the rows' impulses back into their joints. */
void rb_pins_scatter(rb_world *world);
/* The impulse of a plain pin's point: its row's within a step, else its
 * joint's. */
rb_vec2 rb_pin_impulse(const rb_world *world, const rb_joint *joint);

/* ---- the types ------------------------------------------------------------ */

void rb_revolute_prepare_step(rb_joint *joint);
/* Prepares the pin for the substep of length h (joint_point.c), then
 * warm starts it. */
void rb_revolute_warm_start(rb_world *world, rb_joint *joint, double h);
void rb_revolute_solve(rb_world *world, rb_joint *joint, double h);
bool rb_revolute_correct(rb_world *world, rb_joint *joint);
double rb_revolute_angle_error(const rb_world *world, const rb_joint *joint);

void rb_weld_prepare_step(rb_joint *joint);
void rb_weld_warm_start(rb_world *world, rb_joint *joint);
void rb_weld_solve(rb_world *world, rb_joint *joint, double h);
bool rb_weld_correct(rb_world *world, rb_joint *joint);
double rb_weld_angle_error(const rb_world *world, const rb_joint *joint);

void rb_distance_prepare_step(rb_joint *joint);
void rb_distance_prepare(const rb_world *world, rb_joint *joint);
void rb_distance_warm_start(rb_world *world, rb_joint *joint);
void rb_distance_solve(rb_world *world, rb_joint *joint, double h);
bool rb_distance_correct(rb_world *world, rb_joint *joint);
double rb_distance_error(const rb_world *world, const rb_joint *joint);

void rb_mouse_warm_start(rb_world *world, rb_joint *joint);
void rb_mouse_solve(rb_world *world, rb_joint *joint, double h);

void rb_prismatic_prepare_step(rb_joint *joint);
void rb_prismatic_warm_start(rb_world *world, rb_joint *joint);
void rb_prismatic_solve(rb_world *world, rb_joint *joint, double h);
bool rb_prismatic_correct(rb_world *world, rb_joint *joint);
/* Anchor B's distance off the axis or beyond an enabled limit (m, >= 0). */
double rb_prismatic_gap(const rb_world *world, const rb_joint *joint);
double rb_prismatic_angle_error(const rb_world *world, const rb_joint *joint); /* rad, >= 0 */
/* The impulses on body B in the last substep: linear (N·s, world) and
 * angular (N·m·s). */
rb_vec2 rb_prismatic_linear_impulse(const rb_world *world, const rb_joint *joint);
double rb_prismatic_angular_impulse(const rb_joint *joint);

void rb_pulley_warm_start(rb_world *world, rb_joint *joint);
void rb_pulley_solve(rb_world *world, rb_joint *joint, double h);
bool rb_pulley_correct(rb_world *world, rb_joint *joint);
/* How far the rope is longer than its constant, or a body nearer its
 * pulley than min_length (m, >= 0). */
double rb_pulley_gap(const rb_world *world, const rb_joint *joint);
/* The impulse on body B in the last substep, the rope's pull and the
 * stop's push (N·s, world). */
rb_vec2 rb_pulley_impulse_on_b(const rb_world *world, const rb_joint *joint);

#endif
