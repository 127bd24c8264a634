/* SPDX-License-Identifier: MIT */
/* The compliant tendon: Thelen's curve against his own formula, the
 * muscle's static equilibrium (fibre force·cos α = tendon force, computed
 * here from the readout's lengths with the test's own copy of the curves'
 * formulas), the approach to the rigid tendon as the tendon stiffens, the
 * dynamic fibre settling on the static equilibrium, and stability with
 * activation dynamics while a mass swings on the muscle.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/muscle.h"
#include "mu/tendon.h"
#include "test_support.h"

#define FMAX 1000.0
#define REST 0.2  /* l_opt, m */
#define SLACK 0.1 /* tendon slack length, m */
#define H (1.0 / 600.0)

/* Thelen 2003, eq. 4, with his published (rounded) constants. */
static double thelen_published(double strain, double e0)
{
    if (strain <= 0.0) {
        return 0.0;
    }
    const double toe = 0.609 * e0;
    if (strain <= toe) {
        return 0.333 / (exp(3.0) - 1.0) * (exp(3.0 * strain / toe) - 1.0);
    }
    return 1.712 / e0 * (strain - toe) + 0.333;
}

/* The same curve with the exactly joined constants (tendon.h). */
static double thelen_joined(double strain, double e0)
{
    const double a = 0.333 * 3.0 * exp(3.0) / (exp(3.0) - 1.0);
    const double toe = a * e0 / (a + 0.667);
    if (strain <= 0.0) {
        return 0.0;
    }
    if (strain <= toe) {
        return 0.333 / (exp(3.0) - 1.0) * (exp(3.0 * strain / toe) - 1.0);
    }
    return 0.333 + (a + 0.667) / e0 * (strain - toe);
}

Test(tendon, curve_is_thelens)
{
    const double e0 = MU_DEFAULT_TENDON_STRAIN_AT_MAX_FORCE;
    expect_near(e0, 0.049, 0.0, "default strain at Fmax");
    expect_near(mu_tendon_force(e0, e0), 1.0, 1e-12, "f_T(ε0) = 1");
    expect_near(mu_tendon_force(0.0, e0), 0.0, 0.0, "slack at 0");
    expect_near(mu_tendon_force(-0.01, e0), 0.0, 0.0, "a slack tendon does not push");
    expect_near(mu_tendon_stiffness(-0.01, e0), 0.0, 0.0, "no stiffness while slack");
    for (int i = 1; i <= 40; ++i) {
        const double strain = 0.002 * i;
        const double f = mu_tendon_force(strain, e0);
        expect_near(f, thelen_joined(strain, e0), 1e-12, "the joined curve");
        /* Within 1 % of Fmax of Thelen's rounded constants. */
        expect_near(f, thelen_published(strain, e0), 0.01, "Thelen's published curve");
        /* The stiffness against a central difference. */
        const double d = 1e-7;
        expect_near(mu_tendon_stiffness(strain, e0),
                    (mu_tendon_force(strain + d, e0) - mu_tendon_force(strain - d, e0)) / (2.0 * d), 1e-5,
                    "slope against a central difference");
    }
    /* C¹ at the toe's end: the slope just below equals the slope just above. */
    const double toe = 0.611835423 * e0;
    expect_near(mu_tendon_stiffness(toe * (1.0 - 1e-9), e0), mu_tendon_stiffness(toe * (1.0 + 1e-9), e0), 1e-5,
                "slope continuous at the toe");
    cr_expect(isnan(mu_tendon_force(NAN, e0)));
    cr_expect(isnan(mu_tendon_force(0.01, 0.0)));
    cr_expect(strstr(rb_last_error(), "mu_tendon_force") != NULL, "%s", rb_last_error());
}

static mu_curves *tables(void)
{
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &curves), RB_OK, "%s", rb_last_error());
    return curves;
}

/* A muscle from the origin (static) to `insertion` at (path, 0), l_opt
 * 0.2 m, Fmax 1000 N, tendon (slack) length 0.1 m. */
static mu_muscle *make_muscle(rb_world *world, rb_body_id origin, rb_body_id insertion, const mu_curves *curves,
                              bool compliant, double strain_at_max_force, double pennation)
{
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = origin;
    def.bodies[1] = insertion;
    def.rest_length = REST;
    def.max_force = FMAX;
    def.tendon_length = SLACK;
    def.curves = curves;
    def.compliant_tendon = compliant;
    def.tendon_strain_at_max_force = strain_at_max_force;
    def.pennation_angle = pennation;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    return muscle;
}

