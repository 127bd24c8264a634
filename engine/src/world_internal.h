/* SPDX-License-Identifier: MIT */
/* The world's private data: object pools, contacts, solver scratch. The
 * per-body data the solver touches every iteration (velocities and pose)
 * lives apart from the rest in a compact `states` array, indexed like
 * `bodies`, so the hot loops stream through 64 bytes per body. */
#ifndef RB_WORLD_INTERNAL_H
#define RB_WORLD_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "constraint_colouring.h"
#include "rb/body.h"
#include "rb/cable.h"
#include "rb/collision.h"
#include "rb/events.h"
#include "rb/joint.h"
#include "rb/shape.h"
#include "rb/world.h"

/* Manifold points are reported this many linear slops before the shapes
 * touch, so resting contacts stay in the solver without flickering. */
#define RB_SPECULATIVE_SLOPS 4.0

/* m: how far a shape's fat box reaches beyond its swept box in the broad
 * phase (as Box2D's aabbMargin): the pairs are found anew only when a
 * shape has moved about this far since they were last found. */
#define RB_FAT_MARGIN 0.1

/* A slot whose object of this generation is destroyed goes out of use
 * for good rather than to its free list, so that its generation never
 * wraps to one an old id still carries (id.h). */
#define RB_RETIRED_GENERATION UINT32_MAX

typedef struct rb_body_state {
    rb_vec2 linear_velocity; /* m/s, of the centre of mass */
    double angular_velocity; /* rad/s */
    rb_vec2 center;          /* m, world centre of mass */
    rb_rot rotation;         /* cos and sin of `angle` */
    double angle;            /* rad, continuous */
} rb_body_state;

/* Turns the pose by `delta` rad. A solver turns each body many times a
 * step by small angles (every position pass, every substep), and
 * cos/sin of the new angle each time cost a tenth of a joint grid's
 * step: the rotation is instead composed with the rotation by delta,
 * whose cosine and sine come from their Taylor series while |delta| <=
 * 1/32 rad (the first term left out is below 1e-19 there, so the product
 * is as exact as cos and sin would be, to a rounding). The world
 * recomputes every rotation from its angle at the end of each step, so
 * the roundings never accumulate beyond one step. */
static inline void rb_body_state_turn(rb_body_state *state, double delta)
{
    state->angle += delta;
    if (!(fabs(delta) <= 0.03125)) {
        state->rotation = rb_rot_from_angle(state->angle);
        return;
    }
    /* Horner's form, the divisions by constants written as products (a
     * division costs ten products, and the compiler may not swap one for
     * the other itself). */
    double d2 = delta * delta;
    double sine = delta * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0) * (1.0 - d2 * (1.0 / 42.0))));
    double cosine = 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12.0) * (1.0 - d2 * (1.0 / 30.0) * (1.0 - d2 * (1.0 / 56.0))));
    state->rotation = rb_mul_rot(state->rotation, (rb_rot){cosine, sine});
}

typedef struct rb_body {
    int next_free;       /* free-list link while the slot is unused */
    uint32_t generation; /* of the last object made in the slot; RB_RETIRED_GENERATION retires it */
    bool in_use;
    rb_body_type type;
    rb_vec2 local_center;        /* m, centre of mass in the body frame */
    rb_vec2 force;               /* N, accumulated for the next step */
    double torque;               /* N·m, accumulated for the next step */
    double mass, inv_mass;       /* kg, 1/kg; 0 for static and kinematic bodies */
    double inertia, inv_inertia; /* kg·m², about the centre of mass */
    bool has_mass_override;
    rb_mass_data mass_override;
    double linear_damping, angular_damping, gravity_scale;
    bool fixed_rotation, awake, bullet;
    bool enable_sleep;
    double sleep_time; /* s the body has been slower than the sleep tolerances (sleep.c) */
    void *user_data;
    int first_shape; /* -1 when none; shapes link through rb_shape.next_in_body */
    int shape_count;
    int first_joint; /* -1 when none; joints link through rb_joint.next_on_a / next_on_b */
} rb_body;

/* A body the step moves (awake, not static), with what its integration
 * reads, listed once a step (solver.c): the substeps' integration passes
 * then read these instead of every slot of world->bodies. */
typedef struct rb_moving_body {
    int index;                              /* in world->bodies and world->states */
    rb_vec2 acceleration;                   /* m/s², gravity times the body's scale plus force over mass */
    double inv_inertia, torque;             /* 1/(kg·m²), N·m */
    double linear_damping, angular_damping; /* 1/s, >= 0 */
} rb_moving_body;

typedef struct rb_shape {
    int next_free;
    uint32_t generation; /* of the last object made in the slot; RB_RETIRED_GENERATION retires it */
    bool in_use;
    int body;
    int next_in_body;
    rb_shape_type type;
    bool box; /* a polygon on an axis-aligned rectangle of its frame (rb_polygon_is_box), found once */
    union {
        rb_circle circle;
        rb_polygon polygon;
        rb_segment segment;
        rb_chain_segment chain_segment;
    } geometry;
    double friction, restitution, density;
    bool sensor;
    rb_filter filter;
    void *user_data;
    double extent;    /* m, farthest point of the shape from the body's centre of mass */
    rb_aabb aabb;     /* m, broad phase: the box swept over the step and grown by the speculative margin */
    rb_aabb fat_aabb; /* m, broad phase: a box around `aabb`, kept while `aabb` stays inside it */
    /* broad phase, within a step: 0, or 1 + the index in world->refits of
     * the record of its old fat box once `fat_aabb` was made anew */
    int refit_slot;
} rb_shape;

