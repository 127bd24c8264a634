/* SPDX-License-Identifier: MIT */
/* The soft step's contact passes (warm start and soft pass) over blocks
 * of contacts, two and four at a time (contact_blocks.c), the blocks'
 * preparation of their points in the step's first warm start, and the
 * points' preparation two at a time (contact_solver_wide.c), against the
 * references that take one at a time
 * (rb_contact_solver_warm_start_range, rb_contact_solver_solve_soft_range,
 * rb_contact_solver_prepare_points_range): from the same contacts and
 * velocities, both ways must leave the same velocities and impulses,
 * and the preparations the same normals, lever arms and masses, byte for
 * byte.
 * The stated tolerance is none: the values compare equal as numbers
 * (only the sign of a zero may differ, which == does not see), because
 * each lane does the reference's arithmetic in the reference's order.
 *
 * The passes start from real constraints (a pyramid of boxes, whose
 * contacts have two points, against the ground and against each other,
 * and balls on a table, whose contacts have one) with every body's
 * velocity disturbed, so that some points push, some let go, some hit
 * the friction cone and some have their gap still open; and they are run
 * with the spring's push-out (solve) and without it (relax). In some
 * rounds every other constraint is told its spring is the other one (the
 * one against a fixed body, or between moving bodies): a colour's
 * constraints are otherwise all of one kind, and the lanes' choice of
 * spring would go untested. */
#include <math.h>
#include <string.h>

#include "contact.h"
#include "contact_blocks.h"
#include "contact_solver.h"
#include "joint_solver.h"
#include "scenes/scenes.h"
#include "test_support.h"

#define SUBSTEPS 4

/* A step at Box2D v3's budget: the soft step, 4 substeps of one solve
 * and one relax pass. */
static rb_world *soft_world(void)
{
    rb_world_def def = rb_default_world_def();
    def.gravity = rb_v2(0.0, -10.0);
    def.enable_sleep = false;
    def.solver.type = RB_SOLVER_SOFT_STEP;
    def.solver.substeps = SUBSTEPS;
    def.solver.velocity_iterations = 1;
    def.solver.relax_iterations = 1;
    rb_world *world = NULL;
    cr_assert_eq(rb_world_create(&def, &world), RB_OK, "%s", rb_last_error());
    return world;
}

/* A deterministic value in [-1, 1) (a linear congruential generator,
 * Knuth's MMIX constants). */
static double next_unit(uint64_t *state)
{
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (double)(*state >> 11) / (double)(UINT64_C(1) << 52) - 1.0;
}

/* The softness the soft step gives its contacts (solver_soft_step.c). */
static rb_contact_softness softness_of(const rb_world *world, bool use_bias)
{
    const rb_solver_settings *s = &world->settings;
    double h = TEST_DT / s->substeps;
    return (rb_contact_softness){
        .between_moving = rb_make_rigid_softness(s->contact_hertz, s->contact_damping_ratio, h),
        .against_fixed = rb_make_rigid_softness(2.0 * s->contact_hertz, s->contact_damping_ratio, h),
        .max_push_speed = s->max_push_speed,
        .linear_slop = s->linear_slop,
        .inv_h = 1.0 / h,
        .use_bias = use_bias,
    };
}

/* Prepares the world's contacts as a step does
 * (rb_contact_solver_prepare), then fills the constraints of the blocks'
 * contacts by the reference, rb_contact_solver_fill_constraint: the
 * blocks hold those contacts' values in their lanes and leave their
 * constraints as they were. Returns how many constraints there are. */
static int prepare_every_constraint(rb_world *world)
{
    int count = rb_contact_solver_prepare(world);
    cr_assert_geq(count, 0, "out of memory");
    const rb_contact_batches *batches = &world->contact_batches;
    for (int k = 0; k < batches->block_count; ++k) {
        const rb_contact_block_tail *tail = &batches->tails[k];
        for (int lane = 0; lane < RB_BLOCK_LANES && tail->constraints[lane] >= 0; ++lane) {
            rb_contact_solver_fill_constraint(world, tail->contacts[lane],
                                              &world->constraints[tail->constraints[lane]]);
        }
    }
    return count;
}

