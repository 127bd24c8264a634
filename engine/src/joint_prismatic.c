/* SPDX-License-Identifier: MIT */
/* Prismatic joint: body B slides along an axis fixed in body A and does
 * not turn relative to it. With anchor A at pA = cA + rA, anchor B at
 * pB = cB + rB, d = pB - pA, the world axis u = R(θA)·û (û the unit axis
 * in A's frame) and n = u turned +90°, the joint holds
 *   C_n = n·d = 0                      anchor B on the axis,
 *   C_θ = θB - θA - reference = 0      no relative turn,
 * and acts on the translation s = u·d with a spring (towards s = 0), a
 * motor and the one-sided limits s - lower >= 0 and upper - s >= 0.
 *
 * Velocities (Catto, "Modeling and Solving Constraints", GDC 2009: a
 * row's Jacobian is read off dC/dt). The axes turn with body A,
 * du/dt = ωA × u, and (ω × a)·b = ω·(a × b) in 2D, so
 *   dC_n/dt = (ωA × n)·d + n·(vB + ωB × rB - vA - ωA × rA)
 *           = n·(vB - vA) + (rB × n)·ωB - ((d + rA) × n)·ωA,
 * and likewise ds/dt with u for n. Body A's lever arm is d + rA, not rA:
 * the axis pivots with A about A's centre, sweeping anchor B's
 * perpendicular offset. With s_a = (d + rA) × n, s_b = rB × n,
 * a_a = (d + rA) × u, a_b = rB × u and the rows J_n = [-n, -s_a, n, s_b],
 * J_θ = [0, -1, 0, 1], J_u = [-u, -a_a, u, a_b], the block K = J·M⁻¹·Jᵀ
 * (with n·u = 0) is
 *   k_nn = 1/mA + 1/mB + s_a²/IA + s_b²/IB,  k_nθ = s_a/IA + s_b/IB,  k_θθ = 1/IA + 1/IB,
 *   k_nu = s_a·a_a/IA + s_b·a_b/IB,          k_θu = a_a/IA + a_b/IB,
 *   k_uu = 1/mA + 1/mB + a_a²/IA + a_b²/IB.
 * The perpendicular and angular rows are solved together as one 2x2
 * block, or with the nearer limit as one 3x3 block, for the reason the
 * revolute solves its limit with the pin (joint_point.c): row by row,
 * each row would undo part of the other through the shared lever arms.
 *
 * Each substep solves, in order: spring, motor (its accumulated impulse
 * clamped to ±max_force·h), the farther limit alone, then the block; the
 * parts that may give way first, the rigid rows last, as the revolute
 * joint. A limit not yet reached is speculative (approach at |C|/h). */

#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"

rb_prismatic_joint_def rb_default_prismatic_joint_def(void)
{
    return (rb_prismatic_joint_def){.local_axis_a = {1.0, 0.0}, .internal_value = RB_DEF_COOKIE};
}

/* The unit vector along `axis`, which must be finite and non-zero;
 * hypot neither overflows nor underflows on the way. */
static rb_status normalise_axis(const char *f, const char *name, rb_vec2 axis, rb_vec2 *unit)
{
    RB_TRY(rb_check_vec2(f, name, axis));
    double length = hypot(axis.x, axis.y);
    if (!(length > 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s is (0, 0), expected a non-zero direction", f, name);
    }
    *unit = rb_v2(axis.x / length, axis.y / length);
    return RB_OK;
}

rb_status rb_prismatic_joint_def_at(rb_prismatic_joint_def *def, const rb_world *world, rb_body_id body_a,
                                    rb_body_id body_b, rb_vec2 world_anchor, rb_vec2 world_axis)
{
    const char *f = "rb_prismatic_joint_def_at";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "def", def));
    rb_vec2 axis = {0.0, 0.0};
    RB_TRY(normalise_axis(f, "world_axis", world_axis, &axis));
    rb_prismatic_joint_def filled = rb_default_prismatic_joint_def();
    RB_TRY(rb_joint_anchor_at(world, body_a, body_b, world_anchor, f, &filled.local_anchor_a, &filled.local_anchor_b,
                              &filled.reference_angle));
    int a;
    RB_TRY(rb_world_find_body(world, body_a, f, &a));
    filled.local_axis_a = rb_inv_rotate(world->states[a].rotation, axis);
    filled.body_a = body_a;
    filled.body_b = body_b;
    *def = filled;
    return RB_OK;
}

