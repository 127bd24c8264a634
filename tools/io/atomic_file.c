/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* sigaction, sigprocmask, fdopen, stat, getpid, unlink, kill, fsync */

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/atomic_file.h"

/* The signals whose default action ends the program and that a terminal,
 * a shell or a pipe sends: the terminal hung up, Ctrl-C, Ctrl-\ (quit), kill,
 * and a write to a pipe whose reader has gone (sinew ... | head). */
static const int cleanup_signals[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGPIPE};
#define CLEANUP_SIGNAL_COUNT (sizeof cleanup_signals / sizeof cleanup_signals[0])

/* The temporary files the signal handler removes: slot k holds a name while
 * slot_in_use[k] is set. Slots are filled and emptied with the cleanup
 * signals blocked, so the handler never reads a half-written name. */
static char slot_paths[ATOMIC_FILE_MAX_OPEN][ATOMIC_FILE_PATH_MAX];
static volatile sig_atomic_t slot_in_use[ATOMIC_FILE_MAX_OPEN];
static bool handler_installed = false;

static void remove_temp_files_and_die(int signal_number)
{
    for (int k = 0; k < ATOMIC_FILE_MAX_OPEN; ++k) {
        if (slot_in_use[k]) {
            unlink(slot_paths[k]); /* async-signal-safe, unlike remove() */
        }
    }
    /* Dying of the signal itself, rather than exiting with a status, tells
     * the parent the program was interrupted. The signal stays blocked
     * while this handler runs, so it takes effect as the handler returns. */
    signal(signal_number, SIG_DFL);
    raise(signal_number);
}

static sigset_t cleanup_signal_set(void)
{
    sigset_t set;
    sigemptyset(&set);
    for (size_t k = 0; k < CLEANUP_SIGNAL_COUNT; ++k) {
        sigaddset(&set, cleanup_signals[k]);
    }
    return set;
}

/* Installs the handler for the cleanup signals. SIGINT and SIGTERM get it
 * even where they were ignored: a shell without job control starts a
 * background job with SIGINT ignored, and a script that stops such a run
 * with `kill -INT` must still find the file removed. The others keep an
 * inherited SIG_IGN, which is a request: nohup ignores SIGHUP so that the
 * run outlives its terminal, and with SIGPIPE ignored a write to a closed
 * pipe fails (and the file is abandoned) instead of ending the program.
 * All are blocked while the handler runs, so one handler never interrupts
 * another. */
static void install_handler_once(void)
{
    if (handler_installed) {
        return;
    }
    handler_installed = true;
    struct sigaction action = {.sa_handler = remove_temp_files_and_die, .sa_mask = cleanup_signal_set()};
    for (size_t k = 0; k < CLEANUP_SIGNAL_COUNT; ++k) {
        const int number = cleanup_signals[k];
        struct sigaction inherited;
        const bool always = number == SIGINT || number == SIGTERM;
        if (always || (sigaction(number, NULL, &inherited) == 0 && inherited.sa_handler != SIG_IGN)) {
            sigaction(number, &action, NULL);
        }
    }
}

/* The folder of `path` ("." for a bare name) into `folder`, and where the
 * file's own name starts in `path`. */
static const char *split_path(const char *path, char *folder, size_t folder_size)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL) {
        snprintf(folder, folder_size, ".");
        return path;
    }
    snprintf(folder, folder_size, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    return slash + 1;
}

/* Removes the temporary files of `path` that runs killed before they could
 * clean up left behind (SIGKILL, a crash, a power loss): NAME.tmp.PID in
 * the same folder, a regular file, whose process no longer exists. A
 * file whose PID is alive (another run writing the same output now, or a
 * PID reused) is left alone. */
static void remove_stale_temp_files(const char *path)
{
    char folder[ATOMIC_FILE_PATH_MAX];
    const char *name = split_path(path, folder, sizeof folder);
    const size_t name_length = strlen(name);
    DIR *dir = opendir(folder);
    if (dir == NULL) {
        return; /* the open that follows reports why */
    }
    for (struct dirent *entry = readdir(dir); entry != NULL; entry = readdir(dir)) {
        const char *suffix = entry->d_name + name_length;
        if (strncmp(entry->d_name, name, name_length) != 0 || strncmp(suffix, ".tmp.", 5) != 0) {
            continue;
        }
        const char *digits = suffix + 5;
        if (digits[0] == '\0' || strspn(digits, "0123456789") != strlen(digits) || strlen(digits) > 9) {
            continue;
        }
        const pid_t pid = (pid_t)strtol(digits, NULL, 10);
        if (pid <= 0 || pid == getpid() || kill(pid, 0) == 0 || errno != ESRCH) {
            continue;
        }
        char stale[2 * ATOMIC_FILE_PATH_MAX];
        snprintf(stale, sizeof stale, "%s/%s", folder, entry->d_name);
        struct stat info;
        if (lstat(stale, &info) == 0 && S_ISREG(info.st_mode)) {
            unlink(stale);
        }
    }
    closedir(dir);
}

