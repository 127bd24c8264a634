/* SPDX-License-Identifier: MIT */
/* `sinew models` lists the built-in muscle models; `sinew check FILE`
 * validates a model file. Both describe a model by the same counts.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/model_source.h"
#include "cli/user_error.h"
#include "commands.h"
#include "mu/model.h"

static const cli_command models_command = {
    .name = "sinew models",
    .operands = "",
    .operand = "",
    .about = "Lists the built-in models (models/*.json) with their variants, weight choices,\n"
             "muscles, groups and torque muscles: the names `sinew run` takes.\n",
};

static const cli_command check_command = {
    .name = "sinew check",
    .operands = "FILE",
    .max_operands = 1,
    .operand = "model file",
    .about = "Validates the model file FILE (format: docs/model-format.md) and builds it in each\n"
             "of its variants. Prints a one-line summary and each muscle's maximal force with\n"
             "what gave it, and exits 0, or prints what is wrong and where (file:line:column,\n"
             "the JSON path, what was expected) and exits 1.\n",
};

static const char *plural(int count) { return count == 1 ? "" : "s"; }

/* The counts of a description, as one phrase. */
static void print_counts(const mu_model_desc *desc)
{
    printf("%d bodies (%d nail%s, %d bone%s), %d hinge%s, %d glue%s, %d muscle%s, %d group%s",
           desc->nail_count + desc->bone_count, desc->nail_count, plural(desc->nail_count), desc->bone_count,
           plural(desc->bone_count), desc->hinge_count, plural(desc->hinge_count), desc->glue_count,
           plural(desc->glue_count), desc->muscle_count, plural(desc->muscle_count), desc->group_count,
           plural(desc->group_count));
    if (desc->torque_muscle_count > 0) {
        printf(", %d torque muscle%s", desc->torque_muscle_count, plural(desc->torque_muscle_count));
    }
}

/* "200 neurons from the image worm-pool.png, peak 0.01 N·m". */
static void print_torque_muscle(const mu_model_torque_muscle *muscle)
{
    printf("\"%s\" (%d neurons ", muscle->name, muscle->neurons);
    switch (muscle->pool_source) {
    case MU_MODEL_POOL_IMAGE:
        printf("from the image %s", muscle->pool_file);
        break;
    case MU_MODEL_POOL_CSV:
        printf("from the CSV %s", muscle->pool_file);
        break;
    case MU_MODEL_POOL_EXPONENTIAL:
        printf("rising exponentially from %g to %g", muscle->weakest, muscle->strongest);
        break;
    }
    printf(", peak %g N·m; recruit with --recruit \"%s=N\")", muscle->peak_torque, muscle->name);
}

static void print_builtin(const char *name, const mu_model_desc *desc)
{
    printf("%s: ", name);
    print_counts(desc);
    printf("\n  variants:");
    for (int v = 0; v < desc->variant_count; ++v) {
        const mu_model_variant *variant = &desc->variants[v];
        printf("%s%d \"%s\" (%d muscle%s)\n", v == 0 ? "  " : "             ", v, variant->name, variant->muscle_count,
               plural(variant->muscle_count));
    }
    printf("  weights:   ");
    if (!desc->has_weight) {
        printf("none\n");
    }
    for (int w = 0; desc->has_weight && w < desc->weight.mass_count; ++w) {
        printf("%g%s", desc->weight.masses[w], w + 1 < desc->weight.mass_count ? ", " : " kg\n");
    }
    printf("  muscles:   ");
    for (int m = 0; m < desc->muscle_count; ++m) {
        printf("%s\"%s\"", m == 0 ? "" : ", ", desc->muscles[m].name);
    }
    printf("%s\n  groups:    ", desc->muscle_count == 0 ? "none" : "");
    for (int g = 0; g < desc->group_count; ++g) {
        printf("%s\"%s\"", g == 0 ? "" : ", ", desc->groups[g].name);
    }
    printf("%s\n", desc->group_count == 0 ? "none" : "");
    if (desc->torque_muscle_count > 0) {
        printf("  torque muscles: ");
        for (int t = 0; t < desc->torque_muscle_count; ++t) {
            printf("%s", t == 0 ? "" : ",\n                  ");
            print_torque_muscle(&desc->torque_muscles[t]);
        }
        printf("\n");
    }
}

int cmd_models(int argc, char **argv)
{
    const char *operand;
    int id = cli_parse_operand(&models_command, argc, argv, &operand);
    if (id != CLI_END) {
        return id == CLI_HELP ? EXIT_SUCCESS : EXIT_USAGE;
    }
    for (int k = 0; k < mu_builtin_model_count(); ++k) {
        mu_model_desc *desc;
        int code = model_source_load(mu_builtin_model_name(k), &desc);
        if (code != 0) {
            return code;
        }
        printf("%s", k == 0 ? "" : "\n");
        print_builtin(mu_builtin_model_name(k), desc);
        mu_model_desc_destroy(desc);
    }
    printf("\nRun one with `sinew run MODEL [--variant NAME|N] [--weight KG]` (see `sinew run --help`).\n");
    return EXIT_SUCCESS;
}