rb_status rb_prismatic_joint_create(rb_world *world, const rb_prismatic_joint_def *def, rb_joint_id *out)
{
    const char *f = "rb_prismatic_joint_create";
    rb_clear_error();
    int a;
    int b;
    RB_TRY(rb_joint_check_common(world, def, RB_JOINT_COMMON(def), out, f, "rb_default_prismatic_joint_def", &a, &b));
    rb_vec2 axis;
    RB_TRY(normalise_axis(f, "local_axis_a", def->local_axis_a, &axis));
    RB_TRY(rb_check_bound(f, "reference_angle", def->reference_angle, RB_MAX_ANGLE, "rad"));
    RB_TRY(rb_joint_check_limits(f, "lower_translation", "upper_translation", "m", RB_MAX_LENGTH,
                                 def->enable_lower_limit, def->lower_translation, def->enable_upper_limit,
                                 def->upper_translation));
    RB_TRY(rb_joint_check_motor(f, "max_motor_force", def->motor_speed, def->max_motor_force));
    RB_TRY(rb_joint_check_spring(f, def->spring_hertz, def->spring_damping_ratio));
    rb_joint joint = {
        .type = RB_JOINT_PRISMATIC,
        .body_a = a,
        .body_b = b,
        .local_anchor_a = def->local_anchor_a,
        .local_anchor_b = def->local_anchor_b,
        .collide_connected = def->collide_connected,
        .user_data = def->user_data,
        .as.prismatic =
            {
                .local_axis_a = axis,
                .reference_angle = def->reference_angle,
                .enable_lower = def->enable_lower_limit,
                .enable_upper = def->enable_upper_limit,
                .lower = def->lower_translation,
                .upper = def->upper_translation,
                .enable_motor = def->enable_motor,
                .motor_speed = def->motor_speed,
                .max_motor_force = def->max_motor_force,
                .enable_spring = def->enable_spring,
                .spring_hertz = def->spring_hertz,
                .spring_damping_ratio = def->spring_damping_ratio,
            },
    };
    return rb_joint_create(world, &joint, out, f);
}

/* ---- geometry at the poses now ------------------------------------------------ */

/* The world axis, the anchors' separation d and the lever arms of both
 * bodies' centres, from the states as they are now. */
typedef struct slide_geometry {
    rb_vec2 axis, normal, d;
    rb_vec2 arm_a; /* m, d + rA: from A's centre to anchor B */
    rb_vec2 rb;    /* m, from B's centre to anchor B */
} slide_geometry;

static slide_geometry measure(const rb_world *world, const rb_joint *joint)
{
    const rb_body_state *a = &world->states[joint->body_a];
    const rb_body_state *b = &world->states[joint->body_b];
    rb_vec2 ra = rb_rotate(a->rotation, rb_sub(joint->local_anchor_a, world->bodies[joint->body_a].local_center));
    rb_vec2 rb = rb_rotate(b->rotation, rb_sub(joint->local_anchor_b, world->bodies[joint->body_b].local_center));
    slide_geometry g;
    g.axis = rb_rotate(a->rotation, joint->as.prismatic.local_axis_a);
    g.normal = rb_left_perp(g.axis);
    g.d = rb_sub(rb_add(b->center, rb), rb_add(a->center, ra));
    g.arm_a = rb_add(g.d, ra);
    g.rb = rb;
    return g;
}

/* ---- getters and setters ----------------------------------------------------- */

