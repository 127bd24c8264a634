/* SPDX-License-Identifier: MIT */
/* Joints: the pool, creation and destruction, the getters every type
 * shares, and the dispatch of the solver's phases on the joint type. */
#include <float.h>
#include <string.h>

#include "allocator.h"
#include "error.h"
#include "joint_internal.h"
#include "joint_solver.h"
#include "joint_tree.h"
#include "sleep.h"

/* ---- creation and destruction ---------------------------------------------- */

static rb_status allocate_joint_slot(rb_world *world, int *index, const char *function)
{
    if (world->joint_free >= 0) {
        *index = world->joint_free;
        world->joint_free = world->joints[*index].next_free;
        return RB_OK;
    }
    /* The velocity passes' list has room for every joint (make_velocity_joints). */
    if (rb_grow_array((void **)&world->joints, &world->joint_capacity, world->joint_slots + 1, sizeof *world->joints) !=
            0 ||
        rb_grow_array((void **)&world->velocity_joints, &world->velocity_joint_capacity, world->joint_slots + 1,
                      sizeof *world->velocity_joints) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", function);
    }
    *index = world->joint_slots++;
    world->joints[*index].generation = 0;
    return RB_OK;
}

rb_status rb_joint_check_bodies(const rb_world *world, rb_body_id a, rb_body_id b, const char *function, int *index_a,
                                int *index_b)
{
    RB_TRY(rb_world_find_body(world, a, function, index_a));
    RB_TRY(rb_world_find_body(world, b, function, index_b));
    if (*index_a == *index_b) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: body_a and body_b are the same body (index %d)", function,
                               *index_a);
    }
    return RB_OK;
}

rb_status rb_joint_check_common(const rb_world *world, const void *def, rb_joint_common_def common, rb_joint_id *out,
                                const char *function, const char *maker, int *index_a, int *index_b)
{
    RB_TRY(rb_check_pointer(function, "out", out));
    *out = (rb_joint_id){0};
    RB_TRY(rb_check_pointer(function, "def", def));
    RB_TRY(rb_check_def_cookie(function, maker, common.internal_value));
    RB_TRY(rb_joint_check_bodies(world, common.body_a, common.body_b, function, index_a, index_b));
    RB_TRY(rb_check_point(function, "local_anchor_a", common.local_anchor_a));
    return rb_check_point(function, "local_anchor_b", common.local_anchor_b);
}

rb_status rb_joint_anchor_at(const rb_world *world, rb_body_id body_a, rb_body_id body_b, rb_vec2 world_anchor,
                             const char *function, rb_vec2 *local_a, rb_vec2 *local_b, double *reference_angle)
{
    RB_TRY(rb_check_point(function, "world_anchor", world_anchor));
    int a;
    int b;
    RB_TRY(rb_joint_check_bodies(world, body_a, body_b, function, &a, &b));
    *local_a = rb_inv_transform_point(rb_body_origin_transform(world, a), world_anchor);
    *local_b = rb_inv_transform_point(rb_body_origin_transform(world, b), world_anchor);
    *reference_angle = world->states[b].angle - world->states[a].angle;
    return RB_OK;
}

rb_status rb_joint_create(rb_world *world, const rb_joint *prototype, rb_joint_id *out, const char *function)
{
    RB_TRY(rb_world_check_unlocked(world, function));
    int index = -1;
    RB_TRY(allocate_joint_slot(world, &index, function));
    rb_joint *joint = &world->joints[index];
    uint32_t generation = joint->generation + 1u;
    *joint = *prototype;
    joint->generation = generation;
    joint->in_use = true;
    joint->next_on_a = -1;
    if (joint->body_a >= 0) {
        rb_body *a = &world->bodies[joint->body_a];
        joint->next_on_a = a->first_joint;
        a->first_joint = index;
        rb_body_wake(world, joint->body_a);
    }
    rb_body *b = &world->bodies[joint->body_b];
    joint->next_on_b = b->first_joint;
    b->first_joint = index;
    rb_body_wake(world, joint->body_b);
    world->joint_count++;
    world->candidates_stale = true; /* a joint may forbid its bodies to collide */
    *out = rb_make_joint_id(world, index);
    return RB_OK;
}

