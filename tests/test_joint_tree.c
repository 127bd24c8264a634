/* SPDX-License-Identifier: MIT */
/* The pins of a joint tree solved together (engine/src/joint_tree.c),
 * checked against the equations they solve rather than against a second
 * solver: after one velocity pass every pin's anchors move together (up
 * to the centripetal drift the pin asks for), and the bodies' momentum
 * changed by exactly the pins' impulses, M·Δv = Jᵀ·λ; after one position
 * pass on small gaps, the gaps close to second order.
 *
 * The tree branches (a body with three pins), holds a chain, a pin to the
 * ground at its root, a second pin to the ground (a loop through the
 * ground, left to Gauss-Seidel) and a pin closing a loop among moving
 * bodies (likewise); its bodies have unequal masses, from 1 to 1,000.
 */
#include <criterion/criterion.h>
#include <math.h>

#include "joint_solver.h"
#include "joint_tree.h"
#include "rb/rb.h"
#include "test_support.h"
#include "world_internal.h"

#define BODIES 8

typedef struct tree_scene {
    rb_world *world;
    rb_body_id ground, bodies[BODIES];
    rb_joint_id pins[BODIES + 3]; /* with the one kept_trees_step_as_trees_found_anew_after_every_change makes */
    int pin_count;
} tree_scene;

static rb_body_id add_link(rb_world *world, rb_vec2 position, double angle, double density)
{
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = position;
    def.angle = angle;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    rb_polygon box;
    cr_assert_eq(rb_make_box(0.3, 0.1, &box), RB_OK);
    rb_shape_def shape = rb_default_shape_def();
    shape.density = density;
    shape.filter.group_index = -1;
    rb_shape_id id;
    cr_assert_eq(rb_shape_create_polygon(world, body, &shape, &box, &id), RB_OK, "%s", rb_last_error());
    return body;
}

static void pin(tree_scene *scene, rb_body_id a, rb_body_id b, rb_vec2 anchor)
{
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    cr_assert_eq(rb_revolute_joint_def_at(&def, scene->world, a, b, anchor), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_revolute_joint_create(scene->world, &def, &scene->pins[scene->pin_count++]), RB_OK, "%s",
                 rb_last_error());
}

/* A world with the ground and BODIES links of unequal densities (1 to
 * 1,000) along x, the i-th raised by rise·(i mod period), not yet pinned. */
static tree_scene make_links(double rise, int period)
{
    tree_scene scene = {.world = make_world(rb_v2(0.0, -9.8))};
    rb_body_def ground = rb_default_body_def();
    cr_assert_eq(rb_body_create(scene.world, &ground, &scene.ground), RB_OK);
    const double densities[BODIES] = {1.0, 1000.0, 3.0, 10.0, 1.0, 300.0, 2.0, 50.0};
    for (int i = 0; i < BODIES; ++i) {
        scene.bodies[i] = add_link(scene.world, rb_v2(0.5 * i, rise * (i % period)), 0.3 * i, densities[i]);
    }
    return scene;
}

/* Velocities the pins do not allow. */
static void give_velocities_the_pins_forbid(tree_scene *scene)
{
    for (int i = 0; i < BODIES; ++i) {
        cr_assert_eq(rb_body_set_linear_velocity(scene->world, scene->bodies[i], rb_v2(sin(1.7 * i), cos(2.3 * i))),
                     RB_OK);
        cr_assert_eq(rb_body_set_angular_velocity(scene->world, scene->bodies[i], 2.0 * sin(0.9 * i + 0.4)), RB_OK);
    }
}

/* Body 0 pinned to the ground; bodies 1, 2, 3 pinned to body 0 (a
 * branch); 4, 5, 6 a chain from body 1; 7 pinned to body 6 and, with
 * `loops`, to the ground again (a loop through the ground) and to body 2
 * (a loop). */
