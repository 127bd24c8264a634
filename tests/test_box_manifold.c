/* SPDX-License-Identifier: MIT */
/* The box path of the narrow phase (engine/src/box_manifold.c) against
 * the general polygon path it stands in for (rb_collide_convex_polygons
 * in engine/src/manifold.c).
 *
 * The claim checked is the strongest there is: on every pose the two
 * paths give the same manifold to the bit (normal, points, separations,
 * feature ids, which shape holds the reference face), compared with
 * memcmp on each double, so not even the sign of a zero may differ. The
 * independent truth is the general path, which searches every edge
 * against every vertex; the box path takes one corner per edge. The poses
 * are many thousands of random ones and the cases where a shortcut
 * would most likely slip: shapes exactly touching, one deep inside the
 * other, faces exactly parallel (equal boxes stacked: the side planes cut
 * at round-off), turned by exact quarter turns (rotation (0, 1): normals
 * with exact zeros, ties between axes), nearly parallel, and beyond the
 * speculative distance. Counters check that every kind of outcome (two
 * points, one, none, the reference face on either shape) occurred, so the
 * comparison cannot pass by comparing empty manifolds.
 */
#include <criterion/criterion.h>
#include <stdint.h>
#include <string.h>

#include "manifold_internal.h"
#include "test_support.h"
#include "world_internal.h"

/* splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom
 * number generators", 2014): a fixed seed gives the same poses on every
 * run. */
static uint64_t next_random(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi). */
static double uniform(uint64_t *state, double lo, double hi)
{
    return lo + (hi - lo) * (double)(next_random(state) >> 11) * 0x1.0p-53;
}

static int pick(uint64_t *state, int n) { return (int)(next_random(state) % (uint64_t)n); }

static bool same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static bool same_vec_bits(rb_vec2 a, rb_vec2 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }

/* What kinds of manifold the comparisons met. */
typedef struct coverage {
    int compared, empty, one_point, two_points, reference_on_b;
} coverage;

/* The two manifolds are equal to the bit; the case is described by `what`
 * and `index` when they are not. */
static void expect_same_manifold(const rb_manifold *fast, const rb_manifold *general, const char *what, int index,
                                 coverage *seen)
{
    cr_assert_eq(fast->point_count, general->point_count, "%s %d: the box path has %d points, the general path %d",
                 what, index, fast->point_count, general->point_count);
    seen->compared += 1;
    seen->empty += general->point_count == 0;
    seen->one_point += general->point_count == 1;
    seen->two_points += general->point_count == 2;
    if (general->point_count == 0) {
        return;
    }
    seen->reference_on_b += general->reference_on_b;
    cr_assert_eq(fast->reference_on_b, general->reference_on_b, "%s %d: the reference face is on different shapes",
                 what, index);
    cr_assert(same_vec_bits(fast->normal, general->normal),
              "%s %d: normal (%.17g, %.17g) on the box path, (%.17g, %.17g) on the general path", what, index,
              fast->normal.x, fast->normal.y, general->normal.x, general->normal.y);
    for (int i = 0; i < general->point_count; ++i) {
        const rb_manifold_point *p = &fast->points[i];
        const rb_manifold_point *q = &general->points[i];
        cr_assert(same_vec_bits(p->point, q->point) && same_bits(p->separation, q->separation) && p->id == q->id,
                  "%s %d, point %d: (%.17g, %.17g), separation %.17g, id 0x%x on the box path; (%.17g, %.17g), %.17g, "
                  "0x%x on the general path",
                  what, index, i, p->point.x, p->point.y, p->separation, p->id, q->point.x, q->point.y, q->separation,
                  q->id);
        cr_assert(p->normal_impulse == 0.0 && p->tangent_impulse == 0.0, "%s %d: a fresh point carries an impulse",
                  what, index);
    }
}

static rb_polygon box(double hx, double hy)
{
    rb_polygon p;
    cr_assert_eq(rb_make_box(hx, hy, &p), RB_OK, "rb_make_box(%g, %g): %s", hx, hy, rb_last_error());
    return p;
}

/* A box as a world's shape holds it: rb_shape_create_polygon recomputes
 * the normals from the edges, and for some widths 1/w·w rounds below 1, so
 * the normals are not exactly unit. */
static rb_polygon box_from_corners(rb_vec2 lower, rb_vec2 upper)
{
    const rb_vec2 corners[4] = {lower, {upper.x, lower.y}, upper, {lower.x, upper.y}};
    rb_polygon p;
    cr_assert_eq(rb_make_polygon(corners, 4, &p), RB_OK, "rb_make_polygon: %s", rb_last_error());
    return p;
}

