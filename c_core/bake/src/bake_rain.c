/* Rain wetting of a mesh in UV space; the model is documented step by step
 * in soak/bake_rain.h (steps 1-4 below refer to it). */
#include "soak/bake_rain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/poisson.h"

#include "bake_rain_film.h"
#include "bake_rain_runnels.h"
#include "bake_rain_flow.h"
#include "bake_rain_level.h"
#include "bake_rain_scene.h"
#include "bake_rain_surface.h"

static const int *const DX = SOAK_RAIN_DX;
static const int *const DY = SOAK_RAIN_DY;

void soak_rain_defaults(soak_rain_params *p)
{
    memset(p, 0, sizeof *p);
    p->rays = 64;
    p->sky = SOAK_RAIN_SKY_RAIN;
    p->up = soak_v3(0, 0, 1);
    p->rain_dir = soak_v3(0, 0, 1);
    p->spread_deg = 10;
    p->duration = 600;
    p->steps = 32;
    p->rainfall_mm_h = 10;
    p->drop_diameter = 0.002;
    p->splat_radius = 0.002;
    p->evaporation_mm_h = 0.5;
    p->retention = 0.0002;
    p->saturation_depth = 0.0002;
    p->flow_iterations = 16;
    p->gutter = 4;
    p->film = 1;
}

static int unit_ok(soak_vec3 v)
{
    double l = soak_v3_len(v);
    return soak_is_finite(l) && l > 1e-12;
}

soak_status soak_rain_check(const soak_rain_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!(p->rays >= 1 && p->rays <= SOAK_RAIN_MAX_RAYS) || !(p->steps >= 1 && p->steps <= SOAK_RAIN_MAX_STEPS) ||
        !(p->flow_iterations >= 0 && p->flow_iterations <= SOAK_RAIN_MAX_STEPS) ||
        !(p->gutter >= 0 && p->gutter <= SOAK_RAIN_MAX_GUTTER) || (p->film != 0 && p->film != 1) ||
        (p->sky != SOAK_RAIN_SKY_RAIN && p->sky != SOAK_RAIN_SKY_HEMISPHERE))
        return SOAK_ERR_ARG;
    if (!unit_ok(p->up) || !unit_ok(p->rain_dir)) return SOAK_ERR_ARG;
    if (!(soak_v3_dot(soak_v3_norm(p->up), soak_v3_norm(p->rain_dir)) > 1e-6)) return SOAK_ERR_ARG;
    if (!soak_in_range(p->spread_deg, 0, SOAK_RAIN_MAX_SPREAD) || !soak_in_range(p->duration, 0, SOAK_RAIN_MAX_DURATION) ||
        !soak_in_range(p->rainfall_mm_h, 0, SOAK_RAIN_MAX_RATE) ||
        !(p->drop_diameter > 0 && p->drop_diameter <= SOAK_RAIN_MAX_DROP) ||
        !soak_in_range(p->splat_radius, 0, SOAK_RAIN_MAX_SPLAT) ||
        !soak_in_range(p->evaporation_mm_h, 0, SOAK_RAIN_MAX_RATE) ||
        !soak_in_range(p->retention, 0, SOAK_RAIN_MAX_RETENTION) ||
        !(p->saturation_depth > 0 && p->saturation_depth <= SOAK_RAIN_MAX_SATURATION) ||
        !soak_in_range(p->contact_angle_deg, 0, 90))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* ---- step 2: exposure ---- */

typedef struct exposure_job {
    const rain_surface *s;
    const soak_geometry *g;
    const soak_rain_params *p;
    soak_vec3 up, rain_dir, rt, rb;
    double cos_spread, f_open;
    float *out;
    int failed;
} exposure_job;

/* The rays of one texel go to the occlusion test in batches of BATCH
 * (Embree packets); the weights are added in ray order, so acc is the sum a
 * ray-by-ray loop makes. A ray starts at the texel's point moved off the
 * surface to its side (soak_geometry_offset): one of two origins per texel. */
enum { BATCH = 64 };

typedef struct ray_batch {
    soak_vec3 org[2]; /* [0]: moved along n, [1]: against it */
    soak_vec3 dir[BATCH];
    double weight[BATCH];
    unsigned char side[BATCH];
    int n;
} ray_batch;

