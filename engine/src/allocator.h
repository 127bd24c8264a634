/* SPDX-License-Identifier: MIT */
/* The engine's one allocator: every byte the engine holds goes through
 * here, so rb_bytes_in_use() can prove that a destroyed world freed all. */
#ifndef RB_ALLOCATOR_H
#define RB_ALLOCATOR_H

#include <stddef.h>

/* Returns NULL when size is 0 or memory is exhausted. */
void *rb_alloc(size_t size);
/* ptr may be NULL; size must be the size it was allocated with. */
void rb_free(void *ptr, size_t size);

/* The growth of rb_grow_array, for an array that must grow. */
int rb_grow_array_beyond(void **array, int *capacity, int needed, size_t elem_size);

/* Grows *array (of *capacity elements of elem_size bytes) so that it holds
 * at least `needed` elements, at least doubling; the elements it held
 * are kept. Returns 0 on success, -1 when out of memory (the array is
 * then unchanged). Inline: a step asks a dozen times of arrays that are
 * nearly always large enough already. */
static inline int rb_grow_array(void **array, int *capacity, int needed, size_t elem_size)
{
    return needed <= *capacity ? 0 : rb_grow_array_beyond(array, capacity, needed, elem_size);
}

/* Frees an array made by rb_grow_array and zeroes its capacity. */
void rb_free_array(void **array, int *capacity, size_t elem_size);

#endif
