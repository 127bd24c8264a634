/* SPDX-License-Identifier: MIT */
/* The soft step's contacts in blocks: up to four two-point contacts of
 * one colour side by side, solved together.
 *
 * Within a colour no two constraints move the same body
 * (constraint_colouring.h), so several can be solved at once, each in one
 * lane of a vector register, every lane doing what the one-at-a-time
 * reference does for its contact, to the bit (contact_block_passes.h).
 * Four lanes where the processor has AVX, two elsewhere
 * (contact_blocks.h); tests/test_contact_lanes.c checks both widths
 * against the reference.
 *
 * Once a step, as rb_contact_solver_prepare makes the constraints, the
 * two-point constraints of each colour are laid four by four into
 * rb_contact_block (rb_contact_blocks_build): each value of the four
 * contacts side by side, which one load brings into a register, and the
 * addresses of their bodies' states, found once; what the step's last
 * pass alone reads (where the impulses go, the normal in its body's
 * frame) goes into the block's tail, in an array beside the blocks
 * (rb_contact_block_tail), so that the other passes stream 272 bytes a
 * contact rather than 304. Each contact is made straight into its lane,
 * in one pass over the contacts, and its constraint is neither written
 * nor read: a constraint is 456 bytes, and on the base-100 pyramid's
 * 15,000 contacts making each constraint and then copying it into its
 * lane, or only marking it as held by a lane, made the step's
 * preparation stream megabytes through the third-level cache (the step
 * took 9 % longer). What moves with the bodies (the normal's lever arms and the
 * effective masses) the blocks then prepare four at a time, in the step's
 * first warm start, which reads the block anyway (contact_block_passes.h);
 * the bodies have not moved since the constraints were made. The blocks
 * hold the impulses through the step's passes (warm start, solve, relax),
 * and the step's last pass writes each block's into its contacts'
 * manifolds as it solves the block (contact_block_passes.h). The last block of a colour may have
 * empty lanes, whose contact cannot act (no mass, no impulse) between two
 * idle bodies of the batches' own. A contact with one point or with
 * restitution, and the overflow colour (whose constraints may share
 * bodies) go through the reference; colour by colour, a colour's blocks
 * first and then its others, which gives each body the reference's sums
 * in the reference's order (a body is in at most one constraint of a
 * colour).
 *
 * Why four where two were had, measured on the base-20 pyramid at Box2D
 * v3's budget. Sequential impulses are a chain: each of a contact's four
 * rows (two normal, two friction) reads the velocities the row before
 * wrote, some fourteen dependent sums and products; a pair of contacts
 * two wide, about 410 instructions, takes some 260 cycles where its
 * instructions alone would need 92 (llvm-mca, Skylake), and the
 * processor's window of instructions in flight is too short to reach the
 * next pair. So the passes are built to give it independent chains:
 * four contacts on one chain, and the soft pass solves two sets of lanes
 * at once with their rows interleaved (contact_block_passes.h). The
 * start of each chain matters as much: the bodies' addresses are found
 * once a step and kept in the block. Found anew in each pass through a
 * choice per lane (a body index, or an idle body), or handed over
 * through memory, they delayed every chain's first loads, and four wide
 * was then slower than two (0.140 against 0.134 ms of the step's solver
 * phases, against 0.104 ms as it is). */
#include <string.h>

#include "allocator.h"
#include "constraint_colouring.h"
#include "contact.h"
#include "contact_blocks.h"

void rb_contact_batches_free(rb_contact_batches *batches)
{
    rb_free_array((void **)&batches->blocks, &batches->block_capacity, sizeof *batches->blocks);
    rb_free_array((void **)&batches->tails, &batches->tail_capacity, sizeof *batches->tails);
    rb_free_array((void **)&batches->singles, &batches->single_capacity, sizeof *batches->singles);
}

size_t rb_contact_batches_bytes(const rb_contact_batches *batches)
{
    return (size_t)batches->block_capacity * sizeof *batches->blocks +
           (size_t)batches->tail_capacity * sizeof *batches->tails +
           (size_t)batches->single_capacity * sizeof *batches->singles;
}