/* The link that follows joint j in body `body`'s list. */
static int *next_link(rb_world *world, int joint, int body)
{
    rb_joint *j = &world->joints[joint];
    return j->body_a == body ? &j->next_on_a : &j->next_on_b;
}

static void unlink_from_body(rb_world *world, int joint, int body)
{
    int *link = &world->bodies[body].first_joint;
    while (*link != joint) {
        link = next_link(world, *link, body);
    }
    *link = *next_link(world, joint, body);
}

static void free_joint(rb_world *world, int index)
{
    rb_joint *joint = &world->joints[index];
    world->candidates_stale = true; /* its bodies may collide again */
    if (joint->body_a >= 0) {
        unlink_from_body(world, index, joint->body_a);
        rb_body_wake(world, joint->body_a);
    }
    unlink_from_body(world, index, joint->body_b);
    rb_body_wake(world, joint->body_b);
    joint->in_use = false;
    if (joint->generation != RB_RETIRED_GENERATION) {
        joint->next_free = world->joint_free;
        world->joint_free = index;
    }
    world->joint_count--;
}

rb_status rb_joint_destroy(rb_world *world, rb_joint_id id)
{
    rb_clear_error();
    int index;
    RB_TRY(rb_world_find_joint(world, id, "rb_joint_destroy", &index));
    RB_TRY(rb_world_check_unlocked(world, "rb_joint_destroy"));
    free_joint(world, index);
    return RB_OK;
}

void rb_joints_remove_body(rb_world *world, int body)
{
    while (world->bodies[body].first_joint >= 0) {
        free_joint(world, world->bodies[body].first_joint);
    }
}

bool rb_joints_forbid_collision(const rb_world *world, int body_a, int body_b)
{
    for (int j = world->bodies[body_a].first_joint; j >= 0;) {
        const rb_joint *joint = &world->joints[j];
        int other = joint->body_a == body_a ? joint->body_b : joint->body_a;
        if (other == body_b && !joint->collide_connected) {
            return true;
        }
        j = joint->body_a == body_a ? joint->next_on_a : joint->next_on_b;
    }
    return false;
}

bool rb_joint_is_valid(const rb_world *world, rb_joint_id id)
{
    return world != NULL && id.generation != 0 && id.world == world->serial && id.index >= 0 &&
           id.index < world->joint_slots && world->joints[id.index].in_use &&
           world->joints[id.index].generation == id.generation;
}

/* ---- getters ---------------------------------------------------------------- */

rb_vec2 rb_joint_anchor_a(const rb_world *world, const rb_joint *joint)
{
    if (joint->body_a < 0) {
        return joint->as.mouse.target;
    }
    return rb_transform_point(rb_body_origin_transform(world, joint->body_a), joint->local_anchor_a);
}

rb_vec2 rb_joint_anchor_b(const rb_world *world, const rb_joint *joint)
{
    return rb_transform_point(rb_body_origin_transform(world, joint->body_b), joint->local_anchor_b);
}

double rb_joint_relative_angle(const rb_world *world, const rb_joint *joint, double reference)
{
    double angle_a = joint->body_a >= 0 ? world->states[joint->body_a].angle : 0.0;
    return world->states[joint->body_b].angle - angle_a - reference;
}

/* Impulses accumulated over the last substep, as forces on body B. */
static rb_vec2 linear_impulse(const rb_world *world, const rb_joint *joint)
{
    switch (joint->type) {
    case RB_JOINT_REVOLUTE:
        return rb_pin_impulse(world, joint); /* a substep callback may ask within the step */
    case RB_JOINT_WELD:
        return joint->as.weld.point_impulse;
    case RB_JOINT_DISTANCE: {
        const rb_distance_data *d = &joint->as.distance;
        return rb_scale(d->impulse + d->lower_impulse - d->upper_impulse, d->axis);
    }
    case RB_JOINT_MOUSE:
        return joint->as.mouse.impulse;
    case RB_JOINT_PRISMATIC:
        return rb_prismatic_linear_impulse(world, joint);
    case RB_JOINT_PULLEY:
        return rb_pulley_impulse_on_b(world, joint);
    }
    return rb_v2(0.0, 0.0);
}

