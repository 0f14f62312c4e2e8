/* Embree 3 scene of meshes, spheres, quads and boxes; see soak/geometry.h.
 * Quads and boxes become triangle meshes; spheres are Embree user geometry
 * intersected in double precision. Every hit is refined in double from the
 * shape data so t and p do not carry Embree's float error. */
#include "soak/geometry.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct geo_object {
    soak_shape_kind kind;
    size_t nv, nt;
    double *pos; /* 3 nv */
    double *nrm; /* 3 nv or NULL */
    double *uv;  /* 2 nv or NULL */
    unsigned *idx;
    soak_vec3 center; /* spheres */
    double radius;
    int isolated; /* no other surface enters the interior (spheres; set at commit) */
    soak_vec3 clear_c; /* a ball no surface enters (set at commit; clear_r2 = 0: none) */
    double clear_r2;
} geo_object;

struct soak_geometry {
    RTCDevice device;
    RTCScene scene;
    geo_object *objects;
    unsigned count, capacity;
    int committed;
    int robust; /* Embree's robust traversal (on unless soak_geometry_set_robust turns it off) */
    char error[256]; /* last Embree device error, written by its callback */
};

static void device_error(void *user, enum RTCError code, const char *str)
{
    soak_geometry *g = user;
    snprintf(g->error, sizeof g->error, "Embree error %d: %s", (int)code, str ? str : "");
}

soak_status soak_geometry_create(soak_geometry **out, char *err, size_t errlen)
{
    if (!out) return SOAK_ERR_NULL;
    soak_geometry *g = calloc(1, sizeof *g);
    if (!g) return SOAK_ERR_NOMEM;
    g->device = rtcNewDevice(NULL);
    if (!g->device) {
        if (err && errlen) snprintf(err, errlen, "Embree: cannot create a device (error %d)", (int)rtcGetDeviceError(NULL));
        free(g);
        return SOAK_ERR_UNSUPPORTED;
    }
    rtcSetDeviceErrorFunction(g->device, device_error, g);
    g->scene = rtcNewScene(g->device);
    if (!g->scene) {
        if (err && errlen) snprintf(err, errlen, "%s", g->error[0] ? g->error : "Embree: cannot create a scene");
        rtcReleaseDevice(g->device);
        free(g);
        return SOAK_ERR_NOMEM;
    }
    g->robust = 1;
    *out = g;
    return SOAK_OK;
}

void soak_geometry_destroy(soak_geometry *g)
{
    if (!g) return;
    for (unsigned i = 0; i < g->count; ++i) {
        free(g->objects[i].pos);
        free(g->objects[i].nrm);
        free(g->objects[i].uv);
        free(g->objects[i].idx);
    }
    free(g->objects);
    if (g->scene) rtcReleaseScene(g->scene);
    if (g->device) rtcReleaseDevice(g->device);
    free(g);
}

static geo_object *push_object(soak_geometry *g)
{
    if (g->count == g->capacity) {
        unsigned cap = g->capacity ? 2 * g->capacity : 8;
        geo_object *o = realloc(g->objects, cap * sizeof *o);
        if (!o) return NULL;
        g->objects = o;
        g->capacity = cap;
    }
    geo_object *o = &g->objects[g->count];
    memset(o, 0, sizeof *o);
    return o;
}

