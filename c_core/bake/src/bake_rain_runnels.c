/* Runnels: a falling film too thin to wet its face gathers into rivulets
 * (bake_rain_runnels.h; model in soak/bake_rain.h step 3c). */
#include "bake_rain_runnels.h"

#include <math.h>
#include <stdlib.h>

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

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The spacing: soak_rain_runnel_spacing of the median broken film (0: none). */
static soak_status median_spacing(const rain_surface *s, soak_vec3 up, double theta, const double *film,
                                  double *spacing, int *broken)
{
    size_t n = (size_t)s->w * s->h, m = 0;
    double *v = malloc((n ? n : 1) * sizeof *v);
    if (!v) return SOAK_ERR_NOMEM;
    for (size_t i = 0; i < n; ++i) {
        soak_vec3 dir;
        double sn = s->tri[i] >= 0 && film[i] > 0.0 ? across(s, i, up, &dir) : 0.0;
        if (sn > 0.0 && flux_of(film[i], sn) < soak_rain_runnel_min_flux(theta, sn))
            v[m++] = soak_rain_runnel_spacing(film[i], sn);
    }
    qsort(v, m, sizeof *v, by_value);
    *spacing = m ? v[m / 2] : 0.0;
    *broken = (int)(m < 2147483647u ? m : 2147483647u);
    free(v);
    return SOAK_OK;
}

/* Texel i's mean depth of the rivulets about it. */
static double runnel_depth(const rain_surface *s, const soak_rain_flow_grid *g, size_t i, soak_vec3 dir, double sn,
                           double theta, double spacing, double phase, double h)
{
    double a = soak_rain_runnel_half_width(flux_of(h, sn) * spacing, theta, sn);
    if (!(2.0 * a < spacing)) return h; /* the rivulets would touch: the film holds */
    double pos = soak_v3_dot(soak_rain_vget(s->pos, i), dir), w = soak_rain_flow_width(g, i);
    double k = floor((pos - phase * spacing) / spacing + 0.5), depth = 0.0;
    for (int dk = -1; dk <= 1; ++dk) {
        double c = (k + dk + phase) * spacing;
        depth += soak_rain_runnel_mean_depth(a, theta, pos - 0.5 * w - c, pos + 0.5 * w - c);
    }
    return depth;
}

soak_status soak_rain_runnels(const rain_surface *s, const soak_rain_flow_grid *g, soak_vec3 up, double theta,
                              uint64_t seed, double *film, soak_rain_runnel_stats *stats)
{
    if (!s || !g || !film || !stats) return SOAK_ERR_NULL;
    stats->broken = 0, stats->spacing = 0.0;
    if (!(theta > 0.0 && theta <= 0.5 * SOAK_PI)) return theta == 0.0 ? SOAK_OK : SOAK_ERR_ARG;
    up = soak_v3_norm(up);
    double spacing;
    soak_status st = median_spacing(s, up, theta, film, &spacing, &stats->broken);
    if (st != SOAK_OK || !(spacing > 0.0)) return st;
    stats->spacing = spacing;
    soak_rng rng;
    soak_rng_seed(&rng, seed, RUNNEL_STREAM);
    double phase = soak_rng_uniform(&rng);
    for (size_t i = 0, n = (size_t)s->w * s->h; i < n; ++i) {
        soak_vec3 dir;
        double sn = s->tri[i] >= 0 && film[i] > 0.0 ? across(s, i, up, &dir) : 0.0;
        if (!(sn > 0.0) || !(flux_of(film[i], sn) < soak_rain_runnel_min_flux(theta, sn))) continue;
        film[i] = runnel_depth(s, g, i, dir, sn, theta, spacing, phase, film[i]);
    }
    return SOAK_OK;
}
