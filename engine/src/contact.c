/* SPDX-License-Identifier: MIT */
/* Contacts: created and dropped as broad-phase pairs come and go, given
 * a manifold each step, carrying solver impulses between steps, and
 * reporting when they begin and end touching. */

#include "allocator.h"
#include "contact.h"
#include "contact_events.h"
#include "error.h"
#include "manifold_internal.h"

static int compare_pair_keys(const rb_pair *p, const rb_pair *q)
{
    if (p->body_key != q->body_key) {
        return p->body_key < q->body_key ? -1 : 1;
    }
    return (p->shape_key > q->shape_key) - (p->shape_key < q->shape_key);
}

/* The mixing rules: the geometric mean of the two frictions, so that a
 * frictionless shape slides on anything, and the larger restitution, so
 * that a bouncy ball bounces on a dead floor. They depend on the shapes'
 * materials alone, so a contact mixes them when it begins and again when
 * a shape's material changes (rb_contacts_mix_materials), not each step. */
static void mix_materials(const rb_world *world, rb_contact *contact)
{
    const rb_shape *a = &world->shapes[contact->pair.shape_a];
    const rb_shape *b = &world->shapes[contact->pair.shape_b];
    contact->friction = sqrt(a->friction * b->friction);
    contact->restitution = fmax(a->restitution, b->restitution);
}

static rb_contact new_contact(const rb_world *world, const rb_pair *pair)
{
    const rb_shape *a = &world->shapes[pair->shape_a];
    const rb_shape *b = &world->shapes[pair->shape_b];
    rb_contact contact = {
        .pair = *pair,
        .body_a = a->body,
        .body_b = b->body,
        .sensor = a->sensor || b->sensor,
    };
    mix_materials(world, &contact);
    return contact;
}

void rb_contacts_mix_materials(rb_world *world, int shape)
{
    for (int i = 0; i < world->contact_count; ++i) {
        rb_contact *contact = &world->contacts[i];
        if (contact->pair.shape_a == shape || contact->pair.shape_b == shape) {
            mix_materials(world, contact);
        }
    }
}

/* Swaps the contacts with the spare array the merges wrote. */
static void take_merged_contacts(rb_world *world, int count)
{
    rb_contact *swap = world->contacts;
    int swap_capacity = world->contact_capacity;
    world->contacts = world->spare_contacts;
    world->contact_capacity = world->spare_capacity;
    world->spare_contacts = swap;
    world->spare_capacity = swap_capacity;
    world->contact_count = count;
}

static rb_status reserve_spare_contacts(rb_world *world, int count)
{
    if (rb_grow_array((void **)&world->spare_contacts, &world->spare_capacity, count, sizeof *world->spare_contacts) !=
        0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for contacts");
    }
    return RB_OK;
}

/* After a full search: the contacts become world->pairs. Both lists are
 * sorted by key, so one merge pass matches them; an old contact the
 * merge passes over has lost its pair and ends. */
static rb_status follow_all_pairs(rb_world *world)
{
    RB_TRY(reserve_spare_contacts(world, world->pair_count));
    int old = 0;
    int made = 0;
    int ended = 0;
    for (int i = 0; i < world->pair_count; ++i) {
        const rb_pair *pair = &world->pairs[i];
        for (; old < world->contact_count && compare_pair_keys(&world->contacts[old].pair, pair) < 0; ++old, ++ended) {
            rb_contact_events_drop(world, &world->contacts[old]);
        }
        bool kept = old < world->contact_count && compare_pair_keys(&world->contacts[old].pair, pair) == 0;
        made += kept ? 0 : 1;
        world->spare_contacts[i] = kept ? world->contacts[old++] : new_contact(world, pair);
    }
    for (; old < world->contact_count; ++old, ++ended) {
        rb_contact_events_drop(world, &world->contacts[old]);
    }
    take_merged_contacts(world, world->pair_count);
    world->statistics.broad_phase_new_pairs = made;
    world->statistics.broad_phase_ended_pairs = ended;
    return RB_OK;
}

/* Otherwise: the pairs that began are merged in, those that ended are
 * dropped, in one pass, since all three lists are sorted by key. A pair
 * listed as begun that is already a contact, or as ended that is none,
 * leaves the contacts as they are. */
