/* SPDX-License-Identifier: MIT */
/* The soft step's contact passes over the blocks (contact_blocks.c),
 * built at two widths from one text (contact_block_passes.h): two
 * contacts to a vector operation (contact_blocks_two.c, any processor)
 * and four (contact_blocks_four.c, x86-64 processors with AVX). Both give
 * the reference's bits. */
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

void rb_contact_blocks_warm_start_2(rb_world *world);
void rb_contact_blocks_solve_soft_2(rb_world *world, const rb_contact_softness *softness);
#if RB_BLOCKS_FOUR_WIDE
void rb_contact_blocks_warm_start_4(rb_world *world);
void rb_contact_blocks_solve_soft_4(rb_world *world, const rb_contact_softness *softness);
#endif

/* The widest the processor running the program can take: 4 where the
 * four-wide passes are built and it has AVX (and its system saves the
 * AVX registers), else 2. */
int rb_contact_blocks_widest(void);

#endif
