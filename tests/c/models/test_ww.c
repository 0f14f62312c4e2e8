/* Weidlich-Wilkie water-over-base BRDF and its Tri-Ace fast paths.
 * References used here, all independent of the code under test:
 *  - the formula rebuilt from Snell angles, soak/fresnel.h and soak/ggx.h;
 *  - reciprocity; n_water = 1 equals the base BRDF;
 *  - directional albedo by Gauss-Legendre quadrature over the air
 *    hemisphere, <= 1 - F12 (derivation in soak/ww.h), and for a Lambertian
 *    base the flux result T12 (1 - Rint) with 1 - Rint = (1 - R_avg(n)) / n^2;
 *  - Monte Carlo albedo from soak_ww_sample against that quadrature;
 *  - Tri-Ace fast paths: exact identities at normal incidence, Taylor bound
 *    of the linear absorption, and the refraction fit residual.
 * The fast-path accuracy table on the fixed angle grid is printed. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/fresnel.h"
#include "soak/ggx.h"
#include "soak/ww.h"

#define DEG (SOAK_PI / 180.0)

/* 16-point Gauss-Legendre (positive half) on [-1,1], filled once in main. */
static double gx[8], gw[8];

/* Nodes and weights of composite 16-point GL on [a,b] with n panels. */
static int gl_nodes(double a, double b, int n, double *x, double *w)
{
    int k = 0;
    double h = (b - a) / n;
    for (int p = 0; p < n; ++p) {
        double mid = a + (p + 0.5) * h, half = 0.5 * h;
        for (int i = 0; i < 8; ++i) {
            x[k] = mid - half * gx[i];
            w[k++] = half * gw[i];
            x[k] = mid + half * gx[i];
            w[k++] = half * gw[i];
        }
    }
    return k;
}

/* Directional albedo of the non-delta part, int f cos_o dw_o over the air
 * hemisphere, wi in the plane phi = 0 (the integrand is symmetric in phi, so
 * phi in [0, pi] is doubled). The integrand is smooth in (theta_o, phi): the
 * exit transmission vanishes like cos_o at the horizon. */
#define NT (40 * 16)
#define NPH (24 * 16)
static double albedo_quad(const soak_ww *m, double cos_i)
{
    static double tx[NT], tw[NT], px[NPH], pw[NPH];
    int nt = gl_nodes(0.0, 0.5 * SOAK_PI, NT / 16, tx, tw);
    int np = gl_nodes(0.0, SOAK_PI, NPH / 16, px, pw);
    soak_vec3 wi = soak_v3(sqrt(1.0 - cos_i * cos_i), 0.0, cos_i);
    double sum = 0.0;
    for (int a = 0; a < nt; ++a) {
        double st = sin(tx[a]), ct = cos(tx[a]), row = 0.0;
        for (int b = 0; b < np; ++b) {
            double f = 0.0;
            soak_ww_eval(m, wi, soak_v3(st * cos(px[b]), st * sin(px[b]), ct), &f);
            row += pw[b] * f;
        }
        sum += tw[a] * row * ct * st;
    }
    return 2.0 * sum;
}

static soak_ww dielectric(double n_water, double n_base, double alpha, double kd)
{
    soak_ww m;
    soak_ww_default(&m);
    m.n_water = n_water;
    m.n_base = n_base;
    m.alpha = alpha;
    m.kd = kd;
    return m;
}
static soak_ww conductor(double n_water, double n, double k, double alpha)
{
    soak_ww m;
    soak_ww_default(&m);
    m.base = SOAK_WW_CONDUCTOR;
    m.n_water = n_water;
    m.n_base = n;
    m.k_base = k;
    m.alpha = alpha;
    m.kd = 0.0;
    return m;
}

/* The model rebuilt from angles: Snell sin_t = sin_i / n, base from the
 * public GGX/Fresnel API with indices relative to water, /n^2. */
static double ww_ref(const soak_ww *m, soak_vec3 wi, soak_vec3 wo)
{
    double n = m->n_water;
    double ti = acos(wi.z), to = acos(wo.z);
    double pi_ = atan2(wi.y, wi.x), po = atan2(wo.y, wo.x);
    double ti_w = asin(sin(ti) / n), to_w = asin(sin(to) / n);
    soak_vec3 a = soak_v3_polar(ti_w, pi_), b = soak_v3_polar(to_w, po);
    double Fi, Fo, T21o, fb = 0.0;
    soak_fresnel_dielectric(wi.z, n, &Fi, NULL);
    soak_fresnel_dielectric(wo.z, n, &Fo, NULL);
    soak_fresnel_dielectric(cos(to_w), 1.0 / n, &T21o, NULL);
    T21o = 1.0 - T21o; /* computed from the inside, independently of Fo */
    if (m->base == SOAK_WW_CONDUCTOR) {
        soak_ggx_brdf_conductor(m->alpha, m->n_base / n, m->k_base / n, a, b, &fb);
    } else {
        double spec, F3i, F3o;
        soak_ggx_brdf_dielectric(m->alpha, m->n_base / n, a, b, &spec);
        soak_fresnel_dielectric(a.z, m->n_base / n, &F3i, NULL);
        soak_fresnel_dielectric(b.z, m->n_base / n, &F3o, NULL);
        fb = spec + m->kd / SOAK_PI * (1.0 - F3i) * (1.0 - F3o);
    }
    double tau = m->absorption * m->thickness;
    double att = exp(-tau * (1.0 / a.z + 1.0 / b.z));
    return (1.0 - Fi) * fb * att * T21o / (n * n);
}

