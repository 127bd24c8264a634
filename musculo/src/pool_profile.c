/* SPDX-License-Identifier: MIT */
/* Opening a motor pool's profile file (pool_profile.h). Only a regular
 * file is read: a device (/dev/zero), a FIFO or a directory could feed the
 * readers without end or block them, as a model file's size limit
 * (MU_MODEL_MAX_FILE_BYTES) guards the model's own reader against. */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include <errno.h>
#include <string.h>
#include <sys/stat.h>

#include "pool_profile.h"

FILE *mu_pool_profile_open(const char *path, char *problem, size_t problem_size)
{
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        snprintf(problem, problem_size, "cannot open: %s", strerror(errno));
        return NULL;
    }
    struct stat info;
    if (fstat(fileno(file), &info) != 0 || !S_ISREG(info.st_mode)) {
        fclose(file);
        snprintf(problem, problem_size, "cannot read: not a regular file");
        return NULL;
    }
    return file;
}