static const rb_joint *find_prismatic(const rb_world *world, rb_joint_id id, const char *f)
{
    rb_clear_error();
    int index;
    if (rb_joint_find_typed(world, id, RB_JOINT_PRISMATIC, f, &index) != RB_OK) {
        return NULL;
    }
    return &world->joints[index];
}

double rb_prismatic_joint_translation(const rb_world *world, rb_joint_id id)
{
    const rb_joint *joint = find_prismatic(world, id, "rb_prismatic_joint_translation");
    if (joint == NULL) {
        return 0.0;
    }
    slide_geometry g = measure(world, joint);
    return rb_dot(g.axis, g.d);
}

/* ds/dt = (ωA × u)·d + u·(vB + ωB × rB - vA - ωA × rA). */
double rb_prismatic_joint_speed(const rb_world *world, rb_joint_id id)
{
    const rb_joint *joint = find_prismatic(world, id, "rb_prismatic_joint_speed");
    if (joint == NULL) {
        return 0.0;
    }
    slide_geometry g = measure(world, joint);
    const rb_body_state *a = &world->states[joint->body_a];
    const rb_body_state *b = &world->states[joint->body_b];
    rb_vec2 ra = rb_sub(g.arm_a, g.d);
    rb_vec2 vb = rb_add(b->linear_velocity, rb_cross_sv(b->angular_velocity, g.rb));
    rb_vec2 va = rb_add(a->linear_velocity, rb_cross_sv(a->angular_velocity, ra));
    return rb_dot(rb_cross_sv(a->angular_velocity, g.axis), g.d) + rb_dot(g.axis, rb_sub(vb, va));
}

double rb_prismatic_joint_motor_force(const rb_world *world, rb_joint_id id)
{
    const rb_joint *joint = find_prismatic(world, id, "rb_prismatic_joint_motor_force");
    return joint != NULL ? joint->as.prismatic.motor_impulse / world->last_substep : 0.0;
}

static rb_prismatic_data *find_for_change(rb_world *world, rb_joint_id id, const char *f, rb_status *status)
{
    rb_joint *joint = rb_joint_find_for_change(world, id, RB_JOINT_PRISMATIC, f, status);
    return joint != NULL ? &joint->as.prismatic : NULL;
}

rb_status rb_prismatic_joint_set_motor(rb_world *world, rb_joint_id id, bool enable, double speed, double max_force)
{
    const char *f = "rb_prismatic_joint_set_motor";
    rb_status status;
    rb_prismatic_data *p = find_for_change(world, id, f, &status);
    RB_TRY(status);
    RB_TRY(rb_joint_check_motor(f, "max_motor_force", speed, max_force));
    p->enable_motor = enable;
    p->motor_speed = speed;
    p->max_motor_force = max_force;
    return RB_OK;
}

rb_status rb_prismatic_joint_set_limits(rb_world *world, rb_joint_id id, bool enable_lower, double lower,
                                        bool enable_upper, double upper)
{
    const char *f = "rb_prismatic_joint_set_limits";
    rb_status status;
    rb_prismatic_data *p = find_for_change(world, id, f, &status);
    RB_TRY(status);
    RB_TRY(rb_joint_check_limits(f, "lower_translation", "upper_translation", "m", RB_MAX_LENGTH, enable_lower, lower,
                                 enable_upper, upper));
    p->enable_lower = enable_lower;
    p->enable_upper = enable_upper;
    p->lower = lower;
    p->upper = upper;
    return RB_OK;
}

rb_status rb_prismatic_joint_set_spring(rb_world *world, rb_joint_id id, bool enable, double hertz,
                                        double damping_ratio)
{
    const char *f = "rb_prismatic_joint_set_spring";
    rb_status status;
    rb_prismatic_data *p = find_for_change(world, id, f, &status);
    RB_TRY(status);
    RB_TRY(rb_joint_check_spring(f, hertz, damping_ratio));
    p->enable_spring = enable;
    p->spring_hertz = hertz;
    p->spring_damping_ratio = damping_ratio;
    return RB_OK;
}

/* ---- solver ---------------------------------------------------------------------- */

