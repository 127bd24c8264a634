/* SPDX-License-Identifier: MIT */
/* Static optimization (mu/static_optimization.h) against the closed-form
 * Lagrange solutions on one hinge with two agonists, on the arm against
 * its own inverse-dynamics torques, and `sinew optimize` against its
 * errors. */
#define _DEFAULT_SOURCE /* mkstemps, mkdtemp */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_support.h"
#include "io/csv_table.h"
#include "model_support.h"
#include "mu/inverse_dynamics.h"
#include "mu/moment_arms.h"
#include "mu/static_optimization.h"

#define G 9.8

static mu_model *build(const mu_model_desc *desc, int weight_index)
{
    mu_model_options options = mu_default_model_options();
    options.weight_index = weight_index;
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    return model;
}

/* ---- one hinge, two agonists ------------------------------------------------------ */

/* A lever along +x on a hinge at the origin, held horizontal against
 * gravity by two muscles from the ground above it: muscle i runs from
 * O_i = (o_x, o_y) to Q_i = (q, 0) on the lever. Turning the lever by dθ
 * moves Q_i by (0, q)·dθ, so dL/dθ = u·(0, q) = −o_y·q/L with
 * L = |Q_i − O_i|, and the moment arm is r_i = o_y·q/L_i. */
static const double origin_x[2] = {0.02, 0.0}, origin_y[2] = {0.05, 0.08}, insertion[2] = {0.10, 0.05};
static const double max_force[2] = {100.0, 300.0};

static mu_model_desc *two_agonists(void)
{
    char text[4096];
    snprintf(text, sizeof text,
             "{\"name\": \"agonists\", \"gravity\": [0, -%g],"
             " \"nails\": [{\"name\": \"Ground\", \"position\": [0, 0]}],"
             " \"bones\": [{\"name\": \"Lever\", \"centre\": [0.15, 0], \"size\": [0.3, 0.03], \"density\": 20000}],"
             " \"hinges\": [{\"name\": \"Pivot\", \"body_a\": \"Ground\", \"anchor_a\": [0, 0], \"body_b\": \"Lever\","
             "              \"anchor_b\": [-0.15, 0], \"radius\": 0.01, \"lower\": -80, \"upper\": 80}],"
             " \"muscles\": ["
             "  {\"name\": \"One\", \"rest_length\": 0.08, \"max_force\": %g,"
             "   \"path\": [{\"body\": \"Ground\", \"point\": [%g, %g]}, {\"body\": \"Lever\", \"point\": [%g, 0]}]},"
             "  {\"name\": \"Two\", \"rest_length\": 0.08, \"max_force\": %g,"
             "   \"path\": [{\"body\": \"Ground\", \"point\": [%g, %g]}, {\"body\": \"Lever\", \"point\": [%g, 0]}]}],"
             " \"groups\": [], \"variants\": [{\"name\": \"both\", \"muscles\": [\"One\", \"Two\"]}]}",
             G, max_force[0], origin_x[0], origin_y[0], insertion[0] - 0.15, max_force[1], origin_x[1], origin_y[1],
             insertion[1] - 0.15);
    return load_model_text(text);
}

/* The problem's data from independent pieces: the moment arms of the
 * geometry above, each muscle's isometric forces at activation 1
 * (Fmax·f_L·f_V(0) and Fmax·f_P), and the lever's weight moment m·g·d. */
typedef struct lever_problem {
    double c[2]; /* r_i·C_i, N·m per unit activation */
    double left; /* τ − Σ r_i·P_i, N·m */
} lever_problem;