static rb_status follow_pair_changes(rb_world *world)
{
    RB_TRY(reserve_spare_contacts(world, world->contact_count + world->new_pair_count));
    const rb_pair *begun = world->new_pairs;
    const rb_pair *ended = world->ended_pairs;
    int b = 0;
    int e = 0;
    int count = 0;
    int made = 0;
    int dropped = 0;
    for (int old = 0; old < world->contact_count; ++old) {
        const rb_contact *contact = &world->contacts[old];
        for (; b < world->new_pair_count && compare_pair_keys(&begun[b], &contact->pair) < 0; ++b, ++made) {
            world->spare_contacts[count++] = new_contact(world, &begun[b]);
        }
        if (b < world->new_pair_count && compare_pair_keys(&begun[b], &contact->pair) == 0) {
            ++b; /* already a contact */
        }
        while (e < world->ended_pair_count && compare_pair_keys(&ended[e], &contact->pair) < 0) {
            ++e;
        }
        if (e < world->ended_pair_count && compare_pair_keys(&ended[e], &contact->pair) == 0) {
            rb_contact_events_drop(world, contact);
            ++dropped;
            ++e;
            continue;
        }
        world->spare_contacts[count++] = *contact;
    }
    for (; b < world->new_pair_count; ++b, ++made) {
        world->spare_contacts[count++] = new_contact(world, &begun[b]);
    }
    take_merged_contacts(world, count);
    world->statistics.broad_phase_new_pairs = made;
    world->statistics.broad_phase_ended_pairs = dropped;
    return RB_OK;
}

/* Each contact is a pair of the broad phase. When no pair began or
 * ended (a pile at rest) the contacts are left as they are: no copy. */
rb_status rb_contacts_update(rb_world *world)
{
    RB_TRY(rb_contact_events_start_step(world));
    world->statistics.broad_phase_new_pairs = 0;
    world->statistics.broad_phase_ended_pairs = 0;
    if (world->pairs_rebuilt) {
        RB_TRY(follow_all_pairs(world));
    } else if (world->new_pair_count > 0 || world->ended_pair_count > 0) {
        RB_TRY(follow_pair_changes(world));
    }
    return rb_contact_events_reserve_begins(world);
}

/* A manifold computed with the shapes swapped, told from A to B again:
 * the normal turns round, and between outlines the reference face
 * changes side and each id's vertex pair its order. Circle points keep
 * id 0. */
static rb_manifold flip_manifold(rb_manifold m, bool outlines)
{
    m.normal = rb_neg(m.normal);
    if (outlines) {
        m.reference_on_b = !m.reference_on_b;
        for (int i = 0; i < m.point_count; ++i) {
            uint32_t id = m.points[i].id;
            m.points[i].id = rb_feature_id((int)(id & 0xffu), (int)(id >> 8));
        }
    }
    return m;
}

/* The manifold with a segment or chain segment `s` as shape A. */
static rb_manifold collide_segment(const rb_shape *s, rb_transform xfs, const rb_shape *other, rb_transform xfo,
                                   double speculative_distance)
{
    bool chain = s->type == RB_SHAPE_CHAIN_SEGMENT;
    if (other->type == RB_SHAPE_CIRCLE) {
        return chain ? rb_collide_chain_segment_and_circle(&s->geometry.chain_segment, xfs, &other->geometry.circle,
                                                           xfo, speculative_distance)
                     : rb_collide_segment_and_circle(&s->geometry.segment, xfs, &other->geometry.circle, xfo,
                                                     speculative_distance);
    }
    if (other->type == RB_SHAPE_POLYGON) {
        return chain ? rb_collide_chain_segment_and_polygon(&s->geometry.chain_segment, xfs, &other->geometry.polygon,
                                                            xfo, speculative_distance)
                     : rb_collide_segment_and_polygon(&s->geometry.segment, xfs, &other->geometry.polygon, xfo,
                                                      speculative_distance);
    }
    return (rb_manifold){0}; /* segments do not collide with segments */
}

static bool is_segment(const rb_shape *shape)
{
    return shape->type == RB_SHAPE_SEGMENT || shape->type == RB_SHAPE_CHAIN_SEGMENT;
}

static rb_manifold compute_manifold(const rb_world *world, const rb_contact *contact, double speculative_distance)
{
    const rb_shape *a = &world->shapes[contact->pair.shape_a];
    const rb_shape *b = &world->shapes[contact->pair.shape_b];
    rb_transform xfa = rb_body_origin_transform(world, a->body);
    rb_transform xfb = rb_body_origin_transform(world, b->body);
    if (is_segment(a)) {
        return collide_segment(a, xfa, b, xfb, speculative_distance);
    }
    if (is_segment(b)) {
        return flip_manifold(collide_segment(b, xfb, a, xfa, speculative_distance), a->type == RB_SHAPE_POLYGON);
    }
    if (a->type == RB_SHAPE_CIRCLE && b->type == RB_SHAPE_CIRCLE) {
        return rb_collide_circles(&a->geometry.circle, xfa, &b->geometry.circle, xfb, speculative_distance);
    }
    if (a->type == RB_SHAPE_POLYGON && b->type == RB_SHAPE_CIRCLE) {
        return rb_collide_polygon_and_circle(&a->geometry.polygon, xfa, &b->geometry.circle, xfb, speculative_distance);
    }
    if (a->type == RB_SHAPE_CIRCLE && b->type == RB_SHAPE_POLYGON) {
        return flip_manifold(
            rb_collide_polygon_and_circle(&b->geometry.polygon, xfb, &a->geometry.circle, xfa, speculative_distance),
            false);
    }
    /* rb_collide_polygons, with shape A's test for a box made once. */
    return a->box
               ? rb_collide_box_and_polygon(&a->geometry.polygon, xfa, &b->geometry.polygon, xfb, speculative_distance)
               : rb_collide_convex_polygons(&a->geometry.polygon, xfa, &b->geometry.polygon, xfb, speculative_distance);
}

