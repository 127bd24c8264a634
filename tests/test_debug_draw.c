/* SPDX-License-Identifier: MIT */
/* Debug drawing: with callbacks that record what they are given, a world of
 * a static ground, one box and one circle resting on it draws exactly the
 * shapes, contact points, normals, impulses and bounding boxes asked for,
 * and nothing else. */
#include <math.h>

#include "constraint_colouring.h"
#include "scenes/scenes.h"
#include "test_support.h"

#define RECORD_CAPACITY 16

typedef struct polygon_record {
    rb_vec2 vertices[RB_MAX_POLYGON_VERTICES];
    int count;
    uint32_t color;
} polygon_record;

typedef struct recorder {
    int polygon_count, circle_count, segment_count, point_count, transform_count;
    polygon_record polygons[RECORD_CAPACITY];
    struct {
        rb_vec2 center, axis;
        double radius;
        uint32_t color;
    } circles[RECORD_CAPACITY];
    struct {
        rb_vec2 p1, p2;
        uint32_t color;
    } segments[RECORD_CAPACITY];
    struct {
        rb_vec2 p;
        uint32_t color;
    } points[RECORD_CAPACITY];
    rb_transform transforms[RECORD_CAPACITY];
} recorder;

/* Each callback counts every call and keeps the first RECORD_CAPACITY. */
static void record_polygon(const rb_vec2 *vertices, int count, uint32_t color, void *context)
{
    recorder *r = context;
    if (r->polygon_count < RECORD_CAPACITY && count <= RB_MAX_POLYGON_VERTICES) {
        polygon_record *p = &r->polygons[r->polygon_count];
        for (int i = 0; i < count; ++i) {
            p->vertices[i] = vertices[i];
        }
        p->count = count;
        p->color = color;
    }
    r->polygon_count++;
}

static void record_circle(rb_vec2 center, double radius, rb_vec2 axis, uint32_t color, void *context)
{
    recorder *r = context;
    if (r->circle_count < RECORD_CAPACITY) {
        r->circles[r->circle_count].center = center;
        r->circles[r->circle_count].radius = radius;
        r->circles[r->circle_count].axis = axis;
        r->circles[r->circle_count].color = color;
    }
    r->circle_count++;
}

static void record_segment(rb_vec2 p1, rb_vec2 p2, uint32_t color, void *context)
{
    recorder *r = context;
    if (r->segment_count < RECORD_CAPACITY) {
        r->segments[r->segment_count].p1 = p1;
        r->segments[r->segment_count].p2 = p2;
        r->segments[r->segment_count].color = color;
    }
    r->segment_count++;
}

static void record_point(rb_vec2 p, double size, uint32_t color, void *context)
{
    (void)size;
    recorder *r = context;
    if (r->point_count < RECORD_CAPACITY) {
        r->points[r->point_count].p = p;
        r->points[r->point_count].color = color;
    }
    r->point_count++;
}

static void record_transform(rb_transform xf, void *context)
{
    recorder *r = context;
    if (r->transform_count < RECORD_CAPACITY) {
        r->transforms[r->transform_count] = xf;
    }
    r->transform_count++;
}

/* A debug draw with every callback recording into `r` and every flag off. */
static rb_debug_draw recording_draw(recorder *r)
{
    rb_debug_draw draw = rb_default_debug_draw();
    draw.draw_polygon = record_polygon;
    draw.draw_circle = record_circle;
    draw.draw_segment = record_segment;
    draw.draw_point = record_point;
    draw.draw_transform = record_transform;
    draw.draw_shapes = false;
    draw.draw_aabbs = false;
    draw.draw_mass = false;
    draw.draw_contact_points = false;
    draw.draw_contact_normals = false;
    draw.draw_contact_impulses = false;
    draw.context = r;
    return draw;
}

/* The scene: ground box of half-extents (10, 1) with its top face at y = 0,
 * a unit box (density 1: 1 kg) centred at (-2, 0.5) and a circle of radius
 * 0.5 (density 1: π/4 kg) centred at (2, 0.5), both resting on it, run for
 * one second so that the contacts have settled. */
#define BOX_X (-2.0)
#define BALL_X 2.0
#define BALL_RADIUS 0.5

