/* GGX microfacet model: normalisation of D and of the visible-normal
 * distribution by independent quadrature, analytic Smith values, energy of a
 * near-perfect conductor, VNDF sampling against a chi-square histogram test,
 * argument validation and a 10^6-input finiteness sweep. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"

/* 16-point Gauss-Legendre nodes (positive half) and weights on [-1,1],
 * filled once in main by tu_gauss_legendre_unit. */
static double gx[8], gw[8];

/* Composite 16-point Gauss-Legendre of f on [a,b] with n panels. */
typedef double (*fn1)(double x, void *ctx);
static double integrate(fn1 f, void *ctx, double a, double b, int n)
{
    double sum = 0.0, w = (b - a) / n;
    for (int p = 0; p < n; ++p) {
        double mid = a + (p + 0.5) * w, half = 0.5 * w;
        for (int i = 0; i < 8; ++i)
            sum += gw[i] * half * (f(mid - half * gx[i], ctx) + f(mid + half * gx[i], ctx));
    }
    return sum;
}

/* Microfacet normals are parametrised by v in [0, pi/2) with
 * tan(theta_h) = alpha tan(v), which spreads the lobe evenly for any alpha:
 * d(theta_h)/dv = alpha sec^2 v / (1 + alpha^2 tan^2 v). */
static double theta_of_v(double alpha, double v, double *dtheta)
{
    double t = tan(v);
    *dtheta = alpha * (1.0 + t * t) / (1.0 + alpha * alpha * t * t);
    return atan(alpha * t);
}

/* Independent closed form of Walter 2007 eq. 33 written with tan and cos. */
static double D_ref(double alpha, double theta)
{
    double c = cos(theta), t = tan(theta), a2 = alpha * alpha;
    double q = a2 + t * t;
    return a2 / (SOAK_PI * c * c * c * c * q * q);
}

struct dctx {
    double alpha, phi;
};
static double d_norm_integrand(double v, void *p)
{
    struct dctx *c = p;
    double dth;
    double th = theta_of_v(c->alpha, v, &dth);
    double D = 0.0;
    soak_ggx_D(c->alpha, soak_v3_polar(th, c->phi), &D);
    return 2.0 * SOAK_PI * D * cos(th) * sin(th) * dth;
}

static void test_D(void)
{
    const double alphas[] = {1e-4, 1e-3, 0.05, 0.3, 1.0};
    for (int i = 0; i < 5; ++i) {
        struct dctx c = {alphas[i], 0.7};
        double I = integrate(d_norm_integrand, &c, 0.0, 0.5 * SOAK_PI, 64);
        char what[96];
        snprintf(what, sizeof what, "int D cos dw = 1, alpha %g", alphas[i]);
        check_close(what, I, 1.0, 1e-9);
    }
    const double a = 0.3, th = 0.6;
    double D;
    soak_ggx_D(a, soak_v3_polar(th, 2.0), &D);
    check_rel("D vs tan/cos closed form, alpha 0.3, 0.6 rad", D, D_ref(a, th), 1e-12);
    soak_ggx_D(a, soak_v3(0.0, 0.0, 1.0), &D);
    check_rel("D(n) = 1/(pi alpha^2)", D, 1.0 / (SOAK_PI * a * a), 1e-14);
    soak_ggx_D(a, soak_v3(0.0, 0.6, -0.8), &D);
    check_close("D = 0 below the horizon", D, 0.0, 0.0);
}