rb_vec2 rb_joint_force_on_b(const rb_world *world, const rb_joint *joint)
{
    return rb_scale(1.0 / world->last_substep, linear_impulse(world, joint));
}

static double angular_impulse(const rb_joint *joint)
{
    switch (joint->type) {
    case RB_JOINT_REVOLUTE: {
        const rb_revolute_data *r = &joint->as.revolute;
        return r->motor_impulse + r->spring_impulse + r->lower_impulse - r->upper_impulse;
    }
    case RB_JOINT_WELD:
        return joint->as.weld.angular_impulse;
    case RB_JOINT_PRISMATIC:
        return rb_prismatic_angular_impulse(joint);
    case RB_JOINT_DISTANCE:
    case RB_JOINT_MOUSE:
    case RB_JOINT_PULLEY:
        break;
    }
    return 0.0;
}

#define JOINT_GETTER(type, name, zero, expression)                                                                     \
    type name(const rb_world *world, rb_joint_id id)                                                                   \
    {                                                                                                                  \
        rb_clear_error();                                                                                              \
        int index;                                                                                                     \
        if (rb_world_find_joint(world, id, #name, &index) != RB_OK) {                                                  \
            return zero;                                                                                               \
        }                                                                                                              \
        const rb_joint *joint = &world->joints[index];                                                                 \
        return expression;                                                                                             \
    }

static const rb_vec2 zero_vec2 = {0.0, 0.0};
static const rb_body_id null_body = {0, 0, 0};

JOINT_GETTER(rb_joint_type, rb_joint_type_of, RB_JOINT_REVOLUTE, joint->type)
JOINT_GETTER(rb_body_id, rb_joint_body_a, null_body,
             joint->body_a >= 0 ? rb_make_body_id(world, joint->body_a) : null_body)
JOINT_GETTER(rb_body_id, rb_joint_body_b, null_body, rb_make_body_id(world, joint->body_b))
JOINT_GETTER(rb_vec2, rb_joint_world_anchor_a, zero_vec2, rb_joint_anchor_a(world, joint))
JOINT_GETTER(rb_vec2, rb_joint_world_anchor_b, zero_vec2, rb_joint_anchor_b(world, joint))
JOINT_GETTER(rb_vec2, rb_joint_reaction_force, zero_vec2, rb_joint_force_on_b(world, joint))
JOINT_GETTER(double, rb_joint_reaction_torque, 0.0, angular_impulse(joint) / world->last_substep)
JOINT_GETTER(void *, rb_joint_user_data, NULL, joint->user_data)

rb_status rb_joint_find_typed(const rb_world *world, rb_joint_id id, rb_joint_type type, const char *function,
                              int *index)
{
    RB_TRY(rb_world_find_joint(world, id, function, index));
    if (world->joints[*index].type != type) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: joint %d is of another type", function, *index);
    }
    return RB_OK;
}

rb_joint *rb_joint_find_for_change(rb_world *world, rb_joint_id id, rb_joint_type type, const char *function,
                                   rb_status *status)
{
    int index;
    rb_clear_error();
    *status = rb_joint_find_typed(world, id, type, function, &index);
    if (*status == RB_OK) {
        *status = rb_world_check_unlocked(world, function);
    }
    if (*status != RB_OK) {
        return NULL;
    }
    rb_joint *joint = &world->joints[index];
    if (joint->body_a >= 0) {
        rb_body_wake(world, joint->body_a);
    }
    rb_body_wake(world, joint->body_b);
    return joint;
}

