/* Wet material over a scattering medium: [JLD99] (Jensen, Legakis, Dorsey
 * 1999) sec. 3.1-3.2 traced explicitly.
 *
 * Interfaces: air (1) | liquid film (n2) | material (n3), flat and parallel
 * (the film is thin). A path crosses them as a small Markov chain: at each
 * interface it is reflected with the exact Fresnel probability -- F12 at
 * air/film, F23^k at film/material as [JLD99] Eq. 2 (k is [JLD99]'s
 * exponent; k = 1 smooth) -- or transmitted, and may bounce inside the film
 * any number of times (total internal reflection included). [JLD99] Eq. 1-4
 * keep the first crossing only; following the reflected parts conserves
 * energy (white furnace test). Throughput factors for radiance: 1/n^2 into
 * a denser medium, n^2 back out (corrected Eq. 1/2, see soak/jensen.h), so a
 * path entering and leaving carries (n1/n3)^2 (1-F12)(1-F23^k) ... (n3/n1)^2
 * exactly as Eq. 4 and its reverse. Where the object is dry (probability
 * 1 - coverage * wetness at the crossing) there is no film (n2 = 1): the
 * air/material interface reflects F13^k. We read k as a property of the
 * material's own surface (its roughness, which the liquid does not change),
 * so it applies to the dry interface too; with k > 1 the dry surface has a
 * weak specular lobe and the wet one gains the liquid's smooth reflection
 * ([JLD99] sec. 4.2: "more specular due to the smoother air-water
 * interface"). The reflected share is traced as a mirror reflection.
 *
 * Inside: the random walk of soak/medium.h (soak_medium_walk_rgb), the same
 * one `soak measure` validates: per-channel free flights with one-sample MIS
 * over the channels for a homogeneous medium, spectral tracking (Kutz, Habel,
 * Li, Novak, SIGGRAPH 2017, sec. 5.2) against the majorant for a grid.
 * Absorption is carried in the weights, never by killing paths; Russian
 * roulette on max_c beta_c below 1/2 (survival 2 max beta) keeps the
 * estimate unbiased at albedo 1, where it never fires (long walks are capped
 * at RT_MEDIUM_MAX_EVENTS and counted). The boundary of the walk is the
 * object's surface (soak_geometry_intersect_local: closed form for an
 * isolated sphere, a walk over the faces of an isolated convex mesh, the
 * scene's BVH otherwise), and a path arriving at it
 * crosses the layer stack upward (rt_cross_stack), reflected back in or
 * leaving.
 *
 * Next-event estimation inside the medium ([JLD99] sec. 3.1: "for the shadow
 * rays ... we use Equation 4"): for each delta light (sun, point) the light
 * direction wl in air is refracted through the flat film at the surface
 * normal (of the face last crossed, or the opposite one for a light behind
 * it: a sheet lit from behind) into the material (n2 cancels for parallel layers), the exit point
 * is found by tracing that direction, and the estimate is
 *   beta / n3^2 * p(d_in . d3) * T_medium(x -> y) * T_film(cos1) * (cos1 / cos3) * E
 * (1/n3^2: the entry radiance factor, kept out of beta, see rt_cross_stack) where T_film = (1-F12)(1-F23^k) (soak_jensen_shadow, averaged over film /
 * no film with the local coverage) and cos1/cos3 is the change of beam
 * cross-section on refraction (a delta light of irradiance E in air becomes
 * a delta beam of irradiance E T cos1/cos3 in the material). Exact for a
 * planar face; on curved faces the normal of the exit point is used (one
 * refinement), the flat-film approximation of the seed. Area and
 * environment lights are gathered by paths that leave the surface (counted
 * in full: no light sample competes for them from inside). Light that
 * bounces inside the film before entering is reached only by those escaping
 * paths, so for delta lights it is missing; it is second order in the
 * Fresnel reflectances: for water on n3 = 1.5, 7e-5 of the transmitted light
 * at normal incidence, 3e-4 at 60 degrees, 2.4e-3 at 80 degrees. */
#include "render_medium.h"
#include "render_lights.h"
#include "render_stack.h"
#include "render_photon_map.h"
#include "soak/fresnel.h"
#include "soak/hg.h"
#include "soak/jensen.h"
#include "soak/medium.h"

static double lerp(double a, double b, double t) { return a + (b - a) * t; }

