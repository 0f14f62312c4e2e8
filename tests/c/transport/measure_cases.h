/* Validation cases of `soak measure` against independent references
 * (measure_refs.h and closed forms written here). Shared by the slow full
 * tests and the quick sanitizer-pass variant (fewer paths, same checks). */
#ifndef SOAK_TEST_MEASURE_CASES_H
#define SOAK_TEST_MEASURE_CASES_H

#include <math.h>
#include <stdio.h>

#include "check.h"
#include "measure_refs.h"
#include "soak/fresnel.h"
#include "soak/measure.h"
#include "soak/medium.h"

/* |mc - ref| <= 3 sigma (+ the reference's own error). */
static inline int check_3sigma(const char *what, double mc, double sigma, double ref, double ref_err)
{
    char label[256];
    snprintf(label, sizeof label, "%s [sigma %.2e, %.2f sigma off]", what, sigma,
             sigma > 0 ? fabs(mc - ref) / sigma : 0.0);
    return check_close(label, mc, ref, 3.0 * sigma + ref_err);
}

static inline soak_measure_result run_measure(const soak_measure_setup *s)
{
    soak_measure_result r = {0};
    check_status("soak_measure_run", soak_measure_run(s, &r), SOAK_OK);
    return r;
}

/* (a) Smooth film over a Lambertian base. Lekner & Dorf 1988 (Appl. Opt.
 * 27:1278), derived here: a fraction 1 - r_e enters, the base returns A of
 * it diffusely, a fraction 1 - r_i of that escapes and r_i goes back down:
 *   R = r_e + (1 - r_e) A (1 - r_i) / (1 - A r_i),
 * r_e the external reflectance at the incidence (diffuse: its cosine-
 * weighted average), r_i the cosine-weighted average internal reflectance
 * (soak_fresnel_dielectric_avg(1/n)). Normal incidence r_e = ((n-1)/(n+1))^2. */
static inline void case_film(long long paths, int threads)
{
    const double n = 1.33, A_list[3] = {0.2, 0.5, 0.8};
    double ravg_ext, ravg_int;
    check_status("fresnel avg external", soak_fresnel_dielectric_avg(n, &ravg_ext), SOAK_OK);
    check_status("fresnel avg internal", soak_fresnel_dielectric_avg(1.0 / n, &ravg_int), SOAK_OK);
    double r_normal = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    for (int diffuse = 0; diffuse <= 1; ++diffuse)
        for (int k = 0; k < 3; ++k) {
            double A = A_list[k];
            double re = diffuse ? ravg_ext : r_normal;
            double ref = re + (1 - re) * A * (1 - ravg_int) / (1 - A * ravg_int);
            soak_measure_setup s;
            soak_measure_setup_default(&s);
            s.config = SOAK_MEASURE_FILM;
            s.ior = n;
            s.base_albedo = A;
            s.diffuse_incidence = diffuse;
            s.paths = paths;
            s.threads = threads;
            s.seed = 11 + (uint64_t)k + 7 * (uint64_t)diffuse;
            soak_measure_result r = run_measure(&s);
            char what[128];
            snprintf(what, sizeof what, "film n=1.33 A=%.1f %s incidence", A, diffuse ? "diffuse" : "normal");
            printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, r.value, r.std_error, ref);
            check_3sigma(what, r.value, r.std_error, ref, 1e-9);
            check_close(what, r.value, ref, 0.003);
            check_true("film: no capped paths", r.capped == 0);
        }
}

/* Index-matched absorbing film (n = 1, no interface): R = A e^{-tau}
 * 2 E3(tau), E3 by quadrature over the escape cosine. */
