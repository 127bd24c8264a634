/* SPDX-License-Identifier: MIT */
/* Sequential impulses on contacts (Catto, "Iterative Dynamics with
 * Temporal Coherence", GDC 2005; "Fast and Simple Physics using
 * Sequential Impulses", GDC 2006).
 *
 * For a point with anchors rA, rB and normal n, the relative normal
 * velocity is vn = n·(vB + ωB×rB − vA − ωA×rA). An impulse λ along n
 * changes it by λ/m_n, where the effective mass is
 *     1/m_n = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB.
 * Each iteration sets λ so that vn reaches its lower bound, then clamps
 * the accumulated impulse to λ ≥ 0 (contacts push, never pull): this is
 * projected Gauss-Seidel on the velocity-level LCP. Friction is the same
 * along the tangent, clamped to the Coulomb cone |λt| ≤ μ·λn.
 */
#include <assert.h>
#include <string.h>

#include "allocator.h"
#include "contact.h"
#include "contact_blocks.h"
#include "contact_solver.h"
#include "error.h"

/* NGS stops early once no point is deeper than this many slops. */
#define NGS_TOLERANCE_SLOPS 3.0

static rb_vec2 tangent_of(rb_vec2 normal) { return rb_right_perp(normal); }

/* The effective mass of a row whose lever arms are r×d about each centre. */
static inline double mass_from_arms(double inv_mass_sum, double inv_ia, double inv_ib, double arm_a, double arm_b)
{
    double k = inv_mass_sum + inv_ia * arm_a * arm_a + inv_ib * arm_b * arm_b;
    return k > 0.0 ? 1.0 / k : 0.0;
}

static inline double effective_mass(double inv_mass_sum, double inv_ia, double inv_ib, rb_vec2 ra, rb_vec2 rb,
                                    rb_vec2 direction)
{
    return mass_from_arms(inv_mass_sum, inv_ia, inv_ib, rb_cross(ra, direction), rb_cross(rb, direction));
}

/* Relative velocity of the contact point on B with respect to A. */
static rb_vec2 relative_velocity(const rb_body_state *a, const rb_body_state *b, rb_vec2 ra, rb_vec2 rb)
{
    rb_vec2 vb = rb_add(b->linear_velocity, rb_cross_sv(b->angular_velocity, rb));
    rb_vec2 va = rb_add(a->linear_velocity, rb_cross_sv(a->angular_velocity, ra));
    return rb_sub(vb, va);
}

static bool is_solvable(const rb_world *world, const rb_contact *contact)
{
    if (contact->sensor || contact->manifold.point_count == 0) {
        return false;
    }
    const rb_body *a = &world->bodies[contact->body_a];
    const rb_body *b = &world->bodies[contact->body_b];
    return (a->type == RB_BODY_DYNAMIC && a->awake) || (b->type == RB_BODY_DYNAMIC && b->awake);
}

static void prepare_block(rb_contact_constraint *c)
{
    const rb_constraint_point *p1 = &c->points[0];
    const rb_constraint_point *p2 = &c->points[1];
    double inv_mass_sum = c->inv_mass_a + c->inv_mass_b;
    double rn1a = p1->normal_arm_a;
    double rn1b = p1->normal_arm_b;
    double rn2a = p2->normal_arm_a;
    double rn2b = p2->normal_arm_b;
    c->k11 = inv_mass_sum + c->inv_inertia_a * rn1a * rn1a + c->inv_inertia_b * rn1b * rn1b;
    c->k22 = inv_mass_sum + c->inv_inertia_a * rn2a * rn2a + c->inv_inertia_b * rn2b * rn2b;
    c->k12 = inv_mass_sum + c->inv_inertia_a * rn1a * rn2a + c->inv_inertia_b * rn1b * rn2b;
    double det = c->k11 * c->k22 - c->k12 * c->k12;
    c->use_block = c->k11 * c->k11 < MAX_BLOCK_CONDITION * det;
    if (c->use_block) {
        double inv_det = 1.0 / det;
        c->inv_k11 = inv_det * c->k22;
        c->inv_k22 = inv_det * c->k11;
        c->inv_k12 = -inv_det * c->k12;
    }
}

/* The body's index if the solver moves it (dynamic and awake), else -1. */
static int moving_index(const rb_world *world, int body)
{
    const rb_body *b = &world->bodies[body];
    return b->type == RB_BODY_DYNAMIC && b->awake ? body : -1;
}

/* Colours the contacts to solve (constraint_colouring.c), each contact
 * keeping its colour, and makes room for their constraints; for the soft
 * step, also counts each colour's contacts that take a lane of a block
 * (contact_blocks.c). start[k] is where colour k's constraints begin.
 * Returns how many contacts are solved, or -1 when out of memory. */
static int colour_contacts(rb_world *world, int start[RB_COLOUR_COUNT + 1])
{
    rb_colouring *colouring = &world->contact_colouring;
    if (rb_colouring_begin(colouring, world->body_slots) != 0) {
        return -1;
    }
    bool in_blocks = world->settings.type == RB_SOLVER_SOFT_STEP;
    int *lanes = world->contact_batches.lanes;
    if (in_blocks) {
        memset(lanes, 0, sizeof world->contact_batches.lanes);
    }
    int count = 0;
    for (int i = 0; i < world->contact_count; ++i) {
        rb_contact *contact = &world->contacts[i];
        contact->colour = -1;
        if (is_solvable(world, contact)) {
            contact->colour = rb_colouring_assign(colouring, moving_index(world, contact->body_a),
                                                  moving_index(world, contact->body_b));
            if (in_blocks) {
                lanes[contact->colour] += rb_contact_takes_a_lane(contact);
            }
            ++count;
        }
    }
    if (count == 0) {
        /* No colour holds any: the offsets are all 0, without a pass over
         * the colours (a world of joints alone, such as a muscle model). */
        memset(start, 0, (RB_COLOUR_COUNT + 1) * sizeof *start);
        world->statistics.contact_colours = 0;
        return 0;
    }
    if (rb_grow_array((void **)&world->constraints, &world->constraint_capacity, count, sizeof *world->constraints) !=
        0) {
        return -1;
    }
    world->statistics.contact_colours = rb_colouring_offsets(colouring, start);
    return count;
}

