/* The rain bake's fused flow sweep (c_core/bake/src/bake_rain_flow.h)
 * against a straightforward reference written here: the two-pass Jacobi
 * scheme that stores nine float outflows per texel (outflow pass, then
 * gather pass), on a random grid with uncovered texels, one-way adjacency,
 * drip edges and down-facing texels, and on a layout of rectangular charts
 * with dry and uncovered runs. The fused sweep keeps the reference's
 * operation order, so the depths must agree bitwise, at 1, 2 and 3 threads,
 * with the AVX-512, AVX2 (where the CPU has them) and portable kernels, and
 * when one plan runs twice with rain added between the runs.
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

/* Texel (x, y) of the "charts" layout: rectangular islands two texels apart
 * (whole runs of covered texels with all eight neighbours, as a UV layout
 * has), the left third of each dry. */
static int chart_covered(int x, int y)
{
    return x % 13 < 11 && y % 9 < 7;
}

static void grid_make(grid_data *d, int w, int h, uint64_t seed, int drips, int charts)
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
    for (size_t i = 0; i < n; ++i)
        d->covered[i] = charts ? chart_covered((int)(i % w), (int)(i / w)) : soak_rng_uniform(&r) > 0.1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            /* a tilted bowl with noise: puddles and slopes */
            double u = (x - 0.3 * w) / w, v = (y - 0.6 * h) / h;
            d->level[i] = 0.01 * (u * u + v * v) + 0.002 * u + 1e-4 * soak_rng_uniform(&r);
            if (!d->covered[i]) {
                d->area[i] = NAN; /* the bake leaves these unset: nothing may use them */
                continue;
            }
            d->area[i] = (float)(1e-6 * (0.5 + soak_rng_uniform(&r)));
            d->retain[i] = 2e-4 * soak_rng_uniform(&r);
            d->depth[i] = charts && x % 13 < 4 ? 0.0 : 2e-3 * soak_rng_uniform(&r) * soak_rng_uniform(&r);
            double q = soak_rng_uniform(&r);
            if (drips) d->drip[i] = q < 0.03 ? -1.0f : (q < 0.08 ? (float)(1e-3 * soak_rng_uniform(&r)) : 0.0f);
            for (int k = 0; k < 8; ++k) {
                int kx = x + SOAK_RAIN_DX[k], ky = y + SOAK_RAIN_DY[k];
                if (kx < 0 || ky < 0 || kx >= w || ky >= h || !d->covered[(size_t)ky * w + kx]) continue;
                if (charts || soak_rng_uniform(&r) < 0.95) d->adj[i] |= (unsigned char)(1u << k); /* some one-way links */
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
    for (size_t i = 0; i < (size_t)d->w * d->h; ++i)
        if (d->covered[i]) v += depth[i] * d->area[i];
    return v;
}

static size_t texels_differ(const double *a, const double *b, size_t n)
{
    size_t differ = 0;
    for (size_t i = 0; i < n; ++i) differ += memcmp(&a[i], &b[i], sizeof(double)) != 0;
    return differ;
}

/* Rain between two runs of sweeps, as the bake adds it between its steps. */
static void add_rain(const grid_data *d, double *depth)
{
    for (size_t i = 0; i < (size_t)d->w * d->h; ++i)
        if (d->covered[i]) depth[i] += 1e-4 * (double)(i % 7);
}

static const char *const ISA_NAME[3] = {"auto (widest vector)", "portable", "AVX2"};

static void compare(int w, int h, int iterations, int drips, int charts, uint64_t seed)
{
    grid_data d;
    grid_make(&d, w, h, seed, drips, charts);
    size_t n = (size_t)w * h;
    double *ref = malloc(n * sizeof *ref), *got = malloc(n * sizeof *got);
    float *out9 = malloc(9 * n * sizeof *out9);
    memcpy(ref, d.depth, n * sizeof *ref);
    double v0 = volume(&d, ref);
    for (int it = 0; it < iterations; ++it) reference_sweep(&d, ref, out9);
    char what[200];
    if (!drips) {
        snprintf(what, sizeof what, "reference conserves volume without drips (%dx%d, %d sweeps)", w, h, iterations);
        check_rel(what, volume(&d, ref), v0, 1e-6);
    }
    soak_rain_flow_grid g = {w, h, d.covered, d.adj, d.area, d.drip, d.level, d.retain, NULL};
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
        snprintf(what, sizeof what,
                 "fused = two-pass reference bitwise (%dx%d, %d sweeps, drips %d, charts %d, %d threads): %zu texels differ",
                 w, h, iterations, drips, charts, threads, texels_differ(got, ref, n));
        check_true(what, texels_differ(got, ref, n) == 0);
    }
    /* One plan, two runs with rain between (as the bake uses it), each set
     * of kernels; the reference continues from where it was. */
    add_rain(&d, ref);
    for (int it = 0; it < iterations + 1; ++it) reference_sweep(&d, ref, out9);
    for (int isa = SOAK_RAIN_FLOW_AUTO; isa <= SOAK_RAIN_FLOW_AVX2; ++isa)
        for (int threads = 1; threads <= 3; threads += 2) {
            soak_bake_exec ex = {threads, NULL, NULL};
            soak_rain_flow_plan *plan = NULL;
            soak_status st = soak_rain_flow_create(&g, &ex, (soak_rain_flow_isa)isa, &plan);
            memcpy(got, d.depth, n * sizeof *got);
            if (st == SOAK_OK) st = soak_rain_flow_run(plan, got, iterations, &ex, 0.0, 1.0);
            add_rain(&d, got);
            if (st == SOAK_OK) st = soak_rain_flow_run(plan, got, iterations + 1, &ex, 0.0, 1.0); /* odd: ends in the plan's buffer */
            soak_rain_flow_destroy(plan);
            snprintf(what, sizeof what, "plan runs twice (%dx%d, %s kernels, %d threads)", w, h, ISA_NAME[isa], threads);
            check_status(what, st, SOAK_OK);
            snprintf(what, sizeof what, "plan's two runs = reference bitwise (%dx%d, %s kernels, %d threads): %zu texels differ",
                     w, h, ISA_NAME[isa], threads, texels_differ(got, ref, n));
            check_true(what, texels_differ(got, ref, n) == 0);
        }
    free(ref);
    free(got);
    free(out9);
    grid_free(&d);
}

int main(void)
{
    compare(61, 45, 24, 1, 0, 7);  /* bands of 32 rows and a partial one */
    compare(64, 64, 24, 0, 0, 11); /* no drips: closed system */
    compare(5, 3, 9, 1, 0, 3);     /* fewer rows than a band, one group of four texels */
    compare(6, 7, 9, 1, 0, 5);     /* a group of four and two texels left */
    compare(11, 9, 9, 1, 0, 19);   /* a group of eight and three texels left */
    compare(83, 70, 20, 1, 1, 13); /* charts: interiors, dry runs, uncovered runs */
    compare(80, 40, 20, 0, 1, 17);
    soak_rain_flow_grid g = {4, 4, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    check_status("NULL depth refused", soak_rain_flow(&g, NULL, 1, NULL, 0, 1), SOAK_ERR_NULL);
    soak_rain_flow_plan *plan = NULL;
    check_status("grid without arrays refused", soak_rain_flow_create(&g, NULL, SOAK_RAIN_FLOW_AUTO, &plan), SOAK_ERR_NULL);
    return check_finish();
}