/* Whether constraint i is solved in a block. */
static bool in_a_block(const rb_world *world, int i)
{
    const rb_contact_batches *batches = &world->contact_batches;
    for (int k = 0; k < batches->block_count; ++k) {
        for (int lane = 0; lane < RB_BLOCK_LANES; ++lane) {
            if (batches->tails[k].constraints[lane] == i) {
                return true;
            }
        }
    }
    return false;
}

/* The velocities and impulses the blocks' passes at `width` left against
 * the reference's: a block's contacts' impulses in their manifolds, where
 * the last pass writes them, the others' in their constraints; the
 * largest push of the step, which restitution reads, where the
 * constraint keeps it (not in a block, whose contacts have no
 * restitution). */
static void expect_same_results(const rb_world *world, const rb_body_state *reference_states,
                                const rb_contact_constraint *reference_constraints, int width)
{
    for (int i = 0; i < world->body_slots; ++i) {
        const rb_body_state *r = &reference_states[i];
        const rb_body_state *w = &world->states[i];
        cr_expect(r->linear_velocity.x == w->linear_velocity.x && r->linear_velocity.y == w->linear_velocity.y &&
                      r->angular_velocity == w->angular_velocity,
                  "body %d: velocity (%.17g, %.17g, %.17g) one at a time, (%.17g, %.17g, %.17g) %d at a time", i,
                  r->linear_velocity.x, r->linear_velocity.y, r->angular_velocity, w->linear_velocity.x,
                  w->linear_velocity.y, w->angular_velocity, width);
    }
    for (int i = 0; i < world->constraint_count; ++i) {
        const rb_contact_constraint *r = &reference_constraints[i];
        const rb_contact_constraint *w = &world->constraints[i];
        bool in_block = in_a_block(world, i);
        const rb_manifold *m = &world->contacts[r->contact].manifold;
        for (int j = 0; j < r->point_count; ++j) {
            double normal = in_block ? m->points[j].normal_impulse : w->points[j].normal_impulse;
            double tangent = in_block ? m->points[j].tangent_impulse : w->points[j].tangent_impulse;
            cr_expect(r->points[j].normal_impulse == normal && r->points[j].tangent_impulse == tangent &&
                          (in_block || r->points[j].max_normal_impulse == w->points[j].max_normal_impulse),
                      "constraint %d point %d: impulses (%.17g, %.17g, largest %.17g) one at a time, (%.17g, %.17g, "
                      "largest %.17g) %d at a time",
                      i, j, r->points[j].normal_impulse, r->points[j].tangent_impulse, r->points[j].max_normal_impulse,
                      normal, tangent, w->points[j].max_normal_impulse, width);
        }
    }
}

/* The deepest overlap of the constraints in blocks at the poses now,
 * computed here from each constraint's definition (as the reference
 * filled it): its normal turned with the body whose face it is, its
 * surface points carried with their bodies, the overlap the negated
 * distance between them along the normal. A constraint deeper than
 * `trusted` (m) is measured again by the narrow phase at the poses now
 * (rb_contact_deepest_overlap_now), as the step does; `refined` counts
 * them. */
static double deepest_in_blocks(const rb_world *world, const rb_contact_constraint *reference, double trusted,
                                int *refined)
{
    double deepest = 0.0;
    *refined = 0;
    for (int i = 0; i < world->constraint_count; ++i) {
        const rb_contact_constraint *c = &reference[i];
        if (!in_a_block(world, i)) {
            continue;
        }
        const rb_body_state *a = &world->states[c->body_a];
        const rb_body_state *b = &world->states[c->body_b];
        rb_rot turn = c->normal_follows == RB_NORMAL_TURNS_WITH_A ? a->rotation : b->rotation;
        rb_vec2 normal = rb_rotate(turn, c->local_normal);
        double overlap = 0.0;
        for (int j = 0; j < c->point_count; ++j) {
            rb_vec2 pa = rb_add(a->center, rb_rotate(a->rotation, c->points[j].local_surface_a));
            rb_vec2 pb = rb_add(b->center, rb_rotate(b->rotation, c->points[j].local_surface_b));
            overlap = fmax(overlap, -rb_dot(normal, rb_sub(pb, pa)));
        }
        if (overlap > trusted) {
            overlap = rb_contact_deepest_overlap_now(world, &world->contacts[c->contact]);
            ++*refined;
        }
        deepest = fmax(deepest, overlap);
    }
    return deepest;
}

