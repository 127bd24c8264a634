/* SPDX-License-Identifier: MIT */
/* The soft contact pass and the preparation of the contact points, two
 * contacts at a time.
 *
 * Within a colour no two constraints move the same body
 * (constraint_colouring.h), so two of them can be solved at once, each in
 * one lane of the processor's 2 × double registers (SSE2, part of every
 * x86-64 processor): every sum and product of the one-at-a-time
 * reference (rb_contact_solver_solve_soft_range, contact_solver.c) is
 * done for both contacts by one instruction, in the reference's order,
 * and its branches become per-lane choices (select). Each lane so
 * computes what the reference computes for its contact, to the bit but
 * for the sign of a zero: a point with no push is still passed through
 * friction here, with an impulse of zero. tests/test_contact_lanes.c
 * checks that both leave equal velocities and impulses.
 *
 * The constraints stay where rb_contact_solver_prepare put them, one
 * struct each: a lane's values are loaded from its own constraint, one
 * half-register at a time, which costs what the reference's loads cost.
 * Pairs of two-point contacts go two at a time; a contact with one
 * point, the last of an odd colour and the overflow colour (whose
 * constraints may share bodies) go through the reference. Without SSE2
 * the whole pass does.
 *
 * The points' preparation at each substep (anchors, lever arms, masses,
 * bounds: rb_contact_solver_prepare_points_range) goes two at a time the
 * same way, for every solver: each constraint's points depend on its own
 * bodies only, so any two neighbours with two points each pair up, and
 * the constraints come out byte for byte as the reference leaves them.
 *
 * What it saves is the arithmetic: on the base-20 pyramid at Box2D v3's
 * budget the soft pass two at a time took the step from 3.72 M to 3.37 M
 * instructions (callgrind), and with constraint_rows (contact_solver.c)
 * before it from 0.256 to 0.228 ms (medians of 7 runs, interleaved).
 * The loads stay one per value, and each lane's results are taken apart
 * to be stored. Two things were measured and left out: the warm start
 * two at a time (four impulses applied per contact and little else)
 * saved nothing; building these functions a second time with AVX's
 * three-operand encoding, chosen as the program loads, cut the step to
 * 3.16 M instructions but not its time (0.229 ms): the register copies
 * it saves cost the processor next to nothing. */
#include "contact_solver.h"

#if defined(__SSE2__)
#include <emmintrin.h>

#include "constraint_colouring.h"

/* A pair of doubles, lane 0 for the first contact, lane 1 for the second. */
typedef __m128d lanes;

static inline lanes pair(double first, double second) { return _mm_set_pd(second, first); }
static inline lanes both(double value) { return _mm_set1_pd(value); }
static inline lanes add(lanes a, lanes b) { return _mm_add_pd(a, b); }
static inline lanes sub(lanes a, lanes b) { return _mm_sub_pd(a, b); }
static inline lanes mul(lanes a, lanes b) { return _mm_mul_pd(a, b); }
static inline lanes negate(lanes a) { return _mm_xor_pd(a, _mm_set1_pd(-0.0)); }
/* a > b ? a : b and a < b ? a : b in each lane, as rb_max and rb_min. */
static inline lanes max(lanes a, lanes b) { return _mm_max_pd(a, b); }
static inline lanes min(lanes a, lanes b) { return _mm_min_pd(a, b); }
/* In each lane, `yes` where the mask is all ones, `no` where it is zero. */
static inline lanes select(lanes mask, lanes yes, lanes no)
{
    return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}
static inline lanes mask_of(bool first, bool second)
{
    return _mm_castsi128_pd(_mm_set_epi64x(second ? -1 : 0, first ? -1 : 0));
}

static inline double first_of(lanes a) { return _mm_cvtsd_f64(a); }
static inline double second_of(lanes a) { return _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)); }

/* The two bodies' velocities of each contact, as body_velocities is for one. */
typedef struct wide_velocities {
    lanes vax, vay, wa, vbx, vby, wb;
} wide_velocities;

