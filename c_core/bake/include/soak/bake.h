/* Bakers of 2D wet maps: shared plumbing (parallel rows, hashing, output
 * writing, image sequences) and the kinds turbulence, waves, drying and
 * combine. Maps are soak_image (float, top row first); every computation is
 * done in double and stored as float.
 *
 * Determinism: every random quantity is a hash of (seed, lattice or wave or
 * octave index), never a draw from a shared generator stream, and every row
 * is computed by the same arithmetic whichever thread runs it, so a bake is
 * bit-identical for a seed whatever the thread count.
 *
 * Functions that produce a map allocate it (soak_image_alloc); the caller
 * frees it with soak_image_free. On an error nothing is allocated. */
#ifndef SOAK_BAKE_H
#define SOAK_BAKE_H

#include <stddef.h>
#include <stdint.h>

#include "soak/image.h"
#include "soak/status.h"

#define SOAK_BAKE_MAX_SIZE 16384 /* largest accepted width or height */
#define SOAK_BAKE_MAX_THREADS 64

/* ---- shared plumbing (bake_common.c) ---------------------------------- */

/* Progress in [0, 1]; always called from the thread that started the bake. */
typedef void (*soak_progress_fn)(void *user, double fraction);

typedef struct soak_bake_exec {
    int threads;               /* 0 = every online core, else 1..SOAK_BAKE_MAX_THREADS */
    soak_progress_fn progress; /* may be NULL */
    void *progress_user;
} soak_bake_exec;

/* Work on one row (or one column, or one line of any sweep). thread is in
 * [0, thread count) and lets a row function use per-thread scratch. */
typedef void (*soak_row_fn)(void *ctx, int row, int thread);

/* Thread count a bake will use for exec (NULL = defaults); 0 if invalid. */
int soak_bake_threads(const soak_bake_exec *exec);

/* Calls fn(ctx, row, thread) once for every row in [0, rows), spread over
 * soak_bake_threads(exec) threads; progress reports rows done / rows scaled
 * into [progress_lo, progress_hi] (so multi-pass bakes report one ramp). */
soak_status soak_parallel_rows(int rows, const soak_bake_exec *exec, soak_row_fn fn, void *ctx, double progress_lo,
                               double progress_hi);

/* 1..SOAK_BAKE_MAX_SIZE in both directions. */
soak_status soak_bake_check_size(int width, int height);

/* Integer hash of a seed and three lattice/index coordinates (lowbias32
 * finaliser, C. Wellons 2018, chained per coordinate). */
uint32_t soak_hash3(uint64_t seed, int32_t a, int32_t b, int32_t c);
/* The same hash mapped to [0, 1). */
double soak_hash_unit(uint64_t seed, int32_t a, int32_t b, int32_t c);
/* A new seed for sub-stream `index` of seed (octave, wave, channel...). */
uint64_t soak_seed_derive(uint64_t seed, uint64_t index);

/* Hermite smoothstep 3u^2 - 2u^3 of u = (x - e0) / (e1 - e0) clamped to [0,1];
 * e1 <= e0 gives the step x >= e0. */
double soak_smoothstep(double e0, double e1, double x);

/* Output writing by extension: .exr (half, or float when float_exr), .png and
 * .tif (16-bit linear; PNG with gAMA 1.0), .tx (mip-mapped tiled texture via
 * maketx). Atomic and checked (soak/staged.h). */
soak_status soak_bake_write(const char *path, const soak_image *img, int float_exr, char *err, size_t errlen);
/* The same as one member of a set of outputs replaced together. */
struct soak_staged;
soak_status soak_bake_stage(struct soak_staged *stage, const char *path, const soak_image *img, int float_exr,
                            char *err, size_t errlen);

/* 1 if pattern holds exactly one printf integer conversion (%d, %4d, %04d)
 * and otherwise only "%%"; 0 if it holds none; -1 if malformed. */
int soak_bake_pattern_kind(const char *pattern);

/* Expands a sequence pattern for frame (0..9999999) into out. */
soak_status soak_bake_frame_path(const char *pattern, int frame, char *out, size_t outlen);

/* Checks an output path before any work: a supported extension, an existing
 * writable folder, and not the same file as any of the inputs. */
