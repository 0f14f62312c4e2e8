/* Volumetric random walk; sources and conventions in soak/medium.h. */
#include "soak/medium.h"

#include <stddef.h>

#include "soak/fresnel.h"

#define SOAK_SIGMA_MAX 1e12

soak_status soak_medium_validate(const soak_medium *m)
{
    if (!m) return SOAK_ERR_NULL;
    if (!soak_in_range(m->sigma_t, 0.0, SOAK_SIGMA_MAX) || !soak_in_range(m->albedo, 0.0, 1.0))
        return SOAK_ERR_ARG;
    return soak_hg2_validate(&m->phase);
}

soak_status soak_medium_rgb_validate(const soak_medium_rgb *m)
{
    if (!m) return SOAK_ERR_NULL;
    for (int c = 0; c < 3; ++c)
        if (!soak_in_range(soak_rgb_at(m->sigma_t, c), 0.0, SOAK_SIGMA_MAX) ||
            !soak_in_range(soak_rgb_at(m->albedo, c), 0.0, 1.0))
            return SOAK_ERR_ARG;
    return soak_hg2_validate(&m->phase);
}

void soak_walk_options_default(soak_walk_options *opt)
{
    opt->roulette = 1;
    opt->roulette_threshold = 0.25;
    opt->max_events = 1000000;
    opt->on_scatter = NULL;
    opt->scatter_ctx = NULL;
}

static soak_status resolve_options(const soak_walk_options *opt, soak_walk_options *out)
{
    if (!opt) {
        soak_walk_options_default(out);
        return SOAK_OK;
    }
    if (!soak_in_range(opt->roulette_threshold, 1e-12, 1.0) || opt->max_events < 1) return SOAK_ERR_ARG;
    *out = *opt;
    return SOAK_OK;
}

static int unit_vector(soak_vec3 v)
{
    double l2 = soak_v3_dot(v, v);
    return soak_in_range(l2, 1.0 - 1e-6, 1.0 + 1e-6);
}

/* Free-flight distance for extinction sigma (>= 0); INFINITY when sigma = 0.
 * 1 - u is in (0, 1], so the log is finite. */
static double free_flight(double sigma, soak_rng *rng)
{
    double u = soak_rng_uniform(rng);
    return sigma > 0.0 ? -log(1.0 - u) / sigma : INFINITY;
}

static soak_status scatter(const soak_hg2 *phase, soak_vec3 *dir, soak_rng *rng, const soak_walk_options *opt)
{
    double u_lobe = soak_rng_uniform(rng);
    double u_cos = soak_rng_uniform(rng);
    double u_phi = soak_rng_uniform(rng);
    soak_vec3 out;
    double pdf;
    soak_status st = soak_hg2_sample(phase, *dir, u_lobe, u_cos, u_phi, &out, &pdf);
    if (st != SOAK_OK) return st;
    /* Renormalise so that round-off never accumulates over long walks. */
    out = soak_v3_norm(out);
    if (opt->on_scatter) opt->on_scatter(opt->scatter_ctx, *dir, out);
    *dir = out;
    return SOAK_OK;
}

/* Unbiased Russian roulette: a weight w below the threshold t survives with
 * probability w/t and is then raised to t (expected value unchanged).
 * Returns 0 when the path is terminated. */
static int roulette(double *weight, const soak_walk_options *opt, soak_rng *rng)
{
    if (!opt->roulette || *weight >= opt->roulette_threshold) return 1;
    double q = *weight / opt->roulette_threshold;
    if (soak_rng_uniform(rng) >= q) return 0;
    *weight = opt->roulette_threshold;
    return 1;
}

/* Delta tracking: returns the distance to the next real collision, or a
 * value >= dmax when the path reaches the boundary first. */
static soak_status delta_track(const soak_medium *m, soak_vec3 pos, soak_vec3 dir, double dmax, soak_rng *rng,
                               long *events, long max_events, double *t_out)
{
    double t = 0.0;
    for (;;) {
        t += free_flight(m->sigma_t, rng);
        if (t >= dmax) break;
        double d = m->density(m->density_ctx, soak_v3_add(pos, soak_v3_scale(dir, t)));
        if (!soak_in_range(d, 0.0, 1.0)) return SOAK_ERR_NUMERIC;
        if (soak_rng_uniform(rng) < d) break;
        if (++*events >= max_events) {
            *t_out = -1.0; /* capped among null collisions */
            return SOAK_OK;
        }
    }
    *t_out = t;
    return SOAK_OK;
}