/* Medium parameters at a point: the grid's, trilinear between cell centres
 * (clamped at the box's faces), inside its box; the homogeneous values
 * elsewhere or without a grid. */
static void medium_at(const soak_scene_medium *m, soak_vec3 x, soak_medium_point *out)
{
    out->sigma_s = m->sigma_s;
    out->sigma_a = m->sigma_a;
    out->phase = m->phase;
    const soak_volume *v = m->volume;
    if (!v) return;
    double q[3] = {x.x - m->volume_origin.x, x.y - m->volume_origin.y, x.z - m->volume_origin.z};
    int dims[3] = {v->nx, v->ny, v->nz};
    int i0[3], i1[3];
    double fr[3];
    for (int a = 0; a < 3; ++a) {
        if (!(q[a] >= 0 && q[a] <= v->size[a])) return; /* outside the box: homogeneous values */
        double g = q[a] / v->size[a] * dims[a] - 0.5;   /* cell-centred */
        g = fmax(0.0, fmin((double)dims[a] - 1, g));
        i0[a] = (int)floor(g);
        i1[a] = i0[a] + 1 < dims[a] ? i0[a] + 1 : i0[a];
        fr[a] = g - i0[a];
    }
    double val[SOAK_VOL_W + 1];
    for (int ch = 0; ch <= SOAK_VOL_W; ++ch) {
        const float *p = soak_volume_plane(v, ch);
        double c00 = lerp(p[soak_volume_index(v, i0[0], i0[1], i0[2])], p[soak_volume_index(v, i1[0], i0[1], i0[2])], fr[0]);
        double c10 = lerp(p[soak_volume_index(v, i0[0], i1[1], i0[2])], p[soak_volume_index(v, i1[0], i1[1], i0[2])], fr[0]);
        double c01 = lerp(p[soak_volume_index(v, i0[0], i0[1], i1[2])], p[soak_volume_index(v, i1[0], i0[1], i1[2])], fr[0]);
        double c11 = lerp(p[soak_volume_index(v, i0[0], i1[1], i1[2])], p[soak_volume_index(v, i1[0], i1[1], i1[2])], fr[0]);
        val[ch] = lerp(lerp(c00, c10, fr[1]), lerp(c01, c11, fr[1]), fr[2]);
    }
    out->sigma_s = soak_rgb3(val[SOAK_VOL_SIGMA_S_R], val[SOAK_VOL_SIGMA_S_G], val[SOAK_VOL_SIGMA_S_B]);
    out->sigma_a = soak_rgb3(val[SOAK_VOL_SIGMA_A_R], val[SOAK_VOL_SIGMA_A_G], val[SOAK_VOL_SIGMA_A_B]);
    out->phase.g1 = val[SOAK_VOL_G1];
    out->phase.g2 = val[SOAK_VOL_G2];
    out->phase.w = val[SOAK_VOL_W];
}

static soak_status grid_coeffs(const void *ctx, soak_vec3 pos, soak_medium_point *out)
{
    medium_at(ctx, pos, out);
    return SOAK_OK;
}

soak_medium_rgb rt_medium_rgb(const soak_scene_medium *m)
{
    soak_rgb st = soak_rgb_add(m->sigma_s, m->sigma_a), albedo;
    for (int c = 0; c < 3; ++c) {
        double t = soak_rgb_at(st, c);
        soak_rgb_set(&albedo, c, t > 0 ? fmin(1.0, soak_rgb_at(m->sigma_s, c) / t) : 1.0);
    }
    soak_medium_rgb r = {st, albedo, m->phase, NULL, NULL, 0.0};
    if (m->volume) {
        r.coeffs = grid_coeffs;
        r.coeffs_ctx = m;
        r.majorant = m->majorant;
    }
    return r;
}

soak_walk_options rt_walk_options(soak_rgb beta)
{
    soak_walk_options o;
    soak_walk_options_default(&o);
    /* Roulette only once the throughput is below 1/2 (survivors carry 1/2).
     * At threshold 1 every collision plays it, the analog estimator: on the
     * bench scene (albedo 0.92-0.97) the image variance was 2.1x that of 1/2
     * for 0.75x the work; 1/2 gave the best variance x work of 1, 0.7, 0.5,
     * 0.25, 0.1, 0.03 (+39 % over 1). */
    o.roulette_threshold = 0.5;
    o.max_events = RT_MEDIUM_MAX_EVENTS;
    o.weight = beta;
    return o;
}

