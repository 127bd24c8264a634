/* SPDX-License-Identifier: MIT */
/* World queries: box overlap, point containment and ray casts. Each
 * asks the broad phase for the shapes whose boxes overlap the query's
 * box (rb_broad_phase_query), then tests those exactly. */
#include "broad_phase.h"
#include "error.h"
#include "rb/query.h"

rb_query_filter rb_default_query_filter(void)
{
    return (rb_query_filter){.category_bits = 1u, .mask_bits = 0xffffffffu};
}

static bool passes_filter(const rb_shape *shape, rb_query_filter filter, bool include_sensors)
{
    if (shape->sensor && !include_sensors) {
        return false;
    }
    return (shape->filter.category_bits & filter.mask_bits) != 0 &&
           (filter.category_bits & shape->filter.mask_bits) != 0;
}

static rb_status check_box(const char *f, rb_aabb box)
{
    RB_TRY(rb_check_vec2(f, "box lower", box.lower));
    RB_TRY(rb_check_vec2(f, "box upper", box.upper));
    if (box.lower.x > box.upper.x || box.lower.y > box.upper.y) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: box lower (%g, %g) exceeds upper (%g, %g)", f, box.lower.x,
                               box.lower.y, box.upper.x, box.upper.y);
    }
    return RB_OK;
}

static rb_status check_output(const char *f, const void *out, int capacity, const int *count)
{
    RB_TRY(rb_check_pointer(f, "count", count));
    if (capacity < 0) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: capacity is %d, expected >= 0", f, capacity);
    }
    if (capacity > 0) {
        RB_TRY(rb_check_pointer(f, "out", out));
    }
    return RB_OK;
}

static rb_status check_callback(const char *f, rb_query_fn *fn)
{
    if (fn == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: fn is NULL", f);
    }
    return RB_OK;
}

/* ---- overlaps: a box or a point ------------------------------------------ */

/* A query in progress: what it asks, and where the shapes found go (a
 * callback, or an array with a count). */
typedef struct overlap_query {
    rb_query_filter filter;
    bool include_sensors;
    bool by_point;
    rb_vec2 point;
    rb_query_fn *fn;
    void *context;
    rb_shape_id *out;
    int capacity;
    int count;
} overlap_query;

static bool contains_point(const rb_world *world, const rb_shape *shape, rb_vec2 point)
{
    rb_transform xf = rb_body_origin_transform(world, shape->body);
    switch (shape->type) {
    case RB_SHAPE_CIRCLE:
        return rb_circle_contains(&shape->geometry.circle, xf, point);
    case RB_SHAPE_POLYGON:
        return rb_polygon_contains(&shape->geometry.polygon, xf, point);
    case RB_SHAPE_SEGMENT:
    case RB_SHAPE_CHAIN_SEGMENT:
        break;
    }
    return false;
}

static bool visit_overlap(const rb_world *world, int index, void *context)
{
    overlap_query *q = context;
    const rb_shape *shape = &world->shapes[index];
    if (!passes_filter(shape, q->filter, q->include_sensors) ||
        (q->by_point && !contains_point(world, shape, q->point))) {
        return true;
    }
    rb_shape_id id = rb_make_shape_id(world, index);
    if (q->fn != NULL) {
        return q->fn(id, q->context);
    }
    if (q->count < q->capacity) {
        q->out[q->count] = id;
    }
    q->count++;
    return true;
}

rb_status rb_world_query_aabb(const rb_world *world, rb_aabb box, rb_query_filter filter, bool include_sensors,
                              rb_query_fn *fn, void *context)
{
    const char *f = "rb_world_query_aabb";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "world", world));
    RB_TRY(check_box(f, box));
    RB_TRY(check_callback(f, fn));
    overlap_query q = {.filter = filter, .include_sensors = include_sensors, .fn = fn, .context = context};
    rb_broad_phase_query(world, box, visit_overlap, &q);
    return RB_OK;
}

rb_status rb_world_overlap_aabb(const rb_world *world, rb_aabb box, rb_query_filter filter, bool include_sensors,
                                rb_shape_id *out, int capacity, int *count)
{
    const char *f = "rb_world_overlap_aabb";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "world", world));
    RB_TRY(check_box(f, box));
    RB_TRY(check_output(f, out, capacity, count));
    overlap_query q = {.filter = filter, .include_sensors = include_sensors, .out = out, .capacity = capacity};
    rb_broad_phase_query(world, box, visit_overlap, &q);
    *count = q.count;
    return RB_OK;
}

rb_status rb_world_query_point(const rb_world *world, rb_vec2 point, rb_query_filter filter, bool include_sensors,
                               rb_query_fn *fn, void *context)
{
    const char *f = "rb_world_query_point";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "world", world));
    RB_TRY(rb_check_vec2(f, "point", point));
    RB_TRY(check_callback(f, fn));
    overlap_query q = {.filter = filter,
                       .include_sensors = include_sensors,
                       .by_point = true,
                       .point = point,
                       .fn = fn,
                       .context = context};
    rb_broad_phase_query(world, (rb_aabb){point, point}, visit_overlap, &q);
    return RB_OK;
}

