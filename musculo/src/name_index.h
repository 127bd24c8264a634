/* SPDX-License-Identifier: MIT */
/* A hash table from names to objects, which a model's loader fills as it
 * reads the names: finding a name by scanning every object made a file
 * of 65,535 nails take a minute to check (each name checked against all
 * before it), and a 16 MiB file with several full lists hours. */
#ifndef MU_NAME_INDEX_H
#define MU_NAME_INDEX_H

#include <stdbool.h>
#include <stddef.h>

#include "rb/base.h"

typedef struct mu_name_index mu_name_index;

/* Accepts NULL. */
void mu_name_index_destroy(mu_name_index *index);

/* Adds `name` (borrowed: it must outlive the index) with `kind` and
 * `position`, creating the index at *index if it is NULL; the caller has
 * checked that the name is new. RB_ERR_OUT_OF_MEMORY when memory runs out. */
rb_status mu_name_index_add(mu_name_index **index, const char *name, int kind, int position);

/* Whether `name` is in the index (NULL: empty), and its kind and position. */
bool mu_name_index_find(const mu_name_index *index, const char *name, int *kind, int *position);

#endif
