/* SPDX-License-Identifier: MIT */
/* Joints: drift of a chain and of the peers' 100:1 chain, revolute limits
 * and motor, weld reactions, distance spring and rope, the mouse joint,
 * and the API around them: invalid definitions, joints between bodies
 * that cannot move, collide_connected, destruction with a body, the
 * reaction force at rest and the getters.
 *
 * Sign convention (joint.h): the reaction force and torque are what the
 * joint applied to body B during the last step; body A received the
 * opposite.
 */
#include <math.h>
#include <string.h>

#include "scenes/scenes.h"
#include "test_support.h"

#define G 9.8 /* m/s² */
#define DT_240 (1.0 / 240.0)

static double radians(double degrees) { return degrees * RB_PI / 180.0; }

/* The largest distance between a joint's two world anchors, from the
 * anchor getters. */
static double largest_gap(const rb_world *world, const rb_joint_id *joints, int count)
{
    double gap = 0.0;
    for (int i = 0; i < count; ++i) {
        gap = fmax(gap,
                   rb_distance(rb_joint_world_anchor_a(world, joints[i]), rb_joint_world_anchor_b(world, joints[i])));
    }
    return gap;
}

/* A circle of radius r and density ρ centred on a new dynamic body. */
static rb_body_id make_ball(rb_world *world, rb_vec2 position, double radius, double density)
{
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, position, 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), radius, density);
    return ball;
}

/* ---- Drift of chains ---------------------------------------------------------- */

/* Steps a chain `steps` times at dt and returns its worst gap, checking
 * after every step that the world's max_joint_gap is the largest anchor
 * gap measured from the getters: both are the distance between the same
 * two points of the same poses, so they agree to rounding (1e-16 of the
 * chain's few metres; 1e-12 m is generous). */
static double worst_gap_over(rb_world *world, const rb_joint_id *joints, int count, double dt, int steps)
{
    double worst = 0.0, worst_mismatch = 0.0;
    for (int n = 1; n <= steps; ++n) {
        step_world(world, dt, 1);
        const double gap = rb_world_statistics(world).max_joint_gap;
        worst_mismatch = fmax(worst_mismatch, fabs(gap - largest_gap(world, joints, count)));
        worst = fmax(worst, gap);
    }
    cr_expect(worst_mismatch <= 1e-12, "max_joint_gap differs from the anchors' largest gap by up to %g m",
              worst_mismatch);
    cr_expect_eq(rb_world_statistics(world).joint_count, count, "joint_count is %d, expected %d",
                 rb_world_statistics(world).joint_count, count);
    return worst;
}

/* Ten boxes of half-extents 0.25 × 0.05 m and density 1, end to end along
 * +x from a static pin at the origin (the peers' chain without its heavy
 * box, models/scenes), released from horizontal and stepped for 60 s at
 * 60 Hz with the default settings: every anchor gap stays below 5 mm (the
 * required bound, the linear slop). */
Test(joints, chain_of_10_links_stays_together_for_60_s)
{
    enum { LINKS = 10 };
    rb_world *world = make_world(rb_v2(0.0, -G));
    scene_chain chain;
    cr_assert_eq(scene_chain_create(world, LINKS, 0.0, SCENE_CHAIN_SWING, &chain), RB_OK, "scene_chain_create: %s",
                 rb_last_error());
    cr_assert_eq(chain.joint_count, LINKS, "the chain has %d joints, expected %d", chain.joint_count, LINKS);
    const double worst = worst_gap_over(world, chain.joints, LINKS, TEST_DT, 3600);
    cr_expect(worst < 0.005, "the 10-link chain's worst anchor gap over 60 s is %.6f m, above 5 mm", worst);
    destroy_world_and_expect_no_leak(world);
}

/* The shared chain and cantilever scenes refuse what they cannot build,
 * with the engine's error code and a message. */
Test(joints, scenes_refuse_bad_arguments)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    scene_chain chain;
    cr_expect_eq(scene_chain_create(world, 10, -1.0, SCENE_CHAIN_SWING, &chain), RB_ERR_INVALID_ARGUMENT,
                 "a negative heavy density");
    cr_expect(strstr(rb_last_error(), "heavy_density") != NULL, "the message names the field: %s", rb_last_error());
    cr_expect_eq(scene_chain_create(world, 10, NAN, SCENE_CHAIN_SWING, &chain), RB_ERR_INVALID_ARGUMENT,
                 "a NaN heavy density");
    cr_expect_eq(scene_chain_create(world, 0, 0.0, SCENE_CHAIN_SWING, &chain), RB_ERR_INVALID_ARGUMENT, "no links");
    scene_cantilever cantilever;
    cr_expect_eq(scene_cantilever_create(NULL, &cantilever), RB_ERR_INVALID_ARGUMENT, "no world");
    cr_expect_eq(scene_cantilever_create(world, NULL), RB_ERR_INVALID_ARGUMENT, "no result");
    cr_expect_eq(rb_world_statistics(world).body_count, 0, "nothing was built");
    destroy_world_and_expect_no_leak(world);
}

/* The peers' hard case (docs/benchmarks.md): 40 links and a box 100
 * times heavier, swinging from horizontal, gravity (0, -10), 60 Hz, the
 * default solver settings: the worst gap over 0-5 s stays below 0.1 m
 * (Box2D 2.4 and Chipmunk come apart by metres; Box2D v3 with 4 substeps
 * keeps 0.063 m). */
Test(joints, chain_with_a_100_to_1_end_box_holds_together)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    scene_chain chain;
    cr_assert_eq(scene_chain_create(world, 40, 20.0, SCENE_CHAIN_SWING, &chain), RB_OK, "scene_chain_create: %s",
                 rb_last_error());
    cr_assert_eq(chain.joint_count, 41, "the chain has %d joints, expected 41", chain.joint_count);
    const double worst = worst_gap_over(world, chain.joints, chain.joint_count, TEST_DT, 300);
    cr_expect(worst < 0.1, "the 100:1 chain's worst anchor gap over 5 s is %.4f m, above 0.1 m", worst);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Revolute limits ------------------------------------------------------------ */

/* A bob pinned below a static pivot at the origin: a circle of radius
 * 0.05 m and density 100 centred at L = 1 m from the pivot, its body
 * created turned by θ about the pivot. The joint's anchors are the origin
 * on the ground and (0, L) on the bob, its reference angle 0: the joint
 * angle is the bob's body angle, 0 hanging straight down. */
#define BOB_RADIUS 0.05
#define BOB_DENSITY 100.0
#define BOB_ARM 1.0

typedef struct bob {
    rb_world *world;
    rb_body_id ground, body;
    rb_joint_id joint;
} bob;

