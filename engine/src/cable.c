/* SPDX-License-Identifier: MIT */
/* Cables: creation, read-outs, and the implicit tension law in the
 * solver.
 *
 * With J the map from body velocities to the lengthening speed L' and
 * k = J·M⁻¹·Jᵀ, an impulse P of tension shortens the path at k·P. The
 * substep's tension impulse P = h·T must satisfy the law at the end of
 * the substep, T = T0 + c·(L' - k·(P - P_acc)), with P_acc what was
 * applied so far, which gives
 *     P = h·(T0 + c·L' + c·k·P_acc) / (1 + h·c·k),   clamped to P >= 0.
 * This is the backward-Euler step of the damper (Hairer and Wanner,
 * "Solving ODEs II", 1996, §IV.1): stable for any c, where the explicit
 * force c·L' diverges once h·c·k > 2. Only L' and P_acc change within a
 * substep, so the law's three gains are made once a substep and a pass
 * multiplies: in a pass each cable waits on the velocities the one before
 * it left, and a division there would lengthen that chain of waits. */
#include <float.h>
#include <string.h>

#include "allocator.h"
#include "cable_solver.h"
#include "error.h"
#include "sleep.h"

rb_cable_def rb_default_cable_def(void) { return (rb_cable_def){.internal_value = RB_DEF_COOKIE}; }

/* A point at `from_center` from a body's centre of mass in its frame,
 * in the world: turned with the body (no origin transform needed). */
static inline rb_vec2 place(const rb_body_state *s, rb_vec2 from_center)
{
    return rb_add(s->center, rb_rotate(s->rotation, from_center));
}

/* A point of the path in the world. */
static inline rb_vec2 world_point(const rb_world *world, const rb_cable *cable, int i)
{
    return place(&world->states[cable->bodies[i]],
                 rb_sub(cable->local_points[i], world->bodies[cable->bodies[i]].local_center));
}

rb_status rb_cable_create(rb_world *world, const rb_cable_def *def, rb_cable_id *out)
{
    const char *f = "rb_cable_create";
    rb_clear_error();
    RB_TRY(rb_check_pointer(f, "out", out));
    *out = (rb_cable_id){0};
    RB_TRY(rb_check_pointer(f, "def", def));
    RB_TRY(rb_check_def_cookie(f, "rb_default_cable_def", def->internal_value));
    RB_TRY(rb_check_pointer(f, "world", world));
    RB_TRY(rb_world_check_unlocked(world, f));
    if (def->point_count < 2 || def->point_count > RB_MAX_CABLE_POINTS) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: point_count is %d, expected 2 to %d", f, def->point_count,
                               RB_MAX_CABLE_POINTS);
    }
    rb_cable cable = {.point_count = def->point_count, .user_data = def->user_data};
    for (int i = 0; i < def->point_count; ++i) {
        RB_TRY(rb_world_find_body(world, def->bodies[i], f, &cable.bodies[i]));
        RB_TRY(rb_check_point(f, "local_points[i]", def->local_points[i]));
        cable.local_points[i] = def->local_points[i];
        /* The path's distinct bodies, in the order of their first point:
         * the places of their shares of the tension (rb_cables_prepare). */
        int place = 0;
        while (place < cable.body_count && cable.path_bodies[place] != cable.bodies[i]) {
            ++place;
        }
        if (place == cable.body_count) {
            cable.path_bodies[cable.body_count++] = cable.bodies[i];
        }
        cable.point_places[i] = place;
    }
    for (int i = 0; i + 1 < def->point_count; ++i) {
        if (rb_distance(world_point(world, &cable, i), world_point(world, &cable, i + 1)) < RB_POLYGON_WELD_DISTANCE) {
            return rb_report_error(RB_ERR_DEGENERATE_SHAPE, "%s: points %d and %d coincide", f, i, i + 1);
        }
    }
    int index = -1;
    if (world->cable_free >= 0) {
        index = world->cable_free;
        world->cable_free = world->cables[index].next_free;
    } else {
        if (rb_grow_array((void **)&world->cables, &world->cable_capacity, world->cable_slots + 1,
                          sizeof *world->cables) != 0) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
        }
        index = world->cable_slots++;
        world->cables[index].generation = 0;
    }
    cable.generation = world->cables[index].generation + 1u;
    cable.in_use = true;
    world->cables[index] = cable;
    world->cable_count++;
    *out = (rb_cable_id){index, cable.generation, world->serial};
    return RB_OK;
}

/* Why an id names no cable of the world, reported in the name of
 * `function`. */
static rb_status report_bad_cable(const rb_world *world, rb_cable_id id, const char *function)
{
    if (world == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: world is NULL", function);
    }
    if (id.generation == 0 || id.world != world->serial || id.index < 0 || id.index >= world->cable_slots) {
        return rb_report_error(RB_ERR_FOREIGN_ID, "%s: the cable id is null or belongs to another world", function);
    }
    return rb_report_error(RB_ERR_STALE_ID, "%s: the cable id refers to a destroyed cable", function);
}

