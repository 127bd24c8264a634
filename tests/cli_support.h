/* SPDX-License-Identifier: MIT */
/* Running the sinew program from a test (static inline, as
 * test_support.h). The program is SINEW_TOOL, which tests/CMakeLists.txt
 * defines for every test. */
#ifndef TESTS_CLI_SUPPORT_H
#define TESTS_CLI_SUPPORT_H

#include <criterion/criterion.h>
#include <stdbool.h>
#include <stdio.h>
#include <sys/stat.h>
#include <sys/wait.h>

/* What of the program's output a run keeps. */
typedef enum sinew_output {
    SINEW_STDOUT_AND_STDERR, /* both, interleaved as written */
    SINEW_STDERR_ONLY,       /* the messages alone; stdout is dropped */
} sinew_output;

/* Runs `sinew ARGS` (ARGS as a shell would split them) in the folder
 * `dir` (NULL: the test's own), keeps the first size - 1 bytes of what
 * `which` says in `output`, and returns the exit status. The rest of the
 * output is read and dropped, so that a long output never stops the
 * program on a closed pipe. */
static inline int run_sinew_capture(const char *dir, const char *args, sinew_output which, char *output, size_t size)
{
    char command[4096];
    snprintf(command, sizeof command, "%s%s%s'%s' %s %s", dir != NULL ? "cd '" : "", dir != NULL ? dir : "",
             dir != NULL ? "' && " : "", SINEW_TOOL, args, which == SINEW_STDERR_ONLY ? "2>&1 >/dev/null" : "2>&1");
    FILE *pipe = popen(command, "r");
    cr_assert_not_null(pipe, "could not run: %s", command);
    output[fread(output, 1, size - 1, pipe)] = '\0';
    char rest[4096];
    while (fread(rest, 1, sizeof rest, pipe) > 0) {
    }
    const int status = pclose(pipe);
    cr_assert(status != -1 && WIFEXITED(status), "%s did not exit (status %d)", command, status);
    return WEXITSTATUS(status);
}

/* Whether the folder `dir` holds a file `name`. */
static inline bool file_exists_in(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    struct stat info;
    return stat(path, &info) == 0;
}

#endif
