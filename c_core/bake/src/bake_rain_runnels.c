/* Runnels: a falling film too thin to wet its face gathers into rivulets
 * (bake_rain_runnels.h; model in soak/bake_rain.h step 3c). */
#include "bake_rain_runnels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "soak/bake_drops.h"
#include "soak/rng.h"

#define RUNNEL_STREAM 0x52554e4e454cull /* "RUNNEL" */
#define NU (SOAK_RAIN_WATER_VISCOSITY / SOAK_RAIN_WATER_DENSITY)

double soak_rain_runnel_min_flux(double theta, double sin_slope)
{
    if (!(theta > 0.0 && theta <= SOAK_PI)) return 0.0;
    if (!(sin_slope > 0.0)) return INFINITY;
    double g = SOAK_RAIN_GRAVITY * (sin_slope < 1.0 ? sin_slope : 1.0), rho = SOAK_RAIN_WATER_DENSITY;
    double gamma =
        1.69 * pow(SOAK_RAIN_WATER_VISCOSITY * rho / g, 0.2) * pow(SOAK_WATER_SIGMA * (1.0 - cos(theta)), 0.6);
    return gamma / rho;
}

double soak_rain_runnel_spacing(double h, double sin_slope)
{
    if (!(h > 0.0 && h < 1.0) || !(sin_slope > 0.0)) return 0.0;
    double lc2 = SOAK_WATER_SIGMA / (SOAK_RAIN_WATER_DENSITY * SOAK_RAIN_GRAVITY);
    return 14.0 * cbrt(h * lc2 / (sin_slope < 1.0 ? sin_slope : 1.0));
}

double soak_rain_runnel_half_width(double flux, double theta, double sin_slope)
{
    if (!(flux > 0.0 && flux < 1.0) || !(theta > 0.0 && theta <= SOAK_PI) || !(sin_slope > 0.0)) return 0.0;
    double g = SOAK_RAIN_GRAVITY * (sin_slope < 1.0 ? sin_slope : 1.0);
    return pow(105.0 * NU * flux / (4.0 * g * theta * theta * theta), 0.25);
}

double soak_rain_runnel_mean_depth(double a, double theta, double y0, double y1)
{
    if (!(a > 0.0) || !(y1 > y0)) return 0.0;
    double lo = y0 > -a ? y0 : -a, hi = y1 < a ? y1 : a;
    if (!(hi > lo)) return 0.0;
    double area = theta / (2.0 * a) * (a * a * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3.0);
    return area / (y1 - y0);
}

/* Slope sine and the unit direction across the slope of texel i; 0 where
 * the texel is level. */
static double across(const rain_surface *s, size_t i, soak_vec3 up, soak_vec3 *dir)
{
    soak_vec3 n = soak_rain_fget(s->nrm, i), c = soak_v3_cross(up, n);
    double len = soak_v3_len(c);
    if (!(len > SOAK_RAIN_LEVEL_TOL)) return 0.0;
    *dir = soak_v3_scale(c, 1.0 / len);
    return len < 1.0 ? len : 1.0;
}

static double flux_of(double h, double sin_slope) { return SOAK_RAIN_GRAVITY * sin_slope * h * h * h / (3.0 * NU); }

/* -dn_s/ds at texel i (>= 0: concave across the slope, a groove): the
 * least-squares slope of the normal's across component against the
 * across position over its 3D-adjacent neighbours. */
static float concavity(const rain_surface *s, size_t i, soak_vec3 dir)
{
    static const int dx[8] = SOAK_RAIN_DX_INIT, dy[8] = SOAK_RAIN_DY_INIT;
    int x = (int)(i % (size_t)s->w), y = (int)(i / (size_t)s->w);
    soak_vec3 p = soak_rain_vget(s->pos, i), n = soak_rain_fget(s->nrm, i);
    double sxx = 0.0, sxy = 0.0;
    for (int d = 0; d < 8; ++d) {
        if (!(s->adj[i] >> d & 1)) continue;
        size_t j = (size_t)(y + dy[d]) * s->w + (size_t)(x + dx[d]);
        double ds = soak_v3_dot(soak_v3_sub(soak_rain_vget(s->pos, j), p), dir);
        double dn = soak_v3_dot(soak_v3_sub(soak_rain_fget(s->nrm, j), n), dir);
        sxx += ds * ds, sxy += ds * dn;
    }
    double k = sxx > 0.0 ? -sxy / sxx : 0.0;
    return k > 0.0 && k < 1e30 ? (float)k : 0.0f;
}

void soak_rain_runnel_field_free(soak_rain_runnel_field *r)
{
    if (!r) return;
    free(r->sine);
    free(r->across);
    free(r->concave);
    memset(r, 0, sizeof *r);
}

soak_status soak_rain_runnel_field_make(const rain_surface *s, soak_vec3 up, double theta, soak_rain_runnel_field *r)
{
    if (!s || !r) return SOAK_ERR_NULL;
    memset(r, 0, sizeof *r);
    if (!(theta > 0.0 && theta <= 0.5 * SOAK_PI)) return SOAK_ERR_ARG;
    size_t n = (size_t)s->w * s->h;
    r->w = s->w, r->h = s->h, r->theta = theta;
    r->sine = malloc(n * sizeof *r->sine), r->across = malloc(n * sizeof *r->across);
    r->concave = malloc(n * sizeof *r->concave);
    if (!r->sine || !r->across || !r->concave) {
        soak_rain_runnel_field_free(r);
        return SOAK_ERR_NOMEM;
    }
    up = soak_v3_norm(up);
    for (size_t i = 0; i < n; ++i) {
        soak_vec3 dir = soak_v3(0, 0, 0);
        double sn = s->tri[i] >= 0 ? across(s, i, up, &dir) : 0.0;
        r->sine[i] = (float)sn;
        r->across[i] = sn > 0.0 ? soak_v3_dot(soak_rain_vget(s->pos, i), dir) : 0.0;
        r->concave[i] = sn > 0.0 ? concavity(s, i, dir) : 0.0f;
    }
    return SOAK_OK;
}

