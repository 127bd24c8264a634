/* SPDX-License-Identifier: MIT */
/* Fuzz target: a control file's bytes (`sinew run --control FILE`), read
 * into a schedule for the built-in arm and for the worm (whose torque
 * muscle takes recruit lines) as control_file_read reads it, and when it
 * is accepted, applied to the built model over a few frames as a run
 * applies it. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "control_file.h"
#include "memory_file.h"
#include "mu/model.h"

/* Frames run: events at t = 0 and just after act, the pulses among them
 * are undone, and an input stays well under a millisecond. */
enum { FRAMES = 3 };

/* The arm's and the worm's descriptions, loaded once: their muscles,
 * groups and torque muscle are the names a control file addresses, and
 * loading them for every input would only slow the fuzzer down. */
enum { MODELS = 2 };
static mu_model_desc *models[MODELS];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    static const char *const names[MODELS] = {"arm", "worm"};
    for (int m = 0; m < MODELS; ++m) {
        if (mu_model_desc_load_builtin(names[m], &models[m]) != RB_OK) {
            fprintf(stderr, "fuzz_control_file: %s\n", rb_last_error());
            abort();
        }
    }
    return 0;
}

static void read_and_run(const mu_model_desc *desc, const uint8_t *data, size_t size)
{
    controls schedule;
    if (!controls_init(&schedule, desc, 0)) {
        abort();
    }
    memory_file file;
    memory_file_open(&file, data, size);
    char error[1024];
    bool ok = control_file_read(file.path, &schedule, error, sizeof error);
    memory_file_close(&file);
    mu_model *model = NULL;
    if (ok) {
        mu_model_options options = mu_default_model_options();
        if (mu_model_create(desc, &options, &model) != RB_OK) {
            fprintf(stderr, "fuzz_control_file: %s\n", rb_last_error());
            abort();
        }
        for (long frame = 0; frame < FRAMES; ++frame) {
            if (controls_step_frame(&schedule, model, frame) != RB_OK) {
                break;
            }
        }
        mu_model_destroy(model);
    }
    controls_free(&schedule);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    for (int m = 0; m < MODELS; ++m) {
        read_and_run(models[m], data, size);
    }
    return 0;
}
