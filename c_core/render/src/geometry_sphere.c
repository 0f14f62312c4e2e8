/* Spheres as Embree user geometry, intersected in double precision
 * (soak/geometry.h; the roots and surface point: geometry_internal.h). */
#include "geometry_internal.h"

static void sphere_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const geo_object *o = args->geometryUserPtr;
    double r = o->radius * (1 + 1e-6);
    args->bounds_o->lower_x = (float)(o->center.x - r) - 1e-6f * (float)fabs(o->center.x - r);
    args->bounds_o->lower_y = (float)(o->center.y - r) - 1e-6f * (float)fabs(o->center.y - r);
    args->bounds_o->lower_z = (float)(o->center.z - r) - 1e-6f * (float)fabs(o->center.z - r);
    args->bounds_o->upper_x = (float)(o->center.x + r) + 1e-6f * (float)fabs(o->center.x + r);
    args->bounds_o->upper_y = (float)(o->center.y + r) + 1e-6f * (float)fabs(o->center.y + r);
    args->bounds_o->upper_z = (float)(o->center.z + r) + 1e-6f * (float)fabs(o->center.z + r);
}

/* Embree's RTCRayN/RTCHitN accessors are C++ only. The packet layout is
 * structure-of-arrays: field k of ray i sits at word k*N + i, in the order of
 * struct RTCRayHit (org_x org_y org_z tnear dir_x dir_y dir_z time tfar mask
 * id flags | Ng_x Ng_y Ng_z u v primID geomID instID). */
enum { F_ORG = 0, F_TNEAR = 3, F_DIR = 4, F_TFAR = 8, F_NG = 12, F_U = 15, F_V = 16, F_PRIM = 17, F_GEOM = 18, F_INST = 19 };
#define SOA_F(base, k, N, i) (((float *)(base))[(size_t)(k) * (N) + (i)])
#define SOA_U(base, k, N, i) (((unsigned *)(base))[(size_t)(k) * (N) + (i)])

static int sphere_ray_hit(const geo_object *o, void *rays, unsigned N, unsigned i, double *t_out)
{
    soak_vec3 org = soak_v3(SOA_F(rays, F_ORG, N, i), SOA_F(rays, F_ORG + 1, N, i), SOA_F(rays, F_ORG + 2, N, i));
    soak_vec3 dir = soak_v3(SOA_F(rays, F_DIR, N, i), SOA_F(rays, F_DIR + 1, N, i), SOA_F(rays, F_DIR + 2, N, i));
    double t0, t1, tn = SOA_F(rays, F_TNEAR, N, i), tf = SOA_F(rays, F_TFAR, N, i);
    if (!sphere_roots(o->center, o->radius, org, dir, &t0, &t1)) return 0;
    double t = t0 > tn ? t0 : t1;
    if (!(t > tn && t < tf)) return 0;
    *t_out = t;
    return 1;
}

static void sphere_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    const geo_object *o = args->geometryUserPtr;
    void *rh = args->rayhit;
    unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        double t;
        if (!args->valid[i] || !sphere_ray_hit(o, rh, N, i, &t)) continue;
        soak_vec3 org = soak_v3(SOA_F(rh, F_ORG, N, i), SOA_F(rh, F_ORG + 1, N, i), SOA_F(rh, F_ORG + 2, N, i));
        soak_vec3 dir = soak_v3(SOA_F(rh, F_DIR, N, i), SOA_F(rh, F_DIR + 1, N, i), SOA_F(rh, F_DIR + 2, N, i));
        soak_vec3 n = soak_v3_sub(soak_v3_add(org, soak_v3_scale(dir, t)), o->center);
        SOA_F(rh, F_TFAR, N, i) = (float)t;
        SOA_F(rh, F_NG, N, i) = (float)n.x;
        SOA_F(rh, F_NG + 1, N, i) = (float)n.y;
        SOA_F(rh, F_NG + 2, N, i) = (float)n.z;
        SOA_F(rh, F_U, N, i) = 0;
        SOA_F(rh, F_V, N, i) = 0;
        SOA_U(rh, F_PRIM, N, i) = args->primID;
        SOA_U(rh, F_GEOM, N, i) = args->geomID;
        SOA_U(rh, F_INST, N, i) = args->context->instID[0];
    }
}

static void sphere_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    const geo_object *o = args->geometryUserPtr;
    unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        double t;
        if (!args->valid[i]) continue;
        /* sphere_ray_hit accepts either root inside the interval. */
        if (sphere_ray_hit(o, args->ray, N, i, &t)) SOA_F(args->ray, F_TFAR, N, i) = -INFINITY;
    }
}

soak_status soak_geometry_add_sphere(soak_geometry *g, soak_vec3 center, double radius, unsigned *object_id)
{
    if (!g) return SOAK_ERR_NULL;
    if (!vec_ok(center) || !soak_in_range(radius, 1e-12, 1e9)) return SOAK_ERR_ARG;
    geo_object *o = geo_push_object(g);
    if (!o) return SOAK_ERR_NOMEM;
    o->kind = SOAK_SHAPE_SPHERE;
    o->center = center;
    o->radius = radius;
    RTCGeometry geom = rtcNewGeometry(g->device, RTC_GEOMETRY_TYPE_USER);
    if (!geom) return SOAK_ERR_NOMEM;
    rtcSetGeometryUserPrimitiveCount(geom, 1);
    /* The user pointer is re-set at commit: the object array may move. */
    rtcSetGeometryUserData(geom, o);
    rtcSetGeometryBoundsFunction(geom, sphere_bounds, NULL);
    rtcSetGeometryIntersectFunction(geom, sphere_intersect);
    rtcSetGeometryOccludedFunction(geom, sphere_occluded);
    return geo_commit_and_attach(g, geom, object_id);
}
