/* SPDX-License-Identifier: MIT */
/* Contacts: colliding circles against the conservation laws and Newton's
 * law of restitution, a dropped ball's rebound, Coulomb friction on an
 * incline, the friction and restitution mixing rules of shape.h, resting
 * contact, sensors and collision filters. */
#include <math.h>

#include "scenes/scenes.h"
#include "test_support.h"

/* The first shape of a body (every body here has one). */
static rb_shape_id first_shape(rb_world *world, rb_body_id body)
{
    rb_shape_id shape;
    cr_assert_eq(rb_body_shapes(world, body, &shape, 1), 1, "the body should have a shape");
    return shape;
}

static double gravity_magnitude(const rb_world *world) { return rb_length(rb_world_gravity(world)); }

/* ---- Two circles colliding without gravity ------------------------------
 *
 * A (radius 0.5, density 1) moves right at 3/4 of the closing speed, B
 * (radius 0.3, density 2) moves left at 1/4 of it, its centre `offset`
 * above A's line. Unstopped, they would overlap by CONTACT_OVERLAP = 1 mm
 * at the end of step CONTACT_STEP; an engine with speculative contacts
 * stops them earlier, just touching. Either way no overlap beyond the
 * linear slop (5 mm) is left for position correction, and the collision is
 * a pair of equal and opposite impulses at the contact point, which
 * conserve linear momentum and angular momentum about any point exactly.
 *
 * The impact is the step in which the velocities first change; its normal
 * is the line of centres at the start of that step (the circles touch on
 * it), and Newton's law of restitution acts along it. */
#define RADIUS_A 0.5
#define RADIUS_B 0.3
#define DENSITY_A 1.0
#define DENSITY_B 2.0
#define CONTACT_STEP 33
#define CONTACT_OVERLAP 0.001
/* Half a second more: the bodies meet, part and fly apart. */
#define PAIR_STEPS (CONTACT_STEP + 30)

/* Conservation: the momenta are sums of a few products of values of order
 * 1 .. 10, updated by 63 steps of roundoff, so their drift is below 1e-13
 * of the size of their terms; 1e-9 (the required figure) is far above it
 * and far below any real impulse imbalance. */
#define MOMENTUM_REL 1e-9

typedef struct pair {
    rb_world *world;
    rb_body_id a, b;
    double mass_a, mass_b;       /* kg: ρ·π·r² */
    double inertia_a, inertia_b; /* kg·m²: m·r²/2 */
    int impact_step;             /* the step in which the velocities first changed, 0 before */
    rb_vec2 normal;              /* unit, from A's centre to B's at the start of the impact step */
    double approach;             /* m/s, (v_b - v_a)·normal before the impact (< 0) */
} pair;

static rb_body_id make_moving_circle(rb_world *world, rb_vec2 position, rb_vec2 velocity, double radius, double density,
                                     rb_shape_def material)
{
    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_DYNAMIC;
    def.position = position;
    def.linear_velocity = velocity;
    rb_body_id body;
    cr_assert_eq(rb_body_create(world, &def, &body), RB_OK, "%s", rb_last_error());
    material.density = density;
    const rb_circle circle = {.center = {0.0, 0.0}, .radius = radius};
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_circle(world, body, &material, &circle, &shape), RB_OK, "%s", rb_last_error());
    return body;
}

static pair make_pair(double offset, double closing_speed, double restitution, double friction)
{
    pair p = {.world = make_world(rb_v2(0.0, 0.0))};
    rb_shape_def material = rb_default_shape_def();
    material.restitution = restitution;
    material.friction = friction;
    /* Unstopped, the centres would be `distance` apart, dx of it along x,
     * at the end of step CONTACT_STEP. */
    const double distance = RADIUS_A + RADIUS_B - CONTACT_OVERLAP;
    const double dx = sqrt(distance * distance - offset * offset);
    const rb_vec2 xa = rb_v2(-1.0, 0.0);
    const rb_vec2 xb = rb_v2(xa.x + dx + CONTACT_STEP * TEST_DT * closing_speed, offset);
    p.a = make_moving_circle(p.world, xa, rb_v2(0.75 * closing_speed, 0.0), RADIUS_A, DENSITY_A, material);
    p.b = make_moving_circle(p.world, xb, rb_v2(-0.25 * closing_speed, 0.0), RADIUS_B, DENSITY_B, material);
    p.mass_a = DENSITY_A * RB_PI * RADIUS_A * RADIUS_A;
    p.mass_b = DENSITY_B * RB_PI * RADIUS_B * RADIUS_B;
    p.inertia_a = 0.5 * p.mass_a * RADIUS_A * RADIUS_A;
    p.inertia_b = 0.5 * p.mass_b * RADIUS_B * RADIUS_B;
    return p;
}

