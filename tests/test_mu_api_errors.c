/* SPDX-License-Identifier: MIT */
/* Hostile arguments to every function of the muscle layer's API: NULL
 * pointers, indices out of range (-1, the count, INT_MIN, INT_MAX), NaN
 * and infinities where a finite value is documented. Each call must
 * return its documented error value (a status, NaN, NULL, false, -1 or a
 * zero count) and record RB_ERR_INVALID_ARGUMENT with a message naming
 * the function and the argument, as the engine's API does (rb/base.h);
 * run under the sanitizers, a read out of bounds or through NULL fails.
 *
 * The table has one entry per MU_API function, and a test reads the
 * public headers and fails for a function the table does not storm, so
 * a new function gets its checks and its case together.
 */
#define _POSIX_C_SOURCE 200809L

#include <criterion/criterion.h>
#include <criterion/parameterized.h>
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mu/activation.h"
#include "mu/bone_stress.h"
#include "mu/calcium_force.h"
#include "mu/curves.h"
#include "mu/geometry_lengths.h"
#include "mu/inverse_dynamics.h"
#include "mu/joint_loads.h"
#include "mu/model.h"
#include "mu/model_desc.h"
#include "mu/moment_arms.h"
#include "mu/motor_pool.h"
#include "mu/muscle.h"
#include "mu/muscle_statics.h"
#include "mu/pennation.h"
#include "mu/static_optimization.h"
#include "mu/tendon.h"
#include "mu/torque_actuator.h"
#include "mu/version.h"

/* ------------------------------------------------------------ checking */

/* Sets the last status to RB_OK, so that a call that records nothing is
 * seen as such. */
static void clear_error(void) { rb_report_error(RB_OK, "%s", ""); }

/* The last call recorded RB_ERR_INVALID_ARGUMENT with a message naming
 * `function` and `argument`. */
static void expect_refused(const char *function, const char *argument, int line)
{
    const char *message = rb_last_error();
    cr_expect_eq(rb_last_status(), RB_ERR_INVALID_ARGUMENT, "line %d: %s (%s): status %s, message \"%s\"", line,
                 function, argument, rb_status_name(rb_last_status()), message);
    cr_expect(strstr(message, function) != NULL && strstr(message, argument) != NULL,
              "line %d: %s (%s): the message should name the function and the argument: \"%s\"", line, function,
              argument, message);
}

#define REFUSED_STATUS(call, function, argument)                                                                       \
    do {                                                                                                               \
        clear_error();                                                                                                 \
        rb_status status_ = (call);                                                                                    \
        cr_expect_eq(status_, RB_ERR_INVALID_ARGUMENT, "line %d: %s returned %s", __LINE__, #call,                     \
                     rb_status_name(status_));                                                                         \
        expect_refused(function, argument, __LINE__);                                                                  \
    } while (0)

#define REFUSED_NAN(call, function, argument)                                                                          \
    do {                                                                                                               \
        clear_error();                                                                                                 \
        double value_ = (call);                                                                                        \
        cr_expect(isnan(value_), "line %d: %s returned %g, expected NaN", __LINE__, #call, value_);                    \
        expect_refused(function, argument, __LINE__);                                                                  \
    } while (0)

#define REFUSED_VALUE(call, expected, function, argument)                                                              \
    do {                                                                                                               \
        clear_error();                                                                                                 \
        cr_expect((call) == (expected), "line %d: %s did not return %s", __LINE__, #call, #expected);                  \
        expect_refused(function, argument, __LINE__);                                                                  \
    } while (0)

/* A status-returning constructor: refused, and *out left NULL. */
#define REFUSED_CREATE(call, out, function, argument)                                                                  \
    do {                                                                                                               \
        (out) = NULL;                                                                                                  \
        REFUSED_STATUS(call, function, argument);                                                                      \
        cr_expect_null((out), "line %d: %s made an object", __LINE__, #call);                                          \
    } while (0)

/* ------------------------------------------------------------ fixtures */

static const double bad_doubles[] = {NAN, INFINITY, -INFINITY};
#define FOR_BAD_DOUBLES(v) for (size_t k_ = 0; k_ < 3 && ((v) = bad_doubles[k_], true); ++k_)

/* Indices out of range of a list of `count`. */
#define FOR_BAD_INDICES(i, count)                                                                                      \
    for (int j_ = 0, bad_[4] = {-1, (count), INT_MIN, INT_MAX}; j_ < 4 && ((i) = bad_[j_], true); ++j_)

static mu_model_desc *load(const char *name)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin(name, &desc), RB_OK, "%s", rb_last_error());
    return desc;
}

static mu_model *build(const mu_model_desc *desc)
{
    mu_model *model = NULL;
    mu_model_options options = mu_default_model_options();
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    return model;
}

/* A world with a static anchor and a dynamic box, and a muscle between them. */
typedef struct muscle_rig {
    rb_world *world;
    rb_body_id anchor, box;
    mu_curves *curves;
    mu_muscle *muscle;
} muscle_rig;

static muscle_rig make_rig(void)
{
    muscle_rig rig = {0};
    rb_world_def world_def = rb_default_world_def();
    cr_assert_eq(rb_world_create(&world_def, &rig.world), RB_OK, "%s", rb_last_error());
    rb_body_def body_def = rb_default_body_def();
    cr_assert_eq(rb_body_create(rig.world, &body_def, &rig.anchor), RB_OK, "%s", rb_last_error());
    body_def.type = RB_BODY_DYNAMIC;
    body_def.position = rb_v2(0.0, -0.3);
    cr_assert_eq(rb_body_create(rig.world, &body_def, &rig.box), RB_OK, "%s", rb_last_error());
    rb_shape_def shape_def = rb_default_shape_def();
    rb_polygon box;
    cr_assert_eq(rb_make_box(0.05, 0.05, &box), RB_OK);
    rb_shape_id shape;
    cr_assert_eq(rb_shape_create_polygon(rig.world, rig.box, &shape_def, &box, &shape), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &rig.curves), RB_OK, "%s", rb_last_error());
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = rig.anchor;
    def.bodies[1] = rig.box;
    def.local_points[0] = rb_v2(0.0, 0.0);
    def.local_points[1] = rb_v2(0.0, 0.05);
    def.rest_length = 0.2;
    def.max_force = 100.0;
    def.curves = rig.curves;
    cr_assert_eq(mu_muscle_create(rig.world, &def, &rig.muscle), RB_OK, "%s", rb_last_error());
    return rig;
}

static void free_rig(muscle_rig *rig)
{
    mu_muscle_destroy(rig->muscle, rig->world);
    mu_curves_destroy(rig->curves);
    rb_world_destroy(rig->world);
}

static const char *missing_file = SINEW_SOURCE_DIR "/tests/data/no-such-file";

/* ------------------------------------------------------------ the storms */

/* Functions without an argument to check: called once, they succeed. */
static void storm_no_arguments(void)
{
    (void)mu_default_activation_params();
    (void)mu_default_analytic_curves();
    (void)mu_default_model_options();
    (void)mu_default_muscle_def();
    (void)mu_default_torque_actuator_def();
    cr_expect_gt(mu_builtin_model_count(), 0);
    cr_expect_not_null(mu_version());
}

static void storm_activation(void)
{
    mu_activation_params good = mu_default_activation_params();
    double bad;
    REFUSED_NAN(mu_activation_time_constant(0.5, NULL), "mu_activation_time_constant", "params");
    FOR_BAD_DOUBLES(bad)
    {
        REFUSED_NAN(mu_activation_time_constant(bad, &good), "mu_activation_time_constant", "activation");
        mu_activation_params params = good;
        params.excitation = bad;
        REFUSED_NAN(mu_activation_time_constant(0.5, &params), "mu_activation_time_constant", "excitation");
        params = good;
        params.activation_time = bad;
        REFUSED_NAN(mu_activation_step(0.5, 0.01, &params), "mu_activation_step", "activation_time");
        params = good;
        params.deactivation_time = bad;
        REFUSED_NAN(mu_activation_step(0.5, 0.01, &params), "mu_activation_step", "deactivation_time");
        REFUSED_NAN(mu_activation_step(bad, 0.01, &good), "mu_activation_step", "activation");
        REFUSED_NAN(mu_activation_step(0.5, bad, &good), "mu_activation_step", "h");
        double y[1] = {bad}, dydt[1];
        clear_error();
        cr_expect_neq(mu_activation_derivative(0.0, y, dydt, &good), 0);
        expect_refused("mu_activation_derivative", "y", __LINE__);
    }
    REFUSED_NAN(mu_activation_step(0.5, -0.01, &good), "mu_activation_step", "h");
    REFUSED_NAN(mu_activation_step(0.5, 0.01, NULL), "mu_activation_step", "params");
    double y[1] = {0.5}, dydt[1];
    clear_error();
    cr_expect_neq(mu_activation_derivative(0.0, NULL, dydt, &good), 0);
    expect_refused("mu_activation_derivative", "y", __LINE__);
    clear_error();
    cr_expect_neq(mu_activation_derivative(0.0, y, NULL, &good), 0);
    expect_refused("mu_activation_derivative", "dydt", __LINE__);
    clear_error();
    cr_expect_neq(mu_activation_derivative(0.0, y, dydt, NULL), 0);
    expect_refused("mu_activation_derivative", "params", __LINE__);
}

