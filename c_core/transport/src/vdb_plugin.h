/* The table libsoak_vdb.so (transport/plugin/volume_openvdb.cpp, OpenVDB)
 * exports as soak_vdb_plugin_v1; volume_vdb.c prepares the grids and
 * stages the file. The module calls nothing of libsoak; no C++ exception
 * leaves it. */
#ifndef SOAK_VDB_PLUGIN_H
#define SOAK_VDB_PLUGIN_H

#include <stddef.h>

#include "soak/status.h"

/* One float grid of dims[0] x dims[1] x dims[2] values, x fastest. */
typedef struct soak_vdb_grid {
    const char *name;
    const float *values;
    int fog; /* GRID_FOG_VOLUME when set, else GRID_UNKNOWN */
} soak_vdb_grid;

typedef struct soak_vdb_plugin {
    /* Writes the grids to the file tmp (index (i,j,k) at the centre of the
     * voxel of size voxel[]: the cells cover the box) and reads it back;
     * path names the destination in messages. */
    soak_status (*write)(const char *tmp, const char *path, const int dims[3], const double voxel[3],
                         const soak_vdb_grid *grids, int n_grids, char *err, size_t errlen);
    /* soak_volume_read_vdb_grid (soak/volume.h). */
    soak_status (*read_grid)(const char *path, const char *grid, int nx, int ny, int nz, float *values,
                             double voxel_size[3], double origin[3], char *err, size_t errlen);
} soak_vdb_plugin;

#define SOAK_VDB_PLUGIN_FILE "libsoak_vdb.so"
#define SOAK_VDB_PLUGIN_SYMBOL "soak_vdb_plugin_v1"

#endif
