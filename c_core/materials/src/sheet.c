/* Thin-sheet transmittance (soak/sheet.h). */
#include "soak/sheet.h"

#include <math.h>

#define KM_X_MAX 700.0 /* cosh overflows beyond; T is 0 to double precision */

soak_status soak_km_transmittance(double K, double S, double d, double *T)
{
    if (!T) return SOAK_ERR_NULL;
    if (!soak_in_range(K, 0.0, 1e12) || !soak_in_range(S, 0.0, 1e12) || !soak_in_range(d, 0.0, 1e12))
        return SOAK_ERR_ARG;
    double x = d * sqrt(K * K + 2.0 * K * S);
    if (x > KM_X_MAX || (S + K) * d > 1e300) {
        *T = 0.0;
        return SOAK_OK;
    }
    double sinhc = x > 1e-8 ? sinh(x) / x : 1.0;
    *T = 1.0 / ((S + K) * d * sinhc + cosh(x));
    return SOAK_OK;
}

soak_status soak_sheet_transmittance(const soak_wet_params *w, double thickness_mm, soak_rgb *T)
{
    if (!w || !T) return SOAK_ERR_NULL;
    if (!soak_in_range(thickness_mm, 0.0, 1e6) || !soak_in_range(w->mean_cosine, -1.0, 1.0)) return SOAK_ERR_ARG;
    soak_rgb out;
    for (int c = 0; c < 3; ++c) {
        double sa = soak_rgb_at(w->sigma_a, c), ss = soak_rgb_at(w->sigma_s, c);
        if (!soak_in_range(sa, 0.0, 1e12) || !soak_in_range(ss, 0.0, 1e12)) return SOAK_ERR_ARG;
        double K = 2.0 * sa, S = 0.75 * ss * (1.0 - w->mean_cosine) - 0.25 * sa;
        double t = 1.0;
        soak_status st = soak_km_transmittance(K, S > 0.0 ? S : 0.0, thickness_mm, &t);
        if (st != SOAK_OK) return st;
        soak_rgb_set(&out, c, t);
    }
    *T = out;
    return SOAK_OK;
}
