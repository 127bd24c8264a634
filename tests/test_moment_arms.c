/* SPDX-License-Identifier: MIT */
/* Moment arms (mu/moment_arms.h) against closed forms and a central
 * difference of the path length, and `sinew moment-arms` against its own
 * lengths and its errors. */
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
#include "model_support.h"
#include "mu/moment_arms.h"

#define DEG (RB_PI / 180.0)

static mu_model *build(const mu_model_desc *desc)
{
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    return model;
}

/* A lever on a hinge at the origin; a muscle from (0, D) on the ground to
 * a via point on the lever on the circle of radius R about the pivot, at
 * the angle β = asin(R/D) where the segment from (0, D) is tangent to the
 * circle, then on along the lever. Turning the lever by θ puts the via
 * point at V = R(cos(β+θ), sin(β+θ)); only the first segment crosses the
 * hinge, of length L = √(R² + D² - 2RD·sin(β+θ)), so
 *
 *   r = -dL/dθ = R·D·cos(β+θ)/L,
 *
 * which is R at θ = 0, where the segment is tangent: a pulley of radius R. */
#define R 0.03
#define D 0.10

static mu_model_desc *pulley_model(void)
{
    const double beta = asin(R / D);
    char text[2048];
    snprintf(text, sizeof text,
             "{\"name\": \"pulley\", \"gravity\": [0, 0],"
             " \"nails\": [{\"name\": \"Ground\", \"position\": [0, 0]}],"
             " \"bones\": [{\"name\": \"Lever\", \"centre\": [0.1, 0], \"size\": [0.2, 0.02]}],"
             " \"hinges\": [{\"name\": \"Pivot\", \"body_a\": \"Ground\", \"anchor_a\": [0, 0], \"body_b\": \"Lever\","
             "              \"anchor_b\": [-0.1, 0], \"radius\": 0.01, \"lower\": -80, \"upper\": 80}],"
             " \"muscles\": [{\"name\": \"Cord\", \"rest_length\": 0.1, \"max_force\": 100,"
             "   \"path\": [{\"body\": \"Ground\", \"point\": [0, %.17g]},"
             "              {\"body\": \"Lever\", \"point\": [%.17g, %.17g]},"
             "              {\"body\": \"Lever\", \"point\": [0.05, 0]}]}],"
             " \"groups\": [], \"variants\": [{\"name\": \"all\", \"muscles\": [\"Cord\"]}]}",
             D, R * cos(beta) - 0.1, R * sin(beta));
    return load_model_text(text);
}