static void storm_calcium_force(void)
{
    const mu_calcium_force_params good = {.excitation = 0.5, .times = mu_calcium_force_times_of(MU_FIBRE_FAST)};
    clear_error();
    mu_calcium_force_times none = mu_calcium_force_times_of((mu_fibre_type)99);
    cr_expect(isnan(none.calcium_rise_time) && isnan(none.force_decay_time), "an unknown fibre type gives NaN times");
    expect_refused("mu_calcium_force_times_of", "type", __LINE__);
    static const char *const fields[4] = {"calcium_rise_time", "calcium_decay_time", "force_rise_time",
                                          "force_decay_time"};
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        mu_calcium_force_params params = good;
        params.excitation = bad;
        mu_calcium_force_state state = {0.5, 0.5};
        REFUSED_STATUS(mu_calcium_force_step(&state, 0.01, &params), "mu_calcium_force_step", "excitation");
        for (int k = 0; k < 4; ++k) {
            params = good;
            double *times[4] = {&params.times.calcium_rise_time, &params.times.calcium_decay_time,
                                &params.times.force_rise_time, &params.times.force_decay_time};
            *times[k] = bad;
            REFUSED_STATUS(mu_calcium_force_step(&state, 0.01, &params), "mu_calcium_force_step", fields[k]);
        }
        REFUSED_STATUS(mu_calcium_force_step(&state, bad, &good), "mu_calcium_force_step", "h");
        state.calcium = bad;
        REFUSED_STATUS(mu_calcium_force_step(&state, 0.01, &good), "mu_calcium_force_step", "calcium");
        state = (mu_calcium_force_state){0.5, bad};
        REFUSED_STATUS(mu_calcium_force_step(&state, 0.01, &good), "mu_calcium_force_step", "activation");
        double y[2] = {0.5, bad}, dydt[2];
        clear_error();
        cr_expect_neq(mu_calcium_force_derivative(0.0, y, dydt, (void *)&good), 0);
        expect_refused("mu_calcium_force_derivative", "y", __LINE__);
    }
    mu_calcium_force_state state = {0.5, 0.5};
    REFUSED_STATUS(mu_calcium_force_step(NULL, 0.01, &good), "mu_calcium_force_step", "state");
    REFUSED_STATUS(mu_calcium_force_step(&state, 0.01, NULL), "mu_calcium_force_step", "params");
    double y[2] = {0.5, 0.5}, dydt[2];
    clear_error();
    cr_expect_neq(mu_calcium_force_derivative(0.0, NULL, dydt, (void *)&good), 0);
    expect_refused("mu_calcium_force_derivative", "y", __LINE__);
    clear_error();
    cr_expect_neq(mu_calcium_force_derivative(0.0, y, NULL, (void *)&good), 0);
    expect_refused("mu_calcium_force_derivative", "dydt", __LINE__);
    clear_error();
    cr_expect_neq(mu_calcium_force_derivative(0.0, y, dydt, NULL), 0);
    expect_refused("mu_calcium_force_derivative", "params", __LINE__);
}

static void storm_curves_create(void)
{
    mu_curves *curves;
    REFUSED_CREATE(mu_curves_create_tabulated(NULL, MU_INTERPOLATION_LINEAR, &curves), curves,
                   "mu_curves_create_tabulated", "path");
    REFUSED_CREATE(
        mu_curves_create_tabulated(SINEW_SOURCE_DIR "/models/data/hill-curves.csv", (mu_interpolation)99, &curves),
        curves, "mu_curves_create_tabulated", "interpolation");
    REFUSED_STATUS(
        mu_curves_create_tabulated(SINEW_SOURCE_DIR "/models/data/hill-curves.csv", MU_INTERPOLATION_LINEAR, NULL),
        "mu_curves_create_tabulated", "out");
    REFUSED_CREATE(mu_curves_create_seed_tables((mu_interpolation)-1, &curves), curves, "mu_curves_create_seed_tables",
                   "interpolation");
    REFUSED_STATUS(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, NULL), "mu_curves_create_seed_tables", "out");
    REFUSED_CREATE(mu_curves_create_analytic(NULL, &curves), curves, "mu_curves_create_analytic", "parameters");
    mu_analytic_curves good = mu_default_analytic_curves();
    REFUSED_STATUS(mu_curves_create_analytic(&good, NULL), "mu_curves_create_analytic", "out");
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        mu_analytic_curves parameters = good;
        parameters.width = bad;
        REFUSED_CREATE(mu_curves_create_analytic(&parameters, &curves), curves, "mu_curves_create_analytic", "width");
        parameters = good;
        parameters.passive_rate = bad;
        REFUSED_CREATE(mu_curves_create_analytic(&parameters, &curves), curves, "mu_curves_create_analytic",
                       "passive_rate");
    }
    mu_curves_destroy(NULL);
}

static void storm_curves_evaluate(void)
{
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_STEFFEN, &curves), RB_OK);
    mu_curve_hint hint = {0};
    REFUSED_NAN(mu_curve_active_length(NULL, 1.0), "mu_curve_active_length", "curves");
    REFUSED_NAN(mu_curve_passive_length(NULL, 1.0), "mu_curve_passive_length", "curves");
    REFUSED_NAN(mu_curve_velocity(NULL, 0.0), "mu_curve_velocity", "curves");
    REFUSED_NAN(mu_curve_velocity_slope(NULL, 0.0), "mu_curve_velocity_slope", "curves");
    REFUSED_NAN(mu_curve_active_length(curves, NAN), "mu_curve_active_length", "normalized_length");
    REFUSED_NAN(mu_curve_passive_length(curves, NAN), "mu_curve_passive_length", "normalized_length");
    REFUSED_NAN(mu_curve_velocity(curves, NAN), "mu_curve_velocity", "normalized_velocity");
    REFUSED_NAN(mu_curve_velocity_slope(curves, NAN), "mu_curve_velocity_slope", "normalized_velocity");
    REFUSED_NAN(mu_curve_active_length_hinted(NULL, &hint, 1.0), "mu_curve_active_length_hinted", "curves");
    REFUSED_NAN(mu_curve_passive_length_hinted(NULL, &hint, 1.0), "mu_curve_passive_length_hinted", "curves");
    REFUSED_NAN(mu_curve_velocity_hinted(NULL, &hint, 0.0), "mu_curve_velocity_hinted", "curves");
    REFUSED_NAN(mu_curve_velocity_slope_hinted(NULL, &hint, 0.0), "mu_curve_velocity_slope_hinted", "curves");
    REFUSED_NAN(mu_curve_active_length_hinted(curves, &hint, NAN), "mu_curve_active_length_hinted",
                "normalized_length");
    REFUSED_NAN(mu_curve_passive_length_hinted(curves, &hint, NAN), "mu_curve_passive_length_hinted",
                "normalized_length");
    REFUSED_NAN(mu_curve_velocity_hinted(curves, &hint, NAN), "mu_curve_velocity_hinted", "normalized_velocity");
    REFUSED_NAN(mu_curve_velocity_slope_hinted(curves, &hint, NAN), "mu_curve_velocity_slope_hinted",
                "normalized_velocity");
    double slope = 0.0;
    REFUSED_NAN(mu_curve_velocity_and_slope_hinted(NULL, &hint, 0.0, &slope), "mu_curve_velocity_and_slope_hinted",
                "curves");
    cr_expect(isnan(slope), "a refused look-up's slope is NaN");
    REFUSED_NAN(mu_curve_velocity_and_slope_hinted(curves, &hint, NAN, &slope), "mu_curve_velocity_and_slope_hinted",
                "normalized_velocity");
    REFUSED_NAN(mu_curve_velocity_and_slope_hinted(curves, &hint, 0.0, NULL), "mu_curve_velocity_and_slope_hinted",
                "slope");
    /* A hint whose intervals are garbage is only a hint: the look-up is
     * the plain one's. */
    mu_curve_hint garbage = {{(size_t)-1, 123456789, 99}};
    cr_expect_eq(mu_curve_active_length_hinted(curves, &garbage, 1.1), mu_curve_active_length(curves, 1.1));
    cr_expect_eq(mu_curve_passive_length_hinted(curves, &garbage, 1.4), mu_curve_passive_length(curves, 1.4));
    cr_expect_eq(mu_curve_velocity_hinted(curves, &garbage, -0.3), mu_curve_velocity(curves, -0.3));
    cr_expect_eq(mu_curve_velocity_slope_hinted(curves, &garbage, -0.3), mu_curve_velocity_slope(curves, -0.3));
    cr_expect_eq(mu_curve_velocity_and_slope_hinted(curves, &garbage, -0.3, &slope), mu_curve_velocity(curves, -0.3));
    cr_expect_eq(slope, mu_curve_velocity_slope(curves, -0.3));
    mu_curves_destroy(curves);
}

static void storm_geometry_lengths(void)
{
    mu_derived_lengths out;
    REFUSED_STATUS(mu_lengths_from_geometry(0.3, 0.2, 1.0, 0.0, NULL), "mu_lengths_from_geometry", "out");
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        REFUSED_STATUS(mu_lengths_from_geometry(bad, 0.2, 1.0, 0.0, &out), "mu_lengths_from_geometry", "path_length");
        REFUSED_STATUS(mu_lengths_from_geometry(0.3, bad, 1.0, 0.0, &out), "mu_lengths_from_geometry",
                       "tendon_fraction");
        REFUSED_STATUS(mu_lengths_from_geometry(0.3, 0.2, bad, 0.0, &out), "mu_lengths_from_geometry",
                       "start_normalized_length");
        REFUSED_STATUS(mu_lengths_from_geometry(0.3, 0.2, 1.0, bad, &out), "mu_lengths_from_geometry",
                       "pennation_angle");
    }
}

