/* The picture denoiser of soak/denoise.h: firefly removal, then the
 * edge-avoiding a-trous filter (Dammertz et al. 2010) with SVGF's
 * variance-scaled colour term (Schied et al. 2017). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/denoise.h"
#include "soak/vec.h"

/* B3-spline taps (1, 4, 6, 4, 1) / 16, Dammertz et al. 2010 sec. 3. */
static const float B3[5] = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};

void soak_denoise_options_default(soak_denoise_options *o)
{
    o->iterations = 5;
    o->sigma_colour = 4.0;
    o->normal_power = 128.0;
    o->sigma_depth = 0.01;
    o->sigma_wetness = 0.3;
    o->firefly_ratio = 4.0;
}

static float lum3(const float *c) { return (float)soak_rgb_luminance(soak_rgb3(c[0], c[1], c[2])); }

/* The working state: colour and variance ping-pong buffers and the
 * 3x3-smoothed variance. */
typedef struct dn_state {
    int W, H;
    float *col, *var, *col2, *var2, *var_s;
    const soak_denoise_features *f;
    const soak_denoise_options *o;
    float eps; /* colour term's floor: 1e-4 of the image's mean luminance */
} dn_state;

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Step 1 at pixel (x, y): 1 if replaced. */
static int firefly_fix(dn_state *s, const float *src, const float *srcvar, int x, int y)
{
    float yn[8], ys[8];
    int idx[8], n = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int xx = x + dx, yy = y + dy;
            if ((dx || dy) && xx >= 0 && yy >= 0 && xx < s->W && yy < s->H) {
                idx[n] = yy * s->W + xx;
                yn[n] = ys[n] = lum3(src + 3 * (size_t)idx[n]);
                n++;
            }
        }
    if (n < 3) return 0;
    qsort(ys, (size_t)n, sizeof *ys, cmp_float);
    size_t p = (size_t)y * s->W + x;
    float second = ys[n - 2], median = ys[n / 2];
    if (!(lum3(src + 3 * p) > (float)s->o->firefly_ratio * second + s->eps)) return 0;
    for (int k = 0; k < n; ++k)
        if (yn[k] == median) {
            memcpy(s->col + 3 * p, src + 3 * (size_t)idx[k], 3 * sizeof(float));
            s->var[p] = srcvar[idx[k]];
            break;
        }
    return 1;
}

/* Step 1b at pixel (x, y) of s->col, writing dst: a field of sparkles (a
 * film glinting at a few samples a pixel) has bright neighbours, so each is
 * capped at firefly_ratio times the median luminance of its 5 x 5 window
 * (hue kept). 1 if capped. */
static int sparkle_cap(dn_state *s, float *dst, int x, int y)
{
    float win[25];
    int n = 0;
    for (int yy = y - 2; yy <= y + 2; ++yy)
        for (int xx = x - 2; xx <= x + 2; ++xx)
            if (xx >= 0 && yy >= 0 && xx < s->W && yy < s->H) win[n++] = lum3(s->col + 3 * ((size_t)yy * s->W + xx));
    qsort(win, (size_t)n, sizeof *win, cmp_float);
    size_t p = (size_t)y * s->W + x;
    float cap = (float)s->o->firefly_ratio * win[n / 2] + s->eps, l = lum3(s->col + 3 * p);
    memcpy(dst + 3 * p, s->col + 3 * p, 3 * sizeof(float));
    if (!(l > cap)) return 0;
    for (int ch = 0; ch < 3; ++ch) dst[3 * p + ch] *= cap / l;
    return 1;
}

static long remove_fireflies(dn_state *s, const float *src, const float *srcvar)
{
    long fixed = 0;
    for (int y = 0; y < s->H; ++y)
        for (int x = 0; x < s->W; ++x) fixed += firefly_fix(s, src, srcvar, x, y);
    for (int y = 0; y < s->H; ++y)
        for (int x = 0; x < s->W; ++x) fixed += sparkle_cap(s, s->col2, x, y);
    float *t = s->col;
    s->col = s->col2;
    s->col2 = t;
    return fixed;
}

static void smooth_variance(dn_state *s)
{
    static const float g[3] = {0.25f, 0.5f, 0.25f};
    for (int y = 0; y < s->H; ++y)
        for (int x = 0; x < s->W; ++x) {
            float acc = 0, wsum = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= s->W || yy >= s->H) continue;
                    float w = g[dx + 1] * g[dy + 1];
                    acc += w * s->var[(size_t)yy * s->W + xx];
                    wsum += w;
                }
            s->var_s[(size_t)y * s->W + x] = acc / wsum;
        }
}