soak_status soak_medium_walk(const soak_medium *m, const soak_walk_options *opt_in, soak_vec3 pos,
                             soak_vec3 dir, const soak_boundary *boundary, soak_rng *rng,
                             soak_walk_result *out)
{
    if (!m || !boundary || !boundary->distance || !boundary->interact || !rng || !out) return SOAK_ERR_NULL;
    soak_status st = soak_medium_validate(m);
    if (st != SOAK_OK) return st;
    soak_walk_options opt;
    if ((st = resolve_options(opt_in, &opt)) != SOAK_OK) return st;
    if (!soak_is_finite(pos.x) || !soak_is_finite(pos.y) || !soak_is_finite(pos.z) || !unit_vector(dir))
        return SOAK_ERR_ARG;

    soak_walk_result r = {SOAK_WALK_CAPPED, pos, dir, 1.0, 0, 0};
    for (;;) {
        if (r.events >= opt.max_events) break; /* capped: reported, never dropped silently */
        double dmax = boundary->distance(boundary->ctx, r.pos, r.dir);
        if (!(dmax >= 0.0)) return SOAK_ERR_NUMERIC;
        double t;
        if (m->density) {
            if ((st = delta_track(m, r.pos, r.dir, dmax, rng, &r.events, opt.max_events, &t)) != SOAK_OK)
                return st;
            if (t < 0.0) break;
        } else {
            t = free_flight(m->sigma_t, rng);
        }
        ++r.events;
        if (t >= dmax) {
            if (dmax == INFINITY) break; /* flies off parallel to the surface: capped */
            r.pos = soak_v3_add(r.pos, soak_v3_scale(r.dir, dmax));
            soak_boundary_event ev = boundary->interact(boundary->ctx, r.pos, &r.dir, &r.weight, rng);
            if (!soak_in_range(r.weight, 0.0, 1e300) || !unit_vector(r.dir)) return SOAK_ERR_NUMERIC;
            if (ev == SOAK_BOUNDARY_EXIT) {
                r.end = SOAK_WALK_EXITED;
                *out = r;
                return SOAK_OK;
            }
            if (ev == SOAK_BOUNDARY_ABSORB || r.weight == 0.0) {
                r.end = SOAK_WALK_ABSORBED;
                r.weight = 0.0;
                *out = r;
                return SOAK_OK;
            }
        } else {
            r.pos = soak_v3_add(r.pos, soak_v3_scale(r.dir, t));
            r.weight *= m->albedo;
            if (r.weight == 0.0) {
                r.end = SOAK_WALK_ABSORBED;
                *out = r;
                return SOAK_OK;
            }
            if ((st = scatter(&m->phase, &r.dir, rng, &opt)) != SOAK_OK) return st;
            ++r.scatters;
        }
        if (!roulette(&r.weight, &opt, rng)) {
            r.end = SOAK_WALK_ABSORBED;
            r.weight = 0.0;
            *out = r;
            return SOAK_OK;
        }
    }
    r.end = SOAK_WALK_CAPPED;
    *out = r;
    return SOAK_OK;
}

soak_status soak_medium_transmittance(const soak_medium *m, soak_vec3 pos, soak_vec3 dir, double dist,
                                      soak_rng *rng, double *T)
{
    if (!m || !rng || !T) return SOAK_ERR_NULL;
    soak_status st = soak_medium_validate(m);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(dist, 0.0, INFINITY) || !unit_vector(dir)) return SOAK_ERR_ARG;
    if (!m->density) {
        *T = m->sigma_t > 0.0 ? exp(-m->sigma_t * dist) : 1.0;
        return SOAK_OK;
    }
    if (m->sigma_t == 0.0) {
        *T = 1.0;
        return SOAK_OK;
    }
    if (dist == INFINITY) return SOAK_ERR_ARG; /* ratio tracking would not terminate */
    double tr = 1.0, t = 0.0;
    for (;;) {
        t += free_flight(m->sigma_t, rng);
        if (t >= dist) break;
        double d = m->density(m->density_ctx, soak_v3_add(pos, soak_v3_scale(dir, t)));
        if (!soak_in_range(d, 0.0, 1.0)) return SOAK_ERR_NUMERIC;
        tr *= 1.0 - d;
        if (tr == 0.0) break;
    }
    *T = tr;
    return SOAK_OK;
}

