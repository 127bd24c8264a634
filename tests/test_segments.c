/* SPDX-License-Identifier: MIT */
/* Segment and chain shapes: manifolds against hand-derived geometry,
 * the ghost vertices that keep a chain smooth, the mass rule, the chain
 * builder, and two motions with closed forms: a disc rolling down a
 * chain incline (a = 2/3·g·sin θ) and a frictionless box sliding across
 * many chain joints at constant speed (while plain segments catch it).
 *
 * Manifold tolerance: values of order 1 reached in a few dozen
 * operations; 1e-12 is far below the 0.01 m overlaps tested.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "rb/rb.h"
#include "test_support.h"

#define TOLERANCE 1e-12
#define SPECULATIVE 0.02

static rb_transform pose(double x, double y, double angle) { return (rb_transform){{x, y}, rb_rot_from_angle(angle)}; }

static rb_polygon make_box(double hx, double hy)
{
    rb_polygon box;
    cr_assert_eq(rb_make_box(hx, hy, &box), RB_OK, "rb_make_box: %s", rb_last_error());
    return box;
}

static const rb_segment unit_segment = {{-1.0, 0.0}, {1.0, 0.0}};

/* A flat chain segment from (0, 0) to (1, 0) between neighbours on the
 * same line: both joints flat. */
static rb_chain_segment flat_chain_segment(void)
{
    return (rb_chain_segment){.segment = {{0.0, 0.0}, {1.0, 0.0}},
                              .ghost1 = {-1.0, 0.0},
                              .ghost2 = {2.0, 0.0},
                              .has_ghost1 = true,
                              .has_ghost2 = true};
}

/* ---- segment manifolds ---------------------------------------------------- */

/* Circle of radius 0.5 centred 0.4 above the segment's middle: face
 * region, normal +y, separation 0.4 - 0.5 = -0.1, the point midway
 * between the segment (y = 0) and the circle's lowest point (y = -0.1). */
Test(segments, circle_on_segment_face_from_either_side)
{
    rb_circle circle = {{0.0, 0.0}, 0.5};
    rb_manifold above =
        rb_collide_segment_and_circle(&unit_segment, rb_transform_identity(), &circle, pose(0.3, 0.4, 0.0), 0.0);
    cr_assert_eq(above.point_count, 1);
    expect_vec_near(above.normal, rb_v2(0.0, 1.0), TOLERANCE, "normal above");
    expect_vec_near(above.points[0].point, rb_v2(0.3, -0.05), TOLERANCE, "point above");
    expect_near(above.points[0].separation, -0.1, TOLERANCE, "separation above");
    cr_expect_eq(above.points[0].id, 0u);

    rb_manifold below =
        rb_collide_segment_and_circle(&unit_segment, rb_transform_identity(), &circle, pose(0.3, -0.4, 0.0), 0.0);
    cr_assert_eq(below.point_count, 1);
    expect_vec_near(below.normal, rb_v2(0.0, -1.0), TOLERANCE, "normal below");
    expect_vec_near(below.points[0].point, rb_v2(0.3, 0.05), TOLERANCE, "point below");
}

/* Circle of radius 0.6 at (1.3, 0.4): beyond point2 (1, 0), 0.5 away
 * along (0.6, 0.8); separation -0.1; the circle's surface point is
 * c - 0.6·n = (0.94, -0.08), so the midpoint is (0.97, -0.04). The same
 * in a turned and shifted frame G: normal G.q·n, point G·p. */
Test(segments, circle_on_segment_end)
{
    rb_circle circle = {{0.0, 0.0}, 0.6};
    rb_transform g = pose(2.0, -1.0, 0.7);
    rb_vec2 local_center = {1.3, 0.4};
    rb_manifold m = rb_collide_segment_and_circle(&unit_segment, g, &circle,
                                                  (rb_transform){rb_transform_point(g, local_center), g.q}, 0.0);
    cr_assert_eq(m.point_count, 1);
    expect_vec_near(m.normal, rb_rotate(g.q, rb_v2(0.6, 0.8)), TOLERANCE, "normal");
    expect_vec_near(m.points[0].point, rb_transform_point(g, rb_v2(0.97, -0.04)), TOLERANCE, "point");
    expect_near(m.points[0].separation, -0.1, TOLERANCE, "separation");
}

