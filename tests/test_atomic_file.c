/* SPDX-License-Identifier: MIT */
/* The atomic file (tools/io/atomic_file) against what can end a run:
 * every signal a terminal, a shell or a pipe sends removes the temporary
 * file and leaves the target as it was; a run killed beyond cleaning up
 * (SIGKILL) has its temporary file removed by the next run writing the same
 * output, while another live run's is kept; and the data is synced before
 * the rename and the folder after it.
 *
 * The sync order is seen by this program's own fsync, which the static
 * link puts in place of the C library's for atomic_file.c: it records, at
 * each call, whether the descriptor is a folder and whether the final name
 * exists yet, then syncs through the system call.
 */
#define _DEFAULT_SOURCE /* syscall */

#include <criterion/criterion.h>
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/atomic_file.h"

/* ------------------------------------------------------------ fsync seen */

typedef struct sync_call {
    bool folder;       /* the descriptor is a folder */
    bool target_there; /* the final name existed at the call */
} sync_call;

static sync_call sync_calls[8];
static int sync_call_count = 0;
static const char *watched_target = NULL; /* the final name the calls are checked against */
static int failing_sync_errno = 0;        /* fsync fails with this when non-zero */

int fsync(int descriptor)
{
    struct stat info;
    const bool folder = fstat(descriptor, &info) == 0 && S_ISDIR(info.st_mode);
    if (watched_target != NULL && sync_call_count < 8) {
        sync_calls[sync_call_count++] =
            (sync_call){.folder = folder, .target_there = access(watched_target, F_OK) == 0};
    }
    if (failing_sync_errno != 0 && !folder) {
        errno = failing_sync_errno;
        return -1;
    }
    return (int)syscall(SYS_fsync, descriptor);
}

/* ------------------------------------------------------------ helpers */

static char dir[] = "/tmp/sinew-atomic-XXXXXX";

static void path_in_dir(char *path, size_t size, const char *name) { snprintf(path, size, "%s/%s", dir, name); }

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f, "cannot write %s", path);
    fputs(text, f);
    fclose(f);
}

static bool has_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        return false;
    }
    char buffer[256] = "";
    size_t n = fread(buffer, 1, sizeof buffer - 1, f);
    buffer[n] = '\0';
    fclose(f);
    return strcmp(buffer, text) == 0;
}

/* The entries of `dir` whose names start with `prefix`. */
static int count_entries(const char *prefix)
{
    DIR *d = opendir(dir);
    cr_assert_not_null(d);
    int count = 0;
    for (struct dirent *entry = readdir(d); entry != NULL; entry = readdir(d)) {
        count += strncmp(entry->d_name, prefix, strlen(prefix)) == 0;
    }
    closedir(d);
    return count;
}

/* A PID that no process has: a child's, once it has been waited for. */
static pid_t dead_pid(void)
{
    pid_t child = fork();
    cr_assert_geq(child, 0);
    if (child == 0) {
        _exit(0);
    }
    waitpid(child, NULL, 0);
    return child;
}

/* ------------------------------------------------------------ the tests */

Test(atomic_file, every_terminal_signal_removes_the_temporary_file)
{
    cr_assert_not_null(mkdtemp(dir));
    const int signals[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGPIPE};
    char target[600];
    path_in_dir(target, sizeof target, "out.csv");
    write_text(target, "old\n");
    for (size_t k = 0; k < sizeof signals / sizeof signals[0]; ++k) {
        int ready[2];
        cr_assert_eq(pipe(ready), 0);
        pid_t child = fork();
        cr_assert_geq(child, 0);
        if (child == 0) {
            /* As a shell starts it: every signal at its default action. */
            for (size_t s = 0; s < sizeof signals / sizeof signals[0]; ++s) {
                signal(signals[s], SIG_DFL);
            }
            atomic_file file;
            if (!atomic_file_open(&file, target, NULL, 0)) {
                _exit(3);
            }
            fputs("half written", file.stream);
            fflush(file.stream);
            (void)!write(ready[1], "x", 1);
            pause();
            _exit(4);
        }
        close(ready[1]);
        char byte;
        cr_assert_eq(read(ready[0], &byte, 1), 1, "the child did not open its file");
        close(ready[0]);
        cr_assert_eq(count_entries("out.csv.tmp."), 1, "the temporary file exists while writing");
        kill(child, signals[k]);
        int status;
        waitpid(child, &status, 0);
        cr_expect(WIFSIGNALED(status) && WTERMSIG(status) == signals[k], "signal %d: the child should die of it",
                  signals[k]);
        cr_expect_eq(count_entries("out.csv.tmp."), 0, "signal %d left the temporary file", signals[k]);
        cr_expect(has_text(target, "old\n"), "signal %d: the target changed", signals[k]);
    }
    remove(target);
    rmdir(dir);
}

