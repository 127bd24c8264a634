/* SPDX-License-Identifier: MIT */
/* The soft step's contact passes and the preparation of the contact
 * points, two contacts at a time.
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
 * Once a step, after the points are prepared, the two-point constraints
 * of each colour are paired and copied side by side into
 * rb_contact_pair (rb_contact_solver_gather_pairs): each value of the two
 * contacts sits in 16 aligned bytes, which one load brings into a
 * register, or which an instruction reads directly, with no register
 * spent on it. The pairs then hold the impulses through the step's
 * passes (warm start, solve, relax), and rb_contact_solver_scatter_pairs
 * writes them back to the constraints for restitution and the next step.
 * A contact with one point, the last of an odd colour and the overflow
 * colour (whose constraints may share bodies) go through the reference;
 * colour by colour, the pairs of a colour first and then its others,
 * which gives each body the reference's sums in the reference's order
 * (a body is in at most one constraint of a colour). Without SSE2 the
 * whole pass is the reference's.
 *
 * The bodies' velocities and poses are still gathered one value at a
 * time from world->states (64 bytes a body) and their velocities stored
 * back the same way: four bodies to a pair, at scattered places.
 *
 * The points' preparation at each substep (anchors, lever arms, masses,
 * bounds: rb_contact_solver_prepare_points_range) goes two at a time
 * too, for every solver: each constraint's points depend on its own
 * bodies only, so any two neighbours with two points each pair up, and
 * the constraints come out byte for byte as the reference leaves them. */
#include <string.h>

#include "allocator.h"
#include "contact_solver.h"

void rb_contact_batches_free(rb_contact_batches *batches)
{
    rb_free_array((void **)&batches->pairs, &batches->pair_capacity, sizeof *batches->pairs);
    rb_free_array((void **)&batches->singles, &batches->single_capacity, sizeof *batches->singles);
}

size_t rb_contact_batches_bytes(const rb_contact_batches *batches)
{
    return (size_t)batches->pair_capacity * sizeof *batches->pairs +
           (size_t)batches->single_capacity * sizeof *batches->singles;
}

#if defined(__SSE2__)
#include <emmintrin.h>

#include "constraint_colouring.h"

/* A pair of doubles, lane 0 for the first contact, lane 1 for the second. */
typedef __m128d lanes;

static inline lanes pair(double first, double second) { return _mm_set_pd(second, first); }
static inline lanes both(double value) { return _mm_set1_pd(value); }
static inline lanes load(const rb_double2 *x) { return _mm_load_pd(x->v); }
static inline void store(rb_double2 *x, lanes a) { _mm_store_pd(x->v, a); }
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

/* ---- gathering the pairs, and writing their impulses back --------------- */

/* Copies constraint c's values into lane `lane` of pair q. */
static void copy_into_lane(rb_contact_pair *q, int lane, int index, const rb_contact_constraint *c)
{
    q->constraints[lane] = index;
    q->body_a[lane] = c->body_a;
    q->body_b[lane] = c->body_b;
    q->normal_x.v[lane] = c->normal.x;
    q->normal_y.v[lane] = c->normal.y;
    q->inv_mass_a.v[lane] = c->inv_mass_a;
    q->inv_inertia_a.v[lane] = c->inv_inertia_a;
    q->inv_mass_b.v[lane] = c->inv_mass_b;
    q->inv_inertia_b.v[lane] = c->inv_inertia_b;
    q->friction.v[lane] = c->friction;
    q->radius_a.v[lane] = c->radius_a;
    q->radius_b.v[lane] = c->radius_b;
    q->against_fixed[lane] = c->against_fixed;
    for (int j = 0; j < 2; ++j) {
        const rb_constraint_point *p = &c->points[j];
        rb_pair_point *w = &q->points[j];
        w->local_surface_ax.v[lane] = p->local_surface_a.x;
        w->local_surface_ay.v[lane] = p->local_surface_a.y;
        w->local_surface_bx.v[lane] = p->local_surface_b.x;
        w->local_surface_by.v[lane] = p->local_surface_b.y;
        w->normal_arm_a.v[lane] = p->normal_arm_a;
        w->normal_arm_b.v[lane] = p->normal_arm_b;
        w->tangent_arm_a.v[lane] = p->tangent_arm_a;
        w->tangent_arm_b.v[lane] = p->tangent_arm_b;
        w->normal_mass.v[lane] = p->normal_mass;
        w->tangent_mass.v[lane] = p->tangent_mass;
        w->normal_impulse.v[lane] = p->normal_impulse;
        w->tangent_impulse.v[lane] = p->tangent_impulse;
        w->max_normal_impulse.v[lane] = p->max_normal_impulse;
    }
}