typedef struct scene {
    rb_world *world;
    rb_body_id ground, box, ball;
    rb_shape_id shapes[3];
} scene;

static scene make_scene(void)
{
    scene s = {.world = make_world(rb_default_world_def().gravity)};
    /* The resting box and ball would fall asleep: the scene is drawn
     * awake, and sleeping_bodies_are_drawn_grey puts them to sleep. */
    cr_assert_eq(rb_world_enable_sleep(s.world, false), RB_OK);
    s.ground = make_body(s.world, RB_BODY_STATIC, rb_v2(0.0, -1.0), 0.0);
    s.shapes[0] = add_box(s.world, s.ground, 10.0, 1.0, 1.0);
    s.box = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(BOX_X, 0.5), 0.0);
    s.shapes[1] = add_box(s.world, s.box, 0.5, 0.5, 1.0);
    s.ball = make_body(s.world, RB_BODY_DYNAMIC, rb_v2(BALL_X, BALL_RADIUS), 0.0);
    s.shapes[2] = add_circle(s.world, s.ball, rb_v2(0.0, 0.0), BALL_RADIUS, 1.0);
    step_world(s.world, TEST_DT, 60);
    return s;
}

static void draw_world(const scene *s, const rb_debug_draw *draw)
{
    cr_assert_eq(rb_world_draw(s->world, draw), RB_OK, "rb_world_draw: %s", rb_last_error());
}

static void expect_counts(const recorder *r, int polygons, int circles, int segments, int points)
{
    cr_expect_eq(r->polygon_count, polygons, "%d polygons drawn, expected %d", r->polygon_count, polygons);
    cr_expect_eq(r->circle_count, circles, "%d circles drawn, expected %d", r->circle_count, circles);
    cr_expect_eq(r->segment_count, segments, "%d segments drawn, expected %d", r->segment_count, segments);
    cr_expect_eq(r->point_count, points, "%d points drawn, expected %d", r->point_count, points);
}

/* The drawn polygon has exactly the four world corners of a box of
 * half-extents hx, hy on a body with transform xf, in any order. Corners
 * are a few operations from the transform: 1e-12 m. */
static void expect_box_corners(const polygon_record *p, rb_transform xf, double hx, double hy, const char *what)
{
    cr_assert_eq(p->count, 4, "%s: drawn with %d vertices, expected 4", what, p->count);
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
        const rb_vec2 local = rb_v2(sx[k] * hx, sy[k] * hy);
        const rb_vec2 corner =
            rb_v2(xf.p.x + xf.q.c * local.x - xf.q.s * local.y, xf.p.y + xf.q.s * local.x + xf.q.c * local.y);
        int matches = 0;
        for (int i = 0; i < p->count; ++i) {
            matches += rb_distance(p->vertices[i], corner) <= 1e-12;
        }
        cr_expect_eq(matches, 1, "%s: corner (%g, %g) drawn %d times", what, corner.x, corner.y, matches);
    }
}

Test(debug_draw, sleeping_bodies_are_drawn_grey)
{
    scene s = make_scene();
    cr_assert_eq(rb_world_enable_sleep(s.world, true), RB_OK);
    step_world(s.world, TEST_DT, 60);
    cr_assert(!rb_body_is_awake(s.world, s.box) && !rb_body_is_awake(s.world, s.ball), "the scene rests: it sleeps");
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_shapes = true;
    draw_world(&s, &draw);
    expect_counts(&r, 2, 1, 0, 0);
    int grey = 0;
    for (int i = 0; i < r.polygon_count; ++i) {
        grey += r.polygons[i].color == RB_COLOR_SLEEPING;
    }
    cr_expect_eq(grey, 1, "the box is drawn grey, the static ground in its own colour");
    cr_expect(r.circle_count == 1 && r.circles[0].color == RB_COLOR_SLEEPING, "the ball is drawn grey");
    destroy_world_and_expect_no_leak(s.world);
}