static bob make_limited_bob(rb_vec2 gravity, double theta, rb_revolute_joint_def def)
{
    bob b = {.world = make_world(gravity)};
    b.ground = make_body(b.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    b.body = make_body(b.world, RB_BODY_DYNAMIC, rb_v2(BOB_ARM * sin(theta), -BOB_ARM * cos(theta)), theta);
    add_circle(b.world, b.body, rb_v2(0.0, 0.0), BOB_RADIUS, BOB_DENSITY);
    def.body_a = b.ground;
    def.body_b = b.body;
    def.local_anchor_a = rb_v2(0.0, 0.0);
    def.local_anchor_b = rb_v2(0.0, BOB_ARM);
    def.reference_angle = 0.0;
    cr_assert_eq(rb_revolute_joint_create(b.world, &def, &b.joint), RB_OK, "%s", rb_last_error());
    return b;
}

/* Sets the bob turning about the pivot at ω: the rigid motion
 * v = ω × (c - pivot) with the body's own angular velocity ω. */
static void turn_about_pivot(const bob *b, double omega)
{
    const rb_vec2 c = rb_body_world_center(b->world, b->body);
    cr_assert_eq(rb_body_set_linear_velocity(b->world, b->body, rb_cross_sv(omega, c)), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_angular_velocity(b->world, b->body, omega), RB_OK, "%s", rb_last_error());
}

/* Steps a bob and tracks its joint angle, angle(B) - angle(A) from the
 * bodies: its extremes, and how far rb_revolute_joint_angle is from it
 * (the same difference of the same state: rounding only). */
typedef struct angle_record {
    double lowest, highest, worst_getter_error;
} angle_record;

static void record_steps(const bob *b, int steps, angle_record *record)
{
    for (int n = 0; n < steps; ++n) {
        step_world(b->world, TEST_DT, 1);
        const double angle = rb_body_angle(b->world, b->body) - rb_body_angle(b->world, b->ground);
        record->lowest = fmin(record->lowest, angle);
        record->highest = fmax(record->highest, angle);
        record->worst_getter_error =
            fmax(record->worst_getter_error, fabs(rb_revolute_joint_angle(b->world, b->joint) - angle));
    }
}

/* The tolerance on a limit: the solver may leave an error of one linear
 * slop uncorrected; the limit's angle error moves the bob's centre, at
 * BOB_ARM from the pivot, by BOB_ARM times the angle, so the slop as an
 * angle is slop/BOB_ARM (0.005 rad, 0.29°). */
static double limit_tolerance(const rb_world *world) { return rb_world_solver_settings(world).linear_slop / BOB_ARM; }

/* A bob under gravity at theta (rad) on a hinge limited to [-30°, 30°];
 * *def is the hinge's definition. */
static bob bob_within_30_degrees(double theta, rb_revolute_joint_def *def)
{
    *def = rb_default_revolute_joint_def();
    def->enable_lower_limit = def->enable_upper_limit = true;
    def->lower_angle = radians(-30.0);
    def->upper_angle = radians(30.0);
    return make_limited_bob(rb_v2(0.0, -G), theta, *def);
}

/* Limits [-30°, 30°]; released at 25° turning towards the upper limit as
 * fast as a free swing to 120° needs (½·I_p·ω0² = m·g·L·(cos 25° -
 * cos 120°), I_p = m·r²/2 + m·L²), at 60 Hz, where the bob turns up to 5°
 * in a step: a limit that acts only once passed would be overshot by
 * degrees. After 1 s the bob is thrown as fast towards the lower limit.
 * At every step the angle stays in the limits ± the slop as an angle, and
 * both limits are reached. */
Test(joints, revolute_limits_stop_a_fast_swing)
{
    rb_revolute_joint_def def;
    const double theta0 = radians(25.0);
    bob b = bob_within_30_degrees(theta0, &def);
    const double m = BOB_DENSITY * RB_PI * BOB_RADIUS * BOB_RADIUS;
    const double pivot_inertia = 0.5 * m * BOB_RADIUS * BOB_RADIUS + m * BOB_ARM * BOB_ARM;
    const double omega0 = sqrt(2.0 * m * G * BOB_ARM * (cos(theta0) - cos(radians(120.0))) / pivot_inertia);
    turn_about_pivot(&b, omega0);

    angle_record record = {.lowest = theta0, .highest = theta0};
    record_steps(&b, 60, &record);
    turn_about_pivot(&b, -omega0);
    record_steps(&b, 120, &record);

    const double tolerance = limit_tolerance(b.world);
    cr_expect(record.highest <= def.upper_angle + tolerance,
              "the angle reached %.6f rad, upper limit %.6f rad (tolerance %g rad)", record.highest, def.upper_angle,
              tolerance);
    cr_expect(record.lowest >= def.lower_angle - tolerance,
              "the angle reached %.6f rad, lower limit %.6f rad (tolerance %g rad)", record.lowest, def.lower_angle,
              tolerance);
    cr_expect(record.highest >= def.upper_angle - tolerance, "the bob never reached the upper limit (%.6f rad)",
              record.highest);
    cr_expect(record.lowest <= def.lower_angle + tolerance, "the bob never reached the lower limit (%.6f rad)",
              record.lowest);
    cr_expect(record.worst_getter_error <= 1e-12, "rb_revolute_joint_angle differs from the bodies' angles by %g rad",
              record.worst_getter_error);
    destroy_world_and_expect_no_leak(b.world);
}

/* The soft step at Box2D v3's budget (4 substeps of 1 solve and 1 relax
 * pass), the bob thrown at 12 rad/s against its upper limit. A limit is
 * speculative: a pass lets the joint close the margin left at the
 * substep's poses, no more, so the bob meets its stop and does not pass
 * it (to rounding). The relax pass comes after the positions moved
 * within the substep, so it must measure the margin there: with the
 * margin of the substep's start it let the bob pass its stop by 0.2°. */
Test(joints, revolute_limit_holds_through_the_soft_steps_relax_pass)
{
    rb_revolute_joint_def def;
    const double theta0 = radians(25.0);
    bob b = bob_within_30_degrees(theta0, &def);
    rb_solver_settings settings = rb_world_solver_settings(b.world);
    settings.type = RB_SOLVER_SOFT_STEP;
    settings.substeps = 4;
    settings.velocity_iterations = 1;
    settings.relax_iterations = 1;
    cr_assert_eq(rb_world_set_solver_settings(b.world, &settings), RB_OK, "%s", rb_last_error());
    turn_about_pivot(&b, 12.0);
    angle_record record = {.lowest = theta0, .highest = theta0};
    record_steps(&b, 60, &record);
    cr_expect(record.highest <= def.upper_angle + 1e-9, "the angle reached %.9f rad, upper limit %.9f rad",
              record.highest, def.upper_angle);
    cr_expect(record.highest >= def.upper_angle - 1e-3, "the bob never reached its limit (%.6f rad)", record.highest);
    destroy_world_and_expect_no_leak(b.world);
}

/* Only the lower limit, at -30°; the upper angle is set to 30° but not
 * enabled. In zero gravity the bob is thrown at 3 rad/s against the
 * lower limit, which stops it, then at 3 rad/s the other way: it turns
 * freely far past 30° (beyond 90° within the second), the limit giving no
 * torque while the bob is on the free side (angle > 0: more than 30° from
 * the limit, six steps' turn at this speed). */
Test(joints, revolute_lower_limit_alone_leaves_the_other_side_free)
{
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    def.enable_lower_limit = true;
    def.lower_angle = radians(-30.0);
    def.upper_angle = radians(30.0);
    bob b = make_limited_bob(rb_v2(0.0, 0.0), 0.0, def);
    turn_about_pivot(&b, -3.0);
    angle_record record = {.lowest = 0.0, .highest = 0.0};
    record_steps(&b, 60, &record);
    turn_about_pivot(&b, 3.0);
    double largest_free_torque = 0.0;
    for (int n = 0; n < 60; ++n) {
        record_steps(&b, 1, &record);
        if (rb_revolute_joint_angle(b.world, b.joint) > 0.0) {
            largest_free_torque = fmax(largest_free_torque, fabs(rb_joint_reaction_torque(b.world, b.joint)));
        }
    }
    const double tolerance = limit_tolerance(b.world);
    cr_expect(record.lowest >= def.lower_angle - tolerance,
              "the angle reached %.6f rad, lower limit %.6f rad (tolerance %g rad)", record.lowest, def.lower_angle,
              tolerance);
    cr_expect(record.lowest <= def.lower_angle + tolerance, "the bob never reached the lower limit (%.6f rad)",
              record.lowest);
    cr_expect(record.highest > radians(90.0), "the bob turned only to %.4f rad on the free side", record.highest);
    cr_expect_eq(largest_free_torque, 0.0, "the joint applied a torque of %g N·m on the free side",
                 largest_free_torque);
    destroy_world_and_expect_no_leak(b.world);
}

/* ---- Motor ------------------------------------------------------------------------ */

/* A wheel: a circle of radius 0.5 m and density 1 (m = π/4 kg,
 * I = m·r²/2 = π/32 kg·m²) pinned at its centre to a static body in zero
 * gravity. The pin's force acts at the centre and exerts no torque, so
 * only the motor turns the wheel. */
#define WHEEL_RADIUS 0.5
#define WHEEL_INERTIA (0.5 * (RB_PI * WHEEL_RADIUS * WHEEL_RADIUS) * WHEEL_RADIUS * WHEEL_RADIUS)

typedef struct wheel {
    rb_world *world;
    rb_body_id body;
    rb_joint_id joint;
} wheel;

static wheel make_wheel(void)
{
    wheel w = {.world = make_world(rb_v2(0.0, 0.0))};
    rb_body_id ground = make_body(w.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    w.body = make_ball(w.world, rb_v2(2.0, 1.0), WHEEL_RADIUS, 1.0);
    w.joint = make_pin(w.world, ground, w.body, rb_v2(2.0, 1.0));
    return w;
}

/* Target 2 rad/s with up to 10 N·m: the motor gives I·2 = 0.196 N·m·s in
 * two steps of at most 10/60 N·m·s. A single angular constraint on one
 * body is solved exactly, so after 1 s the speed is the target to
 * rounding (1e-9 relative is generous) and the motor, unloaded, gives no
 * torque. */
Test(joints, motor_reaches_its_speed_when_its_torque_suffices)
{
    wheel w = make_wheel();
    cr_assert_eq(rb_revolute_joint_set_motor(w.world, w.joint, true, 2.0, 10.0), RB_OK, "%s", rb_last_error());
    step_world(w.world, TEST_DT, 60);
    expect_near(rb_body_angular_velocity(w.world, w.body), 2.0, 2e-9, "wheel speed");
    expect_near(rb_revolute_joint_speed(w.world, w.joint), 2.0, 2e-9, "rb_revolute_joint_speed");
    expect_near(rb_revolute_joint_motor_torque(w.world, w.joint), 0.0, 1e-9 * 10.0, "unloaded motor torque");
    destroy_world_and_expect_no_leak(w.world);
}

/* Target 100 rad/s with 0.05 N·m: the motor saturates and the wheel
 * accelerates at α = τ_max/I = 0.509 rad/s² (it would need 196 s to reach
 * the target). α from two consecutive steps and the motor's torque are
 * exact to rounding (1e-9 relative). */
Test(joints, motor_without_enough_torque_accelerates_at_max_torque_over_inertia)
{
    const double max_torque = 0.05;
    wheel w = make_wheel();
    cr_assert_eq(rb_revolute_joint_set_motor(w.world, w.joint, true, 100.0, max_torque), RB_OK, "%s", rb_last_error());
    step_world(w.world, TEST_DT, 10);
    const double alpha = max_torque / WHEEL_INERTIA;
    double omega = rb_body_angular_velocity(w.world, w.body);
    for (int n = 0; n < 2; ++n) {
        step_world(w.world, TEST_DT, 1);
        const double next = rb_body_angular_velocity(w.world, w.body);
        expect_near((next - omega) / TEST_DT, alpha, 1e-9 * alpha, "angular acceleration");
        expect_near(rb_revolute_joint_motor_torque(w.world, w.joint), max_torque, 1e-9 * max_torque,
                    "saturated motor torque");
        omega = next;
    }
    destroy_world_and_expect_no_leak(w.world);
}

/* ---- Weld -------------------------------------------------------------------------- */

/* The welded cantilever of models/scenes (scene_cantilever): plank 1
 * (0.2 kg, centre (0.5, 0)) welded at (0, 0) to a static wall, plank 2
 * (0.4 kg, centre (1.5, 0)) welded to plank 1 at (1, 0); body B of each
 * weld is the outer plank. At rest each weld carries what lies beyond
 * it: the force on B is (0, M·g), M the mass carried, and the torque on B
 * balances the weight's moment about the anchor, τ = M·g·d with d the
 * horizontal distance from the anchor to the carried centre of mass
 * (equilibrium of the carried bodies about the anchor; the anchor force
 * has no moment there). Root weld: M = 0.6 kg, M·d = 0.2·0.5 + 0.4·1.5;
 * tip weld: M = 0.4 kg, d = 0.5 m. Within 1 % (the required bound) after
 * 2 s at 60 Hz; plank 2 stays within the linear slop of where it started
 * at every step. */
Test(joints, welded_cantilever_holds_with_static_reactions)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    scene_cantilever cantilever;
    cr_assert_eq(scene_cantilever_create(world, &cantilever), RB_OK, "scene_cantilever_create: %s", rb_last_error());
    const rb_body_id plank2 = cantilever.plank2;
    const rb_joint_id root = cantilever.root, tip = cantilever.tip;
    const double m1 = 0.2, m2 = 0.4;
    cr_assert_float_eq(rb_body_mass(world, cantilever.plank1), m1, 1e-12, "plank 1's mass");
    cr_assert_float_eq(rb_body_mass(world, plank2), m2, 1e-12, "plank 2's mass");

    const double slop = rb_world_solver_settings(world).linear_slop;
    double worst_sag = 0.0;
    for (int n = 0; n < 120; ++n) {
        step_world(world, TEST_DT, 1);
        worst_sag = fmax(worst_sag, rb_distance(rb_body_world_center(world, plank2), rb_v2(1.5, 0.0)));
    }
    cr_expect(worst_sag <= slop, "plank 2 moved %g m from its place", worst_sag);

    const rb_vec2 root_force = {0.0, (m1 + m2) * G};
    const double root_torque = (m1 * 0.5 + m2 * 1.5) * G;
    const rb_vec2 tip_force = {0.0, m2 * G};
    const double tip_torque = m2 * 0.5 * G;
    expect_vec_near(rb_joint_reaction_force(world, root), root_force, 0.01 * root_force.y,
                    "root weld force on plank 1");
    expect_near(rb_joint_reaction_torque(world, root), root_torque, 0.01 * root_torque, "root weld torque on plank 1");
    expect_vec_near(rb_joint_reaction_force(world, tip), tip_force, 0.01 * tip_force.y, "tip weld force on plank 2");
    expect_near(rb_joint_reaction_torque(world, tip), tip_torque, 0.01 * tip_torque, "tip weld torque on plank 2");
    destroy_world_and_expect_no_leak(world);
}

/* ---- Distance joint ------------------------------------------------------------------ */

/* A ball (radius 0.1 m, density 10) on a 2 Hz spring of rest length 1 m
 * without damping, from a static body at the origin to the ball's centre,
 * released 0.2 m stretched along x in zero gravity and stepped at 240 Hz.
 * The anchor is at the centre, so the effective mass the spring acts on
 * is the ball's mass and it oscillates at 2 Hz along x. The soft
 * constraint integrates the spring implicitly, which slows it by about
 * (ω·h)²/3 = 0.1 % (and damps it); the required 2 % bound. The frequency
 * comes from the zero crossings of the stretch, interpolated linearly,
 * over 5 periods. */
Test(joints, distance_spring_oscillates_at_its_frequency)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id ball = make_ball(world, rb_v2(1.2, 0.0), 0.1, 10.0);
    rb_distance_joint_def def = rb_default_distance_joint_def();
    def.body_a = ground;
    def.body_b = ball;
    def.length = 1.0;
    def.enable_spring = true;
    def.spring_hertz = 2.0;
    def.spring_damping_ratio = 0.0;
    rb_joint_id joint;
    cr_assert_eq(rb_distance_joint_create(world, &def, &joint), RB_OK, "%s", rb_last_error());

    double previous = 0.2, first = 0.0, last = 0.0;
    int crossings = 0;
    for (int n = 1; n <= 3 * 240 && crossings < 11; ++n) {
        step_world(world, DT_240, 1);
        const double stretch = rb_body_world_center(world, ball).x - 1.0;
        if ((previous > 0.0) != (stretch > 0.0)) {
            last = (n - 1) * DT_240 + DT_240 * previous / (previous - stretch);
            first = crossings == 0 ? last : first;
            ++crossings;
        }
        previous = stretch;
    }
    cr_assert_eq(crossings, 11, "the stretch crossed zero %d times in 3 s, expected 11", crossings);
    const double hertz = 5.0 / (last - first);
    expect_near(hertz, 2.0, 0.02 * 2.0, "spring frequency (Hz)");
    destroy_world_and_expect_no_leak(world);
}

