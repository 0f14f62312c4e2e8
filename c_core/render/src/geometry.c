/* Embree 3 scene of meshes, spheres, quads and boxes; see soak/geometry.h.
 * This file builds the scene: the object store, meshes, quads and boxes as
 * Embree triangle meshes, the commit and the objects' bounds. Spheres:
 * geometry_sphere.c; queries: geometry_query.c, geometry_local.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry_internal.h"

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
        free(g->objects[i].adj);
    }
    free(g->objects);
    if (g->scene) rtcReleaseScene(g->scene);
    if (g->device) rtcReleaseDevice(g->device);
    free(g);
}

geo_object *geo_push_object(soak_geometry *g)
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

/* Commits geom and attaches it as object g->count (Embree errors surface
 * through device_error into g->error). */
soak_status geo_commit_and_attach(soak_geometry *g, RTCGeometry geom, unsigned *object_id)
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
    return geo_commit_and_attach(g, geom, object_id);
}

static void free_object(geo_object *o)
{
    free(o->pos);
    free(o->nrm);
    free(o->uv);
    free(o->idx);
    free(o->adj);
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

    geo_object *o = geo_push_object(g);
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
    geo_object *o = geo_push_object(g);
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
    geo_object *o = geo_push_object(g);
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
        soak_geometry_object_bounds(g, i, &g->objects[i].bound_lo, &g->objects[i].bound_hi);
    for (unsigned i = 0; i < g->count; ++i)
        if (g->objects[i].kind != SOAK_SHAPE_SPHERE) {
            geo_mark_clear_ball(g, i);
            geo_mark_clear_box(g, i);
            geo_mark_convex(g, i);
        }
    for (unsigned i = 0; i < g->count; ++i) geo_mark_convex_isolated(g, i);
    return geo_mark_isolated(g);
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
