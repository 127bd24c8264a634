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
 */
#include "allocator.h"
#include "error.h"
#include "sleep.h"

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

static void link(rb_world *world, int a, int b)
{
    if (!is_dynamic(world, a) || !is_dynamic(world, b)) {
        return;
    }
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
}

/* Calls visit(world, a, b) for every link: touching solid contacts,
 * joints (b alone, with a = -1, for a mouse joint), and consecutive
 * bodies of every cable. */
static void for_each_link(rb_world *world, void (*visit)(rb_world *, int, int))
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
    world->bodies[body].awake = true;
    world->bodies[body].sleep_time = 0.0;
}

/* A link to a moving kinematic body wakes the dynamic end; a mouse joint
 * (a = -1) wakes its body. */
static void wake_by_kinematic(rb_world *world, int a, int b)
{
    if (is_dynamic(world, a) && (b < 0 || is_moving_kinematic(world, b))) {
        rb_body_wake(world, a);
    }
    if (is_dynamic(world, b) && (a < 0 || is_moving_kinematic(world, a))) {
        rb_body_wake(world, b);
    }
}

/* The same links restart the dynamic end's time at rest. */
static void keep_awake_by_kinematic(rb_world *world, int a, int b)
{
    if (is_dynamic(world, a) && (b < 0 || is_moving_kinematic(world, b))) {
        world->bodies[a].sleep_time = 0.0;
    }
    if (is_dynamic(world, b) && (a < 0 || is_moving_kinematic(world, a))) {
        world->bodies[b].sleep_time = 0.0;
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
    for (int i = 0; i < n; ++i) {
        world->island_parent[i] = i;
        world->island_size[i] = 1;
    }
    for_each_link(world, link);
    if (!world->enable_sleep) {
        return RB_OK;
    }
    for_each_link(world, wake_by_kinematic);
    /* island_size of a root now counts its bodies; reuse the rest array
     * as "some body of the island is awake". */
    for (int i = 0; i < n; ++i) {
        world->island_rest[i] = 0.0;
    }
    for (int i = 0; i < n; ++i) {
        if (world->bodies[i].in_use && is_dynamic(world, i) && world->bodies[i].awake) {
            world->island_rest[find_root(world->island_parent, i)] = 1.0;
        }
    }
    for (int i = 0; i < n; ++i) {
        rb_body *body = &world->bodies[i];
        if (body->in_use && is_dynamic(world, i) && !body->awake &&
            world->island_rest[find_root(world->island_parent, i)] != 0.0) {
            rb_body_wake(world, i);
        }
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

void rb_islands_sleep(rb_world *world, double dt)
{
    int n = world->body_slots;
    int islands = 0;
    int awake = 0;
    for (int i = 0; i < n; ++i) {
        rb_body *body = &world->bodies[i];
        if (body->in_use && is_dynamic(world, i) && body->awake) {
            body->sleep_time =
                world->enable_sleep && body->enable_sleep && is_resting(world, i) ? body->sleep_time + dt : 0.0;
        }
    }
    if (world->enable_sleep) {
        for_each_link(world, keep_awake_by_kinematic);
    }
    /* The island's shortest time at rest, at its root. */
    for (int i = 0; i < n; ++i) {
        world->island_rest[i] = RB_TIME_TO_SLEEP;
    }
    for (int i = 0; i < n; ++i) {
        const rb_body *body = &world->bodies[i];
        if (body->in_use && is_dynamic(world, i)) {
            int root = find_root(world->island_parent, i);
            islands += root == i ? 1 : 0;
            double rest = body->awake ? body->sleep_time : RB_TIME_TO_SLEEP;
            world->island_rest[root] = rest < world->island_rest[root] ? rest : world->island_rest[root];
        }
    }
    for (int i = 0; i < n; ++i) {
        rb_body *body = &world->bodies[i];
        if (!body->in_use || !is_dynamic(world, i) || !body->awake) {
            continue;
        }
        if (world->enable_sleep && world->island_rest[find_root(world->island_parent, i)] >= RB_TIME_TO_SLEEP) {
            body->awake = false;
            body->sleep_time = 0.0;
            world->states[i].linear_velocity = rb_v2(0.0, 0.0);
            world->states[i].angular_velocity = 0.0;
            world->boxes_stale = true; /* its swept boxes, made moving, are made once more at rest */
        } else {
            ++awake;
        }
    }
    world->statistics.island_count = islands;
    world->statistics.awake_body_count = awake;
}
