/* SPDX-License-Identifier: MIT */
/* The words of one line of a text file that people write by hand: the
 * control files of `sinew run --control` and the viewer's scripts
 * (`sinew view --script`) share these rules, so that a name is quoted the
 * same way in both.
 *
 *   - spaces and tabs separate words (and a line's '\r' and '\n' end it);
 *   - a word that starts with '"' runs to the next '"', so it may hold
 *     spaces or a '#' ("Biceps Short"); the quotes are not part of it, and
 *     "" is an empty word; there are no escapes;
 *   - a closing quote must be followed by a space, a tab, a '#' or the end
 *     of the line: `"a"b` is more likely a mistake than two words;
 *   - '#' outside quotes starts a comment, to the end of the line.
 */
#ifndef CLI_WORDS_H
#define CLI_WORDS_H

#include <stddef.h>

/* Splits `line` in place (quotes and separators become NULs) and stores
 * pointers to its first `capacity` words in `words`. Returns how many
 * words the line has, which may be more than `capacity` (so that a caller
 * can name the first extra word when it has room for it), or -1 with
 * *problem set to a phrase for a quote left open or followed by text. */
int words_split(char *line, char **words, int capacity, const char **problem);

#endif