static double add_unoccluded(exposure_job *j, ray_batch *b, double acc)
{
    soak_vec3 dirs[2][BATCH];
    int ray_of[2][BATCH], count[2] = {0, 0}, occ[2][BATCH], blocked[BATCH];
    for (int q = 0; q < b->n; ++q) {
        int s = b->side[q];
        dirs[s][count[s]] = b->dir[q];
        ray_of[s][count[s]++] = q;
    }
    for (int s = 0; s < 2; ++s) {
        if (!count[s]) continue;
        memset(occ[s], 0, sizeof occ[s]);
        if (soak_geometry_occluded_fan(j->g, b->org[s], dirs[s], (size_t)count[s], occ[s]) != SOAK_OK) j->failed = 1;
        for (int k = 0; k < count[s]; ++k) blocked[ray_of[s][k]] = occ[s][k];
    }
    for (int q = 0; q < b->n; ++q)
        if (!blocked[q]) acc += b->weight[q];
    b->n = 0;
    return acc;
}

/* The sky exposure of texel i: the weighted share of its N rays that leave
 * the mesh. */
static double texel_exposure(exposure_job *j, size_t i, ray_batch *b)
{
    const rain_surface *s = j->s;
    int N = j->p->rays;
    soak_vec3 p = soak_rain_vget(s->pos, i), n = soak_rain_fget(s->nrm, i), t, bt;
    soak_v3_basis(n, &t, &bt);
    b->org[0] = soak_geometry_offset(p, n, n);
    b->org[1] = soak_geometry_offset(p, n, soak_v3_scale(n, -1.0));
    b->n = 0;
    soak_rng rng;
    soak_rng_seed(&rng, j->p->seed, (uint64_t)i);
    double acc = 0.0;
    for (int k = 0; k < N; ++k) {
        double xi1 = (k + soak_rng_uniform(&rng)) / N, xi2 = soak_rng_uniform(&rng);
        double phi = 2.0 * SOAK_PI * xi2, weight;
        soak_vec3 u;
        if (j->p->sky == SOAK_RAIN_SKY_HEMISPHERE) {
            double ct = sqrt(1.0 - xi1), st = sqrt(xi1);
            u = soak_v3_add(soak_v3_scale(n, ct), soak_v3_add(soak_v3_scale(t, st * cos(phi)),
                                                               soak_v3_scale(bt, st * sin(phi))));
            weight = 1.0;
        } else {
            double ct = 1.0 - xi1 * (1.0 - j->cos_spread), st2 = 1.0 - ct * ct;
            double st = sqrt(st2 > 0.0 ? st2 : 0.0); /* fmax(0, st2)'s value: st2 is never -0 */
            u = soak_v3_add(soak_v3_scale(j->rain_dir, ct),
                            soak_v3_add(soak_v3_scale(j->rt, st * cos(phi)), soak_v3_scale(j->rb, st * sin(phi))));
            weight = soak_v3_dot(n, u) / j->f_open;
            if (!(weight > 0.0)) continue;
        }
        b->dir[b->n] = u;
        b->weight[b->n] = weight;
        b->side[b->n++] = !(soak_v3_dot(u, n) >= 0); /* soak_geometry_offset's choice of side */
        if (b->n == BATCH) acc = add_unoccluded(j, b, acc);
    }
    if (b->n) acc = add_unoccluded(j, b, acc);
    return acc / N;
}

static void exposure_row(void *ctx, int y, int thread)
{
    (void)thread;
    exposure_job *j = ctx;
    const rain_surface *s = j->s;
    ray_batch b;
    for (int x = 0; x < s->w; ++x) {
        size_t i = (size_t)y * s->w + x;
        j->out[i] = s->tri[i] < 0 ? 0.0f : (float)texel_exposure(j, i, &b);
    }
}

/* ---- step 3: rain, splat, evaporation, flow ---- */

typedef struct water_job {
    const rain_surface *s;
    const soak_rain_params *p;
    const float *exposure;
    double *depth;     /* water depth per texel, m */
    float *deposit;    /* drop volume per texel this step */
    double *retain;    /* film kept per texel */
    double lambda_per_area, drop_volume, evaporation;
    uint64_t step_seed;
} water_job;

