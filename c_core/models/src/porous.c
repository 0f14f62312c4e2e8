/* Merillou porous BRDF post-process and Hnat's wet extension on Blinn-Phong.
 * Formulas, sources and corrections to the sources: soak/porous.h. */
#include "soak/porous.h"
#include "porous_internal.h"

#include <math.h>
#include <stddef.h>

#include "model_dirs.h"

/* ---- building blocks ---- */

/* Schlick 1994: k = sqrt(2 m^2 / pi) = m sqrt(2/pi) (see porous.h for why not
 * [Hnat06]'s 2 m^2 / pi). G1(0) = 0 also for k = 0 (m = 0). */
static double schlick_g1(double k, double c)
{
    if (!(c > 0.0)) return 0.0;
    return c / (c + k * (1.0 - c)); /* = c / (c (1-k) + k); the denominator is >= c, so G1 <= 1 after rounding */
}

static double gp_raw(double m, double cos_i, double cos_o)
{
    double k = m * sqrt(2.0 / SOAK_PI);
    return schlick_g1(k, cos_i) * schlick_g1(k, cos_o);
}

soak_status soak_porous_Gp(double m, double cos_i, double cos_o, double *Gp)
{
    if (!Gp) return SOAK_ERR_NULL;
    if (!soak_in_range(m, 0.0, SOAK_POROUS_M_MAX) || !soak_in_range(cos_i, 0.0, 1.0) ||
        !soak_in_range(cos_o, 0.0, 1.0))
        return SOAK_ERR_ARG;
    *Gp = gp_raw(m, cos_i, cos_o);
    return SOAK_OK;
}

/* [Hnat06] sec. 3.1 with the square restored ([Lag13] has it) and the mean
 * of the two polar angles ([Lag13]'s code multiplies them: typo). Clamp at
 * 0: see porous.h. */
double soak_porous_nb_raw(double sp, double theta_i, double theta_o)
{
    double d = 0.5 * (theta_i + theta_o) - 2.0 * SOAK_PI / (sp + 6.0);
    double nb = sp * (3.7 - 2.0 * d * d);
    return nb > 0.0 ? nb : 0.0;
}

soak_status soak_porous_nb(double sp, double theta_i, double theta_o, double *nb)
{
    if (!nb) return SOAK_ERR_NULL;
    if (!soak_in_range(sp, 0.0, SOAK_POROUS_SP_MAX) || !soak_in_range(theta_i, 0.0, 0.5 * SOAK_PI) ||
        !soak_in_range(theta_o, 0.0, 0.5 * SOAK_PI))
        return SOAK_ERR_ARG;
    *nb = soak_porous_nb_raw(sp, theta_i, theta_o);
    return SOAK_OK;
}

/* Geometric sum k_a sum_{j<n_b} (1-k_a)^j = 1 - (1-k_a)^n_b, written with
 * expm1/log1p so that k_a down to the smallest doubles keeps full relative
 * precision. k_a = 1 would give 0 * -inf for n_b = 0: handled first. */
double soak_porous_Ap_raw(double ka, double nb)
{
    if (nb == 0.0 || ka == 0.0) return 0.0;
    if (ka == 1.0) return 1.0;
    return -expm1(nb * log1p(-ka));
}

double soak_porous_keep_raw(double r, double nb)
{
    if (nb == 0.0) return 1.0;
    return pow(r, nb);
}

soak_status soak_porous_Ap(double ka, double nb, double *Ap)
{
    if (!Ap) return SOAK_ERR_NULL;
    if (!soak_in_range(ka, 0.0, 1.0) || !soak_in_range(nb, 0.0, SOAK_POROUS_NB_MAX)) return SOAK_ERR_ARG;
    *Ap = soak_porous_Ap_raw(ka, nb);
    return SOAK_OK;
}

/* [Hnat06] sec. 3.3.2 table of dt, divided by t_fill. */
soak_status soak_fill_fraction(double t, double t0, double t_fill, double *frac)
{
    if (!frac) return SOAK_ERR_NULL;
    if (!soak_is_finite(t) || !soak_is_finite(t0) || !soak_in_range(t_fill, 0.0, 1.7976931348623157e308))
        return SOAK_ERR_ARG;
    double v;
    /* Zero before t0, one from t0 + t_fill on: right-continuous, so the
     * fill is complete at t0 + t_fill for every t_fill, 0 included. */
    if (t < t0) v = 0.0;
    else if (t_fill == 0.0) v = 1.0;
    else {
        /* t - t0 may overflow to +inf and the ratio may overflow: both mean full. */
        v = (t - t0) / t_fill;
        if (!(v < 1.0)) v = 1.0;
    }
    *frac = v;
    return SOAK_OK;
}

