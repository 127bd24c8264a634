/* SPDX-License-Identifier: MIT */
/* A muscle's maximal force from its architecture in the model file, as
 * Castanyer's report (§2.2) derives it: Fmax = σ·PCSA, PCSA = V/l_f with
 * l_f the optimal fibre length (given, n sarcomeres × 2 µm, or a measured
 * fibre normalized to 2 µm sarcomeres), or PCSA = ACSA/cos β. Each force
 * is checked against the closed form computed here, the built muscle's
 * force against the description's, and two published muscles against the
 * PCSA their authors give; every bad input is refused with its JSON path.
 *
 * The published muscles: Ward, Eng, Smallwood and Lieber, "Are current
 * measurements of lower extremity muscle architecture accurate?" (Clin
 * Orthop Relat Res 467, 2009), table 1: soleus 275.8 g, fibre length
 * 4.40 cm, pennation 28.3°, PCSA 51.8 cm²; medial gastrocnemius 113.5 g,
 * 5.10 cm, 9.9°, 21.1 cm². Volumes from their muscle density, 1.056 g/cm³
 * (Mendez and Keys 1960). Their PCSA is V·cos θ/l_f, the fibres' cross-
 * section projected on the tendon: sinew's Fmax is the fibres' force, and
 * the pennation model passes Fmax·cos θ to the path at the optimal length.
 * Their PCSA is the mean of the specimens', not that of the mean inputs,
 * so the two agree within 2.5 %, not exactly. The specific tension is the
 * report's table's, 0.3 MPa.
 */
#define _DEFAULT_SOURCE /* mkstemps, popen */

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/model.h"
#include "mu/model_desc.h"
#include "mu/muscle.h"
#include "test_support.h"

#define SIGMA 3e5           /* N/m², the report's table */
#define DENSITY 1056.0      /* kg/m³, Mendez and Keys 1960 */
#define SARCOMERE 2e-6      /* m, the report's optimal sarcomere length */
#define DEG (RB_PI / 180.0) /* rad per degree */

/* The sample model (a bar on a nail, a block hanging from it by one
 * muscle) with the muscle's force keys replaced by `keys`, written to a
 * fresh file whose path goes to `path`. The muscle's object starts on
 * line 9. */
static void write_model(const char *keys, char *path, size_t size)
{
    snprintf(path, size, "/tmp/sinew_architecture_XXXXXX.json");
    int fd = mkstemps(path, 5);
    cr_assert(fd >= 0, "mkstemps failed");
    FILE *f = fdopen(fd, "w");
    cr_assert_not_null(f);
    fprintf(
        f,
        "{\n"
        "  \"name\": \"architecture\",\n"
        "  \"nails\": [{ \"name\": \"Nail\", \"position\": [0, 0] }],\n"
        "  \"bones\": [{ \"name\": \"Bar\", \"centre\": [0, -0.1], \"size\": [0.05, 0.2] },\n"
        "            { \"name\": \"Block\", \"centre\": [0.2, -0.6], \"size\": [0.05, 0.05] }],\n"
        "  \"hinges\": [{ \"name\": \"Hinge\", \"body_a\": \"Nail\", \"anchor_a\": [0, 0], \"body_b\": \"Bar\",\n"
        "               \"anchor_b\": [0, 0.1], \"radius\": 0.025 }],\n"
        "  \"muscles\": [\n"
        "    { \"name\": \"Muscle\", \"rest_length\": 0.3, %s,\n"
        "      \"path\": [{ \"body\": \"Bar\", \"point\": [0, -0.1] }, { \"body\": \"Block\", \"point\": [0, 0] }] }\n"
        "  ]\n"
        "}\n",
        keys);
    cr_assert_eq(fclose(f), 0);
}

/* Loads a model whose muscle has `keys`; returns its description (NULL
 * when refused, the message then in rb_last_error()). */
static mu_model_desc *load_with(const char *keys)
{
    char path[64];
    write_model(keys, path, sizeof path);
    mu_model_desc *desc = NULL;
    rb_status status = mu_model_desc_load(path, &desc);
    remove(path);
    cr_assert((status == RB_OK) == (desc != NULL));
    return desc;
}

