/* Thin-sheet transmittance (soak/sheet.h). */
#include "soak/sheet.h"

#include <math.h>

#include "soak/fresnel.h"

#define KM_X_MAX 700.0 /* cosh overflows beyond; T is 0 to double precision */

soak_status soak_km_slab(double K, double S, double d, double *R, double *T)
{
    if (!R || !T) return SOAK_ERR_NULL;
    if (!soak_in_range(K, 0.0, 1e12) || !soak_in_range(S, 0.0, 1e12) || !soak_in_range(d, 0.0, 1e12))
        return SOAK_ERR_ARG;
    double x = d * sqrt(K * K + 2.0 * K * S);
    if (x > KM_X_MAX || (S + K) * d > 1e300) {
        /* thick limit: T = 0, R = the semi-infinite a - b = (S + K - sqrt(K^2 + 2KS)) / S */
        *T = 0.0;
        *R = S > 0.0 ? S / (S + K + sqrt(K * K + 2.0 * K * S)) : 0.0;
        return SOAK_OK;
    }
    double sinhc = x > 1e-8 ? sinh(x) / x : 1.0;
    *T = 1.0 / ((S + K) * d * sinhc + cosh(x));
    *R = S * d * sinhc * *T;
    return SOAK_OK;
}

soak_status soak_km_transmittance(double K, double S, double d, double *T)
{
    double R = 0.0;
    return soak_km_slab(K, S, d, &R, T);
}

/* The two faces added to the slab (sheet.h). 1 - r_i (R + T) > 0, so the
 * denominator (1 - r_i R - r_i T)(1 - r_i R + r_i T) never vanishes. */
static double with_faces(double R, double T, double r_e, double r_i)
{
    double a = 1.0 - r_i * R, b = r_i * T;
    return (1.0 - r_e) * (1.0 - r_i) * T / ((a - b) * (a + b));
}

soak_status soak_sheet_transmittance(const soak_wet_params *w, double thickness_m, double ior, soak_rgb *T)
{
    if (!w || !T) return SOAK_ERR_NULL;
    if (!soak_in_range(thickness_m, 0.0, 1e3) || !soak_in_range(w->mean_cosine, -1.0, 1.0) ||
        !soak_in_range(ior, 1.0, 3.0))
        return SOAK_ERR_ARG;
    double r_e = 0.0, r_i = 0.0;
    soak_status st = soak_fresnel_dielectric_avg(ior, &r_e);
    if (st == SOAK_OK) st = soak_fresnel_dielectric_avg(1.0 / ior, &r_i);
    if (st != SOAK_OK) return st;
    soak_rgb out = {1.0, 1.0, 1.0};
    for (int c = 0; thickness_m > 0.0 && c < 3; ++c) {
        double sa = soak_rgb_at(w->sigma_a_per_m, c), ss = soak_rgb_at(w->sigma_s_per_m, c);
        if (!soak_in_range(sa, 0.0, 1e12) || !soak_in_range(ss, 0.0, 1e12)) return SOAK_ERR_ARG;
        double K = 2.0 * sa, S = 0.75 * ss * (1.0 - w->mean_cosine) - 0.25 * sa;
        double r = 0.0, t = 1.0;
        st = soak_km_slab(K, S > 0.0 ? S : 0.0, thickness_m, &r, &t);
        if (st != SOAK_OK) return st;
        soak_rgb_set(&out, c, with_faces(r, t, r_e, r_i));
    }
    *T = out;
    return SOAK_OK;
}