/* Shape A: a box of one of the kinds the box path takes. */
static rb_polygon random_box(uint64_t *rng)
{
    double hx = uniform(rng, 0.05, 3.0);
    double hy = uniform(rng, 0.05, 3.0);
    switch (pick(rng, 3)) {
    case 0:
        return box(hx, hy);
    case 1: {
        rb_polygon p;
        rb_vec2 center = {uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0)};
        cr_assert_eq(rb_make_offset_box(hx, hy, center, 0.0, &p), RB_OK, "%s", rb_last_error());
        return p;
    }
    default: {
        rb_vec2 lower = {uniform(rng, -3.0, 0.0), uniform(rng, -3.0, 0.0)};
        return box_from_corners(lower, rb_v2(lower.x + 2.0 * hx, lower.y + 2.0 * hy));
    }
    }
}

/* Shape B: a box, a box turned in its own frame, or a convex polygon of 3
 * to 8 vertices. */
static rb_polygon random_polygon(uint64_t *rng)
{
    int kind = pick(rng, 3);
    if (kind == 0) {
        return random_box(rng);
    }
    rb_polygon p;
    if (kind == 1) {
        rb_vec2 center = {uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5)};
        cr_assert_eq(rb_make_offset_box(uniform(rng, 0.05, 2.0), uniform(rng, 0.05, 2.0), center,
                                        uniform(rng, -RB_PI, RB_PI), &p),
                     RB_OK, "%s", rb_last_error());
        return p;
    }
    for (;;) {
        rb_vec2 points[RB_MAX_POLYGON_VERTICES];
        int count = 3 + pick(rng, RB_MAX_POLYGON_VERTICES - 2);
        double radius = uniform(rng, 0.1, 2.0);
        for (int i = 0; i < count; ++i) {
            double angle = uniform(rng, -RB_PI, RB_PI);
            points[i] = rb_v2(radius * cos(angle), radius * sin(angle));
        }
        if (rb_make_polygon_hull(points, count, &p) == RB_OK) {
            return p;
        }
    }
}

/* An exact quarter turn: k = 0 .. 3 times 90°, cosine and sine exactly 0
 * or ±1. */