/* The muscle's force as loaded, and as the built muscle has it. */
static double loaded_force(const char *keys)
{
    mu_model_desc *desc = load_with(keys);
    cr_assert_not_null(desc, "refused: %s", rb_last_error());
    const double force = desc->muscles[0].max_force;
    mu_model_options options = mu_default_model_options();
    mu_model *model = NULL;
    cr_assert_eq(mu_model_create(desc, &options, &model), RB_OK, "%s", rb_last_error());
    expect_near(mu_muscle_max_force(mu_model_built_muscle(model, 0)), force, 1e-9 * force,
                "the built muscle's maximal force");
    mu_model_destroy(model);
    mu_model_desc_destroy(desc);
    return force;
}

Test(model_architecture, the_soleus_from_its_volume_and_fibre_length)
{
    const double volume = 0.2758 / DENSITY, fibre = 0.0440, pennation = 28.3;
    char keys[256];
    snprintf(keys, sizeof keys,
             "\"specific_tension\": %.17g, \"pennation_angle\": %.17g, "
             "\"architecture\": { \"volume\": %.17g, \"fibre_length\": %.17g }",
             SIGMA, pennation, volume, fibre);
    const double force = loaded_force(keys);
    expect_near(force, SIGMA * volume / fibre, 1e-9, "Fmax = σ·V/l_f");
    const double published = SIGMA * 51.8e-4; /* σ times Ward et al.'s PCSA */
    const double on_the_path = force * cos(pennation * DEG);
    cr_expect(fabs(on_the_path / published - 1.0) < 0.025, "Fmax·cos θ %g N against σ·PCSA %g N", on_the_path,
              published);
}

Test(model_architecture, the_medial_gastrocnemius_from_its_volume_and_sarcomere_count)
{
    /* 5.10 cm of optimal fibre is 25,500 sarcomeres of 2 µm. */
    const double volume = 0.1135 / DENSITY, sarcomeres = 25500.0, pennation = 9.9;
    char keys[256];
    snprintf(keys, sizeof keys,
             "\"specific_tension\": %.17g, \"pennation_angle\": %.17g, "
             "\"architecture\": { \"volume\": %.17g, \"sarcomeres\": %.17g }",
             SIGMA, pennation, volume, sarcomeres);
    const double force = loaded_force(keys);
    expect_near(force, SIGMA * volume / (sarcomeres * SARCOMERE), 1e-9, "Fmax = σ·V/(n·2 µm)");
    const double published = SIGMA * 21.1e-4;
    const double on_the_path = force * cos(pennation * DEG);
    cr_expect(fabs(on_the_path / published - 1.0) < 0.025, "Fmax·cos θ %g N against σ·PCSA %g N", on_the_path,
              published);
}

Test(model_architecture, a_measured_fibre_is_normalized_to_two_micrometre_sarcomeres)
{
    /* 8.2 cm of fibre measured with 2.4 µm sarcomeres is 6.83 cm at 2 µm. */
    const double volume = 7.585e-5, measured = 0.082, sarcomere = 2.4e-6;
    char keys[256];
    snprintf(keys, sizeof keys,
             "\"specific_tension\": %.17g, "
             "\"architecture\": { \"volume\": %.17g, \"fibre_length\": %.17g, \"sarcomere_length\": %.17g }",
             SIGMA, volume, measured, sarcomere);
    expect_near(loaded_force(keys), SIGMA * volume / (measured * SARCOMERE / sarcomere), 1e-9, "Fmax = σ·V/(l·2 µm/s)");
}

Test(model_architecture, without_a_fibre_length_the_rest_length_is_the_fibres)
{
    expect_near(loaded_force("\"architecture\": { \"volume\": 1e-4 }"), 1.5e6 * 1e-4 / 0.3, 1e-9,
                "Fmax = σ·V/rest_length at the default σ");
}

Test(model_architecture, the_anatomical_cross_section_over_the_cosine_of_pennation)
{
    char keys[256];
    snprintf(keys, sizeof keys,
             "\"specific_tension\": %.17g, \"pennation_angle\": 25, "
             "\"architecture\": { \"anatomical_cross_section\": 2e-3 }",
             SIGMA);
    expect_near(loaded_force(keys), SIGMA * 2e-3 / cos(25.0 * DEG), 1e-9, "Fmax = σ·ACSA/cos β");
}

