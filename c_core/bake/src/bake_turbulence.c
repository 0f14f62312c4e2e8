/* Procedural wetness from gradient noise: fBm and turbulence.
 *
 * Noise: K. Perlin, "Improving Noise" (SIGGRAPH 2002) -- quintic fade
 * 6t^5 - 15t^4 + 10t^3 and the 12 cube-edge gradients (padded to 16) in 3D.
 * In 2D we use 8 unit gradients at 22.5 + 45k degrees; their noise peaks at
 * |n| = sqrt(2)/2, so 2D values are scaled by sqrt(2) to span about [-1, 1].
 * Instead of Perlin's global permutation table, each lattice point's gradient
 * is picked by hashing (seed, i, j, k): no tables, any seed, and periodicity
 * by wrapping the indices before hashing.
 * Sums: fBm = sum_o g^o n(L^o p); turbulence = sum_o g^o |n(L^o p)| (Perlin
 * 1985, "An image synthesizer", the function Jensen et al. 1999 use for the
 * beach wetness, [JLD99] sec. 4.2). Both are divided by sum_o g^o. Every
 * octave has its own derived seed, so octaves are independent and the
 * variance of the sum is var(n) sum_o g^(2o) / (sum_o g^o)^2. */
#include "soak/bake.h"

#include <math.h>
#include <stdlib.h>

#include "soak/hash.h"

#define COORD_LIMIT 1e9 /* largest lattice coordinate: indices stay in int32 */
#define MAX_TOP_CELLS 2e4

static const double grad2[8][2] = {
    {0.92387953251128674, 0.38268343236508978},  {0.38268343236508978, 0.92387953251128674},
    {-0.38268343236508978, 0.92387953251128674}, {-0.92387953251128674, 0.38268343236508978},
    {-0.92387953251128674, -0.38268343236508978}, {-0.38268343236508978, -0.92387953251128674},
    {0.38268343236508978, -0.92387953251128674}, {0.92387953251128674, -0.38268343236508978},
};

static const double grad3[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 1}, {0, -1, -1},
};

#define NOISE2_SCALE 1.4142135623730951

static inline double fade(double t)
{
    return t * t * t * (t * (t * 6 - 15) + 10);
}

static inline int32_t wrap_index(int64_t i, int period)
{
    if (period <= 0) return (int32_t)i;
    int64_t r = i % period;
    return (int32_t)(r < 0 ? r + period : r);
}

static inline const double *g2(uint32_t key, int32_t i, int32_t j)
{
    return grad2[soak_hash_key2(key, i, j) >> 29];
}

static inline const double *g3(uint32_t key, int32_t i, int32_t j, int32_t k)
{
    return grad3[soak_hash_key3(key, i, j, k) >> 28];
}

/* Gradients of one 2D cell: [corner 00, 10, 01, 11]. */
typedef struct cell2 {
    const double *g[4];
} cell2;

static inline double noise2_in_cell(const cell2 *c, double tx, double ty, double v)
{
    const double *g00 = c->g[0], *g10 = c->g[1], *g01 = c->g[2], *g11 = c->g[3];
    double n00 = g00[0] * tx + g00[1] * ty;
    double n10 = g10[0] * (tx - 1) + g10[1] * ty;
    double n01 = g01[0] * tx + g01[1] * (ty - 1);
    double n11 = g11[0] * (tx - 1) + g11[1] * (ty - 1);
    double u = fade(tx);
    double a = n00 + u * (n10 - n00);
    double b = n01 + u * (n11 - n01);
    return NOISE2_SCALE * (a + v * (b - a));
}

typedef struct cell3 {
    const double *g[8]; /* corner index bit 0: x, bit 1: y, bit 2: z */
} cell3;

static inline double dot3(const double *g, double x, double y, double z)
{
    return g[0] * x + g[1] * y + g[2] * z;
}

static inline double noise3_in_cell(const cell3 *c, double tx, double ty, double tz, double v, double w)
{
    double u = fade(tx);
    double n[4];
    for (int k = 0; k < 4; ++k) {
        double dy = (k & 1) ? ty - 1 : ty, dz = (k & 2) ? tz - 1 : tz;
        double lo = dot3(c->g[2 * k], tx, dy, dz), hi = dot3(c->g[2 * k + 1], tx - 1, dy, dz);
        n[k] = lo + u * (hi - lo);
    }
    double a = n[0] + v * (n[1] - n[0]);
    double b = n[2] + v * (n[3] - n[2]);
    return a + w * (b - a);
}

