/* Diffuse transmittance of a thin scattering sheet (wet paper, cloth) for
 * front ends that cannot trace the medium: a two-flux (Kubelka-Munk) slab
 * with coefficients from the transport ones.
 *
 * Sources: P. Kubelka, "New contributions to the optics of intensely
 * light-scattering materials", JOSA 38(5), 1948 (slab reflectance and
 * transmittance without boundaries); M. J. C. van Gemert & W. M. Star,
 * "Relations between the Kubelka-Munk and the transport equation models for
 * anisotropic scattering", Lasers in the Life Sciences 1(4), 1987:
 *     K = 2 sigma_a,    S = 3/4 sigma_s (1 - g) - 1/4 sigma_a   (S >= 0).
 * Written without the a = (S+K)/S, b = sqrt(a^2-1) division so that S = 0
 * (pure absorber: T = exp(-K d)) and K = 0 (T = 1/(1 + S d)) are exact:
 *     x = d sqrt(K^2 + 2 K S),   T = 1 / ((S + K) d sinh(x)/x + cosh(x)).
 * Boundaries (a sheet of index n in air, lit and seen diffusely): J. L.
 * Saunderson, "Calculation of the color of pigmented plastics", JOSA 32(12),
 * 1942 -- light crossing an interface into the sheet keeps 1 - r_e, light
 * inside meets the faces with the internal diffuse reflectance r_i. Adding
 * the two faces to the slab (R, T of the two-flux slab) gives
 *     T_n = (1 - r_e)(1 - r_i) T / ((1 - r_i R)^2 - (r_i T)^2),
 * with r_e, r_i the cosine-weighted hemispherical Fresnel averages outside
 * and inside (soak_fresnel_dielectric_avg at n and 1/n; total internal
 * reflection included). n = 1 gives r_e = r_i = 0 and T_n = T. The sheet is
 * not backed; its error against traced slabs (index matched and n = 1.53)
 * is measured in tests/c/export/test_export.c. */
#ifndef SOAK_SHEET_H
#define SOAK_SHEET_H

#include "soak/status.h"
#include "soak/vec.h"
#include "soak/wetness.h"

/* Kubelka-Munk transmittance of a slab: K, S >= 0 (1/length), d >= 0 (length). */
soak_status soak_km_transmittance(double K, double S, double d, double *T);

/* Kubelka-Munk reflectance and transmittance of a slab (as above). */
soak_status soak_km_slab(double K, double S, double d, double *R, double *T);

/* Per channel, for wetness parameters w (sigma_s_per_m, sigma_a_per_m,
 * mean cosine), a sheet thickness_m in [0, 1000] m (0: no sheet, T = 1: its
 * faces vanish with it) and the sheet's index ior in [1, 3] relative to air
 * (1: index matched). */
soak_status soak_sheet_transmittance(const soak_wet_params *w, double thickness_m, double ior, soak_rgb *T);

#endif
