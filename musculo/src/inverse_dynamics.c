/* SPDX-License-Identifier: MIT */
/* Inverse dynamics over the model's tree of joints (mu/inverse_dynamics.h). */
#include <math.h>
#include <stdlib.h>

#include "arguments.h"
#include "inverse_dynamics_forces.h"
#include "joint_sides.h"
#include "mu/inverse_dynamics.h"

#define DEGREES (180.0 / RB_PI)

/* A joint of the model as an edge between two body indices: a hinge
 * (hinge >= 0, one degree of freedom) or a weld (hinge = -1, none). */
typedef struct tree_edge {
    rb_joint_id joint;
    int hinge;
    int a, b;
} tree_edge;

/* The model's joints as a tree grown from the static bodies. */
typedef struct joint_tree {
    int body_count, edge_count;
    tree_edge *edges;
    int *parent_edge; /* by body: the edge to its parent, -1 for the ground and for unreached bodies */
    int *order;       /* the moving bodies, parents before children */
    int order_count;
} joint_tree;

static void tree_free(joint_tree *tree)
{
    free(tree->edges);
    free(tree->parent_edge);
    free(tree->order);
    *tree = (joint_tree){0};
}

static void add_edge(const mu_model *model, rb_joint_id joint, int hinge, joint_tree *tree)
{
    if (rb_joint_id_is_null(joint)) {
        return;
    }
    const rb_world *world = mu_model_world_to_read(model);
    tree->edges[tree->edge_count++] =
        (tree_edge){joint, hinge, mu_joint_sides_body_index(model, rb_joint_body_a(world, joint)),
                    mu_joint_sides_body_index(model, rb_joint_body_b(world, joint))};
}

/* The name of a part that became body `body`, for messages. */
static const char *body_name(const mu_model *model, int body)
{
    for (int p = 0; p < mu_model_part_count(model); ++p) {
        if (mu_model_part_body(model, p) == body) {
            return mu_model_part_name(model, p);
        }
    }
    return "(unnamed)";
}

static const char *edge_name(const mu_model *model, const tree_edge *edge)
{
    if (edge->hinge >= 0) {
        return mu_model_hinge_name(model, edge->hinge);
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        if (rb_joint_id_equals(mu_model_glue_joint(model, g), edge->joint)) {
            return mu_model_glue_name(model, g);
        }
    }
    return "the weight's weld";
}

static bool is_ground(const rb_world *world, const mu_model *model, int body)
{
    return rb_body_type_of(world, mu_model_body(model, body)) != RB_BODY_DYNAMIC;
}

/* Grows the tree breadth first from every static body. A joint reached
 * from both ends closes a loop; a joint between two static bodies carries
 * nothing that motion determines and is left out. */
static rb_status tree_build(const mu_model *model, const char *function, joint_tree *tree)
{
    const rb_world *world = mu_model_world_to_read(model);
    const int bodies = mu_model_body_count(model);
    const int joints = mu_model_hinge_count(model) + mu_model_glue_count(model) + 1;
    *tree = (joint_tree){.body_count = bodies};
    tree->edges = malloc((size_t)joints * sizeof *tree->edges);
    tree->parent_edge = malloc(((size_t)bodies + 1) * sizeof *tree->parent_edge);
    tree->order = malloc(((size_t)bodies + 1) * sizeof *tree->order);
    bool *reached = calloc((size_t)bodies + 1, sizeof *reached);
    bool *used = calloc((size_t)joints, sizeof *used);
    int *queue = malloc(((size_t)bodies + 1) * sizeof *queue);
    if (tree->edges == NULL || tree->parent_edge == NULL || tree->order == NULL || reached == NULL || used == NULL ||
        queue == NULL) {
        free(reached);
        free(used);
        free(queue);
        tree_free(tree);
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", function);
    }
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        add_edge(model, mu_model_hinge_joint(model, h), h, tree);
    }
    for (int g = 0; g < mu_model_glue_count(model); ++g) {
        add_edge(model, mu_model_glue_joint(model, g), -1, tree);
    }
    add_edge(model, mu_model_weight_joint(model), -1, tree);

    int head = 0, tail = 0;
    for (int b = 0; b < bodies; ++b) {
        tree->parent_edge[b] = -1;
        if (is_ground(world, model, b)) {
            reached[b] = true;
            queue[tail++] = b;
        }
    }
    rb_status status = RB_OK;
    while (status == RB_OK && head < tail) {
        const int u = queue[head++];
        for (int e = 0; e < tree->edge_count && status == RB_OK; ++e) {
            const tree_edge *edge = &tree->edges[e];
            if (used[e] || (edge->a != u && edge->b != u)) {
                continue;
            }
            used[e] = true;
            const int v = edge->a == u ? edge->b : edge->a;
            if (v < 0) {
                continue;
            }
            if (reached[v] && !(is_ground(world, model, u) && is_ground(world, model, v))) {
                status = rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                         "%s: joint \"%s\" closes a loop of joints (a closed chain): its torques are "
                                         "not determined by the motion alone",
                                         function, edge_name(model, edge));
            } else if (!reached[v]) {
                reached[v] = true;
                tree->parent_edge[v] = e;
                tree->order[tree->order_count++] = v;
                queue[tail++] = v;
            }
        }
    }
    for (int b = 0; b < bodies && status == RB_OK; ++b) {
        if (!reached[b]) {
            status = rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                     "%s: body \"%s\" is not joined to the ground (a floating base): inverse dynamics "
                                     "needs every moving body held to a static one through joints",
                                     function, body_name(model, b));
        }
    }
    free(reached);
    free(used);
    free(queue);
    if (status != RB_OK) {
        tree_free(tree);
    }
    return status;
}

