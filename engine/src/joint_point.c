/* The point constraint shared by revolute and weld joints: anchor A and
 * anchor B coincide, C = (cB + rB) - (cA + rA) = 0.
 *
 * Its velocity Jacobian gives Cdot = vB + ωB × rB - vA - ωA × rA, and an
 * impulse P at the anchors changes Cdot by K·P with the 2x2 matrix
 *   K = (1/mA + 1/mB)·I + (1/IA)·[rA.y², -rA.x·rA.y; -rA.x·rA.y, rA.x²]
 *                       + (1/IB)·[rB.y², -rB.x·rB.y; -rB.x·rB.y, rB.x²]
 * (expand ω × r for an impulse's angular effect (r × P)/I; Catto,
 * Box2D-Lite, Joint.cpp). */
#include "joint_solver.h"

/* K for anchors ra, rb, and its inverse; returns false when K is singular
 * (neither body can move). */
static bool point_mass_matrix(const rb_joint_frame *f, rb_vec2 ra, rb_vec2 rb, double inverse[3])
{
    double m = f->inv_mass_a + f->inv_mass_b;
    double ia = f->inv_inertia_a;
    double ib = f->inv_inertia_b;
    double k11 = m + ia * ra.y * ra.y + ib * rb.y * rb.y;
    double k12 = -ia * ra.x * ra.y - ib * rb.x * rb.y;
    double k22 = m + ia * ra.x * ra.x + ib * rb.x * rb.x;
    double det = k11 * k22 - k12 * k12;
    if (!(det > 0.0)) {
        return false;
    }
    inverse[0] = k22 / det;
    inverse[1] = -k12 / det;
    inverse[2] = k11 / det;
    return true;
}

static rb_vec2 solve_2x2(const double inverse[3], rb_vec2 v)
{
    return rb_v2(inverse[0] * v.x + inverse[1] * v.y, inverse[1] * v.x + inverse[2] * v.y);
}

void rb_point_constraint_solve(rb_world *world, rb_joint *joint, rb_vec2 *accumulated, double h)
{
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    const rb_joint_frame *f = &joint->frame;
    double inverse[3];
    if (!point_mass_matrix(f, f->ra, f->rb, inverse)) {
        return;
    }
    /* Solve for the velocities that keep the anchors together at the end
     * of the substep, not just momentarily (SHAKE; Ryckaert, Ciccotti,
     * Berendsen, J. Comput. Phys. 23, 1977): the anchor offsets turn with
     * their bodies while the positions advance, each by
     * h·ω × r - ½·(h·ω)²·r to second order, so the gap grows by h times
     * Cdot - ½·h·(ωB²·rB - ωA²·rA). Asking for Cdot alone leaves that
     * centripetal drift for the position pass, which removes it without
     * the matching velocity, and a pendulum then loses energy every
     * swing (Box2D 2.4 loses 86 % of a 90° swing's energy in 200 s).
     *
     * The drift is the curvature of one substep's path: millimetres for
     * any body the solver can follow. A larger one means bodies spin
     * faster than the iterations converge (a light link beside a heavy
     * one), and asking for it then feeds the spin until it explodes; it is
     * capped at one linear slop per substep. */
    rb_vec2 drift = rb_scale(0.5 * h, rb_sub(rb_scale(b->angular_velocity * b->angular_velocity, f->rb),
                                             rb_scale(a->angular_velocity * a->angular_velocity, f->ra)));
    double drift_size = rb_length(drift);
    double drift_cap = world->settings.linear_slop / h;
    if (drift_size > drift_cap) {
        drift = rb_scale(drift_cap / drift_size, drift);
    }
    rb_vec2 cdot = rb_sub(rb_joint_relative_velocity(joint, a, b), drift);
    if (world->settings.position_correction == RB_CORRECTION_BAUMGARTE) {
        rb_vec2 gap = rb_sub(rb_add(b->center, f->rb), rb_add(a->center, f->ra));
        cdot = rb_mul_add(cdot, world->settings.baumgarte / h, gap);
    }
    rb_vec2 impulse = rb_neg(solve_2x2(inverse, cdot));
    *accumulated = rb_add(*accumulated, impulse);
    rb_joint_apply_linear(joint, a, b, impulse);
}

double rb_point_constraint_correct(rb_world *world, rb_joint *joint)
{
    rb_body_state *a = rb_joint_state_a(world, joint);
    rb_body_state *b = rb_joint_state_b(world, joint);
    const rb_joint_frame *f = &joint->frame;
    rb_vec2 ra = rb_rotate(a->rotation, f->local_a);
    rb_vec2 rb = rb_rotate(b->rotation, f->local_b);
    rb_vec2 gap = rb_sub(rb_add(b->center, rb), rb_add(a->center, ra));
    double error = rb_length(gap);
    double inverse[3];
    if (!point_mass_matrix(f, ra, rb, inverse)) {
        return error;
    }
    rb_vec2 impulse = rb_neg(solve_2x2(inverse, gap));
    a->center = rb_mul_sub(a->center, f->inv_mass_a, impulse);
    b->center = rb_mul_add(b->center, f->inv_mass_b, impulse);
    if (f->inv_inertia_a > 0.0) {
        a->angle -= f->inv_inertia_a * rb_cross(ra, impulse);
        a->rotation = rb_rot_from_angle(a->angle);
    }
    if (f->inv_inertia_b > 0.0) {
        b->angle += f->inv_inertia_b * rb_cross(rb, impulse);
        b->rotation = rb_rot_from_angle(b->angle);
    }
    return error;
}