/* K of the rows (n, θ, u) for the lever arms s_a, s_b (across the axis)
 * and a_a, a_b (along it). */
static rb_block_matrix make_block(const rb_joint_frame *f, double s_a, double s_b, double a_a, double a_b)
{
    double m = f->inv_mass_a + f->inv_mass_b;
    double ia = f->inv_inertia_a;
    double ib = f->inv_inertia_b;
    return (rb_block_matrix){
        .k11 = m + ia * s_a * s_a + ib * s_b * s_b,
        .k12 = ia * s_a + ib * s_b,
        .k22 = ia + ib,
        .k13 = ia * s_a * a_a + ib * s_b * a_b,
        .k23 = ia * a_a + ib * a_b,
        .k33 = m + ia * a_a * a_a + ib * a_b * a_b,
    };
}

/* A pair that cannot turn leaves the angle row empty: a unit diagonal
 * (and a zero right side) keep the block regular and its impulse 0. */
static bool make_regular(rb_block_matrix *k)
{
    if (k->k22 > 0.0) {
        return true;
    }
    k->k22 = 1.0;
    return false;
}

/* The rows at the poses of this substep. They are not cached in the
 * joint: computed from the frame when needed (the poses do not change
 * during the velocity passes, so every pass sees the same values), they
 * keep rb_prismatic_data no larger than the revolute's, and with it the
 * stride of the joint array the solver walks for every joint type. */
typedef struct slide_rows {
    rb_vec2 axis, normal;      /* world; normal = axis turned +90° */
    double translation;        /* m, s = u·d */
    double offset;             /* m, C_n = n·d */
    double axial_a, axial_b;   /* m, a_a and a_b */
    double normal_a, normal_b; /* m, s_a and s_b */
    rb_block_matrix k;         /* made regular */
    bool turns;                /* whether either body can turn (the angle row is not empty) */
    double axial_mass;         /* kg */
} slide_rows;

/* The mass the axis sees while the rigid rows hold: a unit impulse along
 * the axis, followed by the block's answer, changes ds/dt by the Schur
 * complement k_uu - k_u·K2⁻¹·k_u = 1/(K⁻¹)₃₃ of the rigid 2x2 block, not
 * by k_uu alone, so the mass is (K⁻¹)₃₃. With it a spring of f Hz
 * oscillates at f whatever the lever arms (with 1/k_uu a box whose anchor
 * is 5 cm off its centre would ring at 0.93·f), and the motor meets its
 * speed in one pass. */
static double axial_mass(const rb_block_matrix *k)
{
    rb_vec2 rigid;
    double mass;
    if (rb_block_solve3(k, rb_v2(0.0, 0.0), 1.0, &rigid, &mass) && mass > 0.0) {
        return mass;
    }
    return k->k33 > 0.0 ? 1.0 / k->k33 : 0.0;
}

static slide_rows rows_now(const rb_world *world, const rb_joint *joint)
{
    const rb_joint_frame *f = &joint->frame;
    const rb_body_state *a = &world->states[joint->body_a];
    const rb_body_state *b = &world->states[joint->body_b];
    slide_rows r;
    r.axis = rb_rotate(a->rotation, joint->as.prismatic.local_axis_a);
    r.normal = rb_left_perp(r.axis);
    rb_vec2 d = rb_sub(rb_add(b->center, f->rb), rb_add(a->center, f->ra));
    rb_vec2 arm_a = rb_add(d, f->ra);
    r.translation = rb_dot(r.axis, d);
    r.offset = rb_dot(r.normal, d);
    r.axial_a = rb_cross(arm_a, r.axis);
    r.axial_b = rb_cross(f->rb, r.axis);
    r.normal_a = rb_cross(arm_a, r.normal);
    r.normal_b = rb_cross(f->rb, r.normal);
    r.k = make_block(f, r.normal_a, r.normal_b, r.axial_a, r.axial_b);
    r.turns = make_regular(&r.k);
    r.axial_mass = axial_mass(&r.k);
    return r;
}

