/* Path tracer driver: camera rays, the path loop (emission with MIS,
 * Russian roulette), and the tiled multi-threaded, progressive render with
 * early stop. Surfaces: render_surface.c; media: render_medium.c; lights:
 * render_lights.c. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "rt_ctx.h"
#include "render_adaptive.h"
#include "render_lights.h"
#include "render_surface.h"
#include "render_bsdfs.h"
#include "render_levels.h"
#include "render_photon_map.h"
#include "render_photons.h"

#define TILE 16

void soak_render_options_default(soak_render_options *o)
{
    memset(o, 0, sizeof *o);
    o->threads = 1;
}

void soak_render_expose(soak_image *img, double stops)
{
    if (!img || !img->pixels || !soak_in_range(stops, -50, 50)) return;
    float k = (float)pow(2.0, stops);
    size_t n = (size_t)img->width * img->height * img->channels;
    for (size_t i = 0; i < n; ++i) img->pixels[i] *= k;
}

typedef struct cam_setup {
    soak_vec3 pos, fwd, right, up;
    double tan_half, aspect, aperture, focus;
    int W, H;
} cam_setup;

static soak_vec3 camera_ray(rt_thread *t, const cam_setup *c, int px, int py, soak_vec3 *org)
{
    double jx, jy;
    rt_rand2(t, &jx, &jy);
    double sx = (2 * (px + jx) / c->W - 1) * c->tan_half * c->aspect;
    double sy = (1 - 2 * (py + jy) / c->H) * c->tan_half;
    soak_vec3 d = soak_v3_norm(soak_v3_add(c->fwd, soak_v3_add(soak_v3_scale(c->right, sx), soak_v3_scale(c->up, sy))));
    *org = c->pos;
    if (c->aperture > 0) {
        /* Thin lens: every ray through the lens disk meets at the focus plane. */
        soak_vec3 focus = soak_v3_add(c->pos, soak_v3_scale(d, c->focus / soak_v3_dot(d, c->fwd)));
        double ur, uphi;
        rt_rand2(t, &ur, &uphi);
        double r = c->aperture * sqrt(ur), phi = 2 * SOAK_PI * uphi;
        *org = soak_v3_add(c->pos, soak_v3_add(soak_v3_scale(c->right, r * cos(phi)), soak_v3_scale(c->up, r * sin(phi))));
        d = soak_v3_norm(soak_v3_sub(focus, *org));
    }
    return d;
}

static int light_of_object(const soak_scene *s, unsigned object_id)
{
    for (int i = 0; i < s->n_lights; ++i)
        if (s->lights[i].type == SOAK_LIGHT_SPHERE && s->lights[i].object_id == object_id) return i;
    return -1;
}

static soak_rgb radiance(rt_thread *t, soak_vec3 org, soak_vec3 dir)
{
    const rt_ctx *c = t->ctx;
    const soak_scene *s = c->scene;
    rt_path path;
    memset(&path, 0, sizeof path);
    path.beta = soak_rgb3(1, 1, 1);
    path.eta_scale = 1.0;
    path.org = org;
    path.dir = dir;
    path.prev_delta = 1;
    path.alive = 1;
    for (int depth = 0;; ++depth) {
        if (depth >= c->max_depth) {
            if (rgb_max(path.beta) > 0) t->n.capped++;
            break;
        }
        soak_ray ray = {path.org, path.dir, 0.0, INFINITY};
        soak_hit hit;
        int found = 0;
        t->n.rays++;
        if (soak_geometry_intersect(s->geometry, &ray, &hit, &found) != SOAK_OK) {
            t->n.geom_errors++;
            break;
        }
        if (!found) {
            if (s->env.type != SOAK_ENV_NONE) {
                double w = path.prev_delta ? 1.0 : rt_power(path.prev_pdf, rt_env_pdf(c, path.dir));
                path.L = soak_rgb_add(path.L, soak_rgb_scale(soak_rgb_mul(path.beta, rt_env_eval(c, path.dir)), w));
            }
            break;
        }
        if (path.inside) path.beta = soak_rgb_mul(path.beta, rgb_exp(path.absorb, hit.t));
        const soak_material *m = &s->materials[s->objects[hit.object_id].material];
        if (m->type == SOAK_MAT_EMITTER) {
            int li = light_of_object(s, hit.object_id);
            if (li >= 0 && soak_v3_dot(path.dir, hit.ng) < 0) {
                double w = path.prev_delta ? 1.0
                                           : rt_power(path.prev_pdf, rt_sphere_light_pdf(&s->lights[li], path.prev_pos));
                path.L = soak_rgb_add(path.L, soak_rgb_scale(soak_rgb_mul(path.beta, m->radiance), w));
            }
            break;
        }
        rt_surface(t, &hit, &path);
        if (!path.alive) break;
        if (depth >= 3) {
            /* Roulette with survival min(1, max beta): unbiased, and it never
             * fires while the throughput stays at 1 (albedo 1). */
            double q = fmin(1.0, rt_rr_weight(&path));
            if (!(q > 0) || rt_rand(t) >= q) break;
            path.beta = soak_rgb_scale(path.beta, 1.0 / q);
        }
    }
    if (!(soak_is_finite(path.L.r) && soak_is_finite(path.L.g) && soak_is_finite(path.L.b))) {
        t->n.nan_paths++;
        return soak_rgb3(0, 0, 0);
    }
    return path.L;
}

