/* Volumetric random walk in a participating medium bounded by a surface.
 *
 * Radiative transfer by Monte Carlo (free-flight sampling, analog direction
 * sampling from the phase function, weight = path throughput). Sources:
 *  - free flight t = -ln(1-u)/sigma_t and delta (Woodcock) tracking for
 *    heterogeneous media: Woodcock et al. 1965; Novak et al., "Monte Carlo
 *    methods for volumetric light transport simulation", CGF 37(2), 2018,
 *    sec. 4-5 (delta tracking, ratio tracking);
 *  - two-term Henyey-Greenstein phase function: soak/hg.h (seed 000 Eq. 5,
 *    corrected there);
 *  - RGB: spectral MIS over the three channels (one-sample balance heuristic,
 *    as in hero-wavelength sampling, Wilkie et al., EGSR 2014) with the
 *    channel picked in proportion to the current throughput (Chiang, Kutz,
 *    Burley, "Practical and controllable subsurface scattering for production
 *    path tracing", SIGGRAPH 2016 talk).
 *
 * Units: sigma_t is in 1/length, positions in the same length unit. The
 * single-scattering albedo is sigma_s/sigma_t; absorption is carried in the
 * weight (weight *= albedo per real collision), so no path is terminated
 * for absorption except by Russian roulette, which keeps the estimate
 * unbiased for every albedo including 1 (where weights never decay and the
 * roulette never fires).
 *
 * The surface is abstract: a soak_boundary gives the distance to it and
 * decides what happens there (Fresnel reflection/refraction with total
 * internal reflection, an index-matched exit, a diffuse base...). The planar
 * slab boundary below serves `soak measure`; the renderer supplies its own. */
#ifndef SOAK_MEDIUM_H
#define SOAK_MEDIUM_H

#include "soak/hg.h"
#include "soak/rng.h"
#include "soak/status.h"
#include "soak/vec.h"

/* Density in [0,1] at pos, scaling the majorant sigma_t. Must be pure
 * (thread-safe, no side effects). A value outside [0,1] or NaN makes the
 * walk fail with SOAK_ERR_NUMERIC (delta tracking would be biased). */
typedef double (*soak_density_fn)(const void *ctx, soak_vec3 pos);

typedef struct soak_medium {
    double sigma_t;          /* extinction, or the majorant when density != NULL; [0, 1e12] */
    double albedo;           /* single-scattering albedo sigma_s/sigma_t, [0, 1] */
    soak_hg2 phase;          /* two-term HG; {g,g,1} is a single lobe */
    soak_density_fn density; /* NULL: homogeneous */
    const void *density_ctx;
} soak_medium;

soak_status soak_medium_validate(const soak_medium *m);

/* What the surface did with a path that reached it. */
typedef enum soak_boundary_event {
    SOAK_BOUNDARY_REFLECT, /* *dir now points back into the medium: the walk goes on */
    SOAK_BOUNDARY_EXIT,    /* the path left the medium along *dir: the walk ends */
    SOAK_BOUNDARY_ABSORB   /* the surface absorbed the path: the walk ends */
} soak_boundary_event;

typedef struct soak_boundary {
    /* Distance from pos (inside) along unit dir to the surface, >= 0;
     * INFINITY if the ray never meets it. */
    double (*distance)(const void *ctx, soak_vec3 pos, soak_vec3 dir);
    /* Called at the surface point pos with the arriving direction *dir. It
     * sets *dir to the outgoing direction, may multiply *weight (a partially
     * absorbing surface) and may use rng. */
    soak_boundary_event (*interact)(const void *ctx, soak_vec3 pos, soak_vec3 *dir, double *weight,
                                    soak_rng *rng);
    const void *ctx;
} soak_boundary;

/* Called with the propagation direction before and after every real
 * scattering event (for tests and diagnostics); may be NULL. */
typedef void (*soak_scatter_fn)(void *ctx, soak_vec3 dir_in, soak_vec3 dir_out);

typedef struct soak_walk_options {
    int roulette;              /* 1: Russian roulette on the throughput (default) */
    double roulette_threshold; /* weights below this play roulette, (0,1]; default 0.25 */
    long max_events;           /* cap on tracking steps (real and null collisions plus
                                  surface interactions) per path, >= 1; default 1e6 */
    soak_scatter_fn on_scatter;
    void *scatter_ctx;
} soak_walk_options;

void soak_walk_options_default(soak_walk_options *opt);

