/* SPDX-License-Identifier: MIT */
/* Small limbs solved as one dense system: the pins and reached limits of
 * a few bodies of very different masses, linked by revolute joints, in
 * one exact solve per velocity pass instead of one joint at a time.
 *
 * Why. A limit is held through the bodies between it and the load. In
 * the built-in leg (models/leg.json) a 200 kg weight on the femur drops
 * onto the ankle's stop, and the stop holds it through the 0.5 kg foot,
 * whose other end is pinned to the fixed toe: four pins closing a loop
 * through the ground, and a mass ratio of 400. Gauss-Seidel passes carry
 * such a load a little at a time: at 10 substeps of 4 passes the ankle
 * went 20° past its stop, and even 100 passes left 2°. Solved exactly
 * the same substeps hold it within 0.001°. Joint trees
 * (joint_tree.h) solve chains exactly but neither limits nor loops.
 *
 * Which joints. A connected group of at most RB_BLOCK_MAX_BODIES bodies
 * that move and turn freely, linked to each other and to fixed bodies by
 * at most RB_BLOCK_MAX_JOINTS revolute joints, each with a limit, and by
 * nothing else (a limb with anatomical ranges; the trees take unlimited
 * pins), whose heaviest body is at least RB_BLOCK_MASS_RATIO times its
 * lightest. NGS only, with the trees (tree_pins). Loops are welcome: the
 * leg's four pins close one through the ground, which no tree can solve.
 *
 * How. Each substep stacks the rows that act: every pin's two rows and,
 * of each joint, the nearer limit if the joint could reach it within the
 * substep (a margin below twice what its relative speed covers in the
 * substep, plus the angular slop) or held last substep. With v the
 * bodies' velocities, J the rows' Jacobian and M the masses, the
 * impulses λ that make J·(v + M⁻¹·Jᵀ·λ) + b = 0 solve
 *
 *     K·λ = -(J·v + b),   K = J·M⁻¹·Jᵀ,
 *
 * b holding each pin's centripetal drift (joint_point.c) and each
 * limit's speculative bias (margin / h: it may close, not pass). K is
 * symmetric positive definite while the rows are independent; it is
 * factored once a substep as L·D·Lᵀ (Golub and Van Loan, "Matrix
 * Computations", 4th ed. 2013, §4.1), and every pass solves with the
 * factors. A limit may push, never pull: a pass whose solution would
 * leave a limit's accumulated impulse negative releases that limit (its
 * total set to 0) and solves the rest again, the largest pull first
 * (an active-set method, Nocedal and Wright, "Numerical Optimization",
 * 2006, §16.5). More rows than the bodies' freedoms (two limits reached
 * in a loop) make K singular: the farthest limit is then left out of the
 * substep and its warm-started impulse taken back; a K singular without
 * limits (a loop at a dead centre) leaves the joints to Gauss-Seidel for
 * the substep.
 *
 * The muscles. A damped cable whose moving bodies (at most two) are the
 * block's is a row of it, between the pins' and the limits': its
 * implicit law (cable.c) at the substep's end, P = h·(T0 + c·L') with
 * L' = -J·v, is the soft row J·v + P/(h·c) - T0/c = 0, whose compliance
 * 1/(h·c) adds to K's diagonal; it pulls, never pushes, like a limit.
 * Solved one at a time around the block, each cable's pass would push
 * the bodies against their own masses and the block would take most of
 * it back: the mass ratio again, which would leave the leg's ankle
 * degrees from its converged course at 4 passes. A cable over more
 * bodies, or undamped (a set tension, which its own pass applies once),
 * keeps its own pass, and cables damped so stiffly that they make K
 * singular are given back to theirs before any limit is left out.
 *
 * The later passes. A block that nothing else acts on (no contact, no
 * damped cable that is not its row) and whose pass released no row has
 * its exact solution: the passes after it would find every row met, so
 * they skip it (`closed` and `settled`).
 *
 * Factors kept. K changes with the bodies' poses and the cables' laws,
 * little from one substep to the next while the limb holds a posture. A
 * substep whose rows are those its block's factors were made for (the
 * same pins, cables and limits, in the same order; a body's mass changed
 * between steps is the check's to find) solves with those factors, and
 * its pass checks the solution against K made now, matrix-free:
 * K·λ = J·(M⁻¹·Jᵀ·λ) + C·λ. It stands
 * when the residual |K·λ - r| is at most RB_BLOCK_KEPT_RESIDUAL of |r|;
 * otherwise (or when a row would let go, whose subsets need K) the pass
 * factors K made now and solves again, and the block factors at every
 * substep until the next step. This is the modified Newton method's
 * reuse of a Jacobian's factors while it converges (Hairer and Wanner,
 * "Solving Ordinary Differential Equations II", 2nd ed. 1996, §IV.8),
 * with the residual, not the age, as the test. The residual bounds the
 * velocities' error; the impulses' error is larger by up to K's
 * condition, which a stop holding a limb against its muscles makes
 * large, hence the tolerance: at 1e-2 the leg held on its stops by
 * every muscle for 20 s had its muscle tensions 5 % off and its knee's
 * reaction 16 % of its largest; at 1e-6 the leg's runs agree with
 * factoring every substep to 3e-11 of each figure's largest value and
 * 5e-13° in the angles.
 *
 * The position passes stay Gauss-Seidel (rb_revolute_correct): what the
 * velocity solve leaves is a substep's drift, not a load.
 */
#ifndef RB_JOINT_BLOCK_H
#define RB_JOINT_BLOCK_H

#include "world_internal.h"

/* A group of limited pins is solved as a block when its heaviest body is
 * at least this many times its lightest. Measured on the built-in models
 * at their 10 substeps of 4 passes: Gauss-Seidel let the leg under 10 kg
 * (femur and weight 24 times the foot) pass the ankle's stop by 3.3°,
 * and holds the arm up to 10 kg (8 times its forearm's mass), which thus
 * keeps the figures it was validated with. */
#define RB_BLOCK_MASS_RATIO 20.0

/* The relative residual |K·λ - r| / |r| up to which a pass accepts a
 * solve with factors an earlier substep made for the same rows (see
 * "Factors kept" above). */
#define RB_BLOCK_KEPT_RESIDUAL 1e-6

/* Finds this step's blocks (sets joint->in_block, clears it elsewhere).
 * Call after the step's joint list and frames' masses are prepared
 * (rb_joints_collect_active), before the trees are built. */
void rb_joint_blocks_build(rb_world *world);

/* At each substep, after the cables are prepared and warm started
 * (rb_cables_prepare, rb_cables_warm_start) and the joints' frames
 * (rb_joints_warm_start): chooses the rows that act, takes the cables
 * that pull on the block's bodies alone (rb_cable.in_block), and factors
 * each block's K at the substep's anchors, or keeps the factors made for
 * the same rows. */
void rb_joint_blocks_factor(rb_world *world, double h);

/* One velocity pass over the blocks: each block's impulses solved at
 * once, applied to its bodies and added to its joints' and cables'
 * accumulated impulses; a closed block that the last pass solved is
 * skipped. */
void rb_joint_blocks_solve_velocities(rb_world *world);

#endif