int rb_contact_blocks_widest(void)
{
#if RB_BLOCKS_FOUR_WIDE
    /* GCC's test of the processor, which also asks the system whether it
     * saves the AVX registers. */
    if (__builtin_cpu_supports("avx")) {
        return 4;
    }
#endif
    return 2;
}

/* Lane `slot` of the blocks, counted over all their lanes, is lane
 * lane_of(slot) of block block_of(slot). Unsigned: a shift and a mask,
 * where a signed division takes five more instructions. */
static unsigned block_of(unsigned slot) { return slot / RB_BLOCK_LANES; }
static unsigned lane_of(unsigned slot) { return slot % RB_BLOCK_LANES; }

/* Contact `index`, which takes a lane, made straight into lane `slot` of
 * the blocks and of their tails: every value rb_contact_solver_fill_constraint
 * would give its constraint that a pass reads, by the same arithmetic,
 * and the normal as the bodies turn it now (as
 * rb_contact_solver_prepare_points_range turns it), so a block needs no
 * clearing before its lanes are filled; the lever arms and masses the
 * block's first warm start prepares. A two-point contact has no circle
 * side, so its normal turns with the body of its reference face and its
 * radii are 0. Its constraint, `constraint`, is left as it is: no pass
 * reads it (rb_contact_solver_loose_constraint). */
static void fill_lane(rb_world *world, int index, rb_contact_batches *batches, unsigned slot, int constraint)
{
    const rb_contact *contact = &world->contacts[index];
    const rb_body *body_a = &world->bodies[contact->body_a];
    const rb_body *body_b = &world->bodies[contact->body_b];
    rb_body_state *sa = &world->states[contact->body_a];
    rb_body_state *sb = &world->states[contact->body_b];
    double inv_mass_a = body_a->awake ? body_a->inv_mass : 0.0;
    double inv_inertia_a = body_a->awake ? body_a->inv_inertia : 0.0;
    double inv_mass_b = body_b->awake ? body_b->inv_mass : 0.0;
    double inv_inertia_b = body_b->awake ? body_b->inv_inertia : 0.0;
    rb_vec2 normal = contact->manifold.normal;
    bool on_b = contact->manifold.reference_on_b;
    rb_rot turn = on_b ? sb->rotation : sa->rotation;
    rb_vec2 local_normal = rb_inv_rotate(turn, normal);
    rb_vec2 turned = rb_rotate(turn, local_normal);

    unsigned k = block_of(slot);
    unsigned lane = lane_of(slot);
    rb_contact_block_tail *tail = &batches->tails[k];
    tail->constraints[lane] = constraint;
    tail->contacts[lane] = index;
    tail->turns_with_a[lane] = on_b ? 0 : -1;
    tail->local_normal_x.v[lane] = local_normal.x;
    tail->local_normal_y.v[lane] = local_normal.y;
    rb_contact_block *q = &batches->blocks[k];
    q->body_a[lane] = sa;
    q->body_b[lane] = sb;
    bool against_fixed = (inv_mass_a == 0.0 && inv_inertia_a == 0.0) || (inv_mass_b == 0.0 && inv_inertia_b == 0.0);
    q->against_fixed[lane] = against_fixed ? -1 : 0;
    q->normal_x.v[lane] = turned.x;
    q->normal_y.v[lane] = turned.y;
    q->inv_mass_a.v[lane] = inv_mass_a;
    q->inv_inertia_a.v[lane] = inv_inertia_a;
    q->inv_mass_b.v[lane] = inv_mass_b;
    q->inv_inertia_b.v[lane] = inv_inertia_b;
    q->friction.v[lane] = contact->friction;
    bool warm = world->settings.warm_starting;
    for (int j = 0; j < 2; ++j) {
        const rb_manifold_point *mp = &contact->manifold.points[j];
        rb_vec2 local_a;
        rb_vec2 local_b;
        rb_contact_local_surfaces(mp, normal, 0.0, 0.0, sa, sb, &local_a, &local_b);
        rb_block_point *w = &q->points[j];
        w->local_surface_ax.v[lane] = local_a.x;
        w->local_surface_ay.v[lane] = local_a.y;
        w->local_surface_bx.v[lane] = local_b.x;
        w->local_surface_by.v[lane] = local_b.y;
        w->normal_impulse.v[lane] = warm ? mp->normal_impulse : 0.0;
        w->tangent_impulse.v[lane] = warm ? mp->tangent_impulse : 0.0;
    }
}

