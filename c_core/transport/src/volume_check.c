/* df3 reader and OpenVDB header pre-check (soak/volume_check.h). */
#define _POSIX_C_SOURCE 200809L
#include "soak/volume_check.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "soak/volume.h"
#include "soak/input_file.h"

/* Opens path for reading if it is a regular file; its size in *size. */
static FILE *open_regular(const char *path, long long *size, char *err, size_t errlen)
{
    if (soak_input_check(path, SOAK_INPUT_VOLUME, size, err, errlen) != SOAK_OK) return NULL;
    FILE *f = fopen(path, "rb");
    if (!f) soak_error_at(err, errlen, SOAK_ERR_IO, path, NULL, "cannot read: %s", strerror(errno));
    return f;
}

static soak_status check_box(const char *what, const char *path, long nx, long ny, long nz, char *err, size_t errlen)
{
    if (nx < 1 || ny < 1 || nz < 1 || nx > SOAK_VOLUME_MAX_DIM || ny > SOAK_VOLUME_MAX_DIM || nz > SOAK_VOLUME_MAX_DIM)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, path, NULL, "%s %ldx%ldx%ld: each dimension must be in [1, %d]", what, nx, ny,
                    nz, SOAK_VOLUME_MAX_DIM);
    if ((double)nx * ny * nz > (double)SOAK_DF3_MAX_VOXELS)
        return soak_error_at(err, errlen, SOAK_ERR_ARG, path, NULL, "%s %ldx%ldx%ld: %.0f voxels, the limit is %ld", what, nx, ny, nz,
                    (double)nx * ny * nz, SOAK_DF3_MAX_VOXELS);
    return SOAK_OK;
}

static soak_status df3_header(FILE *f, const char *path, long long size, soak_df3 *d, size_t *count, int *bytes,
                              char *err, size_t errlen)
{
    unsigned char h[6];
    if (size < 6 || fread(h, 1, 6, f) != 6)
        return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "df3 file of %lld bytes is shorter than its 6-byte header", size);
    d->nx = h[0] << 8 | h[1];
    d->ny = h[2] << 8 | h[3];
    d->nz = h[4] << 8 | h[5];
    soak_status st = check_box("df3 dims", path, d->nx, d->ny, d->nz, err, errlen);
    if (st != SOAK_OK) return st;
    *count = (size_t)d->nx * (size_t)d->ny * (size_t)d->nz;
    long long payload = size - 6;
    for (*bytes = 1; *bytes <= 4; *bytes *= 2)
        if (payload == (long long)*count * *bytes) break;
    if (*bytes > 4)
        return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL,
                    "df3 dims %dx%dx%d need %zu, %zu or %zu bytes of samples (8, 16 or 32 bit) after the header; the "
                    "file has %lld",
                    d->nx, d->ny, d->nz, *count, 2 * *count, 4 * *count, payload);
    d->bits = 8 * *bytes;
    return SOAK_OK;
}

soak_status soak_df3_read(const char *path, soak_df3 *out, char *err, size_t errlen)
{
    if (!path || !out) return SOAK_ERR_NULL;
    memset(out, 0, sizeof *out);
    long long size = 0;
    FILE *f = open_regular(path, &size, err, errlen);
    if (!f) return SOAK_ERR_IO;
    soak_df3 d = {0, 0, 0, 0, NULL};
    size_t count = 0;
    int bytes = 0;
    soak_status st = df3_header(f, path, size, &d, &count, &bytes, err, errlen);
    unsigned char *raw = NULL;
    if (st == SOAK_OK) {
        raw = malloc(count * (size_t)bytes);
        d.values = malloc(count * sizeof(float));
        if (!raw || !d.values) st = soak_error_at(err, errlen, SOAK_ERR_NOMEM, path, NULL, "out of memory for %zu voxels", count);
    }
    if (st == SOAK_OK && fread(raw, (size_t)bytes, count, f) != count)
        st = soak_error_at(err, errlen, SOAK_ERR_IO, path, NULL, "read error in the df3 samples");
    fclose(f);
    if (st == SOAK_OK) {
        double max = bytes == 1 ? 255.0 : bytes == 2 ? 65535.0 : 4294967295.0;
        for (size_t i = 0; i < count; ++i) {
            const unsigned char *b = raw + i * (size_t)bytes;
            uint32_t v = 0;
            for (int k = 0; k < bytes; ++k) v = v << 8 | b[k];
            d.values[i] = (float)(v / max);
        }
    }
    free(raw);
    if (st != SOAK_OK) {
        free(d.values);
        return st;
    }
    *out = d;
    return SOAK_OK;
}

void soak_df3_free(soak_df3 *d)
{
    if (!d) return;
    free(d->values);
    d->values = NULL;
}

soak_status soak_vdb_check(const char *path, int nx, int ny, int nz, char *err, size_t errlen)
{
    if (!path) return SOAK_ERR_NULL;
    soak_status st = check_box("grid box", path, nx, ny, nz, err, errlen);
    if (st != SOAK_OK) return st;
    long long size = 0;
    FILE *f = open_regular(path, &size, err, errlen);
    if (!f) return SOAK_ERR_IO;
    unsigned char h[SOAK_VDB_HEADER_BYTES];
    size_t got = fread(h, 1, sizeof h, f);
    fclose(f);
    static const unsigned char magic[8] = {0x20, 0x42, 0x44, 0x56, 0, 0, 0, 0};
    if (got < 8 || memcmp(h, magic, 8) != 0)
        return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "not an OpenVDB file (its first 8 bytes are not the VDB magic)");
    if (got < sizeof h)
        return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "OpenVDB file of %lld bytes is shorter than its %d-byte header",
                    size, SOAK_VDB_HEADER_BYTES);
    uint32_t version = (uint32_t)h[8] | (uint32_t)h[9] << 8 | (uint32_t)h[10] << 16 | (uint32_t)h[11] << 24;
    if (version < SOAK_VDB_VERSION_MIN || version > SOAK_VDB_VERSION_MAX)
        return soak_error_at(err, errlen, SOAK_ERR_PARSE, path, NULL, "OpenVDB file format version %u (readable: %u to %u)", version,
                    SOAK_VDB_VERSION_MIN, SOAK_VDB_VERSION_MAX);
    return SOAK_OK;
}