Test(debug_draw, shapes_draw_one_polygon_per_box_and_one_circle)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_shapes = true;
    draw_world(&s, &draw);
    expect_counts(&r, 2, 1, 0, 0);
    cr_expect_eq(r.transform_count, 0, "no transforms without draw_mass");
    for (int i = 0; i < 2 && i < r.polygon_count; ++i) {
        const polygon_record *p = &r.polygons[i];
        if (p->color == RB_COLOR_STATIC) {
            expect_box_corners(p, rb_body_transform(s.world, s.ground), 10.0, 1.0, "ground");
        } else {
            cr_expect_eq(p->color, RB_COLOR_DYNAMIC, "polygon %d has colour %06x", i, p->color);
            expect_box_corners(p, rb_body_transform(s.world, s.box), 0.5, 0.5, "box");
        }
    }
    cr_expect(r.polygons[0].color != r.polygons[1].color, "the ground and the box must both be drawn");
    if (r.circle_count == 1) {
        const rb_transform xf = rb_body_transform(s.world, s.ball);
        expect_vec_near(r.circles[0].center, xf.p, 1e-12, "circle centre");
        expect_near(r.circles[0].radius, BALL_RADIUS, 1e-12, "circle radius");
        expect_vec_near(r.circles[0].axis, rb_v2(xf.q.c, xf.q.s), 1e-12, "circle axis: the body's x axis");
        cr_expect_eq(r.circles[0].color, RB_COLOR_DYNAMIC, "circle colour %06x", r.circles[0].color);
    }
    destroy_world_and_expect_no_leak(s.world);
}

/* The contact points lie on the ground's top face (midway between the
 * surfaces, so within a linear slop of y = 0): two under the box's bottom
 * corners and one under the circle. */
Test(debug_draw, contact_points_drawn_when_enabled)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_contact_points = true;
    draw_world(&s, &draw);
    expect_counts(&r, 0, 0, 0, 3);
    const double slop = rb_world_solver_settings(s.world).linear_slop;
    const double expected_x[3] = {BOX_X - 0.5, BOX_X + 0.5, BALL_X};
    for (int k = 0; k < 3; ++k) {
        int matches = 0;
        for (int i = 0; i < r.point_count && i < RECORD_CAPACITY; ++i) {
            matches += fabs(r.points[i].p.x - expected_x[k]) <= slop && fabs(r.points[i].p.y) <= slop;
        }
        cr_expect_eq(matches, 1, "contact point at (%g, 0) drawn %d times", expected_x[k], matches);
    }
    for (int i = 0; i < r.point_count && i < RECORD_CAPACITY; ++i) {
        cr_expect_eq(r.points[i].color, RB_COLOR_CONTACT_POINT, "point %d has colour %06x", i, r.points[i].color);
    }
    destroy_world_and_expect_no_leak(s.world);
}

/* In colours, the points of a base-2 pyramid show the graph colouring:
 * the two bottom boxes touch (colour 0), the top box rests on both
 * (colours 1 and 2, as it is in colour 1 already), and both bottom boxes
 * rest on the ground (the top colour, 63, which a body that cannot move
 * may share). Four palette colours then, none the plain contact colour. */
Test(debug_draw, contact_points_drawn_in_their_constraint_colours)
{
    rb_world *world = make_world(rb_v2(0.0, -9.8));
    scene_pyramid pyramid;
    cr_assert_eq(scene_pyramid_create(world, 2, &pyramid), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 2);
    int colours = rb_world_statistics(world).contact_colours;
    cr_assert_eq(colours, 4);

    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_shapes = false;
    draw.draw_contact_points = true;
    draw.draw_contact_colours = true;
    cr_assert_eq(rb_world_draw(world, &draw), RB_OK, "%s", rb_last_error());
    cr_assert(r.point_count > 0 && r.point_count <= RECORD_CAPACITY, "%d points", r.point_count);
    uint32_t seen[RB_CONSTRAINT_PALETTE_SIZE + 1];
    int distinct = 0;
    for (int i = 0; i < r.point_count; ++i) {
        cr_expect_neq(r.points[i].color, RB_COLOR_CONTACT_POINT, "point %d is not in a constraint colour", i);
        bool known = false;
        for (int k = 0; k < distinct; ++k) {
            known = known || seen[k] == r.points[i].color;
        }
        if (!known && distinct <= RB_CONSTRAINT_PALETTE_SIZE) {
            seen[distinct++] = r.points[i].color;
        }
    }
    cr_expect_eq(distinct, colours, "%d colours drawn, the contacts took %d", distinct, colours);
    cr_expect_eq(rb_constraint_colour_rgb(RB_OVERFLOW_COLOUR), 0xffffffu);
    cr_expect_eq(rb_constraint_colour_rgb(0), rb_constraint_colour_rgb(RB_CONSTRAINT_PALETTE_SIZE));
    cr_expect_eq(rb_constraint_colour_rgb(-1), (uint32_t)RB_COLOR_CONTACT_POINT, "a contact not solved");
    cr_expect_eq(rb_constraint_colour_rgb(RB_OVERFLOW_COLOUR + 1), (uint32_t)RB_COLOR_CONTACT_POINT, "no such colour");
    destroy_world_and_expect_no_leak(world);
}