/* What the pass reads from the two constraints but never writes. */
typedef struct wide_rows {
    lanes nx, ny;         /* the normal; the tangent is (ny, -nx) */
    lanes ma, ia, mb, ib; /* inverse masses and inertias */
    lanes friction;       /* Coulomb coefficient */
    lanes bias_rate;      /* 1/s, the spring of each contact (against a fixed body or not) */
    lanes mass_scale, impulse_scale;
} wide_rows;

static inline wide_velocities load_velocities(const rb_body_state *a0, const rb_body_state *b0, const rb_body_state *a1,
                                              const rb_body_state *b1)
{
    return (wide_velocities){
        pair(a0->linear_velocity.x, a1->linear_velocity.x), pair(a0->linear_velocity.y, a1->linear_velocity.y),
        pair(a0->angular_velocity, a1->angular_velocity),   pair(b0->linear_velocity.x, b1->linear_velocity.x),
        pair(b0->linear_velocity.y, b1->linear_velocity.y), pair(b0->angular_velocity, b1->angular_velocity),
    };
}

static inline void store_lane(rb_body_state *a, rb_body_state *b, double vax, double vay, double wa, double vbx,
                              double vby, double wb)
{
    a->linear_velocity = rb_v2(vax, vay);
    a->angular_velocity = wa;
    b->linear_velocity = rb_v2(vbx, vby);
    b->angular_velocity = wb;
}

/* The separation of point j of both contacts at the poses now, as
 * separation_now computes it. */
static inline lanes separation(const rb_contact_constraint *c0, const rb_contact_constraint *c1, int j,
                               const rb_body_state *a0, const rb_body_state *b0, const rb_body_state *a1,
                               const rb_body_state *b1, const wide_rows *m)
{
    const rb_constraint_point *p0 = &c0->points[j];
    const rb_constraint_point *p1 = &c1->points[j];
    lanes lax = pair(p0->local_surface_a.x, p1->local_surface_a.x);
    lanes lay = pair(p0->local_surface_a.y, p1->local_surface_a.y);
    lanes lbx = pair(p0->local_surface_b.x, p1->local_surface_b.x);
    lanes lby = pair(p0->local_surface_b.y, p1->local_surface_b.y);
    lanes qac = pair(a0->rotation.c, a1->rotation.c);
    lanes qas = pair(a0->rotation.s, a1->rotation.s);
    lanes qbc = pair(b0->rotation.c, b1->rotation.c);
    lanes qbs = pair(b0->rotation.s, b1->rotation.s);
    lanes qax = add(pair(a0->center.x, a1->center.x), sub(mul(qac, lax), mul(qas, lay)));
    lanes qay = add(pair(a0->center.y, a1->center.y), add(mul(qas, lax), mul(qac, lay)));
    lanes qbx = add(pair(b0->center.x, b1->center.x), sub(mul(qbc, lbx), mul(qbs, lby)));
    lanes qby = add(pair(b0->center.y, b1->center.y), add(mul(qbs, lbx), mul(qbc, lby)));
    lanes gap = add(mul(m->nx, sub(qbx, qax)), mul(m->ny, sub(qby, qay)));
    return sub(sub(gap, pair(c0->radius_a, c1->radius_a)), pair(c0->radius_b, c1->radius_b));
}

/* The velocity of point B relative to A along (dx, dy), as row_velocity. */
static inline lanes row_velocity(lanes dx, lanes dy, lanes arm_a, lanes arm_b, const wide_velocities *v)
{
    lanes along = add(mul(dx, sub(v->vbx, v->vax)), mul(dy, sub(v->vby, v->vay)));
    return sub(add(along, mul(v->wb, arm_b)), mul(v->wa, arm_a));
}

