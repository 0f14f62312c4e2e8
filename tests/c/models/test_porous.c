/* Porous BRDF (Merillou), wet porous model (Hnat) and the energy-conserving
 * GGX variant. References: explicit geometric sums and Taylor series for A_p,
 * the Smith-Beckmann masking for the scaling of Schlick's k, closed forms
 * for Blinn-Phong normal-incidence albedo, [Lag13]'s simplified form and
 * [Hnat06]'s Eq. 2-3 written out here, reciprocity, and directional albedo by
 * an independent panel quadrature over the outgoing hemisphere. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "porous_cases.h"
#include "testutil.h"
#include "soak/porous.h"

/* 8-point Gauss-Legendre on [-1,1], filled once in main. */
static double gx[8], gw[8];

/* Panel breakpoints on [lo, hi], refined geometrically (c +- w0 2^k) around
 * c and, when edge is set, also towards hi (the horizon, where the
 * diffuse weights 1 - E_s(mu) and the Smith terms vary fastest). Sorted. */
static int breakpoints(double lo, double hi, double c, double w0, int edge, double *bp)
{
    int n = 0;
    bp[n++] = lo;
    bp[n++] = hi;
    if (c > lo && c < hi) bp[n++] = c;
    for (double d = w0; d < hi - lo && n < 200; d *= 2.0) {
        if (c - d > lo) bp[n++] = c - d;
        if (c + d < hi) bp[n++] = c + d;
        if (edge && hi - d > lo) bp[n++] = hi - d;
    }
    for (int i = 1; i < n; ++i) /* insertion sort */
        for (int j = i; j > 0 && bp[j - 1] > bp[j]; --j) {
            double t = bp[j];
            bp[j] = bp[j - 1];
            bp[j - 1] = t;
        }
    int m = 1;
    for (int i = 1; i < n; ++i)
        if (bp[i] > bp[m - 1] + 1e-12) bp[m++] = bp[i];
    return m;
}

/* Directional albedo int f(wi, wo) cos_o dwo over the upper hemisphere,
 * (theta_o, phi_o) panels refined around the mirror direction. wi lies in
 * the xz plane and every BRDF here is even in phi_o: phi_o in [0, pi], x2. */
typedef double (*brdf_fn)(const void *ctx, soak_vec3 wi, soak_vec3 wo);
static double dir_albedo(brdf_fn f, const void *ctx, double theta_i, double width)
{
    soak_vec3 wi = soak_v3_polar(theta_i, 0.0);
    double bt[200], bph[200];
    int nt = breakpoints(0.0, 0.5 * SOAK_PI, theta_i, width, 1, bt);
    int np = breakpoints(0.0, SOAK_PI, SOAK_PI, width, 0, bph);
    double sum = 0.0;
    for (int a = 0; a + 1 < nt; ++a)
        for (int i = 0; i < 8; ++i) {
            double ht = 0.5 * (bt[a + 1] - bt[a]), th = bt[a] + ht * (1.0 + gx[i]);
            double wt = ht * gw[i] * sin(th) * cos(th);
            for (int b = 0; b + 1 < np; ++b)
                for (int j = 0; j < 8; ++j) {
                    double hp = 0.5 * (bph[b + 1] - bph[b]), ph = bph[b] + hp * (1.0 + gx[j]);
                    sum += wt * hp * gw[j] * f(ctx, wi, soak_v3_polar(th, ph));
                }
        }
    return 2.0 * sum;
}

typedef struct bp_ctx {
    const soak_porous_params *p;
    double fill;
} bp_ctx;
typedef struct ggx_ctx {
    const soak_porous_ggx *c;
    double fill;
} ggx_ctx;

static double bp_fn(const void *ctx, soak_vec3 wi, soak_vec3 wo)
{
    const bp_ctx *c = ctx;
    double f = NAN;
    soak_porous_eval(c->p, c->fill, wi, wo, &f);
    return f;
}

static double ggx_fn(const void *ctx, soak_vec3 wi, soak_vec3 wo)
{
    const ggx_ctx *c = ctx;
    double f = NAN;
    soak_porous_ggx_eval(c->c, c->fill, wi, wo, &f);
    return f;
}

/* ---- building blocks ---- */

