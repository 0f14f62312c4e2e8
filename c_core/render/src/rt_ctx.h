/* The path tracer's shared context (render.c and every render_*.c, and
 * accuracy.c, which shades through the renderer's BSDFs): its tuned
 * constants, the per-render context and per-thread state, the thread's
 * random numbers (render_sampler.c) and the small inline maths every
 * stage uses. Each stage's own functions are declared in the header of
 * its file (render_lights.h, render_surface.h, ...), so a file includes
 * the stages it calls and nothing of render.c. */
#ifndef SOAK_RT_CTX_H
#define SOAK_RT_CTX_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "soak/bsdf.h"
#include "soak/film.h"
#include "soak/geometry.h"
#include "soak/hg.h"
#include "soak/medium.h"
#include "soak/render.h"
#include "soak/rng.h"
#include "soak/scene.h"

/* Medium random walks stop after this many tracking events (counted as capped). */
#define RT_MEDIUM_MAX_EVENTS 100000
/* Next-event estimation inside a medium: the shadow estimate is played by
 * Russian roulette with survival T / RT_NEE_ROULETTE_T (at most 1, never below
 * RT_NEE_SURVIVAL_MIN, which bounds a survivor's weight), T the homogeneous
 * transmittance to the surface; survivors are divided by it (unbiased). The
 * threshold 1 (survival = T) was the fastest to a given RMSE on
 * scenes/bench_wet_sphere.json among 0.03, 0.1, 0.3, 1, 3. The roulette is
 * played first on a predicted exit distance, before any ray is cast, with
 * survival never below RT_NEE_PREDICT_MIN since the prediction can be wrong;
 * then on the distance found (floor 0.2: with the walk's roulette at 1/2 and
 * closed-form sphere queries, 0.2 had the best variance x work of 0.01, 0.05,
 * 0.2, 0.5; 0.05 was best before). Lights 0 .. RT_NEE_CACHE - 1 keep their
 * last exit point for the prediction. */
#define RT_NEE_ROULETTE_T 1.0
/* The same for a light behind the face the path last crossed (a sheet lit
 * from behind): there every vertex sees the light only through the object,
 * the pixel is as dark as the transmittance through it, and survival = T
 * turned the estimates of vertices near the viewer's face (T ~ 1e-2) into
 * rare large ones. On scenes/bench_wet_paper.json (T through the sheet 0.013)
 * the relative variance per sample was 2.80 at 1, 1.73 at 0.1 and 0.01, the
 * instructions per path +27 % and +40 %: 0.1 is 22 % faster to an error. */
#define RT_NEE_ROULETTE_T_BEHIND 0.1
#define RT_NEE_SURVIVAL_MIN 1e-3
#define RT_NEE_PREDICT_MIN 0.2
#define RT_NEE_CACHE 4
/* -log(RT_NEE_SURVIVAL_MIN) rounded up: optical depths past it survive at the floor. */
#define RT_NEE_FLOOR_DEPTH 6.9078
/* The same for RT_NEE_ROULETTE_T_BEHIND: -log(RT_NEE_SURVIVAL_MIN RT_NEE_ROULETTE_T_BEHIND). */
#define RT_NEE_FLOOR_DEPTH_BEHIND 9.2104
/* Random numbers per camera path taken from the Sobol pairs (render_sampler.c):
 * pixel, then the first surface's choices. On the bench scene at 64 spp, 8, 16
 * and 32 gave the same variance (within 1 %); 8 costs least. */
#define RT_QMC_DIMS 8
/* Bounces inside the film of one surface interaction. */
#define RT_FILM_MAX_BOUNCES 256

typedef struct rt_env {
    /* Equirectangular map sampling: marginal CDF over rows, conditional over
     * columns, weights luminance * sin(theta) (Pharr, Jakob, Humphreys, PBRT 3rd
     * ed., sec. 14.2.4). */
    double *row_cdf; /* height + 1 */
    double *col_cdf; /* height * (width + 1) */
    double total;
} rt_env;

/* The BSDFs of one material (soak/bsdf.h), set up once per render: dry,
 * and wet (weight wetness * film coverage: light estimates see the mixture
 * of both, a continuation samples one by its weight, render_mix.c) when has_wet. */
typedef struct rt_material_bsdf {
    soak_bsdf dry, wet;
    soak_bsdf pore; /* the liquid's surface at zero thickness over the uncoated base (has_pore) */
    int has_wet, has_pore;
} rt_material_bsdf;

/* The BSDFs of a preset's levels (scene_levels.h, render_levels.c): n
 * entries beside the material's levels->view; n = 0: none. */
typedef struct rt_levels {
    int n;
    rt_material_bsdf *bsdf;
} rt_levels;

struct rt_photon_map;
typedef struct rt_ctx {
    const soak_scene *scene;
    rt_env env;
    const rt_material_bsdf *bsdfs; /* one per material */
    const rt_levels *levels;       /* one per material; NULL: none */
    int max_depth;
    const struct rt_photon_map *caustics; /* NULL: no caustic photons */
} rt_ctx;

typedef struct rt_counters {
    long long rays, capped, leaked;
    long long nan_paths;   /* camera paths whose radiance was NaN/Inf (dropped to 0) */
    long long geom_errors; /* geometry queries that failed (the path or ray ended) */
} rt_counters;