rb_status mu_model_check_tree(const mu_model *model)
{
    const char *f = "mu_model_check_tree";
    if (mu_refuse_null(f, "model", model)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    joint_tree tree;
    const rb_status status = tree_build(model, f, &tree);
    tree_free(&tree);
    return status;
}

/* One body's motion: pose, centre, and the centre's and the body's
 * velocities and accelerations (world frame). */
typedef struct body_motion {
    double angle;   /* rad */
    rb_vec2 origin; /* m */
    rb_vec2 centre; /* m, centre of mass */
    rb_vec2 velocity, acceleration;
    double omega, alpha;
} body_motion;

/* A point's velocity and acceleration on a body whose centre moves as m,
 * r from the centre. */
static rb_vec2 point_velocity(const body_motion *m, rb_vec2 r) { return rb_add(m->velocity, rb_cross_sv(m->omega, r)); }

static rb_vec2 point_acceleration(const body_motion *m, rb_vec2 r)
{
    return rb_sub(rb_add(m->acceleration, rb_cross_sv(m->alpha, r)), rb_scale(m->omega * m->omega, r));
}

/* The forward pass: every moving body's motion from its parent's, across
 * the edge's joint; pivots[e] is the edge's pivot (m, world). */
static void forward_pass(const mu_model *model, const joint_tree *tree, const double *angles_deg, const double *rates,
                         const double *accelerations, body_motion *motion, rb_vec2 *pivots)
{
    const rb_world *world = mu_model_world_to_read(model);
    for (int b = 0; b < tree->body_count; ++b) {
        const rb_body_id body = mu_model_body(model, b);
        motion[b] = (body_motion){.angle = rb_body_angle(world, body),
                                  .origin = rb_body_position(world, body),
                                  .centre = rb_body_world_center(world, body)};
    }
    for (int k = 0; k < tree->order_count; ++k) {
        const int v = tree->order[k];
        const tree_edge *edge = &tree->edges[tree->parent_edge[v]];
        const int u = edge->a == v ? edge->b : edge->a;
        const double sign = v == edge->b ? 1.0 : -1.0;
        const rb_body_id body_u = mu_model_body(model, u), body_v = mu_model_body(model, v);
        /* The joint's shape from the present pose: each anchor in its
         * body's frame, and the relative angle at θ = 0. */
        const double angle_u0 = rb_body_angle(world, body_u), angle_v0 = rb_body_angle(world, body_v);
        const rb_vec2 anchor_u =
            sign > 0.0 ? rb_joint_world_anchor_a(world, edge->joint) : rb_joint_world_anchor_b(world, edge->joint);
        const rb_vec2 anchor_v =
            sign > 0.0 ? rb_joint_world_anchor_b(world, edge->joint) : rb_joint_world_anchor_a(world, edge->joint);
        const rb_vec2 local_u =
            rb_inv_rotate(rb_rot_from_angle(angle_u0), rb_sub(anchor_u, rb_body_position(world, body_u)));
        const rb_vec2 local_v =
            rb_inv_rotate(rb_rot_from_angle(angle_v0), rb_sub(anchor_v, rb_body_position(world, body_v)));
        const rb_vec2 centre_v = rb_body_mass_data(world, body_v).center;
        double theta = 0.0, theta0 = 0.0, rate = 0.0, acceleration = 0.0;
        if (edge->hinge >= 0) {
            theta = angles_deg[edge->hinge] / DEGREES;
            theta0 = mu_model_hinge_angle(model, edge->hinge) / DEGREES;
            rate = rates[edge->hinge];
            acceleration = accelerations[edge->hinge];
        }
        /* θ = angle(B) − angle(A) − offset, the offset fixed by the joint. */
        const double offset = sign * (angle_v0 - angle_u0) - theta0;
        const body_motion *parent = &motion[u];
        body_motion *child = &motion[v];
        child->angle = parent->angle + sign * (theta + offset);
        child->omega = parent->omega + sign * rate;
        child->alpha = parent->alpha + sign * acceleration;
        const rb_vec2 pivot = rb_add(parent->origin, rb_rotate(rb_rot_from_angle(parent->angle), local_u));
        const rb_rot q = rb_rot_from_angle(child->angle);
        child->origin = rb_sub(pivot, rb_rotate(q, local_v));
        child->centre = rb_add(child->origin, rb_rotate(q, centre_v));
        const rb_vec2 to_pivot = rb_sub(pivot, parent->centre), to_centre = rb_sub(child->centre, pivot);
        const body_motion at_pivot = {.velocity = point_velocity(parent, to_pivot),
                                      .acceleration = point_acceleration(parent, to_pivot),
                                      .omega = child->omega,
                                      .alpha = child->alpha};
        child->velocity = point_velocity(&at_pivot, to_centre);
        child->acceleration = point_acceleration(&at_pivot, to_centre);
        pivots[tree->parent_edge[v]] = pivot;
    }
}

/* The torques, and when `forces` is not NULL the forces
 * (inverse_dynamics_forces.h), as `function`. */
static rb_status solve(const mu_model *model, const char *f, const double *angles_deg, const double *rates,
                       const double *accelerations, double *torques, mu_hinge_force *forces)
{
    if (mu_refuse_null(f, "model", model) || mu_refuse_null(f, "angles_deg", angles_deg) ||
        mu_refuse_null(f, "rates", rates) || mu_refuse_null(f, "accelerations", accelerations) ||
        mu_refuse_null(f, "torques", torques)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    const int hinges = mu_model_hinge_count(model);
    for (int h = 0; h < hinges; ++h) {
        torques[h] = NAN;
        if (!rb_joint_id_is_null(mu_model_hinge_joint(model, h)) &&
            (mu_refuse_non_finite(f, "angles_deg", angles_deg[h]) || mu_refuse_non_finite(f, "rates", rates[h]) ||
             mu_refuse_non_finite(f, "accelerations", accelerations[h]))) {
            return RB_ERR_INVALID_ARGUMENT;
        }
    }
    joint_tree tree;
    rb_status status = tree_build(model, f, &tree);
    if (status != RB_OK) {
        return status;
    }
    body_motion *motion = malloc(((size_t)tree.body_count + 1) * sizeof *motion);
    rb_vec2 *pivots = malloc(((size_t)tree.edge_count + 1) * sizeof *pivots);
    double *sums = calloc((size_t)tree.edge_count + 1, sizeof *sums);
    rb_vec2 *force_sums = calloc((size_t)tree.edge_count + 1, sizeof *force_sums);
    if (motion == NULL || pivots == NULL || sums == NULL || force_sums == NULL) {
        status = rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    } else {
        forward_pass(model, &tree, angles_deg, rates, accelerations, motion, pivots);
        const rb_world *world = mu_model_world_to_read(model);
        const rb_vec2 gravity = rb_world_gravity(world);
        /* The backward pass: each moving body's contribution to the sum of
         * every joint between it and the ground. */
        for (int k = 0; k < tree.order_count; ++k) {
            const int b = tree.order[k];
            const rb_body_id body = mu_model_body(model, b);
            const rb_mass_data mass = rb_body_mass_data(world, body);
            const body_motion *m = &motion[b];
            const rb_vec2 g = rb_scale(rb_body_gravity_scale(world, body), gravity);
            /* The engine damps once per substep h, after the solve, as
             * v' = (v + h·a)/(1 + h·c), i.e. (v' − v)/h = a − c·v': a
             * drag c times the velocity reached (engine/src/solver.c). */
            const double linear_drag = rb_body_linear_damping(world, body);
            const double angular_drag = rb_body_angular_damping(world, body);
            /* m·(a − g + d·v): the force the rest must supply to the centre. */
            const rb_vec2 force =
                rb_scale(mass.mass, rb_add(rb_sub(m->acceleration, g), rb_scale(linear_drag, m->velocity)));
            const double spin = mass.rotational_inertia * (m->alpha + angular_drag * m->omega);
            for (int at = b, e = tree.parent_edge[b]; e >= 0; e = tree.parent_edge[at]) {
                sums[e] += spin + rb_cross(rb_sub(m->centre, pivots[e]), force);
                force_sums[e] = rb_add(force_sums[e], force);
                at = tree.edges[e].a == at ? tree.edges[e].b : tree.edges[e].a;
            }
        }
        /* The sum is the torque on the side away from the ground: B's, or
         * A's, which receives −τ. */
        for (int k = 0; k < tree.order_count; ++k) {
            const int v = tree.order[k];
            const tree_edge *edge = &tree.edges[tree.parent_edge[v]];
            if (edge->hinge >= 0) {
                torques[edge->hinge] = v == edge->b ? sums[tree.parent_edge[v]] : -sums[tree.parent_edge[v]];
                if (forces != NULL) {
                    forces[edge->hinge] =
                        (mu_hinge_force){.moving = force_sums[tree.parent_edge[v]], .b_side_moves = v == edge->b};
                }
            }
        }
    }
    free(motion);
    free(pivots);
    free(sums);
    free(force_sums);
    tree_free(&tree);
    return status;
}

rb_status mu_model_inverse_dynamics(const mu_model *model, const double *angles_deg, const double *rates,
                                    const double *accelerations, double *torques)
{
    return solve(model, "mu_model_inverse_dynamics", angles_deg, rates, accelerations, torques, NULL);
}

rb_status mu_inverse_dynamics_with_forces(const mu_model *model, const char *function, const double *angles_deg,
                                          const double *rates, const double *accelerations, double *torques,
                                          mu_hinge_force *forces)
{
    return solve(model, function, angles_deg, rates, accelerations, torques, forces);
}
