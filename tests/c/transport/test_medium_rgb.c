/* The unified walk's RGB extensions (soak/medium.h): spectral tracking of a
 * heterogeneous RGB medium against adding-doubling per channel, RGB ratio
 * tracking through a ramp (analytic), and the vertex hook the renderer uses
 * for next-event estimation and photon storage (collision-estimator and
 * first-collision identities). */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "measure_refs.h"
#include "soak/medium.h"

/* Per-channel optical thickness and albedo of the slab cases (thickness 1). */
static const double TAU[3] = {0.5, 2.0, 1.0}, OMEGA[3] = {0.9, 0.5, 1.0};

/* Constant coefficients: the heterogeneous code path with a majorant of 3
 * above every channel's extinction, so most tentative collisions are null. */
static soak_status constant_coeffs(const void *ctx, soak_vec3 pos, soak_medium_point *out)
{
    (void)ctx;
    (void)pos;
    out->sigma_s = soak_rgb3(TAU[0] * OMEGA[0], TAU[1] * OMEGA[1], TAU[2] * OMEGA[2]);
    out->sigma_a = soak_rgb3(TAU[0] * (1 - OMEGA[0]), TAU[1] * (1 - OMEGA[1]), TAU[2] * (1 - OMEGA[2]));
    out->phase = (soak_hg2){0, 0, 1};
    return SOAK_OK;
}

/* Extinction rising linearly with depth, slope k_c per channel (no scattering). */
static soak_status ramp_coeffs(const void *ctx, soak_vec3 pos, soak_medium_point *out)
{
    const double *k = ctx;
    double z = -pos.z;
    out->sigma_s = soak_rgb3(0, 0, 0);
    out->sigma_a = soak_rgb3(k[0] * z, k[1] * z, k[2] * z);
    out->phase = (soak_hg2){0, 0, 1};
    return SOAK_OK;
}

static soak_status too_dense(const void *ctx, soak_vec3 pos, soak_medium_point *out)
{
    (void)ctx;
    (void)pos;
    out->sigma_s = soak_rgb3(2, 0, 0);
    out->sigma_a = soak_rgb3(2, 0, 0);
    out->phase = (soak_hg2){0, 0, 1};
    return SOAK_OK;
}

static void test_spectral_tracking_slab(void)
{
    soak_medium_rgb m = {soak_rgb3(0, 0, 0), soak_rgb3(0, 0, 0), {0, 0, 1}, constant_coeffs, NULL, 3.0};
    soak_slab_boundary sb = {1.0, 1.0, 0, 0.0};
    soak_boundary b;
    check_status("slab boundary", soak_slab_boundary_make(&sb, &b), SOAK_OK);
    const long N = 100000;
    double R[3] = {0}, R2[3] = {0}, T[3] = {0}, T2[3] = {0};
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 21, (uint64_t)i);
        soak_walk_result_rgb w;
        if (soak_medium_walk_rgb(&m, NULL, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w) != SOAK_OK) {
            check_true("spectral tracking status", 0);
            return;
        }
        if (w.end != SOAK_WALK_EXITED) continue;
        for (int c = 0; c < 3; ++c) {
            double v = soak_rgb_at(w.weight, c);
            if (w.dir.z > 0) {
                R[c] += v;
                R2[c] += v * v;
            } else {
                T[c] += v;
                T2[c] += v * v;
            }
        }
    }
    for (int c = 0; c < 3; ++c) {
        double Rref, Tref;
        ref_slab_doubling(TAU[c], OMEGA[c], 1.0, &Rref, &Tref);
        double r = R[c] / N, t = T[c] / N;
        double er = sqrt((R2[c] / N - r * r) / (N - 1)), et = sqrt((T2[c] / N - t * t) / (N - 1));
        printf("  spectral tracking channel %d (tau %g, omega %g): R %.5f +- %.5f (ref %.5f), T %.5f +- %.5f (ref %.5f)\n",
               c, TAU[c], OMEGA[c], r, er, Rref, t, et, Tref);
        check_close("spectral tracking R vs doubling (3 sigma)", r, Rref, 3 * er + 1e-5);
        check_close("spectral tracking T vs doubling (3 sigma)", t, Tref, 3 * et + 1e-5);
    }
}