static double film_shadow(const soak_material *m, double cover, double cos1)
{
    /* Eq. 4 flux transmittance, averaged over wet (film) and dry points. */
    double n3 = m->medium.ior, T_wet = 0, T_dry = 0;
    soak_jensen_layer dry = {1.0, 1.0, n3, m->film_k};
    if (cover < 1) soak_jensen_shadow(&dry, cos1, &T_dry);
    if (cover > 0) {
        soak_jensen_layer wet = {1.0, m->film_ior, n3, m->film_k};
        soak_jensen_shadow(&wet, cos1, &T_wet);
    }
    return cover * T_wet + (1 - cover) * T_dry;
}

typedef struct nee_ctx {
    rt_thread *t;
    const soak_material *m;
    const soak_object *obj;
    const soak_medium_rgb *med;
    const rt_med_surface *surf;
    unsigned object_id;
    rt_path *path;
    /* Distance from the vertex being estimated to the nearest surface (0:
     * unknown), and the survival cap it gives for the light at hand (see
     * clear_survival). */
    double d_clear, q_clear;
    /* Roulette scale of the light at hand (see RT_NEE_ROULETTE_T_BEHIND) and
     * the optical depth past which its survival is the floor. */
    double t_ref, floor_depth;
    /* Exit point and outward normal of the last shadow path found for light
     * li < RT_NEE_CACHE: its tangent plane predicts the next exit distance. */
    int cached[RT_NEE_CACHE];
    soak_vec3 cache_p[RT_NEE_CACHE], cache_n[RT_NEE_CACHE];
    /* Where the path entered the medium and the face's outward unit normal:
     * the plane the photon gather is clipped by (rt_photons_gather). */
    soak_vec3 entry_p, entry_n;
    /* The film transmittance last computed for light li < RT_NEE_CACHE and
     * its inputs: on a planar face under the sun every estimate has the same
     * cos1 and coverage, and film_shadow would recompute the same value. */
    int tf_known[RT_NEE_CACHE];
    double tf_cover[RT_NEE_CACHE], tf_cos1[RT_NEE_CACHE], tf_value[RT_NEE_CACHE];
    /* The walk's object is the scene's only one and convex (box, sphere):
     * a ray leaving its surface outward meets nothing, so shadow rays from
     * exit points are certain to see the light. */
    int lone_convex;
} nee_ctx;

/* Distance along d from x to the plane through p with normal n (pointing
 * away from x), INFINITY when d does not go toward it. For a convex object and
 * a tangent plane this bounds the distance to the surface from above. */
static double plane_distance(soak_vec3 x, soak_vec3 d, soak_vec3 p, soak_vec3 n)
{
    double den = soak_v3_dot(d, n);
    if (!(den > 1e-9)) return INFINITY;
    return rt_max(0.0, soak_v3_dot(soak_v3_sub(p, x), n)) / den;
}

/* Survival probability of the roulette on a shadow estimate whose medium
 * transmittance is about T. */
static double nee_survival(const nee_ctx *c, double T) { return rt_min(1.0, rt_max(RT_NEE_SURVIVAL_MIN, T / c->t_ref)); }

/* nee_survival of the largest channel transmittance over distance d; the
 * exponential is skipped where the survival is the floor whatever it gives
 * (the optical depth is then above -log(RT_NEE_SURVIVAL_MIN t_ref)). */
static double depth_survival(const nee_ctx *c, double d)
{
    soak_rgb sigma_t = c->med->sigma_t;
    double tau = rt_min(sigma_t.r, rt_min(sigma_t.g, sigma_t.b)) * d;
    if (tau > c->floor_depth) return RT_NEE_SURVIVAL_MIN;
    return nee_survival(c, exp(-tau));
}

/* Roulette scale for a light in front of (behind = 0) or behind the face the
 * path last crossed. */
static void set_roulette_scale(nee_ctx *c, int behind)
{
    c->t_ref = behind ? RT_NEE_ROULETTE_T_BEHIND : RT_NEE_ROULETTE_T;
    c->floor_depth = behind ? RT_NEE_FLOOR_DEPTH_BEHIND : RT_NEE_FLOOR_DEPTH;
}

