/* Volumetric random walk; sources and conventions in soak/medium.h. */
#include "soak/medium.h"

#include <stddef.h>

#include "medium_internal.h"
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
    if (m->coeffs && !soak_in_range(m->majorant, 0.0, SOAK_SIGMA_MAX)) return SOAK_ERR_ARG;
    return soak_hg2_validate(&m->phase);
}

void soak_walk_options_default(soak_walk_options *opt)
{
    opt->roulette = 1;
    opt->roulette_threshold = 0.25;
    opt->max_events = 1000000;
    opt->weight = soak_rgb3(1, 1, 1);
    opt->on_scatter = NULL;
    opt->scatter_ctx = NULL;
    opt->on_vertex = NULL;
    opt->vertex_ctx = NULL;
    opt->guide_prob = 0.0;
    opt->guide_normal = soak_v3(0, 0, 1);
}

static int unit_vector(soak_vec3 v) { return soak_v3_is_unit(v); }

static int finite_point(soak_vec3 p) { return soak_is_finite(p.x) && soak_is_finite(p.y) && soak_is_finite(p.z); }

static int weights_ok(soak_rgb w)
{
    return soak_in_range(w.r, 0.0, 1e300) && soak_in_range(w.g, 0.0, 1e300) && soak_in_range(w.b, 0.0, 1e300);
}

static soak_status resolve_options(const soak_walk_options *opt, soak_walk_options *out)
{
    if (!opt) {
        soak_walk_options_default(out);
        return SOAK_OK;
    }
    if (!soak_in_range(opt->roulette_threshold, 1e-12, 1.0) || opt->max_events < 1) return SOAK_ERR_ARG;
    if (!weights_ok(opt->weight)) return SOAK_ERR_ARG;
    if (!soak_in_range(opt->guide_prob, 0.0, SOAK_GUIDE_PROB_MAX)) return SOAK_ERR_ARG;
    if (opt->guide_prob > 0 && !unit_vector(opt->guide_normal)) return SOAK_ERR_ARG;
    *out = *opt;
    return SOAK_OK;
}

/* Free-flight distance for extinction sigma (>= 0); INFINITY when sigma = 0.
 * 1 - u is in (0, 1], so the log is finite. */
static double free_flight(double sigma, soak_rng *rng)
{
    double u = soak_rng_uniform(rng);
    return sigma > 0.0 ? -log(1.0 - u) / sigma : INFINITY;
}

/* The same flight, also returning its transmittance exp(-sigma t) = 1 - u
 * (saves an exponential where the walk needs it). */
static double free_flight_tr(double sigma, soak_rng *rng, double *tr)
{
    double u = soak_rng_uniform(rng);
    *tr = 1.0 - u;
    return sigma > 0.0 ? -log(1.0 - u) / sigma : INFINITY;
}

/* ---- Scalar media, as RGB media with three equal channels ---------------- */

/* Coefficients of a scalar heterogeneous medium: density * majorant. */
static soak_status scalar_coeffs(const void *ctx, soak_vec3 pos, soak_medium_point *out)
{
    const soak_medium *m = ctx;
    double d = m->density(m->density_ctx, pos);
    if (!soak_in_range(d, 0.0, 1.0)) return SOAK_ERR_NUMERIC; /* delta tracking would be biased */
    double st = d * m->sigma_t, ss = st * m->albedo;
    out->sigma_s = soak_rgb3(ss, ss, ss);
    out->sigma_a = soak_rgb3(st - ss, st - ss, st - ss);
    out->phase = m->phase;
    return SOAK_OK;
}

static soak_medium_rgb scalar_as_rgb(const soak_medium *m)
{
    soak_medium_rgb r = {soak_rgb3(m->sigma_t, m->sigma_t, m->sigma_t), soak_rgb3(m->albedo, m->albedo, m->albedo),
                         m->phase, NULL, NULL, 0.0};
    if (m->density) {
        r.coeffs = scalar_coeffs;
        r.coeffs_ctx = m;
        r.majorant = m->sigma_t;
    }
    return r;
}

