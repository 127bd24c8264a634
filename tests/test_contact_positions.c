// SPDX-License-Identifier: MIT
/* The non-linear Gauss-Seidel position pass over the contacts
 * (rb_contact_solver_correct_positions), which passes over runs of
 * contacts needing no correction after measuring them two at a time
 * (contact_positions_wide.c), against the reference that measures and
 * corrects every contact one at a time
 * (rb_contact_solver_correct_contact_positions): from the same poses both
 * must leave the same poses, byte for byte, and the same verdict on the
 * overlap left. The stated tolerance is none: each lane does the
 * reference's arithmetic in the reference's order, and a contact that
 * needs a correction is left to the reference.
 *
 * The poses are a settled base-20 pyramid (590 contacts of two points)
 * with balls beside it (contacts of one point, which the lanes do not
 * take), some of its boxes pushed down into the ones below by up to a few
 * slops, so that contacts needing a correction fall here and there among
 * resting ones (a few boxes pushed) or make up much of the pass (every
 * box pushed). */
#include <string.h>

#include "contact_solver.h"
#include "pile_support.h"

/* A deterministic value in [0, 1) (a linear congruential generator,
 * Knuth's MMIX constants). */
static double next_fraction(uint64_t *state)
{
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (double)(*state >> 11) / (double)(UINT64_C(1) << 53);
}

/* How the reference's pass went. */
typedef struct reference_pass {
    int corrected; /* contacts whose correction moved a body */
    bool within;   /* no point deeper than the tolerance before it */
} reference_pass;

/* The reference's pass from the poses now: every contact one at a time. */
static reference_pass run_reference(rb_world *world)
{
    reference_pass pass = {0};
    double deepest = 0.0;
    size_t bytes = (size_t)world->body_slots * sizeof *world->states;
    rb_body_state *before = malloc(bytes);
    cr_assert(before);
    for (int i = 0; i < world->constraint_count; ++i) {
        memcpy(before, world->states, bytes);
        rb_contact_solver_correct_contact_positions(world, i, &deepest);
        pass.corrected += memcmp(before, world->states, bytes) != 0;
    }
    free(before);
    /* the pass's tolerance: three slops (contact_solver.c) */
    pass.within = deepest >= -3.0 * world->settings.linear_slop;
    return pass;
}

/* Pushes every `every`-th box of the pyramid down by up to `depth` m and
 * turns it by up to depth/10 rad, prepares the contacts at the settled
 * poses (as a step does before its substeps), and runs both passes from
 * the pushed poses. Returns how many contacts the reference corrected. */
static int expect_passes_agree(rb_world *world, const scene_pyramid *pyramid, int every, double depth, uint64_t seed)
{
    cr_assert_geq(rb_contact_solver_prepare(world), 0, "out of memory");
    int count = world->constraint_count;
    cr_assert_gt(count, 590, "the pyramid's contacts and the balls' (%d)", count);
    for (int k = 0; k < pyramid->box_count; k += every) {
        rb_body_id id = scene_body_at(pyramid->first_box, k);
        rb_body_state *s = &world->states[id.index];
        s->center.y -= depth * next_fraction(&seed);
        s->angle += 0.1 * depth * (next_fraction(&seed) - 0.5);
        s->rotation = rb_rot_from_angle(s->angle);
    }
    size_t bytes = (size_t)world->body_slots * sizeof *world->states;
    rb_body_state *start = malloc(bytes);
    rb_body_state *reference = malloc(bytes);
    cr_assert(start && reference);
    memcpy(start, world->states, bytes);

    reference_pass expected = run_reference(world);
    memcpy(reference, world->states, bytes);
    memcpy(world->states, start, bytes);
    bool within = rb_contact_solver_correct_positions(world);

    cr_expect_eq(within, expected.within, "the pass says the overlap is %swithin the tolerance, the reference %s",
                 within ? "" : "not ", expected.within ? "within" : "not within");
    for (int i = 0; i < world->body_slots; ++i) {
        const rb_body_state *r = &reference[i];
        const rb_body_state *w = &world->states[i];
        cr_expect(memcmp(r, w, sizeof *r) == 0,
                  "body %d: pose (%.17g, %.17g, %.17g rad) one at a time, (%.17g, %.17g, %.17g rad) by the pass "
                  "(every %d-th box pushed by up to %g m)",
                  i, r->center.x, r->center.y, r->angle, w->center.x, w->center.y, w->angle, every, depth);
    }
    free(start);
    free(reference);
    return expected.corrected;
}

Test(contact_positions, the_pass_leaves_the_poses_the_reference_leaves)
{
    scene_pyramid pyramid;
    rb_world *world = make_pile(RB_SOLVER_NGS, &pyramid);
    step_world(world, TEST_DT, 60);

    size_t bytes = (size_t)world->body_slots * sizeof *world->states;
    rb_body_state *settled = malloc(bytes);
    cr_assert(settled);
    memcpy(settled, world->states, bytes);
    double slop = world->settings.linear_slop;
    /* settled: at most a few corrections; then ever more boxes pushed */
    cr_expect_lt(expect_passes_agree(world, &pyramid, 1, 0.0, 1u), 20, "a settled pile needs next to no correction");
    static const struct {
        int every;
        double depth_in_slops;
    } rounds[] = {{29, 3.0}, {11, 4.0}, {5, 6.0}, {2, 8.0}, {1, 10.0}};
    int rounds_count = (int)(sizeof rounds / sizeof rounds[0]);
    int corrected[sizeof rounds / sizeof rounds[0]];
    for (int r = 0; r < rounds_count; ++r) {
        memcpy(world->states, settled, bytes);
        corrected[r] =
            expect_passes_agree(world, &pyramid, rounds[r].every, rounds[r].depth_in_slops * slop, 10u + (uint64_t)r);
    }
    cr_expect(corrected[0] > 0 && corrected[0] < world->constraint_count / 4,
              "a few boxes pushed: some contacts corrected, most passed over (%d of %d)", corrected[0],
              world->constraint_count);
    cr_expect_gt(corrected[rounds_count - 1], world->constraint_count / 4,
                 "every box pushed: many contacts corrected (%d of %d)", corrected[rounds_count - 1],
                 world->constraint_count);
    free(settled);
    destroy_world_and_expect_no_leak(world);
}
