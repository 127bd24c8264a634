/* SPDX-License-Identifier: MIT */
/* The frame of every solver's step, and the body phases they share.
 *
 *   prepare contact constraints (surface points, impulses carried over)
 *   the world's solver: its substeps (solver_baumgarte.c, solver_ngs.c,
 *                       solver_soft_step.c), then restitution
 *   store impulses for the next step, measure the deepest overlap left
 *
 * Semi-implicit (symplectic) Euler updates the velocity first and moves
 * the position with the new velocity; unlike explicit Euler it does not
 * pump energy into oscillators (Hairer, Lubich, Wanner, "Geometric
 * Numerical Integration", 2006, §VI.3).
 */
#include "allocator.h"
#include "cable_solver.h"
#include "contact_solver.h"
#include "error.h"
#include "joint_block.h"
#include "joint_solver.h"
#include "joint_tree.h"
#include "solver.h"

/* Lists the bodies the step moves, the dynamic ones first, with the
 * constants of their integration: forces, gravity and settings cannot
 * change within a step, so a body's acceleration is the same in every
 * substep (the same expression, the same bits). The passes below read
 * this list, a few dozen bytes a body, rather than every slot of
 * world->bodies (some 200 bytes each, for sleeping and static bodies
 * too) twice a substep. */
static inline rb_moving_body moving_body(const rb_world *world, int index)
{
    const rb_body *body = &world->bodies[index];
    bool dynamic = body->type == RB_BODY_DYNAMIC; /* a kinematic body moves at its own velocity, undamped */
    return (rb_moving_body){
        .index = index,
        .acceleration = rb_mul_add(rb_scale(body->gravity_scale, world->gravity), body->inv_mass, body->force),
        .inv_inertia = body->inv_inertia,
        .torque = body->torque,
        .linear_damping = dynamic ? body->linear_damping : 0.0,
        .angular_damping = dynamic ? body->angular_damping : 0.0,
    };
}

static bool is_moving(const rb_body *body, rb_body_type type)
{
    return body->in_use && body->awake && body->type == type;
}

static void list_moving_bodies(rb_world *world)
{
    int count = 0;
    int kinematic = 0;
    for (int i = 0; i < world->body_slots; ++i) {
        if (is_moving(&world->bodies[i], RB_BODY_DYNAMIC)) {
            world->moving_bodies[count++] = moving_body(world, i);
        }
        kinematic += is_moving(&world->bodies[i], RB_BODY_KINEMATIC) ? 1 : 0;
    }
    world->moving_dynamic_count = count;
    /* the kinematic bodies after them, in a second pass when there are some */
    for (int i = 0; kinematic > 0 && i < world->body_slots; ++i) {
        if (is_moving(&world->bodies[i], RB_BODY_KINEMATIC)) {
            world->moving_bodies[count++] = moving_body(world, i);
        }
    }
    world->moving_body_count = count;
    world->moving_bodies_stale = false;
}

void rb_solver_integrate_velocities(rb_world *world, double h)
{
    if (world->moving_bodies_stale) {
        list_moving_bodies(world);
    }
    /* The substep's starting angular velocities, recorded while each body
     * is at hand: a pass of their own over every body, every substep,
     * cost the joint grid 3 % of its cache misses. The bodies that do not
     * move keep theirs from the step's first substep (rb_joints_prepare). */
    double *omega = world->substep_omega;
    for (int k = 0; k < world->moving_dynamic_count; ++k) {
        const rb_moving_body *body = &world->moving_bodies[k];
        rb_body_state *state = &world->states[body->index];
        state->linear_velocity = rb_mul_add(state->linear_velocity, h, body->acceleration);
        state->angular_velocity += h * body->inv_inertia * body->torque;
        omega[body->index] = state->angular_velocity;
    }
    for (int k = world->moving_dynamic_count; k < world->moving_body_count; ++k) { /* kinematic */
        int index = world->moving_bodies[k].index;
        omega[index] = world->states[index].angular_velocity;
    }
}

/* Damping: v ← v / (1 + h·c) is the backward-Euler step of dv/dt = −c·v:
 * it never reverses the velocity however large h·c, and it matches
 * exp(−c·h) to first order; with a constant force it gives the exact
 * terminal velocity a/c. It acts after the constraints are solved: a
 * drag exerts nothing on a body at rest, so a supported body must still
 * carry its full weight (damped before the solve, a body with c = 8/s at
 * 600 Hz would load its supports with m·g/(1 + h·c), 1.3 % short). A
 * kinematic body is listed with no damping, and an undamped body skips
 * the division by 1, which would leave every bit as it is. */
