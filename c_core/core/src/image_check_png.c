/* PNG chunk walk (image_check_png.h). Layout from the PNG specification
 * (ISO/IEC 15948, section 5.3): a chunk is a 4-byte big-endian length (at
 * most 2^31 - 1), a 4-byte type of ASCII letters, the data and a 4-byte
 * CRC; IHDR (13 bytes) first, IEND last. */
#define _POSIX_C_SOURCE 200809L
#include "image_check_png.h"

#include <stdint.h>
#include <string.h>

#include "soak/image.h"

static uint32_t be32(const unsigned char *b)
{
    return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | (uint32_t)b[3];
}

static int letters(const unsigned char *t)
{
    for (int i = 0; i < 4; ++i)
        if (!((t[i] >= 'A' && t[i] <= 'Z') || (t[i] >= 'a' && t[i] <= 'z'))) return 0;
    return 1;
}

/* Channels OpenImageIO decodes for a PNG colour type (palette: RGB, RGBA
 * with a tRNS chunk). */
static int png_channels(int colour_type, int has_trns)
{
    switch (colour_type) {
    case 0: return has_trns ? 2 : 1;
    case 2: return has_trns ? 4 : 3;
    case 3: return has_trns ? 4 : 3;
    case 4: return 2;
    case 6: return 4;
    default: return 0;
    }
}

/* The decoded size against the IDAT bytes (soak/image.h's rule). */
static soak_status budget(const char *path, uint32_t w, uint32_t h, int ch, long long idat, char *err, size_t errlen)
{
    double floats = (double)w * (double)h * ch * 4.0;
    if (floats > SOAK_IMAGE_MAX_BYTES)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, path, NULL, "a %ux%u image needs %lld MiB as float pixels; the limit is "
                      "%lld MiB", w, h, (long long)(floats / 1048576), (long long)(SOAK_IMAGE_MAX_BYTES / 1048576));
    if (floats > SOAK_IMAGE_FREE_BYTES && floats > SOAK_IMAGE_MAX_RATIO * (double)idat)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, path, NULL, "the PNG header claims %ux%ux%d pixels (%lld MiB as float) from "
                      "%lld bytes of pixel data (IDAT): more than %.0f float bytes per byte of pixel data above %.0f "
                      "MiB (a decompression bomb or a corrupt header)", w, h, ch, (long long)(floats / 1048576), idat,
                      SOAK_IMAGE_MAX_RATIO, SOAK_IMAGE_FREE_BYTES / 1048576.0);
    return SOAK_OK;
}

soak_status soak_png_check(FILE *f, const char *path, long long size, long long *payload, char *err, size_t errlen)
{
    long long at = 8, idat = 0;
    uint32_t w = 0, h = 0;
    int colour = -1, trns = 0;
    for (int index = 0;; ++index) {
        unsigned char head[8 + 13];
        if (at + 12 > size || fseeko(f, (off_t)at, SEEK_SET) != 0 || fread(head, 1, 8, f) != 8)
            return soak_error_at(err, errlen, SOAK_ERR_IO, path, NULL, "PNG without its IEND chunk: the file is cut short "
                          "after %lld of its chunks", (long long)index);
        long long len = be32(head);
        if (len > 0x7fffffffLL || !letters(head + 4))
            return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "PNG chunk %d at byte %lld has no valid length and type "
                          "(a corrupt file, or not a PNG)", index, at);
        if (at + 12 + len > size)
            return soak_error_at(err, errlen, SOAK_ERR_IO, path, NULL, "PNG chunk '%.4s' at byte %lld declares %lld bytes, past "
                          "the end of the %lld-byte file (cut short?)", (const char *)head + 4, at, len, size);
        if ((index == 0) != !memcmp(head + 4, "IHDR", 4) || (index == 0 && len != 13))
            return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "PNG whose first chunk is not a 13-byte IHDR");
        if (index == 0) {
            if (fread(head + 8, 1, 13, f) != 13) return soak_error_at(err, errlen, SOAK_ERR_IO, path, NULL, "PNG header cut short");
            w = be32(head + 8), h = be32(head + 12), colour = head[17];
            if (w < 1 || h < 1 || w > 0x7fffffffu || h > 0x7fffffffu || !png_channels(colour, 0))
                return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "PNG header with size %ux%u and colour type %d",
                              w, h, colour);
        }
        if (!memcmp(head + 4, "IDAT", 4)) idat += len;
        if (!memcmp(head + 4, "tRNS", 4)) trns = 1;
        if (!memcmp(head + 4, "IEND", 4)) break;
        at += 12 + len;
    }
    if (idat == 0) return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "PNG without pixel data (no IDAT chunk)");
    *payload = idat;
    return budget(path, w, h, png_channels(colour, trns), idat, err, errlen);
}