/* Does the object's wetness read texture coordinates (a wet map)? */
static inline int rt_object_uses_uv(const soak_object *obj) { return obj->wetness.type == SOAK_WETNESS_MAP; }

/* ---- the thread's random numbers (render_sampler.c) ---- */
/* Quasi-random state of the current camera path: dimensions dim < end come
 * from the scrambled Sobol pairs, the rest from rng. end = 0 (a zeroed
 * thread, e.g. the photon tracer) means plain PCG. */
typedef struct rt_qmc {
    uint32_t seed, index;
    uint32_t pair_index, seed_x, seed_y; /* of the current pair */
    int dim, end;
} rt_qmc;

typedef struct rt_thread {
    const rt_ctx *ctx;
    soak_rng rng;
    rt_qmc qmc;
    rt_counters n;
} rt_thread;

/* Starts the quasi-random dimensions of sample `sample` of pixel `pixel`. */
void rt_qmc_start(rt_thread *t, uint64_t seed, uint64_t pixel, uint32_t sample);
double rt_qmc_next(rt_thread *t);
static inline double rt_rand(rt_thread *t)
{
    return t->qmc.dim < t->qmc.end ? rt_qmc_next(t) : soak_rng_uniform(&t->rng);
}
/* Two numbers meant as one 2D sample (pixel position, a direction): they
 * start a new Sobol pair so they are stratified jointly. */
void rt_rand2(rt_thread *t, double *u1, double *u2);

/* fmax's result (a NaN argument is ignored) without the libm call, which
 * the compiler keeps unless NaN semantics are given up (-ffinite-math-only,
 * which would also break the isnan-based input checks). Signed zeros may
 * come out either way, as C allows fmax to do. */
static inline double rt_max(double a, double b) { return (a > b || b != b) ? a : b; }
static inline double rt_min(double a, double b) { return (a < b || b != b) ? a : b; }
static inline double rgb_max(soak_rgb a) { return rt_max(a.r, rt_max(a.g, a.b)); }
static inline soak_rgb rgb_exp(soak_rgb a, double s) { return soak_rgb3(exp(-a.r * s), exp(-a.g * s), exp(-a.b * s)); }

/* Local shading frame (t, b, n). */
typedef struct rt_frame {
    soak_vec3 t, b, n;
} rt_frame;
static inline rt_frame rt_frame_make(soak_vec3 n)
{
    rt_frame f;
    f.n = n;
    soak_v3_basis(n, &f.t, &f.b);
    return f;
}
static inline soak_vec3 rt_to_local(const rt_frame *f, soak_vec3 v)
{
    return soak_v3(soak_v3_dot(v, f->t), soak_v3_dot(v, f->b), soak_v3_dot(v, f->n));
}
static inline soak_vec3 rt_to_world(const rt_frame *f, soak_vec3 v)
{
    return soak_v3_add(soak_v3_add(soak_v3_scale(f->t, v.x), soak_v3_scale(f->b, v.y)), soak_v3_scale(f->n, v.z));
}

/* Two-term HG value (soak/hg.h) for an already validated phase function.
 * A lobe of weight 0 is not evaluated: w x + 0 y = w x exactly for the
 * finite y it would give, so the value is the same bit for bit. */
static inline double rt_hg2(const soak_hg2 *p, double cos_theta)
{
    if (p->w == 1.0) return soak_hg_eval_raw(p->g1, cos_theta);
    if (p->w == 0.0) return soak_hg_eval_raw(p->g2, cos_theta);
    return p->w * soak_hg_eval_raw(p->g1, cos_theta) + (1 - p->w) * soak_hg_eval_raw(p->g2, cos_theta);
}

/* Power heuristic with exponent 2 (Veach 1997, eq. 9.13). */
static inline double rt_power(double a, double b) { return a * a / (a * a + b * b); }

/* Radiance convention: a refraction into index ratio eta multiplies the
 * radiance by 1/eta^2, and beta carries that factor; eta_scale carries its
 * inverse (pbrt's etaScale), so beta * eta_scale, the weight Russian roulette
 * plays on (rt_rr_weight), does not count a factor that the path's exit
 * undoes. Films and media over a base never put their 1/n^2 into beta:
 * estimates gathered inside carry it explicitly (render_surface.c,
 * render_medium.c). */
typedef struct rt_path {
    soak_rgb beta;    /* throughput, radiance factors of refractions included */
    double eta_scale; /* product of eta^2 over the refractions so far */
    soak_rgb L;       /* radiance gathered */
    soak_vec3 org, dir;
    double prev_pdf; /* solid-angle pdf of the last BSDF-sampled direction */
    int prev_delta;  /* 1: the last direction had no competing light sample (count emission fully) */
    soak_vec3 prev_pos;
    int alive;
    int inside; /* inside a dielectric: absorb applies per unit length */
    soak_rgb absorb;
} rt_path;

/* The weight Russian roulette plays on: max_c beta_c * eta_scale. */
static inline double rt_rr_weight(const rt_path *p) { return rgb_max(p->beta) * p->eta_scale; }

#endif