static tree_scene make_tree_with(bool loops)
{
    tree_scene scene = make_links(0.2, 3);
    pin(&scene, scene.ground, scene.bodies[0], rb_v2(-0.2, 0.0));
    for (int i = 1; i <= 3; ++i) {
        pin(&scene, scene.bodies[0], scene.bodies[i], rb_v2(0.25 * i, 0.1));
    }
    pin(&scene, scene.bodies[1], scene.bodies[4], rb_v2(1.0, 0.1));
    pin(&scene, scene.bodies[4], scene.bodies[5], rb_v2(2.2, 0.2));
    pin(&scene, scene.bodies[5], scene.bodies[6], rb_v2(2.7, 0.0));
    pin(&scene, scene.bodies[6], scene.bodies[7], rb_v2(3.3, 0.3));
    if (loops) {
        pin(&scene, scene.ground, scene.bodies[7], rb_v2(3.6, 0.2));
        pin(&scene, scene.bodies[2], scene.bodies[7], rb_v2(3.4, 0.1));
    }
    give_velocities_the_pins_forbid(&scene);
    return scene;
}

static tree_scene make_tree(void) { return make_tree_with(true); }

/* The solver's set-up of a step's first substep up to the warm start, as
 * rb_solver_step and rb_solver_sequential_substep do it, with the trees
 * on (NGS). */
static void build_substep(rb_world *world)
{
    cr_assert_eq(rb_joints_collect_active(world), RB_OK);
    world->joint_tree.enabled = true;
    world->joint_response = (rb_rigid_response){.mass_scale = 1.0};
    rb_joints_prepare(world);
    rb_joint_tree_build(world);
    rb_pins_gather(world);
}

/* The solver's set-up of one substep of h, the warm start included. */
static void prepare(rb_world *world, double h)
{
    build_substep(world);
    rb_joints_warm_start(world, h, false); /* the frames; the impulses are still 0 */
    rb_joint_tree_start_substep(world);
}

static rb_joint *joint_of(rb_world *world, rb_joint_id id) { return &world->joints[id.index]; }

/* Every body of the scene moved and turned by about a centimetre (0.01
 * rad): one position pass of the trees must close the first `pins` pins'
 * gaps to below 2e-4 m, second order in the displacement. */
static void expect_one_position_pass_closes_centimetre_gaps(tree_scene *scene, int pins)
{
    rb_world *world = scene->world;
    for (int i = 0; i < BODIES; ++i) {
        rb_body_state *state = &world->states[scene->bodies[i].index];
        state->center = rb_add(state->center, rb_v2(1e-2 * sin(3.1 * i), 1e-2 * cos(1.3 * i)));
        rb_body_state_turn(state, 1e-2 * sin(0.7 * i));
    }
    cr_expect_not(rb_joint_tree_correct_positions(world), "gaps of a centimetre are beyond the slop");
    for (int k = 0; k < pins; ++k) {
        rb_joint *joint = joint_of(world, scene->pins[k]);
        const rb_body_state *a = rb_joint_state_a(world, joint);
        const rb_body_state *b = rb_joint_state_b(world, joint);
        rb_vec2 gap = rb_sub(rb_add(b->center, rb_rotate(b->rotation, joint->frame.local_b)),
                             rb_add(a->center, rb_rotate(a->rotation, joint->frame.local_a)));
        cr_expect_lt(rb_length(gap), 2e-4, "pin %d: gap %.3g m after one pass (about 1e-2 before)", k, rb_length(gap));
    }
}

Test(joint_tree, the_tree_takes_every_pin_but_those_closing_loops)
{
    tree_scene scene = make_tree();
    prepare(scene.world, 1.0 / 360.0);
    for (int k = 0; k < scene.pin_count; ++k) {
        bool closes_loop = k >= scene.pin_count - 2;
        cr_expect_eq(joint_of(scene.world, scene.pins[k])->in_tree, !closes_loop, "pin %d", k);
    }
    /* 8 bodies and 8 pins. */
    cr_expect_eq(scene.world->joint_tree.node_count, 16);
    destroy_world_and_expect_no_leak(scene.world);
}

/* The tree's bodies and pins' impulses before a pass. */
typedef struct before_pass {
    rb_body_state states[BODIES];
    rb_vec2 impulses[BODIES + 3];
} before_pass;

static before_pass record(rb_world *world, const tree_scene *scene)
{
    before_pass before;
    for (int i = 0; i < BODIES; ++i) {
        before.states[i] = world->states[scene->bodies[i].index];
    }
    for (int k = 0; k < scene->pin_count; ++k) {
        before.impulses[k] = joint_of(world, scene->pins[k])->as.revolute.point_impulse;
    }
    return before;
}

