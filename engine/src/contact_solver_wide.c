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
 * (tests/test_contact_lanes.c). For NGS and Baumgarte, the pairs of one
 * colour that use the 2x2 block are prepared into rows
 * (rb_contact_row), which their warm start and velocity passes solve two
 * at a time (contact_rows_two.c), instead of their constraints
 * (tests/test_contact_rows.c). Without SSE2 the reference prepares them
 * all. */
#include "contact_solver.h"

#if defined(__SSE2__)
#include "contact_lanes_two.h"

/* 1/k where k > 0, else 0, as mass_from_arms: the effective mass of a row
 * of lever arms a, b about the two centres. */
static inline lanes mass_from_arms(lanes inv_mass_sum, lanes ia, lanes ib, lanes a, lanes b)
{
    lanes k = add(add(inv_mass_sum, mul(mul(ia, a), a)), mul(mul(ib, b), b));
    return select(_mm_cmpgt_pd(k, _mm_setzero_pd()), _mm_div_pd(both(1.0), k), _mm_setzero_pd());
}

/* What the preparation of two contacts reads of their constraints and
 * bodies besides each point's surface points, read once before anything
 * is stored: the stores into the row are doubles, as these are, so the
 * compiler could not tell that they leave these unchanged and would read
 * them again after every one. */
typedef struct two_contacts {
    pose_lanes a, b;          /* the bodies' poses */
    lanes nx, ny;             /* the normal as the bodies now turn it */
    lanes radius_a, radius_b; /* m, of a circle side; 0 for a polygon's */
    lanes inv_mass_a, inv_mass_b, inv_inertia_a, inv_inertia_b;
} two_contacts;

/* Point j of both contacts, as rb_contact_solver_prepare_points_range
 * prepares it, into q. Inlined whatever its size, so that the two points
 * share what they read. */
static inline __attribute__((always_inline)) void
prepare_point(const rb_contact_constraint *c0, const rb_contact_constraint *c1, int j, const two_contacts *t,
              const rb_solver_settings *settings, double inv_h, rb_substep_rows rows, rb_row_point *q)
{
    const rb_constraint_point *p0 = &c0->points[j];
    const rb_constraint_point *p1 = &c1->points[j];
    lanes cax = t->a.cx;
    lanes cay = t->a.cy;
    lanes cbx = t->b.cx;
    lanes cby = t->b.cy;
    lanes qac = t->a.qc;
    lanes qas = t->a.qs;
    lanes qbc = t->b.qc;
    lanes qbs = t->b.qs;
    lanes nx = t->nx;
    lanes ny = t->ny;
    lanes lax = pair(p0->local_surface_a.x, p1->local_surface_a.x);
    lanes lay = pair(p0->local_surface_a.y, p1->local_surface_a.y);
    lanes lbx = pair(p0->local_surface_b.x, p1->local_surface_b.x);
    lanes lby = pair(p0->local_surface_b.y, p1->local_surface_b.y);
    /* current_geometry: each surface point carried by its body, moved out
     * along the normal by a circle's radius. */
    lanes radius_a = t->radius_a;
    lanes radius_b = t->radius_b;
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
    lanes tangent_arm_a = sub(mul(rax, ty), mul(ray, tx));
    lanes tangent_arm_b = sub(mul(rbx, ty), mul(rby, tx));
    store(&q->normal_arm_a, sub(mul(rax, ny), mul(ray, nx)));
    store(&q->normal_arm_b, sub(mul(rbx, ny), mul(rby, nx)));
    store(&q->tangent_arm_a, tangent_arm_a);
    store(&q->tangent_arm_b, tangent_arm_b);
    lanes inv_mass_sum = add(t->inv_mass_a, t->inv_mass_b);
    store(&q->tangent_mass,
          mass_from_arms(inv_mass_sum, t->inv_inertia_a, t->inv_inertia_b, tangent_arm_a, tangent_arm_b));
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
    store(&q->min_normal_velocity, select(open, closing, bound));
}

/* Both contacts' points, as the reference prepares them, into `row`: the
 * normal turned with the body whose face it is, then each point, then the
 * 2x2 block (prepare_block), its inverse kept as the constraint had it
 * where the block is not used. Returns which of the two use the block:
 * bit 0 the first, bit 1 the second. The points' own normal masses, which
 * the reference finds where the block does not replace them, are left to
 * give_back. */
