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
 * The sheet is index matched and not backed; its error against a traced
 * slab is measured in tests/c/test_sheet.c. */
#ifndef SOAK_SHEET_H
#define SOAK_SHEET_H

#include "soak/status.h"
#include "soak/vec.h"
#include "soak/wetness.h"

/* Kubelka-Munk transmittance of a slab: K, S >= 0 (1/length), d >= 0 (length). */
soak_status soak_km_transmittance(double K, double S, double d, double *T);

/* Per channel, for wetness parameters w (sigma in 1/mm, mean cosine) and a
 * sheet thickness_mm >= 0 (0: no sheet, T = 1). */
soak_status soak_sheet_transmittance(const soak_wet_params *w, double thickness_mm, soak_rgb *T);

#endif
