/* Volumetric random walk in a participating medium bounded by a surface.
 *
 * Radiative transfer by Monte Carlo (free-flight sampling, analog direction
 * sampling from the phase function, weight = path throughput). Sources:
 *  - free flight t = -ln(1-u)/sigma_t and delta (Woodcock) tracking for
 *    heterogeneous media: Woodcock et al. 1965; Novak et al., "Monte Carlo
 *    methods for volumetric light transport simulation", CGF 37(2), 2018,
 *    sec. 4-5 (delta tracking, ratio tracking);
 *  - two-term Henyey-Greenstein phase function: soak/hg.h ([JLD99] Eq. 5,
 *    corrected there);
 *  - RGB: spectral MIS over the three channels (one-sample balance heuristic,
 *    as in hero-wavelength sampling, Wilkie et al., EGSR 2014) with the
 *    channel picked in proportion to the current throughput (Chiang, Kutz,
 *    Burley, "Practical and controllable subsurface scattering for production
 *    path tracing", SIGGRAPH 2016 talk).
 *
 * Units: positions in any length unit, sigma_t per that unit. The
 * single-scattering albedo is sigma_s/sigma_t; absorption is carried in the
 * weight (weight *= albedo per real collision), so no path is terminated
 * for absorption except by Russian roulette, which keeps the estimate
 * unbiased for every albedo including 1 (where weights never decay and the
 * roulette never fires).
 *
 * The surface is abstract: a soak_boundary gives the distance to it and
 * decides what happens there (Fresnel reflection/refraction with total
 * internal reflection, an index-matched exit, a diffuse base...). The planar
 * slab boundary below serves `soak measure`; the renderer supplies its own
 * (ray-cast mesh, wet film stack) and its next-event estimation through the
 * soak_vertex_fn hook.
 *
 * One walk serves every medium: soak_medium_walk (scalar, optionally
 * heterogeneous) runs soak_medium_walk_rgb with three equal channels. */
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
     * INFINITY if the ray never meets it. The context is const for the walk;
     * a boundary that must remember the surface it found (a ray-cast hit)
     * keeps it behind a pointer in its context. */
    double (*distance)(const void *ctx, soak_vec3 pos, soak_vec3 dir);
    /* Called at the surface point *pos with the arriving direction *dir. It
     * sets *dir to the outgoing direction, may multiply the per-channel
     * *weight (a partially absorbing surface, a coloured film), may move
     * *pos off the surface (a ray-tracing offset) and may use rng. */
    soak_boundary_event (*interact)(const void *ctx, soak_vec3 *pos, soak_vec3 *dir, soak_rgb *weight,
                                    soak_rng *rng);
    const void *ctx;
    /* Optional (NULL: distance is asked before every flight). A cheap,
     * conservative test: returns 0 only if the surface is certainly farther
     * than dist (finite, >= 0) from pos along dir, else 1. When it is set,
     * the homogeneous walk samples the flight distance t first and calls
     * distance only if within(t) is 1, so in a dense medium most flights end
     * at a collision after one cheap test (e.g. an occlusion ray) instead of
     * a closest-hit query. The random numbers drawn are the same either way
     * (the boundary's queries draw none). Heterogeneous media always ask
     * distance first. */
    int (*within)(const void *ctx, soak_vec3 pos, soak_vec3 dir, double dist);
} soak_boundary;

/* Coefficients of a medium at one point (1/length), for heterogeneous RGB
 * media and for the vertex hook. */
typedef struct soak_medium_point {
    soak_rgb sigma_s, sigma_a;
    soak_hg2 phase;
} soak_medium_point;

/* Called with the propagation direction before and after every real
 * scattering event (for tests and diagnostics); may be NULL. */
typedef void (*soak_scatter_fn)(void *ctx, soak_vec3 dir_in, soak_vec3 dir_out);

/* Called at every real scattering event at pos, before the new direction is
 * sampled: dir_in is the propagation direction, weight the per-channel
 * throughput after the collision (what an in-scattering estimate there is
 * multiplied by), local the medium at pos. It may add a next-event estimate
 * to its own tally and may use rng. Returning 0 ends the walk there
 * (SOAK_WALK_STOPPED), e.g. a photon stored at its first scattering. */
typedef int (*soak_vertex_fn)(void *ctx, soak_vec3 pos, soak_vec3 dir_in, soak_rgb weight,
                              const soak_medium_point *local, soak_rng *rng);

