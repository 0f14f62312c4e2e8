/* Queries from inside one object (soak/geometry.h): an isolated sphere is
 * answered analytically, an isolated convex mesh by a walk over its faces
 * (geometry_convex.c), a segment inside a clear ball needs no traversal. */
#include "geometry_internal.h"

static const geo_object *local_sphere(const soak_geometry *g, unsigned id)
{
    const geo_object *o = id < g->count ? &g->objects[id] : NULL;
    return o && o->kind == SOAK_SHAPE_SPHERE && o->isolated ? o : NULL;
}

/* Object id when it is an isolated closed convex mesh, else NULL. */
static const geo_object *local_convex(const soak_geometry *g, unsigned id)
{
    const geo_object *o = g->committed && id < g->count ? &g->objects[id] : NULL;
    return o && o->convex_isolated ? o : NULL;
}

soak_status soak_geometry_intersect_local(const soak_geometry *g, unsigned object_id, const soak_ray *ray, int want_uv,
                                          soak_hit *hit, int *found)
{
    if (!g || !ray || !hit || !found) return SOAK_ERR_NULL;
    const geo_object *o = g->committed ? local_sphere(g, object_id) : NULL;
    if (!o) {
        if (!ray_ok(ray)) return SOAK_ERR_ARG;
        if (!want_uv && g->committed && object_id < g->count && geo_box_exit(&g->objects[object_id], object_id, ray, hit, found))
            return SOAK_OK;
        const geo_object *cv = want_uv ? NULL : local_convex(g, object_id);
        if (cv && geo_convex_exit(cv, object_id, ray, hit, found)) return SOAK_OK;
        return geo_intersect_scene(g, ray, want_uv, hit, found);
    }
    if (!ray_ok(ray)) return SOAK_ERR_ARG;
    double t0, t1, t;
    *found = 0;
    if (!sphere_roots(o->center, o->radius, ray->org, ray->dir, &t0, &t1)) return SOAK_OK;
    t = t0 > ray->tnear ? t0 : t1;
    if (!(t > ray->tnear && t < ray->tfar)) return SOAK_OK;
    hit->t = t;
    hit->p = soak_v3_add(ray->org, soak_v3_scale(ray->dir, t));
    if (want_uv) {
        sphere_surface(o, hit->p, &hit->ng, &hit->u, &hit->v);
    } else { /* the walk's many boundary hits need no texture lookup (atan2, acos) */
        hit->ng = soak_v3_norm(soak_v3_sub(hit->p, o->center));
        hit->u = hit->v = 0;
    }
    hit->ns = hit->ng;
    hit->prim_id = 0;
    hit->object_id = object_id;
    *found = 1;
    return SOAK_OK;
}

/* 1 when the segment of ray lies inside object id's clear ball (see
 * mark_clear_ball): no surface on it, no traversal needed. */
static int segment_clear(const soak_geometry *g, unsigned id, const soak_ray *ray)
{
    if (!g->committed || id >= g->count || !(ray->tfar < INFINITY)) return 0;
    const geo_object *o = &g->objects[id];
    soak_vec3 pa = soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tnear));
    soak_vec3 pb = soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tfar));
    if (geo_segment_in_clear_box(o, pa, pb)) return 1;
    if (!(o->clear_r2 > 0)) return 0;
    soak_vec3 a = soak_v3_sub(pa, o->clear_c), b = soak_v3_sub(pb, o->clear_c);
    return soak_v3_dot(a, a) < o->clear_r2 && soak_v3_dot(b, b) < o->clear_r2;
}

