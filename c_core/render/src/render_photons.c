/* Volume photon map for caustics into wet media (Jensen & Christensen,
 * "Efficient simulation of light transport in scenes with participating
 * media using photon maps", SIGGRAPH 1998; used by [JLD99] sec. 4.3 for the
 * caustic of the cognac glass).
 *
 * Only the light a path tracer cannot reach is stored: photons leave the sun
 * and point lights toward the bounding sphere of the dielectric objects,
 * are refracted/reflected by them (at least one specular event), enter a wet
 * medium through its film (soak/jensen.h layer stack) and are stored at
 * their FIRST real scattering event, carrying the scattered flux. Direct
 * light is left to next-event estimation and multiple scattering of the
 * caustic light to the camera path's own walk, which gathers the map at
 * every scattering vertex, so nothing is counted twice:
 *     sigma_s L_s(x, w) ~ sum_p p(w_p, w) Phi_p / (4/3 pi r^3)
 * (J&C 1998 eq. 8, our notation). The estimate is biased by the blur of
 * radius r and consistent as r -> 0 with more photons. Sphere lights and the
 * environment emit no photons (their caustics into media are missing). */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "render_photons.h"
#include "render_stack.h"
#include "render_medium.h"
#include "render_photon_map.h"
#include "soak/hg.h"

typedef struct photon_list {
    rt_photon *p;
    size_t n, cap;
} photon_list;

static int push(photon_list *l, soak_vec3 x, soak_vec3 d, soak_rgb power, unsigned obj)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 1024;
        rt_photon *p = realloc(l->p, cap * sizeof *p);
        if (!p) return 0;
        l->p = p;
        l->cap = cap;
    }
    rt_photon *ph = &l->p[l->n++];
    ph->pos[0] = (float)x.x, ph->pos[1] = (float)x.y, ph->pos[2] = (float)x.z;
    ph->dir[0] = (float)d.x, ph->dir[1] = (float)d.y, ph->dir[2] = (float)d.z;
    ph->power[0] = (float)power.r, ph->power[1] = (float)power.g, ph->power[2] = (float)power.b;
    ph->object_id = obj;
    return 1;
}

typedef struct photon_store {
    photon_list *list;
    unsigned object_id;
    int ok;
} photon_store;

/* Vertex hook: store the photon at its first real scattering event and end the walk. */
static int store_first_scatter(void *ctx, soak_vec3 x, soak_vec3 d_in, soak_rgb power, const soak_medium_point *local,
                               soak_rng *rng)
{
    (void)local;
    (void)rng;
    photon_store *ps = ctx;
    ps->ok = push(ps->list, x, d_in, power, ps->object_id);
    return 0;
}

/* Walk inside the medium of object obj (soak/medium.h, the camera paths'
 * walk without roulette: photon powers are not normalised) until the first
 * real scattering event (stored) or until the photon leaves. Returns 0 when
 * out of memory. */
static int walk_to_first_scatter(rt_thread *t, const soak_material *m, const soak_scene_medium *med, const rt_stack *st,
                                 const soak_object *obj, soak_vec3 x, soak_vec3 d, soak_vec3 n_ref, soak_rgb power,
                                 photon_list *out)
{
    soak_medium_rgb mr = rt_medium_rgb(med);
    rt_med_surface surf = {{0}, 0, n_ref};
    rt_med_boundary bd = {t, &surf, obj, m, st};
    soak_boundary boundary = rt_med_boundary_make(&bd);
    photon_store ps = {out, obj->object_id, 1};
    soak_walk_options opt = rt_walk_options(power);
    opt.roulette = 0;
    opt.on_vertex = store_first_scatter;
    opt.vertex_ctx = &ps;
    soak_walk_result_rgb w;
    soak_medium_walk_rgb(&mr, &opt, soak_geometry_offset(x, n_ref, d), d, &boundary, &t->rng, &w);
    return ps.ok;
}

