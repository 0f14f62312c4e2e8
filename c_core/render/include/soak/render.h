/* Reference Monte Carlo path tracer for wet materials (`soak render`).
 *
 * Unidirectional path tracing with next-event estimation and multiple
 * importance sampling (power heuristic, Veach 1997 ch. 9) for surfaces; the
 * wet surface of [JLD99] (Jensen, Legakis, Dorsey 1999) Eq. 1-4 is traced
 * explicitly: reflection at the film top, transmission into the film and the
 * material, a subsurface random walk (two-term HG, [JLD99] Eq. 5 as
 * corrected in soak/hg.h), Fresnel with total internal reflection on the way
 * out, and Eq. 4 transmittance on shadow rays from inside the medium. An
 * optional volume photon map carries caustics (light through dielectrics)
 * into the media (scene render.caustic_photons). See
 * scenes/README.md for the model details, the approximations and the image
 * transforms.
 *
 * Sampling: the first random numbers of a camera path are quasi-random
 * (scrambled Sobol pairs, render_sampler.c), the rest pseudo-random.
 *
 * Determinism: sample s of pixel i always uses RNG stream i * spp + s of the
 * seed and Sobol point s of the pixel's scramble, and a pixel's passes are
 * summed in order, so the image depends only on the scene, seed and spp --
 * not on the thread count or scheduling (it does change when a render is
 * stopped early). */
#ifndef SOAK_RENDER_H
#define SOAK_RENDER_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "soak/image.h"
#include "soak/scene.h"
#include "soak/status.h"

/* Limits of soak_render_options beyond those of a scene's "render" block
 * (SOAK_RENDER_MAX_SIZE, _SPP, _DEPTH: soak/scene.h); `soak render` takes
 * its option ranges from these. */
#define SOAK_RENDER_MAX_THREADS 256
#define SOAK_RENDER_MAX_TIME 1e9      /* time_limit, seconds */

typedef struct soak_render_options {
    int width, height;   /* 0: the scene's */
    int spp;             /* samples per pixel; 0: the scene's */
    int threads;         /* >= 1 */
    uint64_t seed;
    double time_limit;   /* seconds, 0 = none: stop after this and keep what is done */
    int max_depth;       /* 0: the scene's */
    volatile sig_atomic_t *cancel; /* when it becomes non-zero the render stops early */
    /* Called about 5 times a second from the calling thread with the
     * fraction of samples done; may be NULL. */
    void (*progress)(void *ctx, double fraction);
    void *progress_ctx;
    /* 1: trace a film over a Lambert base bounce by bounce (light sampling
     * through the film, total internal reflection) instead of using its
     * closed-form expectation; for validation, the image's expectation is
     * the same. */
    int trace_films;
    /* > 0: render to an error. A tile stops taking samples (spp is then the
     * cap) once each pixel has 16 samples and the standard error of its mean
     * luminance is below target_error x max(mean, 0.01) (render_adaptive.h). */
    double target_error;
    /* Non-NULL: allocated here (1 channel, W x H) with each pixel's variance
     * of its mean luminance (sample variance / samples; 0 below 2 samples),
     * for soak_denoise (soak/denoise.h), which filters pictures only. */
    soak_image *variance;
} soak_render_options;

typedef struct soak_render_stats {
    long long paths;        /* camera paths traced */
    long long rays;         /* closest-hit plus shadow queries */
    long long capped;       /* paths stopped by max_depth or the medium event cap while
                               still carrying throughput (their remainder is the only bias) */
    long long leaked;       /* medium paths that found no boundary (open mesh): dropped */
    long long nan_paths;    /* camera paths whose radiance came out NaN/Inf: counted as black */
    long long geometry_errors; /* failed geometry queries: the path (or shadow ray) ended there */
    double seconds;         /* wall-clock time of the path tracing */
    double cpu_seconds;     /* CPU time (user + system, all threads) of the path tracing */
    int min_spp, max_spp;   /* samples actually taken per pixel */
    int stopped_early;      /* cancel or time limit */
} soak_render_stats;

void soak_render_options_default(soak_render_options *opt);

/* Renders into out (allocated here: RGB float, linear radiance, top row
 * first). A stopped render returns SOAK_OK with the samples done so far
 * (pixels with no sample are 0) and stats->stopped_early set. */
soak_status soak_render(const soak_scene *scene, const soak_render_options *opt, soak_image *out,
                        soak_render_stats *stats, char *err, size_t errlen);

/* Tone mapping for 8/16-bit outputs, in place: multiply by 2^exposure; the
 * sRGB OETF and the clamp to [0,1] are then applied by soak_image_write
 * with SOAK_TONE_SRGB. */
void soak_render_expose(soak_image *img, double exposure_stops);

#endif