static int prepare_two(const rb_contact_constraint *c0, const rb_contact_constraint *c1, const rb_body_state *states,
                       const rb_solver_settings *settings, double inv_h, rb_substep_rows rows, rb_contact_row *row)
{
    const rb_body_state *a0 = &states[c0->body_a];
    const rb_body_state *b0 = &states[c0->body_b];
    const rb_body_state *a1 = &states[c1->body_a];
    const rb_body_state *b1 = &states[c1->body_b];
    two_contacts t = {.a = poses(a0, a1),
                      .b = poses(b0, b1),
                      .radius_a = pair(c0->radius_a, c1->radius_a),
                      .radius_b = pair(c0->radius_b, c1->radius_b),
                      .inv_mass_a = pair(c0->inv_mass_a, c1->inv_mass_a),
                      .inv_mass_b = pair(c0->inv_mass_b, c1->inv_mass_b),
                      .inv_inertia_a = pair(c0->inv_inertia_a, c1->inv_inertia_a),
                      .inv_inertia_b = pair(c0->inv_inertia_b, c1->inv_inertia_b)};
    turned_normals_of_two(c0, c1, a0, b0, a1, b1, &t.nx, &t.ny);
    int kept_block = (int)c0->use_block | (int)c1->use_block << 1;
    store(&row->normal_x, t.nx);
    store(&row->normal_y, t.ny);
    store(&row->tangent_y, negate(t.nx));
    prepare_point(c0, c1, 0, &t, settings, inv_h, rows, &row->points[0]);
    prepare_point(c0, c1, 1, &t, settings, inv_h, rows, &row->points[1]);

    lanes ma = t.inv_mass_a;
    lanes mb = t.inv_mass_b;
    lanes ia = t.inv_inertia_a;
    lanes ib = t.inv_inertia_b;
    store(&row->inv_mass_a, ma);
    store(&row->inv_mass_b, mb);
    store(&row->inv_inertia_a, ia);
    store(&row->inv_inertia_b, ib);
    if (!rows.block_normals) {
        return kept_block;
    }
    lanes inv_mass_sum = add(ma, mb);
    lanes rn1a = load(&row->points[0].normal_arm_a);
    lanes rn1b = load(&row->points[0].normal_arm_b);
    lanes rn2a = load(&row->points[1].normal_arm_a);
    lanes rn2b = load(&row->points[1].normal_arm_b);
    lanes k11 = add(add(inv_mass_sum, mul(mul(ia, rn1a), rn1a)), mul(mul(ib, rn1b), rn1b));
    lanes k22 = add(add(inv_mass_sum, mul(mul(ia, rn2a), rn2a)), mul(mul(ib, rn2b), rn2b));
    lanes k12 = add(add(inv_mass_sum, mul(mul(ia, rn1a), rn2a)), mul(mul(ib, rn1b), rn2b));
    store(&row->k11, k11);
    store(&row->k22, k22);
    store(&row->k12, k12);
    lanes det = sub(mul(k11, k22), mul(k12, k12));
    lanes use_block = _mm_cmplt_pd(mul(k11, k11), mul(both(MAX_BLOCK_CONDITION), det));
    lanes inv_det = divide(both(1.0), det);
    lanes inv_k11 = mul(inv_det, k22);
    lanes inv_k22 = mul(inv_det, k11);
    lanes inv_k12 = mul(negate(inv_det), k12);
    int block = _mm_movemask_pd(use_block);
    if (block != 3) {
        /* the inverse as the constraints have it, kept where the block is
         * not used */
        inv_k11 = select(use_block, inv_k11, pair(c0->inv_k11, c1->inv_k11));
        inv_k22 = select(use_block, inv_k22, pair(c0->inv_k22, c1->inv_k22));
        inv_k12 = select(use_block, inv_k12, pair(c0->inv_k12, c1->inv_k12));
    }
    store(&row->inv_k11, inv_k11);
    store(&row->inv_k22, inv_k22);
    store(&row->inv_k12, inv_k12);
    return block;
}

static inline void give_back_field(double *first, double *second, const rb_lanes2 *field)
{
    *first = field->v[0];
    *second = field->v[1];
}

/* What prepare_two put in `row`, given to the two constraints, with the
 * points' own normal masses where the block (`block`, as prepare_two
 * returned it) does not replace them: the constraints as the reference
 * leaves them. */
