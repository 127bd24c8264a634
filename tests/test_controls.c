/* SPDX-License-Identifier: MIT */
/* Control files (tools/commands/control_file.h, controls.h,
 * control_shape.h): the shapes' values against their closed forms, a
 * schedule applied to the arm and the worm substep by substep, a later
 * line replacing an earlier one, step-only files stepping whole frames as
 * the model's own API does, the example files, and every bad line named by
 * file and line with what was expected.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, popen */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"
#include "control_file.h"
#include "mu/model.h"
#include "test_support.h"

/* The built-in models' substep: 60 frames a second, 10 substeps each. */
#define H (1.0 / 600.0)

static mu_model_desc *load(const char *name)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin(name, &desc), RB_OK, "%s", rb_last_error());
    return desc;
}

/* A model, its schedule read from `text` and built in `variant`. */
typedef struct fixture {
    mu_model_desc *desc;
    controls schedule;
    mu_model *model;
} fixture;

static fixture open_fixture(const char *model, const char *variant, double weight_kg, const char *text)
{
    fixture f = {.desc = load(model)};
    mu_model_options options = mu_default_model_options();
    options.variant = mu_model_desc_find_variant(f.desc, variant);
    cr_assert(options.variant >= 0, "no variant %s", variant);
    for (int w = 0; w < f.desc->weight.mass_count; ++w) {
        options.weight_index = f.desc->weight.masses[w] == weight_kg ? w : options.weight_index;
    }
    cr_assert(controls_init(&f.schedule, f.desc, options.variant));
    char error[1024];
    cr_assert(control_text_read("controls.txt", text, &f.schedule, error, sizeof error), "%s", error);
    cr_assert_eq(mu_model_create(f.desc, &options, &f.model), RB_OK, "%s", rb_last_error());
    return f;
}

static void close_fixture(fixture *f)
{
    mu_model_destroy(f->model);
    controls_free(&f->schedule);
    mu_model_desc_destroy(f->desc);
}

static int muscle_index(const mu_model *model, const char *name)
{
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        if (strcmp(mu_model_muscle_name(model, m), name) == 0) {
            return m;
        }
    }
    cr_assert_fail("no built muscle %s", name);
    return -1;
}

/* Applies the controls and steps substep k; returns the muscle's
 * activation over that substep. */
static double substep_activation(fixture *f, long k, int muscle)
{
    cr_assert_eq(controls_apply(&f->schedule, f->model, k), RB_OK, "%s", rb_last_error());
    cr_assert_eq(mu_model_substep(f->model), RB_OK, "%s", rb_last_error());
    return mu_model_muscle_readout(f->model, muscle).activation;
}

/* ------------------------------------------------------------- shapes */

/* The example: `0.5 ramp "Biceps Short" 0 0.8 1.0` gives 0.4 at
 * t = 1.0 s; the closed form is 0.8·(t − 0.5)/1.0 from 0.5 s to 1.5 s. */
Test(controls, a_ramp_gives_its_closed_form_at_three_times)
{
    fixture f = open_fixture("arm", "All Muscles", 1.0, "0.5 ramp \"Biceps Short\" 0 0.8 1.0\n");
    const int biceps = muscle_index(f.model, "Biceps Short");
    for (long k = 0; k <= 1000; ++k) {
        double activation = substep_activation(&f, k, biceps);
        double t = (double)k * H;
        double closed = t < 0.5 ? 0.0 : t < 1.5 ? 0.8 * (t - 0.5) / 1.0 : 0.8;
        if (k == 450 || k == 600 || k == 750) {
            char what[64];
            snprintf(what, sizeof what, "activation at t = %.2f s", t);
            expect_near(activation, closed, 1e-12, what);
        }
        if (k == 600) {
            expect_near(activation, 0.4, 1e-12, "the issue's 0.4 at t = 1.0 s");
        }
        cr_expect(fabs(activation - closed) <= 1e-12, "substep %ld: %.17g, expected %.17g", k, activation, closed);
    }
    close_fixture(&f);
}