/* After a velocity pass over the first `tree_pins` pins: J·v' = drift for
 * every one, and M·Δv = Jᵀ·λ for every body (momentum and angular
 * momentum about the centre change by the pins' impulses at their
 * anchors). */
static void expect_pins_met(rb_world *world, const tree_scene *scene, int tree_pins, const before_pass *before)
{
    for (int k = 0; k < tree_pins; ++k) {
        rb_joint *joint = joint_of(world, scene->pins[k]);
        rb_vec2 cdot =
            rb_joint_relative_velocity(joint, rb_joint_state_a(world, joint), rb_joint_state_b(world, joint));
        expect_vec_near(cdot, joint->frame.point_drift, 1e-10, "a pin's anchor velocity after the pass");
    }
    for (int i = 0; i < BODIES; ++i) {
        const rb_body *body = &world->bodies[scene->bodies[i].index];
        const rb_body_state *after = &world->states[scene->bodies[i].index];
        rb_vec2 force = rb_v2(0.0, 0.0);
        double torque = 0.0;
        for (int k = 0; k < tree_pins; ++k) {
            rb_joint *joint = joint_of(world, scene->pins[k]);
            rb_vec2 impulse = rb_sub(joint->as.revolute.point_impulse, before->impulses[k]);
            if (joint->body_b == scene->bodies[i].index) {
                force = rb_add(force, impulse);
                torque += rb_cross(joint->frame.rb, impulse);
            } else if (joint->body_a == scene->bodies[i].index) {
                force = rb_sub(force, impulse);
                torque -= rb_cross(joint->frame.ra, impulse);
            }
        }
        rb_vec2 momentum =
            rb_scale(1.0 / body->inv_mass, rb_sub(after->linear_velocity, before->states[i].linear_velocity));
        double angular = (after->angular_velocity - before->states[i].angular_velocity) / body->inv_inertia;
        expect_vec_near(momentum, force, 1e-9 * (1.0 + rb_length(force)), "a body's momentum change");
        expect_near(angular, torque, 1e-9 * (1.0 + fabs(torque)), "a body's angular momentum change");
    }
}

Test(joint_tree, one_velocity_pass_meets_every_pin_with_the_pins_impulses)
{
    tree_scene scene = make_tree();
    rb_world *world = scene.world;
    prepare(world, 1.0 / 360.0);
    cr_assert_not(world->joint_tree.chains, "the tree branches");
    const before_pass before = record(world, &scene);
    rb_joint_tree_solve_velocities(world);
    expect_pins_met(world, &scene, scene.pin_count - 2, &before);
    destroy_world_and_expect_no_leak(scene.world);
}

/* Body 0 pinned to the ground, each further body to the one before: a
 * chain of unequal links (1 to 1,000), the pins' bodies A alternately the
 * upper and the lower link. */
static tree_scene make_chain(void)
{
    tree_scene scene = make_links(0.1, 2);
    pin(&scene, scene.ground, scene.bodies[0], rb_v2(-0.2, 0.0));
    for (int i = 1; i < BODIES; ++i) {
        rb_vec2 anchor = rb_v2(0.5 * i - 0.25, 0.05);
        if (i % 2 == 0) {
            pin(&scene, scene.bodies[i - 1], scene.bodies[i], anchor);
        } else {
            pin(&scene, scene.bodies[i], scene.bodies[i - 1], anchor);
        }
    }
    give_velocities_the_pins_forbid(&scene);
    return scene;
}

/* A chain's pins solved through themselves alone (joint_chain.c) meet
 * the same equations, and give the velocities that the elimination of
 * bodies and pins together gives the same chain. */