/* An impulse lambda along (dx, dy), as apply_row_impulse. */
static inline void apply_row_impulse(const wide_rows *m, lanes dx, lanes dy, lanes arm_a, lanes arm_b, lanes lambda,
                                     wide_velocities *v)
{
    lanes px = mul(lambda, dx);
    lanes py = mul(lambda, dy);
    v->vax = sub(v->vax, mul(m->ma, px));
    v->vay = sub(v->vay, mul(m->ma, py));
    v->wa = sub(v->wa, mul(mul(m->ia, lambda), arm_a));
    v->vbx = add(v->vbx, mul(m->mb, px));
    v->vby = add(v->vby, mul(m->mb, py));
    v->wb = add(v->wb, mul(mul(m->ib, lambda), arm_b));
}

/* Point j's normal row, as solve_soft_point: where the gap is open, close
 * it within the substep; where it is not, the spring (with bias) or no
 * approach (relax). */
static inline void solve_normal(rb_constraint_point *p0, rb_constraint_point *p1, lanes s, const rb_contact_softness *k,
                                const wide_rows *m, wide_velocities *v)
{
    lanes open = _mm_cmpgt_pd(s, _mm_setzero_pd());
    lanes closing = mul(s, both(k->inv_h));
    lanes bias = select(open, closing, _mm_setzero_pd());
    lanes mass_scale = both(1.0);
    lanes impulse_scale = _mm_setzero_pd();
    if (k->use_bias) {
        lanes push = max(mul(m->bias_rate, s), both(-k->max_push_speed));
        bias = select(open, closing, push);
        mass_scale = select(open, mass_scale, m->mass_scale);
        impulse_scale = select(open, impulse_scale, m->impulse_scale);
    }
    lanes arm_a = pair(p0->normal_arm_a, p1->normal_arm_a);
    lanes arm_b = pair(p0->normal_arm_b, p1->normal_arm_b);
    lanes old = pair(p0->normal_impulse, p1->normal_impulse);
    lanes vn = row_velocity(m->nx, m->ny, arm_a, arm_b, v);
    lanes normal_mass = pair(p0->normal_mass, p1->normal_mass);
    lanes impulse = sub(mul(mul(negate(normal_mass), mass_scale), add(vn, bias)), mul(impulse_scale, old));
    lanes accumulated = max(add(old, impulse), _mm_setzero_pd());
    lanes most = max(pair(p0->max_normal_impulse, p1->max_normal_impulse), accumulated);
    _mm_storel_pd(&p0->normal_impulse, accumulated);
    _mm_storeh_pd(&p1->normal_impulse, accumulated);
    _mm_storel_pd(&p0->max_normal_impulse, most);
    _mm_storeh_pd(&p1->max_normal_impulse, most);
    apply_row_impulse(m, m->nx, m->ny, arm_a, arm_b, sub(accumulated, old), v);
}

/* Point j's friction, as solve_point_friction; a lane whose point has
 * neither push nor friction keeps its impulse and applies none. */
static inline void solve_friction(rb_constraint_point *p0, rb_constraint_point *p1, const wide_rows *m,
                                  wide_velocities *v)
{
    lanes normal_impulse = pair(p0->normal_impulse, p1->normal_impulse);
    lanes old = pair(p0->tangent_impulse, p1->tangent_impulse);
    lanes idle = _mm_and_pd(_mm_cmpeq_pd(normal_impulse, _mm_setzero_pd()), _mm_cmpeq_pd(old, _mm_setzero_pd()));
    lanes tx = m->ny;
    lanes ty = negate(m->nx);
    lanes arm_a = pair(p0->tangent_arm_a, p1->tangent_arm_a);
    lanes arm_b = pair(p0->tangent_arm_b, p1->tangent_arm_b);
    lanes vt = row_velocity(tx, ty, arm_a, arm_b, v);
    lanes limit = mul(m->friction, normal_impulse);
    lanes tangent_mass = pair(p0->tangent_mass, p1->tangent_mass);
    lanes accumulated = min(max(sub(old, mul(tangent_mass, vt)), negate(limit)), limit);
    accumulated = select(idle, old, accumulated);
    _mm_storel_pd(&p0->tangent_impulse, accumulated);
    _mm_storeh_pd(&p1->tangent_impulse, accumulated);
    apply_row_impulse(m, tx, ty, arm_a, arm_b, sub(accumulated, old), v);
}