static rb_vec2 linear_momentum(const pair *p)
{
    const rb_vec2 va = rb_body_linear_velocity(p->world, p->a), vb = rb_body_linear_velocity(p->world, p->b);
    return rb_v2(p->mass_a * va.x + p->mass_b * vb.x, p->mass_a * va.y + p->mass_b * vb.y);
}

/* About the origin: Σ m·(c × v) + I·ω. `scale` receives the size of its
 * terms, Σ m·|c|·|v| + I·|ω|, for the tolerance. */
static double angular_momentum(const pair *p, double *scale)
{
    const rb_body_id bodies[2] = {p->a, p->b};
    const double masses[2] = {p->mass_a, p->mass_b}, inertias[2] = {p->inertia_a, p->inertia_b};
    double momentum = 0.0;
    *scale = 0.0;
    for (int i = 0; i < 2; ++i) {
        const rb_vec2 c = rb_body_world_center(p->world, bodies[i]);
        const rb_vec2 v = rb_body_linear_velocity(p->world, bodies[i]);
        const double omega = rb_body_angular_velocity(p->world, bodies[i]);
        momentum += masses[i] * (c.x * v.y - c.y * v.x) + inertias[i] * omega;
        *scale += masses[i] * rb_length(c) * rb_length(v) + inertias[i] * fabs(omega);
    }
    return momentum;
}

static rb_vec2 relative_velocity(const pair *p)
{
    return rb_sub(rb_body_linear_velocity(p->world, p->b), rb_body_linear_velocity(p->world, p->a));
}

/* (v_b - v_a) along the impact normal. */
static double normal_speed(const pair *p) { return rb_dot(relative_velocity(p), p->normal); }

/* Runs the collision, finds the impact, and checks both momenta after
 * every step. */
static void collide_conserving_momentum(pair *p)
{
    const rb_vec2 p0 = linear_momentum(p);
    double scale;
    const double l0 = angular_momentum(p, &scale);
    for (int n = 1; n <= PAIR_STEPS; ++n) {
        const rb_vec2 before = relative_velocity(p);
        step_world(p->world, TEST_DT, 1);
        const rb_vec2 after = relative_velocity(p);
        if (p->impact_step == 0 && (after.x != before.x || after.y != before.y)) {
            /* The speculative contact stops the circles where they meet, at
             * the end of this step: the impact normal is their line of
             * centres then. (The line at the start of the step is turned
             * by the 0.03 m they slide past each other meanwhile, which
             * shifts the normal speed by 4 %.) */
            const rb_vec2 line = rb_sub(rb_body_world_center(p->world, p->b), rb_body_world_center(p->world, p->a));
            p->impact_step = n;
            p->normal = rb_normalize(line);
            p->approach = rb_dot(before, p->normal);
        }
        const rb_vec2 pn = linear_momentum(p);
        cr_expect(rb_distance(pn, p0) <= MOMENTUM_REL * rb_length(p0),
                  "step %d: linear momentum (%.17g, %.17g), was (%.17g, %.17g)", n, pn.x, pn.y, p0.x, p0.y);
        const double ln = angular_momentum(p, &scale);
        cr_expect(fabs(ln - l0) <= MOMENTUM_REL * scale, "step %d: angular momentum %.17g, was %.17g (scale %g)", n, ln,
                  l0, scale);
    }
    cr_assert(p->impact_step > 0, "the circles never met");
    cr_assert(p->approach < 0.0, "the circles were not approaching when they met");
}

Test(contacts, elastic_head_on_collision_reverses_the_normal_velocity)
{
    pair p = make_pair(0.0, 4.0, 1.0, 0.0);
    collide_conserving_momentum(&p);
    /* Newton's law of restitution with e = 1: v_rel,n after = -v_rel,n
     * before, to the required 1 %. */
    expect_near(normal_speed(&p), -p.approach, 0.01 * fabs(p.approach), "e = 1: normal velocity reversed");
    destroy_world_and_expect_no_leak(p.world);
}

