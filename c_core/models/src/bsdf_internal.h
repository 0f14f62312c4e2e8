/* Private pieces of the BSDF adaptors (soak/bsdf.h): one file per kind. */
#ifndef SOAK_BSDF_INTERNAL_H
#define SOAK_BSDF_INTERNAL_H

#include <math.h>

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

/* Per kind: set-up of the base (no film), and its non-delta eval and
 * sampling in the frame of the medium above it (the film when there is
 * one). Sampling returns 0 when no direction results. */
soak_status bsdf_lambert_setup(soak_bsdf *b);
void bsdf_lambert_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int bsdf_lambert_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s);

soak_status bsdf_ggx_setup(soak_bsdf *b);
void bsdf_ggx_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int bsdf_ggx_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s);
/* Density of the reflected direction wi from visible-normal sampling around wo. */
double bsdf_ggx_reflect_pdf(double alpha, soak_vec3 wi, soak_vec3 wo);
/* Visible-normal reflection sample; 0 when it falls below the horizon. */
int bsdf_ggx_reflect_sample(double alpha, soak_vec3 wo, double u1, double u2, soak_vec3 *wi, double *pdf);

soak_status bsdf_glass_setup(soak_bsdf *b);
int bsdf_glass_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s);

soak_status bsdf_model_setup(soak_bsdf *b);
soak_status bsdf_model_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
soak_status bsdf_model_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok);

/* Rough dielectric interface over Lambert (bsdf_coated.c); the tables are
 * rebuilt when a film makes eta relative to the liquid. */
soak_status bsdf_coated_setup(soak_bsdf *b);
void bsdf_coated_tables(soak_bsdf *b);
void bsdf_coated_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int bsdf_coated_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s);

/* Closed-form film over Lambert (bsdf_film.c). */
soak_status bsdf_film_setup(soak_bsdf *b);
void bsdf_film_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int bsdf_film_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s);

/* The base alone (no film), for the walk: dispatch over LAMBERT / GGX / COATED. */
void bsdf_base_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int bsdf_base_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s);

#endif
