/* The guided walk: Dwivedi sampling toward a plane ([KdE14], soak/dwivedi.h)
 * combined with the analog walk by one-sample MIS ([Vea97] Veach 1997,
 * sec. 9.2.4, balance heuristic) over the joint density of the direction
 * leaving a scattering event and the flight distance after it.
 *
 * With p_k the channel shares (throughput / its sum, soak/medium.h), P the
 * guide probability, ph the phase function and D_k(mu) = p_dwivedi(mu) / 2 pi
 * at channel k's v0, sigma'_k = sigma_k (1 - mu / v0_k), the pdf of leaving
 * along w and colliding at distance t is
 *   pdf = (1 - P) ph(w) sum_k p_k sigma_k e^{-sigma_k t}
 *         + P sum_k p_k D_k(mu) sigma'_k e^{-sigma'_k t}
 * (reaching the surface at distance d: the same without the sigma factors,
 * t = d), and channel k's weight is multiplied by ph(w) sigma_s,k e^{-sigma_k t}
 * / pdf (ph(w) e^{-sigma_k d} / pdf at the surface). The weight is bounded
 * by albedo_k / ((1 - P) p_k) times the throughput: no fireflies from it. */
#include <math.h>

#include "medium_internal.h"
#include "soak/dwivedi.h"

void walk_guide_init(walk_guide *g, const soak_medium_rgb *m, const soak_walk_options *opt)
{
    g->prob = m->coeffs ? 0.0 : opt->guide_prob;
    g->n = opt->guide_normal;
    g->armed = 0;
    if (!(g->prob > 0)) return;
    double gm = soak_hg2_mean_cosine(&m->phase);
    for (int k = 0; k < 3; ++k) {
        double a = soak_rgb_at(m->albedo, k);
        double den = 1.0 - a * gm;
        double reduced = den > 0 ? a * (1.0 - gm) / den : 1.0; /* similarity relation, soak/dwivedi.h */
        g->v0[k] = soak_dwivedi_v0(reduced);
        g->norm[k] = soak_dwivedi_norm(g->v0[k]);
    }
}

/* Channel picked in proportion to the throughput (p holds the shares). */
static int pick_channel(soak_rgb w, double u, double p[3])
{
    double sum = w.r + w.g + w.b;
    p[0] = w.r / sum;
    p[1] = w.g / sum;
    p[2] = w.b / sum;
    int c = u < p[0] ? 0 : (u < p[0] + p[1] ? 1 : 2);
    if (p[c] == 0.0) c = p[2] > 0.0 ? 2 : (p[1] > 0.0 ? 1 : 0); /* round-off at the top of [0,1) */
    return c;
}

static soak_vec3 around(soak_vec3 n, double mu, double u_phi)
{
    double s = sqrt(fmax(0.0, (1.0 - mu) * (1.0 + mu))), sp, cp;
    soak_sincos_2pi(u_phi, &sp, &cp);
    soak_vec3 t, b;
    soak_v3_basis(n, &t, &b);
    return soak_v3_norm(soak_v3_add(soak_v3_scale(n, mu), soak_v3_add(soak_v3_scale(t, s * cp), soak_v3_scale(b, s * sp))));
}

soak_status walk_guide_scatter(walk_guide *g, const soak_hg2 *phase, soak_vec3 *dir, soak_rgb weight, soak_rng *rng)
{
    double u_s = soak_rng_uniform(rng), u1 = soak_rng_uniform(rng), u2 = soak_rng_uniform(rng);
    double u3 = soak_rng_uniform(rng);
    soak_vec3 out;
    g->guided = u_s < g->prob;
    if (g->guided) {
        double p[3];
        int c = pick_channel(weight, u1, p);
        g->channel = c;
        out = around(g->n, soak_dwivedi_sample_cos(g->v0[c], g->norm[c], u2), u3);
    } else {
        out = soak_hg2_sample_dir_raw(phase, *dir, u1, u2, u3);
    }
    if (!soak_v3_is_unit(out)) return SOAK_ERR_NUMERIC;
    double cs = soak_v3_dot(*dir, out);
    g->phase_pdf = phase->w * soak_hg_eval_raw(phase->g1, fmax(-1.0, fmin(1.0, cs))) +
                   (1.0 - phase->w) * soak_hg_eval_raw(phase->g2, fmax(-1.0, fmin(1.0, cs)));
    g->armed = 1;
    *dir = out;
    return SOAK_OK;
}

/* MIS pdf of the flight to distance t (collide = 1: a collision there;
 * 0: reaching the surface there, no sigma factor); tc[k] receives each
 * channel's transmittance exp(-sigma_k t). */
static double flight_pdf(const walk_guide *g, const double sig[3], const double p[3], double mu, double t, int collide,
                         double tc[3])
{
    double analog = 0.0, guided = 0.0;
    for (int k = 0; k < 3; ++k) {
        tc[k] = exp(-sig[k] * t);
        analog += p[k] * (collide ? sig[k] : 1.0) * tc[k];
        if (!(p[k] > 0)) continue;
        double sk = sig[k] * (1.0 - mu / g->v0[k]);
        double dk = soak_dwivedi_pdf_cos(g->v0[k], g->norm[k], mu) * (0.5 / SOAK_PI);
        guided += p[k] * dk * (collide ? sk : 1.0) * exp(-sk * t);
    }
    return (1.0 - g->prob) * g->phase_pdf * analog + g->prob * guided;
}

soak_status walk_guide_fly(walk_guide *g, const soak_medium_rgb *m, const soak_boundary *b, soak_walk_result_rgb *r,
                           soak_rng *rng, flight_end *end, double *dmax_out)
{
    g->armed = 0;
    double sig[3] = {m->sigma_t.r, m->sigma_t.g, m->sigma_t.b}, p[3];
    int c = pick_channel(r->weight, soak_rng_uniform(rng), p);
    double mu = soak_v3_dot(r->dir, g->n);
    if (g->guided) c = g->channel;
    double s = g->guided ? sig[c] * (1.0 - mu / g->v0[c]) : sig[c];
    double t = s > 0.0 ? -log(1.0 - soak_rng_uniform(rng)) / s : INFINITY, dmax;
    soak_status st = medium_surface_distance(b, r->pos, r->dir, t, &dmax);
    if (st != SOAK_OK) return st;
    *dmax_out = dmax;
    int collide = t < dmax;
    *end = collide ? FLIGHT_COLLISION : FLIGHT_SURFACE;
    if (!collide && dmax == INFINITY) return SOAK_OK; /* flies off: the walk reports it capped */
    if (!collide) t = dmax;
    double tc[3];
    double pdf = flight_pdf(g, sig, p, mu, t, collide, tc);
    if (!(pdf > 0.0)) return SOAK_ERR_NUMERIC;
    double w[3] = {r->weight.r, r->weight.g, r->weight.b};
    for (int k = 0; k < 3; ++k) {
        double f = g->phase_pdf * tc[k] * (collide ? sig[k] * soak_rgb_at(m->albedo, k) : 1.0);
        w[k] *= f / pdf;
    }
    r->weight = soak_rgb3(w[0], w[1], w[2]);
    if (collide) r->pos = soak_v3_add(r->pos, soak_v3_scale(r->dir, t));
    return SOAK_OK;
}