/* A 1 × 1 box centred at (0.2, 0.45) sinks 0.05 into the segment. Both
 * best axes are 0.05 deep, so the segment keeps the reference face: its
 * edge 1 (point2 -> point1, normal +y). The box's bottom edge (its edge
 * 0, from (-0.3, -0.05) to (0.7, -0.05)) lies within the segment's side
 * planes, so both ends stay, each at separation -0.05 and reported
 * halfway up: y = -0.025. */
Test(segments, box_on_segment)
{
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold m =
        rb_collide_segment_and_polygon(&unit_segment, rb_transform_identity(), &box, pose(0.2, 0.45, 0.0), 0.0);
    cr_assert_eq(m.point_count, 2);
    expect_vec_near(m.normal, rb_v2(0.0, 1.0), TOLERANCE, "normal");
    expect_vec_near(m.points[0].point, rb_v2(-0.3, -0.025), TOLERANCE, "point 0");
    expect_vec_near(m.points[1].point, rb_v2(0.7, -0.025), TOLERANCE, "point 1");
    for (int i = 0; i < 2; ++i) {
        expect_near(m.points[i].separation, -0.05, TOLERANCE, "separation");
        /* Box corner i (bottom left, then bottom right) with the segment's
         * end on its side (point1 on the left, point2 on the right). */
        cr_expect_eq(m.points[i].id, rb_feature_id(i, i), "id %d is %#x", i, m.points[i].id);
    }
}

/* A box corner held in its own face's fan: a 0.5 box resting with its
 * left face against the segment's free end point2 = (1, 0), overlapping
 * by 0.01 in x and reaching 0.3 below the segment. The shallowest axis
 * is the box's left face (x = 0.99, normal -x, 0.01 deep), so the box
 * holds the reference face: the normal from segment to box is +x, one
 * point from point2 with separation -0.01, reported midway to the face
 * at x = 0.995, with the reference face marked as shape B's. */
Test(segments, box_beside_segment_end_uses_the_box_face)
{
    rb_polygon box = make_box(0.5, 0.5);
    rb_manifold m =
        rb_collide_segment_and_polygon(&unit_segment, rb_transform_identity(), &box, pose(1.49, 0.2, 0.0), 0.0);
    cr_assert_eq(m.point_count, 1);
    expect_vec_near(m.normal, rb_v2(1.0, 0.0), TOLERANCE, "normal");
    expect_vec_near(m.points[0].point, rb_v2(0.995, 0.0), TOLERANCE, "point");
    expect_near(m.points[0].separation, -0.01, TOLERANCE, "separation");
    cr_expect(m.reference_on_b, "the box holds the reference face");
}

/* In a world the box's body comes first, so the box is shape A: the
 * normal must point from the box down to the segment, and the manifold
 * must say that the reference face (the segment's) is now shape B's. */
Test(segments, world_contact_with_box_as_shape_a)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.2, 0.45), 0.0);
    add_box(world, box, 0.5, 0.5, 1.0);
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    rb_shape_id segment;
    cr_assert_eq(rb_shape_create_segment(world, ground, &def, &unit_segment, &segment), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 1);
    rb_contact_data contact;
    cr_assert_eq(rb_world_contacts(world, &contact, 1), 1);
    cr_expect(rb_shape_id_equals(contact.shape_b, segment));
    cr_assert_eq(contact.manifold.point_count, 2);
    expect_vec_near(contact.manifold.normal, rb_v2(0.0, -1.0), TOLERANCE, "normal from the box to the segment");
    cr_expect(contact.manifold.reference_on_b, "reference face on shape B");
    destroy_world_and_expect_no_leak(world);
}

/* ---- ghost vertices -------------------------------------------------------- */

/* A 0.5 box sliding right along the line y = 0, sunk 0.004 into it (as a
 * resting box sinks by about the slop), its leading face 0.002 short of
 * the joint at (0, 0). A plain segment from the joint on finds the box's
 * leading face the shallowest axis (0.002 apart against 0.004 deep) and
 * pushes back along -x: the box would catch. As a chain segment with a
 * flat joint that normal is refused, the segment's face is used, and
 * the box's bottom does not reach past the joint yet: no point at all. */
