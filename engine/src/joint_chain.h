/* SPDX-License-Identifier: MIT */
/* Trees that are chains, solved through their pins alone.
 *
 * A chain hung from a fixed body (a rope, the peers' 100:1 chain) is a
 * tree of pins whose every body holds at most two of them. Its bodies can
 * then be eliminated first, with no fill: the pins' own matrix
 * K = J·M⁻¹·Jᵀ couples each pin only with the pins before and after it
 * along the chain, through the body they share, and is block tridiagonal
 * with 2 × 2 blocks. Its L·D·Lᵀ factors are found from the fixed end
 * down, one 2 × 2 pivot a pin, as for any block-tridiagonal system (the
 * block form of the tridiagonal algorithm; Golub and Van Loan, "Matrix
 * Computations", 4th ed., 2013, §4.5). It solves the same system as the
 * tree's elimination of bodies and pins together (joint_tree.c) with
 * no 3 × 3 pivot, for about half the arithmetic.
 *
 * The nodes are the tree's (rb_tree_node), breadth first from each root,
 * which in a chain alternate: the pin to the fixed body, its body, the
 * next pin, its body, ... the last body. The right-hand side is each
 * pin's value (the velocity error, or the gap), the solution each pin's
 * impulse and each body's change of velocity (or of position), as the
 * tree's solve gives them.
 */
#ifndef RB_JOINT_CHAIN_H
#define RB_JOINT_CHAIN_H

#include "world_internal.h"

/* Whether every tree is a chain from a pin to a fixed body: each node's
 * parent the node before it, each root a pin. */
bool rb_joint_chain_all_chains(const rb_joint_tree *tree);

/* Factors the chains at the offsets their pins hold (node ra, rb) and
 * solves them; false when a pivot is singular. */
bool rb_joint_chain_factor_and_solve(rb_joint_tree *tree);

/* Solves them with the factors the nodes hold. */
void rb_joint_chain_solve(rb_joint_tree *tree);

#endif
