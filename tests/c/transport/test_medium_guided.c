/* The guided walk (soak_walk_options.guide_prob, soak/dwivedi.h): the
 * Dwivedi eigenvalue against its defining equation and Case & Zweifel's
 * table, the direction pdf's normalisation and inverse CDF against numerical
 * integration, and the guided walk's means against independent references:
 * adding-doubling for an index-matched RGB slab (exit weights), and the
 * analog walk (a second estimator) for a thick anisotropic slab behind a
 * Fresnel interface, for exits and for a next-event-like tally at every
 * vertex. Unbiasedness is judged within 4 standard errors. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "measure_refs.h"
#include "soak/dwivedi.h"
#include "soak/medium.h"

static void test_eigenvalue(void)
{
    const double a[] = {0.2, 0.5, 0.8, 0.9, 0.95, 0.99, 0.999999};
    for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) {
        double v0 = soak_dwivedi_v0(a[i]);
        char what[64];
        snprintf(what, sizeof what, "a v0 atanh(1/v0) = 1 at albedo %g", a[i]);
        check_close(what, a[i] * v0 * atanh(1.0 / v0), 1.0, 1e-10);
    }
    /* Case & Zweifel 1967, Table of nu_0 for isotropic scattering: c = 0.9 -> 1.9032. */
    check_close("v0(0.9) vs Case & Zweifel", soak_dwivedi_v0(0.9), 1.9032, 5e-5);
    check_true("v0(1) = V0_MAX (no guide)", soak_dwivedi_v0(1.0) == SOAK_DWIVEDI_V0_MAX);
    check_true("v0(NaN) = V0_MAX", soak_dwivedi_v0(NAN) == SOAK_DWIVEDI_V0_MAX);
    check_true("v0(0) = V0_MIN", soak_dwivedi_v0(0.0) == SOAK_DWIVEDI_V0_MIN);
}

/* Midpoint-rule integral of p(mu) from -1 to x. */
static double integral(double v0, double L, double x)
{
    const int n = 20000;
    double h = (x + 1.0) / n, s = 0.0;
    for (int i = 0; i < n; ++i) s += soak_dwivedi_pdf_cos(v0, L, -1.0 + (i + 0.5) * h);
    return s * h;
}

static void test_direction_pdf(void)
{
    const double v0s[] = {1.05, 1.9032, 18.26, 1e8};
    for (int i = 0; i < 4; ++i) {
        double v0 = v0s[i], L = soak_dwivedi_norm(v0);
        char what[80];
        snprintf(what, sizeof what, "integral of p(mu) = 1 at v0 %g", v0);
        check_close(what, integral(v0, L, 1.0), 1.0, 1e-6);
        for (double u = 0.1; u < 1.0; u += 0.2) {
            snprintf(what, sizeof what, "CDF(sample(u = %.1f)) = u at v0 %g", u, v0);
            check_close(what, integral(v0, L, soak_dwivedi_sample_cos(v0, L, u)), u, 1e-6);
        }
    }
}

typedef struct tally {
    double sum[3], sum2[3];
} tally;

/* A sun-like estimate at every vertex: weight x exp(-sigma_t depth). */
typedef struct nee_tally {
    soak_rgb sigma_t;
    double path[3];
} nee_tally;

static int nee_vertex(void *ctx, soak_vec3 pos, soak_vec3 dir_in, soak_rgb weight, const soak_medium_point *local,
                      soak_rng *rng)
{
    (void)dir_in;
    (void)local;
    (void)rng;
    nee_tally *n = ctx;
    for (int c = 0; c < 3; ++c) n->path[c] += soak_rgb_at(weight, c) * exp(pos.z * soak_rgb_at(n->sigma_t, c));
    return 1;
}

static void add(tally *t, int c, double v)
{
    t->sum[c] += v;
    t->sum2[c] += v * v;
}

static double mean(const tally *t, int c, long n) { return t->sum[c] / n; }
static double se(const tally *t, int c, long n)
{
    double m = t->sum[c] / n;
    return sqrt(fmax(0.0, t->sum2[c] / n - m * m) / n);
}

/* N walks entering at the origin along -z; R: exits upward; V: the vertex tally. */
static int run(const soak_medium_rgb *m, const soak_boundary *b, double guide, soak_vec3 n, long N, uint64_t seed,
               tally *R, tally *T, tally *V)
{
    soak_walk_options opt;
    soak_walk_options_default(&opt);
    opt.guide_prob = guide;
    opt.guide_normal = n;
    nee_tally nt = {m->sigma_t, {0, 0, 0}};
    opt.on_vertex = nee_vertex;
    opt.vertex_ctx = &nt;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, seed, (uint64_t)i);
        soak_walk_result_rgb w;
        nt.path[0] = nt.path[1] = nt.path[2] = 0;
        if (soak_medium_walk_rgb(m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), b, &rng, &w) != SOAK_OK) return 0;
        int up = w.end == SOAK_WALK_EXITED && w.dir.z > 0, down = w.end == SOAK_WALK_EXITED && w.dir.z < 0;
        for (int c = 0; c < 3; ++c) {
            add(R, c, up ? soak_rgb_at(w.weight, c) : 0.0);
            add(T, c, down ? soak_rgb_at(w.weight, c) : 0.0);
            add(V, c, nt.path[c]);
        }
    }
    return 1;
}

/* Index-matched slab, per-channel optical thickness and albedo, isotropic:
 * adding-doubling gives R and T (the direct beam included) per channel. */
