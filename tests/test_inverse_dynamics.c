/* SPDX-License-Identifier: MIT */
/* Inverse dynamics (mu/inverse_dynamics.h) against closed forms, the
 * motion filter (tools/commands/motion_filter.h) against its transfer
 * function, and `sinew inverse` against the muscle torques of the forward
 * run it inverts, and its errors. */
#define _DEFAULT_SOURCE /* mkstemps, mkdtemp */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"
#include "io/csv_table.h"
#include "motion_filter.h"
#include "mu/inverse_dynamics.h"

#define DEG (RB_PI / 180.0)
#define G 9.8

static mu_model_desc *load_text(const char *text)
{
    char path[] = "/tmp/sinew-inverse-XXXXXX.json";
    const int fd = mkstemps(path, 5);
    cr_assert(fd >= 0);
    cr_assert_eq(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    mu_model_desc *desc = NULL;
    const rb_status status = mu_model_desc_load(path, &desc);
    unlink(path);
    cr_assert_eq(status, RB_OK, "%s", rb_last_error());
    return desc;
}

static mu_model *build(const mu_model_desc *desc)
{
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    return model;
}

/* ---- closed forms ----------------------------------------------------------------- */

/* A bar of length L1 on a hinge at the origin, lying along +x at θ = 0,
 * without damping; with `second`, a bar of length L2 hinged at its tip
 * (the elbow's bodies named in the order given). */
#define L1 0.4
#define L2 0.3
#define WIDTH 0.04

static mu_model_desc *pendulum(bool second, bool elbow_reversed)
{
    char text[4096];
    snprintf(text, sizeof text,
             "{\"name\": \"pendulum\", \"gravity\": [0, -%g], \"damping\": 0,"
             " \"nails\": [{\"name\": \"Ground\", \"position\": [0, 0]}],"
             " \"bones\": [{\"name\": \"Upper\", \"centre\": [%g, 0], \"size\": [%g, %g]}%s],"
             " \"hinges\": [{\"name\": \"Shoulder\", \"body_a\": \"Ground\", \"anchor_a\": [0, 0],"
             "              \"body_b\": \"Upper\", \"anchor_b\": [%g, 0], \"radius\": 0.01}%s],"
             " \"muscles\": [], \"groups\": [], \"variants\": [{\"name\": \"bare\", \"muscles\": []}]}",
             G, L1 / 2, L1, WIDTH,
             second ? ", {\"name\": \"Lower\", \"centre\": [0.55, 0], \"size\": [0.3, 0.04]}" : "", -L1 / 2,
             !second ? ""
             : elbow_reversed
                 ? ", {\"name\": \"Elbow\", \"body_a\": \"Lower\", \"anchor_a\": [-0.15, 0], \"body_b\": \"Upper\","
                   " \"anchor_b\": [0.2, 0], \"radius\": 0.01}"
                 : ", {\"name\": \"Elbow\", \"body_a\": \"Upper\", \"anchor_a\": [0.2, 0], \"body_b\": \"Lower\","
                   " \"anchor_b\": [-0.15, 0], \"radius\": 0.01}");
    return load_text(text);
}

static rb_mass_data bar_mass(const mu_model *model, int part)
{
    return rb_body_mass_data(mu_model_world_to_read(model), mu_model_body(model, mu_model_part_body(model, part)));
}

/* θ(t) = A·sin(ωt): τ = I_pivot·θ'' + m·g·d·cos θ, with the bar's centre
 * d = L1/2 from the pivot and I_pivot = m·(L1² + w²)/12 + m·d² (a
 * rectangle's inertia about its centre, then Steiner's parallel axes). */
Test(inverse_dynamics, a_pendulum_moved_by_a_sine_needs_the_closed_form_torque)
{
    mu_model_desc *desc = pendulum(false, false);
    mu_model *model = build(desc);
    const int upper = 1; /* parts: the nail, then the bones */
    cr_assert_str_eq(mu_model_part_name(model, upper), "Upper");
    const double m = bar_mass(model, upper).mass, d = L1 / 2;
    const double inertia = m * (L1 * L1 + WIDTH * WIDTH) / 12.0;
    cr_assert(fabs(bar_mass(model, upper).rotational_inertia - inertia) <= 1e-12 * inertia);
    const double pivot_inertia = inertia + m * d * d;
    const double amplitude = 50.0 * DEG, omega = 2.0 * RB_PI * 0.8;
    double worst = 0.0;
    for (double t = 0.0; t <= 2.5; t += 0.01) {
        const double theta = amplitude * sin(omega * t);
        const double angle = theta / DEG, rate = amplitude * omega * cos(omega * t),
                     acceleration = -amplitude * omega * omega * sin(omega * t);
        double torque;
        cr_assert_eq(mu_model_inverse_dynamics(model, &angle, &rate, &acceleration, &torque), RB_OK, "%s",
                     rb_last_error());
        const double expected = pivot_inertia * acceleration + m * G * d * cos(theta);
        worst = fmax(worst, fabs(torque - expected) / fabs(expected));
        cr_assert(fabs(torque - expected) <= 1e-6 * fabs(expected), "t = %g: τ = %.12g N·m, closed form %.12g N·m", t,
                  torque, expected);
    }
    cr_log_info("pendulum: worst relative error %.2g", worst);
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* Two bars at rest: each hinge carries the weight's moment of every bar
 * beyond it, m·g times the horizontal distance from its pivot to the
 * bar's centre. */
static void expect_static_torques(bool elbow_reversed)
{
    mu_model_desc *desc = pendulum(true, elbow_reversed);
    mu_model *model = build(desc);
    const double m1 = bar_mass(model, 1).mass, m2 = bar_mass(model, 2).mass;
    const double poses[][2] = {{0.0, 0.0}, {30.0, 45.0}, {-60.0, 100.0}, {120.0, -30.0}, {-90.0, -90.0}};
    for (size_t k = 0; k < sizeof poses / sizeof poses[0]; ++k) {
        const double t1 = poses[k][0] * DEG, t2 = poses[k][1] * DEG;
        const double c1x = L1 / 2 * cos(t1), elbow_x = L1 * cos(t1), c2x = elbow_x + L2 / 2 * cos(t1 + t2);
        const double shoulder = m1 * G * c1x + m2 * G * c2x, elbow = m2 * G * (c2x - elbow_x);
        /* Reversed, the elbow's angle is angle(Upper) − angle(Lower) = −θ2
         * and its torque is on Upper, −τ. */
        const double sign = elbow_reversed ? -1.0 : 1.0;
        const double angles[2] = {poses[k][0], sign * poses[k][1]}, zero[2] = {0.0, 0.0};
        double torques[2];
        cr_assert_eq(mu_model_inverse_dynamics(model, angles, zero, zero, torques), RB_OK, "%s", rb_last_error());
        cr_expect(fabs(torques[0] - shoulder) <= 1e-9 * (fabs(shoulder) + 1e-3),
                  "pose %zu: shoulder %.12g, expected %.12g", k, torques[0], shoulder);
        cr_expect(fabs(torques[1] - sign * elbow) <= 1e-9 * (fabs(elbow) + 1e-3),
                  "pose %zu: elbow %.12g, expected %.12g", k, torques[1], sign * elbow);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(inverse_dynamics, a_double_pendulum_at_rest_carries_its_weights_moments) { expect_static_torques(false); }

Test(inverse_dynamics, a_hinge_named_from_its_distal_bone_gets_the_opposite_torque) { expect_static_torques(true); }

/* Two bars moving: the equations of motion of a planar two-link arm
 * (Spong, Hutchinson and Vidyasagar, "Robot Modeling and Control", 2006,
 * section 7.4), links of mass m_i, inertia I_i about the centre, centre
 * d_i from the proximal joint, first link L1 long, gravity along −y:
 *
 *   τ1 = M11·θ1'' + M12·θ2'' − h·(2θ1'θ2' + θ2'²) + G1,
 *   τ2 = M12·θ1'' + M22·θ2'' + h·θ1'² + G2,
 *
 * M11 = I1 + m1·d1² + I2 + m2·(L1² + d2² + 2·L1·d2·cos θ2),
 * M12 = I2 + m2·(d2² + L1·d2·cos θ2), M22 = I2 + m2·d2²,
 * h = m2·L1·d2·sin θ2, G1 = (m1·d1 + m2·L1)·g·cos θ1 + m2·d2·g·cos(θ1 + θ2),
 * G2 = m2·d2·g·cos(θ1 + θ2). */
Test(inverse_dynamics, a_moving_double_pendulum_follows_the_two_link_equations)
{
    mu_model_desc *desc = pendulum(true, false);
    mu_model *model = build(desc);
    const rb_mass_data one = bar_mass(model, 1), two = bar_mass(model, 2);
    const double m1 = one.mass, m2 = two.mass, i1 = one.rotational_inertia, i2 = two.rotational_inertia;
    const double d1 = L1 / 2, d2 = L2 / 2;
    const double states[][6] = {{10, 20, 1.0, -2.0, 3.0, 5.0},
                                {-70, 95, -3.0, 4.0, -20.0, 12.0},
                                {150, -140, 6.0, 6.0, 0.0, -40.0},
                                {0, 0, 2.0, 0.0, 0.0, 0.0}};
    for (size_t k = 0; k < sizeof states / sizeof states[0]; ++k) {
        const double t1 = states[k][0] * DEG, t2 = states[k][1] * DEG;
        const double w1 = states[k][2], w2 = states[k][3], a1 = states[k][4], a2 = states[k][5];
        const double m11 = i1 + m1 * d1 * d1 + i2 + m2 * (L1 * L1 + d2 * d2 + 2.0 * L1 * d2 * cos(t2));
        const double m12 = i2 + m2 * (d2 * d2 + L1 * d2 * cos(t2)), m22 = i2 + m2 * d2 * d2;
        const double h = m2 * L1 * d2 * sin(t2);
        const double g1 = (m1 * d1 + m2 * L1) * G * cos(t1) + m2 * d2 * G * cos(t1 + t2);
        const double g2 = m2 * d2 * G * cos(t1 + t2);
        const double expected[2] = {m11 * a1 + m12 * a2 - h * (2.0 * w1 * w2 + w2 * w2) + g1,
                                    m12 * a1 + m22 * a2 + h * w1 * w1 + g2};
        const double angles[2] = {states[k][0], states[k][1]}, rates[2] = {w1, w2}, accelerations[2] = {a1, a2};
        double torques[2];
        cr_assert_eq(mu_model_inverse_dynamics(model, angles, rates, accelerations, torques), RB_OK, "%s",
                     rb_last_error());
        for (int j = 0; j < 2; ++j) {
            cr_expect(fabs(torques[j] - expected[j]) <= 1e-9 * (fabs(expected[j]) + 1.0),
                      "state %zu, hinge %d: %.12g N·m, expected %.12g N·m", k, j, torques[j], expected[j]);
        }
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The leg's chain closes between its two nails; two bars hinged together
 * in the air have no ground to grow the tree from. */
Test(inverse_dynamics, closed_chains_and_floating_bodies_are_refused)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("leg", &desc), RB_OK);
    mu_model *model = build(desc);
    cr_expect_eq(mu_model_check_tree(model), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "closes a loop") != NULL, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    desc = load_text("{\"name\": \"floating\", \"gravity\": [0, 0], \"nails\": [],"
                     " \"bones\": [{\"name\": \"One\", \"centre\": [0, 0], \"size\": [0.2, 0.02]},"
                     "             {\"name\": \"Two\", \"centre\": [0.2, 0], \"size\": [0.2, 0.02]}],"
                     " \"hinges\": [{\"name\": \"Middle\", \"body_a\": \"One\", \"anchor_a\": [0.1, 0],"
                     "              \"body_b\": \"Two\", \"anchor_b\": [-0.1, 0], \"radius\": 0.01}],"
                     " \"muscles\": [], \"groups\": [], \"variants\": [{\"name\": \"bare\", \"muscles\": []}]}");
    model = build(desc);
    cr_expect_eq(mu_model_check_tree(model), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "body \"One\" is not joined to the ground") != NULL, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* ---- the filter ------------------------------------------------------------------- */

/* The two passes of a second-order Butterworth section give the gain
 * |H(f)|² = 1/(1 + (f/f_s)⁴), f_s = f_c/0.802 (the analogue prototype's;
 * the bilinear transform prewarped at f_s differs by less than 0.2 % at
 * f_c here), and no phase: a sine at the cut-off comes out at
 * 1/(1 + 0.802⁴) = 0.7077 of its amplitude (−3 dB, 1/√2 = 0.7071, to
 * 0.1 %), in phase. */
Test(motion_filter, a_sine_at_the_cutoff_keeps_its_phase_and_loses_3_dB)
{
    const double rate = 200.0, cutoff = 6.0;
    const size_t n = 2000;
    double x[2000];
    for (size_t i = 0; i < n; ++i) {
        x[i] = sin(2.0 * RB_PI * cutoff * (double)i / rate);
    }
    cr_assert(motion_filter_low_pass(x, n, cutoff, rate));
    /* The amplitude and phase in the middle: least squares on sin and cos. */
    double s = 0.0, c = 0.0;
    size_t count = 0;
    for (size_t i = n / 4; i < 3 * n / 4; ++i, ++count) {
        s += x[i] * sin(2.0 * RB_PI * cutoff * (double)i / rate);
        c += x[i] * cos(2.0 * RB_PI * cutoff * (double)i / rate);
    }
    const double gain = 2.0 * hypot(s, c) / (double)count, phase = atan2(c, s);
    const double expected = 1.0 / (1.0 + pow(MOTION_FILTER_TWO_PASS_CORRECTION, 4.0));
    cr_expect(fabs(gain - expected) < 2e-3, "gain %.5f, expected %.5f", gain, expected);
    cr_expect(fabs(gain - 1.0 / sqrt(2.0)) < 2e-3, "gain %.5f, expected −3 dB", gain);
    cr_expect(fabs(phase) < 1e-3, "phase %.2g rad, expected 0", phase);
}

/* Second-order differences of a sampled sine, relative to the amplitude
 * of the derivative: truncation errors (ωh)²/6 of the rate and (ωh)²/12
 * of the acceleration inside, (ωh)²/3 and 11(ωh)²/12 at the ends (the
 * Taylor remainders of the one-sided formulas). */
Test(motion_filter, differences_of_a_sine_have_their_truncation_error)
{
    const double h = 1e-3, omega = 2.0 * RB_PI;
    const size_t n = 1000;
    double x[1000], rate[1000], acceleration[1000];
    for (size_t i = 0; i < n; ++i) {
        x[i] = sin(omega * (double)i * h);
    }
    motion_filter_differentiate(x, n, h, rate, acceleration);
    const double wh2 = (omega * h) * (omega * h);
    for (size_t i = 0; i < n; ++i) {
        const double t = (double)i * h;
        const bool end = i == 0 || i == n - 1;
        const double rate_bound = 1.01 * wh2 * (end ? 1.0 / 3.0 : 1.0 / 6.0);
        const double acceleration_bound = 1.01 * wh2 * (end ? 11.0 / 12.0 : 1.0 / 12.0);
        cr_expect(fabs(rate[i] - omega * cos(omega * t)) <= rate_bound * omega, "rate at %zu: %.12g", i, rate[i]);
        cr_expect(fabs(acceleration[i] + omega * omega * sin(omega * t)) <= acceleration_bound * omega * omega,
                  "acceleration at %zu: %.12g", i, acceleration[i]);
    }
}

/* ---- the command ------------------------------------------------------------------ */

static char dir[] = "/tmp/sinew-inverse-XXXXXX";

/* The last run's messages (its stderr). */
static char errors[8192];

static int run_sinew(const char *args)
{
    return run_sinew_capture(dir, args, SINEW_STDERR_ONLY, errors, sizeof errors);
}

static bool exists(const char *name) { return file_exists_in(dir, name); }

static const char *error_text(void) { return errors; }

static void write_file(const char *name, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fputs(text, f);
    fclose(f);
}

static void read_table(const char *name, csv_table *table)
{
    char path[512], error[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    cr_assert(csv_table_read(path, table, error, sizeof error), "%s", error);
}

static void remove_dir(void)
{
    char command[600];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}

/* The largest difference between the inverse torques and the run's own
 * muscle torques plus its limits' torques, `skip` s from either end (the
 * start from rest, the filter's start-up and end, the one-sided
 * differences at the ends), over the range of the latter. */
static double round_trip_error(const csv_table *run, const csv_table *inverse, const char *hinge, double skip)
{
    char name[256];
    snprintf(name, sizeof name, "%s.muscle_torque_N_m", hinge);
    const int muscles = csv_table_find(run, name);
    snprintf(name, sizeof name, "%s.reaction_torque_N_m", hinge);
    const int limits = csv_table_find(run, name);
    snprintf(name, sizeof name, "%s.net_torque_N_m", hinge);
    const int net = csv_table_find(inverse, name);
    const int time = csv_table_find(run, "time_s");
    cr_assert(muscles >= 0 && limits >= 0 && net >= 0 && time >= 0);
    cr_assert_eq(run->row_count, inverse->row_count);
    double low = INFINITY, high = -INFINITY, worst = 0.0;
    for (long r = 0; r < run->row_count; ++r) {
        const double expected = run->columns[muscles].values[r] + run->columns[limits].values[r];
        low = fmin(low, expected);
        high = fmax(high, expected);
        const double t = run->columns[time].values[r];
        if (t > skip && t < run->columns[time].values[run->row_count - 1] - skip) {
            worst = fmax(worst, fabs(inverse->columns[net].values[r] - expected));
        }
    }
    return worst / (high - low);
}

/* The arm, its long biceps driven by a 1 Hz sine of activation and a
 * steady lateral triceps, holding 1 kg: the torques that reproduce its
 * motion are the ones its muscles (and limits) applied. Unsmoothed, the
 * second differences of 60 Hz samples agree within 1 % of the torques'
 * range away from the ends (a second at each); smoothed at 6 Hz,
 * within 3 %, the filter removing the run's components near and above
 * its cut-off (docs/inverse.md). */
Test(inverse_command, inverts_a_forward_run_of_the_arm)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("sine.ctl", "0 activation sine \"Biceps Long\" 0.3 0.15 1 6\n0 activation \"Triceps Lateral\" 0.1\n");
    cr_assert_eq(run_sinew("run arm --weight 1 --duration 6 --control sine.ctl"), 0, "%s", error_text());
    csv_table run, inverse;
    read_table("arm.csv", &run);
    const double limits[2] = {0.01, 0.03};
    const char *cutoffs[2] = {"0", "6"};
    for (int k = 0; k < 2; ++k) {
        char args[256];
        snprintf(args, sizeof args, "inverse arm --weight 1 --motion arm.csv --cutoff %s", cutoffs[k]);
        cr_assert_eq(run_sinew(args), 0, "%s", error_text());
        cr_assert(exists("arm-inverse.csv") && exists("arm-inverse.csv-metadata.json") && exists("arm-inverse.png"));
        read_table("arm-inverse.csv", &inverse);
        for (int h = 0; h < 2; ++h) {
            const char *hinge = h == 0 ? "Shoulder" : "Elbow";
            const double error = round_trip_error(&run, &inverse, hinge, 1.0);
            cr_log_info("cutoff %s Hz, %s: %.3f %% of the range", cutoffs[k], hinge, 100.0 * error);
            cr_expect(error < limits[k], "cutoff %s Hz, %s: %.3f %% of the range", cutoffs[k], hinge, 100.0 * error);
        }
        csv_table_free(&inverse);
    }
    csv_table_free(&run);
    remove_dir();
}

/* The worm, in zero gravity on its static bottom segment, its torque
 * muscle turning the top segment against the one below: after the start
 * the top segment spins steadily about Joint 5 and the muscle's torque
 * only balances the segment's damping (c·I·ω and the drag on its centre),
 * so inverse dynamics must give the muscle's torque about Joint 5 and
 * nothing about the free hinges below. */
Test(inverse_command, gives_the_worms_torque_muscle_back_through_its_damping)
{
    cr_assert_not_null(mkdtemp(dir));
    cr_assert_eq(run_sinew("run worm --recruit \"Torque Muscle=100\" --duration 3"), 0, "%s", error_text());
    cr_assert_eq(run_sinew("inverse worm --motion worm.csv --cutoff 0"), 0, "%s", error_text());
    csv_table run, inverse;
    read_table("worm.csv", &run);
    read_table("worm-inverse.csv", &inverse);
    const int time = csv_table_find(&run, "time_s"), muscle = csv_table_find(&run, "Torque Muscle.torque_N_m");
    const int top = csv_table_find(&inverse, "Joint 5.net_torque_N_m");
    cr_assert(time >= 0 && muscle >= 0 && top >= 0);
    for (long r = 30; r + 1 < run.row_count; ++r) {
        const double expected = run.columns[muscle].values[r];
        cr_expect(fabs(inverse.columns[top].values[r] - expected) <= 5e-4 * fabs(expected),
                  "t = %g s: %.10g N·m, the muscle's %.10g N·m", run.columns[time].values[r],
                  inverse.columns[top].values[r], expected);
        for (int j = 1; j <= 4; ++j) {
            char name[64];
            snprintf(name, sizeof name, "Joint %d.net_torque_N_m", j);
            const double free_hinge = inverse.columns[csv_table_find(&inverse, name)].values[r];
            cr_expect(fabs(free_hinge) <= 1e-3 * fabs(expected), "t = %g s: %s %.3g N·m", run.columns[time].values[r],
                      name, free_hinge);
        }
    }
    csv_table_free(&run);
    csv_table_free(&inverse);
    remove_dir();
}

static void expect_refused(const char *args, const char *message)
{
    cr_expect_neq(run_sinew(args), 0, "%s succeeded", args);
    cr_expect(strstr(error_text(), message) != NULL, "%s: stderr \"%s\", expected \"%s\"", args, error_text(), message);
    cr_expect(!exists("arm-inverse.csv") && !exists("arm-inverse.png") && !exists("leg-inverse.csv"), "%s wrote a file",
              args);
}

Test(inverse_command, refuses_bad_motions_and_writes_nothing)
{
    cr_assert_not_null(mkdtemp(dir));
    write_file("knee.csv", "time_s,Shoulder.angle_deg,Knee.angle_deg\n0,0,0\n0.1,0,0\n0.2,0,0\n0.3,0,0\n");
    expect_refused("inverse arm --motion knee.csv",
                   "knee.csv:1: column \"Knee.angle_deg\" names no hinge of model arm; its hinges' columns are "
                   "\"Shoulder.angle_deg\", \"Elbow.angle_deg\"");
    write_file("no_elbow.csv", "time_s,Shoulder.angle_deg\n0,0\n0.1,0\n0.2,0\n0.3,0\n");
    expect_refused("inverse arm --motion no_elbow.csv", "no_elbow.csv:1: no column \"Elbow.angle_deg\"");
    write_file("short.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.2,0,0\n");
    expect_refused("inverse arm --motion short.csv", "short.csv: 3 rows of data; expected at least 4");
    write_file("nan.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,nan\n0.2,0,0\n0.3,0,0\n");
    expect_refused("inverse arm --motion nan.csv", "nan.csv:3: column \"Elbow.angle_deg\" is not a number");
    write_file("back.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.1,0,0\n0.2,0,0\n");
    expect_refused("inverse arm --motion back.csv", "back.csv:4: time_s = 0.1 does not increase");
    write_file("uneven.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.25,0,0\n0.3,0,0\n");
    expect_refused("inverse arm --motion uneven.csv --cutoff 0", "uneven.csv:4: a time step of 0.15 s");
    write_file("word.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.2,x,0\n0.3,0,0\n");
    expect_refused("inverse arm --motion word.csv", "word.csv:4: column \"Shoulder.angle_deg\" has \"x\"");
    expect_refused("inverse arm --motion missing.csv", "missing.csv");
    write_file("fine.csv", "time_s,Shoulder.angle_deg,Elbow.angle_deg\n0,0,0\n0.1,0,0\n0.2,0,0\n0.3,0,0\n");
    expect_refused("inverse arm --motion fine.csv --cutoff 5", "--cutoff 5 Hz: fine.csv is sampled at 10 Hz");
    expect_refused("inverse leg --motion fine.csv", "closes a loop");
    expect_refused("inverse arm", "missing --motion");
    remove_dir();
}
