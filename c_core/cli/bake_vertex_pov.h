/* The per-vertex wetness as a POV-Ray 3.7 include (bake_rain_vertex_pov.c):
 * `#declare NAME = mesh2 { vertex_vectors, normal_vectors (when the mesh
 * has usable normals), texture_list, face_indices with three texture
 * indices per face }`. The texture list holds Soak_Mesh_Texture(W) of
 * povray/soak_mesh.inc for each wetness level in use (the values rounded
 * to 1/BAKE_VERTEX_POV_LEVELS, so a mesh needs at most LEVELS + 1
 * textures); POV-Ray shades a face's three vertex textures and interpolates
 * the results barycentrically. The mesh file's name reaches the include only
 * through soak_escape_povray (issue 51), in a comment. */
#ifndef SOAK_CLI_BAKE_VERTEX_POV_H
#define SOAK_CLI_BAKE_VERTEX_POV_H

#include <stddef.h>

#include "soak/geometry.h"
#include "soak/status.h"

#define BAKE_VERTEX_POV_LEVELS 1000
#define BAKE_VERTEX_POV_NAME_MAX 40
#define BAKE_VERTEX_POV_DEFAULT_NAME "Soak_Wet_Mesh"

/* 1 when path ends in .inc (any case). */
int bake_vertex_pov_path(const char *path);
/* 1 for an identifier POV-Ray cannot mistake for a keyword (its keywords
 * are lower case): a capital letter, then letters, digits and '_', at most
 * BAKE_VERTEX_POV_NAME_MAX bytes. */
int bake_vertex_pov_name_ok(const char *name);
/* Writes the include through a staged file; values in [0, 1]. */
soak_status bake_vertex_pov_write(const char *path, const soak_mesh *m, const float *values, const char *mesh_path,
                                  const char *name, char *err, size_t errlen);

#endif
