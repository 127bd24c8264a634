/* SPDX-License-Identifier: MIT */
/* Shapes: creation on a body (chains as runs of segments), materials,
 * filters, sensor overlaps. */
#include <float.h>
#include <string.h>

#include "allocator.h"
#include "contact.h"
#include "error.h"
#include "manifold_internal.h"
#include "world_internal.h"

rb_filter rb_default_filter(void) { return (rb_filter){.category_bits = 1u, .mask_bits = 0xffffffffu}; }

rb_shape_def rb_default_shape_def(void)
{
    return (rb_shape_def){.friction = 0.6,
                          .restitution = 0.0,
                          .density = 1.0,
                          .filter = rb_default_filter(),
                          .internal_value = RB_DEF_COOKIE};
}

static rb_status check_shape_def(const rb_shape_def *def, const char *f)
{
    RB_TRY(rb_check_pointer(f, "def", def));
    RB_TRY(rb_check_def_cookie(f, "rb_default_shape_def", def->internal_value));
    RB_TRY(rb_check_range(f, "friction", def->friction, 0.0, RB_MAX_FRICTION));
    RB_TRY(rb_check_range(f, "restitution", def->restitution, 0.0, 1.0));
    RB_TRY(rb_check_range(f, "density", def->density, 0.0, RB_MAX_DENSITY));
    return RB_OK;
}

/* A polygon built by hand must still be convex, counter-clockwise and
 * finite; its normals and centroid are recomputed, not trusted. */
static rb_status check_polygon(const rb_polygon *polygon, rb_polygon *clean)
{
    const char *f = "rb_shape_create_polygon";
    RB_TRY(rb_check_pointer(f, "polygon", polygon));
    if (polygon->count < 3 || polygon->count > RB_MAX_POLYGON_VERTICES) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: polygon count is %d, expected 3 to %d", f, polygon->count,
                               RB_MAX_POLYGON_VERTICES);
    }
    for (int i = 0; i < polygon->count; ++i) {
        RB_TRY(rb_check_point(f, "polygon vertex", polygon->vertices[i]));
    }
    *clean = *polygon;
    int n = polygon->count;
    /* Shoelace formula: twice the signed area. */
    double twice_area = 0.0;
    for (int i = 0; i < n; ++i) {
        twice_area += rb_cross(polygon->vertices[i], polygon->vertices[(i + 1) % n]);
    }
    if (fabs(twice_area) < 2.0 * RB_POLYGON_WELD_DISTANCE * RB_POLYGON_WELD_DISTANCE) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE, "%s: the polygon encloses no area (collinear points)", f);
    }
    for (int i = 0; i < n; ++i) {
        rb_vec2 e1 = rb_sub(polygon->vertices[(i + 1) % n], polygon->vertices[i]);
        rb_vec2 e2 = rb_sub(polygon->vertices[(i + 2) % n], polygon->vertices[(i + 1) % n]);
        if (!(rb_cross(e1, e2) > 0.0) || rb_length(e1) < RB_POLYGON_WELD_DISTANCE) {
            return rb_report_error(RB_ERR_NOT_CONVEX,
                                   "%s: the polygon turns clockwise or folds at vertex %d; build it with "
                                   "rb_make_polygon or rb_make_polygon_hull",
                                   f, (i + 1) % n);
        }
        clean->normals[i] = rb_normalize(rb_right_perp(e1));
    }
    clean->centroid = rb_polygon_mass(clean, 1.0).center;
    return RB_OK;
}

static rb_status allocate_shape_slot(rb_world *world, int *index)
{
    if (world->shape_free >= 0) {
        *index = world->shape_free;
        world->shape_free = world->shapes[*index].next_free;
        return RB_OK;
    }
    if (rb_grow_array((void **)&world->shapes, &world->shape_capacity, world->shape_slots + 1, sizeof *world->shapes) !=
        0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_shape_create: out of memory");
    }
    *index = world->shape_slots++;
    world->shapes[*index].generation = 0;
    return RB_OK;
}