static void test_formula_and_reciprocity(tu_rng *rng)
{
    soak_rgb cn, ck;
    soak_ww_copper(&cn, &ck);
    soak_ww mats[5];
    mats[0] = dielectric(1.33, 1.5, 0.3, 0.5);
    mats[1] = dielectric(1.33, 1.2, 0.05, 0.8); /* base index below water: eta < 1 inside */
    mats[2] = conductor(1.33, cn.r, ck.r, 0.2);
    mats[3] = conductor(1.33, cn.b, ck.b, 1.0);
    mats[4] = dielectric(2.0, 3.0, 1e-3, 1.0);
    mats[0].absorption = 3.5e-3; /* [Lag13] red, per cm */
    mats[0].thickness = 50.0;
    double worst_ref = 0.0, worst_rec = 0.0;
    for (int k = 0; k < 5; ++k)
        for (int s = 0; s < 20000; ++s) {
            soak_vec3 wi = tu_upper_dir(rng, 1e-3), wo = tu_upper_dir(rng, 1e-3);
            double f, g;
            soak_ww_eval(&mats[k], wi, wo, &f);
            soak_ww_eval(&mats[k], wo, wi, &g);
            double r = ww_ref(&mats[k], wi, wo);
            if (r > 1e-300) worst_ref = fmax(worst_ref, fabs(f - r) / r);
            if (f > 1e-300) worst_rec = fmax(worst_rec, fabs(f - g) / f);
        }
    check_close("max rel |f - angle-based rebuild| (5 materials, 1e5 pairs)", worst_ref, 0.0, 1e-9);
    check_close("max rel |f(wi,wo) - f(wo,wi)| (5 materials, 1e5 pairs)", worst_rec, 0.0, 1e-12);

    /* Grazing on both sides: finite and reciprocal. */
    soak_vec3 g1 = soak_v3(sqrt(1.0 - 1e-12), 0.0, 1e-6), g2 = soak_v3(0.0, -sqrt(1.0 - 1e-12), 1e-6);
    double f, g;
    for (int k = 0; k < 5; ++k) {
        check_status("grazing eval", soak_ww_eval(&mats[k], g1, g2, &f), SOAK_OK);
        soak_ww_eval(&mats[k], g2, g1, &g);
        check_true("grazing finite, reciprocal", soak_is_finite(f) && f >= 0.0 && fabs(f - g) <= 1e-12 * f);
    }
}

static void test_no_interface(tu_rng *rng)
{
    /* n_water = 1: f must equal the base BRDF in air (thickness 0 -> a = 1). */
    soak_rgb cn, ck;
    soak_ww_copper(&cn, &ck);
    double worst = 0.0, worst_abs = 0.0;
    for (int s = 0; s < 20000; ++s) {
        soak_vec3 wi = tu_upper_dir(rng, 1e-6), wo = tu_upper_dir(rng, 1e-6);
        soak_ww md = dielectric(1.0, 1.0 + 2.0 * tu_uniform(rng), 1e-3 + 0.999 * tu_uniform(rng), tu_uniform(rng));
        soak_ww mc = conductor(1.0, cn.g, ck.g, 1e-3 + tu_uniform(rng) * 0.999);
        double f, spec, Fi, Fo, want;
        soak_ww_eval(&md, wi, wo, &f);
        soak_ggx_brdf_dielectric(md.alpha, md.n_base, wi, wo, &spec);
        soak_fresnel_dielectric(wi.z, md.n_base, &Fi, NULL);
        soak_fresnel_dielectric(wo.z, md.n_base, &Fo, NULL);
        want = spec + md.kd / SOAK_PI * (1.0 - Fi) * (1.0 - Fo);
        worst = fmax(worst, fabs(f - want) / want);
        soak_ww_eval(&mc, wi, wo, &f);
        soak_ggx_brdf_conductor(mc.alpha, mc.n_base, mc.k_base, wi, wo, &want);
        if (want > 0.0) worst = fmax(worst, fabs(f - want) / want);
        /* With absorption but no interface: base * exp(-tau (1/cos_i + 1/cos_o)). */
        mc.absorption = 0.2;
        mc.thickness = 0.5;
        soak_ww_eval(&mc, wi, wo, &f);
        double att = exp(-0.1 * (1.0 / wi.z + 1.0 / wo.z));
        worst_abs = fmax(worst_abs, fabs(f - want * att) / fmax(want * att, 1e-300));
    }
    check_close("n_water = 1: max rel |f - base| (dielectric + copper G)", worst, 0.0, 1e-13);
    check_close("n_water = 1, absorbing: max rel |f - base e^-tau(..)|", worst_abs, 0.0, 1e-12);
    soak_ww m = dielectric(1.0, 1.5, 0.3, 0.5);
    double R;
    soak_ww_specular(&m, 0.3, &R);
    check_close("n_water = 1: no mirror lobe", R, 0.0, 0.0);
}

