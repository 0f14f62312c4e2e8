/* A denoiser for `soak render` pictures (`soak render --denoise`), never for
 * numbers: a test asserting a radiance reads the unfiltered render.
 *
 * Two steps on the linear image:
 *  1. fireflies: a pixel brighter than firefly_ratio times the second
 *     brightest of its 8 neighbours (so a pair of them is caught too, and a
 *     one-pixel bright line is not) takes the colour of its neighbours'
 *     median-luminance pixel; then every pixel is capped at firefly_ratio
 *     times the median luminance of its 5 x 5 window (a field of sparkles,
 *     where each has bright neighbours). This removes energy (a firefly is
 *     a rare sample of real light): pictures only.
 *  2. the edge-avoiding a-trous wavelet filter of Dammertz, Sewtz, Hanika and
 *     Lensch, "Edge-Avoiding A-Trous Wavelet Transform for fast Global
 *     Illumination Filtering", HPG 2010: `iterations` passes of the 5x5
 *     B3-spline kernel (1, 4, 6, 4, 1)/16 with taps 1, 2, 4, ... pixels
 *     apart, each tap weighted by edge-stopping functions. The colour term
 *     is scaled by each pixel's standard deviation, and the variance is
 *     carried through the passes, as in SVGF (Schied et al., "Spatiotemporal
 *     Variance-Guided Filtering", HPG 2017, Eq. 3-5): w = exp(-|l_p - l_q| /
 *     (sigma_colour sqrt(var_p) + eps)), with the variance smoothed over 3x3;
 *     the feature terms are max(0, n_p.n_q)^normal_power, exp(-|n_p.(x_q -
 *     x_p)| / (sigma_depth z_p)) (q's first hit x_q off p's tangent plane,
 *     relative to p's distance z_p from the camera), the same object, and
 *     exp(-|w_p - w_q| / sigma_wetness) for the wet map. The features come
 *     from the camera's first hits (soak_render_features), so geometric and
 *     wet/dry edges stay sharp whatever the noise; colour edges stay where
 *     they stand out of the pixels' noise.
 * On a flat region the kernel is a normalised low-pass: the mean is kept
 * (tests/c/render/test_render_denoise.c). */
#ifndef SOAK_DENOISE_H
#define SOAK_DENOISE_H

#include <stddef.h>

#include "soak/image.h"
#include "soak/scene.h"
#include "soak/status.h"

/* Per pixel, what the camera sees first; any array may be NULL (its term
 * is then off). */
typedef struct soak_denoise_features {
    int width, height;
    float *
        normal; /* 3 per pixel: the first hit's normal facing the camera (shading, or geometric where they part), lens-averaged */
    float *position; /* 3 per pixel: the first hit, averaged over the lens */
    float *depth;    /* distance to the first hit, averaged over the lens; 0 where only the environment is seen */
    int *object;     /* object id of the pixel centre's first hit through the lens centre; -1: the environment */
    float *wetness;  /* the object's wetness at the first hit (its map, plane or constant), averaged */
} soak_denoise_features;

typedef struct soak_denoise_options {
    int iterations;       /* a-trous passes, [1, 10] */
    double sigma_colour;  /* luminance difference allowed, in the pixel's standard deviations, > 0 */
    double normal_power;  /* >= 0 */
    double sigma_depth;   /* distance off the tangent plane allowed, a fraction of the distance to the camera, > 0 */
    double sigma_wetness; /* > 0 */
    double firefly_ratio; /* > 1; 0 = no firefly step */
} soak_denoise_options;

typedef struct soak_denoise_stats {
    long fireflies; /* pixels replaced or capped by step 1 */
} soak_denoise_stats;

/* iterations 5, sigma_colour 4, normal_power 128 (SVGF's values),
 * sigma_depth 0.01, sigma_wetness 0.1, firefly_ratio 4. */
void soak_denoise_options_default(soak_denoise_options *o);

/* Filters img (RGB float, linear) in place. variance: 1 channel, the
 * variance of each pixel's mean luminance (soak_render_options.variance),
 * same size; features: same size or NULL. SOAK_ERR_ARG for mismatched
 * sizes or options out of range (err says which). */
soak_status soak_denoise(soak_image *img, const soak_image *variance, const soak_denoise_features *features,
                         const soak_denoise_options *opt, soak_denoise_stats *stats, char *err, size_t errlen);

/* The features of a W x H render of the scene's camera: lens_samples
 * (>= 1) rays a pixel, spread over the pixel and the lens. Allocates the
 * four arrays (soak_denoise_features_free). */
soak_status soak_render_features(const soak_scene *scene, int width, int height, int lens_samples,
                                 soak_denoise_features *out, char *err, size_t errlen);
void soak_denoise_features_free(soak_denoise_features *f);

#endif
