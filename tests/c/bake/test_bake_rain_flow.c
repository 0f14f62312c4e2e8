/* The rain bake's fused flow sweep (c_core/bake/src/bake_rain_flow.h)
 * against a straightforward reference written here: the two-pass Jacobi
 * scheme that stores nine float outflows per texel (outflow pass, then
 * gather pass), on a random grid with uncovered texels, one-way adjacency,
 * drip edges and down-facing texels. The fused sweep keeps the reference's
 * operation order, so the depths must agree bitwise, at 1, 2 and 3 threads.
 * Identity check on the reference itself: with no drip anywhere, the total
 * volume sum(depth * area) is conserved (relative 1e-6: outflows are
 * rounded to float). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_flow.h"
#include "check.h"
#include "soak/rng.h"

typedef struct grid_data {
    int w, h;
    unsigned char *covered, *adj;
    float *area, *drip;
    double *level, *retain, *depth;
} grid_data;

static void grid_make(grid_data *d, int w, int h, uint64_t seed, int drips)
{
    size_t n = (size_t)w * h;
    d->w = w;
    d->h = h;
    d->covered = calloc(n, 1);
    d->adj = calloc(n, 1);
    d->area = calloc(n, sizeof *d->area);
    d->drip = calloc(n, sizeof *d->drip);
    d->level = calloc(n, sizeof *d->level);
    d->retain = calloc(n, sizeof *d->retain);
    d->depth = calloc(n, sizeof *d->depth);
    soak_rng r;
    soak_rng_seed(&r, seed, 0);
    for (size_t i = 0; i < n; ++i) d->covered[i] = soak_rng_uniform(&r) > 0.1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            /* a tilted bowl with noise: puddles and slopes */
            double u = (x - 0.3 * w) / w, v = (y - 0.6 * h) / h;
            d->level[i] = 0.01 * (u * u + v * v) + 0.002 * u + 1e-4 * soak_rng_uniform(&r);
            if (!d->covered[i]) continue;
            d->area[i] = (float)(1e-6 * (0.5 + soak_rng_uniform(&r)));
            d->retain[i] = 2e-4 * soak_rng_uniform(&r);
            d->depth[i] = 2e-3 * soak_rng_uniform(&r) * soak_rng_uniform(&r);
            double q = soak_rng_uniform(&r);
            if (drips) d->drip[i] = q < 0.03 ? -1.0f : (q < 0.08 ? (float)(1e-3 * soak_rng_uniform(&r)) : 0.0f);
            for (int k = 0; k < 8; ++k) {
                int kx = x + SOAK_RAIN_DX[k], ky = y + SOAK_RAIN_DY[k];
                if (kx < 0 || ky < 0 || kx >= w || ky >= h || !d->covered[(size_t)ky * w + kx]) continue;
                if (soak_rng_uniform(&r) < 0.95) d->adj[i] |= (unsigned char)(1u << k); /* some one-way links */
            }
        }
}

static void grid_free(grid_data *d)
{
    free(d->covered);
    free(d->adj);
    free(d->area);
    free(d->drip);
    free(d->level);
    free(d->retain);
    free(d->depth);
}

