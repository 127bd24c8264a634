/* SPDX-License-Identifier: MIT */
/* The soft step's contact passes over the blocks (warm start, which in
 * the step's first substep also prepares the points, and the soft pass
 * that solves and relaxes), WIDTH contacts to a vector
 * operation: included once with WIDTH 2 (contact_blocks_two.c) and once
 * with WIDTH 4 (contact_blocks_four.c, built for AVX), it defines
 * rb_contact_blocks_warm_start_WIDTH and rb_contact_blocks_solve_soft_WIDTH.
 *
 * Each lane does for its contact what the one-at-a-time reference
 * (rb_contact_solver_warm_start_range, rb_contact_solver_solve_soft_range,
 * contact_solver.c) does: the same sums and products in the same order,
 * its branches as per-lane choices (select); the vectors are the
 * compiler's own (GCC's vector extensions), so one text serves both
 * widths. A lane so gives the reference's bits, but for the sign of a
 * zero: a point with no push is still passed through friction here, with
 * an impulse of zero. The soft pass solves two sets of lanes together (a
 * block's two halves at WIDTH 2, two blocks at WIDTH 4), their rows
 * interleaved: within a colour the order does not matter, as no two of
 * its contacts move the same body. */
#include <string.h>

#include "contact_blocks.h"

#if WIDTH != 2 && WIDTH != 4
#error "contact_block_passes.h: define WIDTH as 2 or 4 before including it"
#endif

/* The names of this width's passes. */
#define NAMED(name, width) name##width
#define WITH_WIDTH(name, width) NAMED(name, width)

/* The vectors pass between this file's static functions only, every one
 * of them inlined, so GCC's note that a vector of 32 bytes would pass
 * differently between builds with and without AVX concerns no call. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

/* WIDTH doubles, and WIDTH 64-bit masks (all ones or all zeros). */
typedef double lanes __attribute__((vector_size(WIDTH * sizeof(double))));
typedef int64_t mask __attribute__((vector_size(WIDTH * sizeof(int64_t))));

/* The passes' helpers are inlined whatever their size: a vector passed
 * to a function that is not goes through memory. */
#define LANE_INLINE static inline __attribute__((always_inline))

LANE_INLINE lanes both(double value)
{
    lanes r;
    for (int k = 0; k < WIDTH; ++k) {
        r[k] = value;
    }
    return r;
}
LANE_INLINE lanes zero(void) { return both(0.0); }
/* Lanes first .. first + WIDTH - 1 of a block's value. */
LANE_INLINE lanes load(const rb_lanes4 *x, int first)
{
    lanes r;
    memcpy(&r, &x->v[first], sizeof r);
    return r;
}
LANE_INLINE void store(rb_lanes4 *x, int first, lanes a) { memcpy(&x->v[first], &a, sizeof a); }
/* In each lane, `yes` where the mask is all ones, `no` where it is zero. */
LANE_INLINE lanes select(mask m, lanes yes, lanes no) { return (lanes)((m & (mask)yes) | (~m & (mask)no)); }
/* a > b ? a : b and a < b ? a : b in each lane, as rb_max and rb_min:
 * what the x86 instructions maxpd and minpd compute, one instruction
 * where a comparison and a choice take three, on the chain of dependent
 * operations that each contact's rows are (contact_blocks.c). */
#if WIDTH == 2 && defined(__SSE2__)
LANE_INLINE lanes max(lanes a, lanes b) { return __builtin_ia32_maxpd(a, b); }
LANE_INLINE lanes min(lanes a, lanes b) { return __builtin_ia32_minpd(a, b); }
#elif WIDTH == 4 && defined(__AVX__)
LANE_INLINE lanes max(lanes a, lanes b) { return __builtin_ia32_maxpd256(a, b); }
LANE_INLINE lanes min(lanes a, lanes b) { return __builtin_ia32_minpd256(a, b); }
#else
LANE_INLINE lanes max(lanes a, lanes b) { return select(a > b, a, b); }
LANE_INLINE lanes min(lanes a, lanes b) { return select(a < b, a, b); }
#endif

/* The lanes of a block taken at once, from lane `first`, and their bodies. */
typedef struct block_lanes {
    rb_contact_block *q;
    int first;
    rb_body_state *a[WIDTH];
    rb_body_state *b[WIDTH];
} block_lanes;