/* Roulette on the shadow estimate with survival q: 0 when it dies, else
 * *inv_q is divided by q (when q < 1). */
static int nee_roulette(rt_thread *t, double q, double *inv_q)
{
    if (q < 1.0) {
        if (rt_rand(t) >= q) return 0;
        *inv_q /= q;
    }
    return 1;
}

/* Stage 1 of the roulette (see RT_NEE_ROULETTE_T), before any ray: survival
 * for the exit distance predicted by the tangent planes of the surface point
 * the walk is heading for and of light li's last exit point; 1 without one. */
static double predicted_survival(const nee_ctx *c, int li, soak_vec3 x, soak_vec3 d3)
{
    /* surf->hit is the surface the flight was heading for when the walk
     * asked for it, else the last one it found (med_within spared the
     * query): a tangent plane either way, ng outward (med_distance orients
     * it; the entry hit's is outward). */
    const soak_hit *wh = &c->surf->hit;
    double sd = c->surf->lost ? INFINITY : plane_distance(x, d3, wh->p, wh->ng);
    if (li < RT_NEE_CACHE && c->cached[li]) sd = rt_min(sd, plane_distance(x, d3, c->cache_p[li], c->cache_n[li]));
    if (!(sd < INFINITY)) return 1.0;
    return rt_max(RT_NEE_PREDICT_MIN, depth_survival(c, sd));
}

/* Survival of the roulette for the transmittance allowed by the distance
 * from x to the nearest surface (soak_geometry_clear_distance, asked once
 * per vertex; the survival is per light, with its scale): no shadow path is shorter, so the survival the exit found
 * would give (stage 2) is at most this. Capping stage 1 there keeps the
 * overall survival min(q1, q2) as it was and spares the rays of vertices deep
 * inside (on the bench sphere ~70 % of the first exit rays were cast only to
 * be ended by stage 2). 1 for a grid medium, which plays no roulette. */
static double clear_survival(const nee_ctx *c)
{
    if (c->med->coeffs) return 1.0;
    return c->d_clear > 0 ? depth_survival(c, c->d_clear) : 1.0;
}

/* Where the shadow path of a delta light leaves the medium. */
typedef struct nee_exit {
    soak_hit h;      /* exit point */
    soak_vec3 n;     /* outward normal used there */
    soak_vec3 wl;    /* toward the light, in air */
    soak_vec3 d3;    /* wl refracted into the material */
    double cos1, cos3;
    double inv_q;    /* 1 / survival probability of the roulette */
} nee_exit;

/* Refracts the light direction wl through a flat film at normal n (n2
 * cancels for parallel layers) into the material of index n3; cos1 = wl . n. */
static soak_vec3 refract_in(soak_vec3 wl, soak_vec3 n, double cos1, double n3)
{
    soak_vec3 tang = soak_v3_scale(soak_v3_sub(wl, soak_v3_scale(n, cos1)), 1.0 / n3);
    return soak_v3_norm(soak_v3_add(tang, soak_v3_scale(n, sqrt(rt_max(0.0, 1 - soak_v3_dot(tang, tang))))));
}

/* Finds the exit point of light l's shadow path from x: refract at the
 * current normal, trace, and refine once with the exit point's normal (a
 * planar face under the sun is exact at once). Returns 0 when there is none
 * or the roulette ended the estimate. */
