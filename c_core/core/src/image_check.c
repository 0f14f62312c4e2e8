/* OpenEXR header pre-parse (soak/image_check.h). Layout from the OpenEXR
 * file-layout document: magic, version word, then per part a list of
 * attributes (name\0 type\0 int32 size, value) ending with a zero byte;
 * multi-part files end the list of headers with one more zero byte. */
#define _POSIX_C_SOURCE 200809L
#include "soak/image_check.h"

#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "soak/image.h"
#include "soak/input_file.h"
#include "image_check_png.h"

#define EXR_TILED 0x200u
#define EXR_LONG_NAMES 0x400u
#define EXR_NON_IMAGE 0x800u
#define EXR_MULTIPART 0x1000u
#define EXR_MAX_PARTS 1024

typedef struct exr_cursor {
    FILE *f;
    const char *path;
    long long size, pos;
    long long payload; /* bytes after the last header: offset tables and chunks */
    char *err;
    size_t errlen;
} exr_cursor;

typedef struct exr_part {
    int have_channels, have_compression, have_window, have_tiles, deep;
    int channels, compression;
    long long bytes_per_pixel; /* file bytes of one pixel, all channels */
    int32_t window[4];
    uint32_t tile_w, tile_h;
} exr_part;

static soak_status fail(exr_cursor *c, soak_status st, const char *fmt, ...)
{
    va_list ap; /* attribute names come from the file: the message is made printable */
    va_start(ap, fmt);
    soak_verror_at(c->err, c->errlen, st, c->path, NULL, fmt, ap);
    va_end(ap);
    return st;
}

static int read_bytes(exr_cursor *c, void *dst, size_t n)
{
    if (c->pos + (long long)n > c->size || fread(dst, 1, n, c->f) != n) return 0;
    c->pos += (long long)n;
    return 1;
}

static int skip_bytes(exr_cursor *c, long long n)
{
    if (c->pos + n > c->size || fseeko(c->f, (off_t)n, SEEK_CUR) != 0) return 0;
    c->pos += n;
    return 1;
}

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* A zero-terminated name of at most max characters; 0 at the end of the
 * file or when too long. */
static int read_name(exr_cursor *c, char *name, int max)
{
    for (int i = 0; i <= max; ++i) {
        unsigned char ch;
        if (!read_bytes(c, &ch, 1)) return 0;
        name[i] = (char)ch;
        if (!ch) return 1;
    }
    return 0;
}

/* chlist: entries name\0 int32 type, u8 pLinear, 3 reserved, int32 xSampling,
 * int32 ySampling; a zero byte ends the list. */
static soak_status parse_channels(exr_cursor *c, const unsigned char *v, long long size, exr_part *p)
{
    long long i = 0;
    p->channels = 0;
    p->bytes_per_pixel = 0;
    while (i < size && v[i]) {
        const unsigned char *end = memchr(v + i, 0, (size_t)(size - i));
        if (!end) return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'channels': unterminated channel name");
        i = (end - v) + 1;
        if (i + 16 > size) return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'channels': entry cut short");
        uint32_t type = le32(v + i);
        int32_t xs = (int32_t)le32(v + i + 8), ys = (int32_t)le32(v + i + 12);
        if (type > 2)
            return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'channels': pixel type %u (expected 0 uint, 1 half, 2 float)",
                        type);
        if (xs < 1 || ys < 1)
            return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'channels': sampling %d x %d (expected >= 1)", xs, ys);
        p->bytes_per_pixel += type == 1 ? 2 : 4;
        ++p->channels;
        i += 16;
    }
    if (i >= size) return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'channels': list not terminated");
    if (p->channels == 0) return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'channels': no channels");
    p->have_channels = 1;
    return SOAK_OK;
}

/* Values this check needs are small; everything else is skipped. */
static soak_status read_value(exr_cursor *c, const char *name, const char *type, long long size, exr_part *p)
{
    unsigned char v[4096];
    int want = !strcmp(name, "channels") || !strcmp(name, "compression") || !strcmp(name, "dataWindow") ||
               !strcmp(name, "tiles") || !strcmp(name, "type");
    if (!want) return skip_bytes(c, size) ? SOAK_OK : fail(c, SOAK_ERR_PARSE, "OpenEXR header cut short");
    if (size > (long long)sizeof v)
        return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute '%s' of %lld bytes (at most %zu expected)", name, size,
                    sizeof v);
    if (!read_bytes(c, v, (size_t)size)) return fail(c, SOAK_ERR_PARSE, "OpenEXR header cut short");
    if (!strcmp(name, "channels") && !strcmp(type, "chlist")) return parse_channels(c, v, size, p);
    if (!strcmp(name, "compression") && size == 1) {
        if (v[0] > 9) return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'compression': unknown method %u", v[0]);
        p->compression = v[0];
        p->have_compression = 1;
    } else if (!strcmp(name, "dataWindow") && size == 16) {
        for (int k = 0; k < 4; ++k) p->window[k] = (int32_t)le32(v + 4 * k);
        p->have_window = 1;
    } else if (!strcmp(name, "tiles") && size == 9) {
        p->tile_w = le32(v);
        p->tile_h = le32(v + 4);
        p->have_tiles = 1;
    } else if (!strcmp(name, "type")) {
        p->deep = size >= 4 && !memcmp(v, "deep", 4);
    }
    return SOAK_OK;
}

