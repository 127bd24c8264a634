/* SPDX-License-Identifier: MIT */
/* Loading a model file, freeing its description, finding objects in it. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arguments.h"
#include "data_file.h"
#include "model_schema.h"
#include "mu/model_desc.h"
#include "name_index.h"

/* Reads the whole file into *text (not terminated; jansson takes a
 * length), refusing it past MU_MODEL_MAX_FILE_BYTES: a file that never
 * ends (/dev/zero, a FIFO) or a huge one stops there rather than when
 * memory runs out. */
static rb_status read_file(const char *path, char **text, size_t *length)
{
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: cannot open: %s, expected a readable model file", path,
                               strerror(errno));
    }
    size_t capacity = 4096, used = 0;
    char *buffer = malloc(capacity);
    while (buffer != NULL && used <= MU_MODEL_MAX_FILE_BYTES) {
        used += fread(buffer + used, 1, capacity - used, file);
        if (used < capacity) {
            break;
        }
        /* One byte past the limit is enough to know the file is too long. */
        capacity = capacity * 2 <= MU_MODEL_MAX_FILE_BYTES ? capacity * 2 : MU_MODEL_MAX_FILE_BYTES + 1;
        char *grown = realloc(buffer, capacity);
        if (grown == NULL) {
            free(buffer);
        }
        buffer = grown;
    }
    int read_error = ferror(file) ? errno : 0;
    fclose(file);
    if (buffer == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_desc_load: out of memory reading %s", path);
    }
    if (read_error != 0) {
        free(buffer);
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: cannot read: %s, expected a readable model file", path,
                               strerror(read_error));
    }
    if (used > MU_MODEL_MAX_FILE_BYTES) {
        free(buffer);
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "%s: longer than %d bytes, expected a model file of at most %d bytes (16 MiB)", path,
                               MU_MODEL_MAX_FILE_BYTES, MU_MODEL_MAX_FILE_BYTES);
    }
    *text = buffer;
    *length = used;
    return RB_OK;
}

/* Parses and validates the model text (`length` bytes, not terminated),
 * named `path` in messages: a file's, whose folder holds the files it
 * names, or one built into libmu (`builtin`), whose files are built in. */
static rb_status parse_text(const char *path, bool builtin, const char *text, size_t length, mu_model_desc **out)
{
    char folder[4096] = ".";
    const char *slash = strrchr(path, '/');
    if (!builtin && slash != NULL) {
        /* "/m.json" is in "/", "a/b/m.json" in "a/b". */
        const size_t length_of_folder = slash == path ? 1 : (size_t)(slash - path);
        if (length_of_folder >= sizeof folder) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: the path is too long, expected under %zu bytes", path,
                                   sizeof folder);
        }
        memcpy(folder, path, length_of_folder);
        folder[length_of_folder] = '\0';
    }
    /* Duplicate keys are rejected here, so that every JSON path names one value. */
    json_error_t error;
    json_t *root = json_loadb(text, length, JSON_REJECT_DUPLICATES, &error);
    if (root == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s:%d:%d: invalid JSON: %s", path, error.line, error.column,
                               error.text);
    }
    rb_status status = RB_OK;
    mu_model_desc *desc = calloc(1, sizeof *desc);
    if (desc == NULL) {
        status = rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_desc_load: out of memory");
    } else {
        desc->source = malloc(strlen(path) + 1);
        if (desc->source == NULL) {
            status = rb_report_error(RB_ERR_OUT_OF_MEMORY, "mu_model_desc_load: out of memory");
        } else {
            memcpy(desc->source, path, strlen(path) + 1);
            mu_json_reader reader = {.file = path, .folder = builtin ? NULL : folder, .text = text, .length = length};
            status = mu_model_parse(&reader, root, desc);
        }
    }
    json_decref(root);
    if (status != RB_OK) {
        mu_model_desc_destroy(desc);
        return status;
    }
    *out = desc;
    return RB_OK;
}

rb_status mu_model_desc_load(const char *path, mu_model_desc **out)
{
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_desc_load: out is NULL");
    }
    *out = NULL;
    if (path == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_desc_load: path is NULL");
    }
    char *text = NULL;
    size_t length = 0;
    rb_status status = read_file(path, &text, &length);
    if (status != RB_OK) {
        return status;
    }
    status = parse_text(path, false, text, length, out);
    free(text);
    return status;
}