static int find_exit(nee_ctx *c, const soak_light *l, int li, soak_vec3 x, nee_exit *e)
{
    rt_thread *t = c->t;
    const soak_scene *s = t->ctx->scene;
    double n3 = c->m->medium.ior, q1 = 1.0;
    soak_vec3 n = c->surf->n_ref, wl = l->type == SOAK_LIGHT_DIRECTIONAL ? l->direction : soak_v3_norm(soak_v3_sub(l->position, x));
    /* A light behind the face the path came in through (a thin sheet lit
     * from behind) reaches x through another face: start from the opposite
     * normal, the exit search below finds the real face. */
    int behind = !(soak_v3_dot(wl, n) > 0);
    if (behind) n = soak_v3_scale(n, -1.0);
    set_roulette_scale(c, behind);
    c->q_clear = clear_survival(c);
    e->inv_q = 1.0;
    /* The prediction cannot go below RT_NEE_PREDICT_MIN: a cap at or under it
     * decides stage 1 alone, before any direction is computed (most vertices
     * of a walk are that deep). */
    int predict = !c->med->coeffs;
    if (predict && c->q_clear <= RT_NEE_PREDICT_MIN) {
        predict = 0;
        q1 = c->q_clear;
        if (!nee_roulette(t, q1, &e->inv_q)) return 0;
    }
    for (int it = 0; it < 2; ++it) {
        double cos1 = soak_v3_dot(wl, n);
        if (!(cos1 > 0)) return 0;
        e->d3 = refract_in(wl, n, cos1, n3);
        if (it == 0 && predict) {
            q1 = rt_min(c->q_clear, predicted_survival(c, li, x, e->d3));
            if (!nee_roulette(t, q1, &e->inv_q)) return 0;
        }
        soak_ray r = {x, e->d3, 0.0, INFINITY};
        int found = 0;
        t->n.rays++;
        soak_status gst = soak_geometry_intersect_local(s->geometry, c->obj->object_id, &r, rt_object_uses_uv(c->obj), &e->h, &found);
        if (gst != SOAK_OK) t->n.geom_errors++;
        if (gst != SOAK_OK || !found) return 0;
        soak_vec3 ny = soak_v3_dot(e->d3, e->h.ng) >= 0 ? e->h.ng : soak_v3_scale(e->h.ng, -1.0);
        if (l->type == SOAK_LIGHT_POINT) wl = soak_v3_norm(soak_v3_sub(l->position, e->h.p));
        int same = soak_v3_dot(ny, n) > 1 - 1e-12;
        n = ny;
        if (same && l->type == SOAK_LIGHT_DIRECTIONAL) break; /* planar face: exact */
    }
    /* Stage 2, with the exit found: deep inside the light barely gets
     * through, so the rest of the estimate (the shadow ray) survives with
     * overall probability min(q1, nee_survival(T)); survivors are divided by
     * it. Played on the final exit, not the first one: the refinement can
     * move the exit from the far side of the object to next to x (a grazing
     * light near the surface), and a survival from the first distance then
     * weights a bright estimate by up to 1 / RT_NEE_SURVIVAL_MIN (fireflies:
     * one such path of 307,200 added 65 to a pixel on the bench scene). */
    if (!c->med->coeffs && !nee_roulette(t, rt_min(1.0, depth_survival(c, e->h.t) / q1), &e->inv_q))
        return 0;
    e->n = n;
    e->wl = wl;
    e->cos1 = soak_v3_dot(wl, n);
    e->cos3 = soak_v3_dot(e->d3, n);
    return e->cos1 > 0 && e->cos3 > 0;
}

/* film_shadow, reused while light li's cos1 and coverage repeat exactly
 * (same inputs, same value: the estimate is unchanged bit for bit). */
static double film_shadow_at(nee_ctx *c, int li, double cover, double cos1)
{
    if (li >= RT_NEE_CACHE) return film_shadow(c->m, cover, cos1);
    if (c->tf_known[li] && c->tf_cover[li] == cover && c->tf_cos1[li] == cos1) return c->tf_value[li];
    c->tf_known[li] = 1;
    c->tf_cover[li] = cover;
    c->tf_cos1[li] = cos1;
    c->tf_value[li] = film_shadow(c->m, cover, cos1);
    return c->tf_value[li];
}

/* Whether light l is seen from exit e: always for the lone convex object
 * (e->wl leaves it outward, cos1 > 0), and for a convex one when the ray
 * misses every other object's bounds; else by a shadow ray. */
static int exit_sees_light(const nee_ctx *c, const nee_exit *e, double dist_light)
{
    if (c->lone_convex) return 1;
    soak_vec3 org = soak_geometry_offset(e->h.p, e->n, e->wl);
    soak_ray r = {org, e->wl, 0.0, dist_light < INFINITY ? dist_light * (1 - 1e-5) : INFINITY};
    if (soak_geometry_ray_escapes(c->t->ctx->scene->geometry, c->obj->object_id, &r)) return 1;
    return rt_visible(c->t, org, e->wl, dist_light);
}

/* Beer-Lambert in the film on the light's way in, weighted by the share of
 * the film transmittance Tf that crosses a film with thickness (the wet
 * share less the pore water's, which absorbs over none). */
