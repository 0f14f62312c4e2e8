/* The drops bake over time: a water depth per texel, impacts applied in
 * time order, the wet map at a frame's time and, after the rain, the
 * drying bake's pore schedule (soak/bake_drops.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/bake_drops.h"

#define PI 3.14159265358979323846

/* One impact rasterised: disc of radius r texels about (cx, cy), dh metres
 * of water added to each of the texels whose centre lies in it, or only
 * to texel (sx, sy) when none does. */
typedef struct splat {
    double cx, cy, r, dh;
    int single, sx, sy;
} splat;

struct soak_drops_state {
    soak_drops_params p;
    soak_image exposure; /* pixels NULL without */
    int width, height;
    double *depth;
    long next_slab;         /* impacts of earlier slabs are generated */
    soak_drop_impact *pending; /* generated, not applied, in time order */
    size_t n_pending, applied, splashed;
    double time;            /* every impact with t < time is applied */
    splat *splats;
    size_t splat_cap;
};

/* Unwrapped rows j0..j1 whose texel centres may lie in the disc; clipped
 * to the map when not wrapping; at most `height` rows. */
static void disc_rows(const soak_drops_state *s, const splat *sp, long *j0, long *j1)
{
    *j0 = (long)ceil(sp->cy - 0.5 - sp->r);
    *j1 = (long)floor(sp->cy - 0.5 + sp->r);
    if (!s->p.wrap) {
        if (*j0 < 0) *j0 = 0;
        if (*j1 > s->height - 1) *j1 = s->height - 1;
    } else if (*j1 - *j0 >= s->height) {
        *j1 = *j0 + s->height - 1;
    }
}

/* Columns i0..i1 (unwrapped) of row j inside the disc; returns their count. */
static long disc_span(const soak_drops_state *s, const splat *sp, long j, long *i0, long *i1)
{
    double dy = (double)j + 0.5 - sp->cy, q = sp->r * sp->r - dy * dy;
    if (q < 0) return 0;
    double half = sqrt(q);
    *i0 = (long)ceil(sp->cx - 0.5 - half);
    *i1 = (long)floor(sp->cx - 0.5 + half);
    if (!s->p.wrap) {
        if (*i0 < 0) *i0 = 0;
        if (*i1 > s->width - 1) *i1 = s->width - 1;
    } else if (*i1 - *i0 >= s->width) {
        *i1 = *i0 + s->width - 1;
    }
    return *i1 >= *i0 ? *i1 - *i0 + 1 : 0;
}

static long wrap_index(long i, int n)
{
    long m = i % n;
    return m < 0 ? m + n : m;
}

/* The splat of volume m^3 of a drop of d_mm spread by factor f about (x, y). */
static void place_splat(const soak_drops_state *s, double x, double y, double d_mm, double f, double volume, splat *sp)
{
    sp->cx = x, sp->cy = y, sp->r = 0.5 * f * d_mm * 1e-3 / s->p.texel_m;
    long j0, j1, i0, i1, covered = 0;
    disc_rows(s, sp, &j0, &j1);
    for (long j = j0; j <= j1; ++j) covered += disc_span(s, sp, j, &i0, &i1);
    sp->single = covered == 0;
    long tx = (long)floor(x), ty = (long)floor(y);
    if (s->p.wrap) tx = wrap_index(tx, s->width), ty = wrap_index(ty, s->height);
    sp->sx = (int)(tx < 0 ? 0 : (tx > s->width - 1 ? s->width - 1 : tx));
    sp->sy = (int)(ty < 0 ? 0 : (ty > s->height - 1 ? s->height - 1 : ty));
    sp->dh = volume / ((double)(covered ? covered : 1) * s->p.texel_m * s->p.texel_m);
}

static double drop_volume(double d_mm)
{
    double d_m = d_mm * 1e-3;
    return PI / 6 * d_m * d_m * d_m;
}