Test(controls, a_sine_follows_its_closed_form_then_holds_its_mean)
{
    fixture f = open_fixture("arm", "All Muscles", 1.0, "0.25 sine \"Biceps Long\" 0.5 0.3 2 1\n");
    const int biceps = muscle_index(f.model, "Biceps Long");
    for (long k = 0; k < 1000; ++k) {
        double activation = substep_activation(&f, k, biceps);
        double t = (double)k * H;
        double closed = t < 0.25 - 1e-12 ? 0.0 : t < 1.25 ? 0.5 + 0.3 * sin(2.0 * RB_PI * 2.0 * (t - 0.25)) : 0.5;
        cr_expect(fabs(activation - closed) <= 1e-12, "substep %ld (t = %g s): %.17g, expected %.17g", k, t, activation,
                  closed);
    }
    close_fixture(&f);
    /* The shape alone at quarter periods: mean, crest, trough, mean after. */
    control_shape sine = {
        .kind = CONTROL_SINE, .start = 0.25, .duration = 1, .first = 0.5, .second = 0.3, .frequency = 2};
    expect_near(control_shape_value(&sine, 0.25, H), 0.5, 1e-15, "sine at its start");
    expect_near(control_shape_value(&sine, 0.375, H), 0.8, 1e-15, "sine a quarter period on");
    expect_near(control_shape_value(&sine, 0.625, H), 0.2, 1e-15, "sine three quarters on");
    expect_near(control_shape_value(&sine, 1.3, H), 0.5, 0.0, "sine after its duration");
}

/* The substeps on in a train, counted independently: pulse n starts at
 * the first substep at or after start + n/f and lasts round(width/h). */
static bool expected_on(double start, double frequency, double width, double duration, long k)
{
    for (int n = 0; start + n / frequency < start + duration - 1e-12; ++n) {
        long first = (long)ceil((start + n / frequency) * 600.0 - 1e-6);
        if (k >= first && k < first + lround(width * 600.0)) {
            return true;
        }
    }
    return false;
}

Test(controls, a_pulse_train_is_on_for_whole_substeps_at_its_frequency)
{
    /* 2 ms at 100 Hz: one substep (1.667 ms) every 6, five pulses in 50 ms;
     * then 10 ms at 30 Hz: 6 substeps every 20, at level 0.7. */
    fixture f = open_fixture("arm", "All Muscles", 1.0,
                             "0.1 pulses \"Biceps Short\" 1 100 0.002 0.05\n"
                             "0.5 pulses \"Biceps Short\" 0.7 30 0.01 0.1\n");
    const int biceps = muscle_index(f.model, "Biceps Short");
    int on_first = 0, on_second = 0;
    for (long k = 0; k < 420; ++k) {
        double activation = substep_activation(&f, k, biceps);
        double expected = k < 300 ? (expected_on(0.1, 100, 0.002, 0.05, k) ? 1.0 : 0.0)
                                  : (expected_on(0.5, 30, 0.01, 0.1, k) ? 0.7 : 0.0);
        cr_expect_eq(activation, expected, "substep %ld: %g, expected %g", k, activation, expected);
        on_first += k < 300 && activation > 0.0;
        on_second += k >= 300 && activation > 0.0;
    }
    cr_expect_eq(on_first, 5, "5 pulses of one substep, got %d substeps on", on_first);
    cr_expect_eq(on_second, 18, "3 pulses of 6 substeps, got %d substeps on", on_second);
    close_fixture(&f);
    /* The first train's pulses start at substeps 60, 66, 72, 78, 84. */
    control_shape train = {
        .kind = CONTROL_PULSES, .start = 0.1, .duration = 0.05, .first = 1, .frequency = 100, .width = 0.002};
    for (long k = 55; k < 95; ++k) {
        bool on = k >= 60 && k <= 84 && (k - 60) % 6 == 0;
        cr_expect_eq(control_shape_value(&train, (double)k * H, H), on ? 1.0 : 0.0, "substep %ld", k);
    }
}