static void give_back(const rb_contact_row *row, int block, rb_contact_constraint *c0, rb_contact_constraint *c1,
                      rb_substep_rows rows)
{
    give_back_field(&c0->normal.x, &c1->normal.x, &row->normal_x);
    give_back_field(&c0->normal.y, &c1->normal.y, &row->normal_y);
    for (int j = 0; j < 2; ++j) {
        const rb_row_point *q = &row->points[j];
        rb_constraint_point *p0 = &c0->points[j];
        rb_constraint_point *p1 = &c1->points[j];
        give_back_field(&p0->normal_arm_a, &p1->normal_arm_a, &q->normal_arm_a);
        give_back_field(&p0->normal_arm_b, &p1->normal_arm_b, &q->normal_arm_b);
        give_back_field(&p0->tangent_arm_a, &p1->tangent_arm_a, &q->tangent_arm_a);
        give_back_field(&p0->tangent_arm_b, &p1->tangent_arm_b, &q->tangent_arm_b);
        give_back_field(&p0->tangent_mass, &p1->tangent_mass, &q->tangent_mass);
        give_back_field(&p0->min_normal_velocity, &p1->min_normal_velocity, &q->min_normal_velocity);
    }
    if (rows.block_normals) {
        give_back_field(&c0->k11, &c1->k11, &row->k11);
        give_back_field(&c0->k12, &c1->k12, &row->k12);
        give_back_field(&c0->k22, &c1->k22, &row->k22);
        give_back_field(&c0->inv_k11, &c1->inv_k11, &row->inv_k11);
        give_back_field(&c0->inv_k12, &c1->inv_k12, &row->inv_k12);
        give_back_field(&c0->inv_k22, &c1->inv_k22, &row->inv_k22);
        c0->use_block = (block & 1) != 0;
        c1->use_block = (block & 2) != 0;
    }
    /* Two blocks need no points' masses: their divisions, which bound
     * the preparation's time, are left out. */
    if (block == 3) {
        return;
    }
    lanes use_block = mask_of(block & 1, block & 2);
    lanes inv_mass_sum = add(load(&row->inv_mass_a), load(&row->inv_mass_b));
    lanes ia = load(&row->inv_inertia_a);
    lanes ib = load(&row->inv_inertia_b);
    for (int j = 0; j < 2; ++j) {
        const rb_row_point *q = &row->points[j];
        lanes mass = mass_from_arms(inv_mass_sum, ia, ib, load(&q->normal_arm_a), load(&q->normal_arm_b));
        store_pair(&c0->points[j].normal_mass, &c1->points[j].normal_mass,
                   select(use_block, pair(c0->points[j].normal_mass, c1->points[j].normal_mass), mass));
    }
}

/* The rest of a row whose two contacts both use the block: their bodies,
 * friction and impulses, and where their constraints are. */
static void complete_row(rb_contact_row *row, const rb_contact_constraint *constraints, int i0, int i1,
                         rb_body_state *states)
{
    const rb_contact_constraint *c0 = &constraints[i0];
    const rb_contact_constraint *c1 = &constraints[i1];
    row->body_a[0] = &states[c0->body_a];
    row->body_a[1] = &states[c1->body_a];
    row->body_b[0] = &states[c0->body_b];
    row->body_b[1] = &states[c1->body_b];
    store(&row->friction, pair(c0->friction, c1->friction));
    for (int j = 0; j < 2; ++j) {
        store(&row->points[j].normal_impulse, pair(c0->points[j].normal_impulse, c1->points[j].normal_impulse));
        store(&row->points[j].tangent_impulse, pair(c0->points[j].tangent_impulse, c1->points[j].tangent_impulse));
    }
    row->constraints[0] = i0;
    row->constraints[1] = i1;
}

/* Whether a constraint can be prepared in a lane: two points and a normal
 * that turns with a body (circles' normals follow their centres, and
 * their contacts have one point anyway); and then solved in a row: no
 * restitution, whose pass reads the largest push of the step, which the
 * rows do not keep. */
static bool fits_a_row(const rb_contact_constraint *c)
{
    return c->point_count == 2 && c->normal_follows != RB_NORMAL_FROM_CENTERS && c->restitution == 0.0;
}

/* Constraint i, which the rows leave, to its colour's runs: to the last
 * run if it follows on from it. */