void rb_prismatic_prepare_step(rb_joint *joint)
{
    rb_prismatic_data *p = &joint->as.prismatic;
    if (!p->enable_motor) {
        p->motor_impulse = 0.0;
    }
    if (!p->enable_spring) {
        p->spring_impulse = 0.0;
    }
    if (!p->enable_lower) {
        p->lower_impulse = 0.0;
    }
    if (!p->enable_upper) {
        p->upper_impulse = 0.0;
    }
}

/* Applies Jᵀ·(across, angular, along): +P, +L on B, -P, -L on A. */
static void apply(const rb_joint *joint, const slide_rows *r, rb_body_state *a, rb_body_state *b, double across,
                  double angular, double along)
{
    const rb_joint_frame *f = &joint->frame;
    rb_vec2 impulse = rb_add(rb_scale(across, r->normal), rb_scale(along, r->axis));
    a->linear_velocity = rb_mul_sub(a->linear_velocity, f->inv_mass_a, impulse);
    a->angular_velocity -= f->inv_inertia_a * (across * r->normal_a + angular + along * r->axial_a);
    b->linear_velocity = rb_mul_add(b->linear_velocity, f->inv_mass_b, impulse);
    b->angular_velocity += f->inv_inertia_b * (across * r->normal_b + angular + along * r->axial_b);
}

static double axial_total(const rb_prismatic_data *p)
{
    return p->motor_impulse + p->spring_impulse + p->lower_impulse - p->upper_impulse;
}

void rb_prismatic_warm_start(rb_world *world, rb_joint *joint)
{
    const rb_prismatic_data *p = &joint->as.prismatic;
    slide_rows r = rows_now(world, joint);
    apply(joint, &r, rb_joint_state_a(world, joint), rb_joint_state_b(world, joint), p->impulse.x, p->impulse.y,
          axial_total(p));
}

/* Along the axis and across it at the poses now. */
rb_vec2 rb_prismatic_linear_impulse(const rb_world *world, const rb_joint *joint)
{
    const rb_prismatic_data *p = &joint->as.prismatic;
    slide_geometry g = measure(world, joint);
    return rb_add(rb_scale(p->impulse.x, g.normal), rb_scale(axial_total(p), g.axis));
}

/* The torque about B's centre is the angular row's alone: the axial and
 * perpendicular rows act at anchor B, as the reaction force. */
double rb_prismatic_angular_impulse(const rb_joint *joint) { return joint->as.prismatic.impulse.y; }

/* The rates of the rows: across the axis and along it. */
static double across_rate(const slide_rows *r, const rb_body_state *a, const rb_body_state *b)
{
    return rb_dot(r->normal, rb_sub(b->linear_velocity, a->linear_velocity)) + r->normal_b * b->angular_velocity -
           r->normal_a * a->angular_velocity;
}

static double along_rate(const slide_rows *r, const rb_body_state *a, const rb_body_state *b)
{
    return rb_dot(r->axis, rb_sub(b->linear_velocity, a->linear_velocity)) + r->axial_b * b->angular_velocity -
           r->axial_a * a->angular_velocity;
}

/* A limit alone, on the axial mass: it only releases what it held. */
static void solve_limit_alone(rb_world *world, rb_joint *joint, const slide_rows *r, rb_body_state *a, rb_body_state *b,
                              bool lower, double h)
{
    rb_prismatic_data *p = &joint->as.prismatic;
    double sign = lower ? 1.0 : -1.0;
    double margin = lower ? r->translation - p->lower : p->upper - r->translation;
    double *accumulated = lower ? &p->lower_impulse : &p->upper_impulse;
    double cdot = sign * along_rate(r, a, b);
    double total = rb_one_sided_row_total(world, r->axial_mass, cdot, margin, h, *accumulated);
    apply(joint, r, a, b, 0.0, 0.0, sign * (total - *accumulated));
    *accumulated = total;
}

