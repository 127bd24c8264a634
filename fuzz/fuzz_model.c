/* SPDX-License-Identifier: MIT */
/* Fuzz target: a model file's bytes, loaded as `sinew check` and `sinew run`
 * load them (mu_model_desc_load), each variant built and stepped a few
 * frames with every muscle fully active. Any byte sequence must end in
 * a model or an error with a message, in bounded time, without a
 * sanitizer's report; what the steps compute is not judged here. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "memory_file.h"
#include "mu/model.h"
#include "mu/model_desc.h"

/* Frames stepped: enough to run the muscles' tension laws and the solver
 * on the built model, few enough to keep an input well under a millisecond. */
enum { FRAMES = 3 };

/* Variants built, at most: the built-in models have up to 5. */
enum { MAX_VARIANTS = 8 };

/* A failure must say what failed (rb_last_error: the file, the JSON path,
 * what was expected); an empty message is a defect as a crash is. */
static void expect_message(const char *call)
{
    if (rb_last_error()[0] == '\0') {
        fprintf(stderr, "fuzz_model: %s failed without a message\n", call);
        abort();
    }
}

/* Builds variant `variant` at the full level and steps it. The weight
 * choice changes with the variant, so that across variants the weights
 * are met; odd variants keep their glues as weld joints (weld_glues),
 * even ones merge them, so that both builders are fuzzed. */
static void build_and_step(const mu_model_desc *desc, int variant)
{
    mu_model_options options = mu_default_model_options();
    options.variant = variant;
    options.weight_index = desc->has_weight ? variant % desc->weight.mass_count : 0;
    options.weld_glues = variant % 2 == 1;
    mu_model *model = NULL;
    if (mu_model_create(desc, &options, &model) != RB_OK) {
        expect_message("mu_model_create");
        return;
    }
    for (int m = 0; m < mu_model_muscle_count(model); ++m) {
        mu_model_set_activation_at(model, m, 1.0);
    }
    for (int frame = 0; frame < FRAMES && mu_model_step(model) == RB_OK; ++frame) {
    }
    mu_model_destroy(model);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    memory_file file;
    memory_file_open(&file, data, size);
    mu_model_desc *desc = NULL;
    rb_status status = mu_model_desc_load(file.path, &desc);
    memory_file_close(&file);
    if (status != RB_OK) {
        expect_message("mu_model_desc_load");
        return 0;
    }
    for (int v = 0; v < desc->variant_count && v < MAX_VARIANTS; ++v) {
        build_and_step(desc, v);
    }
    mu_model_desc_destroy(desc);
    return 0;
}
