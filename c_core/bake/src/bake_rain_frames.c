/* Frame sequences of the rain bake: the film in time, its drainage and
 * drying (model in soak/bake_rain.h step 5). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_rain_film.h"
#include "bake_rain_stream.h"
#include "bake_rain_flow.h"
#include "bake_rain_level.h"
#include "bake_rain_scene.h"
#include "bake_rain_wave.h"
#include "soak/bake_rain.h"

/* The sweeps leave a film texel alone: its water is never above this. */
#define FILM_TEXEL_RETAIN 1e300

/* The water of the surface after `step` steps, and where it went. */
typedef struct rain_state {
    double *depth;
    long step;
    soak_rain_balance bal;
} rain_state;

struct soak_rain_frames {
    soak_rain_params p;
    soak_rain_scene sc;
    soak_rain_flow_grid grid;
    soak_rain_flow_plan *plan;
    soak_rain_level_plan *puddles; /* NULL: no flow */
    int plan_threads; /* the most threads plan sweeps with */
    size_t *order, count;
    double *retain, *kappa, *source, *inflow;
    soak_rain_box *boxes; /* the wave's scratch: the streams' boxes */
    double dt, rain_m_s, evap_m_s;
    rain_state now, cut; /* after whole steps; and cut short at a frame's time */
    soak_rain_runnel_stats runnel_stats; /* the lattice placed on the steady film */
};

void soak_rain_frames_destroy(soak_rain_frames *f)
{
    if (!f) return;
    soak_rain_flow_destroy(f->plan);
    soak_rain_level_destroy(f->puddles);
    soak_rain_scene_free(&f->sc);
    free(f->order);
    free(f->retain);
    free(f->kappa);
    free(f->source);
    free(f->inflow);
    free(f->boxes);
    free(f->now.depth);
    free(f->cut.depth);
    free(f);
}

/* Static retention, the film's faces (kappa > 0, never swept) and the rain
 * per texel. */
static soak_status film_faces(soak_rain_frames *f)
{
    const soak_rain_scene *sc = &f->sc;
    size_t n = (size_t)sc->w * sc->h;
    double *film = calloc(n, sizeof *film);
    if (!film) return SOAK_ERR_NOMEM;
    soak_status st = SOAK_OK;
    for (size_t i = 0; i < n; ++i) {
        f->retain[i] = sc->covered[i] ? f->p.retention * fmax(0.0, sc->up_dot_n[i]) : 0.0;
        f->source[i] = sc->covered[i] && sc->exposure.pixels[i] > 0.0f
                           ? f->rain_m_s * sc->exposure.pixels[i] * sc->area[i] : 0.0;
    }
    if (f->p.film) st = soak_rain_film_map(&f->grid, sc->up_dot_n, sc->exposure.pixels, f->rain_m_s, f->evap_m_s, film, NULL);
    if (st == SOAK_OK) /* step 3c: the single map's lattice, from the same steady film */
        st = soak_rain_runnel_place(&f->sc.runnels, film, f->p.seed, &f->runnel_stats);
    for (size_t i = 0; i < n && st == SOAK_OK; ++i) {
        double c = sc->up_dot_n[i], s2 = 1.0 - c * c;
        f->kappa[i] = 0.0;
        if (!(film[i] > 0.0 && film[i] >= f->retain[i])) continue;
        f->kappa[i] = soak_rain_wave_kappa(soak_rain_flow_width(&f->grid, i), sqrt(s2 > 0.0 ? s2 : 0.0));
        f->retain[i] = FILM_TEXEL_RETAIN;
    }
    free(film);
    return st;
}

static soak_status frames_alloc(soak_rain_frames *f, const soak_bake_exec *exec)
{
    size_t n = (size_t)f->sc.w * f->sc.h;
    f->retain = malloc(n * sizeof *f->retain);
    f->kappa = malloc(n * sizeof *f->kappa);
    f->source = malloc(n * sizeof *f->source);
    f->inflow = malloc(n * sizeof *f->inflow);
    f->boxes = malloc(n * sizeof *f->boxes);
    f->now.depth = calloc(n, sizeof *f->now.depth);
    f->cut.depth = malloc(n * sizeof *f->cut.depth);
    if (!f->retain || !f->kappa || !f->source || !f->inflow || !f->boxes || !f->now.depth || !f->cut.depth)
        return SOAK_ERR_NOMEM;
    f->grid = (soak_rain_flow_grid){f->sc.w, f->sc.h, f->sc.covered, f->sc.adj, f->sc.area, f->sc.drip, f->sc.level,
                                    f->retain, f->sc.descent};
    soak_status st = film_faces(f);
    if (st == SOAK_OK) st = soak_rain_flow_order(&f->grid, &f->order, &f->count);
    if (st == SOAK_OK) st = soak_rain_flow_create(&f->grid, exec, SOAK_RAIN_FLOW_AUTO, &f->plan);
    if (st == SOAK_OK && f->p.flow_iterations > 0) st = soak_rain_level_create(&f->grid, &f->puddles);
    f->plan_threads = soak_bake_threads(exec);
    return st;
}