/* Within each colour, the first two-point constraint with the second,
 * the third with the fourth and so on; a two-point constraint left
 * without a partner and every other constraint of the colour become
 * singles. The arrays grow only when the contacts outgrow them. */
void rb_contact_solver_gather_pairs(rb_world *world)
{
    rb_contact_batches *batches = &world->contact_batches;
    int count = world->constraint_count;
    batches->pair_count = 0;
    batches->single_count = 0;
    if (rb_grow_array((void **)&batches->pairs, &batches->pair_capacity, count / 2, sizeof *batches->pairs) != 0 ||
        rb_grow_array((void **)&batches->singles, &batches->single_capacity, count, sizeof *batches->singles) != 0) {
        /* Out of memory: every constraint one at a time, as the reference
         * solves them, which needs nothing more. */
        memset(batches->pair_start, 0, sizeof batches->pair_start);
        memset(batches->single_start, 0, sizeof batches->single_start);
        batches->overflow_start = 0;
        return;
    }
    const rb_contact_constraint *constraints = world->constraints;
    int start[RB_COLOUR_COUNT + 1];
    rb_colouring_offsets(&world->contact_colouring, start);
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        batches->pair_start[colour] = batches->pair_count;
        batches->single_start[colour] = batches->single_count;
        int end = start[colour] + world->contact_colouring.sizes[colour];
        int waiting = -1; /* a two-point constraint without a partner yet */
        for (int i = start[colour]; i < end; ++i) {
            if (constraints[i].point_count != 2) {
                batches->singles[batches->single_count++] = i;
            } else if (waiting < 0) {
                waiting = i;
            } else {
                rb_contact_pair *q = &batches->pairs[batches->pair_count++];
                copy_into_lane(q, 0, waiting, &constraints[waiting]);
                copy_into_lane(q, 1, i, &constraints[i]);
                waiting = -1;
            }
        }
        if (waiting >= 0) {
            batches->singles[batches->single_count++] = waiting;
        }
    }
    batches->pair_start[RB_COLOUR_COUNT] = batches->pair_count;
    batches->single_start[RB_COLOUR_COUNT] = batches->single_count;
    batches->overflow_start = start[RB_OVERFLOW_COLOUR];
}

void rb_contact_solver_scatter_pairs(rb_world *world)
{
    const rb_contact_batches *batches = &world->contact_batches;
    for (int k = 0; k < batches->pair_count; ++k) {
        const rb_contact_pair *q = &batches->pairs[k];
        for (int lane = 0; lane < 2; ++lane) {
            rb_contact_constraint *c = &world->constraints[q->constraints[lane]];
            for (int j = 0; j < 2; ++j) {
                c->points[j].normal_impulse = q->points[j].normal_impulse.v[lane];
                c->points[j].tangent_impulse = q->points[j].tangent_impulse.v[lane];
                c->points[j].max_normal_impulse = q->points[j].max_normal_impulse.v[lane];
            }
        }
    }
}

/* ---- the passes over the pairs -------------------------------------------- */

/* The two bodies' velocities of each contact, as body_velocities is for one. */
typedef struct wide_velocities {
    lanes vax, vay, wa, vbx, vby, wb;
} wide_velocities;

/* The four bodies of a pair. */
typedef struct pair_bodies {
    rb_body_state *a0, *b0, *a1, *b1;
} pair_bodies;

