/* SPDX-License-Identifier: MIT */
/* The two-stage excitation-contraction dynamics (mu/calcium_force.h):
 * - the step against the closed forms of two linear first-order stages in
 *   series, for a step of excitation from rest and for the decay from
 *   full activation (the classic difference of two exponentials), with
 *   equal time constants too, and at any h;
 * - the step along a train of pulses, whose branches turn, against GSL's
 *   rk8pd integration of the derivative function;
 * - P1 (`sinew experiment p1 --dynamics fast|slow`) on a rigid tendon:
 *   time to peak within the published range of fast (10-50 ms) or slow
 *   (40-160 ms) muscle (Close, "Dynamic properties of mammalian skeletal
 *   muscles", Physiol Rev 52, 1972), half-relaxation longer than the
 *   contraction, fusion between 30 and 100 Hz, tetanic/twitch between 3
 *   and 5, each measured here from the CSV the command writes;
 * - model files: the dynamics are read and reach the built muscle; a
 *   negative, zero, too long or non-numeric time, an unknown dynamics or
 *   fibre type, a time of the other dynamics are refused with file, line,
 *   column and JSON path;
 * - the C API refuses invalid params, and P1 an unknown --dynamics.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, mkstemp */

#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"
#include "io/csv_table.h"
#include "mu/calcium_force.h"
#include "mu/model.h"
#include "mu/model_desc.h"
#include "test_support.h"

static mu_calcium_force_params params_of(mu_fibre_type type, double excitation)
{
    return (mu_calcium_force_params){.excitation = excitation, .times = mu_calcium_force_times_of(type)};
}

/* Two first-order stages in series, τ1 then τ2, from rest under a unit
 * step: 1 - (τ1·e^(-t/τ1) - τ2·e^(-t/τ2))/(τ1 - τ2), or
 * 1 - (1 + t/τ)·e^(-t/τ) when τ1 = τ2 = τ. */
static double series_step_response(double t, double tau1, double tau2)
{
    if (tau1 == tau2) {
        return 1.0 - (1.0 + t / tau1) * exp(-t / tau1);
    }
    return 1.0 - (tau1 * exp(-t / tau1) - tau2 * exp(-t / tau2)) / (tau1 - tau2);
}

/* Steps from `state` under `params` with substeps of h up to each time. */
static void expect_step_response(mu_calcium_force_params params, mu_calcium_force_state state, double h, bool rising,
                                 const char *what)
{
    const mu_calcium_force_times *t = &params.times;
    const double tau_c = rising ? t->calcium_rise_time : t->calcium_decay_time;
    const double tau_a = rising ? t->force_rise_time : t->force_decay_time;
    const long steps = lround(0.4 / h);
    for (long k = 1; k <= steps; ++k) {
        cr_assert_eq(mu_calcium_force_step(&state, h, &params), RB_OK, "%s", rb_last_error());
        const double time = (double)k * h;
        /* The decay from c = a = 1 mirrors the rise: 1 - response. */
        const double c = rising ? 1.0 - exp(-time / tau_c) : exp(-time / tau_c);
        const double response = series_step_response(time, tau_c, tau_a);
        const double a = rising ? response : 1.0 - response;
        if (fabs(state.calcium - c) > 1e-12 || fabs(state.activation - a) > 1e-12) {
            cr_expect_fail("%s at %.5f s (h %g s): calcium %.15f against %.15f, activation %.15f against %.15f", what,
                           time, h, state.calcium, c, state.activation, a);
            return;
        }
    }
}

Test(calcium_force, a_step_of_excitation_is_the_closed_form_of_two_stages)
{
    /* From rest under u = 1, c rises above a throughout, so both stages
     * stay on their rise branches: exact at every h, a substep or a
     * whole 50 ms. */
    const double steps[] = {1.0 / 6000.0, 1.0 / 600.0, 0.05};
    for (int type = MU_FIBRE_FAST; type <= MU_FIBRE_SLOW; ++type) {
        for (int k = 0; k < 3; ++k) {
            expect_step_response(params_of((mu_fibre_type)type, 1.0), (mu_calcium_force_state){0.0, 0.0}, steps[k],
                                 true, type == MU_FIBRE_FAST ? "fast, rise" : "slow, rise");
        }
    }
}

