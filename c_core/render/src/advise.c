/* The cheapest model per scene material within a tolerance (soak/advise.h). */
#define _POSIX_C_SOURCE 200809L
#include "soak/advise.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "soak/accuracy.h"
#include "soak/geometry.h"

void soak_advise_options_default(soak_advise_options *o)
{
    o->grid_w = 32;
    o->grid_h = 24;
    o->max_hits = 32;
    o->samples = 256;
    o->seed = 1;
    o->cost_rounds = 50;
}

#define ADV_MAX_LIGHTS 8

typedef struct view_hit {
    double cos_o, wetness;
    soak_vec3 wo; /* local frame */
    soak_local_light lights[ADV_MAX_LIGHTS];
    int n_lights;
} view_hit;

typedef struct hit_list {
    view_hit *h;
    int n, cap;
} hit_list;

static int push_hit(hit_list *l, view_hit v)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 64;
        view_hit *h = realloc(l->h, (size_t)cap * sizeof *h);
        if (!h) return 0;
        l->h = h;
        l->cap = cap;
    }
    l->h[l->n++] = v;
    return 1;
}

/* Mean radiance of the environment (what a mirror or a rough lobe sees on
 * average; the map's rows are not solid-angle weighted: a rough figure). */
static soak_rgb env_mean(const soak_environment *e)
{
    if (e->type == SOAK_ENV_CONSTANT) return e->radiance;
    soak_rgb m = soak_rgb3(0, 0, 0);
    if (e->type != SOAK_ENV_MAP || !e->map.pixels || e->map.channels < 3) return m;
    size_t n = (size_t)e->map.width * e->map.height;
    for (size_t i = 0; i < n; ++i) {
        const float *px = e->map.pixels + i * e->map.channels;
        m.r += px[0];
        m.g += px[1];
        m.b += px[2];
    }
    double k = n ? e->scale / (double)n : 0.0;
    return soak_rgb3(m.r * k, m.g * k, m.b * k);
}

/* The scene's lights at p (unoccluded ones), in the frame (t, b, n). */
static void hit_lights(const soak_scene *s, soak_vec3 p, soak_vec3 n, soak_vec3 t, soak_vec3 b, view_hit *v)
{
    v->n_lights = 0;
    for (int i = 0; i < s->n_lights && v->n_lights < ADV_MAX_LIGHTS; ++i) {
        const soak_light *l = &s->lights[i];
        soak_vec3 d;
        double dist = INFINITY, k = 1;
        if (l->type == SOAK_LIGHT_DIRECTIONAL) {
            d = soak_v3_norm(l->direction);
        } else {
            soak_vec3 to = soak_v3_sub(l->position, p);
            dist = soak_v3_len(to);
            if (!(dist > 0)) continue;
            d = soak_v3_scale(to, 1 / dist);
            /* point: intensity / d^2; sphere: radiance * pi r^2 / d^2 (far-field) */
            k = (l->type == SOAK_LIGHT_SPHERE ? SOAK_PI * l->radius * l->radius : 1.0) / (dist * dist);
            if (l->type == SOAK_LIGHT_SPHERE) dist -= l->radius;
        }
        double c = soak_v3_dot(d, n);
        if (!(c > 1e-6)) continue;
        soak_ray ray = {soak_v3_add(p, soak_v3_scale(n, 1e-4)), d, 0.0, dist > 2e-4 ? dist - 1e-4 : dist};
        int occ = 0;
        if (soak_geometry_occluded(s->geometry, &ray, &occ) != SOAK_OK || occ) continue;
        soak_local_light *ll = &v->lights[v->n_lights++];
        ll->wi = soak_v3_norm(soak_v3(soak_v3_dot(d, t), soak_v3_dot(d, b), c));
        ll->irradiance = soak_rgb3(l->value.r * k, l->value.g * k, l->value.b * k);
    }
}

/* Primary rays through pixel centres of a grid_w x grid_h image with the
 * scene's aspect (pinhole at the camera position). */