static inline pair_bodies bodies_of(const rb_contact_pair *q, rb_body_state *states)
{
    return (pair_bodies){&states[q->body_a[0]], &states[q->body_b[0]], &states[q->body_a[1]], &states[q->body_b[1]]};
}

static inline wide_velocities load_velocities(const pair_bodies *s)
{
    return (wide_velocities){
        pair(s->a0->linear_velocity.x, s->a1->linear_velocity.x),
        pair(s->a0->linear_velocity.y, s->a1->linear_velocity.y),
        pair(s->a0->angular_velocity, s->a1->angular_velocity),
        pair(s->b0->linear_velocity.x, s->b1->linear_velocity.x),
        pair(s->b0->linear_velocity.y, s->b1->linear_velocity.y),
        pair(s->b0->angular_velocity, s->b1->angular_velocity),
    };
}

static inline void store_velocities(const wide_velocities *v, const pair_bodies *s)
{
    s->a0->linear_velocity = rb_v2(first_of(v->vax), first_of(v->vay));
    s->a0->angular_velocity = first_of(v->wa);
    s->b0->linear_velocity = rb_v2(first_of(v->vbx), first_of(v->vby));
    s->b0->angular_velocity = first_of(v->wb);
    s->a1->linear_velocity = rb_v2(second_of(v->vax), second_of(v->vay));
    s->a1->angular_velocity = second_of(v->wa);
    s->b1->linear_velocity = rb_v2(second_of(v->vbx), second_of(v->vby));
    s->b1->angular_velocity = second_of(v->wb);
}

/* The separation of point j of both contacts at the poses now, as
 * separation_now computes it. */
static inline lanes separation(const rb_contact_pair *q, const rb_pair_point *p, const pair_bodies *s)
{
    lanes lax = load(&p->local_surface_ax);
    lanes lay = load(&p->local_surface_ay);
    lanes lbx = load(&p->local_surface_bx);
    lanes lby = load(&p->local_surface_by);
    lanes qac = pair(s->a0->rotation.c, s->a1->rotation.c);
    lanes qas = pair(s->a0->rotation.s, s->a1->rotation.s);
    lanes qbc = pair(s->b0->rotation.c, s->b1->rotation.c);
    lanes qbs = pair(s->b0->rotation.s, s->b1->rotation.s);
    lanes qax = add(pair(s->a0->center.x, s->a1->center.x), sub(mul(qac, lax), mul(qas, lay)));
    lanes qay = add(pair(s->a0->center.y, s->a1->center.y), add(mul(qas, lax), mul(qac, lay)));
    lanes qbx = add(pair(s->b0->center.x, s->b1->center.x), sub(mul(qbc, lbx), mul(qbs, lby)));
    lanes qby = add(pair(s->b0->center.y, s->b1->center.y), add(mul(qbs, lbx), mul(qbc, lby)));
    lanes gap = add(mul(load(&q->normal_x), sub(qbx, qax)), mul(load(&q->normal_y), sub(qby, qay)));
    return sub(sub(gap, load(&q->radius_a)), load(&q->radius_b));
}

/* The velocity of point B relative to A along (dx, dy), as row_velocity. */
static inline lanes row_velocity(lanes dx, lanes dy, lanes arm_a, lanes arm_b, const wide_velocities *v)
{
    lanes along = add(mul(dx, sub(v->vbx, v->vax)), mul(dy, sub(v->vby, v->vay)));
    return sub(add(along, mul(v->wb, arm_b)), mul(v->wa, arm_a));
}