/* A rope of 1 m (0 Hz spring, limit max_length 1 m) from a static body at
 * the origin to the centre of a ball (radius 0.1 m, density 1) released at
 * rest 0.6 m away along x: the ball falls freely while the rope is slack
 * (exactly as semi-implicit Euler, v = -g·t, for the first 20 steps, when
 * it is still at most 0.83 m out), then swings on it. At every step of 3 s
 * at 60 Hz its distance from the anchor stays below 1 m plus the linear
 * slop, and the rope does become taut. */
Test(joints, rope_never_stretches_beyond_its_length)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id ball = make_ball(world, rb_v2(0.6, 0.0), 0.1, 1.0);
    rb_distance_joint_def def = rb_default_distance_joint_def();
    def.body_a = ground;
    def.body_b = ball;
    def.length = 1.0;
    def.enable_spring = true;
    def.spring_hertz = 0.0;
    def.enable_limit = true;
    def.min_length = 0.0;
    def.max_length = 1.0;
    rb_joint_id rope;
    cr_assert_eq(rb_distance_joint_create(world, &def, &rope), RB_OK, "%s", rb_last_error());

    const double slop = rb_world_solver_settings(world).linear_slop;
    double longest = 0.0, worst_getter_error = 0.0;
    for (int n = 1; n <= 180; ++n) {
        step_world(world, TEST_DT, 1);
        const double length = rb_length(rb_body_world_center(world, ball));
        longest = fmax(longest, length);
        worst_getter_error = fmax(worst_getter_error, fabs(rb_distance_joint_current_length(world, rope) - length));
        if (n <= 20) {
            expect_vec_near(rb_body_linear_velocity(world, ball), rb_v2(0.0, -G * n * TEST_DT), 1e-12 * G,
                            "velocity while the rope is slack");
        }
    }
    cr_expect(longest <= def.max_length + slop, "the rope stretched to %.6f m, max %.6f m plus the slop %g m", longest,
              def.max_length, slop);
    cr_expect(longest >= def.max_length - slop, "the rope never became taut (longest %.6f m)", longest);
    cr_expect(worst_getter_error <= 1e-12, "rb_distance_joint_current_length is off by %g m", worst_getter_error);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Mouse joint --------------------------------------------------------------------- */