/* The built-in models' names, "sample, arm, ...", for a message. */
static const char *builtin_model_list(void)
{
    static _Thread_local char list[256];
    size_t used = 0;
    list[0] = '\0';
    for (size_t i = 0; i < mu_builtin_model_name_count && used < sizeof list; ++i) {
        int written = snprintf(list + used, sizeof list - used, "%s%s", i > 0 ? ", " : "", mu_builtin_model_names[i]);
        used += written > 0 ? (size_t)written : 0;
    }
    return list;
}

rb_status mu_model_desc_load_builtin(const char *name, mu_model_desc **out)
{
    if (out == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_desc_load_builtin: out is NULL");
    }
    *out = NULL;
    /* A plain name keeps a path made from it inside SINEW_DATA_DIR. */
    if (name == NULL || name[0] == '\0' || strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789_-") != strlen(name)) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_model_desc_load_builtin: name is \"%s\", expected a built-in model's name "
                               "(lower-case letters, digits, '_' or '-')",
                               name != NULL ? name : "(null)");
    }
    char file_name[256];
    int written = snprintf(file_name, sizeof file_name, "%s.json", name);
    if (written < 0 || (size_t)written >= sizeof file_name) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_desc_load_builtin: name \"%s\" is too long", name);
    }
    const char *dir = mu_data_dir();
    if (dir != NULL) {
        char path[4096];
        written = snprintf(path, sizeof path, "%s/%s", dir, file_name);
        if (written < 0 || (size_t)written >= sizeof path) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_model_desc_load_builtin: %s=%s is too long a path",
                                   MU_DATA_DIR_VARIABLE, dir);
        }
        return mu_model_desc_load(path, out);
    }
    const mu_embedded_file *file = mu_embedded_file_find(file_name);
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                               "mu_model_desc_load_builtin: no built-in model is named \"%s\", expected one of %s",
                               name, builtin_model_list());
    }
    char label[300];
    snprintf(label, sizeof label, "%s (built into libmu)", file_name);
    return parse_text(label, true, (const char *)file->data, file->size, out);
}

int mu_builtin_model_count(void) { return (int)mu_builtin_model_name_count; }

const char *mu_builtin_model_name(int index)
{
    if (index < 0 || (size_t)index >= mu_builtin_model_name_count) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "mu_builtin_model_name: index is %d, expected 0 to %d", index,
                        (int)mu_builtin_model_name_count - 1);
        return NULL;
    }
    return mu_builtin_model_names[index];
}

void mu_model_desc_destroy(mu_model_desc *desc)
{
    if (desc == NULL) {
        return;
    }
    mu_name_index_destroy(desc->object_names);
    mu_name_index_destroy(desc->variant_names);
    free(desc->name);
    free(desc->source);
    for (int i = 0; i < desc->nail_count; ++i) {
        free(desc->nails[i].name);
    }
    free(desc->nails);
    for (int i = 0; i < desc->bone_count; ++i) {
        free(desc->bones[i].name);
    }
    free(desc->bones);
    for (int i = 0; i < desc->hinge_count; ++i) {
        free(desc->hinges[i].name);
    }
    free(desc->hinges);
    for (int i = 0; i < desc->glue_count; ++i) {
        free(desc->glues[i].name);
    }
    free(desc->glues);
    free(desc->weight.name);
    free(desc->weight.masses);
    for (int i = 0; i < desc->muscle_count; ++i) {
        free(desc->muscles[i].name);
    }
    free(desc->muscles);
    for (int i = 0; i < desc->group_count; ++i) {
        free(desc->groups[i].name);
        free(desc->groups[i].muscles);
    }
    free(desc->groups);
    for (int i = 0; i < desc->torque_muscle_count; ++i) {
        free(desc->torque_muscles[i].name);
        free(desc->torque_muscles[i].pool_file);
        free(desc->torque_muscles[i].pool_path);
        free(desc->torque_muscles[i].strengths);
    }
    free(desc->torque_muscles);
    for (int i = 0; i < desc->variant_count; ++i) {
        free(desc->variants[i].name);
        free(desc->variants[i].muscles);
        free(desc->variants[i].bones);
    }
    free(desc->variants);
    free(desc);
}

