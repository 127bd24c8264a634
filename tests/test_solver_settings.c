/* SPDX-License-Identifier: MIT */
/* The world's solver settings do what rb/world.h says: the block solver,
 * warm starting, both position-correction methods, substeps, and the
 * counters and profile the step reports.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "rb/rb.h"
#include "scenes/scenes.h"
#include "test_support.h"

#define GRAVITY 9.8 /* m/s², the engine's default */

/* A world with default settings changed by `change`. */
static rb_world *make_world_with(void (*change)(rb_solver_settings *))
{
    rb_world_def def = rb_default_world_def();
    change(&def.solver);
    rb_world *world = NULL;
    cr_assert_eq(rb_world_create(&def, &world), RB_OK, "rb_world_create: %s", rb_last_error());
    return world;
}

/* A static ground whose top face is y = 0, and a dynamic unit box (1 kg,
 * I = 1/6 kg·m²) whose bottom face starts at y = bottom. */
static rb_body_id add_ground_and_box(rb_world *world, double bottom)
{
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, -0.5), 0.0);
    add_box(world, ground, 5.0, 0.5, 1.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, bottom + 0.5), 0.0);
    add_box(world, box, 0.5, 0.5, 1.0);
    return box;
}

static void read_the_one_contact(rb_world *world, rb_contact_data *contact)
{
    cr_assert_eq(rb_world_contacts(world, contact, 1), 1, "expected one contact");
    cr_assert_eq(contact->manifold.point_count, 2, "expected a two-point face contact");
}

static void one_velocity_iteration_with_block(rb_solver_settings *s)
{
    s->substeps = 1;
    s->velocity_iterations = 1;
    s->block_solver = true;
}

static void one_velocity_iteration_without_block(rb_solver_settings *s)
{
    s->substeps = 1;
    s->velocity_iterations = 1;
    s->block_solver = false;
}

Test(solver_settings, block_solver_holds_a_resting_box_in_one_iteration)
{
    /* Both corners of a box resting flat must push m·g·h/2, by symmetry,
     * for the box neither to sink nor to turn. The block solver solves the
     * two-point LCP exactly, so one iteration gives exactly that. */
    rb_world *world = make_world_with(one_velocity_iteration_with_block);
    rb_body_id box = add_ground_and_box(world, 0.0);
    step_world(world, TEST_DT, 1);
    rb_contact_data contact;
    read_the_one_contact(world, &contact);
    const double half_weight_impulse = 0.5 * 1.0 * GRAVITY * TEST_DT;
    for (int i = 0; i < 2; ++i) {
        expect_near(contact.manifold.points[i].normal_impulse, half_weight_impulse, 1e-12 * half_weight_impulse,
                    "normal impulse at one corner = m·g·h/2");
    }
    expect_near(rb_body_angular_velocity(world, box), 0.0, 1e-12, "ω after one step");
    expect_near(rb_body_linear_velocity(world, box).y, 0.0, 1e-12, "v_y after one step");
    destroy_world_and_expect_no_leak(world);
}

Test(solver_settings, sequential_solver_does_one_gauss_seidel_pass)
{
    /* Without the block solver one iteration solves the corners in turn.
     * The effective mass of a corner of a unit box (m = 1, I = 1/6,
     * r × n = ±0.5) is m_n = 1/(1/m + 0.25/I) = 0.4 kg. The first corner
     * stops its own approach speed g·h: λ1 = 0.4·g·h. That impulse lifts
     * the centre by 0.4·g·h and turns the box at ω = ∓0.5·λ1/I = ∓1.2·g·h,
     * so the second corner approaches at g·h·(1 - 0.4 + 0.5·1.2) = 1.2·g·h
     * and gets λ2 = 0.4·1.2·g·h = 0.48·g·h, whichever corner goes first. */
    rb_world *world = make_world_with(one_velocity_iteration_without_block);
    add_ground_and_box(world, 0.0);
    step_world(world, TEST_DT, 1);
    rb_contact_data contact;
    read_the_one_contact(world, &contact);
    const double gh = GRAVITY * TEST_DT;
    expect_near(contact.manifold.points[0].normal_impulse, 0.4 * gh, 1e-12 * gh, "first corner λ1 = 0.4·g·h");
    expect_near(contact.manifold.points[1].normal_impulse, 0.48 * gh, 1e-12 * gh, "second corner λ2 = 0.48·g·h");
    destroy_world_and_expect_no_leak(world);
}