/* One part's attributes up to its terminating zero byte. *empty: the
 * header had no attribute (the end of a multi-part header list). */
static soak_status parse_header(exr_cursor *c, int max_name, exr_part *p, int *empty)
{
    memset(p, 0, sizeof *p);
    *empty = 1;
    for (;;) {
        char name[256], type[256];
        unsigned char sz[4];
        if (!read_name(c, name, max_name))
            return fail(c, SOAK_ERR_PARSE, "OpenEXR header: attribute name unterminated or past the end of the file");
        if (!name[0]) return SOAK_OK;
        *empty = 0;
        if (!read_name(c, type, max_name) || !read_bytes(c, sz, 4))
            return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute '%s': type or size past the end of the file", name);
        long long size = (int32_t)le32(sz);
        if (size < 0 || size > c->size - c->pos)
            return fail(c, SOAK_ERR_PARSE,
                        "OpenEXR attribute '%s' (%s) claims %lld bytes, but only %lld bytes of the %lld-byte file "
                        "follow",
                        name, type, size, c->size - c->pos, c->size);
        soak_status st = read_value(c, name, type, size, p);
        if (st != SOAK_OK) return st;
    }
}

/* Scanlines per chunk by compression method (OpenEXR file layout). */
static long long lines_per_chunk(int compression)
{
    static const int lines[10] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return lines[compression];
}

static soak_status check_part(exr_cursor *c, const exr_part *p, int part, int tiled)
{
    if (!p->have_channels || !p->have_compression || !p->have_window)
        return fail(c, SOAK_ERR_PARSE, "OpenEXR part %d lacks the required attribute '%s'", part,
                    !p->have_channels ? "channels" : !p->have_compression ? "compression" : "dataWindow");
    if (p->deep) return fail(c, SOAK_ERR_UNSUPPORTED, "OpenEXR part %d holds deep data (not supported)", part);
    long long w = (long long)p->window[2] - p->window[0] + 1, h = (long long)p->window[3] - p->window[1] + 1;
    if (w < 1 || h < 1)
        return fail(c, SOAK_ERR_PARSE, "OpenEXR attribute 'dataWindow' (%d, %d)-(%d, %d) is empty", p->window[0],
                    p->window[1], p->window[2], p->window[3]);
    long long chunks;
    if (tiled) {
        if (!p->have_tiles || p->tile_w < 1 || p->tile_h < 1)
            return fail(c, SOAK_ERR_PARSE, "OpenEXR part %d is tiled but has no valid 'tiles' attribute", part);
        chunks = ((w + p->tile_w - 1) / p->tile_w) * ((h + p->tile_h - 1) / p->tile_h);
    } else {
        chunks = (h + lines_per_chunk(p->compression) - 1) / lines_per_chunk(p->compression);
    }
    long long rest = c->size - c->pos;
    if ((double)chunks * SOAK_EXR_MIN_CHUNK_BYTES > (double)rest)
        return fail(c, SOAK_ERR_ARG,
                    "OpenEXR dataWindow %lldx%lld needs %lld %s of at least %d bytes each, but only %lld bytes "
                    "follow the header (a corrupt or hostile header)",
                    w, h, chunks, tiled ? "tiles" : "scanline blocks", SOAK_EXR_MIN_CHUNK_BYTES, rest);
    double raw = (double)w * (double)h * (double)p->bytes_per_pixel;
    if (p->compression == 0 && raw > (double)rest)
        return fail(c, SOAK_ERR_ARG,
                    "uncompressed OpenEXR dataWindow %lldx%lld of %d channels needs %.0f bytes of pixels, but only "
                    "%lld bytes follow the header",
                    w, h, p->channels, raw, rest);
    int ch = p->channels < 4 ? p->channels : 4;
    double floats = (double)w * (double)h * ch * 4.0;
    c->payload = rest;
    /* The ratio counts the chunks, not the header: padding attributes
     * cannot buy a larger image. */
    if (floats > SOAK_IMAGE_MAX_BYTES ||
        (floats > SOAK_IMAGE_FREE_BYTES && floats > SOAK_IMAGE_MAX_RATIO * (double)rest))
        return fail(c, SOAK_ERR_ARG,
                    "OpenEXR dataWindow %lldx%lld with %d channels is %.0f MiB as float pixels from %lld bytes of "
                    "pixel chunks: the limit is %.0f MiB, and above %.0f MiB at most %.0f float bytes per byte of chunks",
                    w, h, ch, floats / 1048576.0, rest, SOAK_IMAGE_MAX_BYTES / 1048576.0,
                    SOAK_IMAGE_FREE_BYTES / 1048576.0, SOAK_IMAGE_MAX_RATIO);
    return SOAK_OK;
}