/* A pair of shapes whose fat boxes overlap. Contacts are kept sorted by
 * (body_key, shape_key): the lower body index first, so the solver meets
 * them in the same order on every run. */
typedef struct rb_pair {
    uint64_t body_key;
    uint64_t shape_key;
    int shape_a, shape_b; /* shape_a belongs to the body of lower index */
} rb_pair;

/* A shape in the broad phase's sorted sweep, with a copy of its box: the
 * sweep compares each box with its neighbours in x, and reading them from
 * this array in order instead of from the shapes (scattered, 300 bytes
 * apart) took a sixth off the pairs phase of the base-100 pyramid. */
struct rb_sweep_entry {
    rb_aabb box; /* m, the shape's fat box */
    int shape;
};

/* A shape whose swept box left its fat box in this step: its new fat box
 * is the shape's, the old one is kept here to tell which of its pairs
 * begin and which end. */
struct rb_refit {
    int shape;
    rb_aabb old_box; /* m, the fat box it had before */
};

typedef struct rb_contact {
    rb_pair pair;
    int body_a, body_b;
    rb_manifold manifold;
    double friction, restitution; /* mixed from the two shapes */
    bool sensor;
    bool touching;
    bool reported_touching; /* the state the last begin or end event told */
    int colour;             /* the solver's colour in this step; -1 when not solved */
} rb_contact;

/* The events of the last step, and the end events of shapes destroyed
 * since, which join the next step's (so the published arrays never move
 * between steps). */
typedef struct rb_event_arrays {
    rb_contact_begin_event *begins;
    int begin_count, begin_capacity;
    rb_contact_end_event *ends;
    int end_count, end_capacity;
    rb_sensor_event *sensor_begins;
    int sensor_begin_count, sensor_begin_capacity;
    rb_sensor_event *sensor_ends;
    int sensor_end_count, sensor_end_capacity;
    rb_contact_end_event *pending_ends;
    int pending_end_count, pending_end_capacity;
    rb_sensor_event *pending_sensor_ends;
    int pending_sensor_end_count, pending_sensor_end_capacity;
} rb_event_arrays;

/* Which joints the passes visit by depth and colour (joint_order.c). */
typedef enum rb_joint_order_scope {
    RB_ORDER_EVERY_JOINT, /* the soft step */
    RB_ORDER_PLAIN_PINS,  /* NGS and Baumgarte: the other joints first, as they were made */
} rb_joint_order_scope;

typedef struct rb_contact_constraint rb_contact_constraint;
typedef struct rb_contact_block rb_contact_block;           /* contact_solver.h */
typedef struct rb_contact_block_tail rb_contact_block_tail; /* contact_solver.h */

/* The soft step's contacts as its passes take them, colour by colour:
 * blocks of two-point constraints solved several at a time, and the
 * colour's other constraints one at a time (rb_contact_blocks_build,
 * contact_blocks.c). */
typedef struct rb_contact_batches {
    rb_contact_block *blocks;
    rb_contact_block_tail *tails; /* block k's tail is tails[k] */
    int block_count, block_capacity, tail_capacity;
    int *singles; /* indices in world->constraints */
    int single_count, single_capacity;
    int block_start[RB_COLOUR_COUNT + 1];  /* colour k's blocks start here; the last entry is block_count */
    int single_start[RB_COLOUR_COUNT + 1]; /* and its singles here */
    int overflow_start;                    /* the overflow colour's constraints, in world->constraints */
    rb_body_state idle_a, idle_b;          /* the bodies of a block's empty lanes: at rest, at the origin */
    int width;                             /* contacts solved by one vector operation: 4 or 2 (contact_blocks.h) */
    int lanes[RB_COLOUR_COUNT + 1];        /* colour k's contacts that take a lane of a block */
    /* The deepest overlap of the blocks' contacts at the step's final
     * poses, measured by its last pass when that pass came after the
     * positions moved (a relax pass), for rb_contact_solver_store_impulses. */
    bool overlap_measured;
    double deepest_overlap; /* m, >= 0 */
} rb_contact_batches;

typedef struct rb_contact_row rb_contact_row; /* contact_solver.h */

/* Constraints begin .. end - 1 of world->constraints. */
typedef struct rb_constraint_run {
    int begin, end;
} rb_constraint_run;

/* The sequential solvers' (NGS's, Baumgarte's) contacts as their warm
 * start and velocity passes take them, colour by colour: rows of two
 * two-point contacts solved side by side, and the colour's other
 * constraints one at a time (contact_rows_two.c). Laid out again by each
 * substep's preparation (contact_solver_wide.c). */