static rb_rot quarter_turn(int k)
{
    static const rb_rot turns[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    return turns[k & 3];
}

/* B's pose against A's: a turn of one of the kinds above, and B's origin
 * within a few sizes of A's. */
static rb_transform random_pose_of_b(uint64_t *rng, rb_transform xfa)
{
    rb_transform xfb;
    switch (pick(rng, 4)) {
    case 0:
        xfb.q = rb_rot_from_angle(uniform(rng, -RB_PI, RB_PI));
        break;
    case 1:
        xfb.q = xfa.q; /* faces exactly parallel */
        break;
    case 2:
        xfb.q = rb_mul_rot(xfa.q, rb_rot_from_angle(uniform(rng, -1e-9, 1e-9))); /* nearly parallel */
        break;
    default:
        xfb.q = rb_mul_rot(xfa.q, quarter_turn(pick(rng, 4)));
        break;
    }
    xfb.p = rb_add(xfa.p, rb_v2(uniform(rng, -4.0, 4.0), uniform(rng, -4.0, 4.0)));
    return xfb;
}

static rb_transform random_pose(uint64_t *rng)
{
    rb_rot q = pick(rng, 3) == 0 ? quarter_turn(pick(rng, 4)) : rb_rot_from_angle(uniform(rng, -RB_PI, RB_PI));
    return (rb_transform){{uniform(rng, -10.0, 10.0), uniform(rng, -10.0, 10.0)}, q};
}

static const double speculative_distances[3] = {0.0, 0.02, 0.5};

Test(box_manifold, matches_the_general_path_on_random_poses)
{
    uint64_t rng = 21;
    coverage seen = {0};
    for (int i = 0; i < 40000; ++i) {
        rb_polygon a = random_box(&rng);
        rb_polygon b = random_polygon(&rng);
        rb_transform xfa = random_pose(&rng);
        rb_transform xfb = random_pose_of_b(&rng, xfa);
        double speculative = speculative_distances[pick(&rng, 3)];
        cr_assert(rb_polygon_is_box(&a), "pose %d: shape A should be a box", i);
        rb_manifold fast = rb_collide_box_and_polygon(&a, xfa, &b, xfb, speculative);
        rb_manifold general = rb_collide_convex_polygons(&a, xfa, &b, xfb, speculative);
        expect_same_manifold(&fast, &general, "random pose", i, &seen);
        rb_manifold dispatched = rb_collide_polygons(&a, xfa, &b, xfb, speculative);
        expect_same_manifold(&dispatched, &general, "rb_collide_polygons, random pose", i, &seen);
    }
    cr_expect(seen.empty > 5000 && seen.one_point > 2000 && seen.two_points > 5000 && seen.reference_on_b > 2000,
              "the random poses should cover every outcome: %d compared, %d empty, %d with one point, %d with two, "
              "%d with the reference face on B",
              seen.compared, seen.empty, seen.one_point, seen.two_points, seen.reference_on_b);
}

/* Boxes B of half-extents (bx, by) on box A of (ax, ay), both turned by
 * `turn` in the world (A) and by `relative` more (B), B's centre at
 * `offset` from A's in A's frame, B turned by `relative`. */
static void compare_posed(rb_polygon a, rb_polygon b, rb_rot turn, rb_rot relative, rb_vec2 offset, double speculative,
                          const char *what, int index, coverage *seen)
{
    rb_transform xfa = {{1.25, -0.75}, turn};
    rb_transform xfb = {rb_transform_point(xfa, offset), rb_mul_rot(turn, relative)};
    rb_manifold fast = rb_collide_box_and_polygon(&a, xfa, &b, xfb, speculative);
    rb_manifold general = rb_collide_convex_polygons(&a, xfa, &b, xfb, speculative);
    expect_same_manifold(&fast, &general, what, index, seen);
}

Test(box_manifold, matches_the_general_path_in_special_poses)
{
    coverage seen = {0};
    const double sizes[][4] = {{0.5, 0.5, 0.5, 0.5},
                               {1.0, 0.25, 0.5, 0.5},
                               {24.5, 0.5, 0.35, 0.35},
                               {0.5, 0.5, 1.5, 0.2},
                               {0.1, 3.0, 0.7, 0.7}};
    int index = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        rb_polygon a = box(sizes[s][0], sizes[s][1]);
        rb_polygon b = box(sizes[s][2], sizes[s][3]);
        rb_polygon a_shape = box_from_corners(rb_v2(-sizes[s][0], -sizes[s][1]), rb_v2(sizes[s][0], sizes[s][1]));
        for (int k = 0; k < 4; ++k) {
            rb_rot turn = quarter_turn(k);
            for (int r = 0; r < 4; ++r) {
                rb_rot relative = quarter_turn(r);
                /* B's half-height along A's y once turned by `relative`. */
                double bh = (r & 1) ? sizes[s][2] : sizes[s][3];
                double top = sizes[s][1] + bh;
                const rb_vec2 offsets[] = {
                    {0.0, top},                     /* exactly touching, face on face */
                    {0.0, top - 0.01},              /* resting, a centimetre deep */
                    {0.0, top + 0.01},              /* a centimetre apart */
                    {0.0, 0.0},                     /* centre on centre */
                    {0.1, 0.2 * sizes[s][1]},       /* deep inside */
                    {sizes[s][0], top},             /* B's centre over A's corner */
                    {sizes[s][0] + 0.3, top - 0.3}, /* corner into the side */
                    {0.0, -top},                    /* underneath */
                    {-sizes[s][0] - bh, 0.0},       /* beside, touching when B is square */
                };
                for (size_t o = 0; o < sizeof offsets / sizeof offsets[0]; ++o) {
                    for (int d = 0; d < 3; ++d) {
                        compare_posed(a, b, turn, relative, offsets[o], speculative_distances[d], "special pose", index,
                                      &seen);
                        compare_posed(a_shape, b, turn, relative, offsets[o], speculative_distances[d],
                                      "special pose, shape's normals", index, &seen);
                        rb_rot tilt = rb_rot_from_angle(1e-12 * (double)(index % 3 - 1));
                        compare_posed(a, b, turn, rb_mul_rot(relative, tilt), offsets[o], speculative_distances[d],
                                      "special pose, tilted 1e-12", index, &seen);
                        ++index;
                    }
                }
            }
        }
    }
    /* A's corner into a face of B turned by 45°: B's face is the reference. */
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        rb_polygon a = box(sizes[s][0], sizes[s][1]);
        rb_polygon b = box(sizes[s][2], sizes[s][3]);
        rb_rot diagonal = rb_rot_from_angle(0.25 * RB_PI);
        for (int k = 0; k < 4; ++k) {
            for (double depth = -0.01; depth <= 0.021; depth += 0.01) {
                /* B's left face, outward normal (-1, -1)/sqrt(2) once turned, at A's upper right corner. */
                rb_vec2 offset = rb_mul_add(rb_v2(sizes[s][0], sizes[s][1]), sizes[s][2] - depth,
                                            rb_rotate(diagonal, rb_v2(1.0, 0.0)));
                for (int d = 0; d < 3; ++d) {
                    compare_posed(a, b, quarter_turn(k), diagonal, offset, speculative_distances[d],
                                  "corner into a turned face", index++, &seen);
                }
            }
        }
    }
    cr_expect(seen.empty > 0 && seen.one_point > 0 && seen.two_points > 0 && seen.reference_on_b > 0,
              "the special poses should cover every outcome: %d compared, %d empty, %d with one point, %d with two, "
              "%d with the reference face on B",
              seen.compared, seen.empty, seen.one_point, seen.two_points, seen.reference_on_b);
}

