/* An object's axis-aligned bounds (soak/geometry.h), from its own vertices
 * or sphere: what the isolation analysis, the clear-box shortcut and the
 * photon tracer ask of the geometry without a ray. */
#include <math.h>

#include "geometry_internal.h"

soak_status soak_geometry_object_bounds(const soak_geometry *g, unsigned id, soak_vec3 *lo, soak_vec3 *hi)
{
    if (!g || !lo || !hi) return SOAK_ERR_NULL;
    if (id >= g->count) return SOAK_ERR_ARG;
    const geo_object *o = &g->objects[id];
    if (o->kind == SOAK_SHAPE_SPHERE) {
        *lo = soak_v3_sub(o->center, soak_v3(o->radius, o->radius, o->radius));
        *hi = soak_v3_add(o->center, soak_v3(o->radius, o->radius, o->radius));
        return SOAK_OK;
    }
    double b[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < o->nv; ++i)
        for (int a = 0; a < 3; ++a) {
            b[a] = fmin(b[a], o->pos[3 * i + a]);
            b[3 + a] = fmax(b[3 + a], o->pos[3 * i + a]);
        }
    *lo = soak_v3(b[0], b[1], b[2]);
    *hi = soak_v3(b[3], b[4], b[5]);
    return SOAK_OK;
}