static soak_status check_exr(exr_cursor *c)
{
    unsigned char head[8];
    if (!read_bytes(c, head, 8)) return fail(c, SOAK_ERR_PARSE, "OpenEXR file cut short in its version field");
    uint32_t version = le32(head + 4);
    if ((version & 0xffu) != 2)
        return fail(c, SOAK_ERR_PARSE, "OpenEXR version %u (only 2 exists)", version & 0xffu);
    int multipart = (version & EXR_MULTIPART) != 0, tiled = (version & EXR_TILED) != 0;
    if (!multipart && (version & EXR_NON_IMAGE))
        return fail(c, SOAK_ERR_UNSUPPORTED, "OpenEXR file holds deep data (not supported)");
    int max_name = (version & EXR_LONG_NAMES) ? 255 : 31;
    exr_part parts[8];
    int n = 0;
    for (;;) {
        exr_part p;
        int empty;
        soak_status st = parse_header(c, max_name, &p, &empty);
        if (st != SOAK_OK) return st;
        if (empty && multipart && n > 0) break;
        if (n >= EXR_MAX_PARTS) return fail(c, SOAK_ERR_PARSE, "OpenEXR file with more than %d parts", EXR_MAX_PARTS);
        /* Parts past the first eight are parsed (bounded) but not kept. */
        if (n < 8) parts[n] = p;
        ++n;
        if (!multipart) break;
    }
    /* Each part's table and pixels follow all the headers: the bound uses
     * what follows the last header. */
    for (int k = 0; k < n && k < 8; ++k) {
        soak_status st = check_part(c, &parts[k], k, multipart ? parts[k].have_tiles : tiled);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

/* A JPEG ends with the end-of-image marker FF D9; libjpeg decodes a file cut
 * short without it, filling the missing rows with grey and only warning.
 * Data some writers append after the marker is allowed within the last
 * JPEG_TAIL_BYTES. */
#define JPEG_TAIL_BYTES 4096
static soak_status check_jpeg(FILE *f, const char *path, long long size, char *err, size_t errlen)
{
    unsigned char tail[JPEG_TAIL_BYTES];
    long long n = size < JPEG_TAIL_BYTES ? size : JPEG_TAIL_BYTES;
    if (fseeko(f, (off_t)(size - n), SEEK_SET) != 0 || fread(tail, 1, (size_t)n, f) != (size_t)n) return SOAK_OK;
    for (long long i = n - 2; i >= 0; --i)
        if (tail[i] == 0xff && tail[i + 1] == 0xd9) return SOAK_OK;
    if (err && errlen)
        snprintf(err, errlen, "%s: JPEG without its end-of-image marker (FF D9) in its last %d bytes: the file is cut "
                 "short", path, JPEG_TAIL_BYTES);
    return SOAK_ERR_PARSE;
}

/* The signature each image extension names; a file without it is refused
 * here, so that no image library walks a non-image (OpenImageIO 2.4 tries
 * every other reader after the one the extension names: its DICOM reader
 * spent 18.5 s on 256 MiB of zeros named .png). */
static soak_status check_signature(const char *path, const unsigned char *m, size_t n, const char **format,
                                   char *err, size_t errlen)
{
    static const struct { const char *ext, *format; unsigned char magic[8]; size_t len; } sigs[] = {
        {"png", "PNG", {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a}, 8},
        {"jpg", "JPEG", {0xff, 0xd8, 0xff}, 3},
        {"jpeg", "JPEG", {0xff, 0xd8, 0xff}, 3},
        {"exr", "OpenEXR", {0x76, 0x2f, 0x31, 0x01}, 4},
        {"hdr", "Radiance HDR", {'#', '?'}, 2},
    };
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    const char *ext = dot && (!slash || dot > slash) ? dot + 1 : "";
    *format = NULL;
    int tiff = !strcasecmp(ext, "tif") || !strcasecmp(ext, "tiff") || !strcasecmp(ext, "tx");
    int tiff_ok = n >= 4 && ((m[0] == 'I' && m[1] == 'I' && m[2] == 42 && (m[3] == 0 || m[3] == 43)) ||
                             (m[0] == 'M' && m[1] == 'M' && m[3] == 42 && m[2] == 0) ||
                             (m[0] == 'M' && m[1] == 'M' && m[3] == 43 && m[2] == 0) ||
                             (m[0] == 'I' && m[1] == 'I' && m[2] == 43 && m[3] == 0));
    if (tiff) *format = "TIFF";
    for (size_t i = 0; !tiff && i < sizeof sigs / sizeof sigs[0]; ++i) {
        if (strcasecmp(ext, sigs[i].ext)) continue;
        *format = sigs[i].format;
        if (n >= sigs[i].len && !memcmp(m, sigs[i].magic, sigs[i].len)) return SOAK_OK;
        break;
    }
    if (!*format || (tiff && tiff_ok)) return SOAK_OK;
    if (err && errlen)
        snprintf(err, errlen, "%s: not a valid %s file: it does not start with the %s signature (the extension names the "
                 "format; soak tries no other reader)", path, *format, *format);
    return SOAK_ERR_PARSE;
}

/* A Radiance HDR header: "#?" lines, an empty line and the resolution line
 * ("-Y n +X m"), all within HDR_HEADER_MAX bytes (a header followed by 2 GiB
 * of zeros kept OpenImageIO's reader looking for its end for minutes). */
#define HDR_HEADER_MAX 65536
static soak_status check_hdr(FILE *f, const char *path, char *err, size_t errlen)
{
    char head[HDR_HEADER_MAX + 1];
    if (fseeko(f, 0, SEEK_SET) != 0) return SOAK_OK;
    size_t n = fread(head, 1, HDR_HEADER_MAX, f);
    head[n] = '\0';
    const char *blank = NULL;
    for (size_t i = 0; i + 1 < n && !blank; ++i)
        if (head[i] == '\n' && head[i + 1] == '\n') blank = head + i + 2;
    char sy, sx, ay, ax;
    long h = 0, w = 0;
    if (!blank || !memchr(blank, '\n', (size_t)(head + n - blank)) ||
        sscanf(blank, "%c%c %ld %c%c %ld", &sy, &ay, &h, &sx, &ax, &w) != 6 || (ay != 'Y' && ay != 'X') || h < 1 || w < 1) {
        if (err && errlen)
            snprintf(err, errlen, "%s: Radiance HDR header without its end (an empty line and the resolution line) in "
                     "its first %d bytes", path, HDR_HEADER_MAX);
        return SOAK_ERR_PARSE;
    }
    return SOAK_OK;
}

static soak_status check_stream(FILE *f, const char *path, long long size, long long *payload, char *err,
                                size_t errlen)
{
    unsigned char magic[8] = {0};
    size_t n = size > 0 ? fread(magic, 1, sizeof magic, f) : 0;
    const char *format = NULL;
    soak_status st = check_signature(path, magic, n, &format, err, errlen);
    if (st != SOAK_OK) return st;
    if (n < 4) return SOAK_OK;
    if (n == 8 && !memcmp(magic, "\x89PNG\r\n\x1a\n", 8)) return soak_png_check(f, path, size, payload, err, errlen);
    if (magic[0] == 0xff && magic[1] == 0xd8 && magic[2] == 0xff) return check_jpeg(f, path, size, err, errlen);
    if (magic[0] == '#' && magic[1] == '?') return check_hdr(f, path, err, errlen);
    if (!(magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01)) return SOAK_OK;
    if (fseeko(f, 0, SEEK_SET) != 0) return SOAK_OK;
    exr_cursor c = {f, path, size, 0, size, err, errlen};
    st = check_exr(&c);
    *payload = c.payload;
    return st;
}

soak_status soak_image_check_header(const char *path, long long *payload, char *err, size_t errlen)
{
    if (!path || !payload) return SOAK_ERR_NULL;
    FILE *f = fopen(path, "rb");
    if (!f) {
        if (err && errlen) snprintf(err, errlen, "%s: cannot read image: %s", path, strerror(errno));
        return SOAK_ERR_IO;
    }
    struct stat sb;
    soak_status st = SOAK_OK;
    *payload = 0;
    if (fstat(fileno(f), &sb) == 0) {
        *payload = (long long)sb.st_size;
        st = check_stream(f, path, (long long)sb.st_size, payload, err, errlen);
        /* The holes of a sparse file hold no data: only allocated blocks
         * count as compressed pixels. */
        long long stored = soak_input_stored_bytes((long long)sb.st_size, (long long)sb.st_blocks);
        if (stored < *payload) *payload = stored;
    }
    fclose(f);
    if (st != SOAK_OK && err && errlen) soak_message_printable(err);
    return st;
}
