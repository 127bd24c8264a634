/* SPDX-License-Identifier: MIT */
/* Engine scenes, defined once and shared by the tests, the benchmarks and
 * the `sinew` tool. Each builds its bodies in an existing world (whose
 * gravity and solver settings the caller chooses) and reports the ids a
 * caller needs to measure it. Every function validates its arguments and
 * returns an rb_status with rb_last_error() set on failure; a scene that
 * fails half-way may leave some of its bodies in the world, which the
 * caller then destroys.
 */
#ifndef SCENES_SCENES_H
#define SCENES_SCENES_H

#include <stdint.h>

#include "rb/rb.h"

/* The k-th body (0-based) of a run of bodies whose first is `first`: the
 * stack's and the pyramid's boxes are such runs (same world and
 * generation, consecutive slot indices). Check the result with
 * rb_body_is_valid() when in doubt. */
static inline rb_body_id scene_body_at(rb_body_id first, int k)
{
    rb_body_id id = first;
    id.index += k;
    return id;
}

/* Vertical stack of `count` (1 .. 1000) square boxes of half-extent 0.5 m,
 * density 1 kg/m², friction 0.6, on a static ground box of half-extents
 * (20, 1) centred at (0, -1); box i (0-based) starts at (0, 0.5 + i).
 * The world must have no destroyed bodies (a fresh world), so that the
 * boxes get consecutive ids. */
typedef struct scene_stack {
    rb_body_id ground;
    rb_body_id top;
    rb_body_id first_box; /* box i is scene_body_at(first_box, i), i = 0 .. count - 1 */
    int count;
} scene_stack;
rb_status scene_stack_create(rb_world *world, int count, scene_stack *out);

/* The pyramid of the peer benchmarks (docs/benchmarks.md): ground box of half-extents
 * (100, 1) at (0, -1); square boxes of half-extent 0.5, density 1,
 * friction 0.6, restitution 0; row i (0-based) has base - i boxes at
 * y = (2i + 1)·0.5 and x = (i + 1)·0.5 + 2(j - i)·0.5 - 0.5·base for
 * j = i .. base - 1. base is 1 .. 1000. The world must have no destroyed
 * bodies (a fresh world), so that the boxes get consecutive ids. */
typedef struct scene_pyramid {
    rb_body_id ground;
    rb_body_id top;       /* the single box of the last row */
    int box_count;        /* base·(base + 1)/2 */
    rb_body_id first_box; /* created in row order: box k is scene_body_at(first_box, k), k = 0 .. box_count - 1 */
} scene_pyramid;
rb_status scene_pyramid_create(rb_world *world, int base, scene_pyramid *out);

/* Many pyramids (the scale benchmark beside the big one): `count`
 * (1 .. 100) pyramids of `base` (1 .. 100) boxes as above, pyramid k
 * centred at x = k·(base + 1) m, all on one static ground box of
 * half-height 1 m whose top is y = 0 and which reaches one box width past
 * either end. `out->top` is the last pyramid's top box; the boxes of all
 * pyramids form one run of ids from `first_box`, pyramid by pyramid.
 * A fresh world, as above. */
#define SCENE_MANY_PYRAMIDS_MAX 100
#define SCENE_MANY_PYRAMIDS_MAX_BASE 100
rb_status scene_many_pyramids_create(rb_world *world, int count, int base, scene_pyramid *out);

/* Rain on a pyramid: the pyramid above (base 1 .. 1000) and `ball_count`
 * (0 .. SCENE_RAIN_MAX_BALLS) balls of radius 0.2 m, density 1, friction
 * 0.6, restitution 0, in columns 1 m apart over the pyramid's base
 * (ball k in column k mod base, moved sideways by up to 0.2 m) and rows
 * 2 m apart from 2 m above its top box (each ball up to 1 m higher), each
 * thrown sideways at up to 3 m/s either way. The random numbers come
 * from `seed` (xoshiro256**, the same on every platform). A fresh world,
 * as for the pyramid. */
#define SCENE_RAIN_MAX_BALLS 10000
typedef struct scene_rain {
    scene_pyramid pyramid;
    rb_body_id first_ball; /* ball k is scene_body_at(first_ball, k), k = 0 .. ball_count - 1 */
    int ball_count;
} scene_rain;
rb_status scene_rain_create(rb_world *world, int base, int ball_count, uint64_t seed, scene_rain *out);