static void test_Ap(void)
{
    const double kas[] = {0.05, 0.3, 0.7, 0.95};
    double worst = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int n = 1; n <= 6; ++n) {
            double sum = 0.0, pw = 1.0; /* explicit k_a sum_{j<n} (1-k_a)^j */
            for (int j = 0; j < n; ++j) {
                sum += kas[a] * pw;
                pw *= 1.0 - kas[a];
            }
            double Ap = NAN;
            soak_porous_Ap(kas[a], n, &Ap);
            worst = fmax(worst, fabs(Ap - sum) / sum);
        }
    check_close("A_p vs explicit geometric sum, n_b = 1..6: max rel err", worst, 0.0, 1e-14);

    const double tiny[] = {1e-30, 1e-15, 1e-8};
    const double nbs[] = {1.0, 2.5, 7.0};
    double worst_s = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            double k = tiny[a], n = nbs[b];
            double series = n * k - n * (n - 1.0) / 2.0 * k * k + n * (n - 1.0) * (n - 2.0) / 6.0 * k * k * k;
            double Ap = NAN;
            soak_porous_Ap(k, n, &Ap);
            worst_s = fmax(worst_s, fabs(Ap - series) / series);
        }
    check_close("A_p for k_a = 1e-30, 1e-15, 1e-8 vs Taylor series: max rel err", worst_s, 0.0, 1e-12);

    double v = NAN;
    check_status("A_p(k_a=0)", soak_porous_Ap(0.0, 3.0, &v), SOAK_OK);
    check_close("A_p(k_a=0) = 0", v, 0.0, 0.0);
    soak_porous_Ap(1.0, 3.0, &v);
    check_close("A_p(k_a=1, n_b=3) = 1", v, 1.0, 0.0);
    soak_porous_Ap(1.0, 0.0, &v);
    check_close("A_p(k_a=1, n_b=0) = 0 (empty sum)", v, 0.0, 0.0);
    soak_porous_Ap(1.0, 0.4, &v);
    check_close("A_p(k_a=1, n_b=0.4) = 1", v, 1.0, 0.0);
    soak_porous_Ap(0.5, 1e4, &v);
    check_close("A_p(k_a=0.5, n_b=1e4) = 1", v, 1.0, 0.0);
}

static void test_fill(void)
{
    double v = NAN, prev = -1.0;
    int mono = 1;
    for (int i = 0; i <= 1000; ++i) {
        soak_fill_fraction(-0.5 + 2.0 * i / 1000.0, 0.2, 0.3, &v);
        if (!(v >= prev && v >= 0.0 && v <= 1.0)) mono = 0;
        prev = v;
    }
    check_true("fill fraction non-decreasing in t and in [0,1]", mono);
    soak_fill_fraction(0.1, 0.2, 0.3, &v);
    check_close("fill before t0", v, 0.0, 0.0);
    soak_fill_fraction(0.2, 0.2, 0.3, &v);
    check_close("fill at t0", v, 0.0, 0.0);
    soak_fill_fraction(0.35, 0.2, 0.3, &v);
    check_close("fill at t0 + t_fill/2", v, 0.5, 1e-15);
    soak_fill_fraction(0.5, 0.2, 0.3, &v);
    check_close("fill at t0 + t_fill", v, 1.0, 1e-15);
    soak_fill_fraction(0.9, 0.2, 0.3, &v);
    check_close("fill after t0 + t_fill", v, 1.0, 0.0);

    check_status("t_fill = 0 accepted", soak_fill_fraction(0.2, 0.2, 0.0, &v), SOAK_OK);
    check_close("t_fill = 0: 1 at t0 (complete at t0 + t_fill)", v, 1.0, 0.0);
    soak_fill_fraction(nextafter(0.2, 1.0), 0.2, 0.0, &v);
    check_close("t_fill = 0: 1 just after t0 (step)", v, 1.0, 0.0);
    soak_fill_fraction(nextafter(0.2, 0.0), 0.2, 0.0, &v);
    check_close("t_fill = 0: 0 just before t0", v, 0.0, 0.0);
    soak_fill_fraction(1e308, -1e308, 1e-300, &v);
    check_close("overflowing t - t0 gives full", v, 1.0, 0.0);

    double t0 = NAN;
    soak_wetmap_t0(1.0, &t0);
    check_close("wet map 1 (first wet) -> t0 = 0", t0, 0.0, 0.0);
    soak_wetmap_t0(0.0, &t0);
    soak_fill_fraction(1.0, t0, 0.3, &v);
    check_close("wet map 0 (never wet) -> fill 0 at t = 1", v, 0.0, 0.0);
}

