/* SPDX-License-Identifier: MIT */
/* A fuzz input as a file: the loaders under test take a path, and a file
 * in memory (memfd_create) reaches them through /proc/self/fd/N without
 * touching a disk or changing their API, at thousands of inputs a second. */
#ifndef FUZZ_MEMORY_FILE_H
#define FUZZ_MEMORY_FILE_H

#include <stddef.h>
#include <stdint.h>

/* Bytes of a memory file's path. */
#define MEMORY_FILE_PATH_SIZE 64

typedef struct memory_file {
    int fd;
    char path[MEMORY_FILE_PATH_SIZE];
} memory_file;

/* Makes a file holding the `size` bytes of `data`; aborts on failure, which
 * is the harness's, not the code's under test. */
void memory_file_open(memory_file *file, const uint8_t *data, size_t size);

void memory_file_close(memory_file *file);

#endif