Test(calcium_force, the_decay_from_full_activation_is_the_closed_form)
{
    /* From c = a = 1 under u = 0 the calcium falls first (τ_c decay <
     * τ_a decay in both sets), so a > c throughout: both decay branches. */
    for (int type = MU_FIBRE_FAST; type <= MU_FIBRE_SLOW; ++type) {
        expect_step_response(params_of((mu_fibre_type)type, 0.0), (mu_calcium_force_state){1.0, 1.0}, 1.0 / 6000.0,
                             false, type == MU_FIBRE_FAST ? "fast, decay" : "slow, decay");
    }
}

Test(calcium_force, equal_time_constants_take_the_limit_without_loss)
{
    /* τ_c = τ_a: the convolution's 0/0 limit, (t/τ)·e^(-t/τ); and 1e-9
     * apart, which moves the response by about 2.5e-10, where the plain
     * difference of exponentials over τ_c - τ_a would lose about 1e-7
     * (rounding of 1e-16 times τ/(τ_c - τ_a) = 1e9). */
    const double tolerances[] = {1e-14, 1e-9};
    const double taus[] = {0.020, 0.020 * (1.0 + 1e-9)};
    for (int k = 0; k < 2; ++k) {
        mu_calcium_force_params p = {.excitation = 1.0,
                                     .times = {.calcium_rise_time = 0.020,
                                               .calcium_decay_time = 0.05,
                                               .force_rise_time = taus[k],
                                               .force_decay_time = 0.05}};
        mu_calcium_force_state state = {0.0, 0.0};
        cr_assert_eq(mu_calcium_force_step(&state, 0.03, &p), RB_OK);
        expect_near(state.activation, series_step_response(0.03, 0.020, 0.020), tolerances[k],
                    "the activation at 30 ms");
    }
}

/* Integrates the derivative function with GSL from `y` to each time. */
static void gsl_integrate(const mu_calcium_force_params *params, double y[2], double from, double to)
{
    gsl_odeiv2_system system = {
        .function = mu_calcium_force_derivative, .jacobian = NULL, .dimension = 2, .params = (void *)params};
    gsl_odeiv2_driver *driver = gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-7, 1e-12, 1e-12);
    double t = from;
    cr_assert_eq(gsl_odeiv2_driver_apply(driver, &t, to, y), GSL_SUCCESS);
    gsl_odeiv2_driver_free(driver);
}

Test(calcium_force, a_pulse_train_follows_gsl_integration)
{
    /* 2 ms pulses at 40 Hz for 0.3 s: the calcium rises and falls each
     * period and crosses the activation, turning the force stage's
     * branch within a substep. GSL's rk8pd integrates each pulse and each
     * gap on its own (the excitation is discontinuous at their ends);
     * the substeps of 1/6000 s agree to 2e-5 (6e-6 measured), the
     * error of freezing a branch for the one substep in which c crosses a. */
    for (int type = MU_FIBRE_FAST; type <= MU_FIBRE_SLOW; ++type) {
        const long substeps_per_period = 150, width = 12, periods = 12;
        const double h = 1.0 / 6000.0;
        mu_calcium_force_state state = {0.0, 0.0};
        double y[2] = {0.0, 0.0};
        double worst = 0.0;
        for (long k = 0; k < periods * substeps_per_period; ++k) {
            const double u = k % substeps_per_period < width ? 1.0 : 0.0;
            mu_calcium_force_params p = params_of((mu_fibre_type)type, u);
            cr_assert_eq(mu_calcium_force_step(&state, h, &p), RB_OK);
            gsl_integrate(&p, y, (double)k * h, (double)(k + 1) * h);
            worst = fmax(worst, fmax(fabs(state.calcium - y[0]), fabs(state.activation - y[1])));
        }
        cr_expect(worst < 2e-5, "%s: the step and GSL differ by up to %g", type == MU_FIBRE_FAST ? "fast" : "slow",
                  worst);
        cr_expect(y[1] > 0.2, "the train activates the muscle: a = %g before the next pulse", y[1]);
    }
}