/* In zero gravity the mouse joint (5 Hz, damping ratio 0.7, ample force)
 * pulls a ball's centre to the target: the error decays as
 * exp(-ζ·ω·t) = exp(-22·t), so after 3 s it is far below 1e-6 m. */
Test(joints, mouse_joint_pulls_a_body_to_its_target)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ball = make_ball(world, rb_v2(0.0, 0.0), 0.2, 1.0);
    rb_mouse_joint_def def = rb_default_mouse_joint_def();
    def.body = ball;
    def.target = rb_v2(1.0, 0.5);
    rb_joint_id mouse;
    cr_assert_eq(rb_mouse_joint_create(world, &def, &mouse), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 180);
    expect_vec_near(rb_body_world_center(world, ball), def.target, 1e-6, "ball pulled to the target");
    /* A new target: the ball follows. */
    cr_assert_eq(rb_mouse_joint_set_target(world, mouse, rb_v2(-1.0, 2.0)), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 180);
    expect_vec_near(rb_body_world_center(world, ball), rb_v2(-1.0, 2.0), 1e-6, "ball pulled to the new target");
    destroy_world_and_expect_no_leak(world);
}

/* Under gravity with max_force = 2·m·g and a target 4.5 m away: the
 * force is capped, so each step's velocity change less gravity's is at
 * most max_force·dt/m, and the reaction force at most max_force (both to
 * rounding); the cap is reached. Once there the ball hangs where the
 * spring k = m·ω² carries its weight, g/ω² = 9.9 mm below the target
 * (ω = 2π·5 Hz), within 1 % of that sag. */
