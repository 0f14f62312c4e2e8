/* Surface interactions of the path tracer.
 *
 * Opaque materials (lambert, conductor, and the wet film over a lambert or
 * GGX base) share one routine: a smooth liquid film of index n2 over an
 * opaque base, traced explicitly (Lekner & Dorf 1988 as used in seed 000
 * sec. 2.1 / 3.1): reflect at the film top with Fresnel probability
 * F12(cos1) (delta lobe); otherwise refract into the film, scatter off the
 * base, and at the underside leave with probability 1 - F21 or be reflected
 * back down (total internal reflection beyond the critical angle). A bare
 * material is the same routine with n2 = 1 (no interface, F = 0).
 *
 * Radiance across the smooth interface: a camera path entering a medium of
 * index n from air gets the factor 1/n^2 and n^2 when it leaves (radiance /
 * n^2 is invariant; the corrected factor of seed 000 Eq. 1/2, see
 * soak/jensen.h). The two cancel for a path that leaves, so beta carries
 * neither while in the film (the roulette then does not kill paths for a
 * factor that is undone later), and the estimates gathered in the film carry
 * the 1/n^2 explicitly. Next-event estimation at the base: the base receives
 * E = (1 - F12(cos1)) L cos1 dw1 from a light seen at cos1 in air, so the
 * radiance it sends back is f_base E, which reaches the camera as
 *   beta * (1/n2^2) * f_base(w2_light, w_up) * (1 - F12) * e^{-a h / cos2} * cos1 * L / pdf_light. The competing BSDF strategy (leave the film and hit
 * the light) has, in air solid angle,
 *   pdf = pdf_base(w2) * (1 - F21(cos2)) * (1/n2)^2 * cos1 / cos2,
 * the Jacobian of Snell's map dw2/dw1 = (n1/n2)^2 cos1/cos2; the two are
 * combined with the power heuristic.
 *
 * A film over a Lambert base skips the bounce-by-bounce tracing: its
 * expectation is the closed-form Lekner-Dorf BSDF (soak/film.h), used
 * instead (film_lambert below); the traced routine remains for GGX bases and
 * for films whose set-up the closed form rejects. */
#include "render_internal.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"

typedef struct base_model {
    soak_base_type type;
    soak_rgb albedo;
    soak_rgb eta, k; /* relative to the film */
    double alpha;
} base_model;

/* f (1/sr) of the base for local directions wi, wo (z > 0). */
static soak_rgb base_eval(const base_model *b, soak_vec3 wi, soak_vec3 wo)
{
    if (!(wi.z > 0 && wo.z > 0)) return soak_rgb3(0, 0, 0);
    if (b->type == SOAK_BASE_LAMBERT) return rgb_scale(b->albedo, SOAK_INV_PI);
    return soak_rgb3(soak_ggx_brdf_conductor_raw(b->alpha, b->eta.r, b->k.r, wi, wo),
                     soak_ggx_brdf_conductor_raw(b->alpha, b->eta.g, b->k.g, wi, wo),
                     soak_ggx_brdf_conductor_raw(b->alpha, b->eta.b, b->k.b, wi, wo));
}

static double base_pdf(const base_model *b, soak_vec3 wi, soak_vec3 wo)
{
    if (!(wi.z > 0 && wo.z > 0)) return 0;
    if (b->type == SOAK_BASE_LAMBERT) return wi.z * SOAK_INV_PI;
    soak_vec3 h = soak_ggx_half_raw(wi, wo);
    double pdf_h = 0;
    if (soak_ggx_pdf_vndf(b->alpha, wo, h, &pdf_h) != SOAK_OK) return 0;
    double oh = soak_v3_dot(wo, h);
    return oh > 0 ? pdf_h / (4 * oh) : 0;
}