static void test_energy(void)
{
    /* Lambertian base (n_base = n_water: no base interface, kd = 1): the
     * flux argument gives albedo = T12(cos_i) (1 - R_avg(n)) / n^2. */
    soak_ww lam = dielectric(1.33, 1.33, 0.5, 1.0);
    double Ravg;
    soak_fresnel_dielectric_avg(1.33, &Ravg);
    const double cl[] = {1.0, 0.5, 0.05};
    for (int i = 0; i < 3; ++i) {
        double F12;
        soak_ww_specular(&lam, cl[i], &F12);
        double want = (1.0 - F12) * (1.0 - Ravg) / (1.33 * 1.33);
        char what[96];
        snprintf(what, sizeof what, "Lambertian under water: albedo = T12 (1-Ravg)/n^2, cos_i %g", cl[i]);
        check_rel(what, albedo_quad(&lam, cl[i]), want, 1e-9);
    }

    soak_rgb cn, ck;
    soak_ww_copper(&cn, &ck);
    soak_ww mats[6];
    const char *names[6] = {"dielectric n1.5 a0.05 kd1", "dielectric n1.5 a1 kd1", "dielectric n1.2 a0.3 kd1",
                            "copper R a0.05", "mirror-like conductor k100 a0.05", "dielectric n3 water2 a0.3 kd1"};
    mats[0] = dielectric(1.33, 1.5, 0.05, 1.0);
    mats[1] = dielectric(1.33, 1.5, 1.0, 1.0);
    mats[2] = dielectric(1.33, 1.2, 0.3, 1.0);
    mats[3] = conductor(1.33, cn.r, ck.r, 0.05);
    mats[4] = conductor(1.33, 1.0, 100.0, 0.05);
    mats[5] = dielectric(2.0, 3.0, 0.3, 1.0);
    const double cosines[] = {1e-6, 0.01, 0.1, 0.5, 0.8, 1.0};
    double worst_excess = -1.0, max_total = 0.0;
    for (int k = 0; k < 6; ++k)
        for (int c = 0; c < 6; ++c) {
            double F12, E = albedo_quad(&mats[k], cosines[c]);
            soak_ww_specular(&mats[k], cosines[c], &F12);
            worst_excess = fmax(worst_excess, E - (1.0 - F12));
            max_total = fmax(max_total, E + F12);
            if (c == 5) printf("     albedo %-36s cos_i 1: non-delta %.6f + mirror %.6f\n", names[k], E, F12);
        }
    check_true("non-delta albedo <= 1 - F12 (= T12) at every angle incl. cos 1e-6", worst_excess <= 1e-9);
    check_true("total albedo <= 1", max_total <= 1.0 + 1e-9);
    printf("     max total albedo over grid %.9f, max (E - T12) %.3g\n", max_total, worst_excess);

    /* The base alone (n_water = 1) must conserve energy too, kd = 1. */
    soak_ww dry = dielectric(1.0, 1.5, 0.3, 1.0);
    double worst_dry = 0.0;
    for (int c = 0; c < 6; ++c) worst_dry = fmax(worst_dry, albedo_quad(&dry, cosines[c]));
    check_true("base alone (n_water 1, kd 1, n 1.5, alpha 0.3): albedo <= 1", worst_dry <= 1.0 + 1e-9);
    printf("     base alone max albedo %.6f\n", worst_dry);
}

static void test_sampling(tu_rng *rng)
{
    soak_rgb cn, ck;
    soak_ww_copper(&cn, &ck);
    soak_ww mats[3];
    mats[0] = dielectric(1.33, 1.5, 0.3, 0.5);
    mats[1] = conductor(1.33, cn.r, ck.r, 0.15);
    mats[2] = dielectric(1.33, 1.5, 0.7, 0.9);
    mats[2].absorption = 1.0;
    mats[2].thickness = 0.1;
    const double cosines[] = {0.9, 0.4};
    for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 2; ++c) {
            double co = cosines[c];
            soak_vec3 wo = soak_v3(sqrt(1.0 - co * co), 0.0, co);
            double F12;
            soak_ww_specular(&mats[k], co, &F12);
            double want = albedo_quad(&mats[k], co) + F12; /* reciprocity: albedo at wo */
            const int n = 200000;
            double sum = 0.0, sum2 = 0.0;
            int pdf_bad = 0;
            for (int s = 0; s < n; ++s) {
                soak_vec3 wi;
                double w, pdf;
                int delta;
                soak_ww_sample(&mats[k], wo, tu_uniform(rng), tu_uniform(rng), tu_uniform(rng), &wi, &w, &pdf, &delta);
                sum += w;
                sum2 += w * w;
                if (!delta && w > 0.0) {
                    double f;
                    soak_ww_eval(&mats[k], wi, wo, &f);
                    if (!(fabs(w * pdf - f * wi.z) <= 1e-9 * f * wi.z)) ++pdf_bad;
                }
            }
            double mean = sum / n, sd = sqrt(fmax(0.0, sum2 / n - mean * mean) / n);
            char what[128];
            snprintf(what, sizeof what, "sampled albedo vs quadrature (4 sigma = %.2g), material %d, cos_o %g",
                     4.0 * sd, k, co);
            check_close(what, mean, want, 4.0 * sd + 1e-6);
            check_true("sample weight * pdf = f cos_i", pdf_bad == 0);
        }
}

/* ---- Tri-Ace fast paths ---- */

