/* Shared harness of the render tests: repeated renders of a scene text with
 * consecutive seeds, reduced to a mean and its standard error. This runs
 * the code under test; the references stay in each test. */
#ifndef SOAK_TEST_RENDER_HARNESS_H
#define SOAK_TEST_RENDER_HARNESS_H

#include <stdint.h>

typedef enum { RH_FIRST_PIXEL, RH_ALL_PIXELS } rh_reduce;

/* Parses `text` (relative paths against base_dir), renders it `reps` times
 * with spp_per_rep samples on 2 threads and seeds seed_base, seed_base+1,
 * ...; each render is reduced to the channel mean of its first pixel or of
 * all pixels. A parse or render failure is a failed check and returns 0. */
int rh_render_mean(const char *what, const char *text, const char *base_dir, int reps, int spp_per_rep,
                   uint64_t seed_base, rh_reduce reduce, double *mean, double *se);
/* The same with films over Lambert traced bounce by bounce
 * (soak_render_options.trace_films) when trace_films is 1. Every render
 * must also report no NaN path and no geometry error (checked). */
int rh_render_mean_opt(const char *what, const char *text, const char *base_dir, int reps, int spp_per_rep,
                       uint64_t seed_base, rh_reduce reduce, int trace_films, double *mean, double *se);

/* Per-channel mean and standard error of a few estimates of one point's
 * radiance, and the standard error of their red/blue (channels share their
 * paths, so red/blue is estimated from the estimates' own ratios). */
typedef struct rh_rgb {
    double mean[3], se[3];
    double rb_se;
} rh_rgb;
/* Parses `text` (paths against "."), renders it on 2 threads with spp
 * samples per pixel: reps >= 2 renders with seeds seed, seed + 1, ... whose
 * first pixel is one estimate each, or (reps = 1) one render whose every
 * pixel is an estimate (pixels that all see the same point). Every render
 * must report no NaN path and no geometry error (checked). */
int rh_render_rgb(const char *what, const char *text, int reps, int spp, uint64_t seed, rh_rgb *e);

#endif