static void evaporate_row(void *ctx, int y, int thread)
{
    (void)thread;
    water_job *j = ctx;
    for (size_t i = (size_t)y * j->s->w, end = i + j->s->w; i < end; ++i)
        j->depth[i] = j->depth[i] > j->evaporation ? j->depth[i] - j->evaporation : 0.0;
}

static void drops_row(void *ctx, int y, int thread)
{
    (void)thread;
    water_job *j = ctx;
    const rain_surface *s = j->s;
    for (int x = 0; x < s->w; ++x) {
        size_t i = (size_t)y * s->w + x;
        j->deposit[i] = 0.0f;
        if (s->tri[i] < 0) continue;
        double lambda = j->lambda_per_area * j->exposure[i] * s->area[i];
        if (!(lambda > 0.0)) continue;
        soak_rng rng;
        soak_rng_seed(&rng, j->step_seed, (uint64_t)i);
        j->deposit[i] = (float)(soak_rng_poisson(lambda, &rng) * j->drop_volume);
    }
}

static void add_deposit_row(void *ctx, int y, int thread)
{
    (void)thread;
    water_job *j = ctx;
    const rain_surface *s = j->s;
    for (int x = 0; x < s->w; ++x) {
        size_t i = (size_t)y * s->w + x;
        if (s->tri[i] >= 0 && s->area[i] > 0.0f) j->depth[i] += j->deposit[i] / s->area[i];
    }
}

/* Step 3b: the falling film into film and, where thicker, into retain. */
static soak_status add_film(const rain_surface *s, const soak_rain_params *p, const soak_rain_flow_grid *grid,
                            const float *exposure, double *retain, double *film, soak_rain_runoff *runoff)
{
    size_t n = (size_t)s->w * s->h;
    float *up_dot_n = malloc(n * sizeof *up_dot_n);
    if (!up_dot_n) return SOAK_ERR_NOMEM;
    soak_vec3 up = soak_v3_norm(p->up);
    soak_rain_flow_balance b;
    for (size_t i = 0; i < n; ++i)
        up_dot_n[i] = s->tri[i] >= 0 ? (float)soak_v3_dot(soak_rain_fget(s->nrm, i), up) : 1.0f;
    soak_status st = soak_rain_film_map(grid, up_dot_n, exposure, p->rainfall_mm_h / 3.6e6,
                                        p->evaporation_mm_h / 3.6e6, film, &b);
    if (st == SOAK_OK) *runoff = (soak_rain_runoff){b.in, b.dripped, b.held, b.lost};
    for (size_t i = 0; i < n && st == SOAK_OK; ++i)
        if (film[i] > retain[i]) retain[i] = film[i];
    free(up_dot_n);
    return st;
}

/* What moves the water of a step: the sweeps and, with the film, the
 * cascade down the slopes (its order and scratch; order NULL without). */
typedef struct water_flow {
    const soak_rain_flow_grid *grid;
    soak_rain_flow_plan *plan;
    soak_rain_level_plan *puddles; /* NULL: no flow */
    size_t *order, count;
    double *inflow;
    unsigned char *fast; /* 1 where the film is thicker than the static retention */
    double sigma_texels, evaporation;
} water_flow;

/* Step `step` of step 3: drops, splat, cascade, sweeps, evaporation. */
static soak_status rain_step(water_job *j, const water_flow *f, int step, const soak_bake_exec *exec)
{
    const rain_surface *s = j->s;
    size_t n = (size_t)s->w * s->h;
    double lo = 0.7 + 0.3 * step / j->p->steps, dripped;
    j->step_seed = soak_seed_derive(j->p->seed, (uint64_t)step + 1);
    soak_status st = soak_parallel_rows(s->h, exec, drops_row, j, lo, lo);
    if (st == SOAK_OK && f->sigma_texels >= 0.3) {
        soak_image in = {s->w, s->h, 1, j->deposit}, blurred = {0, 0, 0, NULL};
        st = soak_map_blur(&in, fmin(f->sigma_texels, 1000.0), 0, exec, &blurred);
        if (st == SOAK_OK) memcpy(j->deposit, blurred.pixels, n * sizeof *j->deposit);
        soak_image_free(&blurred);
    }
    if (st == SOAK_OK) st = soak_parallel_rows(s->h, exec, add_deposit_row, j, lo, lo);
    if (st == SOAK_OK && f->order)
        st = soak_rain_flow_cascade(f->grid, f->fast, f->order, f->count, j->depth, f->inflow, &dripped);
    if (st == SOAK_OK && f->puddles) st = soak_rain_level_run(f->puddles, j->depth);
    if (st == SOAK_OK) st = soak_rain_flow_run(f->plan, j->depth, j->p->flow_iterations, exec, lo, lo);
    j->evaporation = f->evaporation;
    if (st == SOAK_OK) st = soak_parallel_rows(s->h, exec, evaporate_row, j, lo, lo);
    return st;
}