rb_status rb_shape_check_mass(const char *function, rb_shape_type type, const void *geometry, double density,
                              bool gives_mass)
{
    double mass = 0.0;
    if (type == RB_SHAPE_CIRCLE) {
        mass = rb_circle_mass(geometry, density).mass;
    } else if (type == RB_SHAPE_POLYGON) {
        mass = rb_polygon_mass(geometry, density).mass;
    }
    double lowest = gives_mass ? RB_MIN_MASS : 0.0;
    if (!(mass >= lowest && mass <= RB_MAX_MASS)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: the shape's mass (density %g kg/m² times its area) is %g kg, expected %g to %g kg",
                               function, density, mass, lowest, RB_MAX_MASS);
    }
    return RB_OK;
}

static rb_status create_shape(rb_world *world, rb_body_id body_id, const rb_shape_def *def, rb_shape_type type,
                              const void *geometry, rb_shape_id *out, const char *f)
{
    int body_index;
    RB_TRY(rb_world_find_body(world, body_id, f, &body_index));
    RB_TRY(rb_world_check_unlocked(world, f));
    const rb_body *body = &world->bodies[body_index];
    bool massless = type == RB_SHAPE_SEGMENT || type == RB_SHAPE_CHAIN_SEGMENT;
    if (body->type == RB_BODY_DYNAMIC && !body->has_mass_override && massless) {
        return rb_report_error(RB_ERR_NO_MASS,
                               "%s: a segment has no mass; put it on a static or kinematic body, or give the dynamic "
                               "body a mass override (rb_body_set_mass_data) first",
                               f);
    }
    if (body->type == RB_BODY_DYNAMIC && !body->has_mass_override && !(def->density > 0.0)) {
        return rb_report_error(RB_ERR_NO_MASS,
                               "%s: density is %g on a dynamic body without a mass override; expected a density > 0 "
                               "(kg/m²) or rb_body_set_mass_data first",
                               f, def->density);
    }
    bool gives_mass = body->type == RB_BODY_DYNAMIC && !body->has_mass_override;
    RB_TRY(rb_shape_check_mass(f, type, geometry, def->density, gives_mass));
    int index = -1;
    RB_TRY(allocate_shape_slot(world, &index));
    rb_shape *shape = &world->shapes[index];
    uint32_t generation = shape->generation + 1u;
    memset(shape, 0, sizeof *shape);
    shape->generation = generation;
    shape->in_use = true;
    shape->body = body_index;
    shape->next_in_body = -1;
    shape->type = type;
    switch (type) {
    case RB_SHAPE_CIRCLE:
        shape->geometry.circle = *(const rb_circle *)geometry;
        break;
    case RB_SHAPE_POLYGON:
        shape->geometry.polygon = *(const rb_polygon *)geometry;
        shape->box = rb_polygon_is_box(&shape->geometry.polygon);
        break;
    case RB_SHAPE_SEGMENT:
        shape->geometry.segment = *(const rb_segment *)geometry;
        break;
    case RB_SHAPE_CHAIN_SEGMENT:
        shape->geometry.chain_segment = *(const rb_chain_segment *)geometry;
        break;
    }
    shape->friction = def->friction;
    shape->restitution = def->restitution;
    shape->density = def->density;
    shape->sensor = def->is_sensor;
    shape->filter = def->filter;
    shape->user_data = def->user_data;

    /* Append, so a body's shapes stay in creation order. */
    rb_body *owner = &world->bodies[body_index];
    int *link = &owner->first_shape;
    while (*link >= 0) {
        link = &world->shapes[*link].next_in_body;
    }
    *link = index;
    owner->shape_count++;
    world->shape_count++;
    world->solid_shape_count += shape->sensor ? 0 : 1;
    world->sweep_stale = true;
    rb_body_update_mass(world, body_index);
    *out = rb_make_shape_id(world, index);
    return RB_OK;
}