static soak_vec3 vtx(const double *a, unsigned i) { return soak_v3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

static int vec_ok(soak_vec3 v) { return soak_is_finite(v.x) && soak_is_finite(v.y) && soak_is_finite(v.z); }

/* Commits geom and attaches it as object g->count (Embree errors surface
 * through device_error into g->error). */
static soak_status commit_and_attach(soak_geometry *g, RTCGeometry geom, unsigned *object_id)
{
    rtcCommitGeometry(geom);
    g->error[0] = '\0';
    rtcAttachGeometryByID(g->scene, geom, g->count);
    rtcReleaseGeometry(geom);
    if (g->error[0]) return SOAK_ERR_ARG;
    if (object_id) *object_id = g->count;
    g->count++;
    g->committed = 0;
    return SOAK_OK;
}

/* Hands a filled triangle object (last pushed) to Embree. */
static soak_status attach_triangles(soak_geometry *g, geo_object *o, unsigned *object_id)
{
    RTCGeometry geom = rtcNewGeometry(g->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geom) return SOAK_ERR_NOMEM;
    float *vb = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), o->nv);
    unsigned *ib = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), o->nt);
    if (!vb || !ib) {
        rtcReleaseGeometry(geom);
        return SOAK_ERR_NOMEM;
    }
    for (size_t i = 0; i < 3 * o->nv; ++i) vb[i] = (float)o->pos[i];
    memcpy(ib, o->idx, 3 * o->nt * sizeof(unsigned));
    return commit_and_attach(g, geom, object_id);
}

static void free_object(geo_object *o)
{
    free(o->pos);
    free(o->nrm);
    free(o->uv);
    free(o->idx);
    memset(o, 0, sizeof *o);
}

static soak_status alloc_triangles(geo_object *o, size_t nv, size_t nt, int normals, int uvs)
{
    o->nv = nv;
    o->nt = nt;
    o->pos = malloc(3 * nv * sizeof(double));
    o->nrm = normals ? malloc(3 * nv * sizeof(double)) : NULL;
    o->uv = uvs ? malloc(2 * nv * sizeof(double)) : NULL;
    o->idx = malloc(3 * nt * sizeof(unsigned));
    if (!o->pos || !o->idx || (normals && !o->nrm) || (uvs && !o->uv)) {
        free_object(o);
        return SOAK_ERR_NOMEM;
    }
    return SOAK_OK;
}