static soak_rgb film_absorbed(const soak_material *m, double cover, double cos1, double Tf, soak_rgb L)
{
    double n3 = m->medium.ior;
    double cos2 = sqrt(fmax(0.0, 1 - (1 - cos1 * cos1) / (m->film_ior * m->film_ior)));
    soak_jensen_layer wet = {1.0, m->film_ior, n3, m->film_k};
    double Tw = 0;
    soak_jensen_shadow(&wet, cos1, &Tw);
    double share = cover * Tw / Tf * (1.0 - m->film_pore_share);
    soak_rgb a = rgb_exp(m->film_absorption, m->film_thickness / cos2);
    return soak_rgb3(L.r * (1 - share + share * a.r), L.g * (1 - share + share * a.g), L.b * (1 - share + share * a.b));
}

/* Adds the estimate of light l at x through the exit e (see the top of this
 * file) to the path's radiance, unless the light is blocked or nothing gets
 * through. */
static void add_delta_light(nee_ctx *c, const soak_light *l, int li, soak_vec3 x, soak_vec3 d_in, soak_rgb beta,
                            const soak_medium_point *local, const nee_exit *e)
{
    rt_thread *t = c->t;
    const soak_material *m = c->m;
    double n3 = m->medium.ior, dist_light = INFINITY;
    soak_rgb E = l->value;
    if (l->type == SOAK_LIGHT_POINT) {
        soak_vec3 dl = soak_v3_sub(l->position, e->h.p);
        double r2 = soak_v3_dot(dl, dl);
        if (!(r2 > 0)) return;
        dist_light = sqrt(r2);
        E = soak_rgb_scale(E, 1.0 / r2);
    }
    double cover = soak_scene_wetness(c->obj, e->h.p, e->h.u, e->h.v) * m->film_coverage;
    double Tf = film_shadow_at(c, li, cover, e->cos1);
    if (!(Tf > 0)) return;
    double ph = rt_hg2(&local->phase, soak_v3_dot(d_in, e->d3));
    soak_rgb Tm;
    if (!c->med->coeffs)
        Tm = rgb_exp(c->med->sigma_t, e->h.t); /* homogeneous: exact, the medium was checked by the walk */
    else if (soak_medium_rgb_transmittance(c->med, x, e->d3, e->h.t, &t->rng, &Tm) != SOAK_OK)
        return;
    if (!(rgb_max(Tm) > 0)) return;
    if (!exit_sees_light(c, e, dist_light)) return;
    soak_rgb L = soak_rgb_mul(soak_rgb_mul(beta, Tm), E);
    /* 1/n3^2: the radiance factor of entering, left out of beta (rt_cross_stack). */
    L = soak_rgb_scale(L, e->inv_q * ph * Tf * e->cos1 / (e->cos3 * n3 * n3 * c->path->eta_scale)); /* walk weights: see rt_wet_medium */
    if (cover > 0 && m->film_thickness > 0) L = film_absorbed(m, cover, e->cos1, Tf, L);
    c->path->L = soak_rgb_add(c->path->L, L);
}

/* Caustic in-scattering from the photon map: sigma_s L_s / sigma_s, times
 * 1/n3^2. The gather is clipped by the entry face's plane, x's depth below it. */
static soak_rgb caustic_light(const nee_ctx *c, soak_vec3 x, soak_vec3 d_in, soak_rgb beta, const soak_medium_point *local)
{
    double n3 = c->m->medium.ior;
    double depth = soak_v3_dot(soak_v3_sub(c->entry_p, x), c->entry_n);
    soak_rgb g = rt_photons_gather(c->t->ctx->caustics, x, d_in, &local->phase, c->object_id, depth);
    soak_rgb ss = local->sigma_s;
    soak_rgb ls = soak_rgb3(ss.r > 0 ? g.r / ss.r : 0, ss.g > 0 ? g.g / ss.g : 0, ss.b > 0 ? g.b / ss.b : 0);
    return soak_rgb_scale(soak_rgb_mul(beta, ls), 1.0 / (n3 * n3 * c->path->eta_scale));
}

/* Vertex hook of the walk: delta lights by next-event estimation (see the
 * top of this file) and the caustic photon map, both times 1/n3^2. */
