/* Caustic photons traced from the lights (render_photons.c). */
#ifndef SOAK_RENDER_PHOTONS_H
#define SOAK_RENDER_PHOTONS_H

#include <signal.h>

#include "rt_ctx.h"
#include "render_photon_map.h"

/* Traces n photons from the sun and point lights through dielectric objects
 * and stores them at their first scattering event inside a wet medium.
 * Stops early (keeping what is traced, rescaled) when *cancel becomes
 * non-zero or the monotonic clock passes deadline (0: none). */
soak_status rt_photons_build(const rt_ctx *c, long long n, double radius, uint64_t seed,
                             const volatile sig_atomic_t *cancel, double deadline, rt_photon_map *map);

#endif
