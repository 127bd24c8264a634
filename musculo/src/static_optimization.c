/* SPDX-License-Identifier: MIT */
/* Static optimization (mu/static_optimization.h) with NLopt's SLSQP.
 *
 * The variables are x = (a_1 .. a_n, u_1 .. u_H): the n actuators'
 * activations (muscles, then torque muscles) and, per hinge in the
 * problem, the reserve in units of R, u_j = ρ_j/R, so that every
 * variable is of order one where the muscles suffice. The cost and its
 * gradient are
 *
 *   J = Σ_i a_i^p + Σ_j u_j²,   ∂J/∂a_i = p·a_i^(p−1),   ∂J/∂u_j = 2·u_j,
 *
 * and the constraints are linear in x: row j is Σ_i A_ji·a_i + R·u_j = b_j
 * with A_ji the torque about hinge j of actuator i at full activation and
 * b_j = τ_j − Σ_i r_ji·P_i the torque left once the passive forces are
 * counted; their gradient is the row itself.
 */
#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arguments.h"
#include "inverse_dynamics_forces.h"
#include "joint_sides.h"
#include "mu/inverse_dynamics.h"
#include "mu/model_desc.h"
#include "mu/moment_arms.h"
#include "mu/static_optimization.h"

/* A frame is solved when every constraint holds within this, relative to
 * 1 + |τ_j| (N·m). */
#define CONSTRAINT_TOLERANCE 1e-7
/* The first-order conditions hold when each activation's projected
 * gradient step (see optimal) is within this. */
#define KKT_TOLERANCE 1e-5

struct mu_static_optimizer {
    mu_model *model;
    mu_static_optimization_settings settings;
    int muscles, torque_muscles, actuators;
    int hinges;    /* the model's */
    int problem;   /* the hinges in the problem: built, with a side that moves */
    int *hinge_of; /* problem row -> model hinge */
    /* Per row: +1 when B's side of the hinge leaves the ground, -1 when
     * A's does (the side S whose motion inverse dynamics sums). */
    double *sigma;
    bool *path_turns;     /* [row][muscle][point]: whether the path point is on S */
    double *torque_sides; /* [row][torque muscle]: torque on B per unit exertion, N·m */
    nlopt_opt solver;
    double *x;                    /* actuators + problem */
    double *A;                    /* [row][actuator], N·m at full activation */
    double *b;                    /* [row], N·m */
    double *arms;                 /* [row][muscle], m */
    double *capacity;             /* [muscle]: C, N per unit activation */
    double *passive;              /* [muscle]: P, N */
    double *tensions;             /* [muscle]: a·C + P, N */
    double *torques;              /* [hinge]: τ */
    mu_hinge_force *hinge_forces; /* [hinge] */
};

mu_static_optimization_settings mu_default_static_optimization_settings(void)
{
    return (mu_static_optimization_settings){.exponent = MU_STATIC_OPTIMIZATION_DEFAULT_EXPONENT,
                                             .reserve_scale = MU_STATIC_OPTIMIZATION_DEFAULT_RESERVE_SCALE,
                                             .tolerance = 1e-12,
                                             .max_evaluations = 1000};
}

/* ------------------------------------------------------------ the problem */

static double cost(unsigned n, const double *x, double *gradient, void *data)
{
    const mu_static_optimizer *o = data;
    const double p = o->settings.exponent;
    double sum = 0.0;
    for (unsigned i = 0; i < n; ++i) {
        if ((int)i < o->actuators) {
            const double a = fmax(x[i], 0.0);
            sum += pow(a, p);
            if (gradient != NULL) {
                gradient[i] = p * pow(a, p - 1.0);
            }
        } else {
            sum += x[i] * x[i];
            if (gradient != NULL) {
                gradient[i] = 2.0 * x[i];
            }
        }
    }
    return sum;
}

static void constraints(unsigned m, double *result, unsigned n, const double *x, double *gradient, void *data)
{
    const mu_static_optimizer *o = data;
    for (unsigned j = 0; j < m; ++j) {
        const double *row = &o->A[(size_t)j * (size_t)o->actuators];
        double sum = o->settings.reserve_scale * x[o->actuators + (int)j] - o->b[j];
        for (int i = 0; i < o->actuators; ++i) {
            sum += row[i] * x[i];
        }
        result[j] = sum;
        if (gradient != NULL) {
            double *g = &gradient[(size_t)j * n];
            for (unsigned k = 0; k < n; ++k) {
                g[k] = (int)k < o->actuators ? row[k]
                                             : (k == (unsigned)o->actuators + j ? o->settings.reserve_scale : 0.0);
            }
        }
    }
}