/* An impulse lambda along (dx, dy), as apply_row_impulse. */
static inline void apply_row_impulse(const rb_contact_pair *q, lanes dx, lanes dy, lanes arm_a, lanes arm_b,
                                     lanes lambda, wide_velocities *v)
{
    lanes px = mul(lambda, dx);
    lanes py = mul(lambda, dy);
    lanes ma = load(&q->inv_mass_a);
    lanes mb = load(&q->inv_mass_b);
    v->vax = sub(v->vax, mul(ma, px));
    v->vay = sub(v->vay, mul(ma, py));
    v->wa = sub(v->wa, mul(mul(load(&q->inv_inertia_a), lambda), arm_a));
    v->vbx = add(v->vbx, mul(mb, px));
    v->vby = add(v->vby, mul(mb, py));
    v->wb = add(v->wb, mul(mul(load(&q->inv_inertia_b), lambda), arm_b));
}

/* Both points' normal and friction impulses again, as the reference's
 * warm start applies them: point by point, the normal first. */
static void warm_start_pair(const rb_contact_pair *q, rb_body_state *states)
{
    pair_bodies s = bodies_of(q, states);
    wide_velocities v = load_velocities(&s);
    lanes nx = load(&q->normal_x);
    lanes ny = load(&q->normal_y);
    lanes tx = ny;
    lanes ty = negate(nx);
    for (int j = 0; j < 2; ++j) {
        const rb_pair_point *p = &q->points[j];
        apply_row_impulse(q, nx, ny, load(&p->normal_arm_a), load(&p->normal_arm_b), load(&p->normal_impulse), &v);
        apply_row_impulse(q, tx, ty, load(&p->tangent_arm_a), load(&p->tangent_arm_b), load(&p->tangent_impulse), &v);
    }
    store_velocities(&v, &s);
}

/* Colour by colour, as the reference goes through them: the colour's
 * pairs, then its singles; the overflow colour last. */
void rb_contact_solver_warm_start_pairs(rb_world *world)
{
    const rb_contact_batches *batches = &world->contact_batches;
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        for (int k = batches->pair_start[colour]; k < batches->pair_start[colour + 1]; ++k) {
            warm_start_pair(&batches->pairs[k], world->states);
        }
        for (int k = batches->single_start[colour]; k < batches->single_start[colour + 1]; ++k) {
            int i = batches->singles[k];
            rb_contact_solver_warm_start_range(world, i, i + 1);
        }
    }
    rb_contact_solver_warm_start_range(world, batches->overflow_start, world->constraint_count);
}

/* The springs of both contacts of a pair: each lane's, against a fixed
 * body or between moving ones. */
typedef struct wide_springs {
    lanes bias_rate; /* 1/s */
    lanes mass_scale, impulse_scale;
} wide_springs;

/* Point j's normal row, as solve_soft_point: where the gap is open, close
 * it within the substep; where it is not, the spring (with bias) or no
 * approach (relax). */
static inline void solve_normal(const rb_contact_pair *q, rb_pair_point *p, lanes s, const rb_contact_softness *k,
                                const wide_springs *spring, wide_velocities *v)
{
    lanes open = _mm_cmpgt_pd(s, _mm_setzero_pd());
    lanes closing = mul(s, both(k->inv_h));
    lanes bias = select(open, closing, _mm_setzero_pd());
    lanes mass_scale = both(1.0);
    lanes impulse_scale = _mm_setzero_pd();
    if (k->use_bias) {
        lanes push = max(mul(spring->bias_rate, s), both(-k->max_push_speed));
        bias = select(open, closing, push);
        mass_scale = select(open, mass_scale, spring->mass_scale);
        impulse_scale = select(open, impulse_scale, spring->impulse_scale);
    }
    lanes arm_a = load(&p->normal_arm_a);
    lanes arm_b = load(&p->normal_arm_b);
    lanes old = load(&p->normal_impulse);
    lanes nx = load(&q->normal_x);
    lanes ny = load(&q->normal_y);
    lanes vn = row_velocity(nx, ny, arm_a, arm_b, v);
    lanes impulse = sub(mul(mul(negate(load(&p->normal_mass)), mass_scale), add(vn, bias)), mul(impulse_scale, old));
    lanes accumulated = max(add(old, impulse), _mm_setzero_pd());
    store(&p->normal_impulse, accumulated);
    store(&p->max_normal_impulse, max(load(&p->max_normal_impulse), accumulated));
    apply_row_impulse(q, nx, ny, arm_a, arm_b, sub(accumulated, old), v);
}

