#include "surface_mesh.h"

#include <stdlib.h>
#include <string.h>

static void surface_triangles(soak_mesh *m, int nu, int nv)
{
    size_t t = 0;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            unsigned a = (unsigned)(j * (nu + 1) + i), b = a + 1, c = a + (unsigned)(nu + 1), d = c + 1;
            unsigned tri[6] = {a, b, d, a, d, c};
            memcpy(m->indices + 3 * t, tri, sizeof tri);
            t += 2;
        }
}

void surface_mesh(soak_mesh *m, int nu, int nv, surface_fn f)
{
    m->tri_uv = NULL;
    m->n_vertices = (size_t)(nu + 1) * (nv + 1);
    m->n_triangles = 2 * (size_t)nu * nv;
    m->positions = malloc(3 * m->n_vertices * sizeof(double));
    m->uvs = malloc(2 * m->n_vertices * sizeof(double));
    m->normals = NULL;
    m->indices = malloc(3 * m->n_triangles * sizeof(unsigned));
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            size_t k = (size_t)j * (nu + 1) + i;
            m->uvs[2 * k] = (double)i / nu;
            m->uvs[2 * k + 1] = (double)j / nv;
            f(m->uvs[2 * k], m->uvs[2 * k + 1], m->positions + 3 * k);
        }
    surface_triangles(m, nu, nv);
}

void surface_mesh_free(soak_mesh *m)
{
    free(m->positions);
    free(m->uvs);
    free(m->indices);
    free(m->normals);
}

void surface_rain_params(soak_rain_params *p, soak_vec3 rain_dir)
{
    soak_rain_defaults(p);
    p->rays = 1;
    p->spread_deg = 0;
    p->rain_dir = rain_dir;
    p->duration = 60;
    p->steps = 1;
    p->flow_iterations = 1;
    p->evaporation_mm_h = 0;
    p->rainfall_mm_h = 20;
    p->gutter = 0;
}
