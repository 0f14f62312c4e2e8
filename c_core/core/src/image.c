/* soak/image.h: everything that needs no image library is here; decoding
 * and encoding go to libsoak_image.so (OpenImageIO), opened on the first
 * image a command reads or writes (soak/plugin.h). */
#define _GNU_SOURCE
#include "soak/image.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "image_contain.h"
#include "image_plugin.h"
#include "stderr_capture.h"
#include "soak/image_check.h"
#include "soak/input_file.h"
#include "soak/staged.h"

int soak_path_same(const char *a, const char *b)
{
    if (!a || !b) return 0;
    if (strcmp(a, b) == 0) return 1;
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* First non-finite value, as a message naming pixel and channel. */
static soak_status check_finite(const char *path, const soak_image *img, char *err, size_t errlen)
{
    size_t n = (size_t)img->width * img->height * img->channels;
    for (size_t i = 0; i < n; ++i) {
        if (isfinite(img->pixels[i])) continue;
        size_t px = i / img->channels;
        if (err && errlen)
            snprintf(err, errlen, "%s: pixel (%zu, %zu) channel %zu is %s: images must hold finite values", path,
                     px % img->width, px / img->width, i % img->channels, isnan(img->pixels[i]) ? "NaN" : "infinite");
        return SOAK_ERR_ARG;
    }
    return SOAK_OK;
}

/* One line: OpenImageIO's messages span lines ("...\nPNG library error"). */
static void one_line(char *err, size_t errlen)
{
    if (!err || !errlen) return;
    size_t n = strnlen(err, errlen - 1);
    while (n > 0 && (err[n - 1] == '\n' || err[n - 1] == ' ')) err[--n] = '\0';
    for (char *c = err; *c; ++c)
        if (*c == '\n') *c = ';';
}

soak_status soak_image_read(const char *path, soak_image *img, char *err, size_t errlen)
{
    if (!path || !img) return SOAK_ERR_NULL;
    img->pixels = NULL;
    long long size = 0;
    soak_status st = soak_input_check(path, SOAK_INPUT_IMAGE, &size, err, errlen);
    if (st != SOAK_OK) return st;
    /* Headers an image library would allocate from are checked on the bytes
     * first (soak/image_check.h: a 566-byte EXR made OpenEXR allocate 1.7 GB). */
    long long payload = size;
    st = soak_image_check_header(path, &payload, err, errlen);
    if (st != SOAK_OK) return st;
    const soak_image_plugin *p = soak_image_plugin_for(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    st = soak_image_read_contained(p, path, payload, img, err, errlen);
    if (st != SOAK_OK) {
        one_line(err, errlen);
        soak_image_free(img);
        return st;
    }
    st = check_finite(path, img, err, errlen);
    if (st != SOAK_OK) soak_image_free(img);
    return st;
}

soak_status soak_image_probe(const char *path, soak_image_info *info, char *err, size_t errlen)
{
    if (!path || !info) return SOAK_ERR_NULL;
    long long size = 0;
    soak_status st = soak_input_check(path, SOAK_INPUT_IMAGE, &size, err, errlen);
    if (st != SOAK_OK) return st;
    info->payload_bytes = size;
    st = soak_image_check_header(path, &info->payload_bytes, err, errlen);
    if (st != SOAK_OK) return st;
    const soak_image_plugin *p = soak_image_plugin_for(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    soak_stderr_capture quiet;
    soak_stderr_capture_begin(&quiet);
    st = p->probe(path, &info->width, &info->height, &info->channels, err, errlen);
    soak_stderr_capture_end(&quiet);
    if (st != SOAK_OK) one_line(err, errlen);
    return st;
}

soak_status soak_image_stage(soak_staged *stage, const char *path, const soak_image *img,
                             const soak_image_write_opts *opts, char *err, size_t errlen)
{
    if (!stage || !path || !img || !img->pixels) return SOAK_ERR_NULL;
    soak_status st = soak_output_path_check(path, err, errlen);
    if (st != SOAK_OK) return st;
    char ext[32];
    soak_image_extension_of(path, ext, sizeof ext);
    if (!ext[0]) {
        if (err && errlen) snprintf(err, errlen, "%s: output needs an extension (.exr, .png, .tif, ...)", path);
        return SOAK_ERR_ARG;
    }
    soak_image_write_opts o = {SOAK_TONE_LINEAR, SOAK_PIXEL_AUTO};
    if (opts) o = *opts;
    const soak_image_plugin *p = soak_image_plugin_for(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    unsigned char *bytes = NULL;
    size_t n = 0;
    st = p->encode(path, ext, img, &o, &bytes, &n, err, errlen);
    if (st == SOAK_OK) st = soak_staged_write(stage, path, bytes, n, err, errlen);
    free(bytes);
    return st;
}

soak_status soak_image_write(const char *path, const soak_image *img, const soak_image_write_opts *opts, char *err,
                             size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_image_stage(&stage, path, img, opts, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}

soak_status soak_image_stage_tx(soak_staged *stage, const char *path, const soak_image *img, char *err,
                                size_t errlen)
{
    if (!stage || !path || !img || !img->pixels) return SOAK_ERR_NULL;
    const soak_image_plugin *p = soak_image_plugin_for(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    const char *tmp = NULL;
    soak_status st = soak_staged_add(stage, path, &tmp, err, errlen);
    if (st != SOAK_OK) return st;
    return p->write_tx(tmp, path, img, err, errlen);
}

soak_status soak_image_write_tx(const char *path, const soak_image *img, char *err, size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_image_stage_tx(&stage, path, img, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}