static void test_smith(void)
{
    double G;
    /* alpha = 1, theta = 60 deg: Lambda = (-1 + sqrt(1 + tan^2))/2 = 1/2 -> G1 = 2/3. */
    soak_ggx_G1(1.0, soak_v3_polar(SOAK_PI / 3.0, 0.4), &G);
    check_rel("G1(alpha 1, 60 deg) = 2/3", G, 2.0 / 3.0, 1e-14);
    /* alpha = 0.5, theta = 45 deg: Lambda = (-1 + sqrt(1.25))/2. */
    soak_ggx_G1(0.5, soak_v3_polar(SOAK_PI / 4.0, 1.0), &G);
    check_rel("G1(alpha 0.5, 45 deg)", G, 1.0 / (1.0 + 0.5 * (sqrt(1.25) - 1.0)), 1e-14);
    /* Height-correlated G2 = 1/(1 + L_i + L_o) (Heitz 2014 eq. 99); lies between
     * the uncorrelated product G1 G1 and min(G1, G1). */
    soak_vec3 wi = soak_v3_polar(1.1, 0.0), wo = soak_v3_polar(0.5, 2.0);
    double a = 0.4, Gi, Go, G2;
    soak_ggx_G1(a, wi, &Gi);
    soak_ggx_G1(a, wo, &Go);
    soak_ggx_G2(a, wi, wo, &G2);
    check_rel("G2 = 1/(1/G1i + 1/G1o - 1)", G2, 1.0 / (1.0 / Gi + 1.0 / Go - 1.0), 1e-13);
    check_true("G1i G1o <= G2 <= min(G1i, G1o)", Gi * Go <= G2 && G2 <= fmin(Gi, Go));
    soak_ggx_G1(a, soak_v3(0.0, 0.0, 1.0), &G);
    check_close("G1(normal) = 1", G, 1.0, 1e-15);
}

/* Quadrature over microfacet normals h of g(h) for a fixed wo. */
struct hctx {
    double alpha;
    soak_vec3 wo;
    int mode; /* 0: VNDF normalisation, 1: conductor albedo, 2: dielectric albedo */
    double eta, k;
    double v; /* current v for the inner phi integral */
};
static double h_inner(double phi, void *p)
{
    struct hctx *c = p;
    double dth;
    double th = theta_of_v(c->alpha, c->v, &dth);
    soak_vec3 h = soak_v3_polar(th, phi);
    double jac = sin(th) * dth;
    double woh = soak_v3_dot(c->wo, h);
    if (woh <= 0.0) return 0.0;
    double D;
    soak_ggx_D(c->alpha, h, &D);
    if (c->mode == 0) {
        double G1;
        soak_ggx_G1(c->alpha, c->wo, &G1);
        return G1 * woh * D / c->wo.z * jac;
    }
    soak_vec3 wi = soak_v3_sub(soak_v3_scale(h, 2.0 * woh), c->wo);
    if (wi.z <= 0.0) return 0.0;
    wi = soak_v3_norm(wi);
    double f = 0.0;
    if (c->mode == 1) soak_ggx_brdf_conductor(c->alpha, c->eta, c->k, wi, c->wo, &f);
    else soak_ggx_brdf_dielectric(c->alpha, c->eta, wi, c->wo, &f);
    /* f cos_i dw_i with dw_i = 4 (wo.h) dw_h. */
    return f * wi.z * 4.0 * woh * jac;
}
/* The integrand is cut off where wo.h <= 0 (VNDF) or wi.z <= 0 (albedo); both
 * are cos(phi - phi_o) > c for a c known in closed form, so the phi integral
 * runs over exactly that arc and the quadrature never meets a kink. */
static double h_outer(double v, void *p)
{
    struct hctx *c = p;
    c->v = v;
    double dth;
    double th = theta_of_v(c->alpha, v, &dth);
    double so = sqrt(fmax(0.0, 1.0 - c->wo.z * c->wo.z)), st = sin(th), ct = cos(th);
    /* wi.z = 2 (wo.h) h.z - wo.z > 0  <=>  wo.h > wo.z / (2 h.z). */
    double thr = c->mode == 0 ? 0.0 : c->wo.z / (2.0 * ct);
    double phi_o = atan2(c->wo.y, c->wo.x), half;
    if (so * st <= 0.0) half = c->wo.z * ct > thr ? SOAK_PI : 0.0;
    else {
        double cc = (thr - c->wo.z * ct) / (so * st);
        half = cc <= -1.0 ? SOAK_PI : (cc >= 1.0 ? 0.0 : acos(cc));
    }
    if (half <= 0.0) return 0.0;
    return integrate(h_inner, c, phi_o - half, phi_o + half, 4);
}
/* The arc length has square-root kinks in theta_h where the cut-off starts
 * (VNDF: theta_h = pi/2 - theta_o; albedo: theta_h = (pi/2 -+ theta_o)/2,
 * from 2 cos(th) cos(th -+ theta_o) = cos(theta_o)); split the v range there. */