typedef enum soak_walk_end {
    SOAK_WALK_EXITED,   /* left the medium: pos, dir, weight describe the exit */
    SOAK_WALK_ABSORBED, /* absorbed (surface, zero weight, or lost the roulette) */
    SOAK_WALK_CAPPED    /* hit max_events, or flew off to infinity parallel to a
                           surface with no extinction; weight holds the throughput
                           that was not scored, for reporting the possible bias */
} soak_walk_end;

typedef struct soak_walk_result {
    soak_walk_end end;
    soak_vec3 pos, dir; /* last position and direction */
    double weight;      /* throughput at the end (0 when absorbed) */
    long scatters;      /* real scattering events */
    long events;        /* tracking steps counted against max_events */
} soak_walk_result;

/* Random walk of one path starting at pos (inside or on the surface of the
 * medium) with unit propagation direction dir pointing into it, throughput 1.
 * opt == NULL uses the defaults. Returns SOAK_OK whatever the path's fate. */
soak_status soak_medium_walk(const soak_medium *m, const soak_walk_options *opt, soak_vec3 pos,
                             soak_vec3 dir, const soak_boundary *boundary, soak_rng *rng,
                             soak_walk_result *out);

/* Transmittance exp(-integral of sigma_t) over distance dist from pos along
 * dir: exact for a homogeneous medium, an unbiased ratio-tracking estimate
 * (Novak et al. 2018, sec. 5.1) for a heterogeneous one. */
soak_status soak_medium_transmittance(const soak_medium *m, soak_vec3 pos, soak_vec3 dir, double dist,
                                      soak_rng *rng, double *T);

/* ---- RGB ---------------------------------------------------------------
 * Homogeneous medium with per-channel extinction and albedo and one phase
 * function shared by the channels. One path carries all three channels:
 * distances are sampled from one channel picked with probability
 * proportional to its current throughput, and each channel's throughput is
 * multiplied by its own free-flight density over the mixture pdf (one-sample
 * MIS, unbiased for every channel). A channel with sigma_t = 0 is handled
 * (it never collides). Surface weights apply to all channels alike; a
 * colour-dependent surface is handled by walking per channel. Heterogeneous
 * RGB media: walk one channel per path with soak_medium_walk. */
typedef struct soak_medium_rgb {
    soak_rgb sigma_t; /* each [0, 1e12] */
    soak_rgb albedo;  /* each [0, 1] */
    soak_hg2 phase;
} soak_medium_rgb;

soak_status soak_medium_rgb_validate(const soak_medium_rgb *m);

typedef struct soak_walk_result_rgb {
    soak_walk_end end;
    soak_vec3 pos, dir;
    soak_rgb weight; /* per-channel throughput at the end */
    long scatters;
    long events;
} soak_walk_result_rgb;

/* Roulette plays on the largest channel throughput. */
soak_status soak_medium_walk_rgb(const soak_medium_rgb *m, const soak_walk_options *opt, soak_vec3 pos,
                                 soak_vec3 dir, const soak_boundary *boundary, soak_rng *rng,
                                 soak_walk_result_rgb *out);

/* ---- Planar slab boundary ----------------------------------------------
 * The medium fills -thickness <= z <= 0 (thickness = INFINITY: a half-space
 * below z = 0), with a medium of relative index n_medium/n_outside = ior on
 * both faces. At a face, a path is reflected with the exact dielectric
 * Fresnel probability (total internal reflection included, soak/fresnel.h)
 * or leaves refracted by Snell's law; ior == 1 is index-matched (always
 * leaves, undeviated). If diffuse_base is set, the bottom face is instead
 * an opaque Lambertian base of albedo base_albedo: the weight is multiplied
 * by base_albedo and the path is reflected to a cosine-distributed upward
 * direction (the smooth-film-over-a-diffuse-base configuration). */
typedef struct soak_slab_boundary {
    double thickness;   /* (0, INFINITY] */
    double ior;         /* [1, 3] */
    int diffuse_base;   /* 0 or 1 */
    double base_albedo; /* [0, 1], used when diffuse_base */
} soak_slab_boundary;

soak_status soak_slab_boundary_validate(const soak_slab_boundary *s);
/* Fills b with the slab callbacks; s must outlive b. */
soak_status soak_slab_boundary_make(const soak_slab_boundary *s, soak_boundary *b);

/* Direction refracted out of a face of the slab: incident unit dir inside
 * (dir.z != 0), ior as above. Returns 0 under total internal reflection. */
int soak_slab_refract_out(soak_vec3 dir, double ior, soak_vec3 *out);

#endif