Test(joint_tree, a_chain_solved_through_its_pins_meets_every_pin)
{
    tree_scene chain = make_chain();
    prepare(chain.world, 1.0 / 360.0);
    cr_assert(chain.world->joint_tree.chains, "a chain from the ground");
    const before_pass before = record(chain.world, &chain);
    rb_joint_tree_solve_velocities(chain.world);
    expect_pins_met(chain.world, &chain, chain.pin_count, &before);

    tree_scene tree = make_chain();
    prepare(tree.world, 1.0 / 360.0);
    tree.world->joint_tree.chains = false; /* bodies and pins eliminated together (joint_tree.c) */
    rb_joint_tree_solve_velocities(tree.world);
    for (int i = 0; i < BODIES; ++i) {
        const rb_body_state *a = &chain.world->states[chain.bodies[i].index];
        const rb_body_state *b = &tree.world->states[tree.bodies[i].index];
        double speed = rb_length(b->linear_velocity) + fabs(b->angular_velocity);
        expect_vec_near(a->linear_velocity, b->linear_velocity, 1e-12 * (1.0 + speed), "a body's velocity");
        expect_near(a->angular_velocity, b->angular_velocity, 1e-12 * (1.0 + speed), "a body's angular velocity");
    }
    rb_world_destroy(tree.world);

    /* A position pass on gaps of about a centimetre closes them to second
     * order, as the tree's does. */
    rb_world *world = chain.world;
    expect_one_position_pass_closes_centimetre_gaps(&chain, chain.pin_count);
    destroy_world_and_expect_no_leak(world);
}

/* With no other row on its bodies, one pass solves the tree and a second
 * one, which the solver skips, would change no velocity beyond rounding;
 * the pins that close loops are rows of Gauss-Seidel on its bodies, and
 * then every pass solves the tree. */
Test(joint_tree, a_tree_alone_needs_one_velocity_pass_a_substep)
{
    tree_scene scene = make_tree_with(false);
    rb_world *world = scene.world;
    prepare(world, 1.0 / 360.0);
    cr_assert(world->joint_tree.alone, "no row but the tree's pins acts on its bodies");
    rb_joint_tree_solve_velocities(world);
    rb_body_state solved[BODIES];
    for (int i = 0; i < BODIES; ++i) {
        solved[i] = world->states[scene.bodies[i].index];
    }
    rb_joint_tree_solve_velocities(world); /* skipped */
    for (int i = 0; i < BODIES; ++i) {
        const rb_body_state *now = &world->states[scene.bodies[i].index];
        cr_expect(now->linear_velocity.x == solved[i].linear_velocity.x &&
                      now->linear_velocity.y == solved[i].linear_velocity.y &&
                      now->angular_velocity == solved[i].angular_velocity,
                  "body %d: the second pass is skipped", i);
    }
    world->joint_tree.solved = false; /* the pass the solver skips, done */
    rb_joint_tree_solve_velocities(world);
    for (int i = 0; i < BODIES; ++i) {
        const rb_body_state *now = &world->states[scene.bodies[i].index];
        double speed = rb_length(solved[i].linear_velocity) + fabs(solved[i].angular_velocity);
        expect_vec_near(now->linear_velocity, solved[i].linear_velocity, 1e-12 * (1.0 + speed),
                        "a second pass's change of a body's velocity");
        expect_near(now->angular_velocity, solved[i].angular_velocity, 1e-12 * (1.0 + speed),
                    "a second pass's change of a body's angular velocity");
    }
    destroy_world_and_expect_no_leak(scene.world);

    scene = make_tree();
    prepare(scene.world, 1.0 / 360.0);
    cr_expect_not(scene.world->joint_tree.alone, "the pins closing loops act on the tree's bodies");
    destroy_world_and_expect_no_leak(scene.world);
}

/* A tree that no other row touches starts its pins cold under NGS: not
 * warm started, their impulses the first pass's whole solution. The
 * bodies' velocities after that pass are then those of the pins warm
 * started with the impulses they held and corrected by the pass, and the
 * impulses they hold the same, up to rounding: for the branching tree and
 * for a chain, each with held impulses of a few newton-seconds. Those move
 * the lightest link (0.12 kg) by up to 30 m/s in the warm start, which the
 * pass takes back through a system of masses 1 to 1,000: the round trip's
 * rounding, some 1e-11 m/s, bounds the velocities' agreement, where a pin
 * left without its warm start's effect would be metres a second off. */