static double h_integral(struct hctx *c)
{
    double to = acos(c->wo.z), br[4];
    int nb = 0;
    br[nb++] = 0.0;
    if (c->mode == 0) br[nb++] = 0.5 * SOAK_PI - to;
    else {
        br[nb++] = 0.5 * (0.5 * SOAK_PI - to);
        br[nb++] = 0.5 * (0.5 * SOAK_PI + to);
    }
    double sum = 0.0, v0 = 0.0;
    for (int i = 1; i <= nb; ++i) {
        double v1 = i < nb ? atan(tan(br[i]) / c->alpha) : 0.5 * SOAK_PI;
        if (v1 > v0) sum += integrate(h_outer, c, v0, v1, 6);
        if (v1 > v0) v0 = v1;
    }
    return sum;
}

static void test_vndf_normalisation_and_energy(void)
{
    const double alphas[] = {1e-3, 0.05, 0.3, 1.0};
    const double thetas[] = {0.0, 30.0, 60.0, 80.0, 89.0};
    double worst_vndf = 0.0, max_alb = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int t = 0; t < 5; ++t) {
            struct hctx c = {alphas[a], soak_v3_polar(thetas[t] * SOAK_PI / 180.0, 0.3), 0, 1.0, 0.0, 0.0};
            worst_vndf = fmax(worst_vndf, fabs(h_integral(&c) - 1.0));
            c.mode = 1;
            c.eta = 1.0;
            c.k = 1e3; /* R0 = 1e6 / (4 + 1e6): a near-perfect mirror */
            double E = h_integral(&c);
            max_alb = fmax(max_alb, E);
            printf("     conductor(k=1e3) albedo alpha %-6g theta_o %4.0f: %.6f\n", alphas[a], thetas[t], E);
            if (alphas[a] == 0.05 && thetas[t] <= 60.0) {
                char what[96];
                /* Single scattering loses only a few 1e-3 at this roughness
                 * (Heitz et al. 2016, fig. 1): anything below 0.97 is a bug. */
                snprintf(what, sizeof what, "conductor R~1 albedo >= 0.97, alpha 0.05, theta %g", thetas[t]);
                check_true(what, E >= 0.97);
            }
        }
    check_close("max |int G1 (wo.h) D / wo.z dw_h - 1| (all alpha, theta)", worst_vndf, 0.0, 1e-8);
    check_true("conductor R~1 directional albedo <= 1", max_alb <= 1.0 + 1e-6);
    printf("     max conductor albedo %.9f\n", max_alb);

    /* alpha = 1 gives D = 1/pi, and at normal view G2 = G1(wi) = 2 cos_i/(1 + cos_i);
     * with R = 1 the albedo is int_0^{pi/4} 2 tan(t) cos(2t) dt = 1 - ln 2. */
    struct hctx n1 = {1.0, soak_v3(0.0, 0.0, 1.0), 1, 1.0, 1e3, 0.0};
    check_close("alpha 1, normal view, R~1: albedo = 1 - ln 2", h_integral(&n1), 1.0 - log(2.0), 5e-6);

    struct hctx d = {0.3, soak_v3_polar(0.7, 0.0), 2, 1.0, 0.0, 0.0};
    check_close("dielectric eta = 1 (no interface): albedo 0", h_integral(&d), 0.0, 0.0);
    d.eta = 1.5;
    double Ed = h_integral(&d);
    check_true("dielectric eta 1.5 albedo in (0.04, 0.2)", Ed > 0.04 && Ed < 0.2);
}