rb_status rb_shape_create_circle(rb_world *world, rb_body_id body, const rb_shape_def *def, const rb_circle *circle,
                                 rb_shape_id *out)
{
    const char *f = "rb_shape_create_circle";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "out", out));
    *out = (rb_shape_id){0};
    RB_TRY(check_shape_def(def, f));
    RB_TRY(rb_check_pointer(f, "circle", circle));
    RB_TRY(rb_check_point(f, "circle center", circle->center));
    RB_TRY(rb_check_range(f, "circle radius", circle->radius, 0.0, RB_MAX_LENGTH));
    if (circle->radius < RB_POLYGON_WELD_DISTANCE) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE, "%s: circle radius is %g m, expected at least %g m", f,
                               circle->radius, RB_POLYGON_WELD_DISTANCE);
    }
    return create_shape(world, body, def, RB_SHAPE_CIRCLE, circle, out, f);
}

rb_status rb_shape_create_polygon(rb_world *world, rb_body_id body, const rb_shape_def *def, const rb_polygon *polygon,
                                  rb_shape_id *out)
{
    const char *f = "rb_shape_create_polygon";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "out", out));
    *out = (rb_shape_id){0};
    RB_TRY(check_shape_def(def, f));
    rb_polygon clean;
    RB_TRY(check_polygon(polygon, &clean));
    return create_shape(world, body, def, RB_SHAPE_POLYGON, &clean, out, f);
}

/* Frees the slot of a shape that has no contacts left. */
static void destroy_shape(rb_world *world, int index)
{
    rb_shape *shape = &world->shapes[index];
    rb_body *body = &world->bodies[shape->body];
    int *link = &body->first_shape;
    while (*link != index) {
        link = &world->shapes[*link].next_in_body;
    }
    *link = shape->next_in_body;
    body->shape_count--;
    shape->in_use = false;
    if (shape->generation != RB_RETIRED_GENERATION) {
        shape->next_free = world->shape_free;
        world->shape_free = index;
    }
    world->shape_count--;
    world->solid_shape_count -= shape->sensor ? 0 : 1;
    world->sweep_stale = true;
    rb_body_update_mass(world, shape->body);
}

/* Two chain or segment points: finite, and far enough apart to give the
 * segment a direction. */
static rb_status check_segment_points(const char *f, const char *name, int index, rb_vec2 p1, rb_vec2 p2)
{
    if (!(fabs(p1.x) <= RB_MAX_LENGTH && fabs(p1.y) <= RB_MAX_LENGTH && fabs(p2.x) <= RB_MAX_LENGTH &&
          fabs(p2.y) <= RB_MAX_LENGTH)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: %s %d runs from (%g, %g) to (%g, %g) m, expected coordinates in [%g, %g] m", f,
                               name, index, p1.x, p1.y, p2.x, p2.y, -RB_MAX_LENGTH, RB_MAX_LENGTH);
    }
    if (rb_distance(p1, p2) < RB_POLYGON_WELD_DISTANCE) {
        return rb_report_error(RB_ERR_DEGENERATE_SHAPE,
                               "%s: %s %d from (%g, %g) to (%g, %g) is shorter than %g m, expected distinct points", f,
                               name, index, p1.x, p1.y, p2.x, p2.y, RB_POLYGON_WELD_DISTANCE);
    }
    return RB_OK;
}

rb_status rb_shape_create_segment(rb_world *world, rb_body_id body, const rb_shape_def *def, const rb_segment *segment,
                                  rb_shape_id *out)
{
    const char *f = "rb_shape_create_segment";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "out", out));
    *out = (rb_shape_id){0};
    RB_TRY(check_shape_def(def, f));
    RB_TRY(rb_check_pointer(f, "segment", segment));
    RB_TRY(check_segment_points(f, "segment", 0, segment->point1, segment->point2));
    return create_shape(world, body, def, RB_SHAPE_SEGMENT, segment, out, f);
}

