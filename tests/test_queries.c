/* SPDX-License-Identifier: MIT */
/* Ray casts and world queries (rb/geometry.h, rb/query.h): single-shape
 * ray casts against analytic intersections, closest and all hits in
 * order, filters and sensors, point queries picking the bones of the arm
 * model, and box overlaps.
 *
 * Tolerance: intersections of order 1 found in a few dozen operations
 * (one square root for circles): 1e-12.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "mu/model.h"
#include "rb/rb.h"
#include "test_support.h"

#define TOLERANCE 1e-12

static rb_transform pose(double x, double y, double angle) { return (rb_transform){{x, y}, rb_rot_from_angle(angle)}; }

static void expect_hit(rb_ray_cast_output out, double fraction, rb_vec2 point, rb_vec2 normal, const char *what)
{
    cr_assert(out.hit, "%s: expected a hit", what);
    expect_near(out.fraction, fraction, TOLERANCE, what);
    expect_vec_near(out.point, point, TOLERANCE, what);
    expect_vec_near(out.normal, normal, TOLERANCE, what);
}

/* ---- single shapes --------------------------------------------------------- */

/* Circle of radius 0.5 at (1, 2). A ray along y = 2 from x = -1 enters at
 * x = 0.5: fraction 1.5/4. Along y = 2.3 it enters where
 * (x - 1)² = 0.25 - 0.09, x = 0.6: fraction 1.6/4, normal (-0.4, 0.3)/0.5.
 * A circle of radius 1 at (3, 4) seen from the origin along (0.6, 0.8):
 * entry 4 m out of 10, at (2.4, 3.2), normal -(0.6, 0.8). The circle is
 * placed by a transform: centre offset (0.5, 0) on a body at (0.5, 2). */
Test(ray_cast, circle)
{
    rb_circle circle = {{0.5, 0.0}, 0.5};
    rb_transform xf = pose(0.5, 2.0, 0.0);
    expect_hit(rb_ray_cast_circle(&circle, xf, rb_v2(-1.0, 2.0), rb_v2(4.0, 0.0)), 0.375, rb_v2(0.5, 2.0),
               rb_v2(-1.0, 0.0), "through the centre");
    expect_hit(rb_ray_cast_circle(&circle, xf, rb_v2(-1.0, 2.3), rb_v2(4.0, 0.0)), 0.4, rb_v2(0.6, 2.3),
               rb_v2(-0.8, 0.6), "off centre");
    rb_circle far = {{0.0, 0.0}, 1.0};
    expect_hit(rb_ray_cast_circle(&far, pose(3.0, 4.0, 1.0), rb_v2(0.0, 0.0), rb_v2(6.0, 8.0)), 0.4, rb_v2(2.4, 3.2),
               rb_v2(-0.6, -0.8), "diagonal");
}

/* A 2 × 1 box turned by 30° at (2, 1). In its frame a ray from
 * (-3, 0.2) with translation (4, 0.4) meets the face x = -1 after 2 m
 * along x, at (-1, 0.4) (inside -0.5 .. 0.5): fraction 0.5, normal the
 * box's -x axis. The world ray is the same ray carried by the pose. */
Test(ray_cast, rotated_box)
{
    rb_polygon box;
    cr_assert_eq(rb_make_box(1.0, 0.5, &box), RB_OK);
    rb_transform xf = pose(2.0, 1.0, RB_PI / 6.0);
    rb_vec2 origin = rb_transform_point(xf, rb_v2(-3.0, 0.2));
    rb_vec2 translation = rb_rotate(xf.q, rb_v2(4.0, 0.4));
    expect_hit(rb_ray_cast_polygon(&box, xf, origin, translation), 0.5, rb_transform_point(xf, rb_v2(-1.0, 0.4)),
               rb_rotate(xf.q, rb_v2(-1.0, 0.0)), "rotated box");
    /* The same ray 1 m higher in the box frame passes over it. */
    rb_vec2 above = rb_transform_point(xf, rb_v2(-3.0, 1.2));
    cr_expect(!rb_ray_cast_polygon(&box, xf, above, translation).hit, "over the box");
}

