/* Weidlich-Wilkie layered BRDF with a smooth water film (exact model):
 * setup, eval, sample. Derivation, corrections to [Lag13] and the energy
 * argument are in soak/ww.h. */
#include "soak/ww.h"

#include <math.h>
#include <stddef.h>

#include "model_dirs.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"

void soak_ww_default(soak_ww *m)
{
    if (!m) return;
    m->base = SOAK_WW_DIELECTRIC;
    m->n_water = SOAK_WW_N_WATER;
    m->absorption = 0.0;
    m->thickness = 0.0;
    m->alpha = 0.3;
    m->n_base = 1.5;
    m->k_base = 0.0;
    m->kd = 0.5;
}

void soak_ww_copper(soak_rgb *n, soak_rgb *k)
{
    /* [Lag13] (Lagarde), RenderMonkey code: filmetrics spectra convolved
     * with the CIE colour matching functions. */
    if (n) *n = soak_rgb3(3.406149, 2.161600, 1.504326);
    if (k) *k = soak_rgb3(5.225178, 3.756258, 3.018729);
}

soak_status soak_ww_validate(const soak_ww *m)
{
    if (!m) return SOAK_ERR_NULL;
    if (!soak_in_range(m->n_water, SOAK_WW_N_WATER_MIN, SOAK_WW_N_WATER_MAX) ||
        !soak_in_range(m->absorption, 0.0, SOAK_WW_ABSORPTION_MAX) ||
        !soak_in_range(m->thickness, 0.0, SOAK_WW_THICKNESS_MAX) ||
        !soak_in_range(m->alpha, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX))
        return SOAK_ERR_ARG;
    /* The field the base ignores must still be a number: a NaN there is a
     * caller's error (e.g. a NaN k that picked the dielectric base). */
    if (!soak_is_finite(m->k_base) || !soak_is_finite(m->kd)) return SOAK_ERR_ARG;
    if (m->base == SOAK_WW_DIELECTRIC) {
        if (!soak_in_range(m->n_base, SOAK_WW_N_DIELECTRIC_MIN, SOAK_WW_N_DIELECTRIC_MAX) ||
            !soak_in_range(m->kd, 0.0, 1.0))
            return SOAK_ERR_ARG;
    } else if (m->base == SOAK_WW_CONDUCTOR) {
        if (!soak_in_range(m->n_base, SOAK_WW_N_CONDUCTOR_MIN, SOAK_WW_N_CONDUCTOR_MAX) ||
            !soak_in_range(m->k_base, 0.0, SOAK_WW_K_MAX))
            return SOAK_ERR_ARG;
    } else {
        return SOAK_ERR_ARG;
    }
    return SOAK_OK;
}

/* Base BRDF inside the water (indices divided by n_water). */
static double base_raw(const soak_ww *m, soak_vec3 wi, soak_vec3 wo)
{
    double nw = m->n_water;
    if (m->base == SOAK_WW_CONDUCTOR)
        return soak_ggx_brdf_conductor_raw(m->alpha, m->n_base / nw, m->k_base / nw, wi, wo);
    double eta = m->n_base / nw;
    double spec = soak_ggx_brdf_dielectric_raw(m->alpha, eta, wi, wo);
    if (m->kd == 0.0) return spec;
    double ti = 1.0 - soak_fresnel_dielectric_raw(wi.z, eta, NULL);
    double to = 1.0 - soak_fresnel_dielectric_raw(wo.z, eta, NULL);
    return spec + m->kd * SOAK_INV_PI * ti * to;
}

/* Air -> water through the flat film: Snell keeps the tangential momentum,
 * so the tangential part scales by 1/n; the cosine comes with the Fresnel
 * reflectance, which is returned. n >= 1: no total internal reflection. */
static double refract_in(double n, soak_vec3 w, soak_vec3 *w_water)
{
    double ct;
    double F = soak_fresnel_dielectric_raw(w.z, n, &ct);
    *w_water = soak_v3(w.x / n, w.y / n, ct);
    return F;
}