soak_status soak_geometry_occluded_local(const soak_geometry *g, unsigned object_id, const soak_ray *ray, int *occluded)
{
    if (!g || !ray || !occluded) return SOAK_ERR_NULL;
    const geo_object *o = g->committed ? local_sphere(g, object_id) : NULL;
    if (!o) {
        if (!ray_ok(ray)) return SOAK_ERR_ARG;
        if (segment_clear(g, object_id, ray)) {
            *occluded = 0; /* a ball is convex: the whole segment is in it */
            return SOAK_OK;
        }
        const geo_object *cv = local_convex(g, object_id);
        soak_hit h;
        if (cv && geo_convex_exit(cv, object_id, ray, &h, occluded)) return SOAK_OK;
        return soak_geometry_occluded(g, ray, occluded);
    }
    if (!ray_ok(ray)) return SOAK_ERR_ARG;
    /* From inside (the walk's case) the segment crosses the convex surface
     * iff it ends outside: two squared distances, no root. */
    double r2 = o->radius * o->radius;
    soak_vec3 a = soak_v3_sub(soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tnear)), o->center);
    if (soak_v3_dot(a, a) < r2 && ray->tfar < INFINITY) {
        soak_vec3 b = soak_v3_sub(soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tfar)), o->center);
        *occluded = soak_v3_dot(b, b) >= r2;
        return SOAK_OK;
    }
    double t0, t1;
    int n = sphere_roots(o->center, o->radius, ray->org, ray->dir, &t0, &t1);
    *occluded = n && ((t0 > ray->tnear && t0 < ray->tfar) || (t1 > ray->tnear && t1 < ray->tfar));
    return SOAK_OK;
}

int soak_geometry_object_isolated(const soak_geometry *g, unsigned object_id)
{
    return g && g->committed && (local_sphere(g, object_id) != NULL || local_convex(g, object_id) != NULL);
}

double soak_geometry_clear_distance(const soak_geometry *g, unsigned object_id, soak_vec3 p)
{
    if (!g || !g->committed || object_id >= g->count) return 0.0;
    const geo_object *o = &g->objects[object_id];
    const geo_object *sph = local_sphere(g, object_id);
    soak_vec3 c = sph ? sph->center : o->clear_c;
    double r = sph ? sph->radius : sqrt(o->clear_r2);
    double d = r - soak_v3_len(soak_v3_sub(p, c));
    return fmax(d > 0 ? d : 0.0, geo_clear_box_distance(o, p));
}

/* 1 when the ray's segment misses the box [lo, hi] grown by pad (slabs). */
static int misses_box(const soak_ray *r, soak_vec3 lo, soak_vec3 hi, double pad)
{
    double t0 = r->tnear, t1 = r->tfar;
    double o[3] = {r->org.x, r->org.y, r->org.z}, d[3] = {r->dir.x, r->dir.y, r->dir.z};
    double l[3] = {lo.x - pad, lo.y - pad, lo.z - pad}, h[3] = {hi.x + pad, hi.y + pad, hi.z + pad};
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (o[a] < l[a] || o[a] > h[a]) return 1;
            continue;
        }
        double ta = (l[a] - o[a]) / d[a], tb = (h[a] - o[a]) / d[a];
        t0 = fmax(t0, fmin(ta, tb));
        t1 = fmin(t1, fmax(ta, tb));
        if (!(t0 <= t1)) return 1;
    }
    return 0;
}

int soak_geometry_ray_escapes(const soak_geometry *g, unsigned object_id, const soak_ray *ray)
{
    if (!g || !ray || !g->committed || object_id >= g->count || g->count > GEO_ESCAPE_MAX_OBJECTS || !ray_ok(ray))
        return 0;
    const geo_object *o = &g->objects[object_id];
    if (!(o->kind == SOAK_SHAPE_SPHERE || o->kind == SOAK_SHAPE_BOX || o->adj)) return 0;
    /* Conservative by Embree's float error at the scene's scale. */
    double m = fmax(fmax(fabs(ray->org.x), fabs(ray->org.y)), fabs(ray->org.z));
    for (unsigned j = 0; j < g->count; ++j) {
        const geo_object *q = &g->objects[j];
        soak_vec3 a = q->bound_lo, b = q->bound_hi;
        double qm = fmax(fmax(fmax(fabs(a.x), fabs(a.y)), fmax(fabs(a.z), fabs(b.x))), fmax(fabs(b.y), fabs(b.z)));
        if (j != object_id && !misses_box(ray, q->bound_lo, q->bound_hi, 1e-5 * (1 + fmax(m, qm)))) return 0;
    }
    return 1;
}
