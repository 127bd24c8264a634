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
 * Once a step, after the points are prepared, the two-point constraints
 * of each colour are laid four by four into rb_contact_block
 * (rb_contact_solver_gather_blocks): each value of the four contacts side
 * by side, which one load brings into a register, and the addresses of
 * their bodies' states, found once. The blocks then hold the impulses
 * through the step's passes (warm start, solve, relax), and
 * rb_contact_solver_scatter_blocks writes them back to the constraints
 * for restitution and the next step. The last block of a colour may have
 * empty lanes, whose contact cannot act (no mass, no impulse) between
 * two idle bodies of the batches' own. A contact with one point and the
 * overflow colour (whose constraints may share bodies) go through the
 * reference; colour by colour, a colour's blocks first and then its
 * others, which gives each body the reference's sums in the reference's
 * order (a body is in at most one constraint of a colour).
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
#include "contact_blocks.h"

void rb_contact_batches_free(rb_contact_batches *batches)
{
    rb_free_array((void **)&batches->blocks, &batches->block_capacity, sizeof *batches->blocks);
    rb_free_array((void **)&batches->singles, &batches->single_capacity, sizeof *batches->singles);
}

size_t rb_contact_batches_bytes(const rb_contact_batches *batches)
{
    return (size_t)batches->block_capacity * sizeof *batches->blocks +
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
 * and b, into lane `lane` of block q: every field of the lane, so a block
 * needs no clearing before its lanes are filled. */
static void copy_into_lane(rb_contact_block *q, int lane, int index, const rb_contact_constraint *c, rb_body_state *a,
                           rb_body_state *b)
{
    q->body_a[lane] = a;
    q->body_b[lane] = b;
    q->constraints[lane] = index;
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

/* Empties lane `lane` of block q, as copy_into_lane would copy a contact
 * that cannot act: along (1, 0) between the idle bodies, with no mass, no
 * lever arm and no impulse. */
static void empty_lane(rb_contact_block *q, int lane, rb_contact_batches *batches)
{
    static const rb_contact_constraint idle = {.normal = {1.0, 0.0}};
    copy_into_lane(q, lane, -1, &idle, &batches->idle_a, &batches->idle_b);
}

/* Whether a constraint can take a lane of a block: two points, and no
 * circle side (whose radius the blocks do not hold; a circle's contacts
 * have one point anyway). */
static bool fits_a_block(const rb_contact_constraint *c)
{
    return c->point_count == 2 && c->radius_a == 0.0 && c->radius_b == 0.0;
}

/* Within each colour, the two-point constraints in order, four to a
 * block, the colour's last block filled out with empty lanes; the
 * colour's other constraints become singles. The arrays grow only when
 * the contacts outgrow them. */
void rb_contact_solver_gather_blocks(rb_world *world)
{
    rb_contact_batches *batches = &world->contact_batches;
    int count = world->constraint_count;
    batches->block_count = 0;
    batches->single_count = 0;
    batches->width = rb_contact_blocks_widest();
    batches->idle_a = (rb_body_state){.rotation = {1.0, 0.0}};
    batches->idle_b = batches->idle_a;
    /* Each colour's blocks but its last are full, and no block is empty. */
    int most_blocks = count / RB_BLOCK_LANES + RB_COLOUR_COUNT;
    if (most_blocks > count) {
        most_blocks = count;
    }
    if (rb_grow_array((void **)&batches->blocks, &batches->block_capacity, most_blocks, sizeof *batches->blocks) != 0 ||
        rb_grow_array((void **)&batches->singles, &batches->single_capacity, count, sizeof *batches->singles) != 0) {
        /* Out of memory: no blocks and no singles; every constraint is
         * then solved one at a time in order, as the overflow colour's
         * are, which needs nothing more. */
        memset(batches->block_start, 0, sizeof batches->block_start);
        memset(batches->single_start, 0, sizeof batches->single_start);
        batches->overflow_start = 0;
        return;
    }
    const rb_contact_constraint *constraints = world->constraints;
    int start[RB_COLOUR_COUNT + 1];
    rb_colouring_offsets(&world->contact_colouring, start);
    for (int colour = 0; colour < RB_COLOUR_COUNT; ++colour) {
        batches->block_start[colour] = batches->block_count;
        batches->single_start[colour] = batches->single_count;
        int end = start[colour] + world->contact_colouring.sizes[colour];
        int lane = RB_BLOCK_LANES; /* the next free lane of the colour's last block: none yet */
        for (int i = start[colour]; i < end; ++i) {
            if (!fits_a_block(&constraints[i])) {
                batches->singles[batches->single_count++] = i;
                continue;
            }
            if (lane == RB_BLOCK_LANES) {
                ++batches->block_count;
                lane = 0;
            }
            const rb_contact_constraint *c = &constraints[i];
            copy_into_lane(&batches->blocks[batches->block_count - 1], lane++, i, c, &world->states[c->body_a],
                           &world->states[c->body_b]);
        }
        for (; lane < RB_BLOCK_LANES; ++lane) {
            empty_lane(&batches->blocks[batches->block_count - 1], lane, batches);
        }
    }
    batches->block_start[RB_COLOUR_COUNT] = batches->block_count;
    batches->single_start[RB_COLOUR_COUNT] = batches->single_count;
    batches->overflow_start = start[RB_OVERFLOW_COLOUR];
}

void rb_contact_solver_scatter_blocks(rb_world *world)
{
    const rb_contact_batches *batches = &world->contact_batches;
    for (int k = 0; k < batches->block_count; ++k) {
        const rb_contact_block *q = &batches->blocks[k];
        for (int lane = 0; lane < RB_BLOCK_LANES && q->constraints[lane] >= 0; ++lane) {
            rb_contact_constraint *c = &world->constraints[q->constraints[lane]];
            for (int j = 0; j < 2; ++j) {
                c->points[j].normal_impulse = q->points[j].normal_impulse.v[lane];
                c->points[j].tangent_impulse = q->points[j].tangent_impulse.v[lane];
                c->points[j].max_normal_impulse = q->points[j].max_normal_impulse.v[lane];
            }
        }
    }
}

void rb_contact_solver_warm_start_blocks(rb_world *world)
{
#if RB_BLOCKS_FOUR_WIDE
    if (world->contact_batches.width == 4) {
        rb_contact_blocks_warm_start_4(world);
        return;
    }
#endif
    rb_contact_blocks_warm_start_2(world);
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
