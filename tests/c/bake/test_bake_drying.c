/* Drying: exact EDT against brute force; the pore schedule against its
 * closed form with brute-force distances (borders first, monotone in time,
 * t_fill = 0 a step); the implicit diffusion step against the eigenvalues of
 * the discrete Neumann Laplacian, conservation, the fully-mixed limit of a
 * huge step, the maximum principle, and the evaporation-only closed form. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/bake.h"

#define PI 3.14159265358979323846

static unsigned lcg(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static double brute_d2(const unsigned char *f, int w, int h, int x, int y)
{
    double best = -1;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            if (f[j * w + i]) {
                double d = (double)(i - x) * (i - x) + (double)(j - y) * (j - y);
                if (best < 0 || d < best) best = d;
            }
    return best;
}

static void test_edt(void)
{
    unsigned seed = 12345;
    const int sizes[][2] = {{1, 1}, {1, 17}, {23, 1}, {31, 19}, {40, 40}, {64, 9}};
    const double densities[] = {0.002, 0.05, 0.3, 0.9};
    double worst = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
        for (size_t d = 0; d < sizeof densities / sizeof densities[0]; ++d) {
            int w = sizes[s][0], h = sizes[s][1];
            unsigned char *f = malloc((size_t)w * h);
            double *d2 = malloc(sizeof(double) * w * h);
            int any = 0;
            for (int i = 0; i < w * h; ++i) f[i] = (lcg(&seed) % 100000) < densities[d] * 100000;
            if (w * h > 1) f[lcg(&seed) % (w * h)] = 1; /* at least one feature */
            else f[0] = 1;
            check_status("edt", soak_edt_squared(f, w, h, d2, &any), SOAK_OK);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) worst = fmax(worst, fabs(d2[y * w + x] - brute_d2(f, w, h, x, y)));
            free(f), free(d2);
        }
    check_close("EDT = brute-force squared distance on random masks (exact)", worst, 0.0, 0.0);
    unsigned char none[12] = {0};
    double d2[12];
    int any = 1;
    check_status("no feature", soak_edt_squared(none, 4, 3, d2, &any), SOAK_OK);
    check_true("no feature reported, distances filled with w^2 + h^2", any == 0 && d2[5] == 25.0);
}

/* Disc of radius R in an n x n mask. */
static soak_image disc(int n, double R)
{
    soak_image m;
    soak_image_alloc(&m, n, n, 1);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double dx = x + 0.5 - n / 2.0, dy = y + 0.5 - n / 2.0;
            m.pixels[y * n + x] = dx * dx + dy * dy < R * R ? 1.0f : 0.0f;
        }
    return m;
}

static void test_schedule(void)
{
    const int n = 48;
    soak_image mask = disc(n, 17);
    /* Reference: brute-force distance to the nearest dry texel. */
    unsigned char *dry = malloc(n * n);
    double *dist = malloc(sizeof(double) * n * n), dmax = 0;
    for (int i = 0; i < n * n; ++i) dry[i] = mask.pixels[i] <= 0.5f;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            dist[y * n + x] = sqrt(brute_d2(dry, n, n, x, y));
            if (!dry[y * n + x]) dmax = fmax(dmax, dist[y * n + x]);
        }
    const double fills[] = {0.0, 0.25};
    for (int f = 0; f < 2; ++f) {
        soak_drying_params p;
        soak_drying_defaults(&p);
        p.t_fill = fills[f];
        double worst = 0;
        int monotone = 1;
        float *prev = NULL;
        for (int k = 0; k <= 100; ++k) {
            p.time = k / 100.0;
            soak_image out;
            check_status("drying bake", soak_bake_drying(&mask, 0, 0, &p, NULL, &out), SOAK_OK);
            for (int i = 0; i < n * n; ++i) {
                double want = 0;
                if (!dry[i]) {
                    double t0 = (1 - p.t_fill) * dist[i] / dmax;
                    want = p.t_fill == 0 ? (p.time < t0 ? 1.0 : 0.0) : 1 - fmin(1, fmax(0, (p.time - t0) / p.t_fill));
                }
                worst = fmax(worst, fabs(out.pixels[i] - want));
                if (prev && out.pixels[i] > prev[i]) monotone = 0;
            }
            free(prev);
            prev = out.pixels; /* keep the pixels, drop the struct */
        }
        free(prev);
        char what[128];
        snprintf(what, sizeof what, "t_fill %g: wetness = 1 - ramp((t - (1-t_fill) d/d_max)/t_fill), brute-force d", fills[f]);
        check_close(what, worst, 0.0, 1e-6);
        check_true("wetness non-increasing in time per texel", monotone);
    }
    /* Rim before centre: first time each reaches 0, t_fill 0.2. */
    soak_drying_params p;
    soak_drying_defaults(&p);
    int rim = (n / 2) * n + (n / 2 - 16), centre = (n / 2) * n + n / 2;
    double t_rim = -1, t_centre = -1;
    for (int k = 0; k <= 200; ++k) {
        p.time = k / 200.0;
        soak_image out;
        soak_bake_drying(&mask, 0, 0, &p, NULL, &out);
        if (t_rim < 0 && out.pixels[rim] == 0) t_rim = p.time;
        if (t_centre < 0 && out.pixels[centre] == 0) t_centre = p.time;
        soak_image_free(&out);
    }
    printf("disc: rim dry at t = %g, centre at t = %g\n", t_rim, t_centre);
    check_true("rim texel is wet at the start and dries before the centre", t_rim > 0 && t_rim < t_centre);
    check_close("the deepest point dries last, at t = 1", t_centre, 1.0, 0.006);
    /* Noise keeps the schedule valid. */
    p.noise_amount = 0.6;
    p.seed = 3;
    double *t0 = malloc(sizeof(double) * n * n);
    unsigned char *wet = malloc(n * n);
    check_status("start times with noise", soak_drying_start_times(&mask, &p, t0, wet), SOAK_OK);
    int ok = 1;
    for (int i = 0; i < n * n; ++i) ok &= wet[i] == !dry[i] && t0[i] >= 0 && t0[i] <= 1 - p.t_fill + 1e-12;
    check_true("noisy start times in [0, 1 - t_fill], wet flags = mask", ok);
    free(t0), free(wet), free(dry), free(dist);
    soak_image_free(&mask);
}