static void ngs_settings(rb_solver_settings *s) { s->type = RB_SOLVER_NGS; }
static void ngs_without_iterations(rb_solver_settings *s)
{
    s->type = RB_SOLVER_NGS;
    s->position_iterations = 0;
}
static void baumgarte_settings(rb_solver_settings *s) { s->type = RB_SOLVER_BAUMGARTE; }
static void baumgarte_without_bias(rb_solver_settings *s)
{
    s->type = RB_SOLVER_BAUMGARTE;
    s->baumgarte = 0.0;
}
static void baumgarte_with_substeps(rb_solver_settings *s)
{
    s->type = RB_SOLVER_BAUMGARTE;
    s->substeps = 4;
}
static void ngs_with_substeps(rb_solver_settings *s)
{
    s->type = RB_SOLVER_NGS;
    s->substeps = 4;
}

/* Starts the box 5 cm deep in the ground and returns its penetration
 * after one second. */
static double penetration_after_one_second(void (*change)(rb_solver_settings *), rb_world **out_world,
                                           rb_body_id *out_box)
{
    rb_world *world = make_world_with(change);
    rb_body_id box = add_ground_and_box(world, -0.05);
    step_world(world, TEST_DT, 60);
    *out_world = world;
    *out_box = box;
    return -(rb_body_position(world, box).y - 0.5);
}

Test(solver_settings, each_correction_method_removes_overlap_down_to_the_slop)
{
    /* Either method must push the box out until at most the slop
     * (0.005 m) is left, and leave it at rest. Baumgarte removes
     * beta = 20 % of the excess per step: after 60 steps 0.045·0.8^60
     * ≈ 7e-8 m of excess remains; NGS removes it in the position passes.
     * 1e-4 m is far above both residues and far below the 5 cm start. */
    void (*methods[])(rb_solver_settings *) = {ngs_settings, baumgarte_settings, ngs_with_substeps,
                                               baumgarte_with_substeps};
    const char *names[] = {"NGS", "Baumgarte", "NGS, 4 substeps", "Baumgarte, 4 substeps"};
    for (int i = 0; i < 4; ++i) {
        rb_world *world;
        rb_body_id box;
        const double penetration = penetration_after_one_second(methods[i], &world, &box);
        cr_expect(penetration <= 0.005 + 1e-4, "%s: %.6f m of overlap left, expected at most the slop", names[i],
                  penetration);
        cr_expect(penetration >= -1e-4, "%s: the box was pushed %.6f m clear of the ground", names[i], -penetration);
        cr_expect(fabs(rb_body_linear_velocity(world, box).y) < 1e-3, "%s: the box is still moving at %g m/s", names[i],
                  rb_body_linear_velocity(world, box).y);
        destroy_world_and_expect_no_leak(world);
    }
}

Test(solver_settings, without_correction_the_overlap_stays)
{
    /* The control for the test above: with beta = 0 (Baumgarte) or no
     * position iterations (NGS) nothing pushes the box out, and the
     * velocity solve only stops it sinking further: the 5 cm stay. */
    void (*methods[])(rb_solver_settings *) = {ngs_without_iterations, baumgarte_without_bias};
    const char *names[] = {"NGS with 0 position iterations", "Baumgarte with beta = 0"};
    for (int i = 0; i < 2; ++i) {
        rb_world *world;
        rb_body_id box;
        const double penetration = penetration_after_one_second(methods[i], &world, &box);
        cr_expect(penetration > 0.049, "%s: overlap %.6f m, expected the initial 0.05 m to stay", names[i],
                  penetration);
        destroy_world_and_expect_no_leak(world);
    }
}

static void cold_ngs(rb_solver_settings *s) { s->warm_starting = false; }
static void warm_ngs(rb_solver_settings *s) { s->warm_starting = true; }

/* The top box's sideways and vertical travel over 10 s of a 10-box stack. */
static rb_vec2 stack_top_travel(void (*change)(rb_solver_settings *))
{
    rb_world *world = make_world_with(change);
    scene_stack stack;
    cr_assert_eq(scene_stack_create(world, 10, &stack), RB_OK, "%s", rb_last_error());
    const rb_vec2 start = rb_body_position(world, stack.top);
    step_world(world, TEST_DT, 600);
    const rb_vec2 travel = rb_sub(rb_body_position(world, stack.top), start);
    destroy_world_and_expect_no_leak(world);
    return travel;
}

Test(solver_settings, warm_starting_is_what_holds_a_stack)
{
    /* Each box of a 10-box stack carries the weight of those above; the
     * default 2 Gauss-Seidel passes per substep cannot carry 10 boxes'
     * weight down from zero every substep, but impulses carried over from
     * the last substep start each one almost solved (Catto, GDC 2006).
     * With warm starting the top box stays within 1 cm sideways and 5 cm
     * down (the slop compresses each of the 10 contacts by at most 5 mm);
     * without it the stack does not stand: its top box ends more than a
     * metre from where it started. */
    const rb_vec2 warm = stack_top_travel(warm_ngs);
    cr_expect(fabs(warm.x) < 0.01 && warm.y > -0.05, "warm: the top box travelled (%g, %g) m", warm.x, warm.y);
    const rb_vec2 cold = stack_top_travel(cold_ngs);
    cr_expect(rb_length(cold) > 1.0, "cold: the top box travelled (%g, %g) m; expected the stack to fall", cold.x,
              cold.y);
}