/* Segment from (0, 0) to (2, 2); a ray from (0, 2) to (2, 0) crosses it at
 * (1, 1), half way; the normal faces the ray's side: (-1, 1)/√2 from the
 * upper left, (1, -1)/√2 from the lower right. As a chain segment (front
 * on the left, the upper left here) only the first ray hits. */
Test(ray_cast, segment_from_either_side_and_chain_from_the_front)
{
    rb_segment segment = {{0.0, 0.0}, {2.0, 2.0}};
    double h = 1.0 / sqrt(2.0);
    expect_hit(rb_ray_cast_segment(&segment, rb_transform_identity(), rb_v2(0.0, 2.0), rb_v2(2.0, -2.0)), 0.5,
               rb_v2(1.0, 1.0), rb_v2(-h, h), "from the upper left");
    expect_hit(rb_ray_cast_segment(&segment, rb_transform_identity(), rb_v2(2.0, 0.0), rb_v2(-2.0, 2.0)), 0.5,
               rb_v2(1.0, 1.0), rb_v2(h, -h), "from the lower right");
    rb_chain_segment chain = {.segment = segment};
    expect_hit(rb_ray_cast_chain_segment(&chain, rb_transform_identity(), rb_v2(0.0, 2.0), rb_v2(2.0, -2.0)), 0.5,
               rb_v2(1.0, 1.0), rb_v2(-h, h), "chain from the front");
    cr_expect(!rb_ray_cast_chain_segment(&chain, rb_transform_identity(), rb_v2(2.0, 0.0), rb_v2(-2.0, 2.0)).hit,
              "chain from behind");
}

Test(ray_cast, misses)
{
    rb_circle circle = {{0.0, 0.0}, 0.5};
    rb_polygon box;
    cr_assert_eq(rb_make_box(0.5, 0.5, &box), RB_OK);
    rb_segment segment = {{-1.0, 0.0}, {1.0, 0.0}};
    rb_transform at = rb_transform_identity();
    cr_expect(!rb_ray_cast_circle(&circle, at, rb_v2(-2.0, 0.6), rb_v2(4.0, 0.0)).hit, "circle: passes above");
    cr_expect(!rb_ray_cast_circle(&circle, at, rb_v2(-2.0, 0.0), rb_v2(1.4, 0.0)).hit, "circle: stops short");
    cr_expect(!rb_ray_cast_circle(&circle, at, rb_v2(2.0, 0.0), rb_v2(4.0, 0.0)).hit, "circle: points away");
    cr_expect(!rb_ray_cast_circle(&circle, at, rb_v2(-2.0, 0.0), rb_v2(0.0, 0.0)).hit, "circle: zero ray");
    cr_expect(!rb_ray_cast_polygon(&box, at, rb_v2(-2.0, 0.6), rb_v2(4.0, 0.0)).hit, "box: passes above");
    cr_expect(!rb_ray_cast_polygon(&box, at, rb_v2(-2.0, 0.0), rb_v2(1.4, 0.0)).hit, "box: stops short");
    cr_expect(!rb_ray_cast_segment(&segment, at, rb_v2(-2.0, 0.0), rb_v2(4.0, 0.0)).hit, "segment: along it");
    cr_expect(!rb_ray_cast_segment(&segment, at, rb_v2(1.5, 1.0), rb_v2(0.0, -2.0)).hit, "segment: beyond its end");
}

/* A ray that starts inside a shape never enters it, so it does not hit
 * it; from inside one circle it still hits the next. */
Test(ray_cast, start_inside)
{
    rb_circle circle = {{0.0, 0.0}, 0.5};
    rb_polygon box;
    cr_assert_eq(rb_make_box(0.5, 0.5, &box), RB_OK);
    cr_expect(!rb_ray_cast_circle(&circle, rb_transform_identity(), rb_v2(0.1, 0.0), rb_v2(4.0, 0.0)).hit);
    cr_expect(!rb_ray_cast_polygon(&box, rb_transform_identity(), rb_v2(0.1, 0.0), rb_v2(4.0, 0.0)).hit);
    expect_hit(rb_ray_cast_circle(&circle, pose(2.0, 0.0, 0.0), rb_v2(0.1, 0.0), rb_v2(4.0, 0.0)), 1.4 / 4.0,
               rb_v2(1.5, 0.0), rb_v2(-1.0, 0.0), "the next circle");
}