soak_status soak_wetmap_t0(double value, double *t0)
{
    if (!t0) return SOAK_ERR_NULL;
    if (!soak_in_range(value, 0.0, 1.0)) return SOAK_ERR_ARG;
    *t0 = 1.0 - value;
    return SOAK_OK;
}

void soak_porous_gauss_legendre_raw(int n, double *x, double *w)
{
    /* Newton iteration on P_n from Tricomi's initial guess; map [-1,1] -> [0,1]. */
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double z = cos(SOAK_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= n; ++k) {
                double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            double dz = p1 / dp;
            z -= dz;
            if (fabs(dz) < 1e-15) break;
        }
        double wt = 1.0 / ((1.0 - z * z) * dp * dp); /* 2/(...) halved for [0,1] */
        x[i] = 0.5 * (1.0 - z);
        x[n - 1 - i] = 0.5 * (1.0 + z);
        w[i] = w[n - 1 - i] = wt;
    }
}

/* ---- Merillou + Hnat on Blinn-Phong ---- */

soak_status soak_porous_validate(const soak_porous_params *p)
{
    if (!p) return SOAK_ERR_NULL;
    if (!soak_in_range(p->kd, 0.0, 1.0) || !soak_in_range(p->ks, 0.0, 1.0) || !(p->ks + p->kd <= 1.0) ||
        !soak_in_range(p->m, 0.0, SOAK_POROUS_M_MAX) || !soak_in_range(p->spec_power, 0.0, SOAK_POROUS_POWER_MAX) ||
        !soak_in_range(p->porosity, 0.0, 1.0) || !soak_in_range(p->sp, 0.0, SOAK_POROUS_SP_MAX) ||
        !soak_in_range(p->ks_water, 0.0, SOAK_POROUS_KS_WATER_MAX) || !soak_in_range(p->water_power, 0.0, SOAK_POROUS_POWER_MAX) ||
        (p->norm != SOAK_BLINN_NORM_ENERGY && p->norm != SOAK_BLINN_NORM_SEED001))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* [Hnat06] Eq. 2 (k_d-poro-wet) and Eq. 3 (k_s-poro-wet, split into the
 * material and water lobes). The porous diffuse part
 * k_d aG (1-A_p) + k_s aG (1-A_p) = aG (k_s+k_d)^(n_b+1) fades with (1 - fill). */
static soak_porous_coeffs coeffs_raw(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo)
{
    soak_porous_coeffs c;
    double r = p->ks + p->kd;
    c.Gp = gp_raw(p->m, wi.z, wo.z);
    c.nb = soak_porous_nb_raw(p->sp, model_theta(wi), model_theta(wo));
    c.Ap = soak_porous_Ap_raw(1.0 - r, c.nb);
    double aG = p->porosity * c.Gp;
    c.kd_wet = p->kd * (1.0 - aG) + aG * r * soak_porous_keep_raw(r, c.nb) * (1.0 - fill);
    c.ks_mat = p->ks * (1.0 - aG);
    c.ks_water = p->ks_water * aG * fill;
    return c;
}

static soak_status check_pair(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo,
                              soak_vec3 *a, soak_vec3 *b)
{
    soak_status s = soak_porous_validate(p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0) || !model_unit_ok(wi, a) || !model_unit_ok(wo, b)) return SOAK_ERR_ARG;
    return SOAK_OK;
}

soak_status soak_porous_coeffs_eval(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo,
                                    soak_porous_coeffs *c)
{
    if (!c) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    soak_status s = check_pair(p, fill, wi, wo, &a, &b);
    if (s != SOAK_OK) return s;
    if (!(a.z > 0.0 && b.z > 0.0)) {
        soak_porous_coeffs zero = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        *c = zero;
        return SOAK_OK;
    }
    *c = coeffs_raw(p, fill, a, b);
    return SOAK_OK;
}