static void three_substeps(rb_solver_settings *s)
{
    s->substeps = 3;
    s->velocity_iterations = 5;
    s->position_iterations = 2;
}
static void three_substeps_baumgarte(rb_solver_settings *s)
{
    three_substeps(s);
    s->type = RB_SOLVER_BAUMGARTE;
}

Test(solver_settings, statistics_count_bodies_contacts_and_iterations)
{
    /* A box resting on the ground: 2 bodies, 2 shapes, 1 pair, 1 contact
     * of 2 points. Velocity iterations are done in full in every substep
     * (5 × 3); NGS stops early once nothing is deeper than 3 slops, so its
     * count is between 1 per substep and 2 × 3; Baumgarte does none. */
    rb_world *world = make_world_with(three_substeps);
    add_ground_and_box(world, 0.0);
    step_world(world, TEST_DT, 30);
    rb_statistics stats = rb_world_statistics(world);
    cr_expect_eq(stats.body_count, 2);
    cr_expect_eq(stats.shape_count, 2);
    cr_expect_eq(stats.pair_count, 1);
    cr_expect_eq(stats.contact_count, 1);
    cr_expect_eq(stats.manifold_point_count, 2);
    cr_expect_eq(stats.velocity_iterations, 15);
    cr_expect(stats.position_iterations >= 3 && stats.position_iterations <= 6, "NGS did %d position iterations",
              stats.position_iterations);
    cr_expect(stats.max_penetration >= 0.0 && stats.max_penetration <= 0.005 + 1e-4,
              "largest penetration %g m, expected within the slop", stats.max_penetration);
    destroy_world_and_expect_no_leak(world);

    world = make_world_with(three_substeps_baumgarte);
    add_ground_and_box(world, 0.0);
    step_world(world, TEST_DT, 30);
    stats = rb_world_statistics(world);
    cr_expect_eq(stats.velocity_iterations, 15);
    cr_expect_eq(stats.position_iterations, 0, "Baumgarte does no position iterations");
    destroy_world_and_expect_no_leak(world);
}

Test(solver_settings, profile_phases_are_timed_within_the_step)
{
    /* Each phase is a part of the step, timed on the same monotonic clock:
     * every phase time is >= 0 and together they fit inside the step. */
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 10, &pyramid), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 5);
    const rb_profile p = rb_world_profile(world);
    const double phases[] = {p.pairs,
                             p.collide,
                             p.prepare,
                             p.integrate_velocities,
                             p.warm_start,
                             p.solve_velocities,
                             p.integrate_positions,
                             p.correct_positions,
                             p.restitution,
                             p.store_impulses,
                             p.sensors,
                             p.finalize};
    double sum = 0.0;
    for (size_t i = 0; i < sizeof phases / sizeof phases[0]; ++i) {
        cr_expect(phases[i] >= 0.0, "phase %zu took %g ms", i, phases[i]);
        sum += phases[i];
    }
    cr_expect(p.step > 0.0, "the step took %g ms", p.step);
    cr_expect(sum <= p.step, "the phases add up to %g ms, more than the step's %g ms", sum, p.step);
    destroy_world_and_expect_no_leak(world);
}

Test(solver_settings, solver_types_have_names_that_parse_back)
{
    for (int i = 0; i < RB_SOLVER_TYPE_COUNT; ++i) {
        rb_solver_type parsed = RB_SOLVER_TYPE_COUNT;
        cr_assert_eq(rb_solver_type_from_name(rb_solver_type_name((rb_solver_type)i), &parsed), RB_OK);
        cr_assert_eq(parsed, (rb_solver_type)i);
    }
    cr_assert_str_eq(rb_solver_type_name(RB_SOLVER_TYPE_COUNT), "unknown");
    rb_solver_type parsed = RB_SOLVER_NGS;
    cr_assert_eq(rb_solver_type_from_name("jacobi", &parsed), RB_ERR_INVALID_ARGUMENT);
    cr_assert(strstr(rb_last_error(), "\"jacobi\"") != NULL, "%s", rb_last_error());
    cr_assert(strstr(rb_last_error(), "ngs") != NULL, "%s", rb_last_error());
    cr_assert_eq(parsed, RB_SOLVER_NGS, "a failed parse leaves the output alone");
    cr_assert_eq(rb_solver_type_from_name(NULL, &parsed), RB_ERR_INVALID_ARGUMENT);
}
