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

#include "render_internal.h"

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
                path.L = rgb_add(path.L, rgb_scale(rgb_mul(path.beta, rt_env_eval(c, path.dir)), w));
            }
            break;
        }
        if (path.inside) path.beta = rgb_mul(path.beta, rgb_exp(path.absorb, hit.t));
        const soak_material *m = &s->materials[s->objects[hit.object_id].material];
        if (m->type == SOAK_MAT_EMITTER) {
            int li = light_of_object(s, hit.object_id);
            if (li >= 0 && soak_v3_dot(path.dir, hit.ng) < 0) {
                double w = path.prev_delta ? 1.0
                                           : rt_power(path.prev_pdf, rt_sphere_light_pdf(&s->lights[li], path.prev_pos));
                path.L = rgb_add(path.L, rgb_scale(rgb_mul(path.beta, m->radiance), w));
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
            path.beta = rgb_scale(path.beta, 1.0 / q);
        }
    }
    if (!(soak_is_finite(path.L.r) && soak_is_finite(path.L.g) && soak_is_finite(path.L.b))) {
        t->n.nan_paths++;
        return soak_rgb3(0, 0, 0);
    }
    return path.L;
}

typedef struct render_job {
    rt_ctx ctx;
    rt_photon_map caustics;
    cam_setup cam;
    int W, H, spp, passes, tiles_x, tiles_y, n_tiles;
    int *pass_start; /* passes + 1 entries: samples [pass_start[p], pass_start[p+1]) */
    uint64_t seed;
    long total_items;
    atomic_long next_item;
    atomic_long done_items;
    atomic_int stop;
    atomic_int workers_left;
    atomic_int out_of_memory;
    double *sum;   /* 3 per pixel */
    int *count;    /* samples per pixel */
    int *tile_pass; /* passes merged per tile */
    pthread_mutex_t lock;
    pthread_cond_t merged;
    rt_counters counters;
    long long paths;
} render_job;

typedef struct worker_arg {
    render_job *job;
    rt_counters n;
    long long paths;
} worker_arg;

static void *worker(void *argp)
{
    worker_arg *a = argp;
    render_job *j = a->job;
    rt_thread t;
    memset(&t, 0, sizeof t);
    t.ctx = &j->ctx;
    double *local = malloc((size_t)TILE * TILE * 3 * sizeof(double));
    int *lcount = malloc((size_t)TILE * TILE * sizeof(int));
    if (!local || !lcount) {
        atomic_store(&j->out_of_memory, 1);
        atomic_store(&j->stop, 1);
    }
    for (;;) {
        long item = atomic_fetch_add(&j->next_item, 1);
        if (item >= j->total_items) break;
        int pass = (int)(item / j->n_tiles), tile = (int)(item % j->n_tiles);
        int x0 = (tile % j->tiles_x) * TILE, y0 = (tile / j->tiles_x) * TILE;
        int x1 = x0 + TILE < j->W ? x0 + TILE : j->W, y1 = y0 + TILE < j->H ? y0 + TILE : j->H;
        int s0 = j->pass_start[pass], s1 = j->pass_start[pass + 1];
        int tw = x1 - x0;
        if (local && lcount) {
            memset(local, 0, (size_t)TILE * TILE * 3 * sizeof(double));
            memset(lcount, 0, (size_t)TILE * TILE * sizeof(int));
            for (int y = y0; y < y1 && !atomic_load(&j->stop); ++y)
                for (int x = x0; x < x1; ++x) {
                    uint64_t pixel = (uint64_t)y * (uint64_t)j->W + (uint64_t)x;
                    double *acc = local + 3 * ((y - y0) * tw + (x - x0));
                    for (int sidx = s0; sidx < s1; ++sidx) {
                        soak_rng_seed(&t.rng, j->seed, pixel * (uint64_t)j->spp + (uint64_t)sidx);
                        rt_qmc_start(&t, j->seed, pixel, (uint32_t)sidx);
                        soak_vec3 org, dir = camera_ray(&t, &j->cam, x, y, &org);
                        soak_rgb L = radiance(&t, org, dir);
                        acc[0] += L.r;
                        acc[1] += L.g;
                        acc[2] += L.b;
                        a->paths++;
                    }
                    lcount[(y - y0) * tw + (x - x0)] = s1 - s0;
                }
        }
        /* Merge passes of a tile in order so sums do not depend on scheduling. */
        pthread_mutex_lock(&j->lock);
        while (j->tile_pass[tile] != pass) pthread_cond_wait(&j->merged, &j->lock);
        if (local && lcount)
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    size_t pi = (size_t)y * j->W + x, li = (size_t)(y - y0) * tw + (x - x0);
                    for (int ch = 0; ch < 3; ++ch) j->sum[3 * pi + ch] += local[3 * li + ch];
                    j->count[pi] += lcount[li];
                }
        j->tile_pass[tile]++;
        pthread_cond_broadcast(&j->merged);
        pthread_mutex_unlock(&j->lock);
        atomic_fetch_add(&j->done_items, 1);
    }
    free(local);
    free(lcount);
    a->n = t.n;
    atomic_fetch_sub(&j->workers_left, 1);
    return NULL;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

