/* SPDX-License-Identifier: MIT */
/* The preparation of the contact points at each substep (anchors, lever
 * arms, masses, bounds: rb_contact_solver_prepare_points_range), two
 * contacts at a time, for every solver.
 *
 * Each constraint's points depend on its own bodies only, so any two
 * neighbours with two points each can be prepared at once, each in one
 * lane of the processor's 2 × double registers (SSE2, part of every
 * x86-64 processor): every sum and product of the one-at-a-time
 * reference is done for both contacts by one instruction, in the
 * reference's order, and its branches become per-lane choices (select),
 * so the constraints come out byte for byte as the reference leaves them
 * (tests/test_contact_lanes.c). Without SSE2 the reference prepares them
 * all. */
#include "contact_solver.h"

#if defined(__SSE2__)
#include "contact_lanes_two.h"

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
 * prepares it, with the normal (nx, ny) as the bodies now turn it.
 * Inlined whatever its size, so that the two points share their bodies'
 * loads (a call for each point read them twice). */
static inline __attribute__((always_inline)) void prepare_point(rb_contact_constraint *c0, rb_contact_constraint *c1,
                                                                int j, const rb_body_state *a0, const rb_body_state *b0,
                                                                const rb_body_state *a1, const rb_body_state *b1,
                                                                lanes nx, lanes ny, const rb_solver_settings *settings,
                                                                double inv_h, rb_substep_rows rows)
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
    lanes nx, ny;
    turned_normals_of_two(c0, c1, a0, b0, a1, b1, &nx, &ny);
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
    /* Two blocks need no points' masses: their divisions, which bound
     * this function's time, are left out. */
    if (_mm_movemask_pd(use_block) == 3) {
        return;
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

void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows)
{
    rb_contact_solver_prepare_points_range(world, h, rows, 0, world->constraint_count);
}

#endif
