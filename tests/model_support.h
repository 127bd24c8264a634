/* SPDX-License-Identifier: MIT */
/* Helpers for the tests of the muscle layer's models (included by each
 * Criterion program that needs them; static inline, as test_support.h).
 * A program including it defines _DEFAULT_SOURCE before any header, for
 * mkstemps. */
#ifndef TESTS_MODEL_SUPPORT_H
#define TESTS_MODEL_SUPPORT_H

#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mu/model_desc.h"

/* Loads a model from the text of a model file, written to a temporary
 * file (removed again) so that it goes through the file loader. */
static inline mu_model_desc *load_model_text(const char *text)
{
    char path[] = "/tmp/sinew-model-XXXXXX.json";
    const int fd = mkstemps(path, 5);
    cr_assert(fd >= 0);
    cr_assert_eq(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    mu_model_desc *desc = NULL;
    const rb_status status = mu_model_desc_load(path, &desc);
    unlink(path);
    cr_assert_eq(status, RB_OK, "%s", rb_last_error());
    return desc;
}

#endif
