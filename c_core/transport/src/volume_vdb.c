/* OpenVDB output of parameter volumes (soak/volume.h): the grids are made
 * here, written by libsoak_vdb.so (OpenVDB), opened on the first .vdb a
 * command reads or writes (soak/plugin.h). */
#include <stdio.h>
#include <stdlib.h>

#include "soak/plugin.h"
#include "soak/staged.h"
#include "soak/volume.h"
#include "soak/volume_check.h"
#include "vdb_plugin.h"

#ifndef SOAK_HAVE_OPENVDB
#define SOAK_HAVE_OPENVDB 0
#endif

/* Written once under pthread_once, read-only afterwards (soak/plugin.h). */
static soak_plugin_slot vdb_slot = SOAK_PLUGIN_SLOT(SOAK_VDB_PLUGIN_FILE, SOAK_VDB_PLUGIN_SYMBOL, "OpenVDB");

static void vdb_slot_fill(void)
{
    soak_plugin_slot_fill(&vdb_slot);
}

static const soak_vdb_plugin *vdb_plugin(const char *path, char *err, size_t errlen)
{
    if (!SOAK_HAVE_OPENVDB) {
        if (err && errlen) snprintf(err, errlen, "%s: this build of libsoak has no OpenVDB support", path);
        return NULL;
    }
    pthread_once(&vdb_slot.once, vdb_slot_fill);
    char why[1600];
    const soak_vdb_plugin *p = soak_plugin_slot_table(&vdb_slot, why, sizeof why);
    if (!p && err && errlen) snprintf(err, errlen, "%s: %s", path, why);
    return p;
}

int soak_volume_have_vdb(void)
{
    return SOAK_HAVE_OPENVDB;
}

/* Grids of the file: "density" (mean extinction, for Blender's volume
 * object), "sigma_s" and "sigma_a" (means of the RGB channels), then every
 * channel; the sigma grids are fog volumes. */
enum { N_MEANS = 3, N_GRIDS = N_MEANS + SOAK_VOL_NCHANNELS };

static void mean_planes(const soak_volume *v, float *density, float *mean_s, float *mean_a)
{
    const float *s[3], *a[3];
    for (int c = 0; c < 3; ++c) {
        s[c] = soak_volume_plane(v, SOAK_VOL_SIGMA_S_R + c);
        a[c] = soak_volume_plane(v, SOAK_VOL_SIGMA_A_R + c);
    }
    size_t n = soak_volume_count(v);
    for (size_t i = 0; i < n; ++i) {
        mean_s[i] = (float)(((double)s[0][i] + s[1][i] + s[2][i]) / 3.0);
        mean_a[i] = (float)(((double)a[0][i] + a[1][i] + a[2][i]) / 3.0);
        density[i] = mean_s[i] + mean_a[i];
    }
}

soak_status soak_volume_stage_vdb(soak_staged *stage, const soak_volume *v, const char *path, char *err,
                                  size_t errlen)
{
    if (!stage || !v || !v->data || !path) return SOAK_ERR_NULL;
    const soak_vdb_plugin *p = vdb_plugin(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    const char *tmp = NULL;
    soak_status st = soak_staged_add(stage, path, &tmp, err, errlen);
    if (st != SOAK_OK) return st;
    size_t n = soak_volume_count(v);
    float *means = malloc(N_MEANS * n * sizeof(float));
    if (!means) return SOAK_ERR_NOMEM;
    mean_planes(v, means, means + n, means + 2 * n);
    static const char *const mean_names[N_MEANS] = {"density", "sigma_s", "sigma_a"};
    soak_vdb_grid grids[N_GRIDS];
    for (int g = 0; g < N_MEANS; ++g) grids[g] = (soak_vdb_grid){mean_names[g], means + g * n, 1};
    for (int c = 0; c < SOAK_VOL_NCHANNELS; ++c)
        grids[N_MEANS + c] = (soak_vdb_grid){soak_volume_channel_name(c), soak_volume_plane(v, c), c <= SOAK_VOL_SIGMA_A_B};
    const int dims[3] = {v->nx, v->ny, v->nz};
    const double voxel[3] = {v->size[0] / v->nx, v->size[1] / v->ny, v->size[2] / v->nz};
    st = p->write(tmp, path, dims, voxel, grids, N_GRIDS, err, errlen);
    free(means);
    return st;
}

soak_status soak_volume_write_vdb(const soak_volume *v, const char *path, char *err, size_t errlen)
{
    soak_staged stage;
    soak_staged_init(&stage);
    soak_status st = soak_volume_stage_vdb(&stage, v, path, err, errlen);
    if (st != SOAK_OK) {
        soak_staged_abort(&stage);
        return st;
    }
    return soak_staged_commit(&stage, err, errlen);
}

soak_status soak_volume_read_vdb_grid(const char *path, const char *grid, int nx, int ny, int nz, float *values,
                                      double voxel_size[3], double origin[3], char *err, size_t errlen)
{
    if (!path || !grid || !values || !voxel_size || !origin) return SOAK_ERR_NULL;
    if (!(nx >= 1 && ny >= 1 && nz >= 1)) return SOAK_ERR_ARG;
    /* Magic, version, header and box checked on the bytes before OpenVDB
     * sees the file (soak/volume_check.h). */
    soak_status pre = soak_vdb_check(path, nx, ny, nz, err, errlen);
    if (pre != SOAK_OK) return pre;
    const soak_vdb_plugin *p = vdb_plugin(path, err, errlen);
    if (!p) return SOAK_ERR_UNSUPPORTED;
    return p->read_grid(path, grid, nx, ny, nz, values, voxel_size, origin, err, errlen);
}