/* Empties lane `slot` of the blocks: a contact that cannot act, along
 * (1, 0) between the idle bodies, with no mass and no impulse, its
 * surface points at their centres (so no lever arm), and no normal to
 * turn (so no overlap). */
static void empty_lane(rb_contact_batches *batches, unsigned slot)
{
    unsigned k = block_of(slot);
    unsigned lane = lane_of(slot);
    rb_contact_block_tail *tail = &batches->tails[k];
    tail->constraints[lane] = -1;
    tail->contacts[lane] = 0;
    tail->turns_with_a[lane] = 0;
    tail->local_normal_x.v[lane] = tail->local_normal_y.v[lane] = 0.0;
    rb_contact_block *q = &batches->blocks[k];
    q->body_a[lane] = &batches->idle_a;
    q->body_b[lane] = &batches->idle_b;
    q->against_fixed[lane] = 0;
    q->normal_x.v[lane] = 1.0;
    q->normal_y.v[lane] = 0.0;
    q->inv_mass_a.v[lane] = q->inv_inertia_a.v[lane] = q->inv_mass_b.v[lane] = q->inv_inertia_b.v[lane] = 0.0;
    q->friction.v[lane] = 0.0;
    for (int j = 0; j < 2; ++j) {
        rb_block_point *w = &q->points[j];
        w->local_surface_ax.v[lane] = w->local_surface_ay.v[lane] = 0.0;
        w->local_surface_bx.v[lane] = w->local_surface_by.v[lane] = 0.0;
        w->normal_impulse.v[lane] = w->tangent_impulse.v[lane] = 0.0;
    }
}

/* The overlap at the poses now of the contact in lane `lane` of block q,
 * 0 if none: what carried_overlap (contact_solver.c) measures of a
 * constraint, from the lane's values by the same arithmetic. */
static double lane_overlap(const rb_contact_block *q, const rb_contact_block_tail *tail, unsigned lane)
{
    const rb_body_state *a = q->body_a[lane];
    const rb_body_state *b = q->body_b[lane];
    rb_vec2 local_normal = rb_v2(tail->local_normal_x.v[lane], tail->local_normal_y.v[lane]);
    rb_vec2 normal = rb_rotate(tail->turns_with_a[lane] != 0 ? a->rotation : b->rotation, local_normal);
    double deepest = 0.0;
    for (int j = 0; j < 2; ++j) {
        const rb_block_point *p = &q->points[j];
        rb_vec2 local_a = rb_v2(p->local_surface_ax.v[lane], p->local_surface_ay.v[lane]);
        rb_vec2 local_b = rb_v2(p->local_surface_bx.v[lane], p->local_surface_by.v[lane]);
        rb_vec2 pa = rb_add(a->center, rb_rotate(a->rotation, local_a));
        rb_vec2 pb = rb_add(b->center, rb_rotate(b->rotation, local_b));
        double overlap = -rb_dot(normal, rb_sub(pb, pa));
        deepest = overlap > deepest ? overlap : deepest;
    }
    return deepest;
}

double rb_contact_blocks_deepest_overlap(const rb_world *world, double trusted)
{
    const rb_contact_batches *batches = &world->contact_batches;
    double deepest = 0.0;
    for (int k = 0; k < batches->block_count; ++k) {
        const rb_contact_block_tail *tail = &batches->tails[k];
        for (unsigned lane = 0; lane < RB_BLOCK_LANES && tail->constraints[lane] >= 0; ++lane) {
            double overlap = lane_overlap(&batches->blocks[k], tail, lane);
            if (overlap > trusted) {
                overlap = rb_contact_deepest_overlap_now(world, &world->contacts[tail->contacts[lane]]);
            }
            deepest = overlap > deepest ? overlap : deepest;
        }
    }
    return deepest;
}

/* Makes room for the blocks and the singles, and finds where each
 * colour's start, from the lanes rb_contact_solver_prepare counted:
 * every colour's blocks full but its last. Returns 0, or -1 when out of
 * memory. */