Test(atomic_file, nohup_keeps_an_ignored_hangup_ignored)
{
    cr_assert_not_null(mkdtemp(dir));
    char target[600];
    path_in_dir(target, sizeof target, "out.csv");
    pid_t child = fork();
    cr_assert_geq(child, 0);
    if (child == 0) {
        signal(SIGHUP, SIG_IGN);
        atomic_file file;
        if (!atomic_file_open(&file, target, NULL, 0)) {
            _exit(3);
        }
        raise(SIGHUP); /* ignored, as nohup asks */
        fputs("done\n", file.stream);
        _exit(atomic_file_commit(&file, NULL, 0) ? 0 : 5);
    }
    int status;
    waitpid(child, &status, 0);
    cr_expect(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the run under nohup should outlive SIGHUP");
    cr_expect(has_text(target, "done\n"));
    remove(target);
    rmdir(dir);
}

Test(atomic_file, a_killed_runs_temporary_file_is_removed_by_the_next_run)
{
    cr_assert_not_null(mkdtemp(dir));
    char target[600], stale[700], alive[700], other[700], folder[700];
    path_in_dir(target, sizeof target, "arm.csv");
    /* A run killed with SIGKILL, which no handler sees. */
    pid_t child = fork();
    cr_assert_geq(child, 0);
    if (child == 0) {
        atomic_file file;
        if (atomic_file_open(&file, target, NULL, 0)) {
            fputs("half", file.stream);
            fflush(file.stream);
        }
        raise(SIGKILL);
        _exit(1);
    }
    waitpid(child, NULL, 0);
    cr_assert_eq(count_entries("arm.csv.tmp."), 1, "SIGKILL leaves the temporary file");
    snprintf(stale, sizeof stale, "%s.tmp.%ld", target, (long)dead_pid());
    write_text(stale, "stale");
    /* Another run of the same output, alive now: its file is its own. */
    snprintf(alive, sizeof alive, "%s.tmp.%ld", target, (long)getppid());
    write_text(alive, "alive");
    /* Another output's, and a folder of a matching name. */
    snprintf(other, sizeof other, "%s/leg.csv.tmp.%ld", dir, (long)dead_pid());
    write_text(other, "other");
    snprintf(folder, sizeof folder, "%s.tmp.%ld", target, (long)dead_pid());
    cr_assert_eq(mkdir(folder, 0700), 0);

    atomic_file file;
    char error[ATOMIC_FILE_ERROR_SIZE] = "";
    cr_assert(atomic_file_open(&file, target, error, sizeof error), "%s", error);
    fputs("new\n", file.stream);
    cr_assert(atomic_file_commit(&file, error, sizeof error), "%s", error);
    cr_expect(has_text(target, "new\n"));
    cr_expect_eq(access(stale, F_OK), -1, "the dead run's file is removed");
    cr_expect_eq(count_entries("arm.csv.tmp."), 2, "only the live run's file and the folder remain");
    cr_expect(has_text(alive, "alive"), "a live run's file is kept");
    cr_expect(has_text(other, "other"), "another output's file is kept");
    remove(alive);
    remove(other);
    rmdir(folder);
    remove(target);
    rmdir(dir);
}

Test(atomic_file, data_is_synced_before_the_rename_and_the_folder_after)
{
    cr_assert_not_null(mkdtemp(dir));
    char target[600];
    path_in_dir(target, sizeof target, "out.csv");
    watched_target = target;
    sync_call_count = 0;
    atomic_file file;
    char error[ATOMIC_FILE_ERROR_SIZE] = "";
    cr_assert(atomic_file_open(&file, target, error, sizeof error), "%s", error);
    fputs("data\n", file.stream);
    cr_assert(atomic_file_commit(&file, error, sizeof error), "%s", error);
    cr_assert_eq(sync_call_count, 2, "expected two syncs, got %d", sync_call_count);
    cr_expect(!sync_calls[0].folder && !sync_calls[0].target_there, "first the file, before it has its name");
    cr_expect(sync_calls[1].folder && sync_calls[1].target_there, "then the folder, after the rename");

    /* A sync that fails is a failed write: nothing is renamed. */
    remove(target);
    failing_sync_errno = EIO;
    cr_assert(atomic_file_open(&file, target, error, sizeof error), "%s", error);
    fputs("data\n", file.stream);
    cr_expect_not(atomic_file_commit(&file, error, sizeof error));
    cr_expect(strstr(error, target) != NULL && strstr(error, strerror(EIO)) != NULL, "message: %s", error);
    cr_expect_eq(access(target, F_OK), -1, "no file under the final name");
    cr_expect_eq(count_entries("out.csv"), 0, "and no temporary file");
    failing_sync_errno = 0;
    watched_target = NULL;
    rmdir(dir);
}
