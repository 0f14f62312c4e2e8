/* Mesh input: the first byte picks the format (obj ply stl off gltf glb fbx
 * dae 3ds x lwo ms3d; glTF 1.0 rides on gltf/glb), the rest is the file. The
 * table is indexed modulo 12, a multiple of the first table's 6, so every
 * stored input keeps the format it was found with. Under libFuzzer
 * (SOAK_FUZZ_INPROCESS) the Assimp import runs in this process so that its
 * coverage guides the search; the
 * replay build goes through soak_mesh_load, the contained path Soak uses, and
 * checks that every stored crash or hang of Assimp becomes an error. */
#include <math.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "mesh_import.h"
#include "soak/geometry.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const ext[] = {"obj", "ply", "stl", "off", "gltf", "glb",
                                      "fbx", "dae", "3ds", "x",    "lwo", "ms3d"};
    enum { n_ext = sizeof ext / sizeof ext[0] };
    if (size < 1 || size > 1 << 20) return 0;
    const char *path = fuzz_temp_file(data + 1, size - 1, ext[data[0] % n_ext]);
    if (!path) return 0;
    soak_mesh m = {0};
    char err[1024] = "";
#ifdef SOAK_FUZZ_INPROCESS
    soak_status st = soak_mesh_import(path, 0, &m, err, sizeof err);
#else
    soak_status st = soak_mesh_load(path, 0, &m, err, sizeof err);
#endif
    if (st == SOAK_OK) {
        for (size_t i = 0; i < 3 * m.n_vertices; ++i)
            if (!isfinite(m.positions[i])) abort();
        for (size_t i = 0; i < 3 * m.n_triangles; ++i)
            if (m.indices[i] >= m.n_vertices) abort();
        soak_mesh_free(&m);
    } else {
        fuzz_check_message(err, path, NULL);
    }
    return 0;
}
