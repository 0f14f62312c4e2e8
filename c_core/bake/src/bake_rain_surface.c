/* The rain bake's surface in UV space (bake_rain_surface.h; soak/bake_rain.h
 * step 1). */
#include "bake_rain_surface.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_flow.h"

static const int *const DX = SOAK_RAIN_DX;
static const int *const DY = SOAK_RAIN_DY;

void soak_rain_surface_free(rain_surface *s)
{
    free(s->tri);
    free(s->pos);
    free(s->nrm);
    free(s->dpdx);
    free(s->dpdy);
    free(s->area);
    free(s->level);
    free(s->adj);
    free(s->drip);
    free(s->descent);
}

void soak_rain_surface_rasterise(const soak_mesh *m, rain_surface *s, soak_vec3 up)
{
    size_t n = (size_t)s->w * s->h;
    for (size_t i = 0; i < n; ++i) s->tri[i] = -1;
    for (size_t t = 0; t < m->n_triangles; ++t) {
        unsigned ix[3] = {m->indices[3 * t], m->indices[3 * t + 1], m->indices[3 * t + 2]};
        double X[3], Y[3];
        soak_vec3 P[3];
        for (int k = 0; k < 3; ++k) {
            X[k] = m->uvs[2 * ix[k]] * s->w;
            Y[k] = (1.0 - m->uvs[2 * ix[k] + 1]) * s->h;
            P[k] = soak_rain_vget(m->positions, ix[k]);
        }
        double den = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
        soak_vec3 cr = soak_v3_cross(soak_v3_sub(P[1], P[0]), soak_v3_sub(P[2], P[0]));
        double area3 = 0.5 * soak_v3_len(cr);
        if (!(fabs(den) > 1e-12) || !(area3 > 0.0) || !soak_is_finite(den)) continue; /* degenerate */
        soak_vec3 ng = soak_v3_scale(cr, 0.5 / area3);
        if (m->normals) {
            soak_vec3 v0 = soak_rain_vget(m->normals, ix[0]), v1 = soak_rain_vget(m->normals, ix[1]);
            soak_vec3 vn = soak_v3_add(soak_v3_add(v0, v1), soak_rain_vget(m->normals, ix[2]));
            if (soak_v3_dot(vn, ng) < 0) ng = soak_v3_scale(ng, -1.0);
        }
        double texel_area = area3 / (0.5 * fabs(den));
        /* World step per texel: solve P = P0 + a (P1-P0) + b (P2-P0) for X, Y. */
        double ia = 1.0 / den;
        soak_vec3 e1 = soak_v3_sub(P[1], P[0]), e2 = soak_v3_sub(P[2], P[0]);
        /* d(a,b)/dX and d(a,b)/dY of the barycentric map. */
        double dadx = (Y[2] - Y[0]) * ia, dbdx = -(Y[1] - Y[0]) * ia;
        double dady = -(X[2] - X[0]) * ia, dbdy = (X[1] - X[0]) * ia;
        soak_vec3 sx = soak_v3_add(soak_v3_scale(e1, dadx), soak_v3_scale(e2, dbdx));
        soak_vec3 sy = soak_v3_add(soak_v3_scale(e1, dady), soak_v3_scale(e2, dbdy));
        double xmin = fmin(X[0], fmin(X[1], X[2])), xmax = fmax(X[0], fmax(X[1], X[2]));
        double ymin = fmin(Y[0], fmin(Y[1], Y[2])), ymax = fmax(Y[0], fmax(Y[1], Y[2]));
        int x0 = (int)fmax(0.0, floor(xmin - 0.5)), x1 = (int)fmin(s->w - 1.0, ceil(xmax - 0.5));
        int y0 = (int)fmax(0.0, floor(ymin - 0.5)), y1 = (int)fmin(s->h - 1.0, ceil(ymax - 0.5));
        const double eps = -1e-9;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                size_t i = (size_t)y * s->w + x;
                if (s->tri[i] >= 0) continue;
                double px = x + 0.5 - X[0], py = y + 0.5 - Y[0];
                double a = px * dadx + py * dady, b = px * dbdx + py * dbdy;
                if (a < eps || b < eps || a + b > 1.0 - eps) continue;
                soak_vec3 p = soak_v3_add(P[0], soak_v3_add(soak_v3_scale(e1, a), soak_v3_scale(e2, b)));
                s->tri[i] = (int)(t < 0x7fffffff ? t : 0x7fffffff);
                s->pos[3 * i] = p.x, s->pos[3 * i + 1] = p.y, s->pos[3 * i + 2] = p.z;
                s->nrm[3 * i] = (float)ng.x, s->nrm[3 * i + 1] = (float)ng.y, s->nrm[3 * i + 2] = (float)ng.z;
                s->dpdx[3 * i] = (float)sx.x, s->dpdx[3 * i + 1] = (float)sx.y, s->dpdx[3 * i + 2] = (float)sx.z;
                s->dpdy[3 * i] = (float)sy.x, s->dpdy[3 * i + 1] = (float)sy.y, s->dpdy[3 * i + 2] = (float)sy.z;
                s->area[i] = (float)texel_area;
                s->level[i] = soak_v3_dot(p, up);
            }
    }
}