Test(debug_draw, contact_normals_drawn_when_enabled)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_contact_normals = true;
    draw.normal_length = 0.3;
    draw_world(&s, &draw);
    expect_counts(&r, 0, 0, 3, 0);
    for (int i = 0; i < r.segment_count && i < RECORD_CAPACITY; ++i) {
        const rb_vec2 d = rb_sub(r.segments[i].p2, r.segments[i].p1);
        /* Every normal is the ground's: vertical, normal_length long. */
        expect_near(fabs(d.y), 0.3, 1e-12, "normal segment length");
        expect_near(d.x, 0.0, 1e-12, "normal segment is vertical");
        cr_expect_eq(r.segments[i].color, RB_COLOR_CONTACT_NORMAL, "segment %d has colour %06x", i,
                     r.segments[i].color);
    }
    destroy_world_and_expect_no_leak(s.world);
}

/* At rest the normal impulses of a body's contact points add up to its
 * weight times the substep, m·g·h; each is drawn impulse_scale m per N·s
 * long. 1 % as in test_contacts.c (resting contact). */
Test(debug_draw, contact_impulses_drawn_when_enabled)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_contact_impulses = true;
    draw.impulse_scale = 2.0;
    draw_world(&s, &draw);
    expect_counts(&r, 0, 0, 3, 0);
    double box_length = 0.0, ball_length = 0.0;
    for (int i = 0; i < r.segment_count && i < RECORD_CAPACITY; ++i) {
        const double length = rb_distance(r.segments[i].p1, r.segments[i].p2);
        if (r.segments[i].p1.x < 0.0) {
            box_length += length;
        } else {
            ball_length += length;
        }
        cr_expect_eq(r.segments[i].color, RB_COLOR_CONTACT_IMPULSE, "segment %d has colour %06x", i,
                     r.segments[i].color);
    }
    /* The impulses drawn are the last substep's, of length h. */
    const double g = rb_length(rb_world_gravity(s.world));
    const double h = substep_of(s.world, TEST_DT);
    const double box_expected = 2.0 * 1.0 * g * h;
    const double ball_expected = 2.0 * (RB_PI * BALL_RADIUS * BALL_RADIUS) * g * h;
    expect_near(box_length, box_expected, 0.01 * box_expected, "box impulse segments: scale·m·g·h");
    expect_near(ball_length, ball_expected, 0.01 * ball_expected, "ball impulse segment: scale·m·g·h");
    destroy_world_and_expect_no_leak(s.world);
}

/* The world bounds of a box of half-extents hx, hy on a body at xf: the
 * extremes of its four corners. */
static rb_aabb box_bounds(rb_transform xf, double hx, double hy)
{
    const double ex = fabs(xf.q.c) * hx + fabs(xf.q.s) * hy, ey = fabs(xf.q.s) * hx + fabs(xf.q.c) * hy;
    return (rb_aabb){{xf.p.x - ex, xf.p.y - ey}, {xf.p.x + ex, xf.p.y + ey}};
}

static bool contains(rb_aabb outer, rb_aabb inner)
{
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && outer.upper.x >= inner.upper.x &&
           outer.upper.y >= inner.upper.y;
}

/* Each shape's extent is inside exactly one drawn box (a broad phase may
 * enlarge its boxes, so they need not be tight; the shapes are metres
 * apart, so no box holds two of them). */