/* Smith G1 for a Beckmann surface of RMS slope m (Walter et al. 2007). */
static double smith_beckmann(double mu, double m)
{
    double a = mu / (m * sqrt(1.0 - mu * mu));
    double lambda = 0.5 * (erf(a) - 1.0) + exp(-a * a) / (2.0 * a * sqrt(SOAK_PI));
    return 1.0 / (1.0 + lambda);
}

static void test_Gp(void)
{
    double g = NAN, worst = 0.0;
    for (int i = 1; i <= 100; ++i)
        for (int j = 1; j <= 100; ++j) {
            soak_porous_Gp(0.0, i / 100.0, j / 100.0, &g);
            worst = fmax(worst, fabs(g - 1.0));
        }
    check_close("G_p(m = 0) = 1 off grazing", worst, 0.0, 0.0);
    soak_porous_Gp(1e-9, 0.05, 0.05, &g);
    check_close("G_p(m = 1e-9, cos 0.05) -> 1", g, 1.0, 1e-6);
    const double ms[] = {0.0, 0.3, 1.0};
    for (int i = 0; i < 3; ++i) {
        soak_porous_Gp(ms[i], 0.0, 0.7, &g);
        check_close("G_p at cos_i = 0 is 0", g, 0.0, 0.0);
        soak_porous_Gp(ms[i], 0.7, 0.0, &g);
        check_close("G_p at cos_o = 0 is 0", g, 0.0, 0.0);
    }
    /* closed form with k = sqrt(2 m^2 / pi) */
    double m = 0.4, k = sqrt(2.0 * m * m / SOAK_PI), ci = 0.5, co = 0.8;
    soak_porous_Gp(m, ci, co, &g);
    check_rel("G_p Schlick-Smith closed form", g, ci / (ci - k * ci + k) * co / (co - k * co + k), 1e-15);
    /* Why sqrt: near grazing the exact Smith masking of slope m depends on
     * cos / m, so doubling m halves G1. Schlick with k ~ m reproduces that;
     * k ~ m^2 ([Hnat06]) would quarter it. */
    double g1, g2, mu = 1e-4;
    soak_porous_Gp(0.2, mu, 1.0, &g1);
    soak_porous_Gp(0.4, mu, 1.0, &g2);
    check_close("G1(2m)/G1(m) at grazing matches Smith-Beckmann", g2 / g1,
                smith_beckmann(mu, 0.4) / smith_beckmann(mu, 0.2), 1e-3);
}

static void test_nb(void)
{
    double nb = NAN;
    double sp = 1.3, ti = 0.3, to = 1.1;
    soak_porous_nb(sp, ti, to, &nb);
    double d = (ti + to) / 2.0 - 2.0 * SOAK_PI / (sp + 6.0);
    check_rel("n_b with the square restored", nb, sp * (3.7 - 2.0 * d * d), 1e-15);
    double nb2 = NAN;
    soak_porous_nb(sp, to, ti, &nb2);
    check_close("n_b symmetric", nb, nb2, 0.0);
    soak_porous_nb(40.0, 0.5 * SOAK_PI, 0.5 * SOAK_PI, &nb);
    double d40 = 0.5 * SOAK_PI - 2.0 * SOAK_PI / 46.0;
    check_true("raw fit negative at s_p = 40 grazing", 40.0 * (3.7 - 2.0 * d40 * d40) < 0.0);
    check_close("n_b clamped to 0 there", nb, 0.0, 0.0);
    soak_porous_nb(0.0, 0.2, 0.2, &nb);
    check_close("n_b(s_p = 0) = 0", nb, 0.0, 0.0);
}

/* ---- Blinn-Phong model ---- */

