/* SPDX-License-Identifier: MIT */
/* Open addressing with linear probing, kept at most half full, over the
 * 64-bit FNV-1a hash of the name (Fowler, Noll and Vo, "FNV hash", 1991). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "name_index.h"

typedef struct slot {
    const char *name; /* NULL: empty */
    int kind, position;
} slot;

struct mu_name_index {
    size_t capacity; /* a power of 2 */
    size_t count;
    slot *slots;
};

static uint64_t hash(const char *name)
{
    uint64_t h = 14695981039346656037ULL;
    for (const unsigned char *c = (const unsigned char *)name; *c != '\0'; ++c) {
        h = (h ^ *c) * 1099511628211ULL;
    }
    return h;
}

/* The slot of `name`, or the empty one where it would go. */
static slot *find_slot(slot *slots, size_t capacity, const char *name)
{
    size_t i = (size_t)hash(name) & (capacity - 1);
    while (slots[i].name != NULL && strcmp(slots[i].name, name) != 0) {
        i = (i + 1) & (capacity - 1);
    }
    return &slots[i];
}

void mu_name_index_destroy(mu_name_index *index)
{
    if (index != NULL) {
        free(index->slots);
        free(index);
    }
}

static rb_status grow(mu_name_index *index)
{
    const size_t capacity = index->capacity * 2;
    slot *slots = calloc(capacity, sizeof *slots);
    if (slots == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_desc_load: out of memory for the names");
    }
    for (size_t i = 0; i < index->capacity; ++i) {
        if (index->slots[i].name != NULL) {
            *find_slot(slots, capacity, index->slots[i].name) = index->slots[i];
        }
    }
    free(index->slots);
    index->slots = slots;
    index->capacity = capacity;
    return RB_OK;
}

rb_status mu_name_index_add(mu_name_index **index, const char *name, int kind, int position)
{
    if (*index == NULL) {
        *index = calloc(1, sizeof **index);
        slot *slots = calloc(64, sizeof *slots);
        if (*index == NULL || slots == NULL) {
            free(slots);
            free(*index);
            *index = NULL;
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_desc_load: out of memory for the names");
        }
        (*index)->slots = slots;
        (*index)->capacity = 64;
    }
    if (2 * ((*index)->count + 1) > (*index)->capacity) {
        rb_status status = grow(*index);
        if (status != RB_OK) {
            return status;
        }
    }
    *find_slot((*index)->slots, (*index)->capacity, name) = (slot){name, kind, position};
    ++(*index)->count;
    return RB_OK;
}

bool mu_name_index_find(const mu_name_index *index, const char *name, int *kind, int *position)
{
    if (index == NULL) {
        return false;
    }
    const slot *found = find_slot(index->slots, index->capacity, name);
    if (found->name == NULL) {
        return false;
    }
    *kind = found->kind;
    *position = found->position;
    return true;
}
