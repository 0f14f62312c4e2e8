/* Image I/O for every part of Soak, through OpenImageIO (thin C++ shim).
 * Pixels are float, channel-interleaved, top row first, linear values.
 * Writes are atomic and checked: the image is encoded in memory, written to
 * an anonymous temporary in the destination folder, flushed to disk, and only
 * then given its name (soak/staged.h); a failed write is an error. */
#ifndef SOAK_IMAGE_H
#define SOAK_IMAGE_H

#include <stddef.h>
#include "soak/status.h"

typedef struct soak_image {
    int width, height, channels;
    float *pixels; /* width*height*channels floats, owned */
} soak_image;

typedef enum soak_tone {
    SOAK_TONE_LINEAR = 0, /* store values as they are (clamped for integer formats) */
    SOAK_TONE_SRGB        /* clamp to [0,1], apply the sRGB transfer curve (IEC 61966-2-1) */
} soak_tone;

typedef enum soak_pixel_type {
    SOAK_PIXEL_AUTO = 0, /* EXR: half, PNG/TIFF: uint16, JPEG: uint8 */
    SOAK_PIXEL_HALF,
    SOAK_PIXEL_FLOAT,
    SOAK_PIXEL_UINT16,
    SOAK_PIXEL_UINT8
} soak_pixel_type;

typedef struct soak_image_write_opts {
    soak_tone tone;
    soak_pixel_type pixel_type;
} soak_image_write_opts;

/* Allocates a zeroed image. */
soak_status soak_image_alloc(soak_image *img, int width, int height, int channels);
void soak_image_free(soak_image *img);

/* Largest image soak_image_read decodes: 1 GiB of float pixels (e.g.
 * 16384 x 16384 x 1, 8192 x 8192 x 4). */
#define SOAK_IMAGE_MAX_BYTES (1024.0 * 1024.0 * 1024.0)
/* Largest width or height of any image soak reads or makes: one limit for
 * every command (a 65536 x 1 map was read by render and refused by bake). */
#define SOAK_IMAGE_MAX_SIDE 16384
/* Compression-ratio rule: above SOAK_IMAGE_FREE_BYTES of float pixels, an
 * image may claim at most SOAK_IMAGE_MAX_RATIO float bytes per byte of its
 * compressed pixel data (PNG: the IDAT chunks; OpenEXR: the offset tables
 * and chunks after the headers; other formats: the whole file), so a
 * small file cannot make the reader allocate and decode gigabytes (a 249 KB
 * PNG claiming 16000 x 16000). 256 float bytes per byte is 64:1 on 8-bit
 * samples and 8:1 on 1-bit ones (deflate's own limit is 1032:1 on the
 * packed samples); it keeps any input under 2 MB below 512 MiB of float
 * pixels, where 1024 let 1.15 MB of real pixel data decode to 1 GiB and
 * `soak render` peak at 1.2 GB (issue 35). Below the floor any ratio is
 * allowed (uniform masks compress far better). Inputs that are not regular files
 * are refused before they are opened. */
#define SOAK_IMAGE_FREE_BYTES (256.0 * 1024.0 * 1024.0)
#define SOAK_IMAGE_MAX_RATIO 256.0

/* Reads any format OIIO reads, converting to float. err gets a message
 * naming the file on failure. A NaN or infinite pixel is an error
 * (SOAK_ERR_ARG naming the pixel), as is an image above SOAK_IMAGE_MAX_BYTES
 * or wider or taller than SOAK_IMAGE_MAX_SIDE (refused from its header,
 * before any decoding). The file is checked first (soak/input_file.h:
 * a regular file within SOAK_MAX_IMAGE_MB) and must be of the format its
 * extension names (soak/image_check.h): no other reader is tried. */
soak_status soak_image_read(const char *path, soak_image *img, char *err, size_t errlen);

/* What soak_image_read would decode, from the file's checks and header
 * alone (no pixels): width, height, channels (capped at 4) and the bytes of
 * compressed pixel data (soak/image_check.h), after the same input policy
 * and format checks. A command sizes its working memory from it before it
 * reads the image (soak_memory_check). */
typedef struct soak_image_info {
    int width, height, channels;
    long long payload_bytes;
} soak_image_info;
soak_status soak_image_probe(const char *path, soak_image_info *info, char *err, size_t errlen);

/* Memory a command may use for its working buffers, given the bytes of
 * compressed data its inputs hold: SOAK_MAX_MEMORY_MB when set (MiB, in
 * [64, 1e7]), else max(SOAK_MEMORY_FREE_BYTES, SOAK_MEMORY_RATIO x
 * input_bytes), at most half the machine's memory. A small file cannot
 * make a command allocate gigabytes (a 1.16 MB PNG made bake drying take
 * 5.6 GB); a large real input earns a large budget. */
#define SOAK_MEMORY_FREE_BYTES (1024.0 * 1024.0 * 1024.0)
#define SOAK_MEMORY_RATIO 256.0
double soak_memory_budget(long long input_bytes);
/* SOAK_ERR_ARG with "<what> needs about N MiB ... the budget is M MiB
 * (SOAK_MAX_MEMORY_MB raises it)" when estimate_bytes exceeds the budget. */
soak_status soak_memory_check(const char *what, double estimate_bytes, long long input_bytes, char *err,
                              size_t errlen);

/* Writes by extension (.exr .png .tif/.tiff .jpg .hdr ...). Linear PNGs carry
 * a gAMA 1.0 chunk so POV-Ray and viewers do not sRGB-decode them; sRGB-toned
 * PNGs carry the sRGB chunk. opts may be NULL (linear, auto type). */
soak_status soak_image_write(const char *path, const soak_image *img, const soak_image_write_opts *opts,
                             char *err, size_t errlen);

/* Mip-mapped tiled texture (.tx) for OSL via OIIO's make_texture. */
soak_status soak_image_write_tx(const char *path, const soak_image *img, char *err, size_t errlen);

/* The same two writes as members of a set of outputs replaced together
 * (soak/staged.h): nothing reaches path before soak_staged_commit. */
struct soak_staged;
soak_status soak_image_stage(struct soak_staged *stage, const char *path, const soak_image *img,
                             const soak_image_write_opts *opts, char *err, size_t errlen);
soak_status soak_image_stage_tx(struct soak_staged *stage, const char *path, const soak_image *img, char *err,
                                size_t errlen);

/* 1 if both paths name the same existing file (same device and inode), or are
 * equal strings; used to refuse overwriting an input. */
int soak_path_same(const char *a, const char *b);

/* 0 if path is acceptable as an output (see soak/staged.h) and the folder
 * that would contain it exists and is writable; for an image extension
 * also soak_image_output_ready. */
soak_status soak_path_check_writable(const char *path, char *err, size_t errlen);

/* For a path with an image extension (.exr .png .tif .tiff .jpg .jpeg .hdr
 * .tx), opens the image module (soak/plugin.h) now, so that a command checking
 * its outputs fails before its work when the module is missing, and pays for
 * OpenImageIO at start-up rather than after an interrupt; 0 otherwise. */
soak_status soak_image_output_ready(const char *path, char *err, size_t errlen);

#endif
