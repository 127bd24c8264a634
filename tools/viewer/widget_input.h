/* SPDX-License-Identifier: MIT */
/* Sets a control of the window as a user would, from text, so that its
 * own signal handlers run: what the script's `set CONTROL VALUE` does.
 * A drop-down takes the text of one of its items, a spin button or a
 * slider a number, a check or toggle button "on" or "off", a button any
 * value (it is clicked).
 */
#ifndef VIEWER_WIDGET_INPUT_H
#define VIEWER_WIDGET_INPUT_H

#include <gtk/gtk.h>
#include <stdbool.h>
#include <stddef.h>

/* False, with `error` saying what the control expects, for a value it
 * cannot take or a control that is insensitive now. */
bool widget_input_set(GtkWidget *widget, const char *value, char *error, size_t error_size);

#endif