static double absorption(const soak_ww *m, double ci, double co)
{
    double tau = m->absorption * m->thickness;
    if (tau == 0.0) return 1.0; /* also avoids 0 * (huge) at grazing */
    return exp(-tau * (1.0 / ci + 1.0 / co));
}

static double eval_raw(const soak_ww *m, soak_vec3 wi, soak_vec3 wo)
{
    soak_vec3 wi_w, wo_w;
    double Fi = refract_in(m->n_water, wi, &wi_w);
    double Fo = refract_in(m->n_water, wo, &wo_w);
    /* T21(cos_o') = 1 - F12(cos_o): Fresnel reflectance is the same from
     * either side for Snell-paired angles (Stokes relations). */
    double T = (1.0 - Fi) * (1.0 - Fo);
    if (T == 0.0) return 0.0;
    double fb = base_raw(m, wi_w, wo_w);
    return T * fb * absorption(m, wi_w.z, wo_w.z) / (m->n_water * m->n_water);
}

soak_status soak_ww_eval(const soak_ww *m, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!m || !f) return SOAK_ERR_NULL;
    soak_status s = soak_ww_validate(m);
    if (s != SOAK_OK) return s;
    soak_vec3 a, b;
    if (!model_upper_unit_ok(wi, &a) || !model_upper_unit_ok(wo, &b)) return SOAK_ERR_ARG;
    double v = eval_raw(m, a, b);
    if (!soak_is_finite(v) || v < 0.0) return SOAK_ERR_NUMERIC;
    *f = v;
    return SOAK_OK;
}

soak_status soak_ww_specular(const soak_ww *m, double cos_i, double *R)
{
    if (!m || !R) return SOAK_ERR_NULL;
    soak_status s = soak_ww_validate(m);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(cos_i, 0.0, 1.0)) return SOAK_ERR_ARG;
    *R = soak_fresnel_dielectric_raw(cos_i, m->n_water, NULL);
    return SOAK_OK;
}

soak_status soak_ww_base_eval(const soak_ww *m, soak_vec3 wi_water, soak_vec3 wo_water, double *f)
{
    if (!m || !f) return SOAK_ERR_NULL;
    soak_status s = soak_ww_validate(m);
    if (s != SOAK_OK) return s;
    soak_vec3 a, b;
    if (!model_upper_unit_ok(wi_water, &a) || !model_upper_unit_ok(wo_water, &b)) return SOAK_ERR_ARG;
    double v = base_raw(m, a, b);
    if (!soak_is_finite(v) || v < 0.0) return SOAK_ERR_NUMERIC;
    *f = v;
    return SOAK_OK;
}

/* Probability of sampling the GGX lobe rather than the diffuse one, from
 * their weights at the view direction (any positive choice is unbiased). */
static double spec_probability(const soak_ww *m, double co_w)
{
    if (m->base == SOAK_WW_CONDUCTOR || m->kd == 0.0) return 1.0;
    double F = soak_fresnel_dielectric_raw(co_w, m->n_base / m->n_water, NULL);
    double ws = F, wd = m->kd * (1.0 - F);
    if (ws + wd <= 0.0) return 0.5;
    double p = ws / (ws + wd);
    /* Keep both lobes reachable so the rough GGX tail is not starved. */
    return p < 0.1 ? 0.1 : (p > 0.9 ? 0.9 : p);
}

/* Density (solid angle in the water) of the base sampling strategy. */
static double base_pdf(const soak_ww *m, double p_spec, soak_vec3 wo_w, soak_vec3 wi_w)
{
    double pdf = 0.0;
    if (p_spec > 0.0) {
        soak_vec3 h = soak_ggx_half_raw(wi_w, wo_w);
        double oh = soak_v3_dot(wo_w, h);
        if (oh > 0.0)
            pdf += p_spec * soak_ggx_G1_raw(m->alpha, wo_w) * soak_ggx_D_raw(m->alpha, h) / (4.0 * wo_w.z);
    }
    if (p_spec < 1.0) pdf += (1.0 - p_spec) * wi_w.z * SOAK_INV_PI;
    return pdf;
}