/* Writes a printf-style message into `error` (nothing when it is NULL). */
static void report(char *error, size_t error_size, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static void report(char *error, size_t error_size, const char *format, ...)
{
    if (error == NULL || error_size == 0) {
        return;
    }
    va_list arguments;
    va_start(arguments, format);
    vsnprintf(error, error_size, format, arguments);
    va_end(arguments);
}

/* Removes the temporary file, then frees its slot: in this order a signal
 * in between finds the slot still set and at worst unlinks a name that no
 * longer exists. */
static void remove_temp_file(atomic_file *file)
{
    unlink(file->temp_path);
    slot_in_use[file->slot] = 0;
}

bool atomic_file_open(atomic_file *file, const char *path, char *error, size_t error_size)
{
    *file = (atomic_file){.stream = NULL};
    size_t length = strlen(path);
    if (length == 0) {
        report(error, error_size, "cannot write a file with an empty name");
        return false;
    }
    int temp_length = snprintf(file->temp_path, sizeof file->temp_path, "%s.tmp.%ld", path, (long)getpid());
    if (temp_length < 0 || (size_t)temp_length >= sizeof file->temp_path) {
        report(error, error_size, "cannot write %s: the name is too long (at most %d bytes with \".tmp.PID\")", path,
               ATOMIC_FILE_PATH_MAX - 1);
        return false;
    }
    memcpy(file->path, path, length + 1);
    remove_stale_temp_files(path);
    /* The rename would replace a device, a pipe or a directory rather than
     * write to it (as root even /dev/null), so only a regular file or a
     * name not yet in use is accepted, before any work is done. */
    struct stat existing;
    if (stat(path, &existing) == 0 && !S_ISREG(existing.st_mode)) {
        report(error, error_size, "cannot write %s: it exists and is not a regular file", path);
        return false;
    }

    /* Create the file and claim its slot with the signals blocked, so that
     * a signal sees either no file or a file listed in the slot. */
    sigset_t cleanup_signals = cleanup_signal_set();
    sigset_t previous_mask;
    sigprocmask(SIG_BLOCK, &cleanup_signals, &previous_mask);
    install_handler_once();
    int slot = 0;
    while (slot < ATOMIC_FILE_MAX_OPEN && slot_in_use[slot]) {
        ++slot;
    }
    int descriptor = -1;
    int open_errno = 0;
    if (slot < ATOMIC_FILE_MAX_OPEN) {
        descriptor = open(file->temp_path, O_WRONLY | O_CREAT | O_EXCL, 0666);
        open_errno = errno;
        if (descriptor >= 0) {
            memcpy(slot_paths[slot], file->temp_path, (size_t)temp_length + 1);
            slot_in_use[slot] = 1;
            file->slot = slot;
        }
    }
    sigprocmask(SIG_SETMASK, &previous_mask, NULL);

    if (slot == ATOMIC_FILE_MAX_OPEN) {
        report(error, error_size, "cannot write %s: %d files are being written already, the most at once", path,
               ATOMIC_FILE_MAX_OPEN);
        return false;
    }
    if (descriptor < 0) {
        report(error, error_size, "cannot write %s (temporary file %s): %s", path, file->temp_path,
               strerror(open_errno));
        return false;
    }
    file->stream = fdopen(descriptor, "w");
    if (file->stream == NULL) {
        int fdopen_errno = errno;
        close(descriptor);
        remove_temp_file(file);
        report(error, error_size, "cannot write %s (temporary file %s): %s", path, file->temp_path,
               strerror(fdopen_errno));
        return false;
    }
    return true;
}

bool atomic_file_commit(atomic_file *file, char *error, size_t error_size)
{
    if (file->stream == NULL) {
        report(error, error_size, "cannot commit a file that is not open");
        return false;
    }
    /* ferror first: it is the only trace of a write that failed earlier,
     * whose errno is long gone. */
    bool earlier_write_failed = ferror(file->stream) != 0;
    int flush_errno = fflush(file->stream) == 0 ? 0 : errno;
    /* The data reaches the disk before the name does: renamed first, a
     * power loss could leave the final name on an empty file. */
    int sync_errno = flush_errno == 0 && fsync(fileno(file->stream)) != 0 ? errno : 0;
    int close_errno = fclose(file->stream) == 0 ? 0 : errno;
    file->stream = NULL;
    if (earlier_write_failed || flush_errno != 0 || sync_errno != 0 || close_errno != 0) {
        const char *reason = flush_errno != 0   ? strerror(flush_errno)
                             : sync_errno != 0  ? strerror(sync_errno)
                             : close_errno != 0 ? strerror(close_errno)
                                                : "a write failed";
        report(error, error_size, "cannot write %s (temporary file %s): %s", file->path, file->temp_path, reason);
        remove_temp_file(file);
        return false;
    }
    if (rename(file->temp_path, file->path) != 0) {
        report(error, error_size, "cannot rename %s to %s: %s", file->temp_path, file->path, strerror(errno));
        remove_temp_file(file);
        return false;
    }
    /* The name is gone, so a signal before this line unlinks nothing. */
    slot_in_use[file->slot] = 0;
    /* And the rename itself reaches the disk with the folder's entry. A
     * file system that cannot sync a folder (EINVAL) keeps its own order. */
    char folder[ATOMIC_FILE_PATH_MAX];
    split_path(file->path, folder, sizeof folder);
    int folder_descriptor = open(folder, O_RDONLY | O_DIRECTORY);
    int folder_errno = folder_descriptor < 0 ? errno : fsync(folder_descriptor) != 0 ? errno : 0;
    if (folder_descriptor >= 0) {
        close(folder_descriptor);
    }
    if (folder_errno != 0 && folder_errno != EINVAL) {
        report(error, error_size, "wrote %s, but cannot sync its folder %s: %s", file->path, folder,
               strerror(folder_errno));
        return false;
    }
    return true;
}

void atomic_file_abandon(atomic_file *file)
{
    if (file->stream == NULL) {
        return;
    }
    fclose(file->stream);
    file->stream = NULL;
    remove_temp_file(file);
}
