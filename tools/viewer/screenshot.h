/* SPDX-License-Identifier: MIT */
/* A screenshot of the whole window as a PNG: the window's widgets are
 * snapshotted as they are now and rendered by the window's own renderer
 * (GSK; Cairo under GSK_RENDERER=cairo), then written under a temporary
 * name and renamed into place (io/atomic_file.h).
 */
#ifndef VIEWER_SCREENSHOT_H
#define VIEWER_SCREENSHOT_H

#include <gtk/gtk.h>
#include <stdbool.h>
#include <stddef.h>

/* False with `error` saying why when the window is not shown yet or the
 * file cannot be written. */
bool screenshot_window(GtkWidget *window, const char *path, char *error, size_t error_size);

#endif