/* The direction water runs on the surface, in texel steps per metre run:
 * gravity's part in the tangent plane, g_t = -(up - (up.n) n), written as
 * a dpdx + b dpdy by least squares through the UV Jacobian (dpdx, dpdy) and
 * divided by |g_t|. (0, 0) where the surface is level or the Jacobian
 * degenerate. */
static void descent_direction(soak_vec3 sx, soak_vec3 sy, soak_vec3 n, soak_vec3 up, float out[2])
{
    out[0] = out[1] = 0.0f;
    soak_vec3 gt = soak_v3_sub(soak_v3_scale(n, soak_v3_dot(up, n)), up);
    double slope = soak_v3_len(gt);
    if (!(slope > SOAK_RAIN_LEVEL_TOL)) return;
    double xx = soak_v3_dot(sx, sx), xy = soak_v3_dot(sx, sy), yy = soak_v3_dot(sy, sy);
    double rx = soak_v3_dot(sx, gt), ry = soak_v3_dot(sy, gt), det = xx * yy - xy * xy;
    if (!(det > 1e-12 * xx * yy)) return;
    double a = (yy * rx - xy * ry) / det / slope, b = (xx * ry - xy * rx) / det / slope;
    if (!soak_is_finite(a) || !soak_is_finite(b) || !(a * a + b * b > 0.0)) return;
    out[0] = (float)a;
    out[1] = (float)b;
}

typedef struct connect_job {
    rain_surface *s;
    soak_vec3 up;
} connect_job;

/* Neighbour adjacency (covered, and where the UV step says it should be in
 * 3D: not across a UV seam) and the drip edges of row y. */
static void connect_row(void *ctx, int y, int thread)
{
    (void)thread;
    const connect_job *c = ctx;
    rain_surface *s = c->s;
    soak_vec3 up = c->up;
    for (int x = 0; x < s->w; ++x) {
        size_t i = (size_t)y * s->w + x;
        s->adj[i] = 0;
        s->drip[i] = 0.0f;
        s->descent[2 * i] = s->descent[2 * i + 1] = 0.0f;
        if (s->tri[i] < 0) continue;
        soak_vec3 p = soak_rain_vget(s->pos, i), sx = soak_rain_fget(s->dpdx, i), sy = soak_rain_fget(s->dpdy, i);
        soak_vec3 n = soak_rain_fget(s->nrm, i);
        descent_direction(sx, sy, n, up, s->descent + 2 * i);
        int best = -1;
        double best_drop = 0.0;
        for (int d = 0; d < 8; ++d) {
            soak_vec3 step = soak_v3_add(soak_v3_scale(sx, DX[d]), soak_v3_scale(sy, DY[d]));
            double drop = -soak_v3_dot(step, up); /* level decrease along this step */
            int jx = x + DX[d], jy = y + DY[d];
            int ok = jx >= 0 && jy >= 0 && jx < s->w && jy < s->h;
            if (ok) {
                size_t j = (size_t)jy * s->w + jx;
                ok = s->tri[j] >= 0; /* pos is set on covered texels only */
                if (ok) ok = soak_v3_len(soak_v3_sub(soak_rain_vget(s->pos, j), p)) <= 2.0 * soak_v3_len(step) + 1e-12;
                if (ok) s->adj[i] |= (unsigned char)(1u << d);
            }
            if (drop > best_drop * (1 + 1e-9)) {
                best_drop = drop;
                best = d;
            }
        }
        /* Steepest-descent step leaves the surface: an open edge. */
        if (best >= 0 && !(s->adj[i] >> best & 1u)) s->drip[i] = (float)best_drop;
        /* Faces down (an overhang): everything mobile drips. A vertical face
         * (n.up = 0 up to the float normal's rounding) carries its film down. */
        if (soak_v3_dot(n, up) < -SOAK_RAIN_OVERHANG_TOL) s->drip[i] = -1.0f;
    }
}

