/* SPDX-License-Identifier: MIT */
#include <stdbool.h>
#include <string.h>

#include "cli/words.h"

static const char separators[] = " \t\r\n";

int words_split(char *line, char **words, int capacity, const char **problem)
{
    int count = 0;
    char *at = line;
    for (;;) {
        at += strspn(at, separators);
        if (*at == '\0' || *at == '#') {
            return count;
        }
        char *word = at;
        bool line_ends = false;
        if (*at == '"') {
            char *close = strchr(at + 1, '"');
            if (close == NULL) {
                *problem = "a quote is not closed";
                return -1;
            }
            if (close[1] != '\0' && close[1] != '#' && strchr(separators, close[1]) == NULL) {
                *problem = "a closing quote is followed by other text; put a space after it";
                return -1;
            }
            *close = '\0';
            word = at + 1;
            at = close + 1; /* a '#' there is seen by the next round */
        } else {
            at += strcspn(at, " \t\r\n#");
            line_ends = *at == '\0' || *at == '#';
            *at = '\0';
            at += !line_ends;
        }
        if (count < capacity) {
            words[count] = word;
        }
        ++count;
        if (line_ends) {
            return count;
        }
    }
}