/* Each lane's normal, lever arms and masses, as the blocks' first warm
 * start prepared them, against its constraint as the reference
 * (rb_contact_solver_prepare_points_range) prepared it: the same bytes.
 * Returns how many lanes held a contact. */
static int expect_same_preparation(const rb_world *world, const rb_contact_constraint *reference, int width)
{
    const rb_contact_batches *batches = &world->contact_batches;
    int compared = 0;
    for (int k = 0; k < batches->block_count; ++k) {
        const rb_contact_block *q = &batches->blocks[k];
        const int *constraints = batches->tails[k].constraints;
        for (int lane = 0; lane < RB_BLOCK_LANES && constraints[lane] >= 0; ++lane) {
            const rb_contact_constraint *c = &reference[constraints[lane]];
            cr_expect_eq(batches->tails[k].contacts[lane], c->contact,
                         "lane %d of block %d holds contact %d, its constraint %d contact %d", lane, k,
                         batches->tails[k].contacts[lane], constraints[lane], c->contact);
            double lane_values[2 + 2 * 6] = {q->normal_x.v[lane], q->normal_y.v[lane]};
            double reference_values[2 + 2 * 6] = {c->normal.x, c->normal.y};
            for (int j = 0; j < 2; ++j) {
                const rb_block_point *w = &q->points[j];
                const rb_constraint_point *p = &c->points[j];
                double *x = &lane_values[2 + 6 * j];
                double *y = &reference_values[2 + 6 * j];
                x[0] = w->normal_arm_a.v[lane], y[0] = p->normal_arm_a;
                x[1] = w->normal_arm_b.v[lane], y[1] = p->normal_arm_b;
                x[2] = w->tangent_arm_a.v[lane], y[2] = p->tangent_arm_a;
                x[3] = w->tangent_arm_b.v[lane], y[3] = p->tangent_arm_b;
                x[4] = w->normal_mass.v[lane], y[4] = p->normal_mass;
                x[5] = w->tangent_mass.v[lane], y[5] = p->tangent_mass;
            }
            cr_expect(memcmp(lane_values, reference_values, sizeof lane_values) == 0,
                      "constraint %d prepared differently in lane %d of block %d at width %d: normal (%.17g, %.17g) "
                      "and (%.17g, %.17g), first point's normal mass %.17g and %.17g",
                      constraints[lane], lane, k, width, lane_values[0], lane_values[1], reference_values[0],
                      reference_values[1], lane_values[6], reference_values[6]);
            ++compared;
        }
    }
    return compared;
}

/* Every other constraint told its spring is the other one, in its
 * constraint and, if it has one, in its lane. */
static void mix_springs(rb_world *world)
{
    for (int i = 1; i < world->constraint_count; i += 2) {
        world->constraints[i].against_fixed = !world->constraints[i].against_fixed;
    }
    const rb_contact_batches *batches = &world->contact_batches;
    for (int k = 0; k < batches->block_count; ++k) {
        rb_contact_block *q = &batches->blocks[k];
        for (int lane = 0; lane < RB_BLOCK_LANES; ++lane) {
            if (batches->tails[k].constraints[lane] % 2 == 1) {
                q->against_fixed[lane] = ~q->against_fixed[lane];
            }
        }
    }
}

/* How many constraints had two points, and how many of those had
 * restitution. */
typedef struct constraint_counts {
    int two_point, bouncing;
} constraint_counts;