static void test_slab_vs_doubling(void)
{
    const double tau[3] = {0.5, 2.0, 1.0}, omega[3] = {0.9, 0.5, 0.99};
    soak_medium_rgb m = {soak_rgb3(tau[0], tau[1], tau[2]), soak_rgb3(omega[0], omega[1], omega[2]), {0, 0, 1}, NULL,
                         NULL, 0.0};
    soak_slab_boundary sb = {1.0, 1.0, 0, 0.0};
    soak_boundary b;
    check_status("slab boundary", soak_slab_boundary_make(&sb, &b), SOAK_OK);
    const soak_vec3 normals[2] = {soak_v3(0, 0, 1), soak_v3(0, 0, -1)};
    const long N = 100000;
    for (int k = 0; k < 2; ++k) {
        tally R = {{0}, {0}}, T = {{0}, {0}}, V = {{0}, {0}};
        if (!check_true("guided slab walks", run(&m, &b, 0.7, normals[k], N, 31 + k, &R, &T, &V))) return;
        for (int c = 0; c < 3; ++c) {
            double Rref, Tref;
            ref_slab_doubling(tau[c], omega[c], 1.0, &Rref, &Tref);
            char what[96];
            snprintf(what, sizeof what, "guided (n.z %+g) slab R[%d] vs doubling (4 se)", normals[k].z, c);
            check_close(what, mean(&R, c, N), Rref, 4 * se(&R, c, N) + 1e-4);
            snprintf(what, sizeof what, "guided (n.z %+g) slab T[%d] vs doubling (4 se)", normals[k].z, c);
            check_close(what, mean(&T, c, N), Tref, 4 * se(&T, c, N) + 1e-4);
        }
    }
}

/* Thick slab (20 mean free paths) of the bench sphere's stone (HG g = 0.3,
 * albedo 0.92-0.97) behind an n = 1.5 interface: the guided walk's exits and
 * vertex tally against the analog walk's, within 4 combined standard errors. */
static void test_thick_vs_analog(void)
{
    soak_medium_rgb m = {soak_rgb3(30.8, 31.4, 32.6), soak_rgb3(30.0 / 30.8, 30.0 / 31.4, 30.0 / 32.6), {0.3, 0.3, 1},
                         NULL, NULL, 0.0};
    soak_slab_boundary sb = {20.0 / 31.0, 1.5, 0, 0.0};
    soak_boundary b;
    check_status("slab boundary", soak_slab_boundary_make(&sb, &b), SOAK_OK);
    const long N = 40000;
    tally R0 = {{0}, {0}}, T0 = {{0}, {0}}, V0 = {{0}, {0}}, R1 = {{0}, {0}}, T1 = {{0}, {0}}, V1 = {{0}, {0}};
    if (!check_true("analog walks", run(&m, &b, 0.0, soak_v3(0, 0, 1), N, 41, &R0, &T0, &V0))) return;
    if (!check_true("guided walks", run(&m, &b, 0.5, soak_v3(0, 0, 1), N, 42, &R1, &T1, &V1))) return;
    for (int c = 0; c < 3; ++c) {
        char what[96];
        double sR = hypot(se(&R0, c, N), se(&R1, c, N)), sV = hypot(se(&V0, c, N), se(&V1, c, N));
        snprintf(what, sizeof what, "thick slab R[%d]: guided vs analog (4 se)", c);
        check_close(what, mean(&R1, c, N), mean(&R0, c, N), 4 * sR);
        snprintf(what, sizeof what, "thick slab vertex tally[%d]: guided vs analog (4 se)", c);
        check_close(what, mean(&V1, c, N), mean(&V0, c, N), 4 * sV);
        printf("  channel %d: R analog %.5f +- %.5f guided %.5f +- %.5f; tally analog %.5f +- %.5f guided %.5f +- %.5f\n",
               c, mean(&R0, c, N), se(&R0, c, N), mean(&R1, c, N), se(&R1, c, N), mean(&V0, c, N), se(&V0, c, N),
               mean(&V1, c, N), se(&V1, c, N));
    }
}

static void test_bad_options(void)
{
    soak_medium_rgb m = {soak_rgb3(1, 1, 1), soak_rgb3(0.9, 0.9, 0.9), {0, 0, 1}, NULL, NULL, 0.0};
    soak_slab_boundary sb = {1.0, 1.0, 0, 0.0};
    soak_boundary b;
    soak_slab_boundary_make(&sb, &b);
    soak_walk_options opt;
    soak_walk_options_default(&opt);
    soak_rng rng;
    soak_rng_seed(&rng, 1, 1);
    soak_walk_result_rgb w;
    opt.guide_prob = NAN;
    check_status("guide_prob NaN", soak_medium_walk_rgb(&m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w), SOAK_ERR_ARG);
    opt.guide_prob = 1.0;
    check_status("guide_prob 1", soak_medium_walk_rgb(&m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w), SOAK_ERR_ARG);
    opt.guide_prob = 0.5;
    opt.guide_normal = soak_v3(0, 0, 2);
    check_status("guide_normal not unit", soak_medium_walk_rgb(&m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w),
                 SOAK_ERR_ARG);
}

int main(void)
{
    test_eigenvalue();
    test_direction_pdf();
    test_slab_vs_doubling();
    test_thick_vs_analog();
    test_bad_options();
    return check_finish();
}
