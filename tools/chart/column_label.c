/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <string.h>

#include "chart/column_label.h"

/* The unit suffixes sinew writes, longest first so that "_m_s" is read as
 * metres per second and not as seconds. */
static const struct {
    const char *suffix;
    const char *unit;
} suffixes[] = {
    {"_rad_s", "rad/s"}, {"_deg_s", "deg/s"}, {"_mm_s", "mm/s"}, {"_m_s", "m/s"}, {"_N_m", "N·m"}, {"_deg", "deg"},
    {"_rad", "rad"},     {"_mm", "mm"},       {"_ms", "ms"},     {"_kg", "kg"},   {"_Hz", "Hz"},   {"_N", "N"},
    {"_m", "m"},         {"_s", "s"},         {"_J", "J"},       {"_W", "W"},
};

/* Where the unit starts in `name` (its suffix or its " [" bracket) and
 * the unit's text; NULL when the name shows no unit. */
static const char *find_unit(const char *name, const char **unit, size_t *unit_length)
{
    size_t length = strlen(name);
    const char *open = strrchr(name, '[');
    if (length > 2 && name[length - 1] == ']' && open != NULL && open > name) {
        *unit = open + 1;
        *unit_length = (size_t)(name + length - 1 - *unit);
        return open;
    }
    for (size_t k = 0; k < sizeof suffixes / sizeof suffixes[0]; ++k) {
        size_t suffix_length = strlen(suffixes[k].suffix);
        if (length > suffix_length && strcmp(name + length - suffix_length, suffixes[k].suffix) == 0) {
            *unit = suffixes[k].unit;
            *unit_length = strlen(suffixes[k].unit);
            return name + length - suffix_length;
        }
    }
    return NULL;
}

void column_unit(const char *name, char *unit, size_t unit_size)
{
    const char *text;
    size_t length;
    if (find_unit(name, &text, &length) == NULL) {
        snprintf(unit, unit_size, "%s", "");
        return;
    }
    snprintf(unit, unit_size, "%.*s", (int)length, text);
}

void column_label(const char *name, char *label, size_t label_size)
{
    const char *unit;
    size_t unit_length;
    const char *end = find_unit(name, &unit, &unit_length);
    if (end == NULL) {
        snprintf(label, label_size, "%s", name);
        return;
    }
    while (end > name && end[-1] == ' ') {
        --end; /* "force [N]": the space before the bracket */
    }
    int written = snprintf(label, label_size, "%.*s (%.*s)", (int)(end - name), name, (int)unit_length, unit);
    size_t quantity_end = written > 0 ? (size_t)(end - name) : 0;
    for (size_t i = 0; i < quantity_end && i < label_size; ++i) {
        label[i] = label[i] == '_' ? ' ' : label[i];
    }
}