static void make_splat(const soak_drops_state *s, const soak_drop_impact *imp, double share, splat *sp)
{
    double f = s->p.spread_factor > 0 ? s->p.spread_factor : soak_drop_spread_factor(imp->d_mm);
    place_splat(s, imp->x, imp->y, imp->d_mm, f, share * drop_volume(imp->d_mm), sp);
}

typedef struct apply_ctx {
    soak_drops_state *s;
    size_t n;
} apply_ctx;

/* Row y receives every splat in order: the same additions, in the same
 * order, whichever thread runs the row. */
static void apply_row(void *vctx, int y, int thread)
{
    (void)thread;
    const apply_ctx *a = vctx;
    soak_drops_state *s = a->s;
    double *row = s->depth + (size_t)y * s->width, cap = s->p.capacity_m;
    for (size_t k = 0; k < a->n; ++k) {
        const splat *sp = &s->splats[k];
        if (sp->single) {
            if (sp->sy == y) row[sp->sx] = fmin(cap, row[sp->sx] + sp->dh);
            continue;
        }
        long j0, j1, i0, i1;
        disc_rows(s, sp, &j0, &j1);
        long j = s->p.wrap ? j0 + wrap_index(y - j0, s->height) : y;
        if (j < j0 || j > j1 || disc_span(s, sp, j, &i0, &i1) == 0) continue;
        for (long i = i0; i <= i1; ++i) {
            long x = s->p.wrap ? wrap_index(i, s->width) : i;
            row[x] = fmin(cap, row[x] + sp->dh);
        }
    }
}

/* Adds one splat to the depths (the additions apply_row makes). */
static void add_splat(soak_drops_state *s, const splat *sp)
{
    double cap = s->p.capacity_m;
    if (sp->single) {
        double *d = &s->depth[(size_t)sp->sy * s->width + sp->sx];
        *d = fmin(cap, *d + sp->dh);
        return;
    }
    long j0, j1, i0, i1;
    disc_rows(s, sp, &j0, &j1);
    for (long j = j0; j <= j1; ++j) {
        if (disc_span(s, sp, j, &i0, &i1) == 0) continue;
        double *row = s->depth + (size_t)(s->p.wrap ? wrap_index(j, s->height) : j) * s->width;
        for (long i = i0; i <= i1; ++i) {
            long x = s->p.wrap ? wrap_index(i, s->width) : i;
            row[x] = fmin(cap, row[x] + sp->dh);
        }
    }
}

/* Clanet et al.'s spread factor at speed v (m/s), at least 1. */
static double spread_at(double d_mm, double v)
{
    double we = SOAK_WATER_RHO * v * v * d_mm * 1e-3 / SOAK_WATER_SIGMA, f = 0.9 * pow(we, 0.25);
    return f > 1.0 ? f : 1.0;
}

/* Impact imp, splashing where its texel holds water (soak/bake_drops.h):
 * its splat, then its secondaries' (those landing off a clipped map are
 * lost, as the excess over capacity is). */
static void splash_impact(soak_drops_state *s, const soak_drop_impact *imp, soak_splash_drop *sec)
{
    splat sp;
    make_splat(s, imp, 1.0, &sp);
    int m = soak_splash_throw(&s->p, imp, s->depth[(size_t)sp.sy * s->width + sp.sx], sec);
    if (m > 0) {
        make_splat(s, imp, 1.0 - s->p.splash_fraction, &sp);
        ++s->splashed;
    }
    add_splat(s, &sp);
    for (int k = 0; k < m; ++k) {
        if (!s->p.wrap && !(sec[k].x >= 0 && sec[k].x < s->width && sec[k].y >= 0 && sec[k].y < s->height)) continue;
        double d = sec[k].d_mm, volume = PI / 6 * d * d * d * 1e-9;
        place_splat(s, sec[k].x, sec[k].y, d, spread_at(d, sec[k].v), volume, &sp);
        add_splat(s, &sp);
    }
}