typedef struct worker_arg worker_arg;

typedef struct render_job {
    rt_ctx ctx;
    rt_material_bsdf *bsdfs; /* ctx.bsdfs, owned */
    rt_levels *levels;       /* ctx.levels, owned */
    rt_photon_map caustics;
    cam_setup cam;
    int W, H, spp, passes, tiles_x, tiles_y, n_tiles, threads;
    int *pass_start; /* passes + 1 entries: samples [pass_start[p], pass_start[p+1]) */
    uint64_t seed;
    long total_items;
    atomic_long next_item;
    atomic_long done_items;
    atomic_int stop;
    atomic_int workers_left;
    atomic_int out_of_memory;
    double *sum;            /* 3 per pixel */
    double *sum_y, *sum_y2; /* luminance and its square per pixel: target_error only */
    double target_error;
    int want_variance;     /* soak_render_options.variance: sum_y, sum_y2 kept for it */
    atomic_int *tile_done; /* target_error reached: later passes are skipped */
    int *count;            /* samples per pixel */
    int *tile_pass;        /* passes merged per tile */
    worker_arg *args;      /* threads entries */
    pthread_t *th;         /* threads entries */
    pthread_mutex_t lock;
    pthread_cond_t merged;
} render_job;

struct worker_arg {
    render_job *job;
    rt_counters n;
    long long paths;
};

/* One work item: samples [s0, s1) of the pixels [x0, x1) x [y0, y1) of a tile. */
typedef struct tile_item {
    int pass, tile, x0, y0, x1, y1, s0, s1;
} tile_item;

static tile_item tile_item_of(const render_job *j, long item)
{
    tile_item it;
    it.pass = (int)(item / j->n_tiles);
    it.tile = (int)(item % j->n_tiles);
    it.x0 = (it.tile % j->tiles_x) * TILE;
    it.y0 = (it.tile / j->tiles_x) * TILE;
    it.x1 = it.x0 + TILE < j->W ? it.x0 + TILE : j->W;
    it.y1 = it.y0 + TILE < j->H ? it.y0 + TILE : j->H;
    it.s0 = j->pass_start[it.pass];
    it.s1 = j->pass_start[it.pass + 1];
    return it;
}

