/* SPDX-License-Identifier: MIT */
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "allocator.h"
#include "rb/base.h"

static atomic_size_t bytes_in_use;
static atomic_uint_fast64_t allocation_count;

void *rb_alloc(size_t size)
{
    if (size == 0) {
        return NULL;
    }
    void *ptr = malloc(size);
    if (ptr != NULL) {
        atomic_fetch_add(&bytes_in_use, size);
        atomic_fetch_add(&allocation_count, 1);
    }
    return ptr;
}

void rb_free(void *ptr, size_t size)
{
    if (ptr == NULL) {
        return;
    }
    atomic_fetch_sub(&bytes_in_use, size);
    free(ptr);
}

int rb_grow_array_beyond(void **array, int *capacity, int needed, size_t elem_size)
{
    int new_capacity = *capacity < 16 ? 16 : *capacity;
    while (new_capacity < needed) {
        new_capacity *= 2;
    }
    void *grown = rb_alloc((size_t)new_capacity * elem_size);
    if (grown == NULL) {
        return -1;
    }
    if (*array != NULL) {
        memcpy(grown, *array, (size_t)*capacity * elem_size);
        rb_free(*array, (size_t)*capacity * elem_size);
    }
    *array = grown;
    *capacity = new_capacity;
    return 0;
}

void rb_free_array(void **array, int *capacity, size_t elem_size)
{
    rb_free(*array, (size_t)*capacity * elem_size);
    *array = NULL;
    *capacity = 0;
}

size_t rb_bytes_in_use(void) { return atomic_load(&bytes_in_use); }

uint64_t rb_allocation_count(void) { return atomic_load(&allocation_count); }
