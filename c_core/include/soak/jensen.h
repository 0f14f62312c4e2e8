/* Jensen-Legakis-Dorsey two-layer surface (seed 000, Eq. 1-4): a smooth
 * liquid film (index n2) between air (n1) and a scattering material (n3).
 *
 * Corrections and readings of the seed (each tested):
 *  - Eq. 1/2 print the radiance factor as (n1/n2)^2 for the 1->2 direction.
 *    Radiance divided by n^2 is invariant across a smooth interface, so the
 *    factor for radiance crossing from medium a into medium b is (n_b/n_a)^2.
 *    The seed's factor is the one for the backward (b->a) direction, which is
 *    what Eq. 4 needs when it gathers L_s from inside the material for a
 *    viewer in air: (n1/n3)^2 (1-F12)(1-F23^k).  We expose the flux
 *    (energy) transmittance and the radiance factor separately.
 *  - The film is thin and flat, so the direction in the material is given
 *    by Snell's law from n1 to n3 directly (n2 cancels); cos2 is used for F23.
 *  - k (roughness exponent, k >= 1 in the seed) raises F23 to k; k = 1 is a
 *    smooth interface. We accept k in [0.01, 100].
 *  - Going up from inside, F21 can be total internal reflection: T = 0. */
#ifndef SOAK_JENSEN_H
#define SOAK_JENSEN_H

#include "soak/status.h"

typedef struct soak_jensen_layer {
    double n1; /* outside (air), [1, 3] */
    double n2; /* liquid film, [1, 3]; n2 == n1 means no film */
    double n3; /* material, [1, 3] */
    double k;  /* Fresnel exponent of the liquid-material interface */
} soak_jensen_layer;

soak_status soak_jensen_validate(const soak_jensen_layer *l);

/* Light from air at cos1 (0,1] into the material. T: flux transmittance
 * (1-F12)(1-F23^k) in [0,1]; cos3: cosine of the refracted direction in the
 * material. Either output pointer may be NULL. */
soak_status soak_jensen_transmit_down(const soak_jensen_layer *l, double cos1, double *T, double *cos3);

/* Light from inside the material at cos3 (0,1] going up and out into air.
 * T = 0 with *tir = 1 under total internal reflection at either interface. */
soak_status soak_jensen_transmit_up(const soak_jensen_layer *l, double cos3, double *T, double *cos1, int *tir);

/* Eq. 4 radiance factor for a viewer in air gathering radiance from inside:
 * (n1/n3)^2 * T_up. The inverse direction multiplies by (n3/n1)^2. */
soak_status soak_jensen_radiance_out(const soak_jensen_layer *l, double cos3, double *factor);

/* Reflectance of the film's top surface (the delta lobe) at cos1. */
soak_status soak_jensen_reflect_top(const soak_jensen_layer *l, double cos1, double *R);

/* Transmittance for a shadow ray from a distant light at cos1 entering the
 * material (seed 000 uses Eq. 4 on shadow rays): equals soak_jensen_transmit_down's T. */
soak_status soak_jensen_shadow(const soak_jensen_layer *l, double cos1, double *T);

#endif