/* ------------------------------------------------------------ set-up */

/* Reports the last error again as `function`'s, about `muscle` when not
 * NULL (copied first: the message is formatted into the same buffer). */
static rb_status report_again(rb_status status, const char *function, const char *muscle)
{
    char cause[1024];
    snprintf(cause, sizeof cause, "%s", rb_last_error());
    return muscle != NULL ? rb_report_error(status, "%s: muscle \"%s\": %s", function, muscle, cause)
                          : rb_report_error(status, "%s: %s", function, cause);
}

static rb_status check_settings(const mu_static_optimization_settings *s, const char *f)
{
    if (!(isfinite(s->exponent) && s->exponent >= 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: exponent is %g, expected a finite number >= 1", f,
                               s->exponent);
    }
    if (!(isfinite(s->reserve_scale) && s->reserve_scale > 0.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: reserve_scale is %g N·m, expected a finite number > 0", f,
                               s->reserve_scale);
    }
    if (!(s->tolerance > 0.0 && s->tolerance < 1.0)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: tolerance is %g, expected 0 < tolerance < 1", f,
                               s->tolerance);
    }
    if (s->max_evaluations < 1) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: max_evaluations is %d, expected >= 1", f,
                               s->max_evaluations);
    }
    return RB_OK;
}

/* The model body index of a model reference (a nail or a bone). */
static int body_of_ref(const mu_model *model, mu_model_ref ref)
{
    const mu_model_desc *desc = mu_model_description(model);
    return mu_model_part_body(model, ref.kind == MU_MODEL_NAIL ? ref.index : desc->nail_count + ref.index);
}

/* Torque muscle t's torque on S per unit exertion: its peak torque times
 * (s(body) − s(reaction body)), s = 1 on S; the world is never on S. */
static double torque_muscle_side(const mu_model *model, int t, const bool *turns)
{
    const mu_model_desc *desc = mu_model_description(model);
    const char *name = mu_model_torque_muscle_name(model, t);
    for (int d = 0; d < desc->torque_muscle_count; ++d) {
        const mu_model_torque_muscle *m = &desc->torque_muscles[d];
        if (strcmp(m->name, name) != 0) {
            continue;
        }
        const int body = body_of_ref(model, m->body);
        const int reaction = m->has_reaction_body ? body_of_ref(model, m->reaction_body) : -1;
        const double on_body = body >= 0 && turns[body] ? 1.0 : 0.0;
        const double on_reaction = reaction >= 0 && turns[reaction] ? 1.0 : 0.0;
        return m->peak_torque * (on_body - on_reaction);
    }
    return 0.0;
}

/* Puts hinge h in the problem when it is built and one of its sides
 * leaves the ground (S): its sign, and what lies on S. */
static rb_status add_hinge(mu_static_optimizer *o, int h)
{
    const rb_joint_id joint = mu_model_hinge_joint(o->model, h);
    if (rb_joint_id_is_null(joint)) {
        return RB_OK;
    }
    mu_joint_sides sides;
    bool from_a = false;
    rb_status status = mu_joint_sides_find(o->model, joint, false, &sides);
    if (status == RB_OK && sides.grounded) {
        mu_joint_sides_free(&sides);
        from_a = true;
        status = mu_joint_sides_find(o->model, joint, true, &sides);
    }
    if (status != RB_OK) {
        return status;
    }
    if (!sides.grounded) {
        const int row = o->problem;
        o->hinge_of[row] = h;
        o->sigma[row] = from_a ? -1.0 : 1.0;
        for (int i = 0; i < o->muscles; ++i) {
            (void)mu_joint_sides_of_path(
                o->model, i, &sides,
                &o->path_turns[((size_t)row * (size_t)o->muscles + (size_t)i) * RB_MAX_CABLE_POINTS]);
        }
        for (int t = 0; t < o->torque_muscles; ++t) {
            o->torque_sides[(size_t)row * (size_t)o->torque_muscles + (size_t)t] =
                o->sigma[row] * torque_muscle_side(o->model, t, sides.turns);
        }
        o->problem++;
    }
    mu_joint_sides_free(&sides);
    return RB_OK;
}