static inline void leave_to_runs(rb_contact_rows *laid, int colour, int *run_count, int i)
{
    if (*run_count > laid->run_start[colour] && laid->runs[*run_count - 1].end == i) {
        laid->runs[*run_count - 1].end = i + 1;
    } else {
        laid->runs[(*run_count)++] = (rb_constraint_run){i, i + 1};
    }
}

/* Each constraint's points depend on its own bodies alone, so any two can
 * be prepared together; the rows take two of one colour, which share no
 * moving body, so that the passes may solve them at once. The overflow
 * colour's constraints, which may share bodies, are solved one at a
 * time in their order, as are the constraints that do not fit a row and
 * pairs of which one does not use the block.
 *
 * The impulses stay in the rows from one substep to the next: the rows
 * are laid out in the same order each time, so while each new row pairs
 * the same two contacts as the row it replaces, the impulses are already
 * in place. From the first row that differs (a contact's block became
 * ill-conditioned, or well again), the rows left over from the last
 * substep give their impulses back to their constraints, and the new
 * rows take theirs from the constraints. */
void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows)
{
    rb_contact_rows *laid = &world->contact_rows;
    if (world->constraint_count == 0) { /* a world of joints and muscles: no rows, nothing to give back */
        laid->row_count = 0;
        laid->run_count = 0;
        laid->live = false;
        return;
    }
    /* rows held_from .. held_to - 1 still hold the last substep's
     * impulses */
    int held_from = 0;
    int held_to = laid->live ? laid->row_count : 0;
    double inv_h = 1.0 / h;
    rb_contact_constraint *constraints = world->constraints;
    int count = world->constraint_count;
    /* the soft step makes no room for rows: its constraints are only
     * prepared, two at a time where they fit */
    bool room = laid->row_capacity >= count / 2 && laid->run_capacity >= count;
    rb_contact_row scratch;
    int row_count = 0;
    int run_count = 0;
    int colours = laid->colour_count;
    for (int colour = 0; colour < colours; ++colour) {
        laid->row_start[colour] = row_count;
        laid->run_start[colour] = run_count;
        bool pairs = colour != RB_OVERFLOW_COLOUR || !room;
        int waiting = -1; /* a constraint that fits a row, waiting for another */
        int loose = -1;   /* the first of a run of constraints that fit no row, not yet prepared */
        int end = laid->colour_start[colour + 1];
        for (int i = laid->colour_start[colour]; i < end; ++i) {
            rb_contact_constraint *c = &constraints[i];
            if (!pairs || !fits_a_row(c)) {
                loose = loose < 0 ? i : loose;
                if (room) {
                    leave_to_runs(laid, colour, &run_count, i);
                }
                continue;
            }
            if (loose >= 0) {
                rb_contact_solver_prepare_points_range(world, h, rows, loose, i);
                loose = -1;
            }
            if (waiting < 0) {
                waiting = i;
                continue;
            }
            rb_contact_row *row = room ? &laid->rows[row_count] : &scratch;
            int block = prepare_two(&constraints[waiting], c, world->states, &world->settings, inv_h, rows, row);
            if (room && block == 3) {
                if (row_count < held_to && row->constraints[0] == waiting && row->constraints[1] == i) {
                    held_from = row_count + 1; /* the same two contacts: their impulses are in place */
                } else {
                    rb_contact_rows_store_range(world, row_count, held_to);
                    held_to = 0;
                    complete_row(row, constraints, waiting, i, world->states);
                }
                ++row_count;
            } else {
                give_back(row, block, &constraints[waiting], c, rows);
                if (room) {
                    leave_to_runs(laid, colour, &run_count, waiting);
                    leave_to_runs(laid, colour, &run_count, i);
                }
            }
            waiting = -1;
        }
        if (loose >= 0) {
            rb_contact_solver_prepare_points_range(world, h, rows, loose, end);
        }
        if (waiting >= 0) {
            rb_contact_solver_prepare_points_range(world, h, rows, waiting, waiting + 1);
            if (room) {
                leave_to_runs(laid, colour, &run_count, waiting);
            }
        }
    }
    rb_contact_rows_store_range(world, held_from, held_to);
    laid->row_start[colours] = row_count;
    laid->run_start[colours] = run_count;
    laid->row_count = row_count;
    laid->run_count = run_count;
    laid->live = room;
}

#else

void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows)
{
    rb_contact_solver_prepare_points_range(world, h, rows, 0, world->constraint_count);
}

#endif