static inline void case_film_absorbing(long long paths, int threads)
{
    const double alpha = 2000.0, d = 2e-4, A = 0.7, tau = alpha * d;
    double x[64], w[64], e = 0.0;
    tu_gauss_legendre(64, 0.0, 1.0, x, w);
    for (int i = 0; i < 64; ++i) e += w[i] * 2.0 * x[i] * exp(-tau / x[i]);
    double ref = A * exp(-tau) * e;
    soak_measure_setup s;
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_FILM;
    s.ior = 1.0;
    s.base_albedo = A;
    s.film_alpha = alpha;
    s.film_thickness = d;
    s.paths = paths;
    s.threads = threads;
    soak_measure_result r = run_measure(&s);
    printf("MEASURED absorbing film n=1: %.6f +- %.6f ref %.6f\n", r.value, r.std_error, ref);
    check_3sigma("absorbing index-matched film", r.value, r.std_error, ref, 1e-9);
}

/* (b) Index-matched isotropic half-space: R(mu0) = 1 - H(mu0) sqrt(1-omega)
 * (Chandrasekhar 1960, ch. VI; the albedo of a semi-infinite atmosphere). */
static inline void case_halfspace(long long paths, int threads, int n_omega)
{
    const double omegas[4] = {0.5, 0.9, 0.99, 0.999}, mus[2] = {1.0, 0.5};
    static ref_hfunc hf;
    for (int k = 0; k < n_omega; ++k) {
        check_true("H-function iteration converged", ref_h_solve(&hf, omegas[k]));
        for (int m = 0; m < 2; ++m) {
            double ref = 1.0 - ref_h_eval(&hf, mus[m]) * sqrt(1.0 - omegas[k]);
            soak_measure_setup s;
            soak_measure_setup_default(&s);
            s.config = SOAK_MEASURE_HALFSPACE;
            s.albedo = omegas[k];
            s.cos_incidence = mus[m];
            s.paths = paths;
            s.threads = threads;
            s.seed = 101 + (uint64_t)(2 * k + m);
            soak_measure_result r = run_measure(&s);
            char what[128];
            snprintf(what, sizeof what, "half-space omega=%g mu0=%g", omegas[k], mus[m]);
            printf("MEASURED %s: %.6f +- %.6f ref %.6f (capped %lld)\n", what, r.value, r.std_error, ref,
                   r.capped);
            check_3sigma(what, r.value, r.std_error, ref, 1e-6);
            check_true("capped weight negligible", r.capped_weight < 0.1 * r.std_error);
        }
    }
}

/* (c) Index-matched isotropic slab vs adding-doubling; omega = 1 conserves. */
static inline void case_slab(long long paths, int threads)
{
    const double taus[2] = {0.5, 2.0}, omegas[3] = {0.5, 0.9, 1.0};
    for (int t = 0; t < 2; ++t)
        for (int k = 0; k < 3; ++k) {
            double Rref, Tref;
            ref_slab_doubling(taus[t], omegas[k], 1.0, &Rref, &Tref);
            soak_measure_setup s;
            soak_measure_setup_default(&s);
            s.config = SOAK_MEASURE_SLAB;
            s.tau = taus[t];
            s.albedo = omegas[k];
            s.paths = paths;
            s.threads = threads;
            s.seed = 201 + (uint64_t)(3 * t + k);
            soak_measure_result r = run_measure(&s);
            char what[128];
            snprintf(what, sizeof what, "slab tau=%g omega=%g R", taus[t], omegas[k]);
            printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, r.reflectance, r.reflectance_err, Rref);
            check_3sigma(what, r.reflectance, r.reflectance_err, Rref, 2e-5);
            snprintf(what, sizeof what, "slab tau=%g omega=%g T", taus[t], omegas[k]);
            printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, r.transmittance, r.transmittance_err, Tref);
            check_3sigma(what, r.transmittance, r.transmittance_err, Tref, 2e-5);
            if (omegas[k] == 1.0) {
                check_close("solver R + T = 1 at omega = 1", Rref + Tref, 1.0, 1e-9);
                check_close("tracer R + T = 1 at omega = 1", r.reflectance + r.transmittance, 1.0, 1e-12);
            }
        }
}

