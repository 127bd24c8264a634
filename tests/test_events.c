/* SPDX-License-Identifier: MIT */
/* Contact and sensor events, and the pre-solve filter (rb/events.h).
 *
 * The events are checked against what they report on: each step's
 * begins and ends must match the changes of the contacts' touching
 * state seen through rb_world_contacts, one event per change; their
 * times against the integrator's closed form (semi-implicit Euler from
 * rest: after N substeps of h a body has fallen g·h²·N(N+1)/2) and the
 * bounce of a ball of restitution e (back up at e times the impact
 * speed, so it lands again 2·e·v/g later).
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "rb/rb.h"
#include "test_support.h"

#define GRAVITY 9.8

/* A static box whose top face is y = 0 and a ball of radius 0.1 whose
 * lowest point starts `drop` above it, of restitution `e`. The box body
 * comes first, so the box is shape A of their contact. */
typedef struct drop_scene {
    rb_world *world;
    rb_shape_id floor, ball;
    rb_body_id ball_body;
} drop_scene;

static drop_scene make_drop(double drop, double e)
{
    drop_scene s;
    s.world = make_world(rb_v2(0.0, -GRAVITY));
    rb_body_id ground = make_body(s.world, RB_BODY_STATIC, rb_v2(0.0, -0.5), 0.0);
    s.floor = add_box(s.world, ground, 2.0, 0.5, 1.0);
    s.ball_body = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(0.0, drop + 0.1), 0.0);
    s.ball = add_circle(s.world, s.ball_body, rb_v2(0.0, 0.0), 0.1, 1.0);
    cr_assert_eq(rb_shape_set_restitution(s.world, s.ball, e), RB_OK);
    return s;
}

/* Whether the world's only contact touches now. */
static bool touching_now(const rb_world *world)
{
    rb_contact_data contact;
    return rb_world_contacts(world, &contact, 1) == 1 && contact.touching;
}

/* The first step (1-based) after which a body dropped from rest has
 * fallen `height`, by the closed form of semi-implicit Euler. */
static int fall_step(double height, int substeps)
{
    double h = TEST_DT / substeps;
    for (int step = 1;; ++step) {
        double n = (double)step * substeps;
        if (GRAVITY * h * h * n * (n + 1.0) / 2.0 >= height) {
            return step;
        }
    }
}

/* A ball dropped 0.9 m onto a box with e = 0.5: one begin when it lands,
 * one end when it bounces off, again at the next landing, and so on until
 * it rests; never two events for one change, never an event without a
 * change of the touching state. Every event names the box then the ball;
 * a begin carries the manifold, normal from box to ball (+y). */