/* Two two-point contacts of one colour, each as the reference solves it. */
static void solve_two(rb_contact_constraint *c0, rb_contact_constraint *c1, rb_body_state *states,
                      const rb_contact_softness *k)
{
    rb_body_state *a0 = &states[c0->body_a];
    rb_body_state *b0 = &states[c0->body_b];
    rb_body_state *a1 = &states[c1->body_a];
    rb_body_state *b1 = &states[c1->body_b];
    lanes fixed = mask_of(c0->against_fixed, c1->against_fixed);
    wide_rows m = {
        .nx = pair(c0->normal.x, c1->normal.x),
        .ny = pair(c0->normal.y, c1->normal.y),
        .ma = pair(c0->inv_mass_a, c1->inv_mass_a),
        .ia = pair(c0->inv_inertia_a, c1->inv_inertia_a),
        .mb = pair(c0->inv_mass_b, c1->inv_mass_b),
        .ib = pair(c0->inv_inertia_b, c1->inv_inertia_b),
        .friction = pair(c0->friction, c1->friction),
        .bias_rate = select(fixed, both(k->against_fixed.bias_rate), both(k->between_moving.bias_rate)),
        .mass_scale = select(fixed, both(k->against_fixed.mass_scale), both(k->between_moving.mass_scale)),
        .impulse_scale = select(fixed, both(k->against_fixed.impulse_scale), both(k->between_moving.impulse_scale)),
    };
    lanes s0 = separation(c0, c1, 0, a0, b0, a1, b1, &m);
    lanes s1 = separation(c0, c1, 1, a0, b0, a1, b1, &m);
    wide_velocities v = load_velocities(a0, b0, a1, b1);
    solve_normal(&c0->points[0], &c1->points[0], s0, k, &m, &v);
    solve_normal(&c0->points[1], &c1->points[1], s1, k, &m, &v);
    solve_friction(&c0->points[0], &c1->points[0], &m, &v);
    solve_friction(&c0->points[1], &c1->points[1], &m, &v);
    store_lane(a0, b0, first_of(v.vax), first_of(v.vay), first_of(v.wa), first_of(v.vbx), first_of(v.vby),
               first_of(v.wb));
    store_lane(a1, b1, second_of(v.vax), second_of(v.vay), second_of(v.wa), second_of(v.vbx), second_of(v.vby),
               second_of(v.wb));
}

void rb_contact_solver_solve_soft(rb_world *world, const rb_contact_softness *softness)
{
    rb_contact_softness k = *softness;
    rb_contact_constraint *constraints = world->constraints;
    int start[RB_COLOUR_COUNT + 1];
    rb_colouring_offsets(&world->contact_colouring, start);
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        int end = start[colour] + world->contact_colouring.sizes[colour];
        int i = start[colour];
        while (i + 1 < end) {
            rb_contact_constraint *c0 = &constraints[i];
            rb_contact_constraint *c1 = &constraints[i + 1];
            if (c0->point_count == 2 && c1->point_count == 2) {
                solve_two(c0, c1, world->states, &k);
                i += 2;
            } else {
                rb_contact_solver_solve_soft_range(world, &k, i, i + 1);
                i += 1;
            }
        }
        rb_contact_solver_solve_soft_range(world, &k, i, end);
    }
    /* The overflow colour's constraints may share a body: one at a time. */
    rb_contact_solver_solve_soft_range(world, &k, start[RB_OVERFLOW_COLOUR], world->constraint_count);
}

/* ---- preparing the points, two contacts at a time ----------------------- */

/* 1/k where k > 0, else 0, as mass_from_arms: the effective mass of a row
 * of lever arms a, b about the two centres. */