Test(calcium_force, invalid_arguments_are_refused_with_a_message)
{
    mu_calcium_force_params p = params_of(MU_FIBRE_FAST, 1.0);
    mu_calcium_force_state state = {0.0, 0.0};
    p.times.force_decay_time = -0.01;
    cr_expect_eq(mu_calcium_force_step(&state, 0.001, &p), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "force_decay_time -0.01 s") != NULL, "%s", rb_last_error());
    p = params_of(MU_FIBRE_FAST, 1.5);
    cr_expect_eq(mu_calcium_force_step(&state, 0.001, &p), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "excitation is 1.5") != NULL, "%s", rb_last_error());
    p = params_of(MU_FIBRE_FAST, 1.0);
    state.calcium = 2.0;
    cr_expect_eq(mu_calcium_force_step(&state, 0.001, &p), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(state.calcium, 2.0, "the state is left as it was");
    state.calcium = 0.0;
    cr_expect_eq(mu_calcium_force_step(&state, NAN, &p), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_calcium_force_step(NULL, 0.001, &p), RB_ERR_INVALID_ARGUMENT);
    double y[2] = {0.0, NAN}, dydt[2];
    cr_expect_neq(mu_calcium_force_derivative(0.0, y, dydt, &p), 0);
    cr_expect(strstr(rb_last_error(), "expected a finite state") != NULL, "%s", rb_last_error());
}

/* ---- P1 with the two stages ---- */

static char dir[] = "/tmp/sinew-twitch-XXXXXX";

/* Runs `sinew ARGS`, its output in DIR/log.txt read into `log`; returns
 * its exit status. */
static int run_sinew(const char *args, char *log, size_t log_size)
{
    return run_sinew_capture(dir, args, SINEW_STDOUT_AND_STDERR, log, log_size);
}

static const double *column(const csv_table *table, const char *name)
{
    int c = csv_table_find(table, name);
    cr_assert(c >= 0, "no column \"%s\"", name);
    return table->columns[c].values;
}

typedef struct p1_figures {
    double time_to_peak, half_relaxation; /* s */
    double fusion;                        /* Hz: the lowest rate of ripple < 5 % (above it all are) */
    double tetanic_over_twitch;           /* the largest mean up to 200 Hz over the twitch's peak */
} p1_figures;

/* Runs P1 with --dynamics `dynamics` and measures the rigid tendon's
 * figures from its CSV files, as a physiologist reads a recording: the
 * peak of the developed force, the time from the onset (time 0) to it,
 * and from it to half of it, interpolated between rows. */
static p1_figures run_p1(const char *dynamics)
{
    cr_assert_not_null(mkdtemp(dir));
    char args[1024], log[8192];
    snprintf(args, sizeof args, "experiment p1 --dynamics %s --out '%s'", dynamics, dir);
    cr_assert_eq(run_sinew(args, log, sizeof log), 0, "sinew %s failed: %s", args, log);
    cr_expect(strstr(log, "calcium-force") != NULL, "the printout names the dynamics: %s", log);
    csv_table trace, sweep;
    char path[600], error[1024];
    snprintf(path, sizeof path, "%s/p1_twitch_tetanus.csv", dir);
    cr_assert(csv_table_read(path, &trace, error, sizeof error), "%s", error);
    snprintf(path, sizeof path, "%s/p1_twitch_tetanus_sweep.csv", dir);
    cr_assert(csv_table_read(path, &sweep, error, sizeof error), "%s", error);
    const char *files[] = {
        "p1_twitch_tetanus.csv", "p1_twitch_tetanus_sweep.csv",         "p1_twitch_tetanus.png",
        "p1_twitch_tetanus.svg", "p1_twitch_tetanus.csv-metadata.json", "p1_twitch_tetanus_sweep.csv-metadata.json"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; ++k) {
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        remove(path);
    }
    cr_expect_eq(rmdir(dir), 0, "%s holds files not removed", dir);
    strcpy(dir, "/tmp/sinew-twitch-XXXXXX");

    const double *time = column(&trace, "time_s");
    const double *force = column(&trace, "rigid_tendon.twitch.developed_force_N");
    long peak = 0;
    for (long r = 0; r < trace.row_count; ++r) {
        peak = force[r] > force[peak] ? r : peak;
    }
    p1_figures figures = {.time_to_peak = time[peak], .half_relaxation = NAN, .fusion = NAN};
    for (long r = peak + 1; r < trace.row_count; ++r) {
        if (force[r] <= 0.5 * force[peak]) {
            double fraction = (force[r - 1] - 0.5 * force[peak]) / (force[r - 1] - force[r]);
            figures.half_relaxation = time[r - 1] + fraction * (time[r] - time[r - 1]) - time[peak];
            break;
        }
    }
    const double *rate = column(&sweep, "frequency_Hz");
    const double *mean = column(&sweep, "rigid_tendon.mean_developed_force_N");
    const double *ripple = column(&sweep, "rigid_tendon.ripple");
    double tetanic = 0.0;
    for (long r = sweep.row_count - 1; r >= 0; --r) {
        tetanic = rate[r] <= 200.0 ? fmax(tetanic, mean[r]) : tetanic;
        if (ripple[r] >= 0.05 && isnan(figures.fusion) && r + 1 < sweep.row_count) {
            figures.fusion = rate[r + 1];
        }
    }
    figures.tetanic_over_twitch = tetanic / force[peak];
    csv_table_free(&trace);
    csv_table_free(&sweep);
    return figures;
}

