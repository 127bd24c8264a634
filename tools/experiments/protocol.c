/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <stdlib.h>

#include "cli/user_error.h"
#include "commands/control_file.h"
#include "protocol.h"

int experiment_protocol_read(controls *schedule, const experiment_model *run, const char *variant, const char *name,
                             const char *text)
{
    if (!controls_init(schedule, run->desc, mu_model_desc_find_variant(run->desc, variant))) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    char error[1024];
    if (!control_text_read(name, text, schedule, error, sizeof error)) {
        fprintf(stderr, "sinew: %s\n", error);
        return EXIT_FAILURE;
    }
    return 0;
}

int experiment_protocol_apply(controls *schedule, experiment_model *run)
{
    if (controls_apply(schedule, run->model, run->taken) != RB_OK) {
        fprintf(stderr, "sinew: applying the protocol failed: %s\n", user_error());
        return EXIT_FAILURE;
    }
    return 0;
}