/* The balls box of the first engine in Castanyer's report ("Implementació
 * d'un model computacional de sistemes musculoesquelètics", 2023-24): a closed box
 * 2.44 m × 1.22 m of static walls (one body, four boxes 1 m thick so that
 * no ball can cross one in a step) with its lower-left inner corner at the
 * origin, `count` circles (1 .. SCENE_BALLS_MAX) of radius U(0.01, 0.1) m at
 * random non-overlapping positions, mass 0.16 kg × U(0.5, 1.5),
 * restitution U(0.5, 1), friction 0.2 (walls: friction 0.2, restitution
 * 0, so the ball's own restitution applies), each kicked by an impulse of
 * U(2, 70) N × 1/60 s at an angle U(20°, 160°) from +x. The random
 * numbers come from a 64-bit generator seeded with `seed` (xoshiro256**,
 * the same on every platform), so a run can be repeated. Positions are
 * drawn by rejection sampling, at most SCENE_BALLS_PLACEMENT_TRIES per
 * ball; a count too large to fit fails with RB_ERR_INVALID_ARGUMENT.
 * The caller sets gravity (0, -9.81) and calls
 * scene_balls_apply_drag before every step. */
#define SCENE_BALLS_MAX 1000
#define SCENE_BALLS_WIDTH 2.44  /* m, inner */
#define SCENE_BALLS_HEIGHT 1.22 /* m, inner */
#define SCENE_BALLS_PLACEMENT_TRIES 10000
#define SCENE_BALLS_DRAG 0.05 /* N·s/m: the original's linear drag F = -0.05·v */
typedef struct scene_balls {
    rb_body_id walls;
    rb_body_id balls[SCENE_BALLS_MAX];
    int count;
} scene_balls;
rb_status scene_balls_create(rb_world *world, int count, uint64_t seed, scene_balls *out);
/* Applies the original's drag force -0.05·v to every ball. */
rb_status scene_balls_apply_drag(rb_world *world, const scene_balls *balls);

/* A static plank 20 m long and 0.2 m thick, tilted by `angle` (rad,
 * 0 .. 1.4, counter-clockwise, so the slope rises towards +x) with the
 * middle of its top face at the origin, and a box of half-extent 0.25 m
 * and density 1 turned by the same angle, its bottom face lying on the
 * plank's top face and centred 1 m up the slope from the origin. Both
 * shapes get `friction` (finite, >= 0), so the mixed coefficient is
 * `friction`: the box stays when tan(angle) <= friction and otherwise
 * slides with acceleration g·(sin(angle) - friction·cos(angle)). */
typedef struct scene_incline {
    rb_body_id plank;
    rb_body_id box;
    rb_vec2 slope_direction; /* unit, down the slope: -(cos angle, sin angle) */
} scene_incline;
rb_status scene_incline_create(rb_world *world, double angle, double friction, scene_incline *out);

/* A ball of radius 0.1 m and density 1 whose lowest point starts `height`
 * m (> 0, <= 1000) above a static ground box of half-extents (20, 1)
 * whose top face is y = 0; the ball's centre starts at (0, height + 0.1).
 * Both shapes have restitution `restitution` (0 .. 1) and friction 0.6. */
typedef struct scene_drop {
    rb_body_id ground;
    rb_body_id ball;
    double radius; /* m, 0.1 */
} scene_drop;
rb_status scene_drop_create(rb_world *world, double height, double restitution, scene_drop *out);

/* The chain of the peer benchmarks (docs/benchmarks.md): `links` (1 .. 1000) boxes of
 * half-extents 0.25 × 0.05 m and density 1 kg/m² (0.05 kg), joined end to
 * end by revolute joints, the first pinned to a static body (no shape) at
 * the origin, and a heavy box of half-extent 0.25 m and density
 * `heavy_density` (kg/m², finite, >= 0; 20 gives 5 kg, 100× a link)
 * jointed at the end; with heavy_density 0 there is no heavy box (the
 * joint tests' plain chain), `heavy` is the last link and there are
 * `links` joints. Along the chain's direction d, body i (0-based; the
 * heavy box is i = links) has its centre at (0.5·i + 0.25)·d m, and joint i
 * joins the point 0.25 m beyond the centre of body i - 1 (the pin's origin
 * for i = 0), body A, to the point 0.25 m behind the centre of body i,
 * body B, the two coinciding at the start; its reference angle is the
 * bodies' start angle difference. Shapes of the chain do not collide with
 * each other (all in group -1), friction 0.6, restitution 0. Layout "hang"
 * starts vertical below the pin (d = (0, -1), bodies at angle -π/2), at
 * rest; "swing" starts horizontal along +x (d = (1, 0), angle 0) and is
 * released. The peers' figure, the largest gap between a joint's two
 * anchors, is rb_world_statistics().max_joint_gap after each step. */
