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