typedef struct rb_contact_rows {
    rb_contact_row *rows;
    int row_count, row_capacity;
    /* the other constraints, solved one at a time, as runs of neighbours */
    rb_constraint_run *runs;
    int run_count, run_capacity;
    /* colour k's constraints begin at colour_start[k] in world->constraints,
     * the overflow colour's (k = RB_COLOUR_COUNT) last; the last entry is
     * the constraint count */
    int colour_start[RB_COLOUR_COUNT + 2];
    int colour_count;                   /* colours 0 .. colour_count - 1 hold every constraint */
    int row_start[RB_COLOUR_COUNT + 2]; /* colour k's rows begin here; entry colour_count is row_count */
    int run_start[RB_COLOUR_COUNT + 2]; /* and its runs here */
    /* the rows hold their contacts' impulses, which their constraints
     * get back from rb_contact_rows_store_impulses */
    bool live;
} rb_contact_rows;

/* A symmetric 3x3 block K = J·M⁻¹·Jᵀ of three of a joint's rows, whose
 * upper-left 2x2 is solved alone when the third row is not active
 * (joint_solver.h). */
typedef struct rb_block_matrix {
    double k11, k12, k22, k13, k23, k33;
} rb_block_matrix;

/* How a joint's rigid row answers its position error C in the current
 * pass, as the solver sets it (solver_*.c): the row's impulse is
 *   λ = -mass_scale·m·(Cdot + bias_rate·C) - impulse_scale·λ_accumulated
 * with m the row's effective mass. Rigid rows without position feedback
 * (NGS, and the soft step's relax pass) have {0, 1, 0}; a Baumgarte bias
 * {β/dt, 1, 0}; a soft step's spring the coefficients of
 * rb_make_rigid_softness (joint_solver.h). */
typedef struct rb_rigid_response {
    double bias_rate;     /* 1/s */
    double mass_scale;    /* 0 .. 1 */
    double impulse_scale; /* 0 .. 1 */
} rb_rigid_response;

/* The parts of a joint's solver state shared by every type: the masses
 * and the anchors in the body frames prepared once per step, the rest at
 * the start of each substep. The fields every velocity pass of a pin
 * reads come first, in two cache lines; the ones only the preparation and
 * the limits' and welds' 3x3 blocks read after them. */

typedef struct rb_joint_frame {
    double inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b; /* 0 for a body that cannot move */
    rb_vec2 ra, rb; /* m, anchors relative to each centre of mass, turned into the world now */
    /* Pins and welds only, fixed for the substep: the inverse of the
     * upper-left 2x2 of K (rb_point_block; the pin alone), or all 0 when that is
     * singular: every pass of a pin multiplies by it, where solving the
     * 2x2 anew took two divisions each time. */
    double point_inverse11, point_inverse12, point_inverse22;
    rb_vec2 point_drift;      /* m/s, the anchors' centripetal drift over the substep (joint_point.c) */
    rb_vec2 local_a, local_b; /* m, the anchors relative to each centre of mass, in the body frames */
} rb_joint_frame;

/* What a pin solved with an angular row (a limit, a rigid weld's angle)
 * holds fixed for the substep (joint_point.c): the point constraint's K
 * at ra, rb, and K's cofactors and determinant. The world keeps one per
 * joint slot beside the joints (rb_world.point_blocks), not in them: the
 * plain pins of a large grid never read it, and a pass streams every
 * byte of a joint through the caches. */
typedef struct rb_point_block {
    rb_block_matrix mass;
    double det;                             /* of K with its angular row */
    double inverse11, inverse12, inverse13; /* K⁻¹ (symmetric) when det is not 0 */
    double inverse22, inverse23, inverse33;
    /* 1/c33 when c33 > 0, else 0: c33 = k11·k22 - k12² is also the pin
     * alone's determinant, which a limit that lets go solves with. */
    double c33, inverse_c33;
} rb_point_block;

/* A plain pin (a revolute joint with no limit, motor or spring, which no
 * tree solves) as the solver's passes read it: the fields of its
 * rb_joint_frame that the velocity passes read, its bodies and its
 * impulse, 128 bytes. A dense array of them is gathered once a step, in
 * the order of the active joints; every phase of every substep reads and
 * writes the rows alone, and the impulses go back to the joints once, at
 * the end of the step (joint_pin.c). A pass over the 100 x 100 joint
 * grid then streams 128 bytes a pin where it read the first 184 of each
 * 344-byte joint. */
typedef struct rb_pin_row {
    int body_a, body_b;
    double inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
    rb_vec2 ra, rb;
    double point_inverse11, point_inverse12, point_inverse22;
    rb_vec2 point_drift;
    rb_vec2 impulse; /* N·s, accumulated; the joint's point_impulse while the step runs */
} rb_pin_row;

/* A joint of the velocity passes, with what its visit needs found once
 * a step: a plain pin's row, or NULL (joint.c). Both stay put while the
 * step runs, as no joint is made or destroyed. */
typedef struct rb_velocity_visit {
    struct rb_joint *joint;
    rb_pin_row *row;
} rb_velocity_visit;

/* A pin row's anchors in the body frames, which only the preparation
 * and the position passes read: kept beside the rows, not in them. */
typedef struct rb_pin_anchors {
    rb_vec2 local_a, local_b;
} rb_pin_anchors;

