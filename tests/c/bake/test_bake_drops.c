/* Drops bake against independent references: the impact flux against this
 * file's own quadrature of Marshall-Palmer x Atlas et al.; impact counts per
 * cell and per time bin (chi-square), none where the exposure is 0, the
 * exposure-weighted count, complete spatial randomness on the torus
 * (Clark-Evans nearest-neighbour ratio), the Poisson (Boolean-model)
 * coverage law 1 - exp(-n a t) with a from Clanet et al.'s spread factor
 * computed here, water volume conservation, monotone drying to dry, and
 * bit-identical maps at 1 and 2 threads and for frames baked in chunks. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "soak/bake_drops.h"

#define PI 3.14159265358979323846

/* Marshall & Palmer 1948 and Atlas et al. 1973, written out here. */
static double impact_density(double d_mm, double rate)
{
    double lam = 4.1 * pow(rate, -0.21), v = 9.65 - 10.3 * exp(-0.6 * d_mm);
    return 8000.0 * exp(-lam * d_mm) * (v > 0 ? v : 0);
}

/* Clanet et al. 2004: d_max / D = 0.9 We^(1/4), at least 1. */
static double spread_area_m2(double d_mm)
{
    if (d_mm < 0.3) return 0; /* the coverage test's --min-drop */
    double v = 9.65 - 10.3 * exp(-0.6 * d_mm);
    if (v <= 0) return 0;
    double we = 998.2 * v * v * d_mm * 1e-3 / 0.0728, f = fmax(1.0, 0.9 * pow(we, 0.25));
    double d = f * d_mm * 1e-3;
    return PI / 4 * d * d;
}

/* Composite Simpson on [0, 6] mm of density(D) * g(D), 60000 intervals. */
static double simpson(double rate, double (*g)(double))
{
    const int n = 60000;
    double h = 6.0 / n, s = 0;
    for (int i = 0; i <= n; ++i) {
        double d = i * h, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        s += w * impact_density(d, rate) * (g ? g(d) : 1);
    }
    return s * h / 3;
}

static double cube_volume_mm3(double d)
{
    return PI / 6 * d * d * d;
}

static void test_flux(void)
{
    const double rates[] = {0.5, 2, 10, 50, 200};
    for (size_t k = 0; k < sizeof rates / sizeof rates[0]; ++k) {
        char what[160];
        snprintf(what, sizeof what, "impact flux at %g mm/h = quadrature of N(D) v(D)", rates[k]);
        check_rel(what, soak_drop_flux(rates[k], 0, 6), simpson(rates[k], NULL), 1e-6);
    }
    check_rel("Lambda(1 mm/h) = 4.1 /mm (Marshall-Palmer)", soak_mp_lambda(1), 4.1, 1e-12);
    check_rel("v(2 mm) = 9.65 - 10.3 e^-1.2 (Atlas et al.)", soak_drop_velocity(2), 9.65 - 10.3 * exp(-1.2), 1e-12);
    check_close("no drops land below 0.1087 mm", soak_drop_velocity(0.1), 0, 0);
    /* The two fits carry 1.08-1.18 R of water (stated in bake_drops.h). */
    for (double r = 1; r <= 50; r *= 7) {
        double carried = simpson(r, cube_volume_mm3) * 1e-9 * 3.6e6; /* m/s -> mm/h */
        char what[160];
        snprintf(what, sizeof what, "water carried by MP x Atlas at %g mm/h within [1.05, 1.20] R (%.3f R)", r,
                 carried / r);
        check_true(what, carried > 1.05 * r && carried < 1.20 * r);
    }
}

static soak_drops_params plane(double rate, double texel)
{
    soak_drops_params p;
    soak_drops_defaults(&p);
    p.rate_mm_h = rate;
    p.texel_m = texel;
    p.seed = 7;
    return p;
}

/* Chi-square of counts in a bins x bins grid not aligned with the
 * generator's cells, and in 16 time bins. */