rb_status rb_joint_check_limits(const char *function, const char *lower_name, const char *upper_name, const char *unit,
                                double bound, bool enable_lower, double lower, bool enable_upper, double upper)
{
    RB_TRY(rb_check_bound(function, lower_name, lower, bound, unit));
    RB_TRY(rb_check_bound(function, upper_name, upper, bound, unit));
    if (enable_lower && enable_upper && lower > upper) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s %g %s is above %s %g %s", function, lower_name, lower,
                               unit, upper_name, upper, unit);
    }
    return RB_OK;
}

rb_status rb_joint_check_motor(const char *function, const char *max_name, double speed, double max)
{
    RB_TRY(rb_check_bound(function, "motor_speed", speed, RB_MAX_SPEED, "(m or rad)/s"));
    return rb_check_range(function, max_name, max, 0.0, RB_MAX_FORCE);
}

rb_status rb_joint_check_spring(const char *function, double hertz, double damping_ratio)
{
    RB_TRY(rb_check_hertz(function, "spring_hertz", hertz, true));
    return rb_check_range(function, "spring_damping_ratio", damping_ratio, 0.0, RB_MAX_DAMPING_RATIO);
}

rb_status rb_joint_set_user_data(rb_world *world, rb_joint_id id, void *user_data)
{
    rb_clear_error();
    int index;
    RB_TRY(rb_world_find_joint(world, id, "rb_joint_set_user_data", &index));
    world->joints[index].user_data = user_data;
    return RB_OK;
}

/* ---- helpers of the joint types -------------------------------------------- */

rb_softness rb_make_softness(double hertz, double zeta, double effective_mass, double h)
{
    if (hertz <= 0.0 || effective_mass <= 0.0) {
        return (rb_softness){0.0, 0.0};
    }
    double omega = 2.0 * RB_PI * hertz;
    double k = effective_mass * omega * omega;
    double c = 2.0 * effective_mass * zeta * omega;
    double gamma = 1.0 / (h * (c + h * k));
    return (rb_softness){gamma, h * k * gamma};
}

rb_rigid_response rb_make_rigid_softness(double hertz, double zeta, double h)
{
    double omega = 2.0 * RB_PI * hertz;
    double a1 = 2.0 * zeta + h * omega;
    double a2 = h * omega * a1;
    return (rb_rigid_response){
        .bias_rate = omega / a1, .mass_scale = a2 / (1.0 + a2), .impulse_scale = 1.0 / (1.0 + a2)};
}

rb_body_state *rb_joint_state_a(rb_world *world, const rb_joint *joint)
{
    return joint->body_a >= 0 ? &world->states[joint->body_a] : NULL;
}

rb_body_state *rb_joint_state_b(rb_world *world, const rb_joint *joint) { return &world->states[joint->body_b]; }

/* ---- the phases -------------------------------------------------------------- */

/* A joint is solved when one of its bodies is dynamic and awake. */
static bool is_active(const rb_world *world, const rb_joint *joint)
{
    const rb_body *b = &world->bodies[joint->body_b];
    bool b_moves = b->type == RB_BODY_DYNAMIC && b->awake;
    if (joint->body_a < 0) {
        return b_moves;
    }
    const rb_body *a = &world->bodies[joint->body_a];
    return b_moves || (a->type == RB_BODY_DYNAMIC && a->awake);
}

/* What the step cannot change: while the world is locked no body changes
 * its mass, centre or type, falls asleep or wakes, and no joint its
 * settings. */
static void prepare_frame_for_step(rb_world *world, rb_joint *joint)
{
    rb_joint_frame *f = &joint->frame;
    const rb_body *b = &world->bodies[joint->body_b];
    f->inv_mass_b = b->awake ? b->inv_mass : 0.0;
    f->inv_inertia_b = b->awake ? b->inv_inertia : 0.0;
    f->local_b = rb_sub(joint->local_anchor_b, b->local_center);
    if (joint->body_a >= 0) {
        const rb_body *a = &world->bodies[joint->body_a];
        f->inv_mass_a = a->awake ? a->inv_mass : 0.0;
        f->inv_inertia_a = a->awake ? a->inv_inertia : 0.0;
        f->local_a = rb_sub(joint->local_anchor_a, a->local_center);
    } else {
        f->inv_mass_a = 0.0;
        f->inv_inertia_a = 0.0;
        f->local_a = rb_v2(0.0, 0.0);
    }
}

