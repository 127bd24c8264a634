/* SPDX-License-Identifier: MIT */
/* What the joint types' creation functions share with joint.c. */
#ifndef RB_JOINT_INTERNAL_H
#define RB_JOINT_INTERNAL_H

#include "world_internal.h"

/* Looks both bodies up; fails when either is invalid or they are one body. */
rb_status rb_joint_check_bodies(const rb_world *world, rb_body_id a, rb_body_id b, const char *function, int *index_a,
                                int *index_b);

/* A two-body joint's common definition. */
typedef struct rb_joint_common_def {
    rb_body_id body_a, body_b;
    rb_vec2 local_anchor_a, local_anchor_b;
    int32_t internal_value;
} rb_joint_common_def;

/* The common fields of any two-body joint definition `def` (which may be
 * NULL: rb_joint_check_common then reports it). */
#define RB_JOINT_COMMON(def)                                                                                           \
    ((def) != NULL ? (rb_joint_common_def){(def)->body_a, (def)->body_b, (def)->local_anchor_a, (def)->local_anchor_b, \
                                           (def)->internal_value}                                                      \
                   : (rb_joint_common_def){0})

/* The checks every two-body joint's create function begins with: `out`
 * (set to the null id) and `def` are not NULL, `def` was made by `maker`
 * (its default function), the bodies are valid and distinct, the anchors
 * finite. Gives the bodies' indices. */
rb_status rb_joint_check_common(const rb_world *world, const void *def, rb_joint_common_def common, rb_joint_id *out,
                                const char *function, const char *maker, int *index_a, int *index_b);

/* The local anchors of one world point on each body, and angle(B) -
 * angle(A) now: what pins or welds two bodies where they are. */
rb_status rb_joint_anchor_at(const rb_world *world, rb_body_id body_a, rb_body_id body_b, rb_vec2 world_anchor,
                             const char *function, rb_vec2 *local_a, rb_vec2 *local_b, double *reference_angle);

/* Adds a joint filled in from `prototype` (type, bodies, anchors, flags,
 * type data) to the world and the bodies' joint lists. */
rb_status rb_joint_create(rb_world *world, const rb_joint *prototype, rb_joint_id *out, const char *function);

/* Looks a joint up and checks its type. */
rb_status rb_joint_find_typed(const rb_world *world, rb_joint_id id, rb_joint_type type, const char *function,
                              int *index);

/* Looks a joint of `type` up for a call that changes it (never during a
 * step) and wakes its bodies, since the change acts at once. NULL, with
 * *status and the error set, when it cannot. */
rb_joint *rb_joint_find_for_change(rb_world *world, rb_joint_id id, rb_joint_type type, const char *function,
                                   rb_status *status);

/* The checks shared by the joints with limits, a motor and a spring. The
 * names are the definition's fields, `unit` the limits' ("rad", "m") and
 * `bound` their largest magnitude (RB_MAX_ANGLE, RB_MAX_LENGTH). */
rb_status rb_joint_check_limits(const char *function, const char *lower_name, const char *upper_name, const char *unit,
                                double bound, bool enable_lower, double lower, bool enable_upper, double upper);
rb_status rb_joint_check_motor(const char *function, const char *max_name, double speed, double max);
rb_status rb_joint_check_spring(const char *function, double hertz, double damping_ratio);

#endif
