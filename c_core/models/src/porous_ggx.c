/* Energy-conserving wet porous BRDF on a GGX base. Model and its energy
 * argument: soak/porous.h (above soak_porous_ggx_params). GGX terms come from
 * soak/ggx.h; pore terms (n_b, A_p) from porous.c. */
#include "soak/porous.h"
#include "porous_internal.h"

#include <math.h>
#include <stddef.h>

#include "model_dirs.h"
#include "soak/ggx.h"

#define N_TAB SOAK_POROUS_GGX_TABLE
#define MU_MIN 1e-6 /* first table node; below it the node-0 value is used */
#define SETUP_GL 20 /* Gauss nodes per axis (and u2 panel) over the VNDF sample square */
#define ALB_GL 4     /* Gauss nodes per table segment for the white-sky albedo */

soak_status soak_porous_ggx_validate(const soak_porous_ggx_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!soak_in_range(p->albedo, 0.0, 1.0) || !soak_in_range(p->roughness, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX) ||
        !soak_in_range(p->eta, 1.0, 3.0) || !soak_in_range(p->porosity, 0.0, 1.0) ||
        !soak_in_range(p->sp, 0.0, SOAK_POROUS_SP_MAX) ||
        !soak_in_range(p->water_roughness, SOAK_GGX_ALPHA_MIN, SOAK_GGX_ALPHA_MAX) ||
        !soak_in_range(p->eta_water, 1.0, 3.0))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* Table nodes are uniform in s = cbrt((mu - MU_MIN) / (1 - MU_MIN)): they
 * crowd towards grazing, where the specular albedo of a smooth surface
 * changes on the scale of alpha (down to 1e-4), and the tabulated functions
 * are smooth in s. */
static double mu_of_s(double s)
{
    return MU_MIN + (1.0 - MU_MIN) * s * s * s;
}

static double dmu_ds(double s)
{
    return 3.0 * (1.0 - MU_MIN) * s * s;
}

static double node_mu(int j)
{
    return mu_of_s((double)j / (N_TAB - 1));
}

/* Catmull-Rom cubic in s through the node values (second-order one-sided
 * slopes at the ends), constant below MU_MIN. Linear interpolation left
 * errors up to 4e-4 in the specular albedo near grazing. */
static double interp_s(const double *tab, double s)
{
    double x = s * (N_TAB - 1);
    int j = (int)x;
    if (j >= N_TAB - 1) return tab[N_TAB - 1];
    double t = x - j;
    double m0 = j == 0 ? 0.5 * (-3.0 * tab[0] + 4.0 * tab[1] - tab[2]) : 0.5 * (tab[j + 1] - tab[j - 1]);
    double m1 = j + 2 >= N_TAB ? 0.5 * (3.0 * tab[j + 1] - 4.0 * tab[j] + tab[j - 1]) : 0.5 * (tab[j + 2] - tab[j]);
    double t2 = t * t, t3 = t2 * t;
    return (2.0 * t3 - 3.0 * t2 + 1.0) * tab[j] + (t3 - 2.0 * t2 + t) * m0 + (3.0 * t2 - 2.0 * t3) * tab[j + 1] +
           (t3 - t2) * m1;
}

static double interp(const double *tab, double mu)
{
    if (!(mu > MU_MIN)) return tab[0];
    return interp_s(tab, cbrt((mu - MU_MIN) / (1.0 - MU_MIN)));
}

/* 2 int_0^1 g(mu) mu dmu of the interpolant g. In s the integrand is a
 * polynomial of degree 8 on each segment (cubic times mu dmu/ds), so 5-point
 * Gauss per segment is exact: the diffuse normalisation matches the
 * interpolated weights to rounding. */
static double cos_avg(const double *tab)
{
    double gx[5], gw[5];
    soak_porous_gauss_legendre_raw(5, gx, gw);
    double sum = tab[0] * MU_MIN * MU_MIN * 0.5, h = 1.0 / (N_TAB - 1);
    for (int j = 0; j + 1 < N_TAB; ++j)
        for (int i = 0; i < 5; ++i) {
            double s = (j + gx[i]) * h;
            sum += h * gw[i] * interp_s(tab, s) * mu_of_s(s) * dmu_ds(s);
        }
    return 2.0 * sum;
}

