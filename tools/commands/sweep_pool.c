/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* posix_spawn_file_actions_addchdir_np, strdup */
/* The local pool of `sinew run` processes (sweep_pool.h). */
#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "sweep_pool.h"

extern char **environ;

/* Starts run `run` as a child; its pid, or -1 after a line on stderr. */
static pid_t start_run(const sweep_run *run, const char *program, const char *out_dir)
{
    char log[512];
    snprintf(log, sizeof log, "%s.log", run->name);
    char **argv = calloc((size_t)run->argument_count + 3, sizeof *argv);
    posix_spawn_file_actions_t actions;
    if (argv == NULL || posix_spawn_file_actions_init(&actions) != 0) {
        free(argv);
        fprintf(stderr, "sinew: %s: out of memory\n", run->name);
        return -1;
    }
    argv[0] = (char *)program;
    argv[1] = "run";
    for (int k = 0; k < run->argument_count; ++k) {
        argv[k + 2] = run->arguments[k];
    }
    /* As the job list's `cd OUT && SINEW run ... >/dev/null 2>NAME.log`:
     * the actions act in order, so the log is opened in OUT. */
    int failed = posix_spawn_file_actions_addchdir_np(&actions, out_dir);
    failed = failed || posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    failed =
        failed || posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    if (!failed) {
        failed = posix_spawn(&pid, program, &actions, NULL, argv, environ);
    }
    if (failed) {
        fprintf(stderr, "sinew: %s: could not start %s: %s\n", run->name, program, strerror(failed));
        pid = -1;
    }
    posix_spawn_file_actions_destroy(&actions);
    free(argv);
    return pid;
}

bool sweep_pool_run(const sweep_plan *plan, const int *todo, int count, const char *program, const char *out_dir,
                    int jobs, char *error, size_t error_size)
{
    pid_t *pids = calloc((size_t)count + 1, sizeof *pids);
    if (pids == NULL) {
        snprintf(error, error_size, "out of memory");
        return false;
    }
    int next = 0, running = 0, done = 0;
    while (done < count) {
        while (running < jobs && next < count) {
            pids[next] = start_run(&plan->runs[todo[next]], program, out_dir);
            if (pids[next] < 0) {
                ++done;
            } else {
                ++running;
            }
            ++next;
        }
        if (running == 0) {
            continue;
        }
        int wait_status;
        pid_t pid = waitpid(-1, &wait_status, 0);
        if (pid < 0) {
            if (errno == EINTR) {
                continue;
            }
            snprintf(error, error_size, "waiting for the runs: %s", strerror(errno));
            free(pids);
            return false;
        }
        for (int k = 0; k < next; ++k) {
            if (pids[k] == pid) {
                pids[k] = 0;
                if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
                    fprintf(stderr, "sinew: run %s failed (%s %d; its messages are in %s.log)\n",
                            plan->runs[todo[k]].name, WIFEXITED(wait_status) ? "exit status" : "signal",
                            WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : WTERMSIG(wait_status),
                            plan->runs[todo[k]].name);
                }
                --running;
                ++done;
            }
        }
    }
    free(pids);
    return true;
}
