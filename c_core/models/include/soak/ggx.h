/* Isotropic GGX / Trowbridge-Reitz microfacet model.
 * Sources: B. Walter, S. Marschner, H. Li, K. Torrance, "Microfacet Models for
 * Refraction through Rough Surfaces", EGSR 2007 (D, eq. 33; Smith G1, eq. 34);
 * E. Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based
 * BRDFs", JCGT 3(2) 2014 (Lambda, eq. 72; height-correlated G2, eq. 99);
 * E. Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4) 2018.
 *
 * Conventions (see soak/vec.h): unit vectors in the local frame, normal +z.
 * wi, wo must lie in the upper hemisphere (z > 0) and be unit length within
 * SOAK_GGX_UNIT_TOL (they are renormalised internally). A microfacet normal h
 * may point anywhere; D(h) = 0 for h.z <= 0.
 *
 * Roughness: alpha is the GGX width parameter (alpha = 1 is very rough).
 * Accepted range [SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX] = [1e-4, 1]; values
 * outside it (and NaN/Inf) return SOAK_ERR_ARG -- the library never clamps
 * silently. Callers that map an artist roughness to alpha must clamp to this
 * range themselves; below 1e-4 the lobe is narrower than double-precision
 * direction noise can resolve (peak D = 1/(pi alpha^2) = 3.2e7), and such a
 * surface should be treated as a delta (mirror) reflection instead.
 *
 * Index conventions follow soak/fresnel.h: eta = n_base / n_incident_medium,
 * k = extinction coefficient relative to the incident medium.
 *
 * Grazing pairs: the BRDF grows as 1 / (alpha (wi.z + wo.z)) when both
 * directions approach the horizon; where that exceeds the double range (both
 * cosines below ~1e-300, denormal) the checked BRDFs return SOAK_ERR_NUMERIC
 * rather than Inf. D, G1, G2 and the pdf stay finite for every valid input
 * (tests/c/models/test_stability.c).
 *
 * Stability: other models (porous, ww) depend on this header. */
#ifndef SOAK_GGX_H
#define SOAK_GGX_H

#include <math.h>

#include "soak/status.h"
#include "soak/vec.h"

#define SOAK_GGX_ALPHA_MIN 1e-4
#define SOAK_GGX_ALPHA_MAX 1.0
#define SOAK_GGX_UNIT_TOL 5e-6 /* on |v|: soak/vec.h's SOAK_UNIT_TOL on |v|^2 */
#define SOAK_GGX_K_MAX 1e3

/* Normal distribution D(h), 1/sr, normalised so that the integral of
 * D(h) * h.z over the hemisphere of h is 1. */
soak_status soak_ggx_D(double alpha, soak_vec3 h, double *D);

/* Smith masking G1(w) for the macro-direction w (z > 0), in (0, 1]. */
soak_status soak_ggx_G1(double alpha, soak_vec3 w, double *G);

/* Height-correlated masking-shadowing G2(wi, wo) = 1 / (1 + L(wi) + L(wo)). */
soak_status soak_ggx_G2(double alpha, soak_vec3 wi, soak_vec3 wo, double *G);

/* Cook-Torrance specular BRDF (1/sr, no cosine) of a dielectric interface:
 * f = F(wi.h, eta) D(h) G2(wi, wo) / (4 wi.z wo.z), h = normalize(wi + wo),
 * F the exact unpolarised Fresnel reflectance (total internal reflection
 * handled when eta < 1; eta == 1 gives f = 0). eta in [SOAK_ETA_MIN, SOAK_ETA_MAX]. */
soak_status soak_ggx_brdf_dielectric(double alpha, double eta, soak_vec3 wi, soak_vec3 wo, double *f);

/* Same for a conductor with relative complex index eta + i k,
 * eta in [SOAK_ETA_MIN, SOAK_ETA_MAX], k in [0, SOAK_GGX_K_MAX]. */
