/* Private pieces of the path tracer shared by render_*.c (and accuracy.c,
 * which shades through the renderer's BSDFs). Each section names the file
 * its functions live in. */
#ifndef SOAK_RENDER_INTERNAL_H
#define SOAK_RENDER_INTERNAL_H

#include <signal.h>
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
    double *row_cdf;  /* height + 1 */
    double *col_cdf;  /* height * (width + 1) */
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
    long long nan_paths;  /* camera paths whose radiance was NaN/Inf (dropped to 0) */
    long long geom_errors; /* geometry queries that failed (the path or ray ended) */
} rt_counters;

/* Does the object's wetness read texture coordinates (a wet map)? */
static inline int rt_object_uses_uv(const soak_object *obj) { return obj->wetness.type == SOAK_WETNESS_MAP; }

/* ---- sampler (render_sampler.c) ---- */
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
static inline soak_rgb rgb_exp(soak_rgb a, double s)
{
    return soak_rgb3(exp(-a.r * s), exp(-a.g * s), exp(-a.b * s));
}

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
static inline double rt_power(double a, double b)
{
    return a * a / (a * a + b * b);
}

/* ---- lights (render_lights.c) ---- */
soak_status rt_env_build(rt_env *env, const soak_environment *e);
void rt_env_free(rt_env *env);
soak_rgb rt_env_eval(const rt_ctx *c, soak_vec3 dir);
double rt_env_pdf(const rt_ctx *c, soak_vec3 dir);

typedef struct rt_light_sample {
    soak_vec3 wi;  /* unit, toward the light */
    double dist;   /* distance to the light point (INFINITY for directional/env) */
    soak_rgb L;    /* radiance (area/env) or delta value (irradiance E, I/r^2) */
    double pdf;    /* solid angle pdf; 0 for delta lights */
} rt_light_sample;

/* Light index in [0, n_lights) or n_lights for the environment. Returns 0 if
 * the light cannot illuminate p (inside a sphere light, zero value). */
int rt_light_sample_at(rt_thread *t, int light, soak_vec3 p, rt_light_sample *s);
int rt_light_count(const rt_ctx *c); /* lights + the environment if it is a map */
/* Solid-angle pdf of sampling direction wi toward sphere light l from p. */
double rt_sphere_light_pdf(const soak_light *l, soak_vec3 p);
/* 1 when the segment from p (offset already applied) along wi up to dist is free. */
int rt_visible(rt_thread *t, soak_vec3 p, soak_vec3 wi, double dist);

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
    double prev_pdf;  /* solid-angle pdf of the last BSDF-sampled direction */
    int prev_delta;   /* 1: the last direction had no competing light sample (count emission fully) */
    soak_vec3 prev_pos;
    int alive;
    int inside;       /* inside a dielectric: absorb applies per unit length */
    soak_rgb absorb;
} rt_path;

/* The weight Russian roulette plays on: max_c beta_c * eta_scale. */
static inline double rt_rr_weight(const rt_path *p) { return rgb_max(p->beta) * p->eta_scale; }

/* ---- surfaces (render_surface.c) ---- */
/* Handles the surface interaction at hit: gathers next-event estimates into
 * path->L, updates beta and sets the next ray (or alive = 0). */
void rt_surface(rt_thread *t, const soak_hit *hit, rt_path *path);

/* ---- render_mix.c: a surface's dry / wet / pore BSDFs as one mixture ---- */
typedef struct rt_bsdf_mix {
    int n;                 /* components (1: a single BSDF) */
    const soak_bsdf *b[3];
    double w[3];           /* shares, summing to 1 */
    int chosen;            /* the component drawn for the continuation */
} rt_bsdf_mix;
/* 1 when every component is closed-form and reflecting (see render_mix.c). */
int rt_mix_can(const rt_bsdf_mix *m);
int rt_mix_flags(const rt_bsdf_mix *m);
soak_status rt_mix_eval(const rt_bsdf_mix *m, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf);
int rt_mix_reweight(const rt_bsdf_mix *m, soak_vec3 wo, soak_bsdf_sample *s);

/* ---- materials to BSDFs (render_bsdfs.c) ---- */
/* Sets up bsdfs[i] for every material (n_materials entries); trace_films:
 * films over Lambert traced bounce by bounce instead of their closed form.
 * On failure err names the material. */
soak_status rt_bsdfs_setup(const soak_scene *s, int trace_films, rt_material_bsdf *bsdfs, char *err, size_t errlen);
/* The same for one material. */
soak_status rt_material_bsdf_setup(const soak_material *m, int trace_films, rt_material_bsdf *out);

/* ---- a preset's levels of liquid (render_levels.c) ---- */
/* Sets up out[i] (n_materials entries) for every material with levels. */
soak_status rt_levels_setup(const soak_scene *s, int trace_films, rt_levels *out, char *err, size_t errlen);
void rt_levels_free(rt_levels *levels, int n_materials);
/* The material state a hit of obj is shaded with: *m and *mb (the
 * material's own on entry) become a drawn level's when the material has
 * levels. Returns the probability of the liquid's interface (film or pore
 * water) at the hit. */
