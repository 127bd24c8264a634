/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "widget_input.h"

static bool parse_number(const char *text, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    return end != text && *end == '\0' && errno == 0;
}

static bool parse_switch(const char *text, gboolean *out, char *error, size_t error_size)
{
    if (strcmp(text, "on") != 0 && strcmp(text, "off") != 0) {
        snprintf(error, error_size, "expected on or off, got \"%s\"", text);
        return false;
    }
    *out = strcmp(text, "on") == 0;
    return true;
}

static bool select_item(GtkDropDown *drop_down, const char *value, char *error, size_t error_size)
{
    GListModel *items = gtk_drop_down_get_model(drop_down);
    guint count = items != NULL ? g_list_model_get_n_items(items) : 0;
    for (guint k = 0; k < count; ++k) {
        GtkStringObject *item = g_list_model_get_item(items, k);
        bool same = strcmp(gtk_string_object_get_string(item), value) == 0;
        g_object_unref(item);
        if (same) {
            gtk_drop_down_set_selected(drop_down, k);
            return true;
        }
    }
    snprintf(error, error_size, "no choice \"%s\" among the %u offered", value, count);
    return false;
}

bool widget_input_set(GtkWidget *widget, const char *value, char *error, size_t error_size)
{
    double number;
    gboolean active;
    if (!gtk_widget_is_sensitive(widget)) {
        snprintf(error, error_size, "the control is not available now");
        return false;
    }
    if (GTK_IS_DROP_DOWN(widget)) {
        return select_item(GTK_DROP_DOWN(widget), value, error, error_size);
    }
    if (GTK_IS_SPIN_BUTTON(widget) || GTK_IS_RANGE(widget)) {
        if (!parse_number(value, &number)) {
            snprintf(error, error_size, "expected a number, got \"%s\"", value);
            return false;
        }
        /* Out of the control's range, or a fraction for a whole-number
         * control, is an error as it is on the command line: GTK would
         * clamp or round it without a word. */
        GtkAdjustment *adjustment = GTK_IS_SPIN_BUTTON(widget) ? gtk_spin_button_get_adjustment(GTK_SPIN_BUTTON(widget))
                                                               : gtk_range_get_adjustment(GTK_RANGE(widget));
        double lower = gtk_adjustment_get_lower(adjustment);
        double upper = gtk_adjustment_get_upper(adjustment) - gtk_adjustment_get_page_size(adjustment);
        if (!(number >= lower && number <= upper)) {
            snprintf(error, error_size, "%s is out of range, expected %g to %g", value, lower, upper);
            return false;
        }
        if (GTK_IS_SPIN_BUTTON(widget)) {
            if (gtk_spin_button_get_digits(GTK_SPIN_BUTTON(widget)) == 0 && number != floor(number)) {
                snprintf(error, error_size, "%s is not a whole number", value);
                return false;
            }
            gtk_spin_button_set_value(GTK_SPIN_BUTTON(widget), number);
        } else {
            gtk_range_set_value(GTK_RANGE(widget), number);
        }
        return true;
    }
    if (GTK_IS_CHECK_BUTTON(widget) || GTK_IS_TOGGLE_BUTTON(widget)) {
        if (!parse_switch(value, &active, error, error_size)) {
            return false;
        }
        if (GTK_IS_CHECK_BUTTON(widget)) {
            gtk_check_button_set_active(GTK_CHECK_BUTTON(widget), active);
        } else {
            gtk_toggle_button_set_active(GTK_TOGGLE_BUTTON(widget), active);
        }
        return true;
    }
    if (GTK_IS_BUTTON(widget)) {
        g_signal_emit_by_name(widget, "clicked");
        return true;
    }
    snprintf(error, error_size, "this control cannot be set from a script");
    return false;
}
