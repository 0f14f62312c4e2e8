/* Lambertian BSDF: albedo / pi, cosine-weighted sampling. */
#include "bsdf_internal.h"

static soak_status lambert_setup(soak_bsdf *b)
{
    soak_rgb a = b->d.albedo;
    if (!soak_in_range(a.r, 0, 1) || !soak_in_range(a.g, 0, 1) || !soak_in_range(a.b, 0, 1)) return SOAK_ERR_ARG;
    b->flags = SOAK_BSDF_DIFFUSE;
    return SOAK_OK;
}

static double lambert_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    (void)b;
    return wi.z > 0 && wo.z > 0 ? wi.z * SOAK_INV_PI : 0.0;
}

static soak_status lambert_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    int up = wi.z > 0 && wo.z > 0;
    *f = up ? soak_rgb_scale(b->d.albedo, SOAK_INV_PI) : soak_rgb3(0, 0, 0);
    *pdf = lambert_pdf(b, wi, wo);
    return SOAK_OK;
}

static soak_status lambert_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    (void)wo;
    s->wi = soak_cosine_hemisphere(u[1], u[2]);
    s->pdf = s->wi.z * SOAK_INV_PI;
    s->weight = b->d.albedo;
    *ok = s->pdf > 0;
    return SOAK_OK;
}

const soak_bsdf_ops bsdf_lambert_ops = {lambert_setup, lambert_eval, lambert_pdf, lambert_sample, NULL};
