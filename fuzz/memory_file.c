/* SPDX-License-Identifier: MIT */
#define _GNU_SOURCE /* memfd_create */

#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

#include "memory_file.h"

void memory_file_open(memory_file *file, const uint8_t *data, size_t size)
{
    file->fd = memfd_create("fuzz-input", MFD_CLOEXEC);
    if (file->fd < 0) {
        perror("fuzz: memfd_create");
        abort();
    }
    size_t written = 0;
    while (written < size) {
        ssize_t n = write(file->fd, data + written, size - written);
        if (n <= 0) {
            perror("fuzz: writing the input to a memory file");
            abort();
        }
        written += (size_t)n;
    }
    snprintf(file->path, sizeof file->path, "/proc/self/fd/%d", file->fd);
}

void memory_file_close(memory_file *file)
{
    close(file->fd);
    file->fd = -1;
}