/* Slab seen through the RGB walk: each channel has its own optical thickness
 * and albedo; every channel must match its own scalar reference. */
typedef struct rgb_tally {
    double R[3], R2[3], T[3], T2[3];
} rgb_tally;

static inline void case_slab_rgb(long long paths)
{
    const double tau[3] = {0.5, 2.0, 1.0}, omega[3] = {0.9, 0.5, 1.0};
    soak_medium_rgb m = {soak_rgb3(tau[0], tau[1], tau[2]), soak_rgb3(omega[0], omega[1], omega[2]), {0, 0, 1}, NULL, NULL, 0};
    soak_slab_boundary sb = {1.0, 1.0, 0, 0.0};
    soak_boundary b;
    check_status("slab boundary", soak_slab_boundary_make(&sb, &b), SOAK_OK);
    rgb_tally t = {{0}, {0}, {0}, {0}};
    for (long long i = 0; i < paths; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 77, (uint64_t)i);
        soak_walk_result_rgb w;
        if (soak_medium_walk_rgb(&m, NULL, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w) != SOAK_OK) {
            check_true("rgb walk status", 0);
            return;
        }
        if (w.end != SOAK_WALK_EXITED) continue;
        for (int c = 0; c < 3; ++c) {
            double v = soak_rgb_at(w.weight, c);
            if (w.dir.z > 0) {
                t.R[c] += v;
                t.R2[c] += v * v;
            } else {
                t.T[c] += v;
                t.T2[c] += v * v;
            }
        }
    }
    double n = (double)paths;
    for (int c = 0; c < 3; ++c) {
        double Rref, Tref;
        ref_slab_doubling(tau[c], omega[c], 1.0, &Rref, &Tref);
        double R = t.R[c] / n, T = t.T[c] / n;
        double sR = sqrt((t.R2[c] / n - R * R) / (n - 1)), sT = sqrt((t.T2[c] / n - T * T) / (n - 1));
        char what[128];
        snprintf(what, sizeof what, "rgb slab channel %d (tau %g, omega %g) R", c, tau[c], omega[c]);
        printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, R, sR, Rref);
        check_3sigma(what, R, sR, Rref, 2e-5);
        snprintf(what, sizeof what, "rgb slab channel %d (tau %g, omega %g) T", c, tau[c], omega[c]);
        printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, T, sT, Tref);
        check_3sigma(what, T, sT, Tref, 2e-5);
    }
}

/* (d) Directions actually scattered by the walk: the mean cosine is
 * w g1 + (1-w) g2 and, since HG's Legendre moments are g^l, the mean of
 * P2(cos) is w g1^2 + (1-w) g2^2 (Henyey & Greenstein 1941). */
typedef struct cos_tally {
    double n, s1, s1sq, p2, p2sq;
} cos_tally;

static inline void record_cos(void *ctx, soak_vec3 a, soak_vec3 b)
{
    cos_tally *t = ctx;
    double c = soak_v3_dot(a, b), p2 = 1.5 * c * c - 0.5;
    t->n += 1;
    t->s1 += c;
    t->s1sq += c * c;
    t->p2 += p2;
    t->p2sq += p2 * p2;
}