Test(moment_arms, a_via_point_on_an_arc_has_the_closed_form_arm)
{
    mu_model_desc *desc = pulley_model();
    mu_model *model = build(desc);
    cr_assert(mu_model_muscle_crosses(model, 0, 0));
    const double arm = mu_model_moment_arm(model, 0, 0);
    cr_expect(fabs(arm - R) <= 1e-12, "tangent: r = %.15g m, expected R = %g m", arm, R);
    const double beta = asin(R / D);
    for (double degrees = -80.0; degrees <= 80.0; degrees += 10.0) {
        cr_assert_eq(mu_model_pose_hinge(model, 0, degrees), RB_OK, "%s", rb_last_error());
        cr_expect(fabs(mu_model_hinge_angle(model, 0) - degrees) < 1e-9, "posed at %g, reads %g", degrees,
                  mu_model_hinge_angle(model, 0));
        const double phi = beta + degrees * DEG;
        const double expected = R * D * cos(phi) / sqrt(R * R + D * D - 2.0 * R * D * sin(phi));
        const double got = mu_model_moment_arm(model, 0, 0);
        cr_expect(fabs(got - expected) <= 1e-12, "at %g deg: r = %.15g m, closed form %.15g m", degrees, got, expected);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* -dL/dθ by a central difference of the cable's length, the hinge posed
 * at θ ± h with the rest held: error h²·L'''/6, about 1e-10 m at h = 1e-4
 * rad for paths of tens of cm. */
static double central_difference(mu_model *model, int muscle, int hinge, double degrees)
{
    const double h = 1e-4 / DEG;
    const rb_cable_id cable = mu_muscle_cable(mu_model_built_muscle(model, muscle));
    cr_assert_eq(mu_model_pose_hinge(model, hinge, degrees + h), RB_OK, "%s", rb_last_error());
    const double above = rb_cable_length(mu_model_world_to_read(model), cable);
    cr_assert_eq(mu_model_pose_hinge(model, hinge, degrees - h), RB_OK, "%s", rb_last_error());
    const double below = rb_cable_length(mu_model_world_to_read(model), cable);
    cr_assert_eq(mu_model_pose_hinge(model, hinge, degrees), RB_OK);
    return -(above - below) / (2.0 * h * DEG);
}

/* Every muscle of the arm about both hinges, via points included: the
 * analytic arm against the difference, at poses across each range. */
Test(moment_arms, the_arms_paths_match_a_central_difference)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    mu_model *model = build(desc);
    for (int hinge = 0; hinge < mu_model_hinge_count(model); ++hinge) {
        const mu_model_hinge *h = &desc->hinges[hinge];
        int crossing = 0;
        for (double degrees = h->lower + 5.0; degrees < h->upper - 5.0; degrees += 20.0) {
            cr_assert_eq(mu_model_pose_hinge(model, hinge, degrees), RB_OK, "%s", rb_last_error());
            for (int m = 0; m < mu_model_muscle_count(model); ++m) {
                const double arm = mu_model_moment_arm(model, m, hinge);
                const double difference = central_difference(model, m, hinge, degrees);
                cr_expect(fabs(arm - difference) <= 1e-8, "%s about %s at %g deg: r = %.12g m, -dL/dθ = %.12g m",
                          mu_model_muscle_name(model, m), h->name, degrees, arm, difference);
                if (!mu_model_muscle_crosses(model, m, hinge)) {
                    cr_expect_eq(arm, 0.0);
                }
            }
        }
        for (int m = 0; m < mu_model_muscle_count(model); ++m) {
            crossing += mu_model_muscle_crosses(model, m, hinge);
        }
        /* Biceps Short, Biceps Long and Triceps Long cross the shoulder; all five the elbow. */
        cr_expect_eq(crossing, strcmp(h->name, "Shoulder") == 0 ? 3 : 5, "%s: %d crossing", h->name, crossing);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The human biceps' elbow moment arm rises from about 2 cm at full
 * extension to a peak of 4-5 cm and falls again towards full flexion
 * (Murray, Delp and Buchanan, "Variation of muscle moment arms with elbow
 * and forearm position", 1995; Pigeon, Yahia and Feldman, "Moment arms and
 * lengths of human upper limb muscles as functions of joint angles", 1996,
 * whose fit peaks near 100° of flexion). The arm's biceps has that shape
 * and size: positive through flexion, one interior peak of a few cm. Its
 * peak lies at 53-56°, not near 100°: the model's insertion on the radius is
 * 3.9 cm in front of the forearm's axis (the radial tuberosity is about
 * 1 cm), and the peak falls where the insertion's arm from the pivot
 * stands square to the muscle's line (docs/loads.md). */
Test(moment_arms, the_arms_biceps_has_the_published_shape)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("arm", &desc), RB_OK);
    mu_model *model = build(desc);
    int elbow = -1;
    for (int h = 0; h < mu_model_hinge_count(model); ++h) {
        elbow = strcmp(mu_model_hinge_name(model, h), "Elbow") == 0 ? h : elbow;
    }
    for (int m = 0; m < 2; ++m) { /* Biceps Short, Biceps Long */
        double peak = -1.0, peak_angle = 0.0;
        double arms[121];
        for (int degrees = 0; degrees <= 120; ++degrees) {
            cr_assert_eq(mu_model_pose_hinge(model, elbow, degrees), RB_OK);
            arms[degrees] = mu_model_moment_arm(model, m, elbow);
            cr_expect_gt(arms[degrees], 0.0, "%s at %d deg: r = %g m", mu_model_muscle_name(model, m), degrees,
                         arms[degrees]);
            if (arms[degrees] > peak) {
                peak = arms[degrees];
                peak_angle = degrees;
            }
        }
        cr_expect(peak >= 0.02 && peak <= 0.07, "%s peaks at %g m", mu_model_muscle_name(model, m), peak);
        cr_expect(peak_angle > 20.0 && peak_angle < 110.0, "%s peaks at %g deg", mu_model_muscle_name(model, m),
                  peak_angle);
        /* One peak: rising before it, falling after. */
        for (int degrees = 1; degrees <= 120; ++degrees) {
            const bool rising = arms[degrees] >= arms[degrees - 1];
            cr_expect_eq(rising, degrees <= peak_angle, "%s at %d deg", mu_model_muscle_name(model, m), degrees);
        }
        cr_expect_lt(arms[0], 0.7 * peak);
        cr_expect_lt(arms[120], 0.7 * peak);
    }
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

Test(moment_arms, bad_arguments_are_refused)
{
    mu_model_desc *desc = pulley_model();
    mu_model *model = build(desc);
    cr_expect(isnan(mu_model_moment_arm(model, 1, 0)));
    cr_expect(strstr(rb_last_error(), "muscle") != NULL, "%s", rb_last_error());
    cr_expect(isnan(mu_model_moment_arm(model, 0, 1)));
    cr_expect(isnan(mu_model_moment_arm(NULL, 0, 0)));
    cr_expect(!mu_model_muscle_crosses(model, 0, -1));
    cr_expect_eq(mu_model_moment_arms(model, 0, NULL), RB_ERR_INVALID_ARGUMENT);
    cr_expect_eq(mu_model_pose_hinge(model, 0, 81.0), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "outside hinge \"Pivot\"'s limits -80 .. 80") != NULL, "%s", rb_last_error());
    cr_expect_eq(mu_model_pose_hinge(model, 0, NAN), RB_ERR_INVALID_ARGUMENT);
    cr_expect(fabs(mu_model_hinge_angle(model, 0)) < 1e-12, "a refused pose moves nothing");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* The leg is a chain between two nails: its hinges cannot turn alone. */
Test(moment_arms, a_hinge_in_a_closed_chain_cannot_be_posed)
{
    mu_model_desc *desc = NULL;
    cr_assert_eq(mu_model_desc_load_builtin("leg", &desc), RB_OK);
    mu_model *model = build(desc);
    cr_expect_eq(mu_model_pose_hinge(model, 1, mu_model_hinge_angle(model, 1) + 1.0), RB_ERR_INVALID_ARGUMENT);
    cr_expect(strstr(rb_last_error(), "closes a loop") != NULL, "%s", rb_last_error());
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
}

/* ---- the command ------------------------------------------------------------------ */

static char dir[] = "/tmp/sinew-moment-arms-XXXXXX";

/* The last run's messages (its stderr). */
static char errors[8192];

static int run_sinew(const char *args)
{
    return run_sinew_capture(dir, args, SINEW_STDERR_ONLY, errors, sizeof errors);
}

static bool exists(const char *name) { return file_exists_in(dir, name); }

static const char *error_text(void) { return errors; }

Test(moment_arms_command, writes_arms_that_match_its_lengths)
{
    cr_assert_not_null(mkdtemp(dir));
    cr_assert_eq(run_sinew("moment-arms arm --hinge Elbow --from 0 --to 140 --step 1"), 0, "%s", error_text());
    cr_assert(exists("arm-moment-arms-Elbow.csv"));
    cr_expect(exists("arm-moment-arms-Elbow.csv-metadata.json"));
    cr_expect(exists("arm-moment-arms-Elbow.png"));
    char path[512];
    snprintf(path, sizeof path, "%s/arm-moment-arms-Elbow.csv", dir);
    csv_table table;
    char error[1024];
    cr_assert(csv_table_read(path, &table, error, sizeof error), "%s", error);
    cr_assert_eq(table.row_count, 141);
    const int arm = csv_table_find(&table, "Biceps Long.moment_arm_m");
    const int length = csv_table_find(&table, "Biceps Long.length_m");
    cr_assert(arm >= 0 && length >= 0);
    /* -ΔL/Δθ over ±1°: error (1°)²·L'''/6, below 1e-5 m here. */
    for (long r = 1; r + 1 < table.row_count; ++r) {
        const double difference =
            -(table.columns[length].values[r + 1] - table.columns[length].values[r - 1]) / (2.0 * DEG);
        cr_expect(fabs(table.columns[arm].values[r] - difference) < 1e-5, "row %ld: r %g, -dL/dθ %g", r,
                  table.columns[arm].values[r], difference);
    }
    csv_table_free(&table);
    char command[600];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}

static void expect_refused(const char *args, const char *message)
{
    cr_expect_neq(run_sinew(args), 0, "%s succeeded", args);
    cr_expect(strstr(error_text(), message) != NULL, "%s: stderr \"%s\", expected \"%s\"", args, error_text(), message);
}

Test(moment_arms_command, refuses_bad_input_and_writes_nothing)
{
    cr_assert_not_null(mkdtemp(dir));
    expect_refused("moment-arms arm --hinge Knee", "its hinges are \"Shoulder\", \"Elbow\"");
    expect_refused("moment-arms arm --hinge Elbow --from -20", "outside hinge \"Elbow\"'s range -10 .. 150");
    expect_refused("moment-arms arm --hinge Elbow --to 151", "outside hinge \"Elbow\"'s range -10 .. 150");
    expect_refused("moment-arms arm --hinge Elbow --step 0", "--step 0: expected an angle step > 0");
    expect_refused("moment-arms arm --hinge Elbow --step -1", "expected an angle step > 0");
    expect_refused("moment-arms arm --hinge Elbow --muscle Brachialis", "the muscles are \"Biceps Short\"");
    expect_refused("moment-arms leg --hinge Knee", "closes a loop");
    expect_refused("moment-arms arm", "missing --hinge");
    cr_expect(!exists("arm-moment-arms-Elbow.csv") && !exists("arm-moment-arms-Elbow.png") &&
              !exists("leg-moment-arms-Knee.csv"));
    char command[600];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    cr_expect_eq(system(command), 0);
}
