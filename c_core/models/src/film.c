/* Smooth absorbing liquid film over a Lambertian base.
 * Source: Lekner & Dorf 1988 (Appl. Opt. 27(7)), non-absorbing film;
 * Beer-Lambert absorption added here (coefficients: [Lag13], Lagarde).
 *
 * Derivation. Air above (index 1), film of index n and optical thickness
 * tau = alpha * thickness, Lambertian base of albedo A (no Fresnel term at the
 * film/base contact, as in Lekner & Dorf). mu is a cosine inside the film,
 * nu the matching cosine in air (Snell: 1 - nu^2 = n^2 (1 - mu^2)), F(nu)
 * the external Fresnel reflectance, equal to the internal one at mu.
 *  - Collimated light at nu_i: F(nu_i) is mirrored; 1 - F(nu_i) enters and
 *    reaches the base attenuated by a(mu_i) = exp(-tau / mu_i).
 *  - The base re-emits a fraction A, cosine-weighted (2 mu dmu). Of that flux
 *      escape E = 2 int_0^1 mu (1 - F) exp(-tau/mu) dmu   leaves into air,
 *      return Q = 2 int_0^1 mu F exp(-2 tau/mu) dmu        comes back down
 *    (F = 1 for mu < mu_c = sqrt(1 - 1/n^2): total internal reflection).
 *  - Summing the bounces, A E sum_k (A Q)^k:
 *      albedo_dir(nu_i) = F(nu_i) + (1 - F(nu_i)) a(mu_i) A E / (1 - A Q).
 *    With tau = 0: E = 1 - Rint, Q = Rint, Lekner & Dorf's result, where
 *    Rint = 1 - (1 - Rext)/n^2 (Rext = soak_fresnel_dielectric_avg(n)).
 *  - Diffuse light: 2 int nu (1 - F(nu)) a(mu(nu)) dnu = n^2 E (change of
 *    variable nu dnu = n^2 mu dmu), so albedo_diffuse = Rext + A n^2 E^2/(1-AQ).
 *  - BRDF: the base's upward radiance in the film is uniform; leaving, it is
 *    attenuated, transmitted (1 - F(nu_o)) and divided by n^2 (radiance n^2
 *    law), so f = (1-F_i) a_i (1-F_o) a_o A / (pi n^2 (1 - A Q)): symmetric
 *    in i and o, and int f nu_o dw_o = (1-F_i) a_i A E / (1 - A Q).
 * Numerics: the TIR part of Q is 2 mu_c^2 E3(2 tau / mu_c) in closed form;
 * the partially reflecting part is integrated over nu (air side), where the
 * integrand is smooth (the square-root kink of F at mu_c sits at nu = 0 and
 * vanishes there), with Gauss-Legendre panels graded toward nu = 0 (width of
 * the mu(nu) knee ~ mu_c, small for n -> 1) and nu = 1 (exp(-tau/mu) scale
 * ~ n^2/tau for thick films). */
#include "soak/film.h"

#include <math.h>
#include <stddef.h>

#include "soak/fresnel.h"

#include "fast_paths.h"

#define GRADE_LEVELS 10

/* 12-point Gauss-Legendre on [-1,1], positive half. */
static const double gl_x[6] = {0.12523340851146892, 0.36783149899818019, 0.58731795428661745,
                               0.76990267419430469, 0.90411725637047486, 0.98156063424671925};
static const double gl_w[6] = {0.24914704581340279, 0.23349253653835481, 0.20316742672306592,
                               0.16007832854334623, 0.10693932599531843, 0.047175336386511827};

soak_status soak_film_validate(const soak_film *film)
{
    if (!film) return SOAK_ERR_NULL;
    if (!soak_in_range(film->n, SOAK_FILM_MIN_N, SOAK_FILM_MAX_N) || !soak_in_range(film->alpha, 0.0, SOAK_FILM_MAX_ALPHA) ||
        !soak_in_range(film->thickness, 0.0, SOAK_FILM_MAX_THICKNESS))
        return SOAK_ERR_ARG;
    return SOAK_OK;
}

/* Exponential integral E3(x) = int_1^inf exp(-x t) / t^3 dt, x >= 0.
 * x <= 1: power series of E_n (Abramowitz & Stegun 5.1.12) for n = 3;
 * x > 1: continued fraction of E_n (A&S 5.1.22) by the modified Lentz
 * method. Both converge to full double precision. */
