/* SPDX-License-Identifier: MIT */
/* Which of a model's bodies turn with a joint's body B when the joint's
 * angle changes and the rest of the model is held still.
 *
 * Starting from body B (or A), the search follows every other joint of the
 * model (hinges, glues kept as welds, the weight's weld) to the bodies
 * they join, and stops at static bodies (nails, static bones): the
 * ground never turns. Body B itself always turns, static or not, so that
 * a joint whose body B is the ground still has a side to turn. The
 * search notes whether it met the ground (the side is "grounded") and
 * whether it came back to body A (the joint closes a loop, as the leg's
 * chain between its two nails does): either way the bodies found are
 * still the ones a virtual rotation of B's side moves, which is what a
 * moment arm (moment_arms.h) needs, but such a side cannot actually be
 * turned with the rest held.
 */
#ifndef MU_JOINT_SIDES_H
#define MU_JOINT_SIDES_H

#include <stdbool.h>

#include "mu/model.h"

typedef struct mu_joint_sides {
    bool *turns;      /* by model body index (mu_model_body): whether it turns with the start body */
    int start;        /* the body the search started from: the joint's body B (or A, from_a) */
    int other;        /* the joint's other body (-1 when not a model body) */
    bool grounded;    /* the side met a static body */
    bool closes_loop; /* the side reached the other body */
} mu_joint_sides;

/* The side of `cut`, a joint of the model, that turns with its body B
 * (from_a false) or with its body A (from_a true, for a body B held by
 * the ground). Fails on memory or a joint that is not the model's. */
rb_status mu_joint_sides_find(const mu_model *model, rb_joint_id cut, bool from_a, mu_joint_sides *out);

/* The model body index of an engine body, or -1. */
int mu_joint_sides_body_index(const mu_model *model, rb_body_id body);

void mu_joint_sides_free(mu_joint_sides *sides);

/* For each point of built muscle `muscle`'s path, whether its body turns
 * with the side; returns the point count (turns holds RB_MAX_CABLE_POINTS). */
int mu_joint_sides_of_path(const mu_model *model, int muscle, const mu_joint_sides *sides, bool *turns);

/* Whether the path's points lie on both sides. */
bool mu_joint_sides_crosses_path(const bool *turns, int count);

/* The muscle's moment arm (m) about `pivot` for a turn of the side
 * (mu/moment_arms.h gives the formula). */
double mu_joint_sides_moment_arm(const mu_model *model, int muscle, const mu_joint_sides *sides, rb_vec2 pivot);

#endif