/* The slot of a live cable of the world; a muscle asks twice a substep,
 * so the test is inline and the report is not. The generation of a slot
 * in use is never 0, so a matching one also refuses the null id. */
static inline rb_status find_cable(const rb_world *world, rb_cable_id id, const char *function, int *index)
{
    if (world == NULL || id.world != world->serial || id.index < 0 || id.index >= world->cable_slots ||
        !world->cables[id.index].in_use || world->cables[id.index].generation != id.generation) {
        return report_bad_cable(world, id, function);
    }
    *index = id.index;
    return RB_OK;
}

static void free_cable(rb_world *world, int index)
{
    world->cables[index].in_use = false;
    if (world->cables[index].generation != RB_RETIRED_GENERATION) {
        world->cables[index].next_free = world->cable_free;
        world->cable_free = index;
    }
    world->cable_count--;
}

rb_status rb_cable_destroy(rb_world *world, rb_cable_id id)
{
    rb_clear_error();
    int index = -1;
    RB_TRY(find_cable(world, id, "rb_cable_destroy", &index));
    RB_TRY(rb_world_check_unlocked(world, "rb_cable_destroy"));
    free_cable(world, index);
    return RB_OK;
}

void rb_cables_remove_body(rb_world *world, int body)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        rb_cable *cable = &world->cables[c];
        for (int i = 0; cable->in_use && i < cable->point_count; ++i) {
            if (cable->bodies[i] == body) {
                free_cable(world, c);
            }
        }
    }
}

bool rb_cable_is_valid(const rb_world *world, rb_cable_id id)
{
    return world != NULL && id.generation != 0 && id.world == world->serial && id.index >= 0 &&
           id.index < world->cable_slots && world->cables[id.index].in_use &&
           world->cables[id.index].generation == id.generation;
}

rb_status rb_cable_set_tension_law(rb_world *world, rb_cable_id id, double base_tension, double damping)
{
    const char *f = "rb_cable_set_tension_law";
    rb_clear_error();
    int index = -1;
    RB_TRY(find_cable(world, id, f, &index));
    RB_TRY(rb_world_check_unlocked_or_in_substep_callback(world, f));
    RB_TRY(rb_check_bound(f, "base_tension", base_tension, RB_MAX_FORCE, "N"));
    RB_TRY(rb_check_range(f, "damping", damping, 0.0, RB_MAX_FORCE));
    rb_cable *cable = &world->cables[index];
    cable->base_tension = base_tension;
    cable->damping = damping;
    /* A law is set by something that drives the bodies (a muscle, every
     * substep), as a motor does: it wakes them and restarts their time at
     * rest, so they never sleep between two laws. Each of the path's
     * distinct bodies once: waking again changes nothing. */
    for (int b = 0; b < cable->body_count; ++b) {
        rb_body_wake(world, cable->path_bodies[b]);
    }
    return RB_OK;
}

/* ---- read-outs ---------------------------------------------------------------- */

/* A point's velocity v + ω × r from its body. */
static rb_vec2 point_velocity(const rb_world *world, int body, rb_vec2 point)
{
    const rb_body_state *s = &world->states[body];
    return rb_add(s->linear_velocity, rb_cross_sv(s->angular_velocity, rb_sub(point, s->center)));
}

/* Length and lengthening speed in one pass over the path: L is the sum
 * of the segments, L' = Σ u·(v_{i+1} - v_i) with each point's velocity
 * v + ω × r from its body. In the substep callback nothing moves, so the
 * points and segments rb_cables_locate found serve; elsewhere they are
 * found here, the same way. */
static void measure(const rb_world *world, const rb_cable *cable, double *length, double *speed)
{
    rb_vec2 found_points[RB_MAX_CABLE_POINTS];
    double found_lengths[RB_MAX_CABLE_POINTS - 1];
    const rb_vec2 *points = cable->points;
    const double *segment_lengths = cable->segment_lengths;
    if (!(world->in_substep_callback && world->cable_points_fresh)) {
        for (int i = 0; i < cable->point_count; ++i) {
            found_points[i] = world_point(world, cable, i);
        }
        for (int i = 0; i + 1 < cable->point_count; ++i) {
            found_lengths[i] = rb_length(rb_sub(found_points[i + 1], found_points[i]));
        }
        points = found_points;
        segment_lengths = found_lengths;
    }
    double total = 0.0;
    double rate = 0.0;
    rb_vec2 vp = point_velocity(world, cable->bodies[0], points[0]);
    for (int i = 0; i + 1 < cable->point_count; ++i) {
        rb_vec2 vq = point_velocity(world, cable->bodies[i + 1], points[i + 1]);
        total += segment_lengths[i];
        if (segment_lengths[i] > 0.0) {
            rate += rb_dot(rb_sub(points[i + 1], points[i]), rb_sub(vq, vp)) / segment_lengths[i];
        }
        vp = vq; /* each point's velocity is made once */
    }
    *length = total;
    *speed = rate;
}

