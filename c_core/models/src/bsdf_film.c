/* Liquid film over a Lambertian base in closed form (Lekner & Dorf 1988,
 * soak/film.h): the expectation of what the traced layer (bsdf_walk.c)
 * follows bounce by bounce. Two lobes: the mirror of the film top,
 * reflectance F12(cos_o), and the diffuse part f_d of directional albedo
 * D(cos_o) = A_dir(cos_o) - F12 (mean over the channels). The lobe is chosen
 * in proportion to those albedos, P_mirror = F12 / (F12 + D), so both
 * branches carry about the same weight F12 + D (choosing by F12 alone made a
 * wet ground under a uniform sky 14x noisier than a Lambert one). The
 * diffuse direction is cosine-distributed: pdf (1 - P_mirror) cos_i / pi. */
#include "bsdf_internal.h"

static soak_status film_setup(soak_bsdf *b)
{
    for (int ch = 0; ch < 3; ++ch) {
        /* soak_film takes alpha and thickness only as their product tau. */
        double tau = soak_rgb_at(b->d.film_absorption, ch) * b->d.film_thickness;
        soak_film film = {b->d.film_ior, tau, 1.0};
        soak_status st = soak_film_setup(&film, &b->film[ch]);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}

static double mirror_probability(const soak_bsdf *b, double cos_o, double *F)
{
    *F = bsdf_fresnel(cos_o, b->d.film_ior, NULL);
    double D = 0;
    for (int ch = 0; ch < 3; ++ch) {
        double A = 0;
        if (soak_film_ctx_albedo_dir(&b->film[ch], soak_rgb_at(b->d.albedo, ch), cos_o, &A) == SOAK_OK)
            D += fmax(0.0, A - *F) / 3;
    }
    return *F + D > 0 ? *F / (*F + D) : -1.0; /* -1: nothing leaves (black base, index-matched film) */
}

static soak_rgb film_f(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    double f[3] = {0, 0, 0};
    for (int ch = 0; ch < 3; ++ch)
        if (soak_film_ctx_brdf(&b->film[ch], soak_rgb_at(b->d.albedo, ch), wi, wo, &f[ch]) != SOAK_OK) f[ch] = 0;
    return soak_rgb3(f[0], f[1], f[2]);
}

static soak_status film_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    double F, pm = wi.z > 0 && wo.z > 0 ? mirror_probability(b, wo.z, &F) : -1.0;
    *f = pm >= 0 ? film_f(b, wi, wo) : soak_rgb3(0, 0, 0);
    *pdf = pm >= 0 ? (1 - pm) * wi.z * SOAK_INV_PI : 0.0;
    return SOAK_OK;
}

static double film_pdf(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    double F, pm = wi.z > 0 && wo.z > 0 ? mirror_probability(b, wo.z, &F) : -1.0;
    return pm >= 0 ? (1 - pm) * wi.z * SOAK_INV_PI : 0.0;
}

static int film_direction(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s)
{
    double F, pm = wo.z > 0 ? mirror_probability(b, wo.z, &F) : -1.0;
    if (!(pm >= 0)) return 0;
    if (u[0] < pm) {
        s->wi = bsdf_mirror(wo);
        s->weight = soak_rgb3(F / pm, F / pm, F / pm);
        s->delta = 1;
        return 1;
    }
    s->wi = soak_cosine_hemisphere(u[1], u[2]);
    s->pdf = (1 - pm) * s->wi.z * SOAK_INV_PI;
    soak_rgb f = film_f(b, s->wi, wo);
    if (!(s->pdf > 0)) return 0;
    s->weight = soak_rgb_scale(f, s->wi.z / s->pdf);
    return 1;
}

static soak_status film_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    *ok = film_direction(b, wo, u, s);
    return SOAK_OK;
}

const soak_bsdf_ops bsdf_film_ops = {film_setup, film_eval, film_pdf, film_sample, NULL};
