/* Random-walk building blocks: argument checks, Fresnel slab boundary
 * (bounce series, total internal reflection -> capped and reported),
 * absorption-only media, delta and ratio tracking for heterogeneous media,
 * determinism of soak_measure_run across thread counts, exact energy
 * identities of the film configuration. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "measure_refs.h"
#include "soak/fresnel.h"
#include "soak/measure.h"
#include "soak/medium.h"

static double const_density(const void *ctx, soak_vec3 p)
{
    (void)p;
    return *(const double *)ctx;
}

/* Density rising linearly from 0 at z = 0 to 1 at z = -L. */
static double linear_density(const void *ctx, soak_vec3 p)
{
    double L = *(const double *)ctx, d = -p.z / L;
    return d < 0 ? 0 : (d > 1 ? 1 : d);
}

static double bad_density(const void *ctx, soak_vec3 p)
{
    (void)ctx;
    (void)p;
    return 1.5;
}

static void test_arguments(void)
{
    soak_medium m = {1, 0.5, {0, 0, 1}, NULL, NULL};
    soak_slab_boundary sb = {1, 1, 0, 0};
    soak_boundary b;
    soak_rng rng;
    soak_rng_seed(&rng, 1, 0);
    soak_walk_result w;
    check_status("slab make", soak_slab_boundary_make(&sb, &b), SOAK_OK);
    soak_vec3 p = soak_v3(0, 0, 0), down = soak_v3(0, 0, -1);
    check_status("walk ok", soak_medium_walk(&m, NULL, p, down, &b, &rng, &w), SOAK_OK);
    check_status("NULL boundary", soak_medium_walk(&m, NULL, p, down, NULL, &rng, &w), SOAK_ERR_NULL);
    check_status("non-unit dir", soak_medium_walk(&m, NULL, p, soak_v3(0, 0, -2), &b, &rng, &w), SOAK_ERR_ARG);
    check_status("NaN position", soak_medium_walk(&m, NULL, soak_v3(NAN, 0, 0), down, &b, &rng, &w), SOAK_ERR_ARG);
    m.sigma_t = NAN;
    check_status("NaN sigma_t", soak_medium_validate(&m), SOAK_ERR_ARG);
    m.sigma_t = -1;
    check_status("negative sigma_t", soak_medium_validate(&m), SOAK_ERR_ARG);
    m.sigma_t = 1;
    m.albedo = 1.0000001;
    check_status("albedo > 1", soak_medium_validate(&m), SOAK_ERR_ARG);
    m.albedo = 0.5;
    m.phase.g1 = 1.0;
    check_status("g = 1", soak_medium_validate(&m), SOAK_ERR_ARG);
    m.phase.g1 = 0;
    soak_walk_options opt;
    soak_walk_options_default(&opt);
    opt.roulette_threshold = 0;
    check_status("roulette threshold 0", soak_medium_walk(&m, &opt, p, down, &b, &rng, &w), SOAK_ERR_ARG);
    soak_walk_options_default(&opt);
    opt.max_events = 0;
    check_status("max_events 0", soak_medium_walk(&m, &opt, p, down, &b, &rng, &w), SOAK_ERR_ARG);
    soak_slab_boundary bad = {0, 1, 0, 0};
    check_status("zero thickness", soak_slab_boundary_validate(&bad), SOAK_ERR_ARG);
    bad.thickness = 1;
    bad.ior = 0.9;
    check_status("ior < 1", soak_slab_boundary_validate(&bad), SOAK_ERR_ARG);
    bad.ior = 1;
    bad.diffuse_base = 1;
    bad.thickness = INFINITY;
    check_status("diffuse base under a half-space", soak_slab_boundary_validate(&bad), SOAK_ERR_ARG);
    m.density = bad_density;
    check_status("density > 1 detected", soak_medium_walk(&m, NULL, p, down, &b, &rng, &w), SOAK_ERR_NUMERIC);
    soak_medium_rgb mr = {soak_rgb3(1, NAN, 1), soak_rgb3(1, 1, 1), {0, 0, 1}, NULL, NULL, 0};
    check_status("rgb NaN sigma", soak_medium_rgb_validate(&mr), SOAK_ERR_ARG);

    soak_measure_setup s;
    soak_measure_setup_default(&s);
    check_status("default setup valid", soak_measure_validate(&s), SOAK_OK);
    s.quantity = SOAK_MEASURE_T;
    check_status("T of a half-space", soak_measure_validate(&s), SOAK_ERR_ARG);
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_SLAB;
    s.tau = -1;
    check_status("negative tau", soak_measure_validate(&s), SOAK_ERR_ARG);
    s.tau = NAN;
    check_status("NaN tau", soak_measure_validate(&s), SOAK_ERR_ARG);
    soak_measure_setup_default(&s);
    s.cos_incidence = 0;
    check_status("grazing collimated incidence", soak_measure_validate(&s), SOAK_ERR_ARG);
    soak_measure_setup_default(&s);
    s.threads = 0;
    check_status("0 threads", soak_measure_validate(&s), SOAK_ERR_ARG);
}