/* Adjacency and drips by rows in parallel, then the mean texel size as one
 * sum in texel order. */
soak_status soak_rain_surface_connect(rain_surface *s, soak_vec3 up, const soak_bake_exec *exec)
{
    connect_job c = {s, up};
    soak_status st = soak_parallel_rows(s->h, exec, connect_row, &c, 0.0, 0.0);
    double sum = 0.0;
    long count = 0;
    for (size_t i = 0; i < (size_t)s->w * s->h; ++i)
        if (s->tri[i] >= 0) {
            sum += sqrt(s->area[i]);
            ++count;
        }
    s->mean_texel = count ? sum / (double)count : 0.0;
    return st;
}

soak_status soak_rain_surface_alloc(rain_surface *s, int w, int h)
{
    memset(s, 0, sizeof *s);
    s->w = w;
    s->h = h;
    size_t n = (size_t)w * h;
    s->tri = malloc(n * sizeof *s->tri);
    s->pos = malloc(3 * n * sizeof *s->pos);
    s->nrm = malloc(3 * n * sizeof *s->nrm);
    s->dpdx = malloc(3 * n * sizeof *s->dpdx);
    s->dpdy = malloc(3 * n * sizeof *s->dpdy);
    s->area = malloc(n * sizeof *s->area);
    s->level = malloc(n * sizeof *s->level);
    s->adj = malloc(n);
    s->drip = malloc(n * sizeof *s->drip);
    s->descent = malloc(2 * n * sizeof *s->descent);
    if (!s->tri || !s->pos || !s->nrm || !s->dpdx || !s->dpdy || !s->area || !s->level || !s->adj || !s->drip ||
        !s->descent) {
        soak_rain_surface_free(s);
        return SOAK_ERR_NOMEM;
    }
    return SOAK_OK;
}

/* Texture coordinates beyond this are not a texture layout but corrupt data
 * (a UV of 1e30 was called "not finite"). */
#define SOAK_RAIN_UV_MAX 1e6

soak_status soak_rain_check_mesh(const soak_mesh *m, char *err, size_t errlen)
{
    if (!m->positions || !m->indices || m->n_triangles == 0 || m->n_vertices == 0) {
        if (err && errlen) snprintf(err, errlen, "mesh has no triangles");
        return SOAK_ERR_ARG;
    }
    if (!m->uvs) {
        if (err && errlen) snprintf(err, errlen, "mesh has no UVs: the rain bake needs texture coordinates");
        return SOAK_ERR_ARG;
    }
    for (size_t i = 0; i < 3 * m->n_triangles; ++i)
        if (m->indices[i] >= m->n_vertices) {
            if (err && errlen) snprintf(err, errlen, "mesh index %zu out of range", i);
            return SOAK_ERR_ARG;
        }
    for (size_t i = 0; i < m->n_vertices; ++i) {
        for (int k = 0; k < 3; ++k)
            if (!soak_is_finite(m->positions[3 * i + k])) {
                if (err && errlen) snprintf(err, errlen, "mesh vertex %zu is not finite", i);
                return SOAK_ERR_ARG;
            }
        if (!soak_in_range(m->uvs[2 * i], -SOAK_RAIN_UV_MAX, SOAK_RAIN_UV_MAX) ||
            !soak_in_range(m->uvs[2 * i + 1], -SOAK_RAIN_UV_MAX, SOAK_RAIN_UV_MAX)) {
            if (err && errlen)
                snprintf(err, errlen, "mesh UV %zu (%g, %g) is out of range: UVs must be finite and within [-%g, %g]",
                         i, m->uvs[2 * i], m->uvs[2 * i + 1], SOAK_RAIN_UV_MAX, SOAK_RAIN_UV_MAX);
            return SOAK_ERR_ARG;
        }
    }
    return SOAK_OK;
}