soak_status soak_ww_sample(const soak_ww *m, soak_vec3 wo, double u0, double u1, double u2, soak_vec3 *wi,
                           double *weight, double *pdf, int *is_delta)
{
    if (!m || !wi || !weight || !pdf || !is_delta) return SOAK_ERR_NULL;
    soak_status s = soak_ww_validate(m);
    if (s != SOAK_OK) return s;
    soak_vec3 v;
    if (!model_upper_unit_ok(wo, &v) || !soak_in_range(u0, 0.0, 1.0) || !soak_in_range(u1, 0.0, 1.0) ||
        !soak_in_range(u2, 0.0, 1.0))
        return SOAK_ERR_ARG;

    soak_vec3 wo_w;
    double n = m->n_water;
    double Fo = refract_in(n, v, &wo_w);
    if (u0 < Fo) { /* mirror lobe: weight F12 / P(select) = 1 */
        *wi = soak_v3(-v.x, -v.y, v.z);
        *weight = 1.0;
        *pdf = 0.0;
        *is_delta = 1;
        return SOAK_OK;
    }
    double ul = (u0 - Fo) / (1.0 - Fo); /* Fo < 1 here since u0 <= 1 */
    if (ul > 1.0) ul = 1.0;
    double p_spec = spec_probability(m, wo_w.z);

    soak_vec3 wi_w;
    if (p_spec >= 1.0 || ul < p_spec) {
        soak_vec3 h;
        double pdf_h;
        s = soak_ggx_sample_vndf(m->alpha, wo_w, u1, u2, &h, &pdf_h);
        if (s != SOAK_OK) return s;
        wi_w = soak_v3_sub(soak_v3_scale(h, 2.0 * soak_v3_dot(wo_w, h)), wo_w);
    } else { /* cosine-weighted hemisphere */
        wi_w = soak_cosine_hemisphere(u1, u2);
    }

    *is_delta = 0;
    /* Leaving the film: sin_t = n sin_w; beyond the critical angle (or under
     * the base horizon) the light stays trapped and is dropped (no
     * interreflections in this model). */
    double s2 = n * n * (wi_w.x * wi_w.x + wi_w.y * wi_w.y);
    if (!(wi_w.z > 0.0) || s2 >= 1.0) {
        *wi = soak_v3(0.0, 0.0, 1.0);
        *weight = 0.0;
        *pdf = 0.0;
        return SOAK_OK;
    }
    soak_vec3 out = soak_v3_norm(soak_v3(n * wi_w.x, n * wi_w.y, sqrt(1.0 - s2)));
    if (!(out.z > 0.0)) {
        *wi = soak_v3(0.0, 0.0, 1.0);
        *weight = 0.0;
        *pdf = 0.0;
        return SOAK_OK;
    }
    /* Re-derive the water direction from the air one so eval and pdf see
     * exactly the same pair. dw_water / dw_air = cos_air / (n^2 cos_water). */
    soak_vec3 wi_w2;
    refract_in(n, out, &wi_w2);
    double pdf_w = base_pdf(m, p_spec, wo_w, wi_w2);
    double pdf_air = (1.0 - Fo) * pdf_w * out.z / (n * n * wi_w2.z);
    double f = eval_raw(m, out, v);
    double w = pdf_air > 0.0 ? f * out.z / pdf_air : 0.0;
    if (!soak_is_finite(w) || !soak_is_finite(pdf_air)) return SOAK_ERR_NUMERIC;
    *wi = out;
    *weight = w;
    *pdf = pdf_air;
    return SOAK_OK;
}