static inline lanes mass_from_arms(lanes inv_mass_sum, lanes ia, lanes ib, lanes a, lanes b)
{
    lanes k = add(add(inv_mass_sum, mul(mul(ia, a), a)), mul(mul(ib, b), b));
    return select(_mm_cmpgt_pd(k, _mm_setzero_pd()), _mm_div_pd(both(1.0), k), _mm_setzero_pd());
}

/* Stores lane 0 in *first and lane 1 in *second. */
static inline void store_pair(double *first, double *second, lanes a)
{
    _mm_storel_pd(first, a);
    _mm_storeh_pd(second, a);
}

/* Point j of both contacts, as rb_contact_solver_prepare_points_range
 * prepares it, with the normal (nx, ny) as the bodies now turn it. */
static inline void prepare_point(rb_contact_constraint *c0, rb_contact_constraint *c1, int j, const rb_body_state *a0,
                                 const rb_body_state *b0, const rb_body_state *a1, const rb_body_state *b1, lanes nx,
                                 lanes ny, const rb_solver_settings *settings, double inv_h, rb_substep_rows rows)
{
    rb_constraint_point *p0 = &c0->points[j];
    rb_constraint_point *p1 = &c1->points[j];
    lanes cax = pair(a0->center.x, a1->center.x);
    lanes cay = pair(a0->center.y, a1->center.y);
    lanes cbx = pair(b0->center.x, b1->center.x);
    lanes cby = pair(b0->center.y, b1->center.y);
    lanes qac = pair(a0->rotation.c, a1->rotation.c);
    lanes qas = pair(a0->rotation.s, a1->rotation.s);
    lanes qbc = pair(b0->rotation.c, b1->rotation.c);
    lanes qbs = pair(b0->rotation.s, b1->rotation.s);
    lanes lax = pair(p0->local_surface_a.x, p1->local_surface_a.x);
    lanes lay = pair(p0->local_surface_a.y, p1->local_surface_a.y);
    lanes lbx = pair(p0->local_surface_b.x, p1->local_surface_b.x);
    lanes lby = pair(p0->local_surface_b.y, p1->local_surface_b.y);
    /* current_geometry: each surface point carried by its body, moved out
     * along the normal by a circle's radius. */
    lanes radius_a = pair(c0->radius_a, c1->radius_a);
    lanes radius_b = pair(c0->radius_b, c1->radius_b);
    lanes pax = add(add(cax, sub(mul(qac, lax), mul(qas, lay))), mul(radius_a, nx));
    lanes pay = add(add(cay, add(mul(qas, lax), mul(qac, lay))), mul(radius_a, ny));
    lanes pbx = sub(add(cbx, sub(mul(qbc, lbx), mul(qbs, lby))), mul(radius_b, nx));
    lanes pby = sub(add(cby, add(mul(qbs, lbx), mul(qbc, lby))), mul(radius_b, ny));
    lanes s = add(mul(nx, sub(pbx, pax)), mul(ny, sub(pby, pay)));
    /* anchors_at_midpoint */
    lanes half = both(0.5);
    lanes mx = add(pax, mul(half, sub(pbx, pax)));
    lanes my = add(pay, mul(half, sub(pby, pay)));
    lanes rax = sub(mx, cax);
    lanes ray = sub(my, cay);
    lanes rbx = sub(mx, cbx);
    lanes rby = sub(my, cby);
    /* the lever arms r×n and r×t, with t = (ny, -nx) */
    lanes tx = ny;
    lanes ty = negate(nx);
    lanes normal_arm_a = sub(mul(rax, ny), mul(ray, nx));
    lanes normal_arm_b = sub(mul(rbx, ny), mul(rby, nx));
    lanes tangent_arm_a = sub(mul(rax, ty), mul(ray, tx));
    lanes tangent_arm_b = sub(mul(rbx, ty), mul(rby, tx));
    store_pair(&p0->normal_arm_a, &p1->normal_arm_a, normal_arm_a);
    store_pair(&p0->normal_arm_b, &p1->normal_arm_b, normal_arm_b);
    store_pair(&p0->tangent_arm_a, &p1->tangent_arm_a, tangent_arm_a);
    store_pair(&p0->tangent_arm_b, &p1->tangent_arm_b, tangent_arm_b);
    lanes inv_mass_sum = add(pair(c0->inv_mass_a, c1->inv_mass_a), pair(c0->inv_mass_b, c1->inv_mass_b));
    lanes ia = pair(c0->inv_inertia_a, c1->inv_inertia_a);
    lanes ib = pair(c0->inv_inertia_b, c1->inv_inertia_b);
    store_pair(&p0->tangent_mass, &p1->tangent_mass,
               mass_from_arms(inv_mass_sum, ia, ib, tangent_arm_a, tangent_arm_b));
    /* The lower bound of the normal velocity: close an open gap within
     * the substep; push overlap out (Baumgarte) or only stop approach. */
    lanes closing = mul(negate(s), both(inv_h));
    lanes bound = _mm_setzero_pd();
    if (rows.baumgarte_bias) {
        lanes beyond = max(sub(negate(s), both(settings->linear_slop)), _mm_setzero_pd());
        lanes push = min(mul(both(settings->baumgarte), beyond), both(settings->max_linear_correction));
        bound = mul(push, both(inv_h));
    }
    lanes open = _mm_cmpgt_pd(s, _mm_setzero_pd());
    store_pair(&p0->min_normal_velocity, &p1->min_normal_velocity, select(open, closing, bound));
}

