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
 *    only the film counts: the lobe in air weighs ks (1 - c). Sand under its water film: 0.11.
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
 *    of the dry one).
 *
 * 4. The same rule where a renderer draws the surface's parts one at a time
 *    (soak render: a dry part, the film over c, the pore water over
 *    A - c = (1 - c) p f, A = soak_wet_interface_area, p porosity, f fill).
 *    Below the film the surface is grain tops (area fraction 1 - p, where
 *    Merillou/Hnat's weight ks = 1 - p sits: [Hnat06] Eq. 3 at G_p = 1),
 *    empty pores (p (1 - f)) and water-filled pores (p f). The pore water is
 *    a flat liquid surface over the pore's interior: the liquid interface
 *    over the body, with no grain facet under it. So the grain lobe stays in
 *    air over (1 - c) ks of the point, and all of it lies in the dry part,
 *    whose area is (1 - c)(1 - p f); its coat weight k_dry solves
 *      k_dry (1 - c)(1 - p f) = ks (1 - c):   k_dry = ks / (1 - p f),
 *    independent of c (the film takes grains and pores alike). With
 *    ks = 1 - p, k_dry = (1 - p) / (1 - p f) is the grains' share of the dry
 *    part: 1 - p dry (f = 0), 1 once the pores are full (f = 1). Clamped to
 *    1 (only a ks above 1 - p f could exceed it); at p f -> 1 the dry part
 *    has no area and the weight is ks (soak_wet_grain_coat_weight). */
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

/* k_dry of point 4: the material's own lobe weight over the part of the
 * surface in air that is not pore water (grains and empty pores), from w's
 * specular_weight ks and water_specular_weight p f: min(1, ks / (1 - p f)),
 * ks where 1 - p f < 1e-9. In [0, 1]; 0 for NULL or a weight outside [0, 1]. */
double soak_wet_grain_coat_weight(const soak_wet_params *w);

/* R_under of point 1 for one channel: a base of relative index eta_base
 * (to air, >= 1) under a liquid of index n_liquid, two-pass transmittance
 * two_pass in [0, 1]. */
soak_status soak_wet_specular_under(double eta_base, double n_liquid, double two_pass, double *R);

#endif
