/* SPDX-License-Identifier: MIT */
/* Islands and sleeping.
 *
 * An island is a set of dynamic bodies linked by touching contacts,
 * joints and cables: what pushes one body may move any other, so they
 * can only rest together. Static and kinematic bodies do not link
 * islands (a floor under two stacks leaves two islands), but a moving
 * kinematic body keeps what touches it awake. The islands are found anew
 * each step by union-find over the links (Tarjan 1975; union by size,
 * path halving): O(links·α(bodies)), with no state to keep consistent
 * when bodies, contacts or joints come and go.
 *
 * An island falls asleep once every body in it has been slower than the
 * sleep tolerances for RB_TIME_TO_SLEEP (Catto, Box2D 2.x b2Island): a
 * sleeping body is not integrated and acts as static in the solver, and
 * it wakes with its whole island when an awake body touches it, or a
 * force, a joint or the user wakes any body of the island.
 *
 * What a step pays. The union-find itself is one pass over the bodies
 * and one over the links, and it is all a step needs while no body
 * sleeps and none has rested long enough to: the passes that find each
 * body's island (waking sleeping islands, putting resting ones to sleep)
 * run only in the steps that may change something, and the links to
 * moving kinematic bodies are visited again only when there are some.
 */
#include "allocator.h"
#include "error.h"
#include "sleep.h"

/* island_parent of a body that links nothing: a free slot, a static body
 * or a kinematic body at rest. A dynamic body's is a body index (>= 0). */
#define ISLAND_APART (-1)
/* island_parent of a moving kinematic body: it keeps what it touches
 * awake. The missing end of a mouse joint (-1) counts as one. */
#define ISLAND_MOVING_KINEMATIC (-2)

static bool is_dynamic(const rb_world *world, int body)
{
    return body >= 0 && world->bodies[body].type == RB_BODY_DYNAMIC;
}

/* A kinematic body that moves: it keeps what it touches awake. */
static bool is_moving_kinematic(const rb_world *world, int body)
{
    if (body < 0 || world->bodies[body].type != RB_BODY_KINEMATIC) {
        return false;
    }
    const rb_body_state *s = &world->states[body];
    return s->linear_velocity.x != 0.0 || s->linear_velocity.y != 0.0 || s->angular_velocity != 0.0;
}

static int find_root(int *parent, int body)
{
    while (parent[body] != body) {
        parent[body] = parent[parent[body]];
        body = parent[body];
    }
    return body;
}

/* What body is to the islands: its island_parent, or what that stands
 * for (ISLAND_APART, ISLAND_MOVING_KINEMATIC). */
static int island_kind(const rb_world *world, int body)
{
    return body >= 0 ? world->island_parent[body] : ISLAND_MOVING_KINEMATIC;
}

/* Calls visit(world, a, b) for every link: touching solid contacts,
 * joints (b alone, with a = -1, for a mouse joint), and consecutive
 * bodies of every cable. Inline, so that each caller's visit is inlined
 * into its loops rather than called through a pointer (the union-find's
 * link cost twice as much as a call). */
static inline __attribute__((always_inline)) void for_each_link(rb_world *world, void (*visit)(rb_world *, int, int))
{
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *contact = &world->contacts[i];
        if (contact->touching && !contact->sensor) {
            visit(world, contact->body_a, contact->body_b);
        }
    }
    for (int i = 0; i < world->joint_slots; ++i) {
        const rb_joint *joint = &world->joints[i];
        if (joint->in_use) {
            visit(world, joint->body_a, joint->body_b);
        }
    }
    for (int c = 0; c < world->cable_slots; ++c) {
        const rb_cable *cable = &world->cables[c];
        for (int i = 0; cable->in_use && i + 1 < cable->point_count; ++i) {
            visit(world, cable->bodies[i], cable->bodies[i + 1]);
        }
    }
}

void rb_body_wake(rb_world *world, int body)
{
    if (!world->bodies[body].awake) {
        world->moving_bodies_stale = true; /* woken within a step, it is listed again (solver.c) */
    }
    world->bodies[body].awake = true;
    world->bodies[body].sleep_time = 0.0;
}

/* A link joins the islands of two dynamic bodies. A link between a
 * dynamic body and a moving kinematic one (or a mouse joint) is counted
 * and, with sleep on, wakes the dynamic body: that is what
 * keep_awake_by_kinematic repeats after the step. */
static inline __attribute__((always_inline)) void link(rb_world *world, int a, int b)
{
    int kind_a = island_kind(world, a);
    int kind_b = island_kind(world, b);
    if (kind_a >= 0 && kind_b >= 0) {
        int *parent = world->island_parent;
        int root_a = find_root(parent, a);
        int root_b = find_root(parent, b);
        if (root_a == root_b) {
            return;
        }
        if (world->island_size[root_a] < world->island_size[root_b]) {
            int t = root_a;
            root_a = root_b;
            root_b = t;
        }
        parent[root_b] = root_a;
        world->island_size[root_a] += world->island_size[root_b];
        return;
    }
    if (kind_a >= 0 && kind_b == ISLAND_MOVING_KINEMATIC) {
        world->kinematic_link_count += 1;
        if (world->enable_sleep) {
            rb_body_wake(world, a);
        }
    }
    if (kind_b >= 0 && kind_a == ISLAND_MOVING_KINEMATIC) {
        world->kinematic_link_count += 1;
        if (world->enable_sleep) {
            rb_body_wake(world, b);
        }
    }
}