/* The feature terms between pixels p and q, offset (dx, dy) pixels apart. */
static float feature_weight(const dn_state *s, size_t p, size_t q)
{
    const soak_denoise_features *f = s->f;
    if (!f) return 1.0f;
    if (f->object && f->object[p] != f->object[q]) return 0.0f;
    float w = 1.0f;
    if (f->normal) {
        const float *np = f->normal + 3 * p, *nq = f->normal + 3 * q;
        double c = fmax(0.0, (double)np[0] * nq[0] + (double)np[1] * nq[1] + (double)np[2] * nq[2]);
        double lp = sqrt((double)np[0] * np[0] + (double)np[1] * np[1] + (double)np[2] * np[2]);
        double lq = sqrt((double)nq[0] * nq[0] + (double)nq[1] * nq[1] + (double)nq[2] * nq[2]);
        if (lp > 0 && lq > 0) w *= (float)pow(fmin(1.0, c / (lp * lq)), s->o->normal_power);
    }
    if (f->position && f->depth && f->normal) {
        /* q's distance from p's tangent plane: 0 along one flat surface
         * however it recedes, large across an occluding edge. */
        const float *pp = f->position + 3 * p, *pq = f->position + 3 * q, *np = f->normal + 3 * p;
        float d = np[0] * (pq[0] - pp[0]) + np[1] * (pq[1] - pp[1]) + np[2] * (pq[2] - pp[2]);
        float ln = sqrtf(np[0] * np[0] + np[1] * np[1] + np[2] * np[2]);
        float tol = (float)s->o->sigma_depth * f->depth[p] + 1e-9f;
        if (ln > 0) w *= expf(-fabsf(d) / (ln * tol));
    }
    if (f->wetness) w *= expf(-fabsf(f->wetness[p] - f->wetness[q]) / (float)s->o->sigma_wetness);
    return w;
}

/* One a-trous pass with taps `step` pixels apart: col, var -> col2, var2. */
static void atrous_pixel(dn_state *s, int x, int y, int step)
{
    size_t p = (size_t)y * s->W + x;
    float lp = lum3(s->col + 3 * p), denom = (float)s->o->sigma_colour * sqrtf(s->var_s[p]) + s->eps;
    double acc[3] = {0, 0, 0}, wsum = 0, vacc = 0;
    for (int ky = 0; ky < 5; ++ky)
        for (int kx = 0; kx < 5; ++kx) {
            int dx = (kx - 2) * step, dy = (ky - 2) * step, xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= s->W || yy >= s->H) continue;
            size_t q = (size_t)yy * s->W + xx;
            float w = B3[kx] * B3[ky];
            if (q != p) {
                w *= feature_weight(s, p, q);
                if (w > 0) w *= expf(-fabsf(lp - lum3(s->col + 3 * q)) / denom);
            }
            if (!(w > 0)) continue;
            for (int ch = 0; ch < 3; ++ch) acc[ch] += (double)w * s->col[3 * q + ch];
            wsum += w;
            vacc += (double)w * w * s->var[q];
        }
    for (int ch = 0; ch < 3; ++ch) s->col2[3 * p + ch] = (float)(acc[ch] / wsum);
    s->var2[p] = (float)(vacc / (wsum * wsum));
}

static void atrous_pass(dn_state *s, int step)
{
    smooth_variance(s);
    for (int y = 0; y < s->H; ++y)
        for (int x = 0; x < s->W; ++x) atrous_pixel(s, x, y, step);
    float *t = s->col;
    s->col = s->col2;
    s->col2 = t;
    t = s->var;
    s->var = s->var2;
    s->var2 = t;
}

/* A pixel's variance from a few samples is itself noisy (one degree of
 * freedom at 2 samples: often near 0, which would freeze the pixel): the
 * filter starts from its mean over 7 x 7 pixels of the same object, as
 * SVGF estimates a young pixel's variance spatially (Schied et al. 2017,
 * sec. 4.2), or from the pixel's own where that is larger (an outlier keeps
 * the variance that lets its neighbours smooth it). */
