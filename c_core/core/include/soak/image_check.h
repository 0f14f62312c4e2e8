/* Header checks on an image file's own bytes, before any image library
 * opens it (pure C, no OpenImageIO): a few hundred bytes must not make the
 * library allocate gigabytes while it merely reads the header.
 *
 * OpenEXR (magic 76 2f 31 01): every header is parsed here first. Rules, each
 * refused with the numbers:
 *  - every attribute's value lies inside the file (OpenEXR allocates the
 *    size an attribute claims before reading it: a 566-byte file claiming a
 *    1.7 GB string made it allocate 1.7 GB and spend 44 s);
 *  - names are terminated within 255 bytes, the header ends inside the file;
 *  - channels, compression and dataWindow are present and well formed
 *    (chlist entries of type 0..2, compression 0..9, a non-empty window);
 *  - the chunk offset table fits: every scanline block or tile needs at
 *    least SOAK_EXR_MIN_CHUNK_BYTES of the file (an 8-byte table entry and
 *    an 8-byte chunk header);
 *  - uncompressed files hold every sample; compressed ones obey the
 *    compression-ratio rule of soak/image.h (above SOAK_IMAGE_FREE_BYTES of
 *    float pixels at most SOAK_IMAGE_MAX_RATIO float bytes per byte after
 *    the headers: offset tables and chunks)
 *    and SOAK_IMAGE_MAX_BYTES;
 *  - deep (non-image) parts are refused as unsupported.
 * PNG: every chunk inside the file with a valid type, IHDR first, IEND
 * last, pixel data present; the compression-ratio rule counts the IDAT
 * bytes only (a 900 KB private chunk padded a 16384^2 bomb past a rule
 * that counted the whole file).
 * Every extension that names a format (.png, .jpg/.jpeg, .exr, .tif/.tiff/
 * .tx, .hdr) must start with that format's signature: 256 MiB of zeros named
 * .png is refused here, not walked by OpenImageIO's other readers.
 * JPEG (FF D8 FF): the end-of-image marker FF D9 lies within the last 4 KiB
 * (libjpeg decodes a file cut short, filling the missing rows with grey and
 * only warning: a cut at 9/10 was accepted).
 * Other files pass unchanged (their readers bound their
 * headers themselves; the pixel rules of soak_image_read apply to all). */
#ifndef SOAK_IMAGE_CHECK_H
#define SOAK_IMAGE_CHECK_H

#include <stddef.h>

#include "soak/status.h"

#define SOAK_EXR_MIN_CHUNK_BYTES 16

/* SOAK_OK when path passes the rules above; otherwise SOAK_ERR_PARSE
 * (malformed), SOAK_ERR_ARG (sizes the file cannot hold) or
 * SOAK_ERR_UNSUPPORTED, with err naming the file and the attribute.
 * *payload gets the bytes the decoded pixels are budgeted against: the
 * IDAT chunks of a PNG, what follows the headers of an OpenEXR file, the
 * whole file otherwise. */
soak_status soak_image_check_header(const char *path, long long *payload, char *err, size_t errlen);

#endif
