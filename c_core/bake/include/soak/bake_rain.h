/* Rain wetting of a mesh, baked into its UV texture.
 *
 * [Hnat06] (Hnat et al. 2006, sec. 3.3.1 and 5) computes a mesh's rain wet
 * map as the light map of an emissive plane above it, then adds drop impacts
 * rendered into a "drops texture". We compute the real quantities instead:
 *
 * 1. Surface sampling. Every triangle is rasterised in UV space (texel
 *    centres, v = 0 at the bottom image row); a texel covered by a triangle
 *    gets that triangle's surface point p, unit normal n (the geometric
 *    normal turned to the side of the interpolated vertex normal) and world
 *    area (triangle area / UV area * texel UV area). Overlapping UVs: the
 *    first triangle in index order wins. Texels outside every triangle stay
 *    empty (value 0, later filled by a `gutter`-texel dilation).
 *
 * 2. Sky exposure (Monte Carlo, Embree occlusion queries through
 *    soak/geometry.h). Rain arrives from directions u (unit, pointing to the
 *    sky) with a density p(u); the flux onto a surface element is
 *    F(n) = integral p(u) V(p, u) max(0, n.u) du (V = 1 when the ray from p
 *    along u escapes the mesh). Exposure is F(n) / F_open, F_open =
 *    integral p(u) (up.u) du the flux onto an open horizontal surface, so an
 *    open upward plane has exposure 1 and a roofed floor 0. Estimator:
 *    E = (1/N) sum V_i max(0, n.u_i) / F_open with u_i ~ p stratified in
 *    cos theta (N = rays per texel, counter-based random numbers of
 *    (seed, texel), so results do not depend on the thread count).
 *      rain sky: p uniform in solid angle over the cone of half-angle
 *        `spread` around `rain_dir`; F_open = rain_dir.up (1 + cos spread)/2
 *        (mean cosine of the cone, times the tilt).
 *      hemisphere sky ([Hnat06]'s emissive sky, = ambient occlusion): u
 *        cosine-distributed about n, E = (1/N) sum V_i; open plane 1.
 *
 * 3. Rain over time, steps of dt = duration / steps:
 *    - drop impacts: a Poisson process; the number of drops landing in a
 *      texel in a step is Poisson(lambda), lambda = rate_drops * E * A * dt,
 *      rate_drops = rainfall / drop volume (drops per horizontal area per
 *      time). Counts are drawn per (seed, step, texel) by inversion
 *      (lambda > 30: normal approximation, rounded, >= 0).
 *    - splat: each drop's volume is spread by a normalised Gaussian kernel of
 *      standard deviation splat_radius (world length, converted to texels at
 *      the mean texel size), added as depth = volume / area;
 *    - evaporation: depth -= evaporation * dt, not below 0;
 *    - downhill flow: water above the film a surface retains
 *      (retention * max(0, n.up)) is mobile and is routed over the surface by
 *      a multiple-flow-direction scheme (Quinn et al. 1991, "The prediction of
 *      hillslope flow paths for distributed hydrological modelling using
 *      digital terrain models", Hydrol. Process. 5): from texel i to each
 *      3D-adjacent neighbour j in proportion to the drop of the water level
 *      s = p.up + depth, at most half the largest level difference per
 *      iteration (so levels never cross: flat puddles form in concave,
 *      upward-facing regions). A texel whose downhill direction leads off
 *      the surface (an open edge) or that faces down drains its mobile water
 *      off the mesh (drips). flow_iterations routing sweeps per step.
 * 4. Output wetness w = 1 - exp(-depth / saturation_depth) in [0,1]; the
 *    exposure and the water depth are available too.
 *
 * Lengths are in the mesh's unit (metres assumed for the rainfall rates);
 * times in seconds. */
#ifndef SOAK_BAKE_RAIN_H
#define SOAK_BAKE_RAIN_H

#include <stdint.h>

#include "soak/bake.h"
#include "soak/geometry.h"
#include "soak/image.h"
#include "soak/status.h"
#include "soak/vec.h"

typedef enum soak_rain_sky {
    SOAK_RAIN_SKY_RAIN = 0,   /* cone of rain directions (default) */
    SOAK_RAIN_SKY_HEMISPHERE  /* cosine-weighted hemisphere about n (ambient occlusion) */
} soak_rain_sky;

/* Limits of soak_rain_params (soak_rain_check). */
#define SOAK_RAIN_MAX_RAYS 65536
#define SOAK_RAIN_MAX_SPREAD 89      /* degrees */
#define SOAK_RAIN_MAX_DURATION 1e7   /* s */
#define SOAK_RAIN_MAX_STEPS 100000   /* time steps, flow iterations */
#define SOAK_RAIN_MAX_RATE 1000      /* rainfall, evaporation, mm/h */
#define SOAK_RAIN_MAX_DROP 0.01      /* drop diameter, m */
#define SOAK_RAIN_MAX_SPLAT 1        /* m */
#define SOAK_RAIN_MAX_RETENTION 0.1  /* m */
#define SOAK_RAIN_MAX_SATURATION 1   /* m */
#define SOAK_RAIN_MAX_GUTTER 64      /* texels */

typedef struct soak_rain_params {
    uint64_t seed;
    int rays;               /* rays per texel, 1..65536 */
    soak_rain_sky sky;
    soak_vec3 up;           /* world up (unit after normalisation; non-zero) */
    soak_vec3 rain_dir;     /* mean direction the rain comes from (toward the sky), rain_dir.up > 0 */
    double spread_deg;      /* cone half-angle, [0, 89] */
    double duration;        /* s, [0, 1e7]; 0 = exposure only, no water */
    int steps;              /* 1..100000 */
    double rainfall_mm_h;   /* [0, 1000] mm/h of water on a horizontal surface */
    double drop_diameter;   /* m, (0, 0.01] */
    double splat_radius;    /* m, [0, 1]; 0 = drop stays in its texel */
    double evaporation_mm_h;/* [0, 1000] */
    double retention;       /* film depth kept on a flat surface, m, [0, 0.1] */
    double saturation_depth;/* depth for w = 1 - 1/e, m, (0, 1] */
    int flow_iterations;    /* routing sweeps per step, 0..100000 */
    int gutter;             /* texels of dilation into empty texels, 0..64 */
} soak_rain_params;

/* seed 0, 64 rays, rain sky, up +z, rain from +z, spread 10 deg, 600 s in
 * 32 steps, 10 mm/h, 2 mm drops, splat 2 mm, evaporation 0.5 mm/h,
 * retention 0.2 mm, saturation 0.2 mm, 16 flow iterations, gutter 4. */
void soak_rain_defaults(soak_rain_params *p);
soak_status soak_rain_check(const soak_rain_params *p);

typedef struct soak_rain_result {
    soak_image wetness;  /* 1 channel, [0,1] */
    soak_image exposure; /* 1 channel, >= 0 (1 = open horizontal surface) */
    soak_image water;    /* 1 channel, water depth, m */
    soak_image coverage; /* 1 channel, 1 where a triangle covers the texel centre */
} soak_rain_result;

/* Bakes at width x height (soak_bake_check_size). The mesh must have UVs
 * (SOAK_ERR_ARG with "mesh has no UVs" in err otherwise) and at least one
 * triangle. The geometry used for occlusion is built from the mesh inside.
 * On SOAK_OK every image of out is allocated (free with
 * soak_rain_result_free); on error nothing is. */
soak_status soak_bake_rain(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                           const soak_bake_exec *exec, soak_rain_result *out, char *err, size_t errlen);
void soak_rain_result_free(soak_rain_result *r);

#endif
