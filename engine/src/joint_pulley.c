/* SPDX-License-Identifier: MIT */
/* Pulley joint: a rope from anchor A up to a fixed pulley at ground
 * anchor gA, across to a second one at gB and down to anchor B. With
 * l_a = |pA - gA|, l_b = |pB - gB| and the unit directions
 * u_a = (pA - gA)/l_a, u_b = (pB - gB)/l_b, the rope holds
 *   C = constant - l_a - ratio·l_b >= 0,
 * one-sided: a rope pulls and never pushes, so its impulse λ >= 0 and it
 * goes slack when the bodies rise (Catto, "Modeling and Solving
 * Constraints", GDC 2009: inequality rows and the clamped accumulated
 * impulse). Since dl_a/dt = u_a·(vA + ωA × rA),
 *   dC/dt = -u_a·(vA + ωA × rA) - ratio·u_b·(vB + ωB × rB),
 * so J = [-u_a, -(rA × u_a), -ratio·u_b, -ratio·(rB × u_b)], and
 *   1/m = 1/mA + (rA × u_a)²/IA + ratio²·(1/mB + (rB × u_b)²/IB).
 * λ pulls A towards gA with λ and B towards gB with ratio·λ: the tension
 * of a gear of that ratio, the ground taking the rest.
 *
 * The directions are undefined where a side's length is 0, so each body
 * meets its pulley min_length from it: one-sided stops
 * l_a - min_length >= 0 and l_b - min_length >= 0 on one body each, whose
 * impulses push the body away from its pulley. A stop holds whatever
 * brought the body there: the rope (the other body outweighs it) or its
 * own momentum (a rope cannot hold that back). */
#include <float.h>

#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"

/* Below this length a side's direction is taken as undefined (m). */
#define MIN_DIRECTION_LENGTH 1e-9

/* The ratio's range (rb/joint.h): its square multiplies body B's inverse
 * mass in the rope's effective mass, which must stay finite and above 0. */
#define MIN_RATIO 1e-6
#define MAX_RATIO 1e6

rb_pulley_joint_def rb_default_pulley_joint_def(void)
{
    return (rb_pulley_joint_def){
        .length_a = 1.0, .length_b = 1.0, .ratio = 1.0, .min_length = 0.05, .internal_value = RB_DEF_COOKIE};
}

rb_status rb_pulley_joint_def_between(rb_pulley_joint_def *def, const rb_world *world, rb_body_id body_a,
                                      rb_body_id body_b, rb_vec2 ground_anchor_a, rb_vec2 ground_anchor_b,
                                      rb_vec2 anchor_a, rb_vec2 anchor_b)
{
    const char *f = "rb_pulley_joint_def_between";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "def", def));
    RB_TRY(rb_check_point(f, "ground_anchor_a", ground_anchor_a));
    RB_TRY(rb_check_point(f, "ground_anchor_b", ground_anchor_b));
    RB_TRY(rb_check_point(f, "anchor_a", anchor_a));
    RB_TRY(rb_check_point(f, "anchor_b", anchor_b));
    int a;
    int b;
    RB_TRY(rb_joint_check_bodies(world, body_a, body_b, f, &a, &b));
    *def = rb_default_pulley_joint_def();
    def->body_a = body_a;
    def->body_b = body_b;
    def->ground_anchor_a = ground_anchor_a;
    def->ground_anchor_b = ground_anchor_b;
    def->local_anchor_a = rb_inv_transform_point(rb_body_origin_transform(world, a), anchor_a);
    def->local_anchor_b = rb_inv_transform_point(rb_body_origin_transform(world, b), anchor_b);
    def->length_a = rb_distance(ground_anchor_a, anchor_a);
    def->length_b = rb_distance(ground_anchor_b, anchor_b);
    return RB_OK;
}