static double total(const double *u, int n)
{
    double s = 0;
    for (int i = 0; i < n; ++i) s += u[i];
    return s;
}

static void test_diffusion_step(void)
{
    /* Cosine mode along x: eigenvector of the no-flux Laplacian with
     * eigenvalue 2 - 2 cos(pi k / n); one backward-Euler step divides its
     * amplitude by 1 + r (2 - 2 cos(pi k / n)); the y solve leaves it. */
    const int w = 40, h = 6, k = 3;
    const double r = 2.5, eps = 0.3;
    double *u = malloc(sizeof(double) * w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) u[y * w + x] = 1 + eps * cos(PI * k * (x + 0.5) / w);
    check_status("step", soak_diffusion_step(u, w, h, r, 0, NULL), SOAK_OK);
    double want = eps / (1 + r * (2 - 2 * cos(PI * k / w))), worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) worst = fmax(worst, fabs(u[y * w + x] - 1 - want * cos(PI * k * (x + 0.5) / w)));
    check_close("cosine mode decays by 1/(1 + r lambda_k)", worst, 0.0, 1e-12);
    free(u);

    const int n = 64;
    unsigned s = 99;
    u = malloc(sizeof(double) * n * n);
    double *u0 = malloc(sizeof(double) * n * n);
    for (int i = 0; i < n * n; ++i) u0[i] = u[i] = (lcg(&s) % 1000) < 300 ? (lcg(&s) % 1000) / 999.0 : 0.0;
    double sum0 = total(u0, n * n), max0 = 0;
    for (int i = 0; i < n * n; ++i) max0 = fmax(max0, u0[i]);
    for (int t = 0; t < 20; ++t) soak_diffusion_step(u, n, n, 3.7, 0, NULL);
    check_close("no evaporation: |total / initial - 1| (20 steps, r = 3.7)", fabs(total(u, n * n) / sum0 - 1), 0.0, 1e-9);
    soak_bake_exec two = {2, NULL, NULL};
    memcpy(u, u0, sizeof(double) * n * n);
    check_status("huge step", soak_diffusion_step(u, n, n, 1e12, 0, &two), SOAK_OK);
    double lo = 1e300, hi = -1e300, mean = sum0 / (n * n), dev = 0;
    int finite = 1;
    for (int i = 0; i < n * n; ++i) {
        finite &= soak_is_finite(u[i]);
        lo = fmin(lo, u[i]), hi = fmax(hi, u[i]);
        dev = fmax(dev, fabs(u[i] - mean));
    }
    check_true("r = 1e12: finite", finite);
    check_true("r = 1e12: maximum principle, 0 <= u <= max initial", lo >= 0 && hi <= max0);
    check_close("r = 1e12: fully mixed, every texel = the mean", dev, 0.0, 1e-6 * mean);
    check_close("r = 1e12: |total / initial - 1|", fabs(total(u, n * n) / sum0 - 1), 0.0, 1e-9);
    memcpy(u, u0, sizeof(double) * n * n);
    for (int t = 0; t < 5; ++t) soak_diffusion_step(u, n, n, 1e30, 0.001, NULL);
    lo = 1e300, hi = -1e300;
    for (int i = 0; i < n * n; ++i) lo = fmin(lo, u[i]), hi = fmax(hi, u[i]);
    check_true("r = 1e30 with evaporation: 0 <= u <= max initial", lo >= 0 && hi <= max0 && soak_is_finite(hi));
    check_status("r NaN rejected", soak_diffusion_step(u, n, n, NAN, 0, NULL), SOAK_ERR_ARG);
    check_status("negative evaporation rejected", soak_diffusion_step(u, n, n, 1, -1, NULL), SOAK_ERR_ARG);
    free(u), free(u0);
}

