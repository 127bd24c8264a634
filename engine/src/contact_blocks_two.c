/* SPDX-License-Identifier: MIT */
/* The blocks' passes two contacts to a vector operation: 2 × double, the
 * registers of SSE2 (every x86-64 processor) or of NEON (64-bit Arm). */
#define WIDTH 2
#include "contact_block_passes.h"