/* The shape's radius if it is a circle, else 0. */
static double circle_radius(const rb_shape *shape)
{
    return shape->type == RB_SHAPE_CIRCLE ? shape->geometry.circle.radius : 0.0;
}

/* The constraint's values are worked out in local variables and then
 * stored: read back through the pointer, each would be loaded again
 * after every store, the compiler being unable to tell that the stores
 * leave it unchanged. */
void rb_contact_solver_fill_constraint(rb_world *world, int index, rb_contact_constraint *c)
{
    const rb_contact *contact = &world->contacts[index];
    const rb_body *body_a = &world->bodies[contact->body_a];
    const rb_body *body_b = &world->bodies[contact->body_b];
    const rb_body_state *sa = &world->states[contact->body_a];
    const rb_body_state *sb = &world->states[contact->body_b];
    assert(contact->body_a != contact->body_b);
    assert(fabs(rb_length(contact->manifold.normal) - 1.0) < 1e-9);
    double inv_mass_a = body_a->awake ? body_a->inv_mass : 0.0;
    double inv_inertia_a = body_a->awake ? body_a->inv_inertia : 0.0;
    double inv_mass_b = body_b->awake ? body_b->inv_mass : 0.0;
    double inv_inertia_b = body_b->awake ? body_b->inv_inertia : 0.0;
    c->contact = index;
    c->body_a = contact->body_a;
    c->body_b = contact->body_b;
    c->inv_mass_a = inv_mass_a;
    c->inv_inertia_a = inv_inertia_a;
    c->inv_mass_b = inv_mass_b;
    c->inv_inertia_b = inv_inertia_b;
    c->against_fixed = (inv_mass_a == 0.0 && inv_inertia_a == 0.0) || (inv_mass_b == 0.0 && inv_inertia_b == 0.0);
    rb_vec2 normal = contact->manifold.normal;
    c->normal = normal;
    /* Only a circle has a radius, and a contact with a circle has one
     * point (manifold.c, segment_manifold.c): the shapes of a two-point
     * contact, the most common, need not be read. */
    int point_count = contact->manifold.point_count;
    double radius_a = 0.0;
    double radius_b = 0.0;
    bool circle_a = false;
    bool circle_b = false;
    if (point_count < 2) {
        const rb_shape *shape_a = &world->shapes[contact->pair.shape_a];
        const rb_shape *shape_b = &world->shapes[contact->pair.shape_b];
        circle_a = shape_a->type == RB_SHAPE_CIRCLE;
        circle_b = shape_b->type == RB_SHAPE_CIRCLE;
        radius_a = circle_radius(shape_a);
        radius_b = circle_radius(shape_b);
    }
    assert(point_count < 2 || (world->shapes[contact->pair.shape_a].type != RB_SHAPE_CIRCLE &&
                               world->shapes[contact->pair.shape_b].type != RB_SHAPE_CIRCLE));
    c->radius_a = radius_a;
    c->radius_b = radius_b;
    /* Which face the normal belongs to: a polygon's against a circle;
     * between outlines, the reference face. */
    bool reference_on_b = circle_a || (!circle_b && contact->manifold.reference_on_b);
    if (circle_a && circle_b) {
        c->normal_follows = RB_NORMAL_FROM_CENTERS;
        c->local_normal = normal;
    } else if (reference_on_b) {
        c->normal_follows = RB_NORMAL_TURNS_WITH_B;
        c->local_normal = rb_inv_rotate(sb->rotation, normal);
    } else {
        c->normal_follows = RB_NORMAL_TURNS_WITH_A;
        c->local_normal = rb_inv_rotate(sa->rotation, normal);
    }
    c->friction = contact->friction;
    c->restitution = contact->restitution;
    world->bouncing_constraint_count += contact->restitution > 0.0;
    c->point_count = point_count;
    bool warm = world->settings.warm_starting;
    for (int j = 0; j < point_count; ++j) {
        const rb_manifold_point *mp = &contact->manifold.points[j];
        rb_constraint_point *p = &c->points[j];
        rb_contact_local_surfaces(mp, normal, radius_a, radius_b, sa, sb, &p->local_surface_a, &p->local_surface_b);
        p->normal_impulse = warm ? mp->normal_impulse : 0.0;
        p->tangent_impulse = warm ? mp->tangent_impulse : 0.0;
        p->max_normal_impulse = 0.0;
        p->min_normal_velocity = 0.0;
    }
    c->use_block = false;
}

int rb_contact_solver_prepare(rb_world *world)
{
    world->bouncing_constraint_count = 0;
    /* No blocks until rb_contact_blocks_build lays them out: every
     * constraint is loose (rb_contact_solver_loose_constraint). */
    world->contact_batches.block_count = 0;
    world->contact_batches.single_count = 0;
    world->contact_batches.overflow_start = 0;
    int start[RB_COLOUR_COUNT + 1];
    int count = colour_contacts(world, start);
    if (count < 0) {
        world->constraint_count = 0;
        return -1;
    }
    world->constraint_count = count;
    rb_contact_rows *rows = &world->contact_rows;
    rows->live = false;
    memcpy(rows->colour_start, start, sizeof start);
    rows->colour_start[RB_COLOUR_COUNT + 1] = count;
    /* the colours up to the last that has constraints: colours fill from
     * the lowest, and most scenes use a few */
    rows->colour_count = count > 0 ? RB_COLOUR_COUNT + 1 : 0;
    while (rows->colour_count > 0 &&
           rows->colour_start[rows->colour_count - 1] == rows->colour_start[rows->colour_count]) {
        --rows->colour_count;
    }
    /* Room for the sequential solvers' rows (contact_solver_wide.c): at
     * most one a pair of constraints, and a run each of the others. */
    if (world->settings.type != RB_SOLVER_SOFT_STEP &&
        (rb_grow_array((void **)&rows->rows, &rows->row_capacity, count / 2, sizeof *rows->rows) != 0 ||
         rb_grow_array((void **)&rows->runs, &rows->run_capacity, count, sizeof *rows->runs) != 0)) {
        world->constraint_count = 0;
        return -1;
    }
    if (world->settings.type == RB_SOLVER_SOFT_STEP && rb_contact_blocks_build(world, start) == 0) {
        return count; /* the constraints and the blocks in one pass (contact_blocks.c) */
    }
    /* The constraints colour by colour, each colour's in the contacts'
     * order. */
    for (int i = 0; i < world->contact_count; ++i) {
        int colour = world->contacts[i].colour;
        if (colour >= 0) {
            rb_contact_solver_fill_constraint(world, i, &world->constraints[start[colour]++]);
        }
    }
    return count;
}

