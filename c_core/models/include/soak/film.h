/* Smooth liquid film over a Lambertian base, with all interreflections
 * between the base and the underside of the film surface.
 * Source: J. Lekner & M. C. Dorf, "Why some things are darker when wet",
 * Applied Optics 27(7):1278-1280, 1988; absorption by Beer-Lambert with the
 * water coefficients alpha = (0.35, 0.04, 0) 1/m of [Lag13] (Lagarde).
 * The derivation (with absorption, which Lekner & Dorf leave out) is at the
 * top of src/film.c.
 *
 * Quantities are per colour channel (call once per channel). "Albedo" here is
 * the TOTAL reflectance: the specular reflection of the film surface plus the
 * diffuse light that escapes after any number of base/film bounces.
 * n == 1 means no interface: with no absorption the result equals the dry
 * base exactly.
 *
 * Grazing incidence: cos_i = 0 is accepted and is the limit of the model:
 * the film surface mirrors everything (specular = 1, albedo = 1) when n > 1;
 * with n == 1 the light reaches the base only if the film does not absorb. */
#ifndef SOAK_FILM_H
#define SOAK_FILM_H

#include "soak/status.h"
#include "soak/vec.h"

#define SOAK_FILM_MIN_N 1.0
#define SOAK_FILM_MAX_N 3.0
#define SOAK_FILM_MAX_ALPHA 1e6     /* 1/m */
#define SOAK_FILM_MAX_THICKNESS 1e3 /* m */

typedef struct soak_film {
    double n;         /* film index relative to the air above, [SOAK_FILM_MIN_N, SOAK_FILM_MAX_N] */
    double alpha;     /* absorption coefficient of the liquid, 1/m, [0, SOAK_FILM_MAX_ALPHA] */
    double thickness; /* film thickness, m, [0, SOAK_FILM_MAX_THICKNESS]; 0 = no absorption */
} soak_film;

soak_status soak_film_validate(const soak_film *film);

/* Total reflectance for collimated light at cos_i [0,1]. */
soak_status soak_film_albedo_dir(const soak_film *film, double base_albedo, double cos_i, double *albedo);
/* Total reflectance for uniform diffuse (cosine-weighted) illumination. */
soak_status soak_film_albedo_diffuse(const soak_film *film, double base_albedo, double *albedo);
/* Angle-resolved BRDF (1/sr) of the glossy-free part: light refracted in,
 * scattered by the base (with interreflections), refracted out. Reciprocal.
 * wi, wo: unit vectors (|len^2 - 1| <= 1e-5), local frame. Returns 0 when
 * either is at or below the horizon (z <= 0). */
soak_status soak_film_brdf(const soak_film *film, double base_albedo, soak_vec3 wi, soak_vec3 wo, double *f);
/* Reflectance of the delta (mirror) lobe of the film surface at cos_i [0,1]. */
soak_status soak_film_specular(const soak_film *film, double cos_i, double *R);

/* The functions above redo the hemispherical quadratures on every call
 * (a few microseconds). For repeated evaluation of one film, set up a context
 * once; the soak_film_ctx_* functions then cost one Fresnel term and one
 * exponential per direction. Their results equal the plain functions'. */
typedef struct soak_film_ctx {
    double n;        /* film index */
    double tau;      /* optical thickness alpha * thickness */
    double spec_avg; /* cosine-weighted average of the top reflectance seen from air */
    double escape;   /* fraction of the flux leaving the base that reaches the air */
    double ret;      /* fraction of that flux sent back onto the base by the film surface */
} soak_film_ctx;

soak_status soak_film_setup(const soak_film *film, soak_film_ctx *ctx);
soak_status soak_film_ctx_albedo_dir(const soak_film_ctx *ctx, double base_albedo, double cos_i, double *albedo);
soak_status soak_film_ctx_albedo_diffuse(const soak_film_ctx *ctx, double base_albedo, double *albedo);
soak_status soak_film_ctx_brdf(const soak_film_ctx *ctx, double base_albedo, soak_vec3 wi, soak_vec3 wo, double *f);
/* Unchecked form for hot loops (the same value): ctx from soak_film_setup,
 * base_albedo in [0, 1], wi, wo unit with wi.z > 0, wo.z > 0. */
double soak_film_ctx_brdf_raw(const soak_film_ctx *ctx, double base_albedo, soak_vec3 wi, soak_vec3 wo);

#endif
