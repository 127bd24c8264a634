/* SPDX-License-Identifier: MIT */
/* Sequential impulses on contacts: non-penetration with speculative
 * margin, Coulomb friction, restitution, and position correction by
 * Baumgarte bias or non-linear Gauss-Seidel. */
#ifndef RB_CONTACT_SOLVER_H
#define RB_CONTACT_SOLVER_H

#include <stddef.h>

#include "world_internal.h"

/* The block solver is used while cond(K) stays below this (Box2D uses the
 * same bound): beyond it the two points are nearly redundant and the 2x2
 * solve would amplify round-off. */
#define MAX_BLOCK_CONDITION 1000.0

typedef struct rb_constraint_point {
    /* m, the point's lever arms about each centre of mass for this
     * substep's normal and tangent: rA×n, rB×n, rA×t, rB×t, with rA, rB
     * from the centres to the point. A velocity along the normal is then
     * n·(vB - vA) + ωB·(rB×n) - ωA·(rA×n), and an impulse λ along it turns
     * the bodies by ∓λ·(r×n)/I: the rows of the constraint's Jacobian,
     * found once per substep instead of in every pass. */
    double normal_arm_a, normal_arm_b, tangent_arm_a, tangent_arm_b;
    /* m, in each body's frame from its centre of mass: the material point
     * on a polygon's surface, or the centre of a circle (whose surface
     * point is wherever the normal meets it). */
    rb_vec2 local_surface_a;
    rb_vec2 local_surface_b;
    double normal_mass, tangent_mass;       /* kg, effective masses along the normal and the tangent */
    double normal_impulse, tangent_impulse; /* N·s, accumulated */
    double max_normal_impulse;              /* N·s, largest accumulated normal impulse of the step */
    /* Restitution's record (contact_solver.c, record_approach), kept from
     * the last substep before the point first pushed: */
    double impact_velocity;       /* m/s, normal velocity when the surfaces met (< 0 approaching) */
    double approach_acceleration; /* m/s², normal relative acceleration of gravity and forces then */
    double min_normal_velocity;   /* m/s, the velocity solve's lower bound for this substep */
} rb_constraint_point;

struct rb_contact_constraint {
    int contact;        /* index in world->contacts */
    int body_a, body_b; /* indices in world->states */
    double inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
    bool against_fixed; /* one body cannot move: both its inverse mass and inertia are 0 */
    rb_vec2 normal;     /* unit, world, from A to B, this substep */
    /* What the normal follows as the bodies move: the line between two
     * circles' centres, or the reference face of a polygon, on A or B. */
    enum { RB_NORMAL_FROM_CENTERS, RB_NORMAL_TURNS_WITH_A, RB_NORMAL_TURNS_WITH_B } normal_follows;
    rb_vec2 local_normal;      /* the normal in the frame of the body it turns with */
    double radius_a, radius_b; /* m, of a circle side; 0 for a polygon side */
    double friction, restitution;
    int point_count;
    rb_constraint_point points[RB_MAX_MANIFOLD_POINTS];
    bool use_block;                   /* the 2x2 normal mass matrix is well conditioned */
    double k11, k12, k22;             /* normal mass matrix K (1/kg) */
    double inv_k11, inv_k12, inv_k22; /* its inverse (kg) */
};

/* Contacts a block holds side by side (contact_blocks.c). */
#define RB_BLOCK_LANES 4

/* One value of each of a block's contacts, lane k for its k-th. */
typedef struct rb_lanes4 {
    double v[RB_BLOCK_LANES];
} rb_lanes4;

/* A point of a block of contacts (rb_contact_block): the fields of
 * rb_constraint_point the soft step's passes read, lane by lane. */
typedef struct rb_block_point {
    rb_lanes4 local_surface_ax, local_surface_ay, local_surface_bx, local_surface_by;
    rb_lanes4 normal_arm_a, normal_arm_b, tangent_arm_a, tangent_arm_b;
    rb_lanes4 normal_mass, tangent_mass;
    rb_lanes4 normal_impulse, tangent_impulse;
} rb_block_point;

/* Up to four two-point contacts of one colour, with no circle side and no
 * restitution, laid side by side for the passes that solve them together
 * (contact_blocks.c): what every pass reads, 272 bytes a contact. They
 * are laid out as their constraints are made (rb_contact_blocks_build),
 * their points prepared by the step's first warm start, and they hold
 * their impulses until the step's last soft pass writes them into the
 * contacts' manifolds. A lane without a contact holds one that cannot act
 * (no mass, no impulse) between the batches' two idle bodies. */