/* With splashes an impact's outcome depends on the water before it, so
 * impacts go one after another on one thread: the same bits for any
 * thread count and any cut of the work. */
static soak_status apply_splashing(soak_drops_state *s, size_t n)
{
    soak_splash_drop *sec = malloc(SOAK_SPLASH_MAX_FINGERS * sizeof *sec);
    if (!sec) return SOAK_ERR_NOMEM;
    for (size_t k = 0; k < n; ++k) splash_impact(s, &s->pending[k], sec);
    free(sec);
    return SOAK_OK;
}

static soak_status apply_impacts(soak_drops_state *s, size_t n, const soak_bake_exec *exec)
{
    if (n == 0) return SOAK_OK;
    if (s->p.splash) {
        soak_status st = apply_splashing(s, n);
        if (st != SOAK_OK) return st;
        memmove(s->pending, s->pending + n, (s->n_pending - n) * sizeof *s->pending);
        s->n_pending -= n;
        s->applied += n;
        return SOAK_OK;
    }
    if (n > s->splat_cap) {
        splat *v = realloc(s->splats, n * sizeof *v);
        if (!v) return SOAK_ERR_NOMEM;
        s->splats = v, s->splat_cap = n;
    }
    for (size_t k = 0; k < n; ++k) make_splat(s, &s->pending[k], 1.0, &s->splats[k]);
    soak_bake_exec quiet = {exec ? exec->threads : 0, NULL, NULL};
    apply_ctx a = {s, n};
    soak_status st = soak_parallel_rows(s->height, &quiet, apply_row, &a, 0, 1);
    if (st != SOAK_OK) return st;
    memmove(s->pending, s->pending + n, (s->n_pending - n) * sizeof *s->pending);
    s->n_pending -= n;
    s->applied += n;
    return SOAK_OK;
}

static void reset(soak_drops_state *s)
{
    memset(s->depth, 0, sizeof(double) * (size_t)s->width * s->height);
    free(s->pending);
    s->pending = NULL;
    s->n_pending = s->applied = s->splashed = 0;
    s->next_slab = 0;
    s->time = 0;
}

/* Generates slabs [next_slab, last] and queues their impacts. */
static soak_status generate(soak_drops_state *s, long last)
{
    soak_drop_impact *fresh = NULL;
    size_t n = 0;
    soak_status st = soak_drops_impacts(&s->p, s->exposure.pixels ? &s->exposure : NULL, s->width, s->height,
                                        s->next_slab, last + 1, &fresh, &n);
    if (st != SOAK_OK) return st;
    soak_drop_impact *v = realloc(s->pending, (s->n_pending + n + 1) * sizeof *v);
    if (!v) {
        free(fresh);
        return SOAK_ERR_NOMEM;
    }
    if (n) memcpy(v + s->n_pending, fresh, n * sizeof *v);
    free(fresh);
    s->pending = v, s->n_pending += n, s->next_slab = last + 1;
    return SOAK_OK;
}

#define CATCH_UP_SLABS 64 /* slabs per step of a long replay (progress) */

/* Applies every impact with t < target, generating the slabs up to the one
 * holding target a few at a time (a chunk of a farm job replays the rain
 * from t = 0 with progress). The order of additions to every texel is the
 * impacts' time order however the work is cut. */
static soak_status advance(soak_drops_state *s, double target, const soak_bake_exec *exec)
{
    if (target < s->time) reset(s);
    long last = (long)floor(target / SOAK_DROPS_SLAB);
    soak_status st = SOAK_OK;
    do {
        long upto = last - s->next_slab >= CATCH_UP_SLABS ? s->next_slab + CATCH_UP_SLABS - 1 : last;
        if (upto >= s->next_slab) st = generate(s, upto);
        double until = upto < last ? (upto + 1) * SOAK_DROPS_SLAB : target;
        size_t due = 0;
        while (st == SOAK_OK && due < s->n_pending && s->pending[due].t < until) ++due;
        if (st == SOAK_OK) st = apply_impacts(s, due, exec);
        if (st == SOAK_OK && exec && exec->progress && target > 0)
            exec->progress(exec->progress_user, 0.9 * fmin(1.0, until / target));
    } while (st == SOAK_OK && s->next_slab <= last);
    if (st == SOAK_OK) s->time = target;
    return st;
}