/* The worm's torque muscle: a step, a ramp of recruitment (rounded to
 * whole neurons) and a pulse train, read from its motor pool. */
Test(controls, a_recruitment_schedule_drives_the_worms_motor_pool)
{
    fixture f = open_fixture("worm", "Default", 0.0,
                             "0    recruit         \"Torque Muscle\" 20\n"
                             "0.5  recruit ramp    \"Torque Muscle\" 20 120 1\n"
                             "2    recruit pulses  \"Torque Muscle\" 200 10 0.05 0.3\n");
    cr_assert_eq(mu_model_torque_muscle_count(f.model), 1);
    const mu_motor_pool *pool = mu_model_motor_pool(f.model, 0);
    for (long k = 0; k < 1500; ++k) {
        cr_assert_eq(controls_apply(&f.schedule, f.model, k), RB_OK, "%s", rb_last_error());
        double t = (double)k * H;
        long expected = t < 0.5 ? 20 : t < 1.5 ? lround(20.0 + 100.0 * (t - 0.5)) : t < 2.0 - 1e-9 ? 120 : 0;
        if (t >= 2.0 - 1e-9) {
            /* 50 ms = 30 substeps on in every 60, three pulses. */
            long into = k - 1200;
            expected = into % 60 < 30 && into < 180 ? 200 : 0;
        }
        int recruited = mu_motor_pool_recruited(pool);
        cr_expect_eq(recruited, expected, "substep %ld (t = %g s): %d neurons, expected %ld", k, t, recruited,
                     expected);
        cr_expect_eq(mu_motor_pool_exertion(pool), mu_motor_pool_exertion_at(pool, recruited), "exertion at %ld", k);
        cr_assert_eq(mu_model_substep(f.model), RB_OK, "%s", rb_last_error());
    }
    close_fixture(&f);
}

/* ------------------------------------------------------------ overlaps */

/* A later line replaces the muscle's command from its time on, also at
 * the same time (the group's sine replaces Biceps Short's first ramp, the
 * second ramp replaces the sine for that muscle alone); a step on one
 * muscle of the group ends the sine for it; a pulse holds one frame (10
 * substeps) and the ramp goes on after it. */
Test(controls, a_later_line_replaces_the_command_from_its_time)
{
    fixture f = open_fixture("arm", "All Muscles", 1.0,
                             "0  ramp        \"Biceps Short\"                0 1 2\n"
                             "0  sine        \"Biceps Short + Biceps Long\"  0.5 0.2 1 10\n"
                             "0  ramp        \"Biceps Short\"                0 1 2\n"
                             "1  activation  \"Biceps Long\"                 0.1\n"
                             "1  pulse       \"Biceps Short\"                0.9\n");
    const int shorter = muscle_index(f.model, "Biceps Short");
    const int longer = muscle_index(f.model, "Biceps Long");
    for (long k = 0; k < 900; ++k) {
        double activation = substep_activation(&f, k, shorter);
        double t = (double)k * H;
        double expected = k >= 600 && k < 610 ? 0.9 : t / 2.0;
        cr_expect(fabs(activation - expected) <= 1e-12, "Biceps Short at substep %ld: %.17g, expected %.17g", k,
                  activation, expected);
        double other = mu_model_muscle_readout(f.model, longer).activation;
        double sine = k < 600 ? 0.5 + 0.2 * sin(2.0 * RB_PI * t) : 0.1;
        cr_expect(fabs(other - sine) <= 1e-12, "Biceps Long at substep %ld: %.17g, expected %.17g", k, other, sine);
    }
    close_fixture(&f);
}

/* A file of steps on frame boundaries (the example of the quick start)
 * steps whole frames, as the model's API alone does: the run is the same
 * to the last bit as one that sets the activations by hand. */