struct rb_contact_block {
    /* the lanes' bodies in world->states (or the idle ones), found once
     * a step: no body is made or destroyed within a step, so the array
     * stays where it is */
    rb_body_state *body_a[RB_BLOCK_LANES];
    rb_body_state *body_b[RB_BLOCK_LANES];
    int64_t against_fixed[RB_BLOCK_LANES]; /* all ones where the contact is against a body that cannot move */
    rb_lanes4 normal_x, normal_y;
    rb_lanes4 inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
    rb_lanes4 friction;
    rb_block_point points[2];
};

/* What the step's last soft pass alone reads of a block, 32 bytes a
 * contact, in an array beside the blocks (the same index): where its
 * contacts' impulses go, and the normal in the frame of the body that
 * turns it, to measure the overlap left (carried_overlap,
 * contact_solver.c). Kept at the end of each block, these cache lines
 * were streamed through every pass with the rest (the processor fetches
 * a block's lines in a run); apart, the other passes read 272 bytes a
 * contact instead of 304. */
struct rb_contact_block_tail {
    int constraints[RB_BLOCK_LANES];      /* indices in world->constraints; -1 for an empty lane */
    int contacts[RB_BLOCK_LANES];         /* indices in world->contacts, whose manifolds the last pass writes */
    int64_t turns_with_a[RB_BLOCK_LANES]; /* all ones where the normal turns with body A, zero with B */
    rb_lanes4 local_normal_x, local_normal_y;
};

/* Two values side by side, the first contact's in v[0] and the second's
 * in v[1], aligned so that one SSE2 load or store moves both. */
typedef struct rb_lanes2 {
    _Alignas(16) double v[2];
} rb_lanes2;

/* A point of a row of contacts (rb_contact_row): what the sequential
 * solvers' warm start and velocity passes read and write of
 * rb_constraint_point, lane by lane. */
typedef struct rb_row_point {
    rb_lanes2 normal_arm_a, normal_arm_b, tangent_arm_a, tangent_arm_b; /* m */
    rb_lanes2 tangent_mass;                                             /* kg */
    rb_lanes2 min_normal_velocity;                                      /* m/s */
    rb_lanes2 normal_impulse, tangent_impulse;                          /* N·s, accumulated */
} rb_row_point;

/* Two two-point contacts of one colour, neither with restitution, each
 * solving its normal rows as a 2x2 block, laid side by side for the
 * sequential solvers' warm start and velocity passes
 * (contact_rows_two.c): what those passes read, 264 bytes a contact, in
 * the order they read it. Written by each substep's preparation
 * (contact_solver_wide.c). The rows hold their contacts' impulses: taken
 * from the constraints when a row is made, kept from one substep to the
 * next while the row pairs the same contacts, and given back by
 * rb_contact_rows_store_impulses (when the step stores them) or
 * rb_contact_rows_store_range (when the rows change). Their largest
 * pushes are not kept: only restitution reads them, and no row's
 * contact has it. */
struct rb_contact_row {
    rb_body_state *body_a[2];
    rb_body_state *body_b[2];
    rb_lanes2 normal_x, normal_y; /* unit, world, from A to B, this substep */
    rb_lanes2 tangent_y;          /* -normal_x: the tangent is (normal_y, -normal_x) */
    rb_lanes2 inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b; /* 1/kg, 1/(kg·m²); 0 for a body that cannot move */
    rb_lanes2 friction;                                             /* Coulomb's coefficient */
    rb_row_point points[2];
    rb_lanes2 k11, k12, k22;             /* 1/kg, the normal mass matrix K */
    rb_lanes2 inv_k11, inv_k12, inv_k22; /* kg, its inverse */
    int constraints[2];                  /* indices in world->constraints */
};

/* Builds one constraint per touching, non-sensor contact that has a
 * dynamic body, fixing each point's surface points in the bodies' frames;
 * carries the impulses of the last step if warm starting. The constraints
 * are laid out colour by colour (constraint_colouring.h); for the soft
 * step, the blocks are laid out in the same pass (rb_contact_blocks_build).
 * Returns how many, or -1 when out of memory. */
int rb_contact_solver_prepare(rb_world *world);
/* Fills constraint c from contact `index` at the poses now: all but what
 * rb_contact_solver_prepare_points_range prepares. */
void rb_contact_solver_fill_constraint(rb_world *world, int index, rb_contact_constraint *c);

/* A manifold point's two surface points, half the separation either
 * side of it along the normal (a circle side keeps its centre instead,
 * `radius` further), in the frames of the bodies at sa and sb, from their
 * centres of mass: what a constraint keeps of the point
 * (rb_contact_solver_fill_constraint, and the blocks' lanes,
 * contact_blocks.c). */