typedef enum scene_chain_layout {
    SCENE_CHAIN_HANG,
    SCENE_CHAIN_SWING,
} scene_chain_layout;
#define SCENE_CHAIN_MAX_LINKS 1000
typedef struct scene_chain {
    rb_body_id pin;
    rb_body_id heavy;
    rb_joint_id joints[SCENE_CHAIN_MAX_LINKS + 1]; /* links + 1 joints, the last one holds the heavy box (if any) */
    int joint_count;
} scene_chain;
rb_status scene_chain_create(rb_world *world, int links, double heavy_density, scene_chain_layout layout,
                             scene_chain *out);

/* A cantilever of two welded planks: a static wall (a box of half-extents
 * 0.1 × 1 m centred at (-0.1, 0), so its right face is x = 0); plank 1, a
 * box of half-extents 0.5 × 0.1 m and density 1 kg/m² (0.2 kg) centred at
 * (0.5, 0), welded to the wall at (0, 0); plank 2, the same box at
 * density 2 (0.4 kg) centred at (1.5, 0), welded to plank 1 at (1, 0).
 * Body B of each weld is the outer one; the welds are rigid (the default
 * weld definition). At rest under gravity (0, -g) each weld carries what
 * lies beyond it: on B a force (0, M·g) and a torque M·g·d, with M the
 * mass carried and d the horizontal distance from the weld to that
 * mass's centre (root: M = 0.6 kg, M·d = 0.2·0.5 + 0.4·1.5 kg·m; tip:
 * M = 0.4 kg, d = 0.5 m). The planks sag only as far as the solver lets
 * the welds give. */
typedef struct scene_cantilever {
    rb_body_id wall;
    rb_body_id plank1, plank2;
    rb_joint_id root; /* wall to plank 1 */
    rb_joint_id tip;  /* plank 1 to plank 2 */
} scene_cantilever;
rb_status scene_cantilever_create(rb_world *world, scene_cantilever *out);

/* A pendulum: a static pivot (no shape) at the origin and a bob, a
 * circle of radius 0.05 m and density 1, `length` m (> 0, <= 100) to its
 * right, pinned to the pivot by a revolute joint at the origin. Released
 * at rest, it swings down through the vertical and back up to the
 * horizontal on the other side. */
typedef struct scene_pendulum {
    rb_body_id pivot;
    rb_body_id bob;
    rb_joint_id joint;
    double radius; /* m, of the bob: 0.05 */
} scene_pendulum;
rb_status scene_pendulum_create(rb_world *world, double length, scene_pendulum *out);

/* The joint grid of the peer benchmarks (docs/benchmarks.md): n × n (2 .. 1000) circles of
 * radius 0.4 m, density 1 kg/m², friction 0.6, at (k, -i) m for column k
 * and row i (0-based); each body (but the top row's) is joined to the body
 * above it by a revolute joint whose body A is the one above (local
 * anchors (0, -0.5) on A and (0, 0.5) on the body), and each body (but the
 * left column's) to its left neighbour (body A the neighbour, anchors
 * (0.5, 0) and (-0.5, 0)): 2·n·(n - 1) joints, the few between two static
 * bodies included (they do nothing). The top row's bodies with
 * |k - n/2| <= 3 (n/2 in integer division) are static; circles do not
 * collide with each other (all in group -1). Bodies are created column by
 * column, each column from the top down, and each body's joint to the body
 * above before its joint to the left, as the peers do, so that a
 * sequential solver visits the joints in the peers' order. The world must
 * have no destroyed bodies (a fresh world), so that the bodies get
 * consecutive ids. */
typedef struct scene_joint_grid {
    rb_body_id first_body; /* body (row i, column k) is scene_body_at(first_body, k·n + i) */
    int n;
    int joint_count; /* 2·n·(n - 1) */
} scene_joint_grid;
rb_status scene_joint_grid_create(rb_world *world, int n, scene_joint_grid *out);

#endif