typedef struct rb_revolute_data {
    /* What every pass of a plain pin reads, first: */
    bool enable_lower, enable_upper, enable_motor, enable_spring;
    double axial_mass;     /* kg·m², 1/(1/IA + 1/IB) */
    rb_vec2 point_impulse; /* N·s, accumulated */
    double reference_angle;
    double lower, upper;
    double motor_speed, max_motor_torque;
    double spring_hertz, spring_damping_ratio;
    double motor_impulse, lower_impulse, upper_impulse, spring_impulse;
} rb_revolute_data;

typedef struct rb_weld_data {
    double reference_angle;
    double linear_hertz, linear_damping_ratio, angular_hertz, angular_damping_ratio;
    rb_vec2 point_impulse;
    double angular_impulse;
    double axial_mass;
} rb_weld_data;

typedef struct rb_distance_data {
    double length;
    bool enable_spring;
    double spring_hertz, spring_damping_ratio;
    bool enable_limit;
    double min_length, max_length;
    rb_vec2 axis; /* unit, from anchor A to anchor B, this substep */
    double current_length;
    double axial_mass; /* kg, effective mass along the axis */
    double impulse, lower_impulse, upper_impulse;
} rb_distance_data;

typedef struct rb_mouse_data {
    rb_vec2 target;
    double max_force, hertz, damping_ratio;
    rb_vec2 impulse;
} rb_mouse_data;

/* A prismatic joint and a pulley keep no per-substep rows: they compute
 * them from the frame when solved, which keeps their data no larger than
 * the revolute's and the joint array's stride as it was. */
typedef struct rb_prismatic_data {
    rb_vec2 local_axis_a; /* unit, in body A's frame */
    double reference_angle;
    double lower, upper; /* m */
    double motor_speed, max_motor_force;
    double spring_hertz, spring_damping_ratio;
    rb_vec2 impulse; /* accumulated: x across the axis (N·s), y about it (N·m·s) */
    double motor_impulse, spring_impulse, lower_impulse, upper_impulse; /* N·s along the axis */
    bool enable_lower, enable_upper, enable_motor, enable_spring;
} rb_prismatic_data;

typedef struct rb_pulley_data {
    rb_vec2 ground_a, ground_b; /* m, world */
    double ratio;
    double constant;                                /* m, length_a + ratio·length_b when taut */
    double min_length;                              /* m, where a body meets its pulley */
    double impulse, stop_a_impulse, stop_b_impulse; /* N·s, >= 0 */
} rb_pulley_data;

/* A body's share of a cable's unit tension this substep: the direction
 * of the impulse on it and, when the impulse moves it, the velocity a
 * unit impulse gives it. */
typedef struct rb_cable_share {
    /* The body's state: the passes reach it without an index, and the
     * states do not move within a step (no body is made in one). */
    rb_body_state *state;
    rb_vec2 linear;      /* Σ (u_i - u_{i-1}) over the body's points */
    double angular;      /* m, Σ r_i × (u_i - u_{i-1}) */
    rb_vec2 push_linear; /* 1/kg: linear · inverse mass, 0 when the impulse does not move the body */
    double push_angular; /* 1/(kg·m): angular · inverse inertia, likewise */
} rb_cable_share;

/* A cable and, per substep, the direction of a unit tension's impulse on
 * each distinct body of its path. */
typedef struct rb_cable {
    int next_free;
    uint32_t generation; /* of the last object made in the slot; RB_RETIRED_GENERATION retires it */
    bool in_use;
    int point_count;
    int bodies[RB_MAX_CABLE_POINTS];
    rb_vec2 local_points[RB_MAX_CABLE_POINTS]; /* m, from each body's origin */
    rb_vec2
        from_centers[RB_MAX_CABLE_POINTS]; /* m, from each body's centre of mass, this step (rb_cables_prepare_step) */
    void *user_data;
    double base_tension;                 /* N */
    double damping;                      /* N·s/m */
    double impulse;                      /* N·s, accumulated in the current substep */
    rb_vec2 points[RB_MAX_CABLE_POINTS]; /* m, the path in the world at the substep's start (rb_cables_locate) */
    double segment_lengths[RB_MAX_CABLE_POINTS - 1]; /* m, from point i to i + 1, located with the points */
    int body_count;                        /* the path's distinct bodies, in the order of their first points: */
    int path_bodies[RB_MAX_CABLE_POINTS];  /* their slots, fixed at creation */
    int point_places[RB_MAX_CABLE_POINTS]; /* each point's body's place in path_bodies */
    /* This substep: the shares of the path's bodies that are not static
     * (a static body's velocity is 0 and an impulse moves nothing), in
     * path order, and of those, the ones an impulse moves. */
    int share_count;
    rb_cable_share shares[RB_MAX_CABLE_POINTS];
    int moving_count;
    rb_cable_share moving[RB_MAX_CABLE_POINTS]; /* copies of those shares, which the passes push in turn */
    double inverse_mass;                        /* 1/kg: how fast a unit impulse shortens the path */
    /* The implicit law's gains this substep (rb_cables_solve): the
     * impulse is speed_gain·L' + base_impulse + impulse_gain·P_acc. */
    double speed_gain;   /* kg: h·c / (1 + h·c·k) */
    double base_impulse; /* N·s: h·T0 / (1 + h·c·k) */
    double impulse_gain; /* h·c·k / (1 + h·c·k) */
    bool in_block;       /* this substep, its law is a row of a limb block (joint_block.h), not a pass of its own */
} rb_cable;