Test(contacts, off_centre_collision_with_friction_conserves_both_momenta)
{
    pair p = make_pair(0.4, 4.0, 1.0, 0.6);
    collide_conserving_momentum(&p);
    expect_near(normal_speed(&p), -p.approach, 0.01 * fabs(p.approach), "e = 1: normal velocity reversed");
    /* The surfaces slid past each other at about 4·0.4/0.8 = 2 m/s when they met,
     * so friction must have spun both circles (its impulse is about
     * 0.2 N·s, giving A about 1 rad/s). */
    cr_expect(fabs(rb_body_angular_velocity(p.world, p.a)) > 0.1, "friction did not spin A (ω = %g)",
              rb_body_angular_velocity(p.world, p.a));
    destroy_world_and_expect_no_leak(p.world);
}

Test(contacts, inelastic_collision_ends_the_approach)
{
    pair p = make_pair(0.0, 4.0, 0.0, 0.6);
    collide_conserving_momentum(&p);
    expect_near(normal_speed(&p), 0.0, 0.01 * fabs(p.approach), "e = 0: no normal velocity left");
    destroy_world_and_expect_no_leak(p.world);
}

Test(contacts, impact_slower_than_the_restitution_threshold_does_not_bounce)
{
    pair p = make_pair(0.0, 0.5, 1.0, 0.0);
    cr_assert(fabs(p.approach) < rb_world_solver_settings(p.world).restitution_threshold,
              "the impact speed must be below the threshold for this test");
    collide_conserving_momentum(&p);
    expect_near(normal_speed(&p), 0.0, 0.01 * fabs(p.approach), "slow impact with e = 1: no bounce");
    destroy_world_and_expect_no_leak(p.world);
}

/* ---- A ball dropped on the ground -----------------------------------------
 *
 * Newton's law of restitution: a ball dropped from h meets the ground at
 * sqrt(2·g·h), leaves it at e times that speed and rises to e²·h. The
 * simulation differs from that by (a) where the contact is caught: up to
 * one step's fall, v·dt, before or after the surface, which moves the
 * apex by at most v·dt·(1 - e²) = 4.4 m/s · (1/480 s) · 0.75 = 0.7 cm, 2.8 %
 * of e²·h for e = 0.5 and h = 1 m, and (b) the energy semi-implicit Euler
 * loses, ½·g²·dt² a step, under 0.5 % over the fall and the rise. Both stay
 * well inside the required 5 %. */
#define DROP_DT (1.0 / 480.0)
#define DROP_HEIGHT 1.0
#define DROP_TOLERANCE 0.05

/* The height of the ball's lowest point at the top of its first rebound. */
static double rebound_apex(rb_world *world, const scene_drop *drop)
{
    const double impact_speed = sqrt(2.0 * gravity_magnitude(world) * DROP_HEIGHT);
    cr_assert(impact_speed > rb_world_solver_settings(world).restitution_threshold,
              "the impact speed %g m/s must exceed the restitution threshold", impact_speed);
    bool rising = false, fell_again = false;
    double apex = 0.0;
    for (int n = 0; n < (int)(3.0 / DROP_DT) && !fell_again; ++n) {
        step_world(world, DROP_DT, 1);
        const double vy = rb_body_linear_velocity(world, drop->ball).y;
        const double lowest = rb_body_position(world, drop->ball).y - drop->radius;
        if (vy > 0.0) {
            apex = rising ? fmax(apex, lowest) : lowest;
            rising = true;
        } else {
            fell_again = rising;
        }
    }
    cr_assert(fell_again, "the ball did not rebound and fall again within 3 s");
    return apex;
}

static void expect_rebound(double scene_restitution, double ball_restitution, double ground_restitution,
                           double expected_e)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    scene_drop drop;
    cr_assert_eq(scene_drop_create(world, DROP_HEIGHT, scene_restitution, &drop), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_shape_set_restitution(world, first_shape(world, drop.ball), ball_restitution), RB_OK, "%s",
                 rb_last_error());
    cr_assert_eq(rb_shape_set_restitution(world, first_shape(world, drop.ground), ground_restitution), RB_OK, "%s",
                 rb_last_error());
    const double expected = expected_e * expected_e * DROP_HEIGHT;
    const double apex = rebound_apex(world, &drop);
    cr_expect(fabs(apex - expected) <= DROP_TOLERANCE * expected,
              "ball e = %g on ground e = %g: rebound to %.4f m, expected e²·h = %.4f m (±5 %%)", ball_restitution,
              ground_restitution, apex, expected);
    destroy_world_and_expect_no_leak(world);
}