/* Normalised Blinn-Phong lobe in cos(theta_h); see soak_blinn_norm. The
 * energy normaliser is 1 / A(n), A(n) = 8 pi (n + 2^(-n/2)) / ((n+2)(n+4))
 * the lobe's exact albedo at normal incidence (derivation in porous.h). */
static double blinn(soak_blinn_norm norm, double n, double cos_h)
{
    double scale = norm == SOAK_BLINN_NORM_SEED001 ? (n + 2.0) / (2.0 * SOAK_PI)
                                                   : (n + 2.0) * (n + 4.0) / (8.0 * SOAK_PI * (n + exp2(-0.5 * n)));
    return scale * pow(cos_h, n);
}

static double eval_raw(const soak_porous_params *p, double fill, soak_vec3 a, soak_vec3 b)
{
    if (!(a.z > 0.0 && b.z > 0.0)) return 0.0;
    soak_porous_coeffs c = coeffs_raw(p, fill, a, b);
    double cos_h = soak_v3_norm(soak_v3_add(a, b)).z;
    if (cos_h > 1.0) cos_h = 1.0;
    return c.kd_wet * SOAK_INV_PI + c.ks_mat * blinn(p->norm, p->spec_power, cos_h) +
           c.ks_water * blinn(p->norm, p->water_power, cos_h);
}

soak_status soak_porous_eval(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!f) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    soak_status s = check_pair(p, fill, wi, wo, &a, &b);
    if (s != SOAK_OK) return s;
    double v = eval_raw(p, fill, a, b);
    if (!soak_is_finite(v)) return SOAK_ERR_NUMERIC;
    *f = v;
    return SOAK_OK;
}

/* ---- sampling: one-sample mixture of a cosine lobe and two Blinn-Phong
 * half-vector lobes, pdf_h = (n+1)/(2 pi) cos^n(theta_h), picked in
 * proportion to upper bounds of their coefficients. */

static void lobe_probs(const soak_porous_params *p, double fill, double prob[3])
{
    double wd = p->kd + p->porosity * (p->ks + p->kd), ws = p->ks, ww = p->ks_water * p->porosity * fill;
    double sum = wd + ws + ww;
    if (!(sum > 0.0)) {
        wd = sum = 1.0;
        ws = ww = 0.0;
    }
    prob[0] = wd / sum;
    prob[1] = ws / sum;
    prob[2] = ww / sum;
}

static double blinn_pdf_wo(double n, soak_vec3 a, soak_vec3 b)
{
    soak_vec3 h = soak_v3_norm(soak_v3_add(a, b));
    double c = soak_v3_dot(a, h);
    if (!(c > 0.0) || !(h.z > 0.0)) return 0.0;
    return (n + 1.0) / (2.0 * SOAK_PI) * pow(h.z, n) / (4.0 * c);
}

static double pdf_raw(const soak_porous_params *p, double fill, soak_vec3 a, soak_vec3 b)
{
    if (!(a.z > 0.0 && b.z > 0.0)) return 0.0;
    double prob[3];
    lobe_probs(p, fill, prob);
    double pdf = prob[0] * b.z * SOAK_INV_PI;
    if (prob[1] > 0.0) pdf += prob[1] * blinn_pdf_wo(p->spec_power, a, b);
    if (prob[2] > 0.0) pdf += prob[2] * blinn_pdf_wo(p->water_power, a, b);
    return pdf;
}

soak_status soak_porous_pdf(const soak_porous_params *p, double fill, soak_vec3 wi, soak_vec3 wo, double *pdf)
{
    if (!pdf) return SOAK_ERR_NULL;
    soak_vec3 a, b;
    soak_status s = check_pair(p, fill, wi, wo, &a, &b);
    if (s != SOAK_OK) return s;
    double v = pdf_raw(p, fill, a, b);
    if (!soak_is_finite(v)) return SOAK_ERR_NUMERIC;
    *pdf = v;
    return SOAK_OK;
}