Test(segments, a_flat_joint_never_pushes_sideways)
{
    rb_polygon box = make_box(0.25, 0.25);
    rb_transform box_pose = pose(-0.252, 0.246, 0.0);
    rb_segment plain = {{0.0, 0.0}, {1.0, 0.0}};
    rb_manifold catching = rb_collide_segment_and_polygon(&plain, rb_transform_identity(), &box, box_pose, SPECULATIVE);
    cr_assert_eq(catching.point_count, 1, "the plain segment gives one point at its end");
    expect_vec_near(catching.normal, rb_v2(-1.0, 0.0), TOLERANCE, "plain segment: sideways normal");

    rb_chain_segment chain = flat_chain_segment();
    rb_manifold smooth =
        rb_collide_chain_segment_and_polygon(&chain, rb_transform_identity(), &box, box_pose, SPECULATIVE);
    cr_expect_eq(smooth.point_count, 0, "chain segment: no point before the box reaches it");

    /* Once over the joint by 0.1, the chain segment pushes straight up:
     * the bottom edge clipped to x in [0, 0.148] (the joint end first, as
     * clipping keeps the incident edge's order), 0.004 deep. */
    rb_manifold over =
        rb_collide_chain_segment_and_polygon(&chain, rb_transform_identity(), &box, pose(-0.102, 0.246, 0.0), 0.0);
    cr_assert_eq(over.point_count, 2);
    expect_vec_near(over.normal, rb_v2(0.0, 1.0), TOLERANCE, "normal over the joint");
    expect_vec_near(over.points[0].point, rb_v2(0.0, -0.002), TOLERANCE, "joint");
    expect_vec_near(over.points[1].point, rb_v2(0.148, -0.002), TOLERANCE, "incident corner");
}

/* At a free end (no ghost) the box's face may hold the reference, as on a
 * plain segment: the same box as above, beside the end point1. */
Test(segments, a_free_chain_end_is_a_corner)
{
    rb_polygon box = make_box(0.25, 0.25);
    rb_chain_segment chain = flat_chain_segment();
    chain.has_ghost1 = false;
    rb_manifold m =
        rb_collide_chain_segment_and_polygon(&chain, rb_transform_identity(), &box, pose(-0.252, 0.246, 0.0), 0.02);
    cr_assert_eq(m.point_count, 1);
    expect_vec_near(m.normal, rb_v2(-1.0, 0.0), TOLERANCE, "normal at a free end");
    expect_vec_near(m.points[0].point, rb_v2(-0.001, 0.0), TOLERANCE, "point");
}

/* A circle beyond a flat joint belongs to the neighbour; beyond a free
 * end the segment reports its end point; behind a chain it gets nothing. */
Test(segments, chain_circle_regions)
{
    rb_circle circle = {{0.0, 0.0}, 0.5};
    rb_chain_segment chain = flat_chain_segment();
    rb_transform beyond_point2 = pose(1.2, 0.4, 0.0);
    rb_transform before_point1 = pose(-0.2, 0.4, 0.0);
    cr_expect_eq(
        rb_collide_chain_segment_and_circle(&chain, rb_transform_identity(), &circle, beyond_point2, 0.0).point_count,
        0, "beyond a joint: the next segment's");
    cr_expect_eq(
        rb_collide_chain_segment_and_circle(&chain, rb_transform_identity(), &circle, before_point1, 0.0).point_count,
        0, "before a flat joint: the previous segment's");
    cr_expect_eq(
        rb_collide_chain_segment_and_circle(&chain, rb_transform_identity(), &circle, pose(0.5, -0.4, 0.0), 0.0)
            .point_count,
        0, "behind the chain");

    /* Right above the joint at point2 the face still answers (and the
     * next segment's face too): never a gap at a joint. */
    rb_manifold above_joint =
        rb_collide_chain_segment_and_circle(&chain, rb_transform_identity(), &circle, pose(1.0, 0.4, 0.0), 0.0);
    cr_assert_eq(above_joint.point_count, 1, "above the joint");
    expect_vec_near(above_joint.normal, rb_v2(0.0, 1.0), TOLERANCE, "face normal above the joint");
    rb_chain_segment next = {.segment = {{1.0, 0.0}, {2.0, 0.0}}, .ghost1 = {0.0, 0.0}, .has_ghost1 = true};
    cr_expect_eq(rb_collide_chain_segment_and_circle(&next, rb_transform_identity(), &circle, pose(1.0, 0.4, 0.0), 0.0)
                     .point_count,
                 1, "the next segment above its first point");

    chain.has_ghost2 = false;
    rb_manifold end = rb_collide_chain_segment_and_circle(&chain, rb_transform_identity(), &circle, beyond_point2, 0.0);
    cr_assert_eq(end.point_count, 1, "beyond a free end");
    /* From (1, 0) to (1.2, 0.4): distance √0.2, normal (1, 2)/√5. */
    expect_vec_near(end.normal, rb_v2(1.0 / sqrt(5.0), 2.0 / sqrt(5.0)), TOLERANCE, "end normal");
    expect_near(end.points[0].separation, sqrt(0.2) - 0.5, TOLERANCE, "end separation");

    /* A convex joint (the previous segment comes up from (-1, -1)): the
     * circle in the wedge above the joint touches the vertex (0, 0). */
    chain.ghost1 = rb_v2(-1.0, -1.0);
    rb_manifold wedge =
        rb_collide_chain_segment_and_circle(&chain, rb_transform_identity(), &circle, pose(-0.1, 0.45, 0.0), 0.0);
    cr_assert_eq(wedge.point_count, 1, "in the wedge of a convex joint");
    expect_vec_near(wedge.normal, rb_normalize(rb_v2(-0.1, 0.45)), TOLERANCE, "wedge normal");
}

