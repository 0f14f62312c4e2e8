/* The table libsoak_image.so (core/plugin/image_oiio.cpp, OpenImageIO)
 * exports as soak_image_plugin_v3; image.c calls it after the checks that
 * need no image library, in a child process with a time limit
 * (image_contain.c). The module calls nothing of libsoak: pixels go to the
 * caller's sink, encoded bytes are malloc'ed (the caller frees them). No
 * C++ exception leaves it. */
#ifndef SOAK_IMAGE_PLUGIN_H
#define SOAK_IMAGE_PLUGIN_H

#include <stddef.h>

#include "soak/image.h"

/* Where a read delivers its pixels: begin once with the size, then rows
 * in order as floats, channels interleaved; a non-zero return stops the
 * read (the sink has set nothing: the caller knows why). */
typedef struct soak_image_sink {
    void *ctx;
    int (*begin)(void *ctx, int width, int height, int channels);
    int (*rows)(void *ctx, const float *values, size_t n_values);
} soak_image_sink;

typedef struct soak_image_plugin {
    /* Decodes path (a regular file whose compressed pixel data is
     * payload_bytes, soak/image_check.h) to sink (channels capped at 4)
     * with the reader its extension names and no other, refusing from the
     * header what soak/image.h's limits refuse. Finite values are checked
     * by the caller. */
    soak_status (*read_to)(const char *path, long long payload_bytes, const soak_image_sink *sink, char *err,
                           size_t errlen);
    /* The size and channels (capped at 4) the header of path declares,
     * through the same reader as read, without decoding pixels. */
    soak_status (*probe)(const char *path, int *width, int *height, int *channels, char *err, size_t errlen);
    /* Encodes img in the format of path's extension ext (lower case) into a
     * malloc'ed buffer. opts is never NULL. */
    soak_status (*encode)(const char *path, const char *ext, const soak_image *img, const soak_image_write_opts *opts,
                          unsigned char **bytes, size_t *n_bytes, char *err, size_t errlen);
    /* Writes img as a mip-mapped tiled texture to the file tmp, read back;
     * path names the destination in messages. */
    soak_status (*write_tx)(const char *tmp, const char *path, const soak_image *img, char *err, size_t errlen);
} soak_image_plugin;

#define SOAK_IMAGE_PLUGIN_FILE "libsoak_image.so"
#define SOAK_IMAGE_PLUGIN_SYMBOL "soak_image_plugin_v3"

/* The loaded table, or NULL with err naming path and why the library could
 * not be opened (image_plugin.c). */
const soak_image_plugin *soak_image_plugin_for(const char *path, char *err, size_t errlen);

/* path's extension in lower case ("" when it has none or it is n or longer). */
void soak_image_extension_of(const char *path, char *ext, size_t n);

#endif