rb_status rb_cable_state(const rb_world *world, rb_cable_id id, double *length, double *lengthening_speed)
{
    rb_clear_error();
    int index = -1;
    RB_TRY(find_cable(world, id, "rb_cable_state", &index));
    RB_TRY(rb_check_pointer("rb_cable_state", "length", length));
    RB_TRY(rb_check_pointer("rb_cable_state", "lengthening_speed", lengthening_speed));
    measure(world, &world->cables[index], length, lengthening_speed);
    return RB_OK;
}

rb_status rb_cable_read(const rb_world *world, rb_cable_id id, rb_cable_reading *out)
{
    rb_clear_error();
    RB_TRY(rb_check_pointer("rb_cable_read", "out", out));
    *out = (rb_cable_reading){0};
    int index = -1;
    RB_TRY(find_cable(world, id, "rb_cable_read", &index));
    const rb_cable *cable = &world->cables[index];
    measure(world, cable, &out->length, &out->lengthening_speed);
    out->tension = cable->impulse / world->last_substep;
    return RB_OK;
}

double rb_cable_length(const rb_world *world, rb_cable_id id)
{
    double length = 0.0;
    double speed = 0.0;
    return rb_cable_state(world, id, &length, &speed) == RB_OK ? length : 0.0;
}

double rb_cable_lengthening_speed(const rb_world *world, rb_cable_id id)
{
    double length = 0.0;
    double speed = 0.0;
    return rb_cable_state(world, id, &length, &speed) == RB_OK ? speed : 0.0;
}

double rb_cable_tension(const rb_world *world, rb_cable_id id)
{
    rb_clear_error();
    int index = -1;
    if (find_cable(world, id, "rb_cable_tension", &index) != RB_OK) {
        return 0.0;
    }
    return world->cables[index].impulse / world->last_substep;
}

int rb_cable_points(const rb_world *world, rb_cable_id id, rb_vec2 *out, int capacity)
{
    rb_clear_error();
    int index = -1;
    if (find_cable(world, id, "rb_cable_points", &index) != RB_OK) {
        return 0;
    }
    if (out == NULL && capacity > 0) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "rb_cable_points: out is NULL");
        return 0;
    }
    const rb_cable *cable = &world->cables[index];
    int count = cable->point_count < capacity ? cable->point_count : capacity;
    for (int i = 0; i < count; ++i) {
        out[i] = world_point(world, cable, i);
    }
    return count;
}

/* ---- solver --------------------------------------------------------------------- */

void rb_cables_prepare_step(rb_world *world)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        rb_cable *cable = &world->cables[c];
        for (int i = 0; cable->in_use && i < cable->point_count; ++i) {
            cable->from_centers[i] = rb_sub(cable->local_points[i], world->bodies[cable->bodies[i]].local_center);
        }
    }
}

void rb_cables_locate(rb_world *world)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        rb_cable *cable = &world->cables[c];
        if (!cable->in_use) {
            continue;
        }
        for (int i = 0; i < cable->point_count; ++i) {
            cable->points[i] = place(&world->states[cable->bodies[i]], cable->from_centers[i]);
        }
        for (int i = 0; i + 1 < cable->point_count; ++i) {
            cable->segment_lengths[i] = rb_length(rb_sub(cable->points[i + 1], cable->points[i]));
        }
    }
    world->cable_points_fresh = true;
}

/* The unit vector of a segment of the given length: rb_normalize, with
 * the length the points were located with. */
static rb_vec2 unit_along(rb_vec2 segment, double length)
{
    return length < 1e-300 ? rb_v2(0.0, 0.0) : rb_scale(1.0 / length, segment);
}