Test(controls, a_file_of_steps_runs_as_the_api_does_by_hand)
{
    fixture f = {.desc = load("arm")};
    mu_model_options options = mu_default_model_options();
    options.weight_index = 1; /* 1 kg */
    cr_assert_eq(f.desc->weight.masses[1], 1.0);
    cr_assert(controls_init(&f.schedule, f.desc, 0));
    char error[1024];
    cr_assert(control_file_read(SINEW_SOURCE_DIR "/models/controls/biceps_pulse.txt", &f.schedule, error, sizeof error),
              "%s", error);
    mu_model *by_hand = NULL;
    cr_assert_eq(mu_model_create(f.desc, &options, &f.model), RB_OK);
    cr_assert_eq(mu_model_create(f.desc, &options, &by_hand), RB_OK);
    for (long frame = 0; frame < 300; ++frame) {
        if (frame == 120 || frame == 210) {
            mu_model_set_activation(by_hand, "Biceps Short + Biceps Long", frame == 120 ? 0.3 : 0.0);
        }
        cr_assert_eq(mu_model_step(by_hand), RB_OK);
        cr_assert_eq(controls_step_frame(&f.schedule, f.model, frame), RB_OK);
        for (int h = 0; h < mu_model_hinge_count(by_hand); ++h) {
            double scheduled = mu_model_hinge_angle(f.model, h), set = mu_model_hinge_angle(by_hand, h);
            cr_expect(scheduled == set || (isnan(scheduled) && isnan(set)), "hinge %d, frame %ld: %.17g, by hand %.17g",
                      h, frame, scheduled, set);
        }
    }
    cr_expect_eq(controls_pending(&f.schedule), 0);
    mu_model_destroy(by_hand);
    close_fixture(&f);
}

/* Every example of models/controls/ reads for the model it is written for. */
Test(controls, the_example_files_read)
{
    static const struct {
        const char *file, *model;
    } examples[] = {
        {"biceps_pulse.txt", "arm"},
        {"biceps_shapes.txt", "arm"},
        {"worm_recruit.txt", "worm"},
    };
    for (size_t e = 0; e < sizeof examples / sizeof examples[0]; ++e) {
        mu_model_desc *desc = load(examples[e].model);
        controls schedule;
        cr_assert(controls_init(&schedule, desc, 0));
        char path[512], error[1024];
        snprintf(path, sizeof path, "%s/models/controls/%s", SINEW_SOURCE_DIR, examples[e].file);
        cr_expect(control_file_read(path, &schedule, error, sizeof error), "%s", error);
        cr_expect_gt(schedule.event_count, 0, "%s", path);
        controls_free(&schedule);
        mu_model_desc_destroy(desc);
    }
}

/* ---------------------------------------------------------- bad lines */

/* Reads `text` for `model` (variant 0) and expects it refused with
 * "controls.txt:LINE: " and each of the `parts` in the message. */
static void expect_refused(const char *model, const char *text, int line, const char *const *parts, int count)
{
    mu_model_desc *desc = load(model);
    controls schedule;
    cr_assert(controls_init(&schedule, desc, 0));
    char error[2048], prefix[64];
    bool ok = control_text_read("controls.txt", text, &schedule, error, sizeof error);
    cr_expect(!ok, "accepted: %s", text);
    snprintf(prefix, sizeof prefix, "controls.txt:%d: ", line);
    cr_expect(!ok && strncmp(error, prefix, strlen(prefix)) == 0, "expected \"%s...\", got \"%s\"", prefix, error);
    for (int p = 0; p < count && !ok; ++p) {
        cr_expect(strstr(error, parts[p]) != NULL, "expected \"%s\" in \"%s\"", parts[p], error);
    }
    controls_free(&schedule);
    mu_model_desc_destroy(desc);
}

#define REFUSED(model, text, line, ...)                                                                                \
    do {                                                                                                               \
        static const char *const parts[] = {__VA_ARGS__};                                                              \
        expect_refused(model, text, line, parts, (int)(sizeof parts / sizeof parts[0]));                               \
    } while (0)