static void test_forms(tu_rng *rng)
{
    /* [Lag13]'s simplified form and [Hnat06] Eq. 2-3, evaluated here from
     * the building blocks, against soak_porous_eval / coeffs. */
    double worst_simpl = 0.0, worst_eq = 0.0;
    for (int s = 0; s < 2000; ++s) {
        soak_porous_params p = {0.9 * tu_uniform(rng),  0.0,
                                tu_uniform(rng),        1.0 + 100.0 * tu_uniform(rng),
                                tu_uniform(rng),        5.0 * tu_uniform(rng),
                                SOAK_POROUS_KS_WATER_MAX * tu_uniform(rng), 200.0,
                                SOAK_BLINN_NORM_SEED001};
        p.ks = (1.0 - p.kd) * tu_uniform(rng);
        double fill = tu_uniform(rng);
        soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = tu_upper_dir(rng, 1e-6);
        double Gp, nb, Ap;
        soak_porous_Gp(p.m, wi.z, wo.z, &Gp);
        soak_porous_nb(p.sp, acos(wi.z), acos(wo.z), &nb);
        double ka = 1.0 - p.ks - p.kd;
        Ap = 1.0 - pow(1.0 - ka, nb);
        double aG = p.porosity * Gp;
        double hz = soak_v3_norm(soak_v3_add(wi, wo)).z;
        double Fs = (p.spec_power + 2.0) / (2.0 * SOAK_PI) * pow(hz, p.spec_power);
        double Fd = 1.0 / SOAK_PI;

        double fr = p.ks * Fs + p.kd * Fd;
        double simplified = (1.0 - aG) * fr + aG * pow(p.ks + p.kd, nb + 1.0) * Fd;
        double ks_poro = p.ks * (1.0 - aG), kd_poro = p.kd * (1.0 - aG * Ap) + p.ks * aG * (1.0 - Ap);
        double dry = NAN;
        soak_porous_params pd = p;
        pd.ks_water = 0.0;
        soak_porous_eval(&pd, 0.0, wi, wo, &dry);
        worst_simpl = fmax(worst_simpl, fabs(simplified - (ks_poro * Fs + kd_poro * Fd)) / simplified);
        worst_simpl = fmax(worst_simpl, fabs(dry - (ks_poro * Fs + kd_poro * Fd)) / dry);

        double kd_wet = p.kd * (1.0 - aG) + (p.kd * aG * (1.0 - Ap) + p.ks * (1.0 - Ap) * aG) * (1.0 - fill);
        soak_porous_coeffs c;
        soak_porous_coeffs_eval(&p, fill, wi, wo, &c);
        double scale = kd_wet + 1e-300;
        worst_eq = fmax(worst_eq, fabs(c.kd_wet - kd_wet) / scale);
        worst_eq = fmax(worst_eq, fabs(c.ks_mat - p.ks * (1.0 - aG)) / (p.ks + 1e-300));
        worst_eq = fmax(worst_eq, fabs(c.ks_water - p.ks_water * aG * fill) / (p.ks_water + 1e-300));
    }
    check_close("[Lag13] simplified form == [Hnat06] k_s/k_d-poro == eval: max rel diff", worst_simpl, 0.0,
                1e-12);
    check_close("coefficients vs [Hnat06] Eq. 2-3: max rel diff", worst_eq, 0.0, 1e-12);
}

static void test_bp_norm(void)
{
    /* Normal-incidence albedo of the lobe alone: 1 for the energy normaliser
     * 1/A(n) (it was (n+8)(n + 2^(-n/2))/((n+2)(n+4)) up to 1.077 with
     * Hoffman's (n+8)/(8pi), the cause of porous albedos above 1). */
    const double ns[] = {1.0, 10.0, 53.4, 200.0};
    for (int i = 0; i < 4; ++i) {
        double n = ns[i];
        soak_porous_params p = {0.0, 1.0, 0.3, n, 0.0, 1.0, 0.0, 200.0, SOAK_BLINN_NORM_ENERGY};
        bp_ctx ctx = {&p, 0.0};
        double E = dir_albedo(bp_fn, &ctx, 0.0, 0.02);
        check_rel("Blinn-Phong energy 1/A(n) normal-incidence albedo = 1", E, 1.0, 1e-6);
        p.norm = SOAK_BLINN_NORM_SEED001;
        E = dir_albedo(bp_fn, &ctx, 0.0, 0.02);
        check_rel("[Lag13] (n+2)/(2pi) normal-incidence albedo vs closed form", E,
                  4.0 * (n + pow(2.0, -n / 2.0)) / (n + 4.0), 1e-6);
    }
}