rb_status rb_pulley_joint_create(rb_world *world, const rb_pulley_joint_def *def, rb_joint_id *out)
{
    const char *f = "rb_pulley_joint_create";
    rb_clear_error();
    int a;
    int b;
    RB_TRY(rb_joint_check_common(world, def, RB_JOINT_COMMON(def), out, f, "rb_default_pulley_joint_def", &a, &b));
    RB_TRY(rb_check_point(f, "ground_anchor_a", def->ground_anchor_a));
    RB_TRY(rb_check_point(f, "ground_anchor_b", def->ground_anchor_b));
    RB_TRY(rb_check_range(f, "ratio", def->ratio, MIN_RATIO, MAX_RATIO));
    RB_TRY(rb_check_range(f, "min_length", def->min_length, DBL_MIN, RB_MAX_LENGTH));
    RB_TRY(rb_check_range(f, "length_a", def->length_a, def->min_length, RB_MAX_LENGTH));
    RB_TRY(rb_check_range(f, "length_b", def->length_b, def->min_length, RB_MAX_LENGTH));
    double constant = def->length_a + def->ratio * def->length_b;
    if (!isfinite(constant)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: length_a + ratio·length_b is not finite", f);
    }
    rb_joint joint = {
        .type = RB_JOINT_PULLEY,
        .body_a = a,
        .body_b = b,
        .local_anchor_a = def->local_anchor_a,
        .local_anchor_b = def->local_anchor_b,
        .collide_connected = def->collide_connected,
        .user_data = def->user_data,
        .as.pulley =
            {
                .ground_a = def->ground_anchor_a,
                .ground_b = def->ground_anchor_b,
                .ratio = def->ratio,
                .constant = constant,
                .min_length = def->min_length,
            },
    };
    return rb_joint_create(world, &joint, out, f);
}

static double side_length(const rb_world *world, rb_joint_id id, const char *f, bool side_a)
{
    rb_clear_error();
    int index;
    if (rb_joint_find_typed(world, id, RB_JOINT_PULLEY, f, &index) != RB_OK) {
        return 0.0;
    }
    const rb_joint *joint = &world->joints[index];
    const rb_pulley_data *p = &joint->as.pulley;
    return side_a ? rb_distance(p->ground_a, rb_joint_anchor_a(world, joint))
                  : rb_distance(p->ground_b, rb_joint_anchor_b(world, joint));
}

double rb_pulley_joint_length_a(const rb_world *world, rb_joint_id id)
{
    return side_length(world, id, "rb_pulley_joint_length_a", true);
}

double rb_pulley_joint_length_b(const rb_world *world, rb_joint_id id)
{
    return side_length(world, id, "rb_pulley_joint_length_b", false);
}

/* ---- solver ---------------------------------------------------------------------- */

/* One side of the rope at the poses now. */
typedef struct rope_side {
    rb_vec2 direction; /* unit, from the ground anchor to the body anchor; 0 when undefined */
    double length;     /* m */
    double cross;      /* m, r × direction */
} rope_side;

static rope_side measure_side(rb_vec2 ground, rb_vec2 center, rb_vec2 r)
{
    rb_vec2 delta = rb_sub(rb_add(center, r), ground);
    rope_side side = {.length = rb_length(delta)};
    side.direction = side.length > MIN_DIRECTION_LENGTH ? rb_scale(1.0 / side.length, delta) : rb_v2(0.0, 0.0);
    side.cross = rb_cross(r, side.direction);
    return side;
}

/* How fast a unit impulse along a side changes its rate (1/kg):
 * 1/m + (r × u)²/I. */
static double side_inverse_mass(double inv_mass, double inv_inertia, const rope_side *side)
{
    return rb_length_squared(side->direction) * inv_mass + inv_inertia * side->cross * side->cross;
}

static double inverse_to_mass(double k) { return k > 0.0 ? 1.0 / k : 0.0; }

/* The rope's rows at the poses of this substep, from the frame; not
 * cached in the joint (see world_internal.h), and the same in every
 * velocity pass since the poses do not change during them. */
typedef struct rope_rows {
    rope_side a, b;
    double mass, mass_a, mass_b; /* kg, effective masses of the rope and of each body's stop */
} rope_rows;