soak_status soak_bake_check_output(const char *path, const char *const *inputs, int n_inputs, char *err,
                                   size_t errlen);

/* ---- turbulence (bake_turbulence.c) ------------------------------------ */
/* Improved gradient noise (K. Perlin, "Improving Noise", SIGGRAPH 2002:
 * quintic fade 6t^5 - 15t^4 + 10t^3, 12 edge gradients in 3D; 8 unit
 * gradients in 2D), gradients chosen by hashing the lattice point with the
 * seed instead of a global permutation table. A period p > 0 wraps lattice
 * indices modulo p (noise periodic with period p cells); 0 = not periodic.
 * Values lie in about [-1, 1]; mean 0. */
double soak_noise2(uint64_t seed, double x, double y, int period_x, int period_y);
double soak_noise3(uint64_t seed, double x, double y, double z, int period_x, int period_y, int period_z);

typedef enum soak_noise_sum {
    SOAK_NOISE_FBM = 0,   /* sum_o gain^o noise(lacunarity^o p) */
    SOAK_NOISE_TURBULENCE /* sum_o gain^o |noise(lacunarity^o p)| (Perlin 1985) */
} soak_noise_sum;

/* Limits of soak_turbulence_params (soak_turbulence_check); the drying
 * noise shares the octaves and frequency limits. */
#define SOAK_NOISE_MAX_OCTAVES 24
#define SOAK_NOISE_MAX_FREQUENCY 8192
#define SOAK_NOISE_MAX_LACUNARITY 16
#define SOAK_NOISE_MAX_Z 1e6
#define SOAK_NOISE_MAX_THRESHOLD 2 /* threshold in [-max, max] */
#define SOAK_NOISE_MAX_SOFTNESS 2

typedef struct soak_turbulence_params {
    uint64_t seed;
    soak_noise_sum sum;
    int octaves;       /* 1..24 */
    double frequency;  /* noise cells across the image width at octave 0, (0, 8192] */
    double lacunarity; /* frequency ratio of successive octaves, [1, 16]; also
                          frequency * lacunarity^(octaves-1) <= 20000 */
    double gain;       /* amplitude ratio of successive octaves, [0, 1] */
    int tileable;      /* periodic across the image: per-octave cell counts rounded to whole numbers */
    int use_3d;        /* slice the 3D noise at z (animation); else 2D noise */
    double z;          /* slice position in octave-0 cells, |z| <= 1e6 */
    int thresholded;   /* output smoothstep(threshold - softness, threshold + softness, value) */
    double threshold;  /* [-2, 2] */
    double softness;   /* [0, 2]; 0 = hard step */
} soak_turbulence_params;

/* seed 0, fBm, 6 octaves, frequency 4, lacunarity 2, gain 0.5, not tiled, 2D,
 * no threshold (threshold 0.3, softness 0.1 when enabled). */
void soak_turbulence_defaults(soak_turbulence_params *p);
soak_status soak_turbulence_check(const soak_turbulence_params *p);

/* Value of the sum at pixel (x, y) of a width x height bake (pixel centres
 * at integer + 0.5; x in [-width, 2 width], y in [-height, 2 height]),
 * normalised by sum_o gain^o; thresholded if asked. Equal, bit for bit, to
 * the baked texel. */
soak_status soak_turbulence_eval(const soak_turbulence_params *p, int width, int height, double x, double y,
                                 double *value);

/* One-channel map, out allocated here. */
soak_status soak_bake_turbulence(const soak_turbulence_params *p, int width, int height, const soak_bake_exec *exec,
                                 soak_image *out);

/* ---- waves (bake_waves.c) --------------------------------------------- */
/* Beach wetness left by the last N waves (Jensen et al. 1999, sec. 4.2: "a
 * sum of turbulence functions simulating the water left from the four
 * previous waves"). Lengths are in image widths; the image centre is the
 * origin; s = signed distance inland from the still-water line. Wave j
 * (any integer) arrives at time j*period and runs up to reach_j (hashed in
 * [reach_min, reach_max]) plus an fBm displacement along the shore. */