static void test_bp_energy(void)
{
    /* Paper examples ([Lag13]): porosity 0..0.3 with Sp 1.3, and 0.35 with Sp 2. */
    const double por[] = {0.0, 0.1, 0.2, 0.3, 0.35};
    const double sps[] = {1.3, 1.3, 1.3, 1.3, 2.0};
    double worst_of[2] = {0.0, 0.0};
    for (int norm = 0; norm < 2; ++norm) {
        double worst = 0.0, at_t = 0.0;
        for (int a = 0; a < 5; ++a)
            for (int fi = 0; fi <= 2; ++fi)
                for (int t = 0; t <= 6; ++t) {
                    soak_porous_params p = porous_paper_params(por[a], sps[a]);
                    p.norm = (soak_blinn_norm)norm;
                    bp_ctx ctx = {&p, fi / 2.0};
                    double th = (t < 6 ? t * 15.0 : 89.0) * SOAK_PI / 180.0;
                    double E = dir_albedo(bp_fn, &ctx, th, 0.02);
                    if (E > worst) {
                        worst = E;
                        at_t = th;
                    }
                }
        printf("info: Blinn-Phong wet porous, paper parameters, %s normalisation: max directional albedo "
               "%.6f (theta_i %.0f deg)\n",
               norm ? "[Lag13] (n+2)/(2pi)" : "energy 1/A(n)", worst, at_t * 180.0 / SOAK_PI);
        worst_of[norm] = worst;
    }
    check_true("Blinn-Phong, paper parameters, energy normalisation: albedo <= 1", worst_of[0] <= 1.0);
    /* The [Lag13] lobe exceeds 1 alone for large n (closed form above), but
     * with the paper's small Ks the whole model stays below 1: asserted in
     * every case, not only where it holds. */
    check_true("Blinn-Phong, paper parameters, [Lag13] normalisation: albedo <= 1", worst_of[1] <= 1.0);
    /* (n+2)/(2pi) A(n) = 4 (n + 2^(-n/2)) / (n+4) >= 1 for n >= 0: the [Lag13] lobe is the brighter. */
    check_true("[Lag13] normalisation brighter than the energy one", worst_of[1] > worst_of[0]);
}

static void test_bp_identities(tu_rng *rng)
{
    double worst = 0.0, worst_dry = 0.0;
    for (int s = 0; s < 20000; ++s) {
        soak_porous_params p = {0.9 * tu_uniform(rng),   0.0,
                                tu_uniform(rng),         300.0 * tu_uniform(rng),
                                tu_uniform(rng),         50.0 * tu_uniform(rng),
                                SOAK_POROUS_KS_WATER_MAX * tu_uniform(rng), 300.0 * tu_uniform(rng),
                                (soak_blinn_norm)(s & 1)};
        p.ks = (1.0 - p.kd) * tu_uniform(rng);
        double fill = tu_uniform(rng);
        soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = tu_upper_dir(rng, 1e-6);
        double f1, f2;
        soak_porous_eval(&p, fill, wi, wo, &f1);
        soak_porous_eval(&p, fill, wo, wi, &f2);
        worst = fmax(worst, fabs(f1 - f2) / fmax(f1, 1e-300));
        p.porosity = 0.0;
        soak_porous_eval(&p, fill, wi, wo, &f1);
        soak_porous_eval(&p, 0.0, wi, wo, &f2);
        worst_dry = fmax(worst_dry, fabs(f1 - f2));
    }
    check_close("Blinn-Phong porous reciprocity, 2e4 random pairs: max rel diff", worst, 0.0, 1e-12);
    check_close("porosity 0: wet == dry for any fill (max |diff|)", worst_dry, 0.0, 0.0);

    /* Diffuse white-sky albedo: porosity 0 gives k_d exactly; otherwise
     * compare with a midpoint-rule double integral here. */
    soak_porous_params p = porous_paper_params(0.0, 1.3);
    double alb = NAN, fac = NAN;
    soak_porous_albedo_factor(&p, 0.7, &alb, &fac);
    check_rel("porosity 0: diffuse albedo = k_d", alb, p.kd, 1e-12);
    check_close("porosity 0: darkening factor 1", fac, 1.0, 1e-12);
    p = porous_paper_params(0.3, 1.3);
    double ref[2];
    for (int w = 0; w < 2; ++w) {
        double sum = 0.0;
        const int n = 400;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                double mi = (i + 0.5) / n, mo = (j + 0.5) / n;
                soak_porous_coeffs c;
                soak_porous_coeffs_eval(&p, w ? 1.0 : 0.0, soak_v3(sqrt(1 - mi * mi), 0, mi),
                                        soak_v3(-sqrt(1 - mo * mo), 0, mo), &c);
                sum += c.kd_wet * mi * mo;
            }
        ref[w] = 4.0 * sum / ((double)n * n);
    }
    soak_porous_albedo_factor(&p, 1.0, &alb, &fac);
    check_rel("porous diffuse white-sky albedo at fill 1 vs midpoint rule", alb, ref[1], 1e-5);
    check_rel("darkening factor at fill 1 vs midpoint rule", fac, ref[1] / ref[0], 1e-5);
    double fac_half = NAN;
    soak_porous_albedo_factor(&p, 0.5, NULL, &fac_half);
    check_rel("darkening factor linear in fill", fac_half, 0.5 * (1.0 + fac), 1e-12);
    printf("info: paper parameters, porosity 0.3: diffuse albedo dry %.5f, full %.5f, factor %.5f\n", ref[0],
           ref[1], fac);
}