static rope_rows rows_now(const rb_world *world, const rb_joint *joint)
{
    const rb_pulley_data *p = &joint->as.pulley;
    const rb_joint_frame *f = &joint->frame;
    rope_rows r;
    r.a = measure_side(p->ground_a, world->states[joint->body_a].center, f->ra);
    r.b = measure_side(p->ground_b, world->states[joint->body_b].center, f->rb);
    double k_a = side_inverse_mass(f->inv_mass_a, f->inv_inertia_a, &r.a);
    double k_b = side_inverse_mass(f->inv_mass_b, f->inv_inertia_b, &r.b);
    r.mass = inverse_to_mass(k_a + p->ratio * p->ratio * k_b);
    r.mass_a = inverse_to_mass(k_a);
    r.mass_b = inverse_to_mass(k_b);
    return r;
}

/* Pushes the body's anchor away from its pulley with `impulse` (N·s; the
 * rope pulls with a negative one). */
static void push(rb_body_state *state, double inv_mass, double inv_inertia, rb_vec2 r, rb_vec2 direction,
                 double impulse)
{
    rb_vec2 linear = rb_scale(impulse, direction);
    state->linear_velocity = rb_mul_add(state->linear_velocity, inv_mass, linear);
    state->angular_velocity += inv_inertia * rb_cross(r, linear);
}

static void push_a(rb_world *world, const rb_joint *joint, const rope_rows *r, double impulse)
{
    const rb_joint_frame *f = &joint->frame;
    push(&world->states[joint->body_a], f->inv_mass_a, f->inv_inertia_a, f->ra, r->a.direction, impulse);
}

static void push_b(rb_world *world, const rb_joint *joint, const rope_rows *r, double impulse)
{
    const rb_joint_frame *f = &joint->frame;
    push(&world->states[joint->body_b], f->inv_mass_b, f->inv_inertia_b, f->rb, r->b.direction, impulse);
}

void rb_pulley_warm_start(rb_world *world, rb_joint *joint)
{
    const rb_pulley_data *p = &joint->as.pulley;
    rope_rows r = rows_now(world, joint);
    push_a(world, joint, &r, p->stop_a_impulse - p->impulse);
    push_b(world, joint, &r, p->stop_b_impulse - p->ratio * p->impulse);
}

/* Along side b at the poses now. */
rb_vec2 rb_pulley_impulse_on_b(const rb_world *world, const rb_joint *joint)
{
    const rb_pulley_data *p = &joint->as.pulley;
    rb_vec2 delta = rb_sub(rb_joint_anchor_b(world, joint), p->ground_b);
    double length = rb_length(delta);
    rb_vec2 direction = length > MIN_DIRECTION_LENGTH ? rb_scale(1.0 / length, delta) : rb_v2(0.0, 0.0);
    return rb_scale(p->stop_b_impulse - p->ratio * p->impulse, direction);
}

/* The rate at which a side lengthens: u·(v + ω × r). */
static double side_rate(const rb_body_state *state, rb_vec2 r, rb_vec2 direction)
{
    return rb_dot(direction, rb_add(state->linear_velocity, rb_cross_sv(state->angular_velocity, r)));
}

/* The impulse of a one-sided row of rate cdot, margin c and effective
 * mass `mass`, its accumulated impulse kept >= 0 (joint_solver.h);
 * returns the increment. */
static double clamp_increment(const rb_world *world, double *accumulated, double mass, double cdot, double c, double h)
{
    double total = rb_one_sided_row_total(world, mass, cdot, c, h, *accumulated);
    double increment = total - *accumulated;
    *accumulated = total;
    return increment;
}

/* The rope's margin (m, >= 0 while it is not too long) at the given lengths. */
static double rope_margin(const rb_pulley_data *p, double length_a, double length_b)
{
    return p->constant - length_a - p->ratio * length_b;
}