LANE_INLINE block_lanes lanes_of(rb_contact_block *q, int first)
{
    block_lanes s = {.q = q, .first = first};
    for (int k = 0; k < WIDTH; ++k) {
        s.a[k] = q->body_a[first + k];
        s.b[k] = q->body_b[first + k];
    }
    return s;
}

/* The field `field` of the lanes' bodies on side `side` (a or b). */
#if WIDTH == 4
#define GATHER(s, side, field) ((lanes){s->side[0]->field, s->side[1]->field, s->side[2]->field, s->side[3]->field})
#else
#define GATHER(s, side, field) ((lanes){s->side[0]->field, s->side[1]->field})
#endif

/* A value of the lanes' contacts, or of their point p. */
#define VALUE(s, name) load(&(s)->q->name, (s)->first)
#define POINT_VALUE(s, p, name) load(&(p)->name, (s)->first)

/* The two bodies' velocities of each contact, as body_velocities is for one. */
typedef struct block_velocities {
    lanes vax, vay, wa, vbx, vby, wb;
} block_velocities;

LANE_INLINE block_velocities load_velocities(const block_lanes *s)
{
    return (block_velocities){
        GATHER(s, a, linear_velocity.x), GATHER(s, a, linear_velocity.y), GATHER(s, a, angular_velocity),
        GATHER(s, b, linear_velocity.x), GATHER(s, b, linear_velocity.y), GATHER(s, b, angular_velocity),
    };
}

LANE_INLINE void store_velocities(const block_velocities *v, const block_lanes *s)
{
    for (int k = 0; k < WIDTH; ++k) {
        s->a[k]->linear_velocity.x = v->vax[k];
        s->a[k]->linear_velocity.y = v->vay[k];
        s->a[k]->angular_velocity = v->wa[k];
        s->b[k]->linear_velocity.x = v->vbx[k];
        s->b[k]->linear_velocity.y = v->vby[k];
        s->b[k]->angular_velocity = v->wb[k];
    }
}

/* From point p's surface point on A to its surface point on B, each
 * carried by its body to the poses now. */
LANE_INLINE void surface_gap(const block_lanes *s, const rb_block_point *p, lanes *dx, lanes *dy)
{
    lanes lax = POINT_VALUE(s, p, local_surface_ax);
    lanes lay = POINT_VALUE(s, p, local_surface_ay);
    lanes lbx = POINT_VALUE(s, p, local_surface_bx);
    lanes lby = POINT_VALUE(s, p, local_surface_by);
    lanes qac = GATHER(s, a, rotation.c);
    lanes qas = GATHER(s, a, rotation.s);
    lanes qbc = GATHER(s, b, rotation.c);
    lanes qbs = GATHER(s, b, rotation.s);
    lanes qax = GATHER(s, a, center.x) + (qac * lax - qas * lay);
    lanes qay = GATHER(s, a, center.y) + (qas * lax + qac * lay);
    lanes qbx = GATHER(s, b, center.x) + (qbc * lbx - qbs * lby);
    lanes qby = GATHER(s, b, center.y) + (qbs * lbx + qbc * lby);
    *dx = qbx - qax;
    *dy = qby - qay;
}

/* The separation of point p of the lanes' contacts at the poses now, as
 * separation_now computes it; a block's contacts have no circle side, so
 * no radius to take off (x - 0 is x, to the bit). */
LANE_INLINE lanes separation(const block_lanes *s, const rb_block_point *p)
{
    lanes dx;
    lanes dy;
    surface_gap(s, p, &dx, &dy);
    return VALUE(s, normal_x) * dx + VALUE(s, normal_y) * dy;
}

/* The velocity of point B relative to A along (dx, dy), as row_velocity. */
LANE_INLINE lanes row_velocity(lanes dx, lanes dy, lanes arm_a, lanes arm_b, const block_velocities *v)
{
    lanes along = dx * (v->vbx - v->vax) + dy * (v->vby - v->vay);
    return along + v->wb * arm_b - v->wa * arm_a;
}

