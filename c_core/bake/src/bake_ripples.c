/* Ripple flipbook: one capillary-gravity ring per drop impact on a torus
 * in space and time (model in soak/bake_ripples.h). */
#include "soak/bake_ripples.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/bake_drops.h"
#include "soak/bake_rain.h"
#include "soak/poisson.h"

#define PI 3.14159265358979323846
#define ENVELOPE_SIGMAS 3.5 /* ring drawn within R +- 3.5 w (envelope 2e-3 there) */
#define PROFILE_STEP 0.25   /* texels between samples of a ring's radial profile */
#define POISSON_EXACT_MAX 30.0

double soak_capillary_omega(double k)
{
    if (!soak_in_range(k, 1e-300, 1e12)) return 0;
    return sqrt(SOAK_GRAVITY * k + SOAK_WATER_SIGMA / SOAK_WATER_RHO * k * k * k);
}

double soak_capillary_group_velocity(double k)
{
    double w = soak_capillary_omega(k);
    if (w <= 0) return 0;
    return (SOAK_GRAVITY + 3 * SOAK_WATER_SIGMA / SOAK_WATER_RHO * k * k) / (2 * w);
}

void soak_ripples_defaults(soak_ripples_params *p)
{
    if (!p) return;
    memset(p, 0, sizeof *p);
    p->rate_mm_h = 10;
    p->tile_m = 0.5;
    p->size = 512;
    p->frames = 64;
    p->period = 2.56;
    p->wavelength_m = 2 * PI / sqrt(SOAK_WATER_RHO * SOAK_GRAVITY / SOAK_WATER_SIGMA);
    p->width_m = 0.5 * p->wavelength_m;
    p->lifetime = 0.5;
    p->amplitude_m = 3e-4;
    p->min_diameter_mm = 1;
}

soak_status soak_ripples_check(const soak_ripples_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!(soak_in_range(p->rate_mm_h, 0, SOAK_DROP_RATE_MAX) && p->rate_mm_h > 0) ||
        !soak_in_range(p->tile_m, 1e-6, 100) || !(p->size >= 1 && p->size <= SOAK_BAKE_MAX_SIZE) ||
        !(p->frames >= 1 && p->frames <= SOAK_RIPPLES_MAX_FRAMES) || !soak_in_range(p->period, 1e-6, 1e4) ||
        !soak_in_range(p->wavelength_m, 1e-6, 10) || !soak_in_range(p->width_m, 1e-6, 10) ||
        !soak_in_range(p->lifetime, 1e-6, 1e3) || !soak_in_range(p->amplitude_m, 1e-12, 1) ||
        !(soak_in_range(p->min_diameter_mm, 0, SOAK_DROP_D_MAX_MM) && p->min_diameter_mm < SOAK_DROP_D_MAX_MM))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

#define MAX_IMPACTS 50000000.0

soak_status soak_ripples_impacts(const soak_ripples_params *p, soak_ripple_impact **out, size_t *count)
{
    if (!p || !out || !count) return SOAK_ERR_NULL;
    *out = NULL, *count = 0;
    soak_status st = soak_ripples_check(p);
    if (st != SOAK_OK) return st;
    double lambda = soak_drop_flux(p->rate_mm_h, p->min_diameter_mm, SOAK_DROP_D_MAX_MM) * p->tile_m * p->tile_m *
                    p->period;
    if (!(lambda <= MAX_IMPACTS)) return SOAK_ERR_ARG;
    soak_rng rng;
    soak_rng_seed(&rng, p->seed, 0x726970706c6573ULL); /* "ripples" */
    double parts = ceil(lambda / POISSON_EXACT_MAX);
    long n = 0;
    for (double k = 0; k < parts; ++k) n += soak_rng_poisson(lambda / parts, &rng);
    if (n == 0) return SOAK_OK;
    soak_ripple_impact *v = malloc((size_t)n * sizeof *v);
    if (!v) return SOAK_ERR_NOMEM;
    for (long i = 0; i < n; ++i) {
        v[i].x = soak_rng_uniform(&rng) * p->tile_m;
        v[i].y = soak_rng_uniform(&rng) * p->tile_m;
        v[i].t = soak_rng_uniform(&rng) * p->period;
    }
    *out = v, *count = (size_t)n;
    return SOAK_OK;
}

/* A live ring at the frame's time, in texels, with its radial profile h(r)
 * and dh/dr sampled every PROFILE_STEP texels from r0 (linear
 * interpolation: relative error (k step)^2 / 8, 1e-3 at 70 samples per
 * wavelength), so a texel costs a square root, not exp, sin and cos. */
typedef struct ring {
    double cx, cy, radius, r0;
    size_t profile; /* index of its first sample in the profile array */
    int samples;
} ring;

typedef struct frame_ctx {
    const soak_ripples_params *p;
    const ring *rings;
    size_t n;
    const double *profile; /* (h, dh/dr) pairs, metres and metres per texel */
    double reach;          /* drawn half-width, texels */
    double *h, *gx, *gy;   /* height (m) and slopes per texel (x right, y down) */
} frame_ctx;

