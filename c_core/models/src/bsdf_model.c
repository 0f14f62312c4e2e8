/* Any entry of soak_models() as a BSDF: one context per colour channel.
 * Sampling: the model's own sampler (soak_model.sample) on the green
 * channel when it has one, else a one-sample mixture of a cosine lobe and
 * GGX visible-normal reflection at the model's roughness, half each (the
 * cosine half covers the whole hemisphere, so every f > 0 has pdf > 0: the
 * estimator is unbiased for any model). A mirror lobe (soak_model.mirror,
 * e.g. ww's film top) is chosen first with probability R(cos_o) of the
 * green channel, weight R_c / R_green per channel. */
#include "bsdf_internal.h"
#include "soak/ggx.h"

#define MIX_COSINE 0.5

static soak_status model_setup(soak_bsdf *b)
{
    const soak_model *m = b->d.model;
    if (!m) return SOAK_ERR_NULL;
    for (int ch = 0; ch < 3; ++ch) {
        soak_status st = m->setup(&b->d.params[ch], &b->model[ch]);
        if (st != SOAK_OK) return st;
    }
    double a = b->d.params[1].roughness;
    b->d.alpha = soak_in_range(a, SOAK_GGX_ALPHA_MIN, 1) ? a : (a > 1 ? 1 : SOAK_GGX_ALPHA_MIN);
    b->flags = SOAK_BSDF_DIFFUSE | SOAK_BSDF_GLOSSY | (m->mirror ? SOAK_BSDF_DELTA : 0);
    return SOAK_OK;
}

/* Mirror-lobe reflectance of channel ch at cos_o (0 without one). */
static double mirror_R(const soak_bsdf *b, int ch, double cos_o)
{
    double R = 0;
    if (!b->d.model->mirror || b->d.model->mirror(&b->model[ch], cos_o, &R) != SOAK_OK) return 0;
    return soak_in_range(R, 0, 1) ? R : 0;
}

static double nondelta_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    const soak_model *m = b->d.model;
    if (m->pdf) {
        double p = 0;
        return m->pdf(&b->model[1], wi, wo, &p) == SOAK_OK ? p : 0.0;
    }
    return MIX_COSINE * wi.z * SOAK_INV_PI + (1 - MIX_COSINE) * bsdf_ggx_reflect_pdf(b->d.alpha, wi, wo);
}

static double model_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    if (!(wi.z > 0 && wo.z > 0)) return 0;
    return (1 - mirror_R(b, 1, wo.z)) * nondelta_pdf(b, wi, wo);
}

static soak_status model_f(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f)
{
    double v[3];
    for (int ch = 0; ch < 3; ++ch) {
        soak_status st = soak_model_eval(b->d.model, &b->model[ch], wi, wo, &v[ch]);
        if (st != SOAK_OK) return st;
    }
    *f = soak_rgb3(v[0], v[1], v[2]);
    return SOAK_OK;
}

static soak_status model_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    *f = soak_rgb3(0, 0, 0);
    *pdf = 0;
    if (!(wi.z > 0 && wo.z > 0)) return SOAK_OK;
    soak_status st = model_f(b, wi, wo, f);
    if (st != SOAK_OK) return st;
    *pdf = model_pdf(b, wi, wo);
    return SOAK_OK;
}

static int sample_nondelta(const soak_bsdf *b, soak_vec3 wo, double u0, double u1, double u2, soak_vec3 *wi)
{
    const soak_model *m = b->d.model;
    if (m->sample) {
        double f, pdf;
        return m->sample(&b->model[1], wo, u0, u1, u2, wi, &f, &pdf) == SOAK_OK && pdf > 0 && wi->z > 0;
    }
    if (u0 < MIX_COSINE) {
        *wi = soak_cosine_hemisphere(u1, u2);
        return wi->z > 0;
    }
    double pdf;
    return bsdf_ggx_reflect_sample(b->d.alpha, wo, u1, u2, wi, &pdf);
}

static soak_status model_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    *ok = 0;
    if (!(wo.z > 0)) return SOAK_OK;
    double Rg = mirror_R(b, 1, wo.z);
    if (u[0] < Rg) {
        s->wi = bsdf_mirror(wo);
        s->weight = soak_rgb3(mirror_R(b, 0, wo.z) / Rg, 1, mirror_R(b, 2, wo.z) / Rg);
        s->delta = 1;
        *ok = 1;
        return SOAK_OK;
    }
    double u0 = fmin((u[0] - Rg) / (1 - Rg), 1.0);
    if (!sample_nondelta(b, wo, u0, u[1], u[2], &s->wi)) return SOAK_OK;
    soak_rgb f;
    soak_status st = model_eval(b, s->wi, wo, &f, &s->pdf);
    if (st != SOAK_OK) return st;
    if (!(s->pdf > 0)) return SOAK_OK;
    s->weight = soak_rgb_scale(f, s->wi.z / s->pdf);
    *ok = 1;
    return SOAK_OK;
}

const soak_bsdf_ops bsdf_model_ops = {model_setup, model_eval, model_pdf, model_sample, NULL};
