/* Tri-Ace fast paths for the water-over-base Weidlich-Wilkie BRDF ([Lag13],
 * "Refract vector", "Fresnel term", "Absorption term"; Gotanda, tri-Ace).
 * Declared and documented in soak/ww.h; accuracy against soak_ww_eval is
 * measured in tests/c/models/test_ww.c. The per-sample path has no pow/exp, and
 * every division is by a quantity bounded away from zero (refracted cosines
 * >= ~0.65 for n = 1.33, GGX terms >= alpha^2 * cos^2 > 0). */
#include <math.h>

#include "soak/fresnel.h"
#include "soak/ggx.h"
#include "soak/ww.h"

#include "fast_paths.h"

static double f0(double na, double nb, double kb)
{
    double d = nb - na, s = nb + na;
    return (d * d + kb * kb) / (s * s + kb * kb);
}

soak_status soak_triace_fbottom_dielectric(double n2, double n3, double *F)
{
    if (!F) return SOAK_ERR_NULL;
    if (!soak_in_range(n2, SOAK_ETA_MIN, SOAK_ETA_MAX) || !soak_in_range(n3, SOAK_ETA_MIN, SOAK_ETA_MAX))
        return SOAK_ERR_ARG;
    *F = f0(n2, n3, 0.0) * (1.0 - f0(n2, 1.0, 0.0));
    return SOAK_OK;
}

soak_status soak_triace_fbottom_conductor(double n2, double n3, double k3, double *F)
{
    if (!F) return SOAK_ERR_NULL;
    if (!soak_in_range(n2, SOAK_ETA_MIN, SOAK_ETA_MAX) || !soak_in_range(n3, SOAK_ETA_MIN, SOAK_ETA_MAX) ||
        !soak_in_range(k3, 0.0, SOAK_ETA_MAX))
        return SOAK_ERR_ARG;
    *F = f0(n2, n3, k3) * (1.0 - f0(n2, 1.0, 0.0));
    return SOAK_OK;
}

soak_status soak_triace_absorption_linear(double alpha_prime, double cos_l, double cos_v, double *a)
{
    if (!a) return SOAK_ERR_NULL;
    if (!soak_in_range(alpha_prime, 0.0, 1e9) || !(cos_l > 0.0 && cos_l <= 1.0) || !(cos_v > 0.0 && cos_v <= 1.0))
        return SOAK_ERR_ARG;
    if (alpha_prime == 0.0) { /* no absorption; avoids 0 * (huge) */
        *a = 1.0;
        return SOAK_OK;
    }
    double v = 1.0 - alpha_prime * (1.0 / cos_l + 1.0 / cos_v);
    *a = v > 0.0 ? v : 0.0;
    return SOAK_OK;
}

soak_status soak_refract_1_33(soak_vec3 i, soak_vec3 n, soak_vec3 *t)
{
    if (!t) return SOAK_ERR_NULL;
    if (!soak_v3_is_unit(i) || !soak_v3_is_unit(n)) return SOAK_ERR_ARG;
    double c = -soak_v3_dot(i, n);
    if (!(c >= -SOAK_UNIT_TOL)) return SOAK_ERR_ARG; /* i must arrive on the side n points to */
    if (c < 0.0) c = 0.0;
    if (c > 1.0) c = 1.0;
    double p = (R133_C2 * c + R133_C1) * c + R133_C0;
    *t = soak_v3_add(soak_v3_scale(i, R133_ETA), soak_v3_scale(n, p));
    return SOAK_OK;
}

soak_status soak_ww_triace_setup(const soak_ww *m, soak_ww_triace *fast)
{
    if (!m || !fast) return SOAK_ERR_NULL;
    soak_status s = soak_ww_validate(m);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(m->n_water, SOAK_WW_TRIACE_N_MIN, SOAK_WW_TRIACE_N_MAX)) return SOAK_ERR_ARG;
    /* The liquid's own index in every Fresnel term and the radiance
     * compression; only the refraction polynomial stays the 1.33 fit. */
    const double n2 = m->n_water;
    double t21 = 1.0 - f0(n2, 1.0, 0.0);
    soak_ww_triace r;
    r.r0_top = f0(1.0, n2, 0.0);
    if (m->base == SOAK_WW_CONDUCTOR) {
        r.fbottom = f0(n2, m->n_base, m->k_base) * t21;
        r.diffuse = 0.0;
    } else {
        double f23 = f0(n2, m->n_base, 0.0);
        r.fbottom = f23 * t21;
        /* Diffuse counterpart of F_bottom: (1 - F23)^2 for the way in and out
         * of the base, (1 - F21) for leaving the film, all at normal
         * incidence ([Lag13] notes F_bottom must not be applied to the
         * diffuse term). */
        r.diffuse = m->kd * SOAK_INV_PI * t21 * (1.0 - f23) * (1.0 - f23);
    }
    r.alpha2 = m->alpha * m->alpha;
    r.alpha_prime = m->absorption * m->thickness;
    r.inv_n2 = 1.0 / (n2 * n2);
    if (!soak_is_finite(r.alpha_prime) || r.alpha_prime > 1e9) return SOAK_ERR_ARG;
    *fast = r;
    return SOAK_OK;
}

double soak_ww_eval_triace_raw(const soak_ww_triace *fast, soak_vec3 wi, soak_vec3 wo)
{
    triace_fast k = triace_fast_make(fast);
    return triace_eval_fast(&k, wi, wi.x * wi.x + wi.y * wi.y, wo, wo.x * wo.x + wo.y * wo.y);
}

soak_status soak_ww_eval_triace(const soak_ww_triace *fast, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!fast || !f) return SOAK_ERR_NULL;
    if (!soak_in_range(fast->alpha2, SOAK_GGX_ALPHA_MIN * SOAK_GGX_ALPHA_MIN, 1.0) ||
        !soak_in_range(fast->alpha_prime, 0.0, 1e9) || !soak_in_range(fast->fbottom, 0.0, 1.0) ||
        !soak_in_range(fast->diffuse, 0.0, SOAK_INV_PI) || !soak_in_range(fast->r0_top, 0.0, 1.0) ||
        !soak_in_range(fast->inv_n2, 0.0, 1.0))
        return SOAK_ERR_ARG;
    if (!soak_v3_is_unit(wi) || !soak_v3_is_unit(wo) || !(wi.z > 0.0) || !(wo.z > 0.0)) return SOAK_ERR_ARG;
    double li = soak_v3_dot(wi, wi), lo = soak_v3_dot(wo, wo);
    wi = soak_v3_scale(wi, 1.0 / sqrt(li));
    wo = soak_v3_scale(wo, 1.0 / sqrt(lo));
    double v = soak_ww_eval_triace_raw(fast, wi, wo);
    if (!soak_is_finite(v) || v < 0.0) return SOAK_ERR_NUMERIC;
    *f = v;
    return SOAK_OK;
}
