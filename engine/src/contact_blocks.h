/* SPDX-License-Identifier: MIT */
/* The soft step's contacts in blocks (contact_blocks.c), and their
 * passes, built at two widths from one text (contact_block_passes.h):
 * two contacts to a vector operation (contact_blocks_two.c, any
 * processor) and four (contact_blocks_four.c, x86-64 processors with
 * AVX). Both give the reference's bits. */
#ifndef RB_CONTACT_BLOCKS_H
#define RB_CONTACT_BLOCKS_H

#include "contact_solver.h"

/* Whether the four-wide passes are built: where the compiler can build
 * one file for AVX while the rest of the program runs anywhere (GCC, for
 * x86-64). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RB_BLOCKS_FOUR_WIDE 1
#else
#define RB_BLOCKS_FOUR_WIDE 0
#endif

/* Whether a contact to solve takes a lane of a block: two points (so no
 * circle side, whose contacts have one) and no restitution, whose record
 * of the step's largest push the blocks do not keep. */
static inline bool rb_contact_takes_a_lane(const rb_contact *contact)
{
    return contact->manifold.point_count == 2 && contact->restitution == 0.0;
}

/* The soft step's constraints and blocks in one pass over the contacts,
 * after rb_contact_solver_prepare has coloured them and counted each
 * colour's lanes; start[k] is where colour k's constraints begin. Returns
 * 0, or -1 when out of memory for the blocks: then there are no blocks
 * and no singles, and no constraint is filled. */
int rb_contact_blocks_build(rb_world *world, const int start[RB_COLOUR_COUNT + 1]);

/* The deepest overlap at the poses now of the blocks' contacts, 0 if
 * none: each lane's as carried_overlap (contact_solver.c) measures a
 * constraint's, from the lane's values by the same arithmetic, and one
 * deeper than `trusted` (m; INFINITY for none) measured again by the
 * narrow phase (rb_contact_deepest_overlap_now), as
 * rb_contact_solver_store_impulses does. */
double rb_contact_blocks_deepest_overlap(const rb_world *world, double trusted);

void rb_contact_blocks_warm_start_2(rb_world *world, bool prepare);
void rb_contact_blocks_solve_soft_2(rb_world *world, const rb_contact_softness *softness);
#if RB_BLOCKS_FOUR_WIDE
void rb_contact_blocks_warm_start_4(rb_world *world, bool prepare);
void rb_contact_blocks_solve_soft_4(rb_world *world, const rb_contact_softness *softness);
#endif

/* The widest the processor running the program can take: 4 where the
 * four-wide passes are built and it has AVX (and its system saves the
 * AVX registers), else 2. */
int rb_contact_blocks_widest(void);

#endif