/* Both contacts' points, as the reference prepares them: the normal
 * turned with the body whose face it is, then each point, then the 2x2
 * block (prepare_block) and the points' own normal masses where the block
 * does not replace them, each kept as it was where the reference leaves
 * it. */
static void prepare_two(rb_contact_constraint *c0, rb_contact_constraint *c1, const rb_body_state *states,
                        const rb_solver_settings *settings, double inv_h, rb_substep_rows rows)
{
    const rb_body_state *a0 = &states[c0->body_a];
    const rb_body_state *b0 = &states[c0->body_b];
    const rb_body_state *a1 = &states[c1->body_a];
    const rb_body_state *b1 = &states[c1->body_b];
    const rb_body_state *turns0 = c0->normal_follows == RB_NORMAL_TURNS_WITH_A ? a0 : b0;
    const rb_body_state *turns1 = c1->normal_follows == RB_NORMAL_TURNS_WITH_A ? a1 : b1;
    lanes qc = pair(turns0->rotation.c, turns1->rotation.c);
    lanes qs = pair(turns0->rotation.s, turns1->rotation.s);
    lanes lx = pair(c0->local_normal.x, c1->local_normal.x);
    lanes ly = pair(c0->local_normal.y, c1->local_normal.y);
    lanes nx = sub(mul(qc, lx), mul(qs, ly));
    lanes ny = add(mul(qs, lx), mul(qc, ly));
    _mm_storel_pd(&c0->normal.x, nx);
    _mm_storeh_pd(&c1->normal.x, nx);
    _mm_storel_pd(&c0->normal.y, ny);
    _mm_storeh_pd(&c1->normal.y, ny);
    prepare_point(c0, c1, 0, a0, b0, a1, b1, nx, ny, settings, inv_h, rows);
    prepare_point(c0, c1, 1, a0, b0, a1, b1, nx, ny, settings, inv_h, rows);

    lanes inv_mass_sum = add(pair(c0->inv_mass_a, c1->inv_mass_a), pair(c0->inv_mass_b, c1->inv_mass_b));
    lanes ia = pair(c0->inv_inertia_a, c1->inv_inertia_a);
    lanes ib = pair(c0->inv_inertia_b, c1->inv_inertia_b);
    lanes rn1a = pair(c0->points[0].normal_arm_a, c1->points[0].normal_arm_a);
    lanes rn1b = pair(c0->points[0].normal_arm_b, c1->points[0].normal_arm_b);
    lanes rn2a = pair(c0->points[1].normal_arm_a, c1->points[1].normal_arm_a);
    lanes rn2b = pair(c0->points[1].normal_arm_b, c1->points[1].normal_arm_b);
    lanes use_block = mask_of(c0->use_block, c1->use_block);
    if (rows.block_normals) {
        lanes k11 = add(add(inv_mass_sum, mul(mul(ia, rn1a), rn1a)), mul(mul(ib, rn1b), rn1b));
        lanes k22 = add(add(inv_mass_sum, mul(mul(ia, rn2a), rn2a)), mul(mul(ib, rn2b), rn2b));
        lanes k12 = add(add(inv_mass_sum, mul(mul(ia, rn1a), rn2a)), mul(mul(ib, rn1b), rn2b));
        store_pair(&c0->k11, &c1->k11, k11);
        store_pair(&c0->k22, &c1->k22, k22);
        store_pair(&c0->k12, &c1->k12, k12);
        lanes det = sub(mul(k11, k22), mul(k12, k12));
        use_block = _mm_cmplt_pd(mul(k11, k11), mul(both(MAX_BLOCK_CONDITION), det));
        lanes inv_det = _mm_div_pd(both(1.0), det);
        store_pair(&c0->inv_k11, &c1->inv_k11, select(use_block, mul(inv_det, k22), pair(c0->inv_k11, c1->inv_k11)));
        store_pair(&c0->inv_k22, &c1->inv_k22, select(use_block, mul(inv_det, k11), pair(c0->inv_k22, c1->inv_k22)));
        store_pair(&c0->inv_k12, &c1->inv_k12,
                   select(use_block, mul(negate(inv_det), k12), pair(c0->inv_k12, c1->inv_k12)));
        int block = _mm_movemask_pd(use_block);
        c0->use_block = (block & 1) != 0;
        c1->use_block = (block & 2) != 0;
    }
    store_pair(&c0->points[0].normal_mass, &c1->points[0].normal_mass,
               select(use_block, pair(c0->points[0].normal_mass, c1->points[0].normal_mass),
                      mass_from_arms(inv_mass_sum, ia, ib, rn1a, rn1b)));
    store_pair(&c0->points[1].normal_mass, &c1->points[1].normal_mass,
               select(use_block, pair(c0->points[1].normal_mass, c1->points[1].normal_mass),
                      mass_from_arms(inv_mass_sum, ia, ib, rn2a, rn2b)));
}