static int medium_vertex(void *ctx, soak_vec3 x, soak_vec3 d_in, soak_rgb beta, const soak_medium_point *local,
                         soak_rng *rng)
{
    (void)rng; /* the thread's generator: rt_rand draws from the same stream */
    nee_ctx *c = ctx;
    const soak_scene *s = c->t->ctx->scene;
    c->d_clear = c->med->coeffs ? 0.0 : soak_geometry_clear_distance(s->geometry, c->obj->object_id, x);
    for (int li = 0; li < s->n_lights; ++li) {
        const soak_light *l = &s->lights[li];
        if (l->type != SOAK_LIGHT_DIRECTIONAL && l->type != SOAK_LIGHT_POINT) continue;
        nee_exit e;
        if (!find_exit(c, l, li, x, &e)) continue;
        if (li < RT_NEE_CACHE) {
            c->cached[li] = 1;
            c->cache_p[li] = e.h.p;
            c->cache_n[li] = e.n;
        }
        add_delta_light(c, l, li, x, d_in, beta, local, &e);
    }
    if (c->t->ctx->caustics) c->path->L = soak_rgb_add(c->path->L, caustic_light(c, x, d_in, beta, local));
    return 1;
}

static double med_distance(const void *ctx, soak_vec3 pos, soak_vec3 dir)
{
    const rt_med_boundary *b = ctx;
    soak_ray r = {pos, dir, 0.0, INFINITY};
    int found = 0;
    b->t->n.rays++;
    soak_hit *h = &b->surf->hit;
    soak_status st =
        soak_geometry_intersect_local(b->t->ctx->scene->geometry, b->obj->object_id, &r, rt_object_uses_uv(b->obj), h, &found);
    if (st != SOAK_OK) b->t->n.geom_errors++;
    b->surf->lost = st != SOAK_OK || !found;
    if (b->surf->lost) return 0.0; /* interact ends the walk at once */
    if (soak_v3_dot(dir, h->ng) < 0) h->ng = soak_v3_scale(h->ng, -1.0); /* outward: the ray leaves the medium */
    return h->t;
}

/* Occlusion ray up to dist, lengthened by a margin above Embree's float
 * error (the scale of soak_geometry_offset), so that 0 means the surface is
 * certainly beyond dist; a failed query answers 1 (ask the full distance). */
static int med_within(const void *ctx, soak_vec3 pos, soak_vec3 dir, double dist)
{
    const rt_med_boundary *b = ctx;
    double m = rt_max(rt_max(fabs(pos.x), fabs(pos.y)), fabs(pos.z));
    soak_ray r = {pos, dir, 0.0, dist * (1.0 + 1e-5) + 1e-5 * (1.0 + m)};
    int occluded = 1;
    b->t->n.rays++;
    if (soak_geometry_occluded_local(b->t->ctx->scene->geometry, b->obj->object_id, &r, &occluded) != SOAK_OK) {
        b->t->n.geom_errors++;
        return 1;
    }
    return occluded;
}

static soak_boundary_event med_interact(const void *ctx, soak_vec3 *pos, soak_vec3 *dir, soak_rgb *weight,
                                        soak_rng *rng)
{
    (void)rng; /* rt_rand draws from the same stream */
    const rt_med_boundary *b = ctx;
    if (b->surf->lost) return SOAK_BOUNDARY_ABSORB;
    const soak_hit *h = &b->surf->hit;
    double n3 = b->m->medium.ior;
    soak_vec3 ny = soak_v3_dot(*dir, h->ng) >= 0 ? h->ng : soak_v3_scale(h->ng, -1.0);
    double cos3 = soak_v3_dot(*dir, ny);
    soak_vec3 tg = soak_v3_sub(*dir, soak_v3_scale(ny, cos3));
    double tl = soak_v3_len(tg), pp = n3 * tl;
    soak_vec3 td = tl > 1e-12 ? soak_v3_scale(tg, 1.0 / tl) : soak_v3(0, 0, 0);
    rt_stack up = *b->stack;
    up.n2 = rt_rand(b->t) < soak_scene_wetness(b->obj, h->p, h->u, h->v) * b->m->film_coverage ? b->m->film_ior : 1.0;
    b->surf->n_ref = ny;
    if (rt_cross_stack(b->t, &up, pp, 1, weight)) {
        *dir = rt_snell_dir(td, ny, pp, n3, 0);
        *pos = soak_geometry_offset(h->p, ny, *dir);
        return SOAK_BOUNDARY_REFLECT;
    }
    *dir = rt_snell_dir(td, ny, pp, 1.0, 1);
    *pos = h->p;
    return SOAK_BOUNDARY_EXIT;
}