static void test_counts(void)
{
    const int size = 256, bins = 10, tbins = 16;
    soak_drops_params p = plane(10, 1e-3);
    soak_drop_impact *v = NULL;
    size_t n = 0;
    long slabs = 64; /* 4 s */
    check_status("impacts", soak_drops_impacts(&p, NULL, size, size, 0, slabs, &v, &n), SOAK_OK);
    double duration = slabs * SOAK_DROPS_SLAB, area = pow(size * 1e-3, 2);
    double mean = simpson(10, NULL) * area * duration;
    check_close("total impacts within 4 sigma of n A T", (n - mean) / sqrt(mean), 0, 4);
    double cells[100] = {0}, times[16] = {0}, phase[64] = {0};
    int sorted = 1;
    for (size_t i = 0; i < n; ++i) {
        /* position inside the generator's 32-texel cell, 8 x 8 bins: seams or
         * edge effects of the cells would make it non-uniform */
        phase[(int)(fmod(v[i].y, SOAK_DROPS_CELL) / 4) * 8 + (int)(fmod(v[i].x, SOAK_DROPS_CELL) / 4)] += 1;
        cells[(int)(v[i].y * bins / size) * bins + (int)(v[i].x * bins / size)] += 1;
        times[(int)(v[i].t / duration * tbins)] += 1;
        if (i && v[i].t < v[i - 1].t) sorted = 0;
    }
    check_true("impacts in time order", sorted);
    double chi = 0, chit = 0, e = (double)n / (bins * bins), et = (double)n / tbins;
    for (int c = 0; c < bins * bins; ++c) chi += (cells[c] - e) * (cells[c] - e) / e;
    for (int c = 0; c < tbins; ++c) chit += (times[c] - et) * (times[c] - et) / et;
    /* 99 and 15 degrees of freedom: mean +- 4 sd */
    check_true("chi-square over 10x10 cells within 99 +- 4 sqrt(198)", fabs(chi - 99) < 4 * sqrt(198));
    check_true("chi-square over 16 time bins within 15 +- 4 sqrt(30)", fabs(chit - 15) < 4 * sqrt(30));
    double chip = 0, ep = (double)n / 64;
    for (int c = 0; c < 64; ++c) chip += (phase[c] - ep) * (phase[c] - ep) / ep;
    check_true("chi-square of positions within the generator's cells within 63 +- 4 sqrt(126)",
               fabs(chip - 63) < 4 * sqrt(126));
    printf("  chi2 space %.1f (99 dof), time %.1f (15 dof), within cells %.1f (63 dof), %zu impacts (mean %.1f)\n",
           chi, chit, chip, n, mean);
    free(v);
}

static double torus_d2(double ax, double ay, double bx, double by, double size)
{
    double dx = fabs(ax - bx), dy = fabs(ay - by);
    dx = fmin(dx, size - dx), dy = fmin(dy, size - dy);
    return dx * dx + dy * dy;
}

/* Clark & Evans (Ecology 35, 1954): mean nearest-neighbour distance of a
 * Poisson pattern of density rho is 1 / (2 sqrt(rho)), standard error
 * 0.26136 / sqrt(N rho); on the torus no edge correction is needed. Cells
 * of the generator would show as a ratio != 1 (grid: > 1, clumps: < 1). */
static void test_randomness(void)
{
    const int size = 200; /* not a multiple of the 32-texel cells */
    soak_drops_params p = plane(10, 1e-3);
    soak_drop_impact *v = NULL;
    size_t n = 0;
    check_status("impacts", soak_drops_impacts(&p, NULL, size, size, 0, 40, &v, &n), SOAK_OK);
    double sum = 0;
    for (size_t i = 0; i < n; ++i) {
        double best = 1e300;
        for (size_t j = 0; j < n; ++j)
            if (j != i) best = fmin(best, torus_d2(v[i].x, v[i].y, v[j].x, v[j].y, size));
        sum += sqrt(best);
    }
    double rho = n / ((double)size * size), ratio = (sum / n) * 2 * sqrt(rho), se = 0.26136 / sqrt(n * rho);
    printf("  Clark-Evans R = %.4f (%zu points, 1 sd = %.4f)\n", ratio, n, se * 2 * sqrt(rho));
    check_close("Clark-Evans ratio within 4 standard errors of 1", (ratio - 1) / (se * 2 * sqrt(rho)), 0, 4);
    free(v);
}

static void test_exposure(void)
{
    const int size = 128;
    soak_image e;
    check_status("alloc", soak_image_alloc(&e, size, size, 1), SOAK_OK);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) e.pixels[y * size + x] = x < size / 2 ? 0.0f : 0.5f;
    soak_drops_params p = plane(20, 2e-3);
    soak_drop_impact *v = NULL;
    size_t n = 0, left = 0;
    check_status("impacts", soak_drops_impacts(&p, &e, size, size, 0, 64, &v, &n), SOAK_OK);
    for (size_t i = 0; i < n; ++i) left += v[i].x < size / 2;
    check_true("no impact where the exposure is 0", left == 0);
    double mean = 0.5 * simpson(20, NULL) * (size / 2 * 2e-3) * (size * 2e-3) * 64 * SOAK_DROPS_SLAB;
    check_close("impacts where exposure 0.5: 4 sigma of 0.5 n A T", (n - mean) / sqrt(mean), 0, 4);
    free(v);
    v = NULL;
    e.pixels[5] = NAN;
    check_status("NaN exposure rejected", soak_drops_impacts(&p, &e, size, size, 0, 1, &v, &n), SOAK_ERR_ARG);
    e.pixels[5] = -1;
    check_status("negative exposure rejected", soak_drops_impacts(&p, &e, size, size, 0, 1, &v, &n), SOAK_ERR_ARG);
    soak_image_free(&e);
    free(v);
}

