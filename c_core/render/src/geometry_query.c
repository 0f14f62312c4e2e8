/* Ray queries against the committed scene (soak/geometry.h): closest hits
 * refined in double, occlusion, and Embree's 8-ray packets. */
#include "geometry_internal.h"

/* Shading normal and texture coordinates of triangle tri at barycentrics
 * (b1, b2); ng is the face normal. */
static void triangle_shading(const geo_object *o, const unsigned *tri, double b1, double b2, soak_vec3 ng, soak_hit *hit)
{
    double b0 = 1 - b1 - b2;
    if (o->uv) {
        hit->u = b0 * o->uv[2 * tri[0]] + b1 * o->uv[2 * tri[1]] + b2 * o->uv[2 * tri[2]];
        hit->v = b0 * o->uv[2 * tri[0] + 1] + b1 * o->uv[2 * tri[1] + 1] + b2 * o->uv[2 * tri[2] + 1];
    }
    if (o->nrm) {
        soak_vec3 n = soak_v3_add(soak_v3_add(soak_v3_scale(vtx(o->nrm, tri[0]), b0), soak_v3_scale(vtx(o->nrm, tri[1]), b1)),
                                  soak_v3_scale(vtx(o->nrm, tri[2]), b2));
        if (soak_v3_len(n) > 1e-12) {
            n = soak_v3_norm(n);
            hit->ns = soak_v3_dot(n, ng) < 0 ? soak_v3_scale(n, -1.0) : n;
        }
    }
}

/* Fills hit from Embree's result, recomputing t and p in double. Returns 0 if
 * the refined hit falls outside the ray interval (a float-precision graze).
 * Without detail (a walk's boundary query) the hit keeps u = v = 0 and
 * ns = ng: no interpolation, no atan2/acos. */
static int refine(const soak_geometry *g, const soak_ray *r, const struct RTCRayHit *rh, int detail, soak_hit *hit)
{
    const geo_object *o = &g->objects[rh->hit.geomID];
    double t;
    soak_vec3 ng, ns;
    double u = 0, v = 0;
    if (o->kind == SOAK_SHAPE_SPHERE) {
        double t0, t1, tf = rh->ray.tfar;
        if (!sphere_roots(o->center, o->radius, r->org, r->dir, &t0, &t1)) return 0;
        t = fabs(t0 - tf) <= fabs(t1 - tf) ? t0 : t1;
        soak_vec3 p = soak_v3_add(r->org, soak_v3_scale(r->dir, t));
        if (detail) sphere_surface(o, p, &ng, &u, &v);
        else ng = soak_v3_norm(soak_v3_sub(p, o->center));
        ns = ng;
    } else {
        const unsigned *tri = o->idx + 3 * rh->hit.primID;
        soak_vec3 p0 = vtx(o->pos, tri[0]), p1 = vtx(o->pos, tri[1]), p2 = vtx(o->pos, tri[2]);
        ng = soak_v3_norm(soak_v3_cross(soak_v3_sub(p1, p0), soak_v3_sub(p2, p0)));
        double dn = soak_v3_dot(r->dir, ng);
        t = dn != 0 ? soak_v3_dot(soak_v3_sub(p0, r->org), ng) / dn : rh->ray.tfar;
        soak_hit sh;
        sh.u = sh.v = 0;
        sh.ns = ng;
        if (detail) triangle_shading(o, tri, rh->hit.u, rh->hit.v, ng, &sh);
        u = sh.u;
        v = sh.v;
        ns = sh.ns;
    }
    if (!(t > r->tnear && t < r->tfar) || !soak_is_finite(t)) {
        /* Float traversal accepted a hit the double refinement puts just
         * outside the interval: clamp instead of dropping a real surface. */
        t = fmin(fmax(t, r->tnear), r->tfar);
        if (!soak_is_finite(t)) return 0;
    }
    hit->t = t;
    hit->p = soak_v3_add(r->org, soak_v3_scale(r->dir, t));
    hit->ng = ng;
    hit->ns = ns;
    hit->u = u;
    hit->v = v;
    hit->prim_id = rh->hit.primID;
    hit->object_id = rh->hit.geomID;
    return 1;
}

/* Closest hit in the whole scene; detail: see refine. */
soak_status geo_intersect_scene(const soak_geometry *g, const soak_ray *ray, int detail, soak_hit *hit, int *found)
{
    if (!g->committed) return SOAK_ERR_ARG;
    if (!ray_ok(ray)) return SOAK_ERR_ARG;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRayHit rh;
    to_embree(ray, &rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(g->scene, &ctx, &rh);
    *found = 0;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.geomID >= g->count) return SOAK_OK;
    soak_hit h;
    if (!refine(g, ray, &rh, detail, &h)) return SOAK_OK;
    *hit = h;
    *found = 1;
    return SOAK_OK;
}

soak_status soak_geometry_intersect(const soak_geometry *g, const soak_ray *ray, soak_hit *hit, int *found)
{
    if (!g || !ray || !hit || !found) return SOAK_ERR_NULL;
    return geo_intersect_scene(g, ray, 1, hit, found);
}