double rt_level_at(rt_thread *t, const soak_object *obj, const soak_hit *hit, const soak_material **m,
                   const rt_material_bsdf **mb);

/* ---- the layer stack (render_stack.c) ---- */
/* The air | film | material layer stack of a wet surface. */
typedef struct rt_stack {
    double n2, n3, k;  /* film (1 and no absorbing thickness = none), material, Fresnel exponent */
    soak_rgb alpha;    /* film absorption, 1/length */
    double h;          /* film thickness */
} rt_stack;

/* The stack a path meets entering wet medium material m at wetness wet:
 * one draw picks the film (probability wet x coverage, with its thickness),
 * of those a share film_pore_share of pore water (the same interface, no
 * thickness), or dry (no film). */
rt_stack rt_wet_stack(rt_thread *t, const soak_material *m, double wet);

/* Fresnel of the interfaces a path meets (unpolarised, exact): eta = n_t/n_i. */
double rt_fresnel(double cos_i, double eta, double *cos_t);
/* Crosses the stack with Snell invariant p = n sin(theta), starting in the
 * material going up (start_low) or in air going down. Returns 1 when it ends
 * in the material, 0 in air. Multiplies *beta by the film absorption only. */
int rt_cross_stack(rt_thread *t, const rt_stack *s, double p, int start_low, soak_rgb *beta);
/* Direction with tangential unit tdir and invariant p in a medium of index n. */
soak_vec3 rt_snell_dir(soak_vec3 tdir, soak_vec3 n_out, double p, double n, int up);

/* ---- media (render_medium.c) ---- */
/* Wet material with a scattering base: enters at hit (from air, direction
 * path->dir), walks, exits or dies. */
void rt_wet_medium(rt_thread *t, const soak_hit *hit, const soak_object *obj, const soak_material *m, rt_path *path);

/* The scene medium as the random walk of soak/medium.h sees it: homogeneous
 * per-channel, or the grid (trilinear, cell-centred) under its majorant. */
soak_medium_rgb rt_medium_rgb(const soak_scene_medium *m);
/* Walk options of the renderer: roulette on max beta below 1/2, cap RT_MEDIUM_MAX_EVENTS. */
soak_walk_options rt_walk_options(soak_rgb beta);
/* Walk boundary: the scene's surfaces, the wet film stack of a medium object
 * crossed upward on arrival (reflection back in, or exit). */
typedef struct rt_med_surface {
    soak_hit hit;     /* last surface found by the distance callback */
    int lost;         /* the ray missed every surface: open geometry */
    soak_vec3 n_ref;  /* outward normal of the last surface crossed */
} rt_med_surface;
typedef struct rt_med_boundary {
    rt_thread *t;
    rt_med_surface *surf;
    const soak_object *obj;
    const soak_material *m;
    const rt_stack *stack;
} rt_med_boundary;
soak_boundary rt_med_boundary_make(const rt_med_boundary *b);

/* ---- the photon map (render_photon_map.c) ---- */
typedef struct rt_photon {
    float pos[3];
    float dir[3];   /* propagation direction before the scattering event */
    float power[3]; /* flux scattered at the event */
    unsigned object_id;
} rt_photon;

typedef struct rt_photon_map {
    rt_photon *photons; /* sorted by hash cell */
    size_t n;
    uint32_t *cell_start; /* n_cells + 1 */
    size_t n_cells;       /* power of two */
    double radius;
    long long emitted;
} rt_photon_map;

void rt_photons_free(rt_photon_map *map);
/* Stores n photons (copied) into map's hash grid; map->radius already set. */
soak_status rt_photon_map_store(rt_photon_map *map, const rt_photon *photons, size_t n);
/* sigma_s L_s estimate: sum over photons of object obj within the radius of
 * p(cos) * power / V, cos between the photon's propagation and the reverse of
 * the camera path direction d_in; V the part of the gather sphere below a
 * flat surface at distance depth above x (the whole sphere, 4/3 pi r^3, for
 * depth >= r or INFINITY: no surface known). */
soak_rgb rt_photons_gather(const rt_photon_map *map, soak_vec3 x, soak_vec3 d_in, const soak_hg2 *phase, unsigned obj,
                           double depth);
/* Volume of the sphere of radius r below a plane at distance depth above its
 * centre (depth clamped to [0, r]). */
double rt_sphere_volume_below(double r, double depth);

/* ---- caustic photons (render_photons.c) ---- */
/* Traces n photons from the sun and point lights through dielectric objects
 * and stores them at their first scattering event inside a wet medium.
 * Stops early (keeping what is traced, rescaled) when *cancel becomes
 * non-zero or the monotonic clock passes deadline (0: none). */
soak_status rt_photons_build(const rt_ctx *c, long long n, double radius, uint64_t seed,
                             const volatile sig_atomic_t *cancel, double deadline, rt_photon_map *map);

#endif