static void test_fbottom(void)
{
    const double n3s[] = {1.0, 1.2, 1.5, 1.55, 2.4};
    for (int i = 0; i < 5; ++i) {
        double Fb, F21, F23;
        soak_triace_fbottom_dielectric(1.33, n3s[i], &Fb);
        soak_fresnel_dielectric(1.0, 1.0 / 1.33, &F21, NULL);
        soak_fresnel_dielectric(1.0, n3s[i] / 1.33, &F23, NULL);
        char what[96];
        snprintf(what, sizeof what, "F_bottom = (1-F21) F23 at normal incidence, n3 %g", n3s[i]);
        check_close(what, Fb, (1.0 - F21) * F23, 1e-15);
    }
    soak_rgb cn, ck;
    soak_ww_copper(&cn, &ck);
    for (int c = 0; c < 4; ++c) {
        double n3 = c < 3 ? soak_rgb_at(cn, c) : 1.65, k3 = c < 3 ? soak_rgb_at(ck, c) : 9.22; /* Al red, [Lag13] */
        double Fb, F21, F23;
        soak_triace_fbottom_conductor(1.33, n3, k3, &Fb);
        soak_fresnel_dielectric(1.0, 1.0 / 1.33, &F21, NULL);
        soak_fresnel_conductor(1.0, n3 / 1.33, k3 / 1.33, &F23);
        char what[96];
        snprintf(what, sizeof what, "F_bottom conductor = (1-F21) F23 at normal incidence, n3 %g k3 %g", n3, k3);
        check_rel(what, Fb, (1.0 - F21) * F23, 1e-13);
    }
    double Fb, Fd;
    soak_triace_fbottom_conductor(1.33, 1.5, 0.0, &Fb);
    soak_triace_fbottom_dielectric(1.33, 1.5, &Fd);
    check_close("conductor form with k = 0 equals dielectric form", Fb, Fd, 1e-16);
    soak_triace_fbottom_dielectric(1.33, 1.33, &Fd);
    check_close("n3 = n2: no base interface, F_bottom = 0", Fd, 0.0, 0.0);
}

static void test_absorption_linear(tu_rng *rng)
{
    int neg = 0, taylor_bad = 0;
    double worst_first_order = 0.0;
    for (int s = 0; s < 100000; ++s) {
        double ap = s % 2 ? 1e-4 * tu_uniform(rng) : 2.0 * tu_uniform(rng);
        double cl = 1e-3 + (1.0 - 1e-3) * tu_uniform(rng), cv = 1e-3 + (1.0 - 1e-3) * tu_uniform(rng), a;
        soak_triace_absorption_linear(ap, cl, cv, &a);
        if (a < 0.0) ++neg;
        double x = ap * (1.0 / cl + 1.0 / cv), e = exp(-x);
        /* exp(-x) - (1 - x) lies in [0, x^2/2] (alternating Taylor series). */
        if (x <= 1.0 && !(e - a >= -1e-15 && e - a <= 0.5 * x * x + 1e-15)) ++taylor_bad;
        if (x > 1e-4 && x < 1e-3) worst_first_order = fmax(worst_first_order, fabs(a - e) / (x * x));
    }
    check_true("linear absorption >= 0", neg == 0);
    check_true("0 <= exp(-x) - a_lin <= x^2/2 for x <= 1", taylor_bad == 0);
    check_true("a_lin = exp form to first order: |diff| / x^2 <= 1/2, 1e-4 < x < 1e-3", worst_first_order <= 0.5 + 1e-6);
    double a;
    soak_triace_absorption_linear(0.0, 1e-300, 1e-300, &a);
    check_close("alpha' = 0 gives a = 1 even at grazing", a, 1.0, 0.0);
    soak_triace_absorption_linear(0.3, 0.5, 0.5, &a);
    check_close("a_lin clamps at 0 (1 - 0.3*4 < 0)", a, 0.0, 0.0);
}

/* Angle between the polynomial refraction and Snell's law, theta_i on a grid. */
static void test_refract(void)
{
    const double eta = 1.0 / 1.33;
    /* Bound from the fit: the polynomial replaces p(c) = eta c - cos_t, with
     * residual r(c) = poly(c) - p(c). t differs from the exact t0 (|t0| = 1)
     * by r n, so the angle is at most asin(|r| sin_t) ~ |r| eta sin_i. The
     * residual is measured here on a fine c grid, independently of the code. */
    double rmax = 0.0, bound = 0.0;
    for (int k = 0; k <= 100000; ++k) {
        double c = k / 100000.0, s = sqrt(1.0 - c * c);
        double poly = (-0.34853799144237796 * c + 0.7518796992481197) * c - 0.666308423880957;
        double r = fabs(poly - (eta * c - sqrt(1.0 - eta * eta * (1.0 - c * c))));
        rmax = fmax(rmax, r);
        bound = fmax(bound, asin(fmin(1.0, r * eta * s)));
    }
    double worst = 0.0, len_min = 2.0, len_max = 0.0;
    for (int k = 0; k <= 900; ++k) {
        double th = k * 0.1 * DEG;
        soak_vec3 i = soak_v3(sin(th), 0.0, -cos(th)), n = soak_v3(0.0, 0.0, 1.0), t;
        soak_refract_1_33(i, n, &t);
        double tt = asin(sin(th) * eta);
        soak_vec3 t0 = soak_v3(sin(tt), 0.0, -cos(tt));
        double l = soak_v3_len(t);
        len_min = fmin(len_min, l);
        len_max = fmax(len_max, l);
        double cang = fmin(1.0, soak_v3_dot(t, t0) / l);
        worst = fmax(worst, acos(cang));
    }
    printf("     refract_1_33: fit residual max %.4f, |t| in [%.4f, %.4f], max angle %.4f deg (bound %.4f deg)\n",
           rmax, len_min, len_max, worst / DEG, bound / DEG);
    check_true("refract_1_33 max angular error <= residual bound", worst <= bound * (1.0 + 1e-6) + 1e-12);
    check_true("refract_1_33 max angular error < 1 degree", worst < 1.0 * DEG);
    soak_vec3 t;
    soak_refract_1_33(soak_v3(0.0, 0.0, -1.0), soak_v3(0.0, 0.0, 1.0), &t);
    check_close("normal incidence: no bending (x)", t.x, 0.0, 0.0);
    check_true("normal incidence: points into the water", t.z < 0.0);
}