/* ---- GGX variant ---- */

static void test_ggx_energy(void)
{
    const double rough[] = {0.05, 0.4, 1.0};
    const double por[] = {0.0, 0.35, 1.0};
    double worst = 0.0, worst_fit = 0.0, worst_tab = 0.0;
    for (int r = 0; r < 3; ++r) {
        soak_porous_ggx_params p = {1.0, rough[r], 1.5, 0.0, 1.3, 0.02, 1.33};
        for (int a = 0; a < 3; ++a) {
            p.porosity = por[a];
            soak_porous_ggx c;
            if (check_status("ggx setup", soak_porous_ggx_setup(&p, &c), SOAK_OK) == 0) continue;
            for (int fi = 0; fi <= 2; ++fi)
                for (int t = 0; t < 6; ++t) {
                    double th = (t < 5 ? t * 20.0 : 89.0) * SOAK_PI / 180.0;
                    ggx_ctx ctx = {&c, fi / 2.0};
                    double E = dir_albedo(ggx_fn, &ctx, th, 0.005);
                    worst = fmax(worst, E);
                    /* porosity 0 and albedo 1: rho_eff = 1, so E = 1 up to the table error */
                    if (a == 0) worst_fit = fmax(worst_fit, fabs(E - 1.0));
                    /* specular albedo table vs quadrature (albedo 0 kills D) */
                    if (t % 2 == 0) {
                        soak_porous_ggx c0 = c;
                        c0.p.albedo = 0.0;
                        c0.r_wall = 0.0;
                        ggx_ctx ctx0 = {&c0, fi / 2.0};
                        double Es = dir_albedo(ggx_fn, &ctx0, th, 0.005), Et = NAN;
                        soak_porous_ggx_spec_albedo(&c, fi / 2.0, cos(th), &Et);
                        worst_tab = fmax(worst_tab, fabs(Es - Et));
                    }
                }
        }
    }
    check_true("GGX porous: directional albedo <= 1 + 1e-5 at every angle, fill, porosity", worst <= 1.0 + 1e-5);
    printf("info: GGX porous max directional albedo %.7f\n", worst);
    check_close("GGX porous, porosity 0, albedo 1: directional albedo = 1 (max |E-1|)", worst_fit, 0.0, 1e-5);
    check_close("specular albedo table vs panel quadrature (max |diff|)", worst_tab, 0.0, 1e-5);
}

