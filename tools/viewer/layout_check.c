/* SPDX-License-Identifier: MIT */
#include <stdio.h>

#include "layout_check.h"

/* Half a pixel: allocations are whole pixels, bounds may be rounded. */
#define LAYOUT_SLACK_PX 0.5

/* Widgets checked whole: their inner parts (a spin button's text and
 * buttons, a slider's knob, which may stand out of its trough) are
 * theirs to lay out. */
static bool is_control(GtkWidget *widget)
{
    return GTK_IS_BUTTON(widget) || GTK_IS_DROP_DOWN(widget) || GTK_IS_SPIN_BUTTON(widget) || GTK_IS_RANGE(widget) ||
           GTK_IS_CHECK_BUTTON(widget) || GTK_IS_LABEL(widget) || GTK_IS_DRAWING_AREA(widget) || GTK_IS_ENTRY(widget) ||
           GTK_IS_SWITCH(widget);
}

/* A widget as a message names it: its type, and its text if it has one. */
static void describe(GtkWidget *widget, char *text, size_t text_size)
{
    const char *label = NULL;
    if (GTK_IS_BUTTON(widget)) {
        label = gtk_button_get_label(GTK_BUTTON(widget));
    } else if (GTK_IS_CHECK_BUTTON(widget)) {
        label = gtk_check_button_get_label(GTK_CHECK_BUTTON(widget));
    } else if (GTK_IS_LABEL(widget)) {
        label = gtk_label_get_text(GTK_LABEL(widget));
    } else if (GTK_IS_FRAME(widget)) {
        label = gtk_frame_get_label(GTK_FRAME(widget));
    }
    if (label != NULL && label[0] != '\0') {
        snprintf(text, text_size, "%s \"%.40s%s\"", G_OBJECT_TYPE_NAME(widget), label,
                 g_utf8_strlen(label, -1) > 40 ? "..." : "");
    } else {
        snprintf(text, text_size, "%s", G_OBJECT_TYPE_NAME(widget));
    }
}

/* Whether `child` lies within `parent` (its allocation's rectangle). */
static bool fits(GtkWidget *child, GtkWidget *parent, char *error, size_t error_size)
{
    graphene_rect_t bounds;
    if (!gtk_widget_compute_bounds(child, parent, &bounds)) {
        return true; /* not allocated in that parent: nothing drawn to cut */
    }
    double width = gtk_widget_get_width(parent), height = gtk_widget_get_height(parent);
    double left = bounds.origin.x, top = bounds.origin.y;
    double right = left + bounds.size.width, bottom = top + bounds.size.height;
    if (left >= -LAYOUT_SLACK_PX && top >= -LAYOUT_SLACK_PX && right <= width + LAYOUT_SLACK_PX &&
        bottom <= height + LAYOUT_SLACK_PX) {
        return true;
    }
    char what[128], where[128];
    describe(child, what, sizeof what);
    describe(parent, where, sizeof where);
    snprintf(error, error_size,
             "%s is cut off by its %s: it spans x %.0f .. %.0f, y %.0f .. %.0f px, the %s 0 .. %.0f, 0 .. %.0f", what,
             where, left, right, top, bottom, where, width, height);
    return false;
}

/* Whether the content of a scrolled window passes its view along one
 * adjustment. */
static bool overflows(GtkAdjustment *adjustment)
{
    return gtk_adjustment_get_upper(adjustment) - gtk_adjustment_get_lower(adjustment) >
           gtk_adjustment_get_page_size(adjustment) + LAYOUT_SLACK_PX;
}

/* A scrolled window whose content is larger than its view must show the
 * scrollbar that reaches the rest: one its policy allows, and not an
 * overlay. */
static bool scrollbar_shown(GtkWidget *widget, char *error, size_t error_size)
{
    GtkScrolledWindow *scrolled = GTK_SCROLLED_WINDOW(widget);
    GtkPolicyType policies[2];
    gtk_scrolled_window_get_policy(scrolled, &policies[0], &policies[1]);
    GtkAdjustment *adjustments[2] = {gtk_scrolled_window_get_hadjustment(scrolled),
                                     gtk_scrolled_window_get_vadjustment(scrolled)};
    static const char *const directions[2] = {"wide", "tall"};
    for (int k = 0; k < 2; ++k) {
        if (!overflows(adjustments[k])) {
            continue;
        }
        const char *problem = policies[k] == GTK_POLICY_NEVER || policies[k] == GTK_POLICY_EXTERNAL
                                  ? "it has no scrollbar that way: the rest is cut off"
                              : gtk_scrolled_window_get_overlay_scrolling(scrolled)
                                  ? "its scrollbar is an overlay, hidden until the pointer moves over it"
                                  : NULL;
        if (problem != NULL) {
            snprintf(error, error_size, "a GtkScrolledWindow's content is %.0f px %s in a view of %.0f px, and %s",
                     gtk_adjustment_get_upper(adjustments[k]) - gtk_adjustment_get_lower(adjustments[k]), directions[k],
                     gtk_adjustment_get_page_size(adjustments[k]), problem);
            return false;
        }
    }
    return true;
}

static bool check_children(GtkWidget *parent, int *checked, char *error, size_t error_size)
{
    if (GTK_IS_SCROLLED_WINDOW(parent) && !scrollbar_shown(parent, error, error_size)) {
        return false;
    }
    for (GtkWidget *child = gtk_widget_get_first_child(parent); child != NULL;
         child = gtk_widget_get_next_sibling(child)) {
        if (!gtk_widget_get_mapped(child) || GTK_IS_NATIVE(child)) {
            continue;
        }
        /* A viewport's child is the scrolled content, larger than the
         * view by design. */
        if (!GTK_IS_VIEWPORT(parent) && !fits(child, parent, error, error_size)) {
            return false;
        }
        *checked += 1;
        if (!is_control(child) && !check_children(child, checked, error, error_size)) {
            return false;
        }
    }
    return true;
}

bool layout_check_window(GtkWidget *window, int *checked, char *error, size_t error_size)
{
    *checked = 0;
    return check_children(window, checked, error, error_size);
}