static int broken(const soak_rain_runnel_field *r, size_t i, double h)
{
    double sn = r->sine[i];
    return sn > 0.0 && h > 0.0 && flux_of(h, sn) < soak_rain_runnel_min_flux(r->theta, sn);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The spacing: soak_rain_runnel_spacing of the median broken film (0: none). */
static soak_status median_spacing(const soak_rain_runnel_field *r, const double *film, double *spacing, int *count)
{
    size_t n = (size_t)r->w * r->h, m = 0;
    double *v = malloc((n ? n : 1) * sizeof *v);
    if (!v) return SOAK_ERR_NOMEM;
    for (size_t i = 0; i < n; ++i)
        if (broken(r, i, film[i])) v[m++] = soak_rain_runnel_spacing(film[i], r->sine[i]);
    qsort(v, m, sizeof *v, by_value);
    *spacing = m ? v[m / 2] : 0.0;
    *count = (int)(m < 2147483647u ? m : 2147483647u);
    free(v);
    return SOAK_OK;
}

/* The phase that puts rivulets on the grooves: arg of sum over broken
 * texels of concave e^(2 pi i s / spacing), over 2 pi; -1 where no broken
 * texel is concave enough to count (the normal turning less than 1e-3 rad
 * over a spacing). */
static double relief_phase(const soak_rain_runnel_field *r, const double *film)
{
    double re = 0.0, im = 0.0, total = 0.0, floor_k = 1e-3 / r->spacing;
    for (size_t i = 0, n = (size_t)r->w * r->h; i < n; ++i) {
        if (!(r->concave[i] > floor_k) || !broken(r, i, film[i])) continue;
        double a = 2.0 * SOAK_PI * r->across[i] / r->spacing;
        re += r->concave[i] * cos(a), im += r->concave[i] * sin(a), total += r->concave[i];
    }
    if (!(total > 0.0) || !(hypot(re, im) > 1e-9 * total)) return -1.0;
    double phase = atan2(im, re) / (2.0 * SOAK_PI);
    return phase < 0.0 ? phase + 1.0 : phase;
}

soak_status soak_rain_runnel_place(soak_rain_runnel_field *r, const double *film, uint64_t seed,
                                   soak_rain_runnel_stats *stats)
{
    if (!r || !film || !stats) return SOAK_ERR_NULL;
    stats->broken = 0, stats->spacing = 0.0, stats->from_relief = 0;
    r->spacing = 0.0, r->phase = 0.0;
    if (!r->sine) return SOAK_OK;
    soak_status st = median_spacing(r, film, &r->spacing, &stats->broken);
    if (st != SOAK_OK || !(r->spacing > 0.0)) return st;
    stats->spacing = r->spacing;
    r->phase = relief_phase(r, film);
    stats->from_relief = r->phase >= 0.0;
    if (r->phase < 0.0) {
        soak_rng rng;
        soak_rng_seed(&rng, seed, RUNNEL_STREAM);
        r->phase = soak_rng_uniform(&rng);
    }
    return SOAK_OK;
}

double soak_rain_runnel_texel(const soak_rain_runnel_field *r, const soak_rain_flow_grid *g, size_t i, double h)
{
    if (!r || !(r->spacing > 0.0) || !broken(r, i, h)) return h;
    double sn = r->sine[i], spacing = r->spacing;
    double a = soak_rain_runnel_half_width(flux_of(h, sn) * spacing, r->theta, sn);
    if (!(2.0 * a < spacing)) return h; /* the rivulets would touch: the film holds */
    double pos = r->across[i], w = soak_rain_flow_width(g, i);
    double k = floor((pos - r->phase * spacing) / spacing + 0.5), depth = 0.0;
    for (int dk = -1; dk <= 1; ++dk) {
        double c = (k + dk + r->phase) * spacing;
        depth += soak_rain_runnel_mean_depth(a, r->theta, pos - 0.5 * w - c, pos + 0.5 * w - c);
    }
    return depth;
}

soak_status soak_rain_runnels(const rain_surface *s, const soak_rain_flow_grid *g, soak_vec3 up, double theta,
                              uint64_t seed, double *film, soak_rain_runnel_stats *stats)
{
    if (!s || !g || !film || !stats) return SOAK_ERR_NULL;
    stats->broken = 0, stats->spacing = 0.0, stats->from_relief = 0;
    if (!(theta > 0.0 && theta <= 0.5 * SOAK_PI)) return theta == 0.0 ? SOAK_OK : SOAK_ERR_ARG;
    soak_rain_runnel_field r;
    soak_status st = soak_rain_runnel_field_make(s, up, theta, &r);
    if (st == SOAK_OK) st = soak_rain_runnel_place(&r, film, seed, stats);
    for (size_t i = 0, n = (size_t)s->w * s->h; i < n && st == SOAK_OK && r.spacing > 0.0; ++i)
        film[i] = soak_rain_runnel_texel(&r, g, i, film[i]);
    soak_rain_runnel_field_free(&r);
    return st;
}