/* Step 3c: thin films into rivulets; the film's texels keep the larger of
 * their static retention and the rivulets' depth (they stay fast: the
 * water between the rivulets runs on). */
static soak_status add_runnels(const rain_surface *s, const soak_rain_params *p, const water_flow *f, double *retain,
                               double *film, soak_rain_result *out)
{
    if (!(p->contact_angle_deg > 0.0)) return SOAK_OK;
    soak_rain_runnel_stats rs;
    soak_status st = soak_rain_runnels(s, f->grid, p->up, p->contact_angle_deg * SOAK_PI / 180.0, p->seed, film, &rs);
    if (st != SOAK_OK) return st;
    out->runnel_texels = rs.broken, out->runnel_spacing = rs.spacing;
    soak_vec3 up = soak_v3_norm(p->up);
    for (size_t i = 0, n = (size_t)s->w * s->h; i < n; ++i) {
        if (!f->fast[i]) continue;
        double flat = p->retention * fmax(0.0, soak_v3_dot(soak_rain_fget(s->nrm, i), up));
        retain[i] = film[i] > flat ? film[i] : flat;
    }
    return SOAK_OK;
}

/* The film (step 3b) and what the cascade needs, when the film is on and
 * the water flows at all. */
static soak_status prepare_film(const rain_surface *s, const soak_rain_params *p, const float *exposure,
                                water_job *j, water_flow *f, double *film, soak_rain_result *out)
{
    if (!p->film) return SOAK_OK;
    size_t n = (size_t)s->w * s->h;
    f->fast = malloc(n);
    if (!f->fast) return SOAK_ERR_NOMEM;
    for (size_t i = 0; i < n; ++i) f->fast[i] = 0; /* the static retention is in j->retain until add_film */
    soak_status st = add_film(s, p, f->grid, exposure, j->retain, film, &out->runoff);
    for (size_t i = 0; i < n && st == SOAK_OK; ++i) f->fast[i] = film[i] > 0.0 && film[i] == j->retain[i];
    if (st == SOAK_OK) st = add_runnels(s, p, f, j->retain, film, out);
    if (st != SOAK_OK || p->flow_iterations == 0) return st;
    f->inflow = malloc(n * sizeof *f->inflow);
    if (!f->inflow) return SOAK_ERR_NOMEM;
    return soak_rain_flow_order(f->grid, &f->order, &f->count);
}