/* Prepares the world's contacts as a step does, disturbs every dynamic
 * body's velocity by up to `speed` m/s and `speed` rad/s, then from the
 * same start warm starts and runs two passes one at a time over the
 * constraints, prepared by the reference, and the same over the blocks
 * as the step lays them out and prepares them, the second pass as the
 * step's last (writing the impulses into the manifolds and measuring the
 * deepest overlap), at each width the processor runs, and compares. */
static constraint_counts expect_passes_agree(rb_world *world, double speed, bool use_bias, bool mix, uint64_t seed)
{
    double h = TEST_DT / SUBSTEPS;
    for (int i = 0; i < world->body_slots; ++i) {
        if (world->bodies[i].in_use && world->bodies[i].type == RB_BODY_DYNAMIC) {
            rb_body_state *s = &world->states[i];
            s->linear_velocity = rb_add(s->linear_velocity, rb_v2(speed * next_unit(&seed), speed * next_unit(&seed)));
            s->angular_velocity += speed * next_unit(&seed);
            /* Turned too, so that no body's frame is the world's and a
             * point taken into it and back is not always the same point. */
            s->angle += 0.02 * speed * next_unit(&seed);
            s->rotation = rb_rot_from_angle(s->angle);
        }
    }
    int count = prepare_every_constraint(world);
    cr_assert_gt(count, 0, "the scene has contacts to solve");
    rb_contact_solver_prepare_points_range(world, h, (rb_substep_rows){.first_substep = true}, 0, count);
    if (mix) {
        mix_springs(world);
    }
    rb_contact_softness softness = softness_of(world, use_bias);

    size_t state_bytes = (size_t)world->body_slots * sizeof *world->states;
    size_t constraint_bytes = (size_t)count * sizeof *world->constraints;
    rb_body_state *start_states = malloc(state_bytes);
    rb_body_state *reference_states = malloc(state_bytes);
    rb_contact_constraint *prepared = malloc(constraint_bytes);
    rb_contact_constraint *reference_constraints = malloc(constraint_bytes);
    cr_assert(start_states && reference_states && prepared && reference_constraints);
    memcpy(start_states, world->states, state_bytes);
    memcpy(prepared, world->constraints, constraint_bytes);
    /* The impulses the step carries over, which each width starts from
     * again: the blocks' last pass writes into the manifolds. */
    size_t contact_bytes = (size_t)world->contact_count * sizeof *world->contacts;
    rb_contact *start_contacts = malloc(contact_bytes);
    cr_assert(start_contacts);
    memcpy(start_contacts, world->contacts, contact_bytes);

    rb_contact_solver_warm_start_range(world, 0, count);
    rb_contact_solver_solve_soft_range(world, &softness, 0, count);
    rb_contact_solver_solve_soft_range(world, &softness, 0, count);
    memcpy(reference_states, world->states, state_bytes);
    memcpy(reference_constraints, world->constraints, constraint_bytes);
    int moved = 0;
    int two_point = 0;
    int bouncing = 0; /* two-point constraints with restitution, which no block takes */
    for (int i = 0; i < world->body_slots; ++i) {
        moved += reference_states[i].linear_velocity.x != start_states[i].linear_velocity.x;
    }
    for (int i = 0; i < count; ++i) {
        two_point += reference_constraints[i].point_count == 2;
        bouncing += reference_constraints[i].point_count == 2 && reference_constraints[i].restitution > 0.0;
    }
    cr_expect_gt(moved, count / 4, "the pass changed velocities (%d bodies of %d constraints)", moved, count);

    for (int width = 2; width <= rb_contact_blocks_widest(); width += 2) {
        memcpy(world->states, start_states, state_bytes);
        memcpy(world->contacts, start_contacts, contact_bytes);
        cr_assert_eq(rb_contact_solver_prepare(world), count, "the same constraints again");
        rb_contact_solver_prepare_singles(world, h);
        if (mix) {
            mix_springs(world);
        }
        world->contact_batches.width = width;
        rb_contact_solver_warm_start_blocks(world, true);
        int prepared_lanes = expect_same_preparation(world, prepared, width);
        rb_contact_solver_solve_soft(world, &softness);
        rb_contact_softness last = softness;
        last.write_back = true; /* the impulses into the manifolds, as the step's last pass */
        last.measure_overlap = true;
        rb_contact_solver_solve_soft(world, &last);
        expect_same_results(world, reference_states, reference_constraints, width);
        int in_blocks = 0;
        for (int k = 0; k < world->contact_batches.block_count; ++k) {
            for (int lane = 0; lane < RB_BLOCK_LANES; ++lane) {
                in_blocks += world->contact_batches.tails[k].constraints[lane] >= 0;
            }
        }
        int refined = 0;
        double deepest = deepest_in_blocks(world, prepared, INFINITY, &refined);
        cr_expect(in_blocks == 0 || deepest > 0.0, "some contact in a block overlaps, so the measure is tested");
        cr_expect(world->contact_batches.overlap_measured && world->contact_batches.deepest_overlap == deepest,
                  "the blocks' deepest overlap: %.17g m measured by the last pass, %.17g m from the constraints, "
                  "at width %d",
                  world->contact_batches.deepest_overlap, deepest, width);
        /* Measured again from the lanes, as a step whose last pass came
         * before the positions moved does; and with the deeper half
         * measured by the narrow phase, as when some overlap is deeper
         * than the step trusts. */
        double again = rb_contact_blocks_deepest_overlap(world, INFINITY);
        cr_expect(again == deepest, "the lanes' deepest overlap measured again: %.17g m, from the constraints %.17g m",
                  again, deepest);
        double trusted = 0.5 * deepest;
        double refined_deepest = deepest_in_blocks(world, prepared, trusted, &refined);
        again = rb_contact_blocks_deepest_overlap(world, trusted);
        cr_expect(in_blocks == 0 || refined > 0, "some overlap in a block is measured again (%d were)", refined);
        cr_expect(again == refined_deepest,
                  "the lanes' deepest overlap, those deeper than %.17g m measured again: %.17g m, from the "
                  "constraints %.17g m",
                  trusted, again, refined_deepest);
        cr_expect_eq(in_blocks, two_point - bouncing,
                     "every two-point constraint without restitution is solved in a block (%d of %d were)", in_blocks,
                     two_point - bouncing);
        cr_expect_eq(prepared_lanes, in_blocks, "every lane's contact was compared (%d of %d)", prepared_lanes,
                     in_blocks);
        cr_expect(in_blocks == 0 || RB_BLOCK_LANES * world->contact_batches.block_count > in_blocks,
                  "some block has an empty lane, so that empty lanes are tested (%d blocks for %d contacts)",
                  world->contact_batches.block_count, in_blocks);
        /* The empty lanes act on nothing: their bodies stay at rest. */
        const rb_body_state *idle[2] = {&world->contact_batches.idle_a, &world->contact_batches.idle_b};
        for (int k = 0; k < 2; ++k) {
            cr_expect(idle[k]->linear_velocity.x == 0.0 && idle[k]->linear_velocity.y == 0.0 &&
                          idle[k]->angular_velocity == 0.0,
                      "an empty lane moved its idle body: (%g, %g, %g) at width %d", idle[k]->linear_velocity.x,
                      idle[k]->linear_velocity.y, idle[k]->angular_velocity, width);
        }
    }
    free(start_states);
    free(start_contacts);
    free(reference_states);
    free(prepared);
    free(reference_constraints);
    return (constraint_counts){two_point, bouncing};
}