static rb_status allocate(mu_static_optimizer *o)
{
    const size_t n = (size_t)o->actuators, h = (size_t)o->hinges + 1, m = (size_t)o->muscles + 1;
    o->hinge_of = malloc(h * sizeof *o->hinge_of);
    o->sigma = malloc(h * sizeof *o->sigma);
    o->path_turns = calloc(h * m * RB_MAX_CABLE_POINTS, sizeof *o->path_turns);
    o->torque_sides = calloc(h * ((size_t)o->torque_muscles + 1), sizeof *o->torque_sides);
    o->x = calloc(n + h, sizeof *o->x);
    o->A = calloc(h * (n + 1), sizeof *o->A);
    o->b = calloc(h, sizeof *o->b);
    o->arms = calloc(h * m, sizeof *o->arms);
    o->capacity = calloc(m, sizeof *o->capacity);
    o->passive = calloc(m, sizeof *o->passive);
    o->tensions = calloc(m, sizeof *o->tensions);
    o->torques = calloc(h, sizeof *o->torques);
    o->hinge_forces = calloc(h, sizeof *o->hinge_forces);
    return o->hinge_of == NULL || o->sigma == NULL || o->path_turns == NULL || o->torque_sides == NULL ||
                   o->x == NULL || o->A == NULL || o->b == NULL || o->arms == NULL || o->capacity == NULL ||
                   o->passive == NULL || o->tensions == NULL || o->torques == NULL || o->hinge_forces == NULL
               ? RB_ERR_OUT_OF_MEMORY
               : RB_OK;
}

/* The SLSQP problem: bounds, cost and constraints. */
static rb_status set_up_solver(mu_static_optimizer *o)
{
    const unsigned n = (unsigned)(o->actuators + o->problem);
    o->solver = nlopt_create(NLOPT_LD_SLSQP, n);
    double *lower = malloc(n * sizeof *lower), *upper = malloc(n * sizeof *upper);
    double *tolerances = malloc(((size_t)o->problem + 1) * sizeof *tolerances);
    bool ok = o->solver != NULL && lower != NULL && upper != NULL && tolerances != NULL;
    for (unsigned i = 0; ok && i < n; ++i) {
        const bool actuator = (int)i < o->actuators;
        lower[i] = actuator ? 0.0 : -HUGE_VAL;
        upper[i] = actuator ? 1.0 : HUGE_VAL;
    }
    for (int j = 0; ok && j < o->problem; ++j) {
        tolerances[j] = 0.0;
    }
    ok = ok && nlopt_set_lower_bounds(o->solver, lower) > 0 && nlopt_set_upper_bounds(o->solver, upper) > 0 &&
         nlopt_set_min_objective(o->solver, cost, o) > 0 &&
         nlopt_add_equality_mconstraint(o->solver, (unsigned)o->problem, constraints, o, tolerances) > 0 &&
         nlopt_set_xtol_rel(o->solver, o->settings.tolerance) > 0 &&
         nlopt_set_xtol_abs1(o->solver, o->settings.tolerance) > 0 &&
         nlopt_set_maxeval(o->solver, o->settings.max_evaluations) > 0;
    free(lower);
    free(upper);
    free(tolerances);
    return ok ? RB_OK : RB_ERR_OUT_OF_MEMORY;
}

rb_status mu_static_optimizer_create(mu_model *model, const mu_static_optimization_settings *settings,
                                     mu_static_optimizer **out)
{
    const char *f = "mu_static_optimizer_create";
    if (mu_refuse_null(f, "out", out)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    *out = NULL;
    if (mu_refuse_null(f, "model", model) || mu_refuse_null(f, "settings", settings)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    rb_status status = check_settings(settings, f);
    if (status != RB_OK) {
        return status;
    }
    if (mu_model_check_tree(model) != RB_OK) {
        return report_again(RB_ERR_INVALID_ARGUMENT, f, NULL);
    }
    const int muscles = mu_model_muscle_count(model), torque_muscles = mu_model_torque_muscle_count(model);
    if (muscles + torque_muscles == 0) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: the model has no muscle or torque muscle built (at level 3 and above): nothing "
                               "to share its torques among",
                               f);
    }
    const rb_world *world = mu_model_world_to_read(model);
    for (int i = 0; i < muscles; ++i) {
        double capacity, passive;
        if (mu_muscle_forces_at_speed(mu_model_built_muscle(model, i), world, 0.0, &capacity, &passive) != RB_OK) {
            return report_again(RB_ERR_INVALID_ARGUMENT, f, mu_model_muscle_name(model, i));
        }
    }
    mu_static_optimizer *o = calloc(1, sizeof *o);
    if (o == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: out of memory", f);
    }
    *o = (mu_static_optimizer){.model = model,
                               .settings = *settings,
                               .muscles = muscles,
                               .torque_muscles = torque_muscles,
                               .actuators = muscles + torque_muscles,
                               .hinges = mu_model_hinge_count(model)};
    status = allocate(o);
    for (int h = 0; status == RB_OK && h < o->hinges; ++h) {
        status = add_hinge(o, h);
    }
    status = status == RB_OK ? set_up_solver(o) : status;
    if (status != RB_OK) {
        mu_static_optimizer_destroy(o);
        return status == RB_ERR_OUT_OF_MEMORY ? rb_report_error(status, "%s: out of memory", f) : status;
    }
    *out = o;
    return RB_OK;
}