/* The normal of a contact whose normal is a face's, turned with the
 * body of that face as it is now. */
static inline rb_vec2 turned_normal(const rb_contact_constraint *c, const rb_body_state *sa, const rb_body_state *sb)
{
    if (c->normal_follows == RB_NORMAL_TURNS_WITH_A) {
        return rb_rotate(sa->rotation, c->local_normal);
    }
    return rb_rotate(sb->rotation, c->local_normal);
}

/* The contact as the bodies are now: the normal, turned with the body
 * whose face it is (or along the two centres for circles), and the two
 * surface points, each carried by its body (a polygon's material point,
 * or the point of a circle facing the other body). Exact at prepare time,
 * first-order accurate within the step (Catto, Box2D 2.x position
 * solver). */
static inline void current_geometry(const rb_contact_constraint *c, const rb_constraint_point *p,
                                    const rb_body_state *sa, const rb_body_state *sb, rb_vec2 *normal, rb_vec2 *pa,
                                    rb_vec2 *pb)
{
    rb_vec2 qa = rb_add(sa->center, rb_rotate(sa->rotation, p->local_surface_a));
    rb_vec2 qb = rb_add(sb->center, rb_rotate(sb->rotation, p->local_surface_b));
    if (c->normal_follows == RB_NORMAL_FROM_CENTERS) {
        rb_vec2 line = rb_sub(qb, qa);
        *normal = rb_length_squared(line) > 0.0 ? rb_normalize(line) : c->normal;
    } else {
        *normal = turned_normal(c, sa, sb);
    }
    *pa = rb_mul_add(qa, c->radius_a, *normal);
    *pb = rb_mul_sub(qb, c->radius_b, *normal);
}

static double current_separation(const rb_contact_constraint *c, const rb_constraint_point *p, const rb_body_state *sa,
                                 const rb_body_state *sb, rb_vec2 *normal)
{
    rb_vec2 pa;
    rb_vec2 pb;
    current_geometry(c, p, sa, sb, normal, &pa, &pb);
    return rb_dot(*normal, rb_sub(pb, pa));
}

/* The normal now, and the point midway between the two surface points as
 * offsets from each centre of mass. An impulse along that normal applied
 * at this one world point to both bodies conserves their momentum and
 * angular momentum. */
static inline void anchors_at_midpoint(const rb_body_state *sa, const rb_body_state *sb, rb_vec2 pa, rb_vec2 pb,
                                       rb_vec2 *ra, rb_vec2 *rb)
{
    rb_vec2 midpoint = rb_lerp(pa, pb, 0.5);
    *ra = rb_sub(midpoint, sa->center);
    *rb = rb_sub(midpoint, sb->center);
}

static void current_anchors(const rb_contact_constraint *c, const rb_constraint_point *p, const rb_body_state *sa,
                            const rb_body_state *sb, rb_vec2 *normal, rb_vec2 *ra, rb_vec2 *rb)
{
    rb_vec2 pa;
    rb_vec2 pb;
    current_geometry(c, p, sa, sb, normal, &pa, &pb);
    anchors_at_midpoint(sa, sb, pa, pb, ra, rb);
}

/* The linear acceleration gravity and the applied force give a body now
 * (m/s²): none for one that cannot move. */
static rb_vec2 body_acceleration(const rb_world *world, int index, double inv_mass)
{
    const rb_body *body = &world->bodies[index];
    if (body->type != RB_BODY_DYNAMIC || inv_mass == 0.0) {
        return rb_v2(0.0, 0.0);
    }
    return rb_mul_add(rb_scale(body->gravity_scale, world->gravity), inv_mass, body->force);
}

/* Where a bounce starts: the speed at which the surfaces meet, whatever
 * part of the step they meet in. Each substep until a point of a contact
 * with restitution first pushes, this records it from the gap s at the
 * substep's start and the point's normal velocity v (relative, after the
 * substep's gravity). Semi-implicit Euler's velocity is that of the
 * middle of the substep, so the velocity at its start is v - a·h/2, a the
 * normal relative acceleration of gravity and forces; crossing the gap
 * under a, the surfaces meet at -sqrt((v - a·h/2)² - 2·a·s). Measured once
 * per step, at its start, the impact speed of a ball dropped from 1 m at
 * 60 Hz was short by up to g·dt, 0.16 m/s, and its rebound by up to 7.8 %
 * of e²·h. A pass of its own, run only in steps with such contacts,
 * keeps the work (and the registers) out of every other contact's
 * substep. */