/* Ordered by use: what every velocity pass and every walk over the slots
 * reads (the type, whether in use, the bodies, the frame's first fields,
 * the type's first fields) in the first lines,
 * the bookkeeping of the pool and the bodies' lists last. */
typedef struct rb_joint {
    rb_joint_type type;
    bool in_use;    /* read first by every walk over the slots (the islands, the statistics) */
    bool in_tree;   /* this step, a pin solved with its tree (joint_tree.h) */
    bool in_block;  /* this substep, a pin and its limits solved with its block (joint_block.h) */
    bool plain_pin; /* this step, a revolute joint with no limit, motor or spring: the point constraint alone */
    int body_a;     /* -1 for a mouse joint */
    int body_b;
    uint32_t generation; /* of the last object made in the slot; RB_RETIRED_GENERATION retires it */
    rb_joint_frame frame;
    union {
        rb_revolute_data revolute;
        rb_weld_data weld;
        rb_distance_data distance;
        rb_mouse_data mouse;
        rb_prismatic_data prismatic;
        rb_pulley_data pulley;
    } as;
    rb_vec2 local_anchor_a, local_anchor_b; /* m, from each body's origin, in its frame */
    int next_on_a, next_on_b;               /* the next joint in body A's and body B's lists */
    int next_free;
    bool collide_connected;
    void *user_data;
} rb_joint;

/* A node of the pins' trees (joint_tree.h): a body or a pin. */
typedef struct rb_tree_node {
    int body;                     /* body slot, or -1 for a pin */
    int joint;                    /* joint slot, or -1 for a body */
    int parent;                   /* node index, -1 for a root */
    int dim;                      /* 3 for a body (vx, vy, ω), 2 for a pin (its impulse) */
    bool edge_on_b;               /* the edge to the parent joins a pin to its body B (else to its body A) */
    double pivot[6];              /* D(node), dim × dim, summed from its children: the upper triangle, row by row */
    double dinv[6];               /* D(node)⁻¹, likewise */
    double x[6];                  /* D(node)⁻¹·H(node, parent) */
    double value[3];              /* the right-hand side, then the solution */
    double mass, inertia;         /* a body's, kg and kg·m²: its pivot before its children's */
    double inv_mass, inv_inertia; /* a body's, 1/kg and 1/(kg·m²) */
    rb_vec2 ra, rb;               /* a pin's anchor offsets (m) at the poses the nodes were factored at */
} rb_tree_node;

/* What the trees were found from, one per active joint (joint_tree.c,
 * found_from_the_same): the joint's slot and generation (a joint
 * destroyed and another made in its slot differ), its bodies, and what
 * makes it a pin of a tree or a row of its own. */
typedef struct rb_tree_key {
    int joint;           /* slot */
    uint32_t generation; /* of the joint in the slot */
    int body_a, body_b;
    rb_joint_type type;
    bool in_block, plain_pin, enable_lower, enable_upper;
    double inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b; /* the frame's: 0 for a body that cannot move */
} rb_tree_key;

/* The pins solved together this step, with the arrays the search for
 * them reuses from step to step. */
typedef struct rb_joint_tree {
    bool enabled;          /* set by the solvers that use it (NGS, soft step) */
    bool velocity_factors; /* the nodes hold this substep's velocity factors */
    bool pose_factors;     /* the nodes hold factors at the bodies' current poses */
    bool alone;            /* this step, no row outside the trees acts on a body in them */
    bool solved;           /* this substep's velocity pass has solved the trees */
    bool cold;             /* this substep's pins were not warm started: their velocity errors are read */
    bool chains;           /* every tree is a chain from a pin to a fixed body (joint_chain.h) */
    rb_tree_node *nodes;   /* breadth first from each root: a parent before its children */
    int node_count, node_capacity;
    int *body_node; /* per body slot: its node, or -1 */
    int body_node_capacity;
    int *union_parent; /* per body slot: union-find of the bodies the trees link */
    int union_capacity;
    unsigned char *grounded; /* per union root: the tree already holds a pin to a fixed body */
    int grounded_capacity;
    double *mass_range; /* per union root: its lightest and heaviest body's mass, kg */
    int mass_range_capacity;
    /* While there are nodes: this step's active joints less the plain
     * pins the trees solve, the joints the Gauss-Seidel passes visit. */
    int *gauss_seidel_joints;
    int gauss_seidel_count, gauss_seidel_capacity;
    /* The trees are kept from step to step while they would be found
     * the same: found is set once they are found and keys recorded, with
     * the world's body slots, the solver's mass ratio and enabled then. */
    bool found;
    unsigned finds; /* how many times the trees were looked for anew */
    rb_tree_key *keys;
    int key_count, key_capacity;
    int found_body_slots;
    double found_ratio;
    bool found_enabled;
} rb_joint_tree;