static inline void rb_contact_local_surfaces(const rb_manifold_point *mp, rb_vec2 normal, double radius_a,
                                             double radius_b, const rb_body_state *sa, const rb_body_state *sb,
                                             rb_vec2 *local_a, rb_vec2 *local_b)
{
    rb_vec2 surface_a = rb_mul_sub(mp->point, 0.5 * mp->separation + radius_a, normal);
    rb_vec2 surface_b = rb_mul_add(mp->point, 0.5 * mp->separation + radius_b, normal);
    *local_a = rb_inv_rotate(sa->rotation, rb_sub(surface_a, sa->center));
    *local_b = rb_inv_rotate(sb->rotation, rb_sub(surface_b, sb->center));
}
/* What a solver asks of rb_contact_solver_prepare_substep. */
typedef struct rb_substep_rows {
    /* the step's first substep: every point of a contact with restitution
     * records its impact speed anew; in later substeps only those that
     * have not pushed yet (contact_solver.c, record_approaches) */
    bool first_substep;
    /* the normal velocity's lower bound pushes overlap beyond the slop
     * out (Baumgarte) */
    bool baumgarte_bias;
    /* two-point manifolds get the 2x2 normal mass matrix and its inverse
     * when well conditioned (the sequential solvers' block solve), and
     * then no per-point normal masses */
    bool block_normals;
} rb_substep_rows;

/* At the start of a substep of length h: the anchors, normal and
 * effective masses at the poses now, the separations, and from them each
 * point's lower bound on its normal velocity for the sequential solvers. */
void rb_contact_solver_prepare_substep(rb_world *world, double h, rb_substep_rows rows);
/* Its part for each point (anchors, lever arms, masses, bounds), two
 * contacts at a time where the processor allows (contact_solver_wide.c),
 * the others by rb_contact_solver_prepare_points_range, the reference, one
 * at a time over constraints begin .. end - 1 (contact_solver.c). Where
 * the processor allows, the pairs of one colour that fit a row are
 * prepared into the rows (world->contact_rows), not their constraints,
 * the impulses first given back from the last substep's rows. */
void rb_contact_solver_prepare_points(rb_world *world, double h, rb_substep_rows rows);
void rb_contact_solver_prepare_points_range(rb_world *world, double h, rb_substep_rows rows, int begin, int end);
/* The warm start: over the rows, two contacts at a time, and the other
 * constraints one at a time, colour by colour, where the substep's
 * preparation laid out rows (contact_rows_two.c); else the reference. */
void rb_contact_solver_warm_start(rb_world *world);
/* What rb_contact_solver_warm_start does, over the constraints begin ..
 * end - 1: the reference the blocks' warm start agrees with. */
void rb_contact_solver_warm_start_range(rb_world *world, int begin, int end);
/* One pass of sequential impulses at the substep's bounds (Baumgarte,
 * NGS), over the colours in order or, `backwards`, in reverse. NGS
 * alternates: its velocity passes carry no bias, and without the
 * alternation the base-100 pyramid spreads (928 boxes moved more than
 * 0.25 m in 6 s, none with it). Baumgarte's passes carry a push-out bias
 * and sweep forward only: alternated, the pyramid blew apart (measured,
 * as for the soft step, solver_soft_step.c). */
void rb_contact_solver_solve_velocities(rb_world *world, bool backwards);
/* That pass one constraint at a time over constraints begin .. end - 1,
 * in order or, `backwards`, in reverse: the reference
 * (contact_solver.c). rb_contact_solver_solve_velocities takes the rows,
 * where the preparation laid them out, two contacts at a time, and runs
 * this on the other constraints (contact_rows_two.c); without rows, this
 * over them all. */
void rb_contact_solver_solve_velocities_range(rb_world *world, bool backwards, int begin, int end);
/* Gives the rows' impulses back to their constraints and leaves the rows
 * unused until the next preparation lays them out again. */
void rb_contact_rows_store_impulses(rb_world *world);
/* The impulses of rows begin .. end - 1 given back to their constraints,
 * the rows left as they are. */
void rb_contact_rows_store_range(rb_world *world, int begin, int end);
void rb_contact_rows_free(rb_contact_rows *rows);
size_t rb_contact_rows_bytes(const rb_contact_rows *rows);

/* How the soft step's contacts answer overlap in one pass
 * (solver_soft_step.c). */