static void record_approaches(rb_world *world, double h, bool first_substep)
{
    int loose = rb_contact_solver_loose_count(world); /* the blocks' contacts have no restitution */
    for (int k = 0; k < loose; ++k) {
        int i = rb_contact_solver_loose_constraint(world, k);
        const rb_contact_constraint *c = &world->constraints[i];
        if (c->restitution == 0.0) {
            continue;
        }
        const rb_body_state *sa = &world->states[c->body_a];
        const rb_body_state *sb = &world->states[c->body_b];
        rb_vec2 acceleration = rb_sub(body_acceleration(world, c->body_b, c->inv_mass_b),
                                      body_acceleration(world, c->body_a, c->inv_mass_a));
        for (int j = 0; j < c->point_count; ++j) {
            rb_constraint_point *p = &world->constraints[i].points[j];
            if (!first_substep && p->max_normal_impulse > 0.0) {
                continue;
            }
            rb_vec2 normal;
            rb_vec2 pa;
            rb_vec2 pb;
            current_geometry(c, p, sa, sb, &normal, &pa, &pb);
            rb_vec2 ra;
            rb_vec2 rb;
            anchors_at_midpoint(sa, sb, pa, pb, &ra, &rb);
            double s = rb_dot(normal, rb_sub(pb, pa));
            double v = rb_dot(normal, relative_velocity(sa, sb, ra, rb));
            double a = rb_dot(normal, acceleration);
            double at_start = v - 0.5 * a * h;
            p->impact_velocity = -sqrt(fmax(at_start * at_start - 2.0 * a * fmax(s, 0.0), 0.0));
            p->approach_acceleration = a;
        }
    }
}

void rb_contact_solver_record_approaches(rb_world *world, double h)
{
    if (world->bouncing_constraint_count > 0) {
        record_approaches(world, h, true);
    }
}

/* Lower bound of the normal velocity for a substep of length h:
 * - a gap s > 0 may close, but not more: vn >= -s/h (speculative);
 * - with Baumgarte, overlap beyond the slop is pushed out at a fraction
 *   beta of it per substep: vn >= beta·(-s - slop)/h, capped;
 * - with NGS, the velocity solve only stops approach: vn >= 0. */
void rb_contact_solver_prepare_points_range(rb_world *world, double h, rb_substep_rows rows, int begin, int end)
{
    const rb_solver_settings *settings = &world->settings;
    double inv_h = 1.0 / h;
    for (int i = begin; i < end; ++i) {
        rb_contact_constraint *c = &world->constraints[i];
        const rb_body_state *sa = &world->states[c->body_a];
        const rb_body_state *sb = &world->states[c->body_b];
        double inv_mass_sum = c->inv_mass_a + c->inv_mass_b;
        for (int j = 0; j < c->point_count; ++j) {
            rb_constraint_point *p = &c->points[j];
            /* The bodies have moved since prepare (in earlier substeps):
             * act at the contact point and along the normal as they are
             * now, so each impulse conserves momentum. */
            rb_vec2 pa;
            rb_vec2 pb;
            current_geometry(c, p, sa, sb, &c->normal, &pa, &pb);
            double s = rb_dot(c->normal, rb_sub(pb, pa));
            rb_vec2 ra;
            rb_vec2 rb;
            anchors_at_midpoint(sa, sb, pa, pb, &ra, &rb);
            rb_vec2 tangent = tangent_of(c->normal);
            p->normal_arm_a = rb_cross(ra, c->normal);
            p->normal_arm_b = rb_cross(rb, c->normal);
            p->tangent_arm_a = rb_cross(ra, tangent);
            p->tangent_arm_b = rb_cross(rb, tangent);
            p->tangent_mass =
                mass_from_arms(inv_mass_sum, c->inv_inertia_a, c->inv_inertia_b, p->tangent_arm_a, p->tangent_arm_b);
            if (s > 0.0) {
                p->min_normal_velocity = -s * inv_h;
            } else if (rows.baumgarte_bias) {
                double push = rb_min(settings->baumgarte * rb_max(-s - settings->linear_slop, 0.0),
                                     settings->max_linear_correction);
                p->min_normal_velocity = push * inv_h;
            } else {
                p->min_normal_velocity = 0.0;
            }
        }
        if (rows.block_normals && c->point_count == 2) {
            prepare_block(c);
        }
        /* Each point's own normal mass, where the block does not replace
         * them (a division each: a tenth of this function's time). */
        if (!c->use_block) {
            for (int j = 0; j < c->point_count; ++j) {
                rb_constraint_point *p = &c->points[j];
                p->normal_mass =
                    mass_from_arms(inv_mass_sum, c->inv_inertia_a, c->inv_inertia_b, p->normal_arm_a, p->normal_arm_b);
            }
        }
    }
}

void rb_contact_solver_prepare_substep(rb_world *world, double h, rb_substep_rows rows)
{
    rb_contact_solver_prepare_points(world, h, rows);
    if (world->bouncing_constraint_count > 0) {
        record_approaches(world, h, rows.first_substep);
    }
}

/* The velocities of a constraint's two bodies, read once before its
 * points are solved and written back once after: the compiler can keep
 * them in registers, where pointers into the state array (which might
 * alias each other) would be reloaded after every store. */
typedef struct body_velocities {
    rb_vec2 linear_a;
    double angular_a;
    rb_vec2 linear_b;
    double angular_b;
} body_velocities;

static inline body_velocities load_velocities(const rb_body_state *a, const rb_body_state *b)
{
    return (body_velocities){a->linear_velocity, a->angular_velocity, b->linear_velocity, b->angular_velocity};
}

static inline void store_velocities(const body_velocities *v, rb_body_state *a, rb_body_state *b)
{
    a->linear_velocity = v->linear_a;
    a->angular_velocity = v->angular_a;
    b->linear_velocity = v->linear_b;
    b->angular_velocity = v->angular_b;
}

/* What a pass reads from a constraint but never writes, copied out of it
 * once: the impulses a pass stores are doubles, as these are, so the
 * compiler could not tell that a store leaves them unchanged and would
 * load them again after every one (a sixth of the soft pass's
 * instructions, counted by callgrind on the base-20 pyramid). */
typedef struct constraint_rows {
    rb_vec2 normal;
    rb_vec2 tangent;
    double inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
} constraint_rows;

static inline constraint_rows load_rows(const rb_contact_constraint *c)
{
    return (constraint_rows){c->normal,        tangent_of(c->normal), c->inv_mass_a,
                             c->inv_inertia_a, c->inv_mass_b,         c->inv_inertia_b};
}