/* ---- mass and the chain builder ----------------------------------------- */

Test(segments, segments_have_no_mass)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    rb_shape_id shape;
    cr_expect_eq(rb_shape_create_segment(world, body, &def, &unit_segment, &shape), RB_ERR_NO_MASS);
    cr_expect(strstr(rb_last_error(), "rb_shape_create_segment") != NULL, "%s", rb_last_error());
    rb_mass_data mass = {2.0, {0.0, 0.0}, 0.5};
    cr_assert_eq(rb_body_set_mass_data(world, body, &mass), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_shape_create_segment(world, body, &def, &unit_segment, &shape), RB_OK, "%s", rb_last_error());
    expect_near(rb_body_mass(world, body), 2.0, 0.0, "the override's mass");
    cr_expect_eq(rb_body_reset_mass_data(world, body), RB_ERR_NO_MASS, "dropping the override would leave no mass");

    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    cr_assert_eq(rb_shape_create_segment(world, ground, &def, &unit_segment, &shape), RB_OK, "%s", rb_last_error());
    cr_expect_eq(rb_body_set_type(world, ground, RB_BODY_DYNAMIC), RB_ERR_NO_MASS);
    cr_expect_eq(rb_shape_type_of(world, shape), RB_SHAPE_SEGMENT);
    rb_segment back = rb_shape_segment(world, shape);
    expect_vec_near(back.point2, unit_segment.point2, 0.0, "rb_shape_segment");
    rb_aabb box = rb_shape_aabb(world, shape);
    expect_vec_near(box.lower, rb_v2(-1.0, 0.0), 0.0, "box lower");
    expect_vec_near(box.upper, rb_v2(1.0, 0.0), 0.0, "box upper");
    destroy_world_and_expect_no_leak(world);
}