/* T_c = exp(-k_c L^2 / 2) for extinction k_c z over depth L. */
static void test_rgb_ratio_tracking(void)
{
    const double k[3] = {0.2, 0.6, 1.0}, L = 1.5;
    soak_medium_rgb m = {soak_rgb3(0, 0, 0), soak_rgb3(0, 0, 0), {0, 0, 1}, ramp_coeffs, k, k[2] * L};
    const long N = 50000;
    double s[3] = {0}, s2[3] = {0};
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 22, (uint64_t)i);
        soak_rgb T;
        if (soak_medium_rgb_transmittance(&m, soak_v3(0, 0, 0), soak_v3(0, 0, -1), L, &rng, &T) != SOAK_OK) {
            check_true("rgb ratio tracking status", 0);
            return;
        }
        for (int c = 0; c < 3; ++c) {
            s[c] += soak_rgb_at(T, c);
            s2[c] += soak_rgb_at(T, c) * soak_rgb_at(T, c);
        }
    }
    for (int c = 0; c < 3; ++c) {
        double mean = s[c] / N, err = sqrt((s2[c] / N - mean * mean) / (N - 1));
        check_close("rgb ratio tracking through a ramp (3 sigma)", mean, exp(-k[c] * L * L / 2), 3 * err + 1e-12);
    }
    soak_medium_rgb h = {soak_rgb3(0.5, 0, 2), soak_rgb3(1, 1, 1), {0, 0, 1}, NULL, NULL, 0};
    soak_rng rng;
    soak_rng_seed(&rng, 1, 1);
    soak_rgb T;
    check_status("homogeneous rgb transmittance", soak_medium_rgb_transmittance(&h, soak_v3(0, 0, 0), soak_v3(0, 0, -1), L, &rng, &T),
                 SOAK_OK);
    check_close("homogeneous rgb transmittance exact (r)", T.r, exp(-0.5 * L), 1e-15);
    check_close("sigma_t = 0 channel: T = 1", T.g, 1.0, 0.0);
    check_close("homogeneous rgb transmittance exact (b)", T.b, exp(-2 * L), 1e-15);
    m.coeffs = too_dense;
    m.majorant = 3.0;
    check_status("extinction above the majorant detected",
                 soak_medium_rgb_transmittance(&m, soak_v3(0, 0, 0), soak_v3(0, 0, -1), 10.0, &rng, &T), SOAK_ERR_NUMERIC);
}

typedef struct absorb_tally {
    double omega, sum;
} absorb_tally;

/* Collision estimator of absorption: the hook sees the weight after the
 * collision, w omega; the energy absorbed there is w (1 - omega). */
static int tally_absorption(void *ctx, soak_vec3 pos, soak_vec3 dir_in, soak_rgb weight, const soak_medium_point *local,
                            soak_rng *rng)
{
    (void)pos;
    (void)dir_in;
    (void)local;
    (void)rng;
    absorb_tally *t = ctx;
    t->sum += weight.r * (1 - t->omega) / t->omega;
    return 1;
}

static int stop_at_first(void *ctx, soak_vec3 pos, soak_vec3 dir_in, soak_rgb weight, const soak_medium_point *local,
                         soak_rng *rng)
{
    (void)ctx;
    (void)pos;
    (void)dir_in;
    (void)weight;
    (void)local;
    (void)rng;
    return 0;
}

static void test_vertex_hook(void)
{
    const double tau = 1.0, omega = 0.8;
    soak_medium m = {tau, omega, {0, 0, 1}, NULL, NULL};
    soak_slab_boundary sb = {1.0, 1.0, 0, 0.0};
    soak_boundary b;
    soak_slab_boundary_make(&sb, &b);
    absorb_tally tally = {omega, 0};
    soak_walk_options opt;
    soak_walk_options_default(&opt);
    opt.on_vertex = tally_absorption;
    opt.vertex_ctx = &tally;
    const long N = 100000;
    double sa = 0, sa2 = 0;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 23, (uint64_t)i);
        soak_walk_result w;
        tally.sum = 0;
        soak_medium_walk(&m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w);
        sa += tally.sum;
        sa2 += tally.sum * tally.sum;
    }
    double Rref, Tref;
    ref_slab_doubling(tau, omega, 1.0, &Rref, &Tref);
    double A = sa / N, eA = sqrt((sa2 / N - A * A) / (N - 1));
    printf("  collision-estimated absorption %.5f +- %.5f, doubling 1 - R - T %.5f\n", A, eA, 1 - Rref - Tref);
    check_close("vertex hook: absorption = 1 - R - T of doubling (3 sigma)", A, 1 - Rref - Tref, 3 * eA + 1e-5);

    /* First-collision identity: with n = 1 a path collides before leaving a
     * slab of thickness tau with probability 1 - e^-tau; the hook stops it
     * there with the weight omega. */
    opt.on_vertex = stop_at_first;
    long stopped = 0;
    int weight_ok = 1;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 24, (uint64_t)i);
        soak_walk_result w;
        soak_medium_walk(&m, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w);
        if (w.end == SOAK_WALK_STOPPED) {
            ++stopped;
            weight_ok &= w.weight == omega && w.scatters == 0;
        }
    }
    double p = (double)stopped / N;
    check_close("vertex hook stop: P = 1 - e^-tau (3 sigma)", p, 1 - exp(-tau), 3 * sqrt(p * (1 - p) / N));
    check_true("stopped paths carry the first collision's weight", weight_ok);

    soak_medium_rgb mr = {soak_rgb3(1, 1, 1), soak_rgb3(1, 1, 1), {0, 0, 1}, NULL, NULL, 0};
    soak_rng rng;
    soak_rng_seed(&rng, 1, 0);
    soak_walk_result_rgb w;
    soak_walk_options_default(&opt);
    opt.weight = soak_rgb3(1, NAN, 1);
    check_status("NaN entry weight", soak_medium_walk_rgb(&mr, &opt, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w),
                 SOAK_ERR_ARG);
    mr.coeffs = constant_coeffs;
    mr.majorant = -1;
    check_status("negative majorant", soak_medium_rgb_validate(&mr), SOAK_ERR_ARG);
}

int main(void)
{
    test_spectral_tracking_slab();
    test_rgb_ratio_tracking();
    test_vertex_hook();
    return check_finish();
}