/* The reference: outflows of every texel from the old depths, then the gather. */
static void reference_sweep(const grid_data *d, double *depth, float *out9)
{
    int w = d->w, h = d->h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            float *o = out9 + 9 * i;
            for (int k = 0; k < 9; ++k) o[k] = 0.0f;
            if (!d->covered[i]) continue;
            double hh = depth[i], mobile = hh - d->retain[i];
            if (!(mobile > 0.0)) continue;
            if (d->drip[i] < 0.0f) {
                o[8] = (float)mobile;
                continue;
            }
            double lvl = d->level[i] + hh, diff[9], sum = 0.0, mx = 0.0;
            for (int k = 0; k < 8; ++k) {
                diff[k] = 0.0;
                if (!(d->adj[i] >> k & 1u)) continue;
                size_t j = (size_t)(y + SOAK_RAIN_DY[k]) * w + (size_t)(x + SOAK_RAIN_DX[k]);
                double dl = lvl - (d->level[j] + depth[j]);
                if (dl > 0.0) diff[k] = dl;
            }
            diff[8] = d->drip[i] > 0.0f ? hh + d->drip[i] : 0.0;
            for (int k = 0; k < 9; ++k) {
                sum += diff[k];
                mx = fmax(mx, diff[k]);
            }
            if (!(sum > 0.0)) continue;
            double moved = fmin(mobile, 0.5 * mx);
            for (int k = 0; k < 9; ++k) o[k] = (float)(moved * diff[k] / sum);
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            if (!d->covered[i]) continue;
            double out = 0.0, vol_in = 0.0;
            for (int k = 0; k < 9; ++k) out += out9[9 * i + k];
            for (int k = 0; k < 8; ++k) {
                int kx = x + SOAK_RAIN_DX[k], ky = y + SOAK_RAIN_DY[k];
                if (kx < 0 || ky < 0 || kx >= w || ky >= h) continue;
                size_t j = (size_t)ky * w + kx;
                int back = (k + 4) & 7;
                if (d->covered[j] && (d->adj[j] >> back & 1u)) vol_in += out9[9 * j + back] * (double)d->area[j];
            }
            double v = depth[i] - out + vol_in / d->area[i];
            depth[i] = v > 0.0 ? v : 0.0;
        }
}

static double volume(const grid_data *d, const double *depth)
{
    double v = 0.0;
    for (size_t i = 0; i < (size_t)d->w * d->h; ++i) v += depth[i] * d->area[i];
    return v;
}

static void compare(int w, int h, int iterations, int drips, uint64_t seed)
{
    grid_data d;
    grid_make(&d, w, h, seed, drips);
    size_t n = (size_t)w * h;
    double *ref = malloc(n * sizeof *ref), *got = malloc(n * sizeof *got);
    float *out9 = malloc(9 * n * sizeof *out9);
    memcpy(ref, d.depth, n * sizeof *ref);
    double v0 = volume(&d, ref);
    for (int it = 0; it < iterations; ++it) reference_sweep(&d, ref, out9);
    char what[160];
    if (!drips) {
        snprintf(what, sizeof what, "reference conserves volume without drips (%dx%d, %d sweeps)", w, h, iterations);
        check_rel(what, volume(&d, ref), v0, 1e-6);
    }
    soak_rain_flow_grid g = {w, h, d.covered, d.adj, d.area, d.drip, d.level, d.retain};
    double moved = 0.0;
    for (size_t i = 0; i < n; ++i) moved = fmax(moved, fabs(ref[i] - d.depth[i]));
    snprintf(what, sizeof what, "water moves in the reference (%dx%d)", w, h);
    check_true(what, moved > 1e-5);
    for (int threads = 1; threads <= 3; ++threads) {
        memcpy(got, d.depth, n * sizeof *got);
        soak_bake_exec ex = {threads, NULL, NULL};
        soak_status st = soak_rain_flow(&g, got, iterations, &ex, 0.0, 1.0);
        snprintf(what, sizeof what, "fused flow runs (%dx%d, %d threads)", w, h, threads);
        check_status(what, st, SOAK_OK);
        size_t differ = 0;
        for (size_t i = 0; i < n; ++i) differ += memcmp(&got[i], &ref[i], sizeof(double)) != 0;
        snprintf(what, sizeof what, "fused = two-pass reference bitwise (%dx%d, %d sweeps, drips %d, %d threads): %zu texels differ",
                 w, h, iterations, drips, threads, differ);
        check_true(what, differ == 0);
    }
    free(ref);
    free(got);
    free(out9);
    grid_free(&d);
}

int main(void)
{
    compare(61, 45, 24, 1, 7);  /* bands of 16 rows and a partial one */
    compare(64, 64, 24, 0, 11); /* no drips: closed system */
    compare(5, 3, 9, 1, 3);     /* fewer rows than a band */
    soak_rain_flow_grid g = {4, 4, NULL, NULL, NULL, NULL, NULL, NULL};
    check_status("NULL depth refused", soak_rain_flow(&g, NULL, 1, NULL, 0, 1), SOAK_ERR_NULL);
    return check_finish();
}