/* A clear (sigma_t = 0) slab of index n; a path leaving the middle upwards
 * at cosine c bounces between the faces, each hit reflecting with the same
 * Fresnel R (both faces see the same angle): P(exit top) = (1-R) sum R^2k =
 * 1/(1+R). Beyond the critical angle it is trapped and must be reported
 * as capped, not lost. */
static void test_fresnel_slab(void)
{
    const double n = 1.5, c = 0.8;
    double R = soak_fresnel_dielectric_raw(c, 1.0 / n, NULL);
    soak_medium m = {0, 1, {0, 0, 1}, NULL, NULL};
    soak_slab_boundary sb = {1, n, 0, 0};
    soak_boundary b;
    soak_slab_boundary_make(&sb, &b);
    soak_vec3 d = soak_v3(sqrt(1 - c * c), 0, c);
    const long N = 200000;
    long top = 0, bottom = 0, capped = 0;
    int snell = 1;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 9, (uint64_t)i);
        soak_walk_result w;
        soak_medium_walk(&m, NULL, soak_v3(0, 0, -0.5), d, &b, &rng, &w);
        if (w.end == SOAK_WALK_EXITED) {
            if (w.dir.z > 0) ++top; else ++bottom;
            /* Snell: sin_out = n sin_in. */
            snell &= fabs(sqrt(w.dir.x * w.dir.x + w.dir.y * w.dir.y) - n * sqrt(1 - c * c)) < 1e-12;
        } else if (w.end == SOAK_WALK_CAPPED) {
            ++capped;
        }
    }
    double p = (double)top / N, sp = sqrt(p * (1 - p) / N);
    check_close("clear Fresnel slab: P(top) = 1/(1+R) (3 sigma)", p, 1.0 / (1.0 + R), 3 * sp);
    check_true("clear Fresnel slab: every path exits", top + bottom == N && capped == 0);
    check_true("exit directions obey Snell's law", snell);

    soak_vec3 out;
    double ct = 0.5; /* sin_i = 0.866 > 1/1.5: beyond the critical angle */
    check_true("refract_out: TIR detected", !soak_slab_refract_out(soak_v3(sqrt(1 - ct * ct), 0, ct), n, &out));
    soak_walk_options opt;
    soak_walk_options_default(&opt);
    opt.max_events = 1000;
    soak_rng rng;
    soak_rng_seed(&rng, 3, 3);
    soak_walk_result w;
    soak_medium_walk(&m, &opt, soak_v3(0, 0, -0.5), soak_v3(sqrt(1 - ct * ct), 0, ct), &b, &rng, &w);
    check_true("trapped by TIR: reported as capped with its weight", w.end == SOAK_WALK_CAPPED && w.weight == 1.0);
    check_true("trapped by TIR: stopped at the cap", w.events == 1000);
}

/* Purely absorbing slab: R = 0 and T = e^{-tau} in expectation; the
 * walk with albedo 0 ends at the first collision. */
static void test_absorbing(void)
{
    const double tau = 0.7;
    soak_medium m = {tau, 0, {0, 0, 1}, NULL, NULL};
    soak_slab_boundary sb = {1, 1, 0, 0};
    soak_boundary b;
    soak_slab_boundary_make(&sb, &b);
    const long N = 100000;
    long t = 0, r = 0;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 4, (uint64_t)i);
        soak_walk_result w;
        soak_medium_walk(&m, NULL, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w);
        if (w.end == SOAK_WALK_EXITED) {
            if (w.dir.z < 0) ++t; else ++r;
        }
    }
    double T = (double)t / N;
    check_close("absorbing slab: T = e^-tau (3 sigma)", T, exp(-tau), 3 * sqrt(T * (1 - T) / N));
    check_true("absorbing slab: R = 0", r == 0);
}

/* Delta tracking with a constant density 1/2 under majorant 2 is the same
 * medium as sigma_t = 1: compare with adding-doubling. */