/* ---- RGB -------------------------------------------------------------- */

static double rgb_max(soak_rgb c)
{
    double m = c.r > c.g ? c.r : c.g;
    return m > c.b ? m : c.b;
}

soak_status soak_medium_walk_rgb(const soak_medium_rgb *m, const soak_walk_options *opt_in, soak_vec3 pos,
                                 soak_vec3 dir, const soak_boundary *boundary, soak_rng *rng,
                                 soak_walk_result_rgb *out)
{
    if (!m || !boundary || !boundary->distance || !boundary->interact || !rng || !out) return SOAK_ERR_NULL;
    soak_status st = soak_medium_rgb_validate(m);
    if (st != SOAK_OK) return st;
    soak_walk_options opt;
    if ((st = resolve_options(opt_in, &opt)) != SOAK_OK) return st;
    if (!soak_is_finite(pos.x) || !soak_is_finite(pos.y) || !soak_is_finite(pos.z) || !unit_vector(dir))
        return SOAK_ERR_ARG;

    soak_walk_result_rgb r = {SOAK_WALK_CAPPED, pos, dir, soak_rgb3(1, 1, 1), 0, 0};
    double sig[3] = {m->sigma_t.r, m->sigma_t.g, m->sigma_t.b};
    double alb[3] = {m->albedo.r, m->albedo.g, m->albedo.b};
    while (r.events < opt.max_events) {
        double beta[3] = {r.weight.r, r.weight.g, r.weight.b};
        double sum = beta[0] + beta[1] + beta[2];
        if (!(sum > 0.0)) {
            r.end = SOAK_WALK_ABSORBED;
            r.weight = soak_rgb3(0, 0, 0);
            *out = r;
            return SOAK_OK;
        }
        double p[3] = {beta[0] / sum, beta[1] / sum, beta[2] / sum};
        double u = soak_rng_uniform(rng);
        int c = u < p[0] ? 0 : (u < p[0] + p[1] ? 1 : 2);
        if (p[c] == 0.0) c = p[2] > 0.0 ? 2 : (p[1] > 0.0 ? 1 : 0); /* round-off at the top of [0,1) */
        double dmax = boundary->distance(boundary->ctx, r.pos, r.dir);
        if (!(dmax >= 0.0)) return SOAK_ERR_NUMERIC;
        double t = free_flight(sig[c], rng);
        ++r.events;
        if (t >= dmax) {
            if (dmax == INFINITY) break;
            /* Probability of reaching the surface under the channel mixture. */
            double pr = 0.0, tr[3];
            for (int k = 0; k < 3; ++k) {
                tr[k] = exp(-sig[k] * dmax);
                pr += p[k] * tr[k];
            }
            if (!(pr > 0.0)) return SOAK_ERR_NUMERIC;
            for (int k = 0; k < 3; ++k) soak_rgb_set(&r.weight, k, beta[k] * tr[k] / pr);
            r.pos = soak_v3_add(r.pos, soak_v3_scale(r.dir, dmax));
            double w = 1.0;
            soak_boundary_event ev = boundary->interact(boundary->ctx, r.pos, &r.dir, &w, rng);
            if (!soak_in_range(w, 0.0, 1e300) || !unit_vector(r.dir)) return SOAK_ERR_NUMERIC;
            r.weight = soak_rgb3(r.weight.r * w, r.weight.g * w, r.weight.b * w);
            if (ev == SOAK_BOUNDARY_EXIT) {
                r.end = SOAK_WALK_EXITED;
                *out = r;
                return SOAK_OK;
            }
            if (ev == SOAK_BOUNDARY_ABSORB) {
                r.end = SOAK_WALK_ABSORBED;
                r.weight = soak_rgb3(0, 0, 0);
                *out = r;
                return SOAK_OK;
            }
        } else {
            double pdf = 0.0, f[3];
            for (int k = 0; k < 3; ++k) {
                f[k] = sig[k] * exp(-sig[k] * t);
                pdf += p[k] * f[k];
            }
            if (!(pdf > 0.0)) return SOAK_ERR_NUMERIC;
            for (int k = 0; k < 3; ++k) soak_rgb_set(&r.weight, k, beta[k] * alb[k] * f[k] / pdf);
            r.pos = soak_v3_add(r.pos, soak_v3_scale(r.dir, t));
            if ((st = scatter(&m->phase, &r.dir, rng, &opt)) != SOAK_OK) return st;
            ++r.scatters;
        }
        double wmax = rgb_max(r.weight);
        if (!soak_in_range(wmax, 0.0, 1e300)) return SOAK_ERR_NUMERIC;
        if (opt.roulette && wmax < opt.roulette_threshold) {
            double q = wmax / opt.roulette_threshold;
            if (soak_rng_uniform(rng) >= q) {
                r.end = SOAK_WALK_ABSORBED;
                r.weight = soak_rgb3(0, 0, 0);
                *out = r;
                return SOAK_OK;
            }
            r.weight = soak_rgb3(r.weight.r / q, r.weight.g / q, r.weight.b / q);
        }
    }
    r.end = SOAK_WALK_CAPPED;
    *out = r;
    return SOAK_OK;
}