static long wrap_index(long i, long n)
{
    long m = i % n;
    return m < 0 ? m + n : m;
}

/* Adds ring g to texels i0..i1 (unwrapped) of unwrapped row j = image row y. */
static void ring_span(const frame_ctx *c, const ring *g, double dy, long i0, long i1, long y)
{
    long n = c->p->size, x = wrap_index(i0, n);
    const double *prof = c->profile + 2 * g->profile;
    double *h = c->h + (size_t)y * n, *gx = c->gx + (size_t)y * n, *gy = c->gy + (size_t)y * n;
    double last = g->samples - 1, dy2 = dy * dy;
    for (long i = i0; i <= i1; ++i, x = x + 1 == n ? 0 : x + 1) {
        double dx = (double)i + 0.5 - g->cx, r = sqrt(dx * dx + dy2);
        double u = (r - g->r0) * (1.0 / PROFILE_STEP);
        if (!(u >= 0 && u < last)) continue;
        int k = (int)u;
        double f = u - k, hv = prof[2 * k] + f * (prof[2 * k + 2] - prof[2 * k]);
        double dhdr = prof[2 * k + 1] + f * (prof[2 * k + 3] - prof[2 * k + 1]);
        h[x] += hv;
        if (r > 0) {
            double s = dhdr / r;
            gx[x] += s * dx, gy[x] += s * dy;
        }
    }
}

/* Ring g's annulus in unwrapped row j: one span, or two beside its hole.
 * Texels outside the profile's samples are skipped in ring_span, so the
 * spans may be generous by a texel. */
static void ring_row(const frame_ctx *c, const ring *g, long j, long y)
{
    double dy = (double)j + 0.5 - g->cy, out = g->radius + c->reach, in = g->r0;
    if (fabs(dy) > out) return;
    double half = sqrt(out * out - dy * dy);
    long i0 = (long)ceil(g->cx - 0.5 - half), i1 = (long)floor(g->cx - 0.5 + half);
    if (in <= 1 || fabs(dy) >= in - 1) {
        ring_span(c, g, dy, i0, i1, y);
        return;
    }
    double hole = sqrt((in - 1) * (in - 1) - dy * dy);
    long h0 = (long)ceil(g->cx - 0.5 - hole), h1 = (long)floor(g->cx - 0.5 + hole);
    ring_span(c, g, dy, i0, h0 - 1, y);
    ring_span(c, g, dy, h1 + 1, i1, y);
}

static void frame_row(void *vctx, int y, int thread)
{
    (void)thread;
    const frame_ctx *c = vctx;
    long n = c->p->size;
    for (size_t k = 0; k < c->n; ++k) {
        const ring *g = &c->rings[k];
        double top = g->cy - 0.5 - g->radius - c->reach, bottom = g->cy - 0.5 + g->radius + c->reach;
        /* unwrapped rows j = y + m n inside [top, bottom] */
        for (long j = y + n * (long)ceil((top - y) / n); j <= bottom; j += n) ring_row(c, g, j, y);
    }
}

typedef struct ring_set {
    ring *rings;
    size_t n;
    double *profile;
} ring_set;

/* Samples ring g's profile (see soak/bake_ripples.h) at age tau. */
static void ring_profile(const soak_ripples_params *p, double tau, double reach, ring *g, double *prof)
{
    double texel = p->tile_m / p->size, k = 2 * PI / p->wavelength_m, w = p->width_m;
    double radius = soak_capillary_group_velocity(k) * tau, phase = soak_capillary_omega(k) * tau;
    double amp = p->amplitude_m * exp(-tau / p->lifetime) * sqrt(w / (w + radius));
    g->radius = radius / texel;
    g->r0 = fmax(0.0, g->radius - reach);
    g->samples = (int)ceil((g->radius + reach - g->r0) / PROFILE_STEP) + 2;
    for (int s = 0; s < g->samples; ++s) {
        double r = (g->r0 + s * PROFILE_STEP) * texel, u = (r - radius) / w, env = amp * exp(-0.5 * u * u);
        double ph = k * r - phase, cs = cos(ph), sn = sin(ph);
        prof[2 * s] = env * cs;
        prof[2 * s + 1] = env * (-u / w * cs - k * sn); /* dh/dr, metres per metre */
    }
}

