/* POV-Ray 3.7's subsurface conventions (soak/povray_subsurface.h). */
#include "soak/povray_subsurface.h"

#include <math.h>

#include "soak/units.h"

#define RD_NODES 100 /* POV-Ray tabulates alpha' at Rd = i / RD_NODES */
#define BISECT_STEPS 60

static double pov_fdr(double eta)
{
    double x = 1.0 - 1.0 / eta;
    return (x + 3.0 * pow(x, 4.5)) / 4.0;
}

static double rd_of_alpha(double alpha_prime, double A)
{
    double s = sqrt(3.0 * (1.0 - alpha_prime));
    return 0.5 * alpha_prime * (1.0 + exp(-4.0 / 3.0 * A * s)) * exp(-s);
}

/* Rd is increasing in alpha' from 0 (alpha' = 0) to 1 (alpha' = 1). */
static double alpha_of_rd_exact(double rd, double A)
{
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < BISECT_STEPS; ++i) {
        double mid = 0.5 * (lo + hi);
        if (rd_of_alpha(mid, A) < rd) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

soak_status soak_povray_alpha_prime(double rd, double eta, double *alpha_prime)
{
    if (!alpha_prime) return SOAK_ERR_NULL;
    if (!soak_in_range(rd, 0.0, 1.0) || !soak_in_range(eta, 1.0, 10.0)) return SOAK_ERR_ARG;
    double fdr = pov_fdr(eta);
    double A = (1.0 + fdr) / (1.0 - fdr);
    int i = (int)floor(rd * RD_NODES);
    if (i >= RD_NODES) i = RD_NODES - 1;
    double a0 = alpha_of_rd_exact((double)i / RD_NODES, A);
    double a1 = alpha_of_rd_exact((double)(i + 1) / RD_NODES, A);
    double f = rd * RD_NODES - i;
    *alpha_prime = (1.0 - f) * a0 + f * a1;
    return SOAK_OK;
}

static double clamp_translucency(double t)
{
    if (!(t >= SOAK_POVRAY_TRANSLUCENCY_MIN)) return SOAK_POVRAY_TRANSLUCENCY_MIN;
    return t > SOAK_POVRAY_TRANSLUCENCY_MAX ? SOAK_POVRAY_TRANSLUCENCY_MAX : t;
}

soak_status soak_povray_translucency(double rd, double eta, double sigma_tr_per_m, double *translucency_mm)
{
    if (!translucency_mm) return SOAK_ERR_NULL;
    if (!soak_in_range(sigma_tr_per_m, 0.0, 1e15)) return SOAK_ERR_ARG;
    double ap = 0.0;
    soak_status st = soak_povray_alpha_prime(rd, eta, &ap);
    if (st != SOAK_OK) return st;
    double denom = ap * sigma_tr_per_m;
    /* alpha' -> 0 or sigma_tr -> 0: unbounded; alpha' -> 1: T -> 0 (POV-Ray
     * then has no absorption and diffuses without limit whatever T is) */
    *translucency_mm =
        denom > 0.0 ? clamp_translucency(soak_mm_from_m(sqrt(3.0 * (1.0 - ap)) / denom)) : SOAK_POVRAY_TRANSLUCENCY_MAX;
    return SOAK_OK;
}