/* Reflected direction for the visible normal at (u1, u2); 0 on failure. */
static int reflect_vndf(double alpha, soak_vec3 wi, double u1, double u2, soak_vec3 *wo, double *c,
                        double *pdf_h)
{
    soak_vec3 h;
    if (soak_ggx_sample_vndf(alpha, wi, u1, u2, &h, pdf_h) != SOAK_OK || !(*pdf_h > 0.0)) return 0;
    *c = soak_v3_dot(wi, h);
    *wo = soak_v3_sub(soak_v3_scale(h, 2.0 * *c), wi);
    return *c > 0.0;
}

/* Largest u1 whose reflection stays above the horizon along the row u2
 * (bisection; the set is an interval from the centre of the sample disk). */
static double horizon_cut(double alpha, soak_vec3 wi, double u2)
{
    soak_vec3 wo;
    double c, pdf;
    if (reflect_vndf(alpha, wi, 1.0, u2, &wo, &c, &pdf) && wo.z > 0.0) return 1.0;
    if (!reflect_vndf(alpha, wi, 0.0, u2, &wo, &c, &pdf) || !(wo.z > 0.0)) return 1.0;
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 32; ++it) {
        double mid = 0.5 * (lo + hi);
        if (reflect_vndf(alpha, wi, mid, u2, &wo, &c, &pdf) && wo.z > 0.0) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* Directional albedo of one GGX lobe at wi, plain and weighted by G_p, by
 * Gauss quadrature over the visible-normal sample square (Heitz 2018 warp:
 * disk radius sqrt(u1), angle 2 pi u2): the warp puts the nodes where the
 * lobe is, for any roughness. Integrand f cos_o / pdf_o. Its non-smooth
 * places are handled so that Gauss converges fast (~1e-7 at 24 nodes;
 * plain 32 x 32 Gauss was off by ~3e-4 near grazing):
 *  - each row u2 is integrated in u1 only up to the horizon cut, where the
 *    integrand drops to 0 with a kink (G2 ~ cos_o);
 *  - the disk rim (u1 = 1, where the hemisphere height sqrt(1 - u1) has an
 *    infinite slope) and the centre: u1 = cut sin^2(pi v / 2);
 *  - the warp's sqrt(1 - p1^2) is singular on the rim at angles 0 and pi,
 *    i.e. u2 = 0, 1/2, 1: two u2 panels with the same sin^2 clustering. */
static void lobe_albedo(double alpha, double eta, double alpha_gp, soak_vec3 wi, const double *x,
                        const double *w, double *e, double *e_gp)
{
    double sum = 0.0, sum_gp = 0.0;
    for (int p = 0; p < 2; ++p)
        for (int j = 0; j < SETUP_GL; ++j) {
            double sj = sin(0.5 * SOAK_PI * x[j]);
            double u2 = 0.5 * (p + sj * sj), w2 = 0.5 * w[j] * 0.5 * SOAK_PI * sin(SOAK_PI * x[j]);
            double cut = horizon_cut(alpha, wi, u2);
            for (int i = 0; i < SETUP_GL; ++i) {
                double si = sin(0.5 * SOAK_PI * x[i]);
                double u1 = cut * si * si, w1 = cut * w[i] * 0.5 * SOAK_PI * sin(SOAK_PI * x[i]);
                soak_vec3 wo;
                double c, pdf_h;
                if (!reflect_vndf(alpha, wi, u1, u2, &wo, &c, &pdf_h) || !(wo.z > 0.0)) continue;
                wo = soak_v3_norm(wo);
                double v = soak_ggx_brdf_dielectric_raw(alpha, eta, wi, wo) * wo.z * 4.0 * c / pdf_h;
                if (!soak_is_finite(v)) continue;
                sum += w1 * w2 * v;
                sum_gp += w1 * w2 * v * soak_ggx_G2_raw(alpha_gp, wi, wo);
            }
        }
    *e = sum;
    *e_gp = sum_gp;
}

soak_status soak_porous_ggx_setup(const soak_porous_ggx_params *p, soak_porous_ggx *c)
{
    if (!c) return SOAK_ERR_NULL;
    soak_status s = soak_porous_ggx_validate(p);
    if (s != SOAK_OK) return s;
    double x[SETUP_GL], w[SETUP_GL];
    soak_porous_gauss_legendre_raw(SETUP_GL, x, w);
    soak_porous_ggx out;
    out.p = *p;
    for (int j = 0; j < N_TAB; ++j) {
        double mu = node_mu(j);
        soak_vec3 wi = soak_v3(sqrt(1.0 - mu * mu), 0.0, mu);
        double unused;
        out.mu[j] = mu;
        lobe_albedo(p->roughness, p->eta, p->roughness, wi, x, w, &out.e_mat[j], &out.e_gmat[j]);
        lobe_albedo(p->water_roughness, p->eta_water, p->roughness, wi, x, w, &unused, &out.e_gwat[j]);
        if (!soak_is_finite(out.e_mat[j]) || !soak_is_finite(out.e_gmat[j]) || !soak_is_finite(out.e_gwat[j]))
            return SOAK_ERR_NUMERIC;
    }
    out.avg_mat = cos_avg(out.e_mat);
    out.avg_gmat = cos_avg(out.e_gmat);
    out.avg_gwat = cos_avg(out.e_gwat);
    out.r_wall = out.avg_mat + p->albedo * (1.0 - out.avg_mat);
    if (out.r_wall > 1.0) out.r_wall = 1.0;
    *c = out;
    return SOAK_OK;
}

/* Specular albedo E_s(mu) for this fill; linear in the three tables, so the
 * interpolation and the cosine averages commute with the combination. */
static double spec_albedo_raw(const soak_porous_ggx *c, double fill, double mu)
{
    double a = c->p.porosity;
    return interp(c->e_mat, mu) - a * interp(c->e_gmat, mu) + a * fill * interp(c->e_gwat, mu);
}

/* Diffuse weight 1 - E_s(mu), floored at 0 (never active while E_s < 1,
 * i.e. whenever the specular part alone conserves energy). */
static double weight(const soak_porous_ggx *c, double fill, double mu)
{
    double w = 1.0 - spec_albedo_raw(c, fill, mu);
    return w > 0.0 ? w : 0.0;
}

/* 1 - E_s_avg = 2 int (1 - E_s) mu dmu, exact for the interpolants. */
static double weight_avg(const soak_porous_ggx *c, double fill)
{
    double a = c->p.porosity;
    return 1.0 - (c->avg_mat - a * c->avg_gmat + a * fill * c->avg_gwat);
}

/* rho_eff of porous.h: non-porous diffuse plus the porous part, which keeps
 * r^(n_b + 1) of the light entering a pore ([Hnat06] Eq. 2 with k_s + k_d
 * replaced by the wall albedo r) and fades as the pores fill. */
static double rho_eff(const soak_porous_ggx *c, double fill, double aG, double theta_i, double theta_o)
{
    double nb = soak_porous_nb_raw(c->p.sp, theta_i, theta_o);
    return c->p.albedo * (1.0 - aG) + aG * c->r_wall * soak_porous_keep_raw(c->r_wall, nb) * (1.0 - fill);
}

static double eval_raw(const soak_porous_ggx *c, double fill, soak_vec3 a, soak_vec3 b)
{
    if (!(a.z > 0.0 && b.z > 0.0)) return 0.0;
    double aG = c->p.porosity * soak_ggx_G2_raw(c->p.roughness, a, b);
    double spec = (1.0 - aG) * soak_ggx_brdf_dielectric_raw(c->p.roughness, c->p.eta, a, b) +
                  aG * fill * soak_ggx_brdf_dielectric_raw(c->p.water_roughness, c->p.eta_water, a, b);
    double W = weight_avg(c, fill);
    double diff = 0.0;
    if (W > 0.0)
        diff = rho_eff(c, fill, aG, model_theta(a), model_theta(b)) * weight(c, fill, a.z) * weight(c, fill, b.z) /
               (SOAK_PI * W);
    return spec + diff;
}

soak_status soak_porous_ggx_eval(const soak_porous_ggx *c, double fill, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!c || !f) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    soak_status s = soak_porous_ggx_validate(&c->p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0) || !model_unit_ok(wi, &a) || !model_unit_ok(wo, &b)) return SOAK_ERR_ARG;
    double v = eval_raw(c, fill, a, b);
    if (!soak_is_finite(v)) return SOAK_ERR_NUMERIC;
    *f = v;
    return SOAK_OK;
}

