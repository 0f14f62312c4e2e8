/* Film over a Lambertian base (src/film.c) against references built here:
 * Fresnel in Fresnel's own angle form, hemispherical averages by adaptive
 * Simpson quadrature over the film-side cosine, and the interreflection
 * series summed bounce by bounce. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "testutil.h"
#include "soak/film.h"

/* ---- independent reference ------------------------------------------- */


typedef double (*fn1)(double x, const void *p);

static double simpson_rec(fn1 f, const void *p, double a, double b, double fa, double fm, double fb, double whole, double tol,
                          int depth)
{
    double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    double flm = f(lm, p), frm = f(rm, p);
    double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    double diff = left + right - whole;
    if (depth <= 0 || fabs(diff) <= 15.0 * tol) return left + right + diff / 15.0;
    return simpson_rec(f, p, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
           simpson_rec(f, p, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

/* Adaptive Simpson over 32 starting slices, absolute tolerance tol. */
static double integrate(fn1 f, const void *p, double a, double b, double tol)
{
    const int slices = 32;
    double sum = 0.0, h = (b - a) / slices;
    for (int i = 0; i < slices; ++i) {
        double x0 = a + i * h, x1 = x0 + h, xm = 0.5 * (x0 + x1);
        double f0 = f(x0, p), fm = f(xm, p), f1 = f(x1, p);
        sum += simpson_rec(f, p, x0, x1, f0, fm, f1, h / 6.0 * (f0 + 4.0 * fm + f1), tol / slices, 40);
    }
    return sum;
}

typedef struct ref_film {
    double n, tau, mu_c;
    double escape, ret; /* fractions of the base's Lambertian flux */
} ref_film;

/* Partial-reflection region mu = mu_c + (1 - mu_c) s^2, s in [0,1]: the
 * substitution straightens the square-root kink of F at the critical angle. */
static double mu_of_s(const ref_film *r, double s, double *dmu_ds)
{
    *dmu_ds = 2.0 * (1.0 - r->mu_c) * s;
    return r->mu_c + (1.0 - r->mu_c) * s * s;
}
static double escape_integrand(double s, const void *p)
{
    const ref_film *r = p;
    double d, mu = mu_of_s(r, s, &d);
    return 2.0 * mu * (1.0 - tu_fresnel_angle(mu, r->n, 1.0)) * exp(-r->tau / mu) * d;
}
static double return_partial_integrand(double s, const void *p)
{
    const ref_film *r = p;
    double d, mu = mu_of_s(r, s, &d);
    return 2.0 * mu * tu_fresnel_angle(mu, r->n, 1.0) * exp(-2.0 * r->tau / mu) * d;
}
static double return_tir_integrand(double mu, const void *p)
{
    const ref_film *r = p;
    return mu > 0.0 ? 2.0 * mu * exp(-2.0 * r->tau / mu) : 0.0;
}

static ref_film ref_setup(double n, double tau)
{
    ref_film r = {n, tau, sqrt(1.0 - 1.0 / (n * n)), 0.0, 0.0};
    r.escape = integrate(escape_integrand, &r, 0.0, 1.0, 1e-14);
    r.ret = integrate(return_partial_integrand, &r, 0.0, 1.0, 1e-14);
    if (r.mu_c > 0.0) r.ret += integrate(return_tir_integrand, &r, 0.0, r.mu_c, 1e-14);
    return r;
}

/* Total reflectance by following the flux bounce by bounce. */
static double ref_albedo_series(const ref_film *r, double A, double cos_i)
{
    double F = tu_fresnel_angle(cos_i, 1.0, r->n);
    double sin_t = sin(acos(cos_i)) / r->n;
    double cos_t = sqrt(1.0 - sin_t * sin_t);
    double down = (1.0 - F) * (cos_t > 0.0 ? exp(-r->tau / cos_t) : 0.0); /* flux arriving at the base */
    double out = F;
    for (int bounce = 0; bounce < 100000 && down > 1e-20; ++bounce) {
        double up = A * down;
        out += up * r->escape;
        down = up * r->ret;
    }
    return out;
}

typedef struct diffuse_args {
    const ref_film *r;
    double A;
} diffuse_args;
static double diffuse_integrand(double nu, const void *p)
{
    const diffuse_args *d = p;
    return nu > 0.0 ? 2.0 * nu * ref_albedo_series(d->r, d->A, nu) : 0.0;
}

/* ---- tests ------------------------------------------------------------- */

static const double albedos[] = {0.0, 0.2, 0.5, 0.9, 0.999, 1.0};
#define N_ALBEDOS (int)(sizeof albedos / sizeof albedos[0])

static void test_against_series(void)
{
    const double ns[] = {1.33, 1.5};
    const double taus[] = {0.0, 0.35, 2.0};
    const double cosines[] = {1.0, 0.5, 0.1};
    double max_dir = 0.0, max_diff = 0.0;
    int ok = 1;
    for (int in = 0; in < 2; ++in) {
        for (int it = 0; it < 3; ++it) {
            ref_film r = ref_setup(ns[in], taus[it]);
            soak_film film = {ns[in], taus[it], 1.0}; /* alpha * 1 m = tau */
            soak_film_ctx ctx;
            ok &= soak_film_setup(&film, &ctx) == SOAK_OK;
            char what[160];
            snprintf(what, sizeof what, "escape fraction n=%g tau=%g vs quadrature", ns[in], taus[it]);
            check_close(what, ctx.escape, r.escape, 1e-11);
            snprintf(what, sizeof what, "return fraction n=%g tau=%g vs quadrature", ns[in], taus[it]);
            check_close(what, ctx.ret, r.ret, 1e-11);
            for (int ia = 0; ia < N_ALBEDOS; ++ia) {
                for (int ic = 0; ic < 3; ++ic) {
                    double got = -1.0, want = ref_albedo_series(&r, albedos[ia], cosines[ic]);
                    ok &= soak_film_albedo_dir(&film, albedos[ia], cosines[ic], &got) == SOAK_OK;
                    max_dir = fmax(max_dir, fabs(got - want));
                }
                diffuse_args d = {&r, albedos[ia]};
                double got = -1.0, want = integrate(diffuse_integrand, &d, 0.0, 1.0, 1e-13);
                ok &= soak_film_albedo_diffuse(&film, albedos[ia], &got) == SOAK_OK;
                max_diff = fmax(max_diff, fabs(got - want));
            }
        }
    }
    check_true("all series cases evaluated", ok);
    printf("max |albedo_dir - series| = %.3g, max |albedo_diffuse - series quadrature| = %.3g\n", max_dir, max_diff);
    check_close("albedo_dir vs bounce series (36 films x 3 angles)", max_dir, 0.0, 1e-10);
    check_close("albedo_diffuse vs quadrature of the series", max_diff, 0.0, 1e-10);
}

/* Near-index-matched and thick films: relative accuracy of the escape and
 * return fractions, with the reference tolerance scaled to their size. */
static void test_hard_quadrature(void)
{
    const double cases[][2] = {{1.0001, 1e-6}, {1.0001, 0.05}, {1.01, 1.0}, {3.0, 5.0}, {1.33, 20.0}, {2.0, 60.0}};
    for (int c = 0; c < 6; ++c) {
        double n = cases[c][0], tau = cases[c][1];
        ref_film r = {n, tau, sqrt(1.0 - 1.0 / (n * n)), 0.0, 0.0};
        r.escape = integrate(escape_integrand, &r, 0.0, 1.0, 1e-13 * exp(-tau));
        r.ret = integrate(return_partial_integrand, &r, 0.0, 1.0, 1e-13 * exp(-2.0 * tau)) +
                integrate(return_tir_integrand, &r, 0.0, r.mu_c, 1e-13 * exp(-2.0 * tau / r.mu_c));
        soak_film film = {n, tau, 1.0};
        soak_film_ctx ctx;
        soak_film_setup(&film, &ctx);
        char what[160];
        snprintf(what, sizeof what, "escape fraction n=%g tau=%g, relative", n, tau);
        check_rel(what, ctx.escape, r.escape, 1e-10);
        snprintf(what, sizeof what, "return fraction n=%g tau=%g, relative", n, tau);
        check_rel(what, ctx.ret, r.ret, 1e-9);
    }
}

/* Lekner & Dorf's scenario: water, n = 1.33. The diffuse reflectance of a
 * water surface seen from air is the classic 0.066; the identity
 * 1 - Rint = (1 - Rext)/n^2 then gives Rint = 0.472. */
static void test_published_water(void)
{
    ref_film r = ref_setup(1.33, 0.0);
    double r_ext_ref = 1.0 - 1.33 * 1.33 * r.escape; /* = 2 int nu F dnu, by the change of variable */
    check_close("water Rext (published ~0.066)", r_ext_ref, 0.066, 0.001);
    soak_film film = {1.33, 0.0, 0.0};
    soak_film_ctx ctx;
    check_status("setup water", soak_film_setup(&film, &ctx), SOAK_OK);
    check_close("water Rext from the library", ctx.spec_avg, 0.066, 0.001);
    double r_int_published = 1.0 - (1.0 - 0.066) / (1.33 * 1.33);
    check_close("water Rint = 1-(1-0.066)/1.33^2 = 0.472", ctx.ret, r_int_published, 0.001);
    check_close("Rint identity with the library's own Rext", ctx.ret, 1.0 - (1.0 - ctx.spec_avg) / (1.33 * 1.33), 1e-14);
    /* Lekner & Dorf's non-absorbing result, A(1-Rext)(1-Rint)/(1-A Rint) + Rext */
    double A = 0.5, got = -1.0;
    soak_film_albedo_diffuse(&film, A, &got);
    check_close("diffuse albedo = Rext + A(1-Rext)(1-Rint)/(1-A Rint)", got,
                r_ext_ref + A * (1.0 - r_ext_ref) * (1.0 - r.ret) / (1.0 - A * r.ret), 1e-11);
}

static double consistency_integrand(double nu, const void *p)
{
    const double *args = p; /* n, tau, A, cos_i */
    soak_film film = {args[0], args[1], 1.0};
    soak_film_ctx ctx;
    soak_film_setup(&film, &ctx);
    soak_vec3 wi = soak_v3(sqrt(1.0 - args[3] * args[3]), 0.0, args[3]);
    double sum = 0.0, s = sqrt(fmax(0.0, 1.0 - nu * nu));
    const int n_phi = 7; /* f has no azimuth dependence, but do not assume it */
    for (int k = 0; k < n_phi; ++k) {
        double phi = 2.0 * SOAK_PI * (k + 0.5) / n_phi, f = 0.0;
        soak_film_ctx_brdf(&ctx, args[2], wi, soak_v3(s * cos(phi), s * sin(phi), nu), &f);
        sum += f;
    }
    return 2.0 * SOAK_PI * sum / n_phi * nu; /* dw = dnu dphi */
}

static void test_brdf(tu_rng *rng)
{
    /* consistency: int f cos dw + specular = albedo_dir */
    const double cases[][4] = {{1.33, 0.0, 0.7, 0.9}, {1.5, 0.35, 0.999, 0.3}, {1.33, 2.0, 1.0, 0.05}, {2.5, 0.1, 0.2, 1.0}};
    for (int c = 0; c < 4; ++c) {
        soak_film film = {cases[c][0], cases[c][1], 1.0};
        double spec = -1.0, alb = -1.0;
        soak_film_specular(&film, cases[c][3], &spec);
        soak_film_albedo_dir(&film, cases[c][2], cases[c][3], &alb);
        double integral = integrate(consistency_integrand, cases[c], 0.0, 1.0, 1e-12);
        char what[160];
        snprintf(what, sizeof what, "int f cos dw + specular = albedo_dir (n=%g tau=%g A=%g cos=%g)", cases[c][0],
                 cases[c][1], cases[c][2], cases[c][3]);
        check_close(what, integral + spec, alb, 1e-10);
    }
    /* reciprocity on random pairs and films */
    double worst = 0.0;
    int ok = 1;
    for (int i = 0; i < 2000; ++i) {
        soak_film film = {1.0 + 2.0 * tu_uniform(rng), 10.0 * tu_uniform(rng), tu_uniform(rng)};
        double A = tu_uniform(rng);
        soak_vec3 a = tu_upper_dir(rng, 0.0), b = tu_upper_dir(rng, 0.0);
        double fab = -1.0, fba = -1.0;
        ok &= soak_film_brdf(&film, A, a, b, &fab) == SOAK_OK;
        ok &= soak_film_brdf(&film, A, b, a, &fba) == SOAK_OK;
        if (fab > 0.0) worst = fmax(worst, fabs(fab - fba) / fab);
    }
    check_true("brdf evaluations ok", ok);
    check_close("reciprocity f(a,b) = f(b,a), max relative difference", worst, 0.0, 1e-14);
    /* n = 1, no absorption: Lambertian A / pi */
    soak_film dry = {1.0, 0.0, 0.0};
    double f = -1.0;
    soak_film_brdf(&dry, 0.6, soak_v3(0.6, 0.0, 0.8), soak_v3(0.0, 0.0, 1.0), &f);
    check_close("n = 1 BRDF is A/pi", f, 0.6 / SOAK_PI, 1e-16);
    /* below the horizon */
    soak_film wet = {1.33, 0.0, 0.0};
    f = -1.0;
    check_status("wo below horizon accepted", soak_film_brdf(&wet, 0.6, soak_v3(0, 0, 1), soak_v3(0.6, 0.0, -0.8), &f), SOAK_OK);
    check_close("wo below horizon gives 0", f, 0.0, 0.0);
}

static void test_energy(void)
{
    soak_film clear13 = {1.33, 0.0, 0.0}, clear3 = {3.0, 0.0, 0.0};
    const double cosines[] = {1.0, 0.7, 0.3, 0.01, 1e-6};
    double worst = 0.0;
    for (int i = 0; i < 5; ++i) {
        double a = -1.0, b = -1.0;
        soak_film_albedo_dir(&clear13, 1.0, cosines[i], &a);
        soak_film_albedo_dir(&clear3, 1.0, cosines[i], &b);
        worst = fmax(worst, fmax(fabs(a - 1.0), fabs(b - 1.0)));
    }
    check_close("A = 1, clear film: albedo_dir = 1 (n = 1.33, 3)", worst, 0.0, 1e-13);
    double d = -1.0;
    soak_film_albedo_diffuse(&clear13, 1.0, &d);
    check_close("A = 1, clear film: albedo_diffuse = 1", d, 1.0, 1e-13);
    /* n = 1: dry albedo exactly */
    soak_film none = {1.0, 0.0, 0.0};
    int exact = 1;
    for (int ia = 0; ia < N_ALBEDOS; ++ia) {
        for (int i = 0; i < 5; ++i) {
            double a = -1.0;
            soak_film_albedo_dir(&none, albedos[ia], cosines[i], &a);
            exact &= a == albedos[ia];
        }
        double a = -1.0;
        soak_film_albedo_diffuse(&none, albedos[ia], &a);
        exact &= a == albedos[ia];
    }
    check_true("n = 1, no absorption: albedo == base albedo exactly", exact);
    /* n = 1 with absorption: A exp(-tau/cos) 2 E3(tau), E3 by quadrature */
    ref_film r = ref_setup(1.0, 0.5);
    double a = -1.0;
    soak_film absorbing_none = {1.0, 0.5, 1.0};
    soak_film_albedo_dir(&absorbing_none, 0.8, 0.6, &a);
    check_close("n = 1, tau = 0.5: A exp(-tau/cos) * escape", a, 0.8 * exp(-0.5 / 0.6) * r.escape, 1e-12);
}

static void test_thickness(void)
{
    ref_film clear = ref_setup(1.33, 0.0);
    soak_film zero = {1.33, 0.35, 0.0}, thin = {1.33, 0.35, 1e-9}, deep = {1.33, 0.35, 1e3};
    double a0 = -1.0, a1 = -1.0, a2 = -1.0, spec = -1.0;
    soak_film_albedo_dir(&zero, 0.5, 0.8, &a0);
    soak_film_albedo_dir(&thin, 0.5, 0.8, &a1);
    check_close("thickness 0 = clear film (series)", a0, ref_albedo_series(&clear, 0.5, 0.8), 1e-11);
    check_close("thickness 1e-9 m ~ clear film", a1, a0, 1e-9);
    check_true("thickness 1e-9 m absorbs a little", a1 < a0);
    soak_film_albedo_dir(&deep, 0.5, 0.8, &a2);
    soak_film_specular(&deep, 0.8, &spec);
    check_close("1 km of water, red channel: only the specular reflection", a2, spec, 1e-300);
    check_close("specular vs reference Fresnel", spec, tu_fresnel_angle(0.8, 1.0, 1.33), 1e-14);
    double ad = -1.0;
    soak_film_albedo_diffuse(&deep, 0.5, &ad);
    check_close("1 km of water, diffuse light: only Rext", ad, 1.0 - 1.33 * 1.33 * clear.escape, 1e-12);
    /* extreme optical thickness */
    soak_film opaque = {1.5, 1e6, 1e3};
    double ao = -1.0;
    check_status("tau = 1e9 accepted", soak_film_albedo_dir(&opaque, 1.0, 0.5, &ao), SOAK_OK);
    check_close("tau = 1e9: specular only", ao, tu_fresnel_angle(0.5, 1.0, 1.5), 1e-14);
}

static void test_grazing(void)
{
    soak_film water = {1.33, 0.35, 0.01};
    double a = -1.0, s = -1.0;
    check_status("cos_i = 0 accepted", soak_film_albedo_dir(&water, 0.5, 0.0, &a), SOAK_OK);
    check_close("cos_i = 0: everything mirrored", a, 1.0, 0.0);
    soak_film_specular(&water, 0.0, &s);
    check_close("cos_i = 0: specular = 1", s, 1.0, 0.0);
    check_status("cos_i = 1e-12 accepted", soak_film_albedo_dir(&water, 0.5, 1e-12, &a), SOAK_OK);
    check_true("cos_i = 1e-12: finite, in [0,1]", a >= 0.0 && a <= 1.0);
    check_close("cos_i = 1e-12: ~ mirror", a, 1.0, 1e-10);
    soak_film none = {1.0, 0.0, 0.0};
    check_status("n = 1, cos_i = 0", soak_film_albedo_dir(&none, 0.3, 0.0, &a), SOAK_OK);
    check_close("n = 1, cos_i = 0: base albedo", a, 0.3, 0.0);
    soak_film none_abs = {1.0, 1.0, 1.0};
    check_status("n = 1, absorbing, cos_i = 0", soak_film_albedo_dir(&none_abs, 0.3, 0.0, &a), SOAK_OK);
    check_close("n = 1, absorbing, cos_i = 0: infinite path, 0", a, 0.0, 0.0);
    double f = -1.0;
    check_status("brdf at wi.z = 1e-12", soak_film_brdf(&water, 0.5, soak_v3(1.0, 0.0, 1e-12), soak_v3(0, 0, 1), &f), SOAK_OK);
    check_true("brdf at grazing finite and >= 0", f >= 0.0 && f < 1.0);
}

static void test_invalid(void)
{
    const double bad[] = {NAN, INFINITY, -INFINITY};
    soak_film ok = {1.33, 0.35, 0.01};
    double out = 123.0;
    int all = 1;
    for (int i = 0; i < 3; ++i) {
        soak_film f1 = ok, f2 = ok, f3 = ok;
        f1.n = bad[i];
        f2.alpha = bad[i];
        f3.thickness = bad[i];
        all &= soak_film_validate(&f1) == SOAK_ERR_ARG && soak_film_validate(&f2) == SOAK_ERR_ARG &&
               soak_film_validate(&f3) == SOAK_ERR_ARG;
        all &= soak_film_albedo_dir(&ok, bad[i], 0.5, &out) == SOAK_ERR_ARG;
        all &= soak_film_albedo_dir(&ok, 0.5, bad[i], &out) == SOAK_ERR_ARG;
        all &= soak_film_albedo_diffuse(&f1, 0.5, &out) == SOAK_ERR_ARG;
        all &= soak_film_specular(&ok, bad[i], &out) == SOAK_ERR_ARG;
        all &= soak_film_brdf(&ok, 0.5, soak_v3(bad[i], 0, 1), soak_v3(0, 0, 1), &out) == SOAK_ERR_ARG;
        all &= soak_film_brdf(&ok, 0.5, soak_v3(0, 0, 1), soak_v3(0, bad[i], 1), &out) == SOAK_ERR_ARG;
    }
    check_true("NaN/Inf inputs rejected with SOAK_ERR_ARG", all);
    soak_film lo = {0.99, 0, 0}, hi = {3.01, 0, 0}, na = {1.33, -1e-9, 0}, ha = {1.33, 1.1e6, 0}, nt = {1.33, 0, -1e-9},
              ht = {1.33, 0, 1001};
    check_true("out-of-range film fields rejected",
               soak_film_validate(&lo) == SOAK_ERR_ARG && soak_film_validate(&hi) == SOAK_ERR_ARG &&
                   soak_film_validate(&na) == SOAK_ERR_ARG && soak_film_validate(&ha) == SOAK_ERR_ARG &&
                   soak_film_validate(&nt) == SOAK_ERR_ARG && soak_film_validate(&ht) == SOAK_ERR_ARG);
    check_true("out-of-range albedo / cos rejected",
               soak_film_albedo_dir(&ok, -1e-12, 0.5, &out) == SOAK_ERR_ARG &&
                   soak_film_albedo_dir(&ok, 1.0 + 1e-12, 0.5, &out) == SOAK_ERR_ARG &&
                   soak_film_albedo_dir(&ok, 0.5, -1e-12, &out) == SOAK_ERR_ARG &&
                   soak_film_albedo_dir(&ok, 0.5, 1.0 + 1e-12, &out) == SOAK_ERR_ARG);
    check_true("non-unit direction rejected",
               soak_film_brdf(&ok, 0.5, soak_v3(0, 0, 0.9), soak_v3(0, 0, 1), &out) == SOAK_ERR_ARG);
    check_true("output untouched on error", out == 123.0);
    check_status("NULL film", soak_film_validate(NULL), SOAK_ERR_NULL);
    check_status("NULL output", soak_film_albedo_dir(&ok, 0.5, 0.5, NULL), SOAK_ERR_NULL);
    soak_film_ctx bad_ctx = {1.33, 0.0, 0.066, NAN, 0.47};
    check_status("corrupt context rejected", soak_film_ctx_albedo_dir(&bad_ctx, 0.5, 0.5, &out), SOAK_ERR_ARG);
}

static void test_sweep(tu_rng *rng)
{
    long bad = 0, evals = 0, mismatch = 0;
    for (int i = 0; i < 10000; ++i) {
        double u = tu_uniform(rng);
        soak_film film = {1.0 + 2.0 * tu_uniform(rng), u < 0.1 ? 0.0 : pow(10.0, -3.0 + 9.0 * tu_uniform(rng)),
                          u > 0.9 ? 0.0 : pow(10.0, -9.0 + 12.0 * tu_uniform(rng))};
        if (i % 50 == 0) film.n = 1.0;
        soak_film_ctx ctx;
        if (soak_film_setup(&film, &ctx) != SOAK_OK) {
            ++bad;
            continue;
        }
        for (int j = 0; j < 100; ++j) {
            double A = j == 0 ? 1.0 : tu_uniform(rng), c = j == 1 ? 0.0 : tu_uniform(rng), a = -1.0, f = -1.0;
            soak_vec3 wi = tu_upper_dir(rng, 0.0), wo = tu_upper_dir(rng, 0.0);
            soak_status s1 = soak_film_ctx_albedo_dir(&ctx, A, c, &a);
            soak_status s2 = soak_film_ctx_brdf(&ctx, A, wi, wo, &f);
            ++evals;
            if (s1 != SOAK_OK || s2 != SOAK_OK || !(a >= 0.0 && a <= 1.0) || !(f >= 0.0 && f <= 1e3)) ++bad;
        }
        double d = -1.0, d2 = -1.0;
        if (soak_film_ctx_albedo_diffuse(&ctx, 0.5, &d) != SOAK_OK || !(d >= 0.0 && d <= 1.0)) ++bad;
        if (soak_film_albedo_diffuse(&film, 0.5, &d2) != SOAK_OK || d2 != d) ++mismatch;
    }
    printf("sweep: %ld evaluations\n", evals);
    check_true("10^6 random valid inputs: all OK, finite, albedo in [0,1]", bad == 0 && evals == 1000000);
    check_true("plain functions equal the context functions", mismatch == 0);
}

int main(void)
{
    tu_rng rng = tu_splitmix64(0x9E3779B97F4A7C15ull);
    test_against_series();
    test_hard_quadrature();
    test_published_water();
    test_brdf(&rng);
    test_energy();
    test_thickness();
    test_grazing();
    test_invalid();
    test_sweep(&rng);
    return check_finish();
}