/* Exact pieces inside the water for the error table. */
static void exact_pieces(const soak_ww *m, soak_vec3 wi, soak_vec3 wo, double *T21o_F23, double *cos_i_w,
                         double *cos_o_w)
{
    double n = m->n_water;
    double si = sqrt(1.0 - wi.z * wi.z) / n, so = sqrt(1.0 - wo.z * wo.z) / n;
    double pi_ = atan2(wi.y, wi.x), po = atan2(wo.y, wo.x);
    soak_vec3 a = soak_v3(si * cos(pi_), si * sin(pi_), sqrt(1.0 - si * si));
    soak_vec3 b = soak_v3(so * cos(po), so * sin(po), sqrt(1.0 - so * so));
    soak_vec3 h = soak_v3_norm(soak_v3_add(a, b));
    double F21, F23, ch = fmin(1.0, soak_v3_dot(a, h));
    soak_fresnel_dielectric(b.z, 1.0 / n, &F21, NULL);
    if (m->base == SOAK_WW_CONDUCTOR) soak_fresnel_conductor(ch, m->n_base / n, m->k_base / n, &F23);
    else soak_fresnel_dielectric(ch, m->n_base / n, &F23, NULL);
    *T21o_F23 = (1.0 - F21) * F23;
    *cos_i_w = a.z;
    *cos_o_w = b.z;
}