static void storm_model_create(void)
{
    mu_model_desc *desc = load("arm");
    mu_model_options options = mu_default_model_options();
    mu_model *model;
    REFUSED_CREATE(mu_model_create(NULL, &options, &model), model, "mu_model_create", "desc");
    REFUSED_CREATE(mu_model_create(desc, NULL, &model), model, "mu_model_create", "options");
    REFUSED_STATUS(mu_model_create(desc, &options, NULL), "mu_model_create", "out");
    int bad;
    FOR_BAD_INDICES(bad, 5)
    {
        options = mu_default_model_options();
        options.level = bad;
        REFUSED_CREATE(mu_model_create(desc, &options, &model), model, "mu_model_create", "level");
    }
    FOR_BAD_INDICES(bad, desc->variant_count)
    {
        options = mu_default_model_options();
        options.variant = bad;
        REFUSED_CREATE(mu_model_create(desc, &options, &model), model, "mu_model_create", "variant");
    }
    FOR_BAD_INDICES(bad, desc->weight.mass_count)
    {
        options = mu_default_model_options();
        options.weight_index = bad;
        REFUSED_CREATE(mu_model_create(desc, &options, &model), model, "mu_model_create", "weight_index");
    }
    mu_model_destroy(NULL);
    mu_model_desc_destroy(desc);
}