/* ---- sampling: one-sample mixture of VNDF(material), VNDF(water) and a
 * cosine lobe, chosen in proportion to each term's albedo estimate at wi. */

static void lobe_probs(const soak_porous_ggx *c, double fill, double mu, double prob[3])
{
    double a = c->p.porosity;
    double pm = interp(c->e_mat, mu) - a * interp(c->e_gmat, mu);
    double pw = a * fill * interp(c->e_gwat, mu);
    double pd = weight(c, fill, mu) * fmax(c->p.albedo, a * c->r_wall);
    pm = pm > 0.0 ? pm : 0.0;
    pw = pw > 0.0 ? pw : 0.0;
    double sum = pm + pw + pd;
    if (!(sum > 0.0)) {
        pm = pw = 0.0;
        pd = sum = 1.0;
    }
    prob[0] = pm / sum;
    prob[1] = pw / sum;
    prob[2] = pd / sum;
}

static double vndf_pdf_wo(double alpha, soak_vec3 a, soak_vec3 b)
{
    soak_vec3 h = soak_ggx_half_raw(a, b);
    double c = soak_v3_dot(a, h), pdf_h;
    if (!(c > 0.0) || soak_ggx_pdf_vndf(alpha, a, h, &pdf_h) != SOAK_OK) return 0.0;
    return pdf_h / (4.0 * c);
}