/* Point j's friction, as solve_point_friction; a lane whose point has
 * neither push nor friction keeps its impulse and applies none. */
static inline void solve_friction(const rb_contact_pair *q, rb_pair_point *p, wide_velocities *v)
{
    lanes normal_impulse = load(&p->normal_impulse);
    lanes old = load(&p->tangent_impulse);
    lanes idle = _mm_and_pd(_mm_cmpeq_pd(normal_impulse, _mm_setzero_pd()), _mm_cmpeq_pd(old, _mm_setzero_pd()));
    lanes tx = load(&q->normal_y);
    lanes ty = negate(load(&q->normal_x));
    lanes arm_a = load(&p->tangent_arm_a);
    lanes arm_b = load(&p->tangent_arm_b);
    lanes vt = row_velocity(tx, ty, arm_a, arm_b, v);
    lanes limit = mul(load(&q->friction), normal_impulse);
    lanes accumulated = min(max(sub(old, mul(load(&p->tangent_mass), vt)), negate(limit)), limit);
    accumulated = select(idle, old, accumulated);
    store(&p->tangent_impulse, accumulated);
    apply_row_impulse(q, tx, ty, arm_a, arm_b, sub(accumulated, old), v);
}

/* The two contacts of a pair, each as the reference solves it. */
static void solve_pair(rb_contact_pair *q, rb_body_state *states, const rb_contact_softness *k)
{
    pair_bodies s = bodies_of(q, states);
    lanes fixed = mask_of(q->against_fixed[0], q->against_fixed[1]);
    wide_springs spring = {
        .bias_rate = select(fixed, both(k->against_fixed.bias_rate), both(k->between_moving.bias_rate)),
        .mass_scale = select(fixed, both(k->against_fixed.mass_scale), both(k->between_moving.mass_scale)),
        .impulse_scale = select(fixed, both(k->against_fixed.impulse_scale), both(k->between_moving.impulse_scale)),
    };
    lanes s0 = separation(q, &q->points[0], &s);
    lanes s1 = separation(q, &q->points[1], &s);
    wide_velocities v = load_velocities(&s);
    solve_normal(q, &q->points[0], s0, k, &spring, &v);
    solve_normal(q, &q->points[1], s1, k, &spring, &v);
    solve_friction(q, &q->points[0], &v);
    solve_friction(q, &q->points[1], &v);
    store_velocities(&v, &s);
}

void rb_contact_solver_solve_soft(rb_world *world, const rb_contact_softness *softness)
{
    rb_contact_softness k = *softness;
    const rb_contact_batches *batches = &world->contact_batches;
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        for (int p = batches->pair_start[colour]; p < batches->pair_start[colour + 1]; ++p) {
            solve_pair(&batches->pairs[p], world->states, &k);
        }
        for (int p = batches->single_start[colour]; p < batches->single_start[colour + 1]; ++p) {
            int i = batches->singles[p];
            rb_contact_solver_solve_soft_range(world, &k, i, i + 1);
        }
    }
    /* The overflow colour's constraints may share a body: one at a time. */
    rb_contact_solver_solve_soft_range(world, &k, batches->overflow_start, world->constraint_count);
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

/* Without SSE2 every constraint is solved one at a time, in the order
 * rb_contact_solver_prepare laid them out: no pairs. */
void rb_contact_solver_gather_pairs(rb_world *world) { (void)world; }

void rb_contact_solver_scatter_pairs(rb_world *world) { (void)world; }

void rb_contact_solver_warm_start_pairs(rb_world *world) { rb_contact_solver_warm_start(world); }

void rb_contact_solver_solve_soft(rb_world *world, const rb_contact_softness *softness)
{
    rb_contact_solver_solve_soft_range(world, softness, 0, world->constraint_count);
}

void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows)
{
    rb_contact_solver_prepare_points_range(world, h, rows, 0, world->constraint_count);
}

#endif