/* |fibre force·cos α - tendon force| over Fmax at the readout's state, at
 * rest, computed from its lengths: the fibre's force from the curves and
 * the activation, cos α from the fixed width, the tendon's force from the
 * test's own curve at the tendon length path - l_f·cos α. */
static double imbalance(const mu_muscle_readout *r, const mu_curves *curves, double path, double pennation, double e0)
{
    const double l = r->fibre_length / REST;
    const double fibre = FMAX * (r->activation * mu_curve_active_length(curves, l) * mu_curve_velocity(curves, 0.0) +
                                 mu_curve_passive_length(curves, l));
    const double width = REST * sin(pennation);
    const double cosine = sqrt(1.0 - (width / r->fibre_length) * (width / r->fibre_length));
    const double tendon_length = path - r->fibre_length * cosine;
    expect_near(r->tendon_length, tendon_length, 1e-12, "readout tendon length");
    expect_near(cos(r->pennation_angle), cosine, 1e-12, "readout pennation angle");
    const double tendon = FMAX * thelen_joined((tendon_length - SLACK) / SLACK, e0);
    return fabs(fibre * cosine - tendon) / FMAX;
}

Test(tendon, static_equilibrium_balances_fibre_and_tendon)
{
    /* Path lengths from a slack muscle (0.16 m: the tendon slack even with
     * a short fibre) through the ascending limb's end (fibre near 0.5 l_opt
     * under full activation) to far beyond the curves' ends (0.45 m: the
     * fibre where the tables stop, the tendon far into its linear part),
     * at activations 0 to 1, without and with 25° of pennation. */
    mu_curves *curves = tables();
    const double paths[] = {0.16, 0.22, 0.28, 0.3, 0.33, 0.38, 0.45};
    const double activations[] = {0.0, 0.05, 0.5, 1.0};
    const double pennations[] = {0.0, 25.0 * RB_PI / 180.0};
    double worst = 0.0;
    for (size_t p = 0; p < 2; ++p) {
        for (size_t i = 0; i < sizeof paths / sizeof *paths; ++i) {
            rb_world *world = make_world(rb_v2(0.0, 0.0));
            rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
            rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(paths[i], 0.0), 0.0);
            mu_muscle *muscle = make_muscle(world, origin, insertion, curves, true, 0.049, pennations[p]);
            /* At creation: the equilibrium at activation 0. */
            mu_muscle_readout r = mu_muscle_read(muscle);
            worst = fmax(worst, imbalance(&r, curves, paths[i], pennations[p], 0.049));
            for (size_t a = 0; a < sizeof activations / sizeof *activations; ++a) {
                cr_assert_eq(mu_muscle_set_activation(muscle, activations[a]), RB_OK);
                cr_assert_eq(mu_muscle_solve_equilibrium(muscle, world), RB_OK);
                r = mu_muscle_read(muscle);
                const double e = imbalance(&r, curves, paths[i], pennations[p], 0.049);
                cr_expect(e <= 1e-6, "path %g m, a %g, pennation %g: imbalance %g Fmax (fibre %g m)", paths[i],
                          activations[a], pennations[p], e, r.fibre_length);
                worst = fmax(worst, e);
                cr_expect(r.fibre_length >= 0.01 * REST && r.tendon_length > 0.0, "lengths %g, %g", r.fibre_length,
                          r.tendon_length);
                cr_expect(r.pennation_angle < MU_MAX_PENNATION_ANGLE + 1e-12);
            }
            mu_muscle_destroy(muscle, world);
            destroy_world_and_expect_no_leak(world);
        }
    }
    cr_log_info("worst static imbalance %g Fmax", worst);
    mu_curves_destroy(curves);
}

/* The static force at path 0.31 m and activation 1 with a tendon of
 * strain e0 at Fmax, or rigid (e0 < 0). */
static double static_force(const mu_curves *curves, double e0)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(0.31, 0.0), 0.0);
    mu_muscle *muscle = make_muscle(world, origin, insertion, curves, e0 > 0.0, e0 > 0.0 ? e0 : 0.049, 0.0);
    cr_assert_eq(mu_muscle_set_activation(muscle, 1.0), RB_OK);
    cr_assert_eq(mu_muscle_solve_equilibrium(muscle, world), RB_OK);
    const double force = mu_muscle_read(muscle).total_force;
    mu_muscle_destroy(muscle, world);
    destroy_world_and_expect_no_leak(world);
    return force;
}

