/* The table libsoak_mesh.so (render/plugin/mesh_assimp.c, Assimp) exports
 * as soak_mesh_plugin_v2. The module calls nothing of libsoak; the arrays
 * of the mesh it returns are malloc'ed (soak_mesh_free frees them). */
#ifndef SOAK_MESH_PLUGIN_H
#define SOAK_MESH_PLUGIN_H

#include <stddef.h>

#include "soak/geometry.h"

/* What the import is asked for: require_uvs 0 (none), SOAK_MESH_UVS_ALL
 * (soak_mesh_load's: on every face) or SOAK_MESH_UVS_SOME (soak_mesh_load_uv:
 * faces without are marked in tri_uv); uv the UV set (NULL: the first). */
#define SOAK_MESH_UVS_ALL 1
#define SOAK_MESH_UVS_SOME 2
typedef struct soak_mesh_request {
    int require_uvs;
    const soak_mesh_uv_choice *uv;
} soak_mesh_request;

typedef struct soak_mesh_plugin {
    /* The Assimp import of soak_mesh_import (mesh_import.h), before
     * soak_mesh_validate. */
    soak_status (*import)(const char *path, const soak_mesh_request *rq, soak_mesh *mesh, char *err, size_t errlen);
} soak_mesh_plugin;

#define SOAK_MESH_PLUGIN_FILE "libsoak_mesh.so"
#define SOAK_MESH_PLUGIN_SYMBOL "soak_mesh_plugin_v2"

#endif