/* ---- world ray casts -------------------------------------------------------- */

typedef struct row_scene {
    rb_world *world;
    rb_shape_id circles[3]; /* radius 0.5 at x = 2, 4, 6 on y = 0 */
    rb_shape_id box;        /* 1 × 1 at x = 8 */
    rb_shape_id sensor;     /* sensor circle of radius 0.25 at x = 3 */
    rb_shape_id hidden;     /* category 2 circle of radius 0.25 at x = 5 */
} row_scene;

static row_scene make_row(void)
{
    row_scene s;
    s.world = make_world(rb_v2(0.0, 0.0));
    for (int i = 0; i < 3; ++i) {
        rb_body_id body = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(2.0 + 2.0 * i, 0.0), 0.0);
        s.circles[i] = add_circle(s.world, body, rb_v2(0.0, 0.0), 0.5, 1.0);
    }
    rb_body_id box_body = make_body(s.world, RB_BODY_STATIC, rb_v2(8.0, 0.0), 0.3);
    s.box = add_box(s.world, box_body, 0.5, 0.5, 1.0);
    rb_body_id sensor_body = make_body(s.world, RB_BODY_STATIC, rb_v2(3.0, 0.0), 0.0);
    rb_shape_def def = rb_default_shape_def();
    def.is_sensor = true;
    rb_circle small = {{0.0, 0.0}, 0.25};
    cr_assert_eq(rb_shape_create_circle(s.world, sensor_body, &def, &small, &s.sensor), RB_OK);
    rb_body_id hidden_body = make_body(s.world, RB_BODY_STATIC, rb_v2(5.0, 0.0), 0.0);
    def = rb_default_shape_def();
    def.filter.category_bits = 2;
    cr_assert_eq(rb_shape_create_circle(s.world, hidden_body, &def, &small, &s.hidden), RB_OK);
    return s;
}

/* Along y = 0 from the origin over 10 m: the circles are entered at
 * x = 1.5, 3.5, 5.5, the sensor at 2.75, the category-2 circle at 4.75,
 * the box (turned, so its entry is computed by the single-shape cast).
 * The query's mask leaves out category 2, and sensors are left out. */