static int trace_photon(rt_thread *t, soak_vec3 org, soak_vec3 dir, soak_rgb power, photon_list *out)
{
    const soak_scene *sc = t->ctx->scene;
    int specular = 0, inside = 0;
    soak_rgb absorb = soak_rgb3(0, 0, 0);
    for (int bounce = 0; bounce < 64; ++bounce) {
        soak_ray r = {org, dir, 0.0, INFINITY};
        soak_hit h;
        int found = 0;
        if (soak_geometry_intersect(sc->geometry, &r, &h, &found) != SOAK_OK || !found) return 1;
        if (inside) power = soak_rgb_mul(power, rgb_exp(absorb, h.t));
        const soak_object *obj = &sc->objects[h.object_id];
        const soak_material *m = &sc->materials[obj->material];
        if (m->type == SOAK_MAT_DIELECTRIC) {
            soak_vec3 wo = soak_v3_scale(dir, -1.0);
            int entering = soak_v3_dot(wo, h.ng) > 0;
            soak_vec3 n = entering ? h.ng : soak_v3_scale(h.ng, -1.0);
            double eta = entering ? m->ior : 1.0 / m->ior, cos_i = soak_v3_dot(wo, n), cos_t;
            double F = rt_fresnel(cos_i, eta, &cos_t);
            if (rt_rand(t) < F) {
                dir = soak_v3_sub(soak_v3_scale(n, 2 * cos_i), wo);
            } else {
                dir = soak_v3_norm(soak_v3_add(soak_v3_scale(wo, -1.0 / eta), soak_v3_scale(n, cos_i / eta - cos_t)));
                inside = entering;
                absorb = m->absorption;
            }
            org = soak_geometry_offset(h.p, h.ng, dir);
            specular = 1;
            continue;
        }
        if (!specular || m->type != SOAK_MAT_WET || m->base != SOAK_BASE_MEDIUM) return 1;
        soak_vec3 n_out = h.ng;
        double cos1 = -soak_v3_dot(dir, n_out);
        if (!(cos1 > 0)) return 1;
        double wet = soak_scene_wetness(obj, h.p, h.u, h.v);
        const soak_scene_medium *med = (!m->has_dry || rt_rand(t) < wet) ? &m->medium : &m->dry_medium;
        rt_stack st = rt_wet_stack(t, m, wet);
        soak_vec3 tang = soak_v3_add(dir, soak_v3_scale(n_out, cos1));
        double p = soak_v3_len(tang);
        soak_vec3 tdir = p > 1e-12 ? soak_v3_scale(tang, 1.0 / p) : soak_v3(0, 0, 0);
        if (!rt_cross_stack(t, &st, p, 0, &power)) {
            dir = rt_snell_dir(tdir, n_out, p, 1.0, 1); /* reflected by the film: still a caustic path */
            org = soak_geometry_offset(h.p, n_out, dir);
            continue;
        }
        return walk_to_first_scatter(t, m, med, &st, obj, h.p, rt_snell_dir(tdir, n_out, p, m->medium.ior, 0), n_out,
                                     power, out);
    }
    return 1;
}

static int should_stop(const volatile sig_atomic_t *cancel, double deadline)
{
    if (cancel && *cancel) return 1;
    if (!(deadline > 0)) return 0;
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec > deadline;
}

/* Photons traced before a stop carry the power of n: scale them to the k
 * actually emitted so the caustic estimate stays unbiased. */
static void rescale(photon_list *l, long long n, long long k)
{
    if (k <= 0 || k >= n) return;
    double s = (double)n / (double)k;
    for (size_t i = 0; i < l->n; ++i)
        for (int c = 0; c < 3; ++c) l->p[i].power[c] = (float)(l->p[i].power[c] * s);
}

/* Where photons come from: the lights, aimed at the bounding sphere of the
 * dielectric objects, each light chosen in proportion to the luminance flux
 * it sends toward that sphere. */
typedef struct photon_source {
    const soak_scene *scene;
    soak_vec3 center;
    double R;
    double far;   /* distance from center of a sun photon's origin */
    double *flux; /* per light */
    double total;
    long long n;  /* photons to emit: the power of each is divided by it */
} photon_source;

/* Bounding sphere of the dielectric objects; 0 when there is none. */
static int dielectric_sphere(const soak_scene *sc, soak_vec3 *center, double *R)
{
    soak_vec3 lo = soak_v3(INFINITY, INFINITY, INFINITY), hi = soak_v3(-INFINITY, -INFINITY, -INFINITY);
    int any = 0;
    for (int i = 0; i < sc->n_objects; ++i) {
        if (sc->materials[sc->objects[i].material].type != SOAK_MAT_DIELECTRIC) continue;
        soak_vec3 a, b;
        if (soak_geometry_object_bounds(sc->geometry, sc->objects[i].object_id, &a, &b) != SOAK_OK) continue;
        lo = soak_v3(fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z));
        hi = soak_v3(fmax(hi.x, b.x), fmax(hi.y, b.y), fmax(hi.z, b.z));
        any = 1;
    }
    if (!any) return 0;
    *center = soak_v3_scale(soak_v3_add(lo, hi), 0.5);
    *R = 0.5 * soak_v3_len(soak_v3_sub(hi, lo)) * 1.001 + 1e-9;
    return 1;
}

/* Fills flux[] (luminance flux of each light toward the sphere); returns the total. */
static double light_fluxes(const photon_source *src, double *flux)
{
    const soak_scene *sc = src->scene;
    double R = src->R, total = 0;
    for (int i = 0; i < sc->n_lights; ++i) {
        const soak_light *l = &sc->lights[i];
        if (l->type == SOAK_LIGHT_DIRECTIONAL) {
            flux[i] = soak_rgb_luminance(l->value) * SOAK_PI * R * R;
        } else if (l->type == SOAK_LIGHT_POINT) {
            double d = soak_v3_len(soak_v3_sub(src->center, l->position));
            double omega = d > R ? 2 * SOAK_PI * (R * R / (d * d)) / (1 + sqrt(1 - R * R / (d * d))) : 4 * SOAK_PI;
            flux[i] = soak_rgb_luminance(l->value) * omega;
        }
        total += flux[i];
    }
    return total;
}

