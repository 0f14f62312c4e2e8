/* The tracer's quasi-random sampler (render_sampler.c) against properties
 * of the mathematics it claims, not against its own output:
 *  - 2^k consecutive samples of a pixel's dimension pair form a (0,k,2)-net
 *    in base 2 (every elementary interval of area 2^-k holds exactly one
 *    point), the defining property of Sobol's first two dimensions that
 *    Owen scrambling preserves;
 *  - values lie in [0,1) and, over independent seeds, each coordinate is
 *    uniform (chi-square) and integrals are unbiased;
 *  - padding: different pairs of one pixel are not correlated;
 *  - a smooth integrand converges far faster than independent sampling
 *    (its known integral 1/4 to < 1e-3 with 256 points, where the
 *    Monte Carlo standard error is 1.3e-2);
 *  - past RT_QMC_DIMS the numbers come from the PCG stream (an identical
 *    stream drawn separately gives the same values). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "rt_ctx.h"

static void draw_pair(rt_thread *t, uint64_t seed, uint64_t pixel, uint32_t s, int pair, double *x, double *y)
{
    rt_qmc_start(t, seed, pixel, s);
    t->qmc.dim = 2 * pair;
    *x = rt_rand(t);
    *y = rt_rand(t);
}

static void test_nets(void)
{
    rt_thread t;
    memset(&t, 0, sizeof t);
    soak_rng_seed(&t.rng, 1, 2);
    int bad = 0, out_of_range = 0;
    for (int pixel = 0; pixel < 20; ++pixel)
        for (int pair = 0; pair < RT_QMC_DIMS / 2; ++pair) {
            enum { K = 8, N = 1 << K };
            double x[N], y[N];
            for (int s = 0; s < N; ++s) {
                draw_pair(&t, 77, (uint64_t)pixel, (uint32_t)s, pair, &x[s], &y[s]);
                if (!(x[s] >= 0 && x[s] < 1 && y[s] >= 0 && y[s] < 1)) out_of_range++;
            }
            for (int a = 0; a <= K; ++a) { /* intervals 2^-a wide, 2^-(K-a) high */
                int nx = 1 << a, ny = 1 << (K - a), count[N];
                memset(count, 0, sizeof count);
                for (int s = 0; s < N; ++s) count[(int)(x[s] * nx) * ny + (int)(y[s] * ny)]++;
                for (int c = 0; c < N; ++c) bad += count[c] != 1;
            }
        }
    check_true("values in [0,1)", out_of_range == 0);
    check_true("256 samples of every pair form a (0,8,2)-net (20 pixels, every pair, 9 interval shapes)", bad == 0);
}

static void test_uniform_unbiased(void)
{
    rt_thread t;
    memset(&t, 0, sizeof t);
    soak_rng_seed(&t.rng, 3, 4);
    enum { BINS = 64, M = 64000 };
    int hist[BINS];
    memset(hist, 0, sizeof hist);
    double sum = 0, sum2 = 0;
    for (int k = 0; k < M; ++k) {
        /* independent seeds: one 4-point estimate of the area under x + y < 1 */
        double est = 0;
        for (int s = 0; s < 4; ++s) {
            double x, y;
            draw_pair(&t, 1000 + (uint64_t)k, 5, (uint32_t)s, k % (RT_QMC_DIMS / 2), &x, &y);
            if (s == 0) hist[(int)(x * BINS)]++;
            est += (x + y < 1) / 4.0;
        }
        sum += est;
        sum2 += est * est;
    }
    double chi2 = 0, e = (double)M / BINS;
    for (int b = 0; b < BINS; ++b) chi2 += (hist[b] - e) * (hist[b] - e) / e;
    printf("  first coordinate over %d seeds: chi-square %.1f (63 dof, 0.1%% critical 103.4)\n", M, chi2);
    check_true("uniform over seeds (chi-square < 103.4)", chi2 < 103.4);
    double mean = sum / M, se = sqrt((sum2 / M - mean * mean) / M);
    printf("  area of x + y < 1 from 4-point nets: %.5f +- %.5f (exact 0.5)\n", mean, se);
    check_close("unbiased for a discontinuous integrand", mean, 0.5, 4 * se + 1e-12);
}

static void test_padding_and_convergence(void)
{
    rt_thread t;
    memset(&t, 0, sizeof t);
    soak_rng_seed(&t.rng, 5, 6);
    enum { N = 256 };
    double a[N], b[N], sxy = 0;
    for (int s = 0; s < N; ++s) {
        double x, y;
        draw_pair(&t, 9, 123, (uint32_t)s, 0, &a[s], &y);
        draw_pair(&t, 9, 123, (uint32_t)s, 1, &b[s], &y);
        draw_pair(&t, 9, 123, (uint32_t)s, 2, &x, &y);
        sxy += x * y / N;
    }
    double ma = 0, mb = 0, cab = 0, va = 0, vb = 0;
    for (int s = 0; s < N; ++s) ma += a[s] / N, mb += b[s] / N;
    for (int s = 0; s < N; ++s) {
        cab += (a[s] - ma) * (b[s] - mb);
        va += (a[s] - ma) * (a[s] - ma);
        vb += (b[s] - mb) * (b[s] - mb);
    }
    double r = cab / sqrt(va * vb);
    printf("  correlation of dimension 0 and dimension 2 over 256 samples: %.4f (independent: sd 0.063)\n", r);
    check_true("pairs decorrelated by padding (|r| < 0.25)", fabs(r) < 0.25);
    printf("  mean of x*y over 256 points of one pair: %.6f (exact 0.25; Monte Carlo sd 0.013)\n", sxy);
    check_close("smooth integrand: QMC error < 1e-3", sxy, 0.25, 1e-3);
}

static void test_fallback(void)
{
    rt_thread t;
    memset(&t, 0, sizeof t);
    soak_rng ref;
    soak_rng_seed(&t.rng, 11, 12);
    rt_qmc_start(&t, 1, 2, 3);
    for (int d = 0; d < RT_QMC_DIMS; ++d) rt_rand(&t);
    ref = t.rng;
    int same = 1;
    for (int k = 0; k < 10; ++k) same &= rt_rand(&t) == soak_rng_uniform(&ref);
    check_true("after RT_QMC_DIMS the PCG stream takes over", same);
    rt_thread z;
    memset(&z, 0, sizeof z);
    soak_rng_seed(&z.rng, 11, 12);
    ref = z.rng;
    same = 1;
    for (int k = 0; k < 10; ++k) same &= rt_rand(&z) == soak_rng_uniform(&ref);
    check_true("a zeroed thread (photon tracer) draws plain PCG", same);
}

int main(void)
{
    test_nets();
    test_uniform_unbiased();
    test_padding_and_convergence();
    test_fallback();
    return check_finish();
}