void rb_solver_damp_and_integrate_positions(rb_world *world, double h)
{
    if (world->moving_bodies_stale) {
        list_moving_bodies(world);
    }
    for (int k = 0; k < world->moving_body_count; ++k) {
        const rb_moving_body *body = &world->moving_bodies[k];
        rb_body_state *state = &world->states[body->index];
        if (body->linear_damping != 0.0) {
            state->linear_velocity = rb_scale(1.0 / (1.0 + h * body->linear_damping), state->linear_velocity);
        }
        if (body->angular_damping != 0.0) {
            state->angular_velocity /= 1.0 + h * body->angular_damping;
        }
        state->center = rb_mul_add(state->center, h, state->linear_velocity);
        if (state->angular_velocity != 0.0) {
            rb_body_state_turn(state, h * state->angular_velocity);
        }
    }
}

void rb_solver_call_substep_callback(rb_world *world, int substep, double h)
{
    rb_cables_locate(world); /* the paths the callback reads and the cables' preparation share */
    if (world->substep_callback != NULL) {
        world->in_substep_callback = true;
        world->substep_callback(world, substep, h, world->substep_context);
        world->in_substep_callback = false;
    }
}

void rb_solver_sequential_substep(rb_world *world, int substep, double h, bool contact_bias)
{
    rb_profile *profile = &world->profile;
    double t = rb_world_clock(world);
    rb_solver_call_substep_callback(world, substep, h);
    t = rb_world_lap(world, &profile->substep_callback, t);
    world->last_substep = h; /* after the callback, which reads the previous substep's forces */

    rb_solver_integrate_velocities(world, h);
    t = rb_world_lap(world, &profile->integrate_velocities, t);

    rb_cables_prepare(world, h);
    if (substep == 0) {
        rb_joints_prepare(world);
        rb_joint_tree_build(world);
        rb_joints_order(world, RB_ORDER_PLAIN_PINS);
        rb_pins_gather(world); /* the plain pins the trees leave, into their rows, in that order */
    }
    rb_contact_solver_prepare_substep(world, h,
                                      (rb_substep_rows){.first_substep = substep == 0,
                                                        .baumgarte_bias = contact_bias,
                                                        .block_normals = world->settings.block_solver});
    rb_cables_warm_start(world);
    rb_joints_warm_start(world, h, false);
    rb_joint_tree_start_substep(world);
    rb_joint_blocks_factor(world, h);
    rb_contact_solver_warm_start(world);
    t = rb_world_lap(world, &profile->warm_start, t);

    for (int iteration = 0; iteration < world->settings.velocity_iterations; ++iteration) {
        rb_cables_solve(world, h);
        bool backwards = iteration % 2 == 1;
        rb_joints_solve_velocities(world, h, backwards);
        rb_joint_tree_solve_velocities(world);
        rb_joint_blocks_solve_velocities(world);
        rb_contact_solver_solve_velocities(world, backwards && !contact_bias);
    }
    t = rb_world_lap(world, &profile->solve_velocities, t);

    rb_solver_damp_and_integrate_positions(world, h);
    (void)rb_world_lap(world, &profile->integrate_positions, t);
}

rb_status rb_solver_step(rb_world *world, double dt)
{
    rb_profile *profile = &world->profile;
    double t = rb_world_clock(world);
    if (rb_grow_array((void **)&world->moving_bodies, &world->moving_body_capacity, world->body_slots,
                      sizeof *world->moving_bodies) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the list of moving bodies");
    }
    list_moving_bodies(world);
    profile->integrate_velocities += rb_world_clock(world) - t;

    t = rb_world_clock(world);
    if (rb_contact_solver_prepare(world) < 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for contact constraints");
    }
    RB_TRY(rb_joints_collect_active(world));
    rb_joint_blocks_build(world); /* before the trees, which leave its pins to it */
    rb_cables_prepare_step(world);
    profile->prepare = rb_world_clock(world) - t;

    if (!world->settings.warm_starting) {
        rb_joints_reset_impulses(world);
        rb_cables_reset_impulses(world);
    }

    /* NGS and the soft step solve the pins of joint trees together
     * (joint_tree.h). */
    world->joint_tree.enabled = world->settings.type != RB_SOLVER_BAUMGARTE && world->settings.tree_pins;
    rb_solver_counts counts = {0};
    switch (world->settings.type) {
    case RB_SOLVER_BAUMGARTE:
        counts = rb_solve_baumgarte(world, dt);
        break;
    case RB_SOLVER_NGS:
        counts = rb_solve_ngs(world, dt);
        break;
    case RB_SOLVER_SOFT_STEP:
    case RB_SOLVER_TYPE_COUNT:
        counts = rb_solve_soft_step(world, dt);
        break;
    }

    t = rb_world_clock(world);
    rb_pins_scatter(world);
    world->statistics.max_penetration = rb_contact_solver_store_impulses(world);
    profile->store_impulses = rb_world_clock(world) - t;

    world->statistics.velocity_iterations = counts.velocity_iterations;
    world->statistics.position_iterations = counts.position_iterations;
    world->statistics.relax_iterations = counts.relax_iterations;
    return RB_OK;
}