soak_status soak_rain_frames_create(const soak_mesh *mesh, int width, int height, const soak_rain_params *p,
                                    const soak_bake_exec *exec, soak_rain_frames **out, char *err, size_t errlen)
{
    if (!mesh || !p || !out) return SOAK_ERR_NULL;
    *out = NULL;
    if (soak_rain_check(p) == SOAK_OK && !(p->duration > 0)) {
        if (err && errlen) snprintf(err, errlen, "a frame sequence needs rain: duration must be > 0");
        return SOAK_ERR_ARG;
    }
    soak_rain_frames *f = calloc(1, sizeof *f);
    if (!f) return SOAK_ERR_NOMEM;
    f->p = *p;
    soak_status st = soak_rain_scene_build(mesh, width, height, p, exec, &f->sc, err, errlen);
    f->dt = p->duration / p->steps;
    f->rain_m_s = p->rainfall_mm_h / 3.6e6;
    f->evap_m_s = p->evaporation_mm_h / 3.6e6;
    if (st == SOAK_OK) st = frames_alloc(f, exec);
    if (st == SOAK_OK) /* as the single bake's --exposure; the rain reads covered texels only */
        st = soak_rain_dilate(f->sc.exposure.pixels, f->sc.covered, width, height, p->gutter, exec);
    if (st != SOAK_OK) {
        soak_rain_frames_destroy(f);
        return st;
    }
    *out = f;
    return SOAK_OK;
}

/* Water on the surface, m^3, summed in texel order. */
static double volume(const soak_rain_frames *f, const double *depth)
{
    double v = 0.0;
    for (size_t k = 0; k < f->count; ++k) v += depth[f->order[k]] * f->sc.area[f->order[k]];
    return v;
}

typedef struct evap_job {
    const soak_rain_frames *f;
    double *depth, *lost, amount; /* lost: per row, m^3 */
} evap_job;

static void evaporate_row(void *ctx, int y, int thread)
{
    (void)thread;
    evap_job *j = ctx;
    const soak_rain_scene *sc = &j->f->sc;
    double lost = 0.0;
    for (size_t i = (size_t)y * sc->w, end = i + sc->w; i < end; ++i) {
        if (!sc->covered[i]) continue;
        double e = j->depth[i] < j->amount ? j->depth[i] : j->amount;
        j->depth[i] -= e;
        lost += e * sc->area[i];
    }
    j->lost[y] = lost;
}

/* One step of tau seconds of state s, raining or not: the film's wave, the
 * sweeps, evaporation; progress stays at `at`. */
static soak_status advance(soak_rain_frames *f, rain_state *s, double tau, int raining, const soak_bake_exec *exec,
                           double at)
{
    double dripped = 0.0;
    for (size_t k = 0; k < f->count && raining; ++k) s->bal.in += f->source[f->order[k]] * tau;
    soak_status st = soak_rain_wave_step(&f->grid, f->order, f->count, f->kappa, raining ? f->source : NULL, tau,
                                         s->depth, f->inflow, f->boxes, &dripped);
    s->bal.dripped += dripped;
    double before = volume(f, s->depth);
    if (st == SOAK_OK && f->puddles) st = soak_rain_level_run(f->puddles, s->depth);
    if (st == SOAK_OK) st = soak_rain_flow_run(f->plan, s->depth, f->p.flow_iterations, exec, at, at);
    s->bal.dripped += before - volume(f, s->depth);
    evap_job j = {f, s->depth, calloc((size_t)f->sc.h, sizeof(double)), f->evap_m_s * tau};
    if (st == SOAK_OK && !j.lost) st = SOAK_ERR_NOMEM;
    if (st == SOAK_OK) st = soak_parallel_rows(f->sc.h, exec, evaporate_row, &j, at, at);
    for (int y = 0; y < f->sc.h && st == SOAK_OK; ++y) s->bal.evaporated += j.lost[y];
    free(j.lost);
    s->bal.held = volume(f, s->depth);
    return st;
}

static void report(const soak_bake_exec *exec, double fraction)
{
    if (exec && exec->progress) exec->progress(exec->progress_user, fraction);
}

/* f->now after `steps` whole steps (from t = 0 again if it is past them),
 * progress over [0, 0.9]. */
static soak_status whole_steps(soak_rain_frames *f, long steps, const soak_bake_exec *exec)
{
    size_t n = (size_t)f->sc.w * f->sc.h;
    if (f->now.step > steps) {
        memset(f->now.depth, 0, n * sizeof *f->now.depth);
        f->now.step = 0;
        memset(&f->now.bal, 0, sizeof f->now.bal);
    }
    long first = f->now.step;
    soak_status st = SOAK_OK;
    for (; f->now.step < steps && st == SOAK_OK; ++f->now.step) {
        double at = 0.9 * (double)(f->now.step - first) / (double)(steps - first);
        report(exec, at);
        st = advance(f, &f->now, f->dt, f->now.step < f->p.steps, exec, at);
    }
    return st;
}