/* Samples wi for wo; returns 0 on failure. *weight = f cos / pdf. */
static int base_sample(rt_thread *t, const base_model *b, soak_vec3 wo, soak_vec3 *wi, soak_rgb *weight, double *pdf)
{
    if (b->type == SOAK_BASE_LAMBERT) {
        double u1, u2;
        rt_rand2(t, &u1, &u2);
        *wi = soak_cosine_hemisphere(u1, u2);
        *pdf = wi->z * SOAK_INV_PI;
        *weight = b->albedo;
        return *pdf > 0;
    }
    soak_vec3 h;
    double pdf_h;
    if (soak_ggx_sample_vndf(b->alpha, wo, rt_rand(t), rt_rand(t), &h, &pdf_h) != SOAK_OK) return 0;
    double oh = soak_v3_dot(wo, h);
    *wi = soak_v3_sub(soak_v3_scale(h, 2 * oh), wo);
    if (!(wi->z > 0) || !(oh > 0) || !(pdf_h > 0)) return 0;
    *wi = soak_v3_norm(*wi);
    *pdf = pdf_h / (4 * oh);
    *weight = rgb_scale(base_eval(b, *wi, wo), wi->z / *pdf);
    return 1;
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

static void opaque(rt_thread *t, const soak_hit *hit, const base_model *base, double n2, soak_rgb film_alpha,
                   double film_h, rt_path *path)
{
    const rt_ctx *c = t->ctx;
    soak_vec3 wo = soak_v3_scale(path->dir, -1.0);
    soak_vec3 ng = soak_v3_dot(wo, hit->ng) >= 0 ? hit->ng : soak_v3_scale(hit->ng, -1.0);
    soak_vec3 ns = soak_v3_dot(hit->ns, ng) >= 0 ? hit->ns : soak_v3_scale(hit->ns, -1.0);
    if (soak_v3_dot(wo, ns) <= 1e-9) ns = ng; /* shading normal facing away from the viewer */
    rt_frame f = rt_frame_make(ns);
    soak_vec3 wl = rt_to_local(&f, wo);
    double cos1 = wl.z;
    if (!(cos1 > 0)) {
        path->alive = 0;
        return;
    }
    int film = n2 != 1.0;
    int absorbing = film && film_h > 0 && rgb_max(film_alpha) > 0;
    soak_vec3 d; /* propagation direction in the film (local), going down */
    if (film) {
        double cos2;
        double F = rt_fresnel(cos1, n2, &cos2);
        if (rt_rand(t) < F) {
            soak_vec3 r = soak_v3(-wl.x, -wl.y, wl.z);
            path->dir = rt_to_world(&f, r);
            if (soak_v3_dot(path->dir, ng) <= 0) path->dir = soak_v3_sub(path->dir, soak_v3_scale(ng, 2 * soak_v3_dot(path->dir, ng)));
            path->org = soak_geometry_offset(hit->p, ng, path->dir);
            path->prev_delta = 1;
            return;
        }
        d = soak_v3(-wl.x / n2, -wl.y / n2, -cos2);
        if (absorbing) path->beta = rgb_mul(path->beta, rgb_exp(film_alpha, film_h / cos2));
    } else {
        d = soak_v3(-wl.x, -wl.y, -wl.z);
    }
    soak_vec3 p_out = soak_geometry_offset(hit->p, ng, ng);
    int nl = rt_light_count(c);
    for (int bounce = 0; bounce < RT_FILM_MAX_BOUNCES; ++bounce) {
        soak_vec3 w_up = soak_v3(-d.x, -d.y, -d.z);
        /* Next-event estimation at the base, through the film. */
        for (int li = 0; li < nl; ++li) {
            rt_light_sample ls;
            if (!rt_light_sample_at(t, li, p_out, &ls)) continue;
            if (soak_v3_dot(ls.wi, ng) <= 0) continue;
            soak_vec3 l1 = rt_to_local(&f, ls.wi);
            if (!(l1.z > 0)) continue;
            double cos2l = l1.z, T = 1.0;
            soak_vec3 l2 = l1;
            if (film) {
                T = 1.0 - rt_fresnel(l1.z, n2, &cos2l);
                l2 = soak_v3(l1.x / n2, l1.y / n2, cos2l);
            }
            soak_rgb fb = base_eval(base, l2, w_up);
            if (!(rgb_max(fb) > 0) || !(T > 0)) continue;
            double mis = 1.0;
            if (ls.pdf > 0) {
                double pb = base_pdf(base, l2, w_up) * T * (film ? l1.z / (n2 * n2 * cos2l) : 1.0);
                mis = rt_power(ls.pdf, pb);
            }
            if (!rt_visible(t, p_out, ls.wi, ls.dist)) continue;
            soak_rgb contrib = rgb_scale(rgb_mul(path->beta, rgb_mul(fb, ls.L)),
                                         T * l1.z * mis / ((ls.pdf > 0 ? ls.pdf : 1.0) * n2 * n2));
            if (absorbing) contrib = rgb_mul(contrib, rgb_exp(film_alpha, film_h / cos2l));
            path->L = rgb_add(path->L, contrib);
        }
        soak_vec3 wi;
        soak_rgb weight;
        double pdf;
        if (!base_sample(t, base, w_up, &wi, &weight, &pdf)) {
            path->alive = 0;
            return;
        }
        path->beta = rgb_mul(path->beta, weight);
        soak_vec3 out = wi;
        double pdf_air = pdf;
        if (film) {
            if (absorbing) path->beta = rgb_mul(path->beta, rgb_exp(film_alpha, film_h / wi.z));
            double cos_air;
            double F = rt_fresnel(wi.z, 1.0 / n2, &cos_air);
            if (rt_rand(t) < F) {
                d = soak_v3(wi.x, wi.y, -wi.z);
                if (absorbing) path->beta = rgb_mul(path->beta, rgb_exp(film_alpha, film_h / wi.z));
                /* Roulette inside the film keeps absorbing bases from looping. */
                double q = fmin(1.0, rt_rr_weight(path));
                if (q < 1.0) {
                    if (rt_rand(t) >= q) {
                        path->alive = 0;
                        return;
                    }
                    path->beta = rgb_scale(path->beta, 1.0 / q);
                }
                continue;
            }
            out = soak_v3(wi.x * n2, wi.y * n2, cos_air);
            pdf_air = pdf * (1.0 - F) * cos_air / (n2 * n2 * wi.z);
        }
        continue_path(path, hit, ng, rt_to_world(&f, out), pdf_air);
        return;
    }
    t->n.capped++;
    path->alive = 0;
}

void rt_films_setup(const soak_scene *s, rt_film *films)
{
    for (int i = 0; i < s->n_materials; ++i) {
        const soak_material *m = &s->materials[i];
        rt_film *fm = &films[i];
        memset(fm, 0, sizeof *fm);
        if (m->type != SOAK_MAT_WET || m->base != SOAK_BASE_LAMBERT) continue;
        fm->ok = 1;
        for (int ch = 0; ch < 3; ++ch) {
            /* soak_film takes alpha * thickness only as their product tau. */
            double tau = soak_rgb_at(m->film_absorption, ch) * m->film_thickness;
            soak_film film = {m->film_ior, tau, 1.0};
            double a = soak_rgb_at(m->albedo, ch);
            if (!soak_in_range(a, 0.0, 1.0) || soak_film_setup(&film, &fm->ch[ch]) != SOAK_OK) fm->ok = 0;
        }
    }
}

/* Closed-form BRDF of the film over Lambert (diffuse part, 1/sr), per channel. */
static soak_rgb film_lambert_eval(const rt_film *fm, soak_rgb albedo, soak_vec3 wi, soak_vec3 wo)
{
    double f[3] = {0, 0, 0};
    for (int ch = 0; ch < 3; ++ch)
        if (soak_film_ctx_brdf(&fm->ch[ch], soak_rgb_at(albedo, ch), wi, wo, &f[ch]) != SOAK_OK) f[ch] = 0;
    return soak_rgb3(f[0], f[1], f[2]);
}

/* A film over an opaque Lambert base with the film's internal reflections
 * summed in closed form (Lekner & Dorf 1988, soak/film.h): the expectation of
 * what opaque() traces bounce by bounce for the same material. Two lobes: the
 * mirror reflection of the film top, of reflectance F12(cos_o), and the
 * diffuse part f_d, of directional albedo D(cos_o) = A_dir(cos_o) - F12 (the
 * closed form's total minus its mirror part, averaged over the channels). The
 * lobe is chosen in proportion to those albedos, P_mirror = F12 / (F12 + D),
 * so that both branches carry about the same weight F12 + D: choosing by F12
 * alone (weight 1 for the mirror, D / (1 - F12) for the diffuse branch) made
 * a wet ground under a uniform sky 14x noisier than a Lambert one. The
 * diffuse direction is cosine-distributed, pdf (1 - P_mirror) cos_i / pi,
 * which also serves as the BSDF pdf of the MIS with light sampling. Lights
 * are sampled at every interaction (f_d already holds the film's
 * transmittances), so before the lobe choice. */
static void film_lambert(rt_thread *t, const soak_hit *hit, const rt_film *fm, soak_rgb albedo, rt_path *path)
{
    const rt_ctx *c = t->ctx;
    soak_vec3 wo = soak_v3_scale(path->dir, -1.0);
    soak_vec3 ng = soak_v3_dot(wo, hit->ng) >= 0 ? hit->ng : soak_v3_scale(hit->ng, -1.0);
    soak_vec3 ns = soak_v3_dot(hit->ns, ng) >= 0 ? hit->ns : soak_v3_scale(hit->ns, -1.0);
    if (soak_v3_dot(wo, ns) <= 1e-9) ns = ng; /* shading normal facing away from the viewer */
    rt_frame f = rt_frame_make(ns);
    soak_vec3 wl = soak_v3_norm(rt_to_local(&f, wo));
    if (!(wl.z > 0)) {
        path->alive = 0;
        return;
    }
    double F = rt_fresnel(wl.z, fm->ch[0].n, NULL), D = 0;
    for (int ch = 0; ch < 3; ++ch) {
        double A = 0;
        if (soak_film_ctx_albedo_dir(&fm->ch[ch], soak_rgb_at(albedo, ch), wl.z, &A) == SOAK_OK) D += fmax(0.0, A - F) / 3;
    }
    if (!(F + D > 0)) {
        path->alive = 0; /* black base under an index-matched film: nothing leaves */
        return;
    }
    double p_mirror = F / (F + D), p_diffuse = 1.0 - p_mirror;
    /* Next-event estimation for the diffuse part, before the lobe choice. */
    soak_vec3 p_out = soak_geometry_offset(hit->p, ng, ng);
    int nl = rt_light_count(c);
    for (int li = 0; li < nl; ++li) {
        rt_light_sample ls;
        if (!rt_light_sample_at(t, li, p_out, &ls)) continue;
        if (soak_v3_dot(ls.wi, ng) <= 0) continue;
        soak_vec3 l1 = soak_v3_norm(rt_to_local(&f, ls.wi));
        if (!(l1.z > 0)) continue;
        soak_rgb fd = film_lambert_eval(fm, albedo, l1, wl);
        if (!(rgb_max(fd) > 0)) continue;
        double mis = ls.pdf > 0 ? rt_power(ls.pdf, p_diffuse * l1.z * SOAK_INV_PI) : 1.0;
        if (!rt_visible(t, p_out, ls.wi, ls.dist)) continue;
        soak_rgb contrib = rgb_scale(rgb_mul(path->beta, rgb_mul(fd, ls.L)), l1.z * mis / (ls.pdf > 0 ? ls.pdf : 1.0));
        path->L = rgb_add(path->L, contrib);
    }
    if (rt_rand(t) < p_mirror) {
        soak_vec3 r = soak_v3(-wl.x, -wl.y, wl.z);
        path->beta = rgb_scale(path->beta, F / p_mirror);
        path->dir = rt_to_world(&f, r);
        if (soak_v3_dot(path->dir, ng) <= 0) path->dir = soak_v3_sub(path->dir, soak_v3_scale(ng, 2 * soak_v3_dot(path->dir, ng)));
        path->org = soak_geometry_offset(hit->p, ng, path->dir);
        path->prev_delta = 1;
        return;
    }
    double u1, u2;
    rt_rand2(t, &u1, &u2);
    soak_vec3 wi = soak_cosine_hemisphere(u1, u2);
    double pdf = p_diffuse * wi.z * SOAK_INV_PI;
    soak_rgb fd = film_lambert_eval(fm, albedo, wi, wl);
    if (!(pdf > 0) || !(rgb_max(fd) > 0)) {
        path->alive = 0;
        return;
    }
    path->beta = rgb_mul(path->beta, rgb_scale(fd, wi.z / pdf));
    continue_path(path, hit, ng, rt_to_world(&f, wi), pdf);
}

/* Smooth dielectric (glass, liquid): Fresnel choice between mirror
 * reflection and refraction; Beer-Lambert absorption inside is applied by
 * the path loop over each segment travelled while inside. */
static void dielectric(rt_thread *t, const soak_hit *hit, const soak_material *m, rt_path *path)
{
    soak_vec3 wo = soak_v3_scale(path->dir, -1.0);
    int entering = soak_v3_dot(wo, hit->ng) > 0;
    soak_vec3 n = entering ? hit->ng : soak_v3_scale(hit->ng, -1.0);
    double eta = entering ? m->ior : 1.0 / m->ior;
    double cos_i = soak_v3_dot(wo, n), cos_t;
    double F = rt_fresnel(cos_i, eta, &cos_t);
    if (rt_rand(t) < F) {
        path->dir = soak_v3_sub(soak_v3_scale(n, 2 * cos_i), wo);
    } else {
        path->dir = soak_v3_norm(soak_v3_add(soak_v3_scale(wo, -1.0 / eta), soak_v3_scale(n, cos_i / eta - cos_t)));
        path->beta = rgb_scale(path->beta, 1.0 / (eta * eta));
        path->eta_scale *= eta * eta; /* kept out of roulette (rt_rr_weight) */
        path->inside = entering;
        path->absorb = m->absorption;
    }
    path->org = soak_geometry_offset(hit->p, hit->ng, path->dir);
    path->prev_delta = 1;
}

void rt_surface(rt_thread *t, const soak_hit *hit, rt_path *path)
{
    const soak_scene *s = t->ctx->scene;
    const soak_object *obj = &s->objects[hit->object_id];
    const soak_material *m = &s->materials[obj->material];
    base_model b;
    memset(&b, 0, sizeof b);
    soak_rgb no_alpha = soak_rgb3(0, 0, 0);
    switch (m->type) {
    case SOAK_MAT_LAMBERT:
        b.type = SOAK_BASE_LAMBERT;
        b.albedo = m->albedo;
        opaque(t, hit, &b, 1.0, no_alpha, 0, path);
        return;
    case SOAK_MAT_CONDUCTOR:
        b.type = SOAK_BASE_GGX;
        b.eta = m->eta;
        b.k = m->k;
        b.alpha = m->alpha;
        opaque(t, hit, &b, 1.0, no_alpha, 0, path);
        return;
    case SOAK_MAT_DIELECTRIC:
        dielectric(t, hit, m, path);
        return;
    case SOAK_MAT_WET: {
        if (m->base == SOAK_BASE_MEDIUM) {
            rt_wet_medium(t, hit, obj, m, path);
            return;
        }
        double w = soak_scene_wetness(obj, hit->p, hit->u, hit->v) * m->film_coverage;
        double n2 = rt_rand(t) < w ? m->film_ior : 1.0;
        const rt_film *fm = t->ctx->films ? &t->ctx->films[obj->material] : NULL;
        if (n2 != 1.0 && fm && fm->ok) {
            film_lambert(t, hit, fm, m->albedo, path);
            return;
        }
        b.type = m->base;
        b.albedo = m->albedo;
        b.alpha = m->alpha;
        /* The base sits in the liquid: its index is relative to the film. */
        b.eta = rgb_scale(m->eta, 1.0 / n2);
        b.k = rgb_scale(m->k, 1.0 / n2);
        opaque(t, hit, &b, n2, m->film_absorption, m->film_thickness, path);
        return;
    }
    case SOAK_MAT_EMITTER:
        path->alive = 0;
        return;
    }
}