/* The point's velocity on B relative to A along a row: the normal or the
 * tangent, with that row's lever arms. */
static inline double row_velocity(rb_vec2 direction, double arm_a, double arm_b, const body_velocities *v)
{
    return rb_dot(direction, rb_sub(v->linear_b, v->linear_a)) + v->angular_b * arm_b - v->angular_a * arm_a;
}

/* Applies an impulse `lambda` along `direction` (the normal or the
 * tangent) at a point of lever arms arm_a, arm_b: -λ·direction to A,
 * +λ·direction to B. */
static inline void apply_row_impulse(const constraint_rows *m, rb_vec2 direction, double arm_a, double arm_b,
                                     double lambda, body_velocities *v)
{
    rb_vec2 impulse = rb_scale(lambda, direction);
    v->linear_a = rb_mul_sub(v->linear_a, m->inv_mass_a, impulse);
    v->angular_a -= m->inv_inertia_a * lambda * arm_a;
    v->linear_b = rb_mul_add(v->linear_b, m->inv_mass_b, impulse);
    v->angular_b += m->inv_inertia_b * lambda * arm_b;
}

/* Applies impulse P at anchors rA, rB: -P to A, +P to B (restitution,
 * which acts at the anchors as they are after the substeps). */
static inline void apply_impulse_at(const rb_contact_constraint *c, rb_vec2 ra, rb_vec2 rb, body_velocities *v,
                                    rb_vec2 impulse)
{
    v->linear_a = rb_mul_sub(v->linear_a, c->inv_mass_a, impulse);
    v->angular_a -= c->inv_inertia_a * rb_cross(ra, impulse);
    v->linear_b = rb_mul_add(v->linear_b, c->inv_mass_b, impulse);
    v->angular_b += c->inv_inertia_b * rb_cross(rb, impulse);
}

/* A point's accumulated impulses applied again, the normal's then the
 * tangent's. */
static inline void warm_start_point(const constraint_rows *m, const rb_constraint_point *p, body_velocities *v)
{
    apply_row_impulse(m, m->normal, p->normal_arm_a, p->normal_arm_b, p->normal_impulse, v);
    apply_row_impulse(m, m->tangent, p->tangent_arm_a, p->tangent_arm_b, p->tangent_impulse, v);
}

/* The two-point case, by far the most common, written out so the
 * compiler unrolls it (as in solve_friction). */
void rb_contact_solver_warm_start_range(rb_world *world, int begin, int end)
{
    for (int i = begin; i < end; ++i) {
        const rb_contact_constraint *c = &world->constraints[i];
        rb_body_state *a = &world->states[c->body_a];
        rb_body_state *b = &world->states[c->body_b];
        body_velocities v = load_velocities(a, b);
        constraint_rows m = load_rows(c);
        warm_start_point(&m, &c->points[0], &v);
        if (c->point_count == 2) {
            warm_start_point(&m, &c->points[1], &v);
        }
        store_velocities(&v, a, b);
    }
}

static inline void solve_point_friction(const constraint_rows *m, double friction, rb_constraint_point *p,
                                        body_velocities *v)
{
    double normal_impulse = p->normal_impulse;
    double tangent_impulse = p->tangent_impulse;
    if (normal_impulse == 0.0 && tangent_impulse == 0.0) {
        return; /* no push, so no friction to hold or to release */
    }
    double arm_a = p->tangent_arm_a;
    double arm_b = p->tangent_arm_b;
    double vt = row_velocity(m->tangent, arm_a, arm_b, v);
    double limit = friction * normal_impulse;
    double accumulated = rb_clamp(tangent_impulse - p->tangent_mass * vt, -limit, limit);
    p->tangent_impulse = accumulated;
    apply_row_impulse(m, m->tangent, arm_a, arm_b, accumulated - tangent_impulse, v);
}

/* Each point's friction in turn; the two-point case, by far the most
 * common, written out so the compiler unrolls it. */
static inline void solve_friction(rb_contact_constraint *c, const constraint_rows *m, body_velocities *v)
{
    double friction = c->friction;
    solve_point_friction(m, friction, &c->points[0], v);
    if (c->point_count == 2) {
        solve_point_friction(m, friction, &c->points[1], v);
    }
}

/* A normal impulse's change `delta` at point p. */
static inline void apply_normal_impulse(const constraint_rows *m, const rb_constraint_point *p, double delta,
                                        body_velocities *v)
{
    apply_row_impulse(m, m->normal, p->normal_arm_a, p->normal_arm_b, delta, v);
}

static inline double normal_velocity(const constraint_rows *m, const rb_constraint_point *p, const body_velocities *v)
{
    return row_velocity(m->normal, p->normal_arm_a, p->normal_arm_b, v);
}

static inline void solve_normal_point(const constraint_rows *m, rb_constraint_point *p, body_velocities *v)
{
    double vn = normal_velocity(m, p, v);
    double accumulated = rb_max(p->normal_impulse - p->normal_mass * (vn - p->min_normal_velocity), 0.0);
    double delta = accumulated - p->normal_impulse;
    p->normal_impulse = accumulated;
    p->max_normal_impulse = rb_max(p->max_normal_impulse, accumulated);
    apply_normal_impulse(m, p, delta, v);
}

/* Both normal impulses at once: find x >= 0 with w = K·x + b >= 0 and
 * x_i·w_i = 0, where w is each point's normal velocity above its bound
 * and b is w with the impulses removed. The 2x2 linear complementarity
 * problem is solved by trying its four cases in turn (Murty, "Linear
 * Complementarity", 1988, ch. 1): both points pushing, only the first,
 * only the second, neither. If round-off defeats all four, the impulses
 * stay as they were. */
