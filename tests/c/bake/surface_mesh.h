/* Test meshes for the rain bakes' tests: a surface given as a map from
 * (u, v) in [0,1]^2 to a point, triangulated on its own UVs. */
#ifndef SOAK_TEST_SURFACE_MESH_H
#define SOAK_TEST_SURFACE_MESH_H

#include "soak/bake_rain.h"
#include "soak/geometry.h"

typedef void (*surface_fn)(double u, double v, double out[3]);

/* nu x nv quads over uv in [0,1]^2, CCW in (u, v); normals NULL. */
void surface_mesh(soak_mesh *m, int nu, int nv, surface_fn f);

/* Frees what surface_mesh (or a test's own builder) allocated. */
void surface_mesh_free(soak_mesh *m);

/* Rain parameters whose film and exposure have closed forms: one ray along
 * rain_dir (spread 0, so E = n.rain_dir / rain_dir.up exactly), 60 s of
 * 20 mm/h in one step and one flow iteration, no evaporation, no gutter. */
void surface_rain_params(soak_rain_params *p, soak_vec3 rain_dir);

#endif
