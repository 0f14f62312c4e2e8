/* Volume readers: byte 0 picks the reader, the rest is the file.
 *   0 grid: bytes 1-2 (little-endian) give the header's length L, then L
 *     bytes of header JSON (written as in.json) and the payload (in.raw, the
 *     name the seeds' "data" uses);
 *   1 df3: soak_df3_read;
 *   2 OpenVDB: soak_volume_read_vdb_grid of the "density" grid over a 4^3 box.
 * Every value read must be finite, every failure must set a message that
 * names the file (fuzz_check_message). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "soak/volume.h"
#include "soak/volume_check.h"

static void grid(const uint8_t *data, size_t size)
{
    if (size < 2) return;
    size_t len = (size_t)data[0] | (size_t)data[1] << 8;
    if (len > size - 2) len = size - 2;
    const char *raw = fuzz_temp_named("in.raw", data + 2 + len, size - 2 - len);
    const char *json = fuzz_temp_named("in.json", data + 2, len);
    if (!raw || !json) return;
    soak_volume v;
    char err[1024] = "";
    if (soak_volume_read_grid(json, &v, err, sizeof err) == SOAK_OK) {
        size_t n = soak_volume_count(&v) * SOAK_VOL_NCHANNELS;
        for (size_t i = 0; i < n; ++i)
            if (!isfinite(v.data[i])) abort();
        soak_volume_free(&v);
    } else {
        fuzz_check_message(err, json, raw);
    }
}

static void df3(const uint8_t *data, size_t size)
{
    const char *path = fuzz_temp_named("in.df3", data, size);
    if (!path) return;
    soak_df3 d;
    char err[1024] = "";
    if (soak_df3_read(path, &d, err, sizeof err) == SOAK_OK) {
        size_t n = (size_t)d.nx * d.ny * d.nz;
        for (size_t i = 0; i < n; ++i)
            if (!(d.values[i] >= 0.0f && d.values[i] <= 1.0f)) abort();
        soak_df3_free(&d);
    } else {
        fuzz_check_message(err, path, NULL);
    }
}

static void vdb(const uint8_t *data, size_t size)
{
    const char *path = fuzz_temp_named("in.vdb", data, size);
    if (!path) return;
    float values[64];
    double voxel[3], origin[3];
    char err[1024] = "";
    soak_status st = soak_volume_read_vdb_grid(path, "density", 4, 4, 4, values, voxel, origin, err, sizeof err);
    if (st != SOAK_OK) fuzz_check_message(err, path, NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 1 << 20) return 0;
    switch (data[0] % 3) {
    case 0: grid(data + 1, size - 1); break;
    case 1: df3(data + 1, size - 1); break;
    default: vdb(data + 1, size - 1); break;
    }
    return 0;
}
