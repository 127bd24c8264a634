/* SPDX-License-Identifier: MIT */
/* Pins solved together, exactly: the point rows of revolute joints that
 * link bodies into trees (ropes, chains, limbs) as one linear system,
 * instead of one joint at a time.
 *
 * Why. Gauss-Seidel passes carry an impulse one joint per pass, and a
 * light link beside a heavy body passes on only a small part of it: a
 * rope of 30 light links with a box 1,000 times heavier at its end lets
 * the box's momentum stretch the joints faster than a few passes a
 * substep can pull them together, and at the defaults it tore apart for
 * good. Solved as one system the same rope holds at any mass ratio.
 *
 * How (Baraff, "Linear-time dynamics using Lagrange multipliers", 1996).
 * Bodies and pins are the nodes of one graph, each pin joined to its one
 * or two moving bodies. The velocity change Δv of the bodies and the pins'
 * impulses λ satisfy
 *
 *     | M   -Jᵀ | | Δv |   | 0    |
 *     | -J   0  | | λ  | = | Cdot |      (M Δv = Jᵀ λ, J (v + Δv) = 0)
 *
 * with M the bodies' masses and inertias (3×3 diagonal blocks) and J the
 * pins' 2×3 blocks [1 0 -r.y; 0 1 r.x] (negated on body A). When the graph
 * is a forest, eliminating each node after its children (a leaf first)
 * factors this matrix as L·D·Lᵀ with no fill: O(n) small blocks. A body's
 * pivot stays positive definite and a pin's negative definite, so every
 * pivot is invertible provided no pin is eliminated before a body below
 * it, which rooting each tree at its one pin to a fixed body (or, without
 * one, at a body) guarantees.
 *
 * Which pins. A revolute joint whose limits are off (a limit is solved
 * with its pin as one 3×3 block by Gauss-Seidel), between two bodies that
 * each either move and turn freely (mass and inertia finite) or do not
 * move at all. A pin that would close a loop (the joint grid's cells, a
 * body pinned to the ground twice) is left to Gauss-Seidel, which then
 * solves it with the tree's pins held; the tree's pins carry the rest. A
 * revolute joint's motor and spring stay Gauss-Seidel rows too. And only
 * in trees of uneven masses, whose heaviest body is at least
 * RB_TREE_MASS_RATIO times their lightest (the soft step:
 * RB_SOFT_STEP_TREE_MASS_RATIO): below that Gauss-Seidel holds
 * at the defaults (a 40-link chain with a 100:1 end box swings within
 * 0.018 m, the joint grid's equal boxes within 0.5 m), at less cost (the
 * joint grid solved as a spanning tree took twice the time), and the
 * built-in muscle models keep the figures they were validated with.
 *
 * The factors are built at the substep's anchors for the velocity passes,
 * and again at the current poses for each NGS position pass, which asks
 * for the position change Δx with J Δx = -C (C the anchors' gap, each
 * capped at max_linear_correction).
 *
 * The soft step (solver_soft_step.c) solves the trees too: each of its
 * passes at the current poses, softened by the pass's spring, and one
 * position pass after the positions move, as NGS does. Without them a
 * 40-link chain with a 400:1 end box tore apart at Box2D v3's budget
 * (4 substeps of 1 + 1 passes), where Box2D v3 holds it within 0.29 m.
 */
#ifndef RB_JOINT_TREE_H
#define RB_JOINT_TREE_H

#include "world_internal.h"

/* A tree is solved together when its heaviest body is at least this many
 * times its lightest (joint_tree.c, keep_uneven_trees): where Gauss-Seidel
 * starts to let a chain stretch by centimetres (at 600:1 a rope held
 * within 0.065 m, at 700:1 it tore apart). */
#define RB_TREE_MASS_RATIO 100.0
/* The soft step's threshold. At Box2D v3's budget (4 substeps of 1 + 1
 * passes) its pins one at a time hold the peers' 40-link chain with an
 * end box 100, 150 and 200 times a link's mass as Box2D v3 does, at Box2D
 * v3's cost: worst gap over 5 s swinging 0.0626, 0.0804, 0.0990 m (Box2D
 * v3 0.0631, 0.0807, 0.0992 m), hanging 0.0359, 0.0497, 0.0635 m (0.0360,
 * 0.0498, 0.0636 m). From 250:1 they let it stretch further (0.152 m
 * against 0.121 m, at 300:1 0.65 m against 0.14 m), and the trees take
 * over (0.028 m at 250:1, 0.072 m at 400:1). */
#define RB_SOFT_STEP_TREE_MASS_RATIO 200.0

/* Finds the pins solved together this step (sets joint->in_tree) and
 * their trees, or keeps last step's when they would be found the same
 * (the same active joints, bodies, limits, motors, springs and masses,
 * the same settings). On running out of memory no joint is in a tree,
 * and every pin is solved by Gauss-Seidel as before. Call after the
 * step's joint list and frames' masses are prepared
 * (rb_joints_collect_active). */
void rb_joint_tree_build(rb_world *world);

/* Each plain pin of the trees in one sweep over their pins, in place of
 * the joints' visit (rb_joints_warm_start): its anchors turned into the
 * world at the substep's poses (the frame's ra, rb), its centripetal
 * drift for the substep, and its warm start with the impulse it holds.
 * Backwards, the pins are taken in the reverse order. When no other row
 * acts on the trees' bodies this step and the solver is NGS, the pins
 * start cold instead: no warm start, their velocity errors read in the
 * same sweep, and the substep's first pass, which solves the trees
 * exactly, replaces the impulses they hold (joint_tree.c, starts_cold). */
void rb_joint_tree_warm_start(rb_world *world, double h, bool backwards);

/* Starts a substep: the factors the nodes hold are out of date. */
void rb_joint_tree_start_substep(rb_world *world);

/* One velocity pass over the trees' pins: the impulses that make every
 * pin's anchors move together (less the centripetal drift the pin
 * prepared, plus the response's bias), applied to the bodies and added to
 * each pin's accumulated impulse. The substep's first pass factors the
 * trees at the substep's anchors (the pins' offsets at the poses at the
 * substep's start, which their frames hold once the joints are prepared
 * for the substep, rb_joints_warm_start) in the same sweep as it solves;
 * the further passes reuse the factors. When no other row acts on the
 * trees' bodies this step (no other joint, cable or contact), the
 * substep's first pass leaves nothing to solve but rounding, and the
 * further passes return at once: a chain's worst gap stays as it was, at
 * the cost of one pass a substep. */
void rb_joint_tree_solve_velocities(rb_world *world);

/* One soft-step pass over the trees' pins under the pass's response
 * (world->joint_response: the spring, or rigid for the relax pass), at
 * the bodies' current poses. */
void rb_joint_tree_solve_soft(rb_world *world);

/* One NGS position pass over the trees' pins at the current poses;
 * returns whether every pin's gap was within the linear slop before it. */
bool rb_joint_tree_correct_positions(rb_world *world);

/* Says the bodies have moved since the trees were last factored at their
 * poses (rb_joint_tree_solve_soft factors them again). */
void rb_joint_tree_poses_moved(rb_world *world);

/* Frees the trees' arrays (at world destruction). */
void rb_joint_tree_free(rb_world *world);

#endif
