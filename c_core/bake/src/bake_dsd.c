/* Raindrop physics of the drops and ripples bakes: Marshall-Palmer sizes,
 * Atlas et al. terminal velocities, their impact flux and Clanet et al.'s
 * spread on impact (sources and constants in soak/bake_drops.h). */
#include <math.h>

#include "soak/bake_drops.h"
#include "soak/status.h"

#define ATLAS_A 9.65  /* m/s */
#define ATLAS_B 10.3  /* m/s */
#define ATLAS_C 0.6   /* 1/mm */
#define CLANET_K 0.9

static int rate_ok(double r)
{
    return soak_in_range(r, 0, SOAK_DROP_RATE_MAX);
}

double soak_mp_lambda(double rate_mm_h)
{
    if (!(rate_mm_h > 0) || !rate_ok(rate_mm_h)) return 0;
    return 4.1 * pow(rate_mm_h, -0.21);
}

double soak_mp_density(double d_mm, double rate_mm_h)
{
    double lam = soak_mp_lambda(rate_mm_h);
    if (lam <= 0 || !soak_in_range(d_mm, 0, SOAK_DROP_D_MAX_MM)) return 0;
    return SOAK_DROP_N0 * exp(-lam * d_mm);
}

double soak_drop_velocity(double d_mm)
{
    if (!soak_in_range(d_mm, 0, 1e3)) return 0;
    double v = ATLAS_A - ATLAS_B * exp(-ATLAS_C * d_mm);
    return v > 0 ? v : 0;
}

/* Smallest diameter with v > 0: ln(B / A) / C. */
static double landing_diameter(void)
{
    return log(ATLAS_B / ATLAS_A) / ATLAS_C;
}

double soak_drop_flux(double rate_mm_h, double d_lo_mm, double d_hi_mm)
{
    double lam = soak_mp_lambda(rate_mm_h);
    if (lam <= 0 || !soak_in_range(d_lo_mm, 0, 1e3) || !soak_in_range(d_hi_mm, 0, 1e3)) return 0;
    double a = fmax(d_lo_mm, landing_diameter()), b = fmin(d_hi_mm, SOAK_DROP_D_MAX_MM);
    if (!(b > a)) return 0;
    double l2 = lam + ATLAS_C;
    /* int_a^b e^{-k D} dD = (e^{-k a} - e^{-k b}) / k, for k = lam and lam + C */
    double i1 = (exp(-lam * a) - exp(-lam * b)) / lam;
    double i2 = (exp(-l2 * a) - exp(-l2 * b)) / l2;
    double n = SOAK_DROP_N0 * (ATLAS_A * i1 - ATLAS_B * i2);
    return n > 0 ? n : 0;
}

double soak_drop_spread_factor(double d_mm)
{
    double v = soak_drop_velocity(d_mm);
    if (!(d_mm > 0) || v <= 0) return 1;
    double we = SOAK_WATER_RHO * v * v * (d_mm * 1e-3) / SOAK_WATER_SIGMA;
    double f = CLANET_K * pow(we, 0.25);
    return f > 1 ? f : 1;
}

double soak_drop_sample(double rate_mm_h, double d_lo_mm, soak_uniform_fn u, void *ctx)
{
    double lam = soak_mp_lambda(rate_mm_h);
    double a = fmax(soak_in_range(d_lo_mm, 0, SOAK_DROP_D_MAX_MM) ? d_lo_mm : 0, landing_diameter());
    if (lam <= 0 || !u || a >= SOAK_DROP_D_MAX_MM) return a;
    double span = -expm1(-lam * (SOAK_DROP_D_MAX_MM - a));
    /* acceptance v(D) / A >= v(a) / A > 0; bounded loop guards against a
     * broken generator, never reached with a uniform one */
    for (int k = 0; k < 100000; ++k) {
        double d = a - log1p(-u(ctx) * span) / lam;
        if (d > SOAK_DROP_D_MAX_MM) d = SOAK_DROP_D_MAX_MM;
        if (u(ctx) * ATLAS_A < soak_drop_velocity(d)) return d;
    }
    return a;
}