static lever_problem lever_data(const mu_model *model)
{
    lever_problem p = {0};
    const rb_world *world = mu_model_world_to_read(model);
    const rb_mass_data mass = rb_body_mass_data(world, mu_model_body(model, mu_model_part_body(model, 1)));
    p.left = mass.mass * G * 0.15;
    for (int i = 0; i < 2; ++i) {
        const double dx = insertion[i] - origin_x[i], length = hypot(dx, origin_y[i]);
        const double arm = origin_y[i] * insertion[i] / length;
        double active, passive;
        cr_assert_eq(mu_muscle_isometric_forces(mu_model_built_muscle(model, i), world, 1.0, &active, &passive), RB_OK);
        p.c[i] = arm * active;
        p.left -= arm * passive;
    }
    return p;
}

static void solve_at_rest(mu_model *model, double exponent, double *activations, double *reserve, mu_joint_load *load)
{
    mu_static_optimization_settings settings = mu_default_static_optimization_settings();
    settings.exponent = exponent;
    mu_static_optimizer *optimizer = NULL;
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_static_optimizer_actuator_count(optimizer), 2);
    const double angle = 0.0, rate = 0.0, acceleration = 0.0;
    double torque, muscle_torque;
    mu_static_frame frame = {.activations = activations,
                             .reserves = reserve,
                             .net_torques = &torque,
                             .actuator_torques = &muscle_torque,
                             .loads = load};
    cr_assert_eq(mu_static_optimizer_solve(optimizer, &angle, &rate, &acceleration, &frame), RB_OK, "%s",
                 rb_last_error());
    cr_assert(frame.solved, "SLSQP: %d", frame.solver_result);
    cr_assert(fabs(muscle_torque + *reserve - torque) <= 1e-9 * fabs(torque));
    mu_static_optimizer_destroy(optimizer);
}

/* p = 2: minimize a_1² + a_2² + (ρ/R)² subject to c_1·a_1 + c_2·a_2 + ρ = T.
 * The Lagrange conditions 2a_i = λc_i, 2ρ/R² = λ give a_i = c_i·T/(Σc² + R²):
 * activations proportional to r_i·Fmax_i·f_L·f_V, and ρ = R²·T/(Σc² + R²). */