Test(controls, a_ramp_with_a_negative_duration_is_refused_at_its_line)
{
    REFUSED("arm", "0 activation \"Biceps Short\" 0.1\n0.5 ramp \"Biceps Short\" 0 0.8 -1\n", 2,
            "the ramp's DURATION must be more than 0 s", "got -1");
}

Test(controls, unknown_names_are_refused_with_the_names_there_are)
{
    REFUSED("arm", "# comment\n0 ramp Bicep 0 1 1\n", 2, "no muscle or group named \"Bicep\"", "\"Biceps Short\"",
            "\"Biceps Short + Biceps Long\"", "torque muscles (recruit): none");
    REFUSED("worm", "0 recruit Torque 5\n", 1, "no torque muscle named \"Torque\"",
            "torque muscles (recruit): \"Torque Muscle\"");
    REFUSED("worm", "0 activation \"Torque Muscle\" 0.5\n", 1,
            "\"Torque Muscle\" is a torque muscle, driven by recruitment (a recruit line, or --recruit NAME=NEURONS), "
            "not activation");
    REFUSED("arm", "0 recruit \"Biceps Short\" 5\n", 1,
            "recruit drives a torque muscle, and \"Biceps Short\" is a muscle or group");
}

Test(controls, values_out_of_range_are_refused)
{
    REFUSED("arm", "0 ramp \"Biceps Short\" 0 1.5 1\n", 1, "the ramp's TO must be an activation from 0 to 1, got 1.5");
    REFUSED("arm", "0 sine \"Biceps Short\" 0.5 0.6 1 1\n", 1,
            "the sine's MEAN - AMPLITUDE must be an activation from 0 to 1, got -0.1");
    REFUSED("arm", "0 sine \"Biceps Short\" 0.5 -0.1 1 1\n", 1, "the sine's AMPLITUDE must be 0 or more");
    REFUSED("arm", "0 tension pulses \"Biceps Short\" -5 10 0.01 1\n", 1,
            "the pulses' LEVEL must be a tension from 0 to 1e+09 N, got -5");
    REFUSED("worm", "0 recruit \"Torque Muscle\" 201\n", 1,
            "the neurons recruited must be a whole number of neurons from 0 to 200", "got 201");
    REFUSED("worm", "0 recruit ramp \"Torque Muscle\" 2.5 10 1\n", 1, "the ramp's FROM must be a whole number");
    REFUSED("arm", "1 activation \"Biceps Short\" 0.5\n0.5 ramp \"Biceps Short\" 0 1 1\n", 2,
            "before the previous control's 1 s");
}

Test(controls, frequencies_and_widths_the_substeps_cannot_hold_are_refused)
{
    REFUSED("arm", "0 pulses \"Biceps Short\" 1 0 0.01 1\n", 1, "the pulses' FREQUENCY must be more than 0 Hz");
    REFUSED("arm", "0 pulses \"Biceps Short\" 1 10 0.1 1\n", 1,
            "the pulses' WIDTH must be more than 0 s and less than the period");
    REFUSED("arm", "0 pulses \"Biceps Short\" 1 10 0.0005 1\n", 1, "less than half a substep");
    REFUSED("arm", "0 pulses \"Biceps Short\" 1 300 0.003 1\n", 1, "leave no substep between two pulses");
    REFUSED("arm", "0 sine \"Biceps Short\" 0.5 0.1 400 1\n", 1, "above 300 Hz", "alias");
}

