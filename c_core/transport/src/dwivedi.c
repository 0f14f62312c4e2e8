/* Dwivedi sampling; sources and formulas in soak/dwivedi.h. */
#include "soak/dwivedi.h"

#include <math.h>

/* Root x = 1/v0 in (0, 1) of a atanh(x) / x = 1 by Newton's method on
 * h(x) = atanh(x) - x / a, safeguarded by bisection: h < 0 below the root,
 * h > 0 above it (atanh(x)/x grows from 1 to infinity). */
static double inverse_v0(double a)
{
    double lo = 0.0, hi = 1.0;
    double x = a > 0.9 ? sqrt(3.0 * (1.0 - a)) : 1.0 - 2.0 * exp(-2.0 / a); /* diffusion / small-albedo limits */
    if (!(x > lo && x < hi)) x = 0.5;
    for (int it = 0; it < 100; ++it) {
        double h = atanh(x) - x / a;
        if (h < 0) lo = x;
        else hi = x;
        double step = h / (1.0 / ((1.0 - x) * (1.0 + x)) - 1.0 / a);
        double nx = x - step;
        if (!(nx > lo && nx < hi)) nx = 0.5 * (lo + hi);
        if (fabs(nx - x) <= 1e-14 * x) return nx;
        x = nx;
    }
    return x;
}

double soak_dwivedi_v0(double a)
{
    if (!(a >= 0.0 && a < 1.0)) return SOAK_DWIVEDI_V0_MAX;
    if (1.0 - a < 1e-15) return SOAK_DWIVEDI_V0_MAX;
    /* Below albedo 0.1 the root is 1 + 2 exp(-2/a) to double precision. */
    double v0 = a < 0.1 ? 1.0 + 2.0 * exp(-2.0 / a) : 1.0 / inverse_v0(a);
    return v0 < SOAK_DWIVEDI_V0_MIN ? SOAK_DWIVEDI_V0_MIN : (v0 < SOAK_DWIVEDI_V0_MAX ? v0 : SOAK_DWIVEDI_V0_MAX);
}

double soak_dwivedi_norm(double v0) { return log1p(2.0 / (v0 - 1.0)); }

double soak_dwivedi_sample_cos(double v0, double norm, double u)
{
    /* CDF F(mu) = ln((v0 + 1) / (v0 - mu)) / L, so v0 - mu = (v0 + 1) exp(-u L);
     * written with expm1 to keep mu accurate when v0 is large. */
    double mu = -1.0 - (v0 + 1.0) * expm1(-u * norm);
    return mu < -1.0 ? -1.0 : (mu > 1.0 ? 1.0 : mu);
}

double soak_dwivedi_pdf_cos(double v0, double norm, double mu) { return 1.0 / (norm * (v0 - mu)); }