void rb_cables_prepare(rb_world *world, double h)
{
    if (!world->cable_points_fresh) {
        rb_cables_locate(world);
    }
    world->cable_points_fresh = false;
    for (int c = 0; c < world->cable_slots; ++c) {
        rb_cable *cable = &world->cables[c];
        if (!cable->in_use) {
            continue;
        }
        /* Each point's pull, u_i - u_{i-1}, added to its body's share. A
         * body's share starts at its first point, which comes in the order
         * of point_places, as 0 + pull: the sum from 0 of the zeroed arrays
         * it replaces, -0 made +0 included, without zeroing them. */
        rb_vec2 linear[RB_MAX_CABLE_POINTS];
        double angular[RB_MAX_CABLE_POINTS];
        int started = 0; /* the shares started so far */
        const rb_vec2 *points = cable->points;
        rb_vec2 previous = rb_v2(0.0, 0.0); /* u_{i-1}; none before the origin */
        for (int i = 0; i < cable->point_count; ++i) {
            rb_vec2 next = i + 1 < cable->point_count
                               ? unit_along(rb_sub(points[i + 1], points[i]), cable->segment_lengths[i])
                               : rb_v2(0.0, 0.0);
            rb_vec2 pull = rb_sub(next, previous);
            int b = cable->point_places[i];
            double turn = rb_cross(rb_sub(points[i], world->states[cable->path_bodies[b]].center), pull);
            if (b == started) {
                linear[b] = rb_add(rb_v2(0.0, 0.0), pull);
                angular[b] = 0.0 + turn;
                ++started;
            } else {
                linear[b] = rb_add(linear[b], pull);
                angular[b] += turn;
            }
            previous = next;
        }
        /* k = Σ J·M⁻¹·Jᵀ over the bodies the impulse moves. A static body
         * would add 0·(its finite terms), +0, which leaves k as it is. */
        double k = 0.0;
        cable->share_count = 0;
        cable->moving_count = 0;
        cable->in_block = false; /* until a limb block takes it (rb_joint_blocks_factor) */
        for (int b = 0; b < cable->body_count; ++b) {
            const rb_body *body = &world->bodies[cable->path_bodies[b]];
            if (body->type == RB_BODY_STATIC) {
                continue;
            }
            bool moves = body->type == RB_BODY_DYNAMIC && body->awake;
            double inv_mass = moves ? body->inv_mass : 0.0;
            double inv_inertia = moves ? body->inv_inertia : 0.0;
            k += inv_mass * rb_dot(linear[b], linear[b]) + inv_inertia * angular[b] * angular[b];
            const rb_cable_share share = {
                .state = &world->states[cable->path_bodies[b]],
                .linear = linear[b],
                .angular = angular[b],
                .push_linear = rb_scale(inv_mass, linear[b]),
                .push_angular = inv_inertia * angular[b],
            };
            if (inv_mass > 0.0 || inv_inertia > 0.0) {
                cable->moving[cable->moving_count++] = share;
            }
            cable->shares[cable->share_count++] = share;
        }
        cable->inverse_mass = k;
        /* The law's gains for the substep: the substep callback set T0
         * and c before. */
        double gain = h / (1.0 + h * cable->damping * k);
        cable->speed_gain = gain * cable->damping;
        cable->base_impulse = gain * cable->base_tension;
        cable->impulse_gain = gain * cable->damping * k;
    }
}

/* Applies the impulse to the bodies it moves: a muscle's origin is often
 * on a fixed bone, which it would only add zeros to. */
static inline void apply(const rb_cable *cable, double impulse)
{
    for (int m = 0; m < cable->moving_count; ++m) {
        const rb_cable_share *share = &cable->moving[m];
        rb_body_state *s = share->state;
        s->linear_velocity = rb_mul_add(s->linear_velocity, impulse, share->push_linear);
        s->angular_velocity += impulse * share->push_angular;
    }
}

void rb_cables_warm_start(rb_world *world)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        if (world->cables[c].in_use) {
            apply(&world->cables[c], world->cables[c].impulse);
        }
    }
}

void rb_cables_solve(rb_world *world, double h)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        rb_cable *cable = &world->cables[c];
        if (!cable->in_use || cable->in_block) {
            continue; /* a block's cable is solved with the block (joint_block.c) */
        }
        /* L' = -Σ (pull · v + angular · ω): the pulls point inwards. A
         * static body's velocity is 0 and would add ±0: a sum from +0
         * never becomes -0, so leaving it out keeps the bits. */
        double speed = 0.0;
        for (int b = 0; b < cable->share_count; ++b) {
            const rb_cable_share *share = &cable->shares[b];
            const rb_body_state *s = share->state;
            speed -= rb_dot(share->linear, s->linear_velocity) + share->angular * s->angular_velocity;
        }
        if (cable->inverse_mass <= 0.0) {
            /* No tension can move the path's bodies (static, or kinematic
             * with imposed velocities): the tension is the law's at the
             * speed they impose, acting on nothing. */
            cable->impulse = h * fmax(cable->base_tension + cable->damping * speed, 0.0);
            continue;
        }
        double total = cable->speed_gain * speed + (cable->base_impulse + cable->impulse_gain * cable->impulse);
        total = total > 0.0 ? total : 0.0; /* fmax(total, 0), NaN and -0 included, without libm's call */
        apply(cable, total - cable->impulse);
        cable->impulse = total;
    }
}

void rb_cables_reset_impulses(rb_world *world)
{
    for (int c = 0; c < world->cable_slots; ++c) {
        world->cables[c].impulse = 0.0;
    }
}