/* Limits of soak_waves_params (soak_waves_check). */
#define SOAK_WAVES_MAX_WAVES 64
#define SOAK_WAVES_MAX_FRONT_OCTAVES 16
#define SOAK_WAVES_MAX_DIRECTION 3600     /* degrees, either way */
#define SOAK_WAVES_MAX_LENGTH 10          /* |shore|, reach, front amplitude, edge */
#define SOAK_WAVES_MAX_PERIOD 1e6
#define SOAK_WAVES_MAX_DRY_TIME 1e9
#define SOAK_WAVES_MAX_DRY_LENGTH 100     /* dry length, fringe */
#define SOAK_WAVES_MAX_FRONT_FREQUENCY 4096

typedef struct soak_waves_params {
    uint64_t seed;
    int waves;              /* waves still visible, 1..64 */
    double direction_deg;   /* inland direction in the image, degrees from +x towards +y (down) */
    double shore;           /* still-water line offset from the image centre along direction, [-10, 10] */
    double reach_min;       /* run-up range beyond the still-water line, 0 <= min <= max <= 10 */
    double reach_max;
    double period;          /* time between waves, (0, 1e6] */
    double dry_time;        /* e-folding time of the surface water a wave leaves, (0, 1e9] */
    double dry_length;      /* e-folding distance inland of that water (drainage), (0, 100] */
    double fringe;          /* e-folding height of the capillary fringe above the water line, (0, 100] */
    double front_amplitude; /* fBm displacement of each front, [0, 10] */
    double front_frequency; /* fBm cells per image width along the shore, (0, 4096] */
    int front_octaves;      /* 1..16 */
    double edge;            /* width of each front's soft edge, [0, 10] */
    double time;            /* bake time, |time| <= 1e12 */
} soak_waves_params;

/* 4 waves, direction 90 (inland = down the image), shore -0.2 (water line above the centre), reach
 * 0.05..0.3, period 8, dry_time 20, dry_length 0.5, fringe 0.03, front
 * amplitude 0.04 at 3 cells with 4 octaves, edge 0.01, time 0. */
void soak_waves_defaults(soak_waves_params *p);
soak_status soak_waves_check(const soak_waves_params *p);

/* Wetness in [0, 1] at point (u, v) in image widths from the image centre
 * (texel (x, y) of a W x H bake sits at u = (x + 0.5)/W - 1/2,
 * v = (y + 0.5)/W - H/(2W)); the model is documented in bake_waves.c. */
soak_status soak_waves_eval(const soak_waves_params *p, double u, double v, double *wetness);
soak_status soak_bake_waves(const soak_waves_params *p, int width, int height, const soak_bake_exec *exec,
                            soak_image *out);

/* ---- drying (bake_drying.c) ------------------------------------------- */

/* Exact squared Euclidean distance transform (P. Felzenszwalb, D.
 * Huttenlocher, "Distance Transforms of Sampled Functions", Theory of
 * Computing 8, 2012): d2[i] = squared distance from texel i to the nearest
 * texel with feature[i] != 0 (0 on features). If there is no feature,
 * *any_feature = 0 and d2 is filled with width^2 + height^2. */
soak_status soak_edt_squared(const unsigned char *feature, int width, int height, double *d2, int *any_feature);

typedef enum soak_drying_mode {
    SOAK_DRYING_SCHEDULE = 0, /* Hnat et al. 2006 pore schedule, borders first */
    SOAK_DRYING_DIFFUSION     /* evaporation + lateral capillary diffusion, implicit */
} soak_drying_mode;

/* Limits of soak_drying_params (soak_drying_check); its noise has the
 * turbulence's octaves and frequency limits. */
#define SOAK_DRYING_MAX_THRESHOLD 1e6 /* threshold in [-max, max] */
#define SOAK_DRYING_MAX_TIME 1e12     /* time, drying_time */
#define SOAK_DRYING_MAX_LENGTH 1e6    /* diffusion_length, pixels */
#define SOAK_DRYING_MAX_STEPS 100000

typedef struct soak_drying_params {
    soak_drying_mode mode;
    double threshold; /* mask value above which a texel starts wet, [-1e6, 1e6] */
    double time;      /* relative time (schedule: the drying runs over [0, 1]); [0, 1e12] */
    /* schedule mode */
    double t_fill;          /* pore emptying time, [0, 1]; 0 = step */
    double noise_amount;    /* blend of fBm into the start time, [0, 1] (porous, stochastic drying) */
    double noise_frequency; /* fBm cells across the width, (0, 8192] */
    int noise_octaves;      /* 1..24 */
    uint64_t seed;
    /* diffusion mode */
    double drying_time;      /* time to evaporate a unit-depth film, (0, 1e12] */
    double diffusion_length; /* capillary spreading length over drying_time, pixels, [0, 1e6] */
    int steps;               /* implicit time steps, 1..100000 */
} soak_drying_params;

