/* SPDX-License-Identifier: MIT */
/* Where a command writes: DIR/NAME, after checking that DIR (the command's
 * --out) is a folder, so a run fails before it computes anything rather
 * than after.
 */
#ifndef CLI_OUTPUT_PATH_H
#define CLI_OUTPUT_PATH_H

#include <stddef.h>

/* Writes "DIR/STEMSUFFIX.EXTENSION" to `path` (one '/' between DIR and the
 * name, whether or not DIR ends in one); returns 0, or EXIT_FAILURE after
 * one line on stderr naming --out DIR when DIR is not a folder or the path
 * does not fit in `path_size` bytes. */
int output_path_in_folder(const char *out_dir, const char *stem, const char *suffix, const char *extension, char *path,
                          size_t path_size);

#endif
