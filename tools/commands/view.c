/* SPDX-License-Identifier: MIT */
/* `sinew view [MODEL] [options]`: the interactive viewer. It is its own
 * program, sinew-view (tools/viewer/), built beside sinew when GTK 4 is
 * found, so that the command-line tool itself never loads GTK: this
 * command runs it with the same arguments.
 */
#define _POSIX_C_SOURCE 200809L /* readlink */

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

int cmd_view(int argc, char **argv)
{
#ifndef SINEW_VIEWER_BUILT
    (void)argc;
    (void)argv;
    fputs("sinew: the viewer was not built: GTK 4 was not found when the build was configured\n"
          "(install libgtk-4-dev, e.g. with tools/setup.sh, then configure and build again)\n",
          stderr);
    return EXIT_FAILURE;
#else
    /* sinew-view lives in the directory of this executable. */
    char path[PATH_MAX];
    ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
    if (length < 0) {
        fprintf(stderr, "sinew: cannot find the sinew executable's directory: %s\n", strerror(errno));
        return EXIT_FAILURE;
    }
    path[length] = '\0';
    char *slash = strrchr(path, '/');
    const char program[] = "sinew-view";
    if (slash == NULL || (size_t)(slash + 1 - path) + sizeof program > sizeof path) {
        fprintf(stderr, "sinew: cannot place sinew-view beside %s\n", path);
        return EXIT_FAILURE;
    }
    memcpy(slash + 1, program, sizeof program);
    char **arguments = calloc((size_t)argc + 2, sizeof *arguments);
    if (arguments == NULL) {
        fputs("sinew: out of memory\n", stderr);
        return EXIT_FAILURE;
    }
    arguments[0] = path;
    for (int k = 0; k < argc; ++k) {
        arguments[k + 1] = argv[k];
    }
    execv(path, arguments);
    fprintf(stderr, "sinew: cannot run %s: %s\n", path, strerror(errno));
    free(arguments);
    return EXIT_FAILURE;
#endif
}