Test(tendon, a_stiff_tendon_approaches_the_rigid_one)
{
    /* At path 0.31 m the rigid muscle's belly is 0.21 m (l̃ = 1.05, on the
     * plateau's descending side, with some passive force). A compliant
     * tendon stretches, the fibre shortens, and the force differs; the
     * difference shrinks in proportion to ε0. */
    mu_curves *curves = tables();
    const double rigid = static_force(curves, -1.0);
    double previous = INFINITY;
    const double strains[] = {0.049, 4.9e-3, 4.9e-4, 4.9e-5, 4.9e-6};
    for (size_t i = 0; i < sizeof strains / sizeof *strains; ++i) {
        const double difference = fabs(static_force(curves, strains[i]) - rigid);
        cr_expect(difference < previous, "ε0 %g: |F - F_rigid| = %g N did not shrink (was %g)", strains[i], difference,
                  previous);
        previous = difference;
    }
    cr_expect(previous < 1e-3 * rigid, "ε0 = 4.9e-6: the force %g N from the rigid %g N", previous, rigid);
    mu_curves_destroy(curves);
}

/* A world whose step is one engine substep, as the models make it: the
 * muscle's law is set for each substep. */
static rb_world *substep_world(rb_vec2 gravity)
{
    rb_world *world = make_world(gravity);
    set_substeps(world, 1);
    return world;
}

/* A 2 kg mass hanging on the muscle under gravity from a static origin;
 * returns the muscle and the body. */
static mu_muscle *hanging(rb_world *world, const mu_curves *curves, bool compliant, double e0, double damping,
                          bool dynamics, rb_body_id *body)
{
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    *body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -0.3), 0.0);
    const rb_mass_data data = {2.0, {0.0, 0.0}, 0.0};
    cr_assert_eq(rb_body_set_mass_data(world, *body, &data), RB_OK);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = origin;
    def.bodies[1] = *body;
    def.rest_length = REST;
    def.max_force = FMAX;
    def.tendon_length = SLACK;
    def.curves = curves;
    def.compliant_tendon = compliant;
    def.tendon_strain_at_max_force = e0;
    def.fibre_damping = damping;
    def.activation_dynamics = dynamics;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    return muscle;
}

static void substep(mu_muscle *muscle, rb_world *world)
{
    cr_assert_eq(mu_muscle_prepare(muscle, world, H), RB_OK, "%s", rb_last_error());
    step_world(world, H, 1);
    cr_assert_eq(mu_muscle_measure(muscle, world), RB_OK, "%s", rb_last_error());
}

Test(tendon, a_stiff_tendon_moves_the_mass_as_the_rigid_one)
{
    /* 2 kg on the muscle at activation 0.3 for 1 s, the mass shortening
     * the muscle at up to 0.2 m/s. As the tendon stiffens and the fibre's
     * damper fades (ε0 and β divided by 10 each time) the mass's path
     * approaches the rigid muscle's; with ε0 = 1e-5 and β = 1e-4 it stays
     * within 0.5 mm of it (0.25 mm measured) along 12 cm of travel.
     * (Millard's β = 0.1 itself slows the shortening: it adds β·Fmax·ṽ,
     * 47 N at ṽ = -0.47, against a 19.6 N load.) */
    mu_curves *curves = tables();
    const double strains[] = {1e-3, 1e-4, 1e-5};
    const double dampings[] = {1e-2, 1e-3, 1e-4};
    double rigid[600];
    double previous = INFINITY;
    for (int c = -1; c < 3; ++c) {
        rb_world *world = substep_world(rb_v2(0.0, -9.8));
        rb_body_id body;
        mu_muscle *muscle =
            hanging(world, curves, c >= 0, c >= 0 ? strains[c] : 0.049, c >= 0 ? dampings[c] : 0.1, false, &body);
        cr_assert_eq(mu_muscle_set_activation(muscle, 0.3), RB_OK);
        double worst = 0.0;
        for (int i = 0; i < 600; ++i) {
            substep(muscle, world);
            const double y = rb_body_position(world, body).y;
            if (c < 0) {
                rigid[i] = y;
            } else {
                worst = fmax(worst, fabs(y - rigid[i]));
            }
        }
        if (c >= 0) {
            cr_expect(worst < previous, "ε0 %g: %g m from the rigid muscle's path did not shrink (was %g)", strains[c],
                      worst, previous);
            previous = worst;
        }
        mu_muscle_destroy(muscle, world);
        destroy_world_and_expect_no_leak(world);
    }
    cr_expect(previous < 5e-4, "ε0 = 1e-5: %g m from the rigid muscle's path", previous);
    mu_curves_destroy(curves);
}