Test(events, a_dropped_ball_begins_and_ends_once_per_bounce)
{
    drop_scene s = make_drop(0.9, 0.5);
    bool was_touching = false;
    int begin_steps[16];
    int begins = 0;
    int ends = 0;
    for (int step = 1; step <= 300; ++step) {
        step_world(s.world, TEST_DT, 1);
        rb_contact_events events = rb_world_contact_events(s.world);
        bool touching = touching_now(s.world);
        int expected_begins = touching && !was_touching ? 1 : 0;
        int expected_ends = !touching && was_touching ? 1 : 0;
        cr_assert_eq(events.begin_count, expected_begins, "step %d: %d begins, touching %d -> %d", step,
                     events.begin_count, was_touching, touching);
        cr_assert_eq(events.end_count, expected_ends, "step %d: %d ends, touching %d -> %d", step, events.end_count,
                     was_touching, touching);
        for (int i = 0; i < events.begin_count; ++i) {
            const rb_contact_begin_event *e = &events.begin_events[i];
            cr_expect(rb_shape_id_equals(e->shape_a, s.floor) && rb_shape_id_equals(e->shape_b, s.ball));
            cr_expect(e->manifold.point_count == 1 && e->manifold.points[0].separation <= 0.0);
            expect_vec_near(e->manifold.normal, rb_v2(0.0, 1.0), 1e-12, "begin normal");
            if (begins < 16) {
                begin_steps[begins] = step;
            }
            ++begins;
        }
        for (int i = 0; i < events.end_count; ++i) {
            cr_expect(rb_shape_id_equals(events.end_events[i].shape_a, s.floor) &&
                      rb_shape_id_equals(events.end_events[i].shape_b, s.ball));
            ++ends;
        }
        was_touching = touching;
    }
    cr_assert(begins >= 2, "the ball should land, bounce and land again: %d begins", begins);
    cr_expect(ends == begins - 1, "%d begins, %d ends: at rest the last begin stays open", begins, ends);
    cr_expect(touching_now(s.world), "at rest on the box");

    /* Landing: the step at which the ball has fallen 0.9 m, give or take
     * one (the contact begins when the solver stops it, within a step). */
    int substeps = rb_world_solver_settings(s.world).substeps;
    int landing = fall_step(0.9, substeps);
    cr_expect(abs(begin_steps[0] - landing) <= 1, "first begin at step %d, the fall takes %d", begin_steps[0], landing);
    /* Second landing: 2·e·v/g after the first, v = √(2 g 0.9). */
    double flight = 2.0 * 0.5 * sqrt(2.0 * GRAVITY * 0.9) / GRAVITY;
    double measured = (begin_steps[1] - begin_steps[0]) * TEST_DT;
    expect_near(measured, flight, 2.5 * TEST_DT, "time between the first two landings");
    rb_world_destroy(s.world);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

/* A ball falls through a static sensor slab from y = 0.4 to 0.6 (no
 * floor). It begins to overlap when its lowest point has fallen from 0.9
 * to 0.6, and stops when its top (from 1.1) has fallen below 0.4: one
 * begin and one end, at the steps the closed form gives, naming the
 * sensor then the ball. The sensor never pushes, and makes no contact
 * events. */
Test(events, a_ball_falling_through_a_sensor_begins_and_ends_once)
{
    rb_world *world = make_world(rb_v2(0.0, -GRAVITY));
    rb_body_id slab = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.5), 0.0);
    rb_polygon box;
    cr_assert_eq(rb_make_box(2.0, 0.1, &box), RB_OK);
    rb_shape_def def = rb_default_shape_def();
    def.is_sensor = true;
    rb_shape_id sensor;
    cr_assert_eq(rb_shape_create_polygon(world, slab, &def, &box, &sensor), RB_OK);
    rb_body_id ball_body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 1.0), 0.0);
    rb_shape_id ball = add_circle(world, ball_body, rb_v2(0.0, 0.0), 0.1, 1.0);

    int substeps = rb_world_solver_settings(world).substeps;
    int enter = fall_step(0.3, substeps);
    int leave = fall_step(0.7 + 1e-12, substeps);
    int begins = 0;
    int ends = 0;
    for (int step = 1; step <= 40; ++step) {
        step_world(world, TEST_DT, 1);
        rb_sensor_events events = rb_world_sensor_events(world);
        for (int i = 0; i < events.begin_count; ++i) {
            cr_expect_eq(step, enter, "begin at step %d, expected %d", step, enter);
            cr_expect(rb_shape_id_equals(events.begin_events[i].sensor_shape, sensor) &&
                      rb_shape_id_equals(events.begin_events[i].visitor_shape, ball));
            ++begins;
        }
        for (int i = 0; i < events.end_count; ++i) {
            cr_expect_eq(step, leave, "end at step %d, expected %d", step, leave);
            cr_expect(rb_shape_id_equals(events.end_events[i].sensor_shape, sensor) &&
                      rb_shape_id_equals(events.end_events[i].visitor_shape, ball));
            ++ends;
        }
        rb_contact_events contacts = rb_world_contact_events(world);
        cr_expect_eq(contacts.begin_count + contacts.end_count, 0, "a sensor makes no contact events");
    }
    cr_expect_eq(begins, 1);
    cr_expect_eq(ends, 1);
    double n = 40.0 * substeps;
    double h = TEST_DT / substeps;
    expect_near(rb_body_linear_velocity(world, ball_body).y, -GRAVITY * h * n, 1e-9, "free fall through the sensor");
    destroy_world_and_expect_no_leak(world);
}

/* ---- pre-solve ------------------------------------------------------------ */

typedef struct pre_solve_log {
    rb_shape_id floor, ball;
    int calls;
    int wrong_shapes;
    int without_points;
} pre_solve_log;

static bool let_the_ball_through(rb_shape_id shape_a, rb_shape_id shape_b, const rb_manifold *manifold, void *context)
{
    pre_solve_log *log = context;
    log->calls++;
    log->wrong_shapes += rb_shape_id_equals(shape_a, log->floor) && rb_shape_id_equals(shape_b, log->ball) ? 0 : 1;
    log->without_points += manifold->point_count > 0 ? 0 : 1;
    return false;
}

/* With a filter that disables the box-ball contact the ball falls through
 * the 1 m box as if it were not there (the closed form of free fall, to
 * round-off); the filter is asked about the right pair, always with
 * points. The contact still begins and ends as the ball passes. Without
 * the filter the same ball stops on the box. */
Test(events, pre_solve_filter_lets_a_ball_pass_through)
{
    drop_scene s = make_drop(0.2, 0.0);
    pre_solve_log log = {.floor = s.floor, .ball = s.ball};
    cr_assert_eq(rb_world_set_pre_solve(s.world, let_the_ball_through, &log), RB_OK, "%s", rb_last_error());
    int steps = 40;
    int begins = 0;
    int ends = 0;
    for (int i = 0; i < steps; ++i) {
        step_world(s.world, TEST_DT, 1);
        begins += rb_world_contact_events(s.world).begin_count;
        ends += rb_world_contact_events(s.world).end_count;
    }
    int substeps = rb_world_solver_settings(s.world).substeps;
    double h = TEST_DT / substeps;
    double n = (double)steps * substeps;
    expect_near(rb_body_position(s.world, s.ball_body).y, 0.3 - GRAVITY * h * h * n * (n + 1.0) / 2.0, 1e-9,
                "free fall through the box");
    cr_expect(log.calls > 0, "the filter was never asked");
    cr_expect_eq(log.wrong_shapes, 0);
    cr_expect_eq(log.without_points, 0);
    cr_expect_eq(begins, 1, "the ball entering the box");
    cr_expect_eq(ends, 1, "the ball leaving the box");

    cr_assert_eq(rb_world_set_pre_solve(s.world, NULL, NULL), RB_OK);
    rb_world_destroy(s.world);

    drop_scene control = make_drop(0.2, 0.0);
    step_world(control.world, TEST_DT, steps);
    expect_near(rb_body_position(control.world, control.ball_body).y, 0.1, 0.01, "without the filter: on the box");
    destroy_world_and_expect_no_leak(control.world);
}

