/* SPDX-License-Identifier: MIT */
/* Sequential impulses with Baumgarte stabilisation (Baumgarte,
 * "Stabilization of constraints and integrals of motion in dynamical
 * systems", Comput. Methods Appl. Mech. Eng. 1, 1972; Catto, Box2D 2.0):
 * the position error C of each constraint feeds back into its velocity
 * target, Cdot = -β·C/h, so the velocity iterations that stop bodies
 * approaching also push them apart. One pass of work per iteration and
 * no position pass, but the push leaves velocity behind: stacks jitter
 * and bounce a little, and a chain of very unequal masses whose joints
 * cannot converge in the iterations given gains energy from the bias
 * until it diverges. Use it to see what the other two solvers fix.
 *
 *   for each substep of length h = dt / substeps:
 *       the sequential substep, contacts biased    (solver.c)
 *   apply restitution
 *
 * Contacts push out β·(overlap - slop) per substep, capped at
 * max_linear_correction; joints remove β of their error per step of dt
 * (per substep the fractions would compound with warm starting until a
 * hanging chain diverges).
 */
#include "contact_solver.h"
#include "solver.h"

rb_solver_counts rb_solve_baumgarte(rb_world *world, double dt)
{
    const rb_solver_settings *settings = &world->settings;
    int substeps = settings->substeps;
    double h = dt / substeps;
    world->joint_response = (rb_rigid_response){.bias_rate = settings->baumgarte / dt, .mass_scale = 1.0};

    for (int substep = 0; substep < substeps; ++substep) {
        rb_solver_sequential_substep(world, substep, h, true);
    }

    double t = rb_world_clock(world);
    rb_contact_solver_apply_restitution(world, h);
    world->profile.restitution = rb_world_clock(world) - t;
    return (rb_solver_counts){.velocity_iterations = substeps * settings->velocity_iterations};
}