Test(controls, malformed_lines_say_what_was_expected)
{
    REFUSED("arm", "0.5 ramp \"Biceps Short\" 0 0,8 1\n", 1,
            "expected the ramp's TO (an activation from 0 to 1) after FROM, got \"0,8\"");
    REFUSED("arm", "0.5 ramp \"Biceps Short\" 0 0.8\n", 1,
            "a ramp reads TIME [QUANTITY] ramp NAME FROM TO DURATION: expected DURATION (a time in s) after TO");
    REFUSED("arm", "0.5 ramp \"Biceps Short\" 0 0.8 1 2\n", 1, "unexpected \"2\" after the ramp's DURATION");
    REFUSED("arm", "0.5 tension sine \"Biceps Short\" 10 5 x 1\n", 1,
            "expected the sine's FREQUENCY (a frequency in Hz) after AMPLITUDE, got \"x\"");
    REFUSED("arm", "0.5 rmp \"Biceps Short\" 0 0.8 1\n", 1,
            "expected activation, tension, recruit, pulse, step, ramp, sine or pulses after the time, got \"rmp\"");
    REFUSED("arm", "0.5 ramp Biceps Short 0 0.8 1\n", 1, "got \"Short\"", "in double quotes");
    REFUSED("worm", "0 recruit ramp\n", 1, "expected a torque muscle name after \"ramp\"");
}

/* --------------------------------------------------------- the program */

/* Runs `sinew ARGS`; returns its status, stdout and stderr in `output`. */
static int run_sinew(const char *args, char *output, size_t size)
{
    return run_sinew_capture(NULL, args, SINEW_STDOUT_AND_STDERR, output, size);
}

/* `sinew run --control`: a ramp reaches the CSV (each row, taken at the
 * end of a frame, shows the value of the frame's last substep, t − 1/600
 * s), and a bad line stops the run before it starts, named by file and line. */
Test(controls, sinew_run_takes_shapes_and_names_a_bad_line)
{
    char dir[] = "/tmp/sinew-controls-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char path[600], args[1400], output[8192];
    snprintf(path, sizeof path, "%s/ramp.txt", dir);
    FILE *file = fopen(path, "w");
    cr_assert_not_null(file);
    fputs("0.5 ramp \"Biceps Short\" 0 0.8 1.0\n", file);
    fclose(file);
    snprintf(args, sizeof args, "run arm --duration 2 --control '%s' --out '%s'", path, dir);
    cr_assert_eq(run_sinew(args, output, sizeof output), 0, "%s", output);

    char csv[700], line[16384];
    snprintf(csv, sizeof csv, "%s/arm.csv", dir);
    file = fopen(csv, "r");
    cr_assert_not_null(file);
    cr_assert_not_null(fgets(line, sizeof line, file));
    int column = 0;
    for (char *field = strtok(line, ",\n"); field != NULL && strcmp(field, "Biceps Short.activation") != 0;
         field = strtok(NULL, ",\n")) {
        ++column;
    }
    int rows = 0;
    while (fgets(line, sizeof line, file) != NULL) {
        double time = strtod(line, NULL);
        char *field = line;
        for (int c = 0; c < column; ++c) {
            field = strchr(field, ',') + 1;
        }
        double t = time - H;
        double closed = t < 0.5 ? 0.0 : t < 1.5 ? 0.8 * (t - 0.5) : 0.8;
        cr_expect(fabs(strtod(field, NULL) - closed) <= 1e-9, "row at %g s: %s, expected %.10g", time, field, closed);
        ++rows;
    }
    fclose(file);
    cr_expect_eq(rows, 120);

    file = fopen(path, "w");
    cr_assert_not_null(file);
    fputs("0 activation \"Biceps Short\" 0.1\n0.5 ramp \"Biceps Short\" 0 0.8 -1\n", file);
    fclose(file);
    cr_expect_eq(run_sinew(args, output, sizeof output), 1, "%s", output);
    char expected[800];
    snprintf(expected, sizeof expected, "sinew: %s:2: the ramp's DURATION must be more than 0 s", path);
    cr_expect(strstr(output, expected) != NULL, "expected \"%s\" in \"%s\"", expected, output);
    remove(path);
    remove(csv);
    strcat(csv, "-metadata.json");
    remove(csv);
    rmdir(dir);
}