Test(debug_draw, aabbs_drawn_when_enabled)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_aabbs = true;
    draw_world(&s, &draw);
    expect_counts(&r, 3, 0, 0, 0);
    rb_aabb drawn[3];
    for (int i = 0; i < 3 && i < r.polygon_count; ++i) {
        const polygon_record *p = &r.polygons[i];
        cr_expect_eq(p->color, RB_COLOR_AABB, "box %d has colour %06x", i, p->color);
        cr_assert_eq(p->count, 4, "a bounding box has 4 vertices, got %d", p->count);
        drawn[i] = (rb_aabb){p->vertices[0], p->vertices[0]};
        for (int v = 1; v < 4; ++v) {
            drawn[i].lower = rb_vmin(drawn[i].lower, p->vertices[v]);
            drawn[i].upper = rb_vmax(drawn[i].upper, p->vertices[v]);
        }
    }
    const rb_vec2 ball = rb_body_position(s.world, s.ball);
    const rb_aabb shapes[3] = {
        box_bounds(rb_body_transform(s.world, s.ground), 10.0, 1.0),
        box_bounds(rb_body_transform(s.world, s.box), 0.5, 0.5),
        {{ball.x - BALL_RADIUS, ball.y - BALL_RADIUS}, {ball.x + BALL_RADIUS, ball.y + BALL_RADIUS}},
    };
    for (int k = 0; k < 3; ++k) {
        int containing = 0;
        for (int i = 0; i < 3 && i < r.polygon_count; ++i) {
            containing += contains(drawn[i], shapes[k]);
        }
        cr_expect_eq(containing, 1, "shape %d lies in %d drawn bounding boxes, expected 1", k, containing);
    }
    destroy_world_and_expect_no_leak(s.world);
}

/* draw_mass: a frame at the centre of mass of each dynamic body. */
Test(debug_draw, mass_frames_drawn_at_the_centres_of_mass)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_mass = true;
    draw_world(&s, &draw);
    expect_counts(&r, 0, 0, 0, 0);
    const rb_body_id dynamic[2] = {s.box, s.ball};
    for (int k = 0; k < 2; ++k) {
        const rb_vec2 center = rb_body_world_center(s.world, dynamic[k]);
        int matches = 0;
        for (int i = 0; i < r.transform_count && i < RECORD_CAPACITY; ++i) {
            matches += rb_distance(r.transforms[i].p, center) <= 1e-12;
        }
        cr_expect_eq(matches, 1, "the centre of mass of dynamic body %d is drawn %d times", k, matches);
    }
    destroy_world_and_expect_no_leak(s.world);
}

Test(debug_draw, nothing_drawn_when_every_flag_is_off)
{
    scene s = make_scene();
    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw_world(&s, &draw);
    expect_counts(&r, 0, 0, 0, 0);
    cr_expect_eq(r.transform_count, 0, "no transforms with every flag off");
    destroy_world_and_expect_no_leak(s.world);
}

Test(debug_draw, null_callbacks_are_skipped)
{
    scene s = make_scene();
    rb_debug_draw draw = rb_default_debug_draw();
    draw.draw_polygon = NULL;
    draw.draw_circle = NULL;
    draw.draw_segment = NULL;
    draw.draw_point = NULL;
    draw.draw_transform = NULL;
    draw.draw_shapes = draw.draw_aabbs = draw.draw_mass = true;
    draw.draw_contact_points = draw.draw_contact_normals = draw.draw_contact_impulses = true;
    draw_world(&s, &draw);

    /* Only the polygon callback set: it alone is called, for the two boxes
     * and the three bounding boxes. */
    recorder r = {0};
    draw.draw_polygon = record_polygon;
    draw.context = &r;
    draw_world(&s, &draw);
    expect_counts(&r, 5, 0, 0, 0);
    destroy_world_and_expect_no_leak(s.world);
}

Test(debug_draw, defaults_and_bad_arguments)
{
    const rb_debug_draw defaults = rb_default_debug_draw();
    cr_expect_eq(defaults.impulse_scale, 0.1, "debug_draw.h: impulse_scale defaults to 0.1 m per N·s");
    cr_expect_eq(defaults.normal_length, 0.1, "debug_draw.h: normal_length defaults to 0.1 m");

    scene s = make_scene();
    cr_expect_eq(rb_world_draw(s.world, NULL), RB_ERR_INVALID_ARGUMENT, "a NULL draw is an error");
    cr_expect_neq(rb_last_error()[0], '\0', "the error has a message");
    cr_expect_eq(rb_world_draw(NULL, &defaults), RB_ERR_INVALID_ARGUMENT, "a NULL world is an error");
    destroy_world_and_expect_no_leak(s.world);
}