soak_status soak_render(const soak_scene *scene, const soak_render_options *opt, soak_image *out,
                        soak_render_stats *stats, char *err, size_t errlen)
{
    if (!scene || !opt || !out) return SOAK_ERR_NULL;
    int W = opt->width > 0 ? opt->width : scene->width, H = opt->height > 0 ? opt->height : scene->height;
    int spp = opt->spp > 0 ? opt->spp : scene->spp;
    int threads = opt->threads;
    if (!(W >= 1 && W <= SOAK_RENDER_MAX_SIZE && H >= 1 && H <= SOAK_RENDER_MAX_SIZE && spp >= 1 &&
          spp <= SOAK_RENDER_MAX_SPP && threads >= 1 && threads <= SOAK_RENDER_MAX_THREADS) ||
        !soak_in_range(opt->time_limit, 0, SOAK_RENDER_MAX_TIME) || opt->max_depth < 0) {
        if (err && errlen) snprintf(err, errlen, "render options out of range");
        return SOAK_ERR_ARG;
    }
    double t_start = now_seconds(); /* --time covers every phase */
    render_job *j = calloc(1, sizeof *j);
    if (!j) return SOAK_ERR_NOMEM;
    j->ctx.scene = scene;
    j->ctx.max_depth = opt->max_depth > 0 ? opt->max_depth : scene->max_depth;
    rt_material_bsdf *bsdfs = calloc(scene->n_materials > 0 ? (size_t)scene->n_materials : 1, sizeof *bsdfs);
    if (!bsdfs) {
        free(j);
        return SOAK_ERR_NOMEM;
    }
    j->ctx.bsdfs = bsdfs;
    soak_status st = rt_bsdfs_setup(scene, opt->trace_films, bsdfs, err, errlen);
    if (st != SOAK_OK) {
        free(bsdfs);
        free(j);
        return st;
    }
    st = rt_env_build(&j->ctx.env, &scene->env);
    if (st == SOAK_OK && scene->caustic_photons > 0) {
        /* Photons are traced before the render, from the same seed. */
        st = rt_photons_build(&j->ctx, scene->caustic_photons, scene->caustic_radius, opt->seed, opt->cancel,
                              opt->time_limit > 0 ? t_start + opt->time_limit : 0, &j->caustics);
        if (st == SOAK_OK) j->ctx.caustics = &j->caustics;
    }
    if (st != SOAK_OK) {
        rt_env_free(&j->ctx.env);
        free(bsdfs);
        free(j);
        return st;
    }
    const soak_camera *cam = &scene->camera;
    j->cam.pos = cam->position;
    j->cam.fwd = soak_v3_norm(soak_v3_sub(cam->look_at, cam->position));
    j->cam.right = soak_v3_norm(soak_v3_cross(j->cam.fwd, cam->up));
    j->cam.up = soak_v3_cross(j->cam.right, j->cam.fwd);
    j->cam.tan_half = tan(cam->fov_deg * SOAK_PI / 360.0);
    j->cam.aspect = (double)W / H;
    j->cam.aperture = cam->aperture;
    j->cam.focus = cam->focus_distance;
    j->cam.W = W;
    j->cam.H = H;
    j->W = W;
    j->H = H;
    j->spp = spp;
    /* Passes of 1, 2, 4, ... samples up to spp/8: the whole image gets a
     * few samples quickly, so an early stop leaves no black tiles. */
    j->pass_start = calloc((size_t)spp + 2, sizeof(int));
    if (!j->pass_start) {
        rt_photons_free(&j->caustics);
        rt_env_free(&j->ctx.env);
        free(bsdfs);
        free(j);
        return SOAK_ERR_NOMEM;
    }
    {
        int cap = spp >= 8 ? spp / 8 : 1, b = 1, p = 0;
        while (j->pass_start[p] < spp) {
            int next = j->pass_start[p] + b;
            j->pass_start[++p] = next < spp ? next : spp;
            b = 2 * b < cap ? 2 * b : cap;
        }
        j->passes = p;
    }
    j->tiles_x = (W + TILE - 1) / TILE;
    j->tiles_y = (H + TILE - 1) / TILE;
    j->n_tiles = j->tiles_x * j->tiles_y;
    j->total_items = (long)j->passes * j->n_tiles;
    j->seed = opt->seed;
    atomic_init(&j->next_item, 0);
    atomic_init(&j->done_items, 0);
    atomic_init(&j->stop, 0);
    atomic_init(&j->workers_left, threads);
    atomic_init(&j->out_of_memory, 0);
    j->sum = calloc((size_t)W * H * 3, sizeof(double));
    j->count = calloc((size_t)W * H, sizeof(int));
    j->tile_pass = calloc((size_t)j->n_tiles, sizeof(int));
    worker_arg *args = calloc((size_t)threads, sizeof *args);
    pthread_t *th = calloc((size_t)threads, sizeof *th);
    st = soak_image_alloc(out, W, H, 3);
    if (!j->sum || !j->count || !j->tile_pass || !args || !th || st != SOAK_OK) {
        if (st == SOAK_OK) soak_image_free(out);
        st = SOAK_ERR_NOMEM;
        goto done;
    }
    pthread_mutex_init(&j->lock, NULL);
    pthread_cond_init(&j->merged, NULL);
    double t0 = now_seconds();
    int started = 0;
    for (int i = 0; i < threads; ++i) {
        args[i].job = j;
        if (pthread_create(&th[i], NULL, worker, &args[i]) != 0) {
            atomic_fetch_sub(&j->workers_left, threads - i);
            break;
        }
        started++;
    }
    if (started == 0) {
        /* No thread could start: render on the calling thread. */
        atomic_store(&j->workers_left, 1);
        args[0].job = j;
        worker(&args[0]);
    }
    for (long wait_ms = 1; atomic_load(&j->workers_left) > 0; wait_ms = wait_ms < 50 ? 2 * wait_ms : 50) {
        /* Short waits first so tiny renders (tests) do not idle. */
        struct timespec ts = {0, wait_ms * 1000 * 1000};
        nanosleep(&ts, NULL);
        if ((opt->cancel && *opt->cancel) || (opt->time_limit > 0 && now_seconds() - t_start > opt->time_limit))
            atomic_store(&j->stop, 1);
        if (opt->progress)
            opt->progress(opt->progress_ctx, (double)atomic_load(&j->done_items) / (double)j->total_items);
    }
    for (int i = 0; i < started; ++i) pthread_join(th[i], NULL);
    pthread_mutex_destroy(&j->lock);
    pthread_cond_destroy(&j->merged);
    soak_render_stats sst;
    memset(&sst, 0, sizeof sst);
    sst.seconds = now_seconds() - t0;
    sst.min_spp = spp;
    for (int i = 0; i < threads; ++i) {
        sst.rays += args[i].n.rays;
        sst.capped += args[i].n.capped;
        sst.leaked += args[i].n.leaked;
        sst.nan_paths += args[i].n.nan_paths;
        sst.geometry_errors += args[i].n.geom_errors;
        sst.paths += args[i].paths;
    }
    for (size_t i = 0; i < (size_t)W * H; ++i) {
        int n = j->count[i];
        if (n < sst.min_spp) sst.min_spp = n;
        if (n > sst.max_spp) sst.max_spp = n;
        for (int ch = 0; ch < 3; ++ch) out->pixels[3 * i + ch] = n > 0 ? (float)(j->sum[3 * i + ch] / n) : 0.0f;
    }
    sst.stopped_early = atomic_load(&j->stop) && sst.min_spp < spp;
    if (stats) *stats = sst;
    st = SOAK_OK;
    if (atomic_load(&j->out_of_memory)) {
        soak_image_free(out);
        st = SOAK_ERR_NOMEM;
    }
done:
    rt_photons_free(&j->caustics);
    rt_env_free(&j->ctx.env);
    free(j->sum);
    free(j->count);
    free(j->tile_pass);
    free(j->pass_start);
    free(args);
    free(th);
    free(bsdfs);
    free(j);
    return st;
}