static void expect_physiological(const p1_figures *f, double fastest, double slowest, const char *what)
{
    cr_expect(f->time_to_peak >= fastest && f->time_to_peak <= slowest,
              "%s: time to peak %.1f ms, published %.0f-%.0f ms", what, 1e3 * f->time_to_peak, 1e3 * fastest,
              1e3 * slowest);
    cr_expect(f->half_relaxation > f->time_to_peak, "%s: half-relaxation %.1f ms, time to peak %.1f ms", what,
              1e3 * f->half_relaxation, 1e3 * f->time_to_peak);
    cr_expect(f->fusion >= 30.0 && f->fusion <= 100.0, "%s: fuses at %g Hz, expected 30-100 Hz", what, f->fusion);
    cr_expect(f->tetanic_over_twitch >= 3.0 && f->tetanic_over_twitch <= 5.0, "%s: tetanic/twitch %.2f, expected 3-5",
              what, f->tetanic_over_twitch);
}

Test(calcium_force, p1_fast_fibres_twitch_within_the_published_fast_range, .timeout = 60)
{
    /* Measured: 18.7 ms, 34.1 ms, 80 Hz, 3.78. */
    p1_figures f = run_p1("fast");
    expect_physiological(&f, 0.010, 0.050, "fast");
}

Test(calcium_force, p1_slow_fibres_twitch_within_the_published_slow_range, .timeout = 60)
{
    /* Measured: 55.5 ms, 107.9 ms, 30 Hz, 4.35. */
    p1_figures f = run_p1("slow");
    expect_physiological(&f, 0.040, 0.160, "slow");
}

Test(calcium_force, p1_refuses_an_unknown_dynamics_and_others_refuse_the_option)
{
    cr_assert_not_null(mkdtemp(dir));
    char log[4096];
    cr_expect_eq(run_sinew("experiment p1 --dynamics medium", log, sizeof log), 2);
    cr_expect(strstr(log, "--dynamics \"medium\": unknown, expected first_order, fast or slow") != NULL, "%s", log);
    cr_expect_eq(run_sinew("experiment e1 --dynamics fast", log, sizeof log), 2);
    cr_expect(strstr(log, "--dynamics: e1 takes its muscles' dynamics from its model") != NULL, "%s", log);
    rmdir(dir);
}

/* ---- Model files ---- */

/* A one-muscle model whose muscle's activation_dynamics is `dynamics`
 * (on line 8), written to a temporary file named in `path`. */