static void test_brdf_points(void)
{
    soak_vec3 wi = soak_v3_polar(0.9, 0.2), wo = soak_v3_polar(0.4, 3.0);
    double a = 0.25, eta = 1.5, f, fr, D, G2, F;
    soak_vec3 h = soak_v3_norm(soak_v3_add(wi, wo));
    soak_ggx_D(a, h, &D);
    soak_ggx_G2(a, wi, wo, &G2);
    soak_fresnel_dielectric(fmin(1.0, soak_v3_dot(wi, h)), eta, &F, NULL);
    soak_ggx_brdf_dielectric(a, eta, wi, wo, &f);
    check_rel("dielectric f = F D G2 / (4 ci co)", f, F * D * G2 / (4.0 * wi.z * wo.z), 1e-12);
    soak_ggx_brdf_dielectric(a, eta, wo, wi, &fr);
    check_rel("dielectric reciprocity", fr, f, 1e-13);
    soak_ggx_brdf_dielectric(a, 1.0 / 1.33, wi, wo, &f);
    soak_fresnel_dielectric(fmin(1.0, soak_v3_dot(wi, h)), 1.0 / 1.33, &F, NULL);
    check_rel("dielectric eta < 1 (from inside water)", f, F * D * G2 / (4.0 * wi.z * wo.z), 1e-12);
    soak_ggx_brdf_conductor(a, 0.2, 3.0, wi, wo, &f);
    soak_fresnel_conductor(fmin(1.0, soak_v3_dot(wi, h)), 0.2, 3.0, &F);
    check_rel("conductor f = F D G2 / (4 ci co)", f, F * D * G2 / (4.0 * wi.z * wo.z), 1e-12);
    soak_ggx_brdf_conductor(a, 0.2, 3.0, wo, wi, &fr);
    check_rel("conductor reciprocity", fr, f, 1e-13);

    /* Grazing: cos = 1e-6 on both sides stays finite and non-negative. */
    soak_vec3 g1 = soak_v3(sqrt(1.0 - 1e-12), 0.0, 1e-6), g2 = soak_v3(-sqrt(1.0 - 1e-12), 0.0, 1e-6);
    check_status("grazing dielectric", soak_ggx_brdf_dielectric(1e-4, 1.5, g1, g2, &f), SOAK_OK);
    check_true("grazing dielectric finite", soak_is_finite(f) && f >= 0.0);
    check_status("grazing conductor", soak_ggx_brdf_conductor(1.0, 1.0, 1e3, g1, g1, &f), SOAK_OK);
    check_true("grazing conductor finite", soak_is_finite(f) && f >= 0.0);
}

/* Chi-square test of VNDF samples against the density G1 (wo.h) D / wo.z,
 * integrated over each bin by quadrature written here (D_ref, own Lambda). */
struct bin_ctx {
    double alpha;
    soak_vec3 wo;
    double v;
};
static double vndf_ref(double alpha, soak_vec3 wo, double th, double phi)
{
    soak_vec3 h = soak_v3_polar(th, phi);
    double woh = soak_v3_dot(wo, h);
    if (woh <= 0.0) return 0.0;
    double to = sqrt(1.0 - wo.z * wo.z) / wo.z;
    double lambda = 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * to * to));
    return woh * D_ref(alpha, th) / ((1.0 + lambda) * wo.z);
}
static double bin_inner(double phi, void *p)
{
    struct bin_ctx *c = p;
    double dth;
    double th = theta_of_v(c->alpha, c->v, &dth);
    return vndf_ref(c->alpha, c->wo, th, phi) * sin(th) * dth;
}
struct bin_outer_ctx {
    struct bin_ctx *c;
    double p0, p1;
};
static double bin_outer(double v, void *p)
{
    struct bin_outer_ctx *o = p;
    o->c->v = v;
    return integrate(bin_inner, o->c, o->p0, o->p1, 2);
}