static soak_status visible_hits(const soak_scene *s, const soak_advise_options *o, hit_list *lists)
{
    const soak_camera *cam = &s->camera;
    soak_vec3 fwd = soak_v3_norm(soak_v3_sub(cam->look_at, cam->position));
    soak_vec3 right = soak_v3_norm(soak_v3_cross(fwd, cam->up));
    soak_vec3 up = soak_v3_cross(right, fwd);
    double tan_half = tan(cam->fov_deg * SOAK_PI / 360.0), aspect = (double)s->width / s->height;
    for (int y = 0; y < o->grid_h; ++y)
        for (int x = 0; x < o->grid_w; ++x) {
            double sx = (2 * (x + 0.5) / o->grid_w - 1) * tan_half * aspect;
            double sy = (1 - 2 * (y + 0.5) / o->grid_h) * tan_half;
            soak_ray ray = {cam->position, soak_v3_norm(soak_v3_add(fwd, soak_v3_add(soak_v3_scale(right, sx), soak_v3_scale(up, sy)))),
                            0.0, INFINITY};
            soak_hit hit;
            int found = 0;
            soak_status st = soak_geometry_intersect(s->geometry, &ray, &hit, &found);
            if (st != SOAK_OK) return st;
            if (!found || hit.object_id >= (unsigned)s->n_objects) continue;
            const soak_object *obj = &s->objects[hit.object_id];
            if (obj->material < 0 || obj->material >= s->n_materials) continue;
            soak_vec3 n = soak_v3_dot(ray.dir, hit.ns) > 0 ? soak_v3_scale(hit.ns, -1) : hit.ns, t, b;
            soak_v3_basis(n, &t, &b);
            soak_vec3 to_eye = soak_v3_scale(ray.dir, -1);
            view_hit v;
            memset(&v, 0, sizeof v);
            v.cos_o = fmin(fmax(soak_v3_dot(to_eye, n), 1e-3), 1.0);
            v.wetness = soak_scene_wetness(obj, hit.p, hit.u, hit.v);
            double sin_o = sqrt(fmax(0.0, 1 - v.cos_o * v.cos_o)), tx = soak_v3_dot(to_eye, t), ty = soak_v3_dot(to_eye, b);
            double tl = sqrt(tx * tx + ty * ty);
            v.wo = tl > 0 ? soak_v3(sin_o * tx / tl, sin_o * ty / tl, v.cos_o) : soak_v3(0, 0, 1);
            hit_lights(s, hit.p, n, t, b, &v);
            if (!push_hit(&lists[obj->material], v)) return SOAK_ERR_NOMEM;
        }
    return SOAK_OK;
}

/* Up to max hits evenly spread over the list. */
static int pick(const hit_list *l, int max, int i) { return l->n <= max ? i : (int)((long)i * l->n / max); }

/* Albedos of material m at the chosen hits, interleaved RGB. */
static soak_status albedos(const soak_material *m, const hit_list *l, const soak_advise_options *o, soak_rgb env,
                           double *val, double *var)
{
    int n = l->n < o->max_hits ? l->n : o->max_hits;
    if (n == 0) return SOAK_OK;
    soak_shading_material *sm = NULL;
    soak_status st = soak_shading_material_new(m, &sm);
    for (int i = 0; i < n && st == SOAK_OK; ++i) {
        const view_hit *h = &l->h[pick(l, o->max_hits, i)];
        soak_albedo_estimate e;
        st = soak_shading_radiance(sm, h->wetness, h->wo, env, h->lights, h->n_lights, o->samples,
                                   o->seed + (uint64_t)i, &e);
        if (st != SOAK_OK) break;
        for (int ch = 0; ch < 3; ++ch) {
            val[3 * i + ch] = soak_rgb_at(e.value, ch);
            var[3 * i + ch] = soak_rgb_at(e.std_error, ch) * soak_rgb_at(e.std_error, ch);
        }
    }
    soak_shading_material_free(sm);
    return st;
}

static double rel_rms(const double *ref, const double *ref_var, const double *m, const double *m_var, int n3)
{
    double num = 0, noise = 0, den = 0;
    for (int i = 0; i < n3; ++i) {
        num += (m[i] - ref[i]) * (m[i] - ref[i]);
        noise += ref_var[i] + m_var[i];
        den += ref[i] * ref[i];
    }
    return den > 0 ? sqrt(fmax(0.0, num - noise) / den) : (num > noise ? INFINITY : 0.0);
}

static double shading_ns(const soak_material *m, int rounds)
{
    double e = 0, s = 0;
    return soak_material_cost(m, rounds, &e, &s) == SOAK_OK ? e + s : INFINITY;
}

static const char *kept_reason(const soak_material *m)
{
    switch (m->type) {
    case SOAK_MAT_EMITTER: return "emitter";
    case SOAK_MAT_DIELECTRIC: return "dielectric (refraction): no model renders it";
    case SOAK_MAT_WET:
        if (m->base == SOAK_BASE_MEDIUM) return "subsurface medium: no model view (the walk is kept)";
        break;
    default: break;
    }
    return NULL;
}

