/* SPDX-License-Identifier: MIT */
/* The model file's schema: what each key of a model file means, its
 * type, range and default, and the cross-checks between objects
 * (docs/model-format.md documents the format). */
#ifndef MU_MODEL_SCHEMA_H
#define MU_MODEL_SCHEMA_H

#include <jansson.h>

#include "model_json.h"
#include "mu/model_desc.h"

/* Fills `desc` (zeroed) from the document `root`. On failure the error is
 * reported and `desc` holds what was read so far, which
 * mu_model_desc_destroy frees. */
rb_status mu_model_parse(mu_json_reader *reader, const json_t *root, mu_model_desc *desc);

#endif