#define NV 10
#define NP 8
static void chi_square(double alpha, double theta_o, int n, tu_rng *rng)
{
    soak_vec3 wo = soak_v3_polar(theta_o, 0.5);
    static double count[NV][NP];
    for (int i = 0; i < NV; ++i)
        for (int j = 0; j < NP; ++j) count[i][j] = 0.0;
    int pdf_ok = 1;
    for (int s = 0; s < n; ++s) {
        soak_vec3 h;
        double pdf;
        if (soak_ggx_sample_vndf(alpha, wo, tu_uniform(rng), tu_uniform(rng), &h, &pdf) != SOAK_OK) {
            pdf_ok = 0;
            continue;
        }
        double th = acos(fmin(1.0, h.z));
        double v = atan(tan(th) / alpha);
        double phi = atan2(h.y, h.x);
        if (phi < 0.0) phi += 2.0 * SOAK_PI;
        int iv = (int)(v / (0.5 * SOAK_PI) * NV), ip = (int)(phi / (2.0 * SOAK_PI) * NP);
        if (iv >= NV) iv = NV - 1;
        if (ip >= NP) ip = NP - 1;
        count[iv][ip] += 1.0;
        if (s < 1000) {
            double ref = vndf_ref(alpha, wo, th, phi);
            if (!(fabs(pdf - ref) <= 1e-9 * ref + 1e-12)) pdf_ok = 0;
        }
    }
    double chi2 = 0.0, total_p = 0.0;
    int dof = -1;
    struct bin_ctx c = {alpha, wo, 0.0};
    for (int i = 0; i < NV; ++i)
        for (int j = 0; j < NP; ++j) {
            struct bin_outer_ctx o = {&c, j * 2.0 * SOAK_PI / NP, (j + 1) * 2.0 * SOAK_PI / NP};
            double p = integrate(bin_outer, &o, i * 0.5 * SOAK_PI / NV, (i + 1) * 0.5 * SOAK_PI / NV, 2);
            total_p += p;
            double e = p * n;
            if (e < 5.0) continue; /* pooled-out sparse bins (few, far tail) */
            chi2 += (count[i][j] - e) * (count[i][j] - e) / e;
            ++dof;
        }
    /* 99.9% quantile of chi-square with dof degrees of freedom, Wilson-Hilferty. */
    double z = 3.090, k = dof;
    double crit = k * pow(1.0 - 2.0 / (9.0 * k) + z * sqrt(2.0 / (9.0 * k)), 3.0);
    printf("     VNDF alpha %g theta_o %.2f: chi2 %.1f, dof %d, 99.9%% critical %.1f\n", alpha, theta_o, chi2, dof, crit);
    char what[128];
    snprintf(what, sizeof what, "VNDF histogram chi2 %.1f < %.1f (dof %d), alpha %g, theta_o %.2f", chi2, crit,
             dof, alpha, theta_o);
    check_true(what, chi2 < crit);
    snprintf(what, sizeof what, "VNDF bin probabilities sum to 1, alpha %g", alpha);
    check_close(what, total_p, 1.0, 1e-6);
    snprintf(what, sizeof what, "sample pdf = G1 (wo.h) D / wo.z, alpha %g", alpha);
    check_true(what, pdf_ok);
}

