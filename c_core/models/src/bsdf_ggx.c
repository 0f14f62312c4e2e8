/* GGX microfacet reflection (soak/ggx.h): conductor (complex index) or the
 * reflection of a dielectric, sampled by visible normals (Heitz 2018). */
#include "bsdf_internal.h"
#include "soak/ggx.h"

static soak_status ggx_setup(soak_bsdf *b)
{
    soak_bsdf_desc *d = &b->d;
    if (!(d->alpha > 0 && d->alpha <= SOAK_GGX_ALPHA_MAX)) return SOAK_ERR_ARG;
    if (d->alpha < SOAK_GGX_ALPHA_MIN) d->alpha = SOAK_GGX_ALPHA_MIN; /* documented clamp */
    for (int ch = 0; ch < 3; ++ch) {
        if (!soak_in_range(soak_rgb_at(d->eta, ch), SOAK_ETA_MIN, SOAK_ETA_MAX)) return SOAK_ERR_ARG;
        if (!soak_in_range(soak_rgb_at(d->k, ch), 0, SOAK_GGX_K_MAX)) return SOAK_ERR_ARG;
    }
    if (d->kind == SOAK_BSDF_GGX_DIELECTRIC) d->k = soak_rgb3(0, 0, 0);
    b->flags = SOAK_BSDF_GLOSSY;
    return SOAK_OK;
}

double bsdf_ggx_reflect_pdf(double alpha, soak_vec3 wi, soak_vec3 wo)
{
    if (!(wi.z > 0 && wo.z > 0)) return 0;
    soak_vec3 h = soak_ggx_half_raw(wi, wo);
    double pdf_h = 0, oh = soak_v3_dot(wo, h);
    if (!(oh > 0) || soak_ggx_pdf_vndf(alpha, wo, h, &pdf_h) != SOAK_OK) return 0;
    return pdf_h / (4 * oh);
}

int bsdf_ggx_reflect_sample(double alpha, soak_vec3 wo, double u1, double u2, soak_vec3 *wi, double *pdf)
{
    soak_vec3 h;
    double pdf_h;
    if (soak_ggx_sample_vndf(alpha, wo, u1, u2, &h, &pdf_h) != SOAK_OK) return 0;
    double oh = soak_v3_dot(wo, h);
    soak_vec3 r = soak_v3_sub(soak_v3_scale(h, 2 * oh), wo);
    if (!(r.z > 0) || !(oh > 0) || !(pdf_h > 0)) return 0;
    *wi = soak_v3_norm(r);
    *pdf = pdf_h / (4 * oh);
    return 1;
}

static soak_rgb ggx_f(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    const soak_bsdf_desc *d = &b->d;
    double f[3];
    for (int ch = 0; ch < 3; ++ch) {
        double eta = soak_rgb_at(d->eta, ch), k = soak_rgb_at(d->k, ch);
        f[ch] = d->kind == SOAK_BSDF_GGX_CONDUCTOR ? soak_ggx_brdf_conductor_raw(d->alpha, eta, k, wi, wo)
                                                   : soak_ggx_brdf_dielectric_raw(d->alpha, eta, wi, wo);
    }
    return soak_rgb3(f[0], f[1], f[2]);
}

static double ggx_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo) { return bsdf_ggx_reflect_pdf(b->d.alpha, wi, wo); }

static soak_status ggx_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    int up = wi.z > 0 && wo.z > 0;
    *f = up ? ggx_f(b, wi, wo) : soak_rgb3(0, 0, 0);
    *pdf = up ? ggx_pdf(b, wi, wo) : 0.0;
    return SOAK_OK;
}

static soak_status ggx_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    *ok = wo.z > 0 && bsdf_ggx_reflect_sample(b->d.alpha, wo, u[1], u[2], &s->wi, &s->pdf);
    if (*ok) s->weight = soak_rgb_scale(ggx_f(b, s->wi, wo), s->wi.z / s->pdf);
    return SOAK_OK;
}

const soak_bsdf_ops bsdf_ggx_ops = {ggx_setup, ggx_eval, ggx_pdf, ggx_sample, NULL};
