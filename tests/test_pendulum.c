/* SPDX-License-Identifier: MIT */
/* The analytic pendulum suite: periods of simple and compound pendulums
 * against the exact period, energy over 100 periods, and a double
 * pendulum of two rods against its Lagrangian equations integrated by GSL.
 *
 * Exact period. A rigid body turning about a fixed pivot, its centre of
 * mass at distance d from the pivot, obeys I_p·θ'' = -m·g·d·sin θ, θ the
 * angle of the centre of mass from the downward vertical and
 * I_p = I_cm + m·d² its inertia about the pivot. Released from rest at θ0
 * it swings with the period
 *     T = 4·sqrt(I_p/(m·g·d))·K(k),   k = sin(θ0/2),
 * K the complete elliptic integral of the first kind of modulus k (GSL's
 * gsl_sf_ellint_Kcomp takes the modulus k, not the parameter k²). The
 * small-angle period 2π·sqrt(I_p/(m·g·d)) is already 0.05 % short at 5°
 * and is not used.
 *
 * The period is measured from the zero crossings of θ: each is placed by
 * linear interpolation between the two steps around it (θ'' = 0 where
 * θ = 0, so the interpolation error is of third order in the step), and
 * the period is twice the time from the first to the last crossing over
 * the number of half periods between them.
 *
 * Tolerances. Semi-implicit Euler (the engine's integrator) with substeps
 * of h turns an oscillator of angular frequency ω into one of frequency Ω
 * with cos(Ω·h) = 1 - (ω·h)²/2, a relative period error of (ω·h)²/24: at
 * most (one substep a step, h = 1/240 s) 7e-6 for a 1 m pendulum and
 * 1.1e-5 for the rod below, 16 times less with 4 substeps. At small amplitude
 * the tests ask for 1e-4, ten times that and tighter than the required
 * 0.1 %, which would let pass an inertia error as large as forgetting the
 * bob's own I_cm (0.06 % of the period here). At 90° and 150° the required
 * 0.2 % stands: there a solver that loses energy each step shortens the
 * period as the amplitude shrinks, by several per cent for a plain
 * projection of the velocities (Box2D 2.4's).
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>

#include "test_support.h"

#define G 9.8 /* m/s², the world's gravity is (0, -G) */
#define DT_240 (1.0 / 240.0)

static double radians(double degrees) { return degrees * RB_PI / 180.0; }

static double exact_period(double pivot_inertia, double mass, double distance, double theta0)
{
    return 4.0 * sqrt(pivot_inertia / (mass * G * distance)) * gsl_sf_ellint_Kcomp(sin(0.5 * theta0), GSL_PREC_DOUBLE);
}

/* A static body at the origin, the pivot, and a dynamic body whose origin
 * is at `distance` from it at angle θ0 from the downward vertical, turned
 * by θ0. The caller centres the bob's shape on the body origin, then pins
 * it with make_pin(). */
typedef struct pendulum {
    rb_world *world;
    rb_body_id ground, bob;
} pendulum;