soak_status soak_medium_walk(const soak_medium *m, const soak_walk_options *opt_in, soak_vec3 pos,
                             soak_vec3 dir, const soak_boundary *boundary, soak_rng *rng,
                             soak_walk_result *out)
{
    if (!m || !out) return SOAK_ERR_NULL;
    soak_status st = soak_medium_validate(m);
    if (st != SOAK_OK) return st;
    soak_walk_options opt;
    if ((st = resolve_options(opt_in, &opt)) != SOAK_OK) return st;
    opt.weight = soak_rgb3(1, 1, 1);
    soak_medium_rgb rgb = scalar_as_rgb(m);
    soak_walk_result_rgb r;
    if ((st = soak_medium_walk_rgb(&rgb, &opt, pos, dir, boundary, rng, &r)) != SOAK_OK) return st;
    *out = (soak_walk_result){r.end, r.pos, r.dir, r.weight.r, r.scatters, r.events};
    return SOAK_OK;
}

soak_status soak_medium_transmittance(const soak_medium *m, soak_vec3 pos, soak_vec3 dir, double dist,
                                      soak_rng *rng, double *T)
{
    if (!m || !T) return SOAK_ERR_NULL;
    soak_status st = soak_medium_validate(m);
    if (st != SOAK_OK) return st;
    soak_medium_rgb rgb = scalar_as_rgb(m);
    soak_rgb tr;
    if ((st = soak_medium_rgb_transmittance(&rgb, pos, dir, dist, rng, &tr)) != SOAK_OK) return st;
    *T = tr.r;
    return SOAK_OK;
}

/* ---- The walk ------------------------------------------------------------- */

/* Coefficients at pos, checked against the majorant; the null-collision
 * coefficient mu - sigma_t is clamped at 0 within the tolerance. */
static soak_status point_at(const soak_medium_rgb *m, soak_vec3 pos, soak_medium_point *p, soak_rgb *sigma_n)
{
    soak_status st = m->coeffs(m->coeffs_ctx, pos, p);
    if (st != SOAK_OK) return st;
    double mu = m->majorant, tol = 1e-9 * mu;
    for (int c = 0; c < 3; ++c) {
        double ss = soak_rgb_at(p->sigma_s, c), sa = soak_rgb_at(p->sigma_a, c);
        if (!soak_in_range(ss, 0.0, SOAK_SIGMA_MAX) || !soak_in_range(sa, 0.0, SOAK_SIGMA_MAX) ||
            !(ss + sa <= mu + tol))
            return SOAK_ERR_NUMERIC;
        soak_rgb_set(sigma_n, c, fmax(0.0, mu - ss - sa));
    }
    return soak_hg2_validate(&p->phase) == SOAK_OK ? SOAK_OK : SOAK_ERR_NUMERIC;
}

static soak_medium_point homogeneous_point(const soak_medium_rgb *m)
{
    soak_medium_point p;
    for (int c = 0; c < 3; ++c) {
        double st = soak_rgb_at(m->sigma_t, c), ss = st * soak_rgb_at(m->albedo, c);
        soak_rgb_set(&p.sigma_s, c, ss);
        soak_rgb_set(&p.sigma_a, c, st - ss);
    }
    p.phase = m->phase;
    return p;
}

/* Homogeneous free flight toward the surface (channel MIS, see
 * soak/medium.h): the distance t is sampled first, then the surface
 * distance *dmax is asked (lazily, see medium_surface_distance). On a collision
 * r->pos moves there and the weights take the collision factor sigma_s; at
 * the surface they take the transmittance. */