/* Peak bytes of one drying frame of width x height, counted from the
 * buffers bake_drying.c holds at once, per pixel: wet flags 1 and the float
 * output 4, with (schedule) start times 8, dry flags 1 and squared
 * distances 8 or (diffusion) the field 8; then the encoding, the output 4,
 * a float copy 4 and 2-byte samples; the mask itself not counted (measured
 * 8192^2 schedule: 21 bytes per pixel with the mask, estimated 26). */
double soak_drying_peak_bytes(int width, int height, const soak_drying_params *p);

/* schedule, threshold 0.5, time 0.5, t_fill 0.2, no noise (frequency 8, 4
 * octaves), seed 0, drying_time 1, diffusion_length 8, steps 32. */
void soak_drying_defaults(soak_drying_params *p);
soak_status soak_drying_check(const soak_drying_params *p);

/* Mask value of texel i: channel 0 for 1-2 channels, Rec. 709 luma of RGB(A). */
double soak_mask_value(const soak_image *mask, size_t i);

/* Schedule mode: start time t0 of drying per texel (w*h doubles) and wet
 * flag (w*h bytes). t0 = (1 - t_fill) * mix(d / d_max, noise01, noise_amount)
 * with d the exact distance to the nearest dry texel (the image edge is not
 * a border: a map may continue past it), d_max its largest value over wet
 * texels, noise01 = smoothstep(-1/2, 1/2, fBm); a mask without dry texels
 * uses d / d_max = 1 (all start together, noise alone decides). Wetness at
 * time t is 1 - soak_fill_fraction(t, t0, t_fill) on wet texels, 0 else. */
soak_status soak_drying_start_times(const soak_image *mask, const soak_drying_params *p, double *t0,
                                    unsigned char *wet);

/* One implicit step of du/dt = D lap(u) - E [u > 0] on a w x h grid with
 * no-flux borders: backward Euler in x, then in y (locally one-dimensional
 * splitting; each solve is a tridiagonal M-matrix, so the step is stable
 * and keeps min <= u <= max for any r), then u = max(0, u - evap).
 * r = D dt (pixels^2), evap = E dt. Conserves sum(u) when evap = 0. */
soak_status soak_diffusion_step(double *u, int width, int height, double r, double evap,
                                const soak_bake_exec *exec);

/* Wetness map at p->time from a mask (or, mask NULL, a fully wet width x
 * height surface). */
soak_status soak_bake_drying(const soak_image *mask, int width, int height, const soak_drying_params *p,
                             const soak_bake_exec *exec, soak_image *out);

/* ---- combine (bake_combine.c) ----------------------------------------- */
/* Inputs must share width, height and channel count (else SOAK_ERR_ARG). */
typedef enum soak_combine_op { SOAK_COMBINE_MAX = 0, SOAK_COMBINE_MIN, SOAK_COMBINE_MULTIPLY, SOAK_COMBINE_ADD } soak_combine_op;

soak_status soak_map_combine(soak_combine_op op, const soak_image *a, const soak_image *b, soak_image *out);
/* lo <= hi, both finite. */
soak_status soak_map_clamp(const soak_image *in, double lo, double hi, soak_image *out);
/* Linear map of [in_lo, in_hi] onto [out_lo, out_hi] (in_lo != in_hi),
 * clamped to the output range if clamp. */
soak_status soak_map_remap(const soak_image *in, double in_lo, double in_hi, double out_lo, double out_hi, int clamp,
                           soak_image *out);
#define SOAK_BLUR_MAX_SIGMA 1000 /* pixels */
/* Separable Gaussian, sigma in (0, SOAK_BLUR_MAX_SIGMA], kernel radius ceil(3 sigma),
 * normalised weights; edges clamp, or wrap when wrap (tileable maps). */
soak_status soak_map_blur(const soak_image *in, double sigma, int wrap, const soak_bake_exec *exec, soak_image *out);

#endif
