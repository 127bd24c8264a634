/* SPDX-License-Identifier: MIT */
#include <stdio.h>

#include "io/atomic_file.h"
#include "screenshot.h"

static bool write_bytes(GBytes *bytes, const char *path, char *error, size_t error_size)
{
    atomic_file file = {0};
    if (!atomic_file_open(&file, path, error, error_size)) {
        return false;
    }
    gsize size;
    const void *data = g_bytes_get_data(bytes, &size);
    fwrite(data, 1, size, file.stream);
    return atomic_file_commit(&file, error, error_size);
}

bool screenshot_window(GtkWidget *window, const char *path, char *error, size_t error_size)
{
    int width = gtk_widget_get_width(window), height = gtk_widget_get_height(window);
    GskRenderer *renderer = gtk_native_get_renderer(GTK_NATIVE(window));
    if (!gtk_widget_get_mapped(window) || width <= 0 || height <= 0 || renderer == NULL) {
        snprintf(error, error_size, "screenshot %s: the window is not shown yet", path);
        return false;
    }
    GdkPaintable *paintable = gtk_widget_paintable_new(window);
    GtkSnapshot *snapshot = gtk_snapshot_new();
    gdk_paintable_snapshot(paintable, snapshot, width, height);
    GskRenderNode *node = gtk_snapshot_free_to_node(snapshot);
    g_object_unref(paintable);
    if (node == NULL) {
        snprintf(error, error_size, "screenshot %s: the window drew nothing", path);
        return false;
    }
    graphene_rect_t bounds = GRAPHENE_RECT_INIT(0.0f, 0.0f, (float)width, (float)height);
    GdkTexture *texture = gsk_renderer_render_texture(renderer, node, &bounds);
    gsk_render_node_unref(node);
    GBytes *png = gdk_texture_save_to_png_bytes(texture);
    g_object_unref(texture);
    bool written = write_bytes(png, path, error, error_size);
    g_bytes_unref(png);
    return written;
}