Test(contacts, dropped_ball_rebounds_to_e_squared_h)
{
    expect_rebound(0.5, 0.5, 0.5, 0.5);
    expect_rebound(0.8, 0.8, 0.8, 0.8);
}

Test(contacts, restitution_mixes_as_the_larger_of_the_two)
{
    /* The mean (0.4) would rebound to 0.16 m, the product (0) not at all. */
    expect_rebound(0.0, 0.8, 0.0, 0.8);
    expect_rebound(0.0, 0.0, 0.8, 0.8);
}

Test(contacts, restitution_changed_while_the_contact_lasts_takes_effect)
{
    /* A contact mixes its shapes' restitutions when it begins, which is as
     * soon as their fattened boxes overlap, before the shapes touch: a
     * change while it lasts must mix them again. The ball falls with e = 0
     * on ground with e = 0; 2 cm above the ground, its contact long begun,
     * its restitution becomes 0.5, mixed with 0 to 0.5: it rebounds to
     * e²·h = 0.25 m (±5 %), where the stale mix of 0 would not rebound. */
    rb_world *world = make_world(rb_default_world_def().gravity);
    scene_drop drop;
    cr_assert_eq(scene_drop_create(world, DROP_HEIGHT, 0.0, &drop), RB_OK, "%s", rb_last_error());
    while (rb_body_position(world, drop.ball).y - drop.radius > 0.02) {
        step_world(world, DROP_DT, 1);
    }
    cr_assert(rb_body_linear_velocity(world, drop.ball).y < -1.0, "the ball should still be falling");
    cr_assert_eq(rb_shape_set_restitution(world, first_shape(world, drop.ball), 0.5), RB_OK, "%s", rb_last_error());
    const double expected = 0.25 * DROP_HEIGHT;
    const double apex = rebound_apex(world, &drop);
    cr_expect(fabs(apex - expected) <= DROP_TOLERANCE * expected,
              "restitution changed to 0.5 while the contact lasted: rebound to %.4f m, expected %.4f m (±5 %%)", apex,
              expected);
    destroy_world_and_expect_no_leak(world);
}

/* ---- A box on an incline --------------------------------------------------
 *
 * Coulomb friction: the box stays while tan θ <= μ, and otherwise slides
 * with a = g·(sin θ - μ·cos θ). */

/* The incline scene with the plank's and the box's friction then set to
 * `plank_friction` and `box_friction`. */
static rb_world *make_incline(double angle, double plank_friction, double box_friction, scene_incline *incline)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    cr_assert_eq(scene_incline_create(world, angle, plank_friction, incline), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_shape_set_friction(world, first_shape(world, incline->box), box_friction), RB_OK, "%s",
                 rb_last_error());
    return world;
}

/* The acceleration down the slope, from the speeds at 0.25 s and 0.75 s:
 * by then the box slides steadily, and it has gone at most ½·g·t² = 2.8 m
 * of the 11 m of plank below it. Semi-implicit Euler adds a constant
 * acceleration exactly, so the difference measures it. */
static double slope_acceleration(rb_world *world, const scene_incline *incline)
{
    step_world(world, TEST_DT, 15);
    const double v1 = rb_dot(rb_body_linear_velocity(world, incline->box), incline->slope_direction);
    step_world(world, TEST_DT, 30);
    const double v2 = rb_dot(rb_body_linear_velocity(world, incline->box), incline->slope_direction);
    return (v2 - v1) / (30 * TEST_DT);
}

/* The required 3 %: an iterative solver's friction and the speculative
 * contact leave small errors; a wrong mixing rule or friction law is off by
 * 20 % or more in the cases below. */
static void expect_slide(double angle, double plank_friction, double box_friction, double mixed_friction)
{
    scene_incline incline;
    rb_world *world = make_incline(angle, plank_friction, box_friction, &incline);
    const double expected = gravity_magnitude(world) * (sin(angle) - mixed_friction * cos(angle));
    const double a = slope_acceleration(world, &incline);
    cr_expect(fabs(a - expected) <= 0.03 * expected,
              "θ = %g, friction %g on %g: a = %.5f m/s², expected g·(sin θ - μ·cos θ) = %.5f (μ = %g)", angle,
              box_friction, plank_friction, a, expected, mixed_friction);
    destroy_world_and_expect_no_leak(world);
}