void mu_static_optimizer_destroy(mu_static_optimizer *o)
{
    if (o == NULL) {
        return;
    }
    nlopt_destroy(o->solver);
    free(o->hinge_of);
    free(o->sigma);
    free(o->path_turns);
    free(o->torque_sides);
    free(o->x);
    free(o->A);
    free(o->b);
    free(o->arms);
    free(o->capacity);
    free(o->passive);
    free(o->tensions);
    free(o->torques);
    free(o->hinge_forces);
    free(o);
}

int mu_static_optimizer_actuator_count(const mu_static_optimizer *o)
{
    return mu_refuse_null("mu_static_optimizer_actuator_count", "optimizer", o) ? -1 : o->actuators;
}

/* ------------------------------------------------------------ one frame */

static rb_status check_frame(const mu_static_optimizer *o, const double *angles_deg, const double *rates,
                             const double *accelerations, const char *f)
{
    const mu_model_desc *desc = mu_model_description(o->model);
    for (int h = 0; h < o->hinges; ++h) {
        if (rb_joint_id_is_null(mu_model_hinge_joint(o->model, h))) {
            continue;
        }
        if (mu_refuse_non_finite(f, "angles_deg", angles_deg[h]) || mu_refuse_non_finite(f, "rates", rates[h]) ||
            mu_refuse_non_finite(f, "accelerations", accelerations[h])) {
            return RB_ERR_INVALID_ARGUMENT;
        }
        const mu_model_hinge *hinge = &desc->hinges[h];
        if ((hinge->has_lower && angles_deg[h] < hinge->lower) || (hinge->has_upper && angles_deg[h] > hinge->upper)) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "%s: hinge \"%s\" at %g degrees is outside its limits %g .. %g, where the limit "
                                   "and not an actuator would carry torque",
                                   f, hinge->name, angles_deg[h], hinge->has_lower ? hinge->lower : -INFINITY,
                                   hinge->has_upper ? hinge->upper : INFINITY);
        }
    }
    return RB_OK;
}

/* Poses the model and fills A and b from the pose, the rates and the
 * inverse-dynamics torques. */
static rb_status build_problem(mu_static_optimizer *o, const double *angles_deg, const double *rates,
                               const double *accelerations, const char *f)
{
    for (int j = 0; j < o->problem; ++j) {
        const int h = o->hinge_of[j];
        const rb_status status = mu_model_pose_hinge(o->model, h, angles_deg[h]);
        if (status != RB_OK) {
            return report_again(status, f, NULL);
        }
    }
    rb_status status =
        mu_inverse_dynamics_with_forces(o->model, f, angles_deg, rates, accelerations, o->torques, o->hinge_forces);
    for (int j = 0; status == RB_OK && j < o->problem; ++j) {
        status = mu_model_moment_arms(o->model, o->hinge_of[j], &o->arms[(size_t)j * (size_t)o->muscles]);
    }
    const rb_world *world = mu_model_world_to_read(o->model);
    for (int i = 0; status == RB_OK && i < o->muscles; ++i) {
        /* L' = Σ_j (∂L/∂θ_j)·θ'_j = −Σ_j r_ij·θ'_j */
        double speed = 0.0;
        for (int j = 0; j < o->problem; ++j) {
            speed -= o->arms[(size_t)j * (size_t)o->muscles + (size_t)i] * rates[o->hinge_of[j]];
        }
        status = mu_muscle_forces_at_speed(mu_model_built_muscle(o->model, i), world, speed, &o->capacity[i],
                                           &o->passive[i]);
    }
    if (status != RB_OK) {
        return report_again(status, f, NULL);
    }
    for (int j = 0; j < o->problem; ++j) {
        double *row = &o->A[(size_t)j * (size_t)o->actuators];
        const double *arms = &o->arms[(size_t)j * (size_t)o->muscles];
        o->b[j] = o->torques[o->hinge_of[j]];
        for (int i = 0; i < o->muscles; ++i) {
            row[i] = arms[i] * o->capacity[i];
            o->b[j] -= arms[i] * o->passive[i];
        }
        for (int t = 0; t < o->torque_muscles; ++t) {
            row[o->muscles + t] = o->torque_sides[(size_t)j * (size_t)o->torque_muscles + (size_t)t];
        }
    }
    return RB_OK;
}