static inline void solve_normal_block(rb_contact_constraint *c, const constraint_rows *m, body_velocities *v)
{
    rb_constraint_point *p1 = &c->points[0];
    rb_constraint_point *p2 = &c->points[1];
    double x1_old = p1->normal_impulse;
    double x2_old = p2->normal_impulse;
    double w1 = normal_velocity(m, p1, v) - p1->min_normal_velocity;
    double w2 = normal_velocity(m, p2, v) - p2->min_normal_velocity;
    double b1 = w1 - (c->k11 * x1_old + c->k12 * x2_old);
    double b2 = w2 - (c->k12 * x1_old + c->k22 * x2_old);

    double x1;
    double x2;
    /* Case 1: both push, w = 0. */
    x1 = -(c->inv_k11 * b1 + c->inv_k12 * b2);
    x2 = -(c->inv_k12 * b1 + c->inv_k22 * b2);
    if (!(x1 >= 0.0 && x2 >= 0.0)) {
        /* Case 2: only the first pushes. */
        x1 = -b1 / c->k11;
        x2 = 0.0;
        if (!(x1 >= 0.0 && c->k12 * x1 + b2 >= 0.0)) {
            /* Case 3: only the second pushes. */
            x1 = 0.0;
            x2 = -b2 / c->k22;
            if (!(x2 >= 0.0 && c->k12 * x2 + b1 >= 0.0)) {
                /* Case 4: neither pushes; valid when both separate. */
                x1 = 0.0;
                x2 = 0.0;
                if (!(b1 >= 0.0 && b2 >= 0.0)) {
                    return;
                }
            }
        }
    }
    p1->normal_impulse = x1;
    p2->normal_impulse = x2;
    p1->max_normal_impulse = rb_max(p1->max_normal_impulse, x1);
    p2->max_normal_impulse = rb_max(p2->max_normal_impulse, x2);
    apply_normal_impulse(m, p1, x1 - x1_old, v);
    apply_normal_impulse(m, p2, x2 - x2_old, v);
}

void rb_contact_solver_solve_velocities_range(rb_world *world, bool backwards, int begin, int end)
{
    /* the sweep's first constraint and the step to the next one */
    int i = backwards ? end - 1 : begin;
    int next = backwards ? -1 : 1;
    for (int k = begin; k < end; ++k, i += next) {
        rb_contact_constraint *c = &world->constraints[i];
        rb_body_state *a = &world->states[c->body_a];
        rb_body_state *b = &world->states[c->body_b];
        body_velocities v = load_velocities(a, b);
        constraint_rows m = load_rows(c);
        /* Friction first: its bound uses the normal impulse, and the
         * normal constraint, solved last, matters more for stacking. */
        solve_friction(c, &m, &v);
        if (c->use_block) {
            solve_normal_block(c, &m, &v);
        } else {
            for (int j = 0; j < c->point_count; ++j) {
                solve_normal_point(&m, &c->points[j], &v);
            }
        }
        store_velocities(&v, a, b);
    }
}

/* The point's separation at the poses now, along the step's normal:
 * each surface point carried by its body, less the circles' radii. */
static inline double separation_now(const rb_contact_constraint *c, const rb_constraint_point *p,
                                    const rb_body_state *a, const rb_body_state *b)
{
    rb_vec2 qa = rb_add(a->center, rb_rotate(a->rotation, p->local_surface_a));
    rb_vec2 qb = rb_add(b->center, rb_rotate(b->rotation, p->local_surface_b));
    return rb_dot(c->normal, rb_sub(qb, qa)) - c->radius_a - c->radius_b;
}

/* Soft contact (Catto, "Solver2D", 2024): a point whose gap s is open
 * may close it within the substep, vn >= -s/h, rigidly; an overlapping
 * one is a stiff damped spring pushing at the rate bias_rate·s,
 * no faster than max_push_speed, its impulse
 *   λ = -mass_scale·m·(vn + bias) - impulse_scale·λ_accumulated,
 * against a fixed body at twice the frequency (it carries the whole
 * load). Without bias (relax), the overlap only stops approaching. */
static inline void solve_soft_point(const constraint_rows *m, const rb_contact_softness *softness,
                                    const rb_rigid_response *spring, rb_constraint_point *p, double s,
                                    body_velocities *v)
{
    double bias = 0.0;
    double mass_scale = 1.0;
    double impulse_scale = 0.0;
    if (s > 0.0) {
        bias = s * softness->inv_h;
    } else if (softness->use_bias) {
        bias = rb_max(spring->bias_rate * s, -softness->max_push_speed);
        mass_scale = spring->mass_scale;
        impulse_scale = spring->impulse_scale;
    }
    double arm_a = p->normal_arm_a;
    double arm_b = p->normal_arm_b;
    double normal_impulse = p->normal_impulse;
    double vn = row_velocity(m->normal, arm_a, arm_b, v);
    double impulse = -p->normal_mass * mass_scale * (vn + bias) - impulse_scale * normal_impulse;
    double accumulated = rb_max(normal_impulse + impulse, 0.0);
    p->normal_impulse = accumulated;
    p->max_normal_impulse = rb_max(p->max_normal_impulse, accumulated);
    apply_row_impulse(m, m->normal, arm_a, arm_b, accumulated - normal_impulse, v);
}

/* The soft pass over constraints begin .. end - 1, one after another,
 * each one's normal rows first, so friction's bound sees this pass's push.
 * The poses do not change within a pass, so a contact's separations are
 * measured before its velocities are loaded. The softness is copied, for
 * the reason constraint_rows gives. */
void rb_contact_solver_solve_soft_range(rb_world *world, const rb_contact_softness *softness, int begin, int end)
{
    rb_contact_softness k = *softness;
    rb_contact_constraint *constraints = world->constraints;
    rb_body_state *states = world->states;
    for (int i = begin; i < end; ++i) {
        rb_contact_constraint *c = &constraints[i];
        rb_body_state *a = &states[c->body_a];
        rb_body_state *b = &states[c->body_b];
        const rb_rigid_response *spring = c->against_fixed ? &k.against_fixed : &k.between_moving;
        bool two_points = c->point_count == 2;
        double s0 = separation_now(c, &c->points[0], a, b);
        double s1 = two_points ? separation_now(c, &c->points[1], a, b) : 0.0;
        body_velocities v = load_velocities(a, b);
        constraint_rows m = load_rows(c);
        solve_soft_point(&m, &k, spring, &c->points[0], s0, &v);
        if (two_points) {
            solve_soft_point(&m, &k, spring, &c->points[1], s1, &v);
        }
        solve_friction(c, &m, &v);
        store_velocities(&v, a, b);
    }
}