static double wet_fraction(const soak_image *img)
{
    size_t n = (size_t)img->width * img->height, wet = 0;
    for (size_t i = 0; i < n; ++i) wet += img->pixels[i] > 0;
    return (double)wet / n;
}

/* Boolean model: a texel centre stays dry with probability
 * exp(-t int N v a dD) (a = spread disc area); every spread disc is wider
 * than sqrt(2) texels here (always covers a texel centre), so the texels
 * one impact covers average a. The
 * seed-to-seed scatter gives the statistical error. */
static void test_coverage(void)
{
    const int size = 512, seeds = 6;
    const double times[] = {4, 8, 16, 32}, texel = 2.5e-4;
    double na = simpson(10, spread_area_m2);
    for (size_t k = 0; k < sizeof times / sizeof times[0]; ++k) {
        double sum = 0, sum2 = 0;
        for (int s = 0; s < seeds; ++s) {
            soak_drops_params p = plane(10, texel);
            p.min_diameter_mm = 0.3; /* spread >= 0.39 mm, wider than sqrt(2) texels */
            p.duration = 100;
            p.seed = 100 + s;
            p.capacity_m = 1e-9;
            soak_drops_state *st = NULL;
            soak_image img = {0, 0, 0, NULL};
            check_status("create", soak_drops_create(&p, NULL, size, size, &st), SOAK_OK);
            check_status("frame", soak_drops_frame(st, times[k], NULL, &img), SOAK_OK);
            double f = wet_fraction(&img);
            sum += f, sum2 += f * f;
            soak_image_free(&img);
            soak_drops_destroy(st);
        }
        double mean = sum / seeds, sd = sqrt(fmax(0, (sum2 - sum * sum / seeds) / (seeds - 1)));
        double law = 1 - exp(-na * times[k]), err = 4 * sd / sqrt(seeds) + 1e-3;
        char what[200];
        snprintf(what, sizeof what, "wet fraction at %.2f s: %.4f vs 1 - exp(-n a t) = %.4f (+- %.4f)", times[k], mean,
                 law, err);
        check_close(what, mean, law, err);
    }
}

static void test_volume(void)
{
    const int size = 96;
    soak_drops_params p = plane(30, 1e-3);
    p.capacity_m = 1; /* never full */
    soak_drops_state *st = NULL;
    soak_image img = {0, 0, 0, NULL};
    soak_drop_impact *v = NULL;
    size_t n = 0;
    long slabs = 32;
    check_status("create", soak_drops_create(&p, NULL, size, size, &st), SOAK_OK);
    check_status("frame", soak_drops_frame(st, slabs * SOAK_DROPS_SLAB, NULL, &img), SOAK_OK);
    check_status("impacts", soak_drops_impacts(&p, NULL, size, size, 0, slabs, &v, &n), SOAK_OK);
    double want = 0, got = 0;
    for (size_t i = 0; i < n; ++i) want += PI / 6 * pow(v[i].d_mm * 1e-3, 3);
    for (int i = 0; i < size * size; ++i) got += img.pixels[i] * p.capacity_m * 1e-6;
    check_true("every impact before the frame applied", soak_drops_applied(st) == n);
    check_rel("water on the map = sum of drop volumes (float map)", got, want, 1e-5);
    soak_image_free(&img);
    soak_drops_destroy(st);
    free(v);
}

static int same_image(const soak_image *a, const soak_image *b)
{
    return a->width == b->width && a->height == b->height &&
           !memcmp(a->pixels, b->pixels, sizeof(float) * (size_t)a->width * a->height);
}

/* Frames 0..k of one run against a fresh state per frame (a farm chunk),
 * at 1 and 2 threads, during the rain and while drying. */
