/* Puddles that level (c_core/bake/src/bake_rain_level.h), white box, on a
 * 40 x 30 grid tilted 0.01 per texel with two bowls (one nested in the
 * other's rim) and random water:
 *  - the spill levels against a second method written here, the
 *    iterative fill of Planchon & Darboux 2001 (Catena 46, 159-176):
 *    W = level on the outlets (the grid's edge), +inf elsewhere, then
 *    W = max(level, min of the neighbours' W) until nothing changes;
 *  - under the capacity, every wet texel of a depression stands at one
 *    level (1e-12 m) no higher than its spill level, texels outside the
 *    depressions keep their water, and the volume is conserved (1e-12);
 *  - over the capacity, every texel of a depression stands at its spill
 *    level and the volume is still conserved (the excess on the sill). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_level.h"
#include "check.h"
#include "soak/rng.h"

enum { W = 40, H = 30, N = W * H };

typedef struct grid_data {
    unsigned char covered[N], adj[N];
    float area[N], drip[N];
    double level[N], retain[N];
} grid_data;

static double bowl(double x, double y, double cx, double cy, double r, double deep)
{
    double d2 = ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (r * r);
    return -deep * exp(-d2);
}

static void grid_make(grid_data *d, soak_rain_flow_grid *g)
{
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + x;
            d->covered[i] = 1;
            d->area[i] = 1e-4f * (1.0f + 0.1f * (float)((x * 7 + y * 3) % 5));
            d->drip[i] = 0.0f;
            d->retain[i] = 0.0;
            d->level[i] = 0.01 * x + bowl(x, y, 12, 14, 5, 0.08) + bowl(x, y, 26, 10, 3, 0.05);
            d->adj[i] = 0;
            for (int k = 0; k < 8; ++k) {
                int kx = x + SOAK_RAIN_DX[k], ky = y + SOAK_RAIN_DY[k];
                if (kx >= 0 && ky >= 0 && kx < W && ky < H) d->adj[i] |= (unsigned char)(1u << k);
            }
        }
    *g = (soak_rain_flow_grid){W, H, d->covered, d->adj, d->area, d->drip, d->level, d->retain, NULL};
}

/* Planchon & Darboux's fill, the direct form. */
static void reference_spill(const grid_data *d, double *spill)
{
    for (size_t i = 0; i < N; ++i) spill[i] = d->adj[i] == 0xFFu ? INFINITY : d->level[i];
    for (int changed = 1; changed;) {
        changed = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                size_t i = (size_t)y * W + x;
                double lo = INFINITY;
                for (int k = 0; k < 8; ++k)
                    if (d->adj[i] >> k & 1u)
                        lo = fmin(lo, spill[(size_t)(y + SOAK_RAIN_DY[k]) * W + x + SOAK_RAIN_DX[k]]);
                double want = fmax(d->level[i], lo);
                if (want < spill[i]) spill[i] = want, changed = 1;
            }
    }
}

static double volume(const grid_data *d, const double *depth)
{
    double v = 0.0;
    for (size_t i = 0; i < N; ++i) v += depth[i] * d->area[i];
    return v;
}

static void check_case(const char *name, double scale, int over)
{
    static grid_data d;
    soak_rain_flow_grid g;
    grid_make(&d, &g);
    double spill[N], depth[N], before[N];
    reference_spill(&d, spill);
    soak_rng rng;
    soak_rng_seed(&rng, 48, 1);
    for (size_t i = 0; i < N; ++i) before[i] = depth[i] = scale * soak_rng_uniform(&rng);
    char what[200];
    snprintf(what, sizeof what, "%s: level", name);
    if (!check_status(what, soak_rain_level(&g, depth), SOAK_OK)) return;
    snprintf(what, sizeof what, "%s: volume conserved", name);
    check_rel(what, volume(&d, depth), volume(&d, before), 1e-12);
    int pits = 0, kept = 1, under = 1;
    double top[2] = {-INFINITY, -INFINITY}, low[2] = {INFINITY, INFINITY};
    for (size_t i = 0; i < N; ++i) {
        if (!(spill[i] > d.level[i])) {
            kept &= depth[i] >= before[i]; /* only the sill gains */
            continue;
        }
        ++pits;
        int b = spill[i] > 0.2; /* the two depressions' spill levels differ: the big bowl's is lower */
        if (!(depth[i] > 0.0)) continue;
        double s = d.level[i] + depth[i];
        top[b] = fmax(top[b], s), low[b] = fmin(low[b], s);
        under &= s <= spill[i] + 1e-12;
        if (over) under &= fabs(s - spill[i]) <= 1e-12;
    }
    printf("%s: %d depression texels; surfaces %.3g..%.3g and %.3g..%.3g m\n", name, pits, low[0], top[0], low[1],
           top[1]);
    snprintf(what, sizeof what, "%s: two depressions found by the reference (%d texels)", name, pits);
    check_true(what, pits >= 15 && top[0] > -INFINITY && top[1] > -INFINITY);
    snprintf(what, sizeof what, "%s: each pool flat (1e-12 m)", name);
    check_true(what, top[0] - low[0] <= 1e-12 && top[1] - low[1] <= 1e-12);
    snprintf(what, sizeof what, over ? "%s: pools at the reference spill level" : "%s: pools under the spill level",
             name);
    check_true(what, under);
    snprintf(what, sizeof what, "%s: water outside the depressions kept", name);
    check_true(what, kept);
}

int main(void)
{
    check_case("under capacity", 1e-3, 0);
    check_case("over capacity", 0.2, 1);
    return check_finish();
}