Test(box_manifold, equal_boxes_stacked_exactly_give_two_points_at_the_corners)
{
    /* A hand check besides the comparison: unit boxes, B exactly on A. */
    rb_polygon a = box(0.5, 0.5);
    rb_transform xfa = rb_transform_identity();
    rb_transform xfb = {{0.0, 1.0}, {1.0, 0.0}};
    rb_manifold m = rb_collide_box_and_polygon(&a, xfa, &a, xfb, 0.0);
    cr_assert_eq(m.point_count, 2, "exactly touching boxes should have 2 points, got %d", m.point_count);
    expect_vec_near(m.normal, rb_v2(0.0, 1.0), 0.0, "normal");
    for (int i = 0; i < 2; ++i) {
        expect_near(fabs(m.points[i].point.x), 0.5, 0.0, "point x");
        expect_near(m.points[i].point.y, 0.5, 0.0, "point y");
        expect_near(m.points[i].separation, 0.0, 0.0, "separation");
    }
}

Test(box_manifold, recognises_boxes_and_only_boxes)
{
    cr_expect(rb_polygon_is_box(&(rb_polygon){0}) == false, "an empty polygon is not a box");
    rb_polygon p = box(0.5, 2.0);
    cr_expect(rb_polygon_is_box(&p), "rb_make_box makes a box");
    p = box(24.5, 0.5);
    cr_expect(rb_polygon_is_box(&p), "a box whose normals are not exactly unit is still a box");
    cr_assert_eq(rb_make_offset_box(0.5, 0.25, rb_v2(3.0, -1.0), 0.0, &p), RB_OK);
    cr_expect(rb_polygon_is_box(&p), "an offset box at angle 0 is a box");
    cr_assert_eq(rb_make_offset_box(0.5, 0.25, rb_v2(3.0, -1.0), 0.3, &p), RB_OK);
    cr_expect(!rb_polygon_is_box(&p), "a box turned in its body frame takes the general path");
    const rb_vec2 trapezoid[4] = {{-1.0, 0.0}, {1.0, 0.0}, {0.5, 1.0}, {-0.5, 1.0}};
    cr_assert_eq(rb_make_polygon(trapezoid, 4, &p), RB_OK);
    cr_expect(!rb_polygon_is_box(&p), "a trapezoid is not a box");
    const rb_vec2 triangle[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
    cr_assert_eq(rb_make_polygon(triangle, 3, &p), RB_OK);
    cr_expect(!rb_polygon_is_box(&p), "a triangle is not a box");
}

/* A world's narrow phase takes the box path for shape A by the flag the
 * shape was made with (world_internal.h: rb_shape.box), not by testing
 * A's vertices for every pair: the flag must say what rb_polygon_is_box
 * says of the shape's polygon, for every kind of shape a body can have. */
Test(box_manifold, a_shape_is_made_knowing_whether_it_is_a_box)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    rb_polygon polygons[4];
    cr_assert_eq(rb_make_box(0.5, 2.0, &polygons[0]), RB_OK);
    cr_assert_eq(rb_make_offset_box(0.5, 0.25, rb_v2(3.0, -1.0), 0.0, &polygons[1]), RB_OK);
    cr_assert_eq(rb_make_offset_box(0.5, 0.25, rb_v2(3.0, -1.0), 0.3, &polygons[2]), RB_OK);
    const rb_vec2 trapezoid[4] = {{-1.0, 0.0}, {1.0, 0.0}, {0.5, 1.0}, {-0.5, 1.0}};
    cr_assert_eq(rb_make_polygon(trapezoid, 4, &polygons[3]), RB_OK);
    const bool boxes[4] = {true, true, false, false};
    rb_shape_def def = rb_default_shape_def();
    for (int i = 0; i < 4; ++i) {
        rb_shape_id id;
        cr_assert_eq(rb_shape_create_polygon(world, body, &def, &polygons[i], &id), RB_OK, "%s", rb_last_error());
        cr_expect_eq(world->shapes[id.index].box, boxes[i], "polygon %d: box flag %d, expected %d", i,
                     world->shapes[id.index].box, boxes[i]);
    }
    rb_shape_id circle = add_circle(world, body, rb_v2(0.0, 0.0), 0.5, 1.0);
    cr_expect(!world->shapes[circle.index].box, "a circle is not a box");
    destroy_world_and_expect_no_leak(world);
}