static double pdf_raw(const soak_porous_ggx *c, double fill, soak_vec3 a, soak_vec3 b)
{
    if (!(a.z > 0.0 && b.z > 0.0)) return 0.0;
    double prob[3];
    lobe_probs(c, fill, a.z, prob);
    double pdf = prob[2] * b.z * SOAK_INV_PI;
    if (prob[0] > 0.0) pdf += prob[0] * vndf_pdf_wo(c->p.roughness, a, b);
    if (prob[1] > 0.0) pdf += prob[1] * vndf_pdf_wo(c->p.water_roughness, a, b);
    return pdf;
}

soak_status soak_porous_ggx_pdf(const soak_porous_ggx *c, double fill, soak_vec3 wi, soak_vec3 wo, double *pdf)
{
    if (!c || !pdf) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    soak_status s = soak_porous_ggx_validate(&c->p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0) || !model_unit_ok(wi, &a) || !model_unit_ok(wo, &b)) return SOAK_ERR_ARG;
    double v = pdf_raw(c, fill, a, b);
    if (!soak_is_finite(v)) return SOAK_ERR_NUMERIC;
    *pdf = v;
    return SOAK_OK;
}

soak_status soak_porous_ggx_sample(const soak_porous_ggx *c, double fill, soak_vec3 wi, double u_lobe, double u1,
                                   double u2, soak_vec3 *wo, double *f, double *pdf)
{
    if (!c || !wo || !f || !pdf) return SOAK_ERR_NULL;
    soak_vec3 a;
    soak_status s = soak_porous_ggx_validate(&c->p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0) || !model_unit_ok(wi, &a) || !soak_in_range(u_lobe, 0.0, 1.0) ||
        !soak_in_range(u1, 0.0, 1.0) || !soak_in_range(u2, 0.0, 1.0))
        return SOAK_ERR_ARG;
    soak_vec3 b = soak_v3(0.0, 0.0, 1.0);
    int ok = a.z > 0.0;
    if (ok) {
        double prob[3];
        lobe_probs(c, fill, a.z, prob);
        if (u_lobe < prob[0] + prob[1]) {
            double alpha = u_lobe < prob[0] ? c->p.roughness : c->p.water_roughness;
            soak_vec3 h;
            double pdf_h, ch;
            ok = soak_ggx_sample_vndf(alpha, a, u1, u2, &h, &pdf_h) == SOAK_OK;
            if (ok) {
                ch = soak_v3_dot(a, h);
                b = soak_v3_norm(soak_v3_sub(soak_v3_scale(h, 2.0 * ch), a));
                ok = ch > 0.0 && b.z > 0.0;
            }
        } else {
            b = soak_cosine_hemisphere(u1, u2);
            ok = b.z > 0.0;
        }
    }
    double fv = ok ? eval_raw(c, fill, a, b) : 0.0, pv = ok ? pdf_raw(c, fill, a, b) : 0.0;
    /* A grazing wi (z ~ 1e-300) sampled into an equally grazing wo makes the
     * GGX terms overflow (soak/ggx.h): a zero-measure pair, returned as
     * "no sample" like one below the horizon. */
    if (fv == INFINITY || pv == INFINITY) fv = pv = 0.0;
    if (!soak_is_finite(fv) || !soak_is_finite(pv)) return SOAK_ERR_NUMERIC;
    if (!(pv > 0.0)) fv = pv = 0.0;
    *wo = b;
    *f = fv;
    *pdf = pv;
    return SOAK_OK;
}

