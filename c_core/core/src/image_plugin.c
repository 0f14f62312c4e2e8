/* The image library's table, opened once on first use (soak/plugin.h), and
 * the file-name rule that picks a codec. Its own unit so that the staged
 * writer can ask whether an image output can be written without depending
 * on the image reader and writer that stage through it. */
#include "image_plugin.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "soak/plugin.h"

/* Written once under pthread_once, read-only afterwards (soak/plugin.h). */
static soak_plugin_slot image_slot =
    SOAK_PLUGIN_SLOT(SOAK_IMAGE_PLUGIN_FILE, SOAK_IMAGE_PLUGIN_SYMBOL, "image I/O (OpenImageIO)");

static void image_slot_fill(void) { soak_plugin_slot_fill(&image_slot); }

const soak_image_plugin *soak_image_plugin_for(const char *path, char *err, size_t errlen)
{
    pthread_once(&image_slot.once, image_slot_fill);
    char why[1600];
    const soak_image_plugin *p = soak_plugin_slot_table(&image_slot, why, sizeof why);
    if (!p && err && errlen) snprintf(err, errlen, "%s: %s", path, why);
    return p;
}

/* path's extension in lower case ("" when it has none). */
void soak_image_extension_of(const char *path, char *ext, size_t n)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    ext[0] = '\0';
    if (!dot || (slash && dot < slash) || strlen(dot + 1) >= n) return;
    size_t i = 0;
    for (const char *c = dot + 1; *c; ++c) ext[i++] = (char)(*c >= 'A' && *c <= 'Z' ? *c - 'A' + 'a' : *c);
    ext[i] = '\0';
}

soak_status soak_image_output_ready(const char *path, char *err, size_t errlen)
{
    static const char *const image_ext[] = {"exr", "png", "tif", "tiff", "jpg", "jpeg", "hdr", "tx"};
    if (!path) return SOAK_ERR_NULL;
    char ext[32];
    soak_image_extension_of(path, ext, sizeof ext);
    for (size_t i = 0; i < sizeof image_ext / sizeof image_ext[0]; ++i)
        if (!strcmp(ext, image_ext[i]))
            return soak_image_plugin_for(path, err, errlen) ? SOAK_OK : SOAK_ERR_UNSUPPORTED;
    return SOAK_OK;
}