static double expint3(double x)
{
    if (x == 0.0) return 0.5;
    if (x <= 1.0) {
        const double euler_gamma = 0.57721566490153286061;
        double sum = 0.5 - x + 0.5 * x * x * (-log(x) + 1.5 - euler_gamma);
        double term = x * x / 2.0; /* (-x)^k / k! at k = 2 */
        for (int k = 3; k < 60; ++k) {
            term *= -x / k;
            double add = -term / (k - 2);
            sum += add;
            if (fabs(add) < 1e-17 * fabs(sum)) break;
        }
        return sum;
    }
    if (x > 745.0) return 0.0; /* exp(-x) underflows */
    const double tiny = 1e-300;
    double b = x + 3.0, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 200; ++i) {
        double an = -(double)i * (2.0 + i);
        b += 2.0;
        d = an * d + b;
        if (fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double del = c * d;
        h *= del;
        if (fabs(del - 1.0) < 1e-16) break;
    }
    return h * exp(-x);
}

/* Adds 2 * int_a^b of nu (1 - F) e and nu F e^2 over one panel, where
 * e = exp(-tau / mu(nu)). */
static void escape_panel(double a, double b, double n, double tau, double *esc, double *ret)
{
    double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    double se = 0.0, sq = 0.0;
    for (int i = 0; i < 6; ++i) {
        for (int s = -1; s <= 1; s += 2) {
            double nu = mid + s * half * gl_x[i];
            double mu;
            double F = soak_fresnel_dielectric_raw(nu, n, &mu);
            double e = exp(-tau / mu); /* mu >= mu_c > 0 since n > 1 */
            se += gl_w[i] * nu * (1.0 - F) * e;
            sq += gl_w[i] * nu * F * e * e;
        }
    }
    *esc += 2.0 * half * se;
    *ret += 2.0 * half * sq;
}

/* Escape E and return Q fractions of the base's Lambertian flux; r_ext is
 * soak_fresnel_dielectric_avg(n), already computed by the caller (it was
 * 65 % of test_export's time, computed twice per set-up of a clear film). */
static void film_escape_return(double n, double tau, double r_ext, double *escape, double *ret)
{
    if (n == 1.0) { /* no interface: everything not absorbed escapes */
        *escape = 2.0 * expint3(tau);
        *ret = 0.0;
        return;
    }
    double n2 = n * n;
    if (tau == 0.0) {
        *escape = (1.0 - r_ext) / n2;
        *ret = 1.0 - *escape;
        return;
    }
    double mu_c2 = 1.0 - 1.0 / n2;
    double mu_c = sqrt(mu_c2);
    double esc = 0.0, rq = 0.0, prev = 0.0;
    /* panel ends 0, 2^-L, ..., 1/2, 1 - 2^-2, ..., 1 - 2^-L, 1 */
    for (int k = GRADE_LEVELS; k >= 1; --k) {
        double next = ldexp(1.0, -k);
        escape_panel(prev, next, n, tau, &esc, &rq);
        prev = next;
    }
    for (int k = 2; k <= GRADE_LEVELS + 1; ++k) {
        double next = k == GRADE_LEVELS + 1 ? 1.0 : 1.0 - ldexp(1.0, -k);
        escape_panel(prev, next, n, tau, &esc, &rq);
        prev = next;
    }
    *escape = esc / n2;
    *ret = 2.0 * mu_c2 * expint3(2.0 * tau / mu_c) + rq / n2;
}

soak_status soak_film_setup(const soak_film *film, soak_film_ctx *ctx)
{
    if (!ctx) return SOAK_ERR_NULL;
    soak_status st = soak_film_validate(film);
    if (st != SOAK_OK) return st;
    soak_film_ctx c;
    c.n = film->n;
    c.tau = film->alpha * film->thickness;
    c.spec_avg = 0.0;
    if (c.n != 1.0) soak_fresnel_dielectric_avg(c.n, &c.spec_avg);
    film_escape_return(c.n, c.tau, c.spec_avg, &c.escape, &c.ret);
    if (!soak_is_finite(c.escape) || !soak_is_finite(c.ret) || !soak_is_finite(c.spec_avg)) return SOAK_ERR_NUMERIC;
    *ctx = c;
    return SOAK_OK;
}

/* A context not made by soak_film_setup (or corrupted) is rejected cheaply. */
static int ctx_ok(const soak_film_ctx *c)
{
    return soak_in_range(c->n, SOAK_FILM_MIN_N, SOAK_FILM_MAX_N) && soak_in_range(c->tau, 0.0, SOAK_FILM_MAX_ALPHA * SOAK_FILM_MAX_THICKNESS) &&
           soak_in_range(c->escape, 0.0, 1.0) && soak_in_range(c->ret, 0.0, 1.0) && soak_in_range(c->spec_avg, 0.0, 1.0);
}

/* Fraction of collimated light at cos_i (air) that reaches the base,
 * (1 - F) exp(-tau / mu_t); the mirrored fraction F goes to *F_out. */