Test(world_ray_cast, closest_and_all_in_order)
{
    row_scene s = make_row();
    rb_query_filter filter = {.category_bits = 1, .mask_bits = ~2u};
    rb_ray_hit hit;
    bool found = false;
    cr_assert_eq(rb_world_ray_cast_closest(s.world, rb_v2(0.0, 0.0), rb_v2(10.0, 0.0), filter, false, &hit, &found),
                 RB_OK, "%s", rb_last_error());
    cr_assert(found);
    cr_expect(rb_shape_id_equals(hit.shape, s.circles[0]));
    cr_expect(rb_body_id_equals(hit.body, rb_shape_body(s.world, s.circles[0])));
    expect_near(hit.fraction, 0.15, TOLERANCE, "closest fraction");
    expect_vec_near(hit.point, rb_v2(1.5, 0.0), TOLERANCE, "closest point");
    expect_vec_near(hit.normal, rb_v2(-1.0, 0.0), TOLERANCE, "closest normal");

    rb_ray_hit hits[8];
    int count = -1;
    cr_assert_eq(rb_world_ray_cast_all(s.world, rb_v2(0.0, 0.0), rb_v2(10.0, 0.0), filter, false, hits, 8, &count),
                 RB_OK, "%s", rb_last_error());
    cr_assert_eq(count, 4, "three circles and the box, no sensor, no category 2: got %d", count);
    rb_polygon box = rb_shape_polygon(s.world, s.box);
    rb_ray_cast_output box_entry = rb_ray_cast_polygon(&box, rb_body_transform(s.world, rb_shape_body(s.world, s.box)),
                                                       rb_v2(0.0, 0.0), rb_v2(10.0, 0.0));
    const double expected[4] = {0.15, 0.35, 0.55, box_entry.fraction};
    const rb_shape_id shapes[4] = {s.circles[0], s.circles[1], s.circles[2], s.box};
    for (int i = 0; i < 4; ++i) {
        cr_expect(rb_shape_id_equals(hits[i].shape, shapes[i]), "hit %d is shape %d", i, hits[i].shape.index);
        expect_near(hits[i].fraction, expected[i], TOLERANCE, "fraction");
    }

    /* With room for two, the two nearest, and the count of all. */
    cr_assert_eq(rb_world_ray_cast_all(s.world, rb_v2(0.0, 0.0), rb_v2(10.0, 0.0), filter, false, hits, 2, &count),
                 RB_OK);
    cr_expect_eq(count, 4);
    cr_expect(rb_shape_id_equals(hits[0].shape, s.circles[0]) && rb_shape_id_equals(hits[1].shape, s.circles[1]));
    rb_world_destroy(s.world);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

Test(world_ray_cast, filters_and_sensors)
{
    row_scene s = make_row();
    rb_ray_hit hits[8];
    int count = 0;
    rb_query_filter all = rb_default_query_filter();
    cr_assert_eq(rb_world_ray_cast_all(s.world, rb_v2(0.0, 0.0), rb_v2(10.0, 0.0), all, true, hits, 8, &count), RB_OK);
    cr_assert_eq(count, 6, "everything, with the sensor: %d", count);
    cr_expect(rb_shape_id_equals(hits[1].shape, s.sensor), "the sensor second, entered at x = 2.75");
    cr_expect(rb_shape_id_equals(hits[3].shape, s.hidden), "category 2 fourth, entered at x = 4.75");
    expect_near(hits[1].fraction, 0.275, TOLERANCE, "sensor fraction");

    rb_query_filter second = {.category_bits = 1, .mask_bits = 2};
    cr_assert_eq(rb_world_ray_cast_all(s.world, rb_v2(0.0, 0.0), rb_v2(10.0, 0.0), second, true, hits, 8, &count),
                 RB_OK);
    cr_assert_eq(count, 1, "only category 2: %d", count);
    cr_expect(rb_shape_id_equals(hits[0].shape, s.hidden));
    expect_near(hits[0].fraction, 0.475, TOLERANCE, "category 2 fraction");

    /* A query of category 4 is refused by shapes whose mask lacks it. */
    cr_assert_eq(rb_shape_set_filter(s.world, s.circles[0], (rb_filter){1, ~4u, 0}), RB_OK);
    rb_query_filter fourth = {.category_bits = 4, .mask_bits = 0xffffffffu};
    rb_ray_hit hit;
    bool found = false;
    cr_assert_eq(rb_world_ray_cast_closest(s.world, rb_v2(0.0, 0.0), rb_v2(10.0, 0.0), fourth, false, &hit, &found),
                 RB_OK);
    cr_expect(found && rb_shape_id_equals(hit.shape, s.circles[1]), "the first circle refuses category 4");

    cr_assert_eq(rb_world_ray_cast_closest(s.world, rb_v2(0.0, 3.0), rb_v2(10.0, 0.0), all, true, &hit, &found), RB_OK);
    cr_expect(!found, "nothing at y = 3");
    rb_world_destroy(s.world);
}

/* Two equal circles in the same place: the tie goes to the lower index,
 * and the order of the others does not depend on the run. */
Test(world_ray_cast, ties_go_to_the_lower_shape_index)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id b1 = make_body(world, RB_BODY_STATIC, rb_v2(2.0, 0.0), 0.0);
    rb_body_id b2 = make_body(world, RB_BODY_STATIC, rb_v2(2.0, 0.0), 0.0);
    rb_shape_id first = add_circle(world, b1, rb_v2(0.0, 0.0), 0.5, 1.0);
    rb_shape_id second = add_circle(world, b2, rb_v2(0.0, 0.0), 0.5, 1.0);
    rb_ray_hit hits[2];
    int count = 0;
    cr_assert_eq(rb_world_ray_cast_all(world, rb_v2(0.0, 0.0), rb_v2(4.0, 0.0), rb_default_query_filter(), false, hits,
                                       2, &count),
                 RB_OK);
    cr_assert_eq(count, 2);
    cr_expect(rb_shape_id_equals(hits[0].shape, first) && rb_shape_id_equals(hits[1].shape, second));
    destroy_world_and_expect_no_leak(world);
}

