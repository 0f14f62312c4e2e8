/* Private pieces of the BSDF adaptors (soak/bsdf.h): one file per kind. */
#ifndef SOAK_BSDF_INTERNAL_H
#define SOAK_BSDF_INTERNAL_H

#include <math.h>
#include <stdint.h>

#include "soak/bsdf.h"
#include "soak/fresnel.h"

/* Unpolarised dielectric Fresnel for eta = n_t / n_i, cos_i clamped to
 * [0, 1]; eta == 1 is no interface. *cos_t: 0 under total internal reflection. */
static inline double bsdf_fresnel(double cos_i, double eta, double *cos_t)
{
    if (eta == 1.0) {
        if (cos_t) *cos_t = cos_i;
        return 0.0;
    }
    double ct = 0.0;
    double F = soak_fresnel_dielectric_raw(fmin(1.0, fmax(0.0, cos_i)), eta, &ct);
    if (cos_t) *cos_t = ct;
    return F;
}

static inline soak_vec3 bsdf_mirror(soak_vec3 w) { return soak_v3(-w.x, -w.y, w.z); }

/* Beer-Lambert transmittance of the film along a leg at cos (1 when the film does not absorb). */
static inline soak_rgb bsdf_film_absorb(const soak_bsdf *b, double cos)
{
    double s = b->d.film_thickness / cos;
    soak_rgb a = b->d.film_absorption;
    return soak_rgb3(exp(-a.r * s), exp(-a.g * s), exp(-a.b * s));
}

/* One kind of BSDF (or of layer over a base): every entry point the
 * dispatcher (bsdf.c) calls, in the frame of the medium above it (the film
 * when there is one). eval and sample give 0 / *ok = 0 below the horizon;
 * pdf is the density of sample() producing wi (non-delta part), without
 * evaluating f. eval_keyed (NULL for closed forms): the stochastic eval with
 * its random stream chosen by key (eval uses a key hashed from wi, wo). */
typedef struct soak_bsdf_ops {
    soak_status (*setup)(soak_bsdf *b);
    soak_status (*eval)(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
    double (*pdf)(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo);
    soak_status (*sample)(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok);
    soak_status (*eval_keyed)(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, uint64_t key, soak_rgb *f, double *pdf);
} soak_bsdf_ops;

extern const soak_bsdf_ops bsdf_lambert_ops, bsdf_ggx_ops, bsdf_glass_ops, bsdf_model_ops, bsdf_coated_ops;
extern const soak_bsdf_ops bsdf_film_ops; /* closed-form film over Lambert (bsdf_film.c) */
extern const soak_bsdf_ops bsdf_walk_ops; /* traced film over any base (bsdf_walk.c) */

/* Shared by the GGX, coated and model adaptors: the density of the reflected direction wi from visible-normal sampling around wo. */
double bsdf_ggx_reflect_pdf(double alpha, soak_vec3 wi, soak_vec3 wo);
/* Visible-normal reflection sample; 0 when it falls below the horizon. */
int bsdf_ggx_reflect_sample(double alpha, soak_vec3 wo, double u1, double u2, soak_vec3 *wi, double *pdf);

/* COATED: the interface albedo tables, rebuilt when a film makes eta relative to the liquid. */
void bsdf_coated_tables(soak_bsdf *b);
/* The traced layer's random-stream key of a direction pair (soak_bsdf_eval_mean varies it). */
uint64_t bsdf_walk_key(soak_vec3 wi, soak_vec3 wo);

#endif