soak_status soak_drops_create(const soak_drops_params *p, const soak_image *exposure, int width, int height,
                              soak_drops_state **out)
{
    if (!p || !out) return SOAK_ERR_NULL;
    *out = NULL;
    soak_drop_impact *probe = NULL;
    size_t n = 0;
    soak_status st = soak_drops_impacts(p, exposure, width, height, 0, 0, &probe, &n);
    if (st != SOAK_OK) return st;
    soak_drops_state *s = calloc(1, sizeof *s);
    if (!s) return SOAK_ERR_NOMEM;
    s->p = *p, s->width = width, s->height = height;
    s->depth = calloc((size_t)width * height, sizeof(double));
    st = s->depth ? SOAK_OK : SOAK_ERR_NOMEM;
    if (st == SOAK_OK && exposure) st = soak_image_alloc(&s->exposure, width, height, 1);
    if (st == SOAK_OK && exposure)
        memcpy(s->exposure.pixels, exposure->pixels, sizeof(float) * (size_t)width * height);
    if (st != SOAK_OK) {
        soak_drops_destroy(s);
        return st;
    }
    *out = s;
    return SOAK_OK;
}

void soak_drops_destroy(soak_drops_state *s)
{
    if (!s) return;
    soak_image_free(&s->exposure);
    free(s->depth), free(s->pending), free(s->splats), free(s);
}

size_t soak_drops_applied(const soak_drops_state *s)
{
    return s ? s->applied : 0;
}

size_t soak_drops_splashed(const soak_drops_state *s)
{
    return s ? s->splashed : 0;
}

static void wet_map(const soak_drops_state *s, float *out)
{
    size_t n = (size_t)s->width * s->height;
    for (size_t i = 0; i < n; ++i) out[i] = (float)fmin(1.0, s->depth[i] / s->p.capacity_m);
}

/* After the rain: the map at its end times the drying bake's schedule. */
static soak_status dried(const soak_drops_state *s, double t, const soak_bake_exec *exec, soak_image *out)
{
    soak_drying_params dp;
    soak_drying_defaults(&dp);
    dp.threshold = 0;
    dp.t_fill = s->p.t_fill;
    dp.seed = s->p.seed;
    dp.time = fmin((t - s->p.duration) / s->p.dry_time, SOAK_DRYING_MAX_TIME);
    soak_image factor = {0, 0, 0, NULL};
    soak_status st = soak_bake_drying(out, 0, 0, &dp, exec, &factor);
    if (st != SOAK_OK) return st;
    size_t n = (size_t)s->width * s->height;
    for (size_t i = 0; i < n; ++i) out->pixels[i] *= factor.pixels[i];
    soak_image_free(&factor);
    return SOAK_OK;
}

soak_status soak_drops_frame(soak_drops_state *s, double t, const soak_bake_exec *exec, soak_image *out)
{
    if (!s || !out) return SOAK_ERR_NULL;
    if (!soak_in_range(t, 0, SOAK_DROPS_MAX_TIME) || soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;
    soak_status st = advance(s, fmin(t, s->p.duration), exec);
    if (st == SOAK_OK) st = soak_image_alloc(out, s->width, s->height, 1);
    if (st != SOAK_OK) return st;
    wet_map(s, out->pixels);
    if (t > s->p.duration) st = dried(s, t, exec, out);
    if (exec && exec->progress) exec->progress(exec->progress_user, 1);
    if (st != SOAK_OK) soak_image_free(out);
    return st;
}
