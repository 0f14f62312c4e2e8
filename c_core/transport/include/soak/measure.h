/* Virtual gonio-reflectometer: reflectance and transmittance of canonical
 * configurations measured by tracing photons through the actual geometry and
 * media (soak/medium.h); no closed form is used. The analytic and numeric
 * references live in the tests (tests/c/transport/test_measure_*.c).
 *
 * Geometry (infinite, plane-parallel; the top surface is z = 0, air above):
 *  - FILM: smooth liquid film of index ior over an opaque Lambertian base of
 *    albedo base_albedo; Fresnel reflection/refraction at the film top (total
 *    internal reflection included), diffuse bounces at the base, optional
 *    Beer-Lambert absorption (alpha, thickness) along the actual slanted
 *    paths in the film. R = all light leaving upwards (specular included).
 *  - HALFSPACE: semi-infinite medium below z = 0, extinction 1 (lengths are
 *    optical depths), single-scattering albedo, two-term HG phase function,
 *    relative index ior with Fresnel boundary (1 = index-matched).
 *  - COATED: the material's own rough interface over its body, as the
 *    renderer's preset materials have it (soak/bsdf.h COATED): a GGX
 *    microsurface of width coat_alpha and index coat_ior (relative to the
 *    air; to the film's liquid under a film) whose facets reflect with
 *    probability coat_weight x Fresnel and masking, over a Lambertian body
 *    of albedo base_albedo, under a smooth film of index ior (1 = none) with
 *    absorption film_alpha over film_thickness. Traced facet by facet
 *    (measure_coated.c), first-surface: light leaving the body meets the
 *    same facets from below.
 *  - SLAB: as HALFSPACE with optical thickness tau and the same interface
 *    at its bottom face; T = all light leaving downwards (unscattered beam
 *    included).
 * Incidence: collimated at cos_incidence, or diffuse (cosine-weighted over
 * the upper hemisphere, i.e. uniform radiance).
 *
 * Reproducibility: path i always uses RNG stream i of the seed, and paths
 * are summed in fixed blocks in path order, so the result depends only on
 * the setup and seed, not on the thread count. */
#ifndef SOAK_MEASURE_H
#define SOAK_MEASURE_H

#include <stdint.h>

#include "soak/hg.h"
#include "soak/status.h"

typedef enum soak_measure_config {
    SOAK_MEASURE_FILM,
    SOAK_MEASURE_HALFSPACE,
    SOAK_MEASURE_SLAB,
    SOAK_MEASURE_COATED
} soak_measure_config;

typedef enum soak_measure_quantity {
    SOAK_MEASURE_R, /* reflectance (every configuration) */
    SOAK_MEASURE_T  /* transmittance (SLAB only) */
} soak_measure_quantity;

/* Limits of soak_measure_setup (soak_measure_validate); `soak measure` takes
 * its option ranges from here and from soak/film.h. */
#define SOAK_MEASURE_MIN_IOR 1.0
#define SOAK_MEASURE_MAX_IOR 3.0
#define SOAK_MEASURE_MAX_TAU 1e6
#define SOAK_MEASURE_MAX_PATHS 1000000000000LL
#define SOAK_MEASURE_MAX_THREADS 256

typedef struct soak_measure_setup {
    soak_measure_config config;
    soak_measure_quantity quantity;
    int diffuse_incidence;  /* 1: diffuse; 0: collimated at cos_incidence */
    double cos_incidence;   /* (0, 1] */
    double ior;             /* [1, 3] film or medium index relative to the air */
    /* FILM */
    double base_albedo;     /* [0, 1] */
    double film_alpha;      /* absorption coefficient 1/m, [0, 1e6] */
    double film_thickness;  /* m, [0, 1e3]; 0 = no absorption */
    /* COATED (with base_albedo and the film's fields) */
    double coat_ior;        /* [1, 3], relative to the air */
    double coat_alpha;      /* GGX width [1e-4, 1] */
    double coat_weight;     /* [0, 1] */
    /* HALFSPACE, SLAB */
    double albedo;          /* single-scattering albedo [0, 1] */
    soak_hg2 phase;
    double tau;             /* SLAB optical thickness (0, 1e6] */
    /* Run */
    long long paths;        /* [1, 1e12] */
    uint64_t seed;
    int threads;            /* [1, 256] */
    long max_events;        /* per-path cap (see soak_walk_options), >= 1 */
    int roulette;           /* 0 disables Russian roulette (for tests) */
    /* Optional progress report, called from the calling thread only with the
     * fraction of paths done. */
    void (*progress)(void *ctx, double fraction);
    void *progress_ctx;
} soak_measure_setup;

/* Index-matched, isotropic, albedo 1, normal incidence, 1e6 paths, seed 1,
 * 1 thread, roulette on, max_events 1e6, config HALFSPACE, no progress. */
void soak_measure_setup_default(soak_measure_setup *s);

soak_status soak_measure_validate(const soak_measure_setup *s);

typedef struct soak_measure_result {
    double value, std_error;       /* the requested quantity and its standard error */
    double reflectance, reflectance_err;
    double transmittance, transmittance_err;
    long long paths;
    long long capped;              /* paths that hit the event cap (scored 0) */
    double capped_weight;          /* their unscored throughput / paths: a bound on the bias */
    double mean_events;            /* tracking steps per path */
} soak_measure_result;

/* Runs the measurement. SOAK_ERR_NOMEM / SOAK_ERR_UNSUPPORTED if threads or
 * memory cannot be had; outputs written only on SOAK_OK. */
soak_status soak_measure_run(const soak_measure_setup *s, soak_measure_result *out);

#endif
