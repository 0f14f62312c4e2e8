/* Volume files checked on their own bytes before anything is allocated
 * from what they claim (pure C, no OpenVDB).
 *
 * df3 (POV-Ray density file, 3 big-endian uint16 dims then nx*ny*nz
 * big-endian samples of 1, 2 or 4 bytes, x fastest): the payload must be
 * exactly nx*ny*nz samples of one of those widths (POV-Ray infers the width
 * from the length the same way), each dimension at least 1 and at most
 * SOAK_VOLUME_MAX_DIM, and at most SOAK_DF3_MAX_VOXELS voxels; so memory is
 * bounded by 4 bytes per file byte and a fixed cap, and a cut or padded file
 * is refused with both sizes.
 *
 * OpenVDB: the 8-byte magic, a file format version OpenVDB 10 reads
 * (SOAK_VDB_VERSION_MIN..SOAK_VDB_VERSION_MAX) and a complete fixed header
 * (SOAK_VDB_HEADER_BYTES) before OpenVDB opens the file, and the index box
 * the caller asks for within SOAK_VOLUME_MAX_DIM per axis and
 * SOAK_DF3_MAX_VOXELS voxels before it allocates the values. */
#ifndef SOAK_VOLUME_CHECK_H
#define SOAK_VOLUME_CHECK_H

#include <stddef.h>

#include "soak/status.h"

/* 2^28 voxels: 1 GiB as float. */
#define SOAK_DF3_MAX_VOXELS (1L << 28)

typedef struct soak_df3 {
    int nx, ny, nz, bits; /* bits: 8, 16 or 32 */
    float *values;        /* nx*ny*nz, x fastest, raw / (2^bits - 1) in [0, 1]; owned */
} soak_df3;

/* Reads a df3 file (rules above). err names the file and the numbers. */
soak_status soak_df3_read(const char *path, soak_df3 *out, char *err, size_t errlen);
void soak_df3_free(soak_df3 *d);

/* OpenVDB 10 reads file format versions 213 (OpenVDB 2) to 224 (OpenVDB 8+). */
#define SOAK_VDB_VERSION_MIN 213u
#define SOAK_VDB_VERSION_MAX 224u
/* magic 8, format version 4, library version 8, grid-offsets flag 1, UUID 36 */
#define SOAK_VDB_HEADER_BYTES 57

/* The checks above for reading an nx x ny x nz box of a grid of path. */
soak_status soak_vdb_check(const char *path, int nx, int ny, int nz, char *err, size_t errlen);

#endif
