/* Diffuse reflectance of a semi-infinite, index-matched scattering medium
 * and its inverse: the bridge between an albedo (what a texture or a
 * colour chart gives) and a single-scattering albedo omega (what a
 * participating-media renderer needs).
 *
 * Source: H. C. van de Hulst, "Multiple Light Scattering: Tables, Formulas
 * and Applications", vol. 2, Academic Press 1980 -- the approximation of
 * the spherical (diffuse-illumination) albedo of a semi-infinite medium
 *     R(s) = (1 - s)(1 - 0.139 s) / (1 + 1.17 s),
 *     s    = sqrt((1 - omega) / (1 - g omega)),
 * as used for albedo inversion by C. Kulla & A. Conty, "Revisiting Physically
 * Based Shading at Imageworks", SIGGRAPH 2017 course. s depends on omega and
 * the mean cosine g only through the similarity relation (reduced albedo
 * omega' = omega (1 - g) / (1 - omega g), s = sqrt(1 - omega')).
 *
 * Inverse: R(s) = R0 is the quadratic 0.139 s^2 - (1.139 + 1.17 R0) s +
 * (1 - R0) = 0, whose smaller root lies in [0, 1] (R is strictly decreasing
 * from R(0) = 1 to R(1) = 0); it is taken in the cancellation-free form
 * s = 2 c / (b + sqrt(b^2 - 4 a c)). Then omega = (1 - s^2) / (1 - g s^2),
 * exact inversion of the definition of s. No iteration is needed.
 *
 * Limits: R = 1 <-> omega = 1 (s = 0) and R = 0 <-> omega = 0 (s = 1) for any
 * g; both are exact. The boundary is index matched: a refractive boundary
 * would lower R; that is left to front ends that trace the medium. */
#ifndef SOAK_VDHULST_H
#define SOAK_VDHULST_H

#include "soak/hg.h"
#include "soak/status.h"

/* R(omega, g): omega in [0,1], g in [-SOAK_HG_G_MAX, SOAK_HG_G_MAX]. */
soak_status soak_vdhulst_albedo(double omega, double g, double *albedo);

/* omega(R, g): albedo in [0,1]; same g range. */
soak_status soak_vdhulst_invert(double albedo, double g, double *omega);

/* R as a function of the similarity parameter s in [0,1] (no checks). */
double soak_vdhulst_albedo_s_raw(double s);
/* The inverse of it: s for R in [0,1] (no checks). */
double soak_vdhulst_s_of_albedo_raw(double albedo);

#endif