static void cell2_fill(cell2 *c, uint32_t key, int64_t ix, int64_t iy, int px, int py)
{
    int32_t i0 = wrap_index(ix, px), i1 = wrap_index(ix + 1, px);
    int32_t j0 = wrap_index(iy, py), j1 = wrap_index(iy + 1, py);
    c->g[0] = g2(key, i0, j0);
    c->g[1] = g2(key, i1, j0);
    c->g[2] = g2(key, i0, j1);
    c->g[3] = g2(key, i1, j1);
}

static void cell3_fill(cell3 *c, uint32_t key, int64_t ix, int64_t iy, int64_t iz, int px, int py, int pz)
{
    int32_t i[2] = {wrap_index(ix, px), wrap_index(ix + 1, px)};
    int32_t j[2] = {wrap_index(iy, py), wrap_index(iy + 1, py)};
    int32_t k[2] = {wrap_index(iz, pz), wrap_index(iz + 1, pz)};
    for (int b = 0; b < 8; ++b) c->g[b] = g3(key, i[b & 1], j[(b >> 1) & 1], k[(b >> 2) & 1]);
}

static int coords_ok(double x, double y, double z)
{
    return soak_in_range(x, -COORD_LIMIT, COORD_LIMIT) && soak_in_range(y, -COORD_LIMIT, COORD_LIMIT) &&
           soak_in_range(z, -COORD_LIMIT, COORD_LIMIT);
}

double soak_noise2(uint64_t seed, double x, double y, int period_x, int period_y)
{
    if (!coords_ok(x, y, 0)) return 0.0;
    double fx = floor(x), fy = floor(y);
    cell2 c;
    cell2_fill(&c, soak_seed_key(seed), (int64_t)fx, (int64_t)fy, period_x, period_y);
    double ty = y - fy;
    return noise2_in_cell(&c, x - fx, ty, fade(ty));
}

double soak_noise3(uint64_t seed, double x, double y, double z, int period_x, int period_y, int period_z)
{
    if (!coords_ok(x, y, z)) return 0.0;
    double fx = floor(x), fy = floor(y), fz = floor(z);
    cell3 c;
    cell3_fill(&c, soak_seed_key(seed), (int64_t)fx, (int64_t)fy, (int64_t)fz, period_x, period_y, period_z);
    double ty = y - fy, tz = z - fz;
    return noise3_in_cell(&c, x - fx, ty, tz, fade(ty), fade(tz));
}

void soak_turbulence_defaults(soak_turbulence_params *p)
{
    if (!p) return;
    p->seed = 0;
    p->sum = SOAK_NOISE_FBM;
    p->octaves = 6;
    p->frequency = 4;
    p->lacunarity = 2;
    p->gain = 0.5;
    p->tileable = 0;
    p->use_3d = 0;
    p->z = 0;
    p->thresholded = 0;
    p->threshold = 0.3;
    p->softness = 0.1;
}

soak_status soak_turbulence_check(const soak_turbulence_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!(p->sum == SOAK_NOISE_FBM || p->sum == SOAK_NOISE_TURBULENCE)) return SOAK_ERR_ARG;
    if (!(p->octaves >= 1 && p->octaves <= SOAK_NOISE_MAX_OCTAVES)) return SOAK_ERR_ARG;
    if (!soak_in_range(p->frequency, 1e-9, SOAK_NOISE_MAX_FREQUENCY) ||
        !soak_in_range(p->lacunarity, 1, SOAK_NOISE_MAX_LACUNARITY) || !soak_in_range(p->gain, 0, 1) ||
        !soak_in_range(p->z, -SOAK_NOISE_MAX_Z, SOAK_NOISE_MAX_Z) ||
        !soak_in_range(p->threshold, -SOAK_NOISE_MAX_THRESHOLD, SOAK_NOISE_MAX_THRESHOLD) ||
        !soak_in_range(p->softness, 0, SOAK_NOISE_MAX_SOFTNESS))
        return SOAK_ERR_ARG;
    double top = pow(p->lacunarity, p->octaves - 1);
    /* Keep every lattice index inside int32: at most MAX_TOP_CELLS cells
     * across the width at the top octave (already finer than a pixel of the
     * largest bake); the y extent grows with the aspect ratio, at most
     * SOAK_BAKE_MAX_SIZE, and eval accepts points up to one image outside. */
    if (!(p->frequency * top <= MAX_TOP_CELLS)) return SOAK_ERR_ARG;
    if (!(fabs(p->z) * top <= COORD_LIMIT)) return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* Per-octave layout shared by the point and row evaluations, so both run
 * the very same arithmetic. */
