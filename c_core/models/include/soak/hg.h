/* Henyey-Greenstein phase functions, single and two-term.
 * Source: Henyey & Greenstein 1941; two-term form from [JLD99] Eq. 5
 * (Jensen, Legakis, Dorsey 1999), CORRECTED: [JLD99] prints the first
 * denominator as (1 - 2 g1 cos - g1^2)^1.5; the correct term is
 * (1 - 2 g1 cos + g1^2)^1.5, and each lobe carries the 1/(4 pi) that makes
 * it integrate to 1 over the sphere (both tested by quadrature).
 *
 * cos_theta is the cosine between the propagation direction before and after
 * scattering, so g > 0 scatters forward. Mean cosine of the two-term
 * function is w*g1 + (1-w)*g2. |g| < 1 is required; g is accepted up to
 * +-SOAK_HG_G_MAX. */
#ifndef SOAK_HG_H
#define SOAK_HG_H

#include "soak/status.h"
#include "soak/vec.h"

#define SOAK_HG_G_MAX 0.999999

typedef struct soak_hg2 {
    double g1; /* first lobe asymmetry, [-G_MAX, G_MAX] ([JLD99]: forward, >= 0) */
    double g2; /* second lobe asymmetry ([JLD99]: backward, <= 0) */
    double w;  /* weight of the g1 lobe, [0,1] */
} soak_hg2;

soak_status soak_hg2_validate(const soak_hg2 *p);

/* Normalised single-lobe value, units 1/sr. */
soak_status soak_hg_eval(double g, double cos_theta, double *value);
soak_status soak_hg2_eval(const soak_hg2 *p, double cos_theta, double *value);

/* Inverse-CDF sample of cos_theta for one lobe, u in [0,1). Written to stay
 * accurate for |g| -> 0 and |g| -> 1; result always in [-1,1]. */
soak_status soak_hg_sample_cos(double g, double u, double *cos_theta);

/* Sample a scattered direction for incoming propagation direction dir_in
 * (unit). u_lobe picks the lobe, u_cos/u_phi the angles. Writes the new
 * direction and its pdf (= soak_hg2_eval of the realised cosine). */
soak_status soak_hg2_sample(const soak_hg2 *p, soak_vec3 dir_in, double u_lobe, double u_cos,
                            double u_phi, soak_vec3 *dir_out, double *pdf);

double soak_hg2_mean_cosine(const soak_hg2 *p);

/* Unchecked forms for hot loops (inputs already valid). */
double soak_hg_eval_raw(double g, double cos_theta);
double soak_hg_sample_cos_raw(double g, double u);
/* soak_hg2_sample's direction alone: p valid, dir_in unit, u in [0,1). */
soak_vec3 soak_hg2_sample_dir_raw(const soak_hg2 *p, soak_vec3 dir_in, double u_lobe, double u_cos, double u_phi);

#endif