static void test_determinism(void)
{
    const int size = 160;
    soak_drops_params p = plane(15, 1e-3);
    p.duration = 1;
    p.dry_time = 1;
    const double times[] = {0.3, 0.7, 1.0, 1.4, 2.1};
    soak_drops_state *run = NULL;
    check_status("create", soak_drops_create(&p, NULL, size, size, &run), SOAK_OK);
    int chunk_ok = 1, threads_ok = 1, monotone = 1;
    soak_image prev = {0, 0, 0, NULL};
    for (size_t k = 0; k < sizeof times / sizeof times[0]; ++k) {
        soak_bake_exec one = {1, NULL, NULL}, two = {2, NULL, NULL};
        soak_image a = {0, 0, 0, NULL}, b = {0, 0, 0, NULL};
        soak_drops_state *fresh = NULL;
        check_status("run frame", soak_drops_frame(run, times[k], &one, &a), SOAK_OK);
        check_status("create", soak_drops_create(&p, NULL, size, size, &fresh), SOAK_OK);
        check_status("chunk frame", soak_drops_frame(fresh, times[k], &two, &b), SOAK_OK);
        chunk_ok &= same_image(&a, &b);
        threads_ok &= same_image(&a, &b);
        for (int i = 0; prev.pixels && i < size * size; ++i)
            if (times[k] > p.duration ? a.pixels[i] > prev.pixels[i] : a.pixels[i] < prev.pixels[i]) monotone = 0;
        soak_image_free(&prev);
        prev = a;
        soak_image_free(&b);
        soak_drops_destroy(fresh);
    }
    check_true("chunked frames (1 thread, one run) = fresh runs (2 threads), bit for bit", chunk_ok && threads_ok);
    check_true("wetness grows during the rain and falls while drying", monotone);
    soak_image img = {0, 0, 0, NULL};
    check_status("frame at the end of drying", soak_drops_frame(run, p.duration + p.dry_time, NULL, &img), SOAK_OK);
    check_close("dry once the schedule ends", wet_fraction(&img), 0, 0);
    soak_image_free(&img);
    check_status("going back in time replays", soak_drops_frame(run, 0.3, NULL, &img), SOAK_OK);
    soak_image_free(&img);
    soak_image_free(&prev);
    soak_drops_destroy(run);
}

/* A frame 9 s into the rain baked alone replays 144 slabs in steps of 64;
 * the same frame reached through 18 frames applies them in small batches. */
static void test_replay(void)
{
    const int size = 64;
    soak_drops_params p = plane(30, 1e-3);
    p.duration = 20;
    soak_drops_state *alone = NULL, *run = NULL;
    soak_image a = {0, 0, 0, NULL}, b = {0, 0, 0, NULL};
    check_status("create", soak_drops_create(&p, NULL, size, size, &alone), SOAK_OK);
    check_status("create", soak_drops_create(&p, NULL, size, size, &run), SOAK_OK);
    check_status("alone", soak_drops_frame(alone, 9.0, NULL, &a), SOAK_OK);
    for (int k = 1; k <= 18; ++k) {
        soak_image_free(&b);
        check_status("run", soak_drops_frame(run, 0.5 * k, NULL, &b), SOAK_OK);
    }
    check_true("a frame baked alone (long replay) = the same frame at the end of a run", same_image(&a, &b));
    check_true("the same impacts applied", soak_drops_applied(alone) == soak_drops_applied(run));
    soak_image_free(&a), soak_image_free(&b);
    soak_drops_destroy(alone), soak_drops_destroy(run);
}

static void test_errors(void)
{
    soak_drops_params p = plane(10, 1e-3);
    p.rate_mm_h = -1;
    check_status("negative rate", soak_drops_check(&p), SOAK_ERR_ARG);
    p.rate_mm_h = NAN;
    check_status("NaN rate", soak_drops_check(&p), SOAK_ERR_ARG);
    p = plane(10, 0);
    check_status("zero texel size", soak_drops_check(&p), SOAK_ERR_ARG);
    p = plane(10, 1e-3);
    p.spread_factor = 0.5;
    check_status("spread factor below 1", soak_drops_check(&p), SOAK_ERR_ARG);
    p = plane(0, 1e-3);
    soak_drop_impact *v = NULL;
    size_t n = 7;
    check_status("no rain", soak_drops_impacts(&p, NULL, 64, 64, 0, 10, &v, &n), SOAK_OK);
    check_true("no rain, no impacts", n == 0 && v == NULL);
    soak_drops_state *st = NULL;
    soak_image img = {0, 0, 0, NULL};
    check_status("create", soak_drops_create(&p, NULL, 8, 8, &st), SOAK_OK);
    check_status("negative time", soak_drops_frame(st, -1, NULL, &img), SOAK_ERR_ARG);
    check_status("NaN time", soak_drops_frame(st, NAN, NULL, &img), SOAK_ERR_ARG);
    soak_drops_destroy(st);
    check_close("flux of no rain", soak_drop_flux(0, 0, 6), 0, 0);
    check_close("flux of NaN rain", soak_drop_flux(NAN, 0, 6), 0, 0);
}

int main(void)
{
    test_flux();
    test_counts();
    test_randomness();
    test_exposure();
    test_coverage();
    test_volume();
    test_determinism();
    test_replay();
    test_errors();
    return check_finish();
}