/* A pendulum hanging at rest from a static pivot at the origin by a
 * revolute joint with limits [-0.5, 0.5] rad: the bob (a circle of
 * radius 0.1 m, density 1) at (0, -1) is body B. Drawing joints gives two
 * anchor points at the pivot, a segment from each body's centre to its
 * anchor, and one ray per limit, each 2·normal_length long at the angle
 * angle(A) + reference + limit from +x: body A (the pivot) does not turn
 * and the reference angle is 0, so the rays point at ±0.5 rad. The
 * reaction on the bob at rest is its
 * weight upwards, (0, m·g), drawn force_scale m per N long from its
 * anchor. */
Test(debug_draw, joints_and_their_reactions)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    rb_body_id pivot = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id bob = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.0, -1.0), 0.0);
    add_circle(world, bob, rb_v2(0.0, 0.0), 0.1, 1.0);
    rb_revolute_joint_def def = rb_default_revolute_joint_def();
    cr_assert_eq(rb_revolute_joint_def_at(&def, world, pivot, bob, rb_v2(0.0, 0.0)), RB_OK, "%s", rb_last_error());
    def.enable_lower_limit = def.enable_upper_limit = true;
    def.lower_angle = -0.5;
    def.upper_angle = 0.5;
    rb_joint_id joint;
    cr_assert_eq(rb_revolute_joint_create(world, &def, &joint), RB_OK, "%s", rb_last_error());
    step_world(world, TEST_DT, 30);

    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_joints = true;
    cr_assert_eq(rb_world_draw(world, &draw), RB_OK, "%s", rb_last_error());
    int anchors = 0, links = 0, limits = 0;
    for (int i = 0; i < r.point_count; ++i) {
        anchors += r.points[i].color == RB_COLOR_JOINT && rb_length(r.points[i].p) < 1e-9;
    }
    for (int i = 0; i < r.segment_count; ++i) {
        if (r.segments[i].color == RB_COLOR_JOINT) {
            ++links;
        } else if (r.segments[i].color == RB_COLOR_JOINT_LIMIT) {
            const rb_vec2 ray = rb_sub(r.segments[i].p2, r.segments[i].p1);
            expect_near(rb_length(ray), 2.0 * draw.normal_length, 1e-12, "limit ray length");
            expect_near(fabs(atan2(ray.y, ray.x)), 0.5, 1e-9, "limit ray angle");
            ++limits;
        }
    }
    cr_expect_eq(anchors, 2, "%d anchor points at the pivot, expected 2", anchors);
    cr_expect_eq(links, 2, "%d centre-to-anchor segments, expected 2", links);
    cr_expect_eq(limits, 2, "%d limit rays, expected 2", limits);

    recorder reactions = {0};
    draw = recording_draw(&reactions);
    draw.draw_joint_reactions = true;
    cr_assert_eq(rb_world_draw(world, &draw), RB_OK, "%s", rb_last_error());
    cr_assert_eq(reactions.segment_count, 1, "one reaction segment expected, got %d", reactions.segment_count);
    const double weight = rb_body_mass(world, bob) * 10.0;
    const rb_vec2 drawn = rb_sub(reactions.segments[0].p2, reactions.segments[0].p1);
    expect_vec_near(drawn, rb_v2(0.0, draw.force_scale * weight), 1e-9 * weight, "reaction segment");
    cr_expect_eq(reactions.segments[0].color, RB_COLOR_JOINT_REACTION);
    destroy_world_and_expect_no_leak(world);
}

/* Whether recorded segment i joins p and q, either way round (1e-12). */
static bool segment_joins(const recorder *r, int i, rb_vec2 p, rb_vec2 q)
{
    const rb_vec2 p1 = r->segments[i].p1, p2 = r->segments[i].p2;
    return (rb_distance(p1, p) < 1e-12 && rb_distance(p2, q) < 1e-12) ||
           (rb_distance(p1, q) < 1e-12 && rb_distance(p2, p) < 1e-12);
}

