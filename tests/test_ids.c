/* SPDX-License-Identifier: MIT */
/* Ids never come back (rb/id.h): a destroyed object's id stays stale
 * however many objects its slot holds afterwards, and an id of one world
 * stays foreign to every world made after it, for every id kind (body,
 * shape, joint, cable). The 16-bit generations and world serials of old
 * wrapped after 65,535 objects or worlds; these tests go past that. A
 * generation near the end of its 32 bits is reached by setting it
 * (world_internal.h), since counting to it would take minutes. */
#include <criterion/criterion.h>
#include <stdint.h>

#include "rb/rb.h"
#include "test_support.h"
#include "world_internal.h"

/* More objects in one slot, or worlds, than a 16-bit number counts. */
#define PAST_16_BITS 70000

/* A world with two dynamic bodies, each with a circle, far apart: enough
 * for a joint and a cable between them. */
typedef struct pair_world {
    rb_world *world;
    rb_body_id a, b;
} pair_world;

static pair_world make_pair_world(void)
{
    pair_world p = {.world = make_world(rb_v2(0.0, -9.8))};
    p.a = make_body(p.world, RB_BODY_DYNAMIC, rb_v2(0.0, 0.0), 0.0);
    p.b = make_body(p.world, RB_BODY_DYNAMIC, rb_v2(2.0, 0.0), 0.0);
    add_circle(p.world, p.a, rb_v2(0.0, 0.0), 0.2, 1.0);
    add_circle(p.world, p.b, rb_v2(0.0, 0.0), 0.2, 1.0);
    return p;
}

/* One object of each kind, created and destroyed through the public API,
 * so that each kind's test below runs the same loop. */
typedef enum id_kind { KIND_BODY, KIND_SHAPE, KIND_JOINT, KIND_CABLE, KIND_COUNT } id_kind;
static const char *const kind_names[KIND_COUNT] = {"body", "shape", "joint", "cable"};

/* Any id, as the index and generation its kind carries. */
typedef struct any_id {
    rb_body_id body;
    rb_shape_id shape;
    rb_joint_id joint;
    rb_cable_id cable;
} any_id;

static any_id create_object(const pair_world *p, id_kind kind)
{
    any_id id = {0};
    switch (kind) {
    case KIND_BODY:
        id.body = make_body(p->world, RB_BODY_DYNAMIC, rb_v2(5.0, 0.0), 0.0);
        break;
    case KIND_SHAPE:
        id.shape = add_circle(p->world, p->a, rb_v2(0.1, 0.0), 0.1, 1.0);
        break;
    case KIND_JOINT:
        id.joint = make_pin(p->world, p->a, p->b, rb_v2(1.0, 0.0));
        break;
    case KIND_CABLE: {
        rb_cable_def def = rb_default_cable_def();
        def.point_count = 2;
        def.bodies[0] = p->a;
        def.bodies[1] = p->b;
        cr_assert_eq(rb_cable_create(p->world, &def, &id.cable), RB_OK, "rb_cable_create: %s", rb_last_error());
        break;
    }
    case KIND_COUNT:
        break;
    }
    return id;
}

static rb_status destroy_object(rb_world *world, id_kind kind, any_id id)
{
    switch (kind) {
    case KIND_BODY:
        return rb_body_destroy(world, id.body);
    case KIND_SHAPE:
        return rb_shape_destroy(world, id.shape);
    case KIND_JOINT:
        return rb_joint_destroy(world, id.joint);
    case KIND_CABLE:
        return rb_cable_destroy(world, id.cable);
    case KIND_COUNT:
        break;
    }
    return RB_ERR_INVALID_ARGUMENT;
}

static bool is_valid(const rb_world *world, id_kind kind, any_id id)
{
    switch (kind) {
    case KIND_BODY:
        return rb_body_is_valid(world, id.body);
    case KIND_SHAPE:
        return rb_shape_is_valid(world, id.shape);
    case KIND_JOINT:
        return rb_joint_is_valid(world, id.joint);
    case KIND_CABLE:
        return rb_cable_is_valid(world, id.cable);
    case KIND_COUNT:
        break;
    }
    return false;
}

static int32_t index_of(id_kind kind, any_id id)
{
    const int32_t indices[KIND_COUNT] = {id.body.index, id.shape.index, id.joint.index, id.cable.index};
    return indices[kind];
}

/* Creates and destroys an object of `kind` PAST_16_BITS times, always in
 * the slot of the first; the first one's id must stay stale throughout. */
static void expect_stale_after_many_objects(id_kind kind)
{
    pair_world p = make_pair_world();
    const any_id first = create_object(&p, kind);
    cr_assert_eq(destroy_object(p.world, kind, first), RB_OK, "%s", rb_last_error());
    for (int i = 1; i <= PAST_16_BITS; ++i) {
        const any_id next = create_object(&p, kind);
        cr_assert_eq(index_of(kind, next), index_of(kind, first), "%s %d did not reuse the freed slot",
                     kind_names[kind], i);
        cr_assert_not(is_valid(p.world, kind, first), "the first %s's id is valid again after %d %ss in its slot",
                      kind_names[kind], i, kind_names[kind]);
        cr_assert_eq(destroy_object(p.world, kind, next), RB_OK, "%s", rb_last_error());
    }
    cr_expect_eq(destroy_object(p.world, kind, first), RB_ERR_STALE_ID, "destroying the first %s's id again: %s",
                 kind_names[kind], rb_last_error());
    destroy_world_and_expect_no_leak(p.world);
}