Test(static_optimization, two_agonists_share_as_the_lagrange_solution_for_p_2)
{
    mu_model_desc *desc = two_agonists();
    mu_model *model = build(desc, 0);
    const lever_problem p = lever_data(model);
    const double r = MU_STATIC_OPTIMIZATION_DEFAULT_RESERVE_SCALE;
    const double denominator = p.c[0] * p.c[0] + p.c[1] * p.c[1] + r * r;
    double a[2], reserve;
    mu_joint_load load;
    solve_at_rest(model, 2.0, a, &reserve, &load);
    for (int i = 0; i < 2; ++i) {
        const double expected = p.c[i] * p.left / denominator;
        cr_log_info("p = 2: a_%d = %.12g, closed form %.12g", i + 1, a[i], expected);
        cr_assert(expected > 0.01 && expected < 0.99, "the case must keep off the bounds: %g", expected);
        cr_assert(fabs(a[i] - expected) <= 1e-6, "a_%d = %.12g, closed form %.12g", i + 1, a[i], expected);
    }
    cr_assert(fabs(a[0] / a[1] - p.c[0] / p.c[1]) <= 1e-6 * p.c[0] / p.c[1]);
    cr_assert(fabs(reserve - r * r * p.left / denominator) <= 1e-6 * r * r * p.left / denominator + 1e-12);
    /* The lever at rest: the hinge holds what gravity and the two pulls
     * leave, F = m·g·ŷ − Σ T_i·(O_i − Q_i)/|O_i − Q_i|, with the tensions
     * T_i = a_i·Fmax_i·f_L·f_V + Fmax_i·f_P of the activations found. A
     * nail has the world's axes, so along and across are x and y. */
    const rb_world *world = mu_model_world_to_read(model);
    rb_vec2 expected = {0.0, rb_body_mass_data(world, mu_model_body(model, mu_model_part_body(model, 1))).mass * G};
    for (int i = 0; i < 2; ++i) {
        double active, passive;
        cr_assert_eq(mu_muscle_isometric_forces(mu_model_built_muscle(model, i), world, a[i], &active, &passive),
                     RB_OK);
        const double dx = origin_x[i] - insertion[i], dy = origin_y[i], length = hypot(dx, dy);
        expected.x -= (active + passive) * dx / length;
        expected.y -= (active + passive) * dy / length;
    }
    cr_log_info("reaction (%.12g, %.12g) N, expected (%.12g, %.12g) N", load.force.x, load.force.y, expected.x,
                expected.y);
    cr_assert(fabs(load.force.x - expected.x) <= 1e-9 * rb_length(expected));
    cr_assert(fabs(load.force.y - expected.y) <= 1e-9 * rb_length(expected));
    cr_assert(fabs(load.along - load.force.x) <= 1e-12 * rb_length(expected) &&
              fabs(load.across - load.force.y) <= 1e-12 * rb_length(expected));
    cr_assert_eq(load.torque, 0.0);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* p = 3: 3a_i² = λc_i and 2ρ/R² = λ, so a_i = √(λc_i/3) (activations
 * proportional to √(r_i·F_i)) and ρ = λR²/2, with λ the root of
 * Σ c_i·√(λc_i/3) + λR²/2 = T, which rises with λ: found by bisection. */
Test(static_optimization, two_agonists_share_as_the_lagrange_solution_for_p_3)
{
    mu_model_desc *desc = two_agonists();
    mu_model *model = build(desc, 0);
    const lever_problem p = lever_data(model);
    const double r = MU_STATIC_OPTIMIZATION_DEFAULT_RESERVE_SCALE;
    double low = 0.0, high = 1.0;
    while (p.c[0] * sqrt(high * p.c[0] / 3) + p.c[1] * sqrt(high * p.c[1] / 3) + high * r * r / 2 < p.left) {
        high *= 2.0;
    }
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (low + high);
        const double torque = p.c[0] * sqrt(mid * p.c[0] / 3) + p.c[1] * sqrt(mid * p.c[1] / 3) + mid * r * r / 2;
        *(torque < p.left ? &low : &high) = mid;
    }
    const double lambda = 0.5 * (low + high);
    double a[2], reserve;
    mu_joint_load load;
    solve_at_rest(model, 3.0, a, &reserve, &load);
    for (int i = 0; i < 2; ++i) {
        const double expected = sqrt(lambda * p.c[i] / 3.0);
        cr_log_info("p = 3: a_%d = %.12g, closed form %.12g", i + 1, a[i], expected);
        cr_assert(fabs(a[i] - expected) <= 1e-6, "a_%d = %.12g, closed form %.12g", i + 1, a[i], expected);
    }
    cr_assert(fabs(a[0] / a[1] - sqrt(p.c[0] / p.c[1])) <= 1e-5);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* ---- the arm ------------------------------------------------------------------------ */

/* The arm at several poses and rates, with the weight of `weight_index`:
 * the worst |τ − actuators' torque| and the largest |reserve|. */
static void arm_frames(int weight_index, double *worst_mismatch, double *worst_reserve, bool *all_solved)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK, "%s", rb_last_error());
    mu_model *model = build(desc, weight_index);
    mu_static_optimizer *optimizer = NULL;
    const mu_static_optimization_settings settings = mu_default_static_optimization_settings();
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_OK, "%s", rb_last_error());
    *worst_mismatch = 0.0;
    *worst_reserve = 0.0;
    *all_solved = true;
    for (int k = 0; k < 12; ++k) {
        const double angles[2] = {-80.0 + 4.0 * k, 20.0 + 8.0 * k};
        const double rates[2] = {0.5 * sin(k), -1.0 * cos(k)}, accelerations[2] = {2.0 * cos(k), 3.0 * sin(k)};
        double torques[2], muscle_torques[2], reserves[2], activations[5], check[2];
        mu_static_frame frame = {.activations = activations,
                                 .net_torques = torques,
                                 .actuator_torques = muscle_torques,
                                 .reserves = reserves};
        cr_assert_eq(mu_static_optimizer_solve(optimizer, angles, rates, accelerations, &frame), RB_OK, "%s",
                     rb_last_error());
        /* τ as inverse dynamics gives it, independently. */
        cr_assert_eq(mu_model_inverse_dynamics(model, angles, rates, accelerations, check), RB_OK);
        *all_solved = *all_solved && frame.solved;
        for (int h = 0; h < 2; ++h) {
            cr_assert(fabs(check[h] - torques[h]) <= 1e-12 * (1.0 + fabs(check[h])));
            *worst_mismatch = fmax(*worst_mismatch, fabs(muscle_torques[h] - torques[h]));
            *worst_reserve = fmax(*worst_reserve, fabs(reserves[h]));
        }
        for (int i = 0; i < 5; ++i) {
            cr_assert(activations[i] >= 0.0 && activations[i] <= 1.0);
        }
    }
    mu_static_optimizer_destroy(optimizer);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(static_optimization, the_arms_muscles_reproduce_its_torques_where_they_can)
{
    double mismatch, reserve;
    bool solved;
    arm_frames(0, &mismatch, &reserve, &solved);
    cr_log_info("arm, no weight: worst mismatch %.3g N·m, largest reserve %.3g N·m", mismatch, reserve);
    cr_assert(solved);
    cr_assert(mismatch <= 1e-3, "worst |τ − muscles' torque| %g N·m", mismatch);
}

