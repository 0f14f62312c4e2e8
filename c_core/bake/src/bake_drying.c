/* Drying of a wet region given by a mask.
 *
 * Schedule mode ([Hnat06], Hnat et al. 2006, sec. 3.3): pores hold water
 * between a start time t0 and t0 + t_fill with the piecewise-linear Delta-t
 * schedule of sec. 3.3.2 (soak_fill_fraction). We run that schedule as
 * emptying: wetness(t) = 1 - fill_fraction(t, t0, t_fill), so t_fill = 0 is
 * a step. Sec. 3.3.1 observes that "in a drop, border dries first" and
 * blends a circular gradient by hand; we derive t0 from the exact Euclidean
 * distance d to the nearest dry texel instead, t0 = (1 - t_fill) d / d_max,
 * so the rim starts first and the deepest point finishes at t = 1 (the
 * paper's relative time range). Porous materials dry "more stochastically"
 * (same section, Perlin noise): t0 is blended with fBm by noise_amount.
 *
 * Diffusion mode (ours; the sources ([JLD99], [Lag13], [Hnat06]) have no drying dynamics): water depth u
 * obeys du/dt = D lap(u) - E [u > 0]: constant-rate evaporation E from the
 * wet surface (the "constant rate period" of drying porous media) and
 * lateral capillary spreading as diffusion. Water spreads into the thin
 * rim, which then evaporates first: puddles shrink from their edges. Units:
 * E = 1 / drying_time (a unit film dries in drying_time), D =
 * diffusion_length^2 / drying_time (pixels^2 per time). Solved implicitly,
 * see soak_diffusion_step. */
#include "soak/bake.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/porous.h"

#define EDT_BIG 1e20 /* "infinite" squared distance inside the transform only */

/* 1D squared distance transform of a sampled function (Felzenszwalb and
 * Huttenlocher 2012, algorithm DT(f)): lower envelope of the parabolas
 * (q - p)^2 + f(p). v: parabola apexes, z: envelope breakpoints (n + 1). */
static void edt_1d(const double *f, int n, double *d, int *v, double *z)
{
    int k = 0;
    v[0] = 0;
    z[0] = -HUGE_VAL;
    z[1] = HUGE_VAL;
    for (int q = 1; q < n; ++q) {
        /* z[0] = -inf stops the loop at k = 0: every s is finite. */
        double s = ((f[q] + (double)q * q) - (f[v[k]] + (double)v[k] * v[k])) / (2.0 * (q - v[k]));
        while (s <= z[k]) {
            --k;
            s = ((f[q] + (double)q * q) - (f[v[k]] + (double)v[k] * v[k])) / (2.0 * (q - v[k]));
        }
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = HUGE_VAL;
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[k + 1] < q) ++k;
        double dq = q - v[k];
        d[q] = dq * dq + f[v[k]];
    }
}

soak_status soak_edt_squared(const unsigned char *feature, int width, int height, double *d2, int *any_feature)
{
    if (!feature || !d2 || !any_feature) return SOAK_ERR_NULL;
    if (soak_bake_check_size(width, height) != SOAK_OK) return SOAK_ERR_ARG;
    size_t n = (size_t)width * height;
    int any = 0;
    for (size_t i = 0; i < n && !any; ++i) any = feature[i] != 0;
    *any_feature = any;
    if (!any) {
        double fill = (double)width * width + (double)height * height;
        for (size_t i = 0; i < n; ++i) d2[i] = fill;
        return SOAK_OK;
    }
    int m = width > height ? width : height;
    double *f = calloc((size_t)m, sizeof(double)), *d = malloc(sizeof(double) * m);
    double *z = malloc(sizeof(double) * (m + 1));
    int *v = malloc(sizeof(int) * m);
    if (!f || !d || !z || !v) {
        free(f), free(d), free(z), free(v);
        return SOAK_ERR_NOMEM;
    }
    for (int x = 0; x < width; ++x) { /* columns */
        for (int y = 0; y < height; ++y) f[y] = feature[(size_t)y * width + x] ? 0.0 : EDT_BIG;
        edt_1d(f, height, d, v, z);
        for (int y = 0; y < height; ++y) d2[(size_t)y * width + x] = d[y];
    }
    for (int y = 0; y < height; ++y) { /* rows */
        double *row = d2 + (size_t)y * width;
        memcpy(f, row, sizeof(double) * width);
        edt_1d(f, width, row, v, z);
    }
    free(f), free(d), free(z), free(v);
    return SOAK_OK;
}

void soak_drying_defaults(soak_drying_params *p)
{
    if (!p) return;
    p->mode = SOAK_DRYING_SCHEDULE;
    p->threshold = 0.5;
    p->time = 0.5;
    p->t_fill = 0.2;
    p->noise_amount = 0;
    p->noise_frequency = 8;
    p->noise_octaves = 4;
    p->seed = 0;
    p->drying_time = 1;
    p->diffusion_length = 8;
    p->steps = 32;
}