/* An impulse lambda along (dx, dy), as apply_row_impulse. */
LANE_INLINE void apply_row_impulse(const block_lanes *s, lanes dx, lanes dy, lanes arm_a, lanes arm_b, lanes lambda,
                                   block_velocities *v)
{
    lanes px = lambda * dx;
    lanes py = lambda * dy;
    lanes ma = VALUE(s, inv_mass_a);
    lanes mb = VALUE(s, inv_mass_b);
    v->vax = v->vax - ma * px;
    v->vay = v->vay - ma * py;
    v->wa = v->wa - VALUE(s, inv_inertia_a) * lambda * arm_a;
    v->vbx = v->vbx + mb * px;
    v->vby = v->vby + mb * py;
    v->wb = v->wb + VALUE(s, inv_inertia_b) * lambda * arm_b;
}

/* 1/k where k > 0, else 0, as mass_from_arms: the effective mass of a row
 * of lever arms a, b about the two centres. */
LANE_INLINE lanes mass_from_arms(lanes inv_mass_sum, lanes ia, lanes ib, lanes a, lanes b)
{
    lanes k = inv_mass_sum + ia * a * a + ib * b * b;
    return select(k > zero(), both(1.0) / k, zero());
}

/* Point p of the lanes' contacts at the poses now, as
 * rb_contact_solver_prepare_points_range prepares a constraint's: the
 * surface points carried by their bodies, the anchors from each centre
 * to the point midway between them, and the lever arms and effective
 * masses of the normal and the tangent t = (ny, -nx). The reference moves
 * each surface point out by its circle's radius; a block's contacts have
 * none, and the term (0·n) is kept so that even a zero's sign is the
 * reference's. */
LANE_INLINE void prepare_point(const block_lanes *s, rb_block_point *p)
{
    lanes nx = VALUE(s, normal_x);
    lanes ny = VALUE(s, normal_y);
    lanes cax = GATHER(s, a, center.x);
    lanes cay = GATHER(s, a, center.y);
    lanes cbx = GATHER(s, b, center.x);
    lanes cby = GATHER(s, b, center.y);
    lanes qac = GATHER(s, a, rotation.c);
    lanes qas = GATHER(s, a, rotation.s);
    lanes qbc = GATHER(s, b, rotation.c);
    lanes qbs = GATHER(s, b, rotation.s);
    lanes lax = POINT_VALUE(s, p, local_surface_ax);
    lanes lay = POINT_VALUE(s, p, local_surface_ay);
    lanes lbx = POINT_VALUE(s, p, local_surface_bx);
    lanes lby = POINT_VALUE(s, p, local_surface_by);
    lanes radius = zero();
    lanes pax = cax + (qac * lax - qas * lay) + radius * nx;
    lanes pay = cay + (qas * lax + qac * lay) + radius * ny;
    lanes pbx = cbx + (qbc * lbx - qbs * lby) - radius * nx;
    lanes pby = cby + (qbs * lbx + qbc * lby) - radius * ny;
    lanes half = both(0.5);
    lanes mx = pax + half * (pbx - pax);
    lanes my = pay + half * (pby - pay);
    lanes rax = mx - cax;
    lanes ray = my - cay;
    lanes rbx = mx - cbx;
    lanes rby = my - cby;
    lanes tx = ny;
    lanes ty = -nx;
    lanes normal_arm_a = rax * ny - ray * nx;
    lanes normal_arm_b = rbx * ny - rby * nx;
    lanes tangent_arm_a = rax * ty - ray * tx;
    lanes tangent_arm_b = rbx * ty - rby * tx;
    store(&p->normal_arm_a, s->first, normal_arm_a);
    store(&p->normal_arm_b, s->first, normal_arm_b);
    store(&p->tangent_arm_a, s->first, tangent_arm_a);
    store(&p->tangent_arm_b, s->first, tangent_arm_b);
    lanes inv_mass_sum = VALUE(s, inv_mass_a) + VALUE(s, inv_mass_b);
    lanes ia = VALUE(s, inv_inertia_a);
    lanes ib = VALUE(s, inv_inertia_b);
    store(&p->tangent_mass, s->first, mass_from_arms(inv_mass_sum, ia, ib, tangent_arm_a, tangent_arm_b));
    store(&p->normal_mass, s->first, mass_from_arms(inv_mass_sum, ia, ib, normal_arm_a, normal_arm_b));
}

/* Both points' normal and friction impulses again, as the reference's
 * warm start applies them: point by point, the normal first; with
 * `prepare`, each point prepared first. */