static int lay_out_batches(rb_contact_batches *batches, const int start[RB_COLOUR_COUNT + 1])
{
    int blocks = 0;
    int singles = 0;
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        batches->block_start[colour] = blocks;
        batches->single_start[colour] = singles;
        blocks += (batches->lanes[colour] + RB_BLOCK_LANES - 1) / RB_BLOCK_LANES;
        singles += start[colour + 1] - start[colour] - batches->lanes[colour];
    }
    batches->block_start[RB_COLOUR_COUNT] = blocks;
    batches->single_start[RB_COLOUR_COUNT] = singles;
    batches->block_count = blocks;
    batches->single_count = singles;
    batches->overflow_start = start[RB_OVERFLOW_COLOUR];
    return rb_grow_array((void **)&batches->blocks, &batches->block_capacity, blocks, sizeof *batches->blocks) != 0 ||
                   rb_grow_array((void **)&batches->tails, &batches->tail_capacity, blocks, sizeof *batches->tails) !=
                       0 ||
                   rb_grow_array((void **)&batches->singles, &batches->single_capacity, singles,
                                 sizeof *batches->singles) != 0
               ? -1
               : 0;
}

int rb_contact_blocks_build(rb_world *world, const int start[RB_COLOUR_COUNT + 1])
{
    rb_contact_batches *batches = &world->contact_batches;
    batches->width = rb_contact_blocks_widest();
    batches->idle_a = (rb_body_state){.rotation = {1.0, 0.0}};
    batches->idle_b = batches->idle_a;
    if (lay_out_batches(batches, start) != 0) {
        /* Out of memory: no blocks and no singles; every constraint is
         * then solved one at a time in order, as the overflow colour's
         * are, which needs nothing more. */
        batches->block_count = 0;
        batches->single_count = 0;
        memset(batches->block_start, 0, sizeof batches->block_start);
        memset(batches->single_start, 0, sizeof batches->single_start);
        batches->overflow_start = 0;
        return -1;
    }
    int next[RB_COLOUR_COUNT + 1]; /* each colour's next constraint */
    int lane[RB_COLOUR_COUNT];     /* each colour's next lane, counted from the first of its blocks */
    int single[RB_COLOUR_COUNT];   /* and its next single */
    memcpy(next, start, sizeof next);
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        lane[colour] = RB_BLOCK_LANES * batches->block_start[colour];
        single[colour] = batches->single_start[colour];
    }
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *contact = &world->contacts[i];
        int colour = contact->colour;
        if (colour < 0) {
            continue;
        }
        int index = next[colour]++;
        if (colour != RB_OVERFLOW_COLOUR && rb_contact_takes_a_lane(contact)) {
            fill_lane(world, i, batches, (unsigned)lane[colour]++, index);
            continue;
        }
        rb_contact_solver_fill_constraint(world, i, &world->constraints[index]);
        if (colour != RB_OVERFLOW_COLOUR) {
            batches->singles[single[colour]++] = index;
        }
    }
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        for (int k = lane[colour]; k < RB_BLOCK_LANES * batches->block_start[colour + 1]; ++k) {
            empty_lane(batches, (unsigned)k);
        }
    }
    return 0;
}

void rb_contact_solver_prepare_singles(rb_world *world, double h)
{
    const rb_contact_batches *batches = &world->contact_batches;
    rb_substep_rows rows = {.first_substep = true};
    for (int k = 0; k < batches->single_count; ++k) {
        int i = batches->singles[k];
        rb_contact_solver_prepare_points_range(world, h, rows, i, i + 1);
    }
    rb_contact_solver_prepare_points_range(world, h, rows, batches->overflow_start, world->constraint_count);
    rb_contact_solver_record_approaches(world, h);
}

void rb_contact_solver_warm_start_blocks(rb_world *world, bool prepare)
{
#if RB_BLOCKS_FOUR_WIDE
    if (world->contact_batches.width == 4) {
        rb_contact_blocks_warm_start_4(world, prepare);
        return;
    }
#endif
    rb_contact_blocks_warm_start_2(world, prepare);
}

void rb_contact_solver_solve_soft(rb_world *world, const rb_contact_softness *softness)
{
#if RB_BLOCKS_FOUR_WIDE
    if (world->contact_batches.width == 4) {
        rb_contact_blocks_solve_soft_4(world, softness);
        return;
    }
#endif
    rb_contact_blocks_solve_soft_2(world, softness);
}
