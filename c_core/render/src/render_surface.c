/* Surface interactions of the path tracer: a dispatcher over the BSDF
 * interface (soak/bsdf.h). Each material has a dry and a wet BSDF, set up
 * once per render (rt_bsdfs_setup); at a hit the wet one is chosen with
 * probability wetness * film coverage (where that lies strictly between 0
 * and 1 light estimates see the mixture, render_mix.c). Two ways through a BSDF:
 *   - smooth glass (SOAK_BSDF_TRANSMIT): a delta choice that also updates
 *     the path's inside state, absorption and eta_scale;
 *   - every other BSDF (a traced film too: its eval and pdf are estimates):
 *     next-event estimation with eval (value and pdf for the power
 *     heuristic), then one sample.
 * Wet media (base "medium") go to render_medium.c. */
#include <stdlib.h>

#include "render_surface.h"
#include "render_lights.h"
#include "render_mix.h"
#include "render_bsdfs.h"
#include "render_levels.h"
#include "render_medium.h"

/* Shading frame at a hit seen from path->dir: geometric normal on the
 * viewer's side, shading normal flipped to agree (or replaced by the
 * geometric one when it faces away from the viewer). 0: grazing, no frame. */
static int shading_frame(const soak_hit *hit, const rt_path *path, soak_vec3 *ng, rt_frame *f, soak_vec3 *wl)
{
    soak_vec3 wo = soak_v3_scale(path->dir, -1.0);
    *ng = soak_v3_dot(wo, hit->ng) >= 0 ? hit->ng : soak_v3_scale(hit->ng, -1.0);
    soak_vec3 ns = soak_v3_dot(hit->ns, *ng) >= 0 ? hit->ns : soak_v3_scale(hit->ns, -1.0);
    if (soak_v3_dot(wo, ns) <= 1e-9) ns = *ng; /* shading normal facing away from the viewer */
    *f = rt_frame_make(ns);
    *wl = soak_v3_norm(rt_to_local(f, wo));
    return wl->z > 0;
}

/* Continues a path from a surface hit in the world direction dir chosen
 * by a non-delta lobe with solid-angle pdf (kept for MIS at the next hit). */
static void continue_path(rt_path *path, const soak_hit *hit, soak_vec3 ng, soak_vec3 dir, double pdf)
{
    path->dir = soak_v3_norm(dir);
    if (soak_v3_dot(path->dir, ng) <= 0) {
        path->alive = 0; /* below the geometric surface: shading-normal artefact */
        return;
    }
    path->org = soak_geometry_offset(hit->p, ng, path->dir);
    path->prev_pdf = pdf;
    path->prev_delta = 0;
    path->prev_pos = hit->p;
}

/* A mirror direction of a delta lobe, kept above the geometric surface. */
static void continue_delta(rt_path *path, const soak_hit *hit, soak_vec3 ng, const rt_frame *f, soak_vec3 wi)
{
    path->dir = rt_to_world(f, wi);
    if (soak_v3_dot(path->dir, ng) <= 0) path->dir = soak_v3_sub(path->dir, soak_v3_scale(ng, 2 * soak_v3_dot(path->dir, ng)));
    path->org = soak_geometry_offset(hit->p, ng, path->dir);
    path->prev_delta = 1;
}

/* Next-event estimation from every light into path->L. */
static void sample_lights(rt_thread *t, const soak_hit *hit, soak_vec3 ng, const rt_frame *f, soak_vec3 wl,
                          const rt_bsdf_mix *b, rt_path *path)
{
    soak_vec3 p_out = soak_geometry_offset(hit->p, ng, ng);
    int nl = rt_light_count(t->ctx);
    for (int li = 0; li < nl; ++li) {
        rt_light_sample ls;
        if (!rt_light_sample_at(t, li, p_out, &ls)) continue;
        if (soak_v3_dot(ls.wi, ng) <= 0) continue;
        soak_vec3 l1 = soak_v3_norm(rt_to_local(f, ls.wi));
        if (!(l1.z > 0)) continue;
        soak_rgb fv;
        double pdf;
        if (rt_mix_eval(b, l1, wl, &fv, &pdf) != SOAK_OK || !(rgb_max(fv) > 0)) continue;
        double mis = ls.pdf > 0 ? rt_power(ls.pdf, pdf) : 1.0;
        if (!rt_visible(t, p_out, ls.wi, ls.dist)) continue;
        soak_rgb contrib = soak_rgb_scale(soak_rgb_mul(path->beta, soak_rgb_mul(fv, ls.L)), l1.z * mis / (ls.pdf > 0 ? ls.pdf : 1.0));
        path->L = soak_rgb_add(path->L, contrib);
    }
}

static void draw3(rt_thread *t, double u[3])
{
    u[0] = rt_rand(t);
    rt_rand2(t, &u[1], &u[2]);
}