static void prepare_for_step(rb_world *world, rb_joint *joint)
{
    prepare_frame_for_step(world, joint);
    switch (joint->type) {
    case RB_JOINT_REVOLUTE:
        rb_revolute_prepare_step(joint);
        break;
    case RB_JOINT_WELD:
        rb_weld_prepare_step(joint);
        break;
    case RB_JOINT_DISTANCE:
        rb_distance_prepare_step(joint);
        break;
    case RB_JOINT_PRISMATIC:
        rb_prismatic_prepare_step(joint);
        break;
    case RB_JOINT_MOUSE:
    case RB_JOINT_PULLEY:
        break; /* nothing fixed beyond the frame */
    }
}

rb_status rb_joints_collect_active(rb_world *world)
{
    if (rb_grow_array((void **)&world->active_joints, &world->active_joint_capacity, world->joint_count,
                      sizeof *world->active_joints) != 0 ||
        rb_grow_array((void **)&world->substep_omega, &world->substep_omega_capacity, world->body_slots,
                      sizeof *world->substep_omega) != 0 ||
        rb_grow_array((void **)&world->point_blocks, &world->point_block_capacity, world->joint_slots,
                      sizeof *world->point_blocks) != 0 ||
        rb_grow_array((void **)&world->pin_rows, &world->pin_row_capacity, world->joint_count,
                      sizeof *world->pin_rows) != 0 ||
        rb_grow_array((void **)&world->pin_anchors, &world->pin_anchor_capacity, world->joint_count,
                      sizeof *world->pin_anchors) != 0 ||
        rb_grow_array((void **)&world->pin_row_of, &world->pin_row_of_capacity, world->joint_slots,
                      sizeof *world->pin_row_of) != 0 ||
        rb_grow_array((void **)&world->ordered_joints, &world->ordered_joint_capacity, world->joint_count,
                      sizeof *world->ordered_joints) != 0 ||
        rb_grow_array((void **)&world->joint_order_scratch, &world->joint_order_scratch_capacity, world->joint_count,
                      sizeof *world->joint_order_scratch) != 0 ||
        rb_grow_array((void **)&world->joint_keys, &world->joint_key_capacity, world->joint_count,
                      sizeof *world->joint_keys) != 0 ||
        rb_grow_array((void **)&world->body_depth, &world->body_depth_capacity, world->body_slots,
                      sizeof *world->body_depth) != 0 ||
        rb_grow_array((void **)&world->body_queue, &world->body_queue_capacity, world->body_slots + 1,
                      sizeof *world->body_queue) != 0 ||
        rb_grow_array((void **)&world->joint_ends, &world->joint_end_capacity, 2 * world->joint_slots,
                      sizeof *world->joint_ends) != 0 ||
        rb_grow_array((void **)&world->body_edge_start, &world->body_edge_start_capacity, world->body_slots + 1,
                      sizeof *world->body_edge_start) != 0 ||
        rb_grow_array((void **)&world->body_edges, &world->body_edge_capacity, 2 * world->joint_count,
                      sizeof *world->body_edges) != 0 ||
        rb_colouring_begin(&world->joint_colouring, world->body_slots) != 0) {
        world->active_joint_count = 0;
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the joint list");
    }
    /* Each joint prepared as it is listed, while its bodies are at hand. */
    int count = 0;
    for (int i = 0; i < world->joint_slots; ++i) {
        rb_joint *joint = &world->joints[i];
        if (joint->in_use && is_active(world, joint)) {
            world->active_joints[count++] = i;
            prepare_for_step(world, joint);
        }
    }
    world->active_joint_count = count;
    world->joints_ordered = false; /* until the solver orders them (joint_order.c) */
    return RB_OK;
}