static soak_status run_water(const rain_surface *s, const soak_rain_params *p, const float *exposure,
                             const soak_bake_exec *exec, double *depth, double *film, soak_rain_result *out)
{
    size_t n = (size_t)s->w * s->h;
    water_job j;
    memset(&j, 0, sizeof j);
    j.s = s;
    j.p = p;
    j.exposure = exposure;
    j.depth = depth;
    j.deposit = malloc(n * sizeof *j.deposit);
    j.retain = malloc(n * sizeof *j.retain);
    unsigned char *covered = malloc(n);
    water_flow f;
    memset(&f, 0, sizeof f);
    soak_rain_flow_grid grid = {s->w, s->h, covered, s->adj, s->area, s->drip, s->level, j.retain, s->descent};
    f.grid = &grid;
    soak_status st = j.deposit && j.retain && covered ? SOAK_OK : SOAK_ERR_NOMEM;
    soak_vec3 up = soak_v3_norm(p->up);
    for (size_t i = 0; i < n && st == SOAK_OK; ++i) {
        covered[i] = s->tri[i] >= 0;
        j.retain[i] = covered[i] ? p->retention * fmax(0.0, soak_v3_dot(soak_rain_fget(s->nrm, i), up)) : 0.0;
    }
    if (st == SOAK_OK) st = prepare_film(s, p, exposure, &j, &f, film, out);
    if (st == SOAK_OK) st = soak_rain_flow_create(&grid, exec, SOAK_RAIN_FLOW_AUTO, &f.plan);
    if (st == SOAK_OK && p->flow_iterations > 0) st = soak_rain_level_create(&grid, &f.puddles);
    double dt = p->duration / p->steps;
    f.evaporation = p->evaporation_mm_h / 3.6e6 * dt;
    j.drop_volume = SOAK_PI / 6.0 * p->drop_diameter * p->drop_diameter * p->drop_diameter;
    j.lambda_per_area = p->rainfall_mm_h / 3.6e6 / j.drop_volume * dt; /* drops per m^2 of open horizontal surface per step */
    f.sigma_texels = s->mean_texel > 0.0 ? p->splat_radius / s->mean_texel : 0.0;
    for (int step = 0; step < p->steps && st == SOAK_OK; ++step) st = rain_step(&j, &f, step, exec);
    soak_rain_flow_destroy(f.plan);
    soak_rain_level_destroy(f.puddles);
    free(f.order);
    free(f.inflow);
    free(f.fast);
    free(j.deposit);
    free(j.retain);
    free(covered);
    return st;
}

/* ---- outputs ---- */

typedef struct dilate_job {
    const float *img;
    const unsigned char *filled;
    float *val;
    unsigned char *next;
    int w, h;
} dilate_job;

/* One ring of row y: each empty texel with filled neighbours takes their
 * mean (reads img and filled, writes val and next). */
static void dilate_row(void *ctx, int y, int thread)
{
    (void)thread;
    const dilate_job *j = ctx;
    int w = j->w, h = j->h;
    for (int x = 0; x < w; ++x) {
        size_t i = (size_t)y * w + x;
        if (j->filled[i]) continue;
        double sum = 0.0;
        int c = 0;
        for (int d = 0; d < 8; ++d) {
            int kx = x + DX[d], ky = y + DY[d];
            if (kx < 0 || ky < 0 || kx >= w || ky >= h || !j->filled[(size_t)ky * w + kx]) continue;
            sum += j->img[(size_t)ky * w + kx];
            ++c;
        }
        if (c) {
            j->val[i] = (float)(sum / c);
            j->next[i] = 1;
        }
    }
}

/* Empty texels take the mean of their filled neighbours, `gutter` rings. */
static soak_status dilate(float *img, unsigned char *filled, int w, int h, int gutter, const soak_bake_exec *exec)
{
    size_t n = (size_t)w * h;
    unsigned char *next = malloc(n);
    float *val = malloc(n * sizeof *val);
    soak_status st = next && val ? SOAK_OK : SOAK_ERR_NOMEM;
    dilate_job j = {img, filled, val, next, w, h};
    for (int g = 0; g < gutter && st == SOAK_OK; ++g) {
        memcpy(next, filled, n);
        memcpy(val, img, n * sizeof *val);
        st = soak_parallel_rows(h, exec, dilate_row, &j, 1.0, 1.0);
        memcpy(filled, next, n);
        memcpy(img, val, n * sizeof *val);
    }
    free(next);
    free(val);
    return st;
}

double soak_rain_wetness(double depth, double film, double saturation_depth)
{
    if (film >= SOAK_RAIN_FILM_RUNNING) return 1.0; /* a running film: pores full, texel covered */
    if (!(depth > 0.0) || !(saturation_depth > 0.0)) return 0.0;
    return 1.0 - exp(-depth / saturation_depth);
}

typedef struct output_job {
    const rain_surface *s;
    const double *depth, *film;
    double saturation_depth;
    soak_rain_result *r;
} output_job;

static void output_row(void *ctx, int y, int thread)
{
    (void)thread;
    const output_job *j = ctx;
    for (size_t i = (size_t)y * j->s->w, end = i + j->s->w; i < end; ++i) {
        j->r->coverage.pixels[i] = j->s->tri[i] >= 0 ? 1.0f : 0.0f;
        j->r->water.pixels[i] = (float)j->depth[i];
        j->r->film.pixels[i] = (float)j->film[i];
        j->r->wetness.pixels[i] = (float)soak_rain_wetness(j->depth[i], j->film[i], j->saturation_depth);
    }
}