Test(model_architecture, sinew_check_prints_each_derived_force_and_its_inputs)
{
    const double volume = 0.2758 / DENSITY, fibre = 0.0440;
    char keys[256];
    snprintf(keys, sizeof keys,
             "\"specific_tension\": %.17g, \"architecture\": { \"volume\": %.17g, \"fibre_length\": %.17g }", SIGMA,
             volume, fibre);
    char path[64];
    write_model(keys, path, sizeof path);
    char command[256];
    snprintf(command, sizeof command, "%s check %s 2>&1", SINEW_TOOL, path);
    FILE *p = popen(command, "r");
    cr_assert_not_null(p);
    char output[4096];
    output[fread(output, 1, sizeof output - 1, p)] = '\0';
    cr_expect_eq(pclose(p), 0, "sinew check failed: %s", output);
    remove(path);
    char expected[256];
    snprintf(expected, sizeof expected, "muscle \"Muscle\": Fmax %g N = specific tension %g N/m² × PCSA %g m²",
             SIGMA * volume / fibre, SIGMA, volume / fibre);
    cr_expect(strstr(output, expected) != NULL, "no \"%s\" in: %s", expected, output);
    snprintf(expected, sizeof expected, "PCSA = volume %g m³ / fibre length %g m", volume, fibre);
    cr_expect(strstr(output, expected) != NULL, "no \"%s\" in: %s", expected, output);
}

/* `keys` are refused with a message naming the JSON `where` and saying
 * `problem`, after the file and its line. */
static void expect_refused(const char *keys, const char *where, const char *problem)
{
    cr_expect_null(load_with(keys), "accepted: %s", keys);
    const char *message = rb_last_error();
    cr_expect(strstr(message, ".json:9:") != NULL || strstr(message, ".json:10:") != NULL, "the file and line: %s",
              message);
    char path[128];
    snprintf(path, sizeof path, ": %s: ", where);
    cr_expect(strstr(message, path) != NULL, "names %s: %s", where, message);
    cr_expect(strstr(message, problem) != NULL, "says \"%s\": %s", problem, message);
}

Test(model_architecture, bad_architectures_are_refused_with_their_json_path)
{
    expect_refused("\"architecture\": { \"volume\": -1e-4 }", "muscles[0].architecture.volume", "out of range");
    expect_refused("\"architecture\": { \"volume\": 1e-4, \"fibre_length\": 0 }",
                   "muscles[0].architecture.fibre_length", "out of range");
    expect_refused("\"max_force\": 100, \"architecture\": { \"volume\": 1e-4 }", "muscles[0].architecture",
                   "given with max_force, expected one of max_force, rest_width or architecture");
    expect_refused("\"rest_width\": 0.05, \"architecture\": { \"volume\": 1e-4 }", "muscles[0].architecture",
                   "given with rest_width");
    expect_refused("\"symmetry\": 0.5", "muscles[0]",
                   "missing key \"rest_width\", expected the belly's width at rest in m, max_force or architecture");
    expect_refused("\"architecture\": {}", "muscles[0].architecture", "missing key \"volume\"");
    expect_refused("\"architecture\": { \"volume\": 1e-4, \"anatomical_cross_section\": 1e-3 }",
                   "muscles[0].architecture.anatomical_cross_section", "given with volume");
    expect_refused("\"architecture\": { \"anatomical_cross_section\": 1e-3, \"sarcomeres\": 1e4 }",
                   "muscles[0].architecture.sarcomeres", "given with anatomical_cross_section");
    expect_refused("\"architecture\": { \"volume\": 1e-4, \"sarcomeres\": 1e4, \"fibre_length\": 0.02 }",
                   "muscles[0].architecture.fibre_length", "given with sarcomeres");
    expect_refused("\"architecture\": { \"volume\": 1e-4, \"sarcomere_length\": 2.5e-6 }",
                   "muscles[0].architecture.sarcomere_length", "given without fibre_length");
    expect_refused("\"architecture\": { \"volume\": 1e-4, \"fibre\": 0.02 }", "muscles[0].architecture.fibre",
                   "\"fibre\"");
    expect_refused("\"pennation_angle\": 90, \"architecture\": { \"anatomical_cross_section\": 1e-3 }",
                   "muscles[0].pennation_angle", "out of range");
    expect_refused("\"architecture\": { \"volume\": 1e-9, \"fibre_length\": 10 }", "muscles[0].architecture",
                   "the maximal force specific_tension·PCSA in N is");
    expect_refused("\"architecture\": { \"volume\": 1e-4, \"fibre_length\": 0.002, \"sarcomere_length\": 5e-6 }",
                   "muscles[0].architecture", "the optimal fibre length PCSA divides the volume by");
}
