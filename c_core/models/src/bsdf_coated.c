/* Rough dielectric interface over a Lambertian base (soak/bsdf.h, COATED).
 *
 * The interface reflects the GGX single-scattering lobe of soak/ggx.h
 * (Walter et al. 2007, height-correlated Smith G2 of Heitz 2014) with weight
 * ks (the Merillou/Hnat specular weight, [Hnat06] Eq. 3 at G_p = 1); what it
 * does not reflect, 1 - ks E(wo), enters the base unrefracted. The base
 * sends A of it back up, cosine-distributed; there it meets the interface
 * from below, leaves with probability 1 - ks E(mu) or goes back down. The
 * light that leaves a Lambertian base at cos mu from below after one bounce
 * is A cos/pi; summing the bounces (each returning A ks E_avg of the flux)
 *   f_d = A (1 - ks E(wi)) (1 - ks E(wo)) / (pi (1 - A ks E_avg)),
 * E_avg = 2 int_0^1 E(mu) mu dmu. Its hemispherical integral over wi is
 * (1 - ks E(wo)) A (1 - ks E_avg) / (1 - A ks E_avg) <= 1 - ks E(wo), so
 * with the lobe's own ks E(wo) the albedo is <= 1 (the white furnace is 1
 * at A = 1). E and E_avg are of the same piecewise-linear interpolant, so
 * that identity holds to rounding.
 *
 * E(mu) is tabulated at set-up by visible-normal quadrature (a 16 x 16
 * stratified grid of soak_ggx_sample_vndf; the estimator F G2 / G1(wo) is
 * smooth in the grid's variables). Sampling: the lobe with probability
 * P = ks E / (ks E + D) (channel means, D the diffuse albedo), else a
 * cosine; one-sample MIS pdf P pdf_ggx + (1 - P) cos / pi. */
#include "bsdf_internal.h"
#include "soak/ggx.h"

#define COAT_GRID 16

/* E(mu) of the GGX dielectric lobe at one cosine. */
static double lobe_albedo(double alpha, double eta, double mu)
{
    double c = fmax(mu, 1e-4), s = sqrt(fmax(0.0, 1.0 - c * c));
    soak_vec3 wo = soak_v3(s, 0.0, c);
    double g1o = soak_ggx_G1_raw(alpha, wo), sum = 0.0;
    for (int i = 0; i < COAT_GRID; ++i)
        for (int j = 0; j < COAT_GRID; ++j) {
            soak_vec3 h;
            double pdf_h, u1 = (i + 0.5) / COAT_GRID, u2 = (j + 0.5) / COAT_GRID;
            if (soak_ggx_sample_vndf(alpha, wo, u1, u2, &h, &pdf_h) != SOAK_OK) continue;
            double oh = soak_v3_dot(wo, h);
            soak_vec3 wi = soak_v3_sub(soak_v3_scale(h, 2 * oh), wo);
            if (!(wi.z > 0 && oh > 0 && g1o > 0)) continue;
            sum += bsdf_fresnel(oh, eta, NULL) * soak_ggx_G2_raw(alpha, wi, wo) / g1o;
        }
    double E = sum / (COAT_GRID * COAT_GRID);
    return E > 1.0 ? 1.0 : E;
}

/* 2 int E mu dmu of the linear interpolant (Simpson, exact for it). */
static double table_average(const double *E)
{
    double h = 1.0 / (SOAK_BSDF_COAT_NODES - 1), avg = 0.0;
    for (int i = 0; i + 1 < SOAK_BSDF_COAT_NODES; ++i) {
        double a = i * h, b = a + h, m = a + 0.5 * h;
        avg += h / 3.0 * (E[i] * (a + 2 * m) + E[i + 1] * (2 * m + b));
    }
    return avg;
}

void bsdf_coated_tables(soak_bsdf *b)
{
    for (int ch = 0; ch < 3; ++ch) {
        double eta = soak_rgb_at(b->d.eta, ch);
        if (ch > 0 && eta == soak_rgb_at(b->d.eta, ch - 1)) {
            for (int i = 0; i < SOAK_BSDF_COAT_NODES; ++i) b->coat_E[ch][i] = b->coat_E[ch - 1][i];
        } else {
            for (int i = 0; i < SOAK_BSDF_COAT_NODES; ++i)
                b->coat_E[ch][i] = lobe_albedo(b->d.alpha, eta, (double)i / (SOAK_BSDF_COAT_NODES - 1));
        }
        b->coat_E_avg[ch] = table_average(b->coat_E[ch]);
    }
}

static soak_status coated_setup(soak_bsdf *b)
{
    soak_bsdf_desc *d = &b->d;
    if (!soak_in_range(d->coat_weight, 0, 1) || !(d->alpha > 0 && d->alpha <= SOAK_GGX_ALPHA_MAX)) return SOAK_ERR_ARG;
    if (d->alpha < SOAK_GGX_ALPHA_MIN) d->alpha = SOAK_GGX_ALPHA_MIN; /* documented clamp */
    for (int ch = 0; ch < 3; ++ch)
        if (!soak_in_range(soak_rgb_at(d->albedo, ch), 0, 1) || !soak_in_range(soak_rgb_at(d->eta, ch), 1.0, 3.0))
            return SOAK_ERR_ARG;
    d->k = soak_rgb3(0, 0, 0);
    b->flags = SOAK_BSDF_DIFFUSE | SOAK_BSDF_GLOSSY;
    bsdf_coated_tables(b);
    return SOAK_OK;
}