/* The reaction of problem row j's hinge on body B, with the muscles
 * pulling their tensions: Newton's law for S (inverse_dynamics_forces.h)
 * less the muscles' pulls on S's path points. */
static mu_joint_load reaction(const mu_static_optimizer *o, int j, const double *tensions)
{
    const int h = o->hinge_of[j];
    const rb_world *world = mu_model_world_to_read(o->model);
    rb_vec2 on_side = o->hinge_forces[h].moving;
    double muscle_torque = 0.0;
    for (int i = 0; i < o->muscles; ++i) {
        const bool *turns = &o->path_turns[((size_t)j * (size_t)o->muscles + (size_t)i) * RB_MAX_CABLE_POINTS];
        rb_vec2 points[RB_MAX_CABLE_POINTS];
        const int count =
            rb_cable_points(world, mu_muscle_cable(mu_model_built_muscle(o->model, i)), points, RB_MAX_CABLE_POINTS);
        for (int k = 0; k + 1 < count; ++k) {
            if (turns[k] == turns[k + 1]) {
                continue;
            }
            /* The segment pulls its end on S towards its other end. */
            const rb_vec2 end = turns[k] ? points[k] : points[k + 1], other = turns[k] ? points[k + 1] : points[k];
            on_side = rb_sub(on_side, rb_scale(tensions[i], rb_normalize(rb_sub(other, end))));
        }
        muscle_torque += o->arms[(size_t)j * (size_t)o->muscles + (size_t)i] * tensions[i];
    }
    const rb_vec2 force = rb_scale(o->sigma[j], on_side);
    const rb_vec2 axis = mu_model_hinge_bone_axis(o->model, h);
    return (mu_joint_load){.force = force,
                           .along = rb_dot(axis, force),
                           .across = rb_cross(axis, force),
                           .torque = 0.0,
                           .muscle_torque = muscle_torque};
}

static void fill_nan(const mu_static_optimizer *o, mu_static_frame *frame)
{
    const mu_joint_load nan_load = {{NAN, NAN}, NAN, NAN, NAN, NAN};
    for (int h = 0; h < o->hinges; ++h) {
        if (frame->net_torques != NULL) {
            frame->net_torques[h] = NAN;
        }
        if (frame->actuator_torques != NULL) {
            frame->actuator_torques[h] = NAN;
        }
        if (frame->reserves != NULL) {
            frame->reserves[h] = NAN;
        }
        if (frame->loads != NULL) {
            frame->loads[h] = nan_load;
        }
    }
}

/* The frame's outputs from x; whether the constraints hold. */
static bool fill_frame(const mu_static_optimizer *o, mu_static_frame *frame)
{
    double *tensions = o->tensions;
    for (int i = 0; i < o->actuators; ++i) {
        const double a = fmin(fmax(o->x[i], 0.0), 1.0);
        const double force =
            i < o->muscles ? a * o->capacity[i] + o->passive[i]
                           : a * mu_torque_actuator_peak_torque(mu_model_torque_actuator(o->model, i - o->muscles));
        if (i < o->muscles) {
            tensions[i] = force;
        }
        if (frame->activations != NULL) {
            frame->activations[i] = a;
        }
        if (frame->forces != NULL) {
            frame->forces[i] = force;
        }
    }
    fill_nan(o, frame);
    bool holds = true;
    for (int j = 0; j < o->problem; ++j) {
        const int h = o->hinge_of[j];
        const double *row = &o->A[(size_t)j * (size_t)o->actuators];
        const double tau = o->torques[h];
        double actuators = tau - o->b[j]; /* the passive forces' torque */
        for (int i = 0; i < o->actuators; ++i) {
            actuators += row[i] * fmin(fmax(o->x[i], 0.0), 1.0);
        }
        const double reserve = o->settings.reserve_scale * o->x[o->actuators + j];
        holds = holds && fabs(actuators + reserve - tau) <= CONSTRAINT_TOLERANCE * (1.0 + fabs(tau));
        if (frame->net_torques != NULL) {
            frame->net_torques[h] = tau;
        }
        if (frame->actuator_torques != NULL) {
            frame->actuator_torques[h] = actuators;
        }
        if (frame->reserves != NULL) {
            frame->reserves[h] = reserve;
        }
        if (frame->loads != NULL) {
            frame->loads[h] = reaction(o, j, tensions);
        }
    }
    return holds;
}

