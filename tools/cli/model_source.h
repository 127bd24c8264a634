/* SPDX-License-Identifier: MIT */
/* Where a model comes from: the MODEL argument of `sinew run` and `sinew
 * view` names a built-in model (read through mu_model_desc_load_builtin)
 * or a model file.
 */
#ifndef CLI_MODEL_SOURCE_H
#define CLI_MODEL_SOURCE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "mu/model_desc.h"

/* Bytes of a model's stem (model_source_stem), its NUL included. */
#define MODEL_STEM_SIZE 256

/* Whether `argument` is the name of a built-in model (the library lists
 * them: mu_builtin_model_count, mu_builtin_model_name). */
bool model_source_is_builtin(const char *argument);

/* Bytes of model_source_open's message, its NUL included. */
#define MODEL_SOURCE_ERROR_SIZE 1024

typedef enum model_source_result {
    MODEL_SOURCE_LOADED,
    MODEL_SOURCE_UNKNOWN, /* neither a built-in name nor a path */
    MODEL_SOURCE_INVALID, /* the file cannot be read or is invalid */
} model_source_result;

/* Loads the model `argument` names: a built-in name as it is, anything
 * else as a path when it contains a '/' or ends in ".json". On failure
 * `error` holds one line: the built-ins for an unknown name, or the
 * loader's message (file, line, column and JSON path). Prints nothing:
 * the viewer shows the line in its window. */
model_source_result model_source_open(const char *argument, mu_model_desc **out, char *error, size_t error_size);

/* model_source_open for the command line: returns 0 with
 * *out set, or an exit status after one line on stderr: CLI_EXIT_USAGE for a
 * name that is neither, EXIT_FAILURE when the file cannot be read or is
 * invalid. */
int model_source_load(const char *argument, mu_model_desc **out);

/* The variant `text` names or numbers (a name first: a variant may be
 * called "2"), for a command's --variant; NULL gives 0. Returns 0 with
 * *variant set, or CLI_EXIT_USAGE after one line on stderr listing the
 * variants. */
int model_source_choose_variant(const mu_model_desc *desc, const char *text, int *variant);

/* Prints the model's weight choices: "0, 1, 5 kg". */
void model_source_print_weights(FILE *stream, const mu_model_desc *desc);

/* The weight choice a command's --weight KG (has_kilograms) or
 * --weight-index N (index >= 0) asks for; neither gives choice 0.
 * Returns 0 with *weight_index set, or CLI_EXIT_USAGE after one line on
 * stderr: a weight asked of a model without one, an index beyond the
 * choices, or a mass that is none of them (the choices listed). */
int model_source_choose_weight(const mu_model_desc *desc, bool has_kilograms, double kilograms, int index,
                               int *weight_index);

/* The name outputs are called after: a built-in name as it is, a path's
 * file name without its directory and ".json" (truncated to fit; "model"
 * when nothing is left). */
void model_source_stem(const char *argument, char *stem, size_t stem_size);

#endif