Test(joints, mouse_joint_force_never_exceeds_max_force)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    const double radius = 0.2;
    const double m = RB_PI * radius * radius;
    rb_body_id ball = make_ball(world, rb_v2(0.0, 0.0), radius, 1.0);
    rb_mouse_joint_def def = rb_default_mouse_joint_def();
    def.body = ball;
    def.target = rb_v2(4.0, 2.0);
    def.max_force = 2.0 * m * G;
    rb_joint_id mouse;
    cr_assert_eq(rb_mouse_joint_create(world, &def, &mouse), RB_OK, "%s", rb_last_error());

    const double max_dv = def.max_force * TEST_DT / m;
    double worst_dv = 0.0, largest_force = 0.0;
    rb_vec2 v = rb_body_linear_velocity(world, ball);
    for (int n = 0; n < 360; ++n) {
        step_world(world, TEST_DT, 1);
        const rb_vec2 next = rb_body_linear_velocity(world, ball);
        worst_dv = fmax(worst_dv, rb_length(rb_sub(rb_sub(next, v), rb_v2(0.0, -G * TEST_DT))));
        largest_force = fmax(largest_force, rb_length(rb_joint_reaction_force(world, mouse)));
        v = next;
    }
    cr_expect(worst_dv <= max_dv * (1.0 + 1e-9), "a step changed the velocity by %.9g m/s beyond gravity, max %.9g",
              worst_dv, max_dv);
    cr_expect(largest_force <= def.max_force * (1.0 + 1e-9), "reaction force %.9g N above max_force %.9g N",
              largest_force, def.max_force);
    cr_expect(largest_force >= def.max_force * (1.0 - 1e-9), "the force never reached max_force (largest %.9g N)",
              largest_force);
    const double omega = 2.0 * RB_PI * def.hertz;
    const double sag = G / (omega * omega);
    expect_vec_near(rb_body_world_center(world, ball), rb_v2(4.0, 2.0 - sag), 0.01 * sag, "ball hanging on the mouse");
    destroy_world_and_expect_no_leak(world);
}

/* ---- Invalid definitions --------------------------------------------------------------- */

static void expect_status(rb_status status, rb_status expected, const char *what)
{
    cr_expect_eq(status, expected, "%s: returned %s, expected %s", what, rb_status_name(status),
                 rb_status_name(expected));
    cr_expect_eq(rb_last_status(), expected, "%s: rb_last_status() is %s", what, rb_status_name(rb_last_status()));
    cr_expect(rb_last_error()[0] != '\0', "%s: no error message", what);
}

/* Every bad definition is refused with its status; then the world steps,
 * the two free balls (moving apart, so that a joint left between them or
 * to the ground would pull) move exactly as free bodies under
 * semi-implicit Euler (x1 = x0 + v0·dt + ½·g·dt·(dt + h) over substeps of
 * h; a few operations on values of order 10: 1e-12), and the world holds
 * only the joints made on purpose. */