soak_boundary rt_med_boundary_make(const rt_med_boundary *b)
{
    soak_boundary out = {med_distance, med_interact, b, med_within};
    return out;
}

void rt_wet_medium(rt_thread *t, const soak_hit *hit, const soak_object *obj, const soak_material *m, rt_path *path)
{
    soak_vec3 wo = soak_v3_scale(path->dir, -1.0);
    soak_vec3 n_out = hit->ng;
    if (!(soak_v3_dot(wo, n_out) > 0)) {
        path->alive = 0; /* reached the inside of a medium object from air: open or overlapping geometry */
        t->n.leaked++;
        return;
    }
    double wet = soak_scene_wetness(obj, hit->p, hit->u, hit->v);
    const soak_scene_medium *med = (!m->has_dry || rt_rand(t) < wet) ? &m->medium : &m->dry_medium;
    double n3 = m->medium.ior;
    rt_stack st = rt_wet_stack(t, m, wet);
    double cos1 = soak_v3_dot(wo, n_out);
    soak_vec3 tang = soak_v3_sub(path->dir, soak_v3_scale(n_out, -cos1));
    double p = soak_v3_len(tang);
    soak_vec3 tdir = p > 1e-12 ? soak_v3_scale(tang, 1.0 / p) : soak_v3(0, 0, 0);
    if (!rt_cross_stack(t, &st, p, 0, &path->beta)) {
        path->dir = rt_snell_dir(tdir, n_out, p, 1.0, 1);
        path->org = soak_geometry_offset(hit->p, n_out, path->dir);
        path->prev_delta = 1;
        return;
    }
    soak_vec3 d = rt_snell_dir(tdir, n_out, p, n3, 0);
    soak_medium_rgb mr = rt_medium_rgb(med);
    rt_med_surface surf = {*hit, 0, n_out};
    rt_med_boundary bd = {t, &surf, obj, m, &st};
    soak_boundary boundary = rt_med_boundary_make(&bd);
    nee_ctx nc;
    memset(&nc, 0, sizeof nc);
    nc.t = t;
    nc.m = m;
    nc.obj = obj;
    nc.med = &mr;
    nc.surf = &surf;
    nc.object_id = hit->object_id;
    nc.path = path;
    nc.entry_p = hit->p;
    nc.entry_n = soak_v3_norm(n_out);
    const soak_scene *sc = t->ctx->scene;
    nc.lone_convex = sc->n_objects == 1 && (obj->shape == SOAK_SHAPE_BOX || obj->shape == SOAK_SHAPE_SPHERE);
    /* The walk's roulette plays on its weight: start it at beta * eta_scale
     * (rt_rr_weight's convention) and undo the scale on what it returns. */
    soak_walk_options opt = rt_walk_options(soak_rgb_scale(path->beta, path->eta_scale));
    opt.on_vertex = medium_vertex;
    opt.vertex_ctx = &nc;
    /* Guide the walk toward the entry face (as Cycles' random walk guides
     * toward its entry point's normal): most light that leaves does so near
     * where it came in, and every vertex's sun estimate is brightest there. */
    opt.guide_prob = t->ctx->scene->walk_guide;
    opt.guide_normal = soak_v3_norm(n_out);
    soak_walk_result_rgb w;
    soak_status status =
        soak_medium_walk_rgb(&mr, &opt, soak_geometry_offset(hit->p, n_out, d), d, &boundary, &t->rng, &w);
    path->alive = 0;
    /* A numeric failure inside the walk loses the path like open geometry does. */
    if (status != SOAK_OK || surf.lost) {
        t->n.leaked++;
        return;
    }
    if (w.end == SOAK_WALK_CAPPED) t->n.capped++;
    if (w.end != SOAK_WALK_EXITED) return;
    path->alive = 1;
    path->beta = soak_rgb_scale(w.weight, 1.0 / path->eta_scale);
    path->dir = w.dir;
    path->org = soak_geometry_offset(surf.hit.p, surf.n_ref, w.dir);
    path->prev_delta = 1;
}
