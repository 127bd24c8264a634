/* SPDX-License-Identifier: MIT */
/* The blocks' passes four contacts to a vector operation: 4 × double,
 * AVX's registers. This file alone is built for AVX (without FMA, whose
 * fused products would round differently from the reference); the
 * program calls it only on a processor that has AVX
 * (rb_contact_blocks_widest). */
#include "contact_blocks.h"

#if RB_BLOCKS_FOUR_WIDE
#pragma GCC target("avx")
#define WIDTH 4
#include "contact_block_passes.h"
#else
/* ISO C wants a declaration in every file. */
typedef int rb_no_four_wide_passes;
#endif
