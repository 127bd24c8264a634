/* SPDX-License-Identifier: MIT */
/* Fuzz target: a motor pool's profile file, its bytes read as a profile
 * image (mu_motor_pool_load_png, libpng under the setjmp of pool_image.c)
 * and as a CSV of strengths (mu_motor_pool_load_csv), as a model file's
 * "motor_pool" reads them. Any byte sequence must end in a pool or an
 * error with a message; a pool must keep its promises, e(0) = 0 and
 * e(all) = 1 (mu/motor_pool.h). */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "memory_file.h"
#include "mu/motor_pool.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The pool `load` read, or its error, checked. */
static void check(rb_status status, mu_motor_pool *pool, const char *call)
{
    if (status != RB_OK) {
        if (pool != NULL || rb_last_error()[0] == '\0') {
            fprintf(stderr, "fuzz_pool_profile: %s failed without a message or left a pool\n", call);
            abort();
        }
        return;
    }
    const int count = mu_motor_pool_neuron_count(pool);
    if (count < 1 || mu_motor_pool_exertion_at(pool, 0) != 0.0 || mu_motor_pool_exertion_at(pool, count) != 1.0) {
        fprintf(stderr, "fuzz_pool_profile: %s gave a pool of %d neurons without e(0) = 0 and e(all) = 1\n", call,
                count);
        abort();
    }
    mu_motor_pool_destroy(pool);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    memory_file file;
    memory_file_open(&file, data, size);
    mu_motor_pool *pool = NULL;
    rb_status status = mu_motor_pool_load_png(file.path, &pool);
    check(status, pool, "mu_motor_pool_load_png");
    pool = NULL;
    status = mu_motor_pool_load_csv(file.path, &pool);
    check(status, pool, "mu_motor_pool_load_csv");
    memory_file_close(&file);
    return 0;
}
