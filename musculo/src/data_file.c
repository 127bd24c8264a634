/* SPDX-License-Identifier: MIT */
/* The muscle layer's data files, found in SINEW_DATA_DIR or compiled in. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "data_file.h"

const char *mu_data_dir(void)
{
    const char *dir = getenv(MU_DATA_DIR_VARIABLE);
    return dir != NULL && dir[0] != '\0' ? dir : NULL;
}

const mu_embedded_file *mu_embedded_file_find(const char *name)
{
    for (size_t i = 0; i < mu_embedded_file_count; ++i) {
        if (strcmp(mu_embedded_files[i].name, name) == 0) {
            return &mu_embedded_files[i];
        }
    }
    return NULL;
}

rb_status mu_data_file_open(const char *name, const char *function, mu_data_file *out)
{
    out->stream = NULL;
    const char *dir = mu_data_dir();
    if (dir != NULL) {
        int written = snprintf(out->label, sizeof out->label, "%s/%s", dir, name);
        if (written < 0 || (size_t)written >= sizeof out->label) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: %s=%s is too long a path, expected under %zu bytes",
                                   function, MU_DATA_DIR_VARIABLE, dir, sizeof out->label - sizeof "/" - strlen(name));
        }
        out->stream = fopen(out->label, "r");
        if (out->stream == NULL) {
            return rb_report_error(RB_ERR_INVALID_ARGUMENT,
                                   "%s: %s: cannot open the file: %s (%s is set: unset it to use the built-in copy)",
                                   function, out->label, strerror(errno), MU_DATA_DIR_VARIABLE);
        }
        return RB_OK;
    }
    const mu_embedded_file *file = mu_embedded_file_find(name);
    if (file == NULL) {
        return rb_report_error(RB_ERR_INVALID_ARGUMENT, "%s: no data file named %s is built into libmu", function,
                               name);
    }
    snprintf(out->label, sizeof out->label, "%s (built into libmu)", name);
    /* fmemopen takes a non-const buffer; in mode "r" it never writes it. */
    out->stream = fmemopen((void *)file->data, file->size, "r");
    if (out->stream == NULL) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "%s: cannot open the built-in %s: %s", function, name,
                               strerror(errno));
    }
    return RB_OK;
}

void mu_data_file_close(mu_data_file *file)
{
    if (file->stream != NULL) {
        fclose(file->stream);
        file->stream = NULL;
    }
}