static void test_diffusion_bake(void)
{
    const int n = 64;
    soak_image mask = disc(n, 20);
    soak_drying_params p;
    soak_drying_defaults(&p);
    p.mode = SOAK_DRYING_DIFFUSION;
    p.diffusion_length = 0;
    p.time = 0.3;
    p.steps = 7;
    soak_image out;
    check_status("evaporation only", soak_bake_drying(&mask, 0, 0, &p, NULL, &out), SOAK_OK);
    double worst = 0;
    for (int i = 0; i < n * n; ++i) worst = fmax(worst, fabs(out.pixels[i] - (mask.pixels[i] > 0.5f ? 0.7 : 0.0)));
    check_close("no diffusion: film depth 1 - t / drying_time", worst, 0.0, 1e-6);
    soak_image_free(&out);

    p.diffusion_length = 6;
    p.steps = 16;
    int rim = (n / 2) * n + (n / 2 - 19), centre = (n / 2) * n + n / 2;
    double t_rim = -1, t_centre = -1, prev_centre = 2;
    int centre_monotone = 1, bounded = 1;
    for (int k = 1; k <= 60; ++k) {
        p.time = k * 0.025;
        check_status("diffusion bake", soak_bake_drying(&mask, 0, 0, &p, NULL, &out), SOAK_OK);
        for (int i = 0; i < n * n; ++i) bounded &= out.pixels[i] >= 0 && out.pixels[i] <= 1;
        if (t_rim < 0 && out.pixels[rim] == 0) t_rim = p.time;
        if (t_centre < 0 && out.pixels[centre] == 0) t_centre = p.time;
        centre_monotone &= out.pixels[centre] <= prev_centre;
        prev_centre = out.pixels[centre];
        soak_image_free(&out);
    }
    printf("diffusion disc: rim dry at t = %g, centre at t = %g\n", t_rim, t_centre);
    check_true("diffusion: wetness in [0, 1]", bounded);
    check_true("diffusion: the puddle shrinks from its edge (rim dry before the centre)", t_rim > 0 && (t_centre < 0 || t_rim < t_centre));
    check_true("diffusion: centre wetness non-increasing", centre_monotone);
    soak_image_free(&mask);
}

static void test_arguments(void)
{
    soak_drying_params p;
    soak_drying_defaults(&p);
    soak_image out = {0, 0, 0, NULL};
    check_status("no mask, 0 x 5", soak_bake_drying(NULL, 0, 5, &p, NULL, &out), SOAK_ERR_ARG);
    p.t_fill = 1.5;
    check_status("t_fill 1.5", soak_bake_drying(NULL, 8, 8, &p, NULL, &out), SOAK_ERR_ARG);
    soak_drying_defaults(&p);
    p.time = NAN;
    check_status("time NaN", soak_bake_drying(NULL, 8, 8, &p, NULL, &out), SOAK_ERR_ARG);
    soak_drying_defaults(&p);
    p.noise_amount = 1;
    p.time = 0;
    check_status("all-wet surface with noise", soak_bake_drying(NULL, 16, 16, &p, NULL, &out), SOAK_OK);
    int all_wet = 1;
    for (int i = 0; i < 256; ++i) all_wet &= out.pixels[i] == 1.0f;
    check_true("all wet at t = 0", all_wet);
    soak_image_free(&out);
    p.time = 1;
    soak_bake_drying(NULL, 16, 16, &p, NULL, &out);
    int all_dry = 1;
    for (int i = 0; i < 256; ++i) all_dry &= out.pixels[i] == 0.0f;
    check_true("all dry at t = 1", all_dry);
    soak_image_free(&out);
}

int main(void)
{
    test_edt();
    test_schedule();
    test_diffusion_step();
    test_diffusion_bake();
    test_arguments();
    return check_finish();
}