soak_status soak_porous_ggx_spec_albedo(const soak_porous_ggx *c, double fill, double cos_i, double *E)
{
    if (!c || !E) return SOAK_ERR_NULL;
    soak_status s = soak_porous_ggx_validate(&c->p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0) || !soak_in_range(cos_i, 0.0, 1.0)) return SOAK_ERR_ARG;
    double e = spec_albedo_raw(c, fill, cos_i);
    /* the cubic interpolant can undershoot 0 by ~1e-32 next to a zero node */
    *E = e < 0.0 ? 0.0 : (e > 1.0 ? 1.0 : e);
    return SOAK_OK;
}

/* (1/pi) int int D cos_i cos_o = (4 / W) int int rho_eff w(mu_i) w(mu_o)
 * mu_i mu_o dmu_i dmu_o (D and G2 depend on the polar angles only). Gauss
 * nodes in s per table segment, where the interpolant is a cubic. */
static double diffuse_albedo_raw(const soak_porous_ggx *c, double fill)
{
    double W = weight_avg(c, fill);
    if (!(W > 0.0)) return 0.0;
    double gx[ALB_GL], gw[ALB_GL];
    soak_porous_gauss_legendre_raw(ALB_GL, gx, gw);
    enum { M = N_TAB * ALB_GL };
    double mu[M], q[M], th[M];
    double h = 1.0 / (N_TAB - 1);
    for (int seg = 0; seg < N_TAB; ++seg)
        for (int i = 0; i < ALB_GL; ++i) {
            int k = seg * ALB_GL + i;
            double dmu;
            if (seg == N_TAB - 1) { /* the constant piece [0, MU_MIN] */
                mu[k] = MU_MIN * gx[i];
                dmu = MU_MIN * gw[i];
            } else {
                double s = (seg + gx[i]) * h;
                mu[k] = mu_of_s(s);
                dmu = h * gw[i] * dmu_ds(s);
            }
            q[k] = dmu * mu[k] * weight(c, fill, mu[k]);
            th[k] = acos(mu[k]);
        }
    double sum = 0.0;
    for (int i = 0; i < M; ++i) {
        soak_vec3 wi = soak_v3(sqrt(1.0 - mu[i] * mu[i]), 0.0, mu[i]);
        for (int j = 0; j < M; ++j) {
            soak_vec3 wo = soak_v3(sqrt(1.0 - mu[j] * mu[j]), 0.0, mu[j]);
            double aG = c->p.porosity * soak_ggx_G2_raw(c->p.roughness, wi, wo);
            sum += q[i] * q[j] * rho_eff(c, fill, aG, th[i], th[j]);
        }
    }
    return 4.0 * sum / W;
}

soak_status soak_porous_ggx_albedo_factor(const soak_porous_ggx *c, double fill, double *diffuse_albedo,
                                          double *factor)
{
    if (!c) return SOAK_ERR_NULL;
    soak_status s = soak_porous_ggx_validate(&c->p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0)) return SOAK_ERR_ARG;
    double wet = diffuse_albedo_raw(c, fill);
    double dry = fill == 0.0 ? wet : diffuse_albedo_raw(c, 0.0);
    double fac = dry > 0.0 ? wet / dry : 1.0;
    if (!soak_is_finite(wet) || !soak_is_finite(fac)) return SOAK_ERR_NUMERIC;
    if (diffuse_albedo) *diffuse_albedo = wet;
    if (factor) *factor = fac;
    return SOAK_OK;
}