static int count_segments(const recorder *r, rb_vec2 p, rb_vec2 q, uint32_t color)
{
    int count = 0;
    for (int i = 0; i < r->segment_count; ++i) {
        count += r->segments[i].color == color && segment_joins(r, i, p, q);
    }
    return count;
}

/* Before any step (nothing has moved): a prismatic joint along +x from a
 * static body's anchor at the origin to a box's anchor at (0.3, 0), limits
 * at -0.5 and 0.5 m, draws its slide from anchor to anchor and a tick
 * across the axis at each limit, normal_length on each side ((±0.5,
 * ±0.1)); a pulley with pulleys at (2, 3) and (4, 3) and balls at (2, 0)
 * and (4, 0) draws the rope's three lines. Besides them each joint draws
 * its two centre-to-anchor segments: 2 + 3 + 2 + 3 segments in all. */
Test(debug_draw, prismatic_slides_and_pulley_ropes)
{
    rb_world *world = make_world(rb_v2(0.0, -10.0));
    rb_body_id ground = make_body(world, RB_BODY_STATIC, rb_v2(0.0, 0.0), 0.0);
    rb_body_id box = make_body(world, RB_BODY_DYNAMIC, rb_v2(0.3, 0.0), 0.0);
    add_box(world, box, 0.1, 0.1, 1.0);
    rb_prismatic_joint_def slide = rb_default_prismatic_joint_def();
    slide.body_a = ground;
    slide.body_b = box;
    slide.enable_lower_limit = slide.enable_upper_limit = true;
    slide.lower_translation = -0.5;
    slide.upper_translation = 0.5;
    rb_joint_id joint;
    cr_assert_eq(rb_prismatic_joint_create(world, &slide, &joint), RB_OK, "%s", rb_last_error());
    rb_body_id left = make_body(world, RB_BODY_DYNAMIC, rb_v2(2.0, 0.0), 0.0);
    add_circle(world, left, rb_v2(0.0, 0.0), 0.1, 1.0);
    rb_body_id right = make_body(world, RB_BODY_DYNAMIC, rb_v2(4.0, 0.0), 0.0);
    add_circle(world, right, rb_v2(0.0, 0.0), 0.1, 1.0);
    rb_pulley_joint_def rope = rb_default_pulley_joint_def();
    cr_assert_eq(rb_pulley_joint_def_between(&rope, world, left, right, rb_v2(2.0, 3.0), rb_v2(4.0, 3.0),
                                             rb_v2(2.0, 0.0), rb_v2(4.0, 0.0)),
                 RB_OK, "%s", rb_last_error());
    cr_assert_eq(rb_pulley_joint_create(world, &rope, &joint), RB_OK, "%s", rb_last_error());

    recorder r = {0};
    rb_debug_draw draw = recording_draw(&r);
    draw.draw_joints = true;
    cr_assert_eq(rb_world_draw(world, &draw), RB_OK, "%s", rb_last_error());
    cr_expect_eq(r.segment_count, 10, "%d segments, expected 10", r.segment_count);
    cr_expect_eq(count_segments(&r, rb_v2(0.0, 0.0), rb_v2(0.3, 0.0), RB_COLOR_JOINT), 1, "the slide");
    const double n = draw.normal_length;
    cr_expect_eq(count_segments(&r, rb_v2(-0.5, -n), rb_v2(-0.5, n), RB_COLOR_JOINT_LIMIT), 1, "the lower tick");
    cr_expect_eq(count_segments(&r, rb_v2(0.5, -n), rb_v2(0.5, n), RB_COLOR_JOINT_LIMIT), 1, "the upper tick");
    cr_expect_eq(count_segments(&r, rb_v2(2.0, 3.0), rb_v2(2.0, 0.0), RB_COLOR_JOINT), 1, "rope side A");
    cr_expect_eq(count_segments(&r, rb_v2(2.0, 3.0), rb_v2(4.0, 3.0), RB_COLOR_JOINT), 1, "rope over the pulleys");
    cr_expect_eq(count_segments(&r, rb_v2(4.0, 3.0), rb_v2(4.0, 0.0), RB_COLOR_JOINT), 1, "rope side B");
    destroy_world_and_expect_no_leak(world);
}