void rb_joints_prepare(rb_world *world)
{
    if (world->active_joint_count == 0) {
        return;
    }
    for (int i = 0; i < world->body_slots; ++i) {
        world->substep_omega[i] = world->states[i].angular_velocity;
    }
}

/* The anchors turned into the world at the poses now. */
static void prepare_frame(rb_world *world, rb_joint *joint)
{
    rb_joint_frame *f = &joint->frame;
    f->rb = rb_rotate(world->states[joint->body_b].rotation, f->local_b);
    f->ra = joint->body_a >= 0 ? rb_rotate(world->states[joint->body_a].rotation, f->local_a) : rb_v2(0.0, 0.0);
}

/* The k-th of `count`, counted from the end when sweeping backwards. */
static int pass_index(int count, int k, bool backwards) { return backwards ? count - 1 - k : k; }

/* The joints the Gauss-Seidel passes visit this step: the active ones,
 * less the plain pins the trees solve whole (joint_tree.h). */
typedef struct pass_list {
    const int *joints; /* slots */
    int count;
} pass_list;

static pass_list pass_joints(const rb_world *world)
{
    if (world->joints_ordered) {
        return (pass_list){world->ordered_joints, world->ordered_joint_count};
    }
    const rb_joint_tree *tree = &world->joint_tree;
    if (tree->node_count > 0) {
        return (pass_list){tree->gauss_seidel_joints, tree->gauss_seidel_count};
    }
    return (pass_list){world->active_joints, world->active_joint_count};
}

const int *rb_joint_pass_list(const rb_world *world, int *count)
{
    const pass_list list = pass_joints(world);
    *count = list.count;
    return list.joints;
}

/* The slot of the k-th joint of the list. */
static int pass_slot(pass_list list, int k, bool backwards)
{
    return list.joints[pass_index(list.count, k, backwards)];
}

/* The row of the k-th joint of the list, or -1. */
static int pass_row(const rb_world *world, pass_list list, int k, bool backwards)
{
    return world->pin_row_of[pass_slot(list, k, backwards)];
}

/* Whether every joint of the list is a plain pin in its row (the joint
 * grid, a chain): the rows are then the list, in the same order, and the
 * passes run over the rows alone (joint_pin.c). */
static bool all_rows(const rb_world *world, pass_list list) { return world->pin_row_count == list.count; }

/* Each joint in one visit: its substep's frame, then its warm start; a
 * plain pin in its row (joint_pin.c). The plain pins the trees solve
 * whole are prepared and warm started by their trees, in one sweep over
 * their pins (rb_joint_tree_warm_start). */
void rb_joints_warm_start(rb_world *world, double h, bool backwards)
{
    const pass_list list = pass_joints(world);
    if (all_rows(world, list)) {
        rb_pins_warm_start(world, h, backwards);
        rb_joint_tree_warm_start(world, h, backwards);
        return;
    }
    for (int k = 0; k < list.count; ++k) {
        int row = pass_row(world, list, k, backwards);
        if (row >= 0) {
            rb_pin_warm_start(world, row, h);
            continue;
        }
        rb_joint *joint = &world->joints[pass_slot(list, k, backwards)];
        prepare_frame(world, joint);
        switch (joint->type) {
        case RB_JOINT_REVOLUTE:
            rb_revolute_warm_start(world, joint, h);
            break;
        case RB_JOINT_WELD:
            rb_point_constraint_prepare(world, joint, h);
            rb_weld_warm_start(world, joint);
            break;
        case RB_JOINT_DISTANCE:
            rb_distance_prepare(world, joint);
            rb_distance_warm_start(world, joint);
            break;
        case RB_JOINT_MOUSE:
            rb_mouse_warm_start(world, joint);
            break;
        case RB_JOINT_PRISMATIC:
            rb_prismatic_warm_start(world, joint);
            break;
        case RB_JOINT_PULLEY:
            rb_pulley_warm_start(world, joint);
            break;
        }
    }
    rb_joint_tree_warm_start(world, h, backwards);
}

/* A velocity pass over the rows alone, under the pass's response: the
 * rigid one of NGS and 2.4 in fewer operations (rb_pins_solve_rigid). */