static soak_status fly_homogeneous(const soak_medium_rgb *m, const soak_boundary *b, soak_walk_result_rgb *r,
                                   soak_rng *rng, flight_end *end, double *dmax_out)
{
    double sig[3] = {m->sigma_t.r, m->sigma_t.g, m->sigma_t.b};
    double alb[3] = {m->albedo.r, m->albedo.g, m->albedo.b};
    double beta[3] = {r->weight.r, r->weight.g, r->weight.b};
    double t, dmax;
    soak_status st;
    if (sig[0] == sig[1] && sig[1] == sig[2]) {
        t = free_flight(sig[0], rng); /* every channel has the same density: weights 1 */
        if ((st = medium_surface_distance(b, r->pos, r->dir, t, &dmax)) != SOAK_OK) return st;
        *dmax_out = dmax;
        if (t >= dmax) {
            *end = FLIGHT_SURFACE;
            return SOAK_OK;
        }
        for (int k = 0; k < 3; ++k) beta[k] *= alb[k];
    } else {
        double sum = beta[0] + beta[1] + beta[2];
        double p[3] = {beta[0] / sum, beta[1] / sum, beta[2] / sum};
        double u = soak_rng_uniform(rng);
        int c = u < p[0] ? 0 : (u < p[0] + p[1] ? 1 : 2);
        if (p[c] == 0.0) c = p[2] > 0.0 ? 2 : (p[1] > 0.0 ? 1 : 0); /* round-off at the top of [0,1) */
        double tr_c;
        t = free_flight_tr(sig[c], rng, &tr_c);
        if ((st = medium_surface_distance(b, r->pos, r->dir, t, &dmax)) != SOAK_OK) return st;
        *dmax_out = dmax;
        if (t >= dmax) {
            if (dmax == INFINITY) {
                *end = FLIGHT_SURFACE;
                return SOAK_OK;
            }
            /* Probability of reaching the surface under the channel mixture. */
            double pr = 0.0, tr[3];
            for (int k = 0; k < 3; ++k) {
                tr[k] = exp(-sig[k] * dmax);
                pr += p[k] * tr[k];
            }
            if (!(pr > 0.0)) return SOAK_ERR_NUMERIC;
            for (int k = 0; k < 3; ++k) soak_rgb_set(&r->weight, k, beta[k] * tr[k] / pr);
            *end = FLIGHT_SURFACE;
            return SOAK_OK;
        }
        double pdf = 0.0, f[3];
        for (int k = 0; k < 3; ++k) {
            f[k] = sig[k] * (sig[k] == sig[c] ? tr_c : exp(-sig[k] * t));
            pdf += p[k] * f[k];
        }
        if (!(pdf > 0.0)) return SOAK_ERR_NUMERIC;
        for (int k = 0; k < 3; ++k) beta[k] *= alb[k] * f[k] / pdf;
    }
    r->weight = soak_rgb3(beta[0], beta[1], beta[2]);
    r->pos = soak_v3_add(r->pos, soak_v3_scale(r->dir, t));
    *end = FLIGHT_COLLISION;
    return SOAK_OK;
}

/* Spectral tracking toward a surface at dmax (see soak/medium.h); *local
 * receives the coefficients at a real collision. */
static soak_status fly_heterogeneous(const soak_medium_rgb *m, double dmax, long max_events,
                                     soak_walk_result_rgb *r, soak_rng *rng, soak_medium_point *local,
                                     flight_end *end)
{
    double mu = m->majorant, t = 0.0;
    for (;;) {
        t += free_flight(mu, rng);
        if (t >= dmax) {
            *end = FLIGHT_SURFACE;
            return SOAK_OK;
        }
        soak_vec3 x = soak_v3_add(r->pos, soak_v3_scale(r->dir, t));
        soak_rgb sn;
        soak_status st = point_at(m, x, local, &sn);
        if (st != SOAK_OK) return st;
        double mt = 0.0, mn = 0.0, bs[3], bn[3];
        for (int c = 0; c < 3; ++c) {
            double b = soak_rgb_at(r->weight, c), ss = soak_rgb_at(local->sigma_s, c);
            bs[c] = b * ss;
            bn[c] = b * soak_rgb_at(sn, c);
            mt = fmax(mt, b * (ss + soak_rgb_at(local->sigma_a, c)));
            mn = fmax(mn, bn[c]);
        }
        if (!(mt + mn > 0.0)) { /* every channel's throughput is gone */
            r->weight = soak_rgb3(0, 0, 0);
            r->pos = x;
            *end = FLIGHT_COLLISION;
            return SOAK_OK;
        }
        double P = mt / (mt + mn);
        if (soak_rng_uniform(rng) < P) {
            r->weight = soak_rgb3(bs[0] / (mu * P), bs[1] / (mu * P), bs[2] / (mu * P));
            r->pos = x;
            *end = FLIGHT_COLLISION;
            return SOAK_OK;
        }
        r->weight = soak_rgb3(bn[0] / (mu * (1 - P)), bn[1] / (mu * (1 - P)), bn[2] / (mu * (1 - P)));
        if (++r->events >= max_events) {
            r->pos = x;
            *end = FLIGHT_CAPPED; /* capped among null collisions */
            return SOAK_OK;
        }
    }
}

