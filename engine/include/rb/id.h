/* SPDX-License-Identifier: MIT */
/** @file
 * Handles to the objects of a world.
 *
 * An id is a slot index, the generation of the slot (bumped each time an
 * object is created in it) and the serial number of the world that made
 * it: 16 bytes, passed by value in two registers. Passing a destroyed
 * object's id gives RB_ERR_STALE_ID; an id of another world, or the null
 * id, gives RB_ERR_FOREIGN_ID.
 *
 * Neither number ever comes back, so a stale or foreign id is told apart
 * however long a program runs: world serials are 64-bit (a world a
 * nanosecond would take 584 years to wrap them), and a slot whose
 * generation reaches UINT32_MAX is retired instead of reused (it costs
 * one slot's memory every 4 billion objects created in it).
 */
#ifndef RB_ID_H
#define RB_ID_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rb_body_id {
    int32_t index;       /**< the slot */
    uint32_t generation; /**< of the slot when the object was made; 0 in the null id */
    uint64_t world;      /**< the serial number of the world */
} rb_body_id;

typedef struct rb_shape_id {
    int32_t index;       /**< the slot */
    uint32_t generation; /**< of the slot when the object was made; 0 in the null id */
    uint64_t world;      /**< the serial number of the world */
} rb_shape_id;

typedef struct rb_joint_id {
    int32_t index;       /**< the slot */
    uint32_t generation; /**< of the slot when the object was made; 0 in the null id */
    uint64_t world;      /**< the serial number of the world */
} rb_joint_id;

typedef struct rb_cable_id {
    int32_t index;       /**< the slot */
    uint32_t generation; /**< of the slot when the object was made; 0 in the null id */
    uint64_t world;      /**< the serial number of the world */
} rb_cable_id;

static inline bool rb_body_id_is_null(rb_body_id id) { return id.generation == 0; }
static inline bool rb_shape_id_is_null(rb_shape_id id) { return id.generation == 0; }
static inline bool rb_joint_id_is_null(rb_joint_id id) { return id.generation == 0; }
static inline bool rb_cable_id_is_null(rb_cable_id id) { return id.generation == 0; }
static inline bool rb_body_id_equals(rb_body_id a, rb_body_id b)
{
    return a.index == b.index && a.world == b.world && a.generation == b.generation;
}
static inline bool rb_shape_id_equals(rb_shape_id a, rb_shape_id b)
{
    return a.index == b.index && a.world == b.world && a.generation == b.generation;
}

static inline bool rb_joint_id_equals(rb_joint_id a, rb_joint_id b)
{
    return a.index == b.index && a.world == b.world && a.generation == b.generation;
}

#ifdef __cplusplus
}
#endif

#endif