/* The small limbs solved as one dense system (joint_block.h). */
#define RB_BLOCK_MAX_BODIES 4
#define RB_BLOCK_MAX_JOINTS 4
#define RB_BLOCK_MAX_CABLES 8 /* further cables on a block's bodies are left to their own passes */
/* two pin rows and one limit a joint, and a row a cable */
#define RB_BLOCK_MAX_ROWS (3 * RB_BLOCK_MAX_JOINTS + RB_BLOCK_MAX_CABLES)
#define RB_MAX_JOINT_BLOCKS 4 /* further blocks are left to Gauss-Seidel */

/* One row of a block: J·v + bias + compliance·P = 0, P its accumulated
 * impulse, kept in the joint or the cable. */
typedef struct rb_block_row {
    int slot_a, slot_b;  /* the bodies' places in the block; RB_BLOCK_MAX_BODIES for a fixed body */
    double ja[3], jb[3]; /* the Jacobian on A and on B: (vx, vy, ω) */
    double wa[3], wb[3]; /* M⁻¹·Jᵀ: the velocity change of a unit impulse on A and on B */
    double bias;         /* m/s or rad/s */
    double compliance;   /* 1/kg or 1/(kg·m²): 0 for a joint's rigid row, 1/(h·c) for a cable's */
    double *accumulated; /* the joint's or the cable's impulse of this row, N·s or N·m·s */
    bool one_sided;      /* a limit or a cable: its accumulated impulse stays >= 0 */
} rb_block_row;

typedef struct rb_joint_block {
    int body_count, joint_count, row_count;
    int pin_rows;                          /* the pins' rows, first */
    int cable_rows;                        /* the cables' rows, after the pins' and before the limits' */
    rb_cable *cables[RB_BLOCK_MAX_CABLES]; /* this substep, the cables of those rows, in their order */
    bool touched;                          /* this step, a contact acts on one of its bodies */
    /* This substep, nothing outside the block acts on its bodies: no
     * contact, and no damped cable that is not one of its rows. */
    bool closed;
    /* This substep, the last pass released no row: it solved the block
     * exactly, and a closed block's bodies keep those velocities through
     * the later passes, which skip it (joint_block.h). */
    bool settled;
    int bodies[RB_BLOCK_MAX_BODIES];  /* body slots */
    int joints[RB_BLOCK_MAX_JOINTS];  /* joint slots */
    int ends[RB_BLOCK_MAX_JOINTS][2]; /* each joint's bodies' places (A, B), as rb_block_row's */
    /* 1/kg, 1/(kg·m²); the last place stands for every fixed body, 0. */
    double inv_mass[RB_BLOCK_MAX_BODIES + 1], inv_inertia[RB_BLOCK_MAX_BODIES + 1];
    rb_block_row rows[RB_BLOCK_MAX_ROWS];
    /* Row i's envelope in K: the first row it shares a moving body with
     * (i when none before it); L·D·Lᵀ fills in nothing before it. */
    int first[RB_BLOCK_MAX_ROWS];
    double k[RB_BLOCK_MAX_ROWS * RB_BLOCK_MAX_ROWS];      /* J·M⁻¹·Jᵀ: its lower triangle within the envelopes */
    double factor[RB_BLOCK_MAX_ROWS * RB_BLOCK_MAX_ROWS]; /* its L·D·Lᵀ: L below the diagonal, 1/D on it */
    bool factored;                                        /* false: Gauss-Seidel solves it this substep */
    /* Factors made at an earlier substep may serve the next: this place
     * held a block then, and none of the solves with them has missed
     * RB_BLOCK_KEPT_RESIDUAL since (joint_block.h). */
    bool keep_factors;
    /* This substep solves with an earlier substep's factors, made for the
     * same rows (their impulses' addresses, factored_rows), and each pass
     * checks its solve against the rows made now. */
    bool kept;
    bool missed; /* this step, a solve with kept factors missed: its later substeps factor */
    int factored_row_count;
    uintptr_t factored_rows[RB_BLOCK_MAX_ROWS];
} rb_joint_block;

typedef struct rb_joint_blocks {
    int count;
    rb_joint_block blocks[RB_MAX_JOINT_BLOCKS];
} rb_joint_blocks;

struct rb_world {
    uint64_t serial;          /* never 0, never reused (id.h) */
    bool locked;              /* inside rb_world_step */
    bool in_substep_callback; /* inside the user's substep callback, which may set cable laws */
    rb_substep_fn *substep_callback;
    void *substep_context;
    bool profiling; /* time the phases of the step */
    bool enable_sleep;
    rb_vec2 gravity;
    rb_solver_settings settings;

    rb_body *bodies;
    rb_body_state *states;
    /* The states before the solver ran in this step, put back should it
     * leave one non-finite (rb_world_step); grown with `states`, so the
     * step allocates nothing. */
    rb_body_state *saved_states;
    int body_capacity;
    int state_capacity;       /* equals body_capacity once a body exists */
    int saved_state_capacity; /* equals state_capacity */
    int body_slots;           /* slots ever used: live bodies have index < body_slots */
    int body_free;            /* head of the free list, -1 when empty */
    int body_count;

    rb_shape *shapes;
    int shape_capacity;
    int shape_slots;
    int shape_free;
    int shape_count;