/* Prepares the world's contacts, moves and turns every dynamic body a
 * little (so that the poses are not those the points were taken at),
 * prepares the points each way from the same start with `rows` and
 * compares the constraints byte for byte. */
static void expect_preparations_agree(rb_world *world, rb_substep_rows rows, uint64_t seed)
{
    int count = prepare_every_constraint(world);
    cr_assert_gt(count, 0, "the scene has contacts to solve");
    for (int i = 0; i < world->body_slots; ++i) {
        if (world->bodies[i].in_use && world->bodies[i].type == RB_BODY_DYNAMIC) {
            rb_body_state *s = &world->states[i];
            s->center = rb_add(s->center, rb_v2(0.01 * next_unit(&seed), 0.01 * next_unit(&seed)));
            s->angle += 0.02 * next_unit(&seed);
            s->rotation = rb_rot_from_angle(s->angle);
        }
    }
    size_t bytes = (size_t)count * sizeof *world->constraints;
    rb_contact_constraint *start = malloc(bytes);
    rb_contact_constraint *reference = malloc(bytes);
    cr_assert(start && reference);
    memcpy(start, world->constraints, bytes);
    rb_contact_solver_prepare_points_range(world, TEST_DT / SUBSTEPS, rows, 0, count);
    memcpy(reference, world->constraints, bytes);
    memcpy(world->constraints, start, bytes);
    rb_contact_solver_prepare_points(world, TEST_DT / SUBSTEPS, rows);
    int blocks = 0;
    for (int i = 0; i < count; ++i) {
        const rb_contact_constraint *r = &reference[i];
        const rb_contact_constraint *w = &world->constraints[i];
        blocks += r->use_block;
        cr_expect(memcmp(r, w, sizeof *r) == 0,
                  "constraint %d prepared differently: normal (%.17g, %.17g) and (%.17g, %.17g), first point's "
                  "normal mass %.17g and %.17g, bound %.17g and %.17g",
                  i, r->normal.x, r->normal.y, w->normal.x, w->normal.y, r->points[0].normal_mass,
                  w->points[0].normal_mass, r->points[0].min_normal_velocity, w->points[0].min_normal_velocity);
    }
    if (rows.block_normals) {
        cr_expect_gt(blocks, count / 2, "the block solve was taken by %d constraints of %d", blocks, count);
    }
    free(start);
    free(reference);
}

