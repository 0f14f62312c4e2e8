/* What is left of a surface's own specular reflection under the liquid, and
 * the liquid's own mirror, for renderers whose surface model has one base
 * specular lobe and one clear-coat lobe (Blender's Principled BSDF).
 *
 * 1. Dielectric base under a film (wetness.h step 5's interface, normal
 *    incidence, incoherent sum over the film as for conductors there): the
 *    base's specular is now reflected at the base-liquid boundary (relative
 *    index n / n_liquid) and passes the liquid-air boundary twice,
 *      R_under = (1 - R12)^2 R23 e / (1 - R12 R23 e),
 *      R12 = F0(n_liquid), R23 = F0(n / n_liquid), e = exp(-2 sigma_a h);
 *    over the coverage c it replaces the dry F0(n):
 *      base_factor = (1 - c) + c R_under / F0(n)   (channel mean).
 *    Below saturation the grains' tops stay in air ([Hnat06], Merillou/Hnat:
 *    the material's specular weight does not change with pore filling), so
 *    only the film counts. Sand under its water film: 0.11.
 *    Conductors: 1 (their specular is the base colour, wetness.h step 5).
 *
 * 2. The liquid's mirror: the interface area of wetness.h step 5 (film plus
 *    the uncovered water-filled pores), soak_wet_interface_area.
 *
 * 3. Apparent roughness of a conductor under the film: seen through a flat
 *    film of index n_liquid a GGX lobe of width alpha is refracted: internal
 *    angles are 1/n_liquid of the external ones near the normal, and
 *    D(theta / n; alpha) = n^2 D(theta; n alpha) for GGX at small angles,
 *    the n^2 cancelling the radiance's n^2 (Veach 1997 sec. 5.2 for the
 *    n^2 of radiance at a boundary). So the film-covered part looks like a
 *    GGX lobe of width n_liquid alpha (clamped to 1); one lobe for the
 *    mixture: alpha_apparent = alpha (1 + c (n_liquid - 1)). Dielectrics keep
 *    the chain's wet alpha (their remaining base lobe is at most base_factor
 *    of the dry one). */
#ifndef SOAK_WET_SPECULAR_H
#define SOAK_WET_SPECULAR_H

#include "soak/preset.h"
#include "soak/status.h"
#include "soak/wetness.h"

typedef struct soak_wet_specular {
    double base_factor;    /* the base's own specular over its dry value, [0, 1] */
    double interface_area; /* weight of the liquid's mirror lobe, [0, 1] */
    double ggx_alpha;      /* apparent GGX alpha of the base lobe, (0, 1] */
} soak_wet_specular;

/* w: soak_wetness_eval of preset and liquid. SOAK_ERR_NULL / SOAK_ERR_ARG on
 * bad input; out free of NaN/Inf and written only on SOAK_OK. */
soak_status soak_wet_specular_eval(const soak_preset *preset, const soak_liquid *liquid, const soak_wet_params *w,
                                   soak_wet_specular *out);

/* R_under of point 1 for one channel: a base of relative index eta_base
 * (to air, >= 1) under a liquid of index n_liquid, two-pass transmittance
 * two_pass in [0, 1]. */
soak_status soak_wet_specular_under(double eta_base, double n_liquid, double two_pass, double *R);

#endif