/* Segment i of a chain of `count` points runs from point i to point
 * i + 1 (wrapping for a loop); its ghosts are the points before and
 * after, where they exist. */
static rb_chain_segment chain_segment_at(const rb_vec2 *points, int count, bool loop, int i)
{
    rb_chain_segment c = {0};
    c.segment.point1 = points[i];
    c.segment.point2 = points[(i + 1) % count];
    c.has_ghost1 = loop || i > 0;
    c.has_ghost2 = loop || i + 2 < count;
    if (c.has_ghost1) {
        c.ghost1 = points[(i + count - 1) % count];
    }
    if (c.has_ghost2) {
        c.ghost2 = points[(i + 2) % count];
    }
    return c;
}

rb_status rb_shape_create_chain(rb_world *world, rb_body_id body, const rb_shape_def *def, const rb_vec2 *points,
                                int count, bool loop, rb_shape_id *out, int capacity)
{
    const char *f = "rb_shape_create_chain";
    rb_clear_error();
    RB_TRY(check_shape_def(def, f));
    RB_TRY(rb_check_pointer(f, "points", points));
    int minimum = loop ? 3 : 2;
    if (count < minimum) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: count is %d, expected at least %d points for %s chain", f,
                               count, minimum, loop ? "a loop" : "an open");
    }
    int segment_count = loop ? count : count - 1;
    if (out != NULL && capacity < segment_count) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: capacity is %d, expected at least %d (one id per segment)",
                               f, capacity, segment_count);
    }
    for (int i = 0; i < segment_count; ++i) {
        RB_TRY(check_segment_points(f, "segment", i, points[i], points[(i + 1) % count]));
    }
    int body_index;
    RB_TRY(rb_world_find_body(world, body, f, &body_index));
    RB_TRY(rb_world_check_unlocked(world, f));
    int shapes_before = world->bodies[body_index].shape_count;
    for (int i = 0; i < segment_count; ++i) {
        rb_chain_segment segment = chain_segment_at(points, count, loop, i);
        rb_shape_id id;
        rb_status status = create_shape(world, body, def, RB_SHAPE_CHAIN_SEGMENT, &segment, &id, f);
        if (status != RB_OK) {
            /* Leave no partial chain: the segments made so far are the
             * last ones of the body's list. */
            while (world->bodies[body_index].shape_count > shapes_before) {
                int last = world->bodies[body_index].first_shape;
                while (world->shapes[last].next_in_body >= 0) {
                    last = world->shapes[last].next_in_body;
                }
                destroy_shape(world, last);
            }
            return status;
        }
        if (out != NULL) {
            out[i] = id;
        }
    }
    return RB_OK;
}

rb_status rb_shape_destroy(rb_world *world, rb_shape_id id)
{
    rb_clear_error();
    int index;
    RB_TRY(rb_world_find_shape(world, id, "rb_shape_destroy", &index));
    RB_TRY(rb_world_check_unlocked(world, "rb_shape_destroy"));
    RB_TRY(rb_contacts_remove_shape(world, index));
    destroy_shape(world, index);
    return RB_OK;
}

bool rb_shape_is_valid(const rb_world *world, rb_shape_id id)
{
    return world != NULL && id.generation != 0 && id.world == world->serial && id.index >= 0 &&
           id.index < world->shape_slots && world->shapes[id.index].in_use &&
           world->shapes[id.index].generation == id.generation;
}