/* ---- point queries: picking the arm's bones ------------------------------ */

/* The arm model's bones are sensor boxes. A point query at each bone's
 * centre (from the model, not the engine) with sensors included finds a
 * shape whose box is centred there; without sensors it finds no bone. */
Test(point_query, picks_each_bone_of_the_arm)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    mu_model *model = NULL;
    mu_model_options options = mu_default_model_options();
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    for (int i = 0; i < 60; ++i) {
        cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    }
    rb_world *world = mu_model_world(model);
    int bones = 0;
    for (int part = 0; part < mu_model_part_count(model); ++part) {
        rb_vec2 centre = mu_model_part_centre(model, part);
        rb_shape_id found[16];
        int count = 0;
        cr_assert_eq(rb_world_overlap_point(world, centre, rb_default_query_filter(), true, found, 16, &count), RB_OK,
                     "%s", rb_last_error());
        cr_assert(count >= 1 && count <= 16, "%s: %d shapes", mu_model_part_name(model, part), count);
        int centred = -1;
        for (int k = 0; k < count; ++k) {
            rb_polygon box = rb_shape_polygon(world, found[k]);
            rb_body_id body = rb_shape_body(world, found[k]);
            if (rb_shape_type_of(world, found[k]) == RB_SHAPE_POLYGON &&
                rb_distance(rb_body_world_point(world, body, box.centroid), centre) < 1e-9) {
                centred = k;
            }
        }
        cr_expect(centred >= 0, "%s: no shape centred on the part", mu_model_part_name(model, part));
        if (centred >= 0 && rb_shape_is_sensor(world, found[centred])) {
            ++bones;
            int without = 0;
            rb_shape_id others[16];
            cr_assert_eq(rb_world_overlap_point(world, centre, rb_default_query_filter(), false, others, 16, &without),
                         RB_OK);
            for (int k = 0; k < without; ++k) {
                cr_expect(!rb_shape_is_sensor(world, others[k]), "a sensor found without sensors");
            }
        }
    }
    cr_expect_eq(bones, 10, "the arm has 10 bones, picked %d", bones);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    cr_expect_eq(rb_bytes_in_use(), 0);
}

/* Points on the boundary count; a point just outside does not; a
 * segment never contains a point. The callback form sees the same
 * shapes and can stop early. */
static bool count_and_stop(rb_shape_id shape, void *context)
{
    (void)shape;
    int *seen = context;
    ++*seen;
    return false;
}

Test(point_query, boundaries_segments_and_callbacks)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_id body = make_body(world, RB_BODY_STATIC, rb_v2(1.0, 1.0), RB_PI / 4.0);
    add_box(world, body, 0.5, 0.5, 1.0);
    rb_body_id other = make_body(world, RB_BODY_STATIC, rb_v2(1.0, 1.0), 0.0);
    add_circle(world, other, rb_v2(0.0, 0.0), 0.2, 1.0);
    rb_segment segment = {{0.0, 1.0}, {2.0, 1.0}};
    rb_shape_id line;
    rb_shape_def def = rb_default_shape_def();
    cr_assert_eq(rb_shape_create_segment(world, other, &def, &segment, &line), RB_OK);
    rb_query_filter filter = rb_default_query_filter();
    rb_shape_id out[4];
    int count = 0;
    /* The turned box's corner is at (1, 1 + √2/2); a hair above is outside. */
    double corner = 1.0 + sqrt(0.5);
    cr_assert_eq(rb_world_overlap_point(world, rb_v2(1.0, corner - 1e-9), filter, false, out, 4, &count), RB_OK);
    cr_expect_eq(count, 1, "just inside the corner");
    cr_assert_eq(rb_world_overlap_point(world, rb_v2(1.0, corner + 1e-9), filter, false, out, 4, &count), RB_OK);
    cr_expect_eq(count, 0, "just outside the corner");
    cr_assert_eq(rb_world_overlap_point(world, rb_v2(1.1, 1.0), filter, false, out, 4, &count), RB_OK);
    cr_expect_eq(count, 2, "box and circle, never the segment through the point");
    int seen = 0;
    cr_assert_eq(rb_world_query_point(world, rb_v2(1.1, 1.0), filter, false, count_and_stop, &seen), RB_OK);
    cr_expect_eq(seen, 1, "the callback stopped the query");
    destroy_world_and_expect_no_leak(world);
}