/* The phase function is valid here: checked with the medium, or by point_at
 * for a grid. The sampled direction comes back normalised, so round-off
 * never accumulates over long walks. */
static soak_status scatter(const soak_hg2 *phase, soak_vec3 *dir, soak_rng *rng, const soak_walk_options *opt)
{
    double u_lobe = soak_rng_uniform(rng);
    double u_cos = soak_rng_uniform(rng);
    double u_phi = soak_rng_uniform(rng);
    soak_vec3 out = soak_hg2_sample_dir_raw(phase, *dir, u_lobe, u_cos, u_phi);
    if (!unit_vector(out)) return SOAK_ERR_NUMERIC;
    if (opt->on_scatter) opt->on_scatter(opt->scatter_ctx, *dir, out);
    *dir = out;
    return SOAK_OK;
}

/* Unbiased Russian roulette on the largest channel: below the threshold t a
 * path survives with probability q = w_max/t and its weights are divided by
 * q (expected value unchanged). Returns 0 when the path is terminated. */
static int roulette(soak_rgb *weight, const soak_walk_options *opt, soak_rng *rng)
{
    double wmax = soak_rgb_max(*weight);
    if (!opt->roulette || wmax >= opt->roulette_threshold) return 1;
    double q = wmax / opt->roulette_threshold;
    if (soak_rng_uniform(rng) >= q) return 0;
    *weight = soak_rgb3(weight->r / q, weight->g / q, weight->b / q);
    return 1;
}

static soak_status finish(soak_walk_result_rgb *r, soak_walk_end end, soak_walk_result_rgb *out)
{
    r->end = end;
    if (end == SOAK_WALK_ABSORBED) r->weight = soak_rgb3(0, 0, 0);
    *out = *r;
    return SOAK_OK;
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
    if (!finite_point(pos) || !unit_vector(dir)) return SOAK_ERR_ARG;

    soak_walk_result_rgb r = {SOAK_WALK_CAPPED, pos, dir, opt.weight, 0, 0};
    soak_medium_point local = homogeneous_point(m);
    walk_guide guide;
    walk_guide_init(&guide, m, &opt);
    while (r.events < opt.max_events) { /* capped: reported, never dropped silently */
        if (!(soak_rgb_max(r.weight) > 0.0)) return finish(&r, SOAK_WALK_ABSORBED, out);
        double dmax = INFINITY;
        flight_end fe;
        if (m->coeffs) {
            if ((st = medium_surface_distance(boundary, r.pos, r.dir, INFINITY, &dmax)) != SOAK_OK) return st;
            st = fly_heterogeneous(m, dmax, opt.max_events, &r, rng, &local, &fe);
        } else if (guide.armed) {
            st = walk_guide_fly(&guide, m, boundary, &r, rng, &fe, &dmax);
        } else {
            st = fly_homogeneous(m, boundary, &r, rng, &fe, &dmax);
        }
        if (st != SOAK_OK) return st;
        if (fe == FLIGHT_CAPPED) break;
        ++r.events;
        if (fe == FLIGHT_SURFACE) {
            if (dmax == INFINITY) break; /* flies off parallel to the surface: capped */
            r.pos = soak_v3_add(r.pos, soak_v3_scale(r.dir, dmax));
            soak_boundary_event ev = boundary->interact(boundary->ctx, &r.pos, &r.dir, &r.weight, rng);
            if (!weights_ok(r.weight) || !unit_vector(r.dir) || !finite_point(r.pos)) return SOAK_ERR_NUMERIC;
            if (ev == SOAK_BOUNDARY_EXIT) return finish(&r, SOAK_WALK_EXITED, out);
            if (ev == SOAK_BOUNDARY_ABSORB || !(soak_rgb_max(r.weight) > 0.0)) return finish(&r, SOAK_WALK_ABSORBED, out);
        } else {
            if (!(soak_rgb_max(r.weight) > 0.0)) return finish(&r, SOAK_WALK_ABSORBED, out);
            if (!weights_ok(r.weight)) return SOAK_ERR_NUMERIC;
            if (opt.on_vertex && !opt.on_vertex(opt.vertex_ctx, r.pos, r.dir, r.weight, &local, rng))
                return finish(&r, SOAK_WALK_STOPPED, out);
            if (guide.prob > 0) {
                soak_vec3 d_in = r.dir;
                if ((st = walk_guide_scatter(&guide, &local.phase, &r.dir, r.weight, rng)) != SOAK_OK) return st;
                if (opt.on_scatter) opt.on_scatter(opt.scatter_ctx, d_in, r.dir);
            } else if ((st = scatter(&local.phase, &r.dir, rng, &opt)) != SOAK_OK) {
                return st;
            }
            ++r.scatters;
        }
        if (!roulette(&r.weight, &opt, rng)) return finish(&r, SOAK_WALK_ABSORBED, out);
    }
    return finish(&r, SOAK_WALK_CAPPED, out);
}