static void write_model(const char *dynamics, char *path, size_t size)
{
    snprintf(path, size, "/tmp/sinew-dynamics-XXXXXX");
    int fd = mkstemp(path);
    cr_assert(fd >= 0);
    FILE *f = fdopen(fd, "w");
    cr_assert_not_null(f);
    fprintf(f,
            "{\n"
            "  \"name\": \"dynamics\",\n"
            "  \"nails\": [{ \"name\": \"Nail\", \"position\": [0, 0] }],\n"
            "  \"bones\": [{ \"name\": \"Bone\", \"centre\": [0, -0.2], \"size\": [0.05, 0.4] }],\n"
            "  \"hinges\": [{ \"name\": \"Hinge\", \"body_a\": \"Nail\", \"anchor_a\": [0, 0], \"body_b\": "
            "\"Bone\", \"anchor_b\": [0, 0.2], \"radius\": 0.025 }],\n"
            "  \"muscles\": [{\n"
            "    \"name\": \"Muscle\", \"rest_length\": 0.2, \"max_force\": 500,\n"
            "    \"activation_dynamics\": %s,\n"
            "    \"path\": [{ \"body\": \"Nail\", \"point\": [0.1, 0] }, { \"body\": \"Bone\", \"point\": [0, "
            "-0.1] }]\n"
            "  }],\n"
            "  \"variants\": [{ \"name\": \"Default\", \"muscles\": [\"Muscle\"] }]\n"
            "}\n",
            dynamics);
    fclose(f);
}

Test(calcium_force, a_model_file_sets_the_dynamics_and_the_muscle_follows_them)
{
    char path[64];
    write_model("{ \"model\": \"calcium_force\", \"fibre_type\": \"slow\", \"force_decay_time\": 0.1 }", path,
                sizeof path);
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load(path, &desc), RB_OK, "%s", rb_last_error());
    remove(path);
    const mu_model_muscle *m = &desc->muscles[0];
    cr_expect(m->activation_dynamics && m->activation_model == MU_ACTIVATION_CALCIUM_FORCE);
    const mu_calcium_force_times slow = mu_calcium_force_times_of(MU_FIBRE_SLOW);
    cr_expect(m->calcium_force.calcium_rise_time == slow.calcium_rise_time &&
                  m->calcium_force.calcium_decay_time == slow.calcium_decay_time &&
                  m->calcium_force.force_rise_time == slow.force_rise_time,
              "the slow set");
    cr_expect_eq(m->calcium_force.force_decay_time, 0.1, "the override");

    /* Built, excitation 1 for 10 substeps of 1/600 s: the calcium and the
     * activation are the step's closed form (the muscle's own step,
     * independent of the bodies). */
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_set_activation(model, "Muscle", 1.0), RB_OK);
    cr_assert_eq(mu_model_step(model), RB_OK, "%s", rb_last_error());
    const mu_muscle_readout r = mu_model_muscle_readout(model, 0);
    const double t = 1.0 / 60.0;
    expect_near(r.calcium, 1.0 - exp(-t / slow.calcium_rise_time), 1e-9, "the calcium after one frame");
    expect_near(r.activation, series_step_response(t, slow.calcium_rise_time, slow.force_rise_time), 1e-9,
                "the activation after one frame");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

typedef struct bad_dynamics {
    const char *dynamics; /* the value of activation_dynamics */
    const char *at;       /* where in it the error points: the value, or the key */
    const char *message;  /* after "FILE:LINE:COLUMN: " */
} bad_dynamics;

