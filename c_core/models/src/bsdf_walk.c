/* The traced layer (soak/bsdf.h, SOAK_BSDF_WALK): a smooth liquid film of
 * index n2 over an opaque base, followed bounce by bounce (Lekner & Dorf
 * 1988 as used in [JLD99] sec. 2.1 / 3.1). Reflect at the film top with
 * probability F12(cos1) (delta lobe); otherwise refract in, scatter off the
 * base, and at the underside leave with probability 1 - F21 or go back down
 * (total internal reflection beyond the critical angle).
 *
 * Radiance across the interface: entering multiplies radiance by 1/n^2,
 * leaving by n^2 (radiance / n^2 is invariant; the corrected factor of seed
 * 000 Eq. 1/2, see soak/jensen.h). The two cancel for a path that leaves, so
 * the walk's weights carry neither, and light() carries the 1/n^2 of light
 * arriving inside: the base receives E = (1 - F12(cos1)) L cos1 dw1 from a
 * light seen at cos1 in air and sends f_base E back, so
 *   f = f_base(w2_light, up) (1 - F12) e^{-a h / cos2} / n2^2.
 * The competing strategy (leave the film and hit the light) has, in air
 * solid angle, pdf = pdf_base(w2) (1 - F21(cos2)) cos1 / (n2^2 cos2), the
 * Jacobian of Snell's map dw2/dw1 = (n1/n2)^2 cos1/cos2. */
#include "bsdf_internal.h"

static int absorbing(const soak_bsdf *b)
{
    soak_rgb a = b->d.film_absorption;
    return b->d.film_thickness > 0 && (a.r > 0 || a.g > 0 || a.b > 0);
}

static soak_rgb leg(const soak_bsdf *b, double cos)
{
    return absorbing(b) ? bsdf_film_absorb(b, cos) : soak_rgb3(1, 1, 1);
}

soak_walk_event soak_bsdf_walk_start(const soak_bsdf *b, soak_vec3 wo, double u, soak_bsdf_walk *w,
                                     soak_bsdf_sample *s, soak_rgb *weight)
{
    double n2 = b->d.film_ior, cos2;
    if (!(wo.z > 0)) return SOAK_WALK_DEAD;
    double F = bsdf_fresnel(wo.z, n2, &cos2);
    if (u < F) {
        s->wi = bsdf_mirror(wo);
        s->weight = *weight = soak_rgb3(1, 1, 1);
        s->pdf = 0;
        s->delta = 1;
        s->eta = 1;
        return SOAK_WALK_EXIT;
    }
    w->up = soak_v3(wo.x / n2, wo.y / n2, cos2);
    *weight = leg(b, cos2);
    return SOAK_WALK_BOUNCE;
}

void soak_bsdf_walk_light(const soak_bsdf *b, const soak_bsdf_walk *w, soak_vec3 wi, soak_rgb *f, double *pdf)
{
    double n2 = b->d.film_ior, cos2;
    *f = soak_rgb3(0, 0, 0);
    *pdf = 0;
    if (!(wi.z > 0)) return;
    double T = 1.0 - bsdf_fresnel(wi.z, n2, &cos2);
    if (!(T > 0 && cos2 > 0)) return;
    soak_vec3 l2 = soak_v3(wi.x / n2, wi.y / n2, cos2);
    soak_rgb fb;
    double pb;
    bsdf_base_eval(b, l2, w->up, &fb, &pb);
    *f = soak_rgb_mul(soak_rgb_scale(fb, T / (n2 * n2)), leg(b, cos2));
    *pdf = pb * T * wi.z / (n2 * n2 * cos2);
}

soak_walk_event soak_bsdf_walk_step(const soak_bsdf *b, soak_bsdf_walk *w, const double u[4], soak_bsdf_sample *s,
                                    soak_rgb *weight)
{
    double n2 = b->d.film_ior;
    soak_bsdf_sample bs = {.eta = 1};
    if (!bsdf_base_sample(b, w->up, u, &bs)) return SOAK_WALK_DEAD;
    soak_vec3 wi = bs.wi;
    *weight = soak_rgb_mul(bs.weight, leg(b, wi.z)); /* the way up */
    double cos_air;
    double F = bsdf_fresnel(wi.z, 1.0 / n2, &cos_air);
    if (u[3] < F) {
        w->up = bsdf_mirror(wi); /* reflected back down, scattered up again next */
        *weight = soak_rgb_mul(*weight, leg(b, wi.z));
        return SOAK_WALK_BOUNCE;
    }
    s->wi = soak_v3_norm(soak_v3(wi.x * n2, wi.y * n2, cos_air));
    s->pdf = bs.pdf * (1.0 - F) * cos_air / (n2 * n2 * wi.z);
    s->weight = *weight;
    s->delta = 0;
    s->eta = 1;
    return SOAK_WALK_EXIT;
}