soak_status soak_ggx_brdf_conductor(double alpha, double eta, double k, soak_vec3 wi, soak_vec3 wo,
                                    double *f);

/* Visible-normal sampling (Heitz 2018). u1, u2 in [0, 1]. Returns a microfacet
 * normal h (h.z > 0, wo.h >= 0) and its density in solid angle of h:
 *   pdf_h = G1(wo) max(0, wo.h) D(h) / wo.z.
 * The reflected direction wi = 2 (wo.h) h - wo has density pdf_h / (4 wo.h);
 * wi may fall below the horizon, which the caller must reject. */
soak_status soak_ggx_sample_vndf(double alpha, soak_vec3 wo, double u1, double u2, soak_vec3 *h,
                                 double *pdf_h);

/* Density pdf_h of soak_ggx_sample_vndf for a given h (0 if h.z <= 0 or wo.h <= 0). */
soak_status soak_ggx_pdf_vndf(double alpha, soak_vec3 wo, soak_vec3 h, double *pdf_h);

/* ---- Unchecked forms for hot loops inside the library: inputs must already
 * be valid (alpha in range, unit vectors, wi.z > 0, wo.z > 0). ---- */

/* D from sin^2 = x^2 + y^2 rather than 1 - z^2 to avoid cancellation near
 * the peak when alpha is tiny. */
static inline double soak_ggx_D_raw(double alpha, soak_vec3 h)
{
    if (!(h.z > 0.0)) return 0.0;
    double a2 = alpha * alpha;
    double t = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
    return a2 / (SOAK_PI * t * t);
}

/* sqrt(cos^2 + alpha^2 sin^2): 2 cos (1 + Lambda(w)) in Heitz 2014 notation. */
static inline double soak_ggx_lambda_root_raw(double alpha, soak_vec3 w)
{
    return sqrt(w.z * w.z + alpha * alpha * (w.x * w.x + w.y * w.y));
}

static inline double soak_ggx_G1_raw(double alpha, soak_vec3 w)
{
    return 2.0 * w.z / (w.z + soak_ggx_lambda_root_raw(alpha, w));
}

/* Written as 2 / (ri / wi.z + ro / wo.z): each ratio is >= 1, so G2 <= 1,
 * and denormal cosines give 2 / inf = 0 instead of the 0 / 0 of
 * 2 wi.z wo.z / (ri wo.z + ro wi.z). */
static inline double soak_ggx_G2_raw(double alpha, soak_vec3 wi, soak_vec3 wo)
{
    double ri = soak_ggx_lambda_root_raw(alpha, wi);
    double ro = soak_ggx_lambda_root_raw(alpha, wo);
    return 2.0 / (ri / wi.z + ro / wo.z);
}

/* G2 / (4 wi.z wo.z), finite even as wi.z or wo.z -> 0. */
static inline double soak_ggx_vis_raw(double alpha, soak_vec3 wi, soak_vec3 wo)
{
    double ri = soak_ggx_lambda_root_raw(alpha, wi);
    double ro = soak_ggx_lambda_root_raw(alpha, wo);
    return 0.5 / (ri * wo.z + ro * wi.z);
}

/* Half vector of a reflection pair (both above the horizon, so never zero). */
static inline soak_vec3 soak_ggx_half_raw(soak_vec3 wi, soak_vec3 wo)
{
    return soak_v3_norm(soak_v3_add(wi, wo));
}

/* D(h) G2 / (4 wi.z wo.z) without Fresnel; h = half vector. */
static inline double soak_ggx_spec_raw(double alpha, soak_vec3 wi, soak_vec3 wo, soak_vec3 h)
{
    return soak_ggx_D_raw(alpha, h) * soak_ggx_vis_raw(alpha, wi, wo);
}

double soak_ggx_brdf_dielectric_raw(double alpha, double eta, soak_vec3 wi, soak_vec3 wo);
double soak_ggx_brdf_conductor_raw(double alpha, double eta, double k, soak_vec3 wi, soak_vec3 wo);

#endif
