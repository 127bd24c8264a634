/* SPDX-License-Identifier: MIT */
/* Parsing the value of one command-line option, with the checks the tools
 * share: the whole text must be the value (no trailing characters), and a
 * number must lie in its range.
 *
 * The option parser (cli/options.h) checks every option's value with
 * them; the tools use them too for values inside a value (`--recruit
 * NAME=N`) and for a scene's parameters. Each function takes the option's
 * name (only for the message) and the value's text. On success it stores
 * the value in *out and returns true. On failure *out is unchanged, `error` receives a message naming the
 * option, what it expects and the text given (truncated to error_size
 * bytes), and the function returns false; the caller prefixes its program
 * name and prints it.
 */
#ifndef CLI_OPTION_VALUE_H
#define CLI_OPTION_VALUE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Bytes of an error buffer that holds the messages whole unless the text
 * given is very long. */
#define OPTION_ERROR_SIZE 512

/* A decimal integer in [min, max]; INT_MIN <= min <= max <= INT_MAX. */
bool option_parse_int(const char *option, const char *text, long min, long max, int *out, char *error,
                      size_t error_size);

/* A finite decimal number (nan and inf are refused) in [min, max], or in
 * (min, max] when min_open. */
bool option_parse_double(const char *option, const char *text, double min, bool min_open, double max, double *out,
                         char *error, size_t error_size);

/* A decimal integer in [0, 2^64 - 1]; a minus sign is refused rather than
 * wrapped around as strtoull would. */
bool option_parse_u64(const char *option, const char *text, uint64_t *out, char *error, size_t error_size);

/* A file name: any non-empty text. *out points into `text`. */
bool option_parse_path(const char *option, const char *text, const char **out, char *error, size_t error_size);

#endif