static void expect_cold_start_as_warm(tree_scene (*make)(void))
{
    tree_scene runs[2];
    for (int warm = 0; warm < 2; ++warm) {
        tree_scene scene = make();
        rb_world *world = scene.world;
        for (int k = 0; k < scene.pin_count; ++k) {
            joint_of(world, scene.pins[k])->as.revolute.point_impulse = rb_v2(3.0 * sin(1.1 * k), 2.0 * cos(0.7 * k));
        }
        build_substep(world);
        cr_assert(world->joint_tree.alone, "no row but the tree's pins acts on its bodies");
        world->joint_tree.alone = !warm; /* warm: as if another row touched it */
        rb_joints_warm_start(world, 1.0 / 360.0, false);
        cr_assert(world->joint_tree.cold == !warm, "cold only when alone");
        rb_joint_tree_start_substep(world);
        rb_joint_tree_solve_velocities(world);
        runs[warm] = scene;
    }
    for (int i = 0; i < BODIES; ++i) {
        const rb_body_state *cold = &runs[0].world->states[runs[0].bodies[i].index];
        const rb_body_state *warm = &runs[1].world->states[runs[1].bodies[i].index];
        double speed = rb_length(warm->linear_velocity) + fabs(warm->angular_velocity);
        expect_vec_near(cold->linear_velocity, warm->linear_velocity, 1e-10 * (1.0 + speed), "a body's velocity");
        expect_near(cold->angular_velocity, warm->angular_velocity, 1e-10 * (1.0 + speed), "a body's angular velocity");
    }
    for (int k = 0; k < runs[0].pin_count; ++k) {
        rb_vec2 cold = joint_of(runs[0].world, runs[0].pins[k])->as.revolute.point_impulse;
        rb_vec2 warm = joint_of(runs[1].world, runs[1].pins[k])->as.revolute.point_impulse;
        expect_vec_near(cold, warm, 1e-9 * (1.0 + rb_length(warm)), "a pin's impulse");
    }
    rb_world_destroy(runs[0].world);
    destroy_world_and_expect_no_leak(runs[1].world);
}

static tree_scene make_tree_alone(void) { return make_tree_with(false); }

Test(joint_tree, a_tree_alone_starts_cold_with_the_velocities_of_a_warm_start)
{
    expect_cold_start_as_warm(make_tree_alone);
    expect_cold_start_as_warm(make_chain);
}

Test(joint_tree, one_position_pass_closes_small_gaps_to_second_order)
{
    tree_scene scene = make_tree();
    rb_world *world = scene.world;
    prepare(world, 1.0 / 360.0);
    /* Open every pin by about a centimetre, beyond the linear slop. */
    expect_one_position_pass_closes_centimetre_gaps(&scene, scene.pin_count - 2);
    destroy_world_and_expect_no_leak(scene.world);
}

/* ---- the trees kept from step to step ------------------------------------- */

static void step(rb_world *world) { cr_assert_eq(rb_world_step(world, 1.0 / 60.0), RB_OK, "%s", rb_last_error()); }

/* A step that finds nothing changed keeps the trees it found before: a
 * body's mass altered in its node by hand stays altered (finding the trees
 * again would read it from the body), until a joint changes. */
Test(joint_tree, kept_from_step_to_step_while_nothing_changes)
{
    tree_scene scene = make_tree();
    rb_world *world = scene.world;
    step(world);
    cr_assert(world->joint_tree.found && world->joint_tree.node_count == 16, "the trees are found");
    rb_tree_node *node = &world->joint_tree.nodes[world->joint_tree.body_node[scene.bodies[5].index]];
    const double mass = node->mass;
    node->mass = 2.0 * mass;
    step(world);
    node = &world->joint_tree.nodes[world->joint_tree.body_node[scene.bodies[5].index]];
    cr_expect_eq(node->mass, 2.0 * mass, "a step with nothing changed keeps the nodes");
    cr_assert_eq(rb_revolute_joint_set_motor(world, scene.pins[1], true, 1.0, 10.0), RB_OK, "%s", rb_last_error());
    step(world);
    node = &world->joint_tree.nodes[world->joint_tree.body_node[scene.bodies[5].index]];
    cr_expect_eq(node->mass, mass, "a motor turned on: the trees are found again");
    destroy_world_and_expect_no_leak(world);
}