static void storm_model_running(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    REFUSED_VALUE(mu_model_world(NULL), NULL, "mu_model_world", "model");
    REFUSED_VALUE(mu_model_description(NULL), NULL, "mu_model_description", "model");
    REFUSED_STATUS(mu_model_step(NULL), "mu_model_step", "model");
    REFUSED_STATUS(mu_model_substep(NULL), "mu_model_substep", "model");
    REFUSED_NAN(mu_model_time(NULL), "mu_model_time", "model");
    REFUSED_NAN(mu_model_frame_duration(NULL), "mu_model_frame_duration", "model");
    REFUSED_NAN(mu_model_substep_duration(NULL), "mu_model_substep_duration", "model");
    REFUSED_STATUS(mu_model_set_gravity(NULL, rb_v2(0.0, -9.8)), "mu_model_set_gravity", "model");
    REFUSED_STATUS(mu_model_set_gravity(model, rb_v2(NAN, -9.8)), "mu_model_set_gravity", "gravity");
    REFUSED_VALUE(mu_model_warnings(NULL), NULL, "mu_model_warnings", "model");
    REFUSED_VALUE(mu_model_failure(NULL), NULL, "mu_model_failure", "model");
    REFUSED_NAN(mu_model_energy_account(NULL).created, "mu_model_energy_account", "model");
    REFUSED_VALUE(mu_model_body_count(NULL), 0, "mu_model_body_count", "model");
    REFUSED_VALUE(mu_model_joint_count(NULL), 0, "mu_model_joint_count", "model");
    /* The model still runs after all that. */
    cr_expect_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_model_inverse(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    const int n = mu_model_hinge_count(model);
    double zeros[16] = {0}, torques[16];
    cr_assert_leq(n, 16);
    REFUSED_STATUS(mu_model_check_tree(NULL), "mu_model_check_tree", "model");
    REFUSED_STATUS(mu_model_inverse_dynamics(NULL, zeros, zeros, zeros, torques), "mu_model_inverse_dynamics", "model");
    REFUSED_STATUS(mu_model_inverse_dynamics(model, NULL, zeros, zeros, torques), "mu_model_inverse_dynamics",
                   "angles_deg");
    REFUSED_STATUS(mu_model_inverse_dynamics(model, zeros, NULL, zeros, torques), "mu_model_inverse_dynamics", "rates");
    REFUSED_STATUS(mu_model_inverse_dynamics(model, zeros, zeros, NULL, torques), "mu_model_inverse_dynamics",
                   "accelerations");
    REFUSED_STATUS(mu_model_inverse_dynamics(model, zeros, zeros, zeros, NULL), "mu_model_inverse_dynamics", "torques");
    double bad[16] = {0};
    bad[0] = NAN;
    REFUSED_STATUS(mu_model_inverse_dynamics(model, bad, zeros, zeros, torques), "mu_model_inverse_dynamics",
                   "angles_deg");
    REFUSED_STATUS(mu_model_inverse_dynamics(model, zeros, bad, zeros, torques), "mu_model_inverse_dynamics", "rates");
    REFUSED_STATUS(mu_model_inverse_dynamics(model, zeros, zeros, bad, torques), "mu_model_inverse_dynamics",
                   "accelerations");
    /* The arm is a tree; the model still answers after all that. */
    cr_expect_eq(mu_model_check_tree(model), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_model_inverse_dynamics(model, zeros, zeros, zeros, torques), RB_OK, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_static_optimization(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    mu_static_optimizer *optimizer = NULL;
    const mu_static_optimization_settings good = mu_default_static_optimization_settings();
    mu_static_optimization_settings settings = good;
    REFUSED_STATUS(mu_static_optimizer_create(model, &settings, NULL), "mu_static_optimizer_create", "out");
    REFUSED_CREATE(mu_static_optimizer_create(NULL, &settings, &optimizer), optimizer, "mu_static_optimizer_create",
                   "model");
    REFUSED_CREATE(mu_static_optimizer_create(model, NULL, &optimizer), optimizer, "mu_static_optimizer_create",
                   "settings");
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        settings = good;
        settings.exponent = bad;
        REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer,
                       "mu_static_optimizer_create", "exponent");
        settings = good;
        settings.reserve_scale = bad;
        REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer,
                       "mu_static_optimizer_create", "reserve_scale");
        settings = good;
        settings.tolerance = bad;
        REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer,
                       "mu_static_optimizer_create", "tolerance");
    }
    settings = good;
    settings.exponent = 0.99;
    REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer, "mu_static_optimizer_create",
                   "exponent");
    settings = good;
    settings.reserve_scale = -1.0;
    REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer, "mu_static_optimizer_create",
                   "reserve_scale");
    settings = good;
    settings.tolerance = 1.0;
    REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer, "mu_static_optimizer_create",
                   "tolerance");
    settings = good;
    settings.max_evaluations = 0;
    REFUSED_CREATE(mu_static_optimizer_create(model, &settings, &optimizer), optimizer, "mu_static_optimizer_create",
                   "max_evaluations");
    REFUSED_VALUE(mu_static_optimizer_actuator_count(NULL), -1, "mu_static_optimizer_actuator_count", "optimizer");
    REFUSED_VALUE(mu_static_optimizer_result_name(99), NULL, "mu_static_optimizer_result_name", "solver_result");
    cr_expect_str_eq(mu_static_optimizer_result_name(4), "XTOL_REACHED");
    mu_static_optimizer_destroy(NULL);

    cr_assert_eq(mu_static_optimizer_create(model, &good, &optimizer), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_static_optimizer_actuator_count(optimizer), 5);
    double zeros[16] = {0}, angles[16] = {0}, values[16];
    cr_assert_leq(mu_model_hinge_count(model), 16);
    angles[0] = -90.0;
    angles[1] = 90.0;
    mu_static_frame frame = {.net_torques = values};
    const char *f = "mu_static_optimizer_solve";
    REFUSED_STATUS(mu_static_optimizer_solve(NULL, angles, zeros, zeros, &frame), f, "optimizer");
    REFUSED_STATUS(mu_static_optimizer_solve(optimizer, NULL, zeros, zeros, &frame), f, "angles_deg");
    REFUSED_STATUS(mu_static_optimizer_solve(optimizer, angles, NULL, zeros, &frame), f, "rates");
    REFUSED_STATUS(mu_static_optimizer_solve(optimizer, angles, zeros, NULL, &frame), f, "accelerations");
    REFUSED_STATUS(mu_static_optimizer_solve(optimizer, angles, zeros, zeros, NULL), f, "frame");
    FOR_BAD_DOUBLES(bad)
    {
        double broken[16] = {0};
        broken[1] = bad;
        REFUSED_STATUS(mu_static_optimizer_solve(optimizer, broken, zeros, zeros, &frame), f, "angles_deg");
        REFUSED_STATUS(mu_static_optimizer_solve(optimizer, angles, broken, zeros, &frame), f, "rates");
        REFUSED_STATUS(mu_static_optimizer_solve(optimizer, angles, zeros, broken, &frame), f, "accelerations");
    }
    angles[1] = 151.0;
    REFUSED_STATUS(mu_static_optimizer_solve(optimizer, angles, zeros, zeros, &frame), f, "Elbow");
    angles[1] = 90.0;
    /* The optimizer still solves after all that. */
    cr_expect_eq(mu_static_optimizer_solve(optimizer, angles, zeros, zeros, &frame), RB_OK, "%s", rb_last_error());
    cr_expect(frame.solved && isfinite(values[1]));
    mu_static_optimizer_destroy(optimizer);
    mu_model_destroy(model);
    /* No actuators: the arm at level 2. */
    mu_model_options options = mu_default_model_options();
    options.level = 2;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK);
    REFUSED_CREATE(mu_static_optimizer_create(model, &good, &optimizer), optimizer, "mu_static_optimizer_create",
                   "no muscle");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_bone_stress(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    const int bones = desc->bone_count;
    mu_bone_section sections[4];
    rb_vec2 vector;
    double number, scale;
    REFUSED_NAN(mu_model_weight_mass(NULL), "mu_model_weight_mass", "model");
    REFUSED_NAN(mu_model_bone_beam(NULL, 0).length, "mu_model_bone_beam", "model");
    REFUSED_NAN(mu_model_bone_stress(NULL, 0).strain, "mu_model_bone_stress", "model");
    mu_bone_stress stresses[16];
    REFUSED_STATUS(mu_model_bone_stresses(NULL, stresses), "mu_model_bone_stresses", "model");
    REFUSED_STATUS(mu_model_bone_stresses(model, NULL), "mu_model_bone_stresses", "stresses");
    REFUSED_NAN(mu_model_bone_section(NULL, 0, 0.0, false).axial_force, "mu_model_bone_section", "model");
    REFUSED_NAN(mu_model_bone_section(model, 1, NAN, false).axial_force, "mu_model_bone_section", "s");
    REFUSED_STATUS(mu_model_bone_sections(NULL, 0, 4, sections), "mu_model_bone_sections", "model");
    REFUSED_STATUS(mu_model_bone_sections(model, 1, 4, NULL), "mu_model_bone_sections", "sections");
    REFUSED_STATUS(mu_model_bone_sections(model, 1, 0, sections), "mu_model_bone_sections", "count");
    REFUSED_STATUS(mu_model_bone_balance(NULL, 0, &vector, &number, &scale), "mu_model_bone_balance", "model");
    REFUSED_STATUS(mu_model_bone_balance(model, 1, NULL, &number, &scale), "mu_model_bone_balance", "force");
    REFUSED_STATUS(mu_model_bone_balance(model, 1, &vector, NULL, &scale), "mu_model_bone_balance", "moment");
    REFUSED_STATUS(mu_model_bone_balance(model, 1, &vector, &number, NULL), "mu_model_bone_balance", "load_scale");
    REFUSED_STATUS(mu_model_bone_acceleration(NULL, 0, &vector, &number), "mu_model_bone_acceleration", "model");
    REFUSED_STATUS(mu_model_bone_acceleration(model, 1, NULL, &number), "mu_model_bone_acceleration", "acceleration");
    REFUSED_STATUS(mu_model_bone_acceleration(model, 1, &vector, NULL), "mu_model_bone_acceleration", "alpha");
    const int bad_bones[] = {-1, bones, INT_MAX};
    for (size_t k = 0; k < sizeof bad_bones / sizeof bad_bones[0]; ++k) {
        const int b = bad_bones[k];
        REFUSED_NAN(mu_model_bone_beam(model, b).length, "mu_model_bone_beam", "bone");
        REFUSED_NAN(mu_model_bone_stress(model, b).strain, "mu_model_bone_stress", "bone");
        REFUSED_NAN(mu_model_bone_section(model, b, 0.0, false).axial_force, "mu_model_bone_section", "bone");
        REFUSED_STATUS(mu_model_bone_sections(model, b, 4, sections), "mu_model_bone_sections", "bone");
        REFUSED_STATUS(mu_model_bone_balance(model, b, &vector, &number, &scale), "mu_model_bone_balance", "bone");
        REFUSED_STATUS(mu_model_bone_acceleration(model, b, &vector, &number), "mu_model_bone_acceleration", "bone");
    }
    /* The model still answers after all that. */
    cr_expect_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    cr_expect(isfinite(mu_model_bone_beam(model, 0).length), "%s", rb_last_error());
    cr_assert_leq(bones, 16);
    cr_expect_eq(mu_model_bone_stresses(model, stresses), RB_OK, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_model_muscles(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    const char *muscle = desc->muscles[0].name;
    double bad;
    REFUSED_STATUS(mu_model_set_activation(NULL, muscle, 0.5), "mu_model_set_activation", "model");
    REFUSED_STATUS(mu_model_set_activation(model, NULL, 0.5), "mu_model_set_activation", "name");
    REFUSED_STATUS(mu_model_set_activation(model, "nobody", 0.5), "mu_model_set_activation", "nobody");
    REFUSED_STATUS(mu_model_set_tension(NULL, muscle, 10.0), "mu_model_set_tension", "model");
    REFUSED_STATUS(mu_model_set_tension(model, NULL, 10.0), "mu_model_set_tension", "name");
    REFUSED_STATUS(mu_model_set_tension(model, "nobody", 10.0), "mu_model_set_tension", "nobody");
    REFUSED_NAN(mu_model_group_activation(NULL, muscle), "mu_model_group_activation", "model");
    REFUSED_NAN(mu_model_group_activation(model, NULL), "mu_model_group_activation", "name");
    REFUSED_NAN(mu_model_group_activation(model, "nobody"), "mu_model_group_activation", "nobody");
    FOR_BAD_DOUBLES(bad)
    {
        REFUSED_STATUS(mu_model_set_activation(model, muscle, bad), "mu_model_set_activation", "activation");
        REFUSED_STATUS(mu_model_set_tension(model, muscle, bad), "mu_model_set_tension", "newtons");
        REFUSED_STATUS(mu_model_set_activation_at(model, 0, bad), "mu_model_set_activation_at", "activation");
        REFUSED_STATUS(mu_model_set_tension_at(model, 0, bad), "mu_model_set_tension_at", "newtons");
    }
    REFUSED_STATUS(mu_model_set_activation_at(NULL, 0, 0.5), "mu_model_set_activation_at", "model");
    REFUSED_STATUS(mu_model_set_tension_at(NULL, 0, 10.0), "mu_model_set_tension_at", "model");
    REFUSED_VALUE(mu_model_muscle_count(NULL), 0, "mu_model_muscle_count", "model");
    REFUSED_VALUE(mu_model_muscle_name(NULL, 0), NULL, "mu_model_muscle_name", "model");
    REFUSED_NAN(mu_model_muscle_readout(NULL, 0).total_force, "mu_model_muscle_readout", "model");
    REFUSED_VALUE(mu_model_built_muscle(NULL, 0), NULL, "mu_model_built_muscle", "model");
    int index;
    FOR_BAD_INDICES(index, mu_model_muscle_count(model))
    {
        REFUSED_STATUS(mu_model_set_activation_at(model, index, 0.5), "mu_model_set_activation_at", "index");
        REFUSED_STATUS(mu_model_set_tension_at(model, index, 10.0), "mu_model_set_tension_at", "index");
        REFUSED_VALUE(mu_model_muscle_name(model, index), NULL, "mu_model_muscle_name", "index");
        REFUSED_NAN(mu_model_muscle_readout(model, index).active_force, "mu_model_muscle_readout", "index");
        REFUSED_VALUE(mu_model_built_muscle(model, index), NULL, "mu_model_built_muscle", "index");
    }
    cr_expect_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_model_parts(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    REFUSED_VALUE(mu_model_hinge_count(NULL), 0, "mu_model_hinge_count", "model");
    REFUSED_VALUE(mu_model_hinge_name(NULL, 0), NULL, "mu_model_hinge_name", "model");
    REFUSED_NAN(mu_model_hinge_angle(NULL, 0), "mu_model_hinge_angle", "model");
    REFUSED_VALUE(mu_model_part_count(NULL), 0, "mu_model_part_count", "model");
    REFUSED_VALUE(mu_model_part_name(NULL, 0), NULL, "mu_model_part_name", "model");
    REFUSED_NAN(mu_model_part_centre(NULL, 0).x, "mu_model_part_centre", "model");
    REFUSED_NAN(mu_model_part_angle(NULL, 0), "mu_model_part_angle", "model");
    int index;
    FOR_BAD_INDICES(index, mu_model_hinge_count(model))
    {
        REFUSED_VALUE(mu_model_hinge_name(model, index), NULL, "mu_model_hinge_name", "index");
        REFUSED_NAN(mu_model_hinge_angle(model, index), "mu_model_hinge_angle", "index");
    }
    FOR_BAD_INDICES(index, mu_model_part_count(model))
    {
        REFUSED_VALUE(mu_model_part_name(model, index), NULL, "mu_model_part_name", "index");
        REFUSED_NAN(mu_model_part_centre(model, index).y, "mu_model_part_centre", "index");
        REFUSED_NAN(mu_model_part_angle(model, index), "mu_model_part_angle", "index");
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_model_torque_muscles(void)
{
    mu_model_desc *desc = load("worm");
    mu_model *model = build(desc);
    cr_assert_gt(mu_model_torque_muscle_count(model), 0);
    const char *name = mu_model_torque_muscle_name(model, 0);
    const int neurons = mu_motor_pool_neuron_count(mu_model_motor_pool(model, 0));
    REFUSED_VALUE(mu_model_torque_muscle_count(NULL), 0, "mu_model_torque_muscle_count", "model");
    REFUSED_VALUE(mu_model_torque_muscle_name(NULL, 0), NULL, "mu_model_torque_muscle_name", "model");
    REFUSED_STATUS(mu_model_recruit(NULL, name, 1), "mu_model_recruit", "model");
    REFUSED_STATUS(mu_model_recruit(model, NULL, 1), "mu_model_recruit", "name");
    REFUSED_STATUS(mu_model_recruit(model, "nobody", 1), "mu_model_recruit", "nobody");
    REFUSED_STATUS(mu_model_recruit_at(NULL, 0, 1), "mu_model_recruit_at", "model");
    REFUSED_VALUE(mu_model_motor_pool(NULL, 0), NULL, "mu_model_motor_pool", "model");
    REFUSED_VALUE(mu_model_torque_actuator(NULL, 0), NULL, "mu_model_torque_actuator", "model");
    int index;
    FOR_BAD_INDICES(index, mu_model_torque_muscle_count(model))
    {
        REFUSED_VALUE(mu_model_torque_muscle_name(model, index), NULL, "mu_model_torque_muscle_name", "index");
        REFUSED_STATUS(mu_model_recruit_at(model, index, 1), "mu_model_recruit_at", "index");
        REFUSED_VALUE(mu_model_motor_pool(model, index), NULL, "mu_model_motor_pool", "index");
        REFUSED_VALUE(mu_model_torque_actuator(model, index), NULL, "mu_model_torque_actuator", "index");
    }
    /* Neurons out of the pool are refused, not clamped, and recruit nothing. */
    FOR_BAD_INDICES(index, neurons + 1)
    {
        REFUSED_STATUS(mu_model_recruit(model, name, index), "mu_model_recruit", "neurons");
        REFUSED_STATUS(mu_model_recruit_at(model, 0, index), "mu_model_recruit_at", "neurons");
        cr_expect_eq(mu_motor_pool_recruited(mu_model_motor_pool(model, 0)), desc->torque_muscles[0].recruited);
    }
    cr_expect_eq(mu_model_recruit(model, name, neurons), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_model_desc(void)
{
    mu_model_desc *desc;
    REFUSED_CREATE(mu_model_desc_load(NULL, &desc), desc, "mu_model_desc_load", "path");
    REFUSED_STATUS(mu_model_desc_load(SINEW_SOURCE_DIR "/models/arm.json", NULL), "mu_model_desc_load", "out");
    REFUSED_CREATE(mu_model_desc_load_builtin(NULL, &desc), desc, "mu_model_desc_load_builtin", "name");
    REFUSED_STATUS(mu_model_desc_load_builtin("arm", NULL), "mu_model_desc_load_builtin", "out");
    int index;
    FOR_BAD_INDICES(index, mu_builtin_model_count())
    {
        REFUSED_VALUE(mu_builtin_model_name(index), NULL, "mu_builtin_model_name", "index");
    }
    mu_model_desc_destroy(NULL);
    desc = load("arm");
    mu_model_ref ref;
    REFUSED_VALUE(mu_model_desc_find(NULL, "Biceps Long", &ref), false, "mu_model_desc_find", "desc");
    REFUSED_VALUE(mu_model_desc_find(desc, NULL, &ref), false, "mu_model_desc_find", "name");
    REFUSED_VALUE(mu_model_desc_find(desc, desc->bones[0].name, NULL), false, "mu_model_desc_find", "out");
    REFUSED_VALUE(mu_model_desc_find_variant(NULL, "Default"), -1, "mu_model_desc_find_variant", "desc");
    REFUSED_VALUE(mu_model_desc_find_variant(desc, NULL), -1, "mu_model_desc_find_variant", "name");
    REFUSED_VALUE(mu_model_desc_name_of(NULL, (mu_model_ref){MU_MODEL_BONE, 0}), NULL, "mu_model_desc_name_of", "desc");
    REFUSED_VALUE(mu_model_desc_name_of(desc, (mu_model_ref){(mu_model_kind)99, 0}), NULL, "mu_model_desc_name_of",
                  "kind");
    FOR_BAD_INDICES(index, desc->bone_count)
    {
        REFUSED_VALUE(mu_model_desc_name_of(desc, (mu_model_ref){MU_MODEL_BONE, index}), NULL, "mu_model_desc_name_of",
                      "index");
    }
    FOR_BAD_INDICES(index, desc->muscle_count)
    {
        REFUSED_VALUE(mu_model_desc_name_of(desc, (mu_model_ref){MU_MODEL_MUSCLE, index}), NULL,
                      "mu_model_desc_name_of", "index");
    }
    REFUSED_VALUE(mu_model_desc_name_of(desc, (mu_model_ref){MU_MODEL_WEIGHT, 1}), NULL, "mu_model_desc_name_of",
                  "index");
    REFUSED_VALUE(mu_model_variant_has_muscle(NULL, 0), false, "mu_model_variant_has_muscle", "variant");
    REFUSED_VALUE(mu_model_variant_has_bone(NULL, 0), false, "mu_model_variant_has_bone", "variant");
    mu_model_desc_destroy(desc);
}

static void storm_motor_pool_create(void)
{
    mu_motor_pool *pool;
    const double strengths[3] = {1.0, 2.0, 3.0};
    REFUSED_CREATE(mu_motor_pool_create(NULL, 3, &pool), pool, "mu_motor_pool_create", "strengths");
    REFUSED_STATUS(mu_motor_pool_create(strengths, 3, NULL), "mu_motor_pool_create", "out");
    int count;
    FOR_BAD_INDICES(count, MU_MAX_MOTOR_NEURONS + 1)
    {
        REFUSED_CREATE(mu_motor_pool_create(strengths, count, &pool), pool, "mu_motor_pool_create", "count");
        REFUSED_CREATE(mu_motor_pool_create_exponential(count, 1.0, 2.0, &pool), pool,
                       "mu_motor_pool_create_exponential", "count");
    }
    REFUSED_CREATE(mu_motor_pool_create(strengths, 0, &pool), pool, "mu_motor_pool_create", "count");
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        const double with_bad[3] = {1.0, bad, 3.0};
        REFUSED_CREATE(mu_motor_pool_create(with_bad, 3, &pool), pool, "mu_motor_pool_create", "strength");
        REFUSED_CREATE(mu_motor_pool_create_exponential(3, bad, 2.0, &pool), pool, "mu_motor_pool_create_exponential",
                       "weakest");
        REFUSED_CREATE(mu_motor_pool_create_exponential(3, 1.0, bad, &pool), pool, "mu_motor_pool_create_exponential",
                       "strongest");
    }
    REFUSED_STATUS(mu_motor_pool_create_exponential(3, 1.0, 2.0, NULL), "mu_motor_pool_create_exponential", "out");
    REFUSED_CREATE(mu_motor_pool_load_png(NULL, &pool), pool, "mu_motor_pool_load_png", "path");
    REFUSED_STATUS(mu_motor_pool_load_png(missing_file, NULL), "mu_motor_pool_load_png", "out");
    REFUSED_CREATE(mu_motor_pool_load_csv(NULL, &pool), pool, "mu_motor_pool_load_csv", "path");
    REFUSED_STATUS(mu_motor_pool_load_csv(missing_file, NULL), "mu_motor_pool_load_csv", "out");
    mu_motor_pool_destroy(NULL);
}

static void storm_motor_pool_use(void)
{
    mu_motor_pool *pool = NULL;
    cr_assert_eq(mu_motor_pool_create_exponential(10, 1.0, 10.0, &pool), RB_OK);
    muscle_rig rig = make_rig();
    mu_torque_actuator_def def = mu_default_torque_actuator_def();
    def.body = rig.box;
    def.peak_torque = 1.0;
    mu_torque_actuator *actuator = NULL;
    cr_assert_eq(mu_torque_actuator_create(rig.world, &def, &actuator), RB_OK, "%s", rb_last_error());
    REFUSED_VALUE(mu_motor_pool_neuron_count(NULL), 0, "mu_motor_pool_neuron_count", "pool");
    REFUSED_NAN(mu_motor_pool_strength(NULL, 0), "mu_motor_pool_strength", "pool");
    REFUSED_NAN(mu_motor_pool_total_strength(NULL), "mu_motor_pool_total_strength", "pool");
    REFUSED_STATUS(mu_motor_pool_recruit(NULL, 1), "mu_motor_pool_recruit", "pool");
    REFUSED_STATUS(mu_motor_pool_recruit_more(NULL, 1), "mu_motor_pool_recruit_more", "pool");
    REFUSED_VALUE(mu_motor_pool_recruited(NULL), -1, "mu_motor_pool_recruited", "pool");
    REFUSED_NAN(mu_motor_pool_exertion(NULL), "mu_motor_pool_exertion", "pool");
    REFUSED_NAN(mu_motor_pool_exertion_at(NULL, 1), "mu_motor_pool_exertion_at", "pool");
    REFUSED_STATUS(mu_motor_pool_drive_muscle(NULL, rig.muscle), "mu_motor_pool_drive_muscle", "pool");
    REFUSED_STATUS(mu_motor_pool_drive_muscle(pool, NULL), "mu_motor_pool_drive_muscle", "muscle");
    REFUSED_STATUS(mu_motor_pool_drive_torque(NULL, actuator), "mu_motor_pool_drive_torque", "pool");
    REFUSED_STATUS(mu_motor_pool_drive_torque(pool, NULL), "mu_motor_pool_drive_torque", "actuator");
    int index;
    FOR_BAD_INDICES(index, 10) { REFUSED_NAN(mu_motor_pool_strength(pool, index), "mu_motor_pool_strength", "index"); }
    FOR_BAD_INDICES(index, 11)
    {
        REFUSED_STATUS(mu_motor_pool_recruit(pool, index), "mu_motor_pool_recruit", "n");
        cr_expect_eq(mu_motor_pool_recruited(pool), 0, "a refused recruitment recruits nothing");
    }
    mu_torque_actuator_destroy(actuator);
    free_rig(&rig);
    mu_motor_pool_destroy(pool);
}

static void storm_muscle_create(void)
{
    muscle_rig rig = make_rig();
    mu_muscle_def good = mu_default_muscle_def();
    good.point_count = 2;
    good.bodies[0] = rig.anchor;
    good.bodies[1] = rig.box;
    good.rest_length = 0.2;
    good.max_force = 100.0;
    good.curves = rig.curves;
    mu_muscle *muscle;
    REFUSED_CREATE(mu_muscle_create(NULL, &good, &muscle), muscle, "mu_muscle_create", "world");
    REFUSED_CREATE(mu_muscle_create(rig.world, NULL, &muscle), muscle, "mu_muscle_create", "def");
    REFUSED_STATUS(mu_muscle_create(rig.world, &good, NULL), "mu_muscle_create", "out");
    int count;
    FOR_BAD_INDICES(count, RB_MAX_CABLE_POINTS + 1)
    {
        mu_muscle_def def = good;
        def.point_count = count;
        REFUSED_CREATE(mu_muscle_create(rig.world, &def, &muscle), muscle, "mu_muscle_create", "point_count");
    }
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        mu_muscle_def def = good;
        def.rest_length = bad;
        REFUSED_CREATE(mu_muscle_create(rig.world, &def, &muscle), muscle, "mu_muscle_create", "rest_length");
        def = good;
        def.max_force = bad;
        REFUSED_CREATE(mu_muscle_create(rig.world, &def, &muscle), muscle, "mu_muscle_create", "max_force");
        def = good;
        def.local_points[1] = rb_v2(bad, 0.0);
        REFUSED_CREATE(mu_muscle_create(rig.world, &def, &muscle), muscle, "mu_muscle_create", "local_points");
        def = good;
        def.tension_gain = bad;
        REFUSED_CREATE(mu_muscle_create(rig.world, &def, &muscle), muscle, "mu_muscle_create", "tension_gain");
    }
    mu_muscle_destroy(NULL, rig.world);
    free_rig(&rig);
}

static void storm_muscle_use(void)
{
    muscle_rig rig = make_rig();
    const double h = 1.0 / 600.0;
    REFUSED_STATUS(mu_muscle_set_activation(NULL, 0.5), "mu_muscle_set_activation", "muscle");
    REFUSED_STATUS(mu_muscle_set_target_tension(NULL, 10.0), "mu_muscle_set_target_tension", "muscle");
    REFUSED_STATUS(mu_muscle_solve_equilibrium(NULL, rig.world), "mu_muscle_solve_equilibrium", "muscle");
    REFUSED_STATUS(mu_muscle_solve_equilibrium(rig.muscle, NULL), "mu_muscle_solve_equilibrium", "world");
    REFUSED_NAN(mu_muscle_max_force(NULL), "mu_muscle_max_force", "muscle");
    REFUSED_NAN(mu_muscle_tendon_length(NULL), "mu_muscle_tendon_length", "muscle");
    clear_error();
    cr_expect(rb_cable_id_is_null(mu_muscle_cable(NULL)));
    expect_refused("mu_muscle_cable", "muscle", __LINE__);
    REFUSED_STATUS(mu_muscle_prepare(NULL, rig.world, h), "mu_muscle_prepare", "muscle");
    REFUSED_STATUS(mu_muscle_prepare(rig.muscle, NULL, h), "mu_muscle_prepare", "world");
    REFUSED_STATUS(mu_muscle_measure(NULL, rig.world), "mu_muscle_measure", "muscle");
    REFUSED_STATUS(mu_muscle_measure(rig.muscle, NULL), "mu_muscle_measure", "world");
    REFUSED_STATUS(mu_muscle_advance(NULL, rig.world, h), "mu_muscle_advance", "muscle");
    REFUSED_STATUS(mu_muscle_advance(rig.muscle, NULL, h), "mu_muscle_advance", "world");
    REFUSED_NAN(mu_muscle_read(NULL).total_force, "mu_muscle_read", "muscle");
    REFUSED_NAN(mu_muscle_path_speed(NULL), "mu_muscle_path_speed", "muscle");
    REFUSED_NAN(mu_muscle_tension(NULL), "mu_muscle_tension", "muscle");
    double active = 0.0, passive = 0.0;
    REFUSED_STATUS(mu_muscle_isometric_forces(NULL, rig.world, 1.0, &active, &passive), "mu_muscle_isometric_forces",
                   "muscle");
    REFUSED_STATUS(mu_muscle_isometric_forces(rig.muscle, NULL, 1.0, &active, &passive), "mu_muscle_isometric_forces",
                   "world");
    REFUSED_STATUS(mu_muscle_isometric_forces(rig.muscle, rig.world, 1.0, NULL, &passive), "mu_muscle_isometric_forces",
                   "active");
    REFUSED_STATUS(mu_muscle_isometric_forces(rig.muscle, rig.world, 1.0, &active, NULL), "mu_muscle_isometric_forces",
                   "passive");
    REFUSED_STATUS(mu_muscle_isometric_forces(rig.muscle, rig.world, 1.5, &active, &passive),
                   "mu_muscle_isometric_forces", "activation");
    REFUSED_STATUS(mu_muscle_forces_at_speed(NULL, rig.world, 0.0, &active, &passive), "mu_muscle_forces_at_speed",
                   "muscle");
    REFUSED_STATUS(mu_muscle_forces_at_speed(rig.muscle, NULL, 0.0, &active, &passive), "mu_muscle_forces_at_speed",
                   "world");
    REFUSED_STATUS(mu_muscle_forces_at_speed(rig.muscle, rig.world, 0.0, NULL, &passive), "mu_muscle_forces_at_speed",
                   "active_per_activation");
    REFUSED_STATUS(mu_muscle_forces_at_speed(rig.muscle, rig.world, 0.0, &active, NULL), "mu_muscle_forces_at_speed",
                   "passive");
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        REFUSED_STATUS(mu_muscle_set_activation(rig.muscle, bad), "mu_muscle_set_activation", "activation");
        REFUSED_STATUS(mu_muscle_set_target_tension(rig.muscle, bad), "mu_muscle_set_target_tension", "target");
        REFUSED_STATUS(mu_muscle_prepare(rig.muscle, rig.world, bad), "mu_muscle_prepare", "h");
        REFUSED_STATUS(mu_muscle_advance(rig.muscle, rig.world, bad), "mu_muscle_advance", "h");
        REFUSED_STATUS(mu_muscle_isometric_forces(rig.muscle, rig.world, bad, &active, &passive),
                       "mu_muscle_isometric_forces", "activation");
        REFUSED_STATUS(mu_muscle_forces_at_speed(rig.muscle, rig.world, bad, &active, &passive),
                       "mu_muscle_forces_at_speed", "path_speed");
    }
    REFUSED_STATUS(mu_muscle_prepare(rig.muscle, rig.world, 0.0), "mu_muscle_prepare", "h");
    /* The muscle still works. */
    cr_expect_eq(mu_muscle_set_activation(rig.muscle, 0.5), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_muscle_prepare(rig.muscle, rig.world, h), RB_OK, "%s", rb_last_error());
    cr_expect_eq(mu_muscle_measure(rig.muscle, rig.world), RB_OK, "%s", rb_last_error());
    cr_expect(isfinite(mu_muscle_read(rig.muscle).total_force));
    free_rig(&rig);
}

static void storm_model_objects(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    REFUSED_VALUE(mu_model_world_to_read(NULL), NULL, "mu_model_world_to_read", "model");
    clear_error();
    cr_expect(rb_joint_id_is_null(mu_model_hinge_joint(NULL, 0)));
    expect_refused("mu_model_hinge_joint", "model", __LINE__);
    REFUSED_VALUE(mu_model_glue_count(NULL), 0, "mu_model_glue_count", "model");
    REFUSED_VALUE(mu_model_glue_name(NULL, 0), NULL, "mu_model_glue_name", "model");
    clear_error();
    cr_expect(rb_joint_id_is_null(mu_model_glue_joint(NULL, 0)));
    expect_refused("mu_model_glue_joint", "model", __LINE__);
    clear_error();
    cr_expect(rb_joint_id_is_null(mu_model_weight_joint(NULL)));
    expect_refused("mu_model_weight_joint", "model", __LINE__);
    clear_error();
    cr_expect(rb_body_id_is_null(mu_model_body(NULL, 0)));
    expect_refused("mu_model_body", "model", __LINE__);
    REFUSED_VALUE(mu_model_part_body(NULL, 0), -1, "mu_model_part_body", "model");
    REFUSED_VALUE(mu_model_muscle_description_index(NULL, 0), -1, "mu_model_muscle_description_index", "model");
    REFUSED_VALUE(mu_model_muscle_at(NULL, 0), NULL, "mu_model_muscle_at", "model");
    int index;
    FOR_BAD_INDICES(index, mu_model_hinge_count(model))
    {
        clear_error();
        cr_expect(rb_joint_id_is_null(mu_model_hinge_joint(model, index)));
        expect_refused("mu_model_hinge_joint", "index", __LINE__);
    }
    FOR_BAD_INDICES(index, mu_model_glue_count(model))
    {
        REFUSED_VALUE(mu_model_glue_name(model, index), NULL, "mu_model_glue_name", "index");
        clear_error();
        cr_expect(rb_joint_id_is_null(mu_model_glue_joint(model, index)));
        expect_refused("mu_model_glue_joint", "index", __LINE__);
    }
    FOR_BAD_INDICES(index, mu_model_body_count(model))
    {
        clear_error();
        cr_expect(rb_body_id_is_null(mu_model_body(model, index)));
        expect_refused("mu_model_body", "index", __LINE__);
    }
    FOR_BAD_INDICES(index, mu_model_part_count(model))
    {
        REFUSED_VALUE(mu_model_part_body(model, index), -1, "mu_model_part_body", "index");
    }
    FOR_BAD_INDICES(index, mu_model_muscle_count(model))
    {
        REFUSED_VALUE(mu_model_muscle_description_index(model, index), -1, "mu_model_muscle_description_index",
                      "index");
        REFUSED_VALUE(mu_model_muscle_at(model, index), NULL, "mu_model_muscle_at", "index");
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_loads_and_moment_arms(void)
{
    mu_model_desc *desc = load("arm");
    mu_model *model = build(desc);
    double arms[8];
    REFUSED_VALUE(mu_model_muscle_crosses(NULL, 0, 0), false, "mu_model_muscle_crosses", "model");
    REFUSED_NAN(mu_model_moment_arm(NULL, 0, 0), "mu_model_moment_arm", "model");
    REFUSED_STATUS(mu_model_moment_arms(NULL, 0, arms), "mu_model_moment_arms", "model");
    REFUSED_STATUS(mu_model_moment_arms(model, 0, NULL), "mu_model_moment_arms", "arms");
    REFUSED_NAN(mu_model_muscle_torque(NULL, 0, 0), "mu_model_muscle_torque", "model");
    REFUSED_NAN(mu_model_hinge_muscle_torque(NULL, 0), "mu_model_hinge_muscle_torque", "model");
    REFUSED_STATUS(mu_model_pose_hinge(NULL, 0, 0.0), "mu_model_pose_hinge", "model");
    REFUSED_NAN(mu_model_hinge_load(NULL, 0).force.x, "mu_model_hinge_load", "model");
    REFUSED_NAN(mu_model_glue_load(NULL, 0).torque, "mu_model_glue_load", "model");
    REFUSED_NAN(mu_model_hinge_bone_axis(NULL, 0).x, "mu_model_hinge_bone_axis", "model");
    int index;
    FOR_BAD_INDICES(index, mu_model_hinge_count(model))
    {
        REFUSED_VALUE(mu_model_muscle_crosses(model, 0, index), false, "mu_model_muscle_crosses", "hinge");
        REFUSED_NAN(mu_model_moment_arm(model, 0, index), "mu_model_moment_arm", "hinge");
        REFUSED_STATUS(mu_model_moment_arms(model, index, arms), "mu_model_moment_arms", "hinge");
        REFUSED_NAN(mu_model_muscle_torque(model, 0, index), "mu_model_muscle_torque", "hinge");
        REFUSED_NAN(mu_model_hinge_muscle_torque(model, index), "mu_model_hinge_muscle_torque", "hinge");
        REFUSED_STATUS(mu_model_pose_hinge(model, index, 0.0), "mu_model_pose_hinge", "hinge");
        REFUSED_NAN(mu_model_hinge_load(model, index).along, "mu_model_hinge_load", "hinge");
        REFUSED_NAN(mu_model_hinge_bone_axis(model, index).y, "mu_model_hinge_bone_axis", "hinge");
    }
    FOR_BAD_INDICES(index, mu_model_muscle_count(model))
    {
        REFUSED_VALUE(mu_model_muscle_crosses(model, index, 0), false, "mu_model_muscle_crosses", "muscle");
        REFUSED_NAN(mu_model_moment_arm(model, index, 0), "mu_model_moment_arm", "muscle");
        REFUSED_NAN(mu_model_muscle_torque(model, index, 0), "mu_model_muscle_torque", "muscle");
    }
    FOR_BAD_INDICES(index, mu_model_glue_count(model))
    {
        REFUSED_NAN(mu_model_glue_load(model, index).force.y, "mu_model_glue_load", "glue");
    }
    double bad;
    FOR_BAD_DOUBLES(bad) { REFUSED_STATUS(mu_model_pose_hinge(model, 0, bad), "mu_model_pose_hinge", "degrees"); }
    /* Outside the hinge's limits (the elbow's are -10 .. 150). */
    REFUSED_STATUS(mu_model_pose_hinge(model, 1, 151.0), "mu_model_pose_hinge", "limits");
    cr_expect(isfinite(mu_model_moment_arm(model, 0, 1)), "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

static void storm_statics(void)
{
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        REFUSED_NAN(mu_max_force_from_pcsa(bad, 3e5), "mu_max_force_from_pcsa", "pcsa");
        REFUSED_NAN(mu_max_force_from_pcsa(1e-3, bad), "mu_max_force_from_pcsa", "specific_tension");
        REFUSED_NAN(mu_pcsa_from_volume(bad, 0.1), "mu_pcsa_from_volume", "volume");
        REFUSED_NAN(mu_pcsa_from_volume(1e-4, bad), "mu_pcsa_from_volume", "fibre_length");
        REFUSED_NAN(mu_pcsa_from_anatomical(bad, 0.1), "mu_pcsa_from_anatomical", "anatomical_cross_section");
        REFUSED_NAN(mu_pcsa_from_anatomical(1e-3, bad), "mu_pcsa_from_anatomical", "pennation_angle");
        REFUSED_NAN(mu_fibre_length_from_sarcomeres(bad), "mu_fibre_length_from_sarcomeres", "sarcomeres");
        REFUSED_NAN(mu_fibre_length_normalized(bad, 2.5e-6), "mu_fibre_length_normalized", "measured_fibre_length");
        REFUSED_NAN(mu_fibre_length_normalized(0.1, bad), "mu_fibre_length_normalized", "measured_sarcomere_length");
    }
}

static void storm_pennation_and_tendon(void)
{
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        REFUSED_NAN(mu_pennation_width(bad, 0.1), "mu_pennation_width", "optimal_fibre_length");
        REFUSED_NAN(mu_pennation_width(0.1, bad), "mu_pennation_width", "optimal_angle");
        REFUSED_NAN(mu_pennation_min_fibre_length(bad), "mu_pennation_min_fibre_length", "width");
        REFUSED_NAN(mu_pennation_angle(0.1, bad), "mu_pennation_angle", "width");
        REFUSED_NAN(mu_pennation_fibre_length(0.1, bad), "mu_pennation_fibre_length", "width");
        REFUSED_NAN(mu_tendon_force(0.01, bad), "mu_tendon_force", "strain_at_max_force");
        REFUSED_NAN(mu_tendon_stiffness(0.01, bad), "mu_tendon_stiffness", "strain_at_max_force");
    }
    REFUSED_NAN(mu_pennation_angle(NAN, 0.01), "mu_pennation_angle", "fibre_length");
    REFUSED_NAN(mu_pennation_fibre_length(NAN, 0.01), "mu_pennation_fibre_length", "belly_length");
    REFUSED_NAN(mu_tendon_force(NAN, 0.049), "mu_tendon_force", "strain");
    REFUSED_NAN(mu_tendon_stiffness(NAN, 0.049), "mu_tendon_stiffness", "strain");
}

static void storm_torque_actuator(void)
{
    muscle_rig rig = make_rig();
    mu_torque_actuator_def good = mu_default_torque_actuator_def();
    good.body = rig.box;
    good.peak_torque = 2.0;
    mu_torque_actuator *actuator;
    REFUSED_CREATE(mu_torque_actuator_create(NULL, &good, &actuator), actuator, "mu_torque_actuator_create", "world");
    REFUSED_CREATE(mu_torque_actuator_create(rig.world, NULL, &actuator), actuator, "mu_torque_actuator_create", "def");
    REFUSED_STATUS(mu_torque_actuator_create(rig.world, &good, NULL), "mu_torque_actuator_create", "out");
    double bad;
    FOR_BAD_DOUBLES(bad)
    {
        mu_torque_actuator_def def = good;
        def.peak_torque = bad;
        REFUSED_CREATE(mu_torque_actuator_create(rig.world, &def, &actuator), actuator, "mu_torque_actuator_create",
                       "peak_torque");
    }
    cr_assert_eq(mu_torque_actuator_create(rig.world, &good, &actuator), RB_OK, "%s", rb_last_error());
    REFUSED_STATUS(mu_torque_actuator_set_exertion(NULL, 0.5), "mu_torque_actuator_set_exertion", "actuator");
    const double out_of_range[] = {NAN, INFINITY, -INFINITY, -0.1, 1.1};
    for (size_t k = 0; k < sizeof out_of_range / sizeof out_of_range[0]; ++k) {
        REFUSED_STATUS(mu_torque_actuator_set_exertion(actuator, out_of_range[k]), "mu_torque_actuator_set_exertion",
                       "exertion");
    }
    REFUSED_NAN(mu_torque_actuator_exertion(NULL), "mu_torque_actuator_exertion", "actuator");
    REFUSED_NAN(mu_torque_actuator_torque(NULL), "mu_torque_actuator_torque", "actuator");
    REFUSED_NAN(mu_torque_actuator_peak_torque(NULL), "mu_torque_actuator_peak_torque", "actuator");
    REFUSED_NAN(mu_torque_actuator_power(NULL, rig.world), "mu_torque_actuator_power", "actuator");
    REFUSED_NAN(mu_torque_actuator_power(actuator, NULL), "mu_torque_actuator_power", "world");
    REFUSED_STATUS(mu_torque_actuator_apply(NULL, rig.world), "mu_torque_actuator_apply", "actuator");
    REFUSED_STATUS(mu_torque_actuator_apply(actuator, NULL), "mu_torque_actuator_apply", "world");
    cr_expect_eq(mu_torque_actuator_exertion(actuator), 0.0, "refused exertions left it at 0");
    mu_torque_actuator_destroy(actuator);
    mu_torque_actuator_destroy(NULL);
    free_rig(&rig);
}

/* ------------------------------------------------------------ the table */

typedef struct api_storm {
    const char *functions; /* every MU_API function the storm covers, space-separated */
    void (*storm)(void);
} api_storm;

static const api_storm storms[] = {
    {"mu_default_activation_params mu_default_analytic_curves mu_default_model_options mu_default_muscle_def "
     "mu_default_torque_actuator_def mu_builtin_model_count mu_version",
     storm_no_arguments},
    {"mu_activation_time_constant mu_activation_derivative mu_activation_step", storm_activation},
    {"mu_calcium_force_times_of mu_calcium_force_derivative mu_calcium_force_step", storm_calcium_force},
    {"mu_curves_create_tabulated mu_curves_create_seed_tables mu_curves_create_analytic mu_curves_destroy",
     storm_curves_create},
    {"mu_curve_active_length mu_curve_passive_length mu_curve_velocity mu_curve_velocity_slope "
     "mu_curve_active_length_hinted mu_curve_passive_length_hinted mu_curve_velocity_hinted "
     "mu_curve_velocity_slope_hinted mu_curve_velocity_and_slope_hinted",
     storm_curves_evaluate},
    {"mu_lengths_from_geometry", storm_geometry_lengths},
    {"mu_model_create mu_model_destroy", storm_model_create},
    {"mu_model_world mu_model_description mu_model_step mu_model_substep mu_model_time mu_model_frame_duration "
     "mu_model_substep_duration mu_model_set_gravity mu_model_warnings mu_model_failure mu_model_energy_account "
     "mu_model_body_count "
     "mu_model_joint_count",
     storm_model_running},
    {"mu_model_check_tree mu_model_inverse_dynamics", storm_model_inverse},
    {"mu_default_static_optimization_settings mu_static_optimizer_create mu_static_optimizer_destroy "
     "mu_static_optimizer_actuator_count mu_static_optimizer_solve mu_static_optimizer_result_name",
     storm_static_optimization},
    {"mu_model_weight_mass mu_model_bone_beam mu_model_bone_stress mu_model_bone_stresses mu_model_bone_section "
     "mu_model_bone_sections "
     "mu_model_bone_balance mu_model_bone_acceleration",
     storm_bone_stress},
    {"mu_model_set_activation mu_model_set_tension mu_model_set_activation_at mu_model_set_tension_at "
     "mu_model_group_activation mu_model_muscle_count mu_model_muscle_name mu_model_muscle_readout "
     "mu_model_built_muscle",
     storm_model_muscles},
    {"mu_model_world_to_read mu_model_hinge_joint mu_model_glue_count mu_model_glue_name mu_model_glue_joint "
     "mu_model_weight_joint mu_model_body mu_model_part_body mu_model_muscle_description_index mu_model_muscle_at",
     storm_model_objects},
    {"mu_model_muscle_crosses mu_model_moment_arm mu_model_moment_arms mu_model_muscle_torque "
     "mu_model_hinge_muscle_torque mu_model_pose_hinge mu_model_hinge_load mu_model_glue_load "
     "mu_model_hinge_bone_axis",
     storm_loads_and_moment_arms},
    {"mu_model_hinge_count mu_model_hinge_name mu_model_hinge_angle mu_model_part_count mu_model_part_name "
     "mu_model_part_centre mu_model_part_angle",
     storm_model_parts},
    {"mu_model_torque_muscle_count mu_model_torque_muscle_name mu_model_recruit mu_model_recruit_at "
     "mu_model_motor_pool mu_model_torque_actuator",
     storm_model_torque_muscles},
    {"mu_model_desc_load mu_model_desc_load_builtin mu_builtin_model_name mu_model_desc_destroy mu_model_desc_find "
     "mu_model_desc_find_variant mu_model_desc_name_of mu_model_variant_has_muscle mu_model_variant_has_bone",
     storm_model_desc},
    {"mu_motor_pool_create mu_motor_pool_create_exponential mu_motor_pool_load_png mu_motor_pool_load_csv "
     "mu_motor_pool_destroy",
     storm_motor_pool_create},
    {"mu_motor_pool_neuron_count mu_motor_pool_strength mu_motor_pool_total_strength mu_motor_pool_recruit "
     "mu_motor_pool_recruit_more mu_motor_pool_recruited mu_motor_pool_exertion mu_motor_pool_exertion_at "
     "mu_motor_pool_drive_muscle mu_motor_pool_drive_torque",
     storm_motor_pool_use},
    {"mu_muscle_create mu_muscle_destroy", storm_muscle_create},
    {"mu_muscle_set_activation mu_muscle_set_target_tension mu_muscle_solve_equilibrium mu_muscle_max_force "
     "mu_muscle_tendon_length mu_muscle_cable mu_muscle_prepare mu_muscle_measure mu_muscle_advance mu_muscle_read "
     "mu_muscle_path_speed mu_muscle_tension mu_muscle_isometric_forces mu_muscle_forces_at_speed",
     storm_muscle_use},
    {"mu_max_force_from_pcsa mu_pcsa_from_volume mu_pcsa_from_anatomical mu_fibre_length_from_sarcomeres "
     "mu_fibre_length_normalized",
     storm_statics},
    {"mu_pennation_width mu_pennation_min_fibre_length mu_pennation_angle mu_pennation_fibre_length mu_tendon_force "
     "mu_tendon_stiffness",
     storm_pennation_and_tendon},
    {"mu_default_torque_actuator_def mu_torque_actuator_create mu_torque_actuator_destroy "
     "mu_torque_actuator_set_exertion mu_torque_actuator_exertion mu_torque_actuator_torque mu_torque_actuator_power "
     "mu_torque_actuator_peak_torque mu_torque_actuator_apply",
     storm_torque_actuator},
};

#define STORM_COUNT (sizeof storms / sizeof storms[0])

/* Each storm in its own process: a crash fails that storm alone. */
ParameterizedTestParameters(mu_api, storms_every_function)
{
    static size_t indices[STORM_COUNT];
    for (size_t i = 0; i < STORM_COUNT; ++i) {
        indices[i] = i;
    }
    return cr_make_param_array(size_t, indices, STORM_COUNT);
}

ParameterizedTest(size_t *index, mu_api, storms_every_function)
{
    cr_log_info("storm: %s", storms[*index].functions);
    storms[*index].storm();
}

/* Whether `name` is a word of some storm's list. */
static bool stormed(const char *name)
{
    const size_t length = strlen(name);
    for (size_t i = 0; i < STORM_COUNT; ++i) {
        for (const char *at = strstr(storms[i].functions, name); at != NULL; at = strstr(at + 1, name)) {
            const bool starts = at == storms[i].functions || at[-1] == ' ';
            if (starts && (at[length] == ' ' || at[length] == '\0')) {
                return true;
            }
        }
    }
    return false;
}

/* Every function the public headers mark MU_API is in the table. */
Test(mu_api, every_public_function_is_stormed)
{
    const char *folder = SINEW_SOURCE_DIR "/musculo/include/mu";
    DIR *dir = opendir(folder);
    cr_assert_not_null(dir, "cannot list %s", folder);
    int functions = 0;
    for (struct dirent *entry = readdir(dir); entry != NULL; entry = readdir(dir)) {
        const size_t length = strlen(entry->d_name);
        if (length < 3 || strcmp(entry->d_name + length - 2, ".h") != 0) {
            continue;
        }
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", folder, entry->d_name);
        FILE *f = fopen(path, "r");
        cr_assert_not_null(f, "cannot read %s", path);
        /* A declaration may span lines: the name is the identifier before
         * the first '(' after "MU_API ". */
        static char text[1 << 16];
        const size_t n = fread(text, 1, sizeof text - 1, f);
        fclose(f);
        text[n] = '\0';
        for (char *at = strstr(text, "\nMU_API "); at != NULL; at = strstr(at + 1, "\nMU_API ")) {
            char *paren = strchr(at, '(');
            cr_assert_not_null(paren);
            char *end = paren;
            char *start = end;
            while (start > at && (start[-1] == '_' || (start[-1] >= 'a' && start[-1] <= 'z') ||
                                  (start[-1] >= '0' && start[-1] <= '9'))) {
                --start;
            }
            char name[128];
            snprintf(name, sizeof name, "%.*s", (int)(end - start), start);
            ++functions;
            cr_expect(stormed(name), "%s (%s) is not in the table of tests/test_mu_api_errors.c", name, entry->d_name);
        }
    }
    closedir(dir);
    cr_expect_gt(functions, 100, "found only %d MU_API functions: is the header layout still one per line?", functions);
}