Test(segments, chain_builder_links_ghosts)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    const rb_vec2 points[4] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
    rb_shape_id open[3];
    cr_assert_eq(rb_shape_create_chain(world, ground, &def, points, 4, false, open, 3), RB_OK, "%s", rb_last_error());
    rb_chain_segment first = rb_shape_chain_segment(world, open[0]);
    rb_chain_segment middle = rb_shape_chain_segment(world, open[1]);
    rb_chain_segment last = rb_shape_chain_segment(world, open[2]);
    cr_expect(!first.has_ghost1 && first.has_ghost2 && middle.has_ghost1 && middle.has_ghost2 && last.has_ghost1 &&
              !last.has_ghost2);
    expect_vec_near(middle.ghost1, points[0], 0.0, "middle ghost1");
    expect_vec_near(middle.ghost2, points[3], 0.0, "middle ghost2");
    expect_vec_near(rb_shape_segment(world, open[2]).point1, points[2], 0.0, "last point1");

    rb_shape_id loop[4];
    cr_assert_eq(rb_shape_create_chain(world, ground, &def, points, 4, true, loop, 4), RB_OK, "%s", rb_last_error());
    rb_chain_segment closing = rb_shape_chain_segment(world, loop[3]);
    expect_vec_near(closing.segment.point2, points[0], 0.0, "the loop closes");
    expect_vec_near(closing.ghost2, points[1], 0.0, "closing ghost2");
    expect_vec_near(rb_shape_chain_segment(world, loop[0]).ghost1, points[3], 0.0, "first ghost1");
    cr_expect_eq(rb_body_shape_count(world, ground), 7);

    /* Bad input leaves nothing behind. */
    const rb_vec2 repeated[3] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}};
    cr_expect_eq(rb_shape_create_chain(world, ground, &def, repeated, 3, false, NULL, 0), RB_ERR_DEGENERATE_SHAPE);
    cr_expect(strstr(rb_last_error(), "segment 1") != NULL, "%s", rb_last_error());
    cr_expect_eq(rb_shape_create_chain(world, ground, &def, points, 2, true, NULL, 0), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(rb_shape_create_chain(world, ground, &def, points, 4, false, open, 2), RB_ERR_INVALID_ARGUMENT);
    const rb_vec2 not_finite[2] = {{0.0, 0.0}, {NAN, 0.0}};
    cr_expect_eq(rb_shape_create_chain(world, ground, &def, not_finite, 2, false, NULL, 0), RB_ERR_INVALID_ARGUMENT);
    rb_body_id dynamic = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    cr_expect_eq(rb_shape_create_chain(world, dynamic, &def, points, 4, false, NULL, 0), RB_ERR_NO_MASS);
    cr_expect_eq(rb_body_shape_count(world, ground), 7);
    cr_expect_eq(rb_body_shape_count(world, dynamic), 0);
    destroy_world_and_expect_no_leak(world);
}

/* ---- motion on chains ----------------------------------------------------- */

/* A static chain ground from x0 to x1, falling by `slope` per metre, of
 * `count` equal segments (the chain faces up: it runs left to right). */
static void add_chain_ground(rb_world *world, double x0, double x1, double slope, int count, bool plain_segments,
                             double friction)
{
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    def.friction = friction;
    rb_vec2 points[512];
    cr_assert(count + 1 <= 512);
    for (int i = 0; i <= count; ++i) {
        double x = x0 + (x1 - x0) * i / count;
        points[i] = rb_v2(x, -slope * (x - x0));
    }
    if (!plain_segments) {
        cr_assert_eq(rb_shape_create_chain(world, ground, &def, points, count + 1, false, NULL, 0), RB_OK, "%s",
                     rb_last_error());
        return;
    }
    for (int i = 0; i < count; ++i) {
        rb_segment segment = {points[i], points[i + 1]};
        rb_shape_id id;
        cr_assert_eq(rb_shape_create_segment(world, ground, &def, &segment, &id), RB_OK, "%s", rb_last_error());
    }
}

/* A ball of radius 0.1 resting on a slope of angle θ, from x = -1 to 9,
 * made of `segments` chain segments; returns it after 1.5 s. */
static rb_body_id roll_ball(rb_world *world, double theta, int segments)
{
    add_chain_ground(world, -1.0, 9.0, tan(theta), segments, false, 0.6);
    /* Resting on the slope above x = 0: centre r along the normal. */
    rb_vec2 normal = {sin(theta), cos(theta)};
    rb_body_id ball = make_body(world, RB_BODY_DYNAMIC, rb_mul_add(rb_v2(0.0, -tan(theta)), 0.1, normal), 0.0);
    add_circle(world, ball, rb_v2(0.0, 0.0), 0.1, 1.0);
    step_world(world, TEST_DT, 90);
    return ball;
}

/* A uniform disc rolling without slipping down a slope of angle θ:
 * m·a = m·g·sin θ - F and I·α = F·r with α = a/r, I = m·r²/2, so
 * a = g·sin θ/(1 + I/(m r²)) = 2/3·g·sin θ (it needs μ >= tan θ/3 = 0.12
 * at 20°; the chain has 0.6). On a chain of 200 segments of 5 cm the
 * ball moves exactly as on a single segment: the joints are invisible.
 * Its speed after 1.5 s is a·t to 0.1 %; ω·r matches v to 2 % (the
 * solver's friction anchors drift within a step: the same 1.6 % on a
 * single segment). */