static void spatial_variance(dn_state *s)
{
    const int *obj = s->f ? s->f->object : NULL;
    for (int y = 0; y < s->H; ++y)
        for (int x = 0; x < s->W; ++x) {
            size_t p = (size_t)y * s->W + x;
            double acc = 0;
            int n = 0;
            for (int yy = y - 3; yy <= y + 3; ++yy)
                for (int xx = x - 3; xx <= x + 3; ++xx) {
                    if (xx < 0 || yy < 0 || xx >= s->W || yy >= s->H) continue;
                    size_t q = (size_t)yy * s->W + xx;
                    if (obj && obj[q] != obj[p]) continue;
                    acc += s->var[q];
                    n++;
                }
            s->var2[p] = fmaxf(s->var[p], (float)(acc / n));
        }
    memcpy(s->var, s->var2, (size_t)s->W * s->H * sizeof(float));
}

static soak_status check_args(const soak_image *img, const soak_image *variance, const soak_denoise_features *f,
                              const soak_denoise_options *o, char *err, size_t errlen)
{
    const char *why = NULL;
    if (!img->pixels || img->channels != 3) why = "the image must be RGB";
    else if (!variance->pixels || variance->channels != 1 || variance->width != img->width ||
             variance->height != img->height)
        why = "the variance must be one channel of the image's size";
    else if (f && (f->width != img->width || f->height != img->height)) why = "the features must have the image's size";
    else if (!(o->iterations >= 1 && o->iterations <= 10)) why = "iterations must be in [1, 10]";
    else if (!(o->sigma_colour > 0 && o->sigma_depth > 0 && o->sigma_wetness > 0 && o->normal_power >= 0))
        why = "sigma_colour, sigma_depth and sigma_wetness must be > 0, normal_power >= 0";
    else if (!(o->firefly_ratio == 0 || (o->firefly_ratio > 1 && o->firefly_ratio < 1e9)))
        why = "firefly_ratio must be 0 (off) or > 1";
    if (!why) return SOAK_OK;
    if (err && errlen) snprintf(err, errlen, "denoise: %s", why);
    return SOAK_ERR_ARG;
}

static void state_free(dn_state *s)
{
    free(s->col);
    free(s->var);
    free(s->col2);
    free(s->var2);
    free(s->var_s);
}

static soak_status state_init(dn_state *s, const soak_image *img, const soak_image *variance)
{
    size_t n = (size_t)img->width * img->height;
    s->W = img->width;
    s->H = img->height;
    s->col = malloc(3 * n * sizeof(float));
    s->col2 = malloc(3 * n * sizeof(float));
    s->var = malloc(n * sizeof(float));
    s->var2 = malloc(n * sizeof(float));
    s->var_s = malloc(n * sizeof(float));
    if (!s->col || !s->col2 || !s->var || !s->var2 || !s->var_s) return SOAK_ERR_NOMEM;
    double mean = 0;
    for (size_t i = 0; i < n; ++i) {
        for (int ch = 0; ch < 3; ++ch) {
            float v = img->pixels[3 * i + ch];
            s->col[3 * i + ch] = isfinite(v) && v > 0 ? v : 0.0f;
        }
        float v = variance->pixels[i];
        s->var[i] = isfinite(v) && v > 0 ? v : 0.0f;
        mean += lum3(s->col + 3 * i);
    }
    s->eps = (float)(1e-4 * mean / (double)n) + 1e-12f;
    return SOAK_OK;
}

soak_status soak_denoise(soak_image *img, const soak_image *variance, const soak_denoise_features *features,
                         const soak_denoise_options *opt, soak_denoise_stats *stats, char *err, size_t errlen)
{
    if (!img || !variance || !opt) return SOAK_ERR_NULL;
    soak_status st = check_args(img, variance, features, opt, err, errlen);
    if (st != SOAK_OK) return st;
    dn_state s;
    memset(&s, 0, sizeof s);
    s.f = features;
    s.o = opt;
    st = state_init(&s, img, variance);
    long fixed = 0;
    if (st == SOAK_OK && opt->firefly_ratio > 0) {
        /* Read the original, write the copy: a fix never feeds the next test. */
        memcpy(s.col2, s.col, 3 * (size_t)s.W * s.H * sizeof(float));
        memcpy(s.var2, s.var, (size_t)s.W * s.H * sizeof(float));
        fixed = remove_fireflies(&s, s.col2, s.var2);
    }
    if (st == SOAK_OK) {
        spatial_variance(&s);
        for (int it = 0; it < opt->iterations; ++it) atrous_pass(&s, 1 << it);
        memcpy(img->pixels, s.col, 3 * (size_t)s.W * s.H * sizeof(float));
    }
    if (stats) stats->fireflies = fixed;
    state_free(&s);
    return st;
}
