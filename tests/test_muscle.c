/* SPDX-License-Identifier: MIT */
/* The Hill muscle on a cable: its force against the composition of its
 * own curves, its maximal force, the tension controller, the sign of the
 * force-velocity effect, and stability under a stiff force-velocity
 * slope.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/curves.h"
#include "mu/muscle.h"
#include "test_support.h"

/* A muscle along +x from a static body at the origin to the point
 * (path_length, 0) of body `insertion`, rest length 0.2 m, Fmax 1000 N,
 * tendon 0.05 m. */
static mu_muscle *make_muscle(rb_world *world, rb_body_id origin, rb_body_id insertion, const mu_curves *curves)
{
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = origin;
    def.bodies[1] = insertion;
    def.local_points[0] = rb_v2(0.0, 0.0);
    def.local_points[1] = rb_v2(0.0, 0.0);
    def.rest_length = 0.2;
    def.max_force = 1000.0;
    def.tendon_length = 0.05;
    def.curves = curves;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    return muscle;
}

static mu_curves *analytic(void)
{
    const mu_analytic_curves parameters = mu_default_analytic_curves();
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_analytic(&parameters, &curves), RB_OK, "%s", rb_last_error());
    return curves;
}

static mu_curves *tables(void)
{
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &curves), RB_OK, "%s", rb_last_error());
    return curves;
}

/* One substep: the muscle sets its law, the world steps, the muscle reads. */
static void substep(mu_muscle *muscle, rb_world *world, double h)
{
    cr_assert_eq(mu_muscle_prepare(muscle, world, h), RB_OK, "%s", rb_last_error());
    step_world(world, h, 1);
    cr_assert_eq(mu_muscle_measure(muscle, world), RB_OK, "%s", rb_last_error());
}

Test(muscle, isometric_force_at_rest_length_is_the_curves_composition)
{
    /* Both ends static, the belly at its rest length (path 0.25 m, tendon
     * 0.05 m): v = 0, l̃ = 1, so F = a·Fmax·f_L(1)·f_V(0) + Fmax·f_P(1) with
     * the values of the muscle's own curves (the analytic set gives a·Fmax
     * exactly). */
    mu_curves *sets[2] = {analytic(), tables()};
    for (int s = 0; s < 2; ++s) {
        rb_world *world = make_world(rb_v2(0.0, -9.8));
        rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
        rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(0.25, 0.0), 0.0);
        mu_muscle *muscle = make_muscle(world, origin, insertion, sets[s]);
        cr_assert_eq(mu_muscle_set_activation(muscle, 0.6), RB_OK);
        substep(muscle, world, 1.0 / 600.0);
        const mu_muscle_readout r = mu_muscle_read(muscle);
        const double expected = 0.6 * 1000.0 * mu_curve_active_length(sets[s], 1.0) * mu_curve_velocity(sets[s], 0.0) +
                                1000.0 * mu_curve_passive_length(sets[s], 1.0);
        expect_near(r.normalized_length, 1.0, 1e-12, "normalized length");
        expect_near(r.velocity, 0.0, 1e-12, "velocity");
        expect_near(r.total_force, expected, 1e-9 * expected, "isometric force");
        if (s == 0) {
            expect_near(r.total_force, 600.0, 1e-9, "analytic set: a·Fmax");
        }
        mu_muscle_destroy(muscle, world);
        destroy_world_and_expect_no_leak(world);
    }
    mu_curves_destroy(sets[0]);
    mu_curves_destroy(sets[1]);
}

