/* SPDX-License-Identifier: MIT */
/* Small limbs of limited pins solved as one dense block
 * (engine/src/joint_block.c), checked against the equations the block
 * solves rather than against a second solver: after one velocity pass
 * every pin's anchors move together (up to the centripetal drift the pin
 * asks for), a held limit closes no faster than its speculative bias, no
 * limit pulls, and the bodies' momentum changed by exactly the rows'
 * impulses, M·Δv = Jᵀ·λ; two limits reached in a loop, more rows than
 * freedoms, leave one out; factors kept from an earlier substep give
 * what factoring afresh gives, or are made again. Then the whole step: a
 * heavy link dropping onto a stop held through a light one, as in the
 * built-in leg.
 *
 * The limb is a four-bar through the ground, the leg's shape: a heavy
 * horizontal "femur" pinned to the ground, a "tibia" hanging from its
 * end, a light "foot" from the tibia's end, pinned to the ground again at
 * its toe. Every hinge is limited; the ankle's range is ±3°.
 */
#include <criterion/criterion.h>
#include <math.h>

#include "cable_solver.h"
#include "joint_block.h"
#include "joint_solver.h"
#include "rb/rb.h"
#include "test_support.h"
#include "world_internal.h"

#define DEG (RB_PI / 180.0)
#define ANKLE_RANGE (3.0 * DEG)

typedef struct limb {
    rb_world *world;
    rb_body_id bodies[3];  /* femur, tibia, foot */
    rb_joint_id hinges[4]; /* hip, knee, ankle, toe */
    bool has_cable;        /* a muscle's cable on it (add_cable) */
    rb_cable_id cable;
} limb;

static rb_body_id add_bone(rb_world *world, rb_vec2 centre, double width, double height, double density)
{
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, centre, 0.0);
    rb_polygon box;
    cr_assert_eq(rb_make_box(0.5 * width, 0.5 * height, &box), RB_OK);
    rb_shape_def shape = rb_default_shape_def();
    shape.density = density;
    shape.filter.group_index = -1;
    rb_shape_id id;
    cr_assert_eq(rb_shape_create_polygon(world, body, &shape, &box, &id), RB_OK, "%s", rb_last_error());
    return body;
}

static rb_joint_id hinge(rb_world *world, rb_body_id a, rb_body_id b, rb_vec2 anchor, double range)
{
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    cr_assert_eq(rb_revolute_joint_def_at(&def, world, a, b, anchor), RB_OK, "%s", rb_last_error());
    def.enable_lower_limit = def.enable_upper_limit = true;
    def.lower_angle = -range;
    def.upper_angle = range;
    rb_joint_id id;
    cr_assert_eq(rb_revolute_joint_create(world, &def, &id), RB_OK, "%s", rb_last_error());
    return id;
}

/* The femur's density `heavy` (kg/m²): at 20,000 kg/m² its 0.48 × 0.05 m
 * weigh 480 kg, against the tibia's 10.8 kg and the foot's 0.84 kg. */