Test(joints, invalid_definitions_are_refused_and_leave_the_world_usable)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_world *other = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id a = make_ball(world, rb_v2(-3.0, 5.0), 0.1, 1.0);
    rb_body_id b = make_ball(world, rb_v2(3.0, 5.0), 0.1, 1.0);
    cr_assert_eq(rb_body_set_linear_velocity(world, a, rb_v2(-1.0, 2.0)), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_linear_velocity(world, b, rb_v2(1.5, 0.5)), RB_OK, "%s", rb_last_error());
    rb_body_id gone = make_ball(world, rb_v2(0.0, 9.0), 0.1, 1.0);
    cr_assert_eq(rb_body_destroy(world, gone), RB_OK, "%s", rb_last_error());
    rb_body_id foreign = make_ball(other, rb_v2(0.0, 0.0), 0.1, 1.0);
    const rb_body_id null_body = {0};
    rb_joint_id joint;

    rb_revolute_joint_def good = rb_default_revolute_joint_def();
    good.body_a = a;
    good.body_b = b;
    rb_revolute_joint_def r = good;
    expect_status(rb_revolute_joint_create(world, NULL, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, NULL def");
    expect_status(rb_revolute_joint_create(world, &r, NULL), RB_ERR_INVALID_ARGUMENT, "revolute, NULL out");
    expect_status(rb_revolute_joint_create(NULL, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, NULL world");
    r.body_b = a;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, same body twice");
    r = good;
    r.body_b = gone;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_STALE_ID, "revolute, destroyed body");
    r.body_b = foreign;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_FOREIGN_ID, "revolute, other world's body");
    r.body_b = null_body;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_FOREIGN_ID, "revolute, null body");
    r = good;
    r.enable_lower_limit = r.enable_upper_limit = true;
    r.lower_angle = 0.5;
    r.upper_angle = -0.5;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, lower > upper");
    r = good;
    r.max_motor_torque = -1.0;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, torque < 0");
    r = good;
    r.spring_hertz = -1.0;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, hertz < 0");
    r.spring_hertz = NAN;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, hertz NaN");
    r = good;
    r.local_anchor_a.x = NAN;
    expect_status(rb_revolute_joint_create(world, &r, &joint), RB_ERR_INVALID_ARGUMENT, "revolute, anchor NaN");
    expect_status(rb_revolute_joint_def_at(&r, world, a, b, rb_v2(NAN, 0.0)), RB_ERR_INVALID_ARGUMENT,
                  "rb_revolute_joint_def_at, anchor NaN");

    rb_weld_joint_def weld = rb_default_weld_joint_def();
    weld.body_a = a;
    weld.body_b = b;
    rb_weld_joint_def w = weld;
    w.linear_hertz = NAN;
    expect_status(rb_weld_joint_create(world, &w, &joint), RB_ERR_INVALID_ARGUMENT, "weld, linear hertz NaN");
    w = weld;
    w.angular_hertz = -2.0;
    expect_status(rb_weld_joint_create(world, &w, &joint), RB_ERR_INVALID_ARGUMENT, "weld, angular hertz < 0");
    w = weld;
    w.local_anchor_b.y = NAN;
    expect_status(rb_weld_joint_create(world, &w, &joint), RB_ERR_INVALID_ARGUMENT, "weld, anchor NaN");
    expect_status(rb_weld_joint_create(world, NULL, &joint), RB_ERR_INVALID_ARGUMENT, "weld, NULL def");

    rb_distance_joint_def distance = rb_default_distance_joint_def();
    distance.body_a = a;
    distance.body_b = b;
    distance.length = 1.0;
    rb_distance_joint_def d = distance;
    d.length = 0.0;
    expect_status(rb_distance_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "distance, length 0");
    d.length = -1.0;
    expect_status(rb_distance_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "distance, length < 0");
    d = distance;
    d.enable_limit = true;
    d.min_length = 2.0;
    d.max_length = 1.0;
    expect_status(rb_distance_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "distance, min > max");
    d = distance;
    d.enable_spring = true;
    d.spring_hertz = -1.0;
    expect_status(rb_distance_joint_create(world, &d, &joint), RB_ERR_INVALID_ARGUMENT, "distance, hertz < 0");
    expect_status(rb_distance_joint_create(world, &distance, NULL), RB_ERR_INVALID_ARGUMENT, "distance, NULL out");

    rb_mouse_joint_def mouse = rb_default_mouse_joint_def();
    mouse.body = a;
    mouse.max_force = 10.0;
    mouse.hertz = 5.0;
    mouse.damping_ratio = 0.7;
    rb_mouse_joint_def m = mouse;
    m.body = ground;
    expect_status(rb_mouse_joint_create(world, &m, &joint), RB_ERR_INVALID_ARGUMENT, "mouse on a static body");
    m = mouse;
    m.hertz = 0.0;
    expect_status(rb_mouse_joint_create(world, &m, &joint), RB_ERR_INVALID_ARGUMENT, "mouse, hertz 0");
    m.hertz = NAN;
    expect_status(rb_mouse_joint_create(world, &m, &joint), RB_ERR_INVALID_ARGUMENT, "mouse, hertz NaN");
    m = mouse;
    m.max_force = -1.0;
    expect_status(rb_mouse_joint_create(world, &m, &joint), RB_ERR_INVALID_ARGUMENT, "mouse, max_force < 0");
    m = mouse;
    m.target.x = NAN;
    expect_status(rb_mouse_joint_create(world, &m, &joint), RB_ERR_INVALID_ARGUMENT, "mouse, target NaN");

    /* The setters refuse the same values, and a joint of another type. */
    rb_body_id hinge_body = make_ball(world, rb_v2(0.0, -1.0), 0.1, 1.0);
    rb_joint_id hinge = make_pin(world, ground, hinge_body, rb_v2(0.0, 0.0));
    expect_status(rb_revolute_joint_set_limits(world, hinge, true, 0.5, true, -0.5), RB_ERR_INVALID_ARGUMENT,
                  "rb_revolute_joint_set_limits, lower > upper");
    expect_status(rb_revolute_joint_set_motor(world, hinge, true, 1.0, -1.0), RB_ERR_INVALID_ARGUMENT,
                  "rb_revolute_joint_set_motor, torque < 0");
    expect_status(rb_revolute_joint_set_spring(world, hinge, true, NAN, 0.0), RB_ERR_INVALID_ARGUMENT,
                  "rb_revolute_joint_set_spring, hertz NaN");
    rb_body_id dragged = make_ball(world, rb_v2(10.0, 0.0), 0.1, 1.0);
    m = mouse;
    m.body = dragged;
    m.target = rb_v2(10.0, 0.0);
    rb_joint_id drag;
    cr_assert_eq(rb_mouse_joint_create(world, &m, &drag), RB_OK, "%s", rb_last_error());
    expect_status(rb_mouse_joint_set_target(world, drag, rb_v2(0.0, INFINITY)), RB_ERR_INVALID_ARGUMENT,
                  "rb_mouse_joint_set_target, target infinite");
    expect_status(rb_revolute_joint_set_motor(world, drag, true, 1.0, 1.0), RB_ERR_INVALID_ARGUMENT,
                  "rb_revolute_joint_set_motor on a mouse joint");
    /* A limit on one side only may lie above the other side's unused angle. */
    cr_expect_eq(rb_revolute_joint_set_limits(world, hinge, true, 0.5, false, -0.5), RB_OK, "%s", rb_last_error());

    rb_world_destroy(other);
    const rb_body_id balls[2] = {a, b};
    rb_vec2 x0[2], v0[2];
    for (int i = 0; i < 2; ++i) {
        x0[i] = rb_body_position(world, balls[i]);
        v0[i] = rb_body_linear_velocity(world, balls[i]);
    }
    step_world(world, TEST_DT, 1);
    const double fall = step_displacement(-G, TEST_DT, substep_of(world, TEST_DT));
    for (int i = 0; i < 2; ++i) {
        expect_vec_near(rb_body_linear_velocity(world, balls[i]), rb_add(v0[i], rb_v2(0.0, -G * TEST_DT)), 1e-12 * 10.0,
                        "a free ball's velocity");
        expect_vec_near(rb_body_position(world, balls[i]), rb_add(rb_mul_add(x0[i], TEST_DT, v0[i]), rb_v2(0.0, fall)),
                        1e-12 * 10.0, "a free ball's position");
    }
    cr_expect_eq(rb_world_statistics(world).joint_count, 2, "the world has %d joints, expected 2",
                 rb_world_statistics(world).joint_count);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Bodies that cannot move ---------------------------------------------------------------- */

/* Joints between two static bodies (a pin whose anchors are 3 m apart) and
 * between a static and a kinematic body (a weld) are allowed and do
 * nothing: the static bodies stay, the kinematic body moves as its
 * velocities say (x = x0 + v·t after n additions: 1e-12). */
Test(joints, joint_between_bodies_that_cannot_move_does_nothing)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id left = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    add_box(world, left, 0.5, 0.5, 1.0);
    rb_body_id right = make_body(world, RB_BODY_STATIC, rb_v2(3.0, 0.0), 0.2);
    add_box(world, right, 0.5, 0.5, 1.0);
    rb_revolute_joint_def pin = rb_default_revolute_joint_def();
    pin.body_a = left;
    pin.body_b = right;
    rb_joint_id static_pin;
    cr_assert_eq(rb_revolute_joint_create(world, &pin, &static_pin), RB_OK, "%s", rb_last_error());

    rb_body_def def = rb_default_body_def();
    def.type = RB_BODY_KINEMATIC;
    def.position = rb_v2(0.0, 5.0);
    def.linear_velocity = rb_v2(1.0, 0.5);
    def.angular_velocity = 0.3;
    rb_body_id mover;
    cr_assert_eq(rb_body_create(world, &def, &mover), RB_OK, "%s", rb_last_error());
    add_box(world, mover, 0.5, 0.5, 1.0);
    rb_weld_joint_def weld = rb_default_weld_joint_def();
    cr_assert_eq(rb_weld_joint_def_at(&weld, world, left, mover, rb_v2(0.0, 2.0)), RB_OK, "%s", rb_last_error());
    rb_joint_id kinematic_weld;
    cr_assert_eq(rb_weld_joint_create(world, &weld, &kinematic_weld), RB_OK, "%s", rb_last_error());

    step_world(world, TEST_DT, 60);
    const double t = 60 * TEST_DT;
    const rb_vec2 left_position = rb_body_position(world, left), right_position = rb_body_position(world, right);
    cr_expect(left_position.x == 0.0 && left_position.y == 0.0 && rb_body_angle(world, left) == 0.0,
              "the left static body moved");
    cr_expect(right_position.x == 3.0 && right_position.y == 0.0 && rb_body_angle(world, right) == 0.2,
              "the right static body moved");
    expect_vec_near(rb_body_position(world, mover), rb_v2(t, 5.0 + 0.5 * t), 1e-12, "kinematic body position");
    expect_near(rb_body_angle(world, mover), 0.3 * t, 1e-12, "kinematic body angle");
    expect_vec_near(rb_body_linear_velocity(world, mover), def.linear_velocity, 0.0, "kinematic body velocity");
    destroy_world_and_expect_no_leak(world);
}