static soak_status live_rings(const soak_ripples_params *p, const soak_ripple_impact *imp, size_t count, long frame,
                              double reach, ring_set *set)
{
    double t = (double)frame * p->period / p->frames, texel = p->tile_m / p->size;
    double max_age = SOAK_RIPPLES_LIFETIMES * p->lifetime;
    double cg = soak_capillary_group_velocity(2 * PI / p->wavelength_m);
    size_t per = (size_t)ceil(max_age / p->period) + 1, cap = count * per, n = 0, samples = 0;
    int max_samples = (int)ceil((cg * max_age / texel + 2 * reach) / PROFILE_STEP) + 3;
    set->rings = malloc((cap ? cap : 1) * sizeof *set->rings);
    if (!set->rings) return SOAK_ERR_NOMEM;
    size_t prof_cap = 0;
    for (size_t i = 0; i < count; ++i) {
        double age = fmod(t - imp[i].t, p->period);
        if (age < 0) age += p->period;
        for (double tau = age; tau < max_age && n < cap; tau += p->period) {
            if (samples + (size_t)max_samples > prof_cap) {
                size_t grow = prof_cap ? 2 * prof_cap : 4096 + (size_t)max_samples;
                while (grow < samples + (size_t)max_samples) grow *= 2;
                double *v = realloc(set->profile, 2 * grow * sizeof *v);
                if (!v) return SOAK_ERR_NOMEM;
                set->profile = v, prof_cap = grow;
            }
            ring *g = &set->rings[n++];
            g->cx = imp[i].x / texel, g->cy = imp[i].y / texel, g->profile = samples;
            ring_profile(p, tau, reach, g, set->profile + 2 * samples);
            samples += (size_t)g->samples;
        }
    }
    set->n = n;
    return SOAK_OK;
}

/* RGBA from slopes and height, (dh/dx, dh/dy, h) per texel (see
 * soak/bake_ripples.h for the encoding). */
static void encode(const soak_ripples_params *p, const float *field, soak_image *out)
{
    size_t n = (size_t)p->size * p->size;
    for (size_t i = 0; i < n; ++i) {
        double nx = -field[3 * i], ny = field[3 * i + 1], len = sqrt(nx * nx + ny * ny + 1);
        float *px = out->pixels + 4 * i;
        px[0] = (float)(0.5 * (nx / len + 1));
        px[1] = (float)(0.5 * (ny / len + 1));
        px[2] = (float)(0.5 * (1 / len + 1));
        px[3] = (float)fmin(1.0, fmax(0.0, 0.5 + field[3 * i + 2] / (4 * p->amplitude_m)));
    }
}

/* Slopes (metres per metre) and height (m) into a 3-channel image. */
static soak_status render_field(const soak_ripples_params *p, const ring_set *set, const soak_bake_exec *exec,
                                soak_image *field)
{
    size_t n = (size_t)p->size * p->size;
    double *g = calloc(3 * n, sizeof(double)), *h = g + 2 * n;
    if (!g) return SOAK_ERR_NOMEM;
    double texel = p->tile_m / p->size;
    frame_ctx c = {p, set->rings, set->n, set->profile, ENVELOPE_SIGMAS * p->width_m / texel, h, g, g + n};
    soak_bake_exec quiet = {exec ? exec->threads : 0, NULL, NULL};
    soak_status st = soak_parallel_rows(p->size, &quiet, frame_row, &c, 0, 1);
    if (st == SOAK_OK) st = soak_image_alloc(field, p->size, p->size, 3);
    for (size_t i = 0; i < n && st == SOAK_OK; ++i) {
        field->pixels[3 * i] = (float)g[i];
        field->pixels[3 * i + 1] = (float)g[n + i];
        field->pixels[3 * i + 2] = (float)h[i];
    }
    free(g);
    return st;
}

static soak_status check_frame_args(const soak_ripples_params *p, long frame, double filter_px,
                                    const soak_bake_exec *exec)
{
    soak_status st = soak_ripples_check(p);
    if (st != SOAK_OK) return st;
    if (!(filter_px == 0 || soak_in_range(filter_px, 1e-6, SOAK_BLUR_MAX_SIGMA)) || soak_bake_threads(exec) == 0 ||
        !(labs(frame) <= 1000000000L))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

soak_status soak_ripples_frame(const soak_ripples_params *p, const soak_ripple_impact *impacts, size_t count,
                               long frame, double filter_px, const soak_bake_exec *exec, soak_image *out,
                               soak_image *far)
{
    if (!p || !out || (count && !impacts) || (filter_px > 0 && !far)) return SOAK_ERR_NULL;
    soak_status st = check_frame_args(p, frame, filter_px, exec);
    if (st != SOAK_OK) return st;
    ring_set set = {NULL, 0, NULL};
    double texel = p->tile_m / p->size;
    soak_image field = {0, 0, 0, NULL}, blurred = {0, 0, 0, NULL};
    st = live_rings(p, impacts, count, frame, ENVELOPE_SIGMAS * p->width_m / texel, &set);
    if (st == SOAK_OK) st = render_field(p, &set, exec, &field);
    if (st == SOAK_OK) st = soak_image_alloc(out, p->size, p->size, 4);
    if (st == SOAK_OK) encode(p, field.pixels, out);
    if (st == SOAK_OK && filter_px > 0) st = soak_map_blur(&field, filter_px, 1, exec, &blurred);
    if (st == SOAK_OK && filter_px > 0) st = soak_image_alloc(far, p->size, p->size, 4);
    if (st == SOAK_OK && filter_px > 0) encode(p, blurred.pixels, far);
    if (exec && exec->progress) exec->progress(exec->progress_user, 1);
    if (st != SOAK_OK) soak_image_free(out), soak_image_free(far);
    free(set.rings), free(set.profile);
    soak_image_free(&field), soak_image_free(&blurred);
    return st;
}