Test(tendon, the_fibre_settles_on_the_static_equilibrium)
{
    /* Both ends static, activation 0.6, the fibre released from the
     * equilibrium of activation 0: after 4 s of substeps it rests at the
     * balance the static solve finds, within 1e-6 Fmax. */
    mu_curves *curves = tables();
    rb_world *world = substep_world(rb_v2(0.0, 0.0));
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(0.3, 0.0), 0.0);
    mu_muscle *muscle = make_muscle(world, origin, insertion, curves, true, 0.049, 0.3);
    cr_assert_eq(mu_muscle_set_activation(muscle, 0.6), RB_OK);
    for (int i = 0; i < 2400; ++i) {
        substep(muscle, world);
    }
    const mu_muscle_readout r = mu_muscle_read(muscle);
    cr_expect(fabs(r.velocity) < 1e-6, "fibre velocity %g m/s", r.velocity);
    expect_near(imbalance(&r, curves, 0.3, 0.3, 0.049), 0.0, 1e-6, "dynamic rest against static balance");
    cr_expect(r.total_force > 0.3 * FMAX, "force %g N", r.total_force);
    mu_muscle_destroy(muscle, world);
    destroy_world_and_expect_no_leak(world);
    mu_curves_destroy(curves);
}

Test(tendon, compliant_muscle_with_activation_dynamics_stays_bounded)
{
    /* The 2 kg mass on a compliant muscle with activation dynamics, the
     * excitation switched between 1 and 0 every 0.25 s for 6 s at 600 Hz:
     * no NaN, and the mechanical energy E = ½mv² + m·g·y plus the
     * tendon's stored energy stays within what the muscle's pull can give
     * (Fmax over the path's range, 1000 N × 0.3 m = 300 J); in fact the
     * mass never moves faster than Vmax allows the fibre and the tendon's
     * recoil together. */
    mu_curves *curves = tables();
    rb_world *world = substep_world(rb_v2(0.0, -9.8));
    rb_body_id body;
    mu_muscle *muscle = hanging(world, curves, true, 0.049, 0.1, true, &body);
    double worst_energy = 0.0;
    double fastest = 0.0;
    for (int i = 0; i < 3600; ++i) {
        if (i % 150 == 0) {
            cr_assert_eq(mu_muscle_set_activation(muscle, (i / 150) % 2 == 0 ? 1.0 : 0.0), RB_OK);
        }
        substep(muscle, world);
        const rb_vec2 v = rb_body_linear_velocity(world, body);
        const double y = rb_body_position(world, body).y;
        const mu_muscle_readout r = mu_muscle_read(muscle);
        cr_assert(isfinite(v.y) && isfinite(y) && isfinite(r.fibre_length) && isfinite(r.total_force),
                  "substep %d: v %g, y %g, fibre %g, force %g", i, v.y, y, r.fibre_length, r.total_force);
        const double energy = 0.5 * 2.0 * rb_dot(v, v) + 2.0 * 9.8 * (y + 0.3);
        worst_energy = fmax(worst_energy, fabs(energy));
        fastest = fmax(fastest, rb_length(v));
    }
    cr_expect(worst_energy < 300.0, "|E| reached %g J", worst_energy);
    cr_expect(fastest < 5.0, "the mass reached %g m/s", fastest);
    cr_log_info("compliant + activation dynamics: worst |E| %g J, fastest %g m/s", worst_energy, fastest);
    mu_muscle_destroy(muscle, world);
    destroy_world_and_expect_no_leak(world);
    mu_curves_destroy(curves);
}

Test(tendon, compliant_tendon_needs_a_slack_length)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    mu_curves *curves = tables();
    rb_body_id a = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id b = make_body(world, RB_BODY_STATIC, rb_v2(0.15, 0.0), 0.0);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = a;
    def.bodies[1] = b;
    def.rest_length = REST;
    def.max_force = FMAX;
    def.curves = curves;
    def.compliant_tendon = true;
    mu_muscle *muscle = NULL;
    cr_expect_eq(mu_muscle_create(world, &def, &muscle), RB_ERR_INVALID_ARGUMENT, "path 0.15 m < rest length");
    cr_expect(strstr(rb_last_error(), "slack length") != NULL, "%s", rb_last_error());
    cr_expect_null(muscle);
    def.tendon_length = 0.05;
    def.tendon_strain_at_max_force = 0.0;
    cr_expect_eq(mu_muscle_create(world, &def, &muscle), RB_ERR_INVALID_ARGUMENT, "strain 0");
    cr_expect(strstr(rb_last_error(), "tendon_strain_at_max_force") != NULL, "%s", rb_last_error());
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}
