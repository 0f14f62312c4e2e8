/* Rain ripples on standing water (`soak bake ripples`): an animated normal
 * map that tiles in space and loops in time.
 *
 * Waves: linear capillary-gravity waves on deep water, dispersion relation
 *   omega^2 = g k + (sigma / rho) k^3
 * (H. Lamb, "Hydrodynamics", 6th ed., 1932, art. 267; J. Lighthill, "Waves
 * in Fluids", 1978, sec. 3.3). A ring's energy travels at the group velocity
 *   c_g = d omega / d k = (g + 3 (sigma / rho) k^2) / (2 omega),
 * which at the phase-speed minimum k_m = sqrt(rho g / sigma) (wavelength
 * 1.71 cm for water at 20 C) equals the phase speed, 0.231 m/s.
 *
 * Each impact of a drop of at least min_diameter (the impacts of the drops
 * bake's Marshall-Palmer / Atlas et al. flux, soak/bake_drops.h) starts one
 * ring at the carrier wavenumber k = 2 pi / wavelength (ours: one dominant
 * wavelength per ring, not the impact's full spectrum):
 *   h(r, tau) = A(tau) exp(-(r - R)^2 / (2 w^2)) cos(k r - omega tau),
 *   R = c_g tau,  A = amplitude exp(-tau / lifetime) sqrt(w / (w + R)),
 * drawn within R +- 3.5 w
 * (the square root spreads the ring's energy over its circumference; the
 * exponential is the damping, a setting). Rings older than 3 lifetimes are
 * dropped. Periodic: impacts lie on the torus [0, tile)^2 x [0, period)
 * and every ring is summed over all its periodic images in space and time,
 * so the maps tile and the last frame runs into the first.
 *
 * Output: RGBA, RGB = (n + 1) / 2 for the unit normal n = (-dh/du, -dh/dv, 1)
 * normalised, u to the right, v up the image (OpenGL / Blender convention);
 * A = 0.5 + h / (4 amplitude) clamped to [0, 1] (the height, for renderers
 * that bump from a height pattern: POV-Ray). The distance version low-passes
 * slopes and height with a wrapped Gaussian of filter_px texels before normalising
 * (a far puddle shows the mean normal, not noise). */
#ifndef SOAK_BAKE_RIPPLES_H
#define SOAK_BAKE_RIPPLES_H

#include <stddef.h>
#include <stdint.h>

#include "soak/bake.h"
#include "soak/image.h"
#include "soak/status.h"

#define SOAK_RIPPLES_MAX_FRAMES 100000
#define SOAK_RIPPLES_LIFETIMES 3.0 /* rings live this many lifetimes */

/* omega(k) (rad/s) and c_g(k) (m/s) for water at 20 C; 0 for k <= 0. */
double soak_capillary_omega(double k);
double soak_capillary_group_velocity(double k);

typedef struct soak_ripples_params {
    uint64_t seed;
    double rate_mm_h;       /* (0, 500] */
    double tile_m;          /* side of the square tile, (0, 100] m */
    int size;               /* texels per side, 1..16384 */
    int frames;             /* frames per loop, 1..100000 */
    double period;          /* loop duration, (0, 1e4] s */
    double wavelength_m;    /* carrier, (0, 10] m */
    double width_m;         /* ring envelope standard deviation w, (0, 10] m */
    double lifetime;        /* e-folding time of the amplitude, (0, 1e3] s */
    double amplitude_m;     /* ring height at impact, (0, 1] m */
    double min_diameter_mm; /* drops that make rings, [0, 6) mm */
} soak_ripples_params;

/* seed 0, 10 mm/h, 0.5 m tile at 512 texels, 64 frames over 2.56 s,
 * wavelength 2 pi / k_m (1.71 cm), width half a wavelength, lifetime 0.5 s,
 * amplitude 0.3 mm, drops from 1 mm. */
void soak_ripples_defaults(soak_ripples_params *p);
soak_status soak_ripples_check(const soak_ripples_params *p);

typedef struct soak_ripple_impact {
    double x, y, t; /* m on the tile (x right, y down the image), s in [0, period) */
} soak_ripple_impact;

/* The impacts of one loop: Poisson(n tile^2 period) points uniform on the
 * torus (n = soak_drop_flux above min_diameter); *out malloc'ed. */
soak_status soak_ripples_impacts(const soak_ripples_params *p, soak_ripple_impact **out, size_t *count);

/* Frame f (any integer; time f period / frames) of the loop made by the
 * given impacts, RGBA size x size, into out; with filter_px > 0 (at most
 * 1000) also the distance version into far: the same slopes blurred by a
 * wrapped Gaussian of that standard deviation in texels, and the height
 * with them (far may be NULL when filter_px is 0). */
soak_status soak_ripples_frame(const soak_ripples_params *p, const soak_ripple_impact *impacts, size_t count,
                               long frame, double filter_px, const soak_bake_exec *exec, soak_image *out,
                               soak_image *far);

#endif