void rb_pulley_solve(rb_world *world, rb_joint *joint, double h)
{
    rb_pulley_data *p = &joint->as.pulley;
    const rb_joint_frame *f = &joint->frame;
    const rb_body_state *a = &world->states[joint->body_a];
    const rb_body_state *b = &world->states[joint->body_b];
    rope_rows r = rows_now(world, joint);
    if (r.mass_a > 0.0) {
        double c = r.a.length - p->min_length;
        double cdot = side_rate(a, f->ra, r.a.direction);
        push_a(world, joint, &r, clamp_increment(world, &p->stop_a_impulse, r.mass_a, cdot, c, h));
    }
    if (r.mass_b > 0.0) {
        double c = r.b.length - p->min_length;
        double cdot = side_rate(b, f->rb, r.b.direction);
        push_b(world, joint, &r, clamp_increment(world, &p->stop_b_impulse, r.mass_b, cdot, c, h));
    }
    if (r.mass > 0.0) {
        double c = rope_margin(p, r.a.length, r.b.length);
        double cdot = -side_rate(a, f->ra, r.a.direction) - p->ratio * side_rate(b, f->rb, r.b.direction);
        double impulse = clamp_increment(world, &p->impulse, r.mass, cdot, c, h);
        push_a(world, joint, &r, -impulse);
        push_b(world, joint, &r, -p->ratio * impulse);
    }
}

double rb_pulley_gap(const rb_world *world, const rb_joint *joint)
{
    const rb_pulley_data *p = &joint->as.pulley;
    double length_a = rb_distance(p->ground_a, rb_joint_anchor_a(world, joint));
    double length_b = rb_distance(p->ground_b, rb_joint_anchor_b(world, joint));
    double gap = fmax(0.0, -rope_margin(p, length_a, length_b));
    gap = fmax(gap, p->min_length - length_a);
    return fmax(gap, p->min_length - length_b);
}

/* Moves a body's anchor away from its pulley by the position impulse
 * `impulse` (kg·m; towards it when negative). */
static void shift(rb_body_state *state, double inv_mass, double inv_inertia, rb_vec2 r, rb_vec2 direction,
                  double impulse)
{
    rb_vec2 linear = rb_scale(impulse, direction);
    state->center = rb_mul_add(state->center, inv_mass, linear);
    if (inv_inertia > 0.0) {
        rb_body_state_turn(state, inv_inertia * rb_cross(r, linear));
    }
}

/* One NGS pass: each stop, then the rope, by what it is violated
 * (capped), at the poses as the previous row left them. A stop moves its
 * body away from its pulley; the rope moves both towards theirs, body B
 * ratio times as hard. */
bool rb_pulley_correct(rb_world *world, rb_joint *joint)
{
    const rb_pulley_data *p = &joint->as.pulley;
    const rb_joint_frame *f = &joint->frame;
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    double max_correction = world->settings.max_linear_correction;
    double worst = 0.0;
    enum { STOP_A, STOP_B, ROPE };
    for (int row = STOP_A; row <= ROPE; ++row) {
        rb_vec2 ra = rb_rotate(a->rotation, f->local_a);
        rb_vec2 rb = rb_rotate(b->rotation, f->local_b);
        rope_side side_a = measure_side(p->ground_a, a->center, ra);
        rope_side side_b = measure_side(p->ground_b, b->center, rb);
        double k_a = side_inverse_mass(f->inv_mass_a, f->inv_inertia_a, &side_a);
        double k_b = side_inverse_mass(f->inv_mass_b, f->inv_inertia_b, &side_b);
        /* The margin c (>= 0 when met), 1/m of the row, and how much of
         * the row's impulse pushes A and B away from their pulleys. */
        double c = side_a.length - p->min_length, k = k_a, share_a = 1.0, share_b = 0.0;
        if (row == STOP_B) {
            c = side_b.length - p->min_length;
            k = k_b;
            share_a = 0.0;
            share_b = 1.0;
        } else if (row == ROPE) {
            c = rope_margin(p, side_a.length, side_b.length);
            k = k_a + p->ratio * p->ratio * k_b;
            share_a = -1.0;
            share_b = -p->ratio;
        }
        worst = fmax(worst, -c);
        if (c >= 0.0 || !(k > 0.0)) {
            continue;
        }
        double impulse = -fmax(c, -max_correction) / k;
        shift(a, f->inv_mass_a, f->inv_inertia_a, ra, side_a.direction, share_a * impulse);
        shift(b, f->inv_mass_b, f->inv_inertia_b, rb, side_b.direction, share_b * impulse);
    }
    return worst <= world->settings.linear_slop;
}