static void test_ggx_identities(tu_rng *rng)
{
    double worst = 0.0, worst_dry = 0.0;
    for (int s = 0; s < 40; ++s) {
        soak_porous_ggx_params p = {
            tu_uniform(rng),        1e-3 + tu_uniform(rng), 1.0 + 2.0 * tu_uniform(rng), tu_uniform(rng),
            50.0 * tu_uniform(rng), 1e-3 + tu_uniform(rng), 1.0 + 2.0 * tu_uniform(rng)};
        p.roughness = fmin(p.roughness, 1.0);
        p.water_roughness = fmin(p.water_roughness, 1.0);
        soak_porous_ggx c, c0;
        soak_porous_ggx_setup(&p, &c);
        p.porosity = 0.0;
        soak_porous_ggx_setup(&p, &c0);
        for (int k = 0; k < 500; ++k) {
            double fill = tu_uniform(rng);
            soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = tu_upper_dir(rng, 1e-6);
            double f1, f2;
            soak_porous_ggx_eval(&c, fill, wi, wo, &f1);
            soak_porous_ggx_eval(&c, fill, wo, wi, &f2);
            worst = fmax(worst, fabs(f1 - f2) / fmax(f1, 1e-300));
            soak_porous_ggx_eval(&c0, fill, wi, wo, &f1);
            soak_porous_ggx_eval(&c0, 0.0, wi, wo, &f2);
            worst_dry = fmax(worst_dry, fabs(f1 - f2));
        }
    }
    check_close("GGX porous reciprocity, 2e4 random pairs: max rel diff", worst, 0.0, 1e-12);
    check_close("GGX porous, porosity 0: wet == dry for any fill", worst_dry, 0.0, 0.0);

    /* No specular interfaces (eta = eta_water = 1): D is all there is. White-sky
     * albedo and darkening factor by a midpoint rule over (mu_i, mu_o, phi). */
    soak_porous_ggx_params p = {0.8, 0.3, 1.0, 0.4, 1.3, 0.05, 1.0};
    soak_porous_ggx c;
    soak_porous_ggx_setup(&p, &c);
    double ref[2];
    for (int w = 0; w < 2; ++w) {
        double sum = 0.0;
        const int n = 120, nphi = 8;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < nphi; ++k) {
                    double mi = (i + 0.5) / n, mo = (j + 0.5) / n, ph = 2.0 * SOAK_PI * (k + 0.5) / nphi;
                    double so = sqrt(1 - mo * mo), f = NAN;
                    soak_porous_ggx_eval(&c, w ? 1.0 : 0.0, soak_v3(sqrt(1 - mi * mi), 0, mi),
                                         soak_v3(so * cos(ph), so * sin(ph), mo), &f);
                    sum += f * mi * mo;
                }
        ref[w] = 4.0 * SOAK_PI * sum / ((double)n * n * nphi);
    }
    double alb = NAN, fac = NAN;
    soak_porous_ggx_albedo_factor(&c, 1.0, &alb, &fac);
    check_rel("GGX porous diffuse white-sky albedo at fill 1 vs midpoint rule", alb, ref[1], 1e-4);
    check_rel("GGX porous darkening factor vs midpoint rule", fac, ref[1] / ref[0], 1e-4);
    p.porosity = 0.0;
    soak_porous_ggx_setup(&p, &c);
    soak_porous_ggx_albedo_factor(&c, 0.6, &alb, &fac);
    check_rel("GGX, no interfaces, porosity 0: diffuse albedo = albedo", alb, 0.8, 1e-12);
    check_close("GGX porosity 0: factor 1", fac, 1.0, 1e-12);
}

/* ---- sampling ---- */

static double bp_pdf_fn(const void *ctx, soak_vec3 wi, soak_vec3 wo)
{
    const bp_ctx *c = ctx;
    double pdf = NAN;
    soak_porous_pdf(c->p, c->fill, wi, wo, &pdf);
    return pdf / wo.z;
}

static double ggx_pdf_fn(const void *ctx, soak_vec3 wi, soak_vec3 wo)
{
    const ggx_ctx *c = ctx;
    double pdf = NAN;
    soak_porous_ggx_pdf(c->c, c->fill, wi, wo, &pdf);
    return pdf / wo.z;
}

/* One sampler checked three ways at one wi: (1) sample's f and pdf equal
 * eval and pdf at the returned direction; (2) the fraction of valid samples
 * equals the quadrature of the pdf over the hemisphere; (3) the estimator
 * mean(f cos / pdf) equals the quadrature albedo (within 5 sigma). */
typedef soak_status (*sample_fn)(const void *ctx, soak_vec3 wi, double ul, double u1, double u2, soak_vec3 *wo,
                                 double *f, double *pdf);
typedef soak_status (*point_fn)(const void *ctx, soak_vec3 wi, soak_vec3 wo, double *v);

static soak_status bp_sample(const void *ctx, soak_vec3 wi, double ul, double u1, double u2, soak_vec3 *wo,
                             double *f, double *pdf)
{
    const bp_ctx *c = ctx;
    return soak_porous_sample(c->p, c->fill, wi, ul, u1, u2, wo, f, pdf);
}
static soak_status bp_eval(const void *ctx, soak_vec3 wi, soak_vec3 wo, double *v)
{
    const bp_ctx *c = ctx;
    return soak_porous_eval(c->p, c->fill, wi, wo, v);
}
static soak_status bp_pdf(const void *ctx, soak_vec3 wi, soak_vec3 wo, double *v)
{
    const bp_ctx *c = ctx;
    return soak_porous_pdf(c->p, c->fill, wi, wo, v);
}
static soak_status ggx_sample(const void *ctx, soak_vec3 wi, double ul, double u1, double u2, soak_vec3 *wo,
                              double *f, double *pdf)
{
    const ggx_ctx *c = ctx;
    return soak_porous_ggx_sample(c->c, c->fill, wi, ul, u1, u2, wo, f, pdf);
}
static soak_status ggx_eval(const void *ctx, soak_vec3 wi, soak_vec3 wo, double *v)
{
    const ggx_ctx *c = ctx;
    return soak_porous_ggx_eval(c->c, c->fill, wi, wo, v);
}
static soak_status ggx_pdf(const void *ctx, soak_vec3 wi, soak_vec3 wo, double *v)
{
    const ggx_ctx *c = ctx;
    return soak_porous_ggx_pdf(c->c, c->fill, wi, wo, v);
}

