/* The wetness function for any base colour (soak/base_colour.h). */
#include "soak/base_colour.h"

#include <math.h>

#include "soak/fresnel.h"

#define CONDUCTOR_F0_MAX 0.98 /* keeps n <= 50 and k <= 100 (preset limits) */
#define CONDUCTOR_N_MAX 50.0

/* Gulbrandsen 2014, Eq. 3-4 and their inverse: (n, k) <-> (r, g). */
static double gulbrandsen_n_min(double r) { return (1.0 - r) / (1.0 + r); }
static double gulbrandsen_n_max(double r) { return (1.0 + sqrt(r)) / (1.0 - sqrt(r)); }

static soak_status edge_tint(double n, double k, double *g)
{
    double r = 0.0;
    soak_status st = soak_fresnel_r0(n, k, &r);
    if (st != SOAK_OK) return st;
    if (r > CONDUCTOR_F0_MAX) r = CONDUCTOR_F0_MAX;
    double lo = gulbrandsen_n_min(r), hi = gulbrandsen_n_max(r);
    double t = (hi - n) / (hi - lo);
    *g = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return SOAK_OK;
}

static void conductor_from_f0(double r, double g, double *n, double *k)
{
    if (r > CONDUCTOR_F0_MAX) r = CONDUCTOR_F0_MAX;
    double nn = g * gulbrandsen_n_min(r) + (1.0 - g) * gulbrandsen_n_max(r);
    if (nn > CONDUCTOR_N_MAX) nn = CONDUCTOR_N_MAX;
    if (nn < SOAK_ETA_MIN) nn = SOAK_ETA_MIN;
    double k2 = (r * (nn + 1.0) * (nn + 1.0) - (nn - 1.0) * (nn - 1.0)) / (1.0 - r);
    *n = nn;
    *k = k2 > 0.0 ? sqrt(k2) : 0.0;
}

soak_status soak_wet_params_for_base(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_input *in,
                                     soak_rgb dry, soak_wet_params *out)
{
    if (!preset || !liquid || !in || !out) return SOAK_ERR_NULL;
    for (int c = 0; c < 3; ++c)
        if (!soak_in_range(soak_rgb_at(dry, c), 0.0, 1.0)) return SOAK_ERR_ARG;
    soak_preset p = *preset;
    p.albedo = dry;
    if (p.kind == SOAK_KIND_CONDUCTOR) {
        for (int c = 0; c < 3; ++c) {
            double g = 0.0, n = 0.0, k = 0.0;
            soak_status st = edge_tint(soak_rgb_at(preset->ior_n, c), soak_rgb_at(preset->ior_k, c), &g);
            if (st != SOAK_OK) return st;
            conductor_from_f0(soak_rgb_at(dry, c), g, &n, &k);
            soak_rgb_set(&p.ior_n, c, n);
            soak_rgb_set(&p.ior_k, c, k);
        }
    } else {
        soak_status st = soak_preset_derive(&p);
        if (st != SOAK_OK) return st;
    }
    return soak_wetness_eval(&p, liquid, in, out);
}