/* ---- collide_connected -------------------------------------------------------------------- */

/* A static box and a dynamic box of half-extent 0.5 m overlapping by
 * half their width, pinned at (0.25, 0.4) inside the overlap, in zero
 * gravity. With collide_connected false their shapes do not touch: no
 * contact, and the box stays where it is (rest exactly satisfies the pin:
 * 1e-12). With true the contact pushes the box out; the push acts below
 * the pin, so the box turns about it. */
static rb_world *overlapping_pinned_boxes(bool collide_connected, rb_body_id *box)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    add_box(world, ground, 0.5, 0.5, 1.0);
    *box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.5, 0.0), 0.0);
    add_box(world, *box, 0.5, 0.5, 1.0);
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    cr_assert_eq(rb_revolute_joint_def_at(&def, world, ground, *box, rb_v2(0.25, 0.4)), RB_OK, "%s", rb_last_error());
    def.collide_connected = collide_connected;
    rb_joint_id joint;
    cr_assert_eq(rb_revolute_joint_create(world, &def, &joint), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 30);
    return world;
}

Test(joints, collide_connected_false_keeps_jointed_shapes_apart)
{
    rb_body_id box;
    rb_world *world = overlapping_pinned_boxes(false, &box);
    cr_expect_eq(rb_world_contact_count(world), 0, "%d contacts between pinned bodies", rb_world_contact_count(world));
    expect_vec_near(rb_body_position(world, box), rb_v2(0.5, 0.0), 1e-12, "box position");
    expect_near(rb_body_angle(world, box), 0.0, 1e-12, "box angle");
    destroy_world_and_expect_no_leak(world);
}

Test(joints, collide_connected_true_lets_jointed_shapes_collide)
{
    rb_body_id box;
    rb_world *world = overlapping_pinned_boxes(true, &box);
    cr_expect_geq(rb_world_contact_count(world), 1, "no contact between the pinned bodies");
    cr_expect(rb_body_angle(world, box) > 1e-3, "the contact did not turn the box about the pin (angle %g rad)",
              rb_body_angle(world, box));
    destroy_world_and_expect_no_leak(world);
}

/* ---- Destruction ------------------------------------------------------------------------- */

/* Destroying a body destroys its joints: their ids go stale, the body
 * they held falls freely (exactly, as semi-implicit Euler: 1e-12), and
 * the other joints stay. */
Test(joints, destroying_a_body_destroys_its_joints)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id upper = make_ball(world, rb_v2(1.0, 0.0), 0.1, 1.0);
    rb_body_id lower = make_ball(world, rb_v2(2.0, 0.0), 0.1, 1.0);
    rb_body_id other = make_ball(world, rb_v2(-1.0, 0.0), 0.1, 1.0);
    rb_joint_id shoulder = make_pin(world, ground, upper, rb_v2(0.0, 0.0));
    rb_joint_id elbow = make_pin(world, upper, lower, rb_v2(1.5, 0.0));
    rb_joint_id kept = make_pin(world, ground, other, rb_v2(0.0, 0.0));
    step_world(world, TEST_DT, 10);

    cr_assert_eq(rb_body_destroy(world, upper), RB_OK, "%s", rb_last_error());
    cr_expect(!rb_joint_is_valid(world, shoulder), "the joint to the ground survived its body");
    cr_expect(!rb_joint_is_valid(world, elbow), "the joint to the lower ball survived its body");
    cr_expect(rb_joint_is_valid(world, kept), "a joint of other bodies was destroyed");
    expect_status(rb_joint_destroy(world, shoulder), RB_ERR_STALE_ID, "rb_joint_destroy of a destroyed joint");
    (void)rb_joint_type_of(world, elbow);
    cr_expect_eq(rb_last_status(), RB_ERR_STALE_ID, "rb_joint_type_of of a destroyed joint: %s",
                 rb_status_name(rb_last_status()));

    const rb_vec2 v = rb_body_linear_velocity(world, lower);
    const double omega = rb_body_angular_velocity(world, lower);
    step_world(world, TEST_DT, 1);
    expect_vec_near(rb_body_linear_velocity(world, lower), rb_add(v, rb_v2(0.0, -G * TEST_DT)), 1e-12 * 10.0,
                    "the freed ball's velocity");
    expect_near(rb_body_angular_velocity(world, lower), omega, 1e-12, "the freed ball's angular velocity");
    cr_expect_eq(rb_world_statistics(world).joint_count, 1, "%d joints left, expected 1",
                 rb_world_statistics(world).joint_count);
    cr_expect_lt(rb_distance(rb_joint_world_anchor_a(world, kept), rb_joint_world_anchor_b(world, kept)), 0.005,
                 "the kept joint no longer holds");

    cr_assert_eq(rb_joint_destroy(world, kept), RB_OK, "%s", rb_last_error());
    cr_expect(!rb_joint_is_valid(world, kept), "rb_joint_destroy left the joint valid");
    step_world(world, TEST_DT, 1);
    cr_expect_eq(rb_world_statistics(world).joint_count, 0, "%d joints left, expected 0",
                 rb_world_statistics(world).joint_count);
    destroy_world_and_expect_no_leak(world);
}

/* ---- Reaction at rest, getters --------------------------------------------------------------- */

/* A ball (radius 0.1 m, density 50) hanging at rest 1 m straight below a
 * pin. Each step gravity gives it -g·dt and the pin, a single constraint
 * solved exactly, takes that back with an impulse m·g·dt: the force on
 * the ball, body B, is (0, m·g) to rounding (1e-9 relative), and (0, -m·g)
 * on the ground when the ball is body A. A pin gives no torque. */