static limb make_limb(double heavy)
{
    limb l = {.world = make_world(rb_v2(0.0, -9.8))};
    rb_body_id ground = make_body(l.world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    l.bodies[0] = add_bone(l.world, rb_v2(0.24, 0.0), 0.48, 0.05, heavy);
    l.bodies[1] = add_bone(l.world, rb_v2(0.48, -0.18), 0.03, 0.36, 1000.0);
    l.bodies[2] = add_bone(l.world, rb_v2(0.55, -0.36), 0.14, 0.02, 300.0);
    l.hinges[0] = hinge(l.world, ground, l.bodies[0], rb_v2(0.0, 0.0), 90.0 * DEG);
    l.hinges[1] = hinge(l.world, l.bodies[0], l.bodies[1], rb_v2(0.48, 0.0), 90.0 * DEG);
    l.hinges[2] = hinge(l.world, l.bodies[1], l.bodies[2], rb_v2(0.48, -0.36), ANKLE_RANGE);
    l.hinges[3] = hinge(l.world, l.bodies[2], ground, rb_v2(0.62, -0.36), 90.0 * DEG);
    return l;
}

static rb_joint *joint_of(rb_world *world, rb_joint_id id) { return &world->joints[id.index]; }

/* The solver's set-up of one substep of h, as rb_solver_step and
 * rb_solver_sequential_substep do it under NGS. */
static void prepare(rb_world *world, double h)
{
    cr_assert_eq(rb_joints_collect_active(world), RB_OK);
    rb_joint_blocks_build(world);
    rb_cables_prepare_step(world);
    world->joint_response = (rb_rigid_response){.mass_scale = 1.0};
    rb_cables_prepare(world, h);
    rb_joints_prepare(world);
    rb_pins_gather(world);
    rb_cables_warm_start(world);
    rb_joints_warm_start(world, h, false); /* the frames; the joints' impulses are still 0 */
    rb_joint_blocks_factor(world, h);
}

Test(joint_block, a_limited_loop_of_uneven_masses_is_one_block_and_even_masses_are_not)
{
    limb heavy = make_limb(20000.0);
    prepare(heavy.world, 1.0 / 600.0);
    cr_expect_eq(heavy.world->joint_blocks.count, 1);
    for (int k = 0; k < 4; ++k) {
        cr_expect(joint_of(heavy.world, heavy.hinges[k])->in_block, "hinge %d in the block", k);
    }
    destroy_world_and_expect_no_leak(heavy.world);

    /* At 200 kg/m² the femur weighs 4.8 kg, and the heaviest bone, the
     * tibia, 13 times the foot: below RB_BLOCK_MASS_RATIO, Gauss-Seidel's. */
    limb even = make_limb(200.0);
    prepare(even.world, 1.0 / 600.0);
    cr_expect_eq(even.world->joint_blocks.count, 0);
    cr_expect_not(joint_of(even.world, even.hinges[2])->in_block);
    destroy_world_and_expect_no_leak(even.world);
}

Test(joint_block, a_weld_in_the_group_or_the_trees_turned_off_leave_it_to_gauss_seidel)
{
    limb welded = make_limb(20000.0);
    rb_body_id extra = add_bone(welded.world, rb_v2(0.3, 0.1), 0.05, 0.05, 1000.0);
    rb_weld_joint_def weld = rb_default_weld_joint_def();
    cr_assert_eq(rb_weld_joint_def_at(&weld, welded.world, welded.bodies[0], extra, rb_v2(0.3, 0.05)), RB_OK, "%s",
                 rb_last_error());
    rb_joint_id id;
    cr_assert_eq(rb_weld_joint_create(welded.world, &weld, &id), RB_OK, "%s", rb_last_error());
    prepare(welded.world, 1.0 / 600.0);
    cr_expect_eq(welded.world->joint_blocks.count, 0);
    destroy_world_and_expect_no_leak(welded.world);

    limb off = make_limb(20000.0);
    rb_solver_settings settings = rb_world_solver_settings(off.world);
    settings.tree_pins = false;
    cr_assert_eq(rb_world_set_solver_settings(off.world, &settings), RB_OK, "%s", rb_last_error());
    prepare(off.world, 1.0 / 600.0);
    cr_expect_eq(off.world->joint_blocks.count, 0);
    destroy_world_and_expect_no_leak(off.world);
}

/* The limb's bodies' states and its joints' and cable's accumulated
 * impulses, before a velocity pass (or to run one twice, `restore`). */
typedef struct limb_snapshot {
    rb_body_state states[3];
    rb_revolute_data hinges[4];
    double cable_impulse; /* N·s */
} limb_snapshot;

static limb_snapshot snapshot(const limb *l)
{
    limb_snapshot shot;
    for (int i = 0; i < 3; ++i) {
        shot.states[i] = l->world->states[l->bodies[i].index];
    }
    for (int k = 0; k < 4; ++k) {
        shot.hinges[k] = joint_of(l->world, l->hinges[k])->as.revolute;
    }
    shot.cable_impulse = l->has_cable ? l->world->cables[l->cable.index].impulse : 0.0;
    return shot;
}

static void restore(const limb *l, const limb_snapshot *shot)
{
    for (int i = 0; i < 3; ++i) {
        l->world->states[l->bodies[i].index] = shot->states[i];
    }
    for (int k = 0; k < 4; ++k) {
        joint_of(l->world, l->hinges[k])->as.revolute = shot->hinges[k];
    }
    if (l->has_cable) {
        l->world->cables[l->cable.index].impulse = shot->cable_impulse;
    }
}

/* After a pass: every pin's anchors move together up to the centripetal
 * drift it asks for, and M·Δv = Jᵀ·Δλ: every body's momentum and angular
 * momentum about its centre changed by the pass's impulses (each pin's at
 * its anchors, each limit's about the centres, the cable's through each
 * body's share of its tension). */
static void expect_pins_met_by_the_impulses(const limb *l, const limb_snapshot *before)
{
    rb_world *world = l->world;
    for (int k = 0; k < 4; ++k) {
        rb_joint *joint = joint_of(world, l->hinges[k]);
        rb_vec2 cdot =
            rb_joint_relative_velocity(joint, rb_joint_state_a(world, joint), rb_joint_state_b(world, joint));
        expect_vec_near(cdot, joint->frame.point_drift, 1e-10, "a pin's anchor velocity after the pass");
    }
    for (int i = 0; i < 3; ++i) {
        int index = l->bodies[i].index;
        const rb_body *body = &world->bodies[index];
        rb_vec2 force = rb_v2(0.0, 0.0);
        double torque = 0.0;
        for (int k = 0; k < 4; ++k) {
            rb_joint *joint = joint_of(world, l->hinges[k]);
            const rb_revolute_data *d = &joint->as.revolute;
            const rb_revolute_data *was = &before->hinges[k];
            rb_vec2 point = rb_sub(d->point_impulse, was->point_impulse);
            double angular = (d->lower_impulse - d->upper_impulse) - (was->lower_impulse - was->upper_impulse);
            if (joint->body_b == index) {
                force = rb_add(force, point);
                torque += rb_cross(joint->frame.rb, point) + angular;
            } else if (joint->body_a == index) {
                force = rb_sub(force, point);
                torque -= rb_cross(joint->frame.ra, point) + angular;
            }
        }
        const rb_cable *cable = l->has_cable ? &world->cables[l->cable.index] : NULL;
        for (int m = 0; cable != NULL && m < cable->share_count; ++m) {
            if (cable->shares[m].state == &world->states[index]) {
                double pull = cable->impulse - before->cable_impulse;
                force = rb_mul_add(force, pull, cable->shares[m].linear);
                torque += pull * cable->shares[m].angular;
            }
        }
        const rb_body_state *after = &world->states[index];
        const rb_body_state *was = &before->states[i];
        rb_vec2 momentum = rb_scale(1.0 / body->inv_mass, rb_sub(after->linear_velocity, was->linear_velocity));
        double angular = (after->angular_velocity - was->angular_velocity) / body->inv_inertia;
        expect_vec_near(momentum, force, 1e-9 * (1.0 + rb_length(force)), "a body's momentum change");
        expect_near(angular, torque, 1e-9 * (1.0 + fabs(torque)), "a body's angular momentum change");
    }
}

/* Prepares a substep of h, in which the limb must be one factored block
 * of four pins and the ankle's lower limit (nine rows), and runs one
 * velocity pass over it; returns the limb as it was before the pass. */
static limb_snapshot one_pass_over_the_block(const limb *l, double h)
{
    prepare(l->world, h);
    cr_assert_eq(l->world->joint_blocks.count, 1);
    const rb_joint_block *block = &l->world->joint_blocks.blocks[0];
    cr_assert(block->factored);
    cr_assert_eq(block->row_count, 9, "four pins and the ankle's lower limit, %d rows", block->row_count);
    limb_snapshot before = snapshot(l);
    rb_joint_blocks_solve_velocities(l->world);
    return before;
}

/* The ankle's opening speed (rad/s) and its margin above the lower stop (rad). */
static void ankle_motion(const limb *l, double *opening, double *margin)
{
    rb_joint *ankle = joint_of(l->world, l->hinges[2]);
    *opening =
        rb_joint_state_b(l->world, ankle)->angular_velocity - rb_joint_state_a(l->world, ankle)->angular_velocity;
    *margin = rb_joint_relative_angle(l->world, ankle, ankle->as.revolute.reference_angle) - ankle->as.revolute.lower;
}

Test(joint_block, one_velocity_pass_meets_every_row_with_the_rows_impulses)
{
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    /* Turn the ankle to 0.1° from its lower stop, then give every body
     * velocities the joints do not allow; those the pins leave turn the
     * ankle down at about 10 rad/s, onto the stop. */
    for (int i = 0; i < 3; ++i) {
        cr_assert_eq(rb_body_set_linear_velocity(world, l.bodies[i], rb_v2(sin(1.7 * i + 0.3), cos(2.3 * i))), RB_OK);
    }
    cr_assert_eq(rb_body_set_angular_velocity(world, l.bodies[0], 0.5), RB_OK);
    cr_assert_eq(rb_body_set_angular_velocity(world, l.bodies[1], -1.0), RB_OK);
    cr_assert_eq(rb_body_set_angular_velocity(world, l.bodies[2], 4.0), RB_OK);
    rb_body_state *foot = &world->states[l.bodies[2].index];
    rb_body_state_turn(foot, -(ANKLE_RANGE - 0.1 * DEG));
    double h = 1.0 / 600.0;
    limb_snapshot before = one_pass_over_the_block(&l, h);
    expect_pins_met_by_the_impulses(&l, &before);
    /* The ankle's lower limit: it may close its 0.1° margin in the
     * substep, no faster, and pushes (impulse > 0). */
    double opening, margin;
    ankle_motion(&l, &opening, &margin);
    cr_expect_gt(joint_of(world, l.hinges[2])->as.revolute.lower_impulse, 0.0, "the limit holds the ankle");
    expect_near(opening, -margin / h, 1e-9, "the ankle closes on its stop at margin / h");
    destroy_world_and_expect_no_leak(world);
}

/* A limit warm started with a push while the limb turns its joint open:
 * held to its bias, it would pull, so the pass releases it (its total
 * impulse 0, its row's x minus its accumulated impulse) and solves the
 * pins again with that push taken back through K's couplings. */
Test(joint_block, a_limit_that_would_pull_is_released_and_the_pins_still_meet)
{
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    cr_assert_eq(rb_body_set_angular_velocity(world, l.bodies[0], -2.0), RB_OK); /* opens the ankle */
    rb_body_state_turn(&world->states[l.bodies[2].index], -(ANKLE_RANGE - 0.1 * DEG));
    rb_revolute_data *ankle = &joint_of(world, l.hinges[2])->as.revolute;
    ankle->lower_impulse = 0.5;
    double h = 1.0 / 600.0;
    limb_snapshot before = one_pass_over_the_block(&l, h);
    cr_expect_eq(ankle->lower_impulse, 0.0, "the limit let go: %g N·m·s", ankle->lower_impulse);
    expect_pins_met_by_the_impulses(&l, &before);
    double opening, margin;
    ankle_motion(&l, &opening, &margin);
    cr_expect_gt(opening, -margin / h, "released, the ankle opens faster than its stop asks: %g rad/s", opening);
    destroy_world_and_expect_no_leak(world);
}

/* A muscle's cable on the limb, as the leg's gastrocnemius: from the
 * femur near the knee to the foot, across the knee and the ankle, or by
 * way of the tibia (`via_tibia`: three moving bodies, which a block's row
 * does not take). Its law: T0 N and c N·s/m. */
static rb_cable_id add_cable(limb *l, bool via_tibia, double base_tension, double damping)
{
    rb_cable_def def = rb_default_cable_def();
    def.bodies[def.point_count] = l->bodies[0];
    def.local_points[def.point_count++] = rb_v2(0.18, 0.02); /* (0.42, 0.02) in the world */
    if (via_tibia) {
        def.bodies[def.point_count] = l->bodies[1];
        def.local_points[def.point_count++] = rb_v2(-0.02, 0.0); /* (0.46, -0.18) */
    }
    def.bodies[def.point_count] = l->bodies[2];
    def.local_points[def.point_count++] = rb_v2(0.05, 0.01); /* (0.60, -0.35) */
    rb_cable_id id;
    cr_assert_eq(rb_cable_create(l->world, &def, &id), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_cable_set_tension_law(l->world, id, base_tension, damping), RB_OK, "%s", rb_last_error());
    l->has_cable = true;
    l->cable = id;
    return id;
}

/* Velocities the joints do not allow, the ankle well within its stops;
 * `sign` -1 reverses them all. */
static void shake(const limb *l, double sign)
{
    for (int i = 0; i < 3; ++i) {
        rb_vec2 v = rb_scale(sign, rb_v2(sin(1.7 * i + 0.3), cos(2.3 * i)));
        cr_assert_eq(rb_body_set_linear_velocity(l->world, l->bodies[i], v), RB_OK);
        cr_assert_eq(rb_body_set_angular_velocity(l->world, l->bodies[i], sign * (0.5 - 0.4 * i)), RB_OK);
    }
}

/* The cable's lengthening speed L' = -J·v at the bodies' velocities now,
 * through its bodies' shares of a unit tension (m/s). */
static double lengthening_speed(const rb_cable *cable)
{
    double speed = 0.0;
    for (int m = 0; m < cable->share_count; ++m) {
        const rb_cable_share *share = &cable->shares[m];
        speed -= rb_dot(share->linear, share->state->linear_velocity) + share->angular * share->state->angular_velocity;
    }
    return speed;
}

Test(joint_block, a_damped_cable_on_the_block_is_one_of_its_rows_and_meets_its_law_at_the_substeps_end)
{
    /* The implicit law P = h·(T0 + c·L') with L' the lengthening speed
     * after the substep's impulses (cable.c): one pass over the block
     * meets it together with the pins, exactly, where the cable's own
     * pass would meet it only at the velocities the pins had not yet
     * changed. */
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    const double base_tension = 500.0, damping = 100.0;
    rb_cable_id id = add_cable(&l, false, base_tension, damping);
    rb_cable *cable = &world->cables[id.index];
    shake(&l, 1.0);
    double h = 1.0 / 600.0;
    prepare(world, h);
    cr_assert_eq(world->joint_blocks.count, 1);
    const rb_joint_block *block = &world->joint_blocks.blocks[0];
    cr_assert(block->factored);
    cr_expect(cable->in_block, "the cable is a row of the block");
    cr_expect_eq(block->cable_rows, 1);
    cr_expect_eq(block->row_count, 9, "four pins and the cable, %d rows", block->row_count);
    cr_expect(block->closed, "nothing else acts on the limb");
    limb_snapshot before = snapshot(&l);
    rb_joint_blocks_solve_velocities(world);
    double speed = lengthening_speed(cable);
    cr_log_info("the cable's impulse %.9g N·s, its law at the speed after the pass %.9g N·s (L' = %.4g m/s)",
                cable->impulse, h * (base_tension + damping * speed), speed);
    cr_expect_gt(cable->impulse, 0.0, "the cable pulls");
    expect_near(cable->impulse, h * (base_tension + damping * speed), 1e-12, "the law at the substep's end");
    expect_pins_met_by_the_impulses(&l, &before);
    cr_expect(block->settled, "nothing released: the pass solved the block");
    destroy_world_and_expect_no_leak(world);
}

/* The next substep of h over the limb as it stands, up to the block's
 * factors: the cables located and prepared, the impulses warm started. */
static void next_substep(rb_world *world, double h)
{
    rb_cables_locate(world);
    rb_cables_prepare(world, h);
    rb_cables_warm_start(world);
    rb_joints_warm_start(world, h, false);
    rb_joint_blocks_factor(world, h);
}

/* The limb with a cable of PULL_TENSION N and PULL_DAMPING N·s/m on it,
 * moving a little against its joints, after a first substep's set-up
 * (which factors K) and velocity pass. */
#define PULL_TENSION 500.0
#define PULL_DAMPING 100.0

static limb pulled_limb_after_a_pass(double h)
{
    limb l = make_limb(20000.0);
    (void)add_cable(&l, false, PULL_TENSION, PULL_DAMPING);
    shake(&l, 0.1);
    prepare(l.world, h);
    cr_assert(l.world->joint_blocks.blocks[0].factored);
    cr_expect_not(l.world->joint_blocks.blocks[0].kept, "a block's first substep factors K");
    rb_joint_blocks_solve_velocities(l.world);
    return l;
}

/* A substep set up with kept factors that no longer solve its rows: its
 * pass must find the miss, factor K made now, and meet the cable's law
 * (base tension T0 N, damping c N·s/m) and the pins exactly. */
static void expect_kept_factors_to_miss(const limb *l, double h, double base_tension, double damping)
{
    const rb_joint_block *block = &l->world->joint_blocks.blocks[0];
    const rb_cable *cable = &l->world->cables[l->cable.index];
    cr_assert(block->kept, "the same rows: the factors are kept");
    limb_snapshot before = snapshot(l);
    rb_joint_blocks_solve_velocities(l->world);
    cr_expect_not(block->kept, "the kept factors missed: K factored again");
    const double speed = lengthening_speed(cable);
    expect_near(cable->impulse, h * (base_tension + damping * speed), 1e-12, "the law at the substep's end");
    expect_pins_met_by_the_impulses(l, &before);
}

Test(joint_block, a_later_substep_solves_with_the_steps_factors_while_they_meet_its_rows)
{
    /* A block's first substep factors K; a later one whose rows are the
     * same (the same pins, cables and limits) and whose K has barely
     * changed solves with those factors, and its pass accepts the solve
     * when its residual under K made now is within RB_BLOCK_KEPT_RESIDUAL.
     * Here the foot turns by 1e-9 rad and the cable's base tension
     * changes between the substeps: the pass with the kept factors gives
     * the velocities and the impulse that factoring K afresh gives, to
     * that tolerance. */
    const double h = 1.0 / 600.0;
    limb l = pulled_limb_after_a_pass(h);
    rb_world *world = l.world;
    rb_cable *cable = &world->cables[l.cable.index];
    rb_joint_block *block = &world->joint_blocks.blocks[0];
    rb_body_state_turn(&world->states[l.bodies[2].index], 1e-9);
    cr_assert_eq(rb_cable_set_tension_law(world, l.cable, 520.0, PULL_DAMPING), RB_OK, "%s", rb_last_error());
    next_substep(world, h);
    cr_assert(block->kept, "the same rows: the step's factors serve");
    const limb_snapshot start = snapshot(&l);
    rb_joint_blocks_solve_velocities(world);
    cr_expect(block->kept, "the kept factors met the rows");
    const limb_snapshot kept = snapshot(&l);
    restore(&l, &start);
    block->keep_factors = false;
    rb_joint_blocks_factor(world, h);
    cr_assert_not(block->kept);
    rb_joint_blocks_solve_velocities(world);
    for (int i = 0; i < 3; ++i) {
        const rb_body_state *fresh = &world->states[l.bodies[i].index];
        const double near = RB_BLOCK_KEPT_RESIDUAL * (1.0 + rb_length(fresh->linear_velocity));
        expect_vec_near(kept.states[i].linear_velocity, fresh->linear_velocity, near, "a body's velocity");
        expect_near(kept.states[i].angular_velocity, fresh->angular_velocity,
                    RB_BLOCK_KEPT_RESIDUAL * (1.0 + fabs(fresh->angular_velocity)), "a body's angular velocity");
    }
    expect_near(kept.cable_impulse, cable->impulse, RB_BLOCK_KEPT_RESIDUAL * cable->impulse, "the cable's impulse");
    destroy_world_and_expect_no_leak(world);
}

Test(joint_block, a_later_substep_that_the_steps_factors_miss_factors_k_again)
{
    /* The cable's damping, and so its row's compliance 1/(h·c), changes a
     * hundredfold between two substeps: the factors of the first no
     * longer solve the second's rows, the pass finds the residual too
     * large and factors K made now, and the second substep meets the
     * cable's law and the pins exactly. */
    const double h = 1.0 / 600.0, base_tension = 500.0, damping = 10000.0;
    limb l = pulled_limb_after_a_pass(h);
    rb_world *world = l.world;
    cr_assert_eq(rb_cable_set_tension_law(world, l.cable, base_tension, damping), RB_OK, "%s", rb_last_error());
    next_substep(world, h);
    expect_kept_factors_to_miss(&l, h, base_tension, damping);
    cr_expect_not(world->joint_blocks.blocks[0].keep_factors, "for the rest of the step");
    destroy_world_and_expect_no_leak(world);
}

Test(joint_block, a_body_whose_mass_changed_between_steps_makes_the_kept_factors_miss)
{
    /* The next step's block has the same rows and keeps the factors; the
     * foot, four times heavier now, changes K, and the pass's check finds
     * it: the block factors again and meets the cable's law and the pins
     * exactly. */
    const double h = 1.0 / 600.0;
    limb l = pulled_limb_after_a_pass(h);
    rb_world *world = l.world;
    rb_mass_data foot = rb_body_mass_data(world, l.bodies[2]);
    foot.mass *= 4.0;
    foot.rotational_inertia *= 4.0;
    cr_assert_eq(rb_body_set_mass_data(world, l.bodies[2], &foot), RB_OK, "%s", rb_last_error());
    prepare(world, h); /* the next step's first substep */
    expect_kept_factors_to_miss(&l, h, PULL_TENSION, PULL_DAMPING);
    destroy_world_and_expect_no_leak(world);
}

Test(joint_block, a_cable_that_would_push_lets_go_and_the_pins_still_meet)
{
    /* No base tension, and a warm-started pull, while the bodies shorten
     * the path: the law asks for a push, which a cable cannot give, so
     * the pass releases its row (its impulse 0) and solves the pins
     * again; the passes after it must then run, not trust the first. */
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    rb_cable_id id = add_cable(&l, false, 0.0, 100.0);
    rb_cable *cable = &world->cables[id.index];
    shake(&l, -1.0);
    double h = 1.0 / 600.0;
    prepare(world, h);
    cr_assert(cable->in_block);
    cable->impulse = 0.05;
    rb_cables_warm_start(world);
    limb_snapshot before = snapshot(&l);
    rb_joint_blocks_solve_velocities(world);
    cr_expect_eq(cable->impulse, 0.0, "the cable let go: %g N·s", cable->impulse);
    cr_expect_lt(lengthening_speed(cable), 0.0, "released, the path shortens: the law would push");
    expect_pins_met_by_the_impulses(&l, &before);
    cr_expect_not(world->joint_blocks.blocks[0].settled, "a released row: the later passes solve the block again");
    destroy_world_and_expect_no_leak(world);
}

Test(joint_block, a_cable_over_three_moving_bodies_stays_gauss_seidels_and_opens_the_block)
{
    /* A row of the block joins two bodies; a path over three keeps its
     * own pass, which changes the limb's velocities after the block's, so
     * every pass must solve the block again. */
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    rb_cable_id id = add_cable(&l, true, 500.0, 100.0);
    prepare(world, 1.0 / 600.0);
    cr_assert_eq(world->joint_blocks.count, 1);
    const rb_joint_block *block = &world->joint_blocks.blocks[0];
    cr_expect_not(world->cables[id.index].in_block);
    cr_expect_eq(block->cable_rows, 0);
    cr_expect_not(block->closed, "the cable acts on the limb from outside the block");
    destroy_world_and_expect_no_leak(world);
}

Test(joint_block, cables_damped_as_stiffly_as_pins_are_given_back_and_the_block_keeps_its_joints)
{
    /* The limb's pins leave it one freedom. Two cables damped at
     * RB_MAX_FORCE are rows of compliance 1/(h·c) = 6e-13 1/kg: K is
     * singular to rounding, and the block gives the cables back to their
     * own passes rather than its joints to Gauss-Seidel. A cable damped
     * so lightly that T0/c overflows never joins. */
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    rb_cable_id stiff[2] = {add_cable(&l, false, 500.0, RB_MAX_FORCE), add_cable(&l, false, 400.0, RB_MAX_FORCE)};
    rb_cable_id slack = add_cable(&l, false, 500.0, 1e-310);
    shake(&l, 1.0);
    prepare(world, 1.0 / 600.0);
    cr_assert_eq(world->joint_blocks.count, 1);
    const rb_joint_block *block = &world->joint_blocks.blocks[0];
    cr_expect(block->factored, "the block keeps its joints");
    cr_expect_eq(block->cable_rows, 0);
    cr_expect_eq(block->row_count, 8, "the four pins, %d rows", block->row_count);
    for (int c = 0; c < 2; ++c) {
        cr_expect_not(world->cables[stiff[c].index].in_block, "stiff cable %d is its own passes'", c);
    }
    cr_expect_not(world->cables[slack.index].in_block, "the slack cable is its own passes'");
    cr_expect_not(block->closed, "the cables act on the limb from outside the block");
    for (int step = 0; step < 30; ++step) {
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
    }
    for (int i = 0; i < 3; ++i) {
        const rb_body_state *s = &world->states[l.bodies[i].index];
        cr_expect(isfinite(s->center.x) && isfinite(s->center.y) && isfinite(s->angular_velocity),
                  "body %d finite after half a second", i);
    }
    cr_expect_lt(fabs(rb_revolute_joint_angle(world, l.hinges[2])), ANKLE_RANGE + 0.01 * DEG,
                 "the ankle within its stops: %g degrees", rb_revolute_joint_angle(world, l.hinges[2]) / DEG);
    destroy_world_and_expect_no_leak(world);
}

Test(joint_block, a_block_that_cannot_factor_gives_its_pins_back_ready_to_solve)
{
    /* A heavy femur pinned to the ground and a light tibia hanging from
     * it by two limited hinges at one anchor: their rows repeat, K is
     * singular without a limit to leave out, and the block gives the
     * pins back to Gauss-Seidel, which needs each pin's K made: the warm
     * start leaves that to the block. Held so, the tibia stays on the
     * femur. */
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id femur = add_bone(world, rb_v2(0.24, 0.0), 0.48, 0.05, 20000.0);
    rb_body_id tibia = add_bone(world, rb_v2(0.48, -0.18), 0.03, 0.36, 1000.0);
    (void)hinge(world, ground, femur, rb_v2(0.0, 0.0), 90.0 * DEG);
    rb_joint_id knees[2] = {hinge(world, femur, tibia, rb_v2(0.48, 0.0), 90.0 * DEG),
                            hinge(world, femur, tibia, rb_v2(0.48, 0.0), 90.0 * DEG)};
    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.substeps = 10;
    settings.velocity_iterations = 4;
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
    prepare(world, 1.0 / 600.0);
    cr_assert_eq(world->joint_blocks.count, 1);
    cr_expect_not(world->joint_blocks.blocks[0].factored, "repeated rows: K is singular");
    for (int k = 0; k < 2; ++k) {
        /* What the pass will read, against the same made afresh. */
        rb_joint *knee = joint_of(world, knees[k]);
        const rb_point_block given = world->point_blocks[knees[k].index];
        const rb_joint_frame given_frame = knee->frame;
        rb_point_constraint_prepare_matrices(world, knee);
        const rb_point_block made = world->point_blocks[knees[k].index];
        cr_expect(given.mass.k11 == made.mass.k11 && given.mass.k12 == made.mass.k12 &&
                      given.mass.k22 == made.mass.k22 && given.mass.k33 == made.mass.k33 &&
                      given.inverse11 == made.inverse11 && given.inverse33 == made.inverse33 &&
                      given.inverse_c33 == made.inverse_c33 &&
                      given_frame.point_inverse11 == knee->frame.point_inverse11 &&
                      given_frame.point_inverse22 == knee->frame.point_inverse22,
                  "knee %d's K and inverses made for Gauss-Seidel (k11 %g, made %g)", k, given.mass.k11, made.mass.k11);
    }
    double widest = 0.0;
    for (int step = 0; step < 60; ++step) {
        cr_assert_eq(rb_world_step(world, TEST_DT), RB_OK, "%s", rb_last_error());
        for (int k = 0; k < 2; ++k) {
            rb_joint *knee = joint_of(world, knees[k]);
            rb_vec2 a = rb_add(rb_joint_state_a(world, knee)->center,
                               rb_rotate(rb_joint_state_a(world, knee)->rotation, knee->frame.local_a));
            rb_vec2 b = rb_add(rb_joint_state_b(world, knee)->center,
                               rb_rotate(rb_joint_state_b(world, knee)->rotation, knee->frame.local_b));
            widest = fmax(widest, rb_length(rb_sub(b, a)));
        }
    }
    cr_log_info("the knee's anchors at most %.3g m apart over 1 s", widest);
    cr_expect_lt(widest, 1e-3, "the knee's anchors %.3g m apart", widest);
    destroy_world_and_expect_no_leak(world);
}

/* The farthest the ankle went past its stops over `seconds` of 60 Hz
 * steps of 10 substeps of 4 velocity and 1 position pass, the leg's
 * budget (rad). */
static double ankle_overshoot(bool blocks, double seconds)
{
    limb l = make_limb(20000.0);
    rb_solver_settings settings = rb_world_solver_settings(l.world);
    settings.substeps = 10;
    settings.velocity_iterations = 4;
    settings.position_iterations = 1;
    settings.tree_pins = blocks;
    cr_assert_eq(rb_world_set_solver_settings(l.world, &settings), RB_OK, "%s", rb_last_error());
    double worst = 0.0;
    for (int s = 0; s < lround(seconds * 60.0); ++s) {
        cr_assert_eq(rb_world_step(l.world, TEST_DT), RB_OK, "%s", rb_last_error());
        double angle = rb_revolute_joint_angle(l.world, l.hinges[2]);
        worst = fmax(worst, fabs(angle) - ANKLE_RANGE);
    }
    destroy_world_and_expect_no_leak(l.world);
    return worst;
}

Test(joint_block, a_heavy_link_dropping_onto_a_stop_is_held_through_a_light_one)
{
    /* The femur is 570 times the foot: one joint at a time, 4 passes carry
     * its weight to the foot's pin a little at a time and the ankle passes
     * its stop by degrees; as one block it holds within a hundredth of a
     * degree. */
    double gauss_seidel = ankle_overshoot(false, 2.0);
    double block = ankle_overshoot(true, 2.0);
    cr_log_info("the ankle passed its stop by %.4f degrees one joint at a time, %.5f degrees as a block",
                gauss_seidel / DEG, block / DEG);
    cr_expect_gt(gauss_seidel, 1.0 * DEG, "Gauss-Seidel passed the stop by %.3f degrees", gauss_seidel / DEG);
    cr_expect_lt(block, 0.01 * DEG, "the block passed the stop by %.4f degrees", block / DEG);
}

Test(joint_block, two_limits_reached_in_a_loop_leave_one_out_and_release_it)
{
    /* The toe's range narrowed to the ankle's: turning the foot 2.9° down
     * brings the ankle within 0.1° of its lower stop and the toe within
     * 0.1° of its upper one. Four pins and two limits are ten rows on the
     * bodies' nine freedoms: K is singular, and one limit is left out of
     * the substep, its warm-started impulse taken back. */
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    cr_assert_eq(rb_revolute_joint_set_limits(world, l.hinges[3], true, -ANKLE_RANGE, true, ANKLE_RANGE), RB_OK, "%s",
                 rb_last_error());
    cr_assert_eq(rb_body_set_angular_velocity(world, l.bodies[2], 4.0), RB_OK);
    rb_body_state_turn(&world->states[l.bodies[2].index], -(ANKLE_RANGE - 0.1 * DEG));
    rb_revolute_data *ankle = &joint_of(world, l.hinges[2])->as.revolute;
    rb_revolute_data *toe = &joint_of(world, l.hinges[3])->as.revolute;
    ankle->lower_impulse = 1.0;
    toe->upper_impulse = 1.0;
    prepare(world, 1.0 / 600.0);
    cr_assert_eq(world->joint_blocks.count, 1);
    const rb_joint_block *block = &world->joint_blocks.blocks[0];
    cr_expect(block->factored);
    cr_expect_eq(block->row_count, 9, "%d rows", block->row_count);
    cr_expect((ankle->lower_impulse == 0.0) != (toe->upper_impulse == 0.0),
              "one limit released: ankle %g, toe %g N·m·s", ankle->lower_impulse, toe->upper_impulse);
    destroy_world_and_expect_no_leak(world);
}

/* The velocity passes one joint at a time (rb_joints_solve_velocities)
 * leave a block's pins to their block: they visit the joints of a list
 * made once a step without them. A step whose blocks are gone must make
 * the list again and solve the pins: the last pin a forward pass visits,
 * the toe's, then moves its anchors together up to the centripetal drift
 * it asks for (its limits, 90° away, do not act). */
Test(joint_block, the_joint_passes_leave_a_blocks_pins_to_it_and_take_them_back_without_it)
{
    limb l = make_limb(20000.0);
    rb_world *world = l.world;
    for (int i = 0; i < 3; ++i) {
        cr_assert_eq(rb_body_set_linear_velocity(world, l.bodies[i], rb_v2(sin(1.7 * i + 0.3), cos(2.3 * i))), RB_OK);
        cr_assert_eq(rb_body_set_angular_velocity(world, l.bodies[i], 1.0 - i), RB_OK);
    }
    double h = 1.0 / 600.0;
    prepare(world, h);
    cr_assert_eq(world->joint_blocks.count, 1);
    rb_body_state before[3];
    for (int i = 0; i < 3; ++i) {
        before[i] = world->states[l.bodies[i].index];
    }
    rb_joints_solve_velocities(world, h, false);
    for (int i = 0; i < 3; ++i) {
        const rb_body_state *s = &world->states[l.bodies[i].index];
        cr_expect(s->linear_velocity.x == before[i].linear_velocity.x &&
                      s->linear_velocity.y == before[i].linear_velocity.y &&
                      s->angular_velocity == before[i].angular_velocity,
                  "body %d untouched by the joint passes: its pins are the block's", i);
    }

    rb_solver_settings settings = rb_world_solver_settings(world);
    settings.tree_pins = false; /* no blocks: every pin is Gauss-Seidel's */
    cr_assert_eq(rb_world_set_solver_settings(world, &settings), RB_OK, "%s", rb_last_error());
    prepare(world, h);
    cr_assert_eq(world->joint_blocks.count, 0);
    rb_joints_solve_velocities(world, h, false);
    rb_joint *toe = joint_of(world, l.hinges[3]);
    rb_vec2 cdot = rb_joint_relative_velocity(toe, rb_joint_state_a(world, toe), rb_joint_state_b(world, toe));
    expect_vec_near(cdot, toe->frame.point_drift, 1e-10, "the toe's anchor velocity after the pass");
    cr_expect_gt(rb_length(cdot) +
                     rb_length(rb_sub(world->states[l.bodies[2].index].linear_velocity, before[2].linear_velocity)),
                 1e-3, "the pass moved the foot");
    destroy_world_and_expect_no_leak(world);
}
