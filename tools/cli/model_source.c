/* SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/model_source.h"
#include "cli/option_value.h"
#include "cli/options.h"
#include "cli/user_error.h"

static bool ends_with(const char *text, const char *suffix)
{
    size_t length = strlen(text);
    size_t suffix_length = strlen(suffix);
    return length >= suffix_length && strcmp(text + length - suffix_length, suffix) == 0;
}

bool model_source_is_builtin(const char *argument)
{
    for (int k = 0; k < mu_builtin_model_count(); ++k) {
        if (strcmp(argument, mu_builtin_model_name(k)) == 0) {
            return true;
        }
    }
    return false;
}

model_source_result model_source_open(const char *argument, mu_model_desc **out, char *error, size_t error_size)
{
    *out = NULL;
    rb_status status;
    if (model_source_is_builtin(argument)) {
        status = mu_model_desc_load_builtin(argument, out);
    } else if (strchr(argument, '/') != NULL || ends_with(argument, ".json")) {
        status = mu_model_desc_load(argument, out);
    } else {
        /* A bare word that is not a built-in is more likely a misspelt
         * name than a file in the current directory; ./NAME reads one. */
        int written = snprintf(error, error_size, "unknown model \"%s\" (built-in:", argument);
        for (int k = 0; k < mu_builtin_model_count() && written >= 0 && (size_t)written < error_size; ++k) {
            written += snprintf(error + written, error_size - (size_t)written, "%s %s", k == 0 ? "" : ",",
                                mu_builtin_model_name(k));
        }
        if (written >= 0 && (size_t)written < error_size) {
            snprintf(error + written, error_size - (size_t)written, "; or a path to a .json file)");
        }
        return MODEL_SOURCE_UNKNOWN;
    }
    if (status != RB_OK) {
        snprintf(error, error_size, "%s", user_error());
        return MODEL_SOURCE_INVALID;
    }
    return MODEL_SOURCE_LOADED;
}

int model_source_load(const char *argument, mu_model_desc **out)
{
    char error[MODEL_SOURCE_ERROR_SIZE];
    model_source_result result = model_source_open(argument, out, error, sizeof error);
    if (result == MODEL_SOURCE_LOADED) {
        return 0;
    }
    fprintf(stderr, "sinew: %s\n", error);
    return result == MODEL_SOURCE_UNKNOWN ? CLI_EXIT_USAGE : EXIT_FAILURE;
}

void model_source_stem(const char *argument, char *stem, size_t stem_size)
{
    const char *slash = strrchr(argument, '/');
    const char *name = slash != NULL ? slash + 1 : argument;
    size_t length = strlen(name);
    if (ends_with(name, ".json")) {
        length -= strlen(".json");
    }
    if (length == 0) {
        snprintf(stem, stem_size, "model"); /* ".json" alone: still a usable file name */
        return;
    }
    snprintf(stem, stem_size, "%.*s", (int)length, name);
}

int model_source_choose_variant(const mu_model_desc *desc, const char *text, int *variant)
{
    *variant = 0;
    if (text == NULL) {
        return 0;
    }
    *variant = mu_model_desc_find_variant(desc, text);
    char error[OPTION_ERROR_SIZE];
    if (*variant >= 0 ||
        option_parse_int("--variant", text, 0, desc->variant_count - 1, variant, error, sizeof error)) {
        return 0;
    }
    fprintf(stderr, "sinew: unknown variant \"%s\" of model %s; the variants are", text, desc->name);
    for (int v = 0; v < desc->variant_count; ++v) {
        fprintf(stderr, "%s %d \"%s\"", v == 0 ? "" : ",", v, desc->variants[v].name);
    }
    fputs("\n", stderr);
    return CLI_EXIT_USAGE;
}

void model_source_print_weights(FILE *stream, const mu_model_desc *desc)
{
    for (int w = 0; w < desc->weight.mass_count; ++w) {
        fprintf(stream, "%s%g", w == 0 ? "" : ", ", desc->weight.masses[w]);
    }
    fputs(" kg", stream);
}

int model_source_choose_weight(const mu_model_desc *desc, bool has_kilograms, double kilograms, int index,
                               int *weight_index)
{
    *weight_index = 0;
    if ((has_kilograms || index >= 0) && !desc->has_weight) {
        fprintf(stderr, "sinew: model %s has no weight; leave out %s\n", desc->name,
                has_kilograms ? "--weight" : "--weight-index");
        return CLI_EXIT_USAGE;
    }
    if (index >= desc->weight.mass_count) {
        fprintf(stderr, "sinew: --weight-index %d: model %s has weight choices 0 .. %d (", index, desc->name,
                desc->weight.mass_count - 1);
        model_source_print_weights(stderr, desc);
        fputs(")\n", stderr);
        return CLI_EXIT_USAGE;
    }
    if (index >= 0) {
        *weight_index = index;
        return 0;
    }
    if (!has_kilograms) {
        return 0;
    }
    for (int w = 0; w < desc->weight.mass_count; ++w) {
        const double mass = desc->weight.masses[w];
        if (fabs(mass - kilograms) <= 1e-9 * fmax(1.0, mass)) {
            *weight_index = w;
            return 0;
        }
    }
    fprintf(stderr, "sinew: --weight %g: model %s has no such weight choice; its choices are ", kilograms, desc->name);
    model_source_print_weights(stderr, desc);
    fputs("\n", stderr);
    return CLI_EXIT_USAGE;
}