/* ---- Planar slab boundary ---------------------------------------------- */

soak_status soak_slab_boundary_validate(const soak_slab_boundary *s)
{
    if (!s) return SOAK_ERR_NULL;
    if (!(s->thickness > 0.0) || !soak_in_range(s->ior, 1.0, 3.0) || (s->diffuse_base != 0 && s->diffuse_base != 1))
        return SOAK_ERR_ARG;
    if (s->diffuse_base && (!soak_in_range(s->base_albedo, 0.0, 1.0) || s->thickness == INFINITY))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

static double slab_distance(const void *ctx, soak_vec3 pos, soak_vec3 dir)
{
    const soak_slab_boundary *s = ctx;
    double d;
    if (dir.z > 0.0)
        d = -pos.z / dir.z;
    else if (dir.z < 0.0)
        d = s->thickness == INFINITY ? INFINITY : (pos.z + s->thickness) / -dir.z;
    else
        d = INFINITY;
    return d > 0.0 ? d : 0.0;
}

int soak_slab_refract_out(soak_vec3 dir, double ior, soak_vec3 *out)
{
    double cos_i = fabs(dir.z);
    if (ior == 1.0) {
        *out = dir;
        return 1;
    }
    /* Snell: sin_t = ior * sin_i; tangential components scale by ior. */
    double sin2_t = ior * ior * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) return 0;
    double cos_t = sqrt(1.0 - sin2_t);
    *out = soak_v3_norm(soak_v3(ior * dir.x, ior * dir.y, copysign(cos_t, dir.z)));
    return 1;
}

/* Cosine-weighted direction about +z (Malley's method). */
static soak_vec3 cosine_up(soak_rng *rng)
{
    double u1 = soak_rng_uniform(rng), u2 = soak_rng_uniform(rng);
    double r = sqrt(u1), phi = 2.0 * SOAK_PI * u2;
    double z = sqrt(1.0 - u1); /* u1 < 1, so z > 0 */
    return soak_v3(r * cos(phi), r * sin(phi), z);
}

static soak_boundary_event slab_interact(const void *ctx, soak_vec3 pos, soak_vec3 *dir, double *weight,
                                         soak_rng *rng)
{
    const soak_slab_boundary *s = ctx;
    (void)pos;
    if (dir->z < 0.0 && s->diffuse_base) {
        *weight *= s->base_albedo;
        *dir = cosine_up(rng);
        return SOAK_BOUNDARY_REFLECT;
    }
    if (s->ior == 1.0) return SOAK_BOUNDARY_EXIT;
    /* Inside to outside: eta = n_out / n_in = 1 / ior (soak/fresnel.h). */
    double R = soak_fresnel_dielectric_raw(fabs(dir->z), 1.0 / s->ior, NULL);
    soak_vec3 t;
    if (soak_rng_uniform(rng) < R || !soak_slab_refract_out(*dir, s->ior, &t)) {
        dir->z = -dir->z;
        return SOAK_BOUNDARY_REFLECT;
    }
    *dir = t;
    return SOAK_BOUNDARY_EXIT;
}

soak_status soak_slab_boundary_make(const soak_slab_boundary *s, soak_boundary *b)
{
    if (!b) return SOAK_ERR_NULL;
    soak_status st = soak_slab_boundary_validate(s);
    if (st != SOAK_OK) return st;
    b->distance = slab_distance;
    b->interact = slab_interact;
    b->ctx = s;
    return SOAK_OK;
}