static void test_validation(void)
{
    double out = 42.0;
    soak_vec3 up = soak_v3(0.0, 0.0, 1.0), h;
    check_status("alpha below 1e-4", soak_ggx_D(5e-5, up, &out), SOAK_ERR_ARG);
    check_status("alpha above 1", soak_ggx_D(1.0001, up, &out), SOAK_ERR_ARG);
    check_status("alpha NaN", soak_ggx_G1(NAN, up, &out), SOAK_ERR_ARG);
    check_status("alpha Inf", soak_ggx_G2(INFINITY, up, up, &out), SOAK_ERR_ARG);
    check_status("h NaN", soak_ggx_D(0.5, soak_v3(NAN, 0.0, 1.0), &out), SOAK_ERR_ARG);
    check_status("h not unit", soak_ggx_D(0.5, soak_v3(0.0, 0.0, 1.1), &out), SOAK_ERR_ARG);
    check_status("wi below horizon", soak_ggx_G2(0.5, soak_v3(0.0, 0.6, -0.8), up, &out), SOAK_ERR_ARG);
    check_status("wo at horizon", soak_ggx_G1(0.5, soak_v3(1.0, 0.0, 0.0), &out), SOAK_ERR_ARG);
    check_status("eta NaN", soak_ggx_brdf_dielectric(0.5, NAN, up, up, &out), SOAK_ERR_ARG);
    check_status("eta 0", soak_ggx_brdf_dielectric(0.5, 0.0, up, up, &out), SOAK_ERR_ARG);
    check_status("k negative", soak_ggx_brdf_conductor(0.5, 1.0, -1.0, up, up, &out), SOAK_ERR_ARG);
    check_status("k Inf", soak_ggx_brdf_conductor(0.5, 1.0, INFINITY, up, up, &out), SOAK_ERR_ARG);
    check_status("u1 NaN", soak_ggx_sample_vndf(0.5, up, NAN, 0.5, &h, &out), SOAK_ERR_ARG);
    check_status("u2 > 1", soak_ggx_sample_vndf(0.5, up, 0.5, 1.5, &h, &out), SOAK_ERR_ARG);
    check_status("NULL out", soak_ggx_D(0.5, up, NULL), SOAK_ERR_NULL);
    check_status("NULL h", soak_ggx_sample_vndf(0.5, up, 0.5, 0.5, NULL, &out), SOAK_ERR_NULL);
    check_close("output untouched on error", out, 42.0, 0.0);
}

static void test_random_finite(tu_rng *rng)
{
    int bad = 0, errs = 0;
    for (int n = 0; n < 1000000; ++n) {
        double a = SOAK_GGX_ALPHA_MIN +
                   (1.0 - SOAK_GGX_ALPHA_MIN) *
                       (n % 3 == 0 ? tu_uniform(rng) * tu_uniform(rng) * tu_uniform(rng) : tu_uniform(rng));
        double eta = exp(log(SOAK_ETA_MIN) + (log(SOAK_ETA_MAX) - log(SOAK_ETA_MIN)) * tu_uniform(rng));
        double k = n % 4 == 0 ? 0.0 : SOAK_GGX_K_MAX * tu_uniform(rng) * tu_uniform(rng);
        soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = tu_upper_dir(rng, 1e-6), h, hs;
        double o[8], pdf;
        soak_status s[8];
        s[0] = soak_ggx_D(a, wi, &o[0]);
        s[1] = soak_ggx_G1(a, wi, &o[1]);
        s[2] = soak_ggx_G2(a, wi, wo, &o[2]);
        s[3] = soak_ggx_brdf_dielectric(a, eta, wi, wo, &o[3]);
        s[4] = soak_ggx_brdf_conductor(a, eta, k, wi, wo, &o[4]);
        s[5] = soak_ggx_sample_vndf(a, wo, tu_uniform(rng), tu_uniform(rng), &hs, &o[5]);
        h = soak_v3_norm(soak_v3_add(wi, wo));
        s[6] = soak_ggx_pdf_vndf(a, wo, h, &o[6]);
        s[7] = soak_ggx_pdf_vndf(a, wo, hs, &pdf);
        o[7] = pdf;
        for (int i = 0; i < 8; ++i) {
            if (s[i] != SOAK_OK) ++errs;
            else if (!soak_is_finite(o[i]) || o[i] < 0.0) ++bad;
        }
        if (s[5] == SOAK_OK && !(hs.z > 0.0 && soak_is_finite(hs.x) && soak_is_finite(hs.y))) ++bad;
    }
    check_true("1e6 random valid inputs: all SOAK_OK", errs == 0);
    check_true("1e6 random valid inputs: no NaN/Inf/negative", bad == 0);
}

int main(void)
{
    tu_rng rng = tu_splitmix64(0x9E3779B97F4A7C15ull);
    tu_gauss_legendre_unit(16, 8, gx, gw);
    test_D();
    test_smith();
    test_brdf_points();
    test_vndf_normalisation_and_energy();
    chi_square(0.5, 1.0, 200000, &rng);
    chi_square(0.05, 1.3, 200000, &rng);
    chi_square(1.0, 0.0, 100000, &rng);
    test_validation();
    test_random_finite(&rng);
    return check_finish();
}