/* Two worlds run the same changes, step by step; the second finds its
 * trees again before every step. Whatever the change (a motor, limits or
 * a spring turned on and off, a body's mass, type or sleep, a pin
 * destroyed or made, the settings), the first world's kept trees must
 * give the second's state, bit for bit. */
typedef enum tree_change {
    MOTOR_ON,
    MOTOR_OFF,
    LIMITS_ON,
    LIMITS_OFF,
    SPRING_ON,
    SPRING_OFF,
    MASS_SET,
    MASS_RESET,
    MADE_STATIC,
    MADE_DYNAMIC,
    ASLEEP,
    AWAKE,
    TREES_OFF,
    TREES_ON,
    SOFT_STEP,
    NGS,
    PIN_DESTROYED,
    PIN_MADE,
    CHANGE_COUNT
} tree_change;

static void apply_change(tree_scene *scene, tree_change change)
{
    rb_world *world = scene->world;
    rb_solver_settings settings = rb_world_solver_settings(world);
    rb_status status = RB_OK;
    switch (change) {
    case MOTOR_ON:
    case MOTOR_OFF:
        status = rb_revolute_joint_set_motor(world, scene->pins[1], change == MOTOR_ON, 2.0, 50.0);
        break;
    case LIMITS_ON:
    case LIMITS_OFF:
        status =
            rb_revolute_joint_set_limits(world, scene->pins[5], change == LIMITS_ON, -0.1, change == LIMITS_ON, 0.1);
        break;
    case SPRING_ON:
    case SPRING_OFF:
        status = rb_revolute_joint_set_spring(world, scene->pins[6], change == SPRING_ON, 3.0, 0.5);
        break;
    case MASS_SET: {
        rb_mass_data mass = rb_body_mass_data(world, scene->bodies[1]);
        mass.mass *= 0.01; /* the heaviest body no longer 1,000 times the lightest */
        mass.rotational_inertia *= 0.01;
        status = rb_body_set_mass_data(world, scene->bodies[1], &mass);
        break;
    }
    case MASS_RESET:
        status = rb_body_reset_mass_data(world, scene->bodies[1]);
        break;
    case MADE_STATIC:
    case MADE_DYNAMIC:
        status = rb_body_set_type(world, scene->bodies[7], change == MADE_STATIC ? RB_BODY_STATIC : RB_BODY_DYNAMIC);
        break;
    case ASLEEP:
    case AWAKE:
        status = rb_body_set_awake(world, scene->bodies[4], change == AWAKE);
        break;
    case TREES_OFF:
    case TREES_ON:
        settings.tree_pins = change == TREES_ON;
        status = rb_world_set_solver_settings(world, &settings);
        break;
    case SOFT_STEP:
    case NGS:
        settings.type = change == SOFT_STEP ? RB_SOLVER_SOFT_STEP : RB_SOLVER_NGS;
        status = rb_world_set_solver_settings(world, &settings);
        break;
    case PIN_DESTROYED:
        status = rb_joint_destroy(world, scene->pins[5]);
        break;
    case PIN_MADE:
        pin(scene, scene->bodies[3], scene->bodies[6], rb_v2(1.8, 0.2));
        break;
    case CHANGE_COUNT:
        break;
    }
    cr_assert_eq(status, RB_OK, "change %d: %s", (int)change, rb_last_error());
}

Test(joint_tree, kept_trees_step_as_trees_found_anew_after_every_change)
{
    tree_scene kept = make_tree();
    tree_scene anew = make_tree();
    for (int change = -1; change < CHANGE_COUNT; ++change) { /* first a run with nothing changed */
        if (change >= 0) {
            apply_change(&kept, (tree_change)change);
            apply_change(&anew, (tree_change)change);
        }
        for (int i = 0; i < 12; ++i) {
            anew.world->joint_tree.found = false;
            step(kept.world);
            step(anew.world);
            uint64_t a = rb_world_state_hash(kept.world), b = rb_world_state_hash(anew.world);
            cr_assert_eq(a, b, "after change %d, step %d: kept trees %016llx, found anew %016llx", change, i,
                         (unsigned long long)a, (unsigned long long)b);
        }
    }
    rb_world_destroy(anew.world);
    destroy_world_and_expect_no_leak(kept.world);
}