static void check_sampler(const char *name, const void *ctx, sample_fn sample, point_fn eval, point_fn pdf,
                          brdf_fn f_quad, brdf_fn pdf_quad, double theta_i, double width, tu_rng *rng)
{
    soak_vec3 wi = soak_v3_polar(theta_i, 0.0);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0, worst = 0.0;
    int valid = 0;
    for (int k = 0; k < n; ++k) {
        soak_vec3 wo;
        double f, p;
        if (sample(ctx, wi, tu_uniform(rng), tu_uniform(rng), tu_uniform(rng), &wo, &f, &p) != SOAK_OK) {
            worst = INFINITY;
            continue;
        }
        if (!(p > 0.0)) continue;
        ++valid;
        double est = f * wo.z / p;
        sum += est;
        sum2 += est * est;
        if (k % 200 == 0) {
            double fe, pe;
            eval(ctx, wi, wo, &fe);
            pdf(ctx, wi, wo, &pe);
            worst = fmax(worst, fmax(fabs(fe - f) / fmax(fe, 1e-300), fabs(pe - p) / pe));
        }
    }
    char what[200];
    snprintf(what, sizeof what, "%s theta_i %.0f: sample f, pdf == eval, pdf (max rel)", name,
             theta_i * 180.0 / SOAK_PI);
    check_close(what, worst, 0.0, 1e-12);
    double mass = dir_albedo(pdf_quad, ctx, theta_i, width);
    double frac = (double)valid / n, sig_frac = sqrt(mass * (1.0 - mass) / n) + 1e-9;
    snprintf(what, sizeof what, "%s theta_i %.0f: fraction of valid samples vs quadrature of pdf (5 sigma)", name,
             theta_i * 180.0 / SOAK_PI);
    check_close(what, frac, mass, 5.0 * sig_frac);
    check_true("pdf integrates to <= 1", mass <= 1.0 + 1e-6);
    double mean = sum / n, sig = sqrt(fmax(sum2 / n - mean * mean, 0.0) / n) + 1e-9;
    double E = dir_albedo(f_quad, ctx, theta_i, width);
    snprintf(what, sizeof what, "%s theta_i %.0f: MC albedo vs quadrature (5 sigma = %.2g)", name,
             theta_i * 180.0 / SOAK_PI, 5.0 * sig);
    check_close(what, mean, E, 5.0 * sig);
}

static void test_sampling(tu_rng *rng)
{
    const double th[] = {10.0, 60.0, 85.0};
    soak_porous_params p = porous_paper_params(0.3, 1.3);
    p.ks_water = 0.5; /* make the water lobe matter */
    bp_ctx bctx = {&p, 0.6};
    soak_porous_ggx_params g = {0.7, 0.3, 1.5, 0.5, 1.3, 0.05, 1.33};
    soak_porous_ggx c;
    soak_porous_ggx_setup(&g, &c);
    ggx_ctx gctx = {&c, 0.6};
    for (int t = 0; t < 3; ++t) {
        double ti = th[t] * SOAK_PI / 180.0;
        check_sampler("Blinn-Phong porous", &bctx, bp_sample, bp_eval, bp_pdf, bp_fn, bp_pdf_fn, ti, 0.01, rng);
        check_sampler("GGX porous", &gctx, ggx_sample, ggx_eval, ggx_pdf, ggx_fn, ggx_pdf_fn, ti, 0.01, rng);
    }
}

/* ---- validation and robustness ---- */

int main(void)
{
    tu_rng rng = tu_splitmix64(0x2545F4914F6CDD1Dull);
    tu_gauss_legendre_unit(8, 8, gx, gw);
    test_Ap();
    test_fill();
    test_Gp();
    test_nb();
    test_forms(&rng);
    test_bp_norm();
    test_bp_energy();
    test_bp_identities(&rng);
    test_ggx_energy();
    test_ggx_identities(&rng);
    test_sampling(&rng);
    return check_finish();
}