/* Whether a constraint's points can be prepared in a lane: two points
 * and a normal that turns with a body (circles' normals follow their
 * centres, and their contacts have one point anyway). */
static bool fits_a_lane(const rb_contact_constraint *c)
{
    return c->point_count == 2 && c->normal_follows != RB_NORMAL_FROM_CENTERS;
}

/* Each constraint's points depend on its own bodies alone, so any two
 * neighbours can be prepared together, whatever their colours. */
void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows)
{
    double inv_h = 1.0 / h;
    rb_contact_constraint *constraints = world->constraints;
    int count = world->constraint_count;
    int i = 0;
    while (i < count) {
        if (i + 1 < count && fits_a_lane(&constraints[i]) && fits_a_lane(&constraints[i + 1])) {
            prepare_two(&constraints[i], &constraints[i + 1], world->states, &world->settings, inv_h, rows);
            i += 2;
        } else {
            rb_contact_solver_prepare_points_range(world, h, rows, i, i + 1);
            i += 1;
        }
    }
}

#else

void rb_contact_solver_solve_soft(rb_world *world, const rb_contact_softness *softness)
{
    rb_contact_solver_solve_soft_range(world, softness, 0, world->constraint_count);
}

void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows)
{
    rb_contact_solver_prepare_points_range(world, h, rows, 0, world->constraint_count);
}

#endif