static void test_delta_tracking(void)
{
    const double half = 0.5, tau = 1.0, omega = 0.9;
    soak_medium m = {2.0, omega, {0, 0, 1}, const_density, &half};
    soak_slab_boundary sb = {tau, 1, 0, 0};
    soak_boundary b;
    soak_slab_boundary_make(&sb, &b);
    const long N = 100000;
    double sr = 0, sr2 = 0, st = 0, st2 = 0;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 12, (uint64_t)i);
        soak_walk_result w;
        soak_medium_walk(&m, NULL, soak_v3(0, 0, 0), soak_v3(0, 0, -1), &b, &rng, &w);
        if (w.end != SOAK_WALK_EXITED) continue;
        if (w.dir.z > 0) {
            sr += w.weight;
            sr2 += w.weight * w.weight;
        } else {
            st += w.weight;
            st2 += w.weight * w.weight;
        }
    }
    double Rref, Tref;
    ref_slab_doubling(tau, omega, 1.0, &Rref, &Tref);
    double R = sr / N, T = st / N;
    double eR = sqrt((sr2 / N - R * R) / (N - 1)), eT = sqrt((st2 / N - T * T) / (N - 1));
    printf("delta tracking slab: R %.5f +- %.5f (ref %.5f), T %.5f +- %.5f (ref %.5f)\n", R, eR, Rref, T, eT, Tref);
    check_close("delta tracking R vs doubling (3 sigma)", R, Rref, 3 * eR + 1e-5);
    check_close("delta tracking T vs doubling (3 sigma)", T, Tref, 3 * eT + 1e-5);
}

/* Ratio tracking through a linear ramp: integral of sigma over depth L at
 * majorant s is s L / 2, so T = exp(-s L / 2). */
static void test_ratio_tracking(void)
{
    const double L = 2.0, s = 1.5;
    soak_medium m = {s, 1, {0, 0, 1}, linear_density, &L};
    const long N = 100000;
    double sum = 0, sum2 = 0;
    for (long i = 0; i < N; ++i) {
        soak_rng rng;
        soak_rng_seed(&rng, 13, (uint64_t)i);
        double T;
        if (soak_medium_transmittance(&m, soak_v3(0, 0, 0), soak_v3(0, 0, -1), L, &rng, &T) != SOAK_OK) {
            check_true("ratio tracking status", 0);
            return;
        }
        sum += T;
        sum2 += T * T;
    }
    double mean = sum / N, err = sqrt((sum2 / N - mean * mean) / (N - 1));
    check_close("ratio tracking through a ramp (3 sigma)", mean, exp(-s * L / 2), 3 * err);
    m.density = NULL;
    soak_rng rng;
    soak_rng_seed(&rng, 1, 1);
    double T;
    soak_medium_transmittance(&m, soak_v3(0, 0, 0), soak_v3(0, 0, -1), L, &rng, &T);
    check_close("homogeneous transmittance exact", T, exp(-s * L), 1e-15);
    check_status("ratio tracking to infinity refused",
                 soak_medium_transmittance(&(soak_medium){1, 1, {0, 0, 1}, linear_density, &L}, soak_v3(0, 0, 0),
                                           soak_v3(0, 0, -1), INFINITY, &rng, &T),
                 SOAK_ERR_ARG);
}

static void test_measure_identities(void)
{
    soak_measure_setup s;
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_FILM;
    s.ior = 1.33;
    s.base_albedo = 1.0;
    s.paths = 20000;
    soak_measure_result r;
    check_status("film A=1", soak_measure_run(&s, &r), SOAK_OK);
    check_close("lossless film reflects everything", r.value, 1.0, 1e-12);
    check_close("... with zero variance", r.std_error, 0.0, 1e-12);
    s.base_albedo = 0.0;
    s.ior = 1.0;
    check_status("film A=0 n=1", soak_measure_run(&s, &r), SOAK_OK);
    check_close("black base, no interface: R = 0", r.value, 0.0, 0.0);
    s.ior = 1.33;
    s.cos_incidence = 1e-9;
    check_status("near-grazing film", soak_measure_run(&s, &r), SOAK_OK);
    check_true("near-grazing film: mirror-like, finite", r.value > 0.99 && r.value <= 1.0);

    /* Same seed: identical result whatever the thread count. */
    soak_measure_setup_default(&s);
    s.config = SOAK_MEASURE_SLAB;
    s.tau = 1.0;
    s.albedo = 0.8;
    s.phase = (soak_hg2){0.6, -0.3, 0.7};
    s.ior = 1.4;
    s.paths = 30000;
    s.seed = 5;
    soak_measure_result a, b;
    s.threads = 1;
    check_status("1 thread", soak_measure_run(&s, &a), SOAK_OK);
    s.threads = 2;
    check_status("2 threads", soak_measure_run(&s, &b), SOAK_OK);
    check_true("deterministic across thread counts",
               a.value == b.value && a.std_error == b.std_error && a.transmittance == b.transmittance);
    check_true("slab with Fresnel faces: R + T <= 1", a.reflectance + a.transmittance <= 1.0);
    s.seed = 6;
    check_status("other seed", soak_measure_run(&s, &b), SOAK_OK);
    check_true("another seed gives another estimate", a.value != b.value);
}

int main(void)
{
    test_arguments();
    test_fresnel_slab();
    test_absorbing();
    test_delta_tracking();
    test_ratio_tracking();
    test_measure_identities();
    return check_finish();
}