    rb_contact *contacts;
    int contact_count, contact_capacity;
    rb_contact *spare_contacts; /* the merge in the collide phase writes here, then swaps */
    int spare_capacity;
    /* broad phase, after a full search: every pair of shapes that may
     * collide and whose fat boxes overlap, sorted as the contacts are */
    rb_pair *pairs;
    int pair_count, pair_capacity;
    bool pairs_rebuilt; /* `pairs` was found anew in this step: the contacts follow it */
    /* broad phase, otherwise: the pairs that begin and end in this step,
     * each list sorted as the contacts are; both empty for a pile at rest */
    rb_pair *new_pairs;
    int new_pair_count, new_pair_capacity;
    rb_pair *ended_pairs;
    int ended_pair_count, ended_pair_capacity;
    rb_pair *sorted_pairs; /* the broad phase's counting sort writes here, then swaps */
    int sorted_pair_capacity;
    int *pair_bucket; /* the counting sort's start of each body's run of pairs */
    int pair_bucket_capacity;
    struct rb_sweep_entry *sweep; /* broad phase: the shapes sorted by lower x, kept from step to step */
    int sweep_capacity;
    /* m, broad phase: fat boxes wider in x than this (the static ground
     * of a scene, 200 m across) are searched for by the list below, not
     * by a range in the sweep; +inf when there would be many */
    double wide_box_limit;
    double sweep_max_width; /* m, >= 0, broad phase: no other fat box in the sweep is wider in x */
    int *wide_shapes;       /* broad phase: the shapes whose fat box is wider than wide_box_limit */
    int wide_shape_count, wide_shape_capacity;
    struct rb_refit *refits; /* broad phase, within a step: the shapes that left their fat boxes */
    int refit_count, refit_capacity;
    double tallest_dynamic_box;          /* m, >= 0, broad phase: of the swept boxes of dynamic bodies' shapes */
    double widest_dynamic_box;           /* m, >= 0, broad phase: the same in x */
    struct rb_sweep_entry *band_entries; /* broad phase: the sweep cut into bands in y, for a full search */
    int band_entry_capacity;
    int *band_end; /* broad phase: where each band's entries end */
    int band_end_capacity;
    int *island_parent; /* union-find over bodies, found anew each step (sleep.c) */
    int island_capacity;
    int *island_size;
    int island_size_capacity;
    double *island_rest; /* s, by island root: the shortest time at rest */
    int island_rest_capacity;
    /* this step's links from a dynamic body to a moving kinematic one or
     * to a mouse joint (sleep.c) */
    int kinematic_link_count;
    /* The bodies this step moves (solver.c, list_moving_bodies): the
     * dynamic ones first, then the kinematic ones. A body woken within the
     * step (a cable law set in the substep callback) makes the list
     * stale, and the next integration lists them again. */
    rb_moving_body *moving_bodies;
    int moving_body_count, moving_dynamic_count, moving_body_capacity;
    bool moving_bodies_stale;

    int sweep_count;  /* shapes in the sweep: all of them, or none while no shape is solid */
    bool sweep_stale; /* shapes were created or destroyed: rebuild the sweep */
    /* a body was placed (it may be asleep) or the settings changed since
     * the last step: every shape's swept box is made anew, not only those
     * of the bodies that may have moved */
    bool boxes_stale;
    /* a body's type or a shape's filter changed, or a joint came or went:
     * which shapes may collide changed, so the broad phase finds every
     * pair anew */
    bool candidates_stale;
    int solid_shape_count; /* shapes that are not sensors */

    rb_contact_constraint *constraints; /* in colour order */
    int constraint_count, constraint_capacity;
    int bouncing_constraint_count; /* constraints with restitution > 0 this step */
    rb_colouring contact_colouring;
    rb_contact_batches contact_batches;
    rb_contact_rows contact_rows;

    rb_joint *joints;
    int joint_capacity;
    int *active_joints;           /* this step's solved joints (rb_joints_collect_active) */
    rb_point_block *point_blocks; /* per joint slot, for the pins with an angular row (joint_point.c) */
    int point_block_capacity;
    int active_joint_count, active_joint_capacity;
    /* The joints the velocity passes visit: the pass list less the pins
     * their blocks solve (joint.c); made again when it is not fresh. */
    rb_velocity_visit *velocity_joints;
    int velocity_joint_count, velocity_joint_capacity;
    bool velocity_joints_fresh; /* cleared when the pass list or a joint's block may change */
    bool velocity_rows_only;    /* every joint of the pass list a plain pin in its row: no list made */
    double *substep_omega; /* per body slot: rad/s at the substep's start, before any warm start (rb_joints_prepare) */
    int substep_omega_capacity;
    rb_pin_row *pin_rows; /* this step's plain pins, in the order of the pass list (joint_pin.c) */
    int pin_row_count, pin_row_capacity;
    rb_pin_anchors *pin_anchors; /* beside pin_rows */
    int pin_anchor_capacity;
    int *pin_row_of; /* per joint slot: its row in pin_rows this step, or -1 */
    int pin_row_of_capacity;
    bool pin_rows_live; /* the rows, not the joints, hold the pins' impulses (within a step) */
    /* The pass list in its order, while joints_ordered
     * (joint_order.c), and the scratch that finds it: the list in colour
     * order, a key per listed joint, each body's depth from the supports,
     * the search's queue (body_slots + 1) and the bodies' links. */
    int *ordered_joints;
    int ordered_joint_count, ordered_joint_capacity;
    int *joint_order_scratch;
    int joint_order_scratch_capacity;
    int *joint_keys;
    int joint_key_capacity;
    int *body_depth;
    int body_depth_capacity;
    int *body_queue;
    int body_queue_capacity;
    int *joint_ends; /* per joint slot: its bodies, a then b */
    int joint_end_capacity;
    int *body_edge_start; /* body_slots + 1: where each body's joints' other bodies start in body_edges */
    int body_edge_start_capacity;
    int *body_edges;
    int body_edge_capacity;
    rb_colouring joint_colouring;
    bool joints_ordered;
    bool joint_order_kept;                  /* ordered_joints holds the order for the trees' last search... */
    unsigned joint_order_finds;             /* ...this one (rb_joint_tree.finds)... */
    rb_joint_order_scope joint_order_scope; /* ...and ordering this */
    int joint_slots;
    int joint_free;
    int joint_count;