/* Traces the item's samples into the tile-local sums and counts. */
static void trace_tile(rt_thread *t, worker_arg *a, const tile_item *it, double *local, int *lcount)
{
    render_job *j = a->job;
    int tw = it->x1 - it->x0;
    double *local_y2 = local + TILE * TILE * 3;
    memset(local, 0, (size_t)TILE * TILE * 4 * sizeof(double));
    memset(lcount, 0, (size_t)TILE * TILE * sizeof(int));
    for (int y = it->y0; y < it->y1 && !atomic_load(&j->stop); ++y)
        for (int x = it->x0; x < it->x1; ++x) {
            uint64_t pixel = (uint64_t)y * (uint64_t)j->W + (uint64_t)x;
            double *acc = local + 3 * ((y - it->y0) * tw + (x - it->x0));
            for (int sidx = it->s0; sidx < it->s1; ++sidx) {
                soak_rng_seed(&t->rng, j->seed, pixel * (uint64_t)j->spp + (uint64_t)sidx);
                rt_qmc_start(t, j->seed, pixel, (uint32_t)sidx);
                soak_vec3 org, dir = camera_ray(t, &j->cam, x, y, &org);
                soak_rgb L = radiance(t, org, dir);
                acc[0] += L.r;
                acc[1] += L.g;
                acc[2] += L.b;
                double lum = soak_rgb_luminance(L);
                local_y2[(y - it->y0) * tw + (x - it->x0)] += lum * lum;
                a->paths++;
            }
            lcount[(y - it->y0) * tw + (x - it->x0)] = it->s1 - it->s0;
        }
}

static int tile_converged(const render_job *j, const tile_item *it)
{
    for (int y = it->y0; y < it->y1; ++y) {
        size_t row = (size_t)y * j->W + it->x0;
        if (!rt_adaptive_converged(j->sum_y + row, j->sum_y2 + row, j->count + row, it->x1 - it->x0, j->target_error))
            return 0;
    }
    return 1;
}

/* Merges passes of a tile in order so sums do not depend on scheduling;
 * local == NULL (out of memory) only advances the tile's pass. */
static void merge_tile(render_job *j, const tile_item *it, const double *local, const int *lcount)
{
    int tw = it->x1 - it->x0;
    pthread_mutex_lock(&j->lock);
    while (j->tile_pass[it->tile] != it->pass) pthread_cond_wait(&j->merged, &j->lock);
    /* A tile found converged at an earlier pass takes nothing more, whatever
     * a worker traced meanwhile: the image does not depend on scheduling. */
    if (local && !atomic_load(&j->tile_done[it->tile])) {
        for (int y = it->y0; y < it->y1; ++y)
            for (int x = it->x0; x < it->x1; ++x) {
                size_t pi = (size_t)y * j->W + x, li = (size_t)(y - it->y0) * tw + (x - it->x0);
                for (int ch = 0; ch < 3; ++ch) j->sum[3 * pi + ch] += local[3 * li + ch];
                j->count[pi] += lcount[li];
                if (j->sum_y) {
                    j->sum_y[pi] += soak_rgb_luminance(soak_rgb3(local[3 * li], local[3 * li + 1], local[3 * li + 2]));
                    j->sum_y2[pi] += local[TILE * TILE * 3 + li];
                }
            }
        if (j->target_error > 0 && tile_converged(j, it)) atomic_store(&j->tile_done[it->tile], 1);
    }
    j->tile_pass[it->tile]++;
    pthread_cond_broadcast(&j->merged);
    pthread_mutex_unlock(&j->lock);
}

static void *worker(void *argp)
{
    worker_arg *a = argp;
    render_job *j = a->job;
    rt_thread t;
    memset(&t, 0, sizeof t);
    t.ctx = &j->ctx;
    double *local = malloc((size_t)TILE * TILE * 4 * sizeof(double)); /* RGB, then luminance^2 */
    int *lcount = malloc((size_t)TILE * TILE * sizeof(int));
    int have_memory = local && lcount;
    if (!have_memory) {
        atomic_store(&j->out_of_memory, 1);
        atomic_store(&j->stop, 1);
    }
    for (;;) {
        long item = atomic_fetch_add(&j->next_item, 1);
        if (item >= j->total_items) break;
        tile_item it = tile_item_of(j, item);
        if (have_memory && !atomic_load(&j->tile_done[it.tile])) trace_tile(&t, a, &it, local, lcount);
        merge_tile(j, &it, have_memory ? local : NULL, lcount);
        atomic_fetch_add(&j->done_items, 1);
    }
    free(local);
    free(lcount);
    a->n = t.n;
    atomic_fetch_sub(&j->workers_left, 1);
    return NULL;
}