/* The same links restart the dynamic end's time at rest after the step. */
static void keep_awake_by_kinematic(rb_world *world, int a, int b)
{
    if (is_dynamic(world, a) && (b < 0 || is_moving_kinematic(world, b))) {
        world->bodies[a].sleep_time = 0.0;
    }
    if (is_dynamic(world, b) && (a < 0 || is_moving_kinematic(world, a))) {
        world->bodies[b].sleep_time = 0.0;
    }
}

/* Wakes every sleeping dynamic body whose island holds an awake one;
 * island_rest of a root, reused, means "some body of the island is
 * awake". */
static void wake_touched_islands(rb_world *world)
{
    int n = world->body_slots;
    for (int i = 0; i < n; ++i) {
        world->island_rest[i] = 0.0;
    }
    for (int i = 0; i < n; ++i) {
        if (world->island_parent[i] >= 0 && world->bodies[i].awake) {
            world->island_rest[find_root(world->island_parent, i)] = 1.0;
        }
    }
    for (int i = 0; i < n; ++i) {
        if (world->island_parent[i] >= 0 && !world->bodies[i].awake &&
            world->island_rest[find_root(world->island_parent, i)] != 0.0) {
            rb_body_wake(world, i);
        }
    }
}

rb_status rb_islands_wake(rb_world *world)
{
    int n = world->body_slots;
    if (rb_grow_array((void **)&world->island_parent, &world->island_capacity, n, sizeof *world->island_parent) != 0 ||
        rb_grow_array((void **)&world->island_size, &world->island_size_capacity, n, sizeof *world->island_size) != 0 ||
        rb_grow_array((void **)&world->island_rest, &world->island_rest_capacity, n, sizeof *world->island_rest) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the islands");
    }
    bool some_asleep = false;
    for (int i = 0; i < n; ++i) {
        const rb_body *body = &world->bodies[i];
        bool dynamic = body->in_use && body->type == RB_BODY_DYNAMIC;
        bool moving_kinematic = body->in_use && is_moving_kinematic(world, i);
        world->island_parent[i] = dynamic ? i : moving_kinematic ? ISLAND_MOVING_KINEMATIC : ISLAND_APART;
        world->island_size[i] = 1;
        some_asleep = some_asleep || (dynamic && !body->awake);
    }
    world->kinematic_link_count = 0;
    for_each_link(world, link);
    if (world->enable_sleep && some_asleep) {
        wake_touched_islands(world);
    }
    return RB_OK;
}

static bool is_resting(const rb_world *world, int i)
{
    const rb_body_state *s = &world->states[i];
    const double linear = RB_LINEAR_SLEEP_TOLERANCE;
    const double angular = RB_ANGULAR_SLEEP_TOLERANCE;
    return rb_length_squared(s->linear_velocity) <= linear * linear &&
           s->angular_velocity * s->angular_velocity <= angular * angular;
}

/* Puts to sleep every island whose awake bodies have all rested
 * RB_TIME_TO_SLEEP (a sleeping body counts as rested): island_rest of a
 * root is the island's shortest time at rest. Returns the dynamic
 * bodies left awake. */
static int sleep_rested_islands(rb_world *world)
{
    int n = world->body_slots;
    int awake = 0;
    for (int i = 0; i < n; ++i) {
        world->island_rest[i] = RB_TIME_TO_SLEEP;
    }
    for (int i = 0; i < n; ++i) {
        if (world->island_parent[i] >= 0) {
            const rb_body *body = &world->bodies[i];
            int root = find_root(world->island_parent, i);
            double rest = body->awake ? body->sleep_time : RB_TIME_TO_SLEEP;
            world->island_rest[root] = rest < world->island_rest[root] ? rest : world->island_rest[root];
        }
    }
    for (int i = 0; i < n; ++i) {
        rb_body *body = &world->bodies[i];
        if (world->island_parent[i] < 0 || !body->awake) {
            continue;
        }
        if (world->island_rest[find_root(world->island_parent, i)] >= RB_TIME_TO_SLEEP) {
            body->awake = false;
            body->sleep_time = 0.0;
            world->states[i].linear_velocity = rb_v2(0.0, 0.0);
            world->states[i].angular_velocity = 0.0;
            world->boxes_stale = true; /* its swept boxes, made moving, are made once more at rest */
        } else {
            ++awake;
        }
    }
    return awake;
}

void rb_islands_sleep(rb_world *world, double dt)
{
    int n = world->body_slots;
    int islands = 0;
    int awake = 0;
    bool some_rested = false; /* an awake body has rested RB_TIME_TO_SLEEP */
    for (int i = 0; i < n; ++i) {
        if (world->island_parent[i] < 0) {
            continue;
        }
        islands += world->island_parent[i] == i ? 1 : 0;
        rb_body *body = &world->bodies[i];
        /* With sleep off, every time at rest stays 0 (rb_world_enable_sleep
         * woke every body), and the bodies are only counted. */
        if (body->awake && world->enable_sleep) {
            body->sleep_time = body->enable_sleep && is_resting(world, i) ? body->sleep_time + dt : 0.0;
            some_rested = some_rested || body->sleep_time >= RB_TIME_TO_SLEEP;
        }
        awake += body->awake ? 1 : 0;
    }
    if (world->enable_sleep && world->kinematic_link_count > 0) {
        for_each_link(world, keep_awake_by_kinematic);
    }
    if (world->enable_sleep && some_rested) {
        awake = sleep_rested_islands(world);
    }
    world->statistics.island_count = islands;
    world->statistics.awake_body_count = awake;
}