/* 100 kg in the hand: the elbow needs about 100·9.8·0.3 ≈ 300 N·m, more
 * than the flexors give, and the reserve carries the rest, reported. */
Test(static_optimization, a_weight_too_heavy_leaves_a_reported_reserve)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    const int heaviest = desc->weight.mass_count - 1;
    cr_assert(desc->weight.masses[heaviest] >= 100.0);
    mu_model_desc_destroy(desc);
    double mismatch, reserve;
    bool solved;
    arm_frames(heaviest, &mismatch, &reserve, &solved);
    cr_log_info("arm, 100 kg: worst mismatch %.3g N·m, largest reserve %.3g N·m", mismatch, reserve);
    cr_assert(solved);
    cr_assert(reserve > 10.0, "largest reserve %g N·m", reserve);
    cr_assert(fabs(mismatch - reserve) <= 1e-6 * reserve, "the mismatch is the reserve");
}

Test(static_optimization, refuses_bad_settings_and_models_without_actuators)
{
    mu_model_desc *desc = two_agonists();
    mu_model *model = build(desc, 0);
    mu_static_optimizer *optimizer = NULL;
    mu_static_optimization_settings settings = mu_default_static_optimization_settings();
    settings.exponent = 0.5;
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_ERR_INVALID_ARGUMENT);
    cr_assert(strstr(rb_last_error(), "exponent is 0.5, expected a finite number >= 1") != NULL, "%s", rb_last_error());
    settings.exponent = NAN;
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_ERR_INVALID_ARGUMENT);
    settings = mu_default_static_optimization_settings();
    settings.reserve_scale = 0.0;
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_ERR_INVALID_ARGUMENT);
    cr_assert_null(optimizer);
    mu_model_destroy(model);
    mu_model_options options = mu_default_model_options();
    options.level = 2; /* joints only */
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK);
    settings = mu_default_static_optimization_settings();
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_ERR_INVALID_ARGUMENT);
    cr_assert(strstr(rb_last_error(), "no muscle or torque muscle") != NULL, "%s", rb_last_error());
    mu_model_destroy(model);
    /* An angle outside the hinge's limits. */
    model = build(desc, 0);
    cr_assert_eq(mu_static_optimizer_create(model, &settings, &optimizer), RB_OK);
    const double angle = 85.0, zero = 0.0;
    mu_static_frame frame = {0};
    cr_assert_eq(mu_static_optimizer_solve(optimizer, &angle, &zero, &zero, &frame), RB_ERR_INVALID_ARGUMENT);
    cr_assert(strstr(rb_last_error(), "hinge \"Pivot\" at 85 degrees is outside its limits -80 .. 80") != NULL, "%s",
              rb_last_error());
    mu_static_optimizer_destroy(optimizer);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* ---- the command ------------------------------------------------------------------ */

