/* GGX microfacet model: validation wrappers, Cook-Torrance BRDFs and
 * visible-normal sampling. Formulas and sources in soak/ggx.h. */
#include "soak/ggx.h"

#include <stddef.h>

#include "model_dirs.h"
#include "soak/fresnel.h"

static int alpha_ok(double alpha)
{
    return soak_in_range(alpha, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX);
}

soak_status soak_ggx_D(double alpha, soak_vec3 h, double *D)
{
    if (!D) return SOAK_ERR_NULL;
    soak_vec3 hn;
    if (!alpha_ok(alpha) || !model_unit_ok(h, &hn)) return SOAK_ERR_ARG;
    *D = soak_ggx_D_raw(alpha, hn);
    return SOAK_OK;
}

soak_status soak_ggx_G1(double alpha, soak_vec3 w, double *G)
{
    if (!G) return SOAK_ERR_NULL;
    soak_vec3 wn;
    if (!alpha_ok(alpha) || !model_upper_unit_ok(w, &wn)) return SOAK_ERR_ARG;
    *G = soak_ggx_G1_raw(alpha, wn);
    return SOAK_OK;
}

soak_status soak_ggx_G2(double alpha, soak_vec3 wi, soak_vec3 wo, double *G)
{
    if (!G) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    if (!alpha_ok(alpha) || !model_upper_unit_ok(wi, &a) || !model_upper_unit_ok(wo, &b)) return SOAK_ERR_ARG;
    *G = soak_ggx_G2_raw(alpha, a, b);
    return SOAK_OK;
}

double soak_ggx_brdf_dielectric_raw(double alpha, double eta, soak_vec3 wi, soak_vec3 wo)
{
    soak_vec3 h = soak_ggx_half_raw(wi, wo);
    double c = soak_v3_dot(wi, h);
    if (c > 1.0) c = 1.0;
    double F = soak_fresnel_dielectric_raw(c, eta, NULL);
    return F * soak_ggx_spec_raw(alpha, wi, wo, h);
}

double soak_ggx_brdf_conductor_raw(double alpha, double eta, double k, soak_vec3 wi, soak_vec3 wo)
{
    soak_vec3 h = soak_ggx_half_raw(wi, wo);
    double c = soak_v3_dot(wi, h);
    if (c > 1.0) c = 1.0;
    double F = soak_fresnel_conductor_raw(c, eta, k);
    return F * soak_ggx_spec_raw(alpha, wi, wo, h);
}

static soak_status finish(double v, double *out)
{
    if (!soak_is_finite(v)) return SOAK_ERR_NUMERIC;
    *out = v;
    return SOAK_OK;
}

soak_status soak_ggx_brdf_dielectric(double alpha, double eta, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!f) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    if (!alpha_ok(alpha) || !soak_in_range(eta, SOAK_ETA_MIN, SOAK_ETA_MAX) || !model_upper_unit_ok(wi, &a) ||
        !model_upper_unit_ok(wo, &b))
        return SOAK_ERR_ARG;
    return finish(soak_ggx_brdf_dielectric_raw(alpha, eta, a, b), f);
}

soak_status soak_ggx_brdf_conductor(double alpha, double eta, double k, soak_vec3 wi, soak_vec3 wo,
                                    double *f)
{
    if (!f) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    if (!alpha_ok(alpha) || !soak_in_range(eta, SOAK_ETA_MIN, SOAK_ETA_MAX) ||
        !soak_in_range(k, 0.0, SOAK_GGX_K_MAX) || !model_upper_unit_ok(wi, &a) || !model_upper_unit_ok(wo, &b))
        return SOAK_ERR_ARG;
    return finish(soak_ggx_brdf_conductor_raw(alpha, eta, k, a, b), f);
}

static double pdf_vndf_raw(double alpha, soak_vec3 wo, soak_vec3 h)
{
    double c = soak_v3_dot(wo, h);
    if (!(c > 0.0) || !(h.z > 0.0)) return 0.0;
    return soak_ggx_G1_raw(alpha, wo) * c * soak_ggx_D_raw(alpha, h) / wo.z;
}

soak_status soak_ggx_pdf_vndf(double alpha, soak_vec3 wo, soak_vec3 h, double *pdf_h)
{
    if (!pdf_h) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    if (!alpha_ok(alpha) || !model_upper_unit_ok(wo, &a) || !model_unit_ok(h, &b)) return SOAK_ERR_ARG;
    return finish(pdf_vndf_raw(alpha, a, b), pdf_h);
}

/* Heitz 2018, listing 1: stretch the view to the alpha = 1 configuration,
 * sample the projected hemisphere as a disk warped towards the visible half,
 * reproject and unstretch. */
soak_status soak_ggx_sample_vndf(double alpha, soak_vec3 wo, double u1, double u2, soak_vec3 *h,
                                 double *pdf_h)
{
    if (!h || !pdf_h) return SOAK_ERR_NULL;
    soak_vec3 v;
    if (!alpha_ok(alpha) || !model_upper_unit_ok(wo, &v) || !soak_in_range(u1, 0.0, 1.0) ||
        !soak_in_range(u2, 0.0, 1.0))
        return SOAK_ERR_ARG;

    soak_vec3 vh = soak_v3_norm(soak_v3(alpha * v.x, alpha * v.y, v.z));
    double lensq = vh.x * vh.x + vh.y * vh.y;
    soak_vec3 t1 = lensq > 0.0 ? soak_v3_scale(soak_v3(-vh.y, vh.x, 0.0), 1.0 / sqrt(lensq))
                               : soak_v3(1.0, 0.0, 0.0);
    soak_vec3 t2 = soak_v3_cross(vh, t1);

    double r = sqrt(u1);
    double phi = 2.0 * SOAK_PI * u2;
    double p1 = r * cos(phi);
    double p2 = r * sin(phi);
    double s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(fmax(0.0, 1.0 - p1 * p1)) + s * p2;
    double p3 = sqrt(fmax(0.0, 1.0 - p1 * p1 - p2 * p2));

    soak_vec3 nh = soak_v3_add(soak_v3_add(soak_v3_scale(t1, p1), soak_v3_scale(t2, p2)), soak_v3_scale(vh, p3));
    /* Floor on the unstretched z: u1 = 1 maps to the rim of the disk, where
     * h would be horizontal with zero density; keep h strictly upward. */
    soak_vec3 ne = soak_v3_norm(soak_v3(alpha * nh.x, alpha * nh.y, fmax(1e-12, nh.z)));

    double pdf = pdf_vndf_raw(alpha, v, ne);
    if (!soak_is_finite(pdf) || !soak_is_finite(ne.x) || !soak_is_finite(ne.y) || !soak_is_finite(ne.z))
        return SOAK_ERR_NUMERIC;
    *h = ne;
    *pdf_h = pdf;
    return SOAK_OK;
}