static void solve_rows(rb_world *world, bool backwards)
{
    const rb_rigid_response *response = &world->joint_response;
    if (response->mass_scale == 1.0 && response->impulse_scale == 0.0 && response->bias_rate == 0.0) {
        rb_pins_solve_rigid(world, backwards);
        return;
    }
    rb_pins_solve(world, backwards);
}

/* Whether the velocity passes leave the joint to its block: a pin and
 * its limits are the block's, a spring or motor on it stays a joint's
 * (rb_revolute_solve). */
static bool block_solves(const rb_joint *joint)
{
    return joint->in_block && !joint->as.revolute.enable_spring && !joint->as.revolute.enable_motor;
}

/* The joints the velocity passes visit: the pass list less those their
 * blocks solve, each with its row, made at the step's first velocity
 * pass (once the trees, the rows and the order are found) and again when
 * a block gives its joints back (rb_joint_blocks_factor). The leg's four
 * limited pins are all its block's: the passes would visit them only for
 * them to return. The list has room for every joint slot
 * (allocate_joint_slot). */
static void make_velocity_joints(rb_world *world)
{
    const pass_list list = pass_joints(world);
    world->velocity_joints_fresh = true;
    world->velocity_rows_only = all_rows(world, list);
    if (world->velocity_rows_only) {
        world->velocity_joint_count = 0;
        return; /* the rows are the list (solve_rows) */
    }
    int count = 0;
    for (int k = 0; k < list.count; ++k) {
        rb_joint *joint = &world->joints[list.joints[k]];
        int row = world->pin_row_of[list.joints[k]];
        if (!block_solves(joint)) {
            world->velocity_joints[count++] =
                (rb_velocity_visit){.joint = joint, .row = row >= 0 ? &world->pin_rows[row] : NULL};
        }
    }
    world->velocity_joint_count = count;
}

/* One joint's velocity pass. */
static void solve_joint(rb_world *world, rb_velocity_visit visit, double h)
{
    if (visit.row != NULL) {
        rb_pin_solve(world, visit.row);
        return;
    }
    rb_joint *joint = visit.joint;
    switch (joint->type) {
    case RB_JOINT_REVOLUTE:
        rb_revolute_solve(world, joint, h);
        break;
    case RB_JOINT_WELD:
        rb_weld_solve(world, joint, h);
        break;
    case RB_JOINT_DISTANCE:
        rb_distance_solve(world, joint, h);
        break;
    case RB_JOINT_MOUSE:
        rb_mouse_solve(world, joint, h);
        break;
    case RB_JOINT_PRISMATIC:
        rb_prismatic_solve(world, joint, h);
        break;
    case RB_JOINT_PULLEY:
        rb_pulley_solve(world, joint, h);
        break;
    }
}

void rb_joints_solve_velocities(rb_world *world, double h, bool backwards)
{
    if (!world->velocity_joints_fresh) {
        make_velocity_joints(world);
    }
    if (world->velocity_rows_only) {
        solve_rows(world, backwards);
        return;
    }
    const int count = world->velocity_joint_count;
    if (count == 0) {
        return; /* the leg: its four pins are all its block's */
    }
    /* One loop for both directions: the joint's visit is then inlined once. */
    const rb_velocity_visit *visit = backwards ? world->velocity_joints + count - 1 : world->velocity_joints;
    const int step = backwards ? -1 : 1;
    for (int k = 0; k < count; ++k, visit += step) {
        solve_joint(world, *visit, h);
    }
}