typedef struct octave {
    uint32_t key;
    double weight;
    double scale_x, scale_y; /* lattice cells per pixel */
    double z;
    int period_x, period_y;
} octave;

typedef struct layout {
    int n;
    octave oct[24];
    double norm; /* 1 / sum of weights */
    soak_turbulence_params p;
} layout;

static soak_status make_layout(const soak_turbulence_params *p, int width, int height, layout *L)
{
    soak_status st = soak_turbulence_check(p);
    if (st != SOAK_OK) return st;
    if (soak_bake_check_size(width, height) != SOAK_OK) return SOAK_ERR_ARG;
    L->p = *p;
    L->n = 0;
    double sum = 0, f = p->frequency, w = 1;
    for (int o = 0; o < p->octaves; ++o) {
        if (o > 0 && w == 0) break;
        octave *oc = &L->oct[L->n++];
        double fx = f, fy = f * height / width;
        oc->period_x = oc->period_y = 0;
        if (p->tileable) {
            /* Whole cells across the image so opposite edges meet. */
            fx = fmax(1, floor(fx + 0.5));
            fy = fmax(1, floor(fy + 0.5));
            oc->period_x = (int)fx;
            oc->period_y = (int)fy;
        }
        if (!(fy <= COORD_LIMIT && fx <= COORD_LIMIT)) return SOAK_ERR_ARG;
        oc->key = soak_seed_key(soak_seed_derive(p->seed, (uint64_t)o));
        oc->weight = w;
        oc->scale_x = fx / width;
        oc->scale_y = fy / height;
        oc->z = p->z * (f / p->frequency);
        sum += w;
        f *= p->lacunarity;
        w *= p->gain;
    }
    L->norm = 1.0 / sum;
    return SOAK_OK;
}

static double finish_value(const layout *L, double acc)
{
    double v = acc * L->norm;
    if (L->p.thresholded) v = soak_smoothstep(L->p.threshold - L->p.softness, L->p.threshold + L->p.softness, v);
    return v;
}

static double octave_noise(const layout *L, const octave *oc, double px, double py)
{
    double x = px * oc->scale_x, y = py * oc->scale_y;
    double fx = floor(x), fy = floor(y), ty = y - fy;
    if (L->p.use_3d) {
        cell3 c;
        double fz = floor(oc->z), tz = oc->z - fz;
        cell3_fill(&c, oc->key, (int64_t)fx, (int64_t)fy, (int64_t)fz, oc->period_x, oc->period_y, 0);
        return noise3_in_cell(&c, x - fx, ty, tz, fade(ty), fade(tz));
    }
    cell2 c;
    cell2_fill(&c, oc->key, (int64_t)fx, (int64_t)fy, oc->period_x, oc->period_y);
    return noise2_in_cell(&c, x - fx, ty, fade(ty));
}

soak_status soak_turbulence_eval(const soak_turbulence_params *p, int width, int height, double x, double y,
                                 double *value)
{
    if (!p || !value) return SOAK_ERR_NULL;
    layout L;
    soak_status st = make_layout(p, width, height, &L);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(x, -(double)width, 2.0 * width) || !soak_in_range(y, -(double)height, 2.0 * height))
        return SOAK_ERR_ARG;
    double acc = 0;
    for (int o = 0; o < L.n; ++o) {
        double n = octave_noise(&L, &L.oct[o], x, y);
        acc += L.oct[o].weight * (L.p.sum == SOAK_NOISE_TURBULENCE ? fabs(n) : n);
    }
    *value = finish_value(&L, acc);
    return SOAK_OK;
}

