/* Jensen-Legakis-Dorsey two-layer surface ([JLD99], Eq. 1-4): a smooth
 * liquid film (index n2) between air (n1) and a scattering material (n3).
 *
 * Readings and corrections of the seed (each tested in tests/c/models/test_jensen.c):
 *  - Radiance divided by n^2 is invariant across a smooth interface (besides
 *    the 1 - F loss), so radiance carried by light crossing from medium a
 *    into medium b is multiplied by (n_b/n_a)^2 (1 - F). Eq. 1/2 print
 *    (n1/n2)^2 and (n2/n3)^2 under the label "1->2", "2->3": that is the
 *    factor for light travelling the other way (b -> a), i.e. for radiance
 *    gathered along a ray traced from the viewer into the material. Read that
 *    way Eq. 1 x Eq. 2 gives Eq. 4's (n1/n3)^2 (1-F12)(1-F23^k), which is
 *    correct for a viewer in air seeing L_s from inside (radiance_out).
 *    For light actually entering (photons, shadow rays) the radiance factor
 *    is the inverse, (n3/n1)^2; the flux (energy) fraction carries no n
 *    factor. We expose the flux transmittance and the radiance factor
 *    separately.
 *  - Shadow rays: [JLD99] applies Eq. 4 to the light entering at the shadow
 *    ray's hit point from a distant light. Eq. 4's (n1/n3)^2 belongs to
 *    light leaving the material; for light entering, a distant (delta)
 *    light of irradiance E0 (perpendicular to its beam) is carried by flux:
 *    the fraction T = (1-F12)(1-F23^k) of the flux crossing the surface
 *    enters, and the refracted beam, whose cross-section shrinks from cos1
 *    to cos3 of the surface area, has perpendicular irradiance
 *    E0 T cos1/cos3 inside. Using (n1/n3)^2 T instead would remove ~56% of
 *    the light for n3 = 1.5.
 *  - The interfaces are flat and parallel, so n sin(theta) is the same in
 *    all three media: the direction in the material follows from n1 -> n3
 *    directly (n2 cancels); F23 is evaluated at cos2 (seed: "w2 is the
 *    refracted direction into the liquid").
 *  - k raises F23 to a power ("simulating surface roughness"); k = 1 is a
 *    smooth interface. For k > 1, F^k <= F at every angle, so transmission
 *    never decreases; [JLD99] says the gain is largest at non-grazing
 *    angles, which holds because (1 - F12) -> 0 at grazing incidence
 *    (tested for water over n3 = 1.5). We accept k in [0.01, 100].
 *  - Going up from inside, either interface can totally reflect: T = 0.
 *    Going down, the same can happen when n1 > n2 or n1 > n3 (indices in
 *    [1,3] allow it): T = 0 and cos3 = 0.
 * Cosines are accepted in [0,1]; 0 is grazing (T = 0 unless all three
 * indices are equal, which is no interface at all: T = 1). */
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

/* Light from air at cos1 [0,1] into the material. T: flux transmittance
 * (1-F12)(1-F23^k) in [0,1]; cos3: cosine of the refracted direction in the
 * material. Either output pointer may be NULL. */
soak_status soak_jensen_transmit_down(const soak_jensen_layer *l, double cos1, double *T, double *cos3);

/* Light from inside the material at cos3 [0,1] going up and out into air.
 * T = 0 with *tir = 1 under total internal reflection at either interface. */
soak_status soak_jensen_transmit_up(const soak_jensen_layer *l, double cos3, double *T, double *cos1, int *tir);

/* Eq. 4 radiance factor for a viewer in air gathering radiance from inside:
 * (n1/n3)^2 * T_up. The inverse direction multiplies by (n3/n1)^2. */
soak_status soak_jensen_radiance_out(const soak_jensen_layer *l, double cos3, double *factor);

/* Reflectance of the film's top surface (the delta lobe) at cos1. */
soak_status soak_jensen_reflect_top(const soak_jensen_layer *l, double cos1, double *R);

/* Transmittance for a shadow ray from a distant light at cos1 entering the
 * material ([JLD99] uses Eq. 4 on shadow rays; see above): the flux
 * fraction, equal to soak_jensen_transmit_down's T. The beam inside has
 * perpendicular irradiance E0 * T * cos1 / cos3. */
soak_status soak_jensen_shadow(const soak_jensen_layer *l, double cos1, double *T);

#endif