/* The base-20 pyramid (590 contacts of two points) with a row of balls
 * on the ground beside it (contacts of one point, in the colours of the
 * boxes' contacts with the ground). */
Test(contact_lanes, a_pyramid_and_balls_give_the_same_velocities_and_impulses_both_ways)
{
    rb_world *world = soft_world();
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 20, &pyramid), RB_OK, "%s", rb_last_error());
    for (int k = 0; k < 9; ++k) {
        rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(12.0 + 1.5 * k, 0.5), 0.0);
        add_circle(world, ball, rb_v2(0.0, 0.0), 0.5, 1.0);
    }
    step_world(world, TEST_DT, 30);
    /* Every seventh box bounces: its contacts, though they have two
     * points, are solved one at a time, as the blocks do not keep the
     * largest push that restitution reads. */
    for (int k = 0; k < pyramid.box_count; k += 7) {
        rb_shape_id shape;
        cr_assert_eq(rb_body_shapes(world, scene_body_at(pyramid.first_box, k), &shape, 1), 1);
        cr_assert_eq(rb_shape_set_restitution(world, shape, 0.5), RB_OK, "%s", rb_last_error());
    }
    for (int round = 0; round < 6; ++round) {
        constraint_counts n =
            expect_passes_agree(world, 0.5 * (round % 3), round % 2 == 0, round >= 3, 2024u + (uint64_t)round);
        cr_expect_gt(n.two_point, 500, "the pyramid's contacts have two points (%d did)", n.two_point);
        cr_expect(n.bouncing > 50 && n.bouncing < n.two_point / 2,
                  "some of them, not most, have restitution (%d of %d)", n.bouncing, n.two_point);
    }
    /* A box asleep among awake ones (one that does not bounce, so that
     * its contacts take lanes): its contacts move only the others (its
     * inverse mass and inertia count as 0) and take the spring against a
     * fixed body. */
    rb_body *sleeper = &world->bodies[scene_body_at(pyramid.first_box, 7 * (pyramid.box_count / 14) + 3).index];
    sleeper->awake = false;
    expect_passes_agree(world, 0.5, true, false, 99u);
    sleeper->awake = true;
    /* The rows each solver asks for: the soft step's, NGS's, Baumgarte's. */
    expect_preparations_agree(world, (rb_substep_rows){.first_substep = true}, 11u);
    expect_preparations_agree(world, (rb_substep_rows){.block_normals = true}, 12u);
    expect_preparations_agree(world, (rb_substep_rows){.baumgarte_bias = true, .block_normals = true}, 13u);
    destroy_world_and_expect_no_leak(world);
}