static inline void case_hg(long long scatters)
{
    const soak_hg2 sets[4] = {
        {0.05, -0.05, 0.2}, /* [JLD99] sec. 4.1, dry paper */
        {0.8, -0.1, 0.1},   /* [JLD99] sec. 4.1, wet paper */
        {0.95, 0.95, 1.0},
        {-0.95, -0.95, 1.0},
    };
    const char *names[4] = {"paper dry", "paper wet", "g=+0.95", "g=-0.95"};
    for (int k = 0; k < 4; ++k) {
        soak_medium m = {1.0, 1.0, sets[k], NULL, NULL};
        soak_slab_boundary sb = {INFINITY, 1.0, 0, 0.0};
        soak_boundary b;
        check_status("half-space boundary", soak_slab_boundary_make(&sb, &b), SOAK_OK);
        cos_tally t = {0, 0, 0, 0, 0};
        soak_walk_options opt;
        soak_walk_options_default(&opt);
        opt.on_scatter = record_cos;
        opt.scatter_ctx = &t;
        opt.max_events = 2000; /* keeps a path's cost bounded; the count is what matters */
        for (uint64_t i = 0; t.n < (double)scatters; ++i) {
            soak_rng rng;
            soak_rng_seed(&rng, 300 + (uint64_t)k, i);
            soak_walk_result w;
            if (soak_medium_walk(&m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w) != SOAK_OK) {
                check_true("hg walk status", 0);
                return;
            }
        }
        double mean = t.s1 / t.n, sd = sqrt((t.s1sq / t.n - mean * mean) / (t.n - 1));
        double ref = sets[k].w * sets[k].g1 + (1 - sets[k].w) * sets[k].g2;
        char what[128];
        snprintf(what, sizeof what, "HG %s mean cosine over %.0f scatters", names[k], t.n);
        printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, mean, sd, ref);
        check_3sigma(what, mean, sd, ref, 0.0);
        double p2 = t.p2 / t.n, sp2 = sqrt((t.p2sq / t.n - p2 * p2) / (t.n - 1));
        double ref2 = sets[k].w * sets[k].g1 * sets[k].g1 + (1 - sets[k].w) * sets[k].g2 * sets[k].g2;
        snprintf(what, sizeof what, "HG %s mean P2(cos)", names[k]);
        printf("MEASURED %s: %.6f +- %.6f ref %.6f\n", what, p2, sp2, ref2);
        check_3sigma(what, p2, sp2, ref2, 0.0);
    }
}

/* (e) Roulette unbiasedness near albedo 1, and capped paths reported. */
static inline void case_roulette(long long paths, int threads)
{
    static ref_hfunc hf;
    const double omega = 0.9999;
    check_true("H-function iteration converged", ref_h_solve(&hf, omega));
    double ref = 1.0 - ref_h_eval(&hf, 1.0) * sqrt(1.0 - omega);
    soak_measure_setup s;
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_HALFSPACE;
    s.albedo = omega;
    s.paths = paths;
    s.threads = threads;
    s.seed = 401;
    s.max_events = 100000;
    soak_measure_result on = run_measure(&s);
    s.roulette = 0;
    s.seed = 402;
    soak_measure_result off = run_measure(&s);
    double sig = sqrt(on.std_error * on.std_error + off.std_error * off.std_error);
    printf("MEASURED omega=0.9999 roulette on %.6f +- %.6f (capped %lld), off %.6f +- %.6f (capped %lld, "
           "unscored %.2e), H ref %.6f\n",
           on.value, on.std_error, on.capped, off.value, off.std_error, off.capped, off.capped_weight, ref);
    check_3sigma("roulette on vs off, omega 0.9999", on.value - off.value, sig, 0.0, 0.0);
    check_3sigma("roulette on vs H-function", on.value, on.std_error, ref, 1e-6);
    check_3sigma("roulette off vs H-function", off.value, off.std_error, ref, 1e-6);
    check_true("roulette off: capped bias bound below sigma/10", off.capped_weight < 0.1 * off.std_error);

    /* A tiny cap at albedo 1 without roulette: every path either exits with
     * weight 1 or is capped with weight 1, so R + unscored = 1 exactly. */
    s.albedo = 1.0;
    s.max_events = 20;
    s.paths = paths / 10 > 1000 ? paths / 10 : 1000;
    soak_measure_result capped = run_measure(&s);
    printf("MEASURED cap 20 events, omega 1: R %.6f, capped %lld, unscored %.6f\n", capped.value, capped.capped,
           capped.capped_weight);
    check_true("capped paths are counted", capped.capped > 0);
    check_close("R + unscored capped weight = 1 (nothing dropped silently)", capped.value + capped.capped_weight,
                1.0, 1e-12);
}

#endif