double rb_contact_deepest_overlap_now(const rb_world *world, const rb_contact *contact)
{
    rb_manifold now = compute_manifold(world, contact, 0.0);
    double deepest = 0.0;
    for (int j = 0; j < now.point_count; ++j) {
        deepest = fmax(deepest, -now.points[j].separation);
    }
    return deepest;
}

/* How close the two shapes must be for a speculative point: the base
 * distance plus how far their surfaces can approach in dt. */
static double contact_speculative_distance(const rb_world *world, const rb_contact *contact, double dt)
{
    const rb_body_state *sa = &world->states[contact->body_a];
    const rb_body_state *sb = &world->states[contact->body_b];
    double extent_a = world->shapes[contact->pair.shape_a].extent;
    double extent_b = world->shapes[contact->pair.shape_b].extent;
    double approach = rb_length(rb_sub(sb->linear_velocity, sa->linear_velocity)) +
                      fabs(sa->angular_velocity) * extent_a + fabs(sb->angular_velocity) * extent_b;
    return RB_SPECULATIVE_SLOPS * world->settings.linear_slop + dt * approach;
}

static bool manifold_touches(const rb_manifold *m)
{
    for (int j = 0; j < m->point_count; ++j) {
        if (m->points[j].separation <= 0.0) {
            return true;
        }
    }
    return false;
}

/* Copies the impulses of old points onto new points with the same feature. */
static void carry_impulses(const rb_manifold *old, rb_manifold *fresh)
{
    for (int i = 0; i < fresh->point_count; ++i) {
        for (int j = 0; j < old->point_count; ++j) {
            if (fresh->points[i].id == old->points[j].id) {
                fresh->points[i].normal_impulse = old->points[j].normal_impulse;
                fresh->points[i].tangent_impulse = old->points[j].tangent_impulse;
                break;
            }
        }
    }
}

void rb_contacts_collide(rb_world *world, double dt)
{
    bool warm = world->settings.warm_starting;
    for (int i = 0; i < world->contact_count; ++i) {
        rb_contact *contact = &world->contacts[i];
        if (!rb_contact_may_meet_in_step(world, contact)) {
            /* No point, and an end event if it was touching. */
            contact->manifold.point_count = 0;
            contact->touching = false;
            if (!contact->sensor) {
                rb_contact_events_update(world, contact);
            }
            continue;
        }
        rb_manifold fresh = compute_manifold(world, contact, contact_speculative_distance(world, contact, dt));
        if (warm) {
            carry_impulses(&contact->manifold, &fresh);
        }
        contact->manifold = fresh;
        contact->touching = manifold_touches(&fresh);
        if (!contact->sensor) {
            rb_contact_events_update(world, contact);
            if (fresh.point_count > 0 && !rb_contact_events_pre_solve(world, contact)) {
                contact->manifold.point_count = 0; /* disabled for this step */
            }
        }

        /* A moving body that reaches a sleeping one wakes it. */
        rb_body *body_a = &world->bodies[contact->body_a];
        rb_body *body_b = &world->bodies[contact->body_b];
        if (!contact->sensor && fresh.point_count > 0 && body_a->awake != body_b->awake) {
            bool a_moves = body_a->awake && body_a->type != RB_BODY_STATIC;
            bool b_moves = body_b->awake && body_b->type != RB_BODY_STATIC;
            if (a_moves || b_moves) {
                body_a->awake = body_b->awake = true;
            }
        }
    }
}

void rb_contacts_update_sensors(rb_world *world)
{
    for (int i = 0; i < world->contact_count; ++i) {
        rb_contact *contact = &world->contacts[i];
        if (contact->sensor) {
            contact->manifold =
                rb_contact_may_meet_in_step(world, contact) ? compute_manifold(world, contact, 0.0) : (rb_manifold){0};
            contact->touching = manifold_touches(&contact->manifold);
            rb_contact_events_update_sensor(world, contact);
        }
    }
}

rb_status rb_contacts_remove_shape(rb_world *world, int shape)
{
    RB_TRY(rb_contact_events_remove_shape(world, shape));
    int kept = 0;
    for (int i = 0; i < world->contact_count; ++i) {
        const rb_contact *c = &world->contacts[i];
        if (c->pair.shape_a != shape && c->pair.shape_b != shape) {
            world->contacts[kept++] = *c;
        }
    }
    world->contact_count = kept;
    return RB_OK;
}