/* The rigid rows across the axis and about it, with the limit row of
 * sign σ (+1 lower, -1 upper) when `limit` is not 0: σ·ds/dt + bias >= 0,
 * its impulse kept >= 0. In K the limit row's couplings take the sign σ. */
static void solve_block(rb_world *world, rb_joint *joint, const slide_rows *r, rb_body_state *a, rb_body_state *b,
                        int limit, double h)
{
    rb_prismatic_data *p = &joint->as.prismatic;
    rb_vec2 cdot = rb_v2(across_rate(r, a, b), r->turns ? b->angular_velocity - a->angular_velocity : 0.0);
    const rb_rigid_response *response = &world->joint_response;
    double rate = response->bias_rate;
    if (rate > 0.0) {
        double angle = r->turns ? rb_joint_relative_angle(world, joint, p->reference_angle) : 0.0;
        cdot = rb_add(cdot, rb_scale(rate, rb_v2(r->offset, angle)));
    }
    rb_vec2 impulse;
    if (limit != 0) {
        double sign = limit;
        bool lower = limit > 0;
        double margin = lower ? r->translation - p->lower : p->upper - r->translation;
        double *accumulated = lower ? &p->lower_impulse : &p->upper_impulse;
        rb_block_matrix ks = r->k;
        ks.k13 *= sign;
        ks.k23 *= sign;
        double wdot = sign * along_rate(r, a, b) + rb_one_sided_bias(world, margin, h);
        double along;
        if (rb_block_solve3(&ks, rb_neg(cdot), -wdot, &impulse, &along)) {
            impulse = rb_soften(response, impulse, p->impulse);
            along = response->mass_scale * along - response->impulse_scale * *accumulated;
            if (*accumulated + along < 0.0) {
                /* The limit would pull: release it and hold the two rigid
                 * rows alone, net of the release's effect on them. */
                along = -*accumulated;
                rb_vec2 rhs = rb_neg(rb_add(cdot, rb_scale(along, rb_v2(ks.k13, ks.k23))));
                impulse =
                    rb_block_solve2(&r->k, rhs, &impulse) ? rb_soften(response, impulse, p->impulse) : rb_v2(0.0, 0.0);
            }
            *accumulated += along;
            p->impulse = rb_add(p->impulse, impulse);
            apply(joint, r, a, b, impulse.x, impulse.y, sign * along);
            return;
        }
    }
    if (rb_block_solve2(&r->k, rb_neg(cdot), &impulse)) {
        impulse = rb_soften(response, impulse, p->impulse);
        p->impulse = rb_add(p->impulse, impulse);
        apply(joint, r, a, b, impulse.x, impulse.y, 0.0);
    }
}

void rb_prismatic_solve(rb_world *world, rb_joint *joint, double h)
{
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    rb_prismatic_data *p = &joint->as.prismatic;
    slide_rows r = rows_now(world, joint);
    int block_limit = 0;
    if (r.axial_mass > 0.0) {
        if (p->enable_spring && p->spring_hertz > 0.0) {
            rb_softness soft = rb_make_softness(p->spring_hertz, p->spring_damping_ratio, r.axial_mass, h);
            double cdot = along_rate(&r, a, b);
            double impulse = -(cdot + soft.bias_rate * r.translation + soft.gamma * p->spring_impulse) /
                             (1.0 / r.axial_mass + soft.gamma);
            p->spring_impulse += impulse;
            apply(joint, &r, a, b, 0.0, 0.0, impulse);
        }
        if (p->enable_motor) {
            double cdot = along_rate(&r, a, b) - p->motor_speed;
            double limit = p->max_motor_force * h;
            double accumulated = fmin(fmax(p->motor_impulse - r.axial_mass * cdot, -limit), limit);
            double impulse = accumulated - p->motor_impulse;
            p->motor_impulse = accumulated;
            apply(joint, &r, a, b, 0.0, 0.0, impulse);
        }
        /* The nearer enabled limit goes into the block, the other alone. */
        bool lower_nearer =
            p->enable_lower && (!p->enable_upper || r.translation - p->lower <= p->upper - r.translation);
        bool upper_nearer = p->enable_upper && !lower_nearer;
        if (p->enable_lower && !lower_nearer) {
            solve_limit_alone(world, joint, &r, a, b, true, h);
        }
        if (p->enable_upper && !upper_nearer) {
            solve_limit_alone(world, joint, &r, a, b, false, h);
        }
        block_limit = lower_nearer ? 1 : (upper_nearer ? -1 : 0);
    }
    solve_block(world, joint, &r, a, b, block_limit, h);
}