soak_status soak_geometry_add_mesh(soak_geometry *g, const soak_mesh *m, const double *xform, unsigned *object_id)
{
    if (!g || !m || !m->positions || !m->indices) return SOAK_ERR_NULL;
    if (m->n_vertices == 0 || m->n_triangles == 0 || m->n_vertices > 0xFFFFFFFEu || m->n_triangles > 0x3FFFFFFFu)
        return SOAK_ERR_ARG;
    double M[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    if (xform) memcpy(M, xform, sizeof M);
    for (int i = 0; i < 12; ++i)
        if (!soak_is_finite(M[i])) return SOAK_ERR_ARG;
    /* Cofactor matrix of the 3x3 part = det * inverse transpose: maps normals. */
    double a = M[0], b = M[1], c = M[2], d = M[4], e = M[5], f = M[6], h = M[8], k = M[9], l = M[10];
    double C[9] = {e * l - f * k, f * h - d * l, d * k - e * h, c * k - b * l, a * l - c * h,
                   b * h - a * k, b * f - c * e, c * d - a * f, a * e - b * d};
    double det = a * C[0] + b * C[1] + c * C[2];
    if (!(fabs(det) > 1e-300)) return SOAK_ERR_ARG;
    for (size_t i = 0; i < 3 * m->n_triangles; ++i)
        if (m->indices[i] >= m->n_vertices) return SOAK_ERR_ARG;
    for (size_t i = 0; i < 3 * m->n_vertices; ++i)
        if (!soak_is_finite(m->positions[i]) || (m->normals && !soak_is_finite(m->normals[i]))) return SOAK_ERR_ARG;
    if (m->uvs)
        for (size_t i = 0; i < 2 * m->n_vertices; ++i)
            if (!soak_is_finite(m->uvs[i])) return SOAK_ERR_ARG;

    geo_object *o = push_object(g);
    if (!o) return SOAK_ERR_NOMEM;
    soak_status st = alloc_triangles(o, m->n_vertices, m->n_triangles, m->normals != NULL, m->uvs != NULL);
    if (st != SOAK_OK) return st;
    o->kind = SOAK_SHAPE_MESH;
    for (size_t i = 0; i < m->n_vertices; ++i) {
        const double *p = m->positions + 3 * i;
        for (int r = 0; r < 3; ++r) o->pos[3 * i + r] = M[4 * r] * p[0] + M[4 * r + 1] * p[1] + M[4 * r + 2] * p[2] + M[4 * r + 3];
        if (o->nrm) {
            const double *n = m->normals + 3 * i;
            soak_vec3 t = soak_v3(C[0] * n[0] + C[1] * n[1] + C[2] * n[2], C[3] * n[0] + C[4] * n[1] + C[5] * n[2],
                                  C[6] * n[0] + C[7] * n[1] + C[8] * n[2]);
            if (det < 0) t = soak_v3_scale(t, -1.0);
            t = soak_v3_norm(t);
            o->nrm[3 * i] = t.x;
            o->nrm[3 * i + 1] = t.y;
            o->nrm[3 * i + 2] = t.z;
        }
    }
    if (o->uv) memcpy(o->uv, m->uvs, 2 * m->n_vertices * sizeof(double));
    for (size_t i = 0; i < m->n_triangles; ++i) {
        /* A mirroring transform reverses the winding; swap to keep the front side. */
        o->idx[3 * i] = m->indices[3 * i];
        o->idx[3 * i + 1] = m->indices[3 * i + (det < 0 ? 2 : 1)];
        o->idx[3 * i + 2] = m->indices[3 * i + (det < 0 ? 1 : 2)];
    }
    st = attach_triangles(g, o, object_id);
    if (st != SOAK_OK) free_object(o);
    return st;
}

soak_status soak_geometry_add_quad(soak_geometry *g, soak_vec3 origin, soak_vec3 eu, soak_vec3 ev, unsigned *object_id)
{
    if (!g) return SOAK_ERR_NULL;
    if (!vec_ok(origin) || !vec_ok(eu) || !vec_ok(ev)) return SOAK_ERR_ARG;
    soak_vec3 n = soak_v3_cross(eu, ev);
    if (!(soak_v3_len(n) > 1e-300)) return SOAK_ERR_ARG;
    geo_object *o = push_object(g);
    if (!o) return SOAK_ERR_NOMEM;
    soak_status st = alloc_triangles(o, 4, 2, 0, 1);
    if (st != SOAK_OK) return st;
    o->kind = SOAK_SHAPE_QUAD;
    static const double st_uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    for (int i = 0; i < 4; ++i) {
        soak_vec3 p = soak_v3_add(origin, soak_v3_add(soak_v3_scale(eu, st_uv[2 * i]), soak_v3_scale(ev, st_uv[2 * i + 1])));
        o->pos[3 * i] = p.x;
        o->pos[3 * i + 1] = p.y;
        o->pos[3 * i + 2] = p.z;
    }
    memcpy(o->uv, st_uv, sizeof st_uv);
    static const unsigned tri[6] = {0, 1, 2, 0, 2, 3};
    memcpy(o->idx, tri, sizeof tri);
    st = attach_triangles(g, o, object_id);
    if (st != SOAK_OK) free_object(o);
    return st;
}

soak_status soak_geometry_add_box(soak_geometry *g, soak_vec3 lo, soak_vec3 hi, unsigned *object_id)
{
    if (!g) return SOAK_ERR_NULL;
    if (!vec_ok(lo) || !vec_ok(hi) || !(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) return SOAK_ERR_ARG;
    geo_object *o = push_object(g);
    if (!o) return SOAK_ERR_NOMEM;
    soak_status st = alloc_triangles(o, 24, 12, 0, 1);
    if (st != SOAK_OK) return st;
    o->kind = SOAK_SHAPE_BOX;
    /* Each face: axis, side, and two in-plane axes ordered so (u x v) points out. */
    static const int face[6][4] = {{0, 1, 1, 2}, {0, 0, 2, 1}, {1, 1, 2, 0}, {1, 0, 0, 2}, {2, 1, 0, 1}, {2, 0, 1, 0}};
    static const double st_uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    double b[2][3] = {{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}};
    for (int f = 0; f < 6; ++f) {
        int ax = face[f][0], side = face[f][1], ua = face[f][2], va = face[f][3];
        for (int i = 0; i < 4; ++i) {
            double *p = o->pos + 3 * (4 * f + i);
            p[ax] = b[side][ax];
            p[ua] = b[(int)st_uv[2 * i]][ua];
            p[va] = b[(int)st_uv[2 * i + 1]][va];
            o->uv[2 * (4 * f + i)] = st_uv[2 * i];
            o->uv[2 * (4 * f + i) + 1] = st_uv[2 * i + 1];
        }
        unsigned v0 = 4u * (unsigned)f;
        unsigned *t = o->idx + 6 * f;
        t[0] = v0; t[1] = v0 + 1; t[2] = v0 + 2;
        t[3] = v0; t[4] = v0 + 2; t[5] = v0 + 3;
    }
    st = attach_triangles(g, o, object_id);
    if (st != SOAK_OK) free_object(o);
    return st;
}

/* Sphere roots of |o + t d - c|^2 = r^2 in double; returns the count of real
 * roots, t0 <= t1. Uses the numerically stable form (no cancellation). */
static int sphere_roots(soak_vec3 c, double r, soak_vec3 o, soak_vec3 d, double *t0, double *t1)
{
    soak_vec3 oc = soak_v3_sub(o, c);
    double A = soak_v3_dot(d, d), B = soak_v3_dot(oc, d), Cc = soak_v3_dot(oc, oc) - r * r;
    /* Discriminant from the perpendicular distance: less cancellation far away. */
    soak_vec3 perp = soak_v3_sub(oc, soak_v3_scale(d, B / A));
    double disc = A * (r * r - soak_v3_dot(perp, perp));
    if (!(A > 0) || disc < 0) return 0;
    double q = -(B + copysign(sqrt(disc), B));
    double a0 = q / A, a1 = q != 0 ? Cc / q : a0;
    *t0 = fmin(a0, a1);
    *t1 = fmax(a0, a1);
    return 2;
}

/* Outward normal and (longitude, colatitude) texture coordinates at p. */
static void sphere_surface(const geo_object *o, soak_vec3 p, soak_vec3 *ng, double *u, double *v)
{
    soak_vec3 n = soak_v3_norm(soak_v3_sub(p, o->center));
    double phi = atan2(n.y, n.x);
    *ng = n;
    *u = (phi < 0 ? phi + 2 * SOAK_PI : phi) / (2 * SOAK_PI);
    *v = acos(fmax(-1.0, fmin(1.0, n.z))) / SOAK_PI;
}

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
    geo_object *o = push_object(g);
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
    return commit_and_attach(g, geom, object_id);
}

/* Closest point to p on triangle abc, by the Voronoi regions of its
 * vertices, edges and face (C. Ericson, Real-Time Collision Detection, 2005,
 * sec. 5.1.5). */
static soak_vec3 closest_on_triangle(soak_vec3 p, soak_vec3 a, soak_vec3 b, soak_vec3 c)
{
    soak_vec3 ab = soak_v3_sub(b, a), ac = soak_v3_sub(c, a), ap = soak_v3_sub(p, a);
    double d1 = soak_v3_dot(ab, ap), d2 = soak_v3_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    soak_vec3 bp = soak_v3_sub(p, b);
    double d3 = soak_v3_dot(ab, bp), d4 = soak_v3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return soak_v3_add(a, soak_v3_scale(ab, d1 / (d1 - d3)));
    soak_vec3 cp = soak_v3_sub(p, c);
    double d5 = soak_v3_dot(ab, cp), d6 = soak_v3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return soak_v3_add(a, soak_v3_scale(ac, d2 / (d2 - d6)));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return soak_v3_add(b, soak_v3_scale(soak_v3_sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    double den = va + vb + vc;
    if (!(fabs(den) > 0)) return a; /* degenerate triangle */
    return soak_v3_add(a, soak_v3_add(soak_v3_scale(ab, vb / den), soak_v3_scale(ac, vc / den)));
}

typedef struct nearest_query {
    const soak_geometry *g;
    unsigned skip; /* object not counted */
    int skip_concentric; /* nor any sphere centred exactly at p */
    soak_vec3 p;
    double best;   /* smallest distance found so far, double */
} nearest_query;

/* rtcPointQuery callback, once per primitive whose bounds meet the query
 * ball: exact distance in double, and the ball shrinks to it. */
static bool nearest_prim(struct RTCPointQueryFunctionArguments *args)
{
    nearest_query *q = args->userPtr;
    if (args->geomID >= q->g->count || args->geomID == q->skip) return false;
    const geo_object *o = &q->g->objects[args->geomID];
    if (q->skip_concentric && o->kind == SOAK_SHAPE_SPHERE && o->center.x == q->p.x && o->center.y == q->p.y &&
        o->center.z == q->p.z)
        return false;
    double d;
    if (o->kind == SOAK_SHAPE_SPHERE) {
        d = fabs(soak_v3_len(soak_v3_sub(q->p, o->center)) - o->radius);
    } else {
        const unsigned *tri = o->idx + 3 * args->primID;
        d = soak_v3_len(soak_v3_sub(q->p, closest_on_triangle(q->p, vtx(o->pos, tri[0]), vtx(o->pos, tri[1]), vtx(o->pos, tri[2]))));
    }
    if (!(d < q->best)) return false;
    q->best = d;
    args->query->radius = nextafterf((float)d, INFINITY); /* rounded up: never culls a nearer primitive */
    return true;
}

/* A sphere is isolated when every other surface is at least its radius from
 * its centre (less a relative 1e-9, so a plane it rests on, touching it at
 * one point, does not count). */
/* Distance from c to the nearest surface within reach of radius r, other
 * than object skip (and, with skip_concentric, any sphere centred at c). */
static double nearest_surface(const soak_geometry *g, unsigned skip, int skip_concentric, soak_vec3 c, double r)
{
    nearest_query q = {g, skip, skip_concentric, c, INFINITY};
    float reach = (float)(r * (1 + 1e-6)) + 1e-6f * (float)(1 + soak_v3_len(c));
    struct RTCPointQuery pq = {(float)c.x, (float)c.y, (float)c.z, 0.0f, reach};
    struct RTCPointQueryContext ctx;
    rtcInitPointQueryContext(&ctx);
    rtcPointQuery(g->scene, &pq, &ctx, nearest_prim, &q);
    return q.best;
}

static int sphere_isolated(const soak_geometry *g, unsigned id)
{
    const geo_object *o = &g->objects[id];
    return nearest_surface(g, id, 0, o->center, o->radius) >= o->radius * (1 - 1e-9);
}

static int by_centre(const void *pa, const void *pb)
{
    const geo_object *a = *(const geo_object *const *)pa, *b = *(const geo_object *const *)pb;
    if (a->center.x != b->center.x) return a->center.x < b->center.x ? -1 : 1;
    if (a->center.y != b->center.y) return a->center.y < b->center.y ? -1 : 1;
    if (a->center.z != b->center.z) return a->center.z < b->center.z ? -1 : 1;
    return a->radius < b->radius ? -1 : a->radius > b->radius;
}

/* Spheres sharing one centre (sorted by radius in s[0..k)): one point query
 * for the surfaces outside the group instead of k queries that each visit
 * all k (quadratic for stacked spheres). Inside the group the nearest other
 * surface from the centre is the smallest other radius. */
static void concentric_isolated(const soak_geometry *g, geo_object **s, size_t k)
{
    double outside = nearest_surface(g, (unsigned)-1, 1, s[0]->center, s[k - 1]->radius);
    for (size_t i = 0; i < k; ++i) {
        double inside = s[i == 0 ? 1 : 0]->radius;
        double d = inside < outside ? inside : outside;
        s[i]->isolated = d >= s[i]->radius * (1 - 1e-9);
    }
}

/* Sets isolated on every sphere; SOAK_ERR_NOMEM when the sort has no memory. */
static soak_status mark_isolated(soak_geometry *g)
{
    size_t n = 0;
    for (unsigned i = 0; i < g->count; ++i) n += g->objects[i].kind == SOAK_SHAPE_SPHERE;
    if (n == 0) return SOAK_OK;
    geo_object **s = malloc(n * sizeof *s);
    if (!s) return SOAK_ERR_NOMEM;
    n = 0;
    for (unsigned i = 0; i < g->count; ++i)
        if (g->objects[i].kind == SOAK_SHAPE_SPHERE) s[n++] = &g->objects[i];
    qsort(s, n, sizeof *s, by_centre);
    for (size_t i = 0; i < n;) {
        size_t k = 1;
        while (i + k < n && s[i + k]->center.x == s[i]->center.x && s[i + k]->center.y == s[i]->center.y &&
               s[i + k]->center.z == s[i]->center.z)
            ++k;
        if (k == 1) s[i]->isolated = sphere_isolated(g, (unsigned)(s[i] - g->objects));
        else concentric_isolated(g, s + i, k);
        i += k;
    }
    free(s);
    return SOAK_OK;
}

/* The clear ball of a triangle object: around the centre of its bounds, up
 * to the nearest surface of any object, less a margin above Embree's float
 * error (the scale of soak_geometry_offset's), so a segment inside it meets
 * no surface for Embree either. A closed convex object's ball is its
 * inscribed sphere about that centre; a flat or hollow one gets none. */
static void mark_clear_ball(soak_geometry *g, unsigned id)
{
    geo_object *o = &g->objects[id];
    soak_vec3 lo, hi;
    o->clear_r2 = 0;
    if (soak_geometry_object_bounds(g, id, &lo, &hi) != SOAK_OK) return;
    soak_vec3 c = soak_v3_scale(soak_v3_add(lo, hi), 0.5);
    double reach = 0.5 * soak_v3_len(soak_v3_sub(hi, lo));
    double m = fmax(fmax(fabs(c.x), fabs(c.y)), fabs(c.z)) + reach;
    double r = fmin(nearest_surface(g, (unsigned)-1, 0, c, reach), reach) * (1 - 1e-6) - 1e-5 * (1 + m);
    o->clear_c = c;
    o->clear_r2 = r > 0 ? r * r : 0;
}

soak_status soak_geometry_commit(soak_geometry *g)
{
    if (!g) return SOAK_ERR_NULL;
    g->error[0] = '\0';
    for (unsigned i = 0; i < g->count; ++i) {
        if (g->objects[i].kind != SOAK_SHAPE_SPHERE) continue;
        RTCGeometry geom = rtcGetGeometry(g->scene, i);
        rtcSetGeometryUserData(geom, &g->objects[i]);
        rtcCommitGeometry(geom);
    }
    rtcSetSceneFlags(g->scene, g->robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcCommitScene(g->scene);
    if (g->error[0]) return SOAK_ERR_NUMERIC;
    g->committed = 1;
    for (unsigned i = 0; i < g->count; ++i)
        if (g->objects[i].kind != SOAK_SHAPE_SPHERE) mark_clear_ball(g, i);
    return mark_isolated(g);
}

soak_status soak_geometry_set_robust(soak_geometry *g, int robust)
{
    if (!g) return SOAK_ERR_NULL;
    g->robust = robust != 0;
    g->committed = 0;
    return SOAK_OK;
}

unsigned soak_geometry_object_count(const soak_geometry *g) { return g ? g->count : 0; }

soak_shape_kind soak_geometry_object_kind(const soak_geometry *g, unsigned id)
{
    return g && id < g->count ? g->objects[id].kind : SOAK_SHAPE_MESH;
}

size_t soak_geometry_triangle_count(const soak_geometry *g, unsigned id)
{
    return g && id < g->count ? g->objects[id].nt : 0;
}

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

soak_status soak_geometry_bounds(const soak_geometry *g, soak_vec3 *lo, soak_vec3 *hi)
{
    if (!g || !lo || !hi) return SOAK_ERR_NULL;
    if (!g->committed || g->count == 0) return SOAK_ERR_ARG;
    struct RTCBounds b;
    rtcGetSceneBounds(g->scene, &b);
    *lo = soak_v3(b.lower_x, b.lower_y, b.lower_z);
    *hi = soak_v3(b.upper_x, b.upper_y, b.upper_z);
    return SOAK_OK;
}

static int ray_ok(const soak_ray *r)
{
    return vec_ok(r->org) && vec_ok(r->dir) && soak_v3_dot(r->dir, r->dir) > 0 && soak_in_range(r->tnear, 0, 1e300) &&
           r->tfar > r->tnear;
}

static void to_embree(const soak_ray *r, struct RTCRay *e)
{
    e->org_x = (float)r->org.x;
    e->org_y = (float)r->org.y;
    e->org_z = (float)r->org.z;
    e->dir_x = (float)r->dir.x;
    e->dir_y = (float)r->dir.y;
    e->dir_z = (float)r->dir.z;
    e->tnear = (float)r->tnear;
    e->tfar = r->tfar > 3e38 ? INFINITY : (float)r->tfar;
    e->time = 0;
    e->mask = 0xFFFFFFFFu;
    e->id = 0;
    e->flags = 0;
}


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
static soak_status intersect_scene(const soak_geometry *g, const soak_ray *ray, int detail, soak_hit *hit, int *found)
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
    return intersect_scene(g, ray, 1, hit, found);
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

static const geo_object *local_sphere(const soak_geometry *g, unsigned id)
{
    const geo_object *o = id < g->count ? &g->objects[id] : NULL;
    return o && o->kind == SOAK_SHAPE_SPHERE && o->isolated ? o : NULL;
}

soak_status soak_geometry_intersect_local(const soak_geometry *g, unsigned object_id, const soak_ray *ray, int want_uv,
                                          soak_hit *hit, int *found)
{
    if (!g || !ray || !hit || !found) return SOAK_ERR_NULL;
    const geo_object *o = g->committed ? local_sphere(g, object_id) : NULL;
    if (!o) return intersect_scene(g, ray, want_uv, hit, found);
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
    if (!g->committed || id >= g->count || !(g->objects[id].clear_r2 > 0) || !(ray->tfar < INFINITY)) return 0;
    const geo_object *o = &g->objects[id];
    soak_vec3 a = soak_v3_sub(soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tnear)), o->clear_c);
    soak_vec3 b = soak_v3_sub(soak_v3_add(ray->org, soak_v3_scale(ray->dir, ray->tfar)), o->clear_c);
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
    return g && g->committed && local_sphere(g, object_id) != NULL;
}

double soak_geometry_clear_distance(const soak_geometry *g, unsigned object_id, soak_vec3 p)
{
    if (!g || !g->committed || object_id >= g->count) return 0.0;
    const geo_object *o = &g->objects[object_id];
    const geo_object *sph = local_sphere(g, object_id);
    soak_vec3 c = sph ? sph->center : o->clear_c;
    double r = sph ? sph->radius : sqrt(o->clear_r2);
    double d = r - soak_v3_len(soak_v3_sub(p, c));
    return d > 0 ? d : 0.0;
}

soak_vec3 soak_geometry_offset(soak_vec3 p, soak_vec3 ng, soak_vec3 dir)
{
    /* Embree's float traversal errs by a few ulps of the coordinates. */
    double m = fmax(fmax(fabs(p.x), fabs(p.y)), fabs(p.z));
    double eps = 2e-5 * (1.0 + m);
    return soak_v3_add(p, soak_v3_scale(ng, soak_v3_dot(dir, ng) >= 0 ? eps : -eps));
}