soak_status soak_drying_check(const soak_drying_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!(p->mode == SOAK_DRYING_SCHEDULE || p->mode == SOAK_DRYING_DIFFUSION)) return SOAK_ERR_ARG;
    if (!soak_in_range(p->threshold, -SOAK_DRYING_MAX_THRESHOLD, SOAK_DRYING_MAX_THRESHOLD) ||
        !soak_in_range(p->time, 0, SOAK_DRYING_MAX_TIME) || !soak_in_range(p->t_fill, 0, 1) ||
        !soak_in_range(p->noise_amount, 0, 1) || !soak_in_range(p->noise_frequency, 1e-9, SOAK_NOISE_MAX_FREQUENCY) ||
        !(p->noise_octaves >= 1 && p->noise_octaves <= SOAK_NOISE_MAX_OCTAVES) ||
        !soak_in_range(p->drying_time, 1e-300, SOAK_DRYING_MAX_TIME) ||
        !soak_in_range(p->diffusion_length, 0, SOAK_DRYING_MAX_LENGTH) ||
        !(p->steps >= 1 && p->steps <= SOAK_DRYING_MAX_STEPS))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

double soak_mask_value(const soak_image *mask, size_t i)
{
    const float *px = mask->pixels + i * (size_t)mask->channels;
    if (mask->channels < 3) return px[0];
    return soak_rgb_luminance(soak_rgb3(px[0], px[1], px[2]));
}