/* A sun photon: uniform over the sphere's disk seen from the sun, far out. */
static void emit_from_sun(rt_thread *t, const photon_source *src, const soak_light *l, double prob, soak_vec3 *org,
                          soak_vec3 *dir, soak_rgb *power)
{
    double R = src->R;
    rt_frame f = rt_frame_make(l->direction);
    double rr = R * sqrt(rt_rand(t)), phi = 2 * SOAK_PI * rt_rand(t);
    *org = soak_v3_add(src->center, rt_to_world(&f, soak_v3(rr * cos(phi), rr * sin(phi), src->far)));
    *dir = soak_v3_scale(l->direction, -1.0);
    *power = soak_rgb_scale(l->value, SOAK_PI * R * R / (src->n * prob));
}

/* A point-light photon: uniform in the cone around the sphere (the whole
 * sphere of directions from inside it). */
static void emit_from_point(rt_thread *t, const photon_source *src, const soak_light *l, double prob, soak_vec3 *org,
                            soak_vec3 *dir, soak_rgb *power)
{
    double R = src->R;
    soak_vec3 to = soak_v3_sub(src->center, l->position);
    double d = soak_v3_len(to);
    double s2 = d > R ? R * R / (d * d) : 1.0;
    double one_minus = d > R ? s2 / (1 + sqrt(1 - s2)) : 2.0; /* 1 - cos(theta_max) */
    double ct = 1 - rt_rand(t) * one_minus, st = sqrt(fmax(0.0, 1 - ct * ct)), phi = 2 * SOAK_PI * rt_rand(t);
    rt_frame f = rt_frame_make(d > 0 ? soak_v3_scale(to, 1.0 / d) : soak_v3(0, 0, 1));
    *dir = soak_v3_norm(rt_to_world(&f, soak_v3(st * cos(phi), st * sin(phi), ct)));
    *org = l->position;
    *power = soak_rgb_scale(l->value, 2 * SOAK_PI * one_minus / (src->n * prob));
}

/* Chooses a light by flux and emits a photon from it; 0 when the chosen
 * light sends nothing. */
static int emit_photon(rt_thread *t, const photon_source *src, soak_vec3 *org, soak_vec3 *dir, soak_rgb *power)
{
    const soak_scene *sc = src->scene;
    double u = rt_rand(t) * src->total, acc = 0;
    int li = 0;
    while (li < sc->n_lights - 1 && acc + src->flux[li] <= u) acc += src->flux[li++];
    const soak_light *l = &sc->lights[li];
    double prob = src->flux[li] / src->total;
    if (!(prob > 0)) return 0;
    if (l->type == SOAK_LIGHT_DIRECTIONAL)
        emit_from_sun(t, src, l, prob, org, dir, power);
    else
        emit_from_point(t, src, l, prob, org, dir, power);
    return 1;
}

/* Emits and traces photons 0, 1, ... (photon i from its own stream of
 * seed) until n or a stop. Returns how many were emitted, -1 when out of
 * memory. */
static long long trace_photons(const rt_ctx *c, const photon_source *src, uint64_t seed,
                               const volatile sig_atomic_t *cancel, double deadline, photon_list *list)
{
    rt_thread t;
    memset(&t, 0, sizeof t);
    t.ctx = c;
    int ok = 1;
    long long i = 0;
    for (; i < src->n && ok; ++i) {
        if ((i & 1023) == 0 && i > 0 && should_stop(cancel, deadline)) break;
        soak_rng_seed(&t.rng, seed ^ 0x5bd1e9955bd1e995ull, (uint64_t)i);
        soak_vec3 org, dir;
        soak_rgb power;
        if (!emit_photon(&t, src, &org, &dir, &power)) continue;
        ok = trace_photon(&t, org, dir, power, list);
    }
    return ok ? i : -1;
}

soak_status rt_photons_build(const rt_ctx *c, long long n, double radius, uint64_t seed,
                             const volatile sig_atomic_t *cancel, double deadline, rt_photon_map *map)
{
    memset(map, 0, sizeof *map);
    map->radius = radius;
    if (n <= 0 || !(radius > 0)) return SOAK_OK;
    photon_source src;
    memset(&src, 0, sizeof src);
    src.scene = c->scene;
    src.n = n;
    if (!dielectric_sphere(c->scene, &src.center, &src.R)) return SOAK_OK;
    soak_vec3 slo, shi;
    src.far = 4 * src.R;
    if (soak_geometry_bounds(c->scene->geometry, &slo, &shi) == SOAK_OK) src.far += soak_v3_len(soak_v3_sub(shi, slo));
    src.flux = calloc((size_t)c->scene->n_lights + 1, sizeof(double));
    if (!src.flux) return SOAK_ERR_NOMEM;
    soak_status st = SOAK_OK;
    photon_list list = {0};
    src.total = light_fluxes(&src, src.flux);
    if (src.total > 0) {
        long long emitted = trace_photons(c, &src, seed, cancel, deadline, &list);
        if (emitted < 0) {
            st = SOAK_ERR_NOMEM;
        } else {
            rescale(&list, n, emitted);
            map->emitted = emitted;
            if (list.n > 0) st = rt_photon_map_store(map, list.p, list.n);
        }
    }
    free(src.flux);
    free(list.p);
    return st;
}
