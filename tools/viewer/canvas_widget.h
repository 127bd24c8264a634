/* SPDX-License-Identifier: MIT */
/* The simulation canvas as a GTK widget: draws through canvas_draw; the
 * mouse wheel zooms about the cursor, a right click resets the view, a
 * drag of the background pans and a drag of a body pulls it with a mouse
 * joint. The keys act on the whole window unless the focused widget
 * takes them (the canvas takes the focus when clicked, and has it at the
 * start): space pulses the selected muscle or group for one frame at
 * activation 1, Up and Down recruit more or fewer neurons of the worm's
 * motor pool, P plays or pauses, S steps one frame.
 */
#ifndef VIEWER_CANVAS_WIDGET_H
#define VIEWER_CANVAS_WIDGET_H

#include <gtk/gtk.h>

#include "viewer.h"

/* Zoom per wheel notch. */
#define CANVAS_ZOOM_STEP 1.15

/* Creates the drawing area (app->canvas) and puts the keys on app->window. */
GtkWidget *canvas_widget_new(viewer *app);

#endif