typedef struct locked_probe {
    rb_world *world;
    rb_status status;
} locked_probe;

static bool try_to_change_the_world(rb_shape_id shape_a, rb_shape_id shape_b, const rb_manifold *manifold,
                                    void *context)
{
    (void)shape_a;
    (void)shape_b;
    (void)manifold;
    locked_probe *probe = context;
    probe->status = rb_world_set_gravity(probe->world, rb_v2(0.0, 0.0));
    return true;
}

Test(events, the_world_is_locked_during_pre_solve)
{
    drop_scene s = make_drop(0.0, 0.0);
    locked_probe probe = {s.world, RB_OK};
    cr_assert_eq(rb_world_set_pre_solve(s.world, try_to_change_the_world, &probe), RB_OK);
    step_world(s.world, TEST_DT, 1);
    cr_expect_eq(probe.status, RB_ERR_LOCKED, "changing the world from the callback: %s", rb_status_name(probe.status));
    expect_vec_near(rb_world_gravity(s.world), rb_v2(0.0, -GRAVITY), 0.0, "gravity unchanged");
    cr_expect_eq(rb_world_set_pre_solve(NULL, NULL, NULL), RB_ERR_INVALID_ARGUMENT);
    destroy_world_and_expect_no_leak(s.world);
}

/* ---- destruction --------------------------------------------------------- */

/* Destroying the ball while it rests on the box: the last step's event
 * arrays do not move or change, and the contact's end comes with the
 * next step's events, naming the destroyed shape. */
Test(events, destroying_a_touching_shape_ends_its_contact_at_the_next_step)
{
    drop_scene s = make_drop(0.0, 0.0);
    step_world(s.world, TEST_DT, 1);
    rb_contact_events before = rb_world_contact_events(s.world);
    cr_assert_eq(before.begin_count, 1, "the ball starts on the box");
    rb_contact_begin_event kept = before.begin_events[0];
    cr_assert_eq(rb_body_destroy(s.world, s.ball_body), RB_OK, "%s", rb_last_error());
    rb_contact_events still = rb_world_contact_events(s.world);
    cr_expect(still.begin_events == before.begin_events && still.begin_count == 1 && still.end_count == 0,
              "the published events stay as they were until the next step");
    cr_expect(memcmp(&still.begin_events[0], &kept, sizeof kept) == 0);

    step_world(s.world, TEST_DT, 1);
    rb_contact_events after = rb_world_contact_events(s.world);
    cr_expect_eq(after.begin_count, 0);
    cr_assert_eq(after.end_count, 1);
    cr_expect(rb_shape_id_equals(after.end_events[0].shape_a, s.floor) &&
              rb_shape_id_equals(after.end_events[0].shape_b, s.ball));
    cr_expect(!rb_shape_is_valid(s.world, after.end_events[0].shape_b), "the ball's id is stale now");
    step_world(s.world, TEST_DT, 1);
    cr_expect_eq(rb_world_contact_events(s.world).end_count, 0, "reported once");
    destroy_world_and_expect_no_leak(s.world);
}

/* A visitor destroyed inside a sensor ends its overlap the same way. */
Test(events, destroying_a_visitor_ends_its_sensor_overlap)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id zone = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    def.is_sensor = true;
    rb_circle area = {{0.0, 0.0}, 1.0};
    rb_shape_id sensor;
    cr_assert_eq(rb_shape_create_circle(world, zone, &def, &area, &sensor), RB_OK);
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.2, 0.0), 0.0);
    rb_shape_id visitor = add_circle(world, body, rb_v2(0.0, 0.0), 0.1, 1.0);
    step_world(world, TEST_DT, 1);
    cr_assert_eq(rb_world_sensor_events(world).begin_count, 1);
    cr_assert_eq(rb_shape_destroy(world, visitor), RB_OK);
    step_world(world, TEST_DT, 1);
    rb_sensor_events events = rb_world_sensor_events(world);
    cr_assert_eq(events.end_count, 1);
    cr_expect(rb_shape_id_equals(events.end_events[0].sensor_shape, sensor) &&
              rb_shape_id_equals(events.end_events[0].visitor_shape, visitor));
    destroy_world_and_expect_no_leak(world);
}
