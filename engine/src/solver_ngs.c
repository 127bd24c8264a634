/* SPDX-License-Identifier: MIT */
/* Sequential impulses with non-linear Gauss-Seidel position passes
 * (Catto, Box2D 2.4; Erleben, "Stable, Robust, and Versatile Multibody
 * Dynamics Animation", 2005, §5): the velocity iterations only stop
 * approach and hold joints, adding no energy; after the positions move,
 * position passes move the bodies directly to close the overlap beyond
 * the slop and the joints' gaps, each step's correction capped. Nothing
 * is left in the velocities, so stacks rest still; the cost is a second
 * kind of pass, and the corrections, being position changes without
 * matching velocities, let a pendulum lose a little energy.
 *
 *   for each substep of length h = dt / substeps:
 *       the sequential substep, contacts unbiased    (solver.c)
 *       correct positions: NGS passes over contacts and joints until
 *           both are within tolerance or position_iterations are done
 *   apply restitution
 */
#include "contact_solver.h"
#include "joint_solver.h"
#include "solver.h"

/* Non-linear Gauss-Seidel position passes over contacts, then joints,
 * until both are within tolerance or the iterations run out; returns the
 * passes done. */
static int correct_positions(rb_world *world)
{
    int passes = 0;
    while (passes < world->settings.position_iterations) {
        ++passes;
        bool contacts_within = rb_contact_solver_correct_positions(world);
        bool joints_within = rb_joints_correct_positions(world, passes % 2 == 0);
        if (contacts_within && joints_within) {
            break;
        }
    }
    return passes;
}

rb_solver_counts rb_solve_ngs(rb_world *world, double dt)
{
    const rb_solver_settings *settings = &world->settings;
    int substeps = settings->substeps;
    double h = dt / substeps;
    world->joint_response = (rb_rigid_response){.mass_scale = 1.0};
    rb_solver_counts counts = {.velocity_iterations = substeps * settings->velocity_iterations};

    for (int substep = 0; substep < substeps; ++substep) {
        rb_solver_sequential_substep(world, substep, h, false);
        double t = rb_world_clock(world);
        counts.position_iterations += correct_positions(world);
        (void)rb_world_lap(world, &world->profile.correct_positions, t);
    }

    double t = rb_world_clock(world);
    rb_contact_solver_apply_restitution(world, h);
    world->profile.restitution = rb_world_clock(world) - t;
    return counts;
}