/* ---- box overlaps -------------------------------------------------------- */

/* Circles of radius 0.1 on the integer grid 0..4 × 0..4 (shape index
 * 5·y + x). The box (0.95, 0.95)-(2.05, 1.5) overlaps the circle boxes
 * [x-0.1, x+0.1] × [y-0.1, y+0.1] exactly for (1, 1) and (2, 1). After one
 * body is moved (without a step) the query sees it where it is now. */
Test(aabb_query, finds_the_boxes_that_overlap)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_shape_id grid[25];
    rb_body_id bodies[25];
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 5; ++x) {
            bodies[5 * y + x] = make_body(world, RB_BODY_DYNAMIC, rb_v2(x, y), 0.0);
            grid[5 * y + x] = add_circle(world, bodies[5 * y + x], rb_v2(0.0, 0.0), 0.1, 1.0);
        }
    }
    rb_aabb box = {{0.95, 0.95}, {2.05, 1.5}};
    rb_query_filter filter = rb_default_query_filter();
    rb_shape_id out[25];
    int count = 0;
    cr_assert_eq(rb_world_overlap_aabb(world, box, filter, false, out, 25, &count), RB_OK, "%s", rb_last_error());
    cr_assert_eq(count, 2);
    cr_expect(rb_shape_id_equals(out[0], grid[6]) && rb_shape_id_equals(out[1], grid[7]));

    cr_assert_eq(rb_body_set_transform(world, bodies[24], rb_v2(1.5, 1.2), 0.0), RB_OK);
    cr_assert_eq(rb_world_overlap_aabb(world, box, filter, false, out, 25, &count), RB_OK);
    cr_assert_eq(count, 3, "the moved circle is found where it is now");
    cr_expect(rb_shape_id_equals(out[2], grid[24]), "in shape index order");

    cr_assert_eq(rb_world_overlap_aabb(world, box, filter, false, out, 1, &count), RB_OK);
    cr_expect_eq(count, 3, "the count says how many there are beyond the capacity");
    int seen = 0;
    cr_assert_eq(rb_world_query_aabb(world, box, filter, false, count_and_stop, &seen), RB_OK);
    cr_expect_eq(seen, 1);
    destroy_world_and_expect_no_leak(world);
}

Test(aabb_query, bad_arguments)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_query_filter filter = rb_default_query_filter();
    rb_shape_id out[2];
    int count = 0;
    rb_aabb inverted = {{1.0, 0.0}, {0.0, 1.0}};
    cr_expect_eq(rb_world_overlap_aabb(world, inverted, filter, false, out, 2, &count), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "rb_world_overlap_aabb") != NULL, "%s", rb_last_error());
    rb_aabb box = {{0.0, 0.0}, {1.0, 1.0}};
    cr_expect_eq(rb_world_overlap_aabb(NULL, box, filter, false, out, 2, &count), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(rb_world_overlap_aabb(world, box, filter, false, NULL, 2, &count), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(rb_world_overlap_aabb(world, box, filter, false, out, -1, &count), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(rb_world_overlap_aabb(world, box, filter, false, NULL, 0, &count), RB_OK);
    cr_expect_eq(rb_world_query_aabb(world, box, filter, false, NULL, NULL), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(rb_world_overlap_point(world, rb_v2(NAN, 0.0), filter, false, out, 2, &count),
                 RB_ERR_INVALID_ARGUMENT);
    rb_ray_hit hit;
    bool found;
    cr_expect_eq(rb_world_ray_cast_closest(world, rb_v2(0.0, 0.0), rb_v2(INFINITY, 0.0), filter, false, &hit, &found),
                 RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(rb_world_ray_cast_all(world, rb_v2(0.0, 0.0), rb_v2(1.0, 0.0), filter, false, NULL, 1, &count),
                 RB_ERR_INVALID_ARGUMENT);
    destroy_world_and_expect_no_leak(world);
}