Test(contacts, box_stays_on_an_incline_below_the_friction_angle)
{
    /* tan 0.3 = 0.31 < μ = 0.6. */
    scene_incline incline;
    rb_world *world = make_incline(0.3, 0.6, 0.6, &incline);
    const rb_vec2 start = rb_body_position(world, incline.box);
    step_world(world, TEST_DT, 120);
    const double moved = rb_distance(start, rb_body_position(world, incline.box));
    cr_expect(moved < 1e-3, "the box moved %g m in 2 s below the friction angle (limit 1 mm)", moved);
    destroy_world_and_expect_no_leak(world);
}

Test(contacts, box_slides_down_an_incline_above_the_friction_angle)
{
    /* tan 0.5 = 0.55 > μ = 0.2: a = 9.8·(0.479 - 0.2·0.878) = 2.98 m/s². */
    expect_slide(0.5, 0.2, 0.2, 0.2);
    /* Frictionless: a = g·sin θ. */
    expect_slide(0.5, 0.0, 0.0, 0.0);
}

Test(contacts, friction_mixes_as_the_geometric_mean)
{
    /* sqrt(0.8·0.05) = 0.2. The larger (0.8 > tan 0.5) would hold the box;
     * the smaller (0.05) would give a 43 % larger acceleration, the mean
     * (0.425) a 65 % smaller one. */
    expect_slide(0.5, 0.8, 0.05, 0.2);
    /* A frictionless shape slides on anything. */
    expect_slide(0.5, 1.0, 0.0, 0.0);
}

Test(contacts, friction_changed_while_touching_takes_effect)
{
    /* A contact mixes its shapes' frictions when it begins: a change while
     * it lasts must mix them again. The box rests for 1 s at tan 0.5 =
     * 0.55 < μ = 0.6, then its friction drops to 1/15, mixed with the
     * plank's 0.6 to sqrt(0.6/15) = 0.2: a = g·(sin θ - 0.2·cos θ). */
    scene_incline incline;
    rb_world *world = make_incline(0.5, 0.6, 0.6, &incline);
    cr_assert_eq(rb_body_enable_sleep(world, incline.box, false), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 60);
    cr_assert_eq(rb_world_contact_count(world), 1, "the box should touch the plank after 1 s");
    const double held = rb_length(rb_body_linear_velocity(world, incline.box));
    cr_assert(held < 1e-3, "the box slid at %g m/s at μ = 0.6 above tan θ = 0.55", held);
    cr_assert_eq(rb_shape_set_friction(world, first_shape(world, incline.box), 1.0 / 15.0), RB_OK, "%s",
                 rb_last_error());
    const double expected = gravity_magnitude(world) * (sin(0.5) - 0.2 * cos(0.5));
    const double a = slope_acceleration(world, &incline);
    cr_expect(fabs(a - expected) <= 0.03 * expected,
              "friction changed in contact: a = %.5f m/s², expected g·(sin θ - 0.2·cos θ) = %.5f", a, expected);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Resting contact --------------------------------------------------- */

/* A unit box resting on the ground, with the given linear and angular
 * damping (1/s); contacts[0] is its contact after 1 s. */
static rb_world *rest_box(double damping, rb_contact_data *contacts)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, -1.0), 0.0);
    add_box(world, ground, 10.0, 1.0, 1.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.5), 0.0);
    add_box(world, box, 0.5, 0.5, 1.0);
    cr_assert_eq(rb_body_set_linear_damping(world, box, damping), RB_OK);
    cr_assert_eq(rb_body_set_angular_damping(world, box, damping), RB_OK);
    step_world(world, TEST_DT, 60);
    cr_assert_eq(rb_world_contacts(world, contacts, 4), 1, "one contact expected");
    return world;
}

