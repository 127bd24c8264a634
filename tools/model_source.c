#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "model_source.h"

const char *const model_builtin_names[MODEL_BUILTIN_COUNT] = {"sample", "arm", "leg", "worm"};

static bool ends_with(const char *text, const char *suffix)
{
    size_t length = strlen(text);
    size_t suffix_length = strlen(suffix);
    return length >= suffix_length && strcmp(text + length - suffix_length, suffix) == 0;
}

bool model_source_is_builtin(const char *argument)
{
    for (int k = 0; k < MODEL_BUILTIN_COUNT; ++k) {
        if (strcmp(argument, model_builtin_names[k]) == 0) {
            return true;
        }
    }
    return false;
}

int model_source_load(const char *argument, mu_model_desc **out)
{
    *out = NULL;
    rb_status status;
    if (model_source_is_builtin(argument)) {
        status = mu_model_desc_load_builtin(argument, out);
    } else if (strchr(argument, '/') != NULL || ends_with(argument, ".json")) {
        status = mu_model_desc_load(argument, out);
    } else {
        /* A bare word that is not a built-in is more likely a misspelt
         * name than a file in the current directory; ./NAME reads one. */
        fprintf(stderr, "sinew: unknown model \"%s\" (built-in: sample, arm, leg; or a path to a .json file)\n",
                argument);
        return EXIT_USAGE;
    }
    if (status != RB_OK) {
        fprintf(stderr, "sinew: %s\n", rb_last_error());
        return EXIT_FAILURE;
    }
    return 0;
}

void model_source_stem(const char *argument, char *stem, size_t stem_size)
{
    const char *slash = strrchr(argument, '/');
    const char *name = slash != NULL ? slash + 1 : argument;
    size_t length = strlen(name);
    if (ends_with(name, ".json")) {
        length -= strlen(".json");
    }
    if (length == 0) {
        snprintf(stem, stem_size, "model"); /* ".json" alone: still a usable file name */
        return;
    }
    snprintf(stem, stem_size, "%.*s", (int)length, name);
}
