/* Lambertian BSDF: albedo / pi, cosine-weighted sampling. */
#include "bsdf_internal.h"

soak_status bsdf_lambert_setup(soak_bsdf *b)
{
    soak_rgb a = b->d.albedo;
    if (!soak_in_range(a.r, 0, 1) || !soak_in_range(a.g, 0, 1) || !soak_in_range(a.b, 0, 1)) return SOAK_ERR_ARG;
    b->flags = SOAK_BSDF_DIFFUSE;
    return SOAK_OK;
}

void bsdf_lambert_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    int up = wi.z > 0 && wo.z > 0;
    *f = up ? soak_rgb_scale(b->d.albedo, SOAK_INV_PI) : soak_rgb3(0, 0, 0);
    *pdf = up ? wi.z * SOAK_INV_PI : 0.0;
}

int bsdf_lambert_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s)
{
    (void)wo;
    s->wi = soak_cosine_hemisphere(u[1], u[2]);
    s->pdf = s->wi.z * SOAK_INV_PI;
    s->weight = b->d.albedo;
    return s->pdf > 0;
}
