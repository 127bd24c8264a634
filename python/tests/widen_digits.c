// SPDX-License-Identifier: MIT
/* A test-only shim, preloaded into the sinew program (LD_PRELOAD) by
 * test_run_matches_cli.py: its fprintf prints every "%.10g" conversion as
 * "%.17g", the digits that give a double back exactly (17 significant
 * digits suffice for every IEEE 754 double). The program's CSV writer
 * (tools/commands/recorder.c) prints 10, which shows whether two runs agree
 * to 10 digits but not to the bit; with this shim the same, unchanged
 * program writes a CSV whose every number is its double exactly.
 *
 * The program links the C library dynamically, so its fprintf calls come
 * here first; the rest of the format is left as it is, and the call goes on
 * to vfprintf with the same arguments (a "%.17g" takes the same double as
 * a "%.10g"). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fprintf(FILE *stream, const char *format, ...)
{
    static const char narrow[] = "%.10g";
    const size_t length = strlen(format);
    char *widened = malloc(length + 1);
    if (widened != NULL) {
        memcpy(widened, format, length + 1);
        for (char *at = strstr(widened, narrow); at != NULL; at = strstr(at + 1, narrow)) {
            at[3] = '7'; /* "%.10g" becomes "%.17g": the same length */
        }
    }
    va_list arguments;
    va_start(arguments, format);
    const int written = vfprintf(stream, widened != NULL ? widened : format, arguments);
    va_end(arguments);
    free(widened);
    return written;
}
