/* SPDX-License-Identifier: MIT */
/* Soft step (Catto, "Solver2D", 2024, and Box2D v3): every rigid row is
 * solved as a stiff, heavily damped spring, integrated implicitly, so
 * that its push-out is a bounded, damped motion instead of an impulse
 * that depends on how far the iterations converged; substeps give the
 * spring the small time step it needs, and a relax pass after the
 * positions move removes the velocity the push left behind.
 *
 *   prepare the step       contact anchors, normal and masses, fixed for
 *                          the step: the two-point contacts laid four by
 *                          four into blocks within a colour as their
 *                          constraints are made, and prepared by the
 *                          first warm start (contact_blocks.c), the
 *                          others here; each point's separation is
 *                          measured anew from the poses whenever it is
 *                          solved; the joints' masses and anchors in the
 *                          body frames (rb_joints_collect_active)
 *   for each substep of length h = dt / substeps:
 *       substep callback       the user's
 *       integrate velocities
 *       prepare                cables at the poses now, the bodies' spin
 *                              for the joints (and at the first substep,
 *                              find the joint trees and the joints' order)
 *       warm start             the accumulated impulses again, each joint
 *                              prepared at the poses now in the same visit
 *       solve                  velocity_iterations passes with the springs'
 *                              bias: cables, joints, trees' pins, contacts
 *       damp, integrate positions
 *       correct the trees      position_iterations NGS passes over the
 *                              pins of uneven trees (joint_tree.h)
 *       relax                  relax_iterations passes without bias
 *   apply restitution
 *
 * The step's last contact pass (the last relax pass, or the last solve
 * pass where there is none) writes the blocks' impulses into their
 * contacts' manifolds as it goes and, if it is a relax pass, measures
 * their deepest overlap at the final poses (contact_solver.h).
 *
 * The springs are stiff (contact_hertz, joint_hertz) but not beyond a
 * quarter of the substep rate: an implicit spring much stiffer than its
 * step can resolve only damps. Contacts against a body that cannot move
 * carry the whole load alone and get twice the frequency.
 */
#include "cable_solver.h"
#include "contact_solver.h"
#include "joint_solver.h"
#include "joint_tree.h"
#include "solver.h"

/* The springs follow the substep rate up to this fraction of it. */
#define MAX_HERTZ_PER_SUBSTEP_RATE 0.25

static rb_rigid_response spring_for(double hertz, double damping_ratio, double h)
{
    return rb_make_rigid_softness(fmin(hertz, MAX_HERTZ_PER_SUBSTEP_RATE / h), damping_ratio, h);
}

/* Every pass sweeps the joints and the contacts forward: the joints
 * from the free ends to the supports (joint_order.c), the contacts colour
 * by colour; the joints' warm start too. Swept back and forth, the
 * springs' bias re-solved last in one pass what it solved first in the
 * one before: a bottom box of the base-100 pyramid at 6 substeps of 2
 * passes rocked harder each step until it flew, and at Box2D v3's budget,
 * where the biased pass and the relax pass then ran in opposite
 * directions, the 100 x 100 joint grid stretched to 2.79 m. */
#define JOINTS_BACKWARDS false

/* One pass over cables, joints and contacts. */
static void solve_pass(rb_world *world, double h, const rb_contact_softness *contacts)
{
    rb_cables_solve(world, h);
    rb_joints_solve_velocities(world, h, JOINTS_BACKWARDS);
    rb_joint_tree_solve_soft(world);
    rb_contact_solver_solve_soft(world, contacts);
}

rb_solver_counts rb_solve_soft_step(rb_world *world, double dt)
{
    const rb_solver_settings *settings = &world->settings;
    rb_profile *profile = &world->profile;
    int substeps = settings->substeps;
    double h = dt / substeps;
    rb_contact_softness springs = {
        .between_moving = spring_for(settings->contact_hertz, settings->contact_damping_ratio, h),
        .against_fixed = spring_for(2.0 * settings->contact_hertz, settings->contact_damping_ratio, h),
        .max_push_speed = settings->max_push_speed,
        .linear_slop = settings->linear_slop,
        .inv_h = 1.0 / h,
        .use_bias = true,
    };
    rb_contact_softness relax = springs;
    relax.use_bias = false;
    /* The step's last pass writes the blocks' impulses out (velocity
     * iterations are at least 1, so there is always one). */
    bool last_relaxes = settings->relax_iterations > 0;
    rb_contact_softness last = last_relaxes ? relax : springs;
    last.write_back = true;
    last.measure_overlap = last_relaxes; /* after the last positions */
    rb_rigid_response joint_spring = spring_for(settings->joint_hertz, settings->joint_damping_ratio, h);
    rb_rigid_response joint_rigid = {.mass_scale = 1.0};

    double t = rb_world_clock(world);
    rb_contact_solver_prepare_singles(world, h);
    profile->prepare += rb_world_clock(world) - t;

    for (int substep = 0; substep < substeps; ++substep) {
        t = rb_world_clock(world);
        rb_solver_call_substep_callback(world, substep, h);
        t = rb_world_lap(world, &profile->substep_callback, t);
        world->last_substep = h; /* after the callback, which reads the previous substep's forces */

        rb_solver_integrate_velocities(world, h);
        t = rb_world_lap(world, &profile->integrate_velocities, t);

        rb_cables_prepare(world, h);
        if (substep == 0) {
            rb_joints_prepare(world);
            rb_joint_tree_build(world);
            rb_joints_order(world, RB_ORDER_EVERY_JOINT);
            rb_pins_gather(world); /* the plain pins the trees leave, into their rows, in that order */
        }
        rb_cables_warm_start(world);
        rb_joints_warm_start(world, h, JOINTS_BACKWARDS);
        rb_contact_solver_warm_start_blocks(world, substep == 0);
        t = rb_world_lap(world, &profile->warm_start, t);

        world->joint_response = joint_spring;
        for (int iteration = 0; iteration < settings->velocity_iterations; ++iteration) {
            bool is_last = !last_relaxes && substep == substeps - 1 && iteration == settings->velocity_iterations - 1;
            solve_pass(world, h, is_last ? &last : &springs);
        }
        t = rb_world_lap(world, &profile->solve_velocities, t);

        rb_solver_damp_and_integrate_positions(world, h);
        rb_joint_tree_poses_moved(world);
        t = rb_world_lap(world, &profile->integrate_positions, t);

        for (int iteration = 0; iteration < settings->position_iterations; ++iteration) {
            rb_joint_tree_correct_positions(world);
        }
        t = rb_world_lap(world, &profile->correct_positions, t);

        world->joint_response = joint_rigid;
        for (int iteration = 0; iteration < settings->relax_iterations; ++iteration) {
            bool is_last = substep == substeps - 1 && iteration == settings->relax_iterations - 1;
            solve_pass(world, h, is_last ? &last : &relax);
        }
        (void)rb_world_lap(world, &profile->relax, t);
    }

    t = rb_world_clock(world);
    rb_contact_solver_apply_restitution(world, h);
    profile->restitution = rb_world_clock(world) - t;
    return (rb_solver_counts){
        .velocity_iterations = substeps * settings->velocity_iterations,
        .relax_iterations = substeps * settings->relax_iterations,
    };
}