typedef struct frame_job {
    const soak_rain_frames *f;
    const double *depth;
    soak_rain_frame *out;
} frame_job;

static void frame_row(void *ctx, int y, int thread)
{
    (void)thread;
    const frame_job *j = ctx;
    const soak_rain_frames *f = j->f;
    for (size_t i = (size_t)y * f->sc.w, end = i + f->sc.w; i < end; ++i) {
        double d = j->depth[i], film = f->kappa[i] > 0.0 ? d : 0.0;
        if (film > 0.0) /* step 3c: this frame's film gathered into the lattice's rivulets */
            d = film = soak_rain_runnel_texel(&f->sc.runnels, &f->grid, i, film);
        j->out->water.pixels[i] = (float)d;
        j->out->film.pixels[i] = (float)(film < SOAK_RAIN_FILM_MAX ? film : SOAK_RAIN_FILM_MAX);
        j->out->wetness.pixels[i] = (float)soak_rain_wetness(d, film, f->p.saturation_depth);
    }
}

void soak_rain_frame_free(soak_rain_frame *r)
{
    if (!r) return;
    soak_image_free(&r->wetness);
    soak_image_free(&r->water);
    soak_image_free(&r->film);
}

static soak_status frame_images(const soak_rain_frames *f, const rain_state *s, const soak_bake_exec *exec,
                                soak_rain_frame *out)
{
    int w = f->sc.w, h = f->sc.h;
    memset(out, 0, sizeof *out);
    soak_status st = soak_image_alloc(&out->wetness, w, h, 1);
    if (st == SOAK_OK) st = soak_image_alloc(&out->water, w, h, 1);
    if (st == SOAK_OK) st = soak_image_alloc(&out->film, w, h, 1);
    frame_job j = {f, s->depth, out};
    if (st == SOAK_OK) st = soak_parallel_rows(h, exec, frame_row, &j, 0.9, 1.0);
    float *maps[3] = {out->wetness.pixels, out->water.pixels, out->film.pixels};
    for (int k = 0; k < 3 && st == SOAK_OK; ++k) st = soak_rain_dilate(maps[k], f->sc.covered, w, h, f->p.gutter, exec);
    out->balance = s->bal;
    if (st != SOAK_OK) soak_rain_frame_free(out);
    return st;
}

soak_status soak_rain_frames_at(soak_rain_frames *f, double t, const soak_bake_exec *exec, soak_rain_frame *out,
                                char *err, size_t errlen)
{
    if (!f || !out) return SOAK_ERR_NULL;
    if (exec && soak_bake_threads(exec) == 0) return SOAK_ERR_ARG;
    double whole = floor(t / f->dt);
    if (!(t >= 0.0 && t <= SOAK_RAIN_MAX_FRAME_TIME) || !(whole <= (double)SOAK_RAIN_MAX_FRAME_STEPS)) {
        if (err && errlen)
            snprintf(err, errlen, "time %g s is outside 0..%g s or needs more than %ld steps of %g s", t,
                     SOAK_RAIN_MAX_FRAME_TIME, SOAK_RAIN_MAX_FRAME_STEPS, f->dt);
        return SOAK_ERR_ARG;
    }
    if (soak_bake_threads(exec) > f->plan_threads) { /* more threads than the sweeps were made for */
        soak_rain_flow_destroy(f->plan);
        f->plan = NULL;
        soak_status st = soak_rain_flow_create(&f->grid, exec, SOAK_RAIN_FLOW_AUTO, &f->plan);
        if (st != SOAK_OK) return st;
        f->plan_threads = soak_bake_threads(exec);
    }
    long steps = (long)whole;
    double rest = t - (double)steps * f->dt;
    soak_status st = whole_steps(f, steps, exec);
    size_t n = (size_t)f->sc.w * f->sc.h;
    if (st == SOAK_OK) {
        memcpy(f->cut.depth, f->now.depth, n * sizeof *f->cut.depth);
        f->cut.bal = f->now.bal;
        f->cut.step = steps;
        if (rest > 0.0) st = advance(f, &f->cut, rest, steps < f->p.steps, exec, 0.9);
    }
    if (st == SOAK_OK) st = frame_images(f, &f->cut, exec, out);
    return st;
}

const soak_image *soak_rain_frames_exposure(const soak_rain_frames *f)
{
    return f ? &f->sc.exposure : NULL;
}

void soak_rain_frames_runnels(const soak_rain_frames *f, int *texels, double *spacing)
{
    *texels = f ? f->runnel_stats.broken : 0;
    *spacing = f ? f->runnel_stats.spacing : 0.0;
}

const soak_uv_stats *soak_rain_frames_uv(const soak_rain_frames *f)
{
    return &f->sc.uv;
}