static char dir[] = "/tmp/sinew-optimize-XXXXXX";

/* The last run's messages (its stderr). */
static char errors[8192];

static int run_sinew(const char *args)
{
    return run_sinew_capture(dir, args, SINEW_STDERR_ONLY, errors, sizeof errors);
}

static bool exists(const char *name) { return file_exists_in(dir, name); }

static void write_file(const char *name, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fputs(text, f);
    fclose(f);
}

static void remove_dir(void)
{
    char command[600];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}

/* A forward run of the arm holding 1 kg, inverted and optimized: every
 * frame solved, and after the first half second (the arm falling from
 * horizontal, its muscles shortening near their top speed, where f_V
 * leaves them almost no force) the reserves stay below 1e-3 N·m and the
 * muscles' torques match the inverse-dynamics torques within 1e-3 N·m. */
Test(optimize_command, shares_a_forward_runs_torques_among_the_arms_muscles)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("sine.ctl", "0 activation sine \"Biceps Long\" 0.3 0.15 1 3\n0 activation \"Triceps Lateral\" 0.1\n");
    cr_assert_eq(run_sinew("run arm --weight 1 --duration 3 --control sine.ctl"), 0, "%s", errors);
    cr_assert_eq(run_sinew("optimize arm --weight 1 --motion arm.csv --exponent 3"), 0, "%s", errors);
    cr_assert(exists("arm-optimize.csv") && exists("arm-optimize.csv-metadata.json") && exists("arm-optimize.png"));
    csv_table table;
    char path[512], error[1024];
    snprintf(path, sizeof path, "%s/arm-optimize.csv", dir);
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    const int time = csv_table_find(&table, "time_s"), solved = csv_table_find(&table, "solved");
    cr_assert(time >= 0 && solved >= 0);
    double worst = 0.0;
    for (int h = 0; h < 2; ++h) {
        const char *hinge = h == 0 ? "Shoulder" : "Elbow";
        char name[128];
        snprintf(name, sizeof name, "%s.net_torque_N_m", hinge);
        const int net = csv_table_find(&table, name);
        snprintf(name, sizeof name, "%s.muscle_torque_N_m", hinge);
        const int muscles = csv_table_find(&table, name);
        snprintf(name, sizeof name, "%s.reserve_torque_N_m", hinge);
        const int reserve = csv_table_find(&table, name);
        cr_assert(net >= 0 && muscles >= 0 && reserve >= 0);
        for (long r = 0; r < table.row_count; ++r) {
            cr_expect_eq(table.columns[solved].values[r], 1.0, "row %ld not solved", r);
            if (table.columns[time].values[r] > 0.5) {
                worst = fmax(worst, fabs(table.columns[net].values[r] - table.columns[muscles].values[r]));
                cr_expect(fabs(table.columns[reserve].values[r]) <= 1e-3);
            }
        }
    }
    cr_log_info("arm: worst |net − muscles| after 0.5 s %.3g N·m", worst);
    cr_expect(worst <= 1e-3, "worst |net − muscles| %g N·m", worst);
    csv_table_free(&table);
    remove_dir();
}

/* The worm's torque muscle turns its top segment against the one below
 * it, in zero gravity: inverse dynamics gives its torque back about
 * Joint 5 (test_inverse_dynamics.c), so static optimization, with a
 * reserve scale far below its 0.01 N·m peak, must find the exertion the
 * run recruited: within 1e-4 from 0.5 s to 0.5 s before the end (2.1e-5
 * measured), the torque muscle counted as an actuator with the sign of
 * its body and reaction body's sides. */