soak_status soak_medium_rgb_transmittance(const soak_medium_rgb *m, soak_vec3 pos, soak_vec3 dir, double dist,
                                          soak_rng *rng, soak_rgb *T)
{
    if (!m || !rng || !T) return SOAK_ERR_NULL;
    soak_status st = soak_medium_rgb_validate(m);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(dist, 0.0, INFINITY) || !unit_vector(dir)) return SOAK_ERR_ARG;
    if (!m->coeffs) {
        soak_rgb tr;
        for (int c = 0; c < 3; ++c) {
            double s = soak_rgb_at(m->sigma_t, c);
            soak_rgb_set(&tr, c, s > 0.0 ? exp(-s * dist) : 1.0);
        }
        *T = tr;
        return SOAK_OK;
    }
    if (m->majorant == 0.0) {
        *T = soak_rgb3(1, 1, 1);
        return SOAK_OK;
    }
    if (dist == INFINITY) return SOAK_ERR_ARG; /* ratio tracking would not terminate */
    /* Ratio tracking: Novak et al. 2018, sec. 5.1. */
    soak_rgb tr = soak_rgb3(1, 1, 1);
    double t = 0.0, mu = m->majorant;
    for (;;) {
        t += free_flight(mu, rng);
        if (t >= dist) break;
        soak_medium_point p;
        soak_rgb sn;
        if ((st = point_at(m, soak_v3_add(pos, soak_v3_scale(dir, t)), &p, &sn)) != SOAK_OK) return st;
        tr = soak_rgb3(tr.r * sn.r / mu, tr.g * sn.g / mu, tr.b * sn.b / mu);
        if (soak_rgb_max(tr) == 0.0) break;
    }
    *T = tr;
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
    return soak_cosine_hemisphere(u1, u2);
}

static soak_boundary_event slab_interact(const void *ctx, soak_vec3 *pos, soak_vec3 *dir, soak_rgb *weight,
                                         soak_rng *rng)
{
    const soak_slab_boundary *s = ctx;
    (void)pos;
    if (dir->z < 0.0 && s->diffuse_base) {
        double a = s->base_albedo;
        *weight = soak_rgb3(weight->r * a, weight->g * a, weight->b * a);
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
    b->within = NULL; /* the planar distance is already cheap */
    return SOAK_OK;
}