LANE_INLINE void warm_start_lanes(const block_lanes *s, bool prepare)
{
    if (prepare) {
        prepare_point(s, &s->q->points[0]);
        prepare_point(s, &s->q->points[1]);
    }
    block_velocities v = load_velocities(s);
    lanes nx = VALUE(s, normal_x);
    lanes ny = VALUE(s, normal_y);
    lanes tx = ny;
    lanes ty = -nx;
    for (int j = 0; j < 2; ++j) {
        const rb_block_point *p = &s->q->points[j];
        apply_row_impulse(s, nx, ny, POINT_VALUE(s, p, normal_arm_a), POINT_VALUE(s, p, normal_arm_b),
                          POINT_VALUE(s, p, normal_impulse), &v);
        apply_row_impulse(s, tx, ty, POINT_VALUE(s, p, tangent_arm_a), POINT_VALUE(s, p, tangent_arm_b),
                          POINT_VALUE(s, p, tangent_impulse), &v);
    }
    store_velocities(&v, s);
}

/* Colour by colour, as the reference goes through them: the colour's
 * blocks, then its singles; the overflow colour last. */
void WITH_WIDTH(rb_contact_blocks_warm_start_, WIDTH)(rb_world *world, bool prepare)
{
    const rb_contact_batches *batches = &world->contact_batches;
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        for (int k = batches->block_start[colour]; k < batches->block_start[colour + 1]; ++k) {
            for (int first = 0; first < RB_BLOCK_LANES; first += WIDTH) {
                block_lanes s = lanes_of(&batches->blocks[k], first);
                warm_start_lanes(&s, prepare);
            }
        }
        for (int k = batches->single_start[colour]; k < batches->single_start[colour + 1]; ++k) {
            int i = batches->singles[k];
            rb_contact_solver_warm_start_range(world, i, i + 1);
        }
    }
    rb_contact_solver_warm_start_range(world, batches->overflow_start, world->constraint_count);
}

/* The springs of the lanes' contacts: each lane's, against a fixed body
 * or between moving ones. */
typedef struct block_springs {
    lanes bias_rate; /* 1/s */
    lanes mass_scale, impulse_scale;
} block_springs;

/* Point p's normal row, as solve_soft_point: where the gap is open, close
 * it within the substep; where it is not, the spring (with bias) or no
 * approach (relax). */
LANE_INLINE void solve_normal(const block_lanes *s, rb_block_point *p, lanes separation_now,
                              const rb_contact_softness *k, const block_springs *spring, block_velocities *v)
{
    mask open = separation_now > zero();
    lanes closing = separation_now * both(k->inv_h);
    lanes bias = select(open, closing, zero());
    lanes mass_scale = both(1.0);
    lanes impulse_scale = zero();
    if (k->use_bias) {
        lanes push = max(spring->bias_rate * separation_now, both(-k->max_push_speed));
        bias = select(open, closing, push);
        mass_scale = select(open, mass_scale, spring->mass_scale);
        impulse_scale = select(open, impulse_scale, spring->impulse_scale);
    }
    lanes arm_a = POINT_VALUE(s, p, normal_arm_a);
    lanes arm_b = POINT_VALUE(s, p, normal_arm_b);
    lanes old = POINT_VALUE(s, p, normal_impulse);
    lanes nx = VALUE(s, normal_x);
    lanes ny = VALUE(s, normal_y);
    lanes vn = row_velocity(nx, ny, arm_a, arm_b, v);
    lanes impulse = -POINT_VALUE(s, p, normal_mass) * mass_scale * (vn + bias) - impulse_scale * old;
    lanes accumulated = max(old + impulse, zero());
    store(&p->normal_impulse, s->first, accumulated);
    apply_row_impulse(s, nx, ny, arm_a, arm_b, accumulated - old, v);
}

/* Point p's friction, as solve_point_friction; a lane whose point has
 * neither push nor friction keeps its impulse and applies none. */
LANE_INLINE void solve_friction(const block_lanes *s, rb_block_point *p, block_velocities *v)
{
    lanes normal_impulse = POINT_VALUE(s, p, normal_impulse);
    lanes old = POINT_VALUE(s, p, tangent_impulse);
    mask idle = (normal_impulse == zero()) & (old == zero());
    lanes tx = VALUE(s, normal_y);
    lanes ty = -VALUE(s, normal_x);
    lanes arm_a = POINT_VALUE(s, p, tangent_arm_a);
    lanes arm_b = POINT_VALUE(s, p, tangent_arm_b);
    lanes vt = row_velocity(tx, ty, arm_a, arm_b, v);
    lanes limit = VALUE(s, friction) * normal_impulse;
    lanes accumulated = min(max(old - POINT_VALUE(s, p, tangent_mass) * vt, -limit), limit);
    accumulated = select(idle, old, accumulated);
    store(&p->tangent_impulse, s->first, accumulated);
    apply_row_impulse(s, tx, ty, arm_a, arm_b, accumulated - old, v);
}

