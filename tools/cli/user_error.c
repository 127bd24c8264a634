/* SPDX-License-Identifier: MIT */
#include <string.h>

#include "cli/user_error.h"
#include "rb/base.h"

/* The length of a library function's name and its ": " at the start of
 * `text`, or 0: "rb_" or "mu_", then lower-case letters, digits and '_'. */
static size_t function_prefix(const char *text)
{
    if (strncmp(text, "rb_", 3) != 0 && strncmp(text, "mu_", 3) != 0) {
        return 0;
    }
    size_t length = strspn(text, "abcdefghijklmnopqrstuvwxyz0123456789_");
    return text[length] == ':' && text[length + 1] == ' ' ? length + 2 : 0;
}

const char *user_error_text(const char *message)
{
    for (size_t skip = function_prefix(message); skip > 0; skip = function_prefix(message)) {
        message += skip;
    }
    return message;
}

const char *user_error(void) { return user_error_text(rb_last_error()); }
