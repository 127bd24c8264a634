/* SPDX-License-Identifier: MIT */
/* A file written under a temporary name and renamed over its final name
 * only once it is complete, so that an interrupted or failed run never
 * leaves a half-written file: PATH keeps its previous content (or stays
 * absent) until atomic_file_commit succeeds.
 *
 * The temporary file is PATH.tmp.PID, beside PATH because rename() replaces
 * a file atomically only within one file system. It is created exclusively
 * (an existing file of that name is an error, never overwritten or
 * removed). PATH must be a regular file or not exist: a device, a pipe or
 * a directory there is refused, since the rename would replace it. A
 * symbolic link at PATH is replaced by the new file, not written through.
 *
 * Interruption: while a file is open, the signals a terminal, a shell or
 * a pipe sends (SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGPIPE) remove its
 * temporary file. The first atomic_file_open installs a handler that
 * unlinks every open temporary file and then lets the signal's default
 * action end the process, so a parent (a shell loop) still sees that the
 * program was interrupted. SIGINT and SIGTERM get it even where they were
 * ignored (as SIGINT is in a background job of a shell without job
 * control), so `kill -INT` stops such a run too, removing its file; the
 * others keep an inherited SIG_IGN (nohup's SIGHUP).
 *
 * A run that could not clean up (SIGKILL, a crash, a power loss) leaves its
 * PATH.tmp.PID behind: the next atomic_file_open of the same PATH removes
 * every such file whose process no longer exists. PIDs are those this
 * process sees: a run in another PID namespace (another container) writing
 * to the same folder at the same time is not seen, and must not write the
 * same PATH.
 *
 * Power loss: atomic_file_commit syncs the file's data before the rename
 * and the folder after it, so PATH is the old file or the complete new
 * one, never a renamed empty file.
 *
 * Limits:
 *   - at most ATOMIC_FILE_MAX_OPEN files open at once;
 *   - for single-threaded programs that install no handler of their own
 *     for those signals (this one would replace it, or be replaced).
 */
#ifndef IO_ATOMIC_FILE_H
#define IO_ATOMIC_FILE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Bytes for a path, its terminating NUL included. */
#define ATOMIC_FILE_PATH_MAX 4096

/* Files that may be open at the same time in one process. */
#define ATOMIC_FILE_MAX_OPEN 4

/* Bytes of an error buffer that holds any message of this module whole. */
#define ATOMIC_FILE_ERROR_SIZE (2 * ATOMIC_FILE_PATH_MAX + 256)

/* A zero-initialised atomic_file is closed; atomic_file_abandon on it does
 * nothing. An open one must not be copied: both copies would own the same
 * temporary file and clean-up slot.
 *
 * Every message goes to `error`, truncated to error_size bytes
 * (ATOMIC_FILE_ERROR_SIZE holds any whole); `error` may be NULL. */
typedef struct atomic_file {
    FILE *stream;                         /* write here; NULL when closed */
    char path[ATOMIC_FILE_PATH_MAX];      /* final name */
    char temp_path[ATOMIC_FILE_PATH_MAX]; /* PATH.tmp.PID, the name while open */
    int slot;                             /* private: index in the signal handler's list */
} atomic_file;

/* Creates the temporary file for `path` (non-empty, shorter than
 * ATOMIC_FILE_PATH_MAX with its ".tmp.PID" suffix) and opens `stream` on it
 * for writing. On failure `file` is closed, nothing is left on disk, and
 * `error` names the path and the reason. */
bool atomic_file_open(atomic_file *file, const char *path, char *error, size_t error_size);

/* Flushes, syncs and closes the stream and renames the temporary file to
 * the final name, then syncs the folder. Fails, with `error` naming the
 * path and the reason, when the file is not open, any write to the stream
 * failed, the flush, sync or close failed, or the rename failed; the
 * temporary file is then removed and the final name left as it was. When
 * only the folder's sync fails, the new file is in place and `error` says
 * so. Either way `file` is closed afterwards. */
bool atomic_file_commit(atomic_file *file, char *error, size_t error_size);

/* Closes the stream and removes the temporary file; the final name is left
 * as it was. Does nothing on a closed file, so it may follow a failed open
 * or commit. */
void atomic_file_abandon(atomic_file *file);

#endif