/* Moves a body's pose by a position-level impulse. */
static void displace(rb_body_state *s, double inv_mass, double inv_inertia, rb_vec2 r, rb_vec2 impulse)
{
    s->center = rb_mul_add(s->center, inv_mass, impulse);
    if (inv_inertia > 0.0) {
        rb_body_state_turn(s, inv_inertia * rb_cross(r, impulse));
    }
}

/* The two surface points of p as the bodies now carry them, given the
 * normal now: current_geometry's second half. */
static inline void surface_points_now(const rb_contact_constraint *c, const rb_constraint_point *p,
                                      const rb_body_state *sa, const rb_body_state *sb, rb_vec2 normal, rb_vec2 *pa,
                                      rb_vec2 *pb)
{
    *pa = rb_mul_add(rb_add(sa->center, rb_rotate(sa->rotation, p->local_surface_a)), c->radius_a, normal);
    *pb = rb_mul_sub(rb_add(sb->center, rb_rotate(sb->rotation, p->local_surface_b)), c->radius_b, normal);
}

/* Non-linear Gauss-Seidel (Catto, Box2D 2.x): for each point, C is the
 * overlap beyond the slop scaled by beta and capped; the position
 * impulse -C/K along the normal moves the two bodies apart directly,
 * with K the effective mass at the anchors as they are now. A face's
 * normal is the same at both points of a contact until a correction
 * turns its body, so it is turned once and again only after one (the
 * same numbers as current_geometry's for each point). */
bool rb_contact_solver_correct_contact_positions(rb_world *world, int index, double *deepest)
{
    bool corrected = false;
    const rb_contact_constraint *c = &world->constraints[index];
    const rb_solver_settings *settings = &world->settings;
    rb_body_state *a = &world->states[c->body_a];
    rb_body_state *b = &world->states[c->body_b];
    bool face = c->normal_follows != RB_NORMAL_FROM_CENTERS;
    rb_vec2 face_normal = face ? turned_normal(c, a, b) : c->normal;
    for (int j = 0; j < c->point_count; ++j) {
        const rb_constraint_point *p = &c->points[j];
        rb_vec2 normal = face_normal;
        rb_vec2 pa;
        rb_vec2 pb;
        if (face) {
            surface_points_now(c, p, a, b, normal, &pa, &pb);
        } else {
            current_geometry(c, p, a, b, &normal, &pa, &pb);
        }
        double s = rb_dot(normal, rb_sub(pb, pa));
        *deepest = rb_min(*deepest, s);
        double error =
            rb_min(rb_max(settings->baumgarte * (s + settings->linear_slop), -settings->max_linear_correction), 0.0);
        if (error == 0.0) {
            continue;
        }
        rb_vec2 ra;
        rb_vec2 rb;
        anchors_at_midpoint(a, b, pa, pb, &ra, &rb);
        double mass = effective_mass(c->inv_mass_a + c->inv_mass_b, c->inv_inertia_a, c->inv_inertia_b, ra, rb, normal);
        rb_vec2 impulse = rb_scale(-error * mass, normal);
        displace(a, -c->inv_mass_a, -c->inv_inertia_a, ra, impulse);
        displace(b, c->inv_mass_b, c->inv_inertia_b, rb, impulse);
        corrected = true;
        if (face) {
            face_normal = turned_normal(c, a, b);
        }
    }
    return corrected;
}

/* The contacts in order; the runs of them that need no correction are
 * measured two at a time and passed over (contact_positions_wide.c), the
 * others corrected by the reference. Where contacts needing a correction
 * come one after another, as in a pile still settling, the lanes'
 * measure would mostly be thrown away (the base-100 pyramid's step took
 * 0.3 % more instructions with it): after a correction the reference
 * carries on until it finds a contact with none to make. */
bool rb_contact_solver_correct_positions(rb_world *world)
{
    double deepest = 0.0;
    int count = world->constraint_count;
    int i = 0;
    bool resting = true; /* the last contact needed no correction */
    while (i < count) {
        if (resting) {
            i = rb_contact_solver_skip_resting(world, i, &deepest);
        }
        if (i < count) {
            resting = !rb_contact_solver_correct_contact_positions(world, i, &deepest);
            ++i;
        }
    }
    return deepest >= -NGS_TOLERANCE_SLOPS * world->settings.linear_slop;
}

/* Restitution after the step (as Box2D v3 does): a point whose surfaces
 * met faster than the threshold (record_approach) and that the solver
 * pushed leaves at e times that speed. The velocity it is given is, as
 * every semi-implicit Euler velocity, that of the middle of the next
 * substep: e·|impact| - a·h/2 with a the normal acceleration, so that
 * the bounce rises to e² times the height it fell from to within the
 * integrator's error, wherever in the step the impact fell. */
