/* The base's own specular under the liquid; see soak/wet_specular.h. */
#include "soak/wet_specular.h"

#include <math.h>

#include "soak/fresnel.h"

soak_status soak_wet_specular_under(double eta_base, double n_liquid, double two_pass, double *R)
{
    if (!R) return SOAK_ERR_NULL;
    if (!soak_in_range(eta_base, 1.0, 3.0) || !soak_in_range(n_liquid, 1.0, 3.0) || !soak_in_range(two_pass, 0.0, 1.0))
        return SOAK_ERR_ARG;
    double r12 = 0.0, r23 = 0.0;
    soak_status st = soak_fresnel_r0(n_liquid, 0.0, &r12);
    if (st == SOAK_OK) st = soak_fresnel_r0(eta_base / n_liquid, 0.0, &r23);
    if (st != SOAK_OK) return st;
    double t12 = 1.0 - r12;
    /* r12 r23 <= 0.25 * 0.25: the denominator stays >= 15/16 */
    *R = t12 * t12 * r23 * two_pass / (1.0 - r12 * r23 * two_pass);
    return SOAK_OK;
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

double soak_wet_grain_coat_weight(const soak_wet_params *w)
{
    if (!w || !soak_in_range(w->specular_weight, 0.0, 1.0) || !soak_in_range(w->water_specular_weight, 0.0, 1.0))
        return 0.0;
    double open = 1.0 - w->water_specular_weight; /* the dry part's share of the area outside the film */
    if (open < 1e-9) return w->specular_weight;   /* no dry part: the weight is never drawn */
    return fmin(1.0, w->specular_weight / open);
}

soak_status soak_wet_specular_eval(const soak_preset *p, const soak_liquid *l, const soak_wet_params *w,
                                   soak_wet_specular *out)
{
    if (!p || !l || !w || !out) return SOAK_ERR_NULL;
    if (!soak_in_range(w->film_coverage, 0.0, 1.0) || !soak_in_range(w->ggx_alpha, 1e-4, 1.0) ||
        !soak_in_range(w->film_thickness_m, 0.0, SOAK_WET_FILM_MAX_M) || !soak_in_range(l->ior, 1.0, 3.0))
        return SOAK_ERR_ARG;
    const double c = w->film_coverage;
    soak_wet_specular o = {1.0, soak_wet_interface_area(w), w->ggx_alpha};
    if (p->kind == SOAK_KIND_CONDUCTOR) {
        o.ggx_alpha = clamp01(w->ggx_alpha * (1.0 + c * (l->ior - 1.0)));
    } else if (c > 0.0) {
        if (!soak_in_range(p->ior, 1.0, 3.0)) return SOAK_ERR_ARG;
        double dry = 0.0, sum = 0.0;
        soak_status st = soak_fresnel_r0(p->ior, 0.0, &dry);
        for (int i = 0; st == SOAK_OK && i < 3; ++i) {
            double a = soak_rgb_at(w->film_absorption_per_m, i);
            if (!soak_in_range(a, 0.0, 1e9)) return SOAK_ERR_ARG;
            double under = 0.0;
            st = soak_wet_specular_under(p->ior, l->ior, exp(-2.0 * a * w->film_thickness_m), &under);
            sum += under;
        }
        if (st != SOAK_OK) return st;
        /* dry = 0 only at n = 1 (no base interface): nothing to scale */
        double ratio = dry > 0.0 ? (sum / 3.0) / dry : 1.0;
        o.base_factor = clamp01((1.0 - c) + c * ratio);
    }
    if (!soak_is_finite(o.base_factor) || !soak_is_finite(o.interface_area) || !soak_is_finite(o.ggx_alpha))
        return SOAK_ERR_NUMERIC;
    *out = o;
    return SOAK_OK;
}