static pendulum make_pendulum(double theta0, double distance)
{
    pendulum p = {.world = make_world(rb_v2(0.0, -G))};
    p.ground = make_body(p.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    p.bob = make_body(p.world, RB_BODY_DYNAMIC, rb_v2(distance * sin(theta0), -distance * cos(theta0)), theta0);
    return p;
}

/* θ: the angle of the bob's centre of mass from the downward vertical
 * through the pivot (rad, counter-clockwise positive). */
static double swing_angle(const pendulum *p)
{
    const rb_vec2 c = rb_body_world_center(p->world, p->bob);
    return atan2(c.x, -c.y);
}

/* Steps at dt until θ has crossed zero half_periods + 1 times and returns
 * the period measured between the first and the last crossing. */
static double measure_period(const pendulum *p, double dt, int half_periods, double expected_period)
{
    /* About twice the time the crossings need: an engine whose period is
     * that far off has failed anyway. */
    const int max_steps = (int)ceil((half_periods + 1) * expected_period / dt);
    double previous = swing_angle(p);
    double first = 0.0, last = 0.0;
    int crossings = 0;
    for (int n = 1; n <= max_steps && crossings <= half_periods; ++n) {
        step_world(p->world, dt, 1);
        const double theta = swing_angle(p);
        if ((previous > 0.0) != (theta > 0.0)) {
            const double t = (n - 1) * dt + dt * previous / (previous - theta);
            if (crossings == 0) {
                first = t;
            }
            last = t;
            ++crossings;
        }
        previous = theta;
    }
    cr_assert_eq(crossings, half_periods + 1, "θ crossed zero %d times in %d steps, expected %d", crossings, max_steps,
                 half_periods + 1);
    return 2.0 * (last - first) / half_periods;
}

static void expect_period(double measured, double exact, double tolerance, const char *what)
{
    cr_expect(fabs(measured - exact) <= tolerance * exact,
              "%s: period %.9f s, exact %.9f s, relative error %.3g (tolerance %g)", what, measured, exact,
              (measured - exact) / exact, tolerance);
}

/* A simple pendulum: a small dense circle (radius r, density ρ, so
 * m = ρ·π·r² and I_cm = m·r²/2) at L = 1 m from the pivot, its period over
 * five periods at 240 Hz. */
static void check_simple_pendulum(double theta0_degrees, double tolerance, const char *what)
{
    const double L = 1.0, r = 0.05, rho = 100.0;
    const double theta0 = radians(theta0_degrees);
    pendulum p = make_pendulum(theta0, L);
    add_circle(p.world, p.bob, rb_v2(0.0, 0.0), r, rho);
    make_pin(p.world, p.ground, p.bob, rb_v2(0.0, 0.0));
    const double m = rho * RB_PI * r * r;
    const double exact = exact_period(0.5 * m * r * r + m * L * L, m, L, theta0);
    expect_period(measure_period(&p, DT_240, 10, exact), exact, tolerance, what);
    destroy_world_and_expect_no_leak(p.world);
}

Test(pendulum, simple_at_5_degrees) { check_simple_pendulum(5.0, 1e-4, "simple pendulum, 5°"); }

Test(pendulum, simple_at_90_degrees) { check_simple_pendulum(90.0, 2e-3, "simple pendulum, 90°"); }

Test(pendulum, simple_at_150_degrees) { check_simple_pendulum(150.0, 2e-3, "simple pendulum, 150°"); }

/* A compound pendulum: a box rod of length ℓ and width w pivoted at the
 * middle of one end. Its centre of mass is at d = ℓ/2 from the pivot and
 * I_p = m·(ℓ² + w²)/12 + m·(ℓ/2)² (the box's own inertia plus the parallel
 * axis term), so T = 4·sqrt(I_p/(m·g·ℓ/2))·K(sin(θ0/2)); released at 30°,
 * within 1e-4 as the simple pendulum at 5°. */
Test(pendulum, compound_rod_at_30_degrees)
{
    const double length = 1.0, width = 0.05, rho = 1.0;
    const double theta0 = radians(30.0);
    pendulum p = make_pendulum(theta0, 0.5 * length);
    add_box(p.world, p.bob, 0.5 * width, 0.5 * length, rho);
    make_pin(p.world, p.ground, p.bob, rb_v2(0.0, 0.0));
    const double m = rho * length * width;
    const double inertia = m * (length * length + width * width) / 12.0 + m * 0.25 * length * length;
    const double exact = exact_period(inertia, m, 0.5 * length, theta0);
    expect_period(measure_period(&p, DT_240, 10, exact), exact, 1e-4, "box rod pivoted at its end, 30°");
    destroy_world_and_expect_no_leak(p.world);
}

/* Energy over 100 periods of a simple pendulum released at 30°, at 240 Hz:
 *     E = ½·m·|v|² + ½·I_cm·ω² + m·g·(y - y_low),
 * v the velocity of the bob's centre of mass, ω its angular velocity, and
 * the potential measured from y_low = -L, the lowest point of the centre's
 * path, so that E0 = m·g·L·(1 - cos θ0) (the bob starts at rest).
 *
 * Semi-implicit Euler does not conserve E exactly even when it keeps the
 * motion on its orbit: for an oscillator of frequency ω and substeps of h
 * it conserves a nearby quadratic form, E_n = Ẽ + ½·h·ω²·I_p·θ_n·θ'_n, so E
 * oscillates about E0 (θ' = 0 at release) with relative amplitude ω·h/2
 * and no drift. With one substep a step (h = 1/240 s) a 1 m pendulum gives
 * 0.65 %, above the required 0.5 % bound however good the solver; with
 * L = 4 m (ω = 1.57 rad/s) it is at most 0.33 %, which leaves room for the
 * joint solver whatever the number of substeps. The second check, the
 * mean of the last 10 periods against the mean of the first 10 within
 * 0.1 %, averages that oscillation away and catches a secular gain or
 * loss. */
Test(pendulum, energy_over_100_periods)
{
    const double L = 4.0, r = 0.05, rho = 100.0;
    const double theta0 = radians(30.0);
    pendulum p = make_pendulum(theta0, L);
    add_circle(p.world, p.bob, rb_v2(0.0, 0.0), r, rho);
    make_pin(p.world, p.ground, p.bob, rb_v2(0.0, 0.0));
    const double m = rho * RB_PI * r * r;
    const double inertia = 0.5 * m * r * r;
    const double period = exact_period(inertia + m * L * L, m, L, theta0);
    const long steps_per_10 = lround(10.0 * period / DT_240);
    const long steps = 10 * steps_per_10;
    const double e0 = m * G * L * (1.0 - cos(theta0));

    double worst = 0.0, first_sum = 0.0, last_sum = 0.0;
    long worst_step = 0;
    for (long n = 1; n <= steps; ++n) {
        step_world(p.world, DT_240, 1);
        const rb_vec2 v = rb_body_linear_velocity(p.world, p.bob);
        const double omega = rb_body_angular_velocity(p.world, p.bob);
        const double y = rb_body_world_center(p.world, p.bob).y;
        const double e = 0.5 * m * rb_dot(v, v) + 0.5 * inertia * omega * omega + m * G * (y + L);
        /* The world's own count, whose potential is zero at y = 0. */
        const double reported = rb_world_statistics(p.world).energy + m * G * L;
        cr_assert(fabs(reported - e) <= 1e-9 * e0, "step %ld: the world reports %.12g J, the bob has %.12g J", n,
                  reported, e);
        if (fabs(e - e0) > worst) {
            worst = fabs(e - e0);
            worst_step = n;
        }
        if (n <= steps_per_10) {
            first_sum += e;
        } else if (n > steps - steps_per_10) {
            last_sum += e;
        }
    }
    cr_expect(worst <= 5e-3 * e0, "|E - E0|/E0 reached %.3g at step %ld (t = %.2f s), above 0.5 %%", worst / e0,
              worst_step, worst_step * DT_240);
    const double first_mean = first_sum / steps_per_10, last_mean = last_sum / steps_per_10;
    cr_expect(fabs(last_mean - first_mean) <= 1e-3 * first_mean,
              "mean energy of the last 10 periods %.9g J, of the first 10 %.9g J: relative drift %.3g, above 0.1 %%",
              last_mean, first_mean, (last_mean - first_mean) / first_mean);
    destroy_world_and_expect_no_leak(p.world);
}

/* ---- Double pendulum ------------------------------------------------------- */

/* Two uniform rods (boxes) hang from a pivot at the origin: rod i has mass
 * m_i, length l_i and inertia I_i about its centre (m_i·l_i²/12 for a
 * thin rod; the box of width w adds m_i·w²/12). φ_i is the angle of rod i
 * from the downward vertical, counter-clockwise. The centres are
 *     c1 = (l1/2)·(sin φ1, -cos φ1),
 *     c2 = l1·(sin φ1, -cos φ1) + (l2/2)·(sin φ2, -cos φ2),
 * so
 *     |c1'|² = (l1/2)²·φ1'²,
 *     |c2'|² = l1²·φ1'² + (l2/2)²·φ2'² + l1·l2·cos(φ1 - φ2)·φ1'·φ2',
 *     T = ½·m1·|c1'|² + ½·I1·φ1'² + ½·m2·|c2'|² + ½·I2·φ2'²,
 *     V = -m1·g·(l1/2)·cos φ1 - m2·g·(l1·cos φ1 + (l2/2)·cos φ2).
 * With a = m2·l1·l2/2, Lagrange's equations d/dt ∂T/∂φi' - ∂T/∂φi + ∂V/∂φi = 0
 * give M·φ'' = f:
 *     M11 = m1·l1²/4 + I1 + m2·l1²,  M12 = M21 = a·cos(φ1 - φ2),  M22 = m2·l2²/4 + I2,
 *     f1 = -a·sin(φ1 - φ2)·φ2'² - (m1/2 + m2)·g·l1·sin φ1,
 *     f2 =  a·sin(φ1 - φ2)·φ1'² - m2·g·(l2/2)·sin φ2.
 * (A point-mass double pendulum would have I_i = 0 and the masses at the
 * rods' ends: a different system.) */
typedef struct rods {
    double m1, l1, i1, m2, l2, i2;
} rods;

static int rods_derivatives(double t, const double y[], double dydt[], void *params)
{
    (void)t;
    const rods *r = params;
    const double a = r->m2 * r->l1 * r->l2 / 2.0;
    const double c = cos(y[0] - y[1]), s = sin(y[0] - y[1]);
    const double m11 = r->m1 * r->l1 * r->l1 / 4.0 + r->i1 + r->m2 * r->l1 * r->l1;
    const double m12 = a * c;
    const double m22 = r->m2 * r->l2 * r->l2 / 4.0 + r->i2;
    const double f1 = -a * s * y[3] * y[3] - (r->m1 / 2.0 + r->m2) * G * r->l1 * sin(y[0]);
    const double f2 = a * s * y[2] * y[2] - r->m2 * G * (r->l2 / 2.0) * sin(y[1]);
    const double det = m11 * m22 - m12 * m12;
    dydt[0] = y[2];
    dydt[1] = y[3];
    dydt[2] = (f1 * m22 - m12 * f2) / det;
    dydt[3] = (m11 * f2 - m12 * f1) / det;
    return GSL_SUCCESS;
}

/* A box rod of half-extents (w/2, l/2), density ρ, hanging from `top` at
 * angle φ from the downward vertical. */
static rb_body_id make_rod(rb_world *world, rb_vec2 top, double phi, double length, double width, double rho)
{
    const rb_vec2 centre = rb_add(top, rb_v2(0.5 * length * sin(phi), -0.5 * length * cos(phi)));
    rb_body_id rod = make_body(world, RB_BODY_DYNAMIC, centre, phi);
    add_box(world, rod, 0.5 * width, 0.5 * length, rho);
    return rod;
}

/* Released from rest at φ1 = 45°, φ2 = 90° and stepped at 1 kHz for one
 * second; the reference is GSL's rk8pd with absolute and relative
 * tolerances 1e-12, sampled at every step.
 *
 * Tolerances (required): joint angles within 1°, energy (potential from
 * each rod's lowest position, so E0 > 0) within 0.5 % of E0 at every step.
 * A first-order symplectic integrator with (sub)steps of h <= 1 ms lags
 * the true angles by about ½·h·|φ'| (φ' up to 5 rad/s here: at most 0.14°)
 * and its energy oscillates by about ½·h·|φ'| relative (at most 0.25 %),
 * so these bounds leave room for the iterative joint solver; from higher
 * releases the rods turn faster and the integrator's own energy error
 * would approach 0.5 % with one substep a step. */
Test(pendulum, double_pendulum_of_two_rods_against_lagrange)
{
    const double length = 1.0, width = 0.05, rho = 1.0, h = 1e-3;
    const double m = rho * length * width;
    const double inertia = m * (length * length + width * width) / 12.0;
    rods r = {.m1 = m, .l1 = length, .i1 = inertia, .m2 = m, .l2 = length, .i2 = inertia};
    const double phi1 = radians(45.0), phi2 = radians(90.0);

    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    const rb_vec2 elbow = rb_v2(length * sin(phi1), -length * cos(phi1));
    rb_body_id rod1 = make_rod(world, rb_v2(0.0, 0.0), phi1, length, width, rho);
    rb_body_id rod2 = make_rod(world, elbow, phi2, length, width, rho);
    rb_joint_id shoulder = make_pin(world, ground, rod1, rb_v2(0.0, 0.0));
    rb_joint_id knee = make_pin(world, rod1, rod2, elbow);

    gsl_odeiv2_system system = {.function = rods_derivatives, .jacobian = NULL, .dimension = 4, .params = &r};
    gsl_odeiv2_driver *driver = gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-6, 1e-12, 1e-12);
    cr_assert_not_null(driver, "gsl_odeiv2_driver_alloc_y_new failed");
    double y[4] = {phi1, phi2, 0.0, 0.0};
    double t = 0.0;

    /* Potential from the lowest positions of the centres, -l1/2 and -l1 - l2/2. */
    const rb_body_id bodies[2] = {rod1, rod2};
    const double lowest[2] = {-0.5 * length, -1.5 * length};
    const double e0 = m * G * 0.5 * length * (1.0 - cos(phi1)) +
                      m * G * (length * (1.0 - cos(phi1)) + 0.5 * length * (1.0 - cos(phi2)));
    double worst_angle = 0.0, worst_energy = 0.0;
    int worst_angle_step = 0, worst_energy_step = 0;
    for (int n = 1; n <= 1000; ++n) {
        step_world(world, h, 1);
        cr_assert_eq(gsl_odeiv2_driver_apply(driver, &t, n * h, y), GSL_SUCCESS, "GSL integration failed at step %d",
                     n);
        /* A joint angle is angle(B) - angle(A) minus its value at creation. */
        const double expected[2] = {y[0] - phi1, (y[1] - y[0]) - (phi2 - phi1)};
        const double measured[2] = {rb_revolute_joint_angle(world, shoulder), rb_revolute_joint_angle(world, knee)};
        double e = 0.0;
        for (int i = 0; i < 2; ++i) {
            if (fabs(measured[i] - expected[i]) > worst_angle) {
                worst_angle = fabs(measured[i] - expected[i]);
                worst_angle_step = n;
            }
            const rb_vec2 v = rb_body_linear_velocity(world, bodies[i]);
            const double omega = rb_body_angular_velocity(world, bodies[i]);
            const double height = rb_body_world_center(world, bodies[i]).y - lowest[i];
            e += 0.5 * m * rb_dot(v, v) + 0.5 * inertia * omega * omega + m * G * height;
        }
        if (fabs(e - e0) / e0 > worst_energy) {
            worst_energy = fabs(e - e0) / e0;
            worst_energy_step = n;
        }
    }
    cr_expect(worst_angle <= radians(1.0), "a joint angle was %.3f° from the Lagrange reference at step %d",
              worst_angle * 180.0 / RB_PI, worst_angle_step);
    cr_expect(worst_energy <= 5e-3, "|E - E0|/E0 reached %.3g at step %d", worst_energy, worst_energy_step);
    gsl_odeiv2_driver_free(driver);
    destroy_world_and_expect_no_leak(world);
}
