/* SPDX-License-Identifier: MIT */
/* Which bodies turn with a joint's body B (joint_sides.h): a search over
 * the model's joints, by an explicit stack. */
#include <stdlib.h>

#include "joint_sides.h"
#include "mu/moment_arms.h"

int mu_joint_sides_body_index(const mu_model *model, rb_body_id body)
{
    for (int b = 0; b < mu_model_body_count(model); ++b) {
        if (rb_body_id_equals(mu_model_body(model, b), body)) {
            return b;
        }
    }
    return -1;
}

/* The model's joints other than `cut`, as pairs of body indices. */
typedef struct edge {
    int a, b;
} edge;

static int add_edge(const mu_model *model, rb_joint_id joint, rb_joint_id cut, edge *edges, int count)
{
    if (rb_joint_id_is_null(joint) || rb_joint_id_equals(joint, cut)) {
        return count;
    }
    const rb_world *world = mu_model_world_to_read(model);
    edges[count] = (edge){mu_joint_sides_body_index(model, rb_joint_body_a(world, joint)),
                          mu_joint_sides_body_index(model, rb_joint_body_b(world, joint))};
    return count + 1;
}

static int collect_edges(const mu_model *model, rb_joint_id cut, edge *edges)
{
    int count = 0;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        count = add_edge(model, mu_model_hinge_joint(model, h), cut, edges, count);
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        count = add_edge(model, mu_model_glue_joint(model, g), cut, edges, count);
    }
    return add_edge(model, mu_model_weight_joint(model), cut, edges, count);
}

rb_status mu_joint_sides_find(const mu_model *model, rb_joint_id cut, bool from_a, mu_joint_sides *out)
{
    *out = (mu_joint_sides){.start = -1, .other = -1};
    const rb_world *world = mu_model_world_to_read(model);
    const int bodies = mu_model_body_count(model);
    const int joints = mu_model_hinge_count(model) + mu_model_glue_count(model) + 1;
    const int a = mu_joint_sides_body_index(model, rb_joint_body_a(world, cut));
    const int b = mu_joint_sides_body_index(model, rb_joint_body_b(world, cut));
    out->start = from_a ? a : b;
    out->other = from_a ? b : a;
    if (out->start < 0) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_joint_sides_find: the joint is not one of the model's");
    }
    out->turns = calloc((size_t)bodies + 1, sizeof *out->turns);
    edge *edges = malloc((size_t)joints * sizeof *edges);
    int *stack = malloc(((size_t)bodies + 1) * sizeof *stack);
    if (out->turns == NULL || edges == NULL || stack == NULL) {
        free(edges);
        free(stack);
        mu_joint_sides_free(out);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_joint_sides_find: out of memory");
    }
    const int edge_count = collect_edges(model, cut, edges);
    int top = 0;
    stack[top++] = out->start;
    out->turns[out->start] = true;
    out->grounded = rb_body_type_of(world, mu_model_body(model, out->start)) == RB_BODY_STATIC;
    while (top > 0) {
        const int body = stack[--top];
        for (int e = 0; e < edge_count; ++e) {
            const int other = edges[e].a == body ? edges[e].b : edges[e].b == body ? edges[e].a : -1;
            if (other < 0 || out->turns[other]) {
                continue;
            }
            out->closes_loop = out->closes_loop || other == out->other;
            if (rb_body_type_of(world, mu_model_body(model, other)) == RB_BODY_STATIC) {
                out->grounded = true; /* the ground stays where it is */
                continue;
            }
            out->turns[other] = true;
            stack[top++] = other;
        }
    }
    free(edges);
    free(stack);
    return RB_OK;
}

void mu_joint_sides_free(mu_joint_sides *sides)
{
    free(sides->turns);
    sides->turns = NULL;
}

/* ---- a muscle's path across the sides --------------------------------------------- */

/* For each point of a built muscle's path, whether its body turns with
 * the side; returns the point count. */
int mu_joint_sides_of_path(const mu_model *model, int muscle, const mu_joint_sides *sides, bool *turns)
{
    const mu_model_desc *desc = mu_model_description(model);
    const mu_model_muscle *m = &desc->muscles[mu_model_muscle_description_index(model, muscle)];
    for (int i = 0; i < m->point_count; ++i) {
        const mu_model_ref ref = m->path[i].body;
        const int part = ref.kind == MU_MODEL_NAIL ? ref.index : desc->nail_count + ref.index;
        turns[i] = sides->turns[mu_model_part_body(model, part)];
    }
    return m->point_count;
}

bool mu_joint_sides_crosses_path(const bool *turns, int count)
{
    for (int i = 1; i < count; ++i) {
        if (turns[i] != turns[0]) {
            return true;
        }
    }
    return false;
}

/* r = -dL/dθ (moment_arms.h): the sum over segments of
 * -u·(s_Q·k×(Q - c) - s_P·k×(P - c)), where u·(k×v) = v×u. */
double mu_joint_sides_moment_arm(const mu_model *model, int muscle, const mu_joint_sides *sides, rb_vec2 pivot)
{
    bool turns[RB_MAX_CABLE_POINTS];
    rb_vec2 points[RB_MAX_CABLE_POINTS];
    const int count = mu_joint_sides_of_path(model, muscle, sides, turns);
    const rb_cable_id cable = mu_muscle_cable(mu_model_built_muscle(model, muscle));
    rb_cable_points(mu_model_world_to_read(model), cable, points, RB_MAX_CABLE_POINTS);
    double rate = 0.0; /* dL/dθ */
    for (int i = 0; i + 1 < count; ++i) {
        if (turns[i] == turns[i + 1]) {
            continue; /* a rigid segment keeps its length */
        }
        const rb_vec2 u = rb_normalize(rb_sub(points[i + 1], points[i]));
        const rb_vec2 moving = turns[i + 1] ? points[i + 1] : points[i];
        const double sign = turns[i + 1] ? 1.0 : -1.0;
        rate += sign * rb_cross(rb_sub(moving, pivot), u);
    }
    return -rate;
}