/* Each lane's springs, as the reference chooses them. */
LANE_INLINE block_springs springs_of(const block_lanes *s, const rb_contact_softness *k)
{
    mask fixed;
    memcpy(&fixed, &s->q->against_fixed[s->first], sizeof fixed);
    return (block_springs){
        .bias_rate = select(fixed, both(k->against_fixed.bias_rate), both(k->between_moving.bias_rate)),
        .mass_scale = select(fixed, both(k->against_fixed.mass_scale), both(k->between_moving.mass_scale)),
        .impulse_scale = select(fixed, both(k->against_fixed.impulse_scale), both(k->between_moving.impulse_scale)),
    };
}

/* The lanes' contacts, each as the reference solves it. */
LANE_INLINE void solve_lanes(const block_lanes *s, const rb_contact_softness *k)
{
    block_springs spring = springs_of(s, k);
    rb_block_point *p0 = &s->q->points[0];
    rb_block_point *p1 = &s->q->points[1];
    lanes s0 = separation(s, p0);
    lanes s1 = separation(s, p1);
    block_velocities v = load_velocities(s);
    solve_normal(s, p0, s0, k, &spring, &v);
    solve_normal(s, p1, s1, k, &spring, &v);
    solve_friction(s, p0, &v);
    solve_friction(s, p1, &v);
    store_velocities(&v, s);
}

/* Two sets of lanes of one colour, as solve_lanes solves each: they
 * touch different bodies, so their rows are interleaved (the first set's
 * first normal row, the second's, and so on), which gives the processor
 * two independent chains to work on at once (contact_blocks.c). */
LANE_INLINE void solve_two_sets(const block_lanes *s, const block_lanes *t, const rb_contact_softness *k)
{
    block_springs spring_s = springs_of(s, k);
    block_springs spring_t = springs_of(t, k);
    rb_block_point *p0 = &s->q->points[0];
    rb_block_point *p1 = &s->q->points[1];
    rb_block_point *r0 = &t->q->points[0];
    rb_block_point *r1 = &t->q->points[1];
    lanes s0 = separation(s, p0);
    lanes s1 = separation(s, p1);
    lanes t0 = separation(t, r0);
    lanes t1 = separation(t, r1);
    block_velocities v = load_velocities(s);
    block_velocities w = load_velocities(t);
    solve_normal(s, p0, s0, k, &spring_s, &v);
    solve_normal(t, r0, t0, k, &spring_t, &w);
    solve_normal(s, p1, s1, k, &spring_s, &v);
    solve_normal(t, r1, t1, k, &spring_t, &w);
    solve_friction(s, p0, &v);
    solve_friction(t, r0, &w);
    solve_friction(s, p1, &v);
    solve_friction(t, r1, &w);
    store_velocities(&v, s);
    store_velocities(&w, t);
}

/* The deepest overlap of the lanes' two points at the poses now, each
 * lane as carried_overlap measures its constraint (contact_solver.c):
 * the normal turned with the body whose face it is, read with the side
 * it turns with from the block's tail. */
LANE_INLINE lanes carried_overlap(const block_lanes *s, const rb_contact_block_tail *tail)
{
    mask with_a;
    memcpy(&with_a, &tail->turns_with_a[s->first], sizeof with_a);
    lanes qc = select(with_a, GATHER(s, a, rotation.c), GATHER(s, b, rotation.c));
    lanes qs = select(with_a, GATHER(s, a, rotation.s), GATHER(s, b, rotation.s));
    lanes lnx = load(&tail->local_normal_x, s->first);
    lanes lny = load(&tail->local_normal_y, s->first);
    lanes nx = qc * lnx - qs * lny;
    lanes ny = qs * lnx + qc * lny;
    lanes deepest = zero();
    for (int j = 0; j < 2; ++j) {
        lanes dx;
        lanes dy;
        surface_gap(s, &s->q->points[j], &dx, &dy);
        deepest = max(-(nx * dx + ny * dy), deepest);
    }
    return deepest;
}