/* How far the translation lies beyond an enabled limit: negative below
 * the lower one, positive above the upper one, else 0 (m). */
static double limit_violation(const rb_prismatic_data *p, double translation)
{
    if (p->enable_lower && translation < p->lower) {
        return translation - p->lower;
    }
    if (p->enable_upper && translation > p->upper) {
        return translation - p->upper;
    }
    return 0.0;
}

double rb_prismatic_gap(const rb_world *world, const rb_joint *joint)
{
    slide_geometry g = measure(world, joint);
    double violation = limit_violation(&joint->as.prismatic, rb_dot(g.axis, g.d));
    return fmax(fabs(rb_dot(g.normal, g.d)), fabs(violation));
}

double rb_prismatic_angle_error(const rb_world *world, const rb_joint *joint)
{
    return fabs(rb_joint_relative_angle(world, joint, joint->as.prismatic.reference_angle));
}

/* One NGS pass: the position errors (C_n, C_θ and a limit's violation)
 * are removed at once through K at the poses now, each capped as the
 * other joints' corrections; returns whether all were within the slops. */
bool rb_prismatic_correct(rb_world *world, rb_joint *joint)
{
    rb_prismatic_data *p = &joint->as.prismatic;
    const rb_joint_frame *f = &joint->frame;
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    slide_geometry g = measure(world, joint);
    double s_a = rb_cross(g.arm_a, g.normal);
    double s_b = rb_cross(g.rb, g.normal);
    double a_a = rb_cross(g.arm_a, g.axis);
    double a_b = rb_cross(g.rb, g.axis);
    rb_block_matrix k = make_block(f, s_a, s_b, a_a, a_b);
    bool turns = make_regular(&k);
    double across = rb_dot(g.normal, g.d);
    double angle = turns ? rb_joint_relative_angle(world, joint, p->reference_angle) : 0.0;
    double violation = limit_violation(p, rb_dot(g.axis, g.d));
    bool within = fabs(across) <= world->settings.linear_slop && fabs(angle) <= RB_ANGULAR_SLOP &&
                  fabs(violation) <= world->settings.linear_slop;
    double max_linear = world->settings.max_linear_correction;
    rb_vec2 c = rb_v2(fmin(fmax(across, -max_linear), max_linear),
                      fmin(fmax(angle, -RB_MAX_ANGULAR_CORRECTION), RB_MAX_ANGULAR_CORRECTION));
    double c_along = fmin(fmax(violation, -max_linear), max_linear);
    rb_vec2 impulse = rb_v2(0.0, 0.0);
    double along = 0.0;
    bool solved = c_along != 0.0 && rb_block_solve3(&k, rb_neg(c), -c_along, &impulse, &along);
    if (!solved && !rb_block_solve2(&k, rb_neg(c), &impulse)) {
        return within;
    }
    rb_vec2 linear = rb_add(rb_scale(impulse.x, g.normal), rb_scale(along, g.axis));
    a->center = rb_mul_sub(a->center, f->inv_mass_a, linear);
    b->center = rb_mul_add(b->center, f->inv_mass_b, linear);
    if (f->inv_inertia_a > 0.0) {
        rb_body_state_turn(a, -(f->inv_inertia_a * (impulse.x * s_a + impulse.y + along * a_a)));
    }
    if (f->inv_inertia_b > 0.0) {
        rb_body_state_turn(b, f->inv_inertia_b * (impulse.x * s_b + impulse.y + along * a_b));
    }
    return within;
}
