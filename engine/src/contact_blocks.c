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
 * contact rather than 304. Each contact is copied
 * into its lane as soon as its constraint is made, while the constraint
 * is still in the processor's first cache: one pass over the contacts
 * where there were three (make the constraints, prepare their points,
 * copy them into blocks), each of which, on the base-100 pyramid's
 * 15,000 contacts, streamed 6.7 MB of constraints through the third-level
 * cache. What moves with the bodies (the normal's lever arms and the
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
#include <assert.h>
#include <string.h>

#include "allocator.h"
#include "constraint_colouring.h"
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

/* Copies constraint `index`, between the bodies whose states are at a
 * and b, into lane `slot` of the blocks (lane slot % RB_BLOCK_LANES of
 * block slot / RB_BLOCK_LANES) and of their tails: every field the
 * block's first warm start does not prepare, so a block needs no clearing
 * before its lanes are filled. */
static void copy_into_lane(rb_contact_batches *batches, unsigned slot, int index, const rb_contact_constraint *c,
                           rb_body_state *a, rb_body_state *b)
{
    unsigned k = slot / RB_BLOCK_LANES; /* unsigned: a shift and a mask, where a signed division takes five more */
    unsigned lane = slot % RB_BLOCK_LANES;
    rb_contact_block_tail *tail = &batches->tails[k];
    tail->constraints[lane] = index;
    tail->contacts[lane] = c->contact;
    tail->turns_with_a[lane] = c->normal_follows == RB_NORMAL_TURNS_WITH_A ? -1 : 0;
    tail->local_normal_x.v[lane] = c->local_normal.x;
    tail->local_normal_y.v[lane] = c->local_normal.y;
    rb_contact_block *q = &batches->blocks[k];
    q->body_a[lane] = a;
    q->body_b[lane] = b;
    q->against_fixed[lane] = c->against_fixed ? -1 : 0;
    q->normal_x.v[lane] = c->normal.x;
    q->normal_y.v[lane] = c->normal.y;
    q->inv_mass_a.v[lane] = c->inv_mass_a;
    q->inv_inertia_a.v[lane] = c->inv_inertia_a;
    q->inv_mass_b.v[lane] = c->inv_mass_b;
    q->inv_inertia_b.v[lane] = c->inv_inertia_b;
    q->friction.v[lane] = c->friction;
    for (int j = 0; j < 2; ++j) {
        const rb_constraint_point *p = &c->points[j];
        rb_block_point *w = &q->points[j];
        w->local_surface_ax.v[lane] = p->local_surface_a.x;
        w->local_surface_ay.v[lane] = p->local_surface_a.y;
        w->local_surface_bx.v[lane] = p->local_surface_b.x;
        w->local_surface_by.v[lane] = p->local_surface_b.y;
        w->normal_impulse.v[lane] = p->normal_impulse;
        w->tangent_impulse.v[lane] = p->tangent_impulse;
    }
}

/* Empties lane `slot` of the blocks, as copy_into_lane would copy a
 * contact that cannot act: along (1, 0) between the idle bodies, with no
 * mass and no impulse, its surface points at their centres (so no lever
 * arm). */
static void empty_lane(rb_contact_batches *batches, unsigned slot)
{
    static const rb_contact_constraint idle = {.normal = {1.0, 0.0}};
    copy_into_lane(batches, slot, -1, &idle, &batches->idle_a, &batches->idle_b);
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
    rb_contact_constraint *constraints = world->constraints;
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *contact = &world->contacts[i];
        int colour = contact->colour;
        if (colour < 0) {
            continue;
        }
        int index = next[colour]++;
        rb_contact_constraint *c = &constraints[index];
        rb_contact_solver_fill_constraint(world, i, c);
        if (colour == RB_OVERFLOW_COLOUR) {
            continue;
        }
        if (!rb_contact_takes_a_lane(contact)) {
            batches->singles[single[colour]++] = index;
            continue;
        }
        rb_body_state *a = &world->states[c->body_a];
        rb_body_state *b = &world->states[c->body_b];
        /* The normal as the bodies turn it now, as
         * rb_contact_solver_prepare_points_range finds it. */
        assert(c->normal_follows != RB_NORMAL_FROM_CENTERS && c->radius_a == 0.0 && c->radius_b == 0.0);
        c->normal = rb_rotate(c->normal_follows == RB_NORMAL_TURNS_WITH_A ? a->rotation : b->rotation, c->local_normal);
        copy_into_lane(batches, (unsigned)lane[colour]++, index, c, a, b);
        c->in_lane = true;
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