static void test_triace_eval(void)
{
    soak_rgb cn, ck;
    soak_ww_copper(&cn, &ck);
    soak_ww mats[5];
    const char *names[5] = {"dielectric n1.5 a0.3 kd0.5", "dielectric n1.5 a0.3 kd0", "copper R a0.3",
                            "copper G a0.3", "copper B a0.3"};
    mats[0] = dielectric(1.33, 1.5, 0.3, 0.5);
    mats[1] = dielectric(1.33, 1.5, 0.3, 0.0);
    for (int c = 0; c < 3; ++c) mats[2 + c] = conductor(1.33, soak_rgb_at(cn, c), soak_rgb_at(ck, c), 0.3);

    /* Normal incidence, no absorption: Schlick is exact at cos 1, the
     * polynomial refraction does not bend, F_bottom is exact: fast == exact. */
    soak_vec3 up = soak_v3(0.0, 0.0, 1.0);
    for (int k = 0; k < 5; ++k) {
        soak_ww_triace t;
        double ff, fe;
        soak_ww_triace_setup(&mats[k], &t);
        soak_ww_eval_triace(&t, up, up, &ff);
        soak_ww_eval(&mats[k], up, up, &fe);
        char what[96];
        snprintf(what, sizeof what, "fast = exact at normal incidence, %s", names[k]);
        check_rel(what, ff, fe, 1e-12);
    }

    /* Error table on the fixed grid: theta_i, theta_o in 0..85 step 5,
     * relative azimuth 0 and 180 degrees; also the sub-grid theta <= 60. */
    printf("     Tri-Ace fast-path max relative error vs exact, grid theta 0..85 step 5, phi 0/180"
           " [sub-grid theta_i, theta_o <= 60]:\n");
    double e_fb[5] = {0}, e_fb60[5] = {0}, e_full[5] = {0}, e_full60[5] = {0}, e_full_abs[5] = {0};
    double e_abs[3] = {0}, e_schlick = 0.0, e_schlick60 = 0.0;
    int arg_i[5] = {0}, arg_o[5] = {0}, arg_p[5] = {0};
    const double aps[3] = {1e-3, 1e-2, 0.1};
    for (int ti = 0; ti <= 17; ++ti)
        for (int to = 0; to <= 17; ++to)
            for (int ph = 0; ph < 2; ++ph) {
                double a = ti * 5.0 * DEG, b = to * 5.0 * DEG;
                int sub = ti <= 12 && to <= 12;
                soak_vec3 wi = soak_v3(sin(a), 0.0, cos(a));
                soak_vec3 wo = soak_v3(ph ? -sin(b) : sin(b), 0.0, cos(b));
                if (to == 0 && ph == 0) {
                    double F, m5 = pow(1.0 - cos(a), 5.0), r0 = (0.33 / 2.33) * (0.33 / 2.33);
                    soak_fresnel_dielectric(cos(a), 1.33, &F, NULL);
                    double e = fabs((1.0 - (r0 + (1.0 - r0) * m5)) - (1.0 - F)) / (1.0 - F);
                    e_schlick = fmax(e_schlick, e);
                    if (ti <= 12) e_schlick60 = fmax(e_schlick60, e);
                }
                for (int k = 0; k < 5; ++k) {
                    double prod, ciw, cow, Fb;
                    exact_pieces(&mats[k], wi, wo, &prod, &ciw, &cow);
                    if (mats[k].base == SOAK_WW_CONDUCTOR)
                        soak_triace_fbottom_conductor(1.33, mats[k].n_base, mats[k].k_base, &Fb);
                    else soak_triace_fbottom_dielectric(1.33, mats[k].n_base, &Fb);
                    double e = fabs(Fb - prod) / prod;
                    e_fb[k] = fmax(e_fb[k], e);
                    if (sub) e_fb60[k] = fmax(e_fb60[k], e);

                    soak_ww_triace t;
                    double ff, fe;
                    soak_ww_triace_setup(&mats[k], &t);
                    soak_ww_eval_triace(&t, wi, wo, &ff);
                    soak_ww_eval(&mats[k], wi, wo, &fe);
                    e = fabs(ff - fe) / fe;
                    if (e > e_full[k]) {
                        e_full[k] = e;
                        arg_i[k] = ti * 5;
                        arg_o[k] = to * 5;
                        arg_p[k] = ph * 180;
                    }
                    if (sub) e_full60[k] = fmax(e_full60[k], e);
                    soak_ww mabs = mats[k];
                    mabs.absorption = 0.01;
                    mabs.thickness = 1.0;
                    soak_ww_triace_setup(&mabs, &t);
                    soak_ww_eval_triace(&t, wi, wo, &ff);
                    soak_ww_eval(&mabs, wi, wo, &fe);
                    e_full_abs[k] = fmax(e_full_abs[k], fabs(ff - fe) / fe);
                    if (k == 0)
                        for (int j = 0; j < 3; ++j) {
                            double al, ex = exp(-aps[j] * (1.0 / ciw + 1.0 / cow));
                            soak_triace_absorption_linear(aps[j], ciw, cow, &al);
                            e_abs[j] = fmax(e_abs[j], fabs(al - ex) / ex);
                        }
                }
            }
    printf("       Schlick T12 (air->water) vs exact: %.4f [%.4f]\n", e_schlick, e_schlick60);
    for (int k = 0; k < 5; ++k)
        printf("       %-28s F_bottom vs (1-F21(o'))F23(i'.h'): %.4f [%.4f]; full fast eval: %.4f [%.4f]"
               " (max at ti %d to %d phi %d); with alpha'=0.01: %.4f\n",
               names[k], e_fb[k], e_fb60[k], e_full[k], e_full60[k], arg_i[k], arg_o[k], arg_p[k], e_full_abs[k]);
    for (int j = 0; j < 3; ++j)
        printf("       linear absorption alpha' = %-5g (refracted cosines): %.3g\n", aps[j], e_abs[j]);
    int finite = 1;
    for (int k = 0; k < 5; ++k) finite &= soak_is_finite(e_full[k]) && soak_is_finite(e_fb[k]);
    check_true("fast-path error table finite", finite);
    /* Bounds on the table. The fast path's exit transmission is the constant
     * 1 - F0(1.33) where the exact model has 1 - F(theta_o): at the grid's
     * 85 degrees that alone is a relative error of (1 - F0)/(1 - F(85)) - 1
     * (ww.h: the dominant error); the refraction polynomial, Schlick's T12 and
     * F_bottom's normal-incidence F23 may add at most 0.1 on top. Up to
     * 60 degrees the fast path is within 25 % (largest: the kd = 0 dielectric
     * base, whose F23 at n3/n2 = 1.13 varies most with angle). */
    double F85 = 0, r0w = (0.33 / 2.33) * (0.33 / 2.33);
    soak_fresnel_dielectric(cos(85.0 * DEG), 1.33, &F85, NULL);
    double exit_bound = (1.0 - r0w) / (1.0 - F85) - 1.0;
    printf("       exit-transmission bound at 85 deg: %.4f\n", exit_bound);
    for (int k = 0; k < 5; ++k) {
        char what[128];
        snprintf(what, sizeof what, "Tri-Ace %s: error to 85 deg <= exit-transmission bound %.3f + 0.1", names[k],
                 exit_bound);
        check_true(what, e_full[k] <= exit_bound + 0.1 && e_full_abs[k] <= exit_bound + 0.1);
        snprintf(what, sizeof what, "Tri-Ace %s: error to 60 deg <= 0.25", names[k]);
        check_true(what, e_full60[k] <= 0.25);
    }
    check_true("Schlick T12 within 1 % to 60 deg, 15 % to 85 deg", e_schlick60 <= 0.01 && e_schlick <= 0.15);
    /* The linear form's relative error is e^x (x - 1 + e^-x) <= x^2/2 e^x with
     * x <= alpha' * 2 / cos_c' (cos of the critical angle in water, the
     * largest refracted angle): checks the table against its analytic bound. */
    double cc = sqrt(1.0 - 1.0 / (1.33 * 1.33));
    for (int j = 0; j < 3; ++j) {
        double x = 2.0 * aps[j] / cc;
        char what[96];
        snprintf(what, sizeof what, "linear absorption rel err <= x^2/2 e^x bound, alpha' %g", aps[j]);
        check_true(what, e_abs[j] <= 0.5 * x * x * exp(x) * (1.0 + 1e-9));
    }
    soak_ww m = dielectric(1.2, 1.5, 0.3, 0.5);
    soak_ww_triace t;
    check_status("triace setup rejects n_water 1.2 (outside 1.30-1.36)", soak_ww_triace_setup(&m, &t), SOAK_ERR_ARG);
    m.n_water = 1.37;
    check_status("triace setup rejects n_water 1.37", soak_ww_triace_setup(&m, &t), SOAK_ERR_ARG);
    m.n_water = NAN;
    check_status("triace setup rejects NaN n_water", soak_ww_triace_setup(&m, &t), SOAK_ERR_ARG);

    /* The shipped water, n = 1.333: the same grid against the exact model
     * at 1.333 (its Fresnel terms use 1.333, the refraction polynomial is the
     * 1.33 fit). */
    double e133[5] = {0}, e133_60[5] = {0};
    for (int k = 0; k < 5; ++k) {
        soak_ww mk = mats[k];
        mk.n_water = 1.333;
        double ff, fe;
        check_status("triace setup accepts n_water 1.333", soak_ww_triace_setup(&mk, &t), SOAK_OK);
        soak_ww_eval_triace(&t, up, up, &ff);
        soak_ww_eval(&mk, up, up, &fe);
        char what[120];
        snprintf(what, sizeof what, "n 1.333: fast = exact at normal incidence, %s", names[k]);
        check_rel(what, ff, fe, 1e-12);
        for (int ti = 0; ti <= 17; ++ti)
            for (int to = 0; to <= 17; ++to)
                for (int ph = 0; ph < 2; ++ph) {
                    double a = ti * 5.0 * DEG, b = to * 5.0 * DEG;
                    soak_vec3 wi = soak_v3(sin(a), 0.0, cos(a));
                    soak_vec3 wo = soak_v3(ph ? -sin(b) : sin(b), 0.0, cos(b));
                    soak_ww_eval_triace(&t, wi, wo, &ff);
                    soak_ww_eval(&mk, wi, wo, &fe);
                    e133[k] = fmax(e133[k], fabs(ff - fe) / fe);
                    if (ti <= 12 && to <= 12) e133_60[k] = fmax(e133_60[k], fabs(ff - fe) / fe);
                }
        printf("       n 1.333 %-28s full fast eval max rel err: %.4f [%.4f] (n 1.33: %.4f [%.4f])\n", names[k],
               e133[k], e133_60[k], e_full[k], e_full60[k]);
        snprintf(what, sizeof what, "n 1.333: error within 0.02 of the 1.33 fit's (all), 0.005 (<= 60 deg), %s",
                 names[k]);
        check_true(what, e133[k] <= e_full[k] + 0.02 && e133_60[k] <= e_full60[k] + 0.005);
    }
}