void rb_contact_solver_apply_restitution(rb_world *world, double h)
{
    if (world->bouncing_constraint_count == 0) {
        return; /* nothing bounces: a resting pile need not read its constraints again */
    }
    double threshold = world->settings.restitution_threshold;
    int loose = rb_contact_solver_loose_count(world); /* the blocks' contacts have no restitution */
    for (int k = 0; k < loose; ++k) {
        rb_contact_constraint *c = &world->constraints[rb_contact_solver_loose_constraint(world, k)];
        if (c->restitution == 0.0) {
            continue;
        }
        rb_body_state *a = &world->states[c->body_a];
        rb_body_state *b = &world->states[c->body_b];
        for (int j = 0; j < c->point_count; ++j) {
            rb_constraint_point *p = &c->points[j];
            if (p->impact_velocity > -threshold || p->max_normal_impulse == 0.0) {
                continue;
            }
            /* The positions have moved since prepare: act at the contact
             * point as it is now, so the impulse conserves momentum. */
            rb_vec2 normal;
            rb_vec2 ra;
            rb_vec2 rb;
            current_anchors(c, p, a, b, &normal, &ra, &rb);
            double mass =
                effective_mass(c->inv_mass_a + c->inv_mass_b, c->inv_inertia_a, c->inv_inertia_b, ra, rb, normal);
            double vn = rb_dot(normal, relative_velocity(a, b, ra, rb));
            double target = -c->restitution * p->impact_velocity - 0.5 * p->approach_acceleration * h;
            double accumulated = fmax(p->normal_impulse - mass * (vn - target), 0.0);
            double delta = accumulated - p->normal_impulse;
            p->normal_impulse = accumulated;
            p->max_normal_impulse = rb_max(p->max_normal_impulse, accumulated);
            body_velocities v = load_velocities(a, b);
            apply_impulse_at(c, ra, rb, &v, rb_scale(delta, normal));
            store_velocities(&v, a, b);
        }
    }
}

/* The deepest overlap the solver's points say the step left, at or
 * below this many linear slops, is taken as it is: a resting contact's
 * overlap, where their first-order error is far smaller than the slop. */
#define TRUSTED_OVERLAP_SLOPS 4.0

/* The larger of the deepest overlap found so far (a number, >= 0) and
 * `overlap`, which is kept only when it is larger: a NaN or a -0 leaves
 * the deepest as it is. A comparison rather than libm's fmax, whose call
 * makes the compiler save and restore every register of the sweep around
 * it, twice for each contact of the step. */
static inline double deeper(double deepest, double overlap) { return overlap > deepest ? overlap : deepest; }

/* The overlap at a constraint's points as the solver carries them:
 * -current_separation at each, to the bit. A face's normal is the same
 * for all the points, so it is turned once. Between two polygons the
 * radii are 0 and their terms, each adding 0·n to a point, are left out:
 * they could only change the sign of a zero, and a zero is never the
 * deepest overlap. Inline, as the sweep's one call per contact: a call
 * cost 17 instructions a contact, saving and restoring registers. */
static inline __attribute__((always_inline)) double carried_overlap(const rb_world *world,
                                                                    const rb_contact_constraint *c)
{
    const rb_body_state *a = &world->states[c->body_a];
    const rb_body_state *b = &world->states[c->body_b];
    double deepest = 0.0;
    if (c->normal_follows == RB_NORMAL_FROM_CENTERS) {
        for (int j = 0; j < c->point_count; ++j) {
            rb_vec2 normal;
            deepest = deeper(deepest, -current_separation(c, &c->points[j], a, b, &normal));
        }
        return deepest;
    }
    rb_vec2 normal = turned_normal(c, a, b);
    bool polygons = c->radius_a == 0.0 && c->radius_b == 0.0;
    for (int j = 0; j < c->point_count; ++j) {
        const rb_constraint_point *p = &c->points[j];
        rb_vec2 pa = rb_add(a->center, rb_rotate(a->rotation, p->local_surface_a));
        rb_vec2 pb = rb_add(b->center, rb_rotate(b->rotation, p->local_surface_b));
        if (!polygons) {
            pa = rb_mul_add(pa, c->radius_a, normal);
            pb = rb_mul_sub(pb, c->radius_b, normal);
        }
        deepest = deeper(deepest, -rb_dot(normal, rb_sub(pb, pa)));
    }
    return deepest;
}

/* The points are carried with the bodies from the step's narrow phase, so
 * they are first-order: a ball pushed past the end of the face it touched
 * would read as sunk below that face's plane (0.13 m, where the shapes
 * overlapped by under 0.02 m). A constraint whose points read deeper than
 * the trusted overlap is measured again by the narrow phase at the final
 * poses; that takes a pass only on the steps that have one. */
double rb_contact_solver_store_impulses(rb_world *world)
{
    double trusted = TRUSTED_OVERLAP_SLOPS * world->settings.linear_slop;
    /* The sequential solvers' rows hold their contacts' impulses
     * (contact_rows_two.c): first back into the constraints. */
    if (world->contact_rows.live) {
        rb_contact_rows_store_impulses(world);
    }
    /* The soft step's last pass wrote the impulses of the contacts in its
     * blocks to their manifolds, and after a relax pass measured their
     * deepest overlap too; after a last pass that solved, their overlap
     * is measured here from the lanes. The blocks' contacts have no
     * constraint to read. */
    rb_contact_batches *batches = &world->contact_batches;
    double deepest =
        batches->overlap_measured ? batches->deepest_overlap : rb_contact_blocks_deepest_overlap(world, INFINITY);
    batches->overlap_measured = false;
    /* The deepest of several overlaps is the same whichever is met first
     * (deeper never takes a NaN), so the blocks' may come first. */
    int loose = rb_contact_solver_loose_count(world);
    for (int k = 0; k < loose; ++k) {
        const rb_contact_constraint *c = &world->constraints[rb_contact_solver_loose_constraint(world, k)];
        rb_manifold *m = &world->contacts[c->contact].manifold;
        for (int j = 0; j < c->point_count; ++j) {
            m->points[j].normal_impulse = c->points[j].normal_impulse;
            m->points[j].tangent_impulse = c->points[j].tangent_impulse;
        }
        deepest = deeper(deepest, carried_overlap(world, c));
    }
    if (deepest <= trusted) {
        return deepest;
    }
    deepest = rb_contact_blocks_deepest_overlap(world, trusted);
    for (int k = 0; k < loose; ++k) {
        const rb_contact_constraint *c = &world->constraints[rb_contact_solver_loose_constraint(world, k)];
        double overlap = carried_overlap(world, c);
        if (overlap > trusted) {
            overlap = rb_contact_deepest_overlap_now(world, &world->contacts[c->contact]);
        }
        deepest = deeper(deepest, overlap);
    }
    return deepest;
}
