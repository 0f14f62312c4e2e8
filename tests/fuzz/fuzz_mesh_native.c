/* The native OBJ/PLY/STL reader (render/src/mesh_native.h) in this
 * process: the first byte picks the extension (2 modulo 12: stl, as in
 * fuzz_mesh.c; else even: obj, odd: ply), the rest is
 * the file. It is our own parser, so unlike the Assimp target it is fuzzed
 * in process in the short ctest runs too. A file it takes must come out
 * whole (triangles, indices in range, finite positions and UVs, unit
 * normals); a file it declines must say why. */
#include <math.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "mesh_native.h"
#include "soak/geometry.h"

static void check_mesh(const soak_mesh *m)
{
    if (m->n_triangles == 0 || !m->normals) abort();
    for (size_t i = 0; i < 3 * m->n_vertices; ++i)
        if (!isfinite(m->positions[i])) abort();
    for (size_t i = 0; m->uvs && i < 2 * m->n_vertices; ++i)
        if (!isfinite(m->uvs[i])) abort();
    for (size_t v = 0; v < m->n_vertices; ++v) {
        const double *n = m->normals + 3 * v;
        if (!(fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1) < 1e-9)) abort();
    }
    for (size_t i = 0; i < 3 * m->n_triangles; ++i)
        if (m->indices[i] >= m->n_vertices) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 1 << 20) return 0;
    const char *ext = data[0] % 12 == 2 ? "stl" : data[0] % 2 ? "ply" : "obj";
    const char *path = fuzz_temp_file(data + 1, size - 1, ext);
    if (!path) return 0;
    soak_mesh m = {0};
    char why[200] = "";
    soak_mesh_request rq = {0, NULL};
    if (soak_mesh_native_read(path, &rq, &m, why, sizeof why)) {
        check_mesh(&m);
        soak_mesh_free(&m);
    } else if (!why[0]) {
        abort();
    }
    return 0;
}
