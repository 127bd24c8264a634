/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/output_path.h"

int output_path_in_folder(const char *out_dir, const char *stem, const char *suffix, const char *extension, char *path,
                          size_t path_size)
{
    struct stat info;
    if (stat(out_dir, &info) != 0) {
        fprintf(stderr, "sinew: --out %s: %s\n", out_dir, strerror(errno));
        return EXIT_FAILURE;
    }
    if (!S_ISDIR(info.st_mode)) {
        fprintf(stderr, "sinew: --out %s: not a directory\n", out_dir);
        return EXIT_FAILURE;
    }
    const size_t length = strlen(out_dir);
    const char *separator = length > 0 && out_dir[length - 1] == '/' ? "" : "/";
    const int written = snprintf(path, path_size, "%s%s%s%s.%s", out_dir, separator, stem, suffix, extension);
    if (written < 0 || (size_t)written >= path_size) {
        fprintf(stderr, "sinew: --out %s: the output path is too long\n", out_dir);
        return EXIT_FAILURE;
    }
    return 0;
}
