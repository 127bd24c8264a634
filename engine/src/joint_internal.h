/* What the joint types' creation functions share with joint.c. */
#ifndef RB_JOINT_INTERNAL_H
#define RB_JOINT_INTERNAL_H

#include "world_internal.h"

/* Looks both bodies up; fails when either is invalid or they are one body. */
rb_status rb_joint_check_bodies(const rb_world *world, rb_body_id a, rb_body_id b, const char *function, int *index_a,
                                int *index_b);

/* Adds a joint filled in from `prototype` (type, bodies, anchors, flags,
 * type data) to the world and the bodies' joint lists. */
rb_status rb_joint_create(rb_world *world, const rb_joint *prototype, rb_joint_id *out, const char *function);

/* Looks a joint up and checks its type. */
rb_status rb_joint_find_typed(const rb_world *world, rb_joint_id id, rb_joint_type type, const char *function,
                              int *index);

#endif