Test(contacts, a_damped_resting_box_still_carries_its_weight)
{
    /* Damping is a drag: at rest it exerts nothing, so the ground carries
     * the whole weight m·g·h per substep whatever the damping. Damped
     * before the contact solve, a body with c = 8/s would load the ground
     * with m·g·h/(1 + h·c), 2.2 % short at h = 1/360 s; 0.1 % is far
     * below that and above the settled rounding. */
    rb_contact_data contacts[4];
    rb_world *world = rest_box(8.0, contacts);
    double impulse = 0.0;
    for (int i = 0; i < contacts[0].manifold.point_count; ++i) {
        impulse += contacts[0].manifold.points[i].normal_impulse;
    }
    const double weight_impulse = 1.0 * gravity_magnitude(world) * substep_of(world, TEST_DT);
    expect_near(impulse, weight_impulse, 0.001 * weight_impulse, "Σ normal impulse of a damped box = m·g·h");
    destroy_world_and_expect_no_leak(world);
}

Test(contacts, resting_box_contact_impulses_carry_its_weight)
{
    rb_contact_data contacts[4];
    rb_world *world = rest_box(0.0, contacts);

    /* At rest, the normal impulses of a substep (the impulses reported are
     * the last substep's) cancel its gravity impulse m·g·h (m = 1 kg). 1 % leaves room for the last of the
     * settling; an impulse lost or counted twice is off by 50 % or more. */
    cr_expect_eq(contacts[0].manifold.point_count, 2, "a face resting on a face has two points");
    double impulse = 0.0;
    for (int i = 0; i < contacts[0].manifold.point_count; ++i) {
        impulse += contacts[0].manifold.points[i].normal_impulse;
    }
    const double weight_impulse = 1.0 * gravity_magnitude(world) * substep_of(world, TEST_DT);
    expect_near(impulse, weight_impulse, 0.01 * weight_impulse, "Σ normal impulse = m·g·dt");
    cr_expect(contacts[0].touching, "the resting contact is touching");
    destroy_world_and_expect_no_leak(world);
}

/* ---- Sensors ------------------------------------------------------------- */

Test(contacts, sensor_detects_overlap_but_never_pushes)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    const double g = gravity_magnitude(world);
    /* A sensor box spanning y = 0.5 .. 1.5 and a ball of radius 0.25
     * falling through it from y = 3. */
    rb_body_id zone = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 1.0), 0.0);
    rb_polygon box;
    cr_assert_eq(rb_make_box(1.0, 0.5, &box), RB_OK, "%s", rb_last_error());
    rb_shape_def def = rb_default_shape_def();
    def.is_sensor = true;
    rb_shape_id sensor;
    cr_assert_eq(rb_shape_create_polygon(world, zone, &def, &box, &sensor), RB_OK, "%s", rb_last_error());
    cr_expect(rb_shape_is_sensor(world, sensor), "the shape should be a sensor");

    const double radius = 0.25, y0 = 3.0;
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, y0), 0.0);
    rb_shape_id ball_shape = add_circle(world, ball, rb_v2(0.0, 0.0), radius, 1.0);

    int overlapping_steps = 0;
    for (int n = 1; n <= 60; ++n) {
        step_world(world, TEST_DT, 1);
        /* Never pushed: the ball is in free fall (closed form and tolerance
         * as in test_integration.c). */
        const double t = n * TEST_DT;
        const double y = rb_body_position(world, ball).y;
        const double y_expected = y0 - 0.5 * g * t * (t + substep_of(world, TEST_DT));
        cr_expect(fabs(y - y_expected) <= 1e-12 * (y0 + g * t * t), "step %d: y = %.17g, free fall gives %.17g", n, y,
                  y_expected);

        const double bottom = y - radius, top = y + radius;
        const bool expected = bottom < 1.5 && top > 0.5;
        rb_shape_id found[4];
        const int count = rb_shape_sensor_overlaps(world, sensor, found, 4);
        cr_expect_eq(count, expected ? 1 : 0, "step %d: ball spans y = %g .. %g, the sensor reports %d overlaps", n,
                     bottom, top, count);
        if (count == 1) {
            cr_expect(rb_shape_id_equals(found[0], ball_shape), "step %d: the overlap is not the ball", n);
        }
        overlapping_steps += expected;
    }
    /* The ball crosses the 1.5 m band of centre heights at 5 .. 7 m/s. */
    cr_expect(overlapping_steps >= 10, "the ball overlapped the sensor in only %d steps", overlapping_steps);

    cr_expect_eq(rb_shape_sensor_overlaps(world, ball_shape, NULL, 0), -1, "a non-sensor shape has no overlaps");
    cr_expect_neq(rb_last_status(), RB_OK, "asking a non-sensor shape for overlaps is an error");
    destroy_world_and_expect_no_leak(world);
}