Test(muscle, max_force_from_width_and_specific_tension)
{
    /* The arm's biceps short: Fmax = π·w²/4·σ = π·0.0328²/4·1.5e6 N. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    mu_curves *curves = analytic();
    rb_body_id a = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id b = make_body(world, RB_BODY_STATIC, rb_v2(0.3, 0.0), 0.0);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = a;
    def.bodies[1] = b;
    def.rest_length = 0.2087;
    def.rest_width = 0.0328;
    def.start_normalized_length = 1.1;
    def.curves = curves;
    mu_muscle *muscle = NULL;
    cr_assert_eq(mu_muscle_create(world, &def, &muscle), RB_OK, "%s", rb_last_error());
    expect_near(mu_muscle_max_force(muscle), RB_PI * 0.0328 * 0.0328 / 4.0 * 1.5e6, 1e-9, "Fmax");
    /* The tendon takes the rest: 0.3 - 0.2087·1.1. */
    expect_near(mu_muscle_tendon_length(muscle), 0.3 - 0.2087 * 1.1, 1e-12, "tendon length");
    mu_muscle_destroy(muscle, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}

Test(muscle, tension_controller_settles_on_its_target)
{
    /* Isometric at rest length with the tables: each substep the active
     * force F = a·Fmax·f_L·f_V moves towards the target T by the fraction
     * 0.08·f_L(1)·f_V(0) ≈ 0.08 of the error, so after 300 substeps the
     * error is below 0.92^300 ≈ 1e-11 of the start: well within 2 %. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    mu_curves *curves = tables();
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id insertion = make_body(world, RB_BODY_STATIC, rb_v2(0.25, 0.0), 0.0);
    mu_muscle *muscle = make_muscle(world, origin, insertion, curves);
    cr_assert_eq(mu_muscle_set_target_tension(muscle, 300.0), RB_OK);
    for (int i = 0; i < 300; ++i) {
        substep(muscle, world, 1.0 / 600.0);
    }
    const mu_muscle_readout r = mu_muscle_read(muscle);
    expect_near(r.active_force, 300.0, 0.02 * 300.0, "active force under tension control");
    cr_expect_eq(r.target_tension, 300.0);
    cr_assert_eq(mu_muscle_set_target_tension(muscle, 0.0), RB_OK);
    for (int i = 0; i < 300; ++i) {
        substep(muscle, world, 1.0 / 600.0);
    }
    expect_near(mu_muscle_read(muscle).activation, 0.0, 1e-3, "a target of 0 drives the activation to 0");
    cr_expect_eq(mu_muscle_set_target_tension(muscle, -1.0), RB_ERR_INVALID_ARGUMENT, "negative target");
    cr_expect_eq(mu_muscle_set_activation(muscle, NAN), RB_ERR_INVALID_ARGUMENT, "NaN activation");
    mu_muscle_destroy(muscle, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}

/* The force of an active muscle whose insertion moves along the path at
 * `speed` (m/s, > 0 lengthening). */
static double force_while_moving(double speed)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    mu_curves *curves = analytic();
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id insertion = make_body(world, RB_BODY_KINEMATIC, rb_v2(0.25, 0.0), 0.0);
    cr_assert_eq(rb_body_set_linear_velocity(world, insertion, rb_v2(speed, 0.0)), RB_OK);
    mu_muscle *muscle = make_muscle(world, origin, insertion, curves);
    cr_assert_eq(mu_muscle_set_activation(muscle, 1.0), RB_OK);
    substep(muscle, world, 1.0 / 600.0);
    const double force = mu_muscle_read(muscle).active_force;
    mu_muscle_destroy(muscle, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
    return force;
}

Test(muscle, shortening_lowers_and_lengthening_raises_the_force)
{
    /* The original clipped every shortening to zero velocity; with signed
     * velocity a muscle shortening at a tenth of Vmax pulls with
     * f_V(-0.1) < 1 of its isometric force, and one lengthening at that
     * speed with f_V(0.1) > 1 (the insertion is kinematic, so its speed is
     * imposed). */
    mu_curves *curves = analytic();
    const double isometric = force_while_moving(0.0);
    const double shortening = force_while_moving(-0.025);
    const double lengthening = force_while_moving(0.025);
    cr_expect(shortening < isometric && isometric < lengthening, "forces %g < %g < %g expected", shortening, isometric,
              lengthening);
    expect_near(shortening / isometric, mu_curve_velocity(curves, -0.1), 1e-3, "shortening: f_V(-0.1)");
    expect_near(lengthening / isometric, mu_curve_velocity(curves, 0.1), 1e-3, "lengthening: f_V(0.1)");
    mu_curves_destroy(curves);
}

Test(muscle, a_stiff_force_velocity_slope_does_not_ring)
{
    /* A 2 kg mass hangs from an active muscle (Fmax 1000 N, Vmax 0.25 m/s)
     * under gravity at 600 Hz. With the linearly interpolated tables the
     * force-velocity slope at 0 is about 12 per unit ṽ (its two segments:
     * 8.9 and 18.3), a damper of 12·1000/0.25 = 48 kN·s/m: explicitly,
     * h·c/m = 48000/600/2 = 40 per substep would diverge at once (it must
     * stay below 2). With
     * the implicit law: no NaN, and in the second half second the speed
     * neither rings (changes sign between substeps) nor grows. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    mu_curves *curves = tables();
    rb_body_id origin = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id mass = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -0.25), 0.0);
    const rb_mass_data data = {2.0, {0.0, 0.0}, 0.0};
    cr_assert_eq(rb_body_set_mass_data(world, mass, &data), RB_OK);
    mu_muscle *muscle = make_muscle(world, origin, mass, curves);
    cr_assert_eq(mu_muscle_set_activation(muscle, 1.0), RB_OK);
    double previous = 0.0;
    double speed_at_half_time = 0.0;
    double largest_later_speed = 0.0;
    int sign_changes = 0;
    for (int i = 0; i < 600; ++i) {
        substep(muscle, world, 1.0 / 600.0);
        const double v = rb_body_linear_velocity(world, mass).y;
        cr_assert(isfinite(v), "substep %d: velocity %g", i, v);
        if (i == 300) {
            speed_at_half_time = fabs(v);
        } else if (i > 300) {
            largest_later_speed = fmax(largest_later_speed, fabs(v));
            sign_changes += v * previous < 0.0;
        }
        previous = v;
    }
    /* Overdamped: the mass creeps towards equilibrium with the time
     * constant c/k of the damper and the force-length stiffness (seconds),
     * so it need not have stopped; but it must not speed up again. */
    cr_expect(sign_changes < 5, "the velocity changed sign %d times in 300 substeps", sign_changes);
    cr_expect(largest_later_speed <= speed_at_half_time, "the speed grew from %g to %g m/s", speed_at_half_time,
              largest_later_speed);
    mu_muscle_destroy(muscle, world);
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}

/* A world with a muscle lifting a 1 kg mass from a static anchor. */
typedef struct hanging {
    rb_world *world;
    rb_body_id mass;
    mu_muscle *muscle;
} hanging;

static hanging make_hanging(const mu_curves *curves)
{
    hanging s = {.world = make_world(rb_v2(0.0, -9.8))};
    set_substeps(s.world, 1);
    rb_body_id anchor = make_body(s.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    s.mass = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(0.0, -0.25), 0.0);
    add_circle(s.world, s.mass, rb_v2(0.0, 0.0), 0.02, 1.0 / (RB_PI * 0.02 * 0.02));
    s.muscle = make_muscle(s.world, anchor, s.mass, curves);
    cr_assert_eq(mu_muscle_set_activation(s.muscle, 0.5), RB_OK);
    return s;
}

Test(muscle, advance_is_measure_then_prepare)
{
    /* mu_muscle_advance reads the path once for both halves: the run must
     * be bit-identical to measuring and preparing separately. */
    mu_curves *curves = tables();
    hanging separate = make_hanging(curves);
    hanging merged = make_hanging(curves);
    const double h = 1.0 / 600.0;
    cr_assert_eq(mu_muscle_prepare(separate.muscle, separate.world, h), RB_OK);
    cr_assert_eq(mu_muscle_prepare(merged.muscle, merged.world, h), RB_OK);
    for (int n = 0; n < 600; ++n) {
        step_world(separate.world, h, 1);
        step_world(merged.world, h, 1);
        cr_assert_eq(mu_muscle_measure(separate.muscle, separate.world), RB_OK);
        cr_assert_eq(mu_muscle_prepare(separate.muscle, separate.world, h), RB_OK);
        cr_assert_eq(mu_muscle_advance(merged.muscle, merged.world, h), RB_OK, "%s", rb_last_error());
    }
    cr_expect_eq(rb_world_state_hash(merged.world), rb_world_state_hash(separate.world));
    cr_expect_eq(mu_muscle_read(merged.muscle).total_force, mu_muscle_read(separate.muscle).total_force);

    cr_expect_eq(mu_muscle_advance(NULL, merged.world, h), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_muscle_advance(merged.muscle, merged.world, NAN), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_muscle_advance(merged.muscle, merged.world, -h), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "mu_muscle_advance") != NULL, "the message names the function: %s",
              rb_last_error());
    mu_muscle_destroy(separate.muscle, separate.world);
    mu_muscle_destroy(merged.muscle, merged.world);
    rb_world_destroy(separate.world);
    destroy_world_and_expect_no_leak(merged.world);
    mu_curves_destroy(curves);
}

Test(muscle, tension_is_what_the_cable_carried_in_the_substep_measured)
{
    /* mu_muscle_tension is the readout's total force without the rest of
     * the readout: both are the engine's own tension of the cable over
     * the substep the muscle last measured, to the bit, and the readout
     * made later from the kept measure still says what it said then. */
    mu_curves *curves = tables();
    hanging s = make_hanging(curves);
    const double h = 1.0 / 600.0;
    cr_assert_eq(mu_muscle_set_activation(s.muscle, 0.7), RB_OK);
    cr_assert_eq(mu_muscle_prepare(s.muscle, s.world, h), RB_OK);
    double strongest = 0.0;
    for (int n = 0; n < 200; ++n) {
        step_world(s.world, h, 1);
        cr_assert_eq(mu_muscle_measure(s.muscle, s.world), RB_OK, "%s", rb_last_error());
        const double carried = rb_cable_tension(s.world, mu_muscle_cable(s.muscle));
        const mu_muscle_readout before = mu_muscle_read(s.muscle);
        cr_expect_eq(mu_muscle_tension(s.muscle), carried, "substep %d", n);
        cr_expect_eq(before.total_force, carried, "substep %d", n);
        cr_assert_eq(mu_muscle_set_activation(s.muscle, n % 2 == 0 ? 0.2 : 0.7), RB_OK);
        cr_assert_eq(mu_muscle_prepare(s.muscle, s.world, h), RB_OK);
        const mu_muscle_readout after = mu_muscle_read(s.muscle);
        cr_expect_eq(after.activation, before.activation, "substep %d: the readout is the measure's", n);
        cr_expect_eq(after.normalized_length, before.normalized_length, "substep %d", n);
        strongest = fmax(strongest, carried);
    }
    cr_expect(strongest > 1.0, "the muscle pulled (%g N at most)", strongest);
    mu_muscle_destroy(s.muscle, s.world);
    destroy_world_and_expect_no_leak(s.world);
    mu_curves_destroy(curves);
}

Test(muscle, path_speed_is_the_lengthening_speed_of_the_last_measure)
{
    /* The model's energy account takes L' from the muscle instead of
     * reading the path again: it must be what the path does. The hanging
     * mass moves straight down from the anchor, so L' = -v_y of the mass;
     * the engine's own read of the cable gives the same bits. */
    mu_curves *curves = tables();
    hanging s = make_hanging(curves);
    const double h = 1.0 / 600.0;
    cr_expect_eq(mu_muscle_path_speed(s.muscle), 0.0, "0 before the first measure");
    cr_assert_eq(mu_muscle_prepare(s.muscle, s.world, h), RB_OK);
    double fastest = 0.0;
    for (int n = 0; n < 300; ++n) {
        step_world(s.world, h, 1);
        cr_assert_eq(n % 2 == 0 ? mu_muscle_advance(s.muscle, s.world, h) : mu_muscle_measure(s.muscle, s.world), RB_OK,
                     "%s", rb_last_error());
        const double speed = mu_muscle_path_speed(s.muscle);
        const rb_cable_id cable = mu_muscle_cable(s.muscle);
        cr_expect_eq(speed, rb_cable_lengthening_speed(s.world, cable), "substep %d", n);
        cr_expect(fabs(speed + rb_body_linear_velocity(s.world, s.mass).y) <= 1e-12,
                  "substep %d: L' = %.17g, -v_y = %.17g", n, speed, -rb_body_linear_velocity(s.world, s.mass).y);
        fastest = fmax(fastest, fabs(speed));
        if (n % 2 == 1) {
            cr_assert_eq(mu_muscle_prepare(s.muscle, s.world, h), RB_OK);
        }
    }
    cr_expect(fastest > 0.01, "the mass moved (%g m/s at most)", fastest);
    mu_muscle_destroy(s.muscle, s.world);
    destroy_world_and_expect_no_leak(s.world);
    mu_curves_destroy(curves);
}