/* Whether x satisfies the first-order (Karush–Kuhn–Tucker) conditions
 * of the problem. With the multipliers λ_j = 2·w·u_j/S that make the
 * reserves stationary, each activation's gradient of the Lagrangian is
 * g_i = p·a_i^(p−1) − Σ_j λ_j·A_ji, which must vanish inside the bounds,
 * be >= 0 at 0 and <= 0 at 1: the projected gradient step
 * |a_i − clamp(a_i − g_i/(1 + size_i), 0, 1)|, size_i the terms' sum of
 * magnitudes, must be within KKT_TOLERANCE. */
static bool optimal(const mu_static_optimizer *o)
{
    const double p = o->settings.exponent;
    for (int i = 0; i < o->actuators; ++i) {
        const double a = fmin(fmax(o->x[i], 0.0), 1.0);
        const double own = p * pow(a, p - 1.0);
        double pull = 0.0, size = own;
        for (int j = 0; j < o->problem; ++j) {
            const double term = 2.0 * o->x[o->actuators + j] / o->settings.reserve_scale *
                                o->A[(size_t)j * (size_t)o->actuators + (size_t)i];
            pull += term;
            size += fabs(term);
        }
        const double step = a - fmin(fmax(a - (own - pull) / (1.0 + size), 0.0), 1.0);
        if (fabs(step) > KKT_TOLERANCE) {
            return false;
        }
    }
    return true;
}

/* One run of SLSQP from the activations in x and zero reserves (SLSQP
 * stalls when started where the constraints already hold through large
 * reserves); whether it ended at a solution. */
static bool run_solver(mu_static_optimizer *o, mu_static_frame *frame)
{
    for (int j = 0; j < o->problem; ++j) {
        o->x[o->actuators + j] = 0.0;
    }
    double minimum;
    const nlopt_result result = nlopt_optimize(o->solver, o->x, &minimum);
    frame->solver_result = (int)result;
    const bool holds = fill_frame(o, frame);
    return result != NLOPT_INVALID_ARGS && result != NLOPT_OUT_OF_MEMORY && holds && optimal(o);
}

rb_status mu_static_optimizer_solve(mu_static_optimizer *o, const double *angles_deg, const double *rates,
                                    const double *accelerations, mu_static_frame *frame)
{
    const char *f = "mu_static_optimizer_solve";
    if (mu_refuse_null(f, "optimizer", o) || mu_refuse_null(f, "angles_deg", angles_deg) ||
        mu_refuse_null(f, "rates", rates) || mu_refuse_null(f, "accelerations", accelerations) ||
        mu_refuse_null(f, "frame", frame)) {
        return RB_ERR_INVALID_ARGUMENT;
    }
    rb_status status = check_frame(o, angles_deg, rates, accelerations, f);
    status = status == RB_OK ? build_problem(o, angles_deg, rates, accelerations, f) : status;
    if (status != RB_OK) {
        return status;
    }
    /* The warm start: the previous frame's activations; failing that, once
     * more from where that run stopped (SLSQP's quasi-Newton estimate of
     * the cost's curvature starts afresh), and last a cold start from
     * zero. */
    for (int i = 0; i < o->actuators; ++i) {
        o->x[i] = isfinite(o->x[i]) ? fmin(fmax(o->x[i], 0.0), 1.0) : 0.0;
    }
    frame->solved = run_solver(o, frame) || run_solver(o, frame);
    if (!frame->solved) {
        for (int i = 0; i < o->actuators; ++i) {
            o->x[i] = 0.0;
        }
        frame->solved = run_solver(o, frame);
    }
    return RB_OK;
}

const char *mu_static_optimizer_result_name(int solver_result)
{
    const char *name = solver_result >= NLOPT_FORCED_STOP && solver_result <= NLOPT_MAXTIME_REACHED
                           ? nlopt_result_to_string((nlopt_result)solver_result)
                           : NULL;
    if (name == NULL) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT,
                        "mu_static_optimizer_result_name: solver_result is %d, not an NLopt result code",
                        solver_result);
    }
    return name;
}
