/* Henyey-Greenstein phase function (Henyey & Greenstein 1941) and the
 * two-term mixture of [JLD99] Eq. 5, corrected (see soak/hg.h): lobe
 * p_g(c) = (1 - g^2) / (4 pi (1 + g^2 - 2 g c)^{3/2}). */
#include "soak/hg.h"

#include <math.h>

static int g_ok(double g) { return soak_in_range(g, -SOAK_HG_G_MAX, SOAK_HG_G_MAX); }

soak_status soak_hg2_validate(const soak_hg2 *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!g_ok(p->g1) || !g_ok(p->g2) || !soak_in_range(p->w, 0.0, 1.0)) return SOAK_ERR_ARG;
    return SOAK_OK;
}

double soak_hg_eval_raw(double g, double c)
{
    /* 1 + g^2 - 2gc written as (1-g)^2 + 2g(1-c): no cancellation near
     * c = 1, g -> 1, where the lobe peaks at (1+g)/(4 pi (1-g)^2). For g < 0
     * the mirrored form (1+g)^2 - 2g(1+c) does the same near c = -1. */
    double q = g >= 0.0 ? (1.0 - g) * (1.0 - g) + 2.0 * g * (1.0 - c) : (1.0 + g) * (1.0 + g) - 2.0 * g * (1.0 + c);
    return SOAK_INV_4PI * (1.0 - g) * (1.0 + g) / (q * sqrt(q));
}

soak_status soak_hg_eval(double g, double cos_theta, double *value)
{
    if (!value) return SOAK_ERR_NULL;
    if (!g_ok(g) || !soak_in_range(cos_theta, -1.0, 1.0)) return SOAK_ERR_ARG;
    *value = soak_hg_eval_raw(g, cos_theta);
    return SOAK_OK;
}

soak_status soak_hg2_eval(const soak_hg2 *p, double cos_theta, double *value)
{
    if (!value) return SOAK_ERR_NULL;
    soak_status st = soak_hg2_validate(p);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(cos_theta, -1.0, 1.0)) return SOAK_ERR_ARG;
    *value = p->w * soak_hg_eval_raw(p->g1, cos_theta) + (1.0 - p->w) * soak_hg_eval_raw(p->g2, cos_theta);
    return SOAK_OK;
}

/* Inverse CDF for g >= 0. The textbook form (1 + g^2 - s^2)/(2g) with
 * s = (1 - g^2)/(1 - g + 2gu) divides by g and cancels badly for g -> 0.
 * Using 1 + g - s = (1+g) 2gu / d with d = 1 - g + 2gu gives
 * cos = -1 + u (1+g)(1+g+s)/d: only sums of non-negative terms, exact at
 * g = 0 (cos = 2u - 1) and accurate near cos = -1 as g -> 1. */
static double sample_forward(double g, double u)
{
    double d = (1.0 - g) + 2.0 * g * u;
    double s = (1.0 - g) * (1.0 + g) / d;
    double c = -1.0 + u * (1.0 + g) * (1.0 + g + s) / d;
    return c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c);
}

double soak_hg_sample_cos_raw(double g, double u)
{
    /* p_g(c) = p_{-g}(-c): mirror negative g. */
    return g >= 0.0 ? sample_forward(g, u) : -sample_forward(-g, 1.0 - u);
}

soak_status soak_hg_sample_cos(double g, double u, double *cos_theta)
{
    if (!cos_theta) return SOAK_ERR_NULL;
    if (!g_ok(g) || !soak_in_range(u, 0.0, 1.0)) return SOAK_ERR_ARG;
    *cos_theta = soak_hg_sample_cos_raw(g, u);
    return SOAK_OK;
}

soak_status soak_hg2_sample(const soak_hg2 *p, soak_vec3 dir_in, double u_lobe, double u_cos, double u_phi,
                            soak_vec3 *dir_out, double *pdf)
{
    if (!dir_out || !pdf) return SOAK_ERR_NULL;
    soak_status st = soak_hg2_validate(p);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(u_lobe, 0.0, 1.0) || !soak_in_range(u_cos, 0.0, 1.0) || !soak_in_range(u_phi, 0.0, 1.0))
        return SOAK_ERR_ARG;
    double len = soak_v3_len(dir_in);
    if (!soak_in_range(len, 0.999, 1.001)) return SOAK_ERR_ARG; /* also rejects NaN components */
    dir_in = soak_v3_scale(dir_in, 1.0 / len);
    *dir_out = soak_hg2_sample_dir_raw(p, dir_in, u_lobe, u_cos, u_phi);
    double c = fmax(-1.0, fmin(1.0, soak_v3_dot(*dir_out, dir_in)));
    *pdf = p->w * soak_hg_eval_raw(p->g1, c) + (1.0 - p->w) * soak_hg_eval_raw(p->g2, c);
    return SOAK_OK;
}

soak_vec3 soak_hg2_sample_dir_raw(const soak_hg2 *p, soak_vec3 dir_in, double u_lobe, double u_cos, double u_phi)
{
    double g = u_lobe < p->w ? p->g1 : p->g2;
    double c = soak_hg_sample_cos_raw(g, u_cos);
    double s = sqrt(fmax(0.0, (1.0 - c) * (1.0 + c)));
    double sin_phi, cos_phi;
    soak_sincos_2pi(u_phi, &sin_phi, &cos_phi);
    soak_vec3 t, b;
    soak_v3_basis(dir_in, &t, &b);
    soak_vec3 d = soak_v3_add(soak_v3_add(soak_v3_scale(t, s * cos_phi), soak_v3_scale(b, s * sin_phi)),
                              soak_v3_scale(dir_in, c));
    return soak_v3_norm(d);
}

double soak_hg2_mean_cosine(const soak_hg2 *p)
{
    if (soak_hg2_validate(p) != SOAK_OK) return 0.0;
    return p->w * p->g1 + (1.0 - p->w) * p->g2;
}
