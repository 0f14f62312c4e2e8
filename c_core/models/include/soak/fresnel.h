/* Fresnel reflectance: exact dielectric (both directions, total internal
 * reflection), exact conductor (complex index), Schlick, and cosine-weighted
 * hemispherical averages. Source: Born & Wolf, Principles of Optics, 7th ed.,
 * sec. 1.5; conductor form as in [Lag13]'s FresnelConductor (Lagarde, v1.3).
 *
 * Conventions: cos_i in [0,1] is the cosine of the angle of incidence on the
 * incident side; eta = n_transmitted / n_incident (> 0). eta < 1 is the
 * "internal" direction (e.g. water to air, eta = 1/1.33), where total internal
 * reflection gives R = 1 beyond the critical angle. eta == 1 means there is no
 * interface and R = 0 at every angle. */
#ifndef SOAK_FRESNEL_H
#define SOAK_FRESNEL_H

#include "soak/status.h"

#define SOAK_ETA_MIN 1e-3
/* Water at 20 C around 589 nm (IAPWS 1997 formulation): the default liquid
 * index wherever a model or scene does not name one; c_core/data/materials.json
 * ships the same value. */
#define SOAK_WATER_IOR 1.333
#define SOAK_ETA_MAX 1e3

/* Unpolarised dielectric reflectance. Also returns cos of the transmitted
 * angle in *cos_t when cos_t != NULL (0 under total internal reflection). */
soak_status soak_fresnel_dielectric(double cos_i, double eta, double *R, double *cos_t);

/* Unpolarised reflectance of a conductor with relative complex index
 * eta + i*k (both relative to the incident medium; k >= 0, k == 0 reduces to
 * the dielectric form for eta >= 1). */
soak_status soak_fresnel_conductor(double cos_i, double eta, double k, double *R);

/* Schlick (1994) approximation R0 + (1 - R0)(1 - cos_i)^5, R0 in [0,1]. */
soak_status soak_fresnel_schlick(double cos_i, double R0, double *R);

/* Normal-incidence reflectance ((eta-1)^2 + k^2) / ((eta+1)^2 + k^2). */
soak_status soak_fresnel_r0(double eta, double k, double *R0);

/* Cosine-weighted hemispherical average R_avg = 2 * int_0^1 R(mu) mu dmu for
 * light arriving diffusely on the incident side of an interface with relative
 * index eta. Computed by Gauss-Legendre quadrature split at the critical angle
 * (eta < 1) so the kink in R is never inside a panel; accurate to ~1e-12.
 * Identity (tested): 1 - R_avg(1/n) = (1 - R_avg(n)) / n^2. */
soak_status soak_fresnel_dielectric_avg(double eta, double *R_avg);

/* Unchecked forms for hot loops inside the library (inputs already valid). */
double soak_fresnel_dielectric_raw(double cos_i, double eta, double *cos_t);
double soak_fresnel_conductor_raw(double cos_i, double eta, double k);

#endif
