/* PNG chunk walk before any image library sees the file (image_check.c). */
#ifndef SOAK_IMAGE_CHECK_PNG_H
#define SOAK_IMAGE_CHECK_PNG_H

#include <stdio.h>

#include "soak/status.h"

/* f is open on a file of size bytes that starts with the PNG signature.
 * Walks its chunks without reading their data: every chunk lies inside the
 * file and has a valid type, IHDR comes first, IDAT is present, IEND ends
 * the file (libpng reads a file cut short up to its end and then fails
 * with its own lines on stderr). *payload gets the bytes of the IDAT
 * chunks, against which the decoded size is budgeted (soak/image.h: a
 * private chunk of any size buys no pixels). SOAK_ERR_PARSE or SOAK_ERR_ARG
 * with a message naming path. */
soak_status soak_png_check(FILE *f, const char *path, long long size, long long *payload, char *err, size_t errlen);

#endif