soak_status soak_porous_sample(const soak_porous_params *p, double fill, soak_vec3 wi, double u_lobe, double u1,
                               double u2, soak_vec3 *wo, double *f, double *pdf)
{
    if (!wo || !f || !pdf) return SOAK_ERR_NULL;
    soak_vec3 a, b = soak_v3(0.0, 0.0, 1.0);
    soak_status s = check_pair(p, fill, wi, b, &a, &b);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(u_lobe, 0.0, 1.0) || !soak_in_range(u1, 0.0, 1.0) || !soak_in_range(u2, 0.0, 1.0))
        return SOAK_ERR_ARG;
    int ok = a.z > 0.0;
    if (ok) {
        double prob[3];
        lobe_probs(p, fill, prob);
        double phi = 2.0 * SOAK_PI * u2;
        if (u_lobe < prob[0]) {
            b = soak_cosine_hemisphere(u1, u2);
            ok = b.z > 0.0;
        } else {
            double n = u_lobe < prob[0] + prob[1] ? p->spec_power : p->water_power;
            double ch = pow(u1, 1.0 / (n + 1.0)), sh = sqrt(fmax(0.0, 1.0 - ch * ch));
            soak_vec3 h = soak_v3(sh * cos(phi), sh * sin(phi), ch);
            double c = soak_v3_dot(a, h);
            b = soak_v3_norm(soak_v3_sub(soak_v3_scale(h, 2.0 * c), a));
            ok = c > 0.0 && b.z > 0.0;
        }
    }
    double fv = ok ? eval_raw(p, fill, a, b) : 0.0, pv = ok ? pdf_raw(p, fill, a, b) : 0.0;
    if (!soak_is_finite(fv)) return SOAK_ERR_NUMERIC;
    /* The half-vector Jacobian 1 / (4 wi.h) overflows when a grazing wi is
     * reflected straight back (wi.h ~ 1e-310): a zero-measure direction,
     * returned as "no sample" like one below the horizon. */
    if (!(pv > 0.0) || !soak_is_finite(pv)) fv = pv = 0.0;
    *wo = b;
    *f = fv;
    *pdf = pv;
    return SOAK_OK;
}

/* kd_wet depends on the directions only through their polar angles, so the
 * white-sky albedo (1/pi) int int (kd_wet/pi) mu_i mu_o dw_i dw_o reduces to
 * 4 int_0^1 int_0^1 kd_wet mu_i mu_o dmu_i dmu_o. 4 panels x 16 Gauss nodes
 * per axis; kd_wet is smooth except for the n_b clamp. */
#define ALB_GL 16
#define ALB_PANELS 4
static double diffuse_albedo_raw(const soak_porous_params *p, double fill)
{
    double x[ALB_GL], w[ALB_GL];
    soak_porous_gauss_legendre_raw(ALB_GL, x, w);
    enum { N = ALB_GL * ALB_PANELS };
    double mu[N], wt[N];
    for (int k = 0; k < ALB_PANELS; ++k)
        for (int i = 0; i < ALB_GL; ++i) {
            mu[k * ALB_GL + i] = (k + x[i]) / ALB_PANELS;
            wt[k * ALB_GL + i] = w[i] / ALB_PANELS;
        }
    double sum = 0.0;
    for (int i = 0; i < N; ++i) {
        soak_vec3 wi = soak_v3(sqrt(1.0 - mu[i] * mu[i]), 0.0, mu[i]);
        for (int j = 0; j < N; ++j) {
            soak_vec3 wo = soak_v3(sqrt(1.0 - mu[j] * mu[j]), 0.0, mu[j]);
            sum += wt[i] * wt[j] * mu[i] * mu[j] * coeffs_raw(p, fill, wi, wo).kd_wet;
        }
    }
    return 4.0 * sum;
}

soak_status soak_porous_albedo_factor(const soak_porous_params *p, double fill, double *diffuse_albedo,
                                      double *factor)
{
    soak_status s = soak_porous_validate(p);
    if (s != SOAK_OK) return s;
    if (!soak_in_range(fill, 0.0, 1.0)) return SOAK_ERR_ARG;
    double wet = diffuse_albedo_raw(p, fill);
    double dry = fill == 0.0 ? wet : diffuse_albedo_raw(p, 0.0);
    double fac = dry > 0.0 ? wet / dry : 1.0;
    if (!soak_is_finite(wet) || !soak_is_finite(fac)) return SOAK_ERR_NUMERIC;
    if (fac > 1.0) fac = 1.0; /* wet <= dry exactly; only rounding can exceed */
    if (diffuse_albedo) *diffuse_albedo = wet;
    if (factor) *factor = fac;
    return SOAK_OK;
}