static void test_validation(void)
{
    soak_ww m = dielectric(1.33, 1.5, 0.3, 0.5), bad;
    soak_vec3 up = soak_v3(0.0, 0.0, 1.0), v;
    double out = 7.0, w, pdf;
    int delta;
    bad = m;
    bad.n_water = NAN;
    check_status("n_water NaN", soak_ww_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    bad = m;
    bad.n_water = 0.9;
    check_status("n_water < 1", soak_ww_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    bad = m;
    bad.alpha = INFINITY;
    check_status("alpha Inf", soak_ww_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    bad = m;
    bad.kd = 1.5;
    check_status("kd > 1", soak_ww_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    bad = m;
    bad.thickness = -1.0;
    check_status("thickness < 0", soak_ww_specular(&bad, 0.5, &out), SOAK_ERR_ARG);
    bad = m;
    bad.absorption = NAN;
    check_status("absorption NaN", soak_ww_base_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    bad = m;
    bad.base = (soak_ww_base)7;
    check_status("unknown base kind", soak_ww_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    bad = conductor(1.33, 1.0, NAN, 0.3);
    check_status("k NaN", soak_ww_eval(&bad, up, up, &out), SOAK_ERR_ARG);
    check_status("wi below horizon", soak_ww_eval(&m, soak_v3(0.0, 0.6, -0.8), up, &out), SOAK_ERR_ARG);
    check_status("wo NaN", soak_ww_eval(&m, up, soak_v3(NAN, 0.0, 1.0), &out), SOAK_ERR_ARG);
    check_status("cos_i > 1", soak_ww_specular(&m, 1.5, &out), SOAK_ERR_ARG);
    check_status("sample u NaN", soak_ww_sample(&m, up, NAN, 0.5, 0.5, &v, &w, &pdf, &delta), SOAK_ERR_ARG);
    check_status("NULL material", soak_ww_eval(NULL, up, up, &out), SOAK_ERR_NULL);
    check_status("fbottom NaN", soak_triace_fbottom_dielectric(NAN, 1.5, &out), SOAK_ERR_ARG);
    check_status("fbottom k Inf", soak_triace_fbottom_conductor(1.33, 1.5, INFINITY, &out), SOAK_ERR_ARG);
    check_status("absorption cos 0", soak_triace_absorption_linear(0.1, 0.0, 0.5, &out), SOAK_ERR_ARG);
    check_status("absorption alpha' NaN", soak_triace_absorption_linear(NAN, 0.5, 0.5, &out), SOAK_ERR_ARG);
    check_status("refract from below the normal", soak_refract_1_33(up, up, &v), SOAK_ERR_ARG);
    check_status("refract NaN", soak_refract_1_33(soak_v3(NAN, 0, -1), up, &v), SOAK_ERR_ARG);
    soak_ww_triace t;
    soak_ww_triace_setup(&m, &t);
    check_status("fast eval wo Inf", soak_ww_eval_triace(&t, up, soak_v3(0.0, INFINITY, 1.0), &out), SOAK_ERR_ARG);
    check_status("fast eval wi horizon", soak_ww_eval_triace(&t, soak_v3(1.0, 0.0, 0.0), up, &out), SOAK_ERR_ARG);
    check_close("output untouched on error", out, 7.0, 0.0);
}

static void test_random_finite(tu_rng *rng)
{
    long errs = 0, bad = 0;
    for (int s = 0; s < 1000000; ++s) {
        soak_ww m;
        soak_ww_default(&m);
        m.base = s & 1 ? SOAK_WW_CONDUCTOR : SOAK_WW_DIELECTRIC;
        m.n_water = s % 5 == 0 ? SOAK_WW_N_WATER : 1.0 + 2.0 * tu_uniform(rng);
        m.absorption = s % 3 == 0 ? 0.0 : SOAK_WW_ABSORPTION_MAX * tu_uniform(rng) * tu_uniform(rng) * tu_uniform(rng);
        m.thickness = s % 7 == 0 ? 0.0 : SOAK_WW_THICKNESS_MAX * tu_uniform(rng) * tu_uniform(rng) * tu_uniform(rng);
        m.alpha = SOAK_GGX_ALPHA_MIN + (1.0 - SOAK_GGX_ALPHA_MIN) * tu_uniform(rng) * tu_uniform(rng);
        m.n_base = m.base ? 0.01 + 99.99 * tu_uniform(rng) * tu_uniform(rng) : 1.0 + 2.0 * tu_uniform(rng);
        m.k_base = SOAK_WW_K_MAX * tu_uniform(rng) * tu_uniform(rng);
        m.kd = tu_uniform(rng);
        soak_vec3 wi = tu_upper_dir(rng, 1e-9), wo = tu_upper_dir(rng, 1e-9), v;
        double o, w, pdf;
        int delta;
        soak_status st;
#define CHECK_OUT(call, val)                                     \
    st = (call);                                                 \
    if (st != SOAK_OK) ++errs;                                   \
    else if (!soak_is_finite(val) || (val) < 0.0) ++bad;
        CHECK_OUT(soak_ww_eval(&m, wi, wo, &o), o);
        CHECK_OUT(soak_ww_specular(&m, wi.z, &o), o);
        CHECK_OUT(soak_ww_base_eval(&m, wi, wo, &o), o);
        CHECK_OUT(soak_ww_sample(&m, wo, tu_uniform(rng), tu_uniform(rng), tu_uniform(rng), &v, &w, &pdf, &delta), w);
        if (st == SOAK_OK && !(soak_is_finite(pdf) && pdf >= 0.0 && soak_is_finite(v.x) && v.z > 0.0)) ++bad;
        CHECK_OUT(soak_triace_fbottom_dielectric(1.0 + 2.0 * tu_uniform(rng), 1.0 + 2.0 * tu_uniform(rng), &o), o);
        CHECK_OUT(soak_triace_fbottom_conductor(1.0 + 2.0 * tu_uniform(rng), 0.01 + 99.0 * tu_uniform(rng),
                                                100.0 * tu_uniform(rng), &o),
                  o);
        CHECK_OUT(
            soak_triace_absorption_linear(1e3 * tu_uniform(rng) * tu_uniform(rng) * tu_uniform(rng), wi.z, wo.z, &o),
            o);
        st = soak_refract_1_33(soak_v3_scale(wi, -1.0), soak_v3(0.0, 0.0, 1.0), &v);
        if (st != SOAK_OK) ++errs;
        else if (!(soak_is_finite(v.x) && soak_is_finite(v.y) && v.z < 0.0)) ++bad;
        m.n_water = SOAK_WW_N_WATER;
        m.absorption = fmin(m.absorption, 1e3);
        soak_ww_triace t;
        st = soak_ww_triace_setup(&m, &t);
        if (st != SOAK_OK) ++errs;
        else {
            CHECK_OUT(soak_ww_eval_triace(&t, wi, wo, &o), o);
        }
#undef CHECK_OUT
    }
    printf("     random sweep: %ld errors, %ld non-finite/negative\n", errs, bad);
    check_true("1e6 random valid inputs: every public ww function returns SOAK_OK", errs == 0);
    check_true("1e6 random valid inputs: no NaN/Inf/negative output", bad == 0);
}

int main(void)
{
    tu_rng rng = tu_splitmix64(0x2545F4914F6CDD1Dull);
    tu_gauss_legendre_unit(16, 8, gx, gw);
    test_formula_and_reciprocity(&rng);
    test_no_interface(&rng);
    test_energy();
    test_sampling(&rng);
    test_fbottom();
    test_absorption_linear(&rng);
    test_refract();
    test_triace_eval();
    test_validation();
    test_random_finite(&rng);
    return check_finish();
}