Test(contacts, a_moving_sensor_finds_a_solid_shape_created_later)
{
    /* The models' bones are sensors on moving bodies, their nails solid
     * static boxes. While every shape is a sensor no pair can exist; a
     * solid shape created later must still be found. A sensor ball of
     * radius 0.25 falls from y = 1 in zero gravity at 1 m/s; after 10
     * steps a static box spanning y = -0.1 .. 0.1 appears below it, and
     * the ball overlaps it once its bottom passes y = 0.1 (t > 0.65 s). */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 1.0), 0.0);
    cr_assert_eq(rb_body_set_linear_velocity(world, ball, rb_v2(0.0, -1.0)), RB_OK);
    rb_circle circle = {{0.0, 0.0}, 0.25};
    rb_shape_def def = rb_default_shape_def();
    def.is_sensor = true;
    rb_shape_id sensor;
    cr_assert_eq(rb_shape_create_circle(world, ball, &def, &circle, &sensor), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 10);
    rb_body_id nail = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_id box = add_box(world, nail, 0.5, 0.1, 0.0);
    int first_overlap = -1;
    for (int n = 11; n <= 60 && first_overlap < 0; ++n) {
        step_world(world, TEST_DT, 1);
        rb_shape_id found[2];
        if (rb_shape_sensor_overlaps(world, sensor, found, 2) == 1) {
            cr_expect(rb_shape_id_equals(found[0], box));
            first_overlap = n;
        }
    }
    /* The bottom is at 0.75 - t: below 0.1 from t = 0.65 s, first seen after step 40. */
    cr_expect_eq(first_overlap, 40, "first overlap after step %d", first_overlap);
    destroy_world_and_expect_no_leak(world);
}

Test(contacts, a_shape_bounding_box_follows_its_body)
{
    /* A 0.2 x 0.1 m half-extent box turned 90 degrees at (1, 2): its box
     * spans 0.1 m in x and 0.2 m in y about the centre, also right after
     * the body is moved, before any step. */
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_id shape = add_box(world, body, 0.2, 0.1, 1.0);
    cr_assert_eq(rb_body_set_transform(world, body, rb_v2(1.0, 2.0), 0.5 * RB_PI), RB_OK);
    rb_aabb box = rb_shape_aabb(world, shape);
    expect_vec_near(box.lower, rb_v2(0.9, 1.8), 1e-12, "lower corner");
    expect_vec_near(box.upper, rb_v2(1.1, 2.2), 1e-12, "upper corner");
    destroy_world_and_expect_no_leak(world);
}

/* ---- Collision filters ----------------------------------------------------
 *
 * A ball of radius 0.25 whose lowest point is 0.5 m above a ground box (top
 * face y = 0) falls for one second. Either it lands and rests with its
 * centre one radius up, or it falls through as if the ground were not
 * there: then its height is the free-fall closed form. */
#define FILTER_RADIUS 0.25
#define FILTER_Y0 0.75

static double drop_ball_with_filters(rb_filter ground_filter, rb_filter ball_filter, double *free_fall_y)
{
    rb_world *world = make_world(rb_default_world_def().gravity);
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, -1.0), 0.0);
    cr_assert_eq(rb_shape_set_filter(world, add_box(world, ground, 10.0, 1.0, 1.0), ground_filter), RB_OK, "%s",
                 rb_last_error());
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, FILTER_Y0), 0.0);
    cr_assert_eq(rb_shape_set_filter(world, add_circle(world, ball, rb_v2(0.0, 0.0), FILTER_RADIUS, 1.0), ball_filter),
                 RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 60);
    const double g = gravity_magnitude(world);
    *free_fall_y = FILTER_Y0 - 0.5 * g * 1.0 * (1.0 + substep_of(world, TEST_DT));
    const double y = rb_body_position(world, ball).y;
    destroy_world_and_expect_no_leak(world);
    return y;
}

static rb_filter filter(uint32_t category, uint32_t mask, int32_t group)
{
    return (rb_filter){.category_bits = category, .mask_bits = mask, .group_index = group};
}

static void expect_falls_through(rb_filter ground, rb_filter ball, const char *what)
{
    double free_fall;
    const double y = drop_ball_with_filters(ground, ball, &free_fall);
    /* As in test_integration.c: 1e-12 of the size of the terms,
     * |y0| + ½·g·t·(t + h) < 6 m. */
    cr_expect(fabs(y - free_fall) <= 1e-12 * 6.0, "%s: ball at y = %.17g, free fall through the ground gives %.17g",
              what, y, free_fall);
}