rb_status rb_world_overlap_point(const rb_world *world, rb_vec2 point, rb_query_filter filter, bool include_sensors,
                                 rb_shape_id *out, int capacity, int *count)
{
    const char *f = "rb_world_overlap_point";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "world", world));
    RB_TRY(rb_check_vec2(f, "point", point));
    RB_TRY(check_output(f, out, capacity, count));
    overlap_query q = {.filter = filter,
                       .include_sensors = include_sensors,
                       .by_point = true,
                       .point = point,
                       .out = out,
                       .capacity = capacity};
    rb_broad_phase_query(world, (rb_aabb){point, point}, visit_overlap, &q);
    *count = q.count;
    return RB_OK;
}

/* ---- ray casts ----------------------------------------------------------- */

typedef struct ray_query {
    rb_vec2 origin, translation;
    rb_query_filter filter;
    bool include_sensors;
    /* closest: the best hit so far; all: the nearest `capacity` hits, sorted */
    bool closest;
    rb_ray_hit best;
    bool found;
    rb_ray_hit *out;
    int capacity;
    int count;
} ray_query;

static rb_ray_cast_output cast_shape(const rb_world *world, const rb_shape *shape, rb_vec2 origin, rb_vec2 translation)
{
    rb_transform xf = rb_body_origin_transform(world, shape->body);
    switch (shape->type) {
    case RB_SHAPE_CIRCLE:
        return rb_ray_cast_circle(&shape->geometry.circle, xf, origin, translation);
    case RB_SHAPE_POLYGON:
        return rb_ray_cast_polygon(&shape->geometry.polygon, xf, origin, translation);
    case RB_SHAPE_SEGMENT:
        return rb_ray_cast_segment(&shape->geometry.segment, xf, origin, translation);
    case RB_SHAPE_CHAIN_SEGMENT:
        break;
    }
    return rb_ray_cast_chain_segment(&shape->geometry.chain_segment, xf, origin, translation);
}

/* Whether hit a comes before hit b: nearer, or as near with a lower shape index. */
static bool ray_hit_before(const rb_ray_hit *a, const rb_ray_hit *b)
{
    return a->fraction < b->fraction || (a->fraction == b->fraction && a->shape.index < b->shape.index);
}

static bool visit_ray(const rb_world *world, int index, void *context)
{
    ray_query *q = context;
    const rb_shape *shape = &world->shapes[index];
    if (!passes_filter(shape, q->filter, q->include_sensors)) {
        return true;
    }
    rb_ray_cast_output cast = cast_shape(world, shape, q->origin, q->translation);
    if (!cast.hit) {
        return true;
    }
    rb_ray_hit hit = {
        .shape = rb_make_shape_id(world, index),
        .body = rb_make_body_id(world, shape->body),
        .point = cast.point,
        .normal = cast.normal,
        .fraction = cast.fraction,
    };
    if (q->closest) {
        if (!q->found || ray_hit_before(&hit, &q->best)) {
            q->best = hit;
            q->found = true;
        }
        return true;
    }
    /* Insertion into the sorted array of the nearest `capacity` hits. */
    int kept = q->count < q->capacity ? q->count : q->capacity;
    int slot = kept;
    while (slot > 0 && ray_hit_before(&hit, &q->out[slot - 1])) {
        if (slot < q->capacity) {
            q->out[slot] = q->out[slot - 1];
        }
        --slot;
    }
    if (slot < q->capacity) {
        q->out[slot] = hit;
    }
    q->count++;
    return true;
}

/* The box the ray sweeps. */
static rb_aabb ray_box(rb_vec2 origin, rb_vec2 translation)
{
    rb_vec2 end = rb_add(origin, translation);
    return (rb_aabb){rb_vmin(origin, end), rb_vmax(origin, end)};
}

static rb_status check_ray(const char *f, const rb_world *world, rb_vec2 origin, rb_vec2 translation)
{
    RB_TRY(rb_check_pointer(f, "world", world));
    RB_TRY(rb_check_vec2(f, "origin", origin));
    RB_TRY(rb_check_vec2(f, "translation", translation));
    if (!rb_vec2_is_finite(rb_add(origin, translation))) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: origin + translation overflows", f);
    }
    return RB_OK;
}

rb_status rb_world_ray_cast_closest(const rb_world *world, rb_vec2 origin, rb_vec2 translation, rb_query_filter filter,
                                    bool include_sensors, rb_ray_hit *hit, bool *found)
{
    const char *f = "rb_world_ray_cast_closest";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "hit", hit));
    RB_TRY(rb_check_pointer(f, "found", found));
    *hit = (rb_ray_hit){0};
    *found = false;
    RB_TRY(check_ray(f, world, origin, translation));
    ray_query q = {.origin = origin,
                   .translation = translation,
                   .filter = filter,
                   .include_sensors = include_sensors,
                   .closest = true};
    rb_broad_phase_query(world, ray_box(origin, translation), visit_ray, &q);
    *hit = q.best;
    *found = q.found;
    return RB_OK;
}

rb_status rb_world_ray_cast_all(const rb_world *world, rb_vec2 origin, rb_vec2 translation, rb_query_filter filter,
                                bool include_sensors, rb_ray_hit *out, int capacity, int *count)
{
    const char *f = "rb_world_ray_cast_all";
    rb_clear_error();
    RB_TRY(check_output(f, out, capacity, count));
    *count = 0;
    RB_TRY(check_ray(f, world, origin, translation));
    ray_query q = {.origin = origin,
                   .translation = translation,
                   .filter = filter,
                   .include_sensors = include_sensors,
                   .out = out,
                   .capacity = capacity};
    rb_broad_phase_query(world, ray_box(origin, translation), visit_ray, &q);
    *count = q.count;
    return RB_OK;
}