Test(calcium_force, bad_dynamics_in_a_model_file_name_the_json_path)
{
    const bad_dynamics cases[] = {
        {"{ \"model\": \"calcium_force\", \"force_rise_time\": -0.02 }", "-0.02",
         "muscles[0].activation_dynamics.force_rise_time: -0.02 is out of range, expected the force-generating "
         "stage's rise time constant in s (in [0.0001, 10])"},
        {"{ \"model\": \"calcium_force\", \"calcium_decay_time\": 0 }", "0 }",
         "muscles[0].activation_dynamics.calcium_decay_time: 0 is out of range, expected the calcium stage's decay "
         "time constant in s (in [0.0001, 10])"},
        {"{ \"model\": \"calcium_force\", \"force_decay_time\": 11 }", "11",
         "muscles[0].activation_dynamics.force_decay_time: 11 is out of range, expected the force-generating stage's "
         "decay time constant in s (in [0.0001, 10])"},
        {"{ \"model\": \"calcium_force\", \"calcium_rise_time\": \"fast\" }", "\"fast\"",
         "muscles[0].activation_dynamics.calcium_rise_time: found a string, expected the calcium stage's rise time "
         "constant in s (in [0.0001, 10])"},
        {"{ \"model\": \"hatze\" }", "\"hatze\"",
         "muscles[0].activation_dynamics.model: \"hatze\" is no activation dynamics, expected the dynamics, "
         "\"first_order\" or \"calcium_force\""},
        {"{ \"model\": \"calcium_force\", \"fibre_type\": \"medium\" }", "\"medium\"",
         "muscles[0].activation_dynamics.fibre_type: \"medium\" is no fibre type, expected the fibre type, \"fast\" or "
         "\"slow\""},
        {"{ \"model\": \"calcium_force\", \"activation_time\": 0.01 }", "\"activation_time\"",
         "muscles[0].activation_dynamics.activation_time: belongs to the first_order dynamics, expected \"model\": "
         "\"first_order\" or the keys of the calcium_force dynamics"},
        {"{ \"fibre_type\": \"slow\" }", "\"fibre_type\"",
         "muscles[0].activation_dynamics.fibre_type: belongs to the calcium_force dynamics, expected \"model\": "
         "\"calcium_force\" or the keys of the first_order dynamics"},
        {"{ \"model\": \"calcium_force\", \"tau\": 0.01 }", "\"tau\"",
         "muscles[0].activation_dynamics.tau: unknown key \"tau\", expected one of model, activation_time, "
         "deactivation_time, fibre_type, calcium_rise_time, calcium_decay_time, force_rise_time, force_decay_time"},
    };
    /* Line 8 of write_model's file starts with this before the value. */
    const size_t prefix = strlen("    \"activation_dynamics\": ");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char path[64];
        write_model(cases[k].dynamics, path, sizeof path);
        mu_model_desc *desc = NULL;
        rb_status status = mu_model_desc_load(path, &desc);
        remove(path);
        cr_expect_eq(status, RB_ERR_INVALID_ARGUMENT, "%s loaded", cases[k].dynamics);
        cr_expect_null(desc);
        const size_t column = prefix + (size_t)(strstr(cases[k].dynamics, cases[k].at) - cases[k].dynamics) + 1;
        char expected[512];
        snprintf(expected, sizeof expected, "%s:8:%zu: %s", path, column, cases[k].message);
        cr_expect(strstr(rb_last_error(), expected) != NULL, "%s:\n got      %s\n expected %s", cases[k].dynamics,
                  rb_last_error(), expected);
    }
}

Test(calcium_force, a_muscle_def_with_a_bad_time_is_refused)
{
    rb_world *world = make_world(rb_v2(0.0, 0.0));
    rb_body_def body = rb_default_body_def();
    body.type = RB_BODY_STATIC;
    rb_body_id a, b;
    cr_assert_eq(rb_body_create(world, &body, &a), RB_OK);
    body.position = rb_v2(0.3, 0.0);
    cr_assert_eq(rb_body_create(world, &body, &b), RB_OK);
    mu_curves *curves = NULL;
    cr_assert_eq(mu_curves_create_seed_tables(MU_INTERPOLATION_LINEAR, &curves), RB_OK);
    mu_muscle_def def = mu_default_muscle_def();
    def.point_count = 2;
    def.bodies[0] = a;
    def.bodies[1] = b;
    def.rest_length = 0.2;
    def.max_force = 100.0;
    def.curves = curves;
    def.activation_dynamics = true;
    def.activation_model = MU_ACTIVATION_CALCIUM_FORCE;
    def.calcium_force.calcium_rise_time = 0.0;
    mu_muscle *muscle = NULL;
    cr_expect_eq(mu_muscle_create(world, &def, &muscle), RB_ERR_INVALID_ARGUMENT);
    cr_expect_null(muscle);
    cr_expect(strstr(rb_last_error(), "calcium_rise_time 0 s") != NULL, "%s", rb_last_error());
    mu_curves_destroy(curves);
    destroy_world_and_expect_no_leak(world);
}