typedef struct bake_ctx {
    const layout *L;
    int width;
    double *scratch; /* width doubles per thread */
    float *out;
} bake_ctx;

/* One octave along a row; a new cell's gradients are looked up only when
 * the lattice x index changes (reusing the shared edge when it steps by 1). */
static void row_octave2(const layout *L, const octave *oc, int width, double py, double *acc)
{
    double y = py * oc->scale_y, fy = floor(y), ty = y - fy, v = fade(ty);
    int32_t j0 = wrap_index((int64_t)fy, oc->period_y), j1 = wrap_index((int64_t)fy + 1, oc->period_y);
    int turb = L->p.sum == SOAK_NOISE_TURBULENCE;
    int64_t cur = INT64_MIN;
    cell2 c = {{0, 0, 0, 0}};
    for (int i = 0; i < width; ++i) {
        double x = (i + 0.5) * oc->scale_x, fx = floor(x);
        int64_t ix = (int64_t)fx;
        if (ix != cur) {
            int32_t i1 = wrap_index(ix + 1, oc->period_x);
            if (ix == cur + 1) {
                c.g[0] = c.g[1];
                c.g[2] = c.g[3];
            } else {
                int32_t i0 = wrap_index(ix, oc->period_x);
                c.g[0] = g2(oc->key, i0, j0);
                c.g[2] = g2(oc->key, i0, j1);
            }
            c.g[1] = g2(oc->key, i1, j0);
            c.g[3] = g2(oc->key, i1, j1);
            cur = ix;
        }
        double n = noise2_in_cell(&c, x - fx, ty, v);
        acc[i] += oc->weight * (turb ? fabs(n) : n);
    }
}

static void row_octave3(const layout *L, const octave *oc, int width, double py, double *acc)
{
    double y = py * oc->scale_y, fy = floor(y), ty = y - fy, v = fade(ty);
    double fz = floor(oc->z), tz = oc->z - fz, w = fade(tz);
    int turb = L->p.sum == SOAK_NOISE_TURBULENCE;
    int64_t cur = INT64_MIN;
    cell3 c;
    for (int i = 0; i < width; ++i) {
        double x = (i + 0.5) * oc->scale_x, fx = floor(x);
        int64_t ix = (int64_t)fx;
        if (ix != cur) {
            cell3_fill(&c, oc->key, ix, (int64_t)fy, (int64_t)fz, oc->period_x, oc->period_y, 0);
            cur = ix;
        }
        double n = noise3_in_cell(&c, x - fx, ty, tz, v, w);
        acc[i] += oc->weight * (turb ? fabs(n) : n);
    }
}

static void bake_row(void *vctx, int row, int thread)
{
    bake_ctx *ctx = vctx;
    const layout *L = ctx->L;
    double *acc = ctx->scratch + (size_t)thread * ctx->width;
    for (int i = 0; i < ctx->width; ++i) acc[i] = 0;
    double py = row + 0.5;
    for (int o = 0; o < L->n; ++o) {
        if (L->p.use_3d) row_octave3(L, &L->oct[o], ctx->width, py, acc);
        else row_octave2(L, &L->oct[o], ctx->width, py, acc);
    }
    float *dst = ctx->out + (size_t)row * ctx->width;
    for (int i = 0; i < ctx->width; ++i) dst[i] = (float)finish_value(L, acc[i]);
}

soak_status soak_bake_turbulence(const soak_turbulence_params *p, int width, int height, const soak_bake_exec *exec,
                                 soak_image *out)
{
    if (!p || !out) return SOAK_ERR_NULL;
    layout L;
    soak_status st = make_layout(p, width, height, &L);
    if (st != SOAK_OK) return st;
    int threads = soak_bake_threads(exec);
    if (threads == 0) return SOAK_ERR_ARG;
    double *scratch = malloc(sizeof(double) * (size_t)width * (size_t)threads);
    if (!scratch) return SOAK_ERR_NOMEM;
    st = soak_image_alloc(out, width, height, 1);
    if (st != SOAK_OK) {
        free(scratch);
        return st;
    }
    bake_ctx ctx = {&L, width, scratch, out->pixels};
    st = soak_parallel_rows(height, exec, bake_row, &ctx, 0, 1);
    free(scratch);
    if (st != SOAK_OK) soak_image_free(out);
    return st;
}