static double table_at(const double *E, double mu)
{
    double x = fmin(1.0, fmax(0.0, mu)) * (SOAK_BSDF_COAT_NODES - 1);
    int i = (int)x;
    if (i >= SOAK_BSDF_COAT_NODES - 1) return E[SOAK_BSDF_COAT_NODES - 1];
    return E[i] + (x - i) * (E[i + 1] - E[i]);
}

/* ks E(mu) per channel. */
static soak_rgb coat_reflect(const soak_bsdf *b, double mu)
{
    double ks = b->d.coat_weight;
    return soak_rgb3(ks * table_at(b->coat_E[0], mu), ks * table_at(b->coat_E[1], mu), ks * table_at(b->coat_E[2], mu));
}

/* A / (pi (1 - A ks E_avg)) per channel: the base's bounces summed. */
static double base_scale(const soak_bsdf *b, int ch)
{
    double A = soak_rgb_at(b->d.albedo, ch);
    return A * SOAK_INV_PI / (1.0 - A * b->d.coat_weight * b->coat_E_avg[ch]);
}

/* Probability of sampling the lobe for wo; -1 when nothing is reflected. */
static double lobe_probability(const soak_bsdf *b, double mu_o)
{
    soak_rgb ro = coat_reflect(b, mu_o);
    double S = 0.0, D = 0.0;
    for (int ch = 0; ch < 3; ++ch) {
        double r = soak_rgb_at(ro, ch);
        S += r;
        D += base_scale(b, ch) * SOAK_PI * (1.0 - r) * (1.0 - b->d.coat_weight * b->coat_E_avg[ch]);
    }
    return S + D > 0 ? S / (S + D) : -1.0;
}

static soak_rgb coated_f(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    soak_rgb ri = coat_reflect(b, wi.z), ro = coat_reflect(b, wo.z);
    double f[3];
    for (int ch = 0; ch < 3; ++ch) {
        double spec = b->d.coat_weight > 0 ? soak_ggx_brdf_dielectric_raw(b->d.alpha, soak_rgb_at(b->d.eta, ch), wi, wo) : 0.0;
        f[ch] = b->d.coat_weight * spec + base_scale(b, ch) * (1.0 - soak_rgb_at(ri, ch)) * (1.0 - soak_rgb_at(ro, ch));
    }
    return soak_rgb3(f[0], f[1], f[2]);
}

static double coated_pdf(const soak_bsdf *b, double P, soak_vec3 wi, soak_vec3 wo)
{
    double spec = P > 0 ? P * bsdf_ggx_reflect_pdf(b->d.alpha, wi, wo) : 0.0;
    return spec + (1.0 - P) * wi.z * SOAK_INV_PI;
}

static soak_status coated_eval(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo, soak_rgb *f, double *pdf)
{
    double P = wi.z > 0 && wo.z > 0 ? lobe_probability(b, wo.z) : -1.0;
    *f = P >= 0 ? coated_f(b, wi, wo) : soak_rgb3(0, 0, 0);
    *pdf = P >= 0 ? coated_pdf(b, P, wi, wo) : 0.0;
    return SOAK_OK;
}

static double coated_pdf_of(const soak_bsdf *b, soak_vec3 wi, soak_vec3 wo)
{
    double P = wi.z > 0 && wo.z > 0 ? lobe_probability(b, wo.z) : -1.0;
    return P >= 0 ? coated_pdf(b, P, wi, wo) : 0.0;
}

static int coated_direction(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s)
{
    double P = wo.z > 0 ? lobe_probability(b, wo.z) : -1.0, pdf_lobe;
    if (!(P >= 0)) return 0;
    if (u[0] < P) {
        if (!bsdf_ggx_reflect_sample(b->d.alpha, wo, u[1], u[2], &s->wi, &pdf_lobe)) return 0;
    } else {
        s->wi = soak_cosine_hemisphere(u[1], u[2]);
    }
    if (!(s->wi.z > 0)) return 0;
    s->pdf = coated_pdf(b, P, s->wi, wo);
    if (!(s->pdf > 0)) return 0;
    s->weight = soak_rgb_scale(coated_f(b, s->wi, wo), s->wi.z / s->pdf);
    return 1;
}

static soak_status coated_sample(const soak_bsdf *b, soak_vec3 wo, const double u[3], soak_bsdf_sample *s, int *ok)
{
    *ok = coated_direction(b, wo, u, s);
    return SOAK_OK;
}

const soak_bsdf_ops bsdf_coated_ops = {coated_setup, coated_eval, coated_pdf_of, coated_sample, NULL};