void soak_rain_result_free(soak_rain_result *r)
{
    if (!r) return;
    soak_image_free(&r->wetness);
    soak_image_free(&r->exposure);
    soak_image_free(&r->water);
    soak_image_free(&r->coverage);
    soak_image_free(&r->film);
}

static soak_status build_geometry(const soak_mesh *mesh, soak_geometry **g, char *err, size_t errlen)
{
    soak_status st = soak_geometry_create(g, err, errlen);
    if (st != SOAK_OK) return st;
    unsigned id;
    st = soak_geometry_add_mesh(*g, mesh, NULL, &id);
    if (st == SOAK_OK) st = soak_geometry_commit(*g);
    if (st != SOAK_OK) {
        if (err && errlen) snprintf(err, errlen, "cannot build the ray-tracing scene of the mesh (%s)", soak_status_str(st));
        soak_geometry_destroy(*g);
        *g = NULL;
    }
    return st;
}

/* Steps 1 and 2: the surface of mesh and its sky exposure (allocated into
 * *exposure); on error neither is kept. */
static soak_status surface_and_exposure(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                                        const soak_bake_exec *exec, double progress_hi, rain_surface *s,
                                        soak_image *exposure, soak_uv_stats *uv, char *err, size_t errlen)
{
    soak_status st = soak_rain_check(p);
    if (st != SOAK_OK) {
        if (err && errlen) snprintf(err, errlen, "rain parameters out of range");
        return st;
    }
    if ((st = soak_bake_check_size(width, height)) != SOAK_OK) return st;
    if (exec && soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;
    if ((st = soak_rain_check_mesh(mesh, err, errlen)) != SOAK_OK) return st;
    soak_vec3 up = soak_v3_norm(p->up);
    if ((st = soak_rain_surface_alloc(s, width, height)) != SOAK_OK) return st;
    soak_geometry *g = NULL;
    st = soak_rain_rasterise(mesh, &p->uv, s, up, uv, err, errlen);
    if (st == SOAK_OK) st = soak_rain_surface_connect(s, up, exec);
    if (st == SOAK_OK) st = build_geometry(mesh, &g, err, errlen);
    if (st == SOAK_OK) st = soak_image_alloc(exposure, width, height, 1);
    if (st == SOAK_OK) {
        exposure_job ej;
        memset(&ej, 0, sizeof ej);
        ej.s = s;
        ej.g = g;
        ej.p = p;
        ej.up = up;
        ej.rain_dir = soak_v3_norm(p->rain_dir);
        soak_v3_basis(ej.rain_dir, &ej.rt, &ej.rb);
        ej.cos_spread = cos(p->spread_deg * SOAK_PI / 180.0);
        ej.f_open = soak_v3_dot(ej.rain_dir, up) * 0.5 * (1.0 + ej.cos_spread);
        ej.out = exposure->pixels;
        st = soak_parallel_rows(height, exec, exposure_row, &ej, 0.0, progress_hi);
        if (st == SOAK_OK && ej.failed) st = SOAK_ERR_NUMERIC;
        if (st != SOAK_OK) soak_image_free(exposure);
    }
    soak_geometry_destroy(g);
    if (st != SOAK_OK) soak_rain_surface_free(s);
    return st;
}

soak_status soak_bake_rain(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                           const soak_bake_exec *exec, soak_rain_result *out, char *err, size_t errlen)
{
    if (!mesh || !p || !out) return SOAK_ERR_NULL;
    rain_surface s;
    soak_rain_result r;
    memset(&r, 0, sizeof r);
    soak_status st = surface_and_exposure(mesh, width, height, p, exec, p->duration > 0 ? 0.7 : 1.0, &s,
                                          &r.exposure, &r.uv, err, errlen);
    if (st != SOAK_OK) return st;
    size_t n = (size_t)width * height;
    if (st == SOAK_OK) st = soak_image_alloc(&r.wetness, width, height, 1);
    if (st == SOAK_OK) st = soak_image_alloc(&r.water, width, height, 1);
    if (st == SOAK_OK) st = soak_image_alloc(&r.coverage, width, height, 1);
    if (st == SOAK_OK) st = soak_image_alloc(&r.film, width, height, 1);
    double *depth = st == SOAK_OK ? calloc(n, sizeof *depth) : NULL, *film = st == SOAK_OK ? calloc(n, sizeof *film) : NULL;
    if (st == SOAK_OK && (!depth || !film)) st = SOAK_ERR_NOMEM;
    if (st == SOAK_OK && p->duration > 0 && p->rainfall_mm_h > 0)
        st = run_water(&s, p, r.exposure.pixels, exec, depth, film, &r);
    if (st == SOAK_OK) {
        unsigned char *filled = malloc(n);
        if (!filled) st = SOAK_ERR_NOMEM;
        output_job oj = {&s, depth, film, p->saturation_depth, &r};
        if (st == SOAK_OK) st = soak_parallel_rows(height, exec, output_row, &oj, 1.0, 1.0);
        float *maps[4] = {r.exposure.pixels, r.water.pixels, r.wetness.pixels, r.film.pixels};
        for (int k = 0; k < 4 && st == SOAK_OK; ++k) {
            for (size_t i = 0; i < n; ++i) filled[i] = s.tri[i] >= 0;
            st = dilate(maps[k], filled, width, height, p->gutter, exec);
        }
        free(filled);
    }
    free(depth);
    free(film);
    soak_rain_surface_free(&s);
    if (st != SOAK_OK) {
        soak_rain_result_free(&r);
        return st;
    }
    *out = r;
    return SOAK_OK;
}

/* ---- the scene of the frame sequence (bake_rain_scene.h) ---- */

void soak_rain_scene_free(soak_rain_scene *sc)
{
    if (!sc) return;
    free(sc->covered);
    free(sc->adj);
    free(sc->area);
    free(sc->drip);
    free(sc->level);
    free(sc->descent);
    free(sc->up_dot_n);
    soak_rain_runnel_field_free(&sc->runnels);
    soak_image_free(&sc->exposure);
    memset(sc, 0, sizeof *sc);
}

soak_status soak_rain_scene_build(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                                  const soak_bake_exec *exec, soak_rain_scene *out, char *err, size_t errlen)
{
    if (!mesh || !p || !out) return SOAK_ERR_NULL;
    memset(out, 0, sizeof *out);
    rain_surface s;
    soak_status st = surface_and_exposure(mesh, width, height, p, exec, 1.0, &s, &out->exposure, &out->uv, err, errlen);
    if (st != SOAK_OK) return st;
    size_t n = (size_t)width * height;
    out->w = width, out->h = height;
    soak_vec3 up = soak_v3_norm(p->up);
    if (p->film && p->contact_angle_deg > 0.0) /* step 3c, placed on the steady film later */
        st = soak_rain_runnel_field_make(&s, up, p->contact_angle_deg * SOAK_PI / 180.0, &out->runnels);
    out->covered = malloc(n), out->up_dot_n = malloc(n * sizeof *out->up_dot_n);
    out->adj = s.adj, out->area = s.area, out->drip = s.drip, out->level = s.level, out->descent = s.descent;
    s.adj = NULL, s.area = NULL, s.drip = NULL, s.level = NULL, s.descent = NULL;
    if (st == SOAK_OK && out->covered && out->up_dot_n)
        for (size_t i = 0; i < n; ++i) {
            out->covered[i] = s.tri[i] >= 0;
            out->up_dot_n[i] = s.tri[i] >= 0 ? (float)soak_v3_dot(soak_rain_fget(s.nrm, i), up) : 1.0f;
        }
    else if (st == SOAK_OK)
        st = SOAK_ERR_NOMEM;
    soak_rain_surface_free(&s);
    if (st != SOAK_OK) soak_rain_scene_free(out);
    return st;
}

soak_status soak_rain_dilate(float *img, const unsigned char *covered, int w, int h, int gutter,
                             const soak_bake_exec *exec)
{
    unsigned char *filled = malloc((size_t)w * h);
    if (!filled) return SOAK_ERR_NOMEM;
    memcpy(filled, covered, (size_t)w * h);
    soak_status st = dilate(img, filled, w, h, gutter, exec);
    free(filled);
    return st;
}