/* Any reflecting BSDF (or mixture of them): lights, then one sample. */
static void reflect(rt_thread *t, const soak_hit *hit, const rt_bsdf_mix *b, rt_path *path)
{
    soak_vec3 ng, wl;
    rt_frame f;
    if (!shading_frame(hit, path, &ng, &f, &wl)) {
        path->alive = 0;
        return;
    }
    if (rt_mix_flags(b) & (SOAK_BSDF_DIFFUSE | SOAK_BSDF_GLOSSY)) sample_lights(t, hit, ng, &f, wl, b, path);
    double u[3];
    draw3(t, u);
    soak_bsdf_sample s;
    int ok = 0;
    if (soak_bsdf_sample_dir(b->b[b->chosen], wl, u, &s, &ok) != SOAK_OK || !ok || (b->n > 1 && !rt_mix_reweight(b, wl, &s)) ||
        !(rgb_max(s.weight) > 0)) {
        path->alive = 0;
        return;
    }
    path->beta = soak_rgb_mul(path->beta, s.weight);
    if (s.delta) continue_delta(path, hit, ng, &f, s.wi);
    else continue_path(path, hit, ng, rt_to_world(&f, s.wi), s.pdf);
}

/* Smooth dielectric in the frame of the geometric normal (either side);
 * Beer-Lambert absorption inside is applied by the path loop per segment. */
static void dielectric(rt_thread *t, const soak_hit *hit, const soak_material *m, const soak_bsdf *b, rt_path *path)
{
    rt_frame f = rt_frame_make(hit->ng);
    soak_vec3 wo = soak_v3_norm(rt_to_local(&f, soak_v3_scale(path->dir, -1.0)));
    double u[3] = {rt_rand(t), 0, 0};
    soak_bsdf_sample s;
    int ok = 0;
    if (soak_bsdf_sample_dir(b, wo, u, &s, &ok) != SOAK_OK || !ok) {
        path->alive = 0;
        return;
    }
    path->dir = soak_v3_norm(rt_to_world(&f, s.wi));
    if (s.eta != 1.0) {
        path->beta = soak_rgb_mul(path->beta, s.weight);
        path->eta_scale *= s.eta * s.eta; /* kept out of roulette (rt_rr_weight) */
        path->inside = wo.z > 0;
        path->absorb = m->absorption;
    }
    path->org = soak_geometry_offset(hit->p, hit->ng, path->dir);
    path->prev_delta = 1;
}

/* The BSDFs at a hit: dry, wet and pore by their shares (w: the liquid
 * interface's, rt_level_at); one is drawn (one
 * draw: the film's pixels stay as they were without pores) and, unless the
 * components can be mixed (rt_mix_can), it alone is kept. */
static void surface_mix(rt_thread *t, double w, const soak_material *m, const rt_material_bsdf *mb, rt_bsdf_mix *mix)
{
    mix->n = 1;
    mix->b[0] = &mb->dry;
    mix->w[0] = 1.0;
    mix->chosen = 0;
    if (!mb->has_wet) return;
    double u = rt_rand(t), wet = mb->has_pore ? w * (1.0 - m->film_pore_share) : w;
    const soak_bsdf *parts[3] = {&mb->dry, &mb->wet, &mb->pore};
    double share[3] = {1.0 - w, wet, w - wet};
    int pick = u < wet ? 1 : (u < w ? 2 : 0);
    mix->n = 0;
    for (int i = 0; i < 3; ++i) {
        if (!(share[i] > 0)) continue;
        if (i == pick) mix->chosen = mix->n;
        mix->b[mix->n] = parts[i];
        mix->w[mix->n++] = share[i];
    }
    if (mix->n >= 2 && rt_mix_can(mix)) return;
    mix->n = 1;
    mix->b[0] = parts[pick];
    mix->w[0] = 1.0;
    mix->chosen = 0;
}

void rt_surface(rt_thread *t, const soak_hit *hit, rt_path *path)
{
    const soak_scene *s = t->ctx->scene;
    const soak_object *obj = &s->objects[hit->object_id];
    const soak_material *m = &s->materials[obj->material];
    const rt_material_bsdf *mb = &t->ctx->bsdfs[obj->material];
    if (m->type == SOAK_MAT_EMITTER) {
        path->alive = 0;
        return;
    }
    if (m->type == SOAK_MAT_WET && m->base == SOAK_BASE_MEDIUM) {
        rt_wet_medium(t, hit, obj, m, path);
        return;
    }
    rt_bsdf_mix mix;
    double w = rt_level_at(t, obj, hit, &m, &mb);
    surface_mix(t, w, m, mb, &mix);
    if (mix.n == 1 && (mix.b[0]->flags & SOAK_BSDF_TRANSMIT)) dielectric(t, hit, m, mix.b[0], path);
    else reflect(t, hit, &mix, path);
}