static double film_transmit_to_base(const soak_film_ctx *c, double cos_i, double *F_out)
{
    double cos_t;
    double F = soak_fresnel_dielectric_raw(cos_i, c->n, &cos_t);
    if (F_out) *F_out = F;
    double att = 1.0;
    if (c->tau > 0.0) att = cos_t > 0.0 ? exp(-c->tau / cos_t) : 0.0;
    return (1.0 - F) * att;
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

soak_status soak_film_ctx_albedo_dir(const soak_film_ctx *ctx, double base_albedo, double cos_i, double *albedo)
{
    if (!ctx || !albedo) return SOAK_ERR_NULL;
    if (!ctx_ok(ctx) || !soak_in_range(base_albedo, 0.0, 1.0) || !soak_in_range(cos_i, 0.0, 1.0)) return SOAK_ERR_ARG;
    double F;
    double diffuse = film_transmit_to_base(ctx, cos_i, &F) * base_albedo * ctx->escape / (1.0 - base_albedo * ctx->ret);
    /* exact sum <= 1; the clamp only removes rounding above 1 for A = 1, tau = 0 */
    *albedo = clamp01(F + diffuse);
    return SOAK_OK;
}

soak_status soak_film_ctx_albedo_diffuse(const soak_film_ctx *ctx, double base_albedo, double *albedo)
{
    if (!ctx || !albedo) return SOAK_ERR_NULL;
    if (!ctx_ok(ctx) || !soak_in_range(base_albedo, 0.0, 1.0)) return SOAK_ERR_ARG;
    double n2 = ctx->n * ctx->n;
    double diffuse = base_albedo * n2 * ctx->escape * ctx->escape / (1.0 - base_albedo * ctx->ret);
    *albedo = clamp01(ctx->spec_avg + diffuse);
    return SOAK_OK;
}

static int unit_ok(soak_vec3 v) { return soak_v3_is_unit(v); }

soak_status soak_film_ctx_brdf(const soak_film_ctx *ctx, double base_albedo, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!ctx || !f) return SOAK_ERR_NULL;
    if (!ctx_ok(ctx) || !soak_in_range(base_albedo, 0.0, 1.0) || !unit_ok(wi) || !unit_ok(wo)) return SOAK_ERR_ARG;
    *f = wi.z <= 0.0 || wo.z <= 0.0 ? 0.0 : soak_film_ctx_brdf_raw(ctx, base_albedo, wi, wo);
    return SOAK_OK;
}

double soak_film_ctx_brdf_raw(const soak_film_ctx *ctx, double base_albedo, soak_vec3 wi, soak_vec3 wo)
{
    film_fast k = film_fast_make(ctx, base_albedo);
    return film_brdf_fast(&k, wi, wo);
}

soak_status soak_film_albedo_dir(const soak_film *film, double base_albedo, double cos_i, double *albedo)
{
    if (!albedo) return SOAK_ERR_NULL;
    if (!soak_in_range(base_albedo, 0.0, 1.0) || !soak_in_range(cos_i, 0.0, 1.0)) return SOAK_ERR_ARG;
    soak_film_ctx c;
    soak_status st = soak_film_setup(film, &c);
    return st != SOAK_OK ? st : soak_film_ctx_albedo_dir(&c, base_albedo, cos_i, albedo);
}

soak_status soak_film_albedo_diffuse(const soak_film *film, double base_albedo, double *albedo)
{
    if (!albedo) return SOAK_ERR_NULL;
    if (!soak_in_range(base_albedo, 0.0, 1.0)) return SOAK_ERR_ARG;
    soak_film_ctx c;
    soak_status st = soak_film_setup(film, &c);
    return st != SOAK_OK ? st : soak_film_ctx_albedo_diffuse(&c, base_albedo, albedo);
}

soak_status soak_film_brdf(const soak_film *film, double base_albedo, soak_vec3 wi, soak_vec3 wo, double *f)
{
    if (!f) return SOAK_ERR_NULL;
    if (!soak_in_range(base_albedo, 0.0, 1.0) || !unit_ok(wi) || !unit_ok(wo)) return SOAK_ERR_ARG;
    soak_film_ctx c;
    soak_status st = soak_film_setup(film, &c);
    return st != SOAK_OK ? st : soak_film_ctx_brdf(&c, base_albedo, wi, wo, f);
}

soak_status soak_film_specular(const soak_film *film, double cos_i, double *R)
{
    if (!R) return SOAK_ERR_NULL;
    soak_status st = soak_film_validate(film);
    if (st != SOAK_OK) return st;
    if (!soak_in_range(cos_i, 0.0, 1.0)) return SOAK_ERR_ARG;
    *R = soak_fresnel_dielectric_raw(cos_i, film->n, NULL);
    return SOAK_OK;
}