/* Where a muscle's architecture took its fibre length from. */
static void print_fibre_length(const mu_model_architecture *architecture)
{
    printf("fibre length %g m", architecture->fibre_length);
    if (architecture->sarcomeres > 0.0) {
        printf(" = %g sarcomeres × 2 µm", architecture->sarcomeres);
    } else if (architecture->sarcomere_length > 0.0) {
        printf(" = %g m measured × 2 µm / %g µm sarcomeres", architecture->measured_fibre_length,
               architecture->sarcomere_length * 1e6);
    } else if (architecture->measured_fibre_length == 0.0) {
        printf(", the rest length");
    }
}

/* Each muscle's maximal force and what gave it: max_force, the belly's
 * width, or its architecture (docs/model-format.md). */
static void print_forces(const mu_model_desc *desc)
{
    for (int m = 0; m < desc->muscle_count; ++m) {
        const mu_model_muscle *muscle = &desc->muscles[m];
        const mu_model_architecture *architecture = &muscle->architecture;
        printf("  muscle \"%s\": Fmax ", muscle->name);
        if (architecture->given) {
            printf("%g N = specific tension %g N/m² × PCSA %g m²", muscle->max_force, muscle->specific_tension,
                   architecture->pcsa);
            if (architecture->volume > 0.0) {
                printf("; PCSA = volume %g m³ / ", architecture->volume);
                print_fibre_length(architecture);
            } else {
                printf("; PCSA = anatomical cross-section %g m² / cos(pennation %g°)",
                       architecture->anatomical_cross_section, muscle->pennation_angle);
            }
        } else if (muscle->rest_width > 0.0 && muscle->max_force == 0.0) {
            printf("%g N = specific tension %g N/m² × π·(rest_width %g m)²/4",
                   RB_PI * muscle->rest_width * muscle->rest_width / 4.0 * muscle->specific_tension,
                   muscle->specific_tension, muscle->rest_width);
        } else {
            printf("%g N, as given (max_force)", muscle->max_force);
        }
        printf("\n");
    }
}

/* Prints the warning lines of `warnings` not in *printed yet, and adds
 * them to it: variants share muscles, and so their warnings. Returns
 * false when out of memory. */
static bool print_new_warnings(const char *path, const char *warnings, char **printed, size_t *printed_length)
{
    while (*warnings != '\0') {
        size_t length = strcspn(warnings, "\n");
        bool seen = false;
        for (const char *line = *printed; !seen && line < *printed + *printed_length; line += strlen(line) + 1) {
            seen = strlen(line) == length && strncmp(line, warnings, length) == 0;
        }
        if (!seen) {
            fprintf(stderr, "sinew: warning: %s: %.*s\n", path, (int)length, warnings);
            char *grown = realloc(*printed, *printed_length + length + 1);
            if (grown == NULL) {
                return false;
            }
            memcpy(grown + *printed_length, warnings, length);
            grown[*printed_length + length] = '\0';
            *printed = grown;
            *printed_length += length + 1;
        }
        warnings += length + (warnings[length] == '\n');
    }
    return true;
}

/* Builds the description in each variant, at the full level and the
 * first weight choice: a file can be valid and still not build (a path
 * the engine rejects). Warnings go to stderr, each once, and do not fail
 * the check. */
static int build_every_variant(const char *path, const mu_model_desc *desc)
{
    char *printed = NULL; /* the warnings printed, each followed by a NUL */
    size_t printed_length = 0;
    int code = 0;
    for (int v = 0; code == 0 && v < desc->variant_count; ++v) {
        mu_model_options options = mu_default_model_options();
        options.variant = v;
        mu_model *model;
        if (mu_model_create(desc, &options, &model) != RB_OK) {
            /* "FILE: muscle \"M\" (muscles[0]) in variant \"V\" cannot be built: ..." */
            fprintf(stderr, "sinew: %s\n", user_error());
            code = EXIT_FAILURE;
            break;
        }
        if (!print_new_warnings(path, mu_model_warnings(model), &printed, &printed_length)) {
            fputs("sinew: out of memory\n", stderr);
            code = EXIT_FAILURE;
        }
        mu_model_destroy(model);
    }
    free(printed);
    return code;
}

int cmd_check(int argc, char **argv)
{
    const char *path;
    int id = cli_parse_operand(&check_command, argc, argv, &path);
    if (id != CLI_END) {
        return id == CLI_HELP ? EXIT_SUCCESS : EXIT_USAGE;
    }
    if (path == NULL) {
        return cli_usage_error(&check_command, "missing the model file");
    }
    mu_model_desc *desc;
    if (mu_model_desc_load(path, &desc) != RB_OK) {
        fprintf(stderr, "sinew: %s\n", user_error());
        return EXIT_FAILURE;
    }
    int code = build_every_variant(path, desc);
    if (code == 0) {
        printf("%s: valid model \"%s\": ", path, desc->name);
        print_counts(desc);
        printf(", %d variant%s, %d weight choice%s\n", desc->variant_count, plural(desc->variant_count),
               desc->has_weight ? desc->weight.mass_count : 0, plural(desc->has_weight ? desc->weight.mass_count : 0));
        print_forces(desc);
    }
    mu_model_desc_destroy(desc);
    return code;
}