rb_aabb rb_shape_tight_aabb(const rb_world *world, int index)
{
    const rb_shape *shape = &world->shapes[index];
    rb_transform xf = rb_body_origin_transform(world, shape->body);
    switch (shape->type) {
    case RB_SHAPE_CIRCLE:
        return rb_circle_aabb(&shape->geometry.circle, xf);
    case RB_SHAPE_POLYGON:
        return rb_polygon_aabb(&shape->geometry.polygon, xf);
    case RB_SHAPE_SEGMENT:
        return rb_segment_aabb(&shape->geometry.segment, xf);
    case RB_SHAPE_CHAIN_SEGMENT:
        break;
    }
    return rb_segment_aabb(&shape->geometry.chain_segment.segment, xf);
}

/* ---- getters and setters ------------------------------------------------- */

#define SHAPE_GETTER(type, name, zero, expression)                                                                     \
    type name(const rb_world *world, rb_shape_id id)                                                                   \
    {                                                                                                                  \
        rb_clear_error();                                                                                              \
        int index;                                                                                                     \
        if (rb_world_find_shape(world, id, #name, &index) != RB_OK) {                                                  \
            return zero;                                                                                               \
        }                                                                                                              \
        const rb_shape *shape = &world->shapes[index];                                                                 \
        return expression;                                                                                             \
    }

static const rb_circle no_circle = {{0.0, 0.0}, 0.0};
static const rb_polygon no_polygon = {0};
static const rb_segment no_segment = {{0.0, 0.0}, {0.0, 0.0}};
static const rb_chain_segment no_chain_segment = {0};
static const rb_aabb no_aabb = {{0.0, 0.0}, {0.0, 0.0}};
static const rb_filter no_filter = {0u, 0u, 0};
static const rb_body_id no_body = {0, 0, 0};

SHAPE_GETTER(rb_shape_type, rb_shape_type_of, RB_SHAPE_CIRCLE, shape->type)
SHAPE_GETTER(rb_body_id, rb_shape_body, no_body, rb_make_body_id(world, shape->body))
SHAPE_GETTER(rb_circle, rb_shape_circle, no_circle, shape->type == RB_SHAPE_CIRCLE ? shape->geometry.circle : no_circle)
SHAPE_GETTER(rb_polygon, rb_shape_polygon, no_polygon,
             shape->type == RB_SHAPE_POLYGON ? shape->geometry.polygon : no_polygon)
SHAPE_GETTER(rb_segment, rb_shape_segment, no_segment,
             shape->type == RB_SHAPE_SEGMENT         ? shape->geometry.segment
             : shape->type == RB_SHAPE_CHAIN_SEGMENT ? shape->geometry.chain_segment.segment
                                                     : no_segment)
SHAPE_GETTER(rb_chain_segment, rb_shape_chain_segment, no_chain_segment,
             shape->type == RB_SHAPE_CHAIN_SEGMENT ? shape->geometry.chain_segment : no_chain_segment)
SHAPE_GETTER(double, rb_shape_friction, 0.0, shape->friction)
SHAPE_GETTER(double, rb_shape_restitution, 0.0, shape->restitution)
SHAPE_GETTER(double, rb_shape_density, 0.0, shape->density)
SHAPE_GETTER(bool, rb_shape_is_sensor, false, shape->sensor)
SHAPE_GETTER(rb_filter, rb_shape_filter, no_filter, shape->filter)
SHAPE_GETTER(void *, rb_shape_user_data, NULL, shape->user_data)

rb_aabb rb_shape_aabb(const rb_world *world, rb_shape_id id)
{
    rb_clear_error();
    int index = -1;
    if (rb_world_find_shape(world, id, "rb_shape_aabb", &index) != RB_OK) {
        return no_aabb;
    }
    return rb_shape_tight_aabb(world, index);
}

static rb_status find_shape_for_change(rb_world *world, rb_shape_id id, const char *function, int *index)
{
    rb_clear_error();
    RB_TRY(rb_world_find_shape(world, id, function, index));
    return rb_world_check_unlocked(world, function);
}

/* A setter that checks its argument, then stores it in one shape field. */
#define SHAPE_FIELD_SETTER(name, type, argument, field, check)                                                         \
    rb_status name(rb_world *world, rb_shape_id id, type argument)                                                     \
    {                                                                                                                  \
        const char *function = #name;                                                                                  \
        int index;                                                                                                     \
        RB_TRY(find_shape_for_change(world, id, function, &index));                                                    \
        RB_TRY(check);                                                                                                 \
        world->shapes[index].field = argument;                                                                         \
        return RB_OK;                                                                                                  \
    }

SHAPE_FIELD_SETTER(rb_shape_set_user_data, void *, user_data, user_data, RB_OK)

/* A contact mixes its shapes' materials when it begins; a change of
 * material mixes those of the shape's contacts again. */
rb_status rb_shape_set_friction(rb_world *world, rb_shape_id id, double friction)
{
    int index;
    RB_TRY(find_shape_for_change(world, id, "rb_shape_set_friction", &index));
    RB_TRY(rb_check_range("rb_shape_set_friction", "friction", friction, 0.0, RB_MAX_FRICTION));
    world->shapes[index].friction = friction;
    rb_contacts_mix_materials(world, index);
    return RB_OK;
}

rb_status rb_shape_set_restitution(rb_world *world, rb_shape_id id, double restitution)
{
    int index;
    RB_TRY(find_shape_for_change(world, id, "rb_shape_set_restitution", &index));
    RB_TRY(rb_check_range("rb_shape_set_restitution", "restitution", restitution, 0.0, 1.0));
    world->shapes[index].restitution = restitution;
    rb_contacts_mix_materials(world, index);
    return RB_OK;
}

rb_status rb_shape_set_filter(rb_world *world, rb_shape_id id, rb_filter filter)
{
    int index;
    RB_TRY(find_shape_for_change(world, id, "rb_shape_set_filter", &index));
    world->shapes[index].filter = filter;
    world->candidates_stale = true; /* which shapes may collide changed: the broad phase searches anew */
    return RB_OK;
}

rb_status rb_shape_set_density(rb_world *world, rb_shape_id id, double density)
{
    int index;
    RB_TRY(find_shape_for_change(world, id, "rb_shape_set_density", &index));
    RB_TRY(rb_check_range("rb_shape_set_density", "density", density, 0.0, RB_MAX_DENSITY));
    rb_shape *shape = &world->shapes[index];
    const rb_body *body = &world->bodies[shape->body];
    bool gives_mass = body->type == RB_BODY_DYNAMIC && !body->has_mass_override;
    if (gives_mass && !(density > 0.0)) {
        return rb_report_error(RB_ERR_NO_MASS,
                               "rb_shape_set_density: density %g on a dynamic body without a mass override; "
                               "expected > 0",
                               density);
    }
    RB_TRY(rb_shape_check_mass("rb_shape_set_density", shape->type, &shape->geometry, density, gives_mass));
    shape->density = density;
    rb_body_update_mass(world, shape->body);
    return RB_OK;
}

int rb_shape_sensor_overlaps(const rb_world *world, rb_shape_id sensor, rb_shape_id *out, int capacity)
{
    rb_clear_error();
    int index;
    if (rb_world_find_shape(world, sensor, "rb_shape_sensor_overlaps", &index) != RB_OK) {
        return -1;
    }
    if (!world->shapes[index].sensor) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_shape_sensor_overlaps: shape %d is not a sensor", index);
        return -1;
    }
    if (out == NULL && capacity > 0) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_shape_sensor_overlaps: out is NULL");
        return -1;
    }
    int count = 0;
    for (int i = 0; i < world->contact_count && count < capacity; ++i) {
        const rb_contact *c = &world->contacts[i];
        if (!c->touching || (c->pair.shape_a != index && c->pair.shape_b != index)) {
            continue;
        }
        out[count++] = rb_make_shape_id(world, c->pair.shape_a == index ? c->pair.shape_b : c->pair.shape_a);
    }
    return count;
}