soak_status soak_geometry_occluded(const soak_geometry *g, const soak_ray *ray, int *occluded)
{
    if (!g || !ray || !occluded) return SOAK_ERR_NULL;
    if (!g->committed) return SOAK_ERR_ARG;
    if (!ray_ok(ray)) return SOAK_ERR_ARG;
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay r;
    to_embree(ray, &r);
    rtcOccluded1(g->scene, &ctx, &r);
    *occluded = r.tfar == -INFINITY;
    return SOAK_OK;
}

soak_status soak_geometry_intersect_n(const soak_geometry *g, const soak_ray *rays, size_t n, soak_hit *hits, int *found)
{
    if (!g || (n && (!rays || !hits || !found))) return SOAK_ERR_NULL;
    for (size_t i = 0; i < n; ++i) {
        soak_status st = soak_geometry_intersect(g, &rays[i], &hits[i], &found[i]);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

/* Packets of PACKET rays through Embree's packet traversal: the same rays in
 * float as soak_geometry_occluded's, one walk down the BVH for a bundle of
 * similar rays (the rain bake's rays from one texel). */
enum { PACKET = 8 };

static void occluded_packet(const soak_geometry *g, const soak_ray *rays, size_t m, int *occluded)
{
    struct RTCRay8 p;
    _Alignas(32) int valid[PACKET];
    for (size_t k = 0; k < PACKET; ++k) {
        struct RTCRay e;
        to_embree(&rays[k < m ? k : 0], &e);
        valid[k] = k < m ? -1 : 0;
        p.org_x[k] = e.org_x, p.org_y[k] = e.org_y, p.org_z[k] = e.org_z;
        p.dir_x[k] = e.dir_x, p.dir_y[k] = e.dir_y, p.dir_z[k] = e.dir_z;
        p.tnear[k] = e.tnear, p.tfar[k] = e.tfar, p.time[k] = e.time;
        p.mask[k] = e.mask, p.id[k] = e.id, p.flags[k] = e.flags;
    }
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    rtcOccluded8(valid, g->scene, &ctx, &p);
    for (size_t k = 0; k < m; ++k) occluded[k] = p.tfar[k] == -INFINITY;
}

soak_status soak_geometry_occluded_n(const soak_geometry *g, const soak_ray *rays, size_t n, int *occluded)
{
    if (!g || (n && (!rays || !occluded))) return SOAK_ERR_NULL;
    if (n && !g->committed) return SOAK_ERR_ARG;
    for (size_t i = 0; i < n; ++i)
        if (!ray_ok(&rays[i])) return SOAK_ERR_ARG;
    for (size_t i = 0; i < n; i += PACKET) occluded_packet(g, rays + i, n - i < PACKET ? n - i : PACKET, occluded + i);
    return SOAK_OK;
}

/* A packet of rays from one origin (soak_geometry_occluded_fan): the
 * packet's lanes hold what to_embree makes of each ray. */
static void occluded_fan_packet(const soak_geometry *g, const float org[3], const soak_vec3 *dirs, size_t m,
                                int *occluded)
{
    struct RTCRay8 p;
    _Alignas(32) int valid[PACKET];
    for (size_t k = 0; k < PACKET; ++k) {
        const soak_vec3 *d = &dirs[k < m ? k : 0];
        valid[k] = k < m ? -1 : 0;
        p.org_x[k] = org[0], p.org_y[k] = org[1], p.org_z[k] = org[2];
        p.dir_x[k] = (float)d->x, p.dir_y[k] = (float)d->y, p.dir_z[k] = (float)d->z;
        p.tnear[k] = 0.0f, p.tfar[k] = INFINITY, p.time[k] = 0.0f;
        p.mask[k] = 0xFFFFFFFFu, p.id[k] = 0, p.flags[k] = 0;
    }
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    rtcOccluded8(valid, g->scene, &ctx, &p);
    for (size_t k = 0; k < m; ++k) occluded[k] = p.tfar[k] == -INFINITY;
}

soak_status soak_geometry_occluded_fan(const soak_geometry *g, soak_vec3 org, const soak_vec3 *dirs, size_t n,
                                       int *occluded)
{
    if (!g || (n && (!dirs || !occluded))) return SOAK_ERR_NULL;
    if (n && !g->committed) return SOAK_ERR_ARG;
    if (n && !vec_ok(org)) return SOAK_ERR_ARG;
    for (size_t i = 0; i < n; ++i)
        if (!vec_ok(dirs[i]) || !(soak_v3_dot(dirs[i], dirs[i]) > 0)) return SOAK_ERR_ARG;
    const float o[3] = {(float)org.x, (float)org.y, (float)org.z};
    for (size_t i = 0; i < n; i += PACKET) occluded_fan_packet(g, o, dirs + i, n - i < PACKET ? n - i : PACKET, occluded + i);
    return SOAK_OK;
}

soak_vec3 soak_geometry_offset(soak_vec3 p, soak_vec3 ng, soak_vec3 dir)
{
    /* Embree's float traversal errs by a few ulps of the coordinates. */
    double m = fmax(fmax(fabs(p.x), fabs(p.y)), fabs(p.z));
    double eps = 2e-5 * (1.0 + m);
    return soak_v3_add(p, soak_v3_scale(ng, soak_v3_dot(dir, ng) >= 0 ? eps : -eps));
}