    rb_cable *cables;
    int cable_capacity;
    int cable_slots;
    int cable_free;
    int cable_count;
    bool cable_points_fresh; /* the cables' points are at the poses now (rb_cables_locate) */

    rb_joint_tree joint_tree;
    rb_joint_blocks joint_blocks;

    double last_substep;              /* s, the substep length of the last step: impulses / it = forces */
    rb_rigid_response joint_response; /* the current pass's, set by the solver */

    rb_profile profile;
    rb_statistics statistics;

    rb_event_arrays events;
    rb_pre_solve_fn *pre_solve;
    void *pre_solve_context;
};

/* Milliseconds on the monotonic clock while the world is profiling, else
 * 0 (the step's phase times then stay 0 without reading the clock). */
double rb_world_clock(const rb_world *world);
/* Adds the time since `start` (rb_world_clock, or the lap before) to a
 * phase of the profile and returns the time now, where the next phase
 * starts: one reading of the clock ends a phase and begins the next. Only
 * while profiling: a phase run every substep then costs a world that does
 * not profile a test, not an addition of 0 ms, and returns 0. */
static inline double rb_world_lap(const rb_world *world, double *phase, double start)
{
    if (!world->profiling) {
        return 0.0;
    }
    double now = rb_world_clock(world);
    *phase += now - start;
    return now;
}

/* Looks up a live object; on failure records an error naming `function`. */
rb_status rb_world_find_body(const rb_world *world, rb_body_id id, const char *function, int *index);
rb_status rb_world_find_shape(const rb_world *world, rb_shape_id id, const char *function, int *index);
/* Also fails with RB_ERR_LOCKED while the world is stepping. */
rb_status rb_world_check_unlocked(const rb_world *world, const char *function);
/* For the few changes allowed inside the substep callback too (cable
 * tension laws): they alter forces, not the set of objects. */
rb_status rb_world_check_unlocked_or_in_substep_callback(const rb_world *world, const char *function);

rb_status rb_world_find_joint(const rb_world *world, rb_joint_id id, const char *function, int *index);

rb_body_id rb_make_body_id(const rb_world *world, int index);
rb_joint_id rb_make_joint_id(const rb_world *world, int index);
rb_shape_id rb_make_shape_id(const rb_world *world, int index);

/* The body's pose as a transform of its origin: the state keeps the
 * centre of mass, and the origin lies local_center behind it. Inline, as
 * the narrow phase asks it twice for every contact of every step. */
static inline rb_transform rb_body_origin_transform(const rb_world *world, int body)
{
    const rb_body_state *state = &world->states[body];
    rb_vec2 origin = rb_sub(state->center, rb_rotate(state->rotation, world->bodies[body].local_center));
    return (rb_transform){origin, state->rotation};
}

/* Recomputes mass, centre and inertia from the shapes (or the override),
 * keeping the origin in place; also refreshes every shape's extent. */
void rb_body_update_mass(rb_world *world, int body);

/* Fails unless a shape of `type` with this geometry and density weighs
 * at most RB_MAX_MASS and, when it gives a dynamic body its mass
 * (`gives_mass`), at least RB_MIN_MASS (rb/base.h). */
rb_status rb_shape_check_mass(const char *function, rb_shape_type type, const void *geometry, double density,
                              bool gives_mass);

/* The shape's tight world box at the body's current pose. */
rb_aabb rb_shape_tight_aabb(const rb_world *world, int shape);

/* Whether a joint joins the two bodies and forbids their collision. */
bool rb_joints_forbid_collision(const rb_world *world, int body_a, int body_b);

/* Destroys every cable with a point on the body. */
void rb_cables_remove_body(rb_world *world, int body);

/* Destroys every joint attached to the body. */
void rb_joints_remove_body(rb_world *world, int body);

/* Removes every contact that involves the shape, ending those that touch
 * (their end events join the next step's). */
rb_status rb_contacts_remove_shape(rb_world *world, int shape);

#endif