bool rb_joints_correct_positions(rb_world *world, bool backwards)
{
    const pass_list list = pass_joints(world);
    if (all_rows(world, list)) {
        bool pins_within = rb_pins_correct_positions(world, backwards);
        return rb_joint_tree_correct_positions(world) && pins_within;
    }
    bool all_within = true;
    for (int k = 0; k < list.count; ++k) {
        int row = pass_row(world, list, k, backwards);
        if (row >= 0) {
            all_within = rb_pin_correct(world, row) && all_within;
            continue;
        }
        rb_joint *joint = &world->joints[pass_slot(list, k, backwards)];
        bool within = true;
        switch (joint->type) {
        case RB_JOINT_REVOLUTE:
            within = rb_revolute_correct(world, joint);
            break;
        case RB_JOINT_WELD:
            within = rb_weld_correct(world, joint);
            break;
        case RB_JOINT_DISTANCE:
            within = rb_distance_correct(world, joint);
            break;
        case RB_JOINT_PRISMATIC:
            within = rb_prismatic_correct(world, joint);
            break;
        case RB_JOINT_PULLEY:
            within = rb_pulley_correct(world, joint);
            break;
        case RB_JOINT_MOUSE:
            break; /* soft: it has no position error to remove */
        }
        all_within = all_within && within;
    }
    return rb_joint_tree_correct_positions(world) && all_within;
}

void rb_joints_reset_impulses(rb_world *world)
{
    for (int i = 0; i < world->joint_slots; ++i) {
        rb_joint *joint = &world->joints[i];
        if (!joint->in_use) {
            continue;
        }
        switch (joint->type) {
        case RB_JOINT_REVOLUTE: {
            rb_revolute_data *r = &joint->as.revolute;
            r->point_impulse = rb_v2(0.0, 0.0);
            r->motor_impulse = r->lower_impulse = r->upper_impulse = r->spring_impulse = 0.0;
            break;
        }
        case RB_JOINT_WELD:
            joint->as.weld.point_impulse = rb_v2(0.0, 0.0);
            joint->as.weld.angular_impulse = 0.0;
            break;
        case RB_JOINT_DISTANCE:
            joint->as.distance.impulse = joint->as.distance.lower_impulse = joint->as.distance.upper_impulse = 0.0;
            break;
        case RB_JOINT_MOUSE:
            joint->as.mouse.impulse = rb_v2(0.0, 0.0);
            break;
        case RB_JOINT_PRISMATIC: {
            rb_prismatic_data *p = &joint->as.prismatic;
            p->impulse = rb_v2(0.0, 0.0);
            p->motor_impulse = p->spring_impulse = p->lower_impulse = p->upper_impulse = 0.0;
            break;
        }
        case RB_JOINT_PULLEY:
            joint->as.pulley.impulse = joint->as.pulley.stop_a_impulse = joint->as.pulley.stop_b_impulse = 0.0;
            break;
        }
    }
}

void rb_joints_measure_errors(const rb_world *world, double *max_gap, double *max_angle)
{
    *max_gap = 0.0;
    *max_angle = 0.0;
    for (int i = 0; i < world->joint_slots; ++i) {
        const rb_joint *joint = &world->joints[i];
        if (!joint->in_use) {
            continue;
        }
        switch (joint->type) {
        case RB_JOINT_REVOLUTE:
            *max_gap = fmax(*max_gap, rb_distance(rb_joint_anchor_a(world, joint), rb_joint_anchor_b(world, joint)));
            *max_angle = fmax(*max_angle, rb_revolute_angle_error(world, joint));
            break;
        case RB_JOINT_WELD:
            if (joint->as.weld.linear_hertz == 0.0) {
                *max_gap =
                    fmax(*max_gap, rb_distance(rb_joint_anchor_a(world, joint), rb_joint_anchor_b(world, joint)));
            }
            *max_angle = fmax(*max_angle, rb_weld_angle_error(world, joint));
            break;
        case RB_JOINT_DISTANCE:
            *max_gap = fmax(*max_gap, rb_distance_error(world, joint));
            break;
        case RB_JOINT_PRISMATIC:
            *max_gap = fmax(*max_gap, rb_prismatic_gap(world, joint));
            *max_angle = fmax(*max_angle, rb_prismatic_angle_error(world, joint));
            break;
        case RB_JOINT_PULLEY:
            *max_gap = fmax(*max_gap, rb_pulley_gap(world, joint));
            break;
        case RB_JOINT_MOUSE:
            break; /* soft by design: its offset is not an error */
        }
    }
}
