/* SPDX-License-Identifier: MIT */
#include <ctype.h>
#include <stdbool.h>
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
    /* A message may quote another inside it ("muscle 'X': rb_cable_create:
     * ..."), so every name at the start of a word goes, not only the
     * first. The text is copied, up to the size of the engine's messages
     * and more. */
    static _Thread_local char text[2048];
    size_t used = 0;
    for (const char *read = message; *read != '\0' && used + 1 < sizeof text;) {
        const bool word_start = read == message || !(isalnum((unsigned char)read[-1]) || read[-1] == '_');
        const size_t skip = word_start ? function_prefix(read) : 0;
        if (skip > 0) {
            read += skip;
        } else {
            text[used++] = *read++;
        }
    }
    text[used] = '\0';
    return text;
}

const char *user_error(void) { return user_error_text(rb_last_error()); }