/* Block k's impulses into its contacts' manifolds, for the step's last
 * pass, while the block is in the cache: written to the constraints
 * instead, and copied on by rb_contact_solver_store_impulses, they made
 * a stream of 15,000 writes more on the base-100 pyramid. */
LANE_INLINE void write_back(rb_world *world, const rb_contact_batches *batches, int k)
{
    const rb_contact_block *q = &batches->blocks[k];
    const rb_contact_block_tail *tail = &batches->tails[k];
    for (int lane = 0; lane < RB_BLOCK_LANES && tail->constraints[lane] >= 0; ++lane) {
        rb_manifold *m = &world->contacts[tail->contacts[lane]].manifold;
        for (int j = 0; j < 2; ++j) {
            m->points[j].normal_impulse = q->points[j].normal_impulse.v[lane];
            m->points[j].tangent_impulse = q->points[j].tangent_impulse.v[lane];
        }
    }
}

/* Blocks b .. b + n - 1's impulses into their contacts' manifolds
 * (write_back), in a function of its own, not inlined, which only the
 * step's last pass calls: inlined into the pass's loop, with the tails
 * apart from the blocks, it made the loop of every pass 15 % more
 * instructions (callgrind, the base-100 pyramid at Box2D v3's budget). */
static __attribute__((noinline)) void write_back_blocks(rb_world *world, const rb_contact_batches *batches, int b,
                                                        int n)
{
    for (int m = b; m < b + n; ++m) {
        write_back(world, batches, m);
    }
}

void WITH_WIDTH(rb_contact_blocks_solve_soft_, WIDTH)(rb_world *world, const rb_contact_softness *softness)
{
    rb_contact_softness k = *softness;
    rb_contact_batches *batches = &world->contact_batches;
    lanes deepest = zero();
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        /* Two sets of lanes at a time: at WIDTH 2 a block's two halves, at
         * WIDTH 4 two blocks, and the colour's last alone if it is odd. */
        int end = batches->block_start[colour + 1];
        int b = batches->block_start[colour];
#if WIDTH == 2
        for (; b < end; ++b) {
            block_lanes s = lanes_of(&batches->blocks[b], 0);
            block_lanes t = lanes_of(&batches->blocks[b], 2);
            solve_two_sets(&s, &t, &k);
            if (k.write_back) {
                write_back_blocks(world, batches, b, 1);
            }
            if (k.measure_overlap) {
                const rb_contact_block_tail *tail = &batches->tails[b];
                deepest = max(carried_overlap(&s, tail), max(carried_overlap(&t, tail), deepest));
            }
        }
#else
        for (; b + 1 < end; b += 2) {
            block_lanes s = lanes_of(&batches->blocks[b], 0);
            block_lanes t = lanes_of(&batches->blocks[b + 1], 0);
            solve_two_sets(&s, &t, &k);
            if (k.write_back) {
                write_back_blocks(world, batches, b, 2);
            }
            if (k.measure_overlap) {
                deepest = max(carried_overlap(&s, &batches->tails[b]),
                              max(carried_overlap(&t, &batches->tails[b + 1]), deepest));
            }
        }
        if (b < end) {
            block_lanes s = lanes_of(&batches->blocks[b], 0);
            solve_lanes(&s, &k);
            if (k.write_back) {
                write_back_blocks(world, batches, b, 1);
            }
            if (k.measure_overlap) {
                deepest = max(carried_overlap(&s, &batches->tails[b]), deepest);
            }
        }
#endif
        for (int p = batches->single_start[colour]; p < batches->single_start[colour + 1]; ++p) {
            int i = batches->singles[p];
            rb_contact_solver_solve_soft_range(world, &k, i, i + 1);
        }
    }
    /* The overflow colour's constraints may share a body: one at a time. */
    rb_contact_solver_solve_soft_range(world, &k, batches->overflow_start, world->constraint_count);
    if (k.measure_overlap) {
        double overlap = 0.0;
        for (int lane = 0; lane < WIDTH; ++lane) {
            overlap = deepest[lane] > overlap ? deepest[lane] : overlap;
        }
        batches->deepest_overlap = overlap;
        batches->overlap_measured = true;
    }
}