typedef struct rb_contact_softness {
    rb_rigid_response between_moving; /* both bodies can move */
    rb_rigid_response against_fixed;  /* one body cannot move (static, kinematic or asleep) */
    double max_push_speed;            /* m/s, > 0 */
    double linear_slop;               /* m, overlap left alone */
    double inv_h;                     /* 1/s, of the substep */
    bool use_bias;                    /* false in the relax pass: stop approach, push nothing */
    bool write_back;                  /* the step's last pass: each block's impulses into its manifolds */
    bool measure_overlap;             /* and, after the last positions, its deepest overlap (rb_contact_batches) */
} rb_contact_softness;
/* The soft step's contacts several at a time (contact_blocks.c). The
 * two-point contacts of each colour are laid four by four into blocks
 * (world->contact_batches) as rb_contact_solver_prepare makes the other
 * constraints (a block's contact has none); rb_contact_solver_prepare_singles then prepares the
 * points of the other constraints (those with one point, with
 * restitution, or in the overflow colour), which stay where they are and
 * are solved one at a time, and the step's first warm start prepares the
 * blocks' points. From then on the blocks hold those impulses (the soft
 * pass with `write_back` writes them into the contacts' manifolds, not
 * the constraints), and only the passes below may be run on the
 * contacts. */
void rb_contact_solver_prepare_singles(rb_world *world, double h);
/* The constraints the blocks do not hold, the only ones filled (the
 * blocks' lanes hold the others' contacts): k-th of
 * rb_contact_solver_loose_count, in the order of their indices. After a
 * soft step's rb_contact_solver_prepare, its singles and then the
 * overflow colour's; after the others' (no blocks), every constraint. */
static inline int rb_contact_solver_loose_count(const rb_world *world)
{
    const rb_contact_batches *batches = &world->contact_batches;
    return batches->single_count + world->constraint_count - batches->overflow_start;
}
static inline int rb_contact_solver_loose_constraint(const rb_world *world, int k)
{
    const rb_contact_batches *batches = &world->contact_batches;
    return k < batches->single_count ? batches->singles[k] : batches->overflow_start + (k - batches->single_count);
}
/* The warm start over the batches: rb_contact_solver_warm_start's result.
 * With `prepare` (the step's first), each block's points are first
 * prepared at the poses now, as rb_contact_solver_prepare_points_range
 * prepares a constraint's. */
void rb_contact_solver_warm_start_blocks(rb_world *world, bool prepare);
void rb_contact_batches_free(rb_contact_batches *batches);
size_t rb_contact_batches_bytes(const rb_contact_batches *batches);
/* For the restitution of the constraints that bounce, at the step's
 * start: what rb_contact_solver_prepare_substep records in the first
 * substep (contact_solver.c). */
void rb_contact_solver_record_approaches(rb_world *world, double h);

/* One pass of soft contacts, over the batches rb_contact_solver_prepare
 * laid out. The anchors, normal and masses stay as they were prepared at
 * the start of the step; each point's separation is measured anew from the poses now, so a pass
 * after the positions moved sees the gap they left. The two-point
 * contacts of a colour four or two at a time (contact_blocks.c), the
 * others one at a time by rb_contact_solver_solve_soft_range. With
 * softness->write_back (the step's last pass), each block's impulses go
 * straight into its contacts' manifolds as soon as the block is solved,
 * while it is in the cache (the blocks' contacts have no constraint that
 * could hold them). With softness->measure_overlap too (a last pass after
 * the last positions), the pass also measures the blocks' deepest
 * overlap, which rb_contact_solver_store_impulses then takes instead of
 * measuring the lanes again (rb_contact_blocks_deepest_overlap). */
void rb_contact_solver_solve_soft(rb_world *world, const rb_contact_softness *softness);
/* The same pass, one contact at a time, over constraints begin .. end - 1
 * (contact_solver.c): the reference the blocks' pass agrees with. */
void rb_contact_solver_solve_soft_range(rb_world *world, const rb_contact_softness *softness, int begin, int end);
/* One non-linear Gauss-Seidel pass over the contacts; returns whether no
 * point was deeper than the tolerance before it. */
bool rb_contact_solver_correct_positions(rb_world *world);
/* The pass's work on constraint `index` alone, the reference: its points
 * measured and corrected in turn, *deepest (m, <= 0) lowered by each
 * point's separation before its correction. Returns whether a correction
 * moved the bodies. */
bool rb_contact_solver_correct_contact_positions(rb_world *world, int index, double *deepest);
/* The first constraint from `begin` on that the pass above must measure
 * and correct one at a time: those before it (runs of two-point
 * contacts, two at a time where the processor allows) need no correction
 * at the poses now, and their separations (m, < 0 overlapping) have
 * lowered *deepest as the one-at-a-time pass would have
 * (contact_positions_wide.c). Returns `begin` when it cannot tell. */
int rb_contact_solver_skip_resting(const rb_world *world, int begin, double *deepest);
void rb_contact_solver_apply_restitution(rb_world *world, double h);
/* Writes the impulses back to the manifolds for the next step; returns
 * the deepest penetration left (m, >= 0). */
double rb_contact_solver_store_impulses(rb_world *world);

#endif