/* Tries every model on material index mi of a private copy of the scene. */
static soak_status advise_material(soak_scene *s, int mi, const hit_list *l, double tol, const soak_advise_options *o,
                                   soak_advice *a)
{
    const soak_material full = s->materials[mi];
    int n = l->n < o->max_hits ? l->n : o->max_hits;
    double *buf = malloc(sizeof(double) * 12 * (size_t)n);
    if (!buf) return SOAK_ERR_NOMEM;
    double *ref = buf, *ref_var = buf + 3 * n, *val = buf + 6 * n, *var = buf + 9 * n;
    soak_rgb env = env_mean(&s->env);
    soak_status st = albedos(&full, l, o, env, ref, ref_var);
    a->full_ns = a->model_ns = shading_ns(&full, o->cost_rounds);
    size_t nm;
    const soak_model *models = soak_models(&nm);
    double best_err = INFINITY;
    const soak_model *closest = NULL;
    char err[512];
    for (size_t k = 0; k < nm && st == SOAK_OK; ++k) {
        s->materials[mi] = full;
        if (soak_scene_set_model(s, full.name, models[k].name, err, sizeof err) != SOAK_OK) continue;
        if (albedos(&s->materials[mi], l, o, env, val, var) != SOAK_OK) continue;
        double e = rel_rms(ref, ref_var, val, var, 3 * n);
        double ns = shading_ns(&s->materials[mi], o->cost_rounds);
        if (a->n_tried < SOAK_ADVISE_MAX_MODELS) {
            a->tried[a->n_tried].model = &models[k];
            a->tried[a->n_tried].error = e;
            a->tried[a->n_tried++].ns = ns;
        }
        if (e < best_err) {
            best_err = e;
            closest = &models[k];
        }
        if (e <= tol && ns < a->model_ns) {
            a->model = &models[k];
            a->model_ns = ns;
            a->error = e;
        }
    }
    s->materials[mi] = full;
    free(buf);
    if (!a->model && closest)
        snprintf(a->note, sizeof a->note, "kept: closest model %s is %.1f %% off (tolerance %.1f %%)", closest->name,
                 100 * best_err, 100 * tol);
    else if (!a->model)
        snprintf(a->note, sizeof a->note, "kept: no model accepts this material");
    return st;
}

soak_status soak_advise_scene(const soak_scene *scene, double tol, const soak_advise_options *opt, soak_advice **advice,
                              int *n, char *err, size_t errlen)
{
    if (!scene || !advice || !n) return SOAK_ERR_NULL;
    soak_advise_options o;
    if (opt) o = *opt;
    else soak_advise_options_default(&o);
    if (!(tol > 0 && tol <= SOAK_ADVISE_MAX_TOL) || !(o.grid_w >= 1 && o.grid_w <= SOAK_ADVISE_MAX_GRID) ||
        !(o.grid_h >= 1 && o.grid_h <= SOAK_ADVISE_MAX_GRID) || !(o.max_hits >= 1 && o.max_hits <= 4096) ||
        !(o.samples >= SOAK_ADVISE_MIN_SAMPLES && o.samples <= SOAK_ADVISE_MAX_SAMPLES) ||
        !(o.cost_rounds >= 1 && o.cost_rounds <= 100000))
        return SOAK_ERR_ARG;
    int nmat = scene->n_materials;
    soak_advice *out = calloc(nmat > 0 ? (size_t)nmat : 1, sizeof *out);
    hit_list *lists = calloc(nmat > 0 ? (size_t)nmat : 1, sizeof *lists);
    soak_material *mats = malloc((nmat > 0 ? (size_t)nmat : 1) * sizeof *mats);
    soak_status st = out && lists && mats ? visible_hits(scene, &o, lists) : SOAK_ERR_NOMEM;
    if (st != SOAK_OK && err && errlen) snprintf(err, errlen, "%s: finding the visible surfaces failed (%s)", scene->path, soak_status_str(st));
    /* A shallow copy whose material array the trials may change. */
    soak_scene s = *scene;
    if (mats) memcpy(mats, scene->materials, (size_t)nmat * sizeof *mats);
    s.materials = mats;
    for (int i = 0; i < nmat && st == SOAK_OK; ++i) {
        soak_advice *a = &out[i];
        const soak_material *m = &scene->materials[i];
        snprintf(a->material, sizeof a->material, "%s", m->name);
        a->hits = lists[i].n;
        for (int h = 0; h < lists[i].n; ++h) {
            a->mean_wetness += lists[i].h[h].wetness / lists[i].n;
            a->mean_cos += lists[i].h[h].cos_o / lists[i].n;
        }
        const char *why = kept_reason(m);
        if (why || !soak_accuracy_supported(m)) {
            snprintf(a->note, sizeof a->note, "kept: %s", why ? why : "not a surface the models describe");
            continue;
        }
        if (lists[i].n == 0) {
            snprintf(a->note, sizeof a->note, "kept: the camera does not see it");
            continue;
        }
        st = advise_material(&s, i, &lists[i], tol, &o, a);
        if (st != SOAK_OK && err && errlen)
            snprintf(err, errlen, "%s: material '%s': %s", scene->path, m->name, soak_status_str(st));
    }
    for (int i = 0; lists && i < nmat; ++i) free(lists[i].h);
    free(lists);
    free(mats);
    if (st != SOAK_OK) {
        free(out);
        return st;
    }
    *advice = out;
    *n = nmat;
    return SOAK_OK;
}

soak_status soak_advise_apply(soak_scene *scene, const soak_advice *advice, int n, char *err, size_t errlen)
{
    if (!scene || (!advice && n > 0)) return SOAK_ERR_NULL;
    for (int i = 0; i < n; ++i) {
        if (!advice[i].model) continue;
        soak_status st = soak_scene_set_model(scene, advice[i].material, advice[i].model->name, err, errlen);
        if (st != SOAK_OK) return st;
    }
    return SOAK_OK;
}