Test(segments, a_ball_rolls_down_a_chain_at_two_thirds_g_sin_theta)
{
    double theta = 20.0 * RB_PI / 180.0;
    rb_world *single = make_world(rb_v2(0.0, -9.8));
    rb_body_id reference = roll_ball(single, theta, 1);
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id ball = roll_ball(world, theta, 200);
    expect_vec_near(rb_body_position(world, ball), rb_body_position(single, reference), 1e-9,
                    "position on the chain vs on one segment");
    expect_near(rb_body_angular_velocity(world, ball), rb_body_angular_velocity(single, reference), 1e-9,
                "spin on the chain vs on one segment");

    double a = 2.0 / 3.0 * 9.8 * sin(theta);
    double speed = rb_length(rb_body_linear_velocity(world, ball));
    expect_near(speed, a * 1.5, 0.001 * a * 1.5, "rolling speed");
    expect_near(rb_body_angular_velocity(world, ball), -speed / 0.1, 0.02 * speed / 0.1, "ω = -v/r (rolling)");
    /* On the surface: the centre's height over the slope's line less the
     * radius stays within the linear slop (5 mm) and a margin. */
    double gap = rb_dot(rb_v2(sin(theta), cos(theta)), rb_sub(rb_body_position(world, ball), rb_v2(-1.0, 0.0))) - 0.1;
    expect_near(gap, 0.0, 0.008, "height over the slope");
    rb_world_destroy(single);
    destroy_world_and_expect_no_leak(world);
}

/* A frictionless 0.2 m box sliding at 3 m/s along a flat floor of 10 cm
 * segments, for 2 s: 60 joints. The box is sunk 4 mm into the floor,
 * within the 5 mm slop that the position pass leaves alone, as a box
 * that landed hard or carries a load rests. With nothing to slow it the
 * box keeps its speed, does not hop and does not turn. On plain segments
 * (no ghosts) the same box meets each joint's end as a wall 4 mm high:
 * it catches and loses most of its speed. */
static rb_body_id slide_box(rb_world *world, bool plain_segments)
{
    add_chain_ground(world, -1.0, 20.0, 0.0, 210, plain_segments, 0.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.05, 0.1), 0.0);
    rb_polygon shape = make_box(0.1, 0.1);
    rb_shape_def def = rb_default_shape_def();
    def.friction = 0.0;
    rb_shape_id id;
    cr_assert_eq(rb_shape_create_polygon(world, box, &def, &shape, &id), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 30); /* settle */
    cr_assert_eq(rb_body_set_transform(world, box, rb_v2(0.05, 0.096), 0.0), RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_body_set_linear_velocity(world, box, rb_v2(3.0, 0.0)), RB_OK, "%s", rb_last_error());
    return box;
}

Test(segments, a_box_slides_across_chain_joints_without_catching)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id box = slide_box(world, false);
    double x0 = rb_body_position(world, box).x;
    double worst_vy = 0.0;
    double worst_angle = 0.0;
    for (int i = 0; i < 120; ++i) {
        step_world(world, TEST_DT, 1);
        worst_vy = fmax(worst_vy, fabs(rb_body_linear_velocity(world, box).y));
        worst_angle = fmax(worst_angle, fabs(rb_body_angle(world, box)));
    }
    expect_near(rb_body_linear_velocity(world, box).x, 3.0, 1e-6, "speed after 60 joints");
    expect_near(rb_body_position(world, box).x - x0, 6.0, 1e-3, "distance in 2 s");
    cr_expect(worst_vy < 0.01, "the box hopped: |vy| reached %g m/s", worst_vy);
    cr_expect(worst_angle < 1e-3, "the box turned by %g rad", worst_angle);
    destroy_world_and_expect_no_leak(world);
}

Test(segments, plain_segments_catch_the_same_box)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    rb_body_id box = slide_box(world, true);
    step_world(world, TEST_DT, 120);
    double vx = rb_body_linear_velocity(world, box).x;
    cr_expect(vx < 1.5, "on plain segments the box should catch, kept %g m/s of 3", vx);
    destroy_world_and_expect_no_leak(world);
}