Test(optimize_command, finds_the_worms_torque_muscle_exertion)
{
    cr_assert_not_null(mkdtemp(dir));
    cr_assert_eq(run_sinew("run worm --recruit \"Torque Muscle=100\" --duration 3"), 0, "%s", errors);
    cr_assert_eq(run_sinew("optimize worm --motion worm.csv --reserve 0.0001"), 0, "%s", errors);
    csv_table run, found;
    char path[512], error[1024];
    snprintf(path, sizeof path, "%s/worm.csv", dir);
    cr_assert(csv_table_read(path, &run, error, sizeof error), "%s", error);
    snprintf(path, sizeof path, "%s/worm-optimize.csv", dir);
    cr_assert(csv_table_read(path, &found, error, sizeof error), "%s", error);
    const int time = csv_table_find(&run, "time_s"), recruited = csv_table_find(&run, "Torque Muscle.exertion"),
              exertion = csv_table_find(&found, "Torque Muscle.exertion");
    cr_assert(time >= 0 && recruited >= 0 && exertion >= 0);
    cr_assert_eq(run.row_count, found.row_count);
    double worst = 0.0;
    for (long r = 0; r < run.row_count; ++r) {
        const double t = run.columns[time].values[r];
        if (t > 0.5 && t < 2.5) {
            worst = fmax(worst, fabs(found.columns[exertion].values[r] - run.columns[recruited].values[r]));
        }
    }
    cr_log_info("worm: worst |exertion found − recruited| %.3g", worst);
    cr_expect(run.columns[recruited].values[run.row_count / 2] > 0.05);
    cr_expect(worst <= 1e-4, "worst |exertion found − recruited| %g", worst);
    csv_table_free(&run);
    csv_table_free(&found);
    remove_dir();
}

static void expect_refused(const char *args, const char *message)
{
    cr_expect_neq(run_sinew(args), 0, "%s succeeded", args);
    cr_expect(strstr(errors, message) != NULL, "%s: stderr \"%s\", expected \"%s\"", args, errors, message);
    cr_expect(!exists("arm-optimize.csv") && !exists("arm-optimize.png") && !exists("leg-optimize.csv") &&
                  !exists("arm-optimize.csv-metadata.json"),
              "%s wrote a file", args);
}

Test(optimize_command, refuses_bad_input_and_writes_nothing)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("knee.csv", "time_s,Shoulder.angle_deg,Knee.angle_deg\n0,0,0\n0.1,0,0\n0.2,0,0\n0.3,0,0\n");
    expect_refused("optimize arm --motion knee.csv",
                   "knee.csv:1: column \"Knee.angle_deg\" names no hinge of model arm; its hinges' columns are "
                   "\"Shoulder.angle_deg\", \"Elbow.angle_deg\"");
    write_file("short.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.2,0,0\n");
    expect_refused("optimize arm --motion short.csv", "short.csv: 3 rows of data; expected at least 4");
    write_file("nan.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,nan\n0.2,0,0\n0.3,0,0\n");
    expect_refused("optimize arm --motion nan.csv", "nan.csv:3: column \"Elbow.angle_deg\" is not a number");
    write_file("back.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.1,0,0\n0.2,0,0\n");
    expect_refused("optimize arm --motion back.csv", "back.csv:4: time_s = 0.1 does not increase");
    write_file("fine.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.2,0,0\n0.3,0,0\n");
    expect_refused("optimize arm --motion fine.csv --level 2",
                   "model arm (variant \"All Muscles\", level 2): the model has no muscle or torque muscle built");
    expect_refused("optimize arm --motion fine.csv --level 1",
                   "model arm has no hinge at level 1 in variant \"All Muscles\": nothing to compute");
    expect_refused("optimize arm --motion fine.csv --exponent 0.5", "--exponent");
    expect_refused("optimize arm --motion fine.csv --exponent nan", "--exponent");
    expect_refused("optimize arm --motion fine.csv --exponent inf", "--exponent");
    expect_refused("optimize arm --motion fine.csv --reserve 0", "--reserve");
    write_file("bent.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,160\n0.1,0,160\n0.2,0,160\n0.3,0,160\n");
    expect_refused("optimize arm --motion bent.csv --cutoff 0",
                   "bent.csv line 2 (t = 0 s): hinge \"Elbow\" at 160 degrees is outside its limits -10 .. 150");
    expect_refused("optimize leg --motion fine.csv",
                   "model leg (variant \"All Muscles\", level 4): joint \"Ankle\" closes a loop");
    expect_refused("optimize arm", "missing --motion");
    remove_dir();
}