/* Resting: the centre one radius above the ground, within 2 linear slops. */
static void expect_lands(rb_filter ground, rb_filter ball, const char *what)
{
    double free_fall;
    const double y = drop_ball_with_filters(ground, ball, &free_fall);
    const double slop = rb_default_solver_settings().linear_slop;
    cr_expect(fabs(y - FILTER_RADIUS) <= 2.0 * slop, "%s: ball at y = %g, expected to rest at %g", what, y,
              FILTER_RADIUS);
}

Test(contacts, default_filters_collide)
{
    const rb_filter d = rb_default_filter();
    cr_expect(d.category_bits == 1 && d.mask_bits == UINT32_MAX && d.group_index == 0, "shape.h's default filter");
    expect_lands(d, d, "default filters");
}

Test(contacts, category_and_mask_stop_collisions_both_ways)
{
    expect_falls_through(filter(0x1, ~UINT32_C(0x2), 0), filter(0x2, UINT32_MAX, 0),
                         "ground's mask excludes the ball's category");
    expect_falls_through(filter(0x4, UINT32_MAX, 0), filter(0x2, ~UINT32_C(0x4), 0),
                         "ball's mask excludes the ground's category");
    expect_lands(filter(0x4, 0x2, 0), filter(0x2, 0x4, 0), "each category in the other's mask");
}

Test(contacts, shared_negative_group_never_collides)
{
    expect_falls_through(filter(1, UINT32_MAX, -3), filter(1, UINT32_MAX, -3), "shared group -3");
    expect_lands(filter(1, UINT32_MAX, -3), filter(1, UINT32_MAX, -4), "different negative groups use the masks");
}

Test(contacts, shared_positive_group_always_collides)
{
    expect_lands(filter(0x1, 0, 3), filter(0x2, 0, 3), "shared group 3 despite empty masks");
}

/* The deepest overlap among the contacts' manifolds, which the narrow
 * phase computed at the start of the last step: the exact overlap the
 * step before it left. */
static double deepest_overlap_at_step_start(const rb_world *world, rb_contact_data *contacts, int capacity)
{
    int count = rb_world_contacts(world, contacts, capacity);
    cr_assert_lt(count, capacity, "more contacts than the test's buffer");
    double deepest = 0.0;
    for (int k = 0; k < count; ++k) {
        for (int j = 0; j < contacts[k].manifold.point_count; ++j) {
            deepest = fmax(deepest, -contacts[k].manifold.points[j].separation);
        }
    }
    return deepest;
}

/* The statistic's deepest overlap after a step against the narrow phase's
 * at the start of the next, the exact one at the same poses. Balls
 * raining on a pyramid are pushed past the ends of the faces they touch,
 * where the solver's contact points, carried with the bodies, read them
 * deeper than they are (a 0.13 m overlap reported where the narrow phase
 * found under 0.02 m): above four linear slops the statistic must be the
 * narrow phase's. */
Test(contacts, the_reported_deepest_overlap_is_the_narrow_phase_s_when_it_is_large)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    scene_rain rain;
    cr_assert_eq(scene_rain_create(world, 40, 120, 1, &rain), RB_OK, "%s", rb_last_error());
    enum { CAPACITY = 4096 };
    static rb_contact_data contacts[CAPACITY];
    const double trusted = 4.0 * rb_world_solver_settings(world).linear_slop;
    step_world(world, TEST_DT, 1);
    double reported = rb_world_statistics(world).max_penetration;
    double worst_excess = 0.0;
    int worst_step = -1;
    for (int step = 1; step < 240; ++step) {
        step_world(world, TEST_DT, 1);
        double exact = deepest_overlap_at_step_start(world, contacts, CAPACITY);
        double excess = reported - fmax(exact, trusted);
        if (excess > worst_excess) {
            worst_excess = excess;
            worst_step = step - 1;
        }
        reported = rb_world_statistics(world).max_penetration;
    }
    cr_expect_leq(worst_excess, 1e-9, "after step %d the reported overlap exceeded the narrow phase's by %.4f m",
                  worst_step, worst_excess);
    destroy_world_and_expect_no_leak(world);
}