Test(ids, a_body_id_stays_stale_past_65535_bodies_in_its_slot) { expect_stale_after_many_objects(KIND_BODY); }
Test(ids, a_shape_id_stays_stale_past_65535_shapes_in_its_slot) { expect_stale_after_many_objects(KIND_SHAPE); }
Test(ids, a_joint_id_stays_stale_past_65535_joints_in_its_slot) { expect_stale_after_many_objects(KIND_JOINT); }
Test(ids, a_cable_id_stays_stale_past_65535_cables_in_its_slot) { expect_stale_after_many_objects(KIND_CABLE); }

/* The generation the slot of `id` holds, by reference. */
static uint32_t *slot_generation(rb_world *world, id_kind kind, any_id id)
{
    switch (kind) {
    case KIND_BODY:
        return &world->bodies[id.body.index].generation;
    case KIND_SHAPE:
        return &world->shapes[id.shape.index].generation;
    case KIND_JOINT:
        return &world->joints[id.joint.index].generation;
    case KIND_CABLE:
        return &world->cables[id.cable.index].generation;
    case KIND_COUNT:
        break;
    }
    return NULL;
}

/* A slot whose generation reaches the last 32-bit value is retired: the
 * object made at that generation gets it, and once it is destroyed the
 * slot is never used again, so no generation wraps to an old id's. */
static void expect_slot_retired_at_the_last_generation(id_kind kind)
{
    pair_world p = make_pair_world();
    const any_id probe = create_object(&p, kind);
    cr_assert_eq(destroy_object(p.world, kind, probe), RB_OK, "%s", rb_last_error());
    /* As if the slot had held 2^32 - 2 objects. */
    *slot_generation(p.world, kind, probe) = UINT32_MAX - 1u;
    const any_id last = create_object(&p, kind);
    cr_assert_eq(index_of(kind, last), index_of(kind, probe), "the %s slot was not reused", kind_names[kind]);
    cr_assert(is_valid(p.world, kind, last), "the %s of the slot's last generation is not valid", kind_names[kind]);
    cr_assert_eq(destroy_object(p.world, kind, last), RB_OK, "%s", rb_last_error());
    for (int i = 0; i < 3; ++i) {
        const any_id next = create_object(&p, kind);
        cr_expect_neq(index_of(kind, next), index_of(kind, last), "a %s went into the retired slot", kind_names[kind]);
        cr_expect_not(is_valid(p.world, kind, last), "the last generation's %s id is valid again", kind_names[kind]);
        cr_expect(is_valid(p.world, kind, next), "the new %s is not valid", kind_names[kind]);
    }
    cr_expect_eq(destroy_object(p.world, kind, last), RB_ERR_STALE_ID, "destroying the retired %s's id: %s",
                 kind_names[kind], rb_last_error());
    destroy_world_and_expect_no_leak(p.world);
}

Test(ids, a_body_slot_is_retired_at_its_last_generation) { expect_slot_retired_at_the_last_generation(KIND_BODY); }
Test(ids, a_shape_slot_is_retired_at_its_last_generation) { expect_slot_retired_at_the_last_generation(KIND_SHAPE); }
Test(ids, a_joint_slot_is_retired_at_its_last_generation) { expect_slot_retired_at_the_last_generation(KIND_JOINT); }
Test(ids, a_cable_slot_is_retired_at_its_last_generation) { expect_slot_retired_at_the_last_generation(KIND_CABLE); }

/* World A's ids of every kind stay foreign to each of the PAST_16_BITS
 * worlds made after it, whose objects sit in the same slots with the
 * same generations. */
Test(ids, ids_stay_foreign_past_65535_worlds)
{
    pair_world a = make_pair_world();
    any_id ids_a[KIND_COUNT];
    for (int k = 0; k < KIND_COUNT; ++k) {
        ids_a[k] = create_object(&a, (id_kind)k);
    }
    for (int i = 1; i <= PAST_16_BITS; ++i) {
        pair_world b = make_pair_world();
        for (int k = 0; k < KIND_COUNT; ++k) {
            const any_id id_b = create_object(&b, (id_kind)k);
            cr_assert_eq(index_of((id_kind)k, id_b), index_of((id_kind)k, ids_a[k]),
                         "world B's %s is not in world A's slot", kind_names[k]);
            cr_assert_not(is_valid(b.world, (id_kind)k, ids_a[k]),
                          "world A's %s id is valid in the world made %d after it", kind_names[k], i);
        }
        for (int k = KIND_COUNT - 1; k >= 0; --k) {
            cr_assert_eq(destroy_object(b.world, (id_kind)k, ids_a[k]), RB_ERR_FOREIGN_ID,
                         "the world made %d after world A destroying A's %s: %s", i, kind_names[k], rb_last_error());
        }
        rb_world_destroy(b.world);
    }
    destroy_world_and_expect_no_leak(a.world);
}