typedef struct soak_walk_options {
    int roulette;              /* 1: Russian roulette on the throughput (default) */
    double roulette_threshold; /* weights below this play roulette, (0,1]; default 0.25 */
    long max_events;           /* cap on tracking steps (real and null collisions plus
                                  surface interactions) per path, >= 1; default 1e6 */
    soak_rgb weight;           /* throughput on entry, each [0, 1e300]; default 1 (RGB
                                  walk only: channel choice and roulette act on it) */
    soak_scatter_fn on_scatter;
    void *scatter_ctx;
    soak_vertex_fn on_vertex;
    void *vertex_ctx;
    /* Guided walk (homogeneous media only; a grid medium ignores it): a
     * direction sampled at a scattering event comes, with probability
     * guide_prob, from the Dwivedi guide toward the plane of outward unit
     * normal guide_normal (soak/dwivedi.h) with its stretched flight
     * distance, else from the phase function with the analog flight; the
     * weights use the one-sample MIS (balance heuristic) pdf of both over
     * direction and distance, so the estimate is unbiased for any normal.
     * guide_prob in [0, 0.99]; 0 (default) is the analog walk. */
    double guide_prob;
    soak_vec3 guide_normal;
} soak_walk_options;

void soak_walk_options_default(soak_walk_options *opt);

typedef enum soak_walk_end {
    SOAK_WALK_EXITED,   /* left the medium: pos, dir, weight describe the exit */
    SOAK_WALK_ABSORBED, /* absorbed (surface, zero weight, or lost the roulette) */
    SOAK_WALK_CAPPED,   /* hit max_events, or flew off to infinity parallel to a
                           surface with no extinction; weight holds the throughput
                           that was not scored, for reporting the possible bias */
    SOAK_WALK_STOPPED   /* the vertex hook ended the walk at pos (weight as it saw it) */
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
 * One path carries all three channels.
 *
 * Homogeneous (coeffs == NULL): per-channel extinction and albedo, one phase
 * function. Distances are sampled from one channel picked with probability
 * proportional to its current throughput, and each channel's throughput is
 * multiplied by its own free-flight density over the mixture pdf (one-sample
 * MIS, unbiased for every channel); with equal extinctions no channel is
 * picked. A channel with sigma_t = 0 is handled (it never collides).
 *
 * Heterogeneous (coeffs != NULL): coeffs gives sigma_s, sigma_a and the
 * phase function at a point; sigma_t, albedo and phase above are then not
 * used. Spectral tracking (Kutz, Habel, Li, Novak, "Spectral and
 * decomposition tracking for rendering heterogeneous volumes", SIGGRAPH
 * 2017, sec. 5.2) against the majorant mu >= sigma_s + sigma_a of every
 * channel everywhere: a tentative collision is real with probability
 * P = m_t / (m_t + m_n), m_t = max_c beta_c sigma_t,c, m_n = max_c beta_c
 * (mu - sigma_t,c), and then beta_c *= sigma_s,c / (mu P) (absorption carried
 * in the weight), else null with beta_c *= (mu - sigma_t,c) / (mu (1-P)).
 * With equal channels this is Woodcock delta tracking exactly (P =
 * sigma_t/mu, weight *= albedo). A point whose extinction exceeds the
 * majorant by more than 1e-9 relative fails with SOAK_ERR_NUMERIC. */
typedef soak_status (*soak_coeffs_fn)(const void *ctx, soak_vec3 pos, soak_medium_point *out);

typedef struct soak_medium_rgb {
    soak_rgb sigma_t; /* each [0, 1e12] */
    soak_rgb albedo;  /* each [0, 1] */
    soak_hg2 phase;
    soak_coeffs_fn coeffs; /* NULL: homogeneous */
    const void *coeffs_ctx;
    double majorant; /* heterogeneous only, [0, 1e12] */
} soak_medium_rgb;

soak_status soak_medium_rgb_validate(const soak_medium_rgb *m);

typedef struct soak_walk_result_rgb {
    soak_walk_end end;
    soak_vec3 pos, dir;
    soak_rgb weight; /* per-channel throughput at the end */
    long scatters;
    long events;
} soak_walk_result_rgb;

/* Roulette plays on the largest channel throughput. The surface may weight
 * the channels differently. */
soak_status soak_medium_walk_rgb(const soak_medium_rgb *m, const soak_walk_options *opt, soak_vec3 pos,
                                 soak_vec3 dir, const soak_boundary *boundary, soak_rng *rng,
                                 soak_walk_result_rgb *out);

/* Per-channel transmittance over distance dist from pos along dir, as
 * soak_medium_transmittance (ratio tracking against the majorant when
 * heterogeneous). */
soak_status soak_medium_rgb_transmittance(const soak_medium_rgb *m, soak_vec3 pos, soak_vec3 dir, double dist,
                                          soak_rng *rng, soak_rgb *T);

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