/* ---- the round trip ---------------------------------------------------------------- */

/* `sinew experiment loop`: the two runs agree exactly through the settling
 * (the same inputs to a deterministic engine), and in the window the
 * second run, driven by the activations found, follows the first within
 * 1° at both hinges (0.34° measured: the arm hanging under gravity is a
 * stable system, so the open-loop error stays bounded; docs/inverse.md);
 * inverse dynamics matches the first run's muscle torques within 2 % of
 * their range (0.9 % measured) away from the filter's last half second,
 * and the activations found reproduce the inverse torques within 1e-2 N·m
 * (their reserves). */
Test(loop_experiment, the_second_run_follows_the_first)
{
    cr_assert_not_null(mkdtemp(dir));
    cr_assert_eq(run_sinew("experiment loop"), 0, "%s", errors);
    csv_table table;
    char path[512], error[1024];
    snprintf(path, sizeof path, "%s/loop_round_trip.csv", dir);
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    const int time = csv_table_find(&table, "time_s"), solved = csv_table_find(&table, "solved");
    cr_assert(time >= 0 && solved >= 0);
    const double *t = table.columns[time].values;
    const double end = t[table.row_count - 1];
    for (int h = 0; h < 2; ++h) {
        const char *hinge = h == 0 ? "Shoulder" : "Elbow";
        int c[5];
        const char *const columns[5] = {"angle_deg", "replayed_angle_deg", "run_muscle_torque_N_m", "net_torque_N_m",
                                        "found_muscle_torque_N_m"};
        for (int k = 0; k < 5; ++k) {
            char name[128];
            snprintf(name, sizeof name, "%s.%s", hinge, columns[k]);
            c[k] = csv_table_find(&table, name);
            cr_assert(c[k] >= 0, "no column %s", name);
        }
        double drift = 0.0, id_error = 0.0, low = INFINITY, high = -INFINITY, found_error = 0.0;
        for (long r = 0; r < table.row_count; ++r) {
            const double *v[5];
            for (int k = 0; k < 5; ++k) {
                v[k] = table.columns[c[k]].values;
            }
            if (t[r] < 2.0 - 1e-9) {
                cr_assert_eq(v[1][r], v[0][r], "%s at %g s: the runs differ before the window", hinge, t[r]);
                continue;
            }
            cr_expect_eq(table.columns[solved].values[r], 1.0);
            drift = fmax(drift, fabs(v[1][r] - v[0][r]));
            low = fmin(low, v[2][r]);
            high = fmax(high, v[2][r]);
            if (t[r] < end - 0.5) {
                id_error = fmax(id_error, fabs(v[3][r] - v[2][r]));
            }
            found_error = fmax(found_error, fabs(v[4][r] - v[3][r]));
        }
        cr_log_info("%s: tracking %.3f°, inverse %.2f %% of the range, found vs inverse %.2g N·m", hinge, drift,
                    100.0 * id_error / (high - low), found_error);
        cr_expect(drift <= 1.0, "%s: the second run is %g° off the first", hinge, drift);
        cr_expect(id_error <= 0.02 * (high - low), "%s: inverse torques %g N·m off", hinge, id_error);
        cr_expect(found_error <= 1e-2, "%s: the activations found miss the torques by %g N·m", hinge, found_error);
    }
    csv_table_free(&table);
    remove_dir();
}