Test(contact_lanes, balls_on_a_table_give_the_same_velocities_and_impulses_both_ways)
{
    rb_world *world = soft_world();
    scene_balls balls;
    cr_assert_eq(scene_balls_create(world, 50, 2024, &balls), RB_OK, "%s", rb_last_error());
    for (int n = 0; n < 60; ++n) {
        cr_assert_eq(scene_balls_apply_drag(world, &balls), RB_OK, "%s", rb_last_error());
        step_world(world, TEST_DT, 1);
    }
    for (int round = 0; round < 2; ++round) {
        expect_passes_agree(world, 2.0, round == 0, false, 7u + (uint64_t)round);
    }
    destroy_world_and_expect_no_leak(world);
}

/* A dynamic plank 100 m long carrying 80 boxes and 8 balls: the plank's
 * contacts outnumber the colours, so some go to the overflow colour,
 * beside the blocks (the boxes' other contacts) and the singles (the
 * balls'). Every contact the blocks do not hold is solved from its
 * constraint, and the step gives each constraint's impulses back to its
 * manifold, whichever of the two kinds it is
 * (rb_contact_solver_loose_constraint), and measures its overlap. */
Test(contact_lanes, constraints_beside_the_blocks_give_their_impulses_back)
{
    rb_world *world = soft_world();
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, -1.0), 0.0);
    add_box(world, ground, 60.0, 1.0, 1.0);
    rb_body_id plank = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.25), 0.0);
    add_box(world, plank, 50.0, 0.25, 1.0);
    for (int k = 0; k < 80; ++k) {
        rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(-49.0 + 1.2 * k, 0.99), 0.0);
        add_box(world, box, 0.49, 0.49, 1.0);
    }
    for (int k = 0; k < 8; ++k) {
        rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(-48.4 + 12.0 * k, 1.2), 0.0);
        add_circle(world, ball, rb_v2(0.0, 0.0), 0.2, 1.0);
    }
    step_world(world, TEST_DT, 20);
    const rb_contact_batches *batches = &world->contact_batches;
    int overflow = world->constraint_count - batches->overflow_start;
    cr_assert_gt(overflow, 0, "some of the plank's contacts are in the overflow colour");
    cr_assert_gt(batches->single_count, 0, "the balls' contacts are singles");
    cr_assert_gt(batches->block_count, 0, "the boxes' other contacts are in blocks");
    cr_assert_eq(rb_contact_solver_loose_count(world), batches->single_count + overflow);
    int pushing = 0;
    for (int k = 0; k < rb_contact_solver_loose_count(world); ++k) {
        int i = rb_contact_solver_loose_constraint(world, k);
        cr_assert(i >= 0 && i < world->constraint_count);
        if (k > 0) {
            cr_expect_gt(i, rb_contact_solver_loose_constraint(world, k - 1), "in the order of their indices");
        }
        const rb_contact_constraint *c = &world->constraints[i];
        const rb_manifold *m = &world->contacts[c->contact].manifold;
        for (int j = 0; j < c->point_count; ++j) {
            cr_expect(m->points[j].normal_impulse == c->points[j].normal_impulse &&
                          m->points[j].tangent_impulse == c->points[j].tangent_impulse,
                      "constraint %d point %d: impulses (%.17g, %.17g) solved, (%.17g, %.17g) in its manifold", i, j,
                      c->points[j].normal_impulse, c->points[j].tangent_impulse, m->points[j].normal_impulse,
                      m->points[j].tangent_impulse);
            pushing += c->points[j].normal_impulse > 0.0;
        }
    }
    cr_expect_gt(pushing, overflow, "the constraints push (%d points did)", pushing);
    destroy_world_and_expect_no_leak(world);
}