static int object_count(const mu_model_desc *desc, mu_model_kind kind)
{
    switch (kind) {
    case MU_MODEL_NAIL:
        return desc->nail_count;
    case MU_MODEL_BONE:
        return desc->bone_count;
    case MU_MODEL_HINGE:
        return desc->hinge_count;
    case MU_MODEL_GLUE:
        return desc->glue_count;
    case MU_MODEL_WEIGHT:
        return desc->has_weight ? 1 : 0;
    case MU_MODEL_MUSCLE:
        return desc->muscle_count;
    case MU_MODEL_GROUP:
        return desc->group_count;
    case MU_MODEL_TORQUE_MUSCLE:
        return desc->torque_muscle_count;
    }
    return 0;
}

const char *mu_model_desc_name_of(const mu_model_desc *desc, mu_model_ref ref)
{
    const char *f = "mu_model_desc_name_of";
    if (mu_refuse_null(f, "desc", desc)) {
        return NULL;
    }
    if ((int)ref.kind < (int)MU_MODEL_NAIL || (int)ref.kind > (int)MU_MODEL_TORQUE_MUSCLE) {
        rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: ref.kind is %d, expected a mu_model_kind", f, (int)ref.kind);
        return NULL;
    }
    if (mu_refuse_index(f, "ref.index", ref.index, object_count(desc, ref.kind))) {
        return NULL;
    }
    switch (ref.kind) {
    case MU_MODEL_NAIL:
        return desc->nails[ref.index].name;
    case MU_MODEL_BONE:
        return desc->bones[ref.index].name;
    case MU_MODEL_HINGE:
        return desc->hinges[ref.index].name;
    case MU_MODEL_GLUE:
        return desc->glues[ref.index].name;
    case MU_MODEL_WEIGHT:
        return desc->weight.name;
    case MU_MODEL_MUSCLE:
        return desc->muscles[ref.index].name;
    case MU_MODEL_GROUP:
        return desc->groups[ref.index].name;
    case MU_MODEL_TORQUE_MUSCLE:
        return desc->torque_muscles[ref.index].name;
    }
    return NULL;
}

bool mu_model_desc_find(const mu_model_desc *desc, const char *name, mu_model_ref *out)
{
    const char *f = "mu_model_desc_find";
    if (mu_refuse_null(f, "desc", desc) || mu_refuse_null(f, "name", name) || mu_refuse_null(f, "out", out)) {
        return false;
    }
    int kind, index;
    if (mu_name_index_find(desc->object_names, name, &kind, &index)) {
        *out = (mu_model_ref){(mu_model_kind)kind, index};
        return true;
    }
    if (desc->object_names != NULL) {
        return false;
    }
    static const mu_model_kind kinds[] = {MU_MODEL_NAIL,   MU_MODEL_BONE,   MU_MODEL_HINGE, MU_MODEL_GLUE,
                                          MU_MODEL_WEIGHT, MU_MODEL_MUSCLE, MU_MODEL_GROUP, MU_MODEL_TORQUE_MUSCLE};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
        for (int i = 0; i < object_count(desc, kinds[k]); ++i) {
            mu_model_ref ref = {kinds[k], i};
            /* While a file is read, the object being read has no name yet. */
            const char *other = mu_model_desc_name_of(desc, ref);
            if (other != NULL && strcmp(other, name) == 0) {
                *out = ref;
                return true;
            }
        }
    }
    return false;
}

int mu_model_desc_find_variant(const mu_model_desc *desc, const char *name)
{
    const char *f = "mu_model_desc_find_variant";
    if (mu_refuse_null(f, "desc", desc) || mu_refuse_null(f, "name", name)) {
        return -1;
    }
    int kind, index;
    if (mu_name_index_find(desc->variant_names, name, &kind, &index)) {
        return index;
    }
    if (desc->variant_names != NULL) {
        return -1;
    }
    for (int i = 0; i < desc->variant_count; ++i) {
        if (desc->variants[i].name != NULL && strcmp(desc->variants[i].name, name) == 0) {
            return i;
        }
    }
    return -1;
}

static bool contains(const int *indices, int count, int index)
{
    for (int i = 0; i < count; ++i) {
        if (indices[i] == index) {
            return true;
        }
    }
    return false;
}

bool mu_model_variant_has_muscle(const mu_model_variant *variant, int index)
{
    return !mu_refuse_null("mu_model_variant_has_muscle", "variant", variant) &&
           contains(variant->muscles, variant->muscle_count, index);
}

bool mu_model_variant_has_bone(const mu_model_variant *variant, int index)
{
    return !mu_refuse_null("mu_model_variant_has_bone", "variant", variant) &&
           contains(variant->bones, variant->bone_count, index);
}
