/* Rain wetness per vertex (`soak bake rain MESH --per-vertex OUT`), for
 * meshes with or without UVs.
 *
 * The mesh's own UVs are not used. Each triangle becomes its own chart of a
 * generated atlas: triangles two per square cell of a G x G grid,
 * G = ceil(sqrt(n / 2)), cell side c = floor(min(W, H) / G) texels (at
 * least SOAK_VERTEX_CELL_MIN). In texel coordinates of its cell, the first
 * triangle of a cell has corners (1, 1), (c - 3, 1), (1, c - 3), the second
 * (c - 1, c - 1), (3, c - 1), (c - 1, 3): covered texel centres of two
 * charts are never 8-neighbours (2 texels between cells, 4 along the cell's
 * diagonal), so no water passes from one chart to another through the
 * map. The rain bake (soak/bake_rain.h) runs on that atlas; its per-texel
 * surface points, normals and areas come from the 3D triangle, so the
 * exposure of each face is the same as in any other UV layout.
 *
 * A vertex's value is the mean, weighted by triangle area, over the faces
 * using it, of the map at the texel next to that corner inside the face (its
 * centre 0.7 to 1.6 texels from the corner, toward the centroid). Faces of
 * zero area are not baked and give nothing; a vertex on no face with area
 * gets 0 and is counted.
 *
 * The limit: every face edge is an open edge of its chart, so water does
 * not flow from one face to the next; water running down a slope drips off
 * at the lower edge of each face. Films on slopes and puddles spanning
 * several faces are under-estimated; exposure (rain shadow) and the rain
 * each face receives are not affected. */
#ifndef SOAK_BAKE_VERTEX_H
#define SOAK_BAKE_VERTEX_H

#include <stddef.h>

#include "soak/geometry.h"
#include "soak/image.h"
#include "soak/status.h"

#define SOAK_VERTEX_CELL_MIN 8

/* The square map side (texels) the atlas of n triangles needs. */
long soak_vertex_atlas_min_side(size_t n_triangles);

/* out: the atlas mesh of m for a width x height map: one vertex per
 * triangle corner (3 n_triangles), positions and normals copied, UVs of
 * the atlas. SOAK_ERR_ARG with err giving the size needed when the map is
 * too small. Free out with soak_mesh_free. */
soak_status soak_vertex_atlas(const soak_mesh *m, int width, int height, soak_mesh *out, char *err, size_t errlen);

/* values (m->n_vertices floats, each in [0, 1]): map (baked from
 * soak_vertex_atlas(m, map->width, map->height), 1 channel) gathered per
 * vertex as above; *unreached: vertices on no face with area. */
soak_status soak_vertex_gather(const soak_mesh *m, const soak_image *map, float *values, size_t *unreached, char *err,
                               size_t errlen);

/* Writes the values to path through a staged file (soak/staged.h): by the
 * extension, ".ply" an ASCII PLY of the vertices (x y z, float wetness,
 * uchar red green blue = the sRGB encoding of the wetness as a grey, so
 * that a colour attribute read back as linear gives the wetness) and the
 * faces, ".csv" the lines "index,x,y,z,wetness", ".gltf" / ".glb" as
 * soak_vertex_write_gltf. SOAK_ERR_ARG for another extension; every write
 * checked. */
soak_status soak_vertex_write(const char *path, const soak_mesh *m, const float *values, char *err, size_t errlen);
/* glTF 2.0 (bake_vertex_gltf.c): one mesh, one triangle primitive of the
 * vertices as loaded, POSITION (float, with min/max), NORMAL when every
 * normal of m is usable (written unit), COLOR_0 = (w, w, w, 1) as linear
 * float RGBA (the specification's COLOR_0 is linear: no sRGB encoding), the
 * application-specific float attribute _WETNESS = w, uint32 indices; glb 0:
 * JSON with the buffer as a base64 data URI, 1: binary glTF. Staged. */
soak_status soak_vertex_write_gltf(const char *path, const soak_mesh *m, const float *values, int glb, char *err,
                                   size_t errlen);
/* 1 when path ends in .ply, .csv, .gltf or .glb (any case). */
int soak_vertex_path_ok(const char *path);

#endif