static double clock_seconds(clockid_t id)
{
    struct timespec ts;
    if (clock_gettime(id, &ts) != 0) return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double now_seconds(void) { return clock_seconds(CLOCK_MONOTONIC); }

/* Image size and samples: the options' where set, else the scene's. */
static soak_status check_options(const soak_scene *scene, const soak_render_options *opt, int *W, int *H, int *spp,
                                 char *err, size_t errlen)
{
    int w = opt->width > 0 ? opt->width : scene->width, h = opt->height > 0 ? opt->height : scene->height;
    int n = opt->spp > 0 ? opt->spp : scene->spp;
    int threads = opt->threads;
    *W = w;
    *H = h;
    *spp = n;
    if (!(w >= 1 && w <= SOAK_RENDER_MAX_SIZE && h >= 1 && h <= SOAK_RENDER_MAX_SIZE && n >= 1 &&
          n <= SOAK_RENDER_MAX_SPP && threads >= 1 && threads <= SOAK_RENDER_MAX_THREADS) ||
        !soak_in_range(opt->time_limit, 0, SOAK_RENDER_MAX_TIME) || !soak_in_range(opt->target_error, 0, 1) ||
        opt->max_depth < 0) {
        if (err && errlen) snprintf(err, errlen, "render options out of range");
        return SOAK_ERR_ARG;
    }
    return SOAK_OK;
}

/* What the paths read: the materials' BSDFs, the environment's sampling
 * tables and the caustic photon map. */
static soak_status prepare_scene(render_job *j, const soak_scene *scene, const soak_render_options *opt,
                                 double t_start, char *err, size_t errlen)
{
    j->ctx.scene = scene;
    j->ctx.max_depth = opt->max_depth > 0 ? opt->max_depth : scene->max_depth;
    j->bsdfs = calloc(scene->n_materials > 0 ? (size_t)scene->n_materials : 1, sizeof *j->bsdfs);
    if (!j->bsdfs) return SOAK_ERR_NOMEM;
    j->ctx.bsdfs = j->bsdfs;
    soak_status st = rt_bsdfs_setup(scene, opt->trace_films, j->bsdfs, err, errlen);
    if (st != SOAK_OK) return st;
    j->levels = calloc(scene->n_materials > 0 ? (size_t)scene->n_materials : 1, sizeof *j->levels);
    if (!j->levels) return SOAK_ERR_NOMEM;
    j->ctx.levels = j->levels;
    st = rt_levels_setup(scene, opt->trace_films, j->levels, err, errlen);
    if (st != SOAK_OK) return st;
    st = rt_env_build(&j->ctx.env, &scene->env);
    if (st == SOAK_OK && scene->caustic_photons > 0) {
        /* Photons are traced before the render, from the same seed. */
        st = rt_photons_build(&j->ctx, scene->caustic_photons, scene->caustic_radius, opt->seed, opt->cancel,
                              opt->time_limit > 0 ? t_start + opt->time_limit : 0, &j->caustics);
        if (st == SOAK_OK) j->ctx.caustics = &j->caustics;
    }
    return st;
}

static void prepare_camera(cam_setup *c, const soak_camera *cam, int W, int H)
{
    c->pos = cam->position;
    c->fwd = soak_v3_norm(soak_v3_sub(cam->look_at, cam->position));
    c->right = soak_v3_norm(soak_v3_cross(c->fwd, cam->up));
    c->up = soak_v3_cross(c->right, c->fwd);
    c->tan_half = tan(cam->fov_deg * SOAK_PI / 360.0);
    c->aspect = (double)W / H;
    c->aperture = cam->aperture;
    c->focus = cam->focus_distance;
    c->W = W;
    c->H = H;
}

/* Passes of 1, 2, 4, ... samples up to spp/8: the whole image gets a few
 * samples quickly, so an early stop leaves no black tiles. */
static soak_status plan_passes(render_job *j)
{
    int spp = j->spp;
    j->pass_start = calloc((size_t)spp + 2, sizeof(int));
    if (!j->pass_start) return SOAK_ERR_NOMEM;
    int cap = spp >= 8 ? spp / 8 : 1, b = 1, p = 0;
    while (j->pass_start[p] < spp) {
        int next = j->pass_start[p] + b;
        j->pass_start[++p] = next < spp ? next : spp;
        b = 2 * b < cap ? 2 * b : cap;
    }
    j->passes = p;
    j->tiles_x = (j->W + TILE - 1) / TILE;
    j->tiles_y = (j->H + TILE - 1) / TILE;
    j->n_tiles = j->tiles_x * j->tiles_y;
    j->total_items = (long)j->passes * j->n_tiles;
    return SOAK_OK;
}

/* The sums, counts and worker slots, and the output image. */
static soak_status alloc_buffers(render_job *j, soak_image *out)
{
    size_t W = (size_t)j->W, H = (size_t)j->H;
    atomic_init(&j->next_item, 0);
    atomic_init(&j->done_items, 0);
    atomic_init(&j->stop, 0);
    atomic_init(&j->workers_left, j->threads);
    atomic_init(&j->out_of_memory, 0);
    j->sum = calloc(W * H * 3, sizeof(double));
    j->count = calloc(W * H, sizeof(int));
    j->tile_pass = calloc((size_t)j->n_tiles, sizeof(int));
    j->tile_done = calloc((size_t)j->n_tiles, sizeof *j->tile_done);
    for (int i = 0; j->tile_done && i < j->n_tiles; ++i) atomic_init(&j->tile_done[i], 0);
    if (j->target_error > 0 || j->want_variance) {
        j->sum_y = calloc(W * H, sizeof(double));
        j->sum_y2 = calloc(W * H, sizeof(double));
        if (!j->sum_y || !j->sum_y2) return SOAK_ERR_NOMEM;
    }
    j->args = calloc((size_t)j->threads, sizeof *j->args);
    j->th = calloc((size_t)j->threads, sizeof *j->th);
    soak_status st = soak_image_alloc(out, j->W, j->H, 3);
    if (!j->sum || !j->count || !j->tile_pass || !j->tile_done || !j->args || !j->th || st != SOAK_OK) {
        if (st == SOAK_OK) soak_image_free(out);
        return SOAK_ERR_NOMEM;
    }
    return SOAK_OK;
}

/* Starts the workers; returns how many started. None: renders on the
 * calling thread. */
static int start_workers(render_job *j)
{
    int started = 0;
    for (int i = 0; i < j->threads; ++i) {
        j->args[i].job = j;
        if (pthread_create(&j->th[i], NULL, worker, &j->args[i]) != 0) {
            atomic_fetch_sub(&j->workers_left, j->threads - i);
            break;
        }
        started++;
    }
    if (started == 0) {
        atomic_store(&j->workers_left, 1);
        j->args[0].job = j;
        worker(&j->args[0]);
    }
    return started;
}

/* Waits for the workers, reporting progress and telling them to stop on
 * cancel or past the time limit. */
static void watch_workers(render_job *j, const soak_render_options *opt, double t_start)
{
    for (long wait_ms = 1; atomic_load(&j->workers_left) > 0; wait_ms = wait_ms < 50 ? 2 * wait_ms : 50) {
        /* Short waits first so tiny renders (tests) do not idle. */
        struct timespec ts = {0, wait_ms * 1000 * 1000};
        nanosleep(&ts, NULL);
        if ((opt->cancel && *opt->cancel) || (opt->time_limit > 0 && now_seconds() - t_start > opt->time_limit))
            atomic_store(&j->stop, 1);
        if (opt->progress)
            opt->progress(opt->progress_ctx, (double)atomic_load(&j->done_items) / (double)j->total_items);
    }
}

/* Renders every item; sets the wall and CPU seconds the workers took (the
 * process's CPU clock: every thread, user and system; benchmarks on a shared
 * machine compare it, as wall time counts other jobs' turns too). */
static void run_workers(render_job *j, const soak_render_options *opt, double t_start, soak_render_stats *sst)
{
    pthread_mutex_init(&j->lock, NULL);
    pthread_cond_init(&j->merged, NULL);
    double t0 = now_seconds(), c0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    int started = start_workers(j);
    watch_workers(j, opt, t_start);
    for (int i = 0; i < started; ++i) pthread_join(j->th[i], NULL);
    pthread_mutex_destroy(&j->lock);
    pthread_cond_destroy(&j->merged);
    sst->seconds = now_seconds() - t0;
    sst->cpu_seconds = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
}

/* Pixel means into out, and the workers' counters summed into *sst. */
static void collect(const render_job *j, soak_image *out, soak_render_stats *sst)
{
    sst->min_spp = j->spp;
    for (int i = 0; i < j->threads; ++i) {
        const worker_arg *a = &j->args[i];
        sst->rays += a->n.rays;
        sst->capped += a->n.capped;
        sst->leaked += a->n.leaked;
        sst->nan_paths += a->n.nan_paths;
        sst->geometry_errors += a->n.geom_errors;
        sst->paths += a->paths;
    }
    for (size_t i = 0; i < (size_t)j->W * j->H; ++i) {
        int n = j->count[i];
        if (n < sst->min_spp) sst->min_spp = n;
        if (n > sst->max_spp) sst->max_spp = n;
        for (int ch = 0; ch < 3; ++ch) out->pixels[3 * i + ch] = n > 0 ? (float)(j->sum[3 * i + ch] / n) : 0.0f;
    }
    sst->stopped_early = atomic_load(&j->stop) && sst->min_spp < j->spp;
}

/* The variance of each pixel's mean luminance, for soak_render_options.variance. */
static soak_status collect_variance(const render_job *j, soak_image *var)
{
    soak_status st = soak_image_alloc(var, j->W, j->H, 1);
    for (size_t i = 0; st == SOAK_OK && i < (size_t)j->W * j->H; ++i) {
        int k = j->count[i];
        double mean = k > 0 ? j->sum_y[i] / k : 0;
        var->pixels[i] = k > 1 ? (float)(fmax(0.0, (j->sum_y2[i] - k * mean * mean) / (k - 1.0)) / k) : 0.0f;
    }
    return st;
}

/* Renders every pass of every tile into out. */
static soak_status render_image(render_job *j, const soak_render_options *opt, double t_start, soak_image *out,
                                soak_render_stats *stats)
{
    soak_render_stats sst;
    memset(&sst, 0, sizeof sst);
    run_workers(j, opt, t_start, &sst);
    collect(j, out, &sst);
    if (stats) *stats = sst;
    if (j->want_variance && !atomic_load(&j->out_of_memory) && collect_variance(j, opt->variance) != SOAK_OK)
        atomic_store(&j->out_of_memory, 1);
    if (atomic_load(&j->out_of_memory)) {
        soak_image_free(out);
        return SOAK_ERR_NOMEM;
    }
    return SOAK_OK;
}

static void job_free(render_job *j)
{
    rt_photons_free(&j->caustics);
    rt_env_free(&j->ctx.env);
    free(j->sum);
    free(j->count);
    free(j->tile_pass);
    free(j->tile_done);
    free(j->sum_y);
    free(j->sum_y2);
    free(j->pass_start);
    free(j->args);
    free(j->th);
    free(j->bsdfs);
    rt_levels_free(j->levels, j->ctx.scene ? j->ctx.scene->n_materials : 0);
    free(j);
}

soak_status soak_render(const soak_scene *scene, const soak_render_options *opt, soak_image *out,
                        soak_render_stats *stats, char *err, size_t errlen)
{
    if (!scene || !opt || !out) return SOAK_ERR_NULL;
    int W, H, spp;
    soak_status st = check_options(scene, opt, &W, &H, &spp, err, errlen);
    if (st != SOAK_OK) return st;
    double t_start = now_seconds(); /* --time covers every phase */
    render_job *j = calloc(1, sizeof *j);
    if (!j) return SOAK_ERR_NOMEM;
    j->W = W;
    j->H = H;
    j->spp = spp;
    j->threads = opt->threads;
    j->seed = opt->seed;
    j->target_error = opt->target_error;
    j->want_variance = opt->variance != NULL;
    st = prepare_scene(j, scene, opt, t_start, err, errlen);
    if (st == SOAK_OK) {
        prepare_camera(&j->cam, &scene->camera, W, H);
        st = plan_passes(j);
    }
    if (st == SOAK_OK) st = alloc_buffers(j, out);
    if (st == SOAK_OK) st = render_image(j, opt, t_start, out, stats);
    job_free(j);
    return st;
}