Test(joints, reaction_of_a_hanging_pendulum_carries_the_bob)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    const double radius = 0.1, density = 50.0;
    const double weight = density * RB_PI * radius * radius * G;
    rb_body_id hanging_b = make_ball(world, rb_v2(0.0, -1.0), radius, density);
    rb_body_id hanging_a = make_ball(world, rb_v2(5.0, -1.0), radius, density);
    rb_joint_id bob_is_b = make_pin(world, ground, hanging_b, rb_v2(0.0, 0.0));
    rb_joint_id bob_is_a = make_pin(world, hanging_a, ground, rb_v2(5.0, 0.0));
    step_world(world, TEST_DT, 30);
    expect_vec_near(rb_joint_reaction_force(world, bob_is_b), rb_v2(0.0, weight), 1e-9 * weight,
                    "force on the bob (body B)");
    expect_vec_near(rb_joint_reaction_force(world, bob_is_a), rb_v2(0.0, -weight), 1e-9 * weight,
                    "force on the ground (body B) when the bob is body A");
    expect_near(rb_joint_reaction_torque(world, bob_is_b), 0.0, 0.0, "a pin's torque");
    expect_vec_near(rb_body_position(world, hanging_b), rb_v2(0.0, -1.0), 1e-12, "the bob stays at rest");
    destroy_world_and_expect_no_leak(world);
}

/* Two boxes pinned at their common centre, in zero gravity, turning at
 * 1 and 12 rad/s: the pin exerts no torque about the centres, so the
 * speeds stay and the joint angle grows as 11·t from 0, past 2π
 * (continuous, not wrapped). At every step the angle is
 * angle(B) - angle(A) - reference and the speed ωB - ωA (to rounding). */
Test(joints, revolute_angle_and_speed_follow_the_bodies)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id a = make_body(world, RB_BODY_DYNAMIC, rb_v2(1.0, 2.0), 0.3);
    add_box(world, a, 0.5, 0.1, 1.0);
    rb_body_id b = make_body(world, RB_BODY_DYNAMIC, rb_v2(1.0, 2.0), -0.2);
    add_box(world, b, 0.4, 0.2, 1.0);
    rb_joint_id joint = make_pin(world, a, b, rb_v2(1.0, 2.0));
    cr_assert_eq(rb_body_set_angular_velocity(world, a, 1.0), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_angular_velocity(world, b, 12.0), RB_OK, "%s", rb_last_error());
    const double reference = -0.5;
    for (int n = 1; n <= 60; ++n) {
        step_world(world, TEST_DT, 1);
        const double angle = rb_revolute_joint_angle(world, joint);
        expect_near(angle, rb_body_angle(world, b) - rb_body_angle(world, a) - reference, 1e-12, "joint angle");
        expect_near(rb_revolute_joint_speed(world, joint),
                    rb_body_angular_velocity(world, b) - rb_body_angular_velocity(world, a), 1e-12, "joint speed");
        expect_near(angle, 11.0 * n * TEST_DT, 1e-9, "joint angle 11·t");
    }
    cr_expect(rb_revolute_joint_angle(world, joint) > 2.0 * RB_PI, "the joint angle was wrapped");
    destroy_world_and_expect_no_leak(world);
}

/* The getters report what the definitions said. */
Test(joints, getters_report_the_definitions)
{
    rb_world *world = make_world(rb_v2(0.0, -G));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id a = make_ball(world, rb_v2(1.0, 0.0), 0.1, 1.0);
    rb_body_id b = make_ball(world, rb_v2(2.0, 1.0), 0.1, 1.0);
    int tag = 0;

    rb_revolute_joint_def pin = rb_default_revolute_joint_def();
    cr_assert_eq(rb_revolute_joint_def_at(&pin, world, ground, a, rb_v2(0.5, 0.0)), RB_OK, "%s", rb_last_error());
    pin.user_data = &tag;
    rb_joint_id revolute;
    cr_assert_eq(rb_revolute_joint_create(world, &pin, &revolute), RB_OK, "%s", rb_last_error());
    rb_weld_joint_def weld = rb_default_weld_joint_def();
    cr_assert_eq(rb_weld_joint_def_at(&weld, world, a, b, rb_v2(1.5, 0.5)), RB_OK, "%s", rb_last_error());
    rb_joint_id welded;
    cr_assert_eq(rb_weld_joint_create(world, &weld, &welded), RB_OK, "%s", rb_last_error());
    rb_distance_joint_def bar = rb_default_distance_joint_def();
    cr_assert_eq(rb_distance_joint_def_between(&bar, world, ground, b, rb_v2(0.0, 1.0), rb_v2(2.0, 1.0)), RB_OK, "%s",
                 rb_last_error());
    expect_near(bar.length, 2.0, 0.0, "rb_distance_joint_def_between length");
    rb_joint_id distance;
    cr_assert_eq(rb_distance_joint_create(world, &bar, &distance), RB_OK, "%s", rb_last_error());
    rb_mouse_joint_def drag = rb_default_mouse_joint_def();
    drag.body = b;
    drag.target = rb_v2(3.0, 3.0);
    rb_joint_id mouse;
    cr_assert_eq(rb_mouse_joint_create(world, &drag, &mouse), RB_OK, "%s", rb_last_error());

    cr_expect_eq(rb_joint_type_of(world, revolute), RB_JOINT_REVOLUTE, "revolute type");
    cr_expect_eq(rb_joint_type_of(world, welded), RB_JOINT_WELD, "weld type");
    cr_expect_eq(rb_joint_type_of(world, distance), RB_JOINT_DISTANCE, "distance type");
    cr_expect_eq(rb_joint_type_of(world, mouse), RB_JOINT_MOUSE, "mouse type");
    cr_expect(rb_body_id_equals(rb_joint_body_a(world, welded), a) &&
                  rb_body_id_equals(rb_joint_body_b(world, welded), b),
              "the weld's bodies");
    cr_expect(rb_body_id_is_null(rb_joint_body_a(world, mouse)), "a mouse joint's body A is not the null id");
    cr_expect(rb_body_id_equals(rb_joint_body_b(world, mouse), b), "the mouse joint's body");
    /* Anchors in world coordinates, before any step (1e-15 rounding of
     * the frame conversions). */
    expect_vec_near(rb_joint_world_anchor_a(world, revolute), rb_v2(0.5, 0.0), 1e-15, "pin anchor A");
    expect_vec_near(rb_joint_world_anchor_b(world, revolute), rb_v2(0.5, 0.0), 1e-15, "pin anchor B");
    expect_vec_near(rb_joint_world_anchor_b(world, welded), rb_v2(1.5, 0.5), 1e-15, "weld anchor B");
    expect_vec_near(rb_joint_world_anchor_a(world, mouse), drag.target, 0.0, "mouse anchor A is the target");
    expect_near(rb_distance_joint_current_length(world, distance), 2.0, 1e-15, "bar length");
    cr_expect_eq(rb_joint_user_data(world, revolute), &tag, "user data from the definition");
    cr_assert_eq(rb_joint_set_user_data(world, welded, &tag), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_joint_user_data(world, welded), &tag, "user data set later");
    destroy_world_and_expect_no_leak(world);
}
