/* van de Hulst (1980) semi-infinite diffuse albedo and its closed-form
 * inverse; derivation in soak/vdhulst.h. */
#include "soak/vdhulst.h"

#include <math.h>

static int g_ok(double g) { return soak_in_range(g, -SOAK_HG_G_MAX, SOAK_HG_G_MAX); }

double soak_vdhulst_albedo_s_raw(double s)
{
    return (1.0 - s) * (1.0 - 0.139 * s) / (1.0 + 1.17 * s);
}

double soak_vdhulst_s_of_albedo_raw(double albedo)
{
    /* a s^2 - b s + c = 0 with a = 0.139, b = 1.139 + 1.17 R, c = 1 - R.
     * Discriminant b^2 - 4ac >= 1.139^2 - 0.556 > 0 for R in [0,1]. */
    double b = 1.139 + 1.17 * albedo;
    double c = 1.0 - albedo;
    double s = 2.0 * c / (b + sqrt(b * b - 4.0 * 0.139 * c));
    return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s); /* guards rounding only */
}

soak_status soak_vdhulst_albedo(double omega, double g, double *albedo)
{
    if (!albedo) return SOAK_ERR_NULL;
    if (!soak_in_range(omega, 0.0, 1.0) || !g_ok(g)) return SOAK_ERR_ARG;
    /* 1 - g omega >= 1 - |g| > 0 since |g| < 1. */
    double s = sqrt((1.0 - omega) / (1.0 - g * omega));
    if (s > 1.0) s = 1.0; /* g < 0 with omega > 0 gives s <= 1 exactly; rounding only */
    *albedo = soak_vdhulst_albedo_s_raw(s);
    return SOAK_OK;
}

soak_status soak_vdhulst_invert(double albedo, double g, double *omega)
{
    if (!omega) return SOAK_ERR_NULL;
    if (!soak_in_range(albedo, 0.0, 1.0) || !g_ok(g)) return SOAK_ERR_ARG;
    double s = soak_vdhulst_s_of_albedo_raw(albedo);
    double s2 = s * s;
    double w = (1.0 - s2) / (1.0 - g * s2);
    *omega = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
    return SOAK_OK;
}