static soak_status check_mask(const soak_image *mask)
{
    if (!mask->pixels) return SOAK_ERR_NULL;
    if (soak_bake_check_size(mask->width, mask->height) != SOAK_OK || !(mask->channels >= 1 && mask->channels <= 4))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* Wet flags from the mask, or all wet when mask is NULL. */
static void wet_flags(const soak_image *mask, double threshold, size_t n, unsigned char *wet)
{
    for (size_t i = 0; i < n; ++i) wet[i] = mask ? soak_mask_value(mask, i) > threshold : 1;
}

static soak_status start_times(const soak_image *mask, int width, int height, const soak_drying_params *p, double *t0,
                               unsigned char *wet)
{
    size_t n = (size_t)width * height;
    wet_flags(mask, p->threshold, n, wet);
    unsigned char *dry = calloc(n, 1);
    double *d2 = malloc(sizeof(double) * n);
    if (!dry || !d2) {
        free(dry), free(d2);
        return SOAK_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; ++i) dry[i] = !wet[i];
    int any_dry = 0;
    soak_status st = soak_edt_squared(dry, width, height, d2, &any_dry);
    free(dry);
    if (st != SOAK_OK) {
        free(d2);
        return st;
    }
    double dmax = 0;
    for (size_t i = 0; i < n; ++i)
        if (wet[i] && d2[i] > dmax) dmax = d2[i];
    dmax = sqrt(dmax);
    soak_image noise = {0, 0, 0, NULL};
    if (p->noise_amount > 0) {
        soak_turbulence_params tp;
        soak_turbulence_defaults(&tp);
        tp.seed = p->seed;
        tp.octaves = p->noise_octaves;
        tp.frequency = p->noise_frequency;
        st = soak_bake_turbulence(&tp, width, height, NULL, &noise);
        if (st != SOAK_OK) {
            free(d2);
            return st;
        }
    }
    for (size_t i = 0; i < n; ++i) {
        double rel = (any_dry && dmax > 0) ? sqrt(d2[i]) / dmax : 1.0;
        if (noise.pixels) rel = (1 - p->noise_amount) * rel + p->noise_amount * soak_smoothstep(-0.5, 0.5, noise.pixels[i]);
        t0[i] = wet[i] ? (1 - p->t_fill) * rel : 0.0;
    }
    soak_image_free(&noise);
    free(d2);
    return SOAK_OK;
}

soak_status soak_drying_start_times(const soak_image *mask, const soak_drying_params *p, double *t0,
                                    unsigned char *wet)
{
    if (!mask || !p || !t0 || !wet) return SOAK_ERR_NULL;
    soak_status st = check_mask(mask);
    if (st == SOAK_OK) st = soak_drying_check(p);
    if (st != SOAK_OK) return st;
    return start_times(mask, mask->width, mask->height, p, t0, wet);
}

/* ---- implicit diffusion ------------------------------------------------ */

/* LU factors of the n x n no-flux matrix I - r L (L the 1D Laplacian with
 * reflecting ends): pivots m[i] and super-diagonal multipliers c[i]. All
 * lines of one sweep share them. Rows sum to 1 (so do columns: symmetric),
 * hence the solve conserves the line total. */
static void factor_line(int n, double r, double *m, double *c)
{
    for (int i = 0; i < n; ++i) {
        double diag = 1 + ((i == 0 || i == n - 1) ? (n == 1 ? 0 : r) : 2 * r);
        m[i] = i == 0 ? diag : diag + r * c[i - 1];
        c[i] = -r / m[i];
    }
}

typedef struct sweep_ctx {
    double *u;
    int width, height;
    double r;
    const double *m, *c;        /* factors for the sweep's line length */
    double *lo, *hi, *mean;     /* per-thread scratch for the y sweep, COLUMN_BLOCK each */
} sweep_ctx;

/* Each line is solved for its deviation from the line mean (the Laplacian
 * of a constant is 0, so the mean passes through unchanged): rounding then
 * scales with the deviation, not with r times the values, which keeps the
 * total conserved and the solve accurate for arbitrarily large r. The
 * result is clamped to the line's input range, which the exact solution
 * satisfies (discrete maximum principle of an M-matrix with unit row sums),
 * so the clamp only removes rounding. */
static void sweep_x(void *vctx, int row, int thread)
{
    (void)thread;
    sweep_ctx *s = vctx;
    double *u = s->u + (size_t)row * s->width;
    int n = s->width;
    double lo = u[0], hi = u[0], sum = 0;
    for (int i = 0; i < n; ++i) {
        lo = fmin(lo, u[i]);
        hi = fmax(hi, u[i]);
        sum += u[i];
    }
    double mean = sum / n;
    for (int i = 0; i < n; ++i) u[i] = ((u[i] - mean) + (i == 0 ? 0 : s->r * u[i - 1])) / s->m[i];
    for (int i = n - 2; i >= 0; --i) u[i] -= s->c[i] * u[i + 1];
    for (int i = 0; i < n; ++i) u[i] = fmin(hi, fmax(lo, u[i] + mean));
}

#define COLUMN_BLOCK 64

/* The same for a block of columns, sweeping whole row segments for locality. */
static void sweep_y(void *vctx, int block, int thread)
{
    sweep_ctx *s = vctx;
    int x0 = block * COLUMN_BLOCK, x1 = x0 + COLUMN_BLOCK < s->width ? x0 + COLUMN_BLOCK : s->width;
    int w = s->width, n = s->height;
    double *lo = s->lo + (size_t)thread * COLUMN_BLOCK, *hi = s->hi + (size_t)thread * COLUMN_BLOCK;
    double *mean = s->mean + (size_t)thread * COLUMN_BLOCK;
    for (int x = x0; x < x1; ++x) lo[x - x0] = hi[x - x0] = s->u[x], mean[x - x0] = 0;
    for (int i = 0; i < n; ++i) {
        const double *ui = s->u + (size_t)i * w;
        for (int x = x0; x < x1; ++x) {
            lo[x - x0] = fmin(lo[x - x0], ui[x]);
            hi[x - x0] = fmax(hi[x - x0], ui[x]);
            mean[x - x0] += ui[x];
        }
    }
    for (int x = x0; x < x1; ++x) mean[x - x0] /= n;
    for (int i = 0; i < n; ++i) {
        double *ui = s->u + (size_t)i * w;
        const double *up = i > 0 ? ui - w : NULL;
        for (int x = x0; x < x1; ++x)
            ui[x] = ((ui[x] - mean[x - x0]) + (up ? s->r * up[x] : 0)) / s->m[i];
    }
    for (int i = n - 2; i >= 0; --i) {
        double *ui = s->u + (size_t)i * w;
        const double *un = ui + w;
        for (int x = x0; x < x1; ++x) ui[x] -= s->c[i] * un[x];
    }
    for (int i = 0; i < n; ++i) {
        double *ui = s->u + (size_t)i * w;
        for (int x = x0; x < x1; ++x) ui[x] = fmin(hi[x - x0], fmax(lo[x - x0], ui[x] + mean[x - x0]));
    }
}

soak_status soak_diffusion_step(double *u, int width, int height, double r, double evap,
                                const soak_bake_exec *exec)
{
    if (!u) return SOAK_ERR_NULL;
    if (soak_bake_check_size(width, height) != SOAK_OK || !soak_in_range(r, 0, 1e300) ||
        !soak_in_range(evap, 0, 1e300))
        return SOAK_ERR_ARG;
    int threads = soak_bake_threads(exec);
    if (threads == 0) return SOAK_ERR_ARG;
    size_t n = (size_t)width * height;
    for (size_t i = 0; i < n; ++i)
        if (!soak_is_finite(u[i])) return SOAK_ERR_ARG;
    if (r > 0) {
        int m = width > height ? width : height;
        double *mm = malloc(sizeof(double) * m), *cc = malloc(sizeof(double) * m);
        size_t scratch = sizeof(double) * COLUMN_BLOCK * threads;
        double *lo = malloc(scratch), *hi = malloc(scratch), *mean = malloc(scratch);
        if (!mm || !cc || !lo || !hi || !mean) {
            free(mm), free(cc), free(lo), free(hi), free(mean);
            return SOAK_ERR_NOMEM;
        }
        soak_bake_exec quiet = {threads, NULL, NULL};
        sweep_ctx s = {u, width, height, r, mm, cc, lo, hi, mean};
        factor_line(width, r, mm, cc);
        soak_status st = soak_parallel_rows(height, &quiet, sweep_x, &s, 0, 1);
        if (st == SOAK_OK) {
            factor_line(height, r, mm, cc);
            st = soak_parallel_rows((width + COLUMN_BLOCK - 1) / COLUMN_BLOCK, &quiet, sweep_y, &s, 0, 1);
        }
        free(mm), free(cc), free(lo), free(hi), free(mean);
        if (st != SOAK_OK) return st;
    }
    if (evap > 0)
        for (size_t i = 0; i < n; ++i) u[i] = u[i] > evap ? u[i] - evap : 0.0;
    return SOAK_OK;
}

static soak_status bake_diffusion(const unsigned char *wet, int width, int height, const soak_drying_params *p,
                                  const soak_bake_exec *exec, float *out)
{
    size_t n = (size_t)width * height;
    double *u = malloc(sizeof(double) * n);
    if (!u) return SOAK_ERR_NOMEM;
    for (size_t i = 0; i < n; ++i) u[i] = wet[i] ? 1.0 : 0.0;
    soak_status st = SOAK_OK;
    if (p->time > 0) {
        double dt = p->time / p->steps;
        double r = p->diffusion_length * p->diffusion_length * (dt / p->drying_time);
        double evap = dt / p->drying_time;
        if (!soak_is_finite(r) || !soak_is_finite(evap)) st = SOAK_ERR_ARG;
        for (int k = 0; k < p->steps && st == SOAK_OK; ++k) {
            st = soak_diffusion_step(u, width, height, r, evap, exec);
            if (exec && exec->progress) exec->progress(exec->progress_user, (k + 1.0) / p->steps);
        }
    }
    if (st == SOAK_OK)
        for (size_t i = 0; i < n; ++i) out[i] = (float)fmin(1.0, fmax(0.0, u[i]));
    free(u);
    return st;
}

double soak_drying_peak_bytes(int width, int height, const soak_drying_params *p)
{
    const double encode = 4 + 4 + 2; /* output floats, the encoder's float copy, 16-bit samples */
    double work = 1 + 4 + ((p && p->mode == SOAK_DRYING_DIFFUSION) ? 8 : 8 + 1 + 8);
    return (double)width * (double)height * (work > encode ? work : encode);
}

soak_status soak_bake_drying(const soak_image *mask, int width, int height, const soak_drying_params *p,
                             const soak_bake_exec *exec, soak_image *out)
{
    if (!p || !out) return SOAK_ERR_NULL;
    soak_status st = soak_drying_check(p);
    if (st != SOAK_OK) return st;
    if (mask) {
        if ((st = check_mask(mask)) != SOAK_OK) return st;
        width = mask->width;
        height = mask->height;
    } else if (soak_bake_check_size(width, height) != SOAK_OK) {
        return SOAK_ERR_ARG;
    }
    if (soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;
    size_t n = (size_t)width * height;
    unsigned char *wet = malloc(n);
    double *t0 = p->mode == SOAK_DRYING_SCHEDULE ? malloc(sizeof(double) * n) : NULL;
    if (!wet || (p->mode == SOAK_DRYING_SCHEDULE && !t0)) {
        free(wet), free(t0);
        return SOAK_ERR_NOMEM;
    }
    if ((st = soak_image_alloc(out, width, height, 1)) != SOAK_OK) {
        free(wet), free(t0);
        return st;
    }
    if (p->mode == SOAK_DRYING_DIFFUSION) {
        wet_flags(mask, p->threshold, n, wet);
        st = bake_diffusion(wet, width, height, p, exec, out->pixels);
    } else {
        st = start_times(mask, width, height, p, t0, wet);
        for (size_t i = 0; i < n && st == SOAK_OK; ++i) {
            double frac = 1;
            if (wet[i]) st = soak_fill_fraction(p->time, t0[i], p->t_fill, &frac);
            /* (t - t0) / t_fill can round just below 1 at the ramp's end
             * t = t0 + t_fill, where the schedule says dry. */
            out->pixels[i] = frac > 1 - 1e-12 ? 0.0f : (float)(1 - frac);
        }
        if (exec && exec->progress) exec->progress(exec->progress_user, 1);
    }
    free(wet), free(t0);
    if (st != SOAK_OK) soak_image_free(out);
    return st;
}
